//! A case of any method ([`Case`], parsed from TOML; the `method` key decides the schema),
//! the one dispatch [`Case::run`], and what it gives ([`Outcome`]).

pub use crate::hertz_case::{
    BodySpec, CaseFile, ContactKind, ContactSpec, LoadControl, LoadSpec, Method, YieldSpec,
};

use crate::common::{case_file_error, parse_toml};
use kontakt::{Error, Result};
use serde::Serialize;
use std::path::Path;

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
    /// `method = "friction"`: rib friction of a tapered roller bearing
    /// ([`crate::friction_case`]).
    Friction(Box<crate::friction_case::FrictionCase>),
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
            "friction" => Ok(Case::Friction(Box::new(parse_toml(text)?))),
            other => Err(Error::invalid(
                "method",
                other,
                "\"hertz\", \"pimp\", \"bem\", \"traction\" or \"friction\"",
            )),
        }
    }

    /// Read a case of any method from an already parsed TOML table (what a sweep builds
    /// by editing a base case; no text is parsed or written).
    ///
    /// # Errors
    /// [`Error::CaseFile`] with the reader's message for unknown keys or wrong types; an unknown `method` names the valid ones.
    pub fn from_toml_table(table: toml::Table) -> Result<Self> {
        fn read<T: serde::de::DeserializeOwned>(table: toml::Table) -> Result<T> {
            table
                .try_into()
                .map_err(|e: toml::de::Error| case_file_error("", &e))
        }
        let method = match table.get("method") {
            None => "hertz".to_string(),
            Some(toml::Value::String(m)) => m.clone(),
            Some(other) => {
                return Err(Error::invalid(
                    "method",
                    other,
                    "\"hertz\", \"pimp\", \"bem\", \"traction\" or \"friction\"",
                ));
            }
        };
        match method.as_str() {
            "hertz" => Ok(Case::Hertz(read(table)?)),
            "pimp" => Ok(Case::Pimp(Box::new(read(table)?))),
            "bem" => Ok(Case::Bem(Box::new(read(table)?))),
            "traction" => Ok(Case::Traction(Box::new(read(table)?))),
            "friction" => Ok(Case::Friction(Box::new(read(table)?))),
            other => Err(Error::invalid(
                "method",
                other,
                "\"hertz\", \"pimp\", \"bem\", \"traction\" or \"friction\"",
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
            Case::Friction(_) => "friction",
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
            Case::Hertz(case) => Outcome::Hertz(Box::new(crate::hertz_case::run_case(case)?)),
            Case::Pimp(case) => Outcome::Pimp(Box::new(crate::pimp_case::run_pimp_case(case)?)),
            Case::Bem(case) => {
                Outcome::Bem(Box::new(crate::bem_case::run_bem_case(case, base_dir)?))
            }
            Case::Traction(case) => {
                Outcome::Traction(Box::new(crate::traction_case::run_traction_case(case)?))
            }
            Case::Friction(case) => {
                Outcome::Friction(Box::new(crate::friction_case::run_friction_case(case)?))
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
    Hertz(Box<crate::hertz_case::ContactReport>),
    /// A PimP report and solution.
    Pimp(Box<crate::pimp_case::PimpOutcome>),
    /// A half-space report and solution.
    Bem(Box<crate::bem_case::BemOutcome>),
    /// Traction curves.
    Traction(Box<crate::traction_case::TractionReport>),
    /// Rib friction report and the field of its maps.
    Friction(Box<crate::friction_case::FrictionOutcome>),
}

impl Serialize for Outcome {
    fn serialize<S: serde::Serializer>(&self, s: S) -> std::result::Result<S::Ok, S::Error> {
        match self {
            Outcome::Hertz(r) => r.serialize(s),
            Outcome::Pimp(o) => o.report.serialize(s),
            Outcome::Bem(o) => o.report.serialize(s),
            Outcome::Traction(r) => r.serialize(s),
            Outcome::Friction(o) => o.report.serialize(s),
        }
    }
}
