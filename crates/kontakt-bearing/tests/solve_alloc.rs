//! Issue 28, "Speed": the bearing solves allocate nothing per call — the solvers own their
//! per-roller and per-slice buffers and the solutions are `Copy` — cold, warm and for
//! every element kind (the cases of benches/bearing.rs).

// The allocation counter of the kontakt crate's tests, shared rather than copied.
#[path = "support/cases.rs"]
mod cases;
#[path = "../../kontakt/tests/support/counting_alloc.rs"]
mod counting_alloc;

use cases::{crb, crb_load, dgbb, dgbb_load, dgbb_speeds, trb, trb_load, trb_rib};
use counting_alloc::allocations;
use kontakt_bearing::ball_equilibrium::BallBearingSolver;
use kontakt_bearing::ball_speed::{BallSpeedSolver, RaceControl};
use kontakt_bearing::equilibrium::RollerBearingSolver;
use kontakt_bearing::equilibrium::coupled::CoupledSliceSolver;
use kontakt_bearing::roller_equilibrium::RibContactSolver;

#[test]
fn roller_bearing_solves_allocate_nothing_cold_or_warm() {
    let mut solver = RollerBearingSolver::new(trb()).expect("valid TRB");
    let (cold, n) = allocations(|| solver.solve(&trb_load(1.0)).expect("solve"));
    assert!(cold.status.converged());
    assert_eq!(n, 0, "cold TRB solve");
    let start = cold.displacement;
    let (warm, n) = allocations(|| solver.solve_from(&trb_load(1.01), start).expect("solve"));
    assert!(warm.status.converged());
    assert_eq!(n, 0, "warm TRB solve");

    let mut solver = RollerBearingSolver::new(crb()).expect("valid CRB");
    let (s, n) = allocations(|| solver.solve(&crb_load()).expect("solve"));
    assert!(s.status.converged());
    assert_eq!(n, 0, "CRB solve");
}

#[test]
fn ball_bearing_solves_allocate_nothing_cold_or_warm() {
    let mut solver = BallBearingSolver::new(dgbb()).expect("valid ball bearing");
    let (cold, n) = allocations(|| solver.solve(&dgbb_load(1.0)).expect("solve"));
    assert!(cold.status.converged());
    assert_eq!(n, 0, "cold ball solve");
    let start = cold.displacement;
    let (warm, n) = allocations(|| solver.solve_from(&dgbb_load(1.01), start).expect("solve"));
    assert!(warm.status.converged());
    assert_eq!(n, 0, "warm ball solve");
}

#[test]
fn ball_bearing_solves_at_speed_allocate_nothing_cold_or_warm() {
    let mut solver = BallSpeedSolver::new(dgbb(), dgbb_speeds(), RaceControl::Outer)
        .expect("valid ball bearing");
    let (cold, n) = allocations(|| solver.solve(&dgbb_load(1.0)).expect("solve"));
    assert!(cold.status.converged());
    assert_eq!(n, 0, "cold ball solve at speed");
    let start = cold.displacement;
    let (warm, n) = allocations(|| solver.solve_from(&dgbb_load(1.01), start).expect("solve"));
    assert!(warm.status.converged());
    assert_eq!(n, 0, "warm ball solve at speed");
}

/// The coupled slices (docs/bearing-model.md §12) on the TRB: none after the first solve,
/// which builds the process-wide strip table.
#[test]
fn coupled_slice_solves_allocate_nothing_cold_or_warm() {
    let mut solver = CoupledSliceSolver::new(trb()).expect("valid TRB");
    let first = solver.solve(&trb_load(1.0)).expect("solve");
    assert!(first.status.converged());
    let (cold, n) = allocations(|| solver.solve(&trb_load(1.0)).expect("solve"));
    assert!(cold.status.converged());
    assert_eq!(n, 0, "cold coupled TRB solve");
    let start = cold.displacement;
    let (warm, n) = allocations(|| solver.solve_from(&trb_load(1.01), start).expect("solve"));
    assert!(warm.status.converged());
    assert_eq!(n, 0, "warm coupled TRB solve");
}

#[test]
fn rib_contact_solves_allocate_nothing_cold_or_warm() {
    let mut solver = RibContactSolver::new(trb(), trb_rib()).expect("valid TRB and rib");
    let (cold, n) = allocations(|| solver.solve(&trb_load(1.0)).expect("solve"));
    assert!(cold.status.converged());
    assert_eq!(n, 0, "cold rib-contact solve");
    let start = cold.displacement;
    let (warm, n) = allocations(|| solver.solve_from(&trb_load(1.01), start).expect("solve"));
    assert!(warm.status.converged());
    assert_eq!(n, 0, "warm rib-contact solve");
}
