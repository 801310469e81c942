//! Criterion benchmarks of the statistical rough-surface models (`kontakt::rough`): one
//! Greenwood-Tripp pressure distribution (64 intervals, the default) at Johnson's two
//! α of Fig. 12, the solver's set-up, and GW evaluations. Figures are recorded in
//! docs/rough.md and docs/PERFORMANCE.md.

use criterion::{Criterion, criterion_group, criterion_main};
use kontakt::rough::{
    GreenwoodTripp, GreenwoodTrippOptions, GreenwoodTrippParams, GreenwoodWilliamson, SummitHeights,
};
use std::hint::black_box;

/// Steel sphere R 10 mm, 100 N, summit radius 20 µm, roughness for the given α, μ = 17.
fn params(alpha: f64) -> GreenwoodTrippParams {
    let (p, r, e, beta, mu): (f64, f64, f64, f64, f64) = (100.0, 10.0, 115_000.0, 0.02, 17.0);
    let d0 = (9.0 * p * p / (16.0 * r * e * e)).cbrt();
    let sigma = alpha * d0;
    let eta = mu / (8.0 / 3.0 * sigma * (2.0 * r * beta).sqrt());
    GreenwoodTrippParams::new(p, r, e, sigma, eta, beta).expect("valid")
}

fn bench_rough(c: &mut Criterion) {
    let solver = GreenwoodTripp::new(GreenwoodTrippOptions::default()).expect("valid");
    let mut g = c.benchmark_group("rough");
    for alpha in [0.047, 1.85] {
        let p = params(alpha);
        // first solve builds the shared F_n table outside the measurement
        assert!(solver.solve(&p).expect("solves").status.converged());
        g.bench_function(format!("greenwood_tripp_alpha_{alpha}"), |b| {
            b.iter(|| solver.solve(black_box(&p)).expect("solves"))
        });
    }
    g.bench_function("greenwood_tripp_setup_64", |b| {
        b.iter(|| GreenwoodTripp::new(black_box(GreenwoodTrippOptions::default())).expect("valid"))
    });
    let gw = GreenwoodWilliamson::new(2000.0, 0.02, 5e-4, 115_000.0, SummitHeights::Gaussian)
        .expect("valid");
    g.bench_function("gw_gaussian_state", |b| {
        b.iter(|| {
            gw.at_standardised_separation(black_box(1.3))
                .expect("valid")
        })
    });
    g.bench_function("gw_gaussian_inverse", |b| {
        b.iter(|| gw.separation_from_pressure(black_box(0.5)).expect("valid"))
    });
    g.finish();
}

criterion_group!(benches, bench_rough);
criterion_main!(benches);
