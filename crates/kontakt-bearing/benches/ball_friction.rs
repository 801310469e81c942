//! Criterion benchmark of the ball-bearing friction (issue 29, "Speed"): the 10-ball deep
//! groove bearing of the solve benches (d_m 70 mm, D 12.7 mm) under 5 kN radial and 2 kN
//! axial load at 10 000 r/min, its load distribution at speed solved once outside the timed
//! closures; timed: the friction at one operating point (20 contacts: Hertz ellipse, film,
//! spin and differential slip over a 16 × 32 rule, 12 rolling strips each) and a 50-point
//! speed sweep. Run by the lead: `cargo bench -p kontakt-bearing --bench ball_friction`.

#[path = "../tests/support/cases.rs"]
#[allow(dead_code)]
mod cases;

#[path = "../tests/support/friction.rs"]
#[allow(dead_code)]
mod friction;

use cases::{dgbb, dgbb_load, dgbb_speeds};
use criterion::{Criterion, criterion_group, criterion_main};
use kontakt_bearing::ball_speed::{BallSpeedSolver, RaceControl};
use kontakt_bearing::friction::ball::{
    BallAttitude, BallContacts, BallFrictionModel, BallFrictionOperating,
};
use kontakt_bearing::friction::torque::DragModel;
use std::hint::black_box;

fn setup() -> (BallFrictionModel, Vec<BallContacts>) {
    let mut s = BallSpeedSolver::new(dgbb(), dgbb_speeds(), RaceControl::Outer).expect("valid");
    s.solve(&dgbb_load(1.0)).expect("solve");
    let balls = s.ball_loads().iter().map(BallContacts::from).collect();
    let losses = friction::losses(&friction::vg68(), 70.0, true);
    let model =
        BallFrictionModel::new(dgbb(), losses, BallAttitude::OuterRaceControl).expect("model");
    (model, balls)
}

fn point(m: &mut BallFrictionModel, balls: &[BallContacts], w: f64) -> f64 {
    m.evaluate(&BallFrictionOperating {
        inner_speed: w,
        outer_speed: 0.0,
        balls,
        drag: DragModel::None,
        coefficient_basis: None,
    })
    .expect("friction")
    .total_nmm
}

fn bench(c: &mut Criterion) {
    let (mut m, balls) = setup();
    let w = dgbb_speeds().inner_rad_s;
    c.bench_function("ball_friction/dgbb_10_balls_point", |b| {
        b.iter(|| black_box(point(&mut m, &balls, black_box(w))))
    });
    c.bench_function("ball_friction/dgbb_10_balls_sweep_50", |b| {
        b.iter(|| {
            (1..=50)
                .map(|k| point(&mut m, &balls, black_box(w * k as f64 / 50.0)))
                .sum::<f64>()
        })
    });
}

criterion_group!(benches, bench);
criterion_main!(benches);
