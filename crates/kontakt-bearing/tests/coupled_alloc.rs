//! Issue 28, "Speed": the coupled-slice solve allocates nothing per call once built (its
//! influence table is built once per process, on the first solve), cold or warm, on the
//! TRB of benches/bearing.rs.

// only the TRB of the shared cases is used here
#[allow(dead_code)]
#[path = "support/cases.rs"]
mod cases;
#[path = "../../kontakt/tests/support/counting_alloc.rs"]
mod counting_alloc;

use cases::{trb, trb_load};
use counting_alloc::allocations;
use kontakt_bearing::equilibrium::coupled::CoupledSliceSolver;

#[test]
fn coupled_slice_solves_allocate_nothing_cold_or_warm() {
    let mut solver = CoupledSliceSolver::new(trb()).expect("valid TRB");
    // the first solve builds the process-wide strip table
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
