//! Error types of the library.
//!
//! Every public function that can receive bad input returns [`Result<T>`](Result). An
//! error names the offending field, the value received and the valid range, so that a
//! user (or the CLI, which only adds the flag name) can fix the input without reading code.

use std::borrow::Cow;

/// Result alias used throughout kontakt.
pub type Result<T, E = Error> = std::result::Result<T, E>;

/// Everything that can go wrong in kontakt.
#[non_exhaustive]
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum Error {
    /// A single input value is out of its valid range (or not finite).
    #[error("invalid {field} = {value}: expected {expected}")]
    InvalidInput {
        /// Name of the field, e.g. `poisson_ratio` or `body1.radii[0]`.
        field: Cow<'static, str>,
        /// The value received, formatted for humans.
        value: String,
        /// The valid range, e.g. `-1 < nu <= 0.5`.
        expected: Cow<'static, str>,
    },
    /// The geometry admits no Hertzian point contact: the relative curvature is not
    /// positive in every direction (conformal surfaces, bodies that do not touch, or a
    /// line contact that needs [`crate::hertz::line`]).
    #[error("{field}: {reason}")]
    Geometry {
        /// The field or group of fields at fault, e.g. `radii`.
        field: Cow<'static, str>,
        /// What is wrong and how to fix it.
        reason: String,
    },
    /// A case file that cannot be read (key `path`), is not valid TOML or does not follow
    /// its schema (an unknown or missing key, a value of the wrong type), located by its
    /// line and named by its key path as the file spells it (`contact.angle_deg`).
    #[error("{}{message}", .line.map(|l| format!("line {l}: ")).unwrap_or_default())]
    CaseFile {
        /// The line of the file (1-based), when the reader knows it.
        line: Option<usize>,
        /// The key path, e.g. `body1.e_mpa`; `case` when the reader cannot name a key.
        key: Cow<'static, str>,
        /// What is wrong and what the schema takes, e.g. "unknown key `contact.foo`;
        /// \[contact\] takes `kind`, `angle_deg`, `length_mm`".
        message: String,
    },
    /// An iterative computation did not reach its tolerance.
    #[error("{what} did not converge after {iterations} iterations (residual {residual:e})")]
    NotConverged {
        /// The computation that failed.
        what: Cow<'static, str>,
        /// Iterations performed.
        iterations: usize,
        /// Final residual in the computation's own (documented) measure.
        residual: f64,
    },
}

impl Error {
    /// Build an [`Error::InvalidInput`].
    pub fn invalid(
        field: impl Into<Cow<'static, str>>,
        value: impl std::fmt::Display,
        expected: impl Into<Cow<'static, str>>,
    ) -> Self {
        Error::InvalidInput {
            field: field.into(),
            value: shorten(value.to_string()),
            expected: expected.into(),
        }
    }

    /// The field this error is about, if any.
    pub fn field(&self) -> Option<&str> {
        match self {
            Error::InvalidInput { field, .. } | Error::Geometry { field, .. } => Some(field),
            Error::CaseFile { key, .. } => Some(key),
            Error::NotConverged { .. } => None,
        }
    }

    /// Rename the field with `f`, e.g. to prefix it with the body it belongs to
    /// (`youngs_modulus` → `body1.youngs_modulus`) or to map it to a CLI flag.
    #[must_use]
    pub fn map_field(self, f: impl FnOnce(&str) -> String) -> Self {
        match self {
            Error::InvalidInput {
                field,
                value,
                expected,
            } => Error::InvalidInput {
                field: f(&field).into(),
                value,
                expected,
            },
            Error::Geometry { field, reason } => Error::Geometry {
                field: f(&field).into(),
                reason,
            },
            other => other,
        }
    }
}

/// Longest value an error message quotes in full; a longer one is shortened.
const MAX_VALUE_CHARS: usize = 60;

/// A value as an error message quotes it: a number that Rust's `Display` wrote out in
/// hundreds of digits (`1e300`, `1e-303`) in its shortest exponent form, and any other
/// text longer than [`MAX_VALUE_CHARS`] cut with an ellipsis and its length.
fn shorten(value: String) -> String {
    // A value with a line break or another control character (a case-file string
    // `"a\nb"`, found by fuzzing) is escaped: messages stay on one line.
    let value = if value.chars().any(char::is_control) {
        value.chars().flat_map(char::escape_default).collect()
    } else {
        value
    };
    if value.len() > 24
        && let Ok(x) = value.parse::<f64>()
    {
        return format!("{x:e}");
    }
    if value.chars().count() > MAX_VALUE_CHARS {
        let head: String = value.chars().take(MAX_VALUE_CHARS - 20).collect();
        return format!("{head}… ({} characters)", value.chars().count());
    }
    value
}

/// Check that `value` is finite and strictly positive.
pub fn positive(field: &'static str, value: f64) -> Result<f64> {
    positive_as(field, value, "a finite number > 0")
}

/// Check that `value` is finite and strictly positive, stating the valid range as
/// `expected` (with its unit, e.g. "a finite length > 0 mm").
pub fn positive_as(field: &'static str, value: f64, expected: &'static str) -> Result<f64> {
    if value.is_finite() && value > 0.0 {
        Ok(value)
    } else {
        Err(Error::invalid(field, value, expected))
    }
}

/// Check a list of choices (`models = ["hertz", "pimp"]`, `--backends hertz,pimp`): at
/// least one, each one of `valid`, none twice. A repeated choice was accepted and gave
/// duplicate columns in the reports (found by probing); every list of choices goes through
/// this one check.
///
/// # Errors
/// [`Error::InvalidInput`] naming `field`, with the list as given and the valid choices.
pub fn choices(field: &'static str, given: &[&str], valid: &[&str]) -> Result<()> {
    let list = valid.join(", ");
    let shown = given.join(",");
    if given.is_empty() {
        return Err(Error::invalid(
            field,
            "an empty list",
            format!("one or more of {list}"),
        ));
    }
    if let Some(bad) = given.iter().find(|g| !valid.contains(g)) {
        return Err(Error::invalid(
            field,
            shown,
            format!("one or more of {list} (not {bad})"),
        ));
    }
    if let Some((_, twice)) = given
        .iter()
        .enumerate()
        .find(|(i, g)| given[..*i].contains(g))
    {
        return Err(Error::invalid(
            field,
            shown,
            format!("each of {list} at most once ({twice} is given twice)"),
        ));
    }
    Ok(())
}

/// `n` copies of `value` in a vector reserved with [`Vec::try_reserve_exact`]: when the
/// system refuses the memory, an [`Error::InvalidInput`] naming `field` (the grid whose
/// array it is) instead of the process aborting. For the arrays of a grid's size.
///
/// # Errors
/// [`Error::InvalidInput`] with the count and bytes asked for.
pub(crate) fn try_filled<T: Clone>(field: &'static str, n: usize, value: T) -> Result<Vec<T>> {
    let mut v = Vec::new();
    if v.try_reserve_exact(n).is_err() {
        let bytes = n as f64 * std::mem::size_of::<T>() as f64;
        return Err(Error::invalid(
            field,
            format!("{n} cells"),
            format!(
                "a grid whose arrays fit in memory (an array of {:.1} GiB could not be allocated)",
                bytes / f64::from(1u32 << 30)
            ),
        ));
    }
    v.resize(n, value);
    Ok(v)
}

/// Check that `value` is finite and not negative.
pub(crate) fn non_negative(field: &'static str, value: f64) -> Result<f64> {
    if value.is_finite() && value >= 0.0 {
        Ok(value)
    } else {
        Err(Error::invalid(field, value, "a finite number >= 0"))
    }
}

/// The error for an input whose result left the range of `f64` (absurdly large inputs).
pub(crate) fn overflow(field: &'static str, value: f64) -> Error {
    Error::invalid(
        field,
        value,
        "a value small enough for the result to be a finite f64",
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Issue 30 item 7: an array the system cannot give is an error naming the field, not
    /// an abort: a byte count beyond `isize::MAX` (capacity overflow) and one of 2^60 bytes
    /// (refused by the allocator, or by the address space).
    #[test]
    fn refused_allocation_is_an_error() {
        for n in [usize::MAX / 4, 1 << 57] {
            let e = try_filled("grid", n, 0.0f64).map(|v| v.len()).unwrap_err();
            assert_eq!(e.field(), Some("grid"), "{e}");
            assert!(e.to_string().contains("could not be allocated"), "{e}");
        }
        assert_eq!(try_filled("grid", 3, 1.5).ok(), Some(vec![1.5; 3]));
    }

    /// Long numbers come back in exponent form, long text cut with its length; short
    /// values are untouched.
    #[test]
    fn long_values_are_shortened() {
        let e = Error::invalid("force", 1e300, "x");
        assert_eq!(e.to_string(), "invalid force = 1e300: expected x");
        let e = Error::invalid("approach", 1e-303, "x");
        assert_eq!(e.to_string(), "invalid approach = 1e-303: expected x");
        assert_eq!(
            Error::invalid("nu", 0.7, "x").to_string(),
            "invalid nu = 0.7: expected x"
        );
        let long = "a".repeat(500);
        let e = Error::invalid("name", &long, "x");
        let shown = e.to_string();
        assert!(
            shown.contains("… (500 characters)") && shown.len() < 120,
            "{shown}"
        );
    }

    #[test]
    fn message_names_field_value_and_range() {
        let e = Error::invalid("poisson_ratio", 0.7, "-1 < nu <= 0.5");
        assert_eq!(
            e.to_string(),
            "invalid poisson_ratio = 0.7: expected -1 < nu <= 0.5"
        );
        let e = e.map_field(|f| format!("body2.{f}"));
        assert_eq!(e.field(), Some("body2.poisson_ratio"));
    }

    #[test]
    fn helpers_reject_nan_inf_and_sign() {
        assert!(positive("x", f64::NAN).is_err());
        assert!(positive("x", f64::INFINITY).is_err());
        assert!(positive("x", 0.0).is_err());
        assert!(positive("x", 1e-300).is_ok());
        assert!(non_negative("x", 0.0).is_ok());
        assert!(non_negative("x", -1e-300).is_err());
    }
}
