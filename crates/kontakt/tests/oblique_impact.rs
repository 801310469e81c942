//! Oblique impact with friction: the rigid-body regimes (Johnson 1982 eqs 39-40, 64-70) and
//! the elastic analysis of Maw, Barber and Fawcett (1976). Tolerances are stated at each
//! check; derivations and the numbers are in docs/impact.md.

use kontakt::hertz::impact::HertzImpact;
use kontakt::impact::elastic::elastic_rebound_psi;
use kontakt::impact::{
    ElasticImpactOptions, ElasticObliqueImpact, IncidentMotion, RigidObliqueImpact, RigidRegime,
    SphereBody, rigid_rebound_psi, stiffness_ratio,
};
use kontakt::material::{ElasticMaterial, effective_modulus};
use kontakt::{Error, Result};

/// chi of a solid sphere with nu = 0.3: (1 - nu)/(2 - nu) (1 + 5/2).
const CHI_SOLID: f64 = 0.7 / 1.7 * 3.5;

fn steel_ball() -> SphereBody {
    // R = 5 mm, m = 4/3 pi R^3 rho = 4.1102e-6 t
    SphereBody::solid_sphere(5.0, 4.0 / 3.0 * std::f64::consts::PI * 125.0 * 7.85e-9)
        .expect("valid ball")
}

fn rel(a: f64, b: f64) -> f64 {
    (a - b).abs() / b.abs().max(1e-300)
}

fn field_of<T: std::fmt::Debug>(r: Result<T>) -> String {
    match r {
        Err(Error::InvalidInput { field, .. }) => field.into_owned(),
        other => panic!("expected InvalidInput, got {other:?}"),
    }
}

// ---------------------------------------------------------------- rigid body

/// Johnson (1982) eq. (40b)/(69): a solid sphere that slides throughout leaves with
/// w2 = w1 - 7 mu V (e = 1), exactly (1e-12).
#[test]
fn rigid_sliding_is_johnson_eq_40b() -> Result<()> {
    let ball = steel_ball();
    let imp = RigidObliqueImpact::new(ball, 0.2, 1.0)?;
    let inc = IncidentMotion::new(1000.0, 1500.0, 40.0)?; // w1 = 1500 + 200 = 1700 > 1400
    let r = imp.rebound(&inc)?;
    assert_eq!(r.regime, RigidRegime::GrossSliding);
    assert!(rel(r.peripheral_velocity, 1700.0 - 7.0 * 0.2 * 1000.0) < 1e-12);
    assert!(rel(r.friction_impulse.abs(), 0.2 * r.normal_impulse) < 1e-12);
    // and the peripheral velocity recomputed from u2 and omega2
    let w2 = r.tangential_velocity + r.angular_velocity * ball.radius();
    assert!((w2 - r.peripheral_velocity).abs() < 1e-9);
    Ok(())
}

/// The rolling regime: a solid sphere without spin leaves rolling, u2 = 5/7 u1 and
/// omega2 = -u2/R (rolling forward), to 1e-12.
#[test]
fn rigid_rolling_rebound() -> Result<()> {
    let ball = steel_ball();
    let imp = RigidObliqueImpact::new(ball, 0.5, 0.8)?;
    for angle_deg in [5.0_f64, 20.0, 40.0] {
        let inc = IncidentMotion::from_angle(2000.0, angle_deg.to_radians(), 0.0)?;
        let r = imp.rebound(&inc)?;
        assert_eq!(r.regime, RigidRegime::SlidingThenRolling);
        let u1 = inc.tangential_velocity();
        assert!(rel(r.tangential_velocity, 5.0 / 7.0 * u1) < 1e-12);
        assert!(rel(-r.angular_velocity * ball.radius(), r.tangential_velocity) < 1e-12);
        assert_eq!(r.peripheral_velocity, 0.0);
        assert!(rel(r.normal_velocity, 0.8 * inc.normal_speed()) < 1e-15);
    }
    Ok(())
}

/// Invariants over a grid of both regimes, several e and k: angular momentum about the
/// contact point conserved (1e-12), kinetic-energy loss from the velocities equal to the
/// closed form (1e-9 of the incident energy) and >= 0, |J| <= mu P.
#[test]
fn rigid_momentum_and_energy_balance() -> Result<()> {
    for k_over_r in [0.4_f64.sqrt(), (2.0_f64 / 3.0).sqrt(), 0.5_f64.sqrt(), 0.3] {
        let ball = SphereBody::new(4.0, 2.0e-6, k_over_r * 4.0)?;
        for e in [0.0, 0.5, 1.0] {
            let imp = RigidObliqueImpact::new(ball, 0.25, e)?;
            for (u, om) in [
                (3000.0, 0.0),
                (200.0, -300.0),
                (-800.0, 100.0),
                (0.0, 2000.0),
            ] {
                let inc = IncidentMotion::new(700.0, u, om)?;
                let r = imp.rebound(&inc)?;
                let l1 = ball.angular_momentum_about_contact(u, om);
                let l2 =
                    ball.angular_momentum_about_contact(r.tangential_velocity, r.angular_velocity);
                assert!((l1 - l2).abs() <= 1e-12 * (l1.abs() + ball.mass() * 4.0 * 3000.0));
                let ke1 = ball.kinetic_energy(700.0, u, om);
                let ke2 = ball.kinetic_energy(
                    r.normal_velocity,
                    r.tangential_velocity,
                    r.angular_velocity,
                );
                assert!(
                    ((ke1 - ke2) - r.energy_loss).abs() <= 1e-9 * ke1,
                    "{ke1} {ke2} {r:?}"
                );
                assert!(r.energy_loss >= -1e-12 * ke1);
                assert!(r.friction_impulse.abs() <= 0.25 * r.normal_impulse * (1.0 + 1e-12));
            }
        }
    }
    Ok(())
}

/// At the regime boundary |w1| = w_c the two formulas meet: the rebound changes by less
/// than 1e-6 (relative) across w_c (1 -+ 1e-9).
#[test]
fn rigid_regimes_meet_continuously() -> Result<()> {
    let ball = steel_ball();
    let imp = RigidObliqueImpact::new(ball, 0.3, 0.7)?;
    let v = 1200.0;
    let wc = imp.critical_peripheral_velocity(v);
    assert!(rel(wc, 0.3 * 1.7 * v * 3.5) < 1e-12);
    let below = imp.rebound(&IncidentMotion::new(v, wc * (1.0 - 1e-9), 0.0)?)?;
    let above = imp.rebound(&IncidentMotion::new(v, wc * (1.0 + 1e-9), 0.0)?)?;
    assert_eq!(below.regime, RigidRegime::SlidingThenRolling);
    assert_eq!(above.regime, RigidRegime::GrossSliding);
    assert!(rel(below.tangential_velocity, above.tangential_velocity) < 1e-6);
    assert!(rel(below.angular_velocity, above.angular_velocity) < 1e-6);
    assert!(above.peripheral_velocity.abs() < 1e-6 * wc);
    Ok(())
}

/// The non-dimensional rigid result equals the dimensional one: psi2 = kappa w2/(mu V),
/// to 1e-12.
#[test]
fn rigid_psi_form_matches_dimensional() -> Result<()> {
    let s = ElasticMaterial::STEEL;
    let kappa = stiffness_ratio(&s, &s)?;
    let ball = steel_ball();
    let chi = ball.chi(kappa);
    assert!(rel(chi, CHI_SOLID) < 1e-14);
    let mu = 0.15;
    let imp = RigidObliqueImpact::new(ball, mu, 1.0)?;
    for u in [100.0, 900.0, 2500.0, 4000.0, -4000.0] {
        let inc = IncidentMotion::new(1000.0, u, 0.0)?;
        let r = imp.rebound(&inc)?;
        let psi1 = kappa * u / (mu * 1000.0);
        let psi2 = rigid_rebound_psi(psi1, chi, 1.0)?;
        assert!((psi2 - kappa * r.peripheral_velocity / (mu * 1000.0)).abs() < 1e-12 * psi1.abs());
    }
    Ok(())
}

// ---------------------------------------------------------------- elastic

/// The normal part of the elastic integration reproduces the closed-form Hertz impact
/// (crate::hertz::impact): duration, peak force, peak approach to 1e-3 (measured: 3e-8),
/// rebound normal speed = V to 1e-6.
#[test]
fn elastic_normal_problem_is_hertz_impact() -> Result<()> {
    let s = ElasticMaterial::STEEL;
    let ball = steel_ball();
    let imp = ElasticObliqueImpact::new(ball, s, s, 0.3, ElasticImpactOptions::default())?;
    let v = 1000.0;
    let r = imp.rebound(&IncidentMotion::new(v, 100.0, 5.0)?)?;
    let hz = HertzImpact::sphere(5.0, effective_modulus(&s, &s), ball.mass(), v)?.result();
    let errs = [
        rel(r.contact_duration, hz.contact_duration),
        rel(r.max_force, hz.max_force),
        rel(r.max_approach, hz.max_approach),
    ];
    eprintln!(
        "normal: T {} vs {}, F {} vs {}, errors {errs:?}",
        r.contact_duration, hz.contact_duration, r.max_force, hz.max_force
    );
    assert!(errs.iter().all(|e| *e < 1e-3), "{errs:?}");
    assert!(rel(r.normal_velocity, v) < 1e-6);
    assert!(rel(r.normal_impulse, 2.0 * ball.mass() * v) < 1e-6);
    Ok(())
}

/// Large incidence (psi1 > 4 chi - 1): gross sliding throughout, and the elastic rebound
/// equals the rigid sliding result psi2 = psi1 - 4 chi to 1e-3 (absolute in psi; measured
/// < 1e-6). For psi1 >= 4 chi this is also the rigid theory's answer; between 4 chi - 1 and
/// 4 chi the rigid theory would stop the contact point, the elastic one keeps sliding.
#[test]
fn elastic_gross_sliding_equals_rigid() -> Result<()> {
    let o = ElasticImpactOptions::default();
    for psi1 in [5.0, 6.0, 8.0, 12.0, 20.0, -9.0] {
        let psi2 = elastic_rebound_psi(psi1, CHI_SOLID, o)?;
        let sliding = psi1 - psi1.signum() * 4.0 * CHI_SOLID;
        eprintln!("psi1 {psi1}: elastic {psi2}, sliding {sliding}");
        assert!(
            (psi2 - sliding).abs() < 1e-3,
            "psi1 {psi1}: {psi2} vs {sliding}"
        );
        if psi1.abs() >= 4.0 * CHI_SOLID {
            assert_eq!(rigid_rebound_psi(psi1, CHI_SOLID, 1.0)?, sliding);
        }
    }
    // dimensional, with the slid-throughout flag
    let s = ElasticMaterial::STEEL;
    let imp = ElasticObliqueImpact::new(steel_ball(), s, s, 0.1, o)?;
    let inc = IncidentMotion::from_angle(1000.0, 60f64.to_radians(), 0.0)?;
    let r = imp.rebound(&inc)?;
    let rr = RigidObliqueImpact::new(steel_ball(), 0.1, 1.0)?.rebound(&inc)?;
    assert!(r.slid_throughout && r.psi1 > 4.0 * CHI_SOLID);
    assert!(rel(r.tangential_velocity, rr.tangential_velocity) < 1e-3);
    assert!(rel(r.angular_velocity, rr.angular_velocity) < 1e-3);
    Ok(())
}

/// Maw, Barber and Fawcett (1976): gross sliding lasts the whole impact only for
/// psi1 >= 4 chi - 1, below the rigid threshold 4 chi. Just above it the elastic result is
/// the rigid sliding one (1e-3) and the contact slid throughout; just below it it is not.
#[test]
fn elastic_gross_slip_threshold_is_4chi_minus_1() -> Result<()> {
    let s = ElasticMaterial::STEEL;
    let ball = steel_ball();
    let mu = 0.2;
    let imp = ElasticObliqueImpact::new(ball, s, s, mu, ElasticImpactOptions::default())?;
    let kappa = imp.kappa();
    let at = |psi1: f64| -> Result<_> {
        let v = 1000.0;
        imp.rebound(&IncidentMotion::new(v, psi1 * mu * v / kappa, 0.0)?)
    };
    let threshold = 4.0 * CHI_SOLID - 1.0;
    let above = at(threshold + 0.05)?;
    assert!(above.slid_throughout);
    assert!((above.psi2 - (above.psi1 - 4.0 * CHI_SOLID)).abs() < 1e-3);
    let below = at(threshold - 0.2)?;
    eprintln!(
        "threshold {threshold}: above {} -> {}, below {} -> {}",
        above.psi1, above.psi2, below.psi1, below.psi2
    );
    assert!(!below.slid_throughout);
    assert!(below.psi2 - (below.psi1 - 4.0 * CHI_SOLID) > 1e-3);
    Ok(())
}

/// The superball: below the rigid sliding threshold (psi1 < 4 chi, where the rigid theory
/// gives psi2 = 0) the contact point springs back, psi2 < 0: for a solid sphere
/// (chi = 1.441) over 1 <= psi1 <= 5.5, and for the thin diametral slice of Maw, Barber and
/// Fawcett (1981), chi = 1.2558 (nu = 0.28), over 0.2 <= psi1 <= 4.5, where their Fig. 1
/// shows psi2 negative "for low values of psi1". The deepest value for the solid sphere is
/// about -1.48 near psi1 = 3.5 (checked to 0.02). For psi1 < 0.9 the solid sphere's psi2 is
/// slightly positive (the no-slip limit below).
#[test]
fn elastic_negative_rebound_below_the_sliding_threshold() -> Result<()> {
    let o = ElasticImpactOptions::default();
    let slice: f64 = 0.72 / 1.72 * 3.0;
    assert!((slice - 1.2558).abs() < 1e-4);
    for (chi, psis) in [
        (CHI_SOLID, [1.0, 2.0, 3.0, 4.0, 5.0, 5.5]),
        (slice, [0.2, 1.0, 2.0, 3.0, 4.0, 4.5]),
    ] {
        for psi1 in psis {
            let psi2 = elastic_rebound_psi(psi1, chi, o)?;
            eprintln!("chi {chi}: psi1 {psi1} -> psi2 {psi2}");
            assert!(psi2 < 0.0, "chi {chi} psi1 {psi1}: {psi2}");
            let rigid = rigid_rebound_psi(psi1, chi, 1.0)?;
            assert!(rigid >= 0.0);
        }
    }
    let deepest = elastic_rebound_psi(3.5, CHI_SOLID, o)?;
    assert!((deepest + 1.48).abs() < 0.02, "{deepest}");
    Ok(())
}

/// Johnson's superball: a solid rubber ball (nu = 0.5: kappa = 2/3, chi = 7/6) rebounds with
/// w2 < 0 at every incidence below the sliding threshold 4 chi - 1 = 3.67 (and with
/// -1 <= psi2 < 0 up to 4 chi = 4.67), down to psi1 = 0.01, where the rigid theory gives
/// w2 = 0. Thrown forward with back-spin (u1 = w1/4, omega1 R = 3 w1/4), it comes back with
/// both u and omega reversed (J82 Fig. 11a) for psi1 up to 3.6 (the reversal of omega needs
/// psi2 < -psi1/20 with this spin). Checked through the dimensional API.
#[test]
fn superball_springs_back() -> Result<()> {
    let rubber = ElasticMaterial::new(5.0, 0.5)?;
    let ball = SphereBody::solid_sphere(25.0, 6.5e-5)?;
    let mu = 0.8;
    let options = ElasticImpactOptions::default();
    let imp = ElasticObliqueImpact::new(ball, rubber, ElasticMaterial::RIGID, mu, options)?;
    assert!((imp.chi() - 7.0 / 6.0).abs() < 1e-12);
    let v = 3000.0;
    for psi1 in [0.01, 0.1, 0.5, 1.0, 2.0, 3.0, 3.6, 4.6] {
        let w1 = psi1 * mu * v / imp.kappa();
        let inc = IncidentMotion::new(v, 0.25 * w1, 0.75 * w1 / 25.0)?;
        let r = imp.rebound(&inc)?;
        eprintln!(
            "superball psi1 {psi1}: psi2 {}, u2/u1 {}, omega2/omega1 {}",
            r.psi2,
            r.tangential_velocity / inc.tangential_velocity(),
            r.angular_velocity / inc.angular_velocity()
        );
        assert!(r.psi2 < 0.0 && r.psi2 >= -psi1, "psi1 {psi1}: {}", r.psi2);
        if psi1 <= 3.6 {
            assert!(
                r.tangential_velocity < 0.0 && r.angular_velocity < 0.0,
                "psi1 {psi1}"
            );
        }
    }
    Ok(())
}

/// An exact solution: for chi = 1/2 the tangential problem is similar to the normal one
/// (with psi1 <= 1 every spring sticks and the tangential displacement is
/// (w1/V) delta(t)), so the contact point leaves with w2 = -w1 exactly; for psi1 >= 1 = 4 chi
/// - 1 the contact slides throughout, psi2 = psi1 - 2. Tolerance 1e-3 (measured < 1e-5).
#[test]
fn elastic_chi_one_half_reverses_exactly() -> Result<()> {
    let o = ElasticImpactOptions::default();
    for psi1 in [0.01, 0.3, 0.7, 0.95] {
        let psi2 = elastic_rebound_psi(psi1, 0.5, o)?;
        assert!((psi2 + psi1).abs() < 1e-3 * psi1.max(0.1), "{psi1}: {psi2}");
    }
    for psi1 in [1.05, 1.5, 3.0] {
        let psi2 = elastic_rebound_psi(psi1, 0.5, o)?;
        assert!((psi2 - (psi1 - 2.0)).abs() < 1e-3, "{psi1}: {psi2}");
    }
    Ok(())
}

/// The no-slip limit (psi1 -> 0, mu -> infinity) against an independent computation:
/// tools/reference/oblique_impact_noslip.py integrates Q = 8 G* int_0^a (s(t) - s(t_in(x))) dx
/// (history kept on the time grid, not on cells) and gives w2/w1 = 0.23167 for chi = 1.441
/// and 0.3483 for chi = 2 (converged to 1e-5 between 2000 and 4000 steps). Ours at
/// psi1 = 0.005, tolerance 3e-3.
#[test]
fn elastic_no_slip_limit_matches_independent_integration() -> Result<()> {
    let o = ElasticImpactOptions::default();
    for (chi, reference) in [(CHI_SOLID, 0.23167), (2.0, 0.3483)] {
        let ratio = elastic_rebound_psi(0.005, chi, o)? / 0.005;
        eprintln!("chi {chi}: no-slip ratio {ratio} vs {reference}");
        assert!(
            (ratio - reference).abs() < 3e-3,
            "chi {chi}: {ratio} vs {reference}"
        );
    }
    Ok(())
}

/// Physical bounds over a sweep 0 < psi1 <= 10: |psi2| <= psi1 (no energy gain: the
/// tangential energy is m_t w^2/2 at fixed angular momentum about the contact point),
/// psi2 >= psi1 - 4 chi (|friction impulse| <= mu times the normal impulse), both with
/// 1e-9 slack; odd in psi1 (1e-12).
#[test]
fn elastic_physical_bounds_and_symmetry() -> Result<()> {
    let o = ElasticImpactOptions {
        steps: 2000,
        cells: 200,
    };
    let mut psi1 = 0.1;
    while psi1 <= 10.0 {
        let psi2 = elastic_rebound_psi(psi1, CHI_SOLID, o)?;
        assert!(psi2.abs() <= psi1 * (1.0 + 1e-9), "{psi1}: {psi2}");
        assert!(psi2 >= psi1 - 4.0 * CHI_SOLID - 1e-9, "{psi1}: {psi2}");
        let minus = elastic_rebound_psi(-psi1, CHI_SOLID, o)?;
        assert!((minus + psi2).abs() <= 1e-12 * psi1.max(1.0));
        psi1 += 0.35;
    }
    assert_eq!(elastic_rebound_psi(0.0, CHI_SOLID, o)?, 0.0);
    Ok(())
}

/// psi2 depends on psi1 and chi only: two dimensional impacts (different R, m, V, mu,
/// spin, materials with one nu) with the same chi and psi1 give psi2 equal to 1e-9, and
/// equal to the unit problem of `elastic_rebound_psi` to 1e-9. Energy lost >= 0.
#[test]
fn elastic_result_depends_on_psi1_and_chi_only() -> Result<()> {
    let o = ElasticImpactOptions::default();
    let s = ElasticMaterial::STEEL;
    let soft = ElasticMaterial::new(3_000.0, 0.3)?;
    let a = ElasticObliqueImpact::new(steel_ball(), s, s, 0.3, o)?;
    let b_ball = SphereBody::solid_sphere(20.0, 3.0e-5)?;
    let b = ElasticObliqueImpact::new(b_ball, soft, ElasticMaterial::RIGID, 0.8, o)?;
    assert!(rel(a.chi(), b.chi()) < 1e-14);
    let psi1 = 1.7;
    let va = 800.0;
    let ra = a.rebound(&IncidentMotion::new(va, psi1 * 0.3 * va / a.kappa(), 0.0)?)?;
    let vb = 3000.0;
    let wb = psi1 * 0.8 * vb / b.kappa();
    // the same w1 made of a translation and a spin
    let rb = b.rebound(&IncidentMotion::new(vb, 0.25 * wb, 0.75 * wb / 20.0)?)?;
    let unit = elastic_rebound_psi(psi1, a.chi(), o)?;
    eprintln!("psi2: {} {} {unit}", ra.psi2, rb.psi2);
    assert!((ra.psi1 - psi1).abs() < 1e-12 && (rb.psi1 - psi1).abs() < 1e-12);
    assert!((ra.psi2 - rb.psi2).abs() < 1e-9);
    assert!((ra.psi2 - unit).abs() < 1e-9);
    assert!(ra.energy_loss >= 0.0 && rb.energy_loss >= 0.0);
    Ok(())
}

/// Convergence: doubling both the steps and the cells changes psi2 by less than 2e-3 over
/// the partial-slip range.
#[test]
fn elastic_integration_converges() -> Result<()> {
    let coarse = ElasticImpactOptions::default();
    let fine = ElasticImpactOptions {
        steps: 2 * coarse.steps,
        cells: 2 * coarse.cells,
    };
    for psi1 in [0.5, 1.0, 2.0, 3.0, 4.5] {
        let c = elastic_rebound_psi(psi1, CHI_SOLID, coarse)?;
        let f = elastic_rebound_psi(psi1, CHI_SOLID, fine)?;
        eprintln!("psi1 {psi1}: {c} {f} diff {}", (c - f).abs());
        assert!((c - f).abs() < 2e-3, "psi1 {psi1}: {c} vs {f}");
    }
    Ok(())
}

/// In the no-slip limit (psi1 -> 0, i.e. mu -> infinity) the tangential problem is linear:
/// psi2/psi1 tends to a constant; at psi1 = 0.01 and 0.005 the ratios agree to 2e-3.
#[test]
fn elastic_no_slip_limit_is_linear() -> Result<()> {
    let o = ElasticImpactOptions::default();
    let r1 = elastic_rebound_psi(0.01, CHI_SOLID, o)? / 0.01;
    let r2 = elastic_rebound_psi(0.005, CHI_SOLID, o)? / 0.005;
    eprintln!("no-slip ratio {r1} {r2}");
    assert!((r1 - r2).abs() < 2e-3, "{r1} {r2}");
    Ok(())
}

// ---------------------------------------------------------------- bad input

#[test]
fn bad_input_is_named() {
    let ball = steel_ball();
    let s = ElasticMaterial::STEEL;
    let o = ElasticImpactOptions::default();
    assert_eq!(field_of(IncidentMotion::new(0.0, 1.0, 0.0)), "normal_speed");
    assert_eq!(
        field_of(IncidentMotion::new(f64::NAN, 1.0, 0.0)),
        "normal_speed"
    );
    assert_eq!(
        field_of(IncidentMotion::new(-5.0, 1.0, 0.0)),
        "normal_speed"
    );
    assert_eq!(
        field_of(IncidentMotion::new(5.0, f64::NAN, 0.0)),
        "tangential_velocity"
    );
    assert_eq!(
        field_of(IncidentMotion::new(5.0, 1.0, f64::INFINITY)),
        "angular_velocity"
    );
    assert_eq!(field_of(IncidentMotion::from_angle(0.0, 0.1, 0.0)), "speed");
    assert_eq!(
        field_of(IncidentMotion::from_angle(f64::NAN, 0.1, 0.0)),
        "speed"
    );
    for angle in [
        std::f64::consts::FRAC_PI_2,
        -std::f64::consts::FRAC_PI_2,
        2.0,
        f64::NAN,
    ] {
        assert_eq!(
            field_of(IncidentMotion::from_angle(10.0, angle, 0.0)),
            "incidence_angle"
        );
    }
    for mu in [0.0, -0.1, f64::NAN, f64::INFINITY] {
        assert_eq!(
            field_of(RigidObliqueImpact::new(ball, mu, 1.0)),
            "friction_coefficient"
        );
        assert_eq!(
            field_of(ElasticObliqueImpact::new(ball, s, s, mu, o)),
            "friction_coefficient"
        );
    }
    for e in [-0.1, 1.1, f64::NAN] {
        assert_eq!(
            field_of(RigidObliqueImpact::new(ball, 0.2, e)),
            "restitution"
        );
        assert_eq!(field_of(rigid_rebound_psi(1.0, 1.0, e)), "restitution");
    }
    assert_eq!(field_of(SphereBody::new(0.0, 1.0, 1.0)), "radius");
    assert_eq!(field_of(SphereBody::new(1.0, f64::NAN, 1.0)), "mass");
    assert_eq!(
        field_of(SphereBody::new(1.0, 1.0, -1.0)),
        "radius_of_gyration"
    );
    assert_eq!(field_of(SphereBody::solid_sphere(1.0, 0.0)), "mass");
    let r = ElasticMaterial::RIGID;
    assert_eq!(
        field_of(ElasticObliqueImpact::new(ball, r, r, 0.2, o)),
        "materials"
    );
    assert_eq!(field_of(stiffness_ratio(&r, &r)), "materials");
    let few = ElasticImpactOptions {
        steps: 10,
        cells: 400,
    };
    assert_eq!(
        field_of(ElasticObliqueImpact::new(ball, s, s, 0.2, few)),
        "steps"
    );
    let few = ElasticImpactOptions {
        steps: 4000,
        cells: 1,
    };
    assert_eq!(field_of(elastic_rebound_psi(1.0, 1.0, few)), "cells");
    assert_eq!(field_of(elastic_rebound_psi(f64::NAN, 1.0, o)), "psi1");
    assert_eq!(field_of(elastic_rebound_psi(1.0, 0.0, o)), "chi");
    assert_eq!(field_of(elastic_rebound_psi(1.0, f64::INFINITY, o)), "chi");
    assert_eq!(field_of(rigid_rebound_psi(f64::INFINITY, 1.0, 1.0)), "psi1");
    assert_eq!(field_of(rigid_rebound_psi(1.0, -1.0, 1.0)), "chi");
    // absurd scales are an error, never NaN
    assert_eq!(
        field_of(SphereBody::solid_sphere(1e-300, 1e-300)),
        "radius_of_gyration"
    );
    let imp = ElasticObliqueImpact::new(ball, s, s, 0.2, o).expect("valid impact");
    let huge = IncidentMotion::new(1e300, 1.0, 0.0).expect("valid motion");
    assert_eq!(field_of(imp.rebound(&huge)), "incident");
}
