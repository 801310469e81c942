#![allow(clippy::unwrap_used)] // test helpers: a panic is a test failure with its message

//! The contact point of two placed surfaces against closed forms, an independent
//! alternating-projection oracle and rigid-motion invariance.
//!
//! Tolerances: closed forms (sphere/plane, sphere/sphere, ball in a cup, sphere/torus,
//! torus/plane) are met to 1e-12 relative to the bodies' size: the Newton iteration
//! converges quadratically and the final foot point is exact. Rigid-motion invariance holds
//! to 1e-9 (the search runs in a different frame, so rounding differs at ~1e-13).
//! The alternating-projection oracle converges linearly; it is iterated to 1e-13.

use kontakt::Error;
use kontakt::geometry::{ContactPoint, Material, PlacedSurface, Profile, Surface, find_contact};
use nalgebra::{Isometry3, Point3, Translation3, UnitQuaternion, Vector3};
use proptest::prelude::*;
use std::f64::consts::FRAC_PI_2;

fn placed(s: Surface, pose: Isometry3<f64>) -> PlacedSurface {
    PlacedSurface::new(s, pose).unwrap()
}

fn at(s: Surface, x: f64, y: f64, z: f64) -> PlacedSurface {
    placed(s, Isometry3::translation(x, y, z))
}

fn sphere(r: f64) -> Surface {
    Surface::sphere(r, Material::Inside).unwrap()
}

/// The invariants every contact point satisfies.
fn check_invariants(c: &ContactPoint, b1: &PlacedSurface, b2: &PlacedSurface, size: f64) {
    let tol = 1e-12 * size;
    assert!(
        b1.signed_distance(&c.point1).abs() < tol,
        "point1 off surface 1"
    );
    assert!(
        b2.signed_distance(&c.point2).abs() < tol,
        "point2 off surface 2"
    );
    let n1 = b1.normal(&c.point1).into_inner();
    let n2 = b2.normal(&c.point2).into_inner();
    assert!(
        (n2 - c.normal.into_inner()).norm() < 1e-9,
        "normal = outward normal of body 2"
    );
    assert!(
        (n1 + c.normal.into_inner()).norm() < 1e-9,
        "normal = -outward normal of body 1"
    );
    let gap = c.point1 - c.point2;
    assert!((gap - c.normal.into_inner() * c.separation).norm() < 1e-9 * size);
    assert!((c.point - nalgebra::center(&c.point1, &c.point2)).norm() < 1e-15 * size);
}

fn close(a: &Point3<f64>, b: &Point3<f64>, tol: f64) -> bool {
    (a - b).norm() <= tol
}

// ------------------------------------------------------------------------------------------
// Closed forms

proptest! {
    #[test]
    fn sphere_on_plane_is_exact(
        r in 1.0f64..1000.0, h in -0.5f64..2.0, x in -50.0f64..50.0, y in -50.0f64..50.0,
        ax in -1.0f64..1.0, ay in -1.0f64..1.0, az in -1.0f64..1.0,
        sphere_first in any::<bool>(),
    ) {
        // Wirsching et al. (2019)'s sphere on plane: radius 10..1000 mm. The plane tilted and moved.
        let pose = Isometry3::new(Vector3::new(x, y, 3.0), Vector3::new(ax, ay, az));
        let flat = placed(Surface::plane(Material::Inside), pose);
        let up = pose.rotation * Vector3::z();
        let centre = pose * Point3::new(0.3 * x, -0.2 * y, r + h * r);
        let ball = at(sphere(r), centre.x, centre.y, centre.z);
        let (c, flip) = if sphere_first {
            (find_contact(&ball, &flat, None).unwrap(), 1.0)
        } else {
            (find_contact(&flat, &ball, None).unwrap(), -1.0)
        };
        let tol = 1e-12 * r;
        prop_assert!((c.separation - h * r).abs() < tol, "{} vs {}", c.separation, h * r);
        prop_assert!((c.normal.into_inner() - up * flip).norm() < 1e-12);
        let on_ball = centre - up * r;
        let on_flat = centre - up * (r + h * r);
        let (p_ball, p_flat) = if sphere_first { (c.point1, c.point2) } else { (c.point2, c.point1) };
        prop_assert!(close(&p_ball, &on_ball, tol) && close(&p_flat, &on_flat, tol));
        if sphere_first { check_invariants(&c, &ball, &flat, r) } else { check_invariants(&c, &flat, &ball, r) }
    }

    #[test]
    fn sphere_on_sphere_is_exact(
        r1 in 1.0f64..100.0, r2 in 1.0f64..100.0, gap in -0.3f64..1.0,
        dx in -1.0f64..1.0, dy in -1.0f64..1.0, dz in -1.0f64..1.0,
    ) {
        let u = Vector3::new(dx, dy, dz);
        prop_assume!(u.norm() > 0.1);
        let u = u.normalize();
        // External contact; gap < 0 is an interpenetration of depth -gap (r1 + r2 - d).
        let d = (r1 + r2) * (1.0 + gap);
        let c2 = Point3::new(5.0, -7.0, 11.0);
        let c1 = c2 + u * d;
        let (b1, b2) = (at(sphere(r1), c1.x, c1.y, c1.z), at(sphere(r2), c2.x, c2.y, c2.z));
        let c = find_contact(&b1, &b2, None).unwrap();
        let size = r1 + r2;
        prop_assert!((c.separation - (d - r1 - r2)).abs() < 1e-12 * size);
        // The normal is the normalised difference of two points ~10 mm apart: round-off
        // reaches 1.1e-12 (a 1.5 mm sphere half inside a 12 mm one); 1e-11 leaves margin.
        prop_assert!((c.normal.into_inner() - u).norm() < 1e-11);
        prop_assert!(close(&c.point1, &(c1 - u * r1), 1e-12 * size));
        prop_assert!(close(&c.point2, &(c2 + u * r2), 1e-12 * size));
        check_invariants(&c, &b1, &b2, size);
    }

    #[test]
    fn ball_in_a_spherical_cup_is_exact(
        r1 in 1.0f64..50.0, extra in 0.01f64..20.0, off in 0.05f64..0.95,
        dx in -1.0f64..1.0, dy in -1.0f64..1.0, dz in -1.0f64..1.0,
    ) {
        let u = Vector3::new(dx, dy, dz);
        prop_assume!(u.norm() > 0.1);
        let u = u.normalize();
        let r2 = r1 + extra;
        let c2 = Point3::new(1.0, 2.0, 3.0);
        // Ball centre off the cup's centre towards u (off < 1: inside, clearance left).
        let c1 = c2 + u * (off * extra);
        let ball = at(sphere(r1), c1.x, c1.y, c1.z);
        let cup = at(Surface::sphere(r2, Material::Outside).unwrap(), c2.x, c2.y, c2.z);
        let c = find_contact(&ball, &cup, None).unwrap();
        let size = r2;
        // The exact answer for the centres as represented.
        let offset = c1 - c2;
        let u = offset.normalize();
        prop_assert!((c.separation - (r2 - offset.norm() - r1)).abs() < 1e-12 * size);
        // The contact direction is set by the offset off * extra (>= 5e-4 mm here) against
        // coordinates of size r2: an intrinsic condition number r2 / offset (a concentric
        // ball touches everywhere).
        let cond = size / offset.norm();
        prop_assert!((c.normal.into_inner() + u).norm() < 1e-12 + 8.0 * f64::EPSILON * cond,
            "{:?}", c.normal);
        let tol = 1e-12 * size + 8.0 * f64::EPSILON * cond * size;
        prop_assert!(close(&c.point1, &(c1 + u * r1), tol));
        prop_assert!(close(&c.point2, &(c2 + u * r2), tol));
        check_invariants(&c, &ball, &cup, size);
    }

    #[test]
    fn sphere_outside_a_ring_torus_is_exact(
        big_r in 20.0f64..40.0, r in 2.0f64..19.0, rs in 10.0f64..100.0, gap in -0.2f64..1.0,
        theta in -2.0f64..2.0, phi in -3.1f64..3.1,
    ) {
        // Wirsching et al. (2019)'s sphere on torus: sphere 10..100 mm, torus radii 20 and 30 mm.
        let torus = at(Surface::torus(big_r, r, Material::Inside).unwrap(), 0.0, 0.0, 0.0);
        // Ball centre along the tube normal at (theta, phi), clear of the hole's far side.
        let n = Vector3::new(theta.cos() * phi.cos(), theta.cos() * phi.sin(), theta.sin());
        let ring = Point3::new(big_r * phi.cos(), big_r * phi.sin(), 0.0);
        let dist = (r + rs) * (1.0 + 0.1 * gap.max(-0.05));
        let c = ring + n * dist;
        // The closed form needs the ball's nearest circle point to be `ring`: the centre on
        // the same side of the axis.
        prop_assume!(big_r + dist * theta.cos() > 1e-3 * big_r);
        // ... and no second contact with the far side of the ring.
        let far = Point3::new(-big_r * phi.cos(), -big_r * phi.sin(), 0.0);
        prop_assume!((c - far).norm() - r - rs > dist - r - rs + 0.5);
        let ball = at(sphere(rs), c.x, c.y, c.z);
        let cp = find_contact(&ball, &torus, None).unwrap();
        let size = big_r + r + rs;
        prop_assert!((cp.separation - (dist - r - rs)).abs() < 1e-12 * size,
            "{} vs {}", cp.separation, dist - r - rs);
        prop_assert!((cp.normal.into_inner() - n).norm() < 1e-11);
        prop_assert!(close(&cp.point2, &(ring + n * r), 1e-12 * size));
        prop_assert!(close(&cp.point1, &(c - n * rs), 1e-12 * size));
        check_invariants(&cp, &ball, &torus, size);
    }
}

#[test]
fn ball_in_a_toroidal_groove_is_exact() {
    // A bearing ball (radius 6) in an outer-ring groove (torus, material outside the tube).
    let (big_r, r, rs): (f64, f64, f64) = (30.0, 6.2, 6.0);
    let groove = at(
        Surface::torus(big_r, r, Material::Outside).unwrap(),
        0.0,
        0.0,
        0.0,
    );
    let c = Point3::new(30.1, 0.0, 0.05);
    let ball = at(sphere(rs), c.x, c.y, c.z);
    let cp = find_contact(&ball, &groove, None).unwrap();
    let v: Vector3<f64> = Vector3::new(0.1, 0.0, 0.05);
    let sep = r - v.norm() - rs;
    let u = v.normalize();
    assert!((cp.separation - sep).abs() < 1e-12 * big_r);
    assert!((cp.normal.into_inner() + u).norm() < 1e-12);
    assert!(close(
        &cp.point2,
        &(Point3::new(big_r, 0.0, 0.0) + u * r),
        1e-12 * big_r
    ));
    check_invariants(&cp, &ball, &groove, big_r);
}

#[test]
fn tilted_torus_on_a_plane_is_exact() {
    let (big_r, r) = (10.0, 2.0);
    let tilt = 0.3;
    let pose = Isometry3::new(Vector3::new(1.0, 2.0, 5.0), Vector3::new(tilt, 0.0, 0.0));
    let torus = placed(Surface::torus(big_r, r, Material::Inside).unwrap(), pose);
    let flat = placed(Surface::plane(Material::Inside), Isometry3::identity());
    let c = find_contact(&torus, &flat, None).unwrap();
    // Lowest point of the centre circle: centre + R w, w = the in-plane direction of -z.
    let axis = pose.rotation * Vector3::z();
    let w = (-Vector3::z() + axis * axis.z).normalize();
    let lowest = Point3::from(pose.translation.vector) + w * big_r;
    assert!((c.separation - (lowest.z - r)).abs() < 1e-12 * big_r);
    assert!(close(
        &c.point1,
        &(lowest - Vector3::z() * r),
        1e-12 * big_r
    ));
    assert!((c.normal.into_inner() - Vector3::z()).norm() < 1e-12);
    check_invariants(&c, &torus, &flat, big_r);
}

#[test]
fn crowned_roller_on_a_flat_is_exact() {
    // Roller axis along world x, 0.02 mm above the flat at its crown (the centre).
    let roller = Surface::revolution(
        Profile::Crowned {
            radius: 5.0,
            crown_radius: 300.0,
            half_length: 6.0,
        },
        Material::Inside,
    )
    .unwrap();
    let pose = Isometry3::from_parts(
        Translation3::new(1.0, 2.0, 5.02),
        UnitQuaternion::from_euler_angles(0.0, FRAC_PI_2, 0.0),
    );
    let roller = placed(roller, pose);
    let flat = placed(Surface::plane(Material::Inside), Isometry3::identity());
    let c = find_contact(&flat, &roller, None).unwrap();
    assert!(
        (c.separation - 0.02).abs() < 1e-12 * 5.0,
        "{}",
        c.separation
    );
    assert!(close(&c.point2, &Point3::new(1.0, 2.0, 0.02), 1e-12 * 5.0));
    assert!((c.normal.into_inner() + Vector3::z()).norm() < 1e-12);
    check_invariants(&c, &flat, &roller, 5.0);
}

#[test]
fn interpenetrating_spheres_report_the_depth() {
    let (b1, b2) = (
        at(sphere(3.0), 0.0, 0.0, 4.0),
        at(sphere(2.0), 0.0, 0.0, 0.0),
    );
    let c = find_contact(&b1, &b2, None).unwrap();
    assert!((c.separation + 1.0).abs() < 1e-15); // depth 3 + 2 - 4
    assert!(close(&c.point1, &Point3::new(0.0, 0.0, 1.0), 1e-15));
    assert!(close(&c.point2, &Point3::new(0.0, 0.0, 2.0), 1e-15));
    assert!(close(&c.point, &Point3::new(0.0, 0.0, 1.5), 1e-15));
    // Apart: the smallest distance.
    let b1 = at(sphere(3.0), 0.0, 0.0, 5.5);
    let c = find_contact(&b1, &b2, None).unwrap();
    assert!((c.separation - 0.5).abs() < 1e-15);
    // Touching.
    let b1 = at(sphere(3.0), 0.0, 0.0, 5.0);
    assert!(find_contact(&b1, &b2, None).unwrap().separation.abs() < 1e-15);
}

// ------------------------------------------------------------------------------------------
// Pairs without a closed form: the alternating-projection oracle

/// Closest points of two separate bodies by alternating projections (von Neumann):
/// slow but independent of the Newton search.
fn alternating_projection(
    b1: &PlacedSurface,
    b2: &PlacedSurface,
    start: Point3<f64>,
) -> (Point3<f64>, Point3<f64>) {
    let mut p1 = b1.closest_point(&start).0;
    let mut p2 = b2.closest_point(&p1).0;
    for _ in 0..200_000 {
        let q1 = b1.closest_point(&p2).0;
        let q2 = b2.closest_point(&q1).0;
        let moved = (q1 - p1).norm() + (q2 - p2).norm();
        p1 = q1;
        p2 = q2;
        if moved < 1e-14 {
            break;
        }
    }
    (p1, p2)
}

/// PimP-like pairs of Wirsching et al. (2020) Table 1: sphere/cone, sphere/torus, torus/cone,
/// torus/torus, each placed so that a single smooth contact exists (the bodies apart).
fn pimp_pairs() -> Vec<(&'static str, PlacedSurface, PlacedSurface)> {
    let rot = |ax: f64, ay: f64, az: f64| UnitQuaternion::from_euler_angles(ax, ay, az);
    let pose = |x: f64, y: f64, z: f64, q: UnitQuaternion<f64>| {
        Isometry3::from_parts(Translation3::new(x, y, z), q)
    };
    // Rib: a conical hole of half-angle 60° (material outside) or a toroidal groove.
    let cone_rib = placed(
        Surface::cone(1.05, Material::Outside).unwrap(),
        Isometry3::identity(),
    );
    let torus_rib = placed(
        Surface::torus(60.0, 30.0, Material::Outside).unwrap(),
        Isometry3::identity(),
    );
    // Roller end faces: a sphere r_R = 29, a spindle torus e = 2, r_R = 14.
    let ball = placed(sphere(29.0), pose(4.0, -3.0, 60.0, rot(0.0, 0.0, 0.0)));
    let face = placed(
        Surface::torus(2.0, 14.0, Material::Inside).unwrap(),
        pose(5.0, 2.0, 32.0, rot(0.4, -0.2, 0.3)),
    );
    let ball_in_groove = placed(sphere(25.0), pose(62.0, 3.0, 1.5, rot(0.0, 0.0, 0.0)));
    let face_in_groove = placed(
        Surface::torus(2.0, 14.0, Material::Inside).unwrap(),
        pose(61.0, -2.0, 3.0, rot(0.3, 0.5, -0.1)),
    );
    vec![
        ("sphere/cone", ball, cone_rib.clone()),
        ("sphere/torus", ball_in_groove, torus_rib.clone()),
        ("torus/cone", face, cone_rib),
        ("torus/torus", face_in_groove, torus_rib),
    ]
}

#[test]
fn pimp_pairs_agree_with_alternating_projections() {
    for (name, b1, b2) in pimp_pairs() {
        let c = find_contact(&b1, &b2, None).unwrap_or_else(|e| panic!("{name}: {e}"));
        assert!(c.separation > 0.0, "{name}: separation {}", c.separation);
        check_invariants(&c, &b1, &b2, 100.0);
        let (p1, p2) = alternating_projection(&b1, &b2, c.point + Vector3::new(0.3, -0.2, 0.1));
        assert!(
            close(&p1, &c.point1, 1e-7),
            "{name}: {p1:?} vs {:?}",
            c.point1
        );
        assert!(
            close(&p2, &c.point2, 1e-7),
            "{name}: {p2:?} vs {:?}",
            c.point2
        );
        assert!(((p1 - p2).norm() - c.separation).abs() < 1e-10, "{name}");
    }
}

proptest! {
    #[test]
    fn contact_is_invariant_under_a_rigid_motion_of_the_scene(
        which in 0usize..4,
        tx in -100.0f64..100.0, ty in -100.0f64..100.0, tz in -100.0f64..100.0,
        ax in -3.0f64..3.0, ay in -3.0f64..3.0, az in -3.0f64..3.0,
    ) {
        let (name, b1, b2) = pimp_pairs().swap_remove(which);
        let motion = Isometry3::new(Vector3::new(tx, ty, tz), Vector3::new(ax, ay, az));
        let moved = |b: &PlacedSurface| placed(b.surface.clone(), motion * b.pose);
        let (m1, m2) = (moved(&b1), moved(&b2));
        let c = find_contact(&b1, &b2, None).unwrap();
        let cm = find_contact(&m1, &m2, None).unwrap();
        prop_assert!((c.separation - cm.separation).abs() < 1e-9, "{name}");
        prop_assert!(close(&(motion * c.point1), &cm.point1, 1e-9), "{name}");
        prop_assert!(close(&(motion * c.point2), &cm.point2, 1e-9), "{name}");
        prop_assert!(close(&(motion * c.point), &cm.point, 1e-9), "{name}");
        prop_assert!((motion.rotation * c.normal.into_inner() - cm.normal.into_inner()).norm() < 1e-9);
        // With the contact as a guess the same point comes back.
        let cg = find_contact(&m1, &m2, Some(cm.point)).unwrap();
        prop_assert!(close(&cg.point1, &cm.point1, 1e-9));
    }
}

// ------------------------------------------------------------------------------------------
// Two contact zones and the guess

#[test]
fn two_contact_zones_return_the_deeper_unless_a_guess_is_given() {
    // A crowned roller lying across a ring torus touches both sides of the ring; tilted, the
    // x < 0 side is deeper.
    let ring = at(
        Surface::torus(10.0, 2.0, Material::Inside).unwrap(),
        0.0,
        0.0,
        0.0,
    );
    let roller = Surface::revolution(
        Profile::Crowned {
            radius: 1.0,
            crown_radius: 1000.0,
            half_length: 15.0,
        },
        Material::Inside,
    )
    .unwrap();
    let pose = Isometry3::from_parts(
        Translation3::new(0.0, 0.0, 2.0 + 1.0 - 0.05 - 0.01),
        UnitQuaternion::from_euler_angles(0.0, FRAC_PI_2 - 0.001, 0.0),
    );
    let roller = placed(roller, pose);
    let deep = find_contact(&roller, &ring, None).unwrap();
    assert!(deep.point.x < -9.0, "{:?}", deep.point);
    check_invariants(&deep, &roller, &ring, 15.0);
    let shallow = find_contact(&roller, &ring, Some(Point3::new(10.0, 0.0, 2.0))).unwrap();
    assert!(shallow.point.x > 9.0, "{:?}", shallow.point);
    assert!(shallow.separation > deep.separation);
    check_invariants(&shallow, &roller, &ring, 15.0);
}

// ------------------------------------------------------------------------------------------
// Errors

#[test]
fn invalid_inputs_and_degenerate_pairs_are_errors() {
    let s = sphere(1.0);
    let nan_pose = Isometry3::from_parts(
        Translation3::new(f64::NAN, 0.0, 0.0),
        UnitQuaternion::identity(),
    );
    let e = PlacedSurface::new(s.clone(), nan_pose).unwrap_err();
    assert_eq!(e.field(), Some("pose"));
    assert!(
        e.to_string()
            .starts_with("invalid pose = translation [NaN, 0, 0]"),
        "{e}"
    );

    let (b1, b2) = (
        at(sphere(1.0), 0.0, 0.0, 3.0),
        at(sphere(1.0), 0.0, 0.0, 0.0),
    );
    let e = find_contact(&b1, &b2, Some(Point3::new(0.0, f64::NAN, 0.0))).unwrap_err();
    assert_eq!(e.field(), Some("guess"));

    // Two planes: no unique contact point, whether parallel or not.
    let p1 = at(Surface::plane(Material::Inside), 0.0, 0.0, 0.0);
    let p2 = placed(
        Surface::plane(Material::Inside),
        Isometry3::new(
            Vector3::new(0.0, 0.0, 1.0),
            Vector3::new(std::f64::consts::PI, 0.0, 0.0),
        ),
    );
    let e = find_contact(&p1, &p2, None).unwrap_err();
    assert!(matches!(e, Error::Geometry { .. }), "{e}");
    assert!(e.to_string().contains("no unique contact point"), "{e}");

    // A ball whose surface is engulfed by a larger ball around its centre: the extremal
    // normals are parallel.
    let big = at(sphere(10.0), 0.0, 0.0, 0.0);
    let small = at(sphere(2.0), 0.5, 0.0, 0.0);
    let e = find_contact(&small, &big, None).unwrap_err();
    assert!(matches!(e, Error::Geometry { .. }), "{e}");
}
