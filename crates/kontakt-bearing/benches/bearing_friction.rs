//! Criterion benchmark of the whole-bearing friction (issue 29, "Speed"): a 20-roller
//! tapered roller bearing (the rib study's sphere-torus-57 pair, 31 slices) under 15 kN
//! axial load, its load distribution solved once outside the timed closures; timed: the
//! friction at one operating point with Hertz rib contacts (rib loads of every roller, their
//! rib friction, the 1240 raceway slices; target ≤ 1 ms), the same with PimP rib contacts
//! (target ≤ 2 ms), a 50-point speed sweep (target ≤ 50 ms; planned once by
//! `BearingFrictionModel::plan_loads`, and unplanned beside it), and one point under combined
//! load (20 kN radial with the 15 kN axial: rollers of different loads, so the rib friction
//! is solved for each distinct rib load; no target, the cost beside the axial case).
//! Run by the lead: `cargo bench -p kontakt-bearing --bench bearing_friction`.

#[path = "../tests/support/friction.rs"]
#[allow(dead_code)]
mod support;

use criterion::{Criterion, criterion_group, criterion_main};
use kontakt::bearing::{PressureModel, RibFrictionModel, RollerCup};
use kontakt_bearing::friction::torque::{
    BearingFrictionModel, DragModel, FrictionOperating, roller_cups,
};
use std::hint::black_box;

struct Setup {
    pressure: PressureModel,
    rib: RibFrictionModel,
    model: BearingFrictionModel,
    cups: Vec<RollerCup>,
    cup: Vec<f64>,
    cone: Vec<f64>,
}

fn setup(pressure: PressureModel, radial: f64) -> Setup {
    let (rib, mut bearing) = support::rib_study(20);
    bearing.slices = 31;
    let (cup, cone, solver) = support::solved_combined(&bearing, radial, 15_000.0);
    let cups = roller_cups(solver.roller_loads());
    Setup {
        pressure,
        model: BearingFrictionModel::new(bearing, support::losses(&support::vg68(), 70.0, true))
            .expect("model"),
        cups,
        rib,
        cup,
        cone,
    }
}

fn point(s: &mut Setup, w: f64) -> f64 {
    let k = s.rib.kinematics(w, 0.0).expect("kinematics");
    let loads = s.rib.roller_loads_on_cups(&k, &s.cups).expect("rib loads");
    let rib = s
        .rib
        .evaluate_rollers(s.pressure, &k, &loads)
        .expect("rib friction");
    let mut powers = [0.0; 20];
    for (p, r) in powers.iter_mut().zip(&rib.rollers) {
        *p = r.power();
    }
    s.model
        .evaluate(&FrictionOperating {
            inner_speed: w,
            outer_speed: 0.0,
            cup_slices: &s.cup,
            cone_slices: &s.cone,
            tilts: None,
            rib: Some(&powers),
            drag: DragModel::None,
            coefficient_basis: None,
        })
        .expect("friction")
        .total_nmm
}

fn bench(c: &mut Criterion) {
    let mut s = setup(PressureModel::Hertz, 0.0);
    c.bench_function("bearing_friction_trb20_hertz_rib_one_point", |b| {
        b.iter(|| black_box(point(&mut s, black_box(157.0))))
    });
    let speeds: Vec<f64> = (1..=50).map(|i| 6.0 * i as f64).collect();
    // The sweep plans its load distribution once (`plan_loads`, inside the timed closure):
    // the speed-independent part of every slice, then 50 operating points.
    c.bench_function("bearing_friction_trb20_hertz_rib_sweep_50", |b| {
        b.iter(|| {
            s.model.plan_loads(&s.cup, &s.cone, None).expect("plan");
            let mut total = 0.0;
            for &w in &speeds {
                total += point(&mut s, w);
            }
            s.model.clear_plan();
            black_box(total)
        })
    });
    // The same sweep without the plan: 50 independent operating points.
    c.bench_function("bearing_friction_trb20_hertz_rib_sweep_50_unplanned", |b| {
        b.iter(|| {
            let mut total = 0.0;
            for &w in &speeds {
                total += point(&mut s, w);
            }
            black_box(total)
        })
    });
    // The two parts of one point apart: the rib friction of the 20 rollers (kinematics,
    // rib loads, fields, friction integrals) and the 1240 raceway slices.
    c.bench_function("bearing_friction_trb20_hertz_rib_only", |b| {
        b.iter(|| {
            let k = s.rib.kinematics(157.0, 0.0).expect("kinematics");
            let loads = s.rib.roller_loads_on_cups(&k, &s.cups).expect("rib loads");
            let rib = s
                .rib
                .evaluate_rollers(PressureModel::Hertz, &k, &loads)
                .expect("rib friction");
            black_box(rib.power)
        })
    });
    c.bench_function("bearing_friction_trb20_raceways_only", |b| {
        b.iter(|| {
            let f = s
                .model
                .evaluate(&FrictionOperating {
                    inner_speed: black_box(157.0),
                    outer_speed: 0.0,
                    cup_slices: &s.cup,
                    cone_slices: &s.cone,
                    tilts: None,
                    rib: None,
                    drag: DragModel::None,
                    coefficient_basis: None,
                })
                .expect("friction");
            black_box(f.total_nmm)
        })
    });
    let mut pimp = setup(PressureModel::Pimp, 0.0);
    c.bench_function("bearing_friction_trb20_pimp_rib_one_point", |b| {
        b.iter(|| black_box(point(&mut pimp, black_box(157.0))))
    });
    let mut combined = setup(PressureModel::Hertz, 20_000.0);
    c.bench_function(
        "bearing_friction_trb20_hertz_rib_one_point_combined_load",
        |b| b.iter(|| black_box(point(&mut combined, black_box(157.0)))),
    );
}

criterion_group!(benches, bench);
criterion_main!(benches);
