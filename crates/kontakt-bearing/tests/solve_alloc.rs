//! Issue 28, "Speed": the bearing solves allocate nothing per call — the solvers own their
//! per-roller and per-slice buffers and the solutions are `Copy` — cold, warm and for
//! every element kind (the cases of benches/bearing.rs).

// The allocation counter of the kontakt crate's tests, shared rather than copied.
#[path = "../../kontakt/tests/support/counting_alloc.rs"]
mod counting_alloc;

use counting_alloc::allocations;
use kontakt_bearing::ball_equilibrium::BallBearingSolver;
use kontakt_bearing::equilibrium::{RingLoad, RollerBearingSolver};
use kontakt_bearing::geometry::{BallBearing, RollerBearing};

#[test]
fn roller_bearing_solves_allocate_nothing_cold_or_warm() {
    let trb = RollerBearing::tapered(
        108.5,
        20,
        17.0,
        20.7,
        16.0_f64.to_radians(),
        11.7_f64.to_radians(),
    );
    let mut solver = RollerBearingSolver::new(trb).expect("valid TRB");
    let load = RingLoad::forces([20_000.0, 0.0, 10_000.0, 0.0, 0.0]).with_tilts_held();
    let load_1pc = RingLoad::forces([20_200.0, 0.0, 10_100.0, 0.0, 0.0]).with_tilts_held();
    let (cold, n) = allocations(|| solver.solve(&load).expect("solve"));
    assert!(cold.status.converged());
    assert_eq!(n, 0, "cold TRB solve");
    let (warm, n) = allocations(|| {
        solver
            .solve_from(&load_1pc, cold.displacement)
            .expect("solve")
    });
    assert!(warm.status.converged());
    assert_eq!(n, 0, "warm TRB solve");

    let mut crb = RollerBearing::cylindrical(60.0, 14, 10.0, 12.0);
    crb.clearance_mm = 0.01;
    let mut solver = RollerBearingSolver::new(crb).expect("valid CRB");
    let load = RingLoad::forces([10_000.0, 0.0, 0.0, 0.0, 0.0]);
    let (s, n) = allocations(|| solver.solve(&load).expect("solve"));
    assert!(s.status.converged());
    assert_eq!(n, 0, "CRB solve");
}

#[test]
fn ball_bearing_solves_allocate_nothing_cold_or_warm() {
    let mut b = BallBearing::deep_groove(70.0, 10, 12.7, [0.52, 0.53]);
    b.clearance_mm = 0.01;
    let mut solver = BallBearingSolver::new(b).expect("valid ball bearing");
    let load = RingLoad::forces([5_000.0, 0.0, 2_000.0, 0.0, 0.0]);
    let (cold, n) = allocations(|| solver.solve(&load).expect("solve"));
    assert!(cold.status.converged());
    assert_eq!(n, 0, "cold ball solve");
    let load_1pc = RingLoad::forces([5_050.0, 0.0, 2_020.0, 0.0, 0.0]);
    let (warm, n) = allocations(|| {
        solver
            .solve_from(&load_1pc, cold.displacement)
            .expect("solve")
    });
    assert!(warm.status.converged());
    assert_eq!(n, 0, "warm ball solve");
}
