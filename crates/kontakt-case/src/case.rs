//! A case of any method ([`Case`], parsed from TOML; the `method` key decides the schema),
//! the one dispatch [`Case::run`], and what it gives ([`Outcome`]).

pub use crate::hertz_case::{
    BodySpec, CaseFile, ContactKind, ContactSpec, LoadControl, LoadSpec, Method, YieldSpec,
};

use crate::common::parse_toml;
use crate::validity::Checked;
use kontakt::{Error, Result};
use serde::Serialize;
use std::path::Path;

/// The valid `method` values, as an error message names them (from [`Case::METHODS`]).
fn methods_expected() -> String {
    let quoted: Vec<String> = Case::METHODS.iter().map(|m| format!("\"{m}\"")).collect();
    match quoted.split_last() {
        Some((last, rest)) => format!("{} or {last}", rest.join(", ")),
        None => String::new(),
    }
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
    /// `method = "friction"`: rib friction of a tapered roller bearing
    /// ([`crate::friction_case`]).
    Friction(Box<crate::friction_case::FrictionCase>),
    /// `method = "mindlin"`: Cattaneo-Mindlin partial slip and its loading history
    /// ([`crate::mindlin_case`]).
    Mindlin(Box<crate::mindlin_case::MindlinCase>),
    /// `method = "impact"`: a sphere striking a flat, normal or oblique with friction
    /// ([`crate::impact_case`]).
    Impact(Box<crate::impact_case::ImpactCase>),
    /// `method = "rough"`: a periodic rough surface on the half-space solver
    /// ([`crate::rough_case`]).
    Rough(Box<crate::rough_case::RoughCase>),
    /// `method = "bearing"`: the load distribution of a whole roller or ball bearing
    /// ([`crate::bearing_case`]).
    Bearing(Box<crate::bearing_case::BearingCase>),
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
            "mindlin" => Ok(Case::Mindlin(Box::new(parse_toml(text)?))),
            "impact" => Ok(Case::Impact(Box::new(parse_toml(text)?))),
            "rough" => Ok(Case::Rough(Box::new(parse_toml(text)?))),
            "bearing" => Ok(Case::Bearing(Box::new(
                crate::bearing_design::parse_bearing_case(text)?,
            ))),
            other => Err(Error::invalid("method", other, methods_expected())),
        }
    }

    /// Read a case of any method from an already parsed TOML table (what a sweep builds
    /// by editing a base case; no text is parsed or written).
    ///
    /// # Errors
    /// [`Error::CaseFile`] with the reader's message for unknown keys or wrong types; an unknown `method` names the valid ones.
    pub fn from_toml_table(table: toml::Table) -> Result<Self> {
        use crate::common::parse_table as read;
        let method = match table.get("method") {
            None => "hertz".to_string(),
            Some(toml::Value::String(m)) => m.clone(),
            Some(other) => {
                return Err(Error::invalid("method", other, methods_expected()));
            }
        };
        match method.as_str() {
            "hertz" => Ok(Case::Hertz(read(table)?)),
            "pimp" => Ok(Case::Pimp(Box::new(read(table)?))),
            "bem" => Ok(Case::Bem(Box::new(read(table)?))),
            "traction" => Ok(Case::Traction(Box::new(read(table)?))),
            "friction" => Ok(Case::Friction(Box::new(read(table)?))),
            "mindlin" => Ok(Case::Mindlin(Box::new(read(table)?))),
            "impact" => Ok(Case::Impact(Box::new(read(table)?))),
            "rough" => Ok(Case::Rough(Box::new(read(table)?))),
            "bearing" => Ok(Case::Bearing(Box::new(read(
                crate::bearing_design::expanded(table)?,
            )?))),
            other => Err(Error::invalid("method", other, methods_expected())),
        }
    }

    /// Every `method` a case file can name; the dispatch of [`Case::from_toml_str`], the
    /// error for an unknown method and the command line's help are built from it.
    pub const METHODS: [&'static str; 9] = [
        "hertz", "pimp", "bem", "traction", "friction", "mindlin", "impact", "rough", "bearing",
    ];

    /// The method's name, as the `method` key spells it.
    pub fn method(&self) -> &'static str {
        match self {
            Case::Hertz(_) => "hertz",
            Case::Pimp(_) => "pimp",
            Case::Bem(_) => "bem",
            Case::Traction(_) => "traction",
            Case::Friction(_) => "friction",
            Case::Mindlin(_) => "mindlin",
            Case::Impact(_) => "impact",
            Case::Rough(_) => "rough",
            Case::Bearing(_) => "bearing",
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
        // The one validity check of every method: the contacts' size against the bodies
        // (a warning above 0.4 of a radius of curvature, refused at 1) and finite numbers.
        crate::validity::checked(self.run_unchecked(base_dir)?)
    }

    fn run_unchecked(&self, base_dir: &Path) -> Result<Outcome> {
        Ok(match self {
            Case::Hertz(case) => {
                Outcome::Hertz(Box::new(crate::hertz_case::run_case_unchecked(case)?))
            }
            Case::Pimp(case) => {
                Outcome::Pimp(Box::new(crate::pimp_case::run_pimp_case_unchecked(case)?))
            }
            Case::Bem(case) => Outcome::Bem(Box::new(crate::bem_case::run_bem_case_unchecked(
                case, base_dir,
            )?)),
            Case::Traction(case) => Outcome::Traction(Box::new(
                crate::traction_case::run_traction_case_with_map_unchecked(case, None)?.0,
            )),
            Case::Friction(case) => Outcome::Friction(Box::new(
                crate::friction_case::run_friction_case_unchecked(case)?,
            )),
            Case::Mindlin(case) => Outcome::Mindlin(Box::new(
                crate::mindlin_case::run_mindlin_case_unchecked(case)?,
            )),
            Case::Impact(case) => Outcome::Impact(Box::new(
                crate::impact_case::run_impact_case_unchecked(case)?,
            )),
            Case::Rough(case) => Outcome::Rough(Box::new(
                crate::rough_case::run_rough_case_unchecked(case, base_dir)?,
            )),
            Case::Bearing(case) => Outcome::Bearing(Box::new(
                crate::bearing_case::run_bearing_case_unchecked(case)?,
            )),
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
    /// Cattaneo-Mindlin report with its loading history.
    Mindlin(Box<crate::mindlin_case::MindlinReport>),
    /// Impact report.
    Impact(Box<crate::impact_case::ImpactReport>),
    /// Rough-contact report and the pressure at its highest load.
    Rough(Box<crate::rough_case::RoughOutcome>),
    /// Whole-bearing report (load distribution, stiffness).
    Bearing(Box<crate::bearing_case::BearingReport>),
}

/// One field of an [`Outcome`] on its grid: values per cell, row-major with `x` fastest
/// (`values[j * nx + i]` at `(grid.x(i), grid.y(j))`, cell centres), in the grid frame of
/// the method's report (the gap's principal frame).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FieldView<'a> {
    /// The field's name, which is also its file-name suffix: `pressure`, `displacement`,
    /// `gap`.
    pub name: &'static str,
    /// Its unit: `MPa` or `mm`.
    pub unit: &'static str,
    /// The grid \[mm\].
    pub grid: &'a kontakt::geometry::Grid2,
    /// The values, `grid.len()` of them.
    pub values: &'a [f64],
}

impl Outcome {
    /// The fields of a field method, on the grid its report echoes (`grid.*`), for writers
    /// that store them (the sweeps' `fields = "npy"`): PimP the pressure \[MPa\]; the
    /// half-space solver the pressure, the elastic displacement and the undeformed gap
    /// \[mm\] (`+inf` where the bodies cannot meet); a rough case the pressure at its
    /// highest load (grid: its `points` and `spacing_mm`). Hertz and traction cases have none
    /// (their pressure is a closed form), nor rib friction, whose report does not carry the
    /// grid of its map (the CLI's `--map` writes that map).
    pub fn fields(&self) -> Vec<FieldView<'_>> {
        fn view<'a>(
            name: &'static str,
            unit: &'static str,
            grid: &'a kontakt::geometry::Grid2,
            values: &'a [f64],
        ) -> FieldView<'a> {
            FieldView {
                name,
                unit,
                grid,
                values,
            }
        }
        match self {
            Outcome::Hertz(_)
            | Outcome::Traction(_)
            | Outcome::Friction(_)
            | Outcome::Mindlin(_)
            | Outcome::Impact(_)
            | Outcome::Bearing(_) => Vec::new(),
            Outcome::Rough(o) => vec![view("pressure", "MPa", &o.grid, &o.pressure)],
            Outcome::Pimp(o) => vec![view(
                "pressure",
                "MPa",
                &o.solution.grid,
                &o.solution.pressure,
            )],
            Outcome::Bem(o) => {
                let s = &o.solution;
                vec![
                    view("pressure", "MPa", &s.grid, &s.pressure),
                    view("displacement", "mm", &s.grid, &s.detail.displacement),
                    view("gap", "mm", &s.grid, &s.detail.gap),
                ]
            }
        }
    }
}

/// Every variant answers with its report's contacts and warnings: a new method cannot
/// skip the validity check of [`Case::run`].
impl Checked for Outcome {
    fn contacts(&self) -> &[crate::validity::ContactSize] {
        match self {
            Outcome::Hertz(r) => r.contacts(),
            Outcome::Pimp(o) => o.report.contacts(),
            Outcome::Bem(o) => o.report.contacts(),
            Outcome::Traction(r) => r.contacts(),
            Outcome::Friction(o) => o.report.contacts(),
            Outcome::Mindlin(r) => r.contacts(),
            Outcome::Impact(r) => r.contacts(),
            Outcome::Rough(o) => o.contacts(),
            Outcome::Bearing(r) => r.contacts(),
        }
    }

    fn warnings_mut(&mut self) -> Option<&mut Vec<String>> {
        match self {
            Outcome::Hertz(r) => r.warnings_mut(),
            Outcome::Pimp(o) => o.report.warnings_mut(),
            Outcome::Bem(o) => o.report.warnings_mut(),
            Outcome::Traction(r) => r.warnings_mut(),
            Outcome::Friction(o) => o.report.warnings_mut(),
            Outcome::Mindlin(r) => r.warnings_mut(),
            Outcome::Impact(r) => r.warnings_mut(),
            Outcome::Rough(o) => o.warnings_mut(),
            Outcome::Bearing(r) => r.warnings_mut(),
        }
    }

    fn report_value(&self) -> Option<toml::Value> {
        toml::Value::try_from(self).ok()
    }
}

impl Outcome {
    /// The report's warnings (empty when none applies): the results to treat with care.
    pub fn warnings(&self) -> &[String] {
        match self {
            Outcome::Hertz(r) => &r.warnings,
            Outcome::Pimp(o) => &o.report.warnings,
            Outcome::Bem(o) => &o.report.warnings,
            Outcome::Traction(r) => &r.warnings,
            Outcome::Friction(o) => &o.report.warnings,
            Outcome::Mindlin(r) => &r.warnings,
            Outcome::Impact(r) => &r.warnings,
            Outcome::Rough(o) => &o.report.warnings,
            Outcome::Bearing(r) => &r.warnings,
        }
    }
}

/// A periodic rough surface has no curvature to compare its contact with; its report's
/// warnings (header lines skipped, a non-periodic map, pressures above the hardness) pass on.
impl Checked for crate::rough_case::RoughOutcome {
    fn contacts(&self) -> &[crate::validity::ContactSize] {
        &[]
    }

    fn warnings_mut(&mut self) -> Option<&mut Vec<String>> {
        Some(&mut self.report.warnings)
    }

    fn report_value(&self) -> Option<toml::Value> {
        toml::Value::try_from(&self.report).ok()
    }
}

impl Serialize for Outcome {
    fn serialize<S: serde::Serializer>(&self, s: S) -> std::result::Result<S::Ok, S::Error> {
        match self {
            Outcome::Hertz(r) => r.serialize(s),
            Outcome::Pimp(o) => o.report.serialize(s),
            Outcome::Bem(o) => o.report.serialize(s),
            Outcome::Traction(r) => r.serialize(s),
            Outcome::Friction(o) => o.report.serialize(s),
            Outcome::Mindlin(r) => r.serialize(s),
            Outcome::Impact(r) => r.serialize(s),
            Outcome::Rough(o) => o.report.serialize(s),
            Outcome::Bearing(r) => r.serialize(s),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Issue 30 item 19: `Case::METHODS` (which the help of `kontakt solve` prints) is the
    /// dispatch's list: each name reaches its own schema (a case with only `method` is
    /// refused for a missing key, not as an unknown method), and an unknown method's error
    /// names them all.
    #[test]
    fn methods_list_is_the_dispatch() {
        let unknown = Case::from_toml_str("method = \"nope\"")
            .unwrap_err()
            .to_string();
        for m in Case::METHODS {
            assert!(unknown.contains(&format!("\"{m}\"")), "{unknown}");
            match Case::from_toml_str(&format!("method = \"{m}\"\n")) {
                Ok(case) => assert_eq!(case.method(), m),
                Err(e) => assert!(!e.to_string().contains("invalid method"), "{m}: {e}"),
            }
        }
    }

    /// The half-space solver's fields: three of them on the report's grid, the pressure
    /// integrating to the report's force, gap minus displacement equal to the approach
    /// where the pressure is positive (the contact condition, to the solver's tolerance).
    #[test]
    fn bem_outcome_has_its_three_fields_on_its_grid() {
        let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../examples");
        let text = std::fs::read_to_string(dir.join("bem_torus_torus.toml")).unwrap_or_default();
        let outcome = Case::from_toml_str(&text).and_then(|c| c.run(&dir));
        assert!(outcome.is_ok(), "{outcome:?}");
        let Ok(Outcome::Bem(o)) = outcome else {
            return;
        };
        let all = Outcome::Bem(o.clone());
        let f = all.fields();
        let names: Vec<_> = f.iter().map(|v| v.name).collect();
        assert_eq!(names, ["pressure", "displacement", "gap"]);
        let n = o.solution.grid.len();
        assert!(f.iter().all(|v| v.values.len() == n));
        let force = f[0].values.iter().sum::<f64>() * o.solution.grid.cell_area();
        assert!((force - o.report.force_n).abs() < 1e-9 * o.report.force_n);
        let delta = o.report.approach_mm;
        for k in 0..n {
            if f[0].values[k] > 0.0 {
                let gap = f[2].values[k] + f[1].values[k] - delta;
                assert!(gap.abs() < 1e-6 * delta, "cell {k}: {gap}");
            }
        }
    }

    /// Found by fuzzing: a friction coefficient of 1e300 on bodies of 1e-300 MPa gave a
    /// Carter saturation creepage of inf in a report that came back as a success; an
    /// overflowing result is an error naming the report key. (On the twin disc's radii
    /// the contact-size check refuses these moduli first: an ellipse given by its
    /// semi-axes has no radii to check.)
    #[test]
    fn overflowing_report_is_an_error() {
        let text = std::fs::read_to_string(
            Path::new(env!("CARGO_MANIFEST_DIR")).join("../../examples/traction_twin_disc.toml"),
        )
        .unwrap_or_default()
        .lines()
        .filter(|l| !l.starts_with("radii") && !l.starts_with("angle_deg"))
        .collect::<Vec<_>>()
        .join("\n")
        .replace(
            "kind = \"hertz\"",
            "kind = \"ellipse\"\nsemi_axes_mm = [0.3, 0.9]",
        )
        .replace("mu = 0.1", "mu = 1e300")
        .replace("e_mpa = 210000.0", "e_mpa = 1e-300");
        let case = Case::from_toml_str(&text);
        assert!(case.is_ok(), "{case:?}");
        if let Ok(case) = case {
            let e = case.run(Path::new(".")).map(|_| ()).unwrap_err();
            let m = e.to_string();
            assert!(m.contains("inf") && e.field().is_some(), "{m}");
            assert!(!m.contains('\n'), "{m}");
        }
    }
}
