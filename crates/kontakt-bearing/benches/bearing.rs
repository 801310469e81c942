//! Criterion benchmarks of the bearing solvers (issue 28, "Speed"): a tapered roller
//! bearing of 20 rollers × 31 slices (ISO/TS 16281 slice law) under a combined load with
//! the tilts held, cold (from the closed-form start) and warm after a 1 % load change
//! (`solve_from` the previous displacement); a deep-groove ball bearing with 10 balls under
//! a combined load, cold; a cylindrical roller bearing of 14 rollers × 31 slices under a
//! radial load, cold, for reference. The solvers are built once outside the timed closure;
//! the timed call is the solve. The Newton iterations of each case are printed once
//! (stderr). Figures in docs/PERFORMANCE.md, "Bearing load distribution (issue 28)".

use criterion::{Criterion, criterion_group, criterion_main};
use kontakt_bearing::ball_equilibrium::BallBearingSolver;
use kontakt_bearing::equilibrium::{RingLoad, RollerBearingSolver};
use kontakt_bearing::geometry::{BallBearing, RollerBearing};
use std::hint::black_box;

/// The 32216 geometry of examples/bearing_32216.toml (d_m 108.5 mm, rollers 17 × 20.7 mm,
/// cup 16.0°, cone 11.7°, ISO profile, zero clearance) with issue 28's 20 rollers
/// (20 · 17 mm ≤ π d_m = 340.9 mm) and 31 slices.
fn trb() -> RollerBearing {
    let mut b = RollerBearing::tapered(
        108.5,
        20,
        17.0,
        20.7,
        16.0_f64.to_radians(),
        11.7_f64.to_radians(),
    );
    b.slices = 31;
    b
}

/// 20 kN radial and 10 kN axial (above F_r tan α = 5.7 kN), tilts held.
fn trb_load(scale: f64) -> RingLoad {
    RingLoad::forces([20_000.0 * scale, 0.0, 10_000.0 * scale, 0.0, 0.0]).with_tilts_held()
}

/// A 6210-class deep-groove ball bearing: d_m 70 mm, 10 balls of 12.7 mm, osculations
/// 0.52/0.53, 10 µm diametral clearance.
fn dgbb() -> BallBearing {
    let mut b = BallBearing::deep_groove(70.0, 10, 12.7, [0.52, 0.53]);
    b.clearance_mm = 0.01;
    b
}

/// A cylindrical roller bearing of 14 rollers 10 × 12 mm on a 60 mm pitch circle (the
/// crate's example), ISO profile, 10 µm clearance, 31 slices.
fn crb() -> RollerBearing {
    let mut b = RollerBearing::cylindrical(60.0, 14, 10.0, 12.0);
    b.clearance_mm = 0.01;
    b.slices = 31;
    b
}

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

    // Deep-groove ball bearing, 10 balls, combined load, cold.
    let mut ball_solver = BallBearingSolver::new(dgbb()).expect("valid ball bearing");
    let ball_load = RingLoad::forces([5_000.0, 0.0, 2_000.0, 0.0, 0.0]);
    let s = ball_solver.solve(&ball_load).expect("solve");
    assert!(s.status.converged(), "{:?}", s.status);
    eprintln!(
        "dgbb_10: cold {} iterations (residual {:.1e}), Q_max {:.0} N",
        s.status.iterations, s.status.residual, s.max_ball_load_n,
    );
    group.bench_function("dgbb_10_combined_cold", |b| {
        b.iter(|| ball_solver.solve(black_box(&ball_load)).expect("solve"))
    });

    // CRB, 14 rollers × 31 slices, radial load, cold.
    let mut crb_solver = RollerBearingSolver::new(crb()).expect("valid CRB");
    let crb_load = RingLoad::forces([10_000.0, 0.0, 0.0, 0.0, 0.0]);
    let s = crb_solver.solve(&crb_load).expect("solve");
    assert!(s.status.converged(), "{:?}", s.status);
    eprintln!(
        "crb_14x31: cold {} iterations (residual {:.1e}), load zone {:?}, Q_max {:.0} N",
        s.status.iterations, s.status.residual, s.load_zone, s.max_roller_load_n,
    );
    group.bench_function("crb_14x31_radial_cold", |b| {
        b.iter(|| crb_solver.solve(black_box(&crb_load)).expect("solve"))
    });
    group.finish();
}

criterion_group!(benches, bench_bearing);
criterion_main!(benches);
