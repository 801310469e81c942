#![allow(clippy::unwrap_used)]
use super::*;
use crate::ball_equilibrium::BallBearingSolver;
use crate::ball_speed::{BallSpeedSolver, RaceControl};
use crate::equilibrium::RingLoad;
use crate::friction::raceway::RacewayLubrication;
use kontakt::friction::GridFriction;
use kontakt::lubrication::RollingResistanceModel;
use std::f64::consts::PI;

fn rel(a: f64, b: f64) -> f64 {
    (a - b).abs() / b.abs().max(1e-300)
}

/// The 6205-class DGBB of examples/bearing_6205.toml.
fn dgbb() -> BallBearing {
    let mut b = BallBearing::deep_groove(38.5, 9, 7.938, [0.52, 0.53]);
    b.clearance_mm = 0.015;
    b
}

/// The 7205-class ACBB of docs/bearing-model.md §8.5.
fn acbb() -> BallBearing {
    BallBearing::angular_contact(38.5, 12, 7.938, [0.52, 0.53], 40f64.to_radians())
}

/// ISO VG 68 at 70 °C, isothermal, σ = 0.2 µm, Biboulet-Houpert rolling resistance.
fn lubrication(law: FrictionLaw) -> RacewayLubrication {
    let oil = kontakt::lubrication::Lubricant::iso_vg(68, 860.0, 0.02).unwrap();
    let rolling = RollingResistanceModel::BibouletHoupert;
    crate::friction::torque::raceway_lubrication(&oil, 70.0, false, 0.2e-3, law, rolling).unwrap()
}

fn exact_coulomb(mu: f64) -> FrictionLaw {
    FrictionLaw {
        boundary_coefficient: mu,
        sharing: LoadSharing::Boundary,
        fluid: FluidShear::None,
        regularisation_speed: 0.0,
    }
}

/// The mixed law with μ_b = `mu`, outer-race control.
fn mixed(bearing: BallBearing, mu: f64) -> BallFrictionModel {
    let law = FrictionLaw::mixed(mu).unwrap();
    model(bearing, law, BallAttitude::OuterRaceControl)
}

/// The inner ring at `w` rad/s, no drag, no coefficient.
fn running(balls: &[BallContacts], w: f64) -> BallFrictionOperating<'_> {
    BallFrictionOperating {
        inner_speed: w,
        outer_speed: 0.0,
        balls,
        drag: DragModel::None,
        coefficient_basis: None,
    }
}

fn model(bearing: BallBearing, law: FrictionLaw, attitude: BallAttitude) -> BallFrictionModel {
    let losses = RacewayLosses::new(lubrication(law)).unwrap();
    BallFrictionModel::new(bearing, losses, attitude).unwrap()
}

/// The balls of a quasi-static solve of `bearing` under `force` `[Fx, Fy, Fz]` (N).
fn solved_balls(bearing: &BallBearing, force: [f64; 3]) -> Vec<BallContacts> {
    let mut s = BallBearingSolver::new(bearing.clone()).unwrap();
    let load = RingLoad::forces([force[0], force[1], force[2], 0.0, 0.0]);
    s.solve(&load).unwrap();
    s.ball_loads().iter().map(BallContacts::from).collect()
}

/// The spin vanishes at the controlling contact, for both race controls and unequal
/// contact angles, and the Jones kinematics roll without slip at both contact centres
/// (v₀ = 0 to round-off of the surface speeds).
#[test]
fn race_control_and_rolling_at_the_centres() {
    let (d, dm) = (7.938, 38.5);
    let (ai, ao) = (0.75_f64, 0.55_f64);
    for attitude in [
        BallAttitude::OuterRaceControl,
        BallAttitude::InnerRaceControl,
    ] {
        let beta = attitude.pitch(d / dm, ai, ao);
        let kin = kinematics(RingSpeeds::new(1047.0, -50.0), d, dm, ai, ao, beta);
        let field = |inner: bool| {
            sliding_field(
                d,
                dm,
                0.52,
                &ContactKinematics {
                    inner,
                    contact_angle_rad: if inner { ai } else { ao },
                    ring_speed_rad_s: if inner { 1047.0 } else { -50.0 } - kin.cage_rad_s,
                    ball_speed_rad_s: kin.element_rad_s,
                    pitch_rad: beta,
                },
            )
        };
        let (i, o) = (field(true), field(false));
        for f in [i, o] {
            assert!(
                f.centre_mm_s.abs() < 1e-12 * f.ring_surface_mm_s.abs(),
                "{f:?}"
            );
        }
        let controlled = match attitude {
            BallAttitude::OuterRaceControl => (o.spin_rad_s, i.spin_rad_s),
            BallAttitude::InnerRaceControl => (i.spin_rad_s, o.spin_rad_s),
        };
        println!("{attitude:?}: β {beta:.6} rad, spin controlled {controlled:?} rad/s");
        assert!(
            controlled.0.abs() < 1e-12 * kin.element_rad_s.abs(),
            "{attitude:?}"
        );
        assert!(
            controlled.1.abs() > 1.0,
            "{attitude:?}: the other contact spins"
        );
    }
}

/// Heathcote's pure-rolling lines: under Coulomb friction and the differential slip
/// `v_x = q (y² − c² a²)` alone, the tractive force vanishes for the strips' balance
/// `c³ − 3c + 1 = 0`, `c = 2 cos(4π/9) = 0.347296` (independent of the axis ratio; the
/// load per length across is ∝ 1 − y²/a²). The root of F_x(c) = 0 of the friction
/// integral over the field, by bisection, within 1e-3 (the sliding direction jumps on the
/// rolling lines, where the polar rule converges like 1/n: 7e-4 at 64 × 256 nodes, 4e-4 at
/// 64 × 1024).
#[test]
fn heathcote_rolling_lines_at_0347a() {
    const RULE: (usize, usize) = (64, 256);
    let want = 2.0 * (4.0 * PI / 9.0).cos();
    assert!((want.powi(3) - 3.0 * want + 1.0).abs() < 1e-14);
    let law = exact_coulomb(0.1).with_film(&FilmState::dry()).unwrap();
    let rule = EllipseRule::new(RULE.0, RULE.1).unwrap();
    for (a, b) in [(1.0, 1.0), (2.0, 0.25), (0.9, 0.1)] {
        let q = 50.0;
        let force = |c: f64| -> GridFriction {
            let field = SlidingField {
                centre_mm_s: -q * c * c * a * a,
                spin_rad_s: 0.0,
                roll_rad_s: 0.0,
                curvature: q,
                ball_surface_mm_s: 1000.0,
                ring_surface_mm_s: 1000.0,
            };
            ellipse_friction_curved(
                [a, b],
                PI / 2.0,
                1000.0,
                &field.velocity_field(),
                [q, 0.0],
                &law,
                &rule,
            )
            .unwrap()
        };
        let (mut lo, mut hi) = (0.1, 0.6);
        assert!(force(lo).force[0] * force(hi).force[0] < 0.0);
        for _ in 0..50 {
            let mid = 0.5 * (lo + hi);
            if force(mid).force[0] * force(lo).force[0] > 0.0 {
                lo = mid;
            } else {
                hi = mid;
            }
        }
        let c = 0.5 * (lo + hi);
        println!("a {a}, b {b}: c {c:.6} vs {want:.6}");
        assert!((c - want).abs() < 1e-3, "{c} vs {want}");
        // No transverse force, no spin moment (the field is symmetric).
        let f = force(c);
        assert!(f.force[1].abs() < 1e-12 * f.normal_force);
    }
}

/// Pure spin of a circular Hertz contact with Coulomb friction: the spin moment
/// `M = (3π/16) μ P a` (Johnson 1985 §8.4 / Lundberg), power `M ω_s`, 1e-12.
#[test]
fn pure_spin_moment_of_a_circular_contact() {
    let (mu, a, p0, w) = (0.08, 0.3, 1500.0, 40.0);
    let law = exact_coulomb(mu).with_film(&FilmState::dry()).unwrap();
    let rule = EllipseRule::new(16, 32).unwrap();
    let field = SlidingField {
        centre_mm_s: 0.0,
        spin_rad_s: w,
        roll_rad_s: 0.0,
        curvature: 0.0,
        ball_surface_mm_s: 1.0,
        ring_surface_mm_s: 1.0,
    };
    let f = ellipse_friction_curved(
        [a, a],
        0.0,
        p0,
        &field.velocity_field(),
        [0.0, 0.0],
        &law,
        &rule,
    )
    .unwrap();
    let load = 2.0 * PI * p0 * a * a / 3.0;
    let want = 3.0 * PI / 16.0 * mu * load * a;
    println!("spin moment {} vs {want} N·mm", f.moment);
    assert!(rel(-f.moment, want) < 1e-12, "{} vs {want}", f.moment);
    assert!(rel(f.power, want * w * 1e-3) < 1e-12);
    assert!(f.force[0].abs() + f.force[1].abs() < 1e-12 * load);
    // The curved call with zero curvature is the affine integral itself.
    let g =
        kontakt::friction::ellipse_friction([a, a], 0.0, p0, &field.velocity_field(), &law, &rule)
            .unwrap();
    assert!(rel(g.power, f.power) < 1e-13);
}

/// The bearing's power balance: M |Δω| = Σ contact powers + drag power (1e-12), the ring
/// torques opposite, the shares summing to the total; the sum of the balls' torques is the
/// raceway torque.
#[test]
fn power_balance_of_the_bearing() {
    let bearing = dgbb();
    let balls = solved_balls(&bearing, [3000.0, 0.0, 500.0]);
    let mut m = mixed(bearing, 0.1);
    let op = BallFrictionOperating {
        inner_speed: 3000.0 / 60.0 * 2.0 * PI,
        outer_speed: 0.0,
        balls: &balls,
        drag: DragModel::Torque { nmm: 2.5 },
        coefficient_basis: Some((3000.0, 25.0)),
    };
    let r = m.evaluate(&op).unwrap();
    let sum: f64 = m.balls().iter().map(|b| b.power_w()).sum();
    let dw = op.inner_speed;
    println!(
        "M {:.4} N·mm: inner race {:?}, outer race {:?}, P {:.4} W, Λ_min {:.2}, μ {:.5}",
        r.total_nmm,
        r.inner_race,
        r.outer_race,
        r.power.total_w,
        r.min_lambda,
        r.coefficient.unwrap()
    );
    assert!(rel(r.total_nmm * dw * 1e-3, sum + r.power.drag_w) < 1e-12);
    assert!(rel(r.power.total_w, sum + r.power.drag_w) < 1e-12);
    assert_eq!(r.inner_ring_nmm, -r.outer_ring_nmm);
    let balls_nmm: f64 = m.balls().iter().map(|b| b.torque_nmm).sum();
    assert!(rel(balls_nmm + r.drag_nmm, r.total_nmm) < 1e-12);
    assert!(r.inner_race.sliding_nmm > 0.0 && r.outer_race.sliding_nmm > 0.0);
    assert!(r.inner_race.rolling_nmm > 0.0 && r.outer_race.rolling_nmm > 0.0);
    // Outer ring turning instead: the drive torque changes sign.
    let back = m
        .evaluate(&BallFrictionOperating {
            inner_speed: 0.0,
            outer_speed: dw,
            ..op
        })
        .unwrap();
    assert!(back.inner_ring_nmm < 0.0 && back.outer_ring_nmm > 0.0);
}

/// Scaling laws of the sliding power with exact Coulomb friction (no film effect): ∝ μ
/// and ∝ the speed (the kinematics are linear in the ring speeds), so the sliding torque
/// is speed-independent and equal to the starting torque; 1e-12.
#[test]
fn coulomb_sliding_scales_with_mu_and_speed() {
    let bearing = acbb();
    let balls = solved_balls(&bearing, [1000.0, 0.0, 2000.0]);
    let mut m1 = model(
        bearing.clone(),
        exact_coulomb(0.1),
        BallAttitude::OuterRaceControl,
    );
    let mut m2 = model(bearing, exact_coulomb(0.2), BallAttitude::OuterRaceControl);
    let op = |w: f64| running(&balls, w);
    let a = m1.evaluate(&op(100.0)).unwrap();
    let b = m1.evaluate(&op(300.0)).unwrap();
    let c = m2.evaluate(&op(100.0)).unwrap();
    let s = m1.evaluate(&op(0.0)).unwrap();
    let sliding = |r: &BallBearingFriction| r.inner_race.sliding_nmm + r.outer_race.sliding_nmm;
    println!(
        "sliding torque {:.6} N·mm at 100 rad/s, starting {:.6} N·mm",
        sliding(&a),
        s.total_nmm
    );
    assert!(rel(b.power.sliding_w, 3.0 * a.power.sliding_w) < 1e-12);
    assert!(rel(c.power.sliding_w, 2.0 * a.power.sliding_w) < 1e-12);
    assert!(rel(sliding(&b), sliding(&a)) < 1e-12);
    assert!(s.warnings.starting && s.total_nmm.is_finite());
    assert!(rel(s.total_nmm, sliding(&a)) < 1e-12);
    assert_eq!((s.power.total_w, s.min_lambda), (0.0, f64::INFINITY));
}

/// The mixed law's torque approaches the starting torque as the speed falls (no film,
/// boundary friction μ_b, no rolling resistance), within 2e-3 at 1e-4 rad/s, and the
/// starting torque is positive and finite; at speed the film carries part of the load and
/// the torque drops below it.
#[test]
fn starting_torque_is_the_zero_speed_limit() {
    let bearing = dgbb();
    let balls = solved_balls(&bearing, [2000.0, 0.0, 0.0]);
    // Exact Coulomb direction: the regularised law (v_ε = 1 mm/s) turns viscous below
    // v_ε and its torque vanishes with the speed instead.
    let law = FrictionLaw {
        regularisation_speed: 0.0,
        ..FrictionLaw::mixed(0.12).unwrap()
    };
    let mut m = model(bearing, law, BallAttitude::OuterRaceControl);
    let op = |w: f64| running(&balls, w);
    let s = m.evaluate(&op(0.0)).unwrap();
    let slow = m.evaluate(&op(1e-4)).unwrap();
    let fast = m.evaluate(&op(300.0)).unwrap();
    println!(
        "starting {:.5} N·mm, at 1e-4 rad/s {:.5} N·mm, at 300 rad/s {:.5} N·mm (Λ {:.2})",
        s.total_nmm, slow.total_nmm, fast.total_nmm, fast.min_lambda
    );
    assert!(s.total_nmm > 0.0 && s.total_nmm.is_finite());
    assert!(rel(slow.total_nmm, s.total_nmm) < 2e-3);
    assert!(fast.min_lambda > 0.5 && fast.total_nmm < s.total_nmm);
}

/// At speed, the balls of the Jones solver: the friction's kinematics (outer-race control)
/// give the solver's cage speed, ball speed and pitch per ball (1e-12).
#[test]
fn kinematics_match_the_at_speed_solver() {
    let bearing = acbb();
    let speeds = RingSpeeds::from_rpm(12_000.0, 0.0);
    let mut s = BallSpeedSolver::new(bearing.clone(), speeds, RaceControl::Outer).unwrap();
    s.solve(&RingLoad::forces([500.0, 0.0, 1500.0, 0.0, 0.0]))
        .unwrap();
    let loads = s.ball_loads().to_vec();
    let balls: Vec<BallContacts> = loads.iter().map(BallContacts::from).collect();
    let mut m = mixed(bearing, 0.1);
    let r = m.evaluate(&running(&balls, speeds.inner_rad_s)).unwrap();
    for (f, l) in m.balls().iter().zip(&loads) {
        if l.inner_load_n == 0.0 {
            continue;
        }
        assert!(rel(f.cage_speed_rad_s, l.cage_speed_rad_s) < 1e-12);
        assert!(rel(f.ball_speed_rad_s, l.ball_speed_rad_s) < 1e-12);
        assert!(rel(f.pitch_rad, l.ball_axis_pitch_rad) < 1e-12);
        assert!(f.outer.spin_rad_s.abs() < 1e-9 * f.ball_speed_rad_s.abs());
    }
    println!(
        "7205 at 12 000 r/min: M {:.3} N·mm, largest spin {:.1} rad/s",
        r.total_nmm, r.largest_spin_rad_s
    );
    assert!(r.largest_spin_rad_s > 0.0);
}

#[test]
fn bad_input_names_the_field() {
    let bearing = dgbb();
    let balls = solved_balls(&bearing, [2000.0, 0.0, 0.0]);
    let mut m = mixed(bearing, 0.12);
    let op = running(&balls, 100.0);
    let field = |e: Error| e.field().unwrap_or_default().to_string();
    let e = m
        .evaluate(&BallFrictionOperating {
            inner_speed: f64::NAN,
            ..op
        })
        .unwrap_err();
    assert_eq!(field(e), "inner_speed");
    let e = m
        .evaluate(&BallFrictionOperating {
            balls: &balls[1..],
            ..op
        })
        .unwrap_err();
    assert_eq!(field(e), "balls");
    let mut bad = balls.clone();
    bad[2].outer_load_n = -1.0;
    let e = m
        .evaluate(&BallFrictionOperating { balls: &bad, ..op })
        .unwrap_err();
    assert_eq!(field(e), "outer_load_n");
    let mut bad = balls.clone();
    bad[0].inner_contact_angle_rad = f64::INFINITY;
    let e = m
        .evaluate(&BallFrictionOperating { balls: &bad, ..op })
        .unwrap_err();
    assert_eq!(field(e), "inner_contact_angle_rad");
    let e = m
        .evaluate(&BallFrictionOperating {
            drag: DragModel::Torque { nmm: -1.0 },
            ..op
        })
        .unwrap_err();
    assert_eq!(field(e), "drag");
    assert!(!m.evaluate(&op).unwrap().total_nmm.is_nan());
}

/// One contact's sliding power against an independent implementation
/// (tools/reference/ball_contact_power_reference.py: the rigid-body velocities as 3-D cross
/// products, the mixed law written out, SciPy's adaptive `dblquad` to 1e-12): the field of
/// [`sliding_field`] through the friction integral with a fine rule, 1e-9. The kinematics
/// are not the Jones ones (v₀ ≠ 0), so the centre term is checked too.
#[test]
fn contact_power_matches_the_scipy_reference() {
    let text = include_str!("../../tests/data/ball_contact_power_reference.csv");
    let law = FrictionLaw {
        boundary_coefficient: 0.1,
        sharing: LoadSharing::Exponential { b: 1.90, c: 0.99 },
        fluid: FluidShear::Eyring { tau0: 4.0 },
        regularisation_speed: 200.0,
    };
    let cell = law
        .with_film(&FilmState::new(2.0e-4, 0.8, 0.02e-6, 0.005).unwrap())
        .unwrap();
    let rule = EllipseRule::new(48, 96).unwrap();
    let mut rows = 0;
    for line in text.lines().filter(|l| !l.starts_with('#')).skip(1) {
        let v: Vec<f64> = line.split(',').map(|x| x.parse().unwrap()).collect();
        let k = ContactKinematics {
            inner: v[0] == 1.0,
            contact_angle_rad: v[4],
            ring_speed_rad_s: v[7],
            ball_speed_rad_s: v[6],
            pitch_rad: v[5],
        };
        let field = sliding_field(v[1], v[2], v[3], &k);
        let f = ellipse_friction_curved(
            [v[8], v[9]],
            PI / 2.0,
            v[10],
            &field.velocity_field(),
            [field.curvature, 0.0],
            &cell,
            &rule,
        )
        .unwrap();
        println!(
            "inner {}: {:.12} W vs SciPy {:.12} W, rel {:.1e} (v₀ {:.2} mm/s, ω_s {:.1} rad/s)",
            k.inner,
            f.power,
            v[11],
            rel(f.power, v[11]),
            field.centre_mm_s,
            field.spin_rad_s
        );
        assert!(rel(f.power, v[11]) < 1e-9, "{} vs {}", f.power, v[11]);
        rows += 1;
    }
    assert_eq!(rows, 2);
}

/// The model's traction rule (16 × 32) against a fine one (64 × 512) on the contacts of the
/// ACBB at speed (spin and differential slip, the pole inside the ellipse; the Coulomb part
/// turns round it) and of the radially loaded DGBB (differential slip alone: the sliding
/// direction jumps on the rolling lines): the bearing's sliding power within 5e-4 (measured
/// 8.3e-5 and 1.5e-5).
#[test]
fn the_model_rule_against_a_fine_rule() {
    for (bearing, force, speeds) in [
        (
            acbb(),
            [500.0, 0.0, 1500.0],
            RingSpeeds::from_rpm(12_000.0, 0.0),
        ),
        (
            dgbb(),
            [2000.0, 0.0, 0.0],
            RingSpeeds::from_rpm(3000.0, 0.0),
        ),
    ] {
        let mut s = BallSpeedSolver::new(bearing.clone(), speeds, RaceControl::Outer).unwrap();
        s.solve(&RingLoad::forces([force[0], force[1], force[2], 0.0, 0.0]))
            .unwrap();
        let balls: Vec<BallContacts> = s.ball_loads().iter().map(BallContacts::from).collect();
        let mut m = mixed(bearing, 0.1);
        let op = running(&balls, speeds.inner_rad_s);
        let coarse = m.evaluate(&op).unwrap().power.sliding_w;
        m.rule = EllipseRule::new(64, 512).unwrap();
        let fine = m.evaluate(&op).unwrap().power.sliding_w;
        println!(
            "{} balls: sliding {coarse:.6} W (16 × 32) vs {fine:.6} W (64 × 512), rel {:.1e}",
            balls.len(),
            rel(coarse, fine)
        );
        assert!(rel(coarse, fine) < 5e-4);
    }
}

/// The rolling resistance by strips, Zhou & Hoeprich's fit (f ∝ w^0.246 at fixed U, G,
/// isothermal): the strip sum is `f(w₀) a ∫(1 − t²)^0.246 dt = f(w₀) a B(½, 1.246)`,
/// `B = 1.7513683654018104` (SciPy), w₀ = (π/2) p₀ b the central strip's load per length;
/// the 12-point rule within 2e-5 (measured 5.6e-6; the integrand's power is not an integer
/// at the rim); the
/// power is 2 F_r u.
#[test]
fn rolling_strips_integrate_the_line_fit_over_the_ellipse() {
    let mut l = lubrication(FrictionLaw::mixed(0.1).unwrap());
    l.rolling = RollingResistanceModel::ZhouHoeprich;
    let losses = RacewayLosses::new(l).unwrap();
    let m = BallFrictionModel::new(dgbb(), losses.clone(), BallAttitude::OuterRaceControl).unwrap();
    let (a, b, p0, rx, u, e) = (1.2, 0.15, 1800.0, 3.2, 5000.0, 115_000.0);
    let (force, power, _) = m.rolling(a, b, p0, rx, u, e).unwrap();
    let w0 = PI / 2.0 * p0 * b;
    let centre = losses
        .slice(&RacewaySlice {
            load_per_length: w0,
            width: 1.0,
            radius: rx,
            entrainment_speed: u,
            sliding_speed: 0.0,
            reduced_modulus: e,
        })
        .unwrap();
    let want = centre.rolling_force * a * 1.751_368_365_401_810_4;
    println!(
        "strips {force:.6e} N vs closed form {want:.6e} N, rel {:.1e}",
        rel(force, want)
    );
    assert!(rel(force, want) < 2e-5);
    assert!(rel(power, 2.0 * force * u * 1e-3) < 1e-12);
}

/// Mirror symmetry: a deep groove bearing under +F_z and −F_z (contact angles of opposite
/// sign, the ball's axis pitched the other way) has the same torque and spin (1e-9).
#[test]
fn axial_load_direction_is_mirror_symmetric() {
    let bearing = dgbb();
    let mut m = mixed(bearing.clone(), 0.1);
    let mut torque = |fz: f64| {
        let balls = solved_balls(&bearing, [1000.0, 0.0, fz]);
        let r = m.evaluate(&running(&balls, 500.0)).unwrap();
        (
            r.total_nmm,
            r.largest_spin_rad_s,
            balls[0].inner_contact_angle_rad,
        )
    };
    let (up, down) = (torque(800.0), torque(-800.0));
    println!("+F_z: {up:?}, −F_z: {down:?}");
    assert!(up.2 * down.2 < 0.0 && rel(up.2, -down.2) < 1e-9);
    assert!(rel(up.0, down.0) < 1e-9 && rel(up.1, down.1) < 1e-9);
    assert!(up.1 > 0.0);
}

/// An open contact's angle is only the direction of its gap (the at-speed solver reports up
/// to π for a lifted inner contact): the kinematics take the loaded contact's angle there,
/// the torque stays finite and equals that of the angle replaced; a loaded contact beyond
/// ±π/2 is an error naming it.
#[test]
fn an_open_contact_angle_does_not_enter_the_kinematics() {
    let bearing = dgbb();
    let mut balls = solved_balls(&bearing, [2000.0, 0.0, 0.0]);
    let mut m = mixed(bearing, 0.1);
    let idle = balls.iter().position(|b| b.inner_load_n == 0.0).unwrap();
    balls[idle].outer_load_n = 0.6; // the centrifugal force alone
    let want = m.evaluate(&running(&balls, 300.0)).unwrap().total_nmm;
    balls[idle].inner_contact_angle_rad = PI;
    let got = m.evaluate(&running(&balls, 300.0)).unwrap().total_nmm;
    assert!(got.is_finite() && rel(got, want) < 1e-14, "{got} vs {want}");
    balls[0].inner_contact_angle_rad = 2.0;
    let e = m.evaluate(&running(&balls, 300.0)).unwrap_err();
    assert_eq!(e.field(), Some("inner_contact_angle_rad"));
}
