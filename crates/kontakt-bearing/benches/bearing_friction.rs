//! Criterion benchmark of the whole-bearing friction (issue 29, "Speed"): a 20-roller
//! tapered roller bearing (the rib study's sphere-torus-57 pair, 31 slices) under 15 kN
//! axial load, its load distribution solved once outside the timed closures; timed: the
//! friction at one operating point with Hertz rib contacts (rib loads of every roller, their
//! rib friction, the 1240 raceway slices; target ≤ 1 ms) and a 50-point speed sweep
//! (target ≤ 50 ms). Run by the lead: `cargo bench -p kontakt-bearing --bench bearing_friction`.

use criterion::{Criterion, criterion_group, criterion_main};
use kontakt::bearing::{
    PressureModel, RibFrictionModel, RibLubrication, RollerCup, RollerRibSpec, RollerSet,
};
use kontakt::friction::FrictionLaw;
use kontakt::lubrication::{
    FilmFormula, Lubricant, RollingResistanceModel, viscosity_temperature_slope,
};
use kontakt_bearing::equilibrium::{RingLoad, RollerBearingSolver};
use kontakt_bearing::friction::raceway::{RacewayLosses, RacewayLubrication};
use kontakt_bearing::friction::torque::{
    BearingFrictionModel, DragModel, FrictionOperating, iso_slice_loads,
};
use kontakt_bearing::geometry::RollerBearing;
use std::hint::black_box;

struct Setup {
    rib: RibFrictionModel,
    model: BearingFrictionModel,
    cups: Vec<RollerCup>,
    cup: Vec<f64>,
    cone: Vec<f64>,
}

fn setup() -> Setup {
    let oil = Lubricant::iso_vg(68, 860.0, 0.02).expect("oil");
    let set = RollerSet {
        count: 20,
        ..RollerSet::default()
    };
    let rib = RibFrictionModel::new(
        RollerRibSpec::builtin("sphere-torus-57").expect("pair"),
        set,
        FrictionLaw::mixed(0.12).expect("law"),
        Some(RibLubrication {
            lubricant: oil,
            temperature: 70.0,
            roughness: [0.2e-3, 0.2e-3],
            formula: FilmFormula::Chittenden,
        }),
        true,
    )
    .expect("rib model");
    let mut bearing = RollerBearing::of_roller_rib(rib.pair(), &set).expect("bearing");
    bearing.slices = 31;
    let mut solver = RollerBearingSolver::new(bearing.clone()).expect("solver");
    solver
        .solve(&RingLoad::forces([0.0, 0.0, 15_000.0, 0.0, 0.0]).with_tilts_held())
        .expect("solve");
    let n = bearing.rollers * bearing.slices;
    let (mut cup, mut cone) = (vec![0.0; n], vec![0.0; n]);
    iso_slice_loads(
        solver.slice_loads(),
        solver.roller_loads(),
        &mut cup,
        &mut cone,
    )
    .expect("slices");
    let cups = solver
        .roller_loads()
        .iter()
        .map(|r| RollerCup {
            azimuth: r.azimuth_rad,
            outer_raceway: r.outer_n,
        })
        .collect();
    let losses = RacewayLosses::new(RacewayLubrication {
        viscosity: oil.dynamic_viscosity(70.0).expect("viscosity"),
        alpha: oil.alpha(),
        viscosity_slope: Some(viscosity_temperature_slope(&oil, 70.0).expect("slope")),
        conductivity: 0.134,
        film_starvation: 1.0,
        starvation_degree: None,
        roughness: 0.2e-3,
        law: FrictionLaw::mixed(0.12).expect("law"),
        rolling: RollingResistanceModel::BibouletHoupert,
    })
    .expect("losses");
    Setup {
        model: BearingFrictionModel::new(bearing, losses).expect("model"),
        rib,
        cups,
        cup,
        cone,
    }
}

fn point(s: &mut Setup, w: f64) -> f64 {
    let k = s.rib.kinematics(w, 0.0).expect("kinematics");
    let loads = s.rib.roller_loads_on_cups(&k, &s.cups).expect("rib loads");
    let rib = s
        .rib
        .evaluate_rollers(PressureModel::Hertz, &k, &loads)
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
    let mut s = setup();
    c.bench_function("bearing_friction_trb20_hertz_rib_one_point", |b| {
        b.iter(|| black_box(point(&mut s, black_box(157.0))))
    });
    let speeds: Vec<f64> = (1..=50).map(|i| 6.0 * i as f64).collect();
    c.bench_function("bearing_friction_trb20_hertz_rib_sweep_50", |b| {
        b.iter(|| {
            let mut total = 0.0;
            for &w in &speeds {
                total += point(&mut s, w);
            }
            black_box(total)
        })
    });
}

criterion_group!(benches, bench);
criterion_main!(benches);
