//! Half-space cases (`method = "bem"`): the PimP case schema solved by the coupled elastic
//! half-space solver, plus user gap maps.
//!
//! ```toml
//! name = "torus/torus, coupled"
//! method = "bem"
//!
//! [geometry]                 # roller_rib | hertz | surfaces, as for PimP, or a map:
//! kind = "roller_rib"
//! pairing = "torus-torus-14"
//! # kind = "map"
//! # file = "topography.npy"  # or .csv; relative to the case file
//! # spacing_mm = [0.002, 0.002]
//! # values = "height"        # "gap" (default) or "height" (combined topography)
//! # boundary = "periodic"    # "free" (default) or "periodic"
//!
//! [bem]                      # optional
//! cells = [64, 64]
//! tolerance = 1e-8           # relative residual
//! # extent_mm = [1.0, 0.5]   # fixed half-extents; adaptive when left out
//! # margin = 1.2             # adaptive domain over the contact's extent
//! # threads = 2              # FFT threads; all cores when left out
//! # max_iterations = 1000
//!
//! [body1]
//! e_mpa = 210000.0
//! nu = 0.3
//! [body2]
//! e_mpa = 210000.0
//! nu = 0.3
//!
//! [load]
//! force_n = 250.0            # or approach_mm
//! ```

use crate::pimp_case::{
    GapSetup, GeometrySpec, PimpCase, PimpReport, ReportMeta, gap_setup, hertz_echo, material,
    precheck, zone_warnings,
};
use kontakt::gap::GapMap;
use kontakt::halfspace::{Bem, BemOptions, BemSolution, Control};
use kontakt::{Error, Result};

use std::path::Path;

pub use crate::pimp_case::{BemSpec, SolverEcho};

/// A solved `bem` case: the JSON record and the full solution (fields for CSV and maps).
#[derive(Debug, Clone, PartialEq)]
pub struct BemOutcome {
    /// The JSON record (the PimP report's keys, `method = "bem"`).
    pub report: PimpReport,
    /// The solution with pressure, displacement and gap fields.
    pub solution: BemSolution,
}

/// Solve a `method = "bem"` case. Relative map paths are resolved against `base_dir`
/// (the case file's folder).
///
/// # Errors
/// Invalid input (named by its case-file key), bodies that do not touch, a contact that
/// reaches the border of a map or a fixed extent, and non-convergence.
pub fn run_bem_case(case: &PimpCase, base_dir: &Path) -> Result<BemOutcome> {
    crate::validity::checked(run_bem_case_unchecked(case, base_dir)?)
}

crate::validity::checked_report!(BemOutcome, report);

/// [`run_bem_case`] before the validity check of [`crate::validity::checked`].
pub(crate) fn run_bem_case_unchecked(case: &PimpCase, base_dir: &Path) -> Result<BemOutcome> {
    run(case, base_dir, None)
}

/// Solve a `method = "bem"` case of `[geometry] kind = "map"` on a map held in memory
/// (the Python package passes a NumPy array): `map` replaces the file, whose name only
/// labels the report; `spacing_mm` and `values` were applied when `map` was built.
///
/// # Errors
/// As [`run_bem_case`]; a geometry other than a map is refused (field `geometry.kind`).
pub fn run_bem_case_on_map(case: &PimpCase, map: GapMap) -> Result<BemOutcome> {
    if !matches!(case.geometry, GeometrySpec::Map { .. }) {
        return Err(Error::invalid(
            "geometry.kind",
            "not \"map\"",
            "\"map\" for a case solved on a map in memory",
        ));
    }
    crate::validity::checked(run(case, Path::new("."), Some(map))?)
}

fn run(case: &PimpCase, base_dir: &Path, given: Option<GapMap>) -> Result<BemOutcome> {
    if case.method != "bem" {
        return Err(Error::invalid(
            "method",
            &case.method,
            "\"bem\" for this schema",
        ));
    }
    if case.pimp.is_some() {
        return Err(Error::invalid(
            "pimp",
            "a [pimp] table",
            "no [pimp] table in a method = \"bem\" case (it holds PimP's options: use \
             method = \"pimp\", or [bem] for the half-space solver's)",
        ));
    }
    let m1 = material(&case.body1, "body1")?;
    let m2 = material(&case.body2, "body2")?;
    let spec = case.bem.unwrap_or_default();
    let options = BemOptions {
        cells: spec.cells,
        extent: spec.extent_mm,
        margin: spec.margin,
        tolerance: spec.tolerance,
        max_iterations: spec.max_iterations,
        threads: spec.threads,
    };
    let bem = Bem::new(m1, m2, options)
        .map_err(|e| {
            e.map_field(|f| match f {
                "extent[0]" => "bem.extent_mm[0]".into(),
                "extent[1]" => "bem.extent_mm[1]".into(),
                other => format!("bem.{other}"),
            })
        })?
        .with_estimate(kontakt::pimp::zone_estimate(m1, m2)?);
    let map_load = |e: Error| {
        e.map_field(|f| match f {
            "force" => "load.force_n".into(),
            "approach" => "load.approach_mm".into(),
            "cells" => "bem.cells".into(),
            "extent" => "bem.extent_mm".into(),
            "e_star" => "body1.e_mpa, body2.e_mpa".into(),
            "spacing[0]" => "geometry.spacing_mm[0]".into(),
            "spacing[1]" => "geometry.spacing_mm[1]".into(),
            other => other.into(),
        })
    };
    let load_error = || {
        Error::invalid(
            "load",
            "none or both of force_n and approach_mm",
            "exactly one of force_n or approach_mm (or neither for surfaces placed in contact)",
        )
    };
    let (label, solution, separation, rib_angle, curvature, boundary, (warnings, contacts)) =
        match &case.geometry {
            GeometrySpec::Map {
                file,
                spacing_mm,
                values,
                boundary,
            } => {
                let path = base_dir.join(file);
                let mut notes = Vec::new();
                let map = match given {
                    Some(map) => Ok(map),
                    None => crate::maps::read_gap_map(&path, *spacing_mm, *values, 1.0).map(|m| {
                        notes.extend(crate::maps::skipped_note("geometry.file", m.skipped_lines));
                        m.map
                    }),
                }
                .map_err(|e| {
                    e.map_field(|f| match f {
                        "spacing[0]" => "geometry.spacing_mm[0]".into(),
                        "spacing[1]" => "geometry.spacing_mm[1]".into(),
                        "gap_map.file" | "gap_map" => "geometry.file".into(),
                        other => other.into(),
                    })
                })?;
                let control = match (case.load.force_n, case.load.approach_mm) {
                    (Some(f), None) => Control::Force(f),
                    (None, Some(d)) => Control::Approach(d),
                    _ => return Err(load_error()),
                };
                let s = bem.solve_map(&map, control, *boundary).map_err(map_load)?;
                // A map's bodies are unknown: no size check.
                (
                    format!("gap map {file}"),
                    s,
                    None,
                    None,
                    None,
                    *boundary,
                    (notes, Vec::new()),
                )
            }
            g => {
                let GapSetup {
                    label,
                    source,
                    separation,
                    rib_angle,
                } = gap_setup(g)?;
                precheck(g, source.as_ref(), m1, m2, &case.load, separation)?;
                let s = match (case.load.force_n, case.load.approach_mm, separation) {
                    (Some(f), None, _) => bem.solve_force(source.as_ref(), f),
                    (None, Some(d), _) => bem.solve_approach(source.as_ref(), d),
                    (None, None, Some(sep)) if sep < 0.0 => {
                        bem.solve_approach(source.as_ref(), -sep)
                    }
                    (None, None, Some(sep)) => {
                        return Err(Error::Geometry {
                            field: "geometry".into(),
                            reason: format!(
                                "the bodies do not touch: separation = {sep:.6e} mm (give \
                             load.force_n or load.approach_mm to press them together)"
                            ),
                        });
                    }
                    _ => return Err(load_error()),
                }
                .map_err(map_load)?;
                let warnings = zone_warnings(g, source.as_ref(), &s)?;
                let k = source.curvature();
                (
                    label,
                    s,
                    separation,
                    rib_angle,
                    Some(k),
                    kontakt::halfspace::Boundary::Free,
                    warnings,
                )
            }
        };
    let report = PimpReport::assemble(
        ReportMeta {
            name: case.name.clone(),
            method: "bem",
            mode: None,
            geometry: label,
            e_star_mpa: bem.e_star(),
            relative_curvature_per_mm: curvature.map(|k| [k.a_coef, k.b_coef]),
            solver: Some(SolverEcho {
                converged: solution.status.converged(),
                residual: solution.status.residual,
                tolerance: spec.tolerance,
                operator_applications: solution.detail.report.applications,
                max_overlap_mm: solution.detail.report.max_overlap,
                boundary,
            }),
            separation_mm: separation,
            rib_angle_deg: rib_angle,
            hertz: curvature.and_then(|k| hertz_echo(k, m1, m2, solution.force)),
            grid_rounds: solution.domains,
            warnings,
            contacts,
        },
        &solution,
    );
    Ok(BemOutcome { report, solution })
}
