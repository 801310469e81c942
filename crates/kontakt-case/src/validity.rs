//! The one validity check of every result: the contact's size against the bodies it lies
//! on, and finite numbers throughout the report.
//!
//! Every model that produces a contact assumes it small against the bodies' radii of
//! curvature (Johnson 1985, §4.1): Hertz theory through its quadratic gap
//! (`kontakt::hertz::validity`), PimP and the half-space solver through their flat
//! half-spaces (`kontakt::field::validity`). Each runner records the size of every contact
//! it produced as a [`ContactSize`] in its report (not serialized), with the case-file
//! keys of the two bodies; [`checked`], which [`crate::Case::run`] and every public runner
//! (`run_case`, `run_traction_case`, `run_mindlin_case`, ...) go through, then applies the
//! same thresholds to all of them: a ratio above 0.4 adds a warning to the report's
//! `warnings`, a ratio of 1 or more refuses the result naming the key. A model that
//! produces a contact and records none would skip the check: [`Checked::contacts`] must be
//! answered by every report type, and a test runs every method's example through it.
//!
//! The same function refuses a report with a NaN or infinite number, naming its key
//! (finite inputs at the extremes of f64 can overflow a result): never `inf` in the text
//! or `null` in the JSON.

use kontakt::field::validity::CurvatureRatio;
use kontakt::hertz::validity::SizeCheck;
use kontakt::{Error, Result};

/// One contact of a result, sized against the bodies it lies on.
#[derive(Debug, Clone, PartialEq)]
pub struct ContactSize {
    /// Which contact of the report, for a report with several (`model pimp`); `None` for
    /// the case's one contact.
    pub at: Option<String>,
    /// The largest extent-to-radius ratio, by the theory whose assumption it is.
    pub size: Size,
    /// The case-file keys of body 1's and body 2's geometry (`geometry.radii1_mm`,
    /// `sphere.radius_mm`), named by a refusal.
    pub keys: [String; 2],
}

/// The largest ratio of a contact's extent to a body's radius of curvature.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Size {
    /// A Hertz contact (ellipse or strip) against the bodies' principal radii.
    Hertz(SizeCheck),
    /// A field solver's contact zone against the bodies' curvature.
    HalfSpace(CurvatureRatio),
}

impl ContactSize {
    /// A contact without a label with the keys of its two bodies.
    pub fn new(size: Size, keys: [&str; 2]) -> Self {
        ContactSize {
            at: None,
            size,
            keys: keys.map(str::to_string),
        }
    }

    /// The same, labelled `at` in its messages.
    pub fn at(mut self, at: impl Into<String>) -> Self {
        self.at = Some(at.into());
        self
    }

    /// The ratio \[-\].
    pub fn ratio(&self) -> f64 {
        match self.size {
            Size::Hertz(c) => c.ratio,
            Size::HalfSpace(c) => c.ratio,
        }
    }

    /// The warning this contact adds (ratio above 0.4), or the refusal (ratio of 1 or
    /// more) naming the key of the body whose radius it exceeds.
    ///
    /// # Errors
    /// [`Error::Geometry`] with that key.
    pub fn verdict(&self) -> Result<Option<String>> {
        let prefix = self
            .at
            .as_ref()
            .map(|a| format!("{a}: "))
            .unwrap_or_default();
        let (refusal, warning) = match self.size {
            Size::Hertz(c) => (c.refuse_too_large().err(), c.warning()),
            Size::HalfSpace(c) => (c.refuse_too_large().err(), c.warning()),
        };
        if let Some(e) = refusal {
            let body = match self.size {
                Size::Hertz(c) => c.body,
                Size::HalfSpace(c) => c.body,
            };
            let key = self.keys[usize::from(body.clamp(1, 2)) - 1].clone();
            return Err(match e {
                Error::Geometry { reason, .. } => Error::Geometry {
                    field: key.into(),
                    reason: format!("{prefix}{reason}"),
                },
                other => other.map_field(|_| key),
            });
        }
        Ok(warning.map(|w| format!("{prefix}{w}")))
    }
}

/// A report that goes through [`checked`]: its contacts, its warnings and its numbers.
pub trait Checked {
    /// Every contact the result holds (none for a model without one, such as a periodic
    /// rough surface, or a contact given by its semi-axes without the bodies' radii).
    fn contacts(&self) -> &[ContactSize];
    /// The report's warnings, where the size warnings go (`None`: a report without
    /// warnings, which must then have no contacts).
    fn warnings_mut(&mut self) -> Option<&mut Vec<String>>;
    /// The report as written (JSON or TOML), whose numbers must be finite.
    fn report_value(&self) -> Option<toml::Value>;
}

/// Apply the validity check to a result: the contact-size verdict of every contact
/// (warnings first in the report's `warnings`, without repeats; a refusal names the
/// key), then the finiteness of every number of the report.
///
/// # Errors
/// [`Error::Geometry`] naming the body's key for a contact as large as a body's radius
/// of curvature, or the report key of a NaN or infinite number.
pub fn checked<R: Checked>(mut report: R) -> Result<R> {
    let size_warnings = size_verdicts(report.contacts())?;
    if let Some(warnings) = report.warnings_mut() {
        add_size_warnings(size_warnings, warnings);
    }
    // Finite inputs at the extremes of f64 can overflow a result (found by fuzzing: a
    // Carter saturation creepage of inf): an error naming the report key, never inf
    // in the text or null in the JSON.
    if let Some(value) = report.report_value()
        && let Some((key, value)) = non_finite(&value, "")
    {
        return Err(Error::Geometry {
            field: key.into(),
            reason: format!(
                "the result is {value}: the inputs are beyond what f64 arithmetic holds for this model"
            ),
        });
    }
    Ok(report)
}

/// The contact-size verdicts of `contacts`: their warnings without repeats, in order.
///
/// # Errors
/// The first refusal ([`ContactSize::verdict`]).
pub(crate) fn size_verdicts(contacts: &[ContactSize]) -> Result<Vec<String>> {
    let mut size_warnings = Vec::new();
    for c in contacts {
        if let Some(w) = c.verdict()?
            && !size_warnings.contains(&w)
        {
            size_warnings.push(w);
        }
    }
    Ok(size_warnings)
}

/// Put the size warnings `size` first in `warnings`, leaving out those already there (as
/// [`checked`] does; a bearing sweep's row, which has no report, does the same).
pub(crate) fn add_size_warnings(mut size: Vec<String>, warnings: &mut Vec<String>) {
    size.retain(|w| !warnings.contains(w));
    warnings.splice(0..0, size);
}

/// The key path (`rows[3].power_w`) and value of the first NaN or infinite number in `v`.
fn non_finite(v: &toml::Value, path: &str) -> Option<(String, f64)> {
    match v {
        toml::Value::Float(x) if !x.is_finite() => Some((path.to_string(), *x)),
        toml::Value::Table(t) => t.iter().find_map(|(k, x)| {
            let p = if path.is_empty() {
                k.clone()
            } else {
                format!("{path}.{k}")
            };
            non_finite(x, &p)
        }),
        toml::Value::Array(a) => a
            .iter()
            .enumerate()
            .find_map(|(i, x)| non_finite(x, &format!("{path}[{i}]"))),
        _ => None,
    }
}

/// `impl Checked` for a report with the fields `contacts: Vec<ContactSize>` and
/// `warnings: Vec<String>` (`checked_report!(Report)`), or for an outcome holding such a
/// report in a field (`checked_report!(Outcome, report)`).
macro_rules! checked_report {
    ($t:ty $(, $f:ident)?) => {
        impl $crate::validity::Checked for $t {
            fn contacts(&self) -> &[$crate::validity::ContactSize] {
                &self $(.$f)? .contacts
            }
            fn warnings_mut(&mut self) -> Option<&mut Vec<String>> {
                Some(&mut self $(.$f)? .warnings)
            }
            fn report_value(&self) -> Option<toml::Value> {
                toml::Value::try_from(&self $(.$f)?).ok()
            }
        }
    };
}
pub(crate) use checked_report;
