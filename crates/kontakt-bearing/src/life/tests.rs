//! Validation of the rating lives and static safety (docs/VALIDATION.md, life rows).

use super::*;
use crate::equilibrium::{Dof, RingLoad, RollerBearingSolver};
use crate::load_zone::{LINE_EXPONENT, relative_load};
use crate::profile::Profile;
use kontakt::hertz::line::LineContact;
use kontakt::hertz::{HertzPointContact, PointGeometry};
use kontakt::material::ElasticMaterial;
use std::f64::consts::PI;

/// An NU 2xx class CRB with straight rollers and zero clearance.
fn crb() -> RollerBearing {
    let mut b = RollerBearing::cylindrical(60.0, 14, 10.0, 12.0);
    b.roller_profile = Profile::Straight;
    b
}

fn solve(b: &RollerBearing, load: RingLoad) -> (Vec<f64>, f64) {
    let mut s = RollerBearingSolver::new(b.clone()).unwrap();
    let sol = s.solve(&load).unwrap();
    assert!(sol.status.converged());
    let r = s.roller_loads();
    let j = (0..r.len())
        .max_by(|a, c| r[*a].outer_n.total_cmp(&r[*c].outer_n))
        .unwrap();
    (s.slice_loads().to_vec(), r[j].inner_n / r[j].outer_n)
}

fn life(b: &RollerBearing, c: f64, load: RingLoad, opts: LaminaOptions) -> f64 {
    let (q, ratio) = solve(b, load);
    lamina_life(b, c, &q, ratio, opts).unwrap().l10r_mrev
}

fn radial(f: f64) -> RingLoad {
    RingLoad::forces([f, 0.0, 0.0, 0.0, 0.0]).with_tilts_held()
}

/// The raceway capacities recombine to the bearing's C: `C = λν (C1^(−9/2) +
/// C2^(−9/2))^(−2/9)` with `C1 = 0.378 Z cos α Q_ci`, `C2 = 0.364 Z cos α Q_ce`, and
/// `Q_ci/Q_ce = ((1 − γ)/(1 + γ))^(143/108)` (Lundberg-Palmgren's raceway capacities,
/// Harris & Kotzalas 2006: the inner raceway, of the smaller reduced radius, is the weaker).
#[test]
fn raceway_capacities_recombine_to_the_dynamic_capacity() {
    for b in [
        crb(),
        RollerBearing::tapered(54.0, 23, 6.5, 13.66, 0.2473, 0.1950),
    ] {
        let c = 30_000.0;
        let (qi, qe) = raceway_capacities(&b, c).unwrap();
        let z = b.rollers as f64;
        let ca = b.contact_angle_rad.cos();
        let c1 = RADIAL_RATIO_ROTATING * z * ca * qi;
        let c2 = RADIAL_RATIO_STATIONARY * z * ca * qe;
        let back = LAMBDA_NU_RADIAL * (c1.powf(-4.5) + c2.powf(-4.5)).powf(-2.0 / 9.0);
        assert!((back / c - 1.0).abs() < 1e-12, "{back}");
        let g = b.roller_diameter_mm * ca / b.pitch_diameter_mm;
        let rho = ((1.0 - g) / (1.0 + g)).powf(143.0 / 108.0);
        assert!((qi / qe / rho - 1.0).abs() < 1e-12);
        assert!(qi < qe);
    }
    assert!(raceway_capacities(&crb(), 0.0).is_err());
    assert!(raceway_capacities(&crb(), f64::NAN).is_err());
}

/// The standard's 0.378 and 0.364 are `J_r/J_1` and `J_r/J_2` of Sjövall's integrals at
/// ε = 0.5 for line contact with the life exponents 4 (rotating ring) and 9/2 (stationary):
/// `J_1 = [(1/2π) ∫ (Q/Q_max)^4 dψ]^(1/4)`, `J_2` with 9/2. Our quadrature: 0.37637 and
/// 0.36304 with the load exponent 10/9 (0.43 % and 0.27 % below the standard's), 0.37673
/// and 0.36342 with Palmgren's older 1.1, 0.37992 and 0.36688 with 1; and ISO 281's
/// constant 207.9 of the roller bearings' f_c is Lundberg-Palmgren's 552 times `J_r/J_1`
/// at 1.1 (552 · 0.37673 = 207.96, 0.03 %).
#[test]
fn the_standards_ratios_are_sjovall_integrals() {
    let ratios = |n: f64| {
        let m = 200_000;
        let (mut jr, mut j1, mut j2) = (0.0, 0.0, 0.0);
        for i in 0..m {
            let psi = -PI + 2.0 * PI * (i as f64 + 0.5) / m as f64;
            let q = relative_load(psi, 0.5, n);
            jr += q * psi.cos();
            j1 += q.powi(4);
            j2 += q.powf(4.5);
        }
        let (jr, j1, j2) = (
            jr / m as f64,
            (j1 / m as f64).powf(0.25),
            (j2 / m as f64).powf(1.0 / 4.5),
        );
        eprintln!(
            "n = {n}: J_r = {jr:.5}, J_1 = {j1:.5}, J_2 = {j2:.5}, J_r/J_1 = {:.5}, J_r/J_2 = {:.5}",
            jr / j1,
            jr / j2
        );
        (jr / j1, jr / j2)
    };
    for n in [LINE_EXPONENT, 1.1] {
        let (a1, a2) = ratios(n);
        assert!((a1 / RADIAL_RATIO_ROTATING - 1.0).abs() < 5e-3, "{a1}");
        assert!((a2 / RADIAL_RATIO_STATIONARY - 1.0).abs() < 3e-3, "{a2}");
    }
    let (a1, _) = ratios(1.1);
    assert!((552.0 * a1 / 207.9 - 1.0).abs() < 5e-4, "{}", 552.0 * a1);
    // and the exponents matter: with 10/3 and 10/3 · 9/8 the ratios are off by percents
    let (_, a2_1) = ratios(1.0);
    assert!((a2_1 / RADIAL_RATIO_STATIONARY - 1.0).abs() > 5e-3);
}

/// Straight rollers, zero clearance, pure radial load, no edge factor: every roller's
/// slices carry the same load, so the lamina sum collapses to one lamina per roller,
/// independent of the slice count: `L10r = [(Q_ei/Q_ci)^(9/2) + (Q_ee/Q_ce)^(9/2)]^(−8/9)`
/// with `Q_ei = ((1/Z) Σ Q_j^4)^(1/4)`, `Q_ee` with 9/2 (to 1e-9, for 1, 31 and 61 slices).
/// Under ISO 281's assumptions (ε = 0.5, the continuous Sjövall ratios), that is
/// `L10r = (C/(λν F_r))^4`: ISO 281's form at `P = F_r`, with the lamina method's line-contact
/// exponent 4 instead of 10/3 and the standard's reference factor λν = 0.83. For Z = 14 the
/// discrete ratios `J_r/J_1` differ from 0.378 and 0.364 by up to 1.3 %, so the check of
/// ISO 281's form carries a derived tolerance: the standard's 0.378 and 0.364 exceed the
/// ratios of the load exponent 10/9 by 0.43 % and 0.27 % (see the test above), which
/// lowers `L10r (λν F_r/C)^4` by about `4 × 0.4 % = 1.7 %`; the finite Z adds less than
/// 0.3 %: 2 % in all (measured 0.983 at Z = 14 and 0.985 at Z = 40).
#[test]
fn uniform_straight_rollers_reduce_to_the_iso_281_form() {
    let c = 40_000.0;
    let f = 8_000.0;
    for (z, tol) in [(14, 0.02), (40, 0.02)] {
        let mut b = crb();
        b.rollers = z;
        b.pitch_diameter_mm = if z == 14 { 60.0 } else { 140.0 };
        let mut lives = Vec::new();
        for n in [1, 31, 61] {
            b.slices = n;
            let (q, ratio) = solve(&b, radial(f));
            let l = lamina_life(&b, c, &q, ratio, LaminaOptions::default()).unwrap();
            // the per-roller form, from the roller loads
            let rollers: Vec<f64> = q.chunks(n).map(|s| s.iter().sum()).collect();
            let mean =
                |w: f64| (rollers.iter().map(|x| x.powf(w)).sum::<f64>() / z as f64).powf(1.0 / w);
            let want = ((mean(4.0) / l.inner_capacity_n).powf(4.5)
                + (mean(4.5) / l.outer_capacity_n).powf(4.5))
            .powf(-8.0 / 9.0);
            assert!(
                (l.l10r_mrev / want - 1.0).abs() < 1e-9,
                "{} {want}",
                l.l10r_mrev
            );
            lives.push(l.l10r_mrev);
        }
        assert!((lives[1] / lives[0] - 1.0).abs() < 1e-9);
        assert!((lives[2] / lives[0] - 1.0).abs() < 1e-9);
        let iso = (c / (LAMBDA_NU_RADIAL * f)).powi(4);
        let ratio = lives[0] / iso;
        eprintln!(
            "Z = {z}: L10r = {:.4} Mrev, (C/(λν F_r))^4 = {iso:.4}, ratio {ratio:.4}",
            lives[0]
        );
        assert!((ratio - 1.0).abs() < tol, "Z = {z}: ratio {ratio}");
    }
}

/// A thrust bearing under a centric axial load: every roller carries `F_a/Z`, and
/// `L10r = 2^(−8/9) (Q_c Z/F_a)^4 = (C/(λν F_a))^4` exactly (λν = 0.73).
#[test]
fn thrust_bearing_under_axial_load_is_exact() {
    let mut b = RollerBearing::thrust(43.5, 18, 5.0, 5.5);
    b.roller_profile = Profile::Straight;
    let (c, f) = (30_000.0, 5_000.0);
    let l = life(
        &b,
        c,
        RingLoad::forces([0.0, 0.0, f, 0.0, 0.0]),
        LaminaOptions::default(),
    );
    let want = (c / (LAMBDA_NU_THRUST * f)).powi(4);
    assert!((l / want - 1.0).abs() < 1e-9, "{l} {want}");
}

/// Proportional loading with a fixed load zone (straight rollers, zero clearance: the slice
/// law is homogeneous, ε stays 0.5 for a CRB and F_a/F_r fixes ε of a TRB): the slice loads
/// scale with the load, so `L10r ∝ F^(−4)` exactly (the line-contact exponent of the lamina
/// method; ISO 281's 10/3 is a compromise exponent of the basic rating life, not the
/// lamina law).
#[test]
fn lamina_life_scales_with_the_minus_fourth_power_of_the_load() {
    let trb = {
        let mut b = RollerBearing::tapered(54.0, 23, 6.5, 13.66, 0.2473, 0.1950);
        b.roller_profile = Profile::Straight;
        b
    };
    let loads = [
        (crb(), [5_000.0, 0.0, 0.0]),
        (trb, [4_000.0, 1_500.0, 3_000.0]),
    ];
    for (b, f) in loads {
        let at = |s: f64| {
            let l = RingLoad::forces([s * f[0], s * f[1], s * f[2], 0.0, 0.0]).with_tilts_held();
            life(&b, 50_000.0, l, LaminaOptions::default())
        };
        let (l1, l2) = (at(1.0), at(2.5));
        let exponent = (l2 / l1).ln() / 2.5f64.ln();
        assert!((exponent + 4.0).abs() < 1e-8, "{exponent}");
    }
}

/// Misalignment lowers the life: a CRB with the ISO profile under a radial load, the inner
/// ring tilted by 0, 0.5, 1, 2 mrad about the y axis (normal to the load, so that the
/// most loaded rollers see it): L10r falls monotonically.
#[test]
fn misalignment_lowers_the_life() {
    let b = RollerBearing::cylindrical(60.0, 14, 10.0, 12.0);
    let mut lives = Vec::new();
    for tilt in [0.0, 5e-4, 1e-3, 2e-3] {
        let mut load = radial(10_000.0);
        load.dofs[4] = Dof::Displacement(tilt);
        lives.push(life(&b, 40_000.0, load, LaminaOptions::default()));
    }
    eprintln!("L10r over the tilt 0, 0.5, 1, 2 mrad: {lives:?}");
    for w in lives.windows(2) {
        assert!(w[1] < w[0], "{lives:?}");
    }
    assert!(lives[3] < 0.7 * lives[0], "{lives:?}");
}

/// The edge factor as coded: 1 at the centre lamina, symmetric, `1 + 0.01/|ln 0.99250|`
/// = 2.328 at the outermost laminae whatever their count; with it, a straight roller's life
/// falls and depends on the slice count (why it is off by default).
#[test]
fn edge_factor_values() {
    for n in [31, 61] {
        assert_eq!(edge_factor(n / 2, n), 1.0);
        let end = 1.0 - 0.01 / (1.985f64 * 0.5).ln();
        assert!((edge_factor(0, n) - end).abs() < 1e-12);
        assert!((edge_factor(n - 1, n) - end).abs() < 1e-12);
        assert!((end - 2.3283).abs() < 1e-4, "{end}");
    }
    assert_eq!(edge_factor(0, 1), 1.0);
    let mut b = crb();
    let with = |b: &RollerBearing| {
        life(
            b,
            40_000.0,
            radial(8_000.0),
            LaminaOptions {
                edge_factor: true,
                ..Default::default()
            },
        )
    };
    let plain = life(&b, 40_000.0, radial(8_000.0), LaminaOptions::default());
    let l31 = with(&b);
    b.slices = 61;
    let l61 = with(&b);
    assert!(l31 < plain && l61 > l31, "{plain} {l31} {l61}");
}

/// The rotating ring takes the exponent 4, the stationary one 9/2: with the outer ring
/// rotating under a radial load the life changes (the outer ring's capacity is the larger).
#[test]
fn rotating_outer_ring_changes_the_life() {
    let b = crb();
    let inner = life(&b, 40_000.0, radial(8_000.0), LaminaOptions::default());
    let outer = life(
        &b,
        40_000.0,
        radial(8_000.0),
        LaminaOptions {
            rotating: RotatingRing::Outer,
            edge_factor: false,
        },
    );
    assert!((outer / inner - 1.0).abs() > 1e-3, "{inner} {outer}");
}

#[test]
fn lamina_life_rejects_bad_input() {
    let b = crb();
    let n = b.rollers * b.slices;
    let e = lamina_life(&b, 1e4, &[1.0; 3], 1.0, LaminaOptions::default()).unwrap_err();
    assert!(e.to_string().contains("slice_loads"), "{e}");
    let mut q = vec![1.0; n];
    q[5] = f64::NAN;
    assert!(lamina_life(&b, 1e4, &q, 1.0, LaminaOptions::default()).is_err());
    let q = vec![0.0; n];
    let l = lamina_life(&b, 1e4, &q, 1.0, LaminaOptions::default()).unwrap();
    assert!(l.l10r_mrev.is_infinite() && l.reference_load_n == 0.0);
    let e = lamina_life(&b, -1.0, &q, 1.0, LaminaOptions::default()).unwrap_err();
    assert!(e.to_string().contains("dynamic_n"), "{e}");
}

/// `P_ref` is the load whose ISO 281 life equals L10r.
#[test]
fn reference_load_has_the_lamina_life() {
    let b = crb();
    let (q, r) = solve(&b, radial(8_000.0));
    let l = lamina_life(&b, 40_000.0, &q, r, LaminaOptions::default()).unwrap();
    let back = basic_rating_life(40_000.0, l.reference_load_n, Contact::Line);
    assert!((back / l.l10r_mrev - 1.0).abs() < 1e-12);
}

/// ISO 281's X, Y: a TRB at F_a/F_r above and below e = 1.5 tan α; a CRB and a thrust
/// bearing; a DGBB between two rows of the table; the 40° ACBB; and the refusals.
#[test]
fn equivalent_loads() {
    let a = 15f64.to_radians();
    let t = RatingType::Tapered {
        contact_angle_rad: a,
    };
    let e = 1.5 * a.tan();
    let lo = dynamic_equivalent_load(t, 1000.0, 0.9 * e * 1000.0, None).unwrap();
    assert_eq!((lo.load_n, lo.x, lo.y), (1000.0, 1.0, 0.0));
    let hi = dynamic_equivalent_load(t, 1000.0, 2000.0, None).unwrap();
    assert!((hi.load_n - (400.0 + 0.4 / a.tan() * 2000.0)).abs() < 1e-9);
    assert!((hi.e - e).abs() < 1e-15);
    // P is continuous at F_a/F_r = e only approximately: 0.4 + 0.4 cot α · 1.5 tan α = 1
    let at = dynamic_equivalent_load(t, 1000.0, e * 1000.0 * (1.0 + 1e-12), None).unwrap();
    assert!((at.load_n - 1000.0).abs() < 1e-6);
    let p0 = static_equivalent_load(t, 1000.0, 2000.0).unwrap();
    assert!((p0 - (500.0 + 0.22 / a.tan() * 2000.0)).abs() < 1e-9);
    assert_eq!(static_equivalent_load(t, 1000.0, 0.0).unwrap(), 1000.0);

    let c = dynamic_equivalent_load(RatingType::Cylindrical, 1000.0, 0.0, None).unwrap();
    assert_eq!(c.load_n, 1000.0);
    let th = dynamic_equivalent_load(RatingType::Thrust, 0.0, 3000.0, None).unwrap();
    assert_eq!(th.load_n, 3000.0);

    // F_a/C0 = 0.07, halfway between 0.056 and 0.084: e = 0.27, Y = 1.63
    let d =
        dynamic_equivalent_load(RatingType::DeepGrooveBall, 1000.0, 700.0, Some(10_000.0)).unwrap();
    assert!((d.e - 0.27).abs() < 1e-12 && (d.y - 1.63).abs() < 1e-12);
    assert!((d.load_n - (560.0 + 1.63 * 700.0)).abs() < 1e-9);
    let small =
        dynamic_equivalent_load(RatingType::DeepGrooveBall, 1000.0, 100.0, Some(10_000.0)).unwrap();
    assert_eq!(small.load_n, 1000.0); // 0.1 < e = 0.19..0.22
    let e = dynamic_equivalent_load(RatingType::DeepGrooveBall, 1000.0, 100.0, None).unwrap_err();
    assert!(e.to_string().contains("static_n"), "{e}");
    assert_eq!(
        static_equivalent_load(RatingType::DeepGrooveBall, 1000.0, 1000.0).unwrap(),
        1100.0
    );

    let ac = RatingType::AngularContactBall {
        contact_angle_rad: 40f64.to_radians(),
    };
    let p = dynamic_equivalent_load(ac, 1000.0, 2000.0, None).unwrap();
    assert!((p.load_n - (350.0 + 0.57 * 2000.0)).abs() < 1e-9);
    let e = dynamic_equivalent_load(
        RatingType::AngularContactBall {
            contact_angle_rad: 25f64.to_radians(),
        },
        1000.0,
        1000.0,
        None,
    )
    .unwrap_err();
    assert!(e.to_string().contains("contact_angle_deg"), "{e}");
    assert!(dynamic_equivalent_load(t, -1.0, 0.0, None).is_err());
    assert!(static_equivalent_load(t, 1.0, f64::NAN).is_err());
    assert!((basic_rating_life(2.0, 1.0, Contact::Point) - 8.0).abs() < 1e-12);
    assert!((basic_rating_life(2.0, 1.0, Contact::Line) - 2f64.powf(10.0 / 3.0)).abs() < 1e-12);
    assert!(basic_rating_life(2.0, 0.0, Contact::Line).is_infinite());
}

/// The pressure criterion's exponent against kontakt's Hertz contacts: the load s0 · Q
/// raises the contact's maximum pressure from p_max to the limit exactly (line contact:
/// p ∝ Q^(1/2); point contact: p ∝ Q^(1/3)); a wrong exponent misses by 26 % or more.
#[test]
fn static_safety_exponent_matches_hertz() {
    let s = ElasticMaterial::STEEL;
    let line = LineContact::new(5.0, 25.0, s, s).unwrap();
    let q = 800.0; // N/mm
    let p = line.solve(q).unwrap().max_pressure;
    let s0 = static_safety_from_pressure(ROLLER_PRESSURE_LIMIT_MPA, p, Contact::Line).unwrap();
    let p_at = line.solve(q * s0).unwrap().max_pressure;
    assert!(
        (p_at / ROLLER_PRESSURE_LIMIT_MPA - 1.0).abs() < 1e-12,
        "{p_at}"
    );

    let ball = HertzPointContact::new(PointGeometry::sphere_on_flat(4.0).unwrap(), s, s).unwrap();
    let qb = 500.0;
    let pb = ball.solve_force(qb).unwrap().max_pressure;
    let s0b = static_safety_from_pressure(BALL_PRESSURE_LIMIT_MPA, pb, Contact::Point).unwrap();
    let pb_at = ball.solve_force(qb * s0b).unwrap().max_pressure;
    assert!(
        (pb_at / BALL_PRESSURE_LIMIT_MPA - 1.0).abs() < 1e-9,
        "{pb_at}"
    );
    assert!(static_safety_from_pressure(4000.0, 0.0, Contact::Line).is_none());
}

/// A 6205-class DGBB (the example's internal data) with zero clearance.
fn dgbb() -> crate::geometry::BallBearing {
    crate::geometry::BallBearing::deep_groove(38.5, 9, 7.938, [0.52, 0.53])
}

fn ball_loads(b: &crate::geometry::BallBearing, f: f64) -> Vec<f64> {
    let mut s = crate::ball_equilibrium::BallBearingSolver::new(b.clone()).unwrap();
    let sol = s.solve(&radial(f)).unwrap();
    assert!(sol.status.converged());
    s.ball_loads().iter().map(|q| q.load_n).collect()
}

/// The ball raceway capacities recombine to C with Lundberg-Palmgren's point-contact
/// exponent e = 10/9: `C = (C_1^(−10/3) + C_2^(−10/3))^(−3/10)`, and `Q_ci/Q_ce = ρ`.
#[test]
fn ball_raceway_capacities_recombine_to_the_dynamic_capacity() {
    let b = dgbb();
    for alpha in [0.0, 40f64.to_radians()] {
        let c = 14_000.0;
        let (qi, qe) = ball_raceway_capacities(&b, alpha, c).unwrap();
        let zc = b.balls as f64 * alpha.cos().powf(0.7);
        let (c1, c2) = (
            BALL_RATIO_ROTATING * zc * qi,
            BALL_RATIO_STATIONARY * zc * qe,
        );
        let back = (c1.powf(-10.0 / 3.0) + c2.powf(-10.0 / 3.0)).powf(-0.3);
        assert!((back / c - 1.0).abs() < 1e-12, "{back}");
        let g = b.ball_diameter_mm * alpha.cos() / b.pitch_diameter_mm;
        let rho = ((1.0 - g) / (1.0 + g)).powf(1.72)
            * (0.52_f64 * (2.0 * 0.53 - 1.0) / (0.53 * (2.0 * 0.52 - 1.0))).powf(0.41);
        assert!((qi / qe / rho - 1.0).abs() < 1e-12);
    }
    assert!(ball_raceway_capacities(&b, -0.1, 1e4).is_err());
}

/// The standard's 0.407 and 0.389 are `J_r/J_1` and `J_r/J_2` of point contact (load
/// exponent 3/2) at ε = 0.5, with the equivalent-load exponents 3 (rotating) and 10/3
/// (stationary): our quadrature gives 0.40681 and 0.38954 (0.05 % and 0.14 % off).
#[test]
fn the_standards_ball_ratios_are_sjovall_integrals() {
    let m = 200_000;
    let (mut jr, mut j1, mut j2) = (0.0, 0.0, 0.0);
    for i in 0..m {
        let psi = -PI + 2.0 * PI * (i as f64 + 0.5) / m as f64;
        let q = relative_load(psi, 0.5, 1.5);
        jr += q * psi.cos();
        j1 += q.powi(3);
        j2 += q.powf(10.0 / 3.0);
    }
    let jr = jr / m as f64;
    let (a1, a2) = (
        jr / (j1 / m as f64).powf(1.0 / 3.0),
        jr / (j2 / m as f64).powf(0.3),
    );
    eprintln!("point contact: J_r/J_1 = {a1:.5}, J_r/J_2 = {a2:.5}");
    assert!((a1 / BALL_RATIO_ROTATING - 1.0).abs() < 2e-3, "{a1}");
    assert!((a2 / BALL_RATIO_STATIONARY - 1.0).abs() < 2e-3, "{a2}");
}

/// DGBB, zero clearance, pure radial load (α = 0 stays 0, ε = 0.5): the ball law is
/// homogeneous, so `L10r ∝ F_r^(−3)` exactly, ISO 281's ball exponent; and with the
/// standard's ratios equal to the integrals `L10r = (C/F_r)^3`. For Z = 9 the discrete
/// ratios (0.4053, 0.3882) are 0.4 % and 0.2 % below the standard's 0.407 and 0.389, which
/// lowers the life by about `(1 − 0.004)^3 = 0.988`: measured 0.9882; tolerance 2 %.
#[test]
fn ball_reference_life_reduces_to_the_iso_281_form_and_scales_with_the_cube() {
    let b = dgbb();
    let c = 14_000.0;
    let at = |f: f64| {
        ball_reference_life(&b, 0.0, c, &ball_loads(&b, f), RotatingRing::Inner)
            .unwrap()
            .l10r_mrev
    };
    let (l1, l2) = (at(2_000.0), at(5_000.0));
    let exponent = (l2 / l1).ln() / 2.5f64.ln();
    assert!((exponent + 3.0).abs() < 1e-8, "{exponent}");
    // the discrete ratios of the 9 balls at ε = 0.5 (phase 0)
    let z = b.balls;
    let q: Vec<f64> = (0..z)
        .map(|j| relative_load(2.0 * PI * j as f64 / z as f64, 0.5, 1.5))
        .collect();
    let jr = (0..z)
        .map(|j| q[j] * (2.0 * PI * j as f64 / z as f64).cos())
        .sum::<f64>()
        / z as f64;
    let m = |w: f64| (q.iter().map(|x| x.powf(w)).sum::<f64>() / z as f64).powf(1.0 / w);
    let (a1, a2) = (jr / m(3.0), jr / m(10.0 / 3.0));
    let l = at(2_000.0);
    let iso = (c / 2_000.0f64).powi(3);
    eprintln!(
        "Z = 9: L10r = {l:.3} Mrev, (C/F_r)^3 = {iso:.3}, ratio {:.4}; discrete J_r/J_1 = {a1:.4}, J_r/J_2 = {a2:.4}",
        l / iso
    );
    assert!((l / iso - 1.0).abs() < 0.02, "{}", l / iso);
    let e = ball_reference_life(&b, 0.0, c, &[1.0; 3], RotatingRing::Inner).unwrap_err();
    assert!(e.to_string().contains("ball_loads"), "{e}");
}
