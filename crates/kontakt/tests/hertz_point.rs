//! The exact point-contact solution against independent closed forms, an independent
//! Legendre-form oracle, scaling laws and invariances.
//!
//! Tolerances: closed forms are evaluated with the same IEEE arithmetic, so agreement to
//! 1e-12 relative is expected (a few ulps through cbrt, sqrt and the elliptic integrals).
//! The Legendre oracle bisects the shape equation to 1e-15 in e; 1e-10 covers the
//! precision loss of m = e² in Legendre's form at moderate eccentricity.

#![allow(clippy::unwrap_used)] // test helpers: a panic is a test failure with its message

use approx::assert_relative_eq;
use kontakt::geometry::RelativeCurvature;
use kontakt::hertz::{HertzPointContact, PointGeometry, curvature_ratio};
use kontakt::material::{ElasticMaterial, effective_modulus};
use proptest::prelude::*;
use std::f64::consts::PI;

const INF: f64 = f64::INFINITY;
const STEEL: ElasticMaterial = ElasticMaterial::STEEL;

/// Johnson's eqs (56a-c) solved with Legendre's K(m), E(m) and plain bisection on e:
/// an implementation path independent of the Carlson form used by the library.
fn legendre_oracle(a_coef: f64, b_coef: f64, e_star: f64, force: f64) -> [f64; 4] {
    let ratio = |e: f64| {
        let m = e * e;
        let (k, ee) = (ellip::ellipk(m).unwrap(), ellip::ellipe(m).unwrap());
        let ab2 = 1.0 / (1.0 - m); // (a/b)^2
        (ab2 * ee - k) / (k - ee)
    };
    let target = b_coef / a_coef;
    let (mut lo, mut hi) = (1e-6_f64, 1.0 - 1e-15);
    for _ in 0..200 {
        let mid = 0.5 * (lo + hi);
        if ratio(mid) < target {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    let e = 0.5 * (lo + hi);
    let m = e * e;
    let kp = (1.0 - m).sqrt();
    let (k, ee) = (ellip::ellipk(m).unwrap(), ellip::ellipe(m).unwrap());
    // A = (p0/E*)(b/(a^2 e^2))(K - E) with p0 = 3F/(2 pi a b): A = 3F(K-E)/(2 pi E* a^3 e^2).
    let a = (3.0 * force * (k - ee) / (2.0 * PI * e_star * a_coef * m)).cbrt();
    let b = kp * a;
    let p0 = 3.0 * force / (2.0 * PI * a * b);
    let delta = p0 * b * k / e_star;
    [a, b, p0, delta]
}

fn solve(
    r1: [f64; 2],
    r2: [f64; 2],
    deg: f64,
    m1: ElasticMaterial,
    m2: ElasticMaterial,
    f: f64,
) -> kontakt::hertz::HertzPointSolution {
    let g = PointGeometry::new(r1, r2, deg.to_radians()).unwrap();
    HertzPointContact::new(g, m1, m2)
        .unwrap()
        .solve_force(f)
        .unwrap()
}

/// Sphere on plane and sphere on sphere: a = (3FR/4E*)^(1/3), p0 = 3F/(2 pi a^2),
/// delta = a^2/R (Johnson 1982 eqs 13-15).
#[test]
fn spheres_match_closed_form() {
    let e_star = effective_modulus(&STEEL, &STEEL);
    for (r1, r2, r) in [
        (10.0, INF, 10.0),
        (1000.0, INF, 1000.0),
        (10.0, 30.0, 7.5),
        (10.0, -30.0, 15.0), // sphere in a spherical cup
    ] {
        for f in [1.0, 100.0, 5000.0] {
            let s = solve([r1, r1], [r2, r2], 0.0, STEEL, STEEL, f);
            let a = (3.0 * f * r / (4.0 * e_star)).cbrt();
            assert_relative_eq!(s.semi_axes[0], a, max_relative = 1e-13);
            assert_relative_eq!(s.semi_axes[1], a, max_relative = 1e-13);
            assert_relative_eq!(
                s.max_pressure,
                3.0 * f / (2.0 * PI * a * a),
                max_relative = 1e-13
            );
            assert_relative_eq!(s.approach, a * a / r, max_relative = 1e-13);
            assert_relative_eq!(s.stiffness, 2.0 * a * e_star, max_relative = 1e-13);
        }
    }
}

/// Dissimilar materials: E* from eq. (5); glass lens on steel flat.
#[test]
fn dissimilar_materials_closed_form() {
    let glass = ElasticMaterial::new(70_000.0, 0.22).unwrap();
    let e_star: f64 = 1.0 / ((1.0 - 0.22 * 0.22) / 70_000.0 + 0.91 / 210_000.0);
    let s = solve([25.0, 25.0], [INF, INF], 0.0, glass, STEEL, 50.0);
    let a = (3.0 * 50.0 * 25.0 / (4.0 * e_star)).cbrt();
    assert_relative_eq!(s.semi_axes[0], a, max_relative = 1e-13);
    assert_relative_eq!(s.approach, a * a / 25.0, max_relative = 1e-13);
}

/// Crossed equal cylinders at angle theta: A, B = (1 -+ cos theta)/(2R); the ellipse
/// against the Legendre oracle. At 90 degrees the contact is a circle of a sphere of
/// radius R.
#[test]
fn crossed_cylinders_at_angles() {
    let r = 12.0;
    let e_star = effective_modulus(&STEEL, &STEEL);
    for deg in [20.0f64, 45.0, 60.0, 75.0, 90.0, 120.0] {
        let s = solve([INF, r], [INF, r], deg, STEEL, STEEL, 300.0);
        let c = deg.to_radians().cos().abs();
        let (a_coef, b_coef) = ((1.0 - c) / (2.0 * r), (1.0 + c) / (2.0 * r));
        if deg == 90.0 {
            let a = (3.0 * 300.0 * r / (4.0 * e_star)).cbrt();
            assert_relative_eq!(s.semi_axes[0], a, max_relative = 1e-12);
            assert_relative_eq!(s.semi_axes[1], a, max_relative = 1e-12);
            continue;
        }
        let [a, b, p0, d] = legendre_oracle(a_coef, b_coef, e_star, 300.0);
        assert_relative_eq!(s.semi_axes[0], a, max_relative = 1e-10);
        assert_relative_eq!(s.semi_axes[1], b, max_relative = 1e-10);
        assert_relative_eq!(s.max_pressure, p0, max_relative = 1e-10);
        assert_relative_eq!(s.approach, d, max_relative = 1e-10);
        // Major axis along the bisector of the acute angle between the cylinder axes.
        let expected = if deg <= 90.0 {
            deg / 2.0
        } else {
            deg / 2.0 + 90.0
        }
        .to_radians();
        let o = s.orientation;
        let diff = ((o - expected) / PI).round() * PI - (o - expected);
        assert!(diff.abs() < 1e-12, "{deg}: orientation {o} vs {expected}");
    }
}

/// A ball in a conformal groove (concave curvature): 6205 inner and outer race and a
/// tight groove, against the Legendre oracle.
#[test]
fn ball_in_conformal_groove() {
    let e_star = effective_modulus(&STEEL, &STEEL);
    for race in [[15.281, -4.128], [-23.219, -4.128], [20.0, -4.01]] {
        let s = solve([3.969, 3.969], race, 0.0, STEEL, STEEL, 1000.0);
        let k = RelativeCurvature::from_radii([3.969; 2], race, 0.0).unwrap();
        let [a, b, p0, d] = legendre_oracle(k.a_coef, k.b_coef, e_star, 1000.0);
        assert_relative_eq!(s.semi_axes[0], a, max_relative = 1e-10);
        assert_relative_eq!(s.semi_axes[1], b, max_relative = 1e-10);
        assert_relative_eq!(s.max_pressure, p0, max_relative = 1e-10);
        assert_relative_eq!(s.approach, d, max_relative = 1e-10);
        // The long axis lies across the rolling direction (along the groove's curvature).
        assert!((s.orientation.abs() - PI / 2.0).abs() < 1e-12);
    }
}

/// Thin ellipses approach the line contact: b = 2 p0 R''/E* (Johnson 1982 eq. 26) with
/// R'' = 1/(2B); the correction is O((b/a)^2 ln(a/b)).
#[test]
fn thin_ellipse_approaches_line_contact() {
    for ratio in [1e4, 1e6, 1e8] {
        let k = RelativeCurvature::from_tensor(2.0 / ratio, 2.0, 0.0).unwrap();
        let c = HertzPointContact::new(PointGeometry::from_curvature(k), STEEL, STEEL).unwrap();
        let s = c.solve_force(100.0).unwrap();
        let kp = s.semi_axes[1] / s.semi_axes[0];
        let line_b = 2.0 * s.max_pressure * (0.5 / k.b_coef) / c.e_star();
        let tol = 10.0 * kp * kp * (1.0 / kp).ln() + 1e-13;
        assert_relative_eq!(s.semi_axes[1], line_b, max_relative = tol);
    }
}

/// Pressure sampled on a grid integrates to the force and peaks at p0.
#[test]
fn sampled_pressure_integrates_to_force() {
    let g = PointGeometry::new([8.0, 30.0], [15.0, -90.0], 0.4).unwrap();
    let s = HertzPointContact::new(g, STEEL, STEEL)
        .unwrap()
        .solve_force(400.0)
        .unwrap();
    let h = 1.05 * s.semi_axes[0];
    let grid = kontakt::geometry::Grid2::centered(h, h, 801, 801).unwrap();
    let p = s.sample_pressure(&grid);
    let total: f64 = p.iter().sum::<f64>() * grid.cell_area();
    // Midpoint rule on a square-root edge: error ~ (cell/b)^1.5; ~0.1 % here.
    assert_relative_eq!(total, 400.0, max_relative = 2e-3);
    assert_relative_eq!(s.pressure_at(0.0, 0.0), s.max_pressure);
    let max = p.iter().cloned().fold(0.0, f64::max);
    assert!(max <= s.max_pressure && max > 0.99 * s.max_pressure);
    // Outside the ellipse along the major axis: zero.
    let (sn, cs) = s.orientation.sin_cos();
    assert_eq!(
        s.pressure_at(1.001 * s.semi_axes[0] * cs, 1.001 * s.semi_axes[0] * sn),
        0.0
    );
    let mut buf = vec![0.0; grid.len()];
    s.sample_pressure_into(&grid, &mut buf).unwrap();
    assert_eq!(buf, p);
    assert!(s.sample_pressure_into(&grid, &mut buf[1..]).is_err());
}

/// The circular case falls out of the general one exactly.
#[test]
fn circle_is_exact_special_case() {
    let g = PointGeometry::new([7.0, 7.0], [INF, INF], 0.3).unwrap();
    let c = HertzPointContact::new(g, STEEL, STEEL).unwrap();
    assert_eq!(c.axis_ratio(), 1.0);
    assert_eq!(c.shape_evaluations(), 0);
    assert_eq!(curvature_ratio(1.0).unwrap(), 1.0);
}

fn arb_radius() -> impl Strategy<Value = f64> {
    prop_oneof![(1.0f64..500.0), Just(INF)]
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(256))]

    /// Eccentricity inversion is robust from b/a = 1 down to 1e-4.
    #[test]
    fn eccentricity_inversion_round_trips(log_kp in -4.0f64..0.0) {
        let kp = 10f64.powf(log_kp);
        let r = curvature_ratio(kp).unwrap();
        let k = RelativeCurvature::from_tensor(1.0, r, 0.0).unwrap();
        let c = HertzPointContact::new(PointGeometry::from_curvature(k), STEEL, STEEL).unwrap();
        prop_assert!((c.axis_ratio() / kp - 1.0).abs() < 1e-12, "{} vs {}", c.axis_ratio(), kp);
        prop_assert!(c.shape_evaluations() <= 8);
    }

    /// a and p0 scale as F^(1/3), delta as F^(2/3); force-approach round-trips.
    #[test]
    fn scaling_laws_and_round_trip(
        r11 in 2.0f64..100.0, r12 in 2.0f64..100.0, r21 in arb_radius(), r22 in arb_radius(),
        theta in -3.0f64..3.0, f in 0.01f64..1e5, scale in 1.5f64..1000.0,
    ) {
        let g = PointGeometry::new([r11, r12], [r21, r22], theta).unwrap();
        let c = HertzPointContact::new(g, STEEL, STEEL).unwrap();
        let s1 = c.solve_force(f).unwrap();
        let s2 = c.solve_force(f * scale).unwrap();
        let t = scale.cbrt();
        prop_assert!((s2.semi_axes[0] / s1.semi_axes[0] / t - 1.0).abs() < 1e-12);
        prop_assert!((s2.max_pressure / s1.max_pressure / t - 1.0).abs() < 1e-12);
        prop_assert!((s2.approach / s1.approach / (t * t) - 1.0).abs() < 1e-12);
        let back = c.force_from_approach(s1.approach).unwrap();
        prop_assert!((back / f - 1.0).abs() < 1e-12);
        let sd = c.solve_approach(s1.approach).unwrap();
        prop_assert!((sd.max_pressure / s1.max_pressure - 1.0).abs() < 1e-12);
        // Stiffness equals the numerical derivative dF/d(delta).
        let h = 1e-6 * s1.approach;
        let num = (c.force_from_approach(s1.approach + h).unwrap()
            - c.force_from_approach(s1.approach - h).unwrap()) / (2.0 * h);
        prop_assert!((num / s1.stiffness - 1.0).abs() < 1e-6);
    }

    /// Swapping the bodies and rotating both by the same angle change nothing physical.
    #[test]
    fn swap_and_rotation_invariance(
        r11 in 2.0f64..100.0, r12 in 2.0f64..100.0, r21 in arb_radius(), r22 in arb_radius(),
        theta in -3.0f64..3.0, phi in -3.0f64..3.0,
    ) {
        let e = ElasticMaterial::new(120_000.0, 0.25).unwrap();
        let g = PointGeometry::new([r11, r12], [r21, r22], theta).unwrap();
        let s = HertzPointContact::new(g, STEEL, e).unwrap().solve_force(250.0).unwrap();
        let gs = PointGeometry::new([r21, r22], [r11, r12], -theta).unwrap();
        let ss = HertzPointContact::new(gs, e, STEEL).unwrap().solve_force(250.0).unwrap();
        for (x, y) in [
            (s.semi_axes[0], ss.semi_axes[0]), (s.semi_axes[1], ss.semi_axes[1]),
            (s.max_pressure, ss.max_pressure), (s.approach, ss.approach),
        ] {
            prop_assert!((x / y - 1.0).abs() < 1e-10, "{x} vs {y}");
        }
        // Rotate the summed curvature tensor by phi: A, B unchanged, orientation + phi.
        let k = g.curvature();
        let (sn, cs) = (k.orientation).sin_cos();
        let (kxx, kyy, kxy) = (
            2.0 * (k.a_coef * cs * cs + k.b_coef * sn * sn),
            2.0 * (k.a_coef * sn * sn + k.b_coef * cs * cs),
            2.0 * (k.a_coef - k.b_coef) * sn * cs,
        );
        let (sp, cp) = phi.sin_cos();
        let rxx = cp * cp * kxx - 2.0 * sp * cp * kxy + sp * sp * kyy;
        let ryy = sp * sp * kxx + 2.0 * sp * cp * kxy + cp * cp * kyy;
        let rxy = sp * cp * (kxx - kyy) + (cp * cp - sp * sp) * kxy;
        let kr = RelativeCurvature::from_tensor(rxx, ryy, rxy).unwrap();
        prop_assert!((kr.a_coef / k.a_coef - 1.0).abs() < 1e-9);
        prop_assert!((kr.b_coef / k.b_coef - 1.0).abs() < 1e-9);
        if k.b_coef / k.a_coef > 1.0 + 1e-6 {
            let d = kr.orientation - (k.orientation + phi);
            let wrapped = d - (d / PI).round() * PI;
            prop_assert!(wrapped.abs() < 1e-6, "orientation {} vs {}", kr.orientation, k.orientation + phi);
        }
    }

    /// Random finite inputs give a solution with finite fields or a clear error, never a
    /// panic or NaN.
    #[test]
    fn never_nan(
        r11 in -1e4f64..1e4, r12 in -1e4f64..1e4, r21 in -1e4f64..1e4, r22 in -1e4f64..1e4,
        theta in -10.0f64..10.0, f in -10.0f64..1e6,
    ) {
        if let Ok(g) = PointGeometry::new([r11, r12], [r21, r22], theta)
            && let Ok(c) = HertzPointContact::new(g, STEEL, STEEL)
            && let Ok(s) = c.solve_force(f)
        {
            for x in [s.semi_axes[0], s.semi_axes[1], s.max_pressure, s.approach, s.stiffness] {
                prop_assert!(x.is_finite() && x > 0.0);
            }
            prop_assert!(s.semi_axes[0] >= s.semi_axes[1]);
        }
    }
}

/// Every invalid field gives a clear error naming it.
#[test]
fn bad_input_is_named() {
    let e = PointGeometry::new([0.0, 1.0], [INF, INF], 0.0).unwrap_err();
    assert_eq!(e.field(), Some("body1.radii[0]"));
    let e = PointGeometry::new([1.0, 1.0], [INF, f64::NAN], 0.0).unwrap_err();
    assert_eq!(e.field(), Some("body2.radii[1]"));
    let e = PointGeometry::new([1.0, 1.0], [INF, INF], f64::INFINITY).unwrap_err();
    assert_eq!(e.field(), Some("angle"));
    // Concave radius smaller than the ball: the ball does not fit (not touching at a point).
    let e = PointGeometry::new([5.0, 5.0], [-4.9, -4.9], 0.0).unwrap_err();
    assert!(e.to_string().contains("conformal or separate"), "{e}");
    // Convex-on-concave with identical radii: conformal.
    assert!(PointGeometry::new([5.0, 5.0], [-5.0, -5.0], 0.0).is_err());
    let g = PointGeometry::sphere_on_flat(5.0).unwrap();
    assert!(PointGeometry::sphere_on_flat(-5.0).is_err());
    let c = HertzPointContact::new(g, STEEL, STEEL).unwrap();
    for f in [0.0, -1.0, f64::NAN, f64::INFINITY] {
        let e = c.solve_force(f).unwrap_err();
        assert_eq!(e.field(), Some("force"));
        assert!(c.approach_from_force(f).is_err());
        let e = c.solve_approach(f).unwrap_err();
        assert_eq!(e.field(), Some("approach"));
    }
    assert!(curvature_ratio(0.0).is_err());
    assert!(curvature_ratio(1.5).is_err());
}
