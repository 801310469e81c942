//! Validation of the ball-bearing equilibrium (docs/VALIDATION.md, ball bearing rows).
#![allow(clippy::unwrap_used)]

use super::*;
use crate::load_zone::{POINT_EXPONENT, discrete, relative_load};
use crate::test_support::{
    assert_same_displacement, assert_same_load, assert_stiffness_matches_central_differences,
};
use kontakt::hertz::{HertzPointContact, PointGeometry};
use kontakt::material::ElasticMaterial;

/// A 6205-class deep-groove ball bearing: representative internal data, not a
/// manufacturer's (d_m 38.5 mm, 9 balls of 7.938 mm, f_i 0.52, f_o 0.53).
fn dgbb() -> BallBearing {
    BallBearing::deep_groove(38.5, 9, 7.938, [0.52, 0.53])
}

/// A 7205-class angular-contact ball bearing (representative: d_m 38.5 mm, 12 balls of
/// 7.938 mm, f_i 0.52, f_o 0.53, α0 = 40°).
fn acbb() -> BallBearing {
    BallBearing::angular_contact(38.5, 12, 7.938, [0.52, 0.53], 40f64.to_radians())
}

fn rel(a: f64, b: f64) -> f64 {
    (a - b).abs() / b.abs()
}

/// Harris's pure axial relation `F_a = Z K (B D)^1.5 sin α (cos α0/cos α − 1)^1.5`, solved
/// for α by a safeguarded scalar Newton (bisection when a step leaves the bracket).
fn harris_axial_angle(fa: f64, z: f64, k: f64, bd: f64, alpha0: f64) -> f64 {
    let c0 = alpha0.cos();
    let g = |a: f64| {
        let c = c0 / a.cos() - 1.0;
        let dc = c0 * a.sin() / (a.cos() * a.cos());
        let v = z * k * bd.powf(1.5) * a.sin() * c.powf(1.5) - fa;
        let dv = z * k * bd.powf(1.5) * (a.cos() * c.powf(1.5) + a.sin() * 1.5 * c.sqrt() * dc);
        (v, dv)
    };
    let (mut lo, mut hi) = (alpha0, 0.5 * PI - 1e-9);
    let mut a = 0.5 * (lo + hi);
    for _ in 0..200 {
        let (v, dv) = g(a);
        if v > 0.0 {
            hi = a;
        } else {
            lo = a;
        }
        let next = a - v / dv;
        let next = if next > lo && next < hi {
            next
        } else {
            0.5 * (lo + hi)
        };
        if (next - a).abs() < 1e-16 {
            break;
        }
        a = next;
    }
    a
}

/// Also a deep-groove bearing with 20 µm clearance, whose free contact angle
/// `acos(1 − P_d/(2 B D))` (12.89°) enters the same relation.
#[test]
fn acbb_pure_axial_load_follows_harris_closed_form() {
    let mut dg = dgbb();
    dg.clearance_mm = 0.02;
    for b in [acbb(), dg] {
        let (z, bd, a0) = (
            b.balls as f64,
            b.centre_distance_mm(),
            b.free_contact_angle(),
        );
        let mut s = BallBearingSolver::new(b).unwrap();
        let k = s.ball_stiffness();
        for fa in [10.0, 300.0, 3_000.0, 20_000.0] {
            let sol = s
                .solve(&RingLoad::forces([0.0, 0.0, fa, 0.0, 0.0]))
                .unwrap();
            assert!(sol.status.converged(), "{sol:?}");
            let alpha = harris_axial_angle(fa, z, k, bd, a0);
            let q = k * (bd * (a0.cos() / alpha.cos() - 1.0)).powf(1.5);
            // the closed form's own consistency: Z Q sin α = F_a
            assert!(rel(z * q * alpha.sin(), fa) < 1e-12);
            for ball in s.ball_loads() {
                assert!(
                    (ball.contact_angle_rad - alpha).abs() < 1e-9,
                    "F_a {fa}: {} vs {alpha}",
                    ball.contact_angle_rad
                );
                assert!(
                    rel(ball.load_n, q) < 1e-9,
                    "F_a {fa}: {} vs {q}",
                    ball.load_n
                );
            }
            let u = sol.displacement;
            assert!(u[0].abs() < 1e-12 && u[1].abs() < 1e-12 && u[3].abs() < 1e-14);
        }
    }
}

#[test]
fn dgbb_radial_load_reproduces_the_point_contact_sjovall_sums() {
    let n = POINT_EXPONENT;
    for clearance in [-0.004, 0.0, 0.005, 0.02] {
        for fr in [200.0, 5_000.0] {
            let mut b = dgbb();
            b.clearance_mm = clearance;
            let z = b.balls;
            let mut s = BallBearingSolver::new(b).unwrap();
            let sol = s
                .solve(&RingLoad::forces([fr, 0.0, 0.0, 0.0, 0.0]))
                .unwrap();
            assert!(sol.status.converged(), "{sol:?}");
            // the contact angle stays 0 (symmetric groove, no axial load): the load zone
            // of rigid rings, ε = (δ_r − P_d/2)/(2 δ_r)
            let dr = sol.displacement[0];
            let eps = (dr - 0.5 * clearance) / (2.0 * dr);
            let j = discrete(eps, n, z, 0.0).unwrap();
            let q_max = fr / (z as f64 * j.j_r);
            let balls = s.ball_loads();
            assert!(
                rel(balls[0].load_n, q_max) < 1e-9,
                "P_d {clearance} F {fr}: {} vs {q_max}",
                balls[0].load_n
            );
            for ball in balls {
                assert!(ball.contact_angle_rad.abs() < 1e-12, "{ball:?}");
                let want = q_max * relative_load(ball.azimuth_rad, eps, n);
                assert!(
                    (ball.load_n - want).abs() < 1e-9 * q_max,
                    "{ball:?} vs {want}"
                );
            }
            if clearance == 0.0 {
                // zero clearance: ε = 1/2 exactly; 1/J_r for 9 balls is near 4.37
                assert!((eps - 0.5).abs() < 1e-12, "{eps}");
                let factor = z as f64 * q_max / fr;
                assert!((factor - 4.37).abs() < 0.1, "{factor}");
            }
        }
    }
}

/// The round-trip case: an angular-contact bearing in all five degrees of freedom.
fn round_trip_case() -> (BallBearingSolver, [f64; 5]) {
    let s = BallBearingSolver::new(acbb()).unwrap();
    (s, [0.004, -0.002, 0.015, 1e-4, -2e-4])
}

#[test]
fn equilibrium_residual_and_round_trip() {
    let (mut s, u) = round_trip_case();
    let (f, _) = s.load_at(u);
    let sol = s.solve(&RingLoad::forces(f)).unwrap();
    assert!(sol.status.converged(), "{sol:?}");
    let r = 0.5 * s.bearing().pitch_diameter_mm;
    let (g, _) = s.load_at(sol.displacement);
    assert_same_load(&g, &f, r, 1e-9);
    assert_same_displacement(&sol.displacement, &u);
    assert!(sol.status.iterations <= 15, "{sol:?}");
    let again = s
        .solve_from(&RingLoad::forces(f), sol.displacement)
        .unwrap();
    assert!(
        again.status.converged() && again.status.iterations <= 1,
        "{again:?}"
    );
}

#[test]
fn stiffness_matches_central_differences() {
    for (b, u) in [
        (acbb(), [0.004, -0.002, 0.015, 1e-4, -2e-4]),
        (dgbb(), [0.01, 0.003, 0.02, -2e-4, 1e-4]),
    ] {
        let mut s = BallBearingSolver::new(b).unwrap();
        assert_stiffness_matches_central_differences(|u| s.load_at(u), u);
    }
}

#[test]
fn mirrored_loads_give_mirrored_solutions() {
    // y → −y (the balls at ±ψ): (Fx, −Fy, Fz, −Mx, My); z → −z on the deep groove:
    // (Fx, Fy, −Fz, −Mx, −My)
    let load = [3_000.0, 800.0, 1_200.0, 20_000.0, -15_000.0];
    let mut s = BallBearingSolver::new(dgbb()).unwrap();
    let a = s.solve(&RingLoad::forces(load)).unwrap();
    assert!(a.status.converged(), "{a:?}");
    let qa: Vec<BallLoad> = s.ball_loads().to_vec();
    let zb = qa.len();
    let y_mirror = [1.0, -1.0, 1.0, -1.0, 1.0];
    let z_mirror = [1.0, 1.0, -1.0, -1.0, -1.0];
    for (m, ball_map, angle_sign) in [(y_mirror, true, 1.0), (z_mirror, false, -1.0)] {
        let lm: [f64; 5] = std::array::from_fn(|i| load[i] * m[i]);
        let b = s.solve(&RingLoad::forces(lm)).unwrap();
        assert!(b.status.converged(), "{b:?}");
        for (i, (mi, (ub, ua))) in m
            .iter()
            .zip(b.displacement.iter().zip(a.displacement))
            .enumerate()
        {
            let tol = if i < 3 { 1e-12 } else { 1e-14 };
            assert!((ub - mi * ua).abs() < tol, "{i}");
        }
        for (j, qb) in s.ball_loads().iter().enumerate() {
            let jm = if ball_map { (zb - j) % zb } else { j };
            assert!((qb.load_n - qa[jm].load_n).abs() < 1e-9 * a.max_ball_load_n);
            if qb.load_n > 0.0 {
                assert!(
                    (qb.contact_angle_rad - angle_sign * qa[jm].contact_angle_rad).abs() < 1e-10
                );
            }
        }
    }
}

#[test]
fn max_pressure_of_the_most_loaded_ball_is_kontakts_hertz() {
    for (b, load) in [
        (dgbb(), [6_000.0, 0.0, 0.0, 0.0, 0.0]),
        (acbb(), [2_000.0, 0.0, 5_000.0, 0.0, 0.0]),
    ] {
        let (dm, d, fi, fo) = (
            b.pitch_diameter_mm,
            b.ball_diameter_mm,
            b.inner_osculation,
            b.outer_osculation,
        );
        let alpha = b.stiffness_contact_angle();
        let mut s = BallBearingSolver::new(b).unwrap();
        let sol = s.solve(&RingLoad::forces(load).with_tilts_held()).unwrap();
        assert!(sol.status.converged(), "{sol:?}");
        let q = sol.max_ball_load_n;
        let steel = ElasticMaterial::new(210_000.0, 0.3).unwrap();
        let p = |r_roll: f64, f: f64| {
            let g = PointGeometry::new([0.5 * d; 2], [r_roll, -f * d], 0.0).unwrap();
            HertzPointContact::new(g, steel, steel)
                .unwrap()
                .solve_force(q)
                .unwrap()
                .max_pressure
        };
        let c = alpha.cos();
        let (pi, po) = (p(0.5 * (dm / c - d), fi), p(-0.5 * (dm / c + d), fo));
        assert!(
            rel(sol.max_pressure_mpa[0], pi) < 1e-12,
            "{} vs {pi}",
            sol.max_pressure_mpa[0]
        );
        assert!(
            rel(sol.max_pressure_mpa[1], po) < 1e-12,
            "{} vs {po}",
            sol.max_pressure_mpa[1]
        );
        // the inner raceway (convex along the rolling direction) is the more loaded one
        assert!(pi > po && pi > 1_000.0 && pi < 4_000.0, "{pi} {po}");
    }
}

#[test]
fn zero_load_preload_and_loads_that_cannot_be_carried() {
    // zero load with clearance: every ball lifted off, converged, zero force, a note
    let mut b = dgbb();
    b.clearance_mm = 0.01;
    let mut s = BallBearingSolver::new(b).unwrap();
    let sol = s.solve(&RingLoad::forces([0.0; 5])).unwrap();
    assert!(
        sol.status.converged() && sol.max_ball_load_n == 0.0,
        "{sol:?}"
    );
    assert_eq!(sol.note, Some("every ball is lifted off: zero load"));
    // radial preload P_d = −6 µm: every ball K_n (3 µm)^1.5
    let mut b = dgbb();
    b.clearance_mm = -0.006;
    let mut s = BallBearingSolver::new(b).unwrap();
    let sol = s.solve(&RingLoad::forces([0.0; 5])).unwrap();
    assert!(sol.status.converged(), "{sol:?}");
    let want = s.ball_stiffness() * 0.003f64.powf(1.5);
    for ball in s.ball_loads() {
        assert!(rel(ball.load_n, want) < 1e-12, "{ball:?} vs {want}");
    }
    // a negative axial force on an angular-contact bearing: refused, named
    let mut s = BallBearingSolver::new(acbb()).unwrap();
    let e = s
        .solve(&RingLoad::forces([0.0, 0.0, -100.0, 0.0, 0.0]))
        .unwrap_err()
        .to_string();
    assert!(
        e.starts_with("invalid load.fz_n = -100: expected a load >= 0 N"),
        "{e}"
    );
    let e = s
        .solve(&RingLoad::forces([f64::NAN, 0.0, 0.0, 0.0, 0.0]))
        .unwrap_err()
        .to_string();
    assert!(e.starts_with("invalid load.fx_n = NaN"), "{e}");
    // issue 28, bad input: a radial load without axial load: no ball can be loaded;
    // refused, named
    let e = s
        .solve(&RingLoad::forces([2_000.0, 0.0, 0.0, 0.0, 0.0]).with_tilts_held())
        .unwrap_err()
        .to_string();
    assert!(
        e.starts_with("invalid load.fz_n = 0: expected an axial load > 0 N"),
        "{e}"
    );
    // with enough axial load the same radial load is carried, every angle > 0
    let sol = s
        .solve(&RingLoad::forces([2_000.0, 0.0, 2_000.0, 0.0, 0.0]).with_tilts_held())
        .unwrap();
    assert!(sol.status.converged(), "{sol:?}");
    assert!(
        s.ball_loads()
            .iter()
            .all(|b| b.load_n == 0.0 || b.contact_angle_rad > 0.0)
    );
}

#[test]
fn converges_over_five_decades_of_load_with_moments() {
    let mut worst = 0;
    for (b, held, ratios) in [
        (
            dgbb(),
            false,
            [
                [1.0, 0.0, 0.0, 0.0, 0.0],
                [1.0, 0.0, 0.3, 0.0, 0.0],
                [0.0, 0.0, 1.0, 0.0, 0.0],
                [1.0, 0.5, -0.4, 5.0, -3.0],
                [0.0, 0.0, 0.0, 10.0, 0.0],
            ],
        ),
        (
            acbb(),
            true,
            [
                [0.0, 0.0, 1.0, 0.0, 0.0],
                [0.5, 0.0, 1.0, 0.0, 0.0],
                [1.0, 0.0, 1.5, 0.0, 0.0],
                [0.0, 0.0, 1.0, 1.5, 1.0],
                [0.0, 0.0, 1.0, 2.0, 0.0],
            ],
        ),
    ] {
        for clearance in [0.0, 0.015] {
            let mut b = b.clone();
            b.clearance_mm = clearance;
            let mut s = BallBearingSolver::new(b).unwrap();
            for scale in [1.0, 100.0, 10_000.0, 50_000.0] {
                for r in ratios {
                    let f: [f64; 5] = std::array::from_fn(|i| r[i] * scale);
                    // a single angular-contact row cannot balance the moment of its own
                    // forces under a radial load: the shaft holds the tilts (as for a TRB)
                    let mut load = RingLoad::forces(f);
                    if held && r[0] != 0.0 {
                        load = load.with_tilts_held();
                    }
                    let sol = s.solve(&load).unwrap();
                    assert!(sol.status.converged(), "{f:?} P_d {clearance}: {sol:?}");
                    assert!(sol.status.residual <= 1e-9);
                    worst = worst.max(sol.status.iterations);
                }
            }
        }
    }
    eprintln!("worst iterations {worst}");
    assert!(worst <= 40, "{worst}");
}

/// The ring's rigid motion at the inner groove centres against an independent 3-D
/// evaluation: the exact rotation (Rodrigues) of the centre `c_i0 = (ℜ_i e_r, z_i)` by
/// θ = (θx, θy, 0) plus the translation, projected on the ball's axial plane. At θ ≈ 1e-4
/// rad the linearised approach agrees to second order (≤ 1e-6 mm here, measured 1.5e-7);
/// a sign slip of the tilt's radial term (θ × c_i0)·e_r moves it by 2.2e-5 mm. The moment
/// of the ball loads is `Σ c_i0 × Q n` to 1e-9.
#[test]
fn tilt_kinematics_and_moments_match_an_independent_rigid_body_evaluation() {
    let b = acbb();
    let (dm, d, fi) = (b.pitch_diameter_mm, b.ball_diameter_mm, b.inner_osculation);
    let [ar, az] = b.unloaded_centre_offset();
    let a0 = b.centre_distance_mm();
    let alpha0 = b.contact_angle_rad;
    let mut s = BallBearingSolver::new(b).unwrap();
    let u = [0.003, -0.001, 0.012, 1.2e-4, -0.8e-4];
    let sol = s.solve(&RingLoad::displacements(u)).unwrap();
    let lever = (fi - 0.5) * d;
    let (pr, pz) = (0.5 * dm + lever * alpha0.cos(), lever * alpha0.sin());
    let th = [u[3], u[4], 0.0];
    let angle = (th[0] * th[0] + th[1] * th[1]).sqrt();
    let axis = [th[0] / angle, th[1] / angle, 0.0];
    let cross = |a: [f64; 3], b: [f64; 3]| {
        [
            a[1] * b[2] - a[2] * b[1],
            a[2] * b[0] - a[0] * b[2],
            a[0] * b[1] - a[1] * b[0],
        ]
    };
    let dot = |a: [f64; 3], b: [f64; 3]| a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
    let mut moment = [0.0; 3];
    let mut worst: f64 = 0.0;
    for ball in s.ball_loads() {
        let (sp, cp) = ball.azimuth_rad.sin_cos();
        let (er, ez) = ([cp, sp, 0.0], [0.0, 0.0, 1.0]);
        let c0 = [pr * cp, pr * sp, pz];
        // Rodrigues: v cos φ + (k × v) sin φ + k (k·v)(1 − cos φ)
        let kxv = cross(axis, c0);
        let kv = dot(axis, c0);
        let rot: [f64; 3] = std::array::from_fn(|i| {
            c0[i] * angle.cos() + kxv[i] * angle.sin() + axis[i] * kv * (1.0 - angle.cos())
        });
        let ci: [f64; 3] = std::array::from_fn(|i| rot[i] + u[i]);
        let co: [f64; 3] = std::array::from_fn(|i| c0[i] - ar * er[i] - az * ez[i]);
        let a: [f64; 3] = std::array::from_fn(|i| ci[i] - co[i]);
        let (a_r, a_z) = (dot(a, er), dot(a, ez));
        let approach = a_r.hypot(a_z) - a0;
        worst = worst.max((approach - ball.approach_mm).abs());
        let (sa, ca) = ball.contact_angle_rad.sin_cos();
        let force: [f64; 3] = std::array::from_fn(|i| ball.load_n * (ca * er[i] + sa * ez[i]));
        let m = cross(c0, force);
        for i in 0..3 {
            moment[i] += m[i];
        }
    }
    assert!(worst < 1e-6, "{worst}");
    let scale = sol.load[3].hypot(sol.load[4]);
    assert!(
        (moment[0] - sol.load[3]).abs() < 1e-9 * scale,
        "{moment:?} {:?}",
        sol.load
    );
    assert!(
        (moment[1] - sol.load[4]).abs() < 1e-9 * scale,
        "{moment:?} {:?}",
        sol.load
    );
    eprintln!("tilt kinematics: worst approach difference {worst:e} mm");
}
