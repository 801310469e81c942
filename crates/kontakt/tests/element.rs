#![allow(clippy::unwrap_used)]
//! The contact element (issue 12, first step): a sphere on a flat against Hertz's closed form
//! (force, direction, moments about both reference points), separation, Coulomb friction of
//! a sliding sphere, smooth damping, PimP and half-space back-ends against Hertz, the
//! validity flag, continuity of the force along a fine approach sweep, a roller/rib pair
//! from poses, bad input, `Send`, and the gap moved in place (`SurfacePairGap::move_to`).
//! Units: mm, N, N·mm, mm/s, rad/s, W.

use kontakt::bearing::{RollerRib, RollerRibSpec, TABLE1};
use kontakt::element::{Backend, ContactElement, ContactStatus, Damping, ElementSpec};
use kontakt::friction::FrictionLaw;
use kontakt::geometry::{
    ContactPoint, Material, PlacedSurface, Profile, Surface, Twist, find_contact,
};
use kontakt::halfspace::BemOptions;
use kontakt::hertz::{HertzPointContact, PointGeometry};
use kontakt::material::ElasticMaterial;
use kontakt::pimp::{PimpOptions, SurfacePairGap};
use nalgebra::{Isometry3, Point3, Quaternion, Translation3, Unit, UnitQuaternion, Vector3};

const R: f64 = 10.0;

/// A ball of radius 10 mm in body 1 (centre at body 1's origin) over a flat (z = 0) in
/// body 2.
fn ball_on_flat() -> ElementSpec {
    ElementSpec::new(
        PlacedSurface::new(
            Surface::sphere(R, Material::Inside).unwrap(),
            Isometry3::identity(),
        )
        .unwrap(),
        PlacedSurface::new(Surface::plane(Material::Inside), Isometry3::identity()).unwrap(),
    )
    .unwrap()
}

fn at(x: f64, y: f64, z: f64) -> Isometry3<f64> {
    Isometry3::translation(x, y, z)
}

fn hertz_force(delta: f64) -> f64 {
    let steel = ElasticMaterial::STEEL;
    HertzPointContact::new(PointGeometry::sphere_on_flat(R).unwrap(), steel, steel)
        .unwrap()
        .force_from_approach(delta)
        .unwrap()
}

/// Hertz back-end, ball pressed 5 µm into the flat: the normal force equals Hertz's closed
/// form (1e-9), along +z on the ball; the moment about the ball's centre is zero (the force
/// passes through it, 1e-9 F R); about the flat's reference point (5, 0, 0) the moment on the
/// flat is (0, −5F, 0) (1e-9).
#[test]
fn ball_on_flat_matches_hertz_with_moments() {
    let mut e = ContactElement::new(ball_on_flat()).unwrap();
    let delta = 0.005;
    let r = e
        .evaluate(
            &at(0.0, 0.0, R - delta),
            &at(5.0, 0.0, 0.0),
            &Twist::zero(),
            &Twist::zero(),
        )
        .unwrap();
    let f = hertz_force(delta);
    println!(
        "F = {:.9} N (Hertz {f:.9}), approach {:.3e}",
        r.normal_force, r.approach
    );
    assert_eq!(r.status, ContactStatus::Contact);
    assert!((r.approach - delta).abs() < 1e-12);
    assert!((r.normal_force - f).abs() < 1e-9 * f);
    assert!((r.force1 - Vector3::new(0.0, 0.0, f)).norm() < 1e-9 * f);
    assert!(r.moment1.norm() < 1e-9 * f * R, "{:?}", r.moment1);
    assert!((r.moment2 - Vector3::new(0.0, -5.0 * f, 0.0)).norm() < 1e-9 * f * 5.0);
    assert!((r.normal.z - 1.0).abs() < 1e-12);
}

/// Apart: zero force, status separated, the separation reported.
#[test]
fn separated_bodies_give_zero_force() {
    let mut e = ContactElement::new(ball_on_flat()).unwrap();
    let r = e
        .evaluate(
            &at(0.0, 0.0, R + 0.2),
            &Isometry3::identity(),
            &Twist::zero(),
            &Twist::zero(),
        )
        .unwrap();
    assert_eq!(r.status, ContactStatus::Separated);
    assert!((r.separation - 0.2).abs() < 1e-12);
    assert_eq!(r.force1, Vector3::zeros());
    assert_eq!(r.moment1, Vector3::zeros());
}

/// The ball slides along +x at 100 mm/s without rolling: Coulomb friction −μ F x̂ with the
/// regularisation factor v/√(v² + v_ε²) (v_ε = 1 mm/s), power μ F v × that factor / 1000 W;
/// the friction moment about the ball's centre is (F_t R) about +y... with sign: the force
/// −x at the bottom point (0, 0, −R) gives r × F = (0, 0, −R) × (−F_t, 0, 0) = (0, R F_t, 0).
/// Tolerance 1e-9 relative.
#[test]
fn sliding_ball_gets_coulomb_friction() {
    let mut e = ContactElement::new(ball_on_flat()).unwrap();
    let delta = 0.004;
    let v = 100.0;
    let r = e
        .evaluate(
            &at(0.0, 0.0, R - delta),
            &Isometry3::identity(),
            &Twist::new(Vector3::new(v, 0.0, 0.0), Vector3::zeros()),
            &Twist::zero(),
        )
        .unwrap();
    let f = r.normal_force;
    let reg = v / (v * v + 1.0).sqrt();
    let ft = 0.1 * f * reg;
    println!("F_t = {:?}, expected {ft:.9}", r.friction_force);
    assert!((r.friction_force - Vector3::new(-ft, 0.0, 0.0)).norm() < 1e-9 * ft);
    assert!((r.friction_power - ft * v * 1e-3).abs() < 1e-9 * ft * v * 1e-3);
    // Moment about the centre: the friction acts at the contact (z ≈ −R + δ/2).
    let arm = R - delta / 2.0;
    assert!(
        (r.moment1.y - arm * ft).abs() < 1e-6 * arm * ft,
        "{:?}",
        r.moment1
    );
}

/// Damping switches on smoothly: zero at first touch, c_max δ̇ beyond the ramp; the total
/// never pulls.
#[test]
fn damping_switches_on_smoothly() {
    let mut spec = ball_on_flat();
    spec.damping = Some(Damping {
        coefficient: 2.0,
        ramp: 0.002,
    });
    let mut e = ContactElement::new(spec).unwrap();
    let approaching = Twist::new(Vector3::new(0.0, 0.0, -10.0), Vector3::zeros());
    let eval = |e: &mut ContactElement, delta: f64, t: &Twist| {
        e.evaluate(
            &at(0.0, 0.0, R - delta),
            &Isometry3::identity(),
            t,
            &Twist::zero(),
        )
        .unwrap()
    };
    let deep = eval(&mut e, 0.004, &approaching);
    assert!((deep.damping_force - 2.0 * 10.0).abs() < 1e-12);
    let mid = eval(&mut e, 0.001, &approaching);
    // s(1/2) = 1/2; the approach R − (R − δ) carries a rounding of 1e-16 mm.
    assert!((mid.damping_force - 2.0 * 0.5 * 10.0).abs() < 1e-9);
    let touch = eval(&mut e, 1e-9, &approaching);
    assert!(touch.damping_force.abs() < 1e-9, "{}", touch.damping_force);
    // Leaving fast: the damping would pull; the total is clamped at zero.
    let leaving = Twist::new(Vector3::new(0.0, 0.0, 1e6), Vector3::zeros());
    let l = eval(&mut e, 0.004, &leaving);
    assert!((l.normal_force + l.damping_force).abs() < 1e-9 * l.normal_force);
}

/// The field back-ends on the ball: PimP (corrected) within 0.5 % of Hertz's force, the
/// half-space solver within 2 % (its grid).
#[test]
fn field_backends_agree_with_hertz_on_a_ball() {
    let delta = 0.005;
    let f = hertz_force(delta);
    for (backend, tol) in [
        (Backend::Pimp(PimpOptions::default()), 5e-3),
        (Backend::HalfSpace(BemOptions::default()), 2e-2),
    ] {
        let mut spec = ball_on_flat();
        spec.backend = backend;
        let mut e = ContactElement::new(spec).unwrap();
        let r = e
            .evaluate(
                &at(0.0, 0.0, R - delta),
                &Isometry3::identity(),
                &Twist::zero(),
                &Twist::zero(),
            )
            .unwrap();
        println!("{backend:?}: F = {:.4} N vs Hertz {f:.4}", r.normal_force);
        assert!((r.normal_force / f - 1.0).abs() < tol);
        assert!(r.moment1.norm() < 1e-6 * f * R);
    }
}

/// Beyond the validity limit (approach > 1 % of the radius) the status says so with a
/// message; the force is still the model's (continuous for the integrator).
#[test]
fn deep_overlap_is_flagged() {
    let mut e = ContactElement::new(ball_on_flat()).unwrap();
    let r = e
        .evaluate(
            &at(0.0, 0.0, R - 0.2),
            &Isometry3::identity(),
            &Twist::zero(),
            &Twist::zero(),
        )
        .unwrap();
    assert_eq!(r.status, ContactStatus::OutOfValidity);
    assert!(r.message.contains("exceeds"), "{}", r.message);
    assert!((r.normal_force - hertz_force(0.2)).abs() < 1e-9 * r.normal_force);
}

/// Continuity along a fine approach sweep from 1 µm (Hertz: 2000 steps of 2.5 nm; PimP, in
/// the debug build of the tests: 300 steps of 2.5 nm): the second difference of the force
/// is below 1e-4 of the force everywhere. The smooth law F ∝ δ^1.5 alone gives
/// 0.75 (h/δ)² = 4.7e-6; a jump of 1e-4 F (e.g. at a grid resize) would show as a spike.
#[test]
fn force_is_continuous_along_a_fine_sweep() {
    for (backend, steps) in [
        (Backend::Hertz, 2000),
        (Backend::Pimp(PimpOptions::default()), 300),
    ] {
        let mut spec = ball_on_flat();
        spec.backend = backend;
        let mut e = ContactElement::new(spec).unwrap();
        let forces: Vec<f64> = (0..steps)
            .map(|i| {
                let delta = 0.001 + i as f64 * 2.5e-6;
                e.evaluate(
                    &at(0.0, 0.0, R - delta),
                    &Isometry3::identity(),
                    &Twist::zero(),
                    &Twist::zero(),
                )
                .unwrap()
                .normal_force
            })
            .collect();
        let worst = forces
            .windows(3)
            .map(|w| (w[2] - 2.0 * w[1] + w[0]).abs() / w[1])
            .fold(0.0, f64::max);
        println!("{backend:?}: largest second difference / F = {worst:.3e}");
        assert!(worst < 1e-4, "{worst}");
    }
}

/// The roller end face against the rib from poses: the reference placement of the
/// torus/torus pairing, the roller moved 4 µm along the contact normal into the rib gives
/// PimP's force at that approach, directed along the normal (the friction is zero at rest).
#[test]
fn roller_rib_from_poses() {
    let rr = RollerRib::new(RollerRibSpec::builtin("torus-torus-14").unwrap()).unwrap();
    let mut spec = ElementSpec::new(rr.face.clone(), rr.rib.clone()).unwrap();
    spec.backend = Backend::Pimp(PimpOptions::default());
    let mut e = ContactElement::new(spec).unwrap();
    let n = rr.contact.normal.into_inner();
    let delta = 0.004;
    let shift = Isometry3::from_parts(Translation3::from(-n * delta), UnitQuaternion::identity());
    let r = e
        .evaluate(
            &shift,
            &Isometry3::identity(),
            &Twist::zero(),
            &Twist::zero(),
        )
        .unwrap();
    println!(
        "roller/rib: F = {:.3} N, p_max = {:.1} MPa",
        r.normal_force, r.max_pressure
    );
    assert_eq!(r.status, ContactStatus::Contact);
    assert!((r.approach - delta).abs() < 1e-9);
    assert!(r.normal_force > 100.0 && r.normal_force < 1000.0);
    assert!((r.force1.normalize() - n).norm() < 1e-9);
}

/// `stiffness` evaluates every difference from the element's state at the call and leaves
/// that state as it was: along an approach ramp of the torus/torus pairing through a PimP
/// grid resize (and its fade), at every 10th of 2000 steps, two calls give the same matrix
/// bit for bit, and the next evaluation equals that of a copy that took no stiffness. (With
/// the differences run from the state each left behind, the warm starts and the fade's
/// weight moved between them.)
#[test]
fn stiffness_leaves_the_element_as_it_was() {
    let rr = RollerRib::new(RollerRibSpec::builtin("torus-torus-28").unwrap()).unwrap();
    let mut spec = ElementSpec::new(rr.face.clone(), rr.rib.clone()).unwrap();
    spec.backend = Backend::Pimp(PimpOptions::default());
    let mut e = ContactElement::new(spec).unwrap();
    let n = rr.contact.normal.into_inner();
    let at = |delta: f64| {
        Isometry3::from_parts(Translation3::from(-n * delta), UnitQuaternion::identity())
    };
    let (id, z) = (Isometry3::identity(), Twist::zero());
    let steps = 2000;
    for i in 0..steps {
        let delta = 0.0005 + 0.0042 * i as f64 / steps as f64;
        if i % 10 == 5 {
            let mut twin = e.clone();
            let k1 = e.stiffness(&at(delta), &id, &z, &z, 4e-6, 1e-6).unwrap();
            let k2 = e.stiffness(&at(delta), &id, &z, &z, 4e-6, 1e-6).unwrap();
            assert_eq!(k1, k2, "step {i}");
            let (r, r_twin) = (
                e.evaluate(&at(delta), &id, &z, &z).unwrap(),
                twin.evaluate(&at(delta), &id, &z, &z).unwrap(),
            );
            assert_eq!(
                (r.force1, r.moment1),
                (r_twin.force1, r_twin.moment1),
                "step {i}"
            );
        } else {
            e.evaluate(&at(delta), &id, &z, &z).unwrap();
        }
    }
}

/// Bad input: NaN pose, non-unit rotation (of a pose or of a placement), NaN twist, bad
/// damping and validity; each error names its field.
#[test]
fn bad_input_names_the_field() {
    let mut e = ContactElement::new(ball_on_flat()).unwrap();
    let field = |r: kontakt::error::Result<kontakt::element::ElementResult>| {
        r.unwrap_err().field().unwrap().to_string()
    };
    let id = Isometry3::identity();
    let z = Twist::zero();
    assert_eq!(
        field(e.evaluate(&at(f64::NAN, 0.0, R), &id, &z, &z)),
        "pose1"
    );
    let skew = Isometry3::from_parts(
        Translation3::new(0.0, 0.0, 0.0),
        UnitQuaternion::new_unchecked(Quaternion::new(2.0, 0.0, 0.0, 0.0)),
    );
    assert_eq!(field(e.evaluate(&at(0.0, 0.0, R), &skew, &z, &z)), "pose2");
    let nan = Twist::new(Vector3::new(f64::NAN, 0.0, 0.0), Vector3::zeros());
    assert_eq!(field(e.evaluate(&at(0.0, 0.0, R), &id, &nan, &z)), "twist1");
    assert_eq!(field(e.evaluate(&at(0.0, 0.0, R), &id, &z, &nan)), "twist2");
    let mut spec = ball_on_flat();
    spec.damping = Some(Damping {
        coefficient: -1.0,
        ramp: 0.001,
    });
    assert_eq!(
        ContactElement::new(spec.clone()).unwrap_err().field(),
        Some("damping.coefficient")
    );
    spec.damping = Some(Damping {
        coefficient: 1.0,
        ramp: 0.0,
    });
    assert_eq!(
        ContactElement::new(spec.clone()).unwrap_err().field(),
        Some("damping.ramp")
    );
    spec.damping = None;
    spec.max_approach_ratio = f64::NAN;
    assert_eq!(
        ContactElement::new(spec.clone()).unwrap_err().field(),
        Some("max_approach_ratio")
    );
    spec.max_approach_ratio = 0.01;
    // A placement made as a struct literal, past PlacedSurface::new's check.
    let mut placed = spec.clone();
    placed.surface2.pose = skew;
    assert_eq!(
        ContactElement::new(placed).unwrap_err().field(),
        Some("surface2.pose")
    );
    spec.friction = FrictionLaw {
        boundary_coefficient: 2.0,
        ..FrictionLaw::coulomb(0.1).unwrap()
    };
    assert_eq!(
        ContactElement::new(spec).unwrap_err().field(),
        Some("boundary_coefficient")
    );
}

/// An element can move to another thread (one element per roller, many threads).
#[test]
fn element_is_send() {
    fn send<T: Send>() {}
    send::<ContactElement>();
}

/// A dynamic check: a steel ball (R = 10 mm, 32.9 g) pressed onto the flat by a constant
/// 200 N, released from the unloaded Hertz position at rest (δ = 0), oscillates about the
/// equilibrium without damping; velocity Verlet with 200 steps per period over 100
/// oscillations conserves the energy ½ m v² + (2/5) F(δ) δ − F₀ δ to 1e-3 of the oscillation
/// energy (the Hertz back-end: the force from the element, the potential from Hertz's
/// F ∝ δ^1.5). A force with jumps or a wrong direction would pump or drain energy.
#[test]
fn undamped_oscillation_conserves_energy() {
    let mut e = ContactElement::new(ball_on_flat()).unwrap();
    let mass = 7850e-9 * 4.0 / 3.0 * std::f64::consts::PI * R.powi(3); // kg
    let f0 = 200.0; // N, pressing the ball onto the flat
    let id = Isometry3::identity();
    let force = |e: &mut ContactElement, z: f64| {
        e.evaluate(&at(0.0, 0.0, R - z), &id, &Twist::zero(), &Twist::zero())
            .unwrap()
            .force1
            .z
    };
    // δ = z (penetration); acceleration of δ: (F₀ − F(δ)) / m, in mm/s² (N/kg = 1e3 mm/s²).
    let acc = |f: f64| (f0 - f) / mass * 1e3;
    let steel = ElasticMaterial::STEEL;
    let hertz =
        HertzPointContact::new(PointGeometry::sphere_on_flat(R).unwrap(), steel, steel).unwrap();
    let d_eq = hertz.approach_from_force(f0).unwrap();
    let k = 1.5 * f0 / d_eq; // N/mm
    let period = 2.0 * std::f64::consts::PI * (mass / (k * 1e3)).sqrt(); // s
    let dt = period / 200.0;
    // Energy in N·mm: kinetic ½ m v² [kg mm²/s²] × 1e-3.
    let energy = |d: f64, v: f64| {
        let f = if d > 0.0 {
            hertz.force_from_approach(d).unwrap()
        } else {
            0.0
        };
        0.5 * mass * v * v * 1e-3 + 0.4 * f * d - f0 * d
    };
    let (mut d, mut v) = (0.0, 0.0);
    let mut a = acc(0.0);
    let e0 = energy(d, v);
    let mut worst: f64 = 0.0;
    let mut kinetic_max: f64 = 0.0;
    for _ in 0..(200 * 100) {
        d += v * dt + 0.5 * a * dt * dt;
        let a_new = acc(if d > 0.0 { force(&mut e, d) } else { 0.0 });
        v += 0.5 * (a + a_new) * dt;
        a = a_new;
        worst = worst.max((energy(d, v) - e0).abs());
        kinetic_max = kinetic_max.max(0.5 * mass * v * v * 1e-3);
    }
    println!(
        "period {:.3e} s, max energy error {worst:.3e} N·mm of kinetic max {kinetic_max:.3e} N·mm",
        period
    );
    assert!(
        kinetic_max > 0.0 && worst < 1e-3 * kinetic_max,
        "{worst} vs {kinetic_max}"
    );
}

/// Pure spin of the ball about the contact normal (ω = 50 rad/s, μ = 0.1, exact Coulomb):
/// the friction moment about the normal is −(3π/16) μ F a in full slip (μ ∫ p r dA over the
/// Hertz circle, a the contact radius: the lever arm 3πa/16 of docs/friction.md §4.2 at
/// e = 0). The Hertz back-end integrates over the ellipse by a polar rule (docs/mbs.md)
/// centred on the spin pole here, where the stress direction depends on the angle alone:
/// tolerance 1e-9 (the former 16 × 16 sampled field: −0.23 %); the friction force vanishes
/// by symmetry.
#[test]
fn spinning_ball_friction_moment() {
    let mut spec = ball_on_flat();
    // Exact Coulomb: spin slip speeds near the centre are below any regularisation speed.
    spec.friction.regularisation_speed = 0.0;
    let mut e = ContactElement::new(spec).unwrap();
    let delta = 0.005;
    let r = e
        .evaluate(
            &at(0.0, 0.0, R - delta),
            &Isometry3::identity(),
            &Twist::new(Vector3::zeros(), Vector3::new(0.0, 0.0, 50.0)),
            &Twist::zero(),
        )
        .unwrap();
    let a = (R * delta).sqrt();
    let exact = -3.0 * std::f64::consts::PI / 16.0 * 0.1 * r.normal_force * a;
    println!(
        "spin moment {:.9} N·mm, exact {exact:.9} N·mm, error {:.1e}",
        r.moment1.z,
        r.moment1.z / exact - 1.0
    );
    assert!((r.moment1.z / exact - 1.0).abs() < 1e-9);
    assert!(r.friction_force.norm() < 1e-9 * r.normal_force);
    // The friction's own moment about the contact point: all of it, along the normal.
    assert!((r.friction_moment - Vector3::new(0.0, 0.0, exact)).norm() < 1e-9 * exact.abs());
}

/// The stiffness matrix by central differences against the ball's closed forms (δ = 5 µm,
/// steps 5 nm and 1e-6 rad): ∂F_z/∂z₁ = −(3/2) F/δ (1e-5 relative: O(h²)); lateral and
/// rotational terms of the force vanish (a ball on a flat: the normal stays vertical, the
/// force through the centre), and so does every moment about the ball's centre (1e-6 of
/// F R per unit step).
#[test]
fn stiffness_matches_the_ball_closed_form() {
    let mut e = ContactElement::new(ball_on_flat()).unwrap();
    let delta = 0.005;
    let pose1 = at(0.0, 0.0, R - delta);
    let z = Twist::zero();
    let k = e
        .stiffness(&pose1, &Isometry3::identity(), &z, &z, 5e-6, 1e-6)
        .unwrap();
    let f = hertz_force(delta);
    let kzz = -1.5 * f / delta;
    println!("K =\n{k:.4}\nexpected dFz/dz = {kzz:.4} N/mm");
    assert!((k[(2, 2)] / kzz - 1.0).abs() < 1e-5);
    for (i, j) in [(0, 0), (1, 1), (0, 2), (2, 0), (0, 3), (1, 4), (2, 5)] {
        assert!(
            k[(i, j)].abs() < 1e-6 * kzz.abs() * R,
            "K[{i}][{j}] = {}",
            k[(i, j)]
        );
    }
    for i in 3..6 {
        for j in 0..6 {
            assert!(
                k[(i, j)].abs() < 1e-6 * f * R / 5e-6,
                "K[{i}][{j}] = {}",
                k[(i, j)]
            );
        }
    }
    let bad = e.stiffness(&pose1, &Isometry3::identity(), &z, &z, 0.0, 1e-6);
    assert_eq!(bad.unwrap_err().field(), Some("step_translation"));
}

/// Load control: pressing the ball down to 250 N reaches Hertz's approach for 250 N
/// (1e-9 relative in force, 1e-9 in approach), from apart and from too deep; a direction
/// that does not approach is refused.
#[test]
fn press_to_force_reaches_the_hertz_approach() {
    let mut e = ContactElement::new(ball_on_flat()).unwrap();
    let steel = ElasticMaterial::STEEL;
    let hertz =
        HertzPointContact::new(PointGeometry::sphere_on_flat(R).unwrap(), steel, steel).unwrap();
    let target = hertz.approach_from_force(250.0).unwrap();
    let down = -Vector3::z_axis();
    for start in [R + 0.05, R - 0.01] {
        let (pose, r) = e
            .press_to_force(
                &at(0.0, 0.0, start),
                &Isometry3::identity(),
                &Twist::zero(),
                &Twist::zero(),
                &down,
                250.0,
            )
            .unwrap();
        assert!((r.normal_force / 250.0 - 1.0).abs() < 1e-9);
        assert!(
            (r.approach / target - 1.0).abs() < 1e-9,
            "{} vs {target}",
            r.approach
        );
        assert!((pose.translation.vector.z - (R - target)).abs() < 1e-9);
    }
    let err = e
        .press_to_force(
            &at(0.0, 0.0, R),
            &Isometry3::identity(),
            &Twist::zero(),
            &Twist::zero(),
            &Vector3::z_axis(),
            250.0,
        )
        .unwrap_err();
    assert_eq!(err.field(), Some("direction"));
}

// `SurfacePairGap::move_to`, the element's gap moved in place each call (2026-11-27).

/// `move_to` is `new` at the new poses, bit for bit (frame, curvature, the faces' edges),
/// for every built-in roller/rib pairing and a crowned roller (whose profile ends are
/// edges), moved by a shift along the normal, a slide and a tilt.
#[test]
fn moving_a_gap_equals_building_it_anew() {
    let roller = PlacedSurface::new(
        Surface::revolution(
            Profile::Crowned {
                radius: 5.0,
                crown_radius: 300.0,
                half_length: 6.0,
            },
            Material::Inside,
        )
        .unwrap(),
        // Axis along x, 5 mm above the plane z = 0, its end 1 mm from the origin.
        Isometry3::from_parts(
            Translation3::new(5.0, 0.0, 5.0),
            UnitQuaternion::from_axis_angle(&Vector3::y_axis(), std::f64::consts::FRAC_PI_2),
        ),
    )
    .unwrap();
    let plane = PlacedSurface::new(
        Surface::plane(Material::Inside),
        Isometry3::from_parts(
            Translation3::new(0.0, 0.0, 0.0),
            UnitQuaternion::from_axis_angle(&Vector3::y_axis(), 1e-3),
        ),
    )
    .unwrap();
    let mut pairs: Vec<(PlacedSurface, PlacedSurface, Point3<f64>)> = TABLE1
        .iter()
        .map(|(name, ..)| {
            let rr = RollerRib::new(RollerRibSpec::builtin(name).unwrap()).unwrap();
            (rr.face, rr.rib, rr.contact.point)
        })
        .collect();
    pairs.push((roller, plane, Point3::new(5.0, 0.0, 0.0)));
    for (face, other, guess) in pairs {
        let n = find_contact(&face, &other, Some(guess)).unwrap().normal;
        let at = |motion: Isometry3<f64>| {
            let moved = PlacedSurface::new(face.surface.clone(), motion * face.pose).unwrap();
            let contact = find_contact(&moved, &other, Some(guess)).unwrap();
            (moved, contact)
        };
        let (f0, c0) = at(Isometry3::translation(
            -n.x * 4e-3,
            -n.y * 4e-3,
            -n.z * 4e-3,
        ));
        let (f1, c1) = at(Isometry3::from_parts(
            Translation3::from(-n.into_inner() * 5e-3 + n.cross(&Vector3::z()) * 0.02),
            UnitQuaternion::from_axis_angle(&Vector3::x_axis(), 2e-3),
        ));
        let mut gap = SurfacePairGap::new(f0, other.clone(), c0).unwrap();
        gap.move_to(&f1.pose, &other.pose, c1).unwrap();
        assert_eq!(gap, SurfacePairGap::new(f1, other.clone(), c1).unwrap());
    }
}

/// A move that `new` refuses (here a contact whose normal is not finite, so the
/// curvature is not) is refused alike, and leaves the gap as it was.
#[test]
fn a_refused_move_leaves_the_gap_unchanged() {
    let ball = |r: f64, m, z: f64| {
        PlacedSurface::new(
            Surface::sphere(r, m).unwrap(),
            Isometry3::translation(0.0, 0.0, z),
        )
        .unwrap()
    };
    let (b1, socket) = (
        ball(4.0, Material::Inside, 0.0),
        ball(5.0, Material::Outside, 0.0),
    );
    let c = find_contact(&b1, &socket, None).unwrap();
    let mut gap = SurfacePairGap::new(b1.clone(), socket.clone(), c).unwrap();
    let before = gap.clone();
    let moved = ball(4.0, Material::Inside, 1e-4);
    let bad = ContactPoint {
        normal: Unit::new_unchecked(Vector3::new(f64::NAN, 0.0, 1.0)),
        ..find_contact(&moved, &socket, None).unwrap()
    };
    let fresh = SurfacePairGap::new(moved.clone(), socket.clone(), bad);
    let result = gap.move_to(&moved.pose, &socket.pose, bad);
    assert!(fresh.is_err() && result.is_err(), "{fresh:?} {result:?}");
    assert_eq!(gap, before);
}
