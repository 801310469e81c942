#![allow(clippy::unwrap_used)]
//! The contact element's half-space back-end between calls: the warm start on a kept grid
//! gives the cold solve's force with far fewer iterations, elements share one plan through
//! a planner, and the grid is re-laid smoothly when the zone outgrows it. Units: mm, N.

use kontakt::bearing::{RollerRib, RollerRibSpec};
use kontakt::element::{Backend, ContactElement, ElementSpec};
use kontakt::geometry::Twist;
use kontakt::halfspace::{BemOptions, HalfSpacePlanner};
use nalgebra::{Isometry3, Translation3, UnitQuaternion, Vector3};
use std::sync::{Arc, Mutex};

/// The torus/torus roller-end/rib pairing (Wirsching, Schwarz & Tremmel 2020, Table 1) with
/// the half-space back-end on one thread, and the roller pose at approach `depth` \[mm\]
/// moved `across` \[mm\] across the contact.
fn roller_rib() -> (ElementSpec, impl Fn(f64, f64) -> Isometry3<f64>) {
    let rr = RollerRib::new(RollerRibSpec::builtin("torus-torus-14").unwrap()).unwrap();
    let n = rr.contact.normal.into_inner();
    let side = n.cross(&Vector3::z()).normalize();
    let mut spec = ElementSpec::new(rr.face.clone(), rr.rib.clone()).unwrap();
    spec.backend = Backend::HalfSpace(BemOptions {
        threads: Some(1),
        ..BemOptions::default()
    });
    let pose = move |depth: f64, across: f64| {
        Isometry3::from_parts(
            Translation3::from(-n * depth + side * across),
            UnitQuaternion::identity(),
        )
    };
    (spec, pose)
}

/// The element of `spec` with the half-space solver's tolerance `bem_tolerance` and the
/// warm tolerance `warm_tolerance`, one thread.
fn tolerances(spec: &ElementSpec, bem_tolerance: f64, warm_tolerance: f64) -> ContactElement {
    let mut s = spec.clone();
    s.backend = Backend::HalfSpace(BemOptions {
        threads: Some(1),
        tolerance: bem_tolerance,
        ..BemOptions::default()
    });
    s.warm_tolerance = warm_tolerance;
    ContactElement::new(s).unwrap()
}

/// Step `k` of `benches/element.rs`: a 1 % load step (the approach alternates between two
/// values whose Hertz forces differ by 1 %) or a pose step of 1.4 µm across the contact,
/// back and forth over ±70 µm.
fn bench_step(pose: &impl Fn(f64, f64) -> Isometry3<f64>, k: usize, load: bool) -> Isometry3<f64> {
    if load {
        let depth = [0.0042, 0.0042 * 1.01f64.powf(2.0 / 3.0)];
        pose(depth[k % 2], 0.0)
    } else {
        let m = k % 200;
        let tri = if m < 100 { m } else { 200 - m } as f64 - 50.0;
        pose(0.0042, tri * 1.4e-3)
    }
}

fn force(e: &mut ContactElement, pose: &Isometry3<f64>) -> (f64, usize) {
    let r = e
        .evaluate(pose, &Isometry3::identity(), &Twist::zero(), &Twist::zero())
        .unwrap();
    (r.normal_force, r.iterations)
}

/// A step of 0.1 % of the contact width (1.4 µm): the warm solve gives the force of a
/// fresh element's cold solve at the new pose to 1e-6 (the cold solve converges to a
/// residual of 1e-8, the warm one to the element's warm tolerance of 1e-6, on the same
/// ladder grid), in under a third of its iterations.
#[test]
fn warm_start_gives_the_cold_force_in_fewer_iterations() {
    let (spec, pose) = roller_rib();
    let mut warm = ContactElement::new(spec.clone()).unwrap();
    force(&mut warm, &pose(0.0042, 0.0));
    let (f_warm, it_warm) = force(&mut warm, &pose(0.0042, 1.4e-3));
    let mut cold = ContactElement::new(spec).unwrap();
    let (f_cold, it_cold) = force(&mut cold, &pose(0.0042, 1.4e-3));
    assert!(
        (f_warm / f_cold - 1.0).abs() < 1e-6,
        "warm {f_warm} N, cold {f_cold} N"
    );
    assert!(3 * it_warm < it_cold, "warm {it_warm}, cold {it_cold}");
    // reset forgets the grid: the next call is cold again.
    warm.reset();
    let (f_reset, it_reset) = force(&mut warm, &pose(0.0042, 1.4e-3));
    assert!((f_reset / f_cold - 1.0).abs() < 1e-9);
    assert_eq!(it_reset, it_cold);
}

/// Two elements on one planner: the second, at the same pose, builds no plan of its own.
#[test]
fn elements_share_one_plan() {
    let (spec, pose) = roller_rib();
    let planner = Arc::new(Mutex::new(HalfSpacePlanner::new()));
    let mut a = ContactElement::with_planner(spec.clone(), planner.clone()).unwrap();
    force(&mut a, &pose(0.0042, 0.0));
    let built = planner.lock().unwrap().plans_built();
    assert!(built >= 1);
    let mut b = ContactElement::with_planner(spec, planner.clone()).unwrap();
    force(&mut b, &pose(0.0042, 0.0));
    force(&mut b, &pose(0.0042, 1.4e-3));
    assert_eq!(planner.lock().unwrap().plans_built(), built);
}

/// A load ramp through grid re-layings: the approach grows from 2 to 8 µm in 0.5 % steps
/// (the contact width doubles, so the zone outgrows the first grids). The Hertz-normalised
/// stiffness F/δ^1.5 changes smoothly: no step differs from the mean of its neighbours
/// by more than 2e-4 (measured 2.2e-5 with the discretisation changes at the re-laid
/// grids, 64 × 64 cells).
#[test]
fn load_ramp_through_new_grids_is_smooth() {
    let (spec, pose) = roller_rib();
    let mut e = ContactElement::new(spec).unwrap();
    let mut k = Vec::new();
    let mut depth = 0.002;
    while depth < 0.008 {
        let (f, _) = force(&mut e, &pose(depth, 0.0));
        k.push(f / depth.powf(1.5));
        depth *= 1.005;
    }
    let mut worst: f64 = 0.0;
    for w in k.windows(3) {
        worst = worst.max((w[1] / (0.5 * (w[0] + w[2])) - 1.0).abs());
    }
    assert!(e.grids_laid() >= 3, "{} grids laid", e.grids_laid());
    assert!(worst < 2e-4, "largest kink {worst:e}");
}

/// From the full contact (4.2 µm) to a touch of a few cells (0.3-3 µm, 24 approaches),
/// each time from the full contact, then to 1e-14 mm (the round-off overlap of surfaces
/// placed exactly tangent) and back: every call converges (a warm start's first step can
/// unload every cell; the solver then re-admits the overlapping ones), a touch that reaches
/// no cell centre gives zero force, and the full contact comes back to 1e-6.
#[test]
fn from_full_contact_to_a_touch_and_back() {
    let (spec, pose) = roller_rib();
    let mut e = ContactElement::new(spec).unwrap();
    let (f_full, _) = force(&mut e, &pose(0.0042, 0.0));
    for k in 0..24 {
        let depth = 3e-4 * 10f64.powf(k as f64 / 23.0);
        let (f_touch, _) = force(&mut e, &pose(depth * 1e-3, 0.0));
        assert!(
            f_touch >= 0.0 && f_touch < 0.5 * f_full,
            "{depth} µm: {f_touch} N"
        );
        force(&mut e, &pose(0.0042, 0.0));
    }
    let (f_zero, _) = force(&mut e, &pose(1e-14, 0.0));
    assert_eq!(f_zero, 0.0);
    let (f_back, _) = force(&mut e, &pose(0.0042, 0.0));
    assert!((f_back / f_full - 1.0).abs() < 1e-6, "{f_back} vs {f_full}");
}

/// The steps of `benches/element.rs` (`evaluate_halfspace_64*`): warm after a pose step of
/// 1.4 µm across the contact, and after a 1 % load step (the approach alternating between
/// two values whose Hertz forces differ by 1 %). With the FFT preconditioner (Vollebregt
/// 2014, the default) a pose step took 13-16 iterations and a load step 9-14 at 1e-8; the
/// unpreconditioned solver took 26-44 and 44-46 on these steps (2026-11-24), so the bounds
/// fail it. With the secant start and the element's warm tolerance of 1e-6 (2026-11-27):
/// [6, 5, 2, 3, 2, 2] and [9, 7, 0, 0, 0, 0].
#[test]
fn preconditioned_warm_steps_take_a_few_iterations() {
    let (spec, pose) = roller_rib();
    let mut e = ContactElement::new(spec.clone()).unwrap();
    force(&mut e, &pose(0.0042, 0.0));
    let mut pose_its = Vec::new();
    for k in 1..=6 {
        pose_its.push(force(&mut e, &pose(0.0042, 1.4e-3 * k as f64)).1);
    }
    let mut e = ContactElement::new(spec).unwrap();
    force(&mut e, &bench_step(&pose, 0, true));
    let mut load_its = Vec::new();
    for k in 1..=6 {
        load_its.push(force(&mut e, &bench_step(&pose, k, true)).1);
    }
    eprintln!("warm iterations: pose steps {pose_its:?}, load steps {load_its:?}");
    assert!(pose_its.iter().all(|&n| n <= 20), "{pose_its:?}");
    assert!(load_its.iter().all(|&n| n <= 18), "{load_its:?}");
}

/// The element's warm tolerance ([`ElementSpec::warm_tolerance`], default 1e-6, with the
/// secant start and incremental displacement updates of its warm calls) against the
/// same steps solved to 1e-12 (`BemOptions::tolerance` 1e-12, `warm_tolerance` 0): 40
/// pose steps of 1.4 µm and 40 load steps of 1 % (the steps of `benches/element.rs`).
/// The force differs by at most 2e-6 of itself (measured 1.1e-6 on the pose steps,
/// 5.5e-7 on the load steps, 2026-11-27); at `warm_tolerance` 0 (the solver's 1e-8) by at
/// most 2e-8. The mean warm iterations are printed.
#[test]
fn warm_tolerance_costs_at_most_2e_6_of_the_force() {
    let (spec, pose) = roller_rib();
    let run = |bem_tolerance: f64, warm_tolerance: f64, load: bool| {
        let mut e = tolerances(&spec, bem_tolerance, warm_tolerance);
        let at = |k: usize| bench_step(&pose, k, load);
        force(&mut e, &at(0));
        let steps: Vec<(f64, usize)> = (1..=40).map(|k| force(&mut e, &at(k))).collect();
        assert_eq!(e.grids_laid(), 1);
        steps
    };
    for load in [false, true] {
        let exact = run(1e-12, 0.0, load);
        for (warm_tolerance, bound) in [(kontakt::element::WARM_TOLERANCE, 2e-6), (0.0, 2e-8)] {
            let steps = run(1e-8, warm_tolerance, load);
            let worst = steps
                .iter()
                .zip(&exact)
                .map(|((f, _), (fx, _))| (f / fx - 1.0).abs())
                .fold(0.0, f64::max);
            let mean = steps.iter().map(|s| s.1).sum::<usize>() as f64 / steps.len() as f64;
            eprintln!(
                "{} steps, warm tolerance {warm_tolerance:e}: force error {worst:.2e}, \
                 {mean:.2} iterations on average",
                if load { "load" } else { "pose" }
            );
            assert!(worst < bound, "{worst:e}");
        }
    }
}

/// What a warm call returns besides the force, against the same steps solved to 1e-12
/// (`BemOptions::tolerance` 1e-12, `warm_tolerance` 0): 40 pose steps of 1.4 µm and 40
/// load steps of 1 % (the steps of `benches/element.rs`), the roller spinning at 10 rad/s
/// about the world z axis. The warm calls (the secant start without the Hertz-like
/// estimate, the displacement extrapolated, the friction by blocks of cells) give the
/// moments on both bodies, the friction force and power within 2e-6 of their sizes and
/// the largest pressure within 2e-6 (measured 1.1e-6 and 5.0e-7 on the pose steps, 5.5e-7
/// and 4.3e-7 on the load steps, 2026-11-27); the contact area within 1e-3 (2 of about
/// 1980 loaded cells; measured one cell on a pose step).
#[test]
fn warm_moments_and_friction_match_tight_solves() {
    let (spec, pose) = roller_rib();
    let spin = Twist::new(Vector3::zeros(), Vector3::new(0.0, 0.0, 10.0));
    let run = |bem_tolerance: f64, warm_tolerance: f64, load: bool| {
        let mut e = tolerances(&spec, bem_tolerance, warm_tolerance);
        let at = |k: usize| bench_step(&pose, k, load);
        (0..=40)
            .map(|k| {
                e.evaluate(&at(k), &Isometry3::identity(), &spin, &Twist::zero())
                    .unwrap()
            })
            .skip(1)
            .collect::<Vec<_>>()
    };
    for load in [false, true] {
        let exact = run(1e-12, 0.0, load);
        let warm = run(1e-8, kontakt::element::WARM_TOLERANCE, load);
        let mut worst = [0.0f64; 6];
        for (w, x) in warm.iter().zip(&exact) {
            let rel = |a: f64, b: f64, scale: f64| (a - b).abs() / scale;
            let e = [
                (w.moment1 - x.moment1).norm() / x.moment1.norm(),
                (w.moment2 - x.moment2).norm() / x.moment2.norm(),
                (w.friction_force - x.friction_force).norm() / x.friction_force.norm(),
                rel(w.friction_power, x.friction_power, x.friction_power),
                rel(w.max_pressure, x.max_pressure, x.max_pressure),
                rel(w.contact_area, x.contact_area, x.contact_area),
            ];
            for (a, b) in worst.iter_mut().zip(e) {
                *a = a.max(b);
            }
        }
        eprintln!(
            "{} steps: moment1 {:.1e}, moment2 {:.1e}, friction force {:.1e}, power {:.1e}, \
             max pressure {:.1e}, area {:.1e}",
            if load { "load" } else { "pose" },
            worst[0],
            worst[1],
            worst[2],
            worst[3],
            worst[4],
            worst[5]
        );
        assert!(worst[..5].iter().all(|&e| e < 2e-6), "{worst:?}");
        assert!(worst[5] < 1e-3, "{worst:?}");
    }
}
