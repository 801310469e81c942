//! Published worked Hertz examples, each to the precision its source prints.
//!
//! `tests/data/published_examples.json` holds, per example, the full citation, the inputs,
//! every printed value exactly as printed, and the tolerance used for it:
//! `|ours - printed| <= rounding_abs + method_rel * |printed|`. `rounding_abs` is half a unit
//! in the last printed digit; `method_rel` is non-zero only where the source used an
//! approximate method (curve fits, table interpolation), and the file says why. The table of
//! our values against the printed ones is in `docs/hertz_reference.md`.

#![allow(clippy::unwrap_used)] // test helpers: a panic is a test failure with its message

use kontakt::hertz::{HertzPointContact, HertzPointSolution, PointGeometry};
use kontakt::material::ElasticMaterial;
use serde::Deserialize;
use std::collections::BTreeMap;

#[derive(Debug, Deserialize)]
struct File {
    header: BTreeMap<String, serde_json::Value>,
    examples: Vec<Example>,
}

#[derive(Debug, Deserialize)]
struct Material {
    youngs_modulus: String,
    poisson_ratio: String,
}

#[derive(Debug, Deserialize)]
struct Inputs {
    body1_radii: [String; 2],
    body2_radii: [String; 2],
    angle_deg: String,
    body1: Material,
    body2: Material,
    force: Option<String>,
    approach: Option<String>,
}

#[derive(Debug, Deserialize)]
struct Printed {
    quantity: String,
    /// The value as printed (absent when the source prints a formula instead).
    printed: Option<String>,
    /// A printed formula, evaluated here (see `formula_value`).
    formula: Option<String>,
    unit: String,
    scale: f64,
    rounding_abs: f64,
    method_rel: f64,
    why: String,
}

#[derive(Debug, Deserialize)]
struct Example {
    id: String,
    citation: String,
    retrieved_from: String,
    source_method: String,
    inputs: Inputs,
    printed: Vec<Printed>,
}

fn num(s: &str) -> f64 {
    s.parse::<f64>()
        .unwrap_or_else(|e| panic!("cannot parse {s:?} as f64: {e}"))
}

fn load() -> File {
    let path = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/tests/data/published_examples.json"
    );
    let text = std::fs::read_to_string(path).unwrap_or_else(|e| panic!("{path}: {e}"));
    serde_json::from_str(&text).unwrap_or_else(|e| panic!("{path}: {e}"))
}

/// The example's contact and its solution at the given force or approach.
fn solve(
    ex: &Example,
) -> Result<(HertzPointContact, HertzPointSolution, [ElasticMaterial; 2]), String> {
    let i = &ex.inputs;
    let radii = |r: &[String; 2]| [num(&r[0]), num(&r[1])];
    let material = |m: &Material| {
        ElasticMaterial::new(num(&m.youngs_modulus), num(&m.poisson_ratio))
            .map_err(|e| format!("{}: ElasticMaterial::new: {e}", ex.id))
    };
    let (m1, m2) = (material(&i.body1)?, material(&i.body2)?);
    let geometry = PointGeometry::new(
        radii(&i.body1_radii),
        radii(&i.body2_radii),
        num(&i.angle_deg).to_radians(),
    )
    .map_err(|e| format!("{}: PointGeometry::new: {e}", ex.id))?;
    let contact = HertzPointContact::new(geometry, m1, m2)
        .map_err(|e| format!("{}: HertzPointContact::new: {e}", ex.id))?;
    let s = match (&i.force, &i.approach) {
        (Some(f), None) => contact.solve_force(num(f)),
        (None, Some(d)) => contact.solve_approach(num(d)),
        _ => panic!("{}: give exactly one of force and approach", ex.id),
    }
    .map_err(|e| format!("{}: solve: {e}", ex.id))?;
    Ok((contact, s, [m1, m2]))
}

/// Our value of `quantity` in kontakt units (mm, N, MPa).
fn ours(
    quantity: &str,
    contact: &HertzPointContact,
    s: &HertzPointSolution,
    m: &[ElasticMaterial; 2],
) -> f64 {
    let k = contact.geometry().curvature();
    let (sum, diff) = (k.a_coef + k.b_coef, k.b_coef - k.a_coef);
    // Norton's length scale (3 F (m1 + m2) / (4 A_N))^(1/3) with A_N = A + B.
    let norton_scale = (3.0 * s.force / (4.0 * contact.e_star() * sum)).cbrt();
    match quantity {
        "a" | "a_from_approach" => s.semi_axes[0],
        "b" => s.semi_axes[1],
        "area" => s.contact_area,
        "p0" | "p0_from_approach" => s.max_pressure,
        "pm" => s.mean_pressure,
        "delta" => s.approach,
        "half_curvature_sum" => sum,
        "half_curvature_difference" => diff,
        "norton_angle_deg" => (diff / sum).acos().to_degrees(),
        "compliance_body1" => m[0].compliance(),
        "norton_ka" => s.semi_axes[0] / norton_scale,
        "norton_kb" => s.semi_axes[1] / norton_scale,
        "inv_rx" => 2.0 * k.a_coef,
        "inv_ry" => 2.0 * k.b_coef,
        "inv_r_reduced" => 1.0 / k.effective_radius(),
        "e_prime" => 2.0 * contact.e_star(),
        other => panic!("unknown quantity {other:?}"),
    }
}

/// A printed formula evaluated from the example's inputs (only the code_aster reference).
fn formula_value(ex: &Example, formula: &str) -> f64 {
    let i = &ex.inputs;
    let e = num(&i.body1.youngs_modulus);
    let nu = num(&i.body1.poisson_ratio);
    let r = num(&i.body1_radii[0]);
    let h = num(i.approach.as_deref().expect("an approach"));
    match formula {
        "E/(pi*(1-nu^2))*sqrt(2*h/R)" => {
            e / (std::f64::consts::PI * (1.0 - nu * nu)) * (2.0 * h / r).sqrt()
        }
        "sqrt(R*h/2)" => (r * h / 2.0).sqrt(),
        other => panic!("{}: unknown formula {other:?}", ex.id),
    }
}

#[test]
fn every_example_is_cited_and_has_a_failable_tolerance() {
    let f = load();
    assert!(f.header.contains_key("tolerance_rule"));
    assert!(f.examples.len() >= 2, "at least two published examples");
    for ex in &f.examples {
        assert!(ex.citation.len() > 40, "{}: citation too short", ex.id);
        assert!(ex.retrieved_from.starts_with("http"), "{}", ex.id);
        assert!(!ex.source_method.is_empty(), "{}", ex.id);
        assert!(!ex.printed.is_empty(), "{}: no printed values", ex.id);
        for p in &ex.printed {
            assert!(
                !p.why.is_empty() && !p.unit.is_empty(),
                "{}: {}",
                ex.id,
                p.quantity
            );
            assert!(
                p.printed.is_some() != p.formula.is_some(),
                "{}: {} needs exactly one of printed/formula",
                ex.id,
                p.quantity
            );
            // No comparison may be looser than 2 % plus rounding: it must be able to fail.
            assert!(p.method_rel <= 0.02, "{}: {} method_rel", ex.id, p.quantity);
            if let Some(v) = &p.printed {
                let v = num(v);
                assert!(
                    p.rounding_abs <= 0.05 * v.abs(),
                    "{}: {} rounding tolerance is more than 5 % of the value",
                    ex.id,
                    p.quantity
                );
            }
        }
    }
}

#[test]
fn published_examples_agree_to_printed_precision() {
    let f = load();
    let mut failures = Vec::new();
    println!(
        "{:40} {:26} {:>14} {:>16} {:>10} {:>10}",
        "example", "quantity", "printed", "ours", "rel.diff", "allowed"
    );
    for ex in &f.examples {
        let (contact, s, m) = match solve(ex) {
            Ok(v) => v,
            Err(e) => {
                failures.push(e);
                continue;
            }
        };
        for p in &ex.printed {
            let reference = match (&p.printed, &p.formula) {
                (Some(v), None) => num(v),
                (None, Some(fm)) => formula_value(ex, fm),
                _ => unreachable!("checked by the other test"),
            };
            let value = ours(&p.quantity, &contact, &s, &m) * p.scale;
            let allowed = p.rounding_abs + p.method_rel * reference.abs();
            let diff = (value - reference).abs();
            println!(
                "{:40} {:26} {:>14} {:>16.8e} {:>10.2e} {:>10.2e}",
                ex.id,
                p.quantity,
                p.printed.as_deref().unwrap_or("(formula)"),
                value,
                diff / reference.abs(),
                allowed / reference.abs()
            );
            if diff.is_nan() || diff > allowed {
                failures.push(format!(
                    "{}: {} = {value:.8e} {}, printed {reference:.8e}, |diff| {diff:.3e} > allowed {allowed:.3e} ({})",
                    ex.id, p.quantity, p.unit, p.why
                ));
            }
        }
    }
    assert!(
        failures.is_empty(),
        "{} published values not matched:\n{}",
        failures.len(),
        failures.join("\n")
    );
}
