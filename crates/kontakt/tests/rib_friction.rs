#![allow(clippy::unwrap_used)]
//! Bearing level (issue 11, items 4-5): the rib load from the roller's equilibrium, the exact
//! rib torque for constant μ against Aihara's (1987) e μ cos β F_a, the centrifugal term,
//! the integrated field against the point formula, speed scaling, and bad input.
//! Units: mm, N, MPa, rad/s; torque N·mm, power W.

use kontakt::bearing::{
    Operating, PressureModel, RibFrictionModel, RollerRibSpec, RollerSet, TaperedKinematics,
    roller_loads,
};
use kontakt::friction::FrictionLaw;
use nalgebra::{Point3, Vector3};

fn exact_coulomb(mu: f64) -> FrictionLaw {
    FrictionLaw {
        regularisation_speed: 0.0,
        ..FrictionLaw::coulomb(mu).unwrap()
    }
}

/// Pure axial load, constant μ, a point contact at height e with the rib normal along the
/// roller axis: the power balance gives M = Z μ Q_f |ω_rel| e / ω_i, and with
/// Q_f = 2 Q_e sin β (equilibrium) and |ω_rel| = ω_i sin α_o / sin 2β this is exactly
/// μ e F_a / cos β (1e-12). Aihara's (1987) μ e cos β F_a differs by the factor cos² β:
/// relative difference sin² β (1e-12), i.e. the two agree to second order in β
/// (difference / β² → 1 as β → 0, checked at β = 4°, 2°, 1°, 0.5° within β²/3 + 1e-9).
#[test]
fn rib_torque_for_constant_mu_is_mu_e_fa_over_cos_beta() {
    let (mu, e, f_a, z) = (0.1, 2.0, 8000.0, 17usize);
    let mut last = f64::NAN;
    for beta_deg in [4.0f64, 2.0, 1.0, 0.5] {
        let beta = beta_deg.to_radians();
        let k =
            TaperedKinematics::new(20f64.to_radians(), beta, Point3::origin(), 80.0, 150.0, 0.0)
                .unwrap();
        let e_r = k.directions(0.0).roller_axis;
        let loads = roller_loads(&k, &(-e_r), f_a, z, 0.0).unwrap();
        assert!((loads.rib - 2.0 * loads.outer_raceway * beta.sin()).abs() < 1e-12 * loads.rib);
        assert!((loads.inner_raceway - loads.outer_raceway).abs() < 1e-12 * loads.rib);
        let torque = z as f64 * mu * loads.rib * k.relative_speed.abs() * e / k.inner_speed;
        let exact = mu * e * f_a / beta.cos();
        let aihara = mu * e * beta.cos() * f_a;
        let rel = (exact - aihara) / exact;
        println!(
            "beta = {beta_deg}°: M = {torque:.6} N·mm, mu e Fa / cos b = {exact:.6}, \
             Aihara {aihara:.6}, (exact - Aihara)/exact = {rel:.3e}, / beta² = {:.6}",
            rel / (beta * beta)
        );
        assert!((torque - exact).abs() < 1e-12 * exact);
        assert!((rel - beta.sin().powi(2)).abs() < 1e-12);
        assert!((rel / (beta * beta) - 1.0).abs() < beta * beta / 3.0 + 1e-9);
        last = rel;
    }
    assert!(last < 1e-4);
}

/// The centrifugal force: with the rib normal along the roller axis the equilibrium gives
/// Q_f = 2 Q_e sin β + F_c sin α_i / cos β and Q_i = Q_e − F_c cos α_m / cos β
/// (1e-12), and in the model the rib load grows as ω² (the increase at 2ω is 4 times that
/// at ω, 1e-9). The roller's mass is a frustum's: checked against a 10⁵-slice sum (1e-8).
#[test]
fn centrifugal_force_adds_to_the_rib_load_as_omega_squared() {
    let k = TaperedKinematics::new(
        18f64.to_radians(),
        2.5f64.to_radians(),
        Point3::origin(),
        90.0,
        300.0,
        0.0,
    )
    .unwrap();
    let e_r = k.directions(0.0).roller_axis;
    let (ai, b) = (k.inner_raceway_angle, k.roller_half_angle);
    let am = ai + b;
    let fc = 37.0;
    let l = roller_loads(&k, &(-e_r), 5000.0, 20, fc).unwrap();
    let qf = 2.0 * l.outer_raceway * b.sin() + fc * ai.sin() / b.cos();
    let qi = l.outer_raceway - fc * am.cos() / b.cos();
    assert!((l.rib - qf).abs() < 1e-12 * qf, "{} vs {qf}", l.rib);
    assert!((l.inner_raceway - qi).abs() < 1e-12 * qi);

    let spec = RollerRibSpec::builtin("sphere-torus-57").unwrap();
    let rollers = RollerSet::default();
    let model = RibFrictionModel::new(spec, rollers, exact_coulomb(0.1), None, true).unwrap();
    let op = |w| Operating {
        axial_load: 6000.0,
        inner_speed: w,
        outer_speed: 0.0,
    };
    let q = |w| model.loads(&op(w)).unwrap().1.rib;
    let (q0, q1, q2) = (q(0.0), q(300.0), q(600.0));
    println!(
        "rib load {q0:.4} N at rest, +{:.4} N at 300 rad/s, +{:.4} N at 600",
        q1 - q0,
        q2 - q0
    );
    assert!(((q2 - q0) / (q1 - q0) - 4.0).abs() < 1e-9);
    // Frustum mass by slices.
    let rr = model.pair();
    let beta = rr.spec.bearing.roller_half_angle_deg.to_radians();
    let big = rr.spec.bearing.roller_large_end_radius;
    let n = 100_000;
    let dz = rollers.length / n as f64;
    let (mut v, mut moment) = (0.0, 0.0);
    for i in 0..n {
        let z = (i as f64 + 0.5) * dz; // from the large end
        let r = big - z * beta.tan();
        let dv = std::f64::consts::PI * r * r * dz;
        v += dv;
        moment += dv * z;
    }
    let m = model.roller_mass();
    let s_large = big / beta.tan();
    println!(
        "mass {:.6} g, slices {:.6} g",
        m.mass * 1e3,
        rollers.density * v * 1e-6
    );
    assert!((m.mass - rollers.density * v * 1e-9).abs() < 1e-8 * m.mass);
    assert!((m.apex_distance - (s_large - moment / v)).abs() < 1e-8 * s_large);
}

/// The integrated field against the point formula: with constant μ and the Hertz field of
/// the rib contact, the rib torque Z P / ω_i equals Z μ Q_f |v_s(centre)| / ω_i up to the
/// lever-arm correction, which is positive and of order (s/e)²/10 (s the patch's extent):
/// 0 < ratio − 1 < (s/e)². At constant μ without regularisation the torque does not depend
/// on speed (P ∝ ω, 1e-12 over 10-600 rad/s), and the field is solved once.
#[test]
fn integrated_rib_torque_against_the_point_formula() {
    for name in ["sphere-torus-57", "torus-cone-14"] {
        let spec = RollerRibSpec::builtin(name).unwrap();
        let model =
            RibFrictionModel::new(spec, RollerSet::default(), exact_coulomb(0.1), None, false)
                .unwrap();
        let sweep = model
            .sweep(PressureModel::Hertz, 6000.0, &[10.0, 100.0, 600.0])
            .unwrap();
        let r = &sweep[1];
        let z = RollerSet::default().count as f64;
        // Z μ Q_f |v_s| / ω_i: N · mm/s / (rad/s) = N·mm.
        let point = z * 0.1 * r.loads.rib * r.sliding_speed / 100.0;
        let ratio = r.bearing_torque / point;
        // The sampled Hertz field carries the rib load to its sampling error (2 %).
        let n = r.contact.grid.normal_force;
        assert!(
            (n - r.loads.rib).abs() < 0.02 * r.loads.rib,
            "{n} vs {}",
            r.loads.rib
        );
        let reach = model
            .solve(PressureModel::Hertz, r.loads.rib)
            .unwrap()
            .semi_axes
            .iter()
            .fold(0.0f64, |m, v| m.max(*v));
        let bound = (reach / r.contact_height).powi(2);
        println!(
            "{name}: Q_f = {:.3} N, e = {:.4} mm, M = {:.4} N·mm, point formula {point:.4}, \
             ratio - 1 = {:.3e}, (s/e)² = {bound:.3e}, mu_eff = {:.5}",
            r.loads.rib,
            r.contact_height,
            r.bearing_torque,
            ratio - 1.0,
            r.coefficient
        );
        assert!(ratio > 1.0 && ratio - 1.0 < bound, "{ratio}");
        for other in [&sweep[0], &sweep[2]] {
            assert!((other.bearing_torque - r.bearing_torque).abs() < 1e-12 * r.bearing_torque);
        }
        assert!(r.coefficient <= 0.1 * (1.0 + 1e-12));
    }
}

/// Bad input names its field.
#[test]
fn bad_input_names_the_field() {
    let k = TaperedKinematics::new(0.3, 0.05, Point3::origin(), 80.0, 100.0, 0.0).unwrap();
    let e_r = k.directions(0.0).roller_axis;
    let field = |r: kontakt::error::Result<_>| {
        r.map(|_: kontakt::bearing::RollerLoads| ())
            .unwrap_err()
            .field()
            .unwrap()
            .to_string()
    };
    assert_eq!(field(roller_loads(&k, &(-e_r), 0.0, 10, 0.0)), "axial_load");
    assert_eq!(
        field(roller_loads(&k, &(-e_r), f64::NAN, 10, 0.0)),
        "axial_load"
    );
    assert_eq!(field(roller_loads(&k, &(-e_r), 1e3, 2, 0.0)), "count");
    assert_eq!(
        field(roller_loads(&k, &(-e_r), 1e3, 10, -1.0)),
        "centrifugal"
    );
    assert_eq!(field(roller_loads(&k, &e_r, 1e3, 10, 0.0)), "rib_normal");
    assert_eq!(
        field(roller_loads(
            &k,
            &Vector3::new(f64::NAN, 0.0, 0.0),
            1e3,
            10,
            0.0
        )),
        "rib_normal"
    );
    assert_eq!(
        field(roller_loads(&k, &(-e_r), 1e3, 10, 1e9)),
        "inner_speed"
    );
    let spec = RollerRibSpec::builtin("sphere-cone-29").unwrap();
    for (rollers, name) in [
        (
            RollerSet {
                count: 2,
                ..RollerSet::default()
            },
            "count",
        ),
        (
            RollerSet {
                length: 0.0,
                ..RollerSet::default()
            },
            "length",
        ),
        (
            RollerSet {
                length: 500.0,
                ..RollerSet::default()
            },
            "length",
        ),
        (
            RollerSet {
                density: f64::INFINITY,
                ..RollerSet::default()
            },
            "density",
        ),
    ] {
        let err = RibFrictionModel::new(spec, rollers, exact_coulomb(0.1), None, true).unwrap_err();
        assert_eq!(err.field(), Some(name));
    }
    let model =
        RibFrictionModel::new(spec, RollerSet::default(), exact_coulomb(0.1), None, true).unwrap();
    let err = model.sweep(PressureModel::Pimp, 5000.0, &[]).unwrap_err();
    assert_eq!(err.field(), Some("speeds"));
    let err = model
        .sweep(PressureModel::Pimp, 5000.0, &[f64::NAN])
        .unwrap_err();
    assert_eq!(err.field(), Some("inner_speed"));
}

/// The lubricated rib (Aihara's law μ = 0.2 exp(−1.8 Λ^1.2), no fluid shear, an ISO VG 68
/// oil at 70 °C, σ = 0.2 µm on both surfaces, Hamrock-Dowson central film): at constant
/// rib load (no centrifugal force) the film grows as the entrainment speed to the power
/// 0.67 (the formula's exponent: Λ(ω₂)/Λ(ω₁) = (ω₂/ω₁)^0.67, 1e-12), and the effective
/// coefficient is the dry one times exp(−1.8 Λ^1.2) (1e-12): the Stribeck curve falls from
/// the boundary value with speed. The rib contact lies outside the Hamrock-Dowson fit
/// (k < 1) and the report says so.
#[test]
fn lubricated_rib_follows_aihara_with_the_film_of_the_speed() {
    use kontakt::lubrication::{FilmFormula, Lubricant};
    let spec = RollerRibSpec::builtin("sphere-torus-57").unwrap();
    let lub = kontakt::bearing::RibLubrication {
        lubricant: Lubricant::iso_vg(68, 860.0, 0.02).unwrap(),
        temperature: 70.0,
        roughness: [0.2e-3, 0.2e-3],
        formula: FilmFormula::HamrockDowson,
    };
    let law = FrictionLaw {
        regularisation_speed: 0.0,
        ..FrictionLaw::aihara()
    };
    let wet = RibFrictionModel::new(spec, RollerSet::default(), law, Some(lub), false).unwrap();
    let dry =
        RibFrictionModel::new(spec, RollerSet::default(), exact_coulomb(0.2), None, false).unwrap();
    let speeds = [5.0, 20.0, 80.0, 320.0];
    let w = wet.sweep(PressureModel::Pimp, 6000.0, &speeds).unwrap();
    let d = dry.sweep(PressureModel::Pimp, 6000.0, &speeds).unwrap();
    let mut last = f64::INFINITY;
    for (i, (a, b)) in w.iter().zip(&d).enumerate() {
        let lambda = a.film.lambda;
        let h = a.film_thickness.unwrap();
        println!(
            "omega_i = {:5} rad/s: h_c = {:.4} µm, Lambda = {lambda:.4}, mu = {:.5} \
             (dry {:.5}), M = {:.2} N·mm, k = {:.3}, warnings: {:?}",
            speeds[i],
            h.central * 1e3,
            a.coefficient,
            b.coefficient,
            a.bearing_torque,
            h.regime.k,
            h.warning_lines()
        );
        let expected = b.coefficient * (-1.8 * lambda.powf(1.2)).exp();
        assert!((a.coefficient - expected).abs() < 1e-12 * b.coefficient);
        assert!(a.coefficient < last);
        last = a.coefficient;
        assert!(h.warnings.ellipticity_below_fit);
        if i > 0 {
            let ratio = lambda / w[i - 1].film.lambda;
            assert!((ratio - (speeds[i] / speeds[i - 1]).powf(0.67)).abs() < 1e-12);
        }
    }
}
