#![allow(clippy::unwrap_used)]
//! Kinematics of the common-apex tapered roller bearing (issue 11, item 1): pure rolling on
//! the raceway contact lines, sliding at the rib, the epicyclic relations, the common-apex
//! formulas against the general twist form and against finite differences of body points,
//! the per-cell velocity field, and bad input. Units: mm, mm/s, rad, rad/s.

use kontakt::bearing::{
    BodyState, ContactFrame, ContactPair, RollerRib, RollerRibSpec, TABLE1, TaperedKinematics,
};
use kontakt::geometry::{Grid2, Twist};
use kontakt::pimp::SurfacePairGap;
use nalgebra::{Point3, Rotation3, Unit, Vector3};

fn pair(name: &str) -> RollerRib {
    RollerRib::new(RollerRibSpec::builtin(name).unwrap()).unwrap()
}

/// (inner, outer) ring speeds \[rad/s\]: outer fixed, counter-rotating, inner fixed.
const SPEEDS: [(f64, f64); 3] = [(100.0, 0.0), (100.0, -30.0), (0.0, 50.0)];
const CAGE_ANGLES: [f64; 3] = [0.0, 0.7, 2.5];

/// A point of the section plane (cage angle 0) turned to cage angle `theta` about the ring
/// axis through the apex.
fn turned(k: &TaperedKinematics, p: &Point3<f64>, theta: f64) -> Point3<f64> {
    k.apex + Rotation3::from_axis_angle(&Vector3::z_axis(), theta) * (p - k.apex)
}

/// Distance of `p` from the ring axis (through the apex along Z).
fn radius(k: &TaperedKinematics, p: &Point3<f64>) -> f64 {
    let d = p - k.apex;
    d.x.hypot(d.y)
}

/// Pure rolling: on points along each raceway contact line the roller's velocity (twist
/// form) equals the ring's, to 1e-9 of the rolling speed |ω_ring − ω_c| R.
#[test]
fn pure_rolling_on_both_raceway_contact_lines() {
    let rr = pair("sphere-cone-29");
    for (wi, wo) in SPEEDS {
        let k = TaperedKinematics::of_roller_rib(&rr, wi, wo).unwrap();
        for theta in CAGE_ANGLES {
            let b = k.bodies(theta, 0.0).unwrap();
            let d = k.directions(theta);
            // The roller spans about 70 to 105 mm from the apex.
            for s in [60.0, 75.0, 90.0, 105.0] {
                for (line, ring, w) in [(d.inner_line, b.inner, wi), (d.outer_line, b.outer, wo)] {
                    let p = k.apex + line * s;
                    let rolling = (w - k.cage_speed).abs() * radius(&k, &p);
                    assert!(rolling > 100.0, "rolling speed {rolling} mm/s");
                    let slip = (b.roller.velocity_at(&p) - ring.velocity_at(&p)).norm();
                    assert!(
                        slip <= 1e-9 * rolling,
                        "({wi}, {wo}) θ {theta} s {s}: slip {slip:e} mm/s of {rolling}"
                    );
                }
            }
        }
    }
}

/// The rib contact always slides: |v_s| = |ω_rel| e at the contact centre, e the distance of
/// the rib contact point from the inner raceway contact line (the instantaneous axis of the
/// roller relative to the inner ring), to 1e-12 relative; the sliding velocity lies in the
/// contact plane (the projection removes nothing), and the twist form agrees with the
/// common-apex form ω_rel × (P − A).
#[test]
fn rib_contact_slides_at_relative_speed_times_height() {
    for (name, ..) in TABLE1 {
        let rr = pair(name);
        for (wi, wo) in SPEEDS {
            let k = TaperedKinematics::of_roller_rib(&rr, wi, wo).unwrap();
            for theta in CAGE_ANGLES {
                let p = turned(&k, &rr.contact.point, theta);
                let n = Unit::new_normalize(
                    Rotation3::from_axis_angle(&Vector3::z_axis(), theta)
                        * rr.contact.normal.into_inner(),
                );
                let v = k.rib_pair(theta).unwrap().velocities(&p, &n).unwrap();
                let w_rel = k.relative_angular_velocity(theta);
                let e = (p - k.apex).cross(&k.directions(theta).inner_line).norm();
                assert!(e > 1.0 && e < 5.5, "{name}: e = {e} mm");
                let expected = w_rel.norm() * e;
                let got = v.sliding.norm();
                assert!(
                    (got - expected).abs() <= 1e-12 * expected,
                    "{name} ({wi}, {wo}) θ {theta}: |v_s| {got} vs |ω_rel| e {expected}"
                );
                let apex_form = k.relative_velocity_at(theta, &p);
                assert!((v.sliding - apex_form).norm() <= 1e-12 * expected);
                assert!(v.slide_to_roll().unwrap() > 0.0);
            }
        }
    }
}

/// Epicyclic relations against forms derived independently from the geometry:
/// ω_c = (ω_i R_i + ω_o R_o)/(R_i + R_o) with R_i, R_o the raceway radii at the feet of the
/// roller's mid-point on the two contact lines (rolling of the raceways on the roller seen
/// from the cage, equal roller radius at both feet), and the roller spin from equal surface
/// speeds in the cage frame, ω_R ρ = −(ω_i − ω_c) R_i, ρ the roller radius at the inner
/// foot (its distance from the roller axis). Adding a common speed to both rings adds it to the cage and leaves spin and
/// relative speed unchanged. Tolerance 1e-12 relative.
#[test]
fn epicyclic_relations_of_the_cone_geometry() {
    let rr = pair("torus-torus-14");
    for (wi, wo) in SPEEDS {
        let k = TaperedKinematics::of_roller_rib(&rr, wi, wo).unwrap();
        let d = k.directions(0.0);
        let mid = k.apex + d.roller_axis * 88.0;
        let foot = |line: Vector3<f64>| k.apex + line * (mid - k.apex).dot(&line);
        let (fi, fo) = (foot(d.inner_line), foot(d.outer_line));
        let (ri, ro) = (radius(&k, &fi), radius(&k, &fo));
        let cage = (wi * ri + wo * ro) / (ri + ro);
        let scale = wi.abs().max(wo.abs());
        assert!(
            (k.cage_speed - cage).abs() <= 1e-12 * scale,
            "({wi}, {wo}): ω_c {} vs {cage}",
            k.cage_speed
        );
        // Roller radius at a foot: its distance from the roller axis.
        let to_axis = |f: Point3<f64>| (f - k.apex).cross(&d.roller_axis).norm();
        let rho = to_axis(fi);
        assert!((to_axis(fo) - rho).abs() < 1e-12 * rho);
        let spin = -(wi - k.cage_speed) * ri / rho;
        assert!(
            (k.roller_spin - spin).abs() <= 1e-12 * k.roller_spin.abs().max(scale),
            "({wi}, {wo}): ω_R {} vs {spin}",
            k.roller_spin
        );
        // Outer ring fixed: the closed form in the cone angles.
        if wo == 0.0 {
            let (si, so) = (k.inner_raceway_angle.sin(), k.outer_raceway_angle().sin());
            assert!((k.cage_speed - wi * si / (si + so)).abs() <= 1e-12 * wi);
        }
        // A common rotation of the whole bearing.
        let shifted = TaperedKinematics::of_roller_rib(&rr, wi + 40.0, wo + 40.0).unwrap();
        assert!((shifted.cage_speed - k.cage_speed - 40.0).abs() <= 1e-12 * (scale + 40.0));
        assert!((shifted.roller_spin - k.roller_spin).abs() <= 1e-12 * (scale + 40.0) * 10.0);
        assert!((shifted.relative_speed - k.relative_speed).abs() <= 1e-12 * (scale + 40.0) * 10.0);
    }
}

/// Zero cone angles: with the roller half-angle β → 0 (inner raceway radius R_i = 35 mm,
/// roller radius ρ = 5.5 mm kept; α_i = asin(R_i tan β / ρ)), the cage speed and roller spin
/// tend to the textbook cylindrical roller bearing, outer ring fixed:
/// ω_c = ω_i (1 − γ)/2 = ω_i D_i/(D_i + D_o), ω_R = −ω_i (d_m / 2D_w)(1 − γ²), with
/// D_w = 2ρ, d_m = 2R_i + D_w, γ = D_w/d_m. The difference is of second order in β (the
/// raceway and roller radii vary along the taper): asserted ≤ 5 β² and falling by > 50
/// for β / 10.
#[test]
fn zero_cone_angle_limit_is_the_cylindrical_roller_bearing() {
    let (ri, rho, wi) = (35.0, 5.5, 100.0);
    let (dw, dm) = (2.0 * rho, 2.0 * ri + 2.0 * rho);
    let gamma = dw / dm;
    let cage = wi * (1.0 - gamma) / 2.0;
    let spin = -wi * dm / (2.0 * dw) * (1.0 - gamma * gamma);
    let errors = |beta_deg: f64| {
        let beta = f64::to_radians(beta_deg);
        let alpha_i = (ri * beta.tan() / rho).asin();
        let k = TaperedKinematics::new(alpha_i, beta, Point3::origin(), rho / beta.tan(), wi, 0.0)
            .unwrap();
        let e = (
            (k.cage_speed / cage - 1.0).abs(),
            (k.roller_spin / spin - 1.0).abs(),
        );
        assert!(
            e.0 <= 5.0 * beta * beta && e.1 <= 5.0 * beta * beta,
            "β {beta_deg}°: {e:?}"
        );
        e
    };
    let mut last = errors(1.0);
    for beta_deg in [0.1, 0.01] {
        let e = errors(beta_deg);
        assert!(
            e.0 < last.0 / 50.0 && e.1 < last.1 / 50.0,
            "{e:?} after {last:?}"
        );
        last = e;
    }
}

/// The twist form (reference point on the roller axis carried by the cage) against the
/// common-apex form ω × (P − A) for points all over the roller, to 1e-12 of |ω| |P − A|;
/// and every body's twist against a central difference of its body points between the poses
/// at t ± h, h = 1e-6 s: truncation (ω h)² |v| / 6 < 2e-8 |v| for ω ≤ 300 rad/s, round-off
/// ~1e-16 |P| / h ≈ 1e-8 mm/s; asserted 1e-6 |v| + 1e-6 mm/s.
#[test]
fn twist_form_matches_common_apex_and_finite_differences() {
    let rr = pair("torus-cone-28");
    for (wi, wo) in SPEEDS {
        let k = TaperedKinematics::of_roller_rib(&rr, wi, wo).unwrap();
        for theta in CAGE_ANGLES {
            let b = k.bodies(theta, 0.0).unwrap();
            let w = k.roller_angular_velocity(theta);
            assert!((b.roller.twist.angular - w).norm() <= 1e-12 * w.norm());
            let d = k.directions(theta);
            let side = d.roller_axis.cross(&d.axis).normalize();
            let points: Vec<Point3<f64>> = [70.0, 88.0, 105.0]
                .iter()
                .flat_map(|&s| [-4.0, 0.0, 3.0].map(|q| k.apex + d.roller_axis * s + side * q))
                .collect();
            for p in &points {
                let apex_form = w.cross(&(p - k.apex));
                let scale = w.norm() * (p - k.apex).norm();
                assert!((b.roller.velocity_at(p) - apex_form).norm() <= 1e-12 * scale);
                let rel = b.roller.velocity_at(p) - b.inner.velocity_at(p);
                assert!((rel - k.relative_velocity_at(theta, p)).norm() <= 1e-12 * scale);
            }
            let h = 1e-6;
            let (before, after) = (k.bodies(theta, -h).unwrap(), k.bodies(theta, h).unwrap());
            let triples = [
                (b.inner, before.inner, after.inner),
                (b.outer, before.outer, after.outer),
                (b.cage, before.cage, after.cage),
                (b.roller, before.roller, after.roller),
            ];
            for (now, prev, next) in triples {
                for p in &points {
                    let local = now.pose.inverse_transform_point(p);
                    let fd = (next.pose * local - prev.pose * local) / (2.0 * h);
                    let v = now.velocity_at(p);
                    assert!(
                        (fd - v).norm() <= 1e-6 * v.norm() + 1e-6,
                        "({wi}, {wo}) θ {theta}: difference {fd} vs twist {v}"
                    );
                }
            }
        }
    }
}

/// The per-cell field on the gap's grid, turned by an orientation: every cell equals the
/// point function at its world point, projected on the grid axes (1e-12 relative); the
/// sliding field is the common-apex rotation ω_rel × (P − A) and the entrainment the mean of
/// the roller's and ring's velocities in the cage frame, ω_R e_r × (P − C) and
/// (ω_i − ω_c) e_z × (P − A), built here independently; the affine form
/// `ContactPair::velocity_field` equals the per-cell fill (1e-12 relative).
#[test]
fn velocity_field_on_a_rotated_grid() {
    let rr = pair("sphere-torus-57");
    let gap = SurfacePairGap::new(rr.face.clone(), rr.rib.clone(), rr.contact).unwrap();
    let frame = ContactFrame::of_gap(&gap);
    let k = TaperedKinematics::of_roller_rib(&rr, 150.0, 0.0).unwrap();
    let pair = k.rib_pair(0.0).unwrap();
    let grid = Grid2::centered(0.8, 0.4, 9, 7).unwrap();
    let orientation = 0.3;
    let mut slide = vec![[0.0; 2]; grid.len()];
    let mut entrain = vec![[0.0; 2]; grid.len()];
    pair.fill_field(&frame, &grid, orientation, &mut slide, &mut entrain)
        .unwrap();
    let affine = pair.velocity_field(&frame, orientation).unwrap();
    let (s, c) = f64::sin_cos(orientation);
    let gx = frame.ex.into_inner() * c + frame.ey.into_inner() * s;
    let gy = frame.normal.cross(&gx);
    let d = k.directions(0.0);
    let centre = k.apex + d.roller_axis * k.roller_reference;
    let scale = k.relative_speed.abs() * 5.0;
    for j in 0..grid.ny() {
        for i in 0..grid.nx() {
            let p = frame.origin + gx * grid.x(i) + gy * grid.y(j);
            let v = pair.velocities(&p, &frame.normal).unwrap();
            let cell = j * grid.nx() + i;
            let vs = k.relative_velocity_at(0.0, &p);
            let u = 0.5
                * ((d.roller_axis * k.roller_spin).cross(&(p - centre))
                    + (d.axis * (k.inner_speed - k.cage_speed)).cross(&(p - k.apex)));
            let (x, y) = (grid.x(i), grid.y(j));
            // The affine form (what the friction integral evaluates) equals the per-cell fill.
            let (sa, ua) = (affine.sliding_at(x, y), affine.entrainment_at(x, y));
            for a in 0..2 {
                assert!((slide[cell][a] - sa[a]).abs() <= 1e-12 * scale, "{sa:?}");
                assert!((entrain[cell][a] - ua[a]).abs() <= 1e-12 * scale, "{ua:?}");
            }
            for (field, point, direct) in [(&slide, v.sliding, vs), (&entrain, v.entrainment, u)] {
                for (a, axis) in [gx, gy].iter().enumerate() {
                    assert!((field[cell][a] - point.dot(axis)).abs() <= 1e-12 * scale);
                    assert!((field[cell][a] - direct.dot(axis)).abs() <= 1e-12 * scale);
                }
            }
        }
    }
}

/// Slide-to-roll ratio is `None` (not NaN or inf) when the entrainment velocity is zero.
#[test]
fn slide_to_roll_undefined_without_entrainment() {
    let still = BodyState::at_rest();
    let p = ContactPair {
        body1: still,
        body2: still,
        observer: still,
    };
    let v = p
        .velocities(&Point3::new(1.0, 2.0, 3.0), &Vector3::z_axis())
        .unwrap();
    assert_eq!(v.slide_to_roll(), None);
    // Pure sliding: one body translates, the other is still, so the mean is half the
    // sliding velocity: ratio 2; the normal component (7 mm/s) is projected out.
    let spinning = BodyState {
        twist: Twist::new(Vector3::new(10.0, 0.0, 7.0), Vector3::zeros()),
        ..still
    };
    let v = ContactPair {
        body1: spinning,
        ..p
    }
    .velocities(&Point3::origin(), &Vector3::z_axis())
    .unwrap();
    assert_eq!(v.sliding, Vector3::new(10.0, 0.0, 0.0));
    assert_eq!(v.entrainment, Vector3::new(5.0, 0.0, 0.0));
    assert!((v.slide_to_roll().unwrap() - 2.0).abs() < 1e-15);
}

/// Bad input gives an error naming the field.
#[test]
fn bad_input_names_the_field() {
    let rr = pair("sphere-cone-29");
    let field =
        |r: kontakt::error::Result<TaperedKinematics>| r.unwrap_err().field().unwrap().to_string();
    assert_eq!(
        field(TaperedKinematics::of_roller_rib(&rr, f64::NAN, 0.0)),
        "inner_speed"
    );
    assert_eq!(
        field(TaperedKinematics::of_roller_rib(&rr, 1.0, f64::INFINITY)),
        "outer_speed"
    );
    assert_eq!(
        field(TaperedKinematics::of_roller_rib(
            &rr,
            f64::NEG_INFINITY,
            0.0
        )),
        "inner_speed"
    );
    let k = TaperedKinematics::of_roller_rib(&rr, 100.0, 0.0).unwrap();
    assert_eq!(
        k.bodies(f64::NAN, 0.0).unwrap_err().field(),
        Some("cage_angle")
    );
    assert_eq!(
        k.bodies(0.0, f64::INFINITY).unwrap_err().field(),
        Some("time")
    );
    let pair = k.rib_pair(0.0).unwrap();
    let nan = Point3::new(f64::NAN, 0.0, 0.0);
    assert_eq!(
        pair.velocities(&nan, &Vector3::z_axis())
            .unwrap_err()
            .field(),
        Some("point")
    );
    let gap = SurfacePairGap::new(rr.face.clone(), rr.rib.clone(), rr.contact).unwrap();
    let grid = Grid2::centered(1.0, 1.0, 4, 4).unwrap();
    let (mut a, mut b) = (vec![[0.0; 2]; 15], vec![[0.0; 2]; 16]);
    let frame = ContactFrame::of_gap(&gap);
    let err = pair
        .fill_field(&frame, &grid, 0.0, &mut a, &mut b)
        .unwrap_err();
    assert_eq!(err.field(), Some("sliding"));
    let mut a = vec![[0.0; 2]; 16];
    let err = pair
        .fill_field(&frame, &grid, f64::NAN, &mut a, &mut b)
        .unwrap_err();
    assert_eq!(err.field(), Some("orientation"));
}
