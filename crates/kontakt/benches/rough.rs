//! Criterion benchmarks of the statistical rough-surface models (`kontakt::rough`): one
//! Greenwood-Tripp pressure distribution (64 intervals, the default) at Johnson's two
//! α of Fig. 12, the solver's set-up, GW evaluations, and a 1024² self-affine surface. Figures are recorded in
//! docs/rough.md and docs/PERFORMANCE.md.

use criterion::{Criterion, criterion_group, criterion_main};
use kontakt::rough::{
    Amplitude, GreenwoodTripp, GreenwoodTrippOptions, GreenwoodTrippParams, GreenwoodWilliamson,
    RoughContact, SelfAffineSpec, SummitHeights,
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
    // Issue 16's target: a 1024 x 1024 self-affine surface in under 0.2 s.
    let surface = SelfAffineSpec {
        points: [1024, 1024],
        size: [1.0, 1.0],
        hurst: 0.8,
        long_cutoff: 1.0,
        rolloff: 0.5,
        short_cutoff: 4.0 / 1024.0,
        amplitude: Amplitude::RmsSlope(0.1),
        seed: 1,
    };
    g.sample_size(10);
    g.bench_function("self_affine_surface_1024", |b| {
        b.iter(|| black_box(&surface).generate().expect("valid"))
    });
    // Issue 16's target for deterministic rough contact: a 512² periodic rough contact at
    // most as long as the same grid's Hertz solve per iteration times the iterations it
    // needs (docs/PERFORMANCE.md, cold Hertz solves at 512², 1 thread).
    let spec = SelfAffineSpec {
        points: [512, 512],
        short_cutoff: 8.0 / 512.0,
        rolloff: 1.0,
        ..surface
    };
    let map = spec.generate().expect("valid").height_map().expect("valid");
    let options = kontakt::halfspace::SolverOptions {
        tolerance: 1e-6,
        max_iterations: 3000,
        threads: Some(1),
        ..Default::default()
    };
    let point = RoughContact::new(&map, 1000.0, 0.1, options)
        .expect("valid")
        .solve(1.0)
        .expect("solves");
    eprintln!(
        "rough_contact_512: A/A0 = {:.4}, {} iterations",
        point.area_fraction, point.status.iterations
    );
    g.bench_function("rough_contact_512_cold_1_thread", |b| {
        b.iter(|| {
            RoughContact::new(black_box(&map), 1000.0, 0.1, options)
                .expect("valid")
                .solve(1.0)
                .expect("solves")
        })
    });
    g.finish();
}

criterion_group!(benches, bench_rough);
criterion_main!(benches);
