//! The rib friction of every roller (issue 28 §5): the rib loads come from the whole
//! bearing (`RollerBearing::of_roller_rib`, kontakt-bearing's equilibrium) under any
//! combination of radial load, axial load and moment, each roller's rib contact with its
//! own load.
//!
//! - Under pure axial load every roller's loads and rib friction, and the bearing's
//!   totals, equal the rib study's 2-D balance (`RibFrictionModel::sweep`, one roller
//!   times Z) to 1e-9 relative, for Hertz, PimP and the half-space solver, with and
//!   without the centrifugal force, in the library and through the case.
//! - Under combined load the rollers' cone and rib forces on the inner ring balance the
//!   applied load (1e-9), rollers outside the load zone get no rib load (no centrifugal
//!   force) or the rib load of their centrifugal force alone (with it), and the totals are
//!   the sums over the rollers.

#![allow(clippy::unwrap_used)] // tests: a panic is a failure with its message

use kontakt::bearing::{
    BearingRibFriction, PressureModel, RibFrictionModel, RollerCup, TaperedKinematics,
    roller_loads_on_cup,
};
use kontakt_bearing::equilibrium::{RingLoad, RollerBearingSolver};
use kontakt_bearing::geometry::RollerBearing;
use kontakt_case::Case;
use kontakt_case::friction_case::{FrictionCase, FrictionReport, run_friction_case};
use kontakt_case::pimp_case::roller_rib_from_spec;
use nalgebra::Vector3;

const RPM: f64 = std::f64::consts::PI / 30.0;

fn example() -> FrictionCase {
    let text = include_str!("../../../examples/rib_friction.toml");
    let Case::Friction(case) = Case::from_toml_str(text).unwrap() else {
        panic!("not a friction case")
    };
    *case
}

/// The example's model with or without the centrifugal force.
fn model(case: &FrictionCase, centrifugal: bool) -> RibFrictionModel {
    let (_, pair) = roller_rib_from_spec(&case.geometry).unwrap().unwrap();
    let lub = case.lubricant.as_ref().map(|l| l.lubrication().unwrap());
    let law = case.friction.law(lub.is_some()).unwrap();
    RibFrictionModel::new(pair.spec, case.rollers, law, lub, centrifugal).unwrap()
}

/// The cup loads of the rib study's bearing under `(F_r, F_a)` with both tilts held.
fn cups(case: &FrictionCase, m: &RibFrictionModel, radial: f64, axial: f64) -> Vec<RollerCup> {
    let b = RollerBearing::of_roller_rib(m.pair(), &case.rollers).unwrap();
    let mut solver = RollerBearingSolver::new(b).unwrap();
    let load = RingLoad::forces([radial, 0.0, axial, 0.0, 0.0]).with_tilts_held();
    let sol = solver.solve(&load).unwrap();
    assert!(sol.status.converged());
    solver
        .roller_loads()
        .iter()
        .map(|r| RollerCup {
            azimuth: r.azimuth_rad,
            outer_raceway: r.outer_n,
        })
        .collect()
}

fn rel(a: f64, b: f64) -> f64 {
    if a == b { 0.0 } else { (a - b).abs() / b.abs() }
}

fn speeds() -> Vec<f64> {
    [50.0, 900.0, 6000.0].map(|n| n * RPM).to_vec()
}

/// Pure axial load: every roller's loads, rib pressure, coefficient and power, and the
/// bearing's power, torque and inner-ring moment, against the 2-D rib study (one roller
/// times Z), for every pressure model, with and without the centrifugal force.
#[test]
fn pure_axial_load_reproduces_the_rib_study_roller_by_roller() {
    let case = example();
    let mut worst: f64 = 0.0;
    for centrifugal in [false, true] {
        let m = model(&case, centrifugal);
        let cups = cups(&case, &m, 0.0, case.load.axial_n);
        for pm in PressureModel::ALL {
            let today = m.sweep(pm, case.load.axial_n, &speeds()).unwrap();
            let new = m.sweep_rollers(pm, &cups, &speeds()).unwrap();
            for (t, b) in today.iter().zip(&new) {
                assert_eq!(b.rollers.len(), case.rollers.count);
                for r in &b.rollers {
                    let f = r.friction.as_ref().unwrap();
                    for (a, e) in [
                        (r.loads.outer_raceway, t.loads.outer_raceway),
                        (r.loads.inner_raceway, t.loads.inner_raceway),
                        (r.loads.rib, t.loads.rib),
                        (r.loads.centrifugal, t.loads.centrifugal),
                        (f.max_pressure, t.max_pressure),
                        (f.coefficient, t.coefficient),
                        (f.power, t.power),
                        (f.film.lambda.max(1e-300), t.film.lambda.max(1e-300)),
                    ] {
                        worst = worst.max(rel(a, e));
                    }
                }
                for (a, e) in [
                    (b.power, t.bearing_power),
                    (b.torque, t.bearing_torque),
                    (b.ring_axis_moment, t.ring_axis_moment),
                    (b.rib_load, case.rollers.count as f64 * t.loads.rib),
                ] {
                    worst = worst.max(rel(a, e));
                }
            }
        }
    }
    eprintln!("pure axial: largest relative deviation from the 2-D rib study {worst:.3e}");
    assert!(worst < 1e-9, "{worst:e}");
}

/// The same through the case (`kontakt friction`): the rows of `examples/rib_friction.toml`
/// equal the 2-D rib study's per-roller and bearing numbers to 1e-9.
#[test]
fn the_friction_case_under_axial_load_reports_todays_numbers() {
    let case = example();
    let r = run_friction_case(&case).unwrap().report;
    let m = model(&case, case.load.centrifugal);
    let rpm = case.speed.speeds().unwrap();
    let w: Vec<f64> = rpm.iter().map(|n| n * RPM).collect();
    let mut worst: f64 = 0.0;
    for (k, pm) in case.models.iter().enumerate() {
        let today = m.sweep(*pm, case.load.axial_n, &w).unwrap();
        for (i, t) in today.iter().enumerate() {
            let row = &r.rows[k * rpm.len() + i];
            assert_eq!(row.model, pm.as_str());
            for (a, e) in [
                (row.rib_load_n, t.loads.rib),
                (row.max_pressure_mpa, t.max_pressure),
                (row.coefficient, t.coefficient),
                (row.power_w, t.power),
                (row.bearing_power_w, t.bearing_power),
                (row.bearing_drag_torque_nmm, t.bearing_torque),
                (row.inner_ring_rib_moment_nmm, t.ring_axis_moment),
                (row.roller_axis_moment_nmm, t.roller_axis_moment),
            ] {
                worst = worst.max(rel(a, e));
            }
            assert_eq!(row.rib_contacts, case.rollers.count);
        }
    }
    eprintln!("case, pure axial: largest relative deviation {worst:.3e}");
    assert!(worst < 1e-9, "{worst:e}");
}

/// The force of roller `j` (loads `q`) on the inner ring, `−(Q_i n_i + Q_f d)` turned to
/// its azimuth, in the rib study's frame (x radial at azimuth 0, z its axial direction).
fn on_inner_ring(
    k: &TaperedKinematics,
    d: &Vector3<f64>,
    psi: f64,
    qi: f64,
    qf: f64,
) -> Vector3<f64> {
    let ai = k.inner_raceway_angle;
    let (x, z) = (-(qi * ai.cos() + qf * d.x), -(-qi * ai.sin() + qf * d.z));
    Vector3::new(x * psi.cos(), x * psi.sin(), z)
}

/// Combined load (F_r = 8 kN: every roller loaded; 30 kN: a load zone of less than half
/// the ring), with and without the centrifugal force: wherever every loaded roller stays
/// on the cone, the rollers' cone and rib forces on the inner ring add up to the applied
/// load (`(−F_r, 0, F_a)` in the rib study's frame) to 1e-9, the centrifugal forces
/// cancelling over the ring. Rollers outside the load zone carry no rib load without the
/// centrifugal force; with it, they are held by cup and rib against it alone.
#[test]
fn under_combined_load_the_rollers_balance_the_ring_and_unloaded_ones_have_no_rib_load() {
    let case = example();
    let fa = case.load.axial_n;
    for (fr, centrifugal, all_loaded) in [
        (8000.0, false, true),
        (8000.0, true, true),
        (30_000.0, false, false),
        (30_000.0, true, false),
    ] {
        let m = model(&case, centrifugal);
        let cups = cups(&case, &m, fr, fa);
        let n = m.pair().contact.normal.into_inner();
        let d = Vector3::new(n.x, 0.0, n.z).normalize();
        for w in speeds() {
            let k = m.kinematics(w, 0.0).unwrap();
            let fc = m.centrifugal_force(&k);
            let loads = m.roller_loads_on_cups(&k, &cups).unwrap();
            let unloaded = cups.iter().filter(|c| c.outer_raceway == 0.0).count();
            assert_eq!(unloaded == 0, all_loaded, "F_r = {fr}");
            let ao = k.outer_raceway_angle();
            let mut sum = Vector3::zeros();
            // what the rollers off the cone add: their cup loads above the model's
            let mut excess = Vector3::zeros();
            for (c, r) in cups.iter().zip(&loads) {
                let q = r.loads;
                sum += on_inner_ring(&k, &d, r.azimuth, q.inner_raceway, q.rib);
                let extra = q.outer_raceway - c.outer_raceway;
                let (s, co) = r.azimuth.sin_cos();
                excess += Vector3::new(-ao.cos() * co, -ao.cos() * s, ao.sin()) * extra;
                if c.outer_raceway == 0.0 && fc == 0.0 {
                    assert_eq!((q.outer_raceway, q.inner_raceway, q.rib), (0.0, 0.0, 0.0));
                }
                if c.outer_raceway == 0.0 && fc > 0.0 {
                    // off the cone: Q_e n_o + Q_f d + F_c e_x = 0 with Q_i = 0
                    let res = Vector3::new(-ao.cos(), 0.0, ao.sin()) * q.outer_raceway
                        + d * q.rib
                        + Vector3::x() * fc;
                    assert_eq!(q.inner_raceway, 0.0);
                    assert!(q.rib > 0.0 && res.norm() < 1e-12 * fc, "{res}");
                }
            }
            let expected = Vector3::new(-fr, 0.0, fa);
            let err = (sum - expected).norm() / fa;
            let off = (sum - expected - excess).norm() / fa;
            eprintln!(
                "F_r = {fr} N, F_c = {fc:.4} N: {unloaded} rollers outside the load zone, \
                 ring balance error {err:.2e} of F_a, {off:.2e} with the rollers off the cone"
            );
            if unloaded == 0 || fc == 0.0 {
                assert!(err < 1e-9, "{err:e}");
                assert_eq!(excess.norm(), 0.0);
            } else {
                // the rollers off the cone add their centrifugal reactions (the stated
                // approximation of a static load distribution at speed), and only those
                assert!(err > 1e-9, "{err:e}");
            }
            assert!(off < 1e-9, "{off:e}");
        }
    }
}

/// The case under a combined load: the report's totals are the sums over the rollers of
/// its per-roller table, the drag torque `Σ P_j / ω_i`; rollers outside the load zone
/// have no rib contact without the centrifugal force.
#[test]
fn the_case_totals_are_sums_over_the_rollers() {
    for centrifugal in [false, true] {
        let mut case = example();
        case.load.radial_n = 30_000.0;
        case.load.centrifugal = centrifugal;
        case.models = vec![PressureModel::Hertz, PressureModel::Pimp];
        let r: FrictionReport = run_friction_case(&case).unwrap().report;
        assert!(r.bearing.load_zone.unwrap() < 0.5);
        for row in &r.rows {
            let rollers: Vec<_> = r
                .roller_table
                .iter()
                .filter(|t| t.pressure_model == row.model && t.inner_speed_rpm == row.speed_rpm)
                .collect();
            assert_eq!(rollers.len(), case.rollers.count);
            let power: f64 = rollers.iter().map(|t| t.roller_power_w).sum();
            let rib: f64 = rollers.iter().map(|t| t.roller_rib_load_n).sum();
            let contacts = rollers.iter().filter(|t| t.roller_rib_load_n > 0.0).count();
            assert!(rel(row.bearing_power_w, power) < 1e-12);
            assert!(rel(row.rib_load_sum_n, rib) < 1e-12);
            let torque = power * 1e3 / (row.speed_rpm * RPM);
            assert!(rel(row.bearing_drag_torque_nmm, torque) < 1e-12);
            assert_eq!(row.rib_contacts, contacts);
            let most = rollers
                .iter()
                .map(|t| t.roller_rib_load_n)
                .fold(0.0, f64::max);
            assert_eq!(row.rib_load_n, most);
            if centrifugal {
                assert_eq!(contacts, case.rollers.count);
            } else {
                assert!(contacts < case.rollers.count, "{contacts}");
                for t in &rollers {
                    assert_eq!(t.cup_load_n == 0.0, t.roller_rib_load_n == 0.0);
                    assert_eq!(t.cup_load_n == 0.0, t.roller_power_w == 0.0);
                }
            }
        }
    }
}

/// A roller exactly at the threshold of leaving the cone has the same loads from both
/// branches of its balance (continuity, 1e-12).
#[test]
fn leaving_the_cone_is_continuous() {
    let case = example();
    let m = model(&case, true);
    let k = m.kinematics(6000.0 * RPM, 0.0).unwrap();
    let n = m.pair().contact.normal.into_inner();
    let fc = m.centrifugal_force(&k);
    let off = roller_loads_on_cup(&k, &n, 0.0, fc).unwrap();
    let at = roller_loads_on_cup(&k, &n, off.outer_raceway, fc).unwrap();
    assert!(at.inner_raceway.abs() < 1e-12 * off.outer_raceway);
    assert!(rel(at.rib, off.rib) < 1e-12, "{} {}", at.rib, off.rib);
    let e = roller_loads_on_cup(&k, &n, -1.0, fc)
        .unwrap_err()
        .to_string();
    assert!(e.contains("cup_load"), "{e}");
}

/// Bad combined loads are named by their key.
#[test]
fn bad_combined_loads_are_named() {
    let mut case = example();
    case.load.radial_n = -1.0;
    let e = run_friction_case(&case).unwrap_err().to_string();
    assert!(e.contains("load.radial_n"), "{e}");
    let mut case = example();
    case.load.moment_nmm = Some(f64::NAN);
    let e = run_friction_case(&case).unwrap_err().to_string();
    assert!(e.contains("load.moment_nmm"), "{e}");
}

/// Checks the sums helper is not vacuous: a bearing result's totals differ from Z times
/// its most loaded roller under combined load.
#[test]
fn under_combined_load_the_total_is_not_z_times_one_roller() {
    let case = example();
    let m = model(&case, false);
    let cups = cups(&case, &m, 30_000.0, case.load.axial_n);
    let b: BearingRibFriction = m
        .sweep_rollers(PressureModel::Hertz, &cups, &[900.0 * RPM])
        .unwrap()
        .remove(0);
    let most = b.most_loaded().unwrap().power();
    let z = case.rollers.count as f64;
    eprintln!("sum {:.4} W, Z x most loaded {:.4} W", b.power, z * most);
    assert!(b.power < 0.8 * z * most);
}

/// The tilt held or free: applying as `moment_nmm` the moment the shaft takes with the
/// tilts held gives zero tilt and the same rib loads (1e-6), so the moment reaches the
/// rollers through the bearing model; a different moment changes them.
#[test]
fn an_applied_moment_equal_to_the_held_reaction_changes_nothing() {
    let mut case = example();
    case.load.radial_n = 8000.0;
    case.models = vec![PressureModel::Hertz];
    case.speed = toml::from_str("rpm = [900.0]").unwrap();
    let held = run_friction_case(&case).unwrap().report;
    let m = held.bearing.moment_nmm.unwrap()[1];
    assert!(m.abs() > 1e4, "{m}");
    case.load.moment_nmm = Some(m);
    let free = run_friction_case(&case).unwrap().report;
    let tilt = free.bearing.tilt_rad.unwrap()[1];
    assert!(tilt.abs() < 1e-9, "{tilt}");
    let worst = held
        .roller_table
        .iter()
        .zip(&free.roller_table)
        .map(|(a, b)| rel(b.roller_rib_load_n, a.roller_rib_load_n))
        .fold(0.0, f64::max);
    eprintln!("moment {m:.1} N·mm applied: tilt {tilt:.2e} rad, rib loads within {worst:.2e}");
    assert!(worst < 1e-6, "{worst:e}");
    case.load.moment_nmm = Some(0.0);
    let zero = run_friction_case(&case).unwrap().report;
    assert!(zero.bearing.tilt_rad.unwrap()[1].abs() > 1e-4);
    assert!(rel(zero.rows[0].rib_load_n, held.rows[0].rib_load_n) > 0.1);
}
