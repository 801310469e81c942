//! Gear-tooth deflection (Johnson 1982 Appendix 2): a hand-derived value and the exact
//! scaling laws. Derivation in docs/impact.md ("Gear teeth").

use kontakt::gear::{
    JOHNSON_BENDING_COEFFICIENT, bending_deflection, cantilever_bending_coefficient,
    contact_deflection, tooth_pair_deflection,
};
use kontakt::material::{ElasticMaterial, effective_modulus};
use kontakt::{Error, Result};
use std::f64::consts::PI;

fn field_of<T: std::fmt::Debug>(r: Result<T>) -> String {
    match r {
        Err(Error::InvalidInput { field, .. }) => field.into_owned(),
        other => panic!("expected InvalidInput, got {other:?}"),
    }
}

/// Steel pair (E = 210 GPa, nu = 0.3), module 4 mm, P' = 200 N/mm, by hand:
/// E* = 115 384.615 MPa, a = 2 sqrt(200 * 8 / (pi E*)) = 0.132 874 33 mm,
/// h = pi mm, 2 ln(h/a) = 6.326 18, minus nu/(1-nu) = 0.428 571,
/// delta_C = 2 * 200 * 0.91/(pi 210 000) * 5.897 61 = 3.253 920e-3 mm;
/// delta_B = 6 * 200 / E* = 1.04e-2 mm. Tolerance 1e-9 relative (the hand values are
/// given to 7 digits: 1e-6).
#[test]
fn hand_derived_tooth_pair() -> Result<()> {
    let s = ElasticMaterial::STEEL;
    let d = tooth_pair_deflection(200.0, 4.0, JOHNSON_BENDING_COEFFICIENT, &s, &s)?;
    assert!((d.half_width / 0.132_874_33 - 1.0).abs() < 1e-6);
    assert!(
        (d.contact / 3.253_920e-3 - 1.0).abs() < 1e-6,
        "{}",
        d.contact
    );
    assert!((d.bending / 1.04e-2 - 1.0).abs() < 1e-12);
    assert!((d.total - d.bending - d.contact).abs() < 1e-18);
    // Johnson's closed form for one nu: P'/(pi E*) [ln(m E*/P') + 2 ln(pi/8 sqrt(pi/2)) - nu/(1-nu)]
    let e_star = effective_modulus(&s, &s);
    let c = 2.0 * (PI / 8.0 * (PI / 2.0).sqrt()).ln() - 0.3 / 0.7;
    assert!((c + 1.846).abs() < 1e-3); // Johnson's "- 1.8"
    let closed = 200.0 / (PI * e_star) * ((4.0 * e_star / 200.0).ln() + c);
    assert!((d.contact / closed - 1.0).abs() < 1e-12);
    // "The contact deflexion is roughly one-third of the bending deflexion"
    assert!((d.contact / d.bending - 0.313).abs() < 1e-3);
    Ok(())
}

/// Exact scaling laws: bending linear in load (1e-14); contact deflection
/// delta_C(lambda P)/lambda - delta_C(P) = -(P/(pi E*)) ln(lambda) (both bodies, one nu),
/// doubling h adds 2 P ln 2/(pi E*) (1e-12 relative); independent of the module at fixed
/// m E*/P' in units of P'/E* (bending and contact, 1e-12).
#[test]
fn scaling_laws() -> Result<()> {
    let s = ElasticMaterial::STEEL;
    let e_star = effective_modulus(&s, &s);
    let k = JOHNSON_BENDING_COEFFICIENT;
    let b1 = bending_deflection(100.0, e_star, k)?;
    let b3 = bending_deflection(300.0, e_star, k)?;
    assert!((b3 / b1 - 3.0).abs() < 1e-14);
    let p = 150.0;
    let (r, h) = (8.0, 3.0);
    let d1 = contact_deflection(p, r, h, &s, &s)?;
    for lambda in [2.0, 5.0, 0.3] {
        let dl = contact_deflection(lambda * p, r, h, &s, &s)?;
        let expect = -(p / (PI * e_star)) * f64::ln(lambda);
        assert!(
            ((dl / lambda - d1) / expect - 1.0).abs() < 1e-10,
            "{lambda}"
        );
    }
    let d2h = contact_deflection(p, r, 2.0 * h, &s, &s)?;
    assert!(((d2h - d1) / (2.0 * p * 2f64.ln() / (PI * e_star)) - 1.0).abs() < 1e-10);
    // module independence at fixed m E*/P'
    let a = tooth_pair_deflection(100.0, 2.0, k, &s, &s)?;
    let b = tooth_pair_deflection(400.0, 8.0, k, &s, &s)?;
    assert!((b.contact / 400.0 - a.contact / 100.0).abs() < 1e-12 * a.contact / 100.0);
    assert!((b.bending / 400.0 - a.bending / 100.0).abs() < 1e-12 * a.bending / 100.0);
    Ok(())
}

/// A rigid partner carries no contact deflection of its own; two different materials add
/// their own terms.
#[test]
fn materials_add_their_own_terms() -> Result<()> {
    let s = ElasticMaterial::STEEL;
    let al = ElasticMaterial::new(70_000.0, 0.33)?;
    let rig = ElasticMaterial::RIGID;
    let (p, r, h) = (120.0, 6.0, 2.5);
    // each body's term with the common semi-width of the pair
    let e_star = effective_modulus(&s, &al);
    let a = 2.0 * (p * r / (PI * e_star)).sqrt();
    let term =
        |e: f64, nu: f64| p * (1.0 - nu * nu) / (PI * e) * (2.0 * (h / a).ln() - nu / (1.0 - nu));
    let both = contact_deflection(p, r, h, &s, &al)?;
    assert!((both / (term(210_000.0, 0.3) + term(70_000.0, 0.33)) - 1.0).abs() < 1e-12);
    let e_r = effective_modulus(&s, &rig);
    let a_r = 2.0 * (p * r / (PI * e_r)).sqrt();
    let one = contact_deflection(p, r, h, &s, &rig)?;
    let expect = p * 0.91 / (PI * 210_000.0) * (2.0 * (h / a_r).ln() - 0.3 / 0.7);
    assert!((one / expect - 1.0).abs() < 1e-12);
    Ok(())
}

/// The cantilever constant K = 4 cos^2(phi) (l/t)^3: cubic in the arm, by hand for a
/// standard tooth (l = 1.25 m, t = pi m / 2, phi = 20 deg): K = 1.7799.
#[test]
fn cantilever_constant() -> Result<()> {
    let k1 = cantilever_bending_coefficient(1.0, 1.0, 0.0)?;
    let k2 = cantilever_bending_coefficient(2.0, 1.0, 0.0)?;
    assert_eq!(k1, 4.0);
    assert!((k2 / k1 - 8.0).abs() < 1e-14);
    let std = cantilever_bending_coefficient(1.25, PI / 2.0, 20f64.to_radians())?;
    assert!((std - 1.779_926).abs() < 1e-6, "{std}");
    Ok(())
}

#[test]
fn bad_input_is_named() {
    let s = ElasticMaterial::STEEL;
    let r = ElasticMaterial::RIGID;
    assert_eq!(field_of(bending_deflection(0.0, 1e5, 6.0)), "line_load");
    assert_eq!(field_of(bending_deflection(1.0, f64::NAN, 6.0)), "e_star");
    assert_eq!(
        field_of(bending_deflection(1.0, 1e5, -6.0)),
        "bending_coefficient"
    );
    assert_eq!(
        field_of(contact_deflection(-1.0, 8.0, 3.0, &s, &s)),
        "line_load"
    );
    assert_eq!(
        field_of(contact_deflection(1.0, 0.0, 3.0, &s, &s)),
        "relative_radius"
    );
    assert_eq!(
        field_of(contact_deflection(1.0, 8.0, f64::NAN, &s, &s)),
        "datum_depth"
    );
    assert_eq!(
        field_of(contact_deflection(1.0, 8.0, 3.0, &r, &r)),
        "materials"
    );
    // a contact wider than the datum depth
    assert_eq!(
        field_of(contact_deflection(1e6, 8.0, 0.1, &s, &s)),
        "line_load"
    );
    assert_eq!(
        field_of(tooth_pair_deflection(200.0, 0.0, 6.0, &s, &s)),
        "module"
    );
    assert_eq!(
        field_of(cantilever_bending_coefficient(0.0, 1.0, 0.3)),
        "arm"
    );
    assert_eq!(
        field_of(cantilever_bending_coefficient(1.0, f64::NAN, 0.3)),
        "thickness"
    );
    for phi in [-0.1, std::f64::consts::FRAC_PI_2, f64::NAN] {
        assert_eq!(
            field_of(cantilever_bending_coefficient(1.0, 1.0, phi)),
            "pressure_angle"
        );
    }
}
