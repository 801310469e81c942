//! The TOML case schema (`schema_version = 1`). All lengths in mm, forces in N, moduli in
//! MPa, angles in degrees (converted to radians at this edge).
//!
//! ```toml
//! name = "ball on flat"
//! method = "hertz"            # "hertz"; "pimp" and "bem" cases: see io::pimp_case, io::bem_case
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

use kontakt::hertz::subsurface::YieldCriterion;
use kontakt::{Error, Result};
use serde::{Deserialize, Serialize};
use std::path::Path;

/// A complete case, as read from a TOML file.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
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
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Method {
    /// Closed-form Hertz theory.
    #[default]
    Hertz,
}

/// Point or line contact.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum ContactKind {
    /// Point contact (elliptical or circular).
    Point,
    /// Line contact of parallel cylinders.
    Line,
}

/// `[contact]` table.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
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
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
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
#[derive(Debug, Clone, PartialEq, Default, Serialize, Deserialize)]
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
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
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
    /// [`Error::InvalidInput`] with field `case` and the parser's message (with line and
    /// column) for malformed TOML, unknown keys or wrong types.
    pub fn from_toml_str(text: &str) -> Result<Self> {
        parse_toml(text)
    }
}

/// Parse TOML into `T`, turning parser errors into [`Error::InvalidInput`] with field
/// `case`, the line number and the parser's message.
pub(crate) fn parse_toml<T: serde::de::DeserializeOwned>(text: &str) -> Result<T> {
    toml::from_str(text).map_err(|e| {
        let location = e
            .span()
            .map(|s| {
                let line = text[..s.start.min(text.len())].matches('\n').count() + 1;
                format!(" at line {line}")
            })
            .unwrap_or_default();
        Error::invalid(
            "case",
            format!("TOML{location}: {}", e.message().trim()),
            "a case file following docs/case-schema.md",
        )
    })
}

/// A case of any method: the `method` key decides the schema.
#[derive(Debug, Clone, PartialEq)]
pub enum Case {
    /// `method = "hertz"` (or absent).
    Hertz(CaseFile),
    /// `method = "pimp"`.
    Pimp(Box<crate::pimp_case::PimpCase>),
    /// `method = "bem"`: the PimP schema solved by the half-space solver.
    Bem(Box<crate::pimp_case::PimpCase>),
    /// `method = "traction"`: traction curves ([`crate::traction_case`]).
    Traction(Box<crate::traction_case::TractionCase>),
}

impl Case {
    /// Parse a case of any method from TOML text.
    ///
    /// # Errors
    /// As [`CaseFile::from_toml_str`]; an unknown `method` names the valid ones.
    pub fn from_toml_str(text: &str) -> Result<Self> {
        let table: toml::Table = parse_toml(text)?;
        match table
            .get("method")
            .and_then(|m| m.as_str())
            .unwrap_or("hertz")
        {
            "hertz" => Ok(Case::Hertz(parse_toml(text)?)),
            "pimp" => Ok(Case::Pimp(Box::new(parse_toml(text)?))),
            "bem" => Ok(Case::Bem(Box::new(parse_toml(text)?))),
            "traction" => Ok(Case::Traction(Box::new(parse_toml(text)?))),
            other => Err(Error::invalid(
                "method",
                other,
                "\"hertz\", \"pimp\", \"bem\" or \"traction\"",
            )),
        }
    }

    /// The method's name, as the `method` key spells it.
    pub fn method(&self) -> &'static str {
        match self {
            Case::Hertz(_) => "hertz",
            Case::Pimp(_) => "pimp",
            Case::Bem(_) => "bem",
            Case::Traction(_) => "traction",
        }
    }

    /// Run the case: the one dispatch that the CLI, the Python package and the sweeps
    /// call. Relative file paths in the case (gap maps) are resolved against `base_dir`,
    /// the case file's folder.
    ///
    /// # Errors
    /// Invalid input named by its case-file key, geometry the method cannot solve, and
    /// non-convergence; see each method's runner.
    pub fn run(&self, base_dir: &Path) -> Result<Outcome> {
        Ok(match self {
            Case::Hertz(case) => Outcome::Hertz(Box::new(crate::report::run_case(case)?)),
            Case::Pimp(case) => Outcome::Pimp(Box::new(crate::pimp_case::run_pimp_case(case)?)),
            Case::Bem(case) => {
                Outcome::Bem(Box::new(crate::bem_case::run_bem_case(case, base_dir)?))
            }
            Case::Traction(case) => {
                Outcome::Traction(Box::new(crate::traction_case::run_traction_case(case)?))
            }
        })
    }
}

/// What running a [`Case`] gives: the JSON report and, for the field methods, the full
/// solution (pressure per cell, and for the half-space solver displacement and gap).
/// Serializes as the method's report.
#[derive(Debug, Clone, PartialEq)]
pub enum Outcome {
    /// A Hertz report.
    Hertz(Box<crate::report::ContactReport>),
    /// A PimP report and solution.
    Pimp(Box<crate::pimp_case::PimpOutcome>),
    /// A half-space report and solution.
    Bem(Box<crate::bem_case::BemOutcome>),
    /// Traction curves.
    Traction(Box<crate::traction_case::TractionReport>),
}

impl Serialize for Outcome {
    fn serialize<S: serde::Serializer>(&self, s: S) -> std::result::Result<S::Ok, S::Error> {
        match self {
            Outcome::Hertz(r) => r.serialize(s),
            Outcome::Pimp(o) => o.report.serialize(s),
            Outcome::Bem(o) => o.report.serialize(s),
            Outcome::Traction(r) => r.serialize(s),
        }
    }
}
