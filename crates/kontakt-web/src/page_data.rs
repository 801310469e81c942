//! What the pages draw beside the report: the stresses along the load axis of a Hertz
//! contact and the pressure field of a PimP or half-space solution. The report (what
//! `kontakt solve --json` prints) carries neither: the stresses only as their peaks, the
//! field only in `--csv` and `--map`. Both come from the library's own functions on the
//! solved outcome ([`kontakt::hertz::subsurface`], [`kontakt_case::Outcome::fields`]);
//! nothing is computed here that the CLI does not compute.

use kontakt::hertz::subsurface::{self, AxisStress};
use kontakt_case::Outcome;
use kontakt_case::hertz_case::{ContactKind, ContactReport};
use serde_json::{Map, Value, json};

/// Depth points of the stress profile, from the surface to [`DEPTH_SPAN`] minor semi-axes.
pub const DEPTH_POINTS: usize = 121;
/// Depth of the profile's last point in minor semi-axes (half-widths): the shear peak lies
/// at 0.47-0.79 of them (Johnson 1985 §3.5, §4.2).
pub const DEPTH_SPAN: f64 = 3.0;

/// The members the API adds to a solve's answer beside `report` and `warnings`:
/// `axis_stress` for a Hertz case, `fields` for PimP, half-space and rough cases (the
/// pressure only: the displacement and the gap, which is infinite where the bodies cannot
/// meet, stay in the CLI's CSV). Empty for the other methods.
pub fn extras(outcome: &Outcome) -> Map<String, Value> {
    let mut out = Map::new();
    if let Outcome::Hertz(report) = outcome
        && let Some(profile) = axis_stress(report)
    {
        out.insert("axis_stress".into(), profile);
    }
    let fields: Vec<Value> = outcome
        .fields()
        .into_iter()
        .filter(|f| f.name == "pressure")
        .map(|f| {
            let g = f.grid;
            let (nx, ny) = (g.nx(), g.ny());
            json!({
                "name": f.name,
                "unit": f.unit,
                "cells": [nx, ny],
                "x_range_mm": [g.x(0) - 0.5 * g.dx(), g.x(nx - 1) + 0.5 * g.dx()],
                "y_range_mm": [g.y(0) - 0.5 * g.dy(), g.y(ny - 1) + 0.5 * g.dy()],
                "values": f.values,
            })
        })
        .collect();
    if !fields.is_empty() {
        out.insert("fields".into(), Value::Array(fields));
    }
    out
}

/// The stresses on the load axis below the contact centre \[MPa\] against the depth \[mm\],
/// for each body's Poisson's ratio (one entry when they are equal): `{"depth_mm": [...],
/// "bodies": [{"body", "nu", "sigma_x_mpa", "sigma_y_mpa", "sigma_z_mpa",
/// "max_shear_mpa", "von_mises_mpa"}]}`. Point contacts with the elliptical (circular)
/// solution, line contacts in plane strain: [`subsurface::axis_stress_elliptical`],
/// [`subsurface::axis_stress_circular`], [`subsurface::axis_stress_line`]. None when the
/// report has no positive pressure (it always has after a solve).
pub fn axis_stress(report: &ContactReport) -> Option<Value> {
    let [a, b] = report.semi_axes_mm;
    let p0 = report.max_pressure_mpa;
    let (major, minor) = (a.max(b), a.min(b));
    if !(p0 > 0.0 && minor > 0.0 && major.is_finite()) {
        return None;
    }
    let depth: Vec<f64> = (0..DEPTH_POINTS)
        .map(|i| DEPTH_SPAN * minor * i as f64 / (DEPTH_POINTS - 1) as f64)
        .collect();
    let (nu1, nu2) = (report.inputs.nu1, report.inputs.nu2);
    let bodies: Vec<(usize, f64)> = if nu1 == nu2 {
        vec![(1, nu1)]
    } else {
        vec![(1, nu1), (2, nu2)]
    };
    let mut entries = Vec::new();
    for (body, nu) in bodies {
        let at = |z: f64| -> kontakt::Result<AxisStress> {
            match report.kind {
                ContactKind::Line => subsurface::axis_stress_line(p0, minor, nu, z),
                ContactKind::Point if major - minor <= 1e-12 * major => {
                    subsurface::axis_stress_circular(p0, major, nu, z)
                }
                ContactKind::Point => subsurface::axis_stress_elliptical(p0, major, minor, nu, z),
            }
        };
        let stresses: Vec<AxisStress> = depth
            .iter()
            .map(|&z| at(z))
            .collect::<Result<_, _>>()
            .ok()?;
        let column = |f: fn(&AxisStress) -> f64| stresses.iter().map(f).collect::<Vec<f64>>();
        entries.push(json!({
            "body": body,
            "nu": nu,
            "sigma_x_mpa": column(|s| s.sigma_x),
            "sigma_y_mpa": column(|s| s.sigma_y),
            "sigma_z_mpa": column(|s| s.sigma_z),
            "max_shear_mpa": column(|s| s.max_shear),
            "von_mises_mpa": column(|s| s.von_mises),
        }));
    }
    Some(json!({ "depth_mm": depth, "bodies": entries }))
}

#[cfg(test)]
mod tests {
    #![allow(clippy::unwrap_used, clippy::expect_used)] // a panic is the test's failure
    use super::*;
    use std::path::Path;

    fn run(text: &str) -> Outcome {
        kontakt_case::Case::from_toml_str(text)
            .unwrap()
            .run(Path::new("."))
            .unwrap()
    }

    fn largest(v: &Value) -> f64 {
        v.as_array()
            .unwrap()
            .iter()
            .map(|x| x.as_f64().unwrap())
            .fold(f64::MIN, f64::max)
    }

    const BALL: &str = "method = \"hertz\"\n[contact]\nkind = \"point\"\n[body1]\nradii_mm = [6.35, 6.35]\ne_mpa = 210000.0\nnu = 0.3\n[body2]\nradii_mm = [inf, inf]\ne_mpa = 210000.0\nnu = 0.3\n[load]\nforce_n = 100.0\n";

    /// The profile's peaks are the report's (found by the library's own peak search): on
    /// a 121-point depth grid the sampled maximum lies within 0.1 % below the true one, and
    /// the circular contact starts at sigma_z = -p0 on the surface (Johnson 1985 eq. 3.45).
    #[test]
    fn profile_peaks_are_the_reports() {
        for (text, body2_nu) in [
            (BALL.to_string(), None),
            (
                BALL.replace("[inf, inf]", "[inf, -40.0]").replacen(
                    "nu = 0.3\n[load]",
                    "nu = 0.25\n[load]",
                    1,
                ),
                Some(0.25),
            ),
            (
                BALL.replace("kind = \"point\"", "kind = \"line\"\nlength_mm = 10.0")
                    .replace("[6.35, 6.35]", "[6.35]")
                    .replace("[inf, inf]", "[inf]"),
                None,
            ),
        ] {
            let outcome = run(&text);
            let Outcome::Hertz(report) = &outcome else {
                panic!()
            };
            let x = extras(&outcome);
            let p = &x["axis_stress"];
            let bodies = p["bodies"].as_array().unwrap();
            assert_eq!(bodies.len(), if body2_nu.is_some() { 2 } else { 1 });
            let shear = bodies
                .iter()
                .map(|b| largest(&b["max_shear_mpa"]))
                .fold(f64::MIN, f64::max);
            let mises = bodies
                .iter()
                .map(|b| largest(&b["von_mises_mpa"]))
                .fold(f64::MIN, f64::max);
            let want = report.max_shear_stress_mpa;
            assert!(
                shear <= want * (1.0 + 1e-12) && shear > want * 0.999,
                "{shear} vs {want}"
            );
            let want = report.max_von_mises_stress_mpa;
            assert!(
                mises <= want * (1.0 + 1e-12) && mises > want * 0.999,
                "{mises} vs {want}"
            );
            let sz0 = bodies[0]["sigma_z_mpa"][0].as_f64().unwrap();
            assert!(
                (sz0 + report.max_pressure_mpa).abs() < 1e-9 * report.max_pressure_mpa,
                "{sz0}"
            );
            assert!(x.get("fields").is_none());
        }
    }

    /// A PimP solution's pressure field: its cells and ranges are the report's grid, its
    /// largest value the report's maximum pressure.
    #[test]
    fn pimp_field_is_the_reports_grid() {
        let text = std::fs::read_to_string(concat!(
            env!("CARGO_MANIFEST_DIR"),
            "/../../examples/roller_rib_torus_torus.toml"
        ))
        .unwrap();
        let outcome = run(&text);
        let Outcome::Pimp(o) = &outcome else { panic!() };
        let x = extras(&outcome);
        let f = &x["fields"][0];
        let report = serde_json::to_value(&o.report).unwrap();
        assert_eq!(f["cells"], report["grid"]["cells"]);
        for k in ["x_range_mm", "y_range_mm"] {
            for i in 0..2 {
                let (a, b) = (
                    f[k][i].as_f64().unwrap(),
                    report["grid"][k][i].as_f64().unwrap(),
                );
                assert!((a - b).abs() < 1e-12, "{k}: {a} vs {b}");
            }
        }
        assert_eq!(f["values"].as_array().unwrap().len(), 64 * 64);
        assert!(
            (largest(&f["values"]) - o.report.max_pressure_mpa).abs()
                < 1e-9 * o.report.max_pressure_mpa
        );
        assert!(x.get("axis_stress").is_none());
    }
}
