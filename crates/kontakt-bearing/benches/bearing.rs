//! Criterion benchmarks of the bearing solvers (issue 28, "Speed"): a tapered roller
//! bearing of 20 rollers × 31 slices (ISO/TS 16281 slice law) under a combined load with
//! the tilts held, cold (from the closed-form start) and warm after a 1 % load change
//! (`solve_from` the previous displacement); a deep-groove ball bearing with 10 balls under
//! a combined load, cold, at rest and at 10 000 r/min; a cylindrical roller bearing of 14
//! rollers × 31 slices under a radial load, cold, for reference; the same TRB with the
//! rib-contact roller model (`roller_equilibrium`: every roller in its own balance, Hertz
//! rib contacts), cold and warm after a 1 % load change; the TRB with coupled slices
//! (half-space strips), cold. The solvers are built once outside the timed closure; the
//! timed call is the solve. The Newton iterations of each case are printed once (stderr).
//! Figures in docs/PERFORMANCE.md, "Bearing load distribution (issue 28)".

#[path = "../tests/support/cases.rs"]
mod cases;

use cases::{crb, crb_load, dgbb, dgbb_load, dgbb_speeds, trb, trb_load, trb_rib};
use criterion::{Criterion, criterion_group, criterion_main};
use kontakt_bearing::ball_equilibrium::BallBearingSolver;
use kontakt_bearing::ball_speed::{BallSpeedSolver, RaceControl};
use kontakt_bearing::equilibrium::RollerBearingSolver;
use kontakt_bearing::equilibrium::coupled::CoupledSliceSolver;
use kontakt_bearing::roller_equilibrium::RibContactSolver;
use std::hint::black_box;

fn bench_bearing(c: &mut Criterion) {
    let mut group = c.benchmark_group("bearing");

    // TRB, cold and warm.
    let mut trb_solver = RollerBearingSolver::new(trb()).expect("valid TRB");
    let (load, load_1pc) = (trb_load(1.0), trb_load(1.01));
    let previous = trb_solver.solve(&load).expect("solve");
    assert!(previous.status.converged(), "{:?}", previous.status);
    let warm = trb_solver
        .solve_from(&load_1pc, previous.displacement)
        .expect("solve");
    assert!(warm.status.converged(), "{:?}", warm.status);
    eprintln!(
        "trb_20x31: cold {} iterations (residual {:.1e}), warm after +1 % {} iterations (residual {:.1e}), load zone {:?}, Q_max {:.0} N",
        previous.status.iterations,
        previous.status.residual,
        warm.status.iterations,
        warm.status.residual,
        previous.load_zone,
        previous.max_roller_load_n,
    );
    group.bench_function("trb_20x31_cold", |b| {
        b.iter(|| trb_solver.solve(black_box(&load)).expect("solve"))
    });
    let start = previous.displacement;
    group.bench_function("trb_20x31_warm_1pc", |b| {
        b.iter(|| {
            trb_solver
                .solve_from(black_box(&load_1pc), black_box(start))
                .expect("solve")
        })
    });

    // TRB with every roller in its own balance and Hertz rib contacts (the rib-contact
    // roller model), cold and warm: issue 28's "ISO slice law, Hertz rib contacts" case.
    let mut rib_solver = RibContactSolver::new(trb(), trb_rib()).expect("valid TRB and rib");
    let previous = rib_solver.solve(&load).expect("solve");
    assert!(previous.status.converged(), "{:?}", previous.status);
    let warm = rib_solver
        .solve_from(&load_1pc, previous.displacement)
        .expect("solve");
    assert!(warm.status.converged(), "{:?}", warm.status);
    eprintln!(
        "trb_rib_20x31: cold {} iterations (residual {:.1e}), warm after +1 % {} iterations (residual {:.1e}), Q_max {:.0} N, rib {:.0} N",
        previous.status.iterations,
        previous.status.residual,
        warm.status.iterations,
        warm.status.residual,
        previous.max_roller_load_n,
        rib_solver.max_rib_load_n(),
    );
    group.bench_function("trb_rib_20x31_cold", |b| {
        b.iter(|| rib_solver.solve(black_box(&load)).expect("solve"))
    });
    // alternate between the two loads, each solve warm from the other's equilibrium (ring
    // and rollers): every timed call is a warm solve after a 1 % load change
    let starts = [previous.displacement, warm.displacement];
    let loads = [load_1pc, load];
    let mut turn = 0;
    group.bench_function("trb_rib_20x31_warm_1pc", |b| {
        b.iter(|| {
            let s = rib_solver
                .solve_from(black_box(&loads[turn]), black_box(starts[turn]))
                .expect("solve");
            turn = 1 - turn;
            s
        })
    });

    // Deep-groove ball bearing, 10 balls, combined load, cold.
    let mut ball_solver = BallBearingSolver::new(dgbb()).expect("valid ball bearing");
    let ball_load = dgbb_load(1.0);
    let s = ball_solver.solve(&ball_load).expect("solve");
    assert!(s.status.converged(), "{:?}", s.status);
    eprintln!(
        "dgbb_10: cold {} iterations (residual {:.1e}), Q_max {:.0} N",
        s.status.iterations, s.status.residual, s.max_ball_load_n,
    );
    group.bench_function("dgbb_10_combined_cold", |b| {
        b.iter(|| ball_solver.solve(black_box(&ball_load)).expect("solve"))
    });

    // The same ball bearing at 10 000 r/min (Jones's high-speed model, outer-race
    // control), cold: the quasi-static start, then every ball's own Newton inside the
    // ring's (issue 28: at most 50 µs).
    let mut speed_solver = BallSpeedSolver::new(dgbb(), dgbb_speeds(), RaceControl::Outer)
        .expect("valid ball bearing");
    let s = speed_solver.solve(&ball_load).expect("solve");
    assert!(s.status.converged(), "{:?}", s.status);
    eprintln!(
        "dgbb_10_speed: cold {} iterations at speed (residual {:.1e}), Q_max {:.0} N, load zone {:?}",
        s.status.iterations, s.status.residual, s.max_ball_load_n, s.load_zone,
    );
    group.bench_function("dgbb_10_combined_10000rpm_cold", |b| {
        b.iter(|| speed_solver.solve(black_box(&ball_load)).expect("solve"))
    });

    // CRB, 14 rollers × 31 slices, radial load, cold.
    let mut crb_solver = RollerBearingSolver::new(crb()).expect("valid CRB");
    let crb_load = crb_load();
    let s = crb_solver.solve(&crb_load).expect("solve");
    assert!(s.status.converged(), "{:?}", s.status);
    eprintln!(
        "crb_14x31: cold {} iterations (residual {:.1e}), load zone {:?}, Q_max {:.0} N",
        s.status.iterations, s.status.residual, s.load_zone, s.max_roller_load_n,
    );
    group.bench_function("crb_14x31_radial_cold", |b| {
        b.iter(|| crb_solver.solve(black_box(&crb_load)).expect("solve"))
    });

    // The same TRB with coupled slices (half-space strips), cold: the ISO solve as its
    // start, then the ring's Newton with a slice solve per roller and evaluation.
    let mut coupled = CoupledSliceSolver::new(trb()).expect("valid TRB");
    let s = coupled.solve(&load).expect("solve");
    assert!(s.status.converged(), "{:?}", s.status);
    eprintln!(
        "trb_20x31_coupled: cold {} ring iterations (residual {:.1e}), at most {} slice iterations per roller, Q_max {:.0} N",
        s.status.iterations,
        s.status.residual,
        coupled.slice_iterations(),
        s.max_roller_load_n,
    );
    group.bench_function("trb_20x31_coupled_cold", |b| {
        b.iter(|| coupled.solve(black_box(&load)).expect("solve"))
    });
    group.finish();
}

criterion_group!(benches, bench_bearing);
criterion_main!(benches);
