//! Criterion benchmarks of the tangential-contact hot paths: FASTSIM per creepage point,
//! 100-point traction curves (Carter, Kalker linear, FASTSIM), Kalker's coefficient
//! lookup and the Mindlin-Deresiewicz loading history. Figures are recorded in
//! docs/tangential.md (Performance).

use criterion::{Criterion, criterion_group, criterion_main};
use kontakt::material::ElasticMaterial;
use kontakt::tangential::{
    Carter, ContactEllipse, Creepage, Fastsim, FastsimOptions, KalkerLinear, Mindlin,
    TractionCurve, creep_coefficients,
};
use std::hint::black_box;

/// A ball-on-race-like ellipse: a = 0.25 mm along rolling, b = 1.2 mm, 1500 N.
fn ellipse() -> ContactEllipse {
    ContactEllipse::new(0.25, 1.2, 1500.0).expect("valid ellipse")
}

fn creepages() -> Vec<f64> {
    (0..100).map(|i| 4e-3 * i as f64 / 99.0).collect()
}

fn bench_fastsim(c: &mut Criterion) {
    let steel = ElasticMaterial::STEEL;
    let mut g = c.benchmark_group("fastsim");
    let plan = Fastsim::new(ellipse(), &steel, &steel, 0.1, FastsimOptions::default())
        .expect("valid plan");
    // One creepage point at 50x50 in partial slip, with all three creepages.
    let point = Creepage {
        longitudinal: 1e-3,
        lateral: -4e-4,
        spin: 0.02,
    };
    g.bench_function("point_50x50", |b| {
        b.iter(|| plan.solve(black_box(&point)).expect("valid"))
    });
    g.bench_function("point_50x50_pure_longitudinal", |b| {
        b.iter(|| {
            plan.solve(black_box(&Creepage::longitudinal(1e-3)))
                .expect("valid")
        })
    });
    let mut field = plan.new_field();
    g.bench_function("point_50x50_with_field", |b| {
        b.iter(|| {
            plan.solve_field(black_box(&point), &mut field)
                .expect("valid")
        })
    });
    g.bench_function("plan_50x50", |b| {
        b.iter(|| {
            Fastsim::new(
                black_box(ellipse()),
                &steel,
                &steel,
                0.1,
                FastsimOptions::default(),
            )
            .expect("valid plan")
        })
    });
    let xs = creepages();
    g.bench_function("curve_100_points_50x50", |b| {
        b.iter(|| plan.traction_curve(black_box(&xs)).expect("valid"))
    });
    g.finish();
}

fn bench_curves(c: &mut Criterion) {
    let steel = ElasticMaterial::STEEL;
    let xs = creepages();
    let mut g = c.benchmark_group("traction_curve");
    let carter = Carter::from_ellipse(&ellipse(), &steel, &steel, 0.1).expect("valid");
    g.bench_function("carter_100_points", |b| {
        b.iter(|| carter.traction_curve(black_box(&xs)).expect("valid"))
    });
    let kalker = KalkerLinear::new(ellipse(), &steel, &steel, 0.1).expect("valid");
    g.bench_function("kalker_linear_100_points", |b| {
        b.iter(|| kalker.traction_curve(black_box(&xs)).expect("valid"))
    });
    g.bench_function("kalker_plan_and_100_points", |b| {
        b.iter(|| {
            let k = KalkerLinear::new(black_box(ellipse()), &steel, &steel, 0.1).expect("valid");
            k.traction_curve(black_box(&xs)).expect("valid")
        })
    });
    g.bench_function("creep_coefficients_lookup", |b| {
        b.iter(|| creep_coefficients(black_box(0.37), black_box(0.28)).expect("valid"))
    });
    g.finish();
}

fn bench_mindlin(c: &mut Criterion) {
    let steel = ElasticMaterial::STEEL;
    let e = ContactEllipse::new(0.3, 0.2, 500.0).expect("valid ellipse");
    let m = Mindlin::new(e, steel, steel, 0.3).expect("valid contact");
    let mut g = c.benchmark_group("mindlin");
    g.bench_function("plan_elliptical", |b| {
        b.iter(|| Mindlin::new(black_box(e), steel, steel, 0.3).expect("valid"))
    });
    g.bench_function("displacement", |b| {
        b.iter(|| m.displacement(black_box(90.0)).expect("valid"))
    });
    g.bench_function("energy_per_cycle", |b| {
        b.iter(|| {
            m.dissipated_energy_per_cycle(black_box(90.0))
                .expect("valid")
        })
    });
    // One full cycle Q = 100 cos(2 pi i/100) with reversal memory: 100 steps.
    let forces: Vec<f64> = (0..100)
        .map(|i| 100.0 * (2.0 * std::f64::consts::PI * i as f64 / 100.0).cos())
        .collect();
    g.bench_function("history_cycle_100_steps", |b| {
        b.iter(|| {
            let mut h = m.history();
            let mut d = 0.0;
            for &q in &forces {
                d = h.apply_force(black_box(q)).expect("valid");
            }
            d
        })
    });
    g.finish();
}

criterion_group!(benches, bench_fastsim, bench_curves, bench_mindlin);
criterion_main!(benches);
