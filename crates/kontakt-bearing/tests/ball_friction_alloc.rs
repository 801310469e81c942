//! Issue 29, "Speed": the ball-bearing friction allocates nothing per operating point (the
//! model owns its traction rule, its strips and its per-ball buffer; every result is
//! `Copy`), at speed and at standstill, on a solved load distribution (quasi-static and at
//! speed).

#[path = "support/cases.rs"]
#[allow(dead_code)]
mod cases;
#[path = "../../kontakt/tests/support/counting_alloc.rs"]
mod counting_alloc;
#[path = "support/friction.rs"]
#[allow(dead_code)]
mod friction;

use cases::{dgbb, dgbb_load, dgbb_speeds};
use counting_alloc::allocations;
use kontakt_bearing::ball_equilibrium::BallBearingSolver;
use kontakt_bearing::ball_speed::{BallSpeedSolver, RaceControl};
use kontakt_bearing::friction::ball::{
    BallAttitude, BallContacts, BallFrictionModel, BallFrictionOperating,
};
use kontakt_bearing::friction::torque::DragModel;

fn model() -> BallFrictionModel {
    let losses = friction::losses(&friction::vg68(), 70.0, true);
    BallFrictionModel::new(dgbb(), losses, BallAttitude::OuterRaceControl).expect("model")
}

#[test]
fn ball_friction_allocates_nothing_per_operating_point() {
    let mut rest = BallBearingSolver::new(dgbb()).expect("valid ball bearing");
    rest.solve(&dgbb_load(1.0)).expect("solve");
    let quasi: Vec<BallContacts> = rest.ball_loads().iter().map(BallContacts::from).collect();
    let mut fast = BallSpeedSolver::new(dgbb(), dgbb_speeds(), RaceControl::Outer)
        .expect("valid ball bearing");
    fast.solve(&dgbb_load(1.0)).expect("solve");
    let speed: Vec<BallContacts> = fast.ball_loads().iter().map(BallContacts::from).collect();
    let mut m = model();
    for balls in [&quasi, &speed] {
        for w in [0.0, 1047.0] {
            let op = BallFrictionOperating {
                inner_speed: w,
                outer_speed: 0.0,
                balls,
                drag: DragModel::Torque { nmm: 1.0 },
                coefficient_basis: Some((5_000.0, 50.0)),
            };
            let (r, n) = allocations(|| m.evaluate(&op).expect("friction"));
            assert!(r.total_nmm.is_finite() && r.total_nmm > 0.0);
            assert_eq!(n, 0, "at {w} rad/s");
        }
    }
}
