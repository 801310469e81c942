//! Criterion benchmarks of the asperity traction model (`kontakt::traction`): one curve
//! point and a 100-point curve of a circular contact with 1020 asperities, and the
//! planning step. Figures are recorded in docs/traction-asperity.md.

use criterion::{Criterion, criterion_group, criterion_main};
use kontakt::material::ElasticMaterial;
use kontakt::traction::{AsperityTraction, AsperityTractionParams, NominalContact};
use std::hint::black_box;

/// Circular steel contact of radius 0.9 mm under 3000 N, Hertzian asperities of radius
/// 0.02 mm every 0.05 mm: 1020 asperities.
fn params() -> AsperityTractionParams {
    let nominal = NominalContact::Circular {
        half_width: 0.9,
        max_pressure: None,
    };
    AsperityTractionParams::new(
        nominal,
        3000.0,
        0.3,
        ElasticMaterial::STEEL,
        [0.02, 0.02],
        0.05,
    )
}

fn bench_asperity(c: &mut Criterion) {
    let model = AsperityTraction::new(params()).expect("valid model");
    assert_eq!(model.asperities().len(), 1020);
    let full = model
        .full_sliding_slide_to_roll()
        .expect("every asperity slides eventually");
    // Half of the asperities' range: a mix of sticking and sliding asperities.
    let xi = 0.5 * full;
    let srr: Vec<f64> = (0..100).map(|i| 1.2 * full * i as f64 / 99.0).collect();

    let mut g = c.benchmark_group("asperity");
    g.bench_function("curve_point_1020", |b| {
        b.iter(|| model.traction_ratio(black_box(xi)).expect("valid"))
    });
    g.bench_function("curve_100_points_1020", |b| {
        b.iter(|| model.curve(black_box(&srr)).expect("valid"))
    });
    g.bench_function("plan_1020", |b| {
        b.iter(|| AsperityTraction::new(black_box(params())).expect("valid"))
    });
    g.bench_function("plan_and_curve_100_points_1020", |b| {
        b.iter(|| {
            AsperityTraction::new(black_box(params()))
                .expect("valid")
                .curve(black_box(&srr))
                .expect("valid")
        })
    });
    g.finish();
}

criterion_group!(benches, bench_asperity);
criterion_main!(benches);
