//! The exact elliptical Hertz solution against independent golden values.
//!
//! `tests/data/hertz_elliptic_mpmath.json` is produced by `tools/reference/hertz_mpmath.py`
//! with mpmath at 70 (checked at 100) significant digits from Johnson (1982) eqs (51), (56),
//! (57) in Legendre form, root-finding the eccentricity directly; kontakt uses Carlson's
//! symmetric integrals and a secant iteration on ln(b/a), so the two share no code and no
//! formulation. See `docs/hertz_reference.md` for how to regenerate the data.
//!
//! Every quantity must agree to 1e-9 relative. The file's header records that rounding the
//! inputs to f64 changes the exact answer by less than 4e-16, so the tolerance measures the
//! library, not the data.

#![allow(clippy::unwrap_used)] // test helpers: a panic is a test failure with its message

use kontakt::hertz::{HertzPointContact, PointGeometry};
use kontakt::material::ElasticMaterial;
use serde::Deserialize;
use std::collections::BTreeMap;

/// Relative tolerance for every compared quantity.
const TOL: f64 = 1e-9;

#[derive(Debug, Deserialize)]
struct File {
    header: BTreeMap<String, serde_json::Value>,
    cases: Vec<Case>,
}

#[derive(Debug, Deserialize)]
struct Material {
    youngs_modulus: String,
    poisson_ratio: String,
}

#[derive(Debug, Deserialize)]
struct Case {
    id: String,
    family: String,
    body1_radii: [String; 2],
    body2_radii: [String; 2],
    angle_deg: String,
    body1: Material,
    body2: Material,
    force: String,
    expected: BTreeMap<String, String>,
}

fn num(s: &str) -> f64 {
    s.parse::<f64>()
        .unwrap_or_else(|e| panic!("cannot parse {s:?} as f64: {e}"))
}

fn load() -> File {
    let path = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/tests/data/hertz_elliptic_mpmath.json"
    );
    let text = std::fs::read_to_string(path).unwrap_or_else(|e| panic!("{path}: {e}"));
    serde_json::from_str(&text).unwrap_or_else(|e| panic!("{path}: {e}"))
}

fn rel(ours: f64, reference: f64) -> f64 {
    ((ours - reference) / reference).abs()
}

impl Case {
    fn expected(&self, key: &str) -> f64 {
        num(self
            .expected
            .get(key)
            .unwrap_or_else(|| panic!("{}: no expected {key}", self.id)))
    }

    /// Plan the contact as a user would: f64 inputs, angle converted with `to_radians`.
    fn contact(&self) -> Result<HertzPointContact, String> {
        let radii = |r: &[String; 2]| [num(&r[0]), num(&r[1])];
        let material = |m: &Material| {
            ElasticMaterial::new(num(&m.youngs_modulus), num(&m.poisson_ratio))
                .map_err(|e| format!("{}: ElasticMaterial::new: {e}", self.id))
        };
        let geometry = PointGeometry::new(
            radii(&self.body1_radii),
            radii(&self.body2_radii),
            num(&self.angle_deg).to_radians(),
        )
        .map_err(|e| format!("{}: PointGeometry::new: {e}", self.id))?;
        HertzPointContact::new(geometry, material(&self.body1)?, material(&self.body2)?)
            .map_err(|e| format!("{}: HertzPointContact::new: {e}", self.id))
    }
}

/// Largest relative error per quantity over all cases, with the case that produced it.
#[derive(Default)]
struct Worst(BTreeMap<&'static str, (f64, String)>);

impl Worst {
    fn record(&mut self, what: &'static str, err: f64, id: &str) {
        let e = self.0.entry(what).or_insert((0.0, String::new()));
        if err > e.0 || e.1.is_empty() {
            *e = (err, id.to_string());
        }
    }
}

#[test]
fn golden_file_is_complete() {
    let f = load();
    for key in ["source", "method", "equations", "mpmath_version", "date"] {
        assert!(f.header.contains_key(key), "header lacks {key}");
    }
    assert_eq!(
        f.header["case_count"].as_u64(),
        Some(f.cases.len() as u64),
        "header case_count disagrees with the number of cases"
    );
    assert!(f.cases.len() >= 140, "only {} cases", f.cases.len());
    // The sweep must reach both ends of the shape range: the circle and b/a ~ 1e-4.
    let ratios: Vec<f64> = f.cases.iter().map(|c| c.expected("B_over_A")).collect();
    let shapes: Vec<f64> = f.cases.iter().map(|c| c.expected("b_over_a")).collect();
    assert!(ratios.contains(&1.0), "no circular case");
    assert!(ratios.iter().cloned().fold(0.0, f64::max) >= 1e7);
    assert!(shapes.iter().cloned().fold(1.0, f64::min) < 1.1e-4);
    for family in [
        "crossed cylinders",
        "groove",
        "general",
        "ellipsoid_on_flat",
    ] {
        assert!(
            f.cases.iter().any(|c| c.family.contains(family)),
            "no {family} case"
        );
    }
    // Every case carries every quantity the comparison needs.
    for c in &f.cases {
        for key in [
            "a",
            "b",
            "p0",
            "delta",
            "area",
            "stiffness",
            "B_over_A",
            "b_over_a",
            "e_star",
            "A",
            "B",
        ] {
            assert!(c.expected.contains_key(key), "{}: lacks {key}", c.id);
        }
    }
}

#[test]
fn exact_solution_matches_mpmath_to_1e_9() {
    let f = load();
    let mut worst = Worst::default();
    let mut failures = Vec::new();
    for c in &f.cases {
        let contact = match c.contact() {
            Ok(contact) => contact,
            Err(e) => {
                failures.push(e);
                continue;
            }
        };
        let force = num(&c.force);
        let s = contact
            .solve_force(force)
            .unwrap_or_else(|e| panic!("{}: {e}", c.id));
        let delta_ref = c.expected("delta");
        let k = contact.geometry().curvature();
        let checks: [(&'static str, f64, f64); 14] = [
            ("a", s.semi_axes[0], c.expected("a")),
            ("b", s.semi_axes[1], c.expected("b")),
            ("p0", s.max_pressure, c.expected("p0")),
            (
                "mean_pressure",
                s.mean_pressure,
                c.expected("mean_pressure"),
            ),
            ("delta", s.approach, delta_ref),
            ("area", s.contact_area, c.expected("area")),
            ("stiffness", s.stiffness, c.expected("stiffness")),
            ("b_over_a", contact.axis_ratio(), c.expected("b_over_a")),
            ("B_over_A", k.ratio(), c.expected("B_over_A")),
            ("A", k.a_coef, c.expected("A")),
            ("B", k.b_coef, c.expected("B")),
            ("e_star", contact.e_star(), c.expected("e_star")),
            (
                "force_from_approach(delta_ref)",
                contact
                    .force_from_approach(delta_ref)
                    .unwrap_or_else(|e| panic!("{}: {e}", c.id)),
                force,
            ),
            (
                "approach_from_force(F)",
                contact
                    .approach_from_force(force)
                    .unwrap_or_else(|e| panic!("{}: {e}", c.id)),
                delta_ref,
            ),
        ];
        for (what, ours, reference) in checks {
            let err = rel(ours, reference);
            worst.record(what, err, &c.id);
            if err.is_nan() || err > TOL {
                failures.push(format!(
                    "{}: {what} = {ours:.17e}, reference {reference:.17e}, relative error {err:.3e}",
                    c.id
                ));
            }
        }
        // solve_approach at the reference approach gives back the reference state.
        let sa = contact
            .solve_approach(delta_ref)
            .unwrap_or_else(|e| panic!("{}: {e}", c.id));
        for (what, ours, reference) in [
            ("solve_approach.force", sa.force, force),
            ("solve_approach.a", sa.semi_axes[0], c.expected("a")),
            ("solve_approach.p0", sa.max_pressure, c.expected("p0")),
        ] {
            let err = rel(ours, reference);
            worst.record(what, err, &c.id);
            if err.is_nan() || err > TOL {
                failures.push(format!(
                    "{}: {what} = {ours:.17e}, reference {reference:.17e}, relative error {err:.3e}",
                    c.id
                ));
            }
        }
    }
    println!(
        "largest relative errors over {} cases (tolerance {TOL:e}):",
        f.cases.len()
    );
    for (what, (err, id)) in &worst.0 {
        println!("  {what:32} {err:.3e}  ({id})");
    }
    assert!(
        failures.is_empty(),
        "{} comparisons exceed {TOL:e}:\n{}",
        failures.len(),
        failures.join("\n")
    );
}

/// The comparison is not vacuous: a solution perturbed by 1e-8 relative must fail it.
#[test]
fn tolerance_detects_a_1e_8_error() {
    let f = load();
    let c = f
        .cases
        .iter()
        .find(|c| c.id.starts_with("ratio_1e7_"))
        .expect("a B/A = 1e7 case");
    let s = c
        .contact()
        .expect("plans")
        .solve_force(num(&c.force))
        .expect("solves");
    assert!(rel(s.semi_axes[1], c.expected("b")) <= TOL);
    assert!(rel(s.semi_axes[1] * (1.0 + 1e-8), c.expected("b")) > TOL);
}
