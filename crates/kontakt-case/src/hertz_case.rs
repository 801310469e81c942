//! The Hertz case: its TOML schema (`schema_version = 1`), runner and report. All lengths
//! in mm, forces in N, moduli in MPa, angles in degrees (converted to radians at this edge).
//!
//! ```toml
//! name = "ball on flat"
//! method = "hertz"            # "hertz"; "pimp" and "bem" cases: see pimp_case, bem_case
//!
//! [contact]
//! kind = "point"              # "point" or "line"
//! angle_deg = 0.0             # point: angle between the principal planes
//! # length_mm = 20.0          # line: contact length (needed for approach and area)
//!
//! [body1]
//! radii_mm = [6.35, 6.35]     # point: two principal radii; line: one radius
//! e_mpa = 210000.0            # convex > 0, concave < 0, inf = flat
//! nu = 0.3
//!
//! [body2]
//! radii_mm = [inf, inf]
//! e_mpa = 210000.0
//! nu = 0.3
//!
//! [load]
//! force_n = 100.0             # exactly one of force_n / approach_mm (line: also line_load_n_per_mm)
//!
//! [yield]                     # optional
//! stress_mpa = 1500.0
//! criterion = "von_mises"     # or "tresca"
//! ```
//!
//! The result record of a case has stable, unit-suffixed keys (`schema_version = 1`).
//! Keys are never renamed without bumping the schema version; new keys may be added.

use crate::common::{SCHEMA_VERSION, material_keys, parse_toml};
use crate::validity::{ContactSize, Size, checked, checked_report};
use kontakt::hertz::line::LineContact;
use kontakt::hertz::point_stress::FirstYield;
use kontakt::hertz::subsurface::YieldCriterion;
use kontakt::hertz::validity::{line_size, point_size};
use kontakt::hertz::{HertzPointContact, PointGeometry};
use kontakt::material::{ElasticMaterial, dundurs_beta};
use kontakt::{Error, Result};
use serde::{Deserialize, Serialize, Serializer};

/// A complete case, as read from a TOML file.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize, schemars::JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct CaseFile {
    /// Optional label echoed in the report.
    #[serde(default)]
    pub name: Option<String>,
    /// Solution method.
    #[serde(default)]
    pub method: Method,
    /// Contact kind and geometry parameters.
    pub contact: ContactSpec,
    /// Body 1.
    pub body1: BodySpec,
    /// Body 2.
    pub body2: BodySpec,
    /// Load control.
    pub load: LoadSpec,
    /// Optional first-yield evaluation.
    #[serde(default, rename = "yield")]
    pub yield_check: Option<YieldSpec>,
}

/// Solution method.
#[derive(
    Debug, Clone, Copy, PartialEq, Eq, Default, Serialize, Deserialize, schemars::JsonSchema,
)]
#[serde(rename_all = "snake_case")]
pub enum Method {
    /// Closed-form Hertz theory.
    #[default]
    Hertz,
}

/// Point or line contact.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize, schemars::JsonSchema)]
#[serde(rename_all = "snake_case")]
pub enum ContactKind {
    /// Point contact (elliptical or circular).
    Point,
    /// Line contact of parallel cylinders.
    Line,
}

/// `[contact]` table.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize, schemars::JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct ContactSpec {
    /// Point or line.
    pub kind: ContactKind,
    /// Angle between the principal planes of the bodies \[deg\] (point contact).
    #[serde(default)]
    pub angle_deg: f64,
    /// Contact length \[mm\] (line contact; gives the approach, area and stiffness).
    #[serde(default)]
    pub length_mm: Option<f64>,
}

/// `[body1]` / `[body2]` table.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize, schemars::JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct BodySpec {
    /// Principal radii of curvature \[mm\]: two for a point contact, one for a line contact.
    /// Convex > 0, concave < 0, `inf` for flat.
    pub radii_mm: Vec<f64>,
    /// Young's modulus \[MPa\], > 0.
    pub e_mpa: f64,
    /// Poisson's ratio, -1 < nu <= 0.5.
    pub nu: f64,
}

/// `[load]` table: exactly one entry.
#[derive(Debug, Clone, PartialEq, Default, Serialize, Deserialize, schemars::JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct LoadSpec {
    /// Normal force \[N\].
    #[serde(default)]
    pub force_n: Option<f64>,
    /// Approach of distant points \[mm\] (point contact).
    #[serde(default)]
    pub approach_mm: Option<f64>,
    /// Load per unit length [N/mm] (line contact).
    #[serde(default)]
    pub line_load_n_per_mm: Option<f64>,
}

/// `[yield]` table.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize, schemars::JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct YieldSpec {
    /// Yield stress of the weaker body \[MPa\], > 0.
    pub stress_mpa: f64,
    /// Criterion, `von_mises` (default) or `tresca`.
    #[serde(default = "default_criterion")]
    pub criterion: YieldCriterion,
}

fn default_criterion() -> YieldCriterion {
    YieldCriterion::VonMises
}

pub use kontakt::load::LoadControl;

impl LoadSpec {
    /// The single load entry, validated to be present and unique.
    ///
    /// # Errors
    /// None or more than one of the entries given.
    pub fn control(&self) -> Result<LoadControl> {
        let given: Vec<LoadControl> = [
            self.force_n.map(LoadControl::Force),
            self.approach_mm.map(LoadControl::Approach),
            self.line_load_n_per_mm.map(LoadControl::LineLoad),
        ]
        .into_iter()
        .flatten()
        .collect();
        match given.as_slice() {
            [one] => Ok(*one),
            _ => Err(Error::invalid(
                "load",
                format!("{} entries", given.len()),
                "exactly one of force_n, approach_mm or line_load_n_per_mm",
            )),
        }
    }
}

impl CaseFile {
    /// Parse a case from TOML text.
    ///
    /// # Errors
    /// [`Error::CaseFile`] (line, key path, what the schema takes) for malformed TOML,
    /// unknown keys or wrong types.
    pub fn from_toml_str(text: &str) -> Result<Self> {
        parse_toml(text)
    }
}

/// Result of one case. Every key carries its unit; `null` marks a quantity that does not
/// apply (e.g. no yield stress given).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct ContactReport {
    /// Version of kontakt that produced the record.
    pub kontakt_version: &'static str,
    /// Version of this schema.
    pub schema_version: u32,
    /// The case's name, if any.
    pub name: Option<String>,
    /// `"hertz"`.
    pub method: Method,
    /// `"point"` or `"line"`.
    pub kind: ContactKind,
    /// The inputs, echoed (radii `"inf"` for flat).
    pub inputs: InputsEcho,
    /// Contact modulus E* \[MPa\].
    pub e_star_mpa: f64,
    /// Dundurs' beta (body 1 relative to body 2).
    pub dundurs_beta: f64,
    /// Relative curvature [A, B] [1/mm] (point) or [0, 1/(2R)] (line).
    pub relative_curvature_per_mm: [f64; 2],
    /// Semi-axes [a, b] \[mm\], a >= b; for a line contact [L/2, b], with L/2 written as
    /// `"inf"` when no length is given.
    #[serde(serialize_with = "ser_radii_array")]
    pub semi_axes_mm: [f64; 2],
    /// b/a (0 for a line contact).
    pub axis_ratio: f64,
    /// Angle from body 1's first principal direction to the major axis \[deg\].
    pub orientation_deg: f64,
    /// Normal force \[N\] (null for a line contact without length).
    pub force_n: Option<f64>,
    /// Line load [N/mm] (line contact only).
    pub line_load_n_per_mm: Option<f64>,
    /// Approach of distant points \[mm\] (line: Lundberg, needs the length).
    pub approach_mm: Option<f64>,
    /// Maximum contact pressure p0 \[MPa\].
    pub max_pressure_mpa: f64,
    /// Mean contact pressure \[MPa\].
    pub mean_pressure_mpa: f64,
    /// Contact area \[mm²\] (line: 2 b L, needs the length).
    pub contact_area_mm2: Option<f64>,
    /// Contact stiffness dF/d(delta) [N/mm].
    pub stiffness_n_per_mm: Option<f64>,
    /// Maximum principal shear stress below the surface \[MPa\].
    pub max_shear_stress_mpa: f64,
    /// Its depth \[mm\].
    pub max_shear_depth_mm: f64,
    /// Maximum von Mises stress below the surface \[MPa\].
    pub max_von_mises_stress_mpa: f64,
    /// Its depth \[mm\].
    pub max_von_mises_depth_mm: f64,
    /// Normal force at first yield \[N\] (line contact: needs the length).
    pub first_yield_load_n: Option<f64>,
    /// Line load at first yield [N/mm] (line contact).
    pub first_yield_line_load_n_per_mm: Option<f64>,
    /// Maximum pressure at first yield \[MPa\].
    pub first_yield_max_pressure_mpa: Option<f64>,
    /// Ratio of the first-yield pressure to the actual maximum pressure (> 1: elastic).
    pub yield_pressure_margin: Option<f64>,
    /// Where the result is outside the theory's comfortable range: a contact large against
    /// a body's radius of curvature (`kontakt::hertz::validity`), a maximum pressure above
    /// first yield. Empty when none applies.
    pub warnings: Vec<String>,
    /// The contact's size against the bodies, for the validity check
    /// ([`crate::validity`]); not in the JSON.
    #[serde(skip)]
    pub contacts: Vec<ContactSize>,
}

checked_report!(ContactReport);

/// Inputs echoed in the report.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct InputsEcho {
    /// Body 1 radii \[mm\].
    #[serde(serialize_with = "ser_radii")]
    pub body1_radii_mm: Vec<f64>,
    /// Body 2 radii \[mm\].
    #[serde(serialize_with = "ser_radii")]
    pub body2_radii_mm: Vec<f64>,
    /// Angle between principal planes \[deg\].
    pub angle_deg: f64,
    /// Contact length \[mm\] (line).
    pub length_mm: Option<f64>,
    /// Body 1 Young's modulus \[MPa\].
    pub e1_mpa: f64,
    /// Body 1 Poisson's ratio.
    pub nu1: f64,
    /// Body 2 Young's modulus \[MPa\].
    pub e2_mpa: f64,
    /// Body 2 Poisson's ratio.
    pub nu2: f64,
    /// Given force \[N\].
    pub force_n: Option<f64>,
    /// Given approach \[mm\].
    pub approach_mm: Option<f64>,
    /// Given line load [N/mm].
    pub line_load_n_per_mm: Option<f64>,
    /// Yield stress \[MPa\].
    pub yield_stress_mpa: Option<f64>,
    /// Yield criterion.
    pub yield_criterion: Option<YieldCriterion>,
}

fn radius_value(r: f64) -> serde_json_like::Value {
    if r.is_infinite() {
        serde_json_like::Value::Str(if r > 0.0 { "inf" } else { "-inf" })
    } else {
        serde_json_like::Value::Num(r)
    }
}

/// Minimal untagged value so that infinite radii serialize as `"inf"` (JSON has no inf).
mod serde_json_like {
    use serde::{Serialize, Serializer};
    pub enum Value {
        Num(f64),
        Str(&'static str),
    }
    impl Serialize for Value {
        fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
            match self {
                Value::Num(x) => s.serialize_f64(*x),
                Value::Str(t) => s.serialize_str(t),
            }
        }
    }
}

fn ser_radii<S: Serializer>(radii: &[f64], s: S) -> std::result::Result<S::Ok, S::Error> {
    s.collect_seq(radii.iter().map(|&r| radius_value(r)))
}

fn ser_radii_array<S: Serializer>(radii: &[f64; 2], s: S) -> std::result::Result<S::Ok, S::Error> {
    ser_radii(radii, s)
}

fn material(body: &BodySpec, prefix: &'static str) -> Result<ElasticMaterial> {
    material_keys(body.e_mpa, body.nu, prefix)
}

fn radii<const N: usize>(body: &BodySpec, prefix: &'static str, kind: &str) -> Result<[f64; N]> {
    body.radii_mm.as_slice().try_into().map_err(|_| {
        Error::invalid(
            format!("{prefix}.radii_mm"),
            format!("{} values", body.radii_mm.len()),
            format!("{N} radii for a {kind} contact"),
        )
    })
}

/// Map the library's field names to the case file's keys (`body1.radii[0]` →
/// `body1.radii_mm[0]`, `force` → `load.force_n`, ...).
fn case_field(f: &str) -> String {
    if f.contains(".radii_mm") {
        return f.to_string();
    }
    let f = f
        .replace(".radii", ".radii_mm")
        .replace(".radius", ".radii_mm[0]");
    match f.as_str() {
        "force" => "load.force_n".into(),
        "approach" => "load.approach_mm".into(),
        "line_load" => "load.line_load_n_per_mm".into(),
        "angle" => "contact.angle_deg".into(),
        "length" => "contact.length_mm".into(),
        "yield_stress" => "yield.stress_mpa".into(),
        // A geometry error about the pair of radii (conformal or separate surfaces).
        "radii" => "body1.radii_mm, body2.radii_mm".into(),
        _ => f,
    }
}

/// Solve a case.
///
/// # Errors
/// Any invalid input, with the field named by its case-file key
/// (e.g. `body1.e_mpa`, `load.force_n`, `body2.radii_mm[1]`).
pub fn run_case(case: &CaseFile) -> Result<ContactReport> {
    checked(run_case_unchecked(case)?)
}

/// [`run_case`] before the validity check of [`crate::validity::checked`] (what
/// [`crate::Case::run`] dispatches to, and checks).
pub(crate) fn run_case_unchecked(case: &CaseFile) -> Result<ContactReport> {
    run_case_inner(case).map_err(|e| e.map_field(case_field))
}

/// The size of a Hertz contact against the bodies (case keys `body1.radii_mm`,
/// `body2.radii_mm`), refused here already when too large (before the stresses are
/// computed on a contact that is refused anyway).
fn hertz_size(size: kontakt::hertz::validity::SizeCheck) -> Result<ContactSize> {
    let c = ContactSize::new(Size::Hertz(size), ["body1.radii_mm", "body2.radii_mm"]);
    c.verdict()?;
    Ok(c)
}

fn run_case_inner(case: &CaseFile) -> Result<ContactReport> {
    let m1 = material(&case.body1, "body1")?;
    let m2 = material(&case.body2, "body2")?;
    let control = case.load.control()?;
    let inputs = InputsEcho {
        body1_radii_mm: case.body1.radii_mm.clone(),
        body2_radii_mm: case.body2.radii_mm.clone(),
        angle_deg: case.contact.angle_deg,
        length_mm: case.contact.length_mm,
        e1_mpa: case.body1.e_mpa,
        nu1: case.body1.nu,
        e2_mpa: case.body2.e_mpa,
        nu2: case.body2.nu,
        force_n: case.load.force_n,
        approach_mm: case.load.approach_mm,
        line_load_n_per_mm: case.load.line_load_n_per_mm,
        yield_stress_mpa: case.yield_check.map(|y| y.stress_mpa),
        yield_criterion: case.yield_check.map(|y| y.criterion),
    };
    let beta = dundurs_beta(&m1, &m2);
    match case.contact.kind {
        ContactKind::Point => {
            if case.contact.length_mm.is_some() {
                return Err(Error::invalid(
                    "contact.length_mm",
                    case.contact.length_mm.unwrap_or_default(),
                    "no length for a point contact (remove it or use kind = \"line\")",
                ));
            }
            let angle = case.contact.angle_deg;
            if !angle.is_finite() {
                return Err(Error::invalid("angle", angle, "a finite angle in degrees"));
            }
            let geometry = PointGeometry::new(
                radii::<2>(&case.body1, "body1", "point")?,
                radii::<2>(&case.body2, "body2", "point")?,
                angle.to_radians(),
            )?;
            let contact = HertzPointContact::new(geometry, m1, m2)?;
            let sol = match control {
                LoadControl::Force(f) => contact.solve_force(f)?,
                LoadControl::Approach(d) => contact.solve_approach(d)?,
                LoadControl::LineLoad(_) => {
                    return Err(Error::invalid(
                        "load.line_load_n_per_mm",
                        "given",
                        "force_n or approach_mm for a point contact",
                    ));
                }
            };
            let size = hertz_size(point_size(&geometry, &sol))?;
            let (peaks, _) = contact.subsurface_peaks(&sol)?;
            let fy = case
                .yield_check
                .map(|y| contact.first_yield(y.stress_mpa, y.criterion))
                .transpose()?;
            let k = geometry.curvature();
            ContactReport {
                kontakt_version: kontakt::VERSION,
                schema_version: SCHEMA_VERSION,
                name: case.name.clone(),
                method: case.method,
                kind: ContactKind::Point,
                inputs,
                e_star_mpa: contact.e_star(),
                dundurs_beta: beta,
                relative_curvature_per_mm: [k.a_coef, k.b_coef],
                semi_axes_mm: sol.semi_axes,
                axis_ratio: contact.axis_ratio(),
                orientation_deg: sol.orientation.to_degrees(),
                force_n: Some(sol.force),
                line_load_n_per_mm: None,
                approach_mm: Some(sol.approach),
                max_pressure_mpa: sol.max_pressure,
                mean_pressure_mpa: sol.mean_pressure,
                contact_area_mm2: Some(sol.contact_area),
                stiffness_n_per_mm: Some(sol.stiffness),
                max_shear_stress_mpa: peaks.max_shear,
                max_shear_depth_mm: peaks.max_shear_depth,
                max_von_mises_stress_mpa: peaks.max_von_mises,
                max_von_mises_depth_mm: peaks.max_von_mises_depth,
                first_yield_load_n: fy.map(|f: FirstYield| f.load),
                first_yield_line_load_n_per_mm: None,
                first_yield_max_pressure_mpa: fy.map(|f| f.max_pressure),
                yield_pressure_margin: fy.map(|f| f.max_pressure / sol.max_pressure),
                warnings: warnings(fy.map(|f| f.max_pressure / sol.max_pressure)),
                contacts: vec![size],
            }
            .finite()
        }
        ContactKind::Line => {
            let [r1] = radii::<1>(&case.body1, "body1", "line")?;
            let [r2] = radii::<1>(&case.body2, "body2", "line")?;
            if case.contact.angle_deg != 0.0 {
                return Err(Error::invalid(
                    "contact.angle_deg",
                    case.contact.angle_deg,
                    "0 for a line contact (parallel cylinders)",
                ));
            }
            let length = case
                .contact
                .length_mm
                .map(|l| kontakt::error::positive("length", l))
                .transpose()?;
            let contact = LineContact::new(r1, r2, m1, m2)?;
            let line_load = match (control, length) {
                (LoadControl::LineLoad(q), _) => q,
                (LoadControl::Force(f), Some(l)) => {
                    kontakt::error::positive("force", f)?;
                    f / l
                }
                (LoadControl::Force(_), None) => {
                    return Err(Error::invalid(
                        "contact.length_mm",
                        "missing",
                        "a contact length > 0 mm when a line contact is loaded by force_n",
                    ));
                }
                (LoadControl::Approach(_), _) => {
                    return Err(Error::invalid(
                        "load.approach_mm",
                        "given",
                        "force_n or line_load_n_per_mm for a line contact",
                    ));
                }
            };
            let sol = contact.solve(line_load)?;
            let size = hertz_size(line_size(contact.radii(), &sol))?;
            let b = sol.half_width;
            let force = length.map(|l| line_load * l);
            let approach = match (force, length) {
                (Some(f), Some(l)) => Some(contact.lundberg_approach(f, l)?),
                _ => None,
            };
            let stiffness = length
                .map(|l| contact.stiffness(line_load, l))
                .transpose()?;
            let (peaks, _) = contact.subsurface_peaks(&sol)?;
            let yield_line_load = case
                .yield_check
                .map(|y| -> Result<(f64, f64)> {
                    let fy = contact.first_yield(y.stress_mpa, y.criterion)?;
                    Ok((fy.line_load, fy.max_pressure))
                })
                .transpose()?;
            ContactReport {
                kontakt_version: kontakt::VERSION,
                schema_version: SCHEMA_VERSION,
                name: case.name.clone(),
                method: case.method,
                kind: ContactKind::Line,
                inputs,
                e_star_mpa: contact.e_star(),
                dundurs_beta: beta,
                relative_curvature_per_mm: [0.0, 0.5 / contact.effective_radius()],
                semi_axes_mm: [length.map_or(f64::INFINITY, |l| 0.5 * l), b],
                axis_ratio: 0.0,
                orientation_deg: 0.0,
                force_n: force,
                line_load_n_per_mm: Some(line_load),
                approach_mm: approach,
                max_pressure_mpa: sol.max_pressure,
                mean_pressure_mpa: sol.mean_pressure,
                contact_area_mm2: length.map(|l| 2.0 * b * l),
                stiffness_n_per_mm: stiffness,
                max_shear_stress_mpa: peaks.max_shear,
                max_shear_depth_mm: peaks.max_shear_depth,
                max_von_mises_stress_mpa: peaks.max_von_mises,
                max_von_mises_depth_mm: peaks.max_von_mises_depth,
                first_yield_load_n: match (yield_line_load, length) {
                    (Some((q, _)), Some(l)) => Some(q * l),
                    _ => None,
                },
                first_yield_line_load_n_per_mm: yield_line_load.map(|(q, _)| q),
                first_yield_max_pressure_mpa: yield_line_load.map(|(_, p)| p),
                yield_pressure_margin: yield_line_load.map(|(_, p)| p / sol.max_pressure),
                warnings: warnings(yield_line_load.map(|(_, p)| p / sol.max_pressure)),
                contacts: vec![size],
            }
            .finite()
        }
    }
}

/// The report's warnings but the contact's size (added by [`crate::validity::checked`]): a
/// maximum pressure above the first-yield pressure (`margin` = p0,Y / p0 < 1: the bodies
/// yield, and elastic theory no longer describes them).
fn warnings(margin: Option<f64>) -> Vec<String> {
    let mut w = Vec::new();
    if let Some(m) = margin.filter(|&m| m < 1.0) {
        w.push(format!(
            "first yield: the maximum pressure is {:.2} times the first-yield pressure; the \
             bodies deform plastically and elastic Hertz theory overestimates the pressure",
            1.0 / m
        ));
    }
    w
}

impl ContactReport {
    /// `Ok(self)` when every number is finite; otherwise the quantity that overflowed (or
    /// underflowed to a division by zero) as an error, never `inf` in the text or `null`
    /// in JSON, where `null` means "does not apply".
    fn finite(self) -> Result<Self> {
        let required = [
            ("e_star_mpa", self.e_star_mpa),
            ("dundurs_beta", self.dundurs_beta),
            (
                "relative_curvature_per_mm[0]",
                self.relative_curvature_per_mm[0],
            ),
            (
                "relative_curvature_per_mm[1]",
                self.relative_curvature_per_mm[1],
            ),
            ("semi_axes_mm[1]", self.semi_axes_mm[1]),
            ("axis_ratio", self.axis_ratio),
            ("orientation_deg", self.orientation_deg),
            ("max_pressure_mpa", self.max_pressure_mpa),
            ("mean_pressure_mpa", self.mean_pressure_mpa),
            ("max_shear_stress_mpa", self.max_shear_stress_mpa),
            ("max_shear_depth_mm", self.max_shear_depth_mm),
            ("max_von_mises_stress_mpa", self.max_von_mises_stress_mpa),
            ("max_von_mises_depth_mm", self.max_von_mises_depth_mm),
        ];
        let optional = [
            ("force_n", self.force_n),
            ("line_load_n_per_mm", self.line_load_n_per_mm),
            ("approach_mm", self.approach_mm),
            ("contact_area_mm2", self.contact_area_mm2),
            ("stiffness_n_per_mm", self.stiffness_n_per_mm),
            ("first_yield_load_n", self.first_yield_load_n),
            (
                "first_yield_line_load_n_per_mm",
                self.first_yield_line_load_n_per_mm,
            ),
            (
                "first_yield_max_pressure_mpa",
                self.first_yield_max_pressure_mpa,
            ),
            ("yield_pressure_margin", self.yield_pressure_margin),
        ];
        let values = required
            .into_iter()
            .chain(optional.into_iter().filter_map(|(k, v)| v.map(|v| (k, v))));
        // A line contact's semi_axes_mm[0] is L/2, infinite when no length is given.
        let line_without_length = self.kind == ContactKind::Line && self.inputs.length_mm.is_none();
        for (key, value) in values
            .chain((!line_without_length).then_some(("semi_axes_mm[0]", self.semi_axes_mm[0])))
        {
            if !value.is_finite() {
                // The first-yield results scale with the yield stress alone: name it.
                let field = if key.contains("yield") {
                    "yield.stress_mpa"
                } else {
                    "case"
                };
                return Err(Error::Geometry {
                    field: field.into(),
                    reason: format!(
                        "the result {key} = {value} is beyond the range of double precision \
                         numbers; the inputs are too extreme to give a meaningful result \
                         (scale the radii, moduli or load towards engineering values)"
                    ),
                });
            }
        }
        Ok(self)
    }
}
