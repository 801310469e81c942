#![allow(clippy::unwrap_used)] // test helpers: a panic is a test failure with its message

//! Analytic surfaces and ray casting against independent checks.
//!
//! Tolerances: a hit point must lie on the surface to 1e-12 of the surface's size
//! (|signed distance| / size), which a few ulps of rounding in the coordinates meet with
//! a margin of ~100; a quartic solved in monomial form misses this by 6 orders of
//! magnitude on the R = 1000, r = 1 torus. Normals are compared with the central finite
//! difference of the implicit function (truncation ~h², h = 1e-5 size → 1e-7 tolerance).
//! The first-root oracle brackets sign changes of the signed distance on a fine uniform
//! sampling (step size/500) and bisects; it agrees to 1e-9 of the size.

use kontakt::geometry::{Material, PlacedSurface, Profile, Ray, Surface};
use nalgebra::{Isometry3, Point3, Translation3, UnitQuaternion, Vector3};
use proptest::prelude::*;
use std::f64::consts::{FRAC_PI_2, PI};

fn dir(cos_polar: f64, azimuth: f64) -> Vector3<f64> {
    let s = (1.0 - cos_polar * cos_polar).max(0.0).sqrt();
    Vector3::new(s * azimuth.cos(), s * azimuth.sin(), cos_polar)
}

fn ray(o: Point3<f64>, d: Vector3<f64>) -> Ray {
    Ray::new(o, d).unwrap()
}

/// Central-difference gradient of the implicit function.
fn fd_gradient(s: &Surface, p: &Point3<f64>, h: f64) -> Vector3<f64> {
    let mut g = Vector3::zeros();
    for k in 0..3 {
        let mut e = Vector3::zeros();
        e[k] = h;
        g[k] = (s.implicit(&(p + e)) - s.implicit(&(p - e))) / (2.0 * h);
    }
    g
}

/// First sign change of the signed distance along the ray in [t0, t1] by uniform sampling
/// and bisection (independent of the library's root finder).
fn oracle_first_root(s: &Surface, r: &Ray, t0: f64, t1: f64, step: f64) -> Option<f64> {
    oracle_first_root_where(s, r, t0, t1, step, |_| true)
}

/// As [`oracle_first_root`], counting only roots whose point satisfies `valid`.
fn oracle_first_root_where(
    s: &Surface,
    r: &Ray,
    t0: f64,
    t1: f64,
    step: f64,
    valid: impl Fn(&Point3<f64>) -> bool,
) -> Option<f64> {
    let f = |t: f64| s.signed_distance(&r.at(t));
    let mut a = t0;
    let mut fa = f(a);
    while a < t1 {
        let b = (a + step).min(t1);
        let fb = f(b);
        if fa == 0.0 {
            return Some(a);
        }
        if (fa > 0.0) != (fb > 0.0) {
            let (mut lo, mut hi, flo) = (a, b, fa);
            for _ in 0..200 {
                let mid = 0.5 * (lo + hi);
                let fm = f(mid);
                if (fm > 0.0) == (flo > 0.0) {
                    lo = mid;
                } else {
                    hi = mid;
                }
            }
            let t = 0.5 * (lo + hi);
            if valid(&r.at(t)) {
                return Some(t);
            }
        }
        a = b;
        fa = fb;
    }
    None
}

/// Every property of a hit that can be checked without knowing the answer.
fn check_hit(s: &Surface, r: &Ray, t_min: f64, t_max: f64, size: f64) -> Option<f64> {
    let hit = s.intersect(r, t_min, t_max)?;
    assert!(
        hit.t >= t_min && hit.t <= t_max,
        "t {} outside range",
        hit.t
    );
    let sd = s.signed_distance(&hit.point);
    assert!(
        sd.abs() <= 1e-12 * size,
        "off the surface by {sd:e} (size {size})"
    );
    let on_ray = (r.at(hit.t) - hit.point).norm();
    assert!(
        on_ray <= 1e-12 * (size + r.origin.coords.norm() + hit.t.abs()),
        "point not on the ray: {on_ray:e}"
    );
    assert!((hit.normal.norm() - 1.0).abs() < 1e-14);
    // The normal is the normalised gradient of the implicit function (finite difference).
    let h = 1e-5 * size;
    let g = fd_gradient(s, &hit.point, h);
    // (The implicit function of a surface of revolution is continued with the end radius
    // beyond the patch: no finite difference across an end.)
    let near_end = match s {
        Surface::Revolution(rev) => {
            let [z0, z1] = rev.z_range();
            hit.point.z < z0 + 2.0 * h || hit.point.z > z1 - 2.0 * h
        }
        _ => false,
    };
    if g.norm() > 0.0 && !near_end {
        let diff = (hit.normal.into_inner() - g.normalize()).norm();
        assert!(diff < 1e-6, "normal {:?} vs gradient {:?}", hit.normal, g);
    }
    // Outward: a step along the normal leaves the material.
    assert!(s.signed_distance(&(hit.point + hit.normal.into_inner() * 1e-6 * size)) > 0.0);
    Some(hit.t)
}

// ------------------------------------------------------------------------------------------
// Validation

#[test]
fn constructors_reject_degenerate_surfaces_with_the_field_and_range() {
    let e = Surface::sphere(0.0, Material::Inside).unwrap_err();
    assert_eq!(
        e.to_string(),
        "invalid radius = 0: expected a finite radius > 0 mm"
    );
    for r in [-1.0, f64::NAN, f64::INFINITY] {
        assert_eq!(
            Surface::sphere(r, Material::Outside).unwrap_err().field(),
            Some("radius")
        );
    }
    for a in [0.0, FRAC_PI_2, -0.1, 2.0, f64::NAN] {
        let e = Surface::cone(a, Material::Inside).unwrap_err();
        assert_eq!(e.field(), Some("half_angle"), "{a}");
        assert!(e.to_string().contains("(0, pi/2) rad"), "{e}");
    }
    assert!(Surface::cone(1e-9, Material::Inside).is_ok());
    assert!(Surface::cone(FRAC_PI_2 - 1e-9, Material::Inside).is_ok());
    assert_eq!(
        Surface::torus(-1.0, 1.0, Material::Inside)
            .unwrap_err()
            .field(),
        Some("major")
    );
    assert_eq!(
        Surface::torus(f64::NAN, 1.0, Material::Inside)
            .unwrap_err()
            .field(),
        Some("major")
    );
    assert_eq!(
        Surface::torus(2.0, 0.0, Material::Inside)
            .unwrap_err()
            .field(),
        Some("minor")
    );
    // A spindle torus is a valid solid but not a valid groove.
    assert!(Surface::torus(2.0, 14.0, Material::Inside).is_ok());
    let e = Surface::torus(2.0, 14.0, Material::Outside).unwrap_err();
    assert_eq!(e.field(), Some("minor"));
    assert!(
        e.to_string().contains("minor radius <= major = 2 mm"),
        "{e}"
    );
    assert!(Surface::torus(14.0, 14.0, Material::Outside).is_ok());
    assert!(Surface::torus(0.0, 3.0, Material::Inside).is_ok());
}

#[test]
fn profiles_are_validated() {
    let crowned = |radius, crown_radius, half_length| Profile::Crowned {
        radius,
        crown_radius,
        half_length,
    };
    let field = |p| {
        Surface::revolution(p, Material::Inside)
            .unwrap_err()
            .field()
            .map(str::to_owned)
    };
    assert_eq!(
        field(crowned(0.0, 100.0, 5.0)).as_deref(),
        Some("profile.radius")
    );
    assert_eq!(
        field(crowned(10.0, 0.0, 5.0)).as_deref(),
        Some("profile.crown_radius")
    );
    assert_eq!(
        field(crowned(10.0, 4.0, 5.0)).as_deref(),
        Some("profile.half_length")
    );
    assert_eq!(
        field(crowned(0.1, 5.1, 5.0)).as_deref(),
        Some("profile.radius")
    );
    assert!(Surface::revolution(crowned(10.0, f64::INFINITY, 5.0), Material::Inside).is_ok());
    let log = |end_drop, scale| Profile::Logarithmic {
        radius: 10.0,
        half_length: 5.0,
        end_drop,
        scale,
    };
    assert_eq!(field(log(-0.1, 0.01)).as_deref(), Some("profile.end_drop"));
    assert_eq!(field(log(10.0, 0.01)).as_deref(), Some("profile.end_drop"));
    assert_eq!(field(log(0.01, 0.0)).as_deref(), Some("profile.scale"));
    let table = |z: Vec<f64>, rho: Vec<f64>| Profile::Table { z, rho };
    assert_eq!(
        field(table(vec![0.0, 1.0, 2.0], vec![1.0; 3])).as_deref(),
        Some("profile.z")
    );
    assert_eq!(
        field(table(vec![0.0, 1.0, 1.0, 2.0], vec![1.0; 4])).as_deref(),
        Some("profile.z[2]")
    );
    assert_eq!(
        field(table(vec![0.0, 1.0, 2.0, 3.0], vec![1.0; 3])).as_deref(),
        Some("profile.rho")
    );
    assert_eq!(
        field(table(vec![0.0, 1.0, 2.0, 3.0], vec![1.0, 0.0, 1.0, 1.0])).as_deref(),
        Some("profile.rho[1]")
    );
    // Positive at the points but the spline overshoots below zero in between.
    assert_eq!(
        field(table(
            vec![0.0, 1.0, 1.1, 2.0, 3.0],
            vec![5.0, 0.01, 5.0, 5.0, 5.0]
        ))
        .as_deref(),
        Some("profile.rho")
    );
}

#[test]
fn placed_surface_rejects_a_nan_pose() {
    let s = Surface::sphere(1.0, Material::Inside).unwrap();
    let bad = Isometry3::from_parts(
        Translation3::new(0.0, f64::NAN, 0.0),
        UnitQuaternion::identity(),
    );
    let e = PlacedSurface::new(s.clone(), bad).unwrap_err();
    assert_eq!(e.field(), Some("pose"));
    assert!(e.to_string().contains("NaN"), "{e}");
    let bad_rot = Isometry3::from_parts(
        Translation3::identity(),
        UnitQuaternion::new_unchecked(nalgebra::Quaternion::new(f64::NAN, 0.0, 0.0, 0.0)),
    );
    assert_eq!(
        PlacedSurface::new(s, bad_rot).unwrap_err().field(),
        Some("pose")
    );
}

#[test]
fn ray_constructor_validates() {
    assert_eq!(
        Ray::new(Point3::origin(), Vector3::zeros())
            .unwrap_err()
            .field(),
        Some("dir")
    );
    assert_eq!(
        Ray::new(Point3::new(f64::NAN, 0.0, 0.0), Vector3::x())
            .unwrap_err()
            .field(),
        Some("origin")
    );
}

#[cfg(feature = "serde")]
#[test]
fn surfaces_round_trip_through_toml() {
    let cases = [
        Surface::plane(Material::Outside),
        Surface::sphere(29.0, Material::Inside).unwrap(),
        Surface::cone(1.0, Material::Outside).unwrap(),
        Surface::torus(30.0, 90.0, Material::Inside).unwrap(),
        Surface::revolution(
            Profile::Logarithmic {
                radius: 5.0,
                half_length: 4.0,
                end_drop: 0.02,
                scale: 0.005,
            },
            Material::Inside,
        )
        .unwrap(),
    ];
    #[derive(Debug, serde::Serialize, serde::Deserialize)]
    struct Doc {
        surface: Surface,
    }
    for s in cases {
        let text = toml::to_string(&Doc { surface: s.clone() }).unwrap();
        let back: Doc = toml::from_str(&text).unwrap();
        assert_eq!(back.surface, s, "{text}");
    }
    let bad = "[surface]\ntype = \"cone\"\nhalf_angle = 0.0\nmaterial = \"inside\"\n";
    let e = toml::from_str::<Doc>(bad).unwrap_err().to_string();
    assert!(e.contains("half_angle"), "{e}");
}

// ------------------------------------------------------------------------------------------
// Sphere

proptest! {
    #[test]
    fn sphere_hits_match_the_closed_form(
        r in 0.1f64..100.0,
        ox in -5.0f64..5.0, oy in -5.0f64..5.0, oz in -5.0f64..5.0,
        cp in -1.0f64..1.0, az in 0.0f64..(2.0 * PI),
        inside in any::<bool>(),
    ) {
        let mat = if inside { Material::Inside } else { Material::Outside };
        let s = Surface::sphere(r, mat).unwrap();
        let o = Point3::new(ox, oy, oz) * r;
        let d = dir(cp, az);
        let rr = ray(o, d);
        let got = check_hit(&s, &rr, 0.0, f64::INFINITY, r);
        // Closed form in plain arithmetic: |o + t d|² = r².
        let b = o.coords.dot(&d);
        let c = o.coords.norm_squared() - r * r;
        let disc = b * b - c;
        let expected = if disc > 0.0 {
            [-b - disc.sqrt(), -b + disc.sqrt()].into_iter().find(|t| *t >= 0.0)
        } else {
            None
        };
        match (got, expected) {
            (Some(t), Some(e)) => prop_assert!((t - e).abs() <= 1e-10 * r * (1.0 + o.coords.norm() / r)),
            (None, None) => {}
            (g, e) => prop_assert!(disc.abs() < 1e-12 * r * r, "got {g:?}, expected {e:?}"),
        }
    }
}

#[test]
fn sphere_misses_and_grazing() {
    let s = Surface::sphere(2.0, Material::Inside).unwrap();
    // Pointing away.
    assert!(
        s.intersect(&ray(Point3::new(0.0, 0.0, 5.0), Vector3::z()), 0.0, 1e9)
            .is_none()
    );
    // Passing outside.
    assert!(
        s.intersect(&ray(Point3::new(0.0, 2.5, 5.0), -Vector3::z()), 0.0, 1e9)
            .is_none()
    );
    // Tangent.
    assert!(
        s.intersect(&ray(Point3::new(0.0, 2.0, 5.0), -Vector3::z()), 0.0, 1e9)
            .is_none()
    );
    // Empty or inverted range, NaN.
    let r = ray(Point3::new(0.0, 0.0, 5.0), -Vector3::z());
    assert!(s.intersect(&r, 0.0, 2.9).is_none());
    assert!(s.intersect(&r, 1.0, 0.0).is_none());
    assert!(s.intersect(&r, f64::NAN, 1.0).is_none());
    assert!((s.intersect(&r, 0.0, 3.0).unwrap().t - 3.0).abs() < 1e-15);
    // From inside: the exit.
    let hit = s
        .intersect(&ray(Point3::origin(), Vector3::x()), 0.0, 10.0)
        .unwrap();
    assert!((hit.t - 2.0).abs() < 1e-15 && (hit.normal.x - 1.0).abs() < 1e-15);
}

#[test]
fn sphere_curvature_sign_follows_the_material() {
    for (mat, k) in [(Material::Inside, 0.25), (Material::Outside, -0.25)] {
        let s = Surface::sphere(4.0, mat).unwrap();
        let c = s.curvature(&Point3::new(1.0, 2.0, 3.0));
        assert!((c.k1 - k).abs() < 1e-15 && (c.k2 - k).abs() < 1e-15);
        let n = s.normal(&Point3::new(1.0, 2.0, 3.0));
        assert!(c.d1.dot(&n).abs() < 1e-15 && c.d2.dot(&n).abs() < 1e-15);
        assert!((c.d1.cross(&c.d2) - n.into_inner()).norm() < 1e-14);
    }
    let p = Surface::plane(Material::Inside).curvature(&Point3::new(3.0, 4.0, 5.0));
    assert_eq!((p.k1, p.k2), (0.0, 0.0));
}

// ------------------------------------------------------------------------------------------
// Plane

#[test]
fn plane_hits_and_misses() {
    let s = Surface::plane(Material::Inside);
    let hit = s
        .intersect(
            &ray(Point3::new(1.0, 2.0, 3.0), Vector3::new(0.0, 0.6, -0.8)),
            0.0,
            10.0,
        )
        .unwrap();
    assert!((hit.t - 3.75).abs() < 1e-15);
    assert_eq!(hit.point.z, 0.0);
    assert_eq!(hit.normal.into_inner(), Vector3::z());
    assert!(
        s.intersect(&ray(Point3::new(1.0, 2.0, 3.0), Vector3::x()), 0.0, 10.0)
            .is_none()
    );
    assert!(
        s.intersect(&ray(Point3::new(1.0, 2.0, 3.0), Vector3::z()), 0.0, 10.0)
            .is_none()
    );
    let out = Surface::plane(Material::Outside);
    assert_eq!(out.signed_distance(&Point3::new(0.0, 0.0, 2.0)), -2.0);
    assert_eq!(out.normal(&Point3::origin()).into_inner(), -Vector3::z());
}

// ------------------------------------------------------------------------------------------
// Cone

proptest! {
    #[test]
    fn cone_hits_lie_on_the_upper_nappe(
        alpha in 0.05f64..1.5,
        ox in -3.0f64..3.0, oy in -3.0f64..3.0, oz in -3.0f64..3.0,
        cp in -1.0f64..1.0, az in 0.0f64..(2.0 * PI),
        inside in any::<bool>(),
    ) {
        let mat = if inside { Material::Inside } else { Material::Outside };
        let s = Surface::cone(alpha, mat).unwrap();
        let o = Point3::new(ox, oy, oz);
        let rr = ray(o, dir(cp, az));
        let size = 10.0;
        let got = check_hit(&s, &rr, 0.0, 10.0, size);
        if let Some(t) = got {
            prop_assert!(rr.at(t).z >= -1e-12);
        }
        let oracle = oracle_first_root(&s, &rr, 0.0, 10.0, size / 2000.0);
        match (got, oracle) {
            (Some(t), Some(e)) => prop_assert!((t - e).abs() < 1e-9 * size, "{t} vs {e}"),
            (None, None) => {}
            (g, e) => {
                // Only a near-tangent chord shorter than the oracle's step may differ.
                let t = g.or(e).unwrap();
                let n = s.normal(&rr.at(t));
                prop_assert!(n.dot(&rr.dir).abs() < 1e-2, "got {g:?}, oracle {e:?}");
            }
        }
    }
}

#[test]
fn cone_ignores_the_mirrored_nappe_and_has_the_exact_distance() {
    let alpha = 0.6f64;
    let s = Surface::cone(alpha, Material::Inside).unwrap();
    // A horizontal ray below the apex crosses only the mirrored nappe: a miss.
    assert!(
        s.intersect(&ray(Point3::new(-5.0, 0.0, -1.0), Vector3::x()), 0.0, 10.0)
            .is_none()
    );
    // Above the apex: enters at rho = z tan(alpha).
    let hit = s
        .intersect(&ray(Point3::new(-5.0, 0.0, 2.0), Vector3::x()), 0.0, 10.0)
        .unwrap();
    assert!((hit.point.x + 2.0 * alpha.tan()).abs() < 1e-14);
    // Exact distance in both regions.
    let (sn, cs) = alpha.sin_cos();
    let p = Point3::new(3.0, 0.0, 1.0);
    assert!((s.signed_distance(&p) - (3.0 * cs - sn)).abs() < 1e-15);
    let below = Point3::new(1.0, 0.0, -4.0);
    assert!((s.signed_distance(&below) - 17f64.sqrt()).abs() < 1e-15);
    // A ray through the apex from below into the nappe crosses there.
    let up = s
        .intersect(&ray(Point3::new(0.0, 0.0, -1.0), Vector3::z()), 0.0, 5.0)
        .unwrap();
    assert!(up.t == 1.0 && up.point == Point3::origin());
}

#[test]
fn cone_curvature_is_zero_along_the_generatrix_and_cos_over_rho_around() {
    let alpha = 0.4f64;
    for (mat, sign) in [(Material::Inside, 1.0), (Material::Outside, -1.0)] {
        let s = Surface::cone(alpha, mat).unwrap();
        let z = 3.0;
        let rho = z * alpha.tan();
        let p = Point3::new(rho * 0.6, rho * 0.8, z);
        let c = s.curvature(&p);
        let k_around = sign * alpha.cos() / rho;
        let (k_gen, k_ar) = if sign > 0.0 {
            (c.k1, c.k2)
        } else {
            (c.k2, c.k1)
        };
        assert!(k_gen.abs() < 1e-15);
        assert!((k_ar - k_around).abs() < 1e-14, "{k_ar} vs {k_around}");
        fd_shape_operator(&s, &p, 1e-5);
    }
}

// ------------------------------------------------------------------------------------------
// Torus

/// The shape operator by finite differences of the normal: dn/ds along d_i = k_i d_i.
fn fd_shape_operator(s: &Surface, p: &Point3<f64>, h: f64) {
    let (q, _) = s.closest_point(p);
    let c = s.curvature(&q);
    for (k, d) in [(c.k1, c.d1), (c.k2, c.d2)] {
        let fwd = s.closest_point(&(q + d.into_inner() * h));
        let bwd = s.closest_point(&(q - d.into_inner() * h));
        let dn = (fwd.1.into_inner() - bwd.1.into_inner()) / (fwd.0 - bwd.0).norm();
        assert!(
            (dn - d.into_inner() * k).norm() < 1e-5 * (1.0 + k.abs()),
            "k = {k}, dn = {dn:?}, d = {d:?}"
        );
    }
}

proptest! {
    #[test]
    fn torus_hits_match_the_sampling_oracle(
        big_r in 0.0f64..40.0, r in 0.5f64..20.0,
        ox in -2.0f64..2.0, oy in -2.0f64..2.0, oz in -2.0f64..2.0,
        cp in -1.0f64..1.0, az in 0.0f64..(2.0 * PI),
        inside in any::<bool>(),
    ) {
        let mat = if inside || big_r < r { Material::Inside } else { Material::Outside };
        let s = Surface::torus(big_r, r, mat).unwrap();
        let size = big_r + r;
        let o = Point3::new(ox, oy, oz) * size;
        let rr = ray(o, dir(cp, az));
        let t_max = 6.0 * size;
        let got = check_hit(&s, &rr, 0.0, t_max, size);
        let oracle = oracle_first_root(&s, &rr, 0.0, t_max, size / 500.0);
        match (got, oracle) {
            (Some(t), Some(e)) => prop_assert!((t - e).abs() < 1e-9 * size, "{t} vs {e}"),
            (None, None) => {}
            (g, e) => {
                let t = g.or(e).unwrap();
                let n = s.normal(&rr.at(t));
                prop_assert!(n.dot(&rr.dir).abs() < 1e-2, "got {g:?}, oracle {e:?}");
            }
        }
    }

    #[test]
    fn torus_curvatures_are_analytic(
        big_r in 0.0f64..40.0, r in 0.5f64..20.0,
        theta_frac in -1.0f64..1.0, phi in -PI..PI,
        inside in any::<bool>(),
    ) {
        let mat = if inside || big_r < r { Material::Inside } else { Material::Outside };
        let sign = if mat == Material::Inside { 1.0 } else { -1.0 };
        // The outer sheet (R + r cos(theta) > 0), away from a spindle's cusps.
        let theta_max = if big_r >= r { PI } else { (-big_r / r).acos() };
        let theta = theta_frac * theta_max;
        let rho = big_r + r * theta.cos();
        prop_assume!(rho > 1e-3 * r);
        let s = Surface::torus(big_r, r, mat).unwrap();
        let p = Point3::new(rho * phi.cos(), rho * phi.sin(), r * theta.sin());
        prop_assert!(s.signed_distance(&p).abs() < 1e-13 * (big_r + r));
        let c = s.curvature(&p);
        let (k_tube, k_around) = (sign / r, sign * theta.cos() / rho);
        let mut expected = [k_tube, k_around];
        expected.sort_by(f64::total_cmp);
        prop_assert!((c.k1 - expected[0]).abs() < 1e-12 * (1.0 / r + 1.0 / rho));
        prop_assert!((c.k2 - expected[1]).abs() < 1e-12 * (1.0 / r + 1.0 / rho));
        fd_shape_operator(&s, &p, 1e-5 * r.min(rho));
    }
}

#[test]
fn torus_without_cancellation_for_r_1000_over_1_from_1e4_away() {
    let (big_r, r) = (1000.0, 1.0);
    let s = Surface::torus(big_r, r, Material::Inside).unwrap();
    let mut hits = 0;
    for k in 0..200 {
        // Aim from 1e4 away at a point of the tube; the ray may hit another part first.
        let th = 0.37 * k as f64;
        let ph = 0.11 * k as f64;
        let target = Point3::new(
            (big_r + r * th.cos()) * ph.cos(),
            (big_r + r * th.cos()) * ph.sin(),
            r * th.sin(),
        );
        let from = dir((0.73 * k as f64).sin(), 1.3 * k as f64);
        let o = target + from * 1e4;
        let rr = ray(o, target - o);
        let hit = s.intersect(&rr, 0.0, 2e4).unwrap();
        // On the surface to 1e-12 of the *tube* radius, not just of R.
        let sd = s.signed_distance(&hit.point);
        assert!(sd.abs() <= 1e-12 * r, "ray {k}: sdf {sd:e}");
        // Not beyond the target, and no earlier crossing near the torus (oracle).
        assert!(hit.t <= 1e4 * (1.0 + 1e-12));
        let t0 = 1e4 - 2.0 * (big_r + r);
        if let Some(e) = oracle_first_root(&s, &rr, t0, 1e4 + 1.0, r / 200.0) {
            assert!((hit.t - e).abs() < 1e-9 * 1e4, "ray {k}: {} vs {e}", hit.t);
        }
        hits += 1;
    }
    assert_eq!(hits, 200);
}

#[test]
fn torus_misses_are_misses() {
    let s = Surface::torus(10.0, 2.0, Material::Inside).unwrap();
    // Pointing away from outside.
    assert!(
        s.intersect(&ray(Point3::new(20.0, 0.0, 0.0), Vector3::x()), 0.0, 1e9)
            .is_none()
    );
    // Outside the bounding sphere.
    assert!(
        s.intersect(&ray(Point3::new(-50.0, 12.5, 0.0), Vector3::x()), 0.0, 1e9)
            .is_none()
    );
    // Through the hole along the axis.
    assert!(
        s.intersect(&ray(Point3::new(0.0, 0.0, 50.0), -Vector3::z()), 0.0, 1e9)
            .is_none()
    );
    // Tangent to the top of the tube (a touch, not a crossing), across its whole width.
    assert!(
        s.intersect(&ray(Point3::new(-50.0, 10.0, 2.0), Vector3::x()), 0.0, 1e9)
            .is_none()
    );
    // Skimming 1e-9 above the top along the centre circle's tangent.
    let skim = ray(Point3::new(-50.0, 10.0, 2.0 + 1e-9), Vector3::x());
    assert!(s.intersect(&skim, 0.0, 1e9).is_none());
    // 1e-9 below: a real (short) crossing.
    let dip = ray(Point3::new(-50.0, 10.0, 2.0 - 1e-9), Vector3::x());
    let hit = s.intersect(&dip, 0.0, 1e9).unwrap();
    assert!(s.signed_distance(&hit.point).abs() < 1e-13 * 12.0);
    assert!(hit.point.x < 0.0);
}

#[test]
fn torus_grazing_rays_terminate_quickly() {
    // Rays tangent to the tube at many places and angles, slightly in and out: each call
    // must return (correctly) without running into the step cap; the time bound is loose.
    let s = Surface::torus(1000.0, 1.0, Material::Inside).unwrap();
    let start = std::time::Instant::now();
    let mut n = 0;
    for k in 0..400 {
        let th = 0.173 * k as f64;
        let ph = 0.07 * k as f64;
        let nrm = Vector3::new(th.cos() * ph.cos(), th.cos() * ph.sin(), th.sin());
        let q = Point3::new(
            (1000.0 + th.cos()) * ph.cos(),
            (1000.0 + th.cos()) * ph.sin(),
            th.sin(),
        );
        let (e1, e2) = {
            let a = if nrm.x.abs() < 0.9 {
                Vector3::x()
            } else {
                Vector3::y()
            };
            let e1 = nrm.cross(&a).normalize();
            (e1, nrm.cross(&e1))
        };
        let w = 0.31 * k as f64;
        let tangent = e1 * w.cos() + e2 * w.sin();
        for off in [1e-12, -1e-12, 1e-6, -1e-6] {
            let o = q + nrm * off - tangent * 50.0;
            let rr = ray(o, tangent);
            if let Some(h) = s.intersect(&rr, 0.0, 100.0) {
                // Relative to the size: a near-tangent root is ill-conditioned in t.
                assert!(s.signed_distance(&h.point).abs() <= 1e-12 * 1001.0);
            }
            n += 1;
        }
    }
    let per_ray = start.elapsed().as_secs_f64() / n as f64;
    assert!(per_ray < 2e-3, "{per_ray} s per grazing ray");
}

#[test]
fn spindle_torus_r2_r14_hits_the_outer_sheet_only() {
    let (big_r, r) = (2.0, 14.0);
    let s = Surface::torus(big_r, r, Material::Inside).unwrap();
    // From the centre (inside the lemon), every ray exits through the apple: no root at the
    // lemon's surface.
    for k in 0..100 {
        let d = dir((0.37 * k as f64).sin(), 0.9 * k as f64);
        let hit = s.intersect(&ray(Point3::origin(), d), 0.0, 100.0).unwrap();
        let p = hit.point;
        let rho = p.x.hypot(p.y);
        // On the apple: distance r from the *near* circle point.
        assert!(((rho - big_r).hypot(p.z) - r).abs() < 1e-13 * (big_r + r));
        assert!(hit.normal.dot(&d) > 0.0, "exits");
    }
    // The cusps: on the axis at z = ±sqrt(r² - R²); the distance inside is exact there.
    let zc = (r * r - big_r * big_r).sqrt();
    let down = s
        .intersect(&ray(Point3::new(0.0, 0.0, 30.0), -Vector3::z()), 0.0, 100.0)
        .unwrap();
    assert!((down.point.z - zc).abs() < 1e-12 * zc);
    assert!((s.signed_distance(&Point3::origin()) + zc).abs() < 1e-14 * zc);
    // A ray through the lemon region from outside crosses the apple once going in.
    let side = s
        .intersect(&ray(Point3::new(-40.0, 0.0, 1.0), Vector3::x()), 0.0, 100.0)
        .unwrap();
    assert!(side.point.x < -15.0 && side.normal.x < 0.0);
    // Curvature on the outer equator: 1/r along the tube, 1/(R + r) around.
    let c = s.curvature(&Point3::new(big_r + r, 0.0, 0.0));
    assert!((c.k1 - 1.0 / (big_r + r)).abs() < 1e-15 && (c.k2 - 1.0 / r).abs() < 1e-15);
}

#[test]
fn implicit_is_the_papers_quartic_and_negative_inside() {
    let (big_r, r) = (30.0, 7.0);
    let s = Surface::torus(big_r, r, Material::Inside).unwrap();
    for p in [
        Point3::new(1.0, 2.0, 3.0),
        Point3::new(35.0, 4.0, -2.0),
        Point3::new(-20.0, 30.0, 9.0),
    ] {
        let q = p.coords.norm_squared() + big_r * big_r - r * r;
        let quartic = q * q - 4.0 * big_r * big_r * (p.x * p.x + p.y * p.y);
        assert!((s.implicit(&p) - quartic).abs() < 1e-9 * quartic.abs());
    }
    assert!(s.implicit(&Point3::new(big_r, 0.0, 0.0)) < 0.0);
    let out = Surface::torus(big_r, r, Material::Outside).unwrap();
    assert!(out.implicit(&Point3::new(big_r, 0.0, 0.0)) > 0.0);
    // Spindle: negative in the lemon too (inside the union of balls).
    let spindle = Surface::torus(2.0, 14.0, Material::Inside).unwrap();
    assert!(spindle.implicit(&Point3::origin()) < 0.0);
    // Cone: the mirrored nappe is not a zero.
    let cone = Surface::cone(0.5, Material::Inside).unwrap();
    assert!(cone.implicit(&Point3::new(0.0, 0.0, -1.0)) > 0.0);
    assert!(cone.implicit(&Point3::new(0.0, 0.0, 1.0)) < 0.0);
}

// ------------------------------------------------------------------------------------------
// intersect_near

proptest! {
    #[test]
    fn intersect_near_returns_the_same_root_as_intersect(
        big_r in 0.0f64..40.0, r in 0.5f64..20.0,
        ox in -2.0f64..2.0, oy in -2.0f64..2.0, oz in -2.0f64..2.0,
        cp in -1.0f64..1.0, az in 0.0f64..(2.0 * PI),
        guess_offset in -0.2f64..0.2, far_guess in 0.0f64..1.0,
    ) {
        let s = Surface::torus(big_r, r, Material::Inside).unwrap();
        let size = big_r + r;
        let rr = ray(Point3::new(ox, oy, oz) * size, dir(cp, az));
        let (t_min, t_max) = (0.0, 6.0 * size);
        let exact = s.intersect(&rr, t_min, t_max).map(|h| h.t);
        // A guess near the root, and a guess anywhere in range: both must agree.
        for guess in [exact.unwrap_or(0.0) + guess_offset * r, far_guess * t_max] {
            let near = s.intersect_near(&rr, guess, t_min, t_max);
            match (near, exact) {
                (Some(a), Some(b)) => prop_assert!((a - b).abs() < 1e-9 * size, "{a} vs {b}"),
                (None, None) => {}
                (a, b) => prop_assert!(false, "near {a:?} vs intersect {b:?}"),
            }
        }
    }

    #[test]
    fn intersect_near_on_a_pimp_like_grid(
        big_r in 1.0f64..40.0, r in 0.5f64..20.0,
        theta in -3.0f64..3.0, tilt in -0.3f64..0.3,
    ) {
        let s = Surface::torus(big_r.max(r), r, Material::Inside).unwrap();
        let big_r = big_r.max(r);
        // Rays along the normal from a tangent plane at a surface point, sampled on a
        // grid, each guessed from its neighbour: the hot path of PimP.
        let rho = big_r + r * theta.cos();
        let q = Point3::new(rho, 0.0, r * theta.sin());
        let n = s.normal(&q).into_inner();
        let e1 = Vector3::y();
        let e2 = n.cross(&e1);
        let d = -(n + e2 * tilt).normalize();
        let mut guess = -r;
        for i in 0..16 {
            let x = (i as f64 - 7.5) / 7.5 * 0.3 * r;
            let o = q + e1 * x + n * r;
            let rr = ray(o, d);
            let exact = s.intersect(&rr, 0.0, 4.0 * r).map(|h| h.t);
            let near = s.intersect_near(&rr, guess, 0.0, 4.0 * r);
            match (near, exact) {
                (Some(a), Some(b)) => {
                    prop_assert!((a - b).abs() < 1e-9 * (big_r + r), "{a} vs {b}");
                    guess = a;
                }
                (None, None) => {}
                (a, b) => prop_assert!(false, "near {a:?} vs intersect {b:?}"),
            }
        }
    }
}

// ------------------------------------------------------------------------------------------
// Surfaces of revolution

fn crowned() -> Surface {
    Surface::revolution(
        Profile::Crowned {
            radius: 10.0,
            crown_radius: 200.0,
            half_length: 12.0,
        },
        Material::Inside,
    )
    .unwrap()
}

#[test]
fn crowned_roller_matches_its_torus() {
    // A crowned cylinder is a torus patch: R = radius - crown_radius (negative, i.e. the
    // crown circle's centre on the other side of the axis): rho(z) = 10 - 200 + sqrt(200² - z²).
    let s = crowned();
    for z in [-11.0, -5.0, 0.0, 3.0, 11.9] {
        let rho = 10.0 - 200.0 + (200.0f64 * 200.0 - z * z).sqrt();
        let p = Point3::new(rho * 0.6, rho * 0.8, z);
        assert!(
            s.signed_distance(&p).abs() < 1e-12 * 10.0,
            "{}",
            s.signed_distance(&p)
        );
        let c = s.curvature(&p);
        // Meridian curvature 1/200 exactly (a circle), around: cos(psi)/rho.
        let slope = -z / (200.0f64 * 200.0 - z * z).sqrt();
        let around = 1.0 / (rho * (1.0 + slope * slope).sqrt());
        let mut expected = [1.0 / 200.0, around];
        expected.sort_by(f64::total_cmp);
        assert!((c.k1 - expected[0]).abs() < 1e-13 && (c.k2 - expected[1]).abs() < 1e-13);
        fd_shape_operator(&s, &p, 1e-5);
    }
}

proptest! {
    #[test]
    fn revolution_hits_match_the_sampling_oracle(
        ox in -30.0f64..30.0, oy in -30.0f64..30.0, oz in -30.0f64..30.0,
        cp in -1.0f64..1.0, az in 0.0f64..(2.0 * PI),
        which in 0usize..3,
    ) {
        let s = match which {
            0 => crowned(),
            1 => Surface::revolution(
                Profile::Logarithmic { radius: 8.0, half_length: 10.0, end_drop: 0.05, scale: 0.02 },
                Material::Inside,
            ).unwrap(),
            _ => Surface::revolution(
                Profile::Table {
                    z: vec![-10.0, -6.0, -1.0, 0.0, 4.0, 10.0],
                    rho: vec![6.0, 7.5, 8.0, 8.1, 7.0, 5.0],
                },
                Material::Outside,
            ).unwrap(),
        };
        let rr = ray(Point3::new(ox, oy, oz), dir(cp, az));
        let size = s.extent();
        let t_max = 100.0;
        let got = check_hit(&s, &rr, 0.0, t_max, size);
        // The patch only: the continuation of the meridian beyond the ends is no surface.
        let [z0, z1] = match &s { Surface::Revolution(r) => r.z_range(), _ => unreachable!() };
        let oracle = oracle_first_root_where(&s, &rr, 0.0, t_max, size / 500.0,
            |p| p.z >= z0 && p.z <= z1);
        match (got, oracle) {
            (Some(t), Some(e)) => prop_assert!((t - e).abs() < 1e-9 * size, "{t} vs {e}"),
            (None, None) => {}
            (g, e) => {
                let t = g.or(e).unwrap();
                let p = rr.at(t);
                // Grazing, or a root within the oracle's step of a patch end.
                let grazing = s.normal(&p).dot(&rr.dir).abs() < 1e-2;
                let at_end = p.z <= z0 + size / 500.0 || p.z >= z1 - size / 500.0;
                prop_assert!(grazing || at_end, "got {g:?}, oracle {e:?}");
            }
        }
        if let Some(t) = got {
            let near = s.intersect_near(&rr, t + 0.01, 0.0, t_max).unwrap();
            prop_assert!((near - t).abs() < 1e-9 * size);
        }
    }
}

// ------------------------------------------------------------------------------------------
// Closest points

proptest! {
    #[test]
    fn closest_points_are_feet_of_perpendiculars(
        px in -2.0f64..2.0, py in -2.0f64..2.0, pz in -2.0f64..2.0,
        which in 0usize..5,
    ) {
        let (s, size) = match which {
            0 => (Surface::sphere(3.0, Material::Outside).unwrap(), 3.0),
            1 => (Surface::torus(20.0, 4.0, Material::Inside).unwrap(), 24.0),
            2 => (Surface::torus(2.0, 14.0, Material::Inside).unwrap(), 16.0),
            3 => (Surface::cone(0.7, Material::Outside).unwrap(), 10.0),
            _ => (crowned(), 12.0),
        };
        let p = Point3::new(px, py, pz) * size;
        let (q, n) = s.closest_point(&p);
        prop_assert!(s.signed_distance(&q).abs() < 1e-12 * size);
        let v = p - q;
        let sd = s.signed_distance(&p);
        prop_assert!((v.norm() - sd.abs()).abs() < 1e-9 * size, "{} vs {}", v.norm(), sd);
        let at_patch_edge = which == 4 && q.z.abs() >= 12.0 * (1.0 - 1e-12);
        if v.norm() > 1e-6 * size && !at_patch_edge {
            // Along the normal (the cusp of a spindle torus and the cone's apex have a
            // normal cone instead: there p - q is itself the returned normal).
            prop_assert!((v.normalize() * sd.signum() - n.into_inner()).norm() < 1e-6,
                "v {:?} n {:?}", v.normalize(), n);
        }
    }
}

#[test]
fn placed_surfaces_transform_queries() {
    let s = Surface::torus(10.0, 2.0, Material::Inside).unwrap();
    let pose = Isometry3::new(Vector3::new(1.0, -2.0, 3.0), Vector3::new(0.3, -0.2, 0.9));
    let placed = PlacedSurface::new(s.clone(), pose).unwrap();
    let local = ray(Point3::new(-30.0, 0.5, 0.3), Vector3::new(1.0, 0.01, 0.0));
    let world = Ray {
        origin: pose * local.origin,
        dir: pose.rotation * local.dir,
    };
    let hl = s.intersect(&local, 0.0, 100.0).unwrap();
    let hw = placed.intersect(&world, 0.0, 100.0).unwrap();
    assert!((hl.t - hw.t).abs() < 1e-12);
    assert!((pose * hl.point - hw.point).norm() < 1e-12);
    assert!((pose.rotation * hl.normal.into_inner() - hw.normal.into_inner()).norm() < 1e-14);
    let tn = placed
        .intersect_near(&world, hl.t + 0.1, 0.0, 100.0)
        .unwrap();
    assert!((tn - hl.t).abs() < 1e-12);
    let p = Point3::new(3.0, 4.0, 5.0);
    assert!((placed.signed_distance(&(pose * p)) - s.signed_distance(&p)).abs() < 1e-13);
    let (cw, cl) = (placed.curvature(&(pose * p)), s.curvature(&p));
    assert!((cw.k1 - cl.k1).abs() < 1e-15 && (cw.k2 - cl.k2).abs() < 1e-15);
    assert!((cw.d1.into_inner() - pose.rotation * cl.d1.into_inner()).norm() < 1e-14);
}
