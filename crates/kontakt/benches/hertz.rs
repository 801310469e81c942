//! Criterion benchmarks of the Hertz hot paths. Figures are recorded in
//! docs/PERFORMANCE.md.

use criterion::{Criterion, criterion_group, criterion_main};
use kontakt::hertz::{HertzPointContact, PointGeometry};
use kontakt::material::ElasticMaterial;
use std::hint::black_box;

fn bench_point(c: &mut Criterion) {
    let steel = ElasticMaterial::STEEL;
    let mut g = c.benchmark_group("hertz_point");
    // Exact elliptical solve from scratch: curvature, eccentricity inversion, solution.
    // Deep-groove ball / inner race: B/A about 17, b/a about 0.12.
    g.bench_function("elliptical_full_solve", |bch| {
        bch.iter(|| {
            let geo = PointGeometry::new(
                black_box([6.0, 6.0]),
                black_box([20.0, -6.24]),
                black_box(0.0),
            )
            .expect("valid geometry");
            let c = HertzPointContact::new(geo, steel, steel).expect("valid contact");
            c.solve_force(black_box(1000.0)).expect("valid force")
        })
    });
    // Worst case of the inversion: a very thin ellipse (B/A = 1e6, b/a about 3e-4).
    g.bench_function("elliptical_thin_full_solve", |bch| {
        bch.iter(|| {
            let geo = PointGeometry::new(
                black_box([1e6, 1.0]),
                black_box([f64::INFINITY; 2]),
                black_box(0.0),
            )
            .expect("valid geometry");
            let c = HertzPointContact::new(geo, steel, steel).expect("valid contact");
            c.solve_force(black_box(1000.0)).expect("valid force")
        })
    });
    // Circular: sphere on flat, full solve.
    g.bench_function("circular_full_solve", |bch| {
        bch.iter(|| {
            let geo = PointGeometry::new(
                black_box([6.35, 6.35]),
                black_box([f64::INFINITY; 2]),
                black_box(0.0),
            )
            .expect("valid geometry");
            let c = HertzPointContact::new(geo, steel, steel).expect("valid contact");
            c.solve_force(black_box(100.0)).expect("valid force")
        })
    });
    // Planned contact: force from approach (the multi-body path).
    let geo = PointGeometry::new([6.0, 6.0], [20.0, -6.24], 0.0).expect("valid geometry");
    let planned = HertzPointContact::new(geo, steel, steel).expect("valid contact");
    g.bench_function("force_from_approach_planned", |bch| {
        bch.iter(|| planned.force_from_approach(black_box(0.01)).expect("valid"))
    });
    g.bench_function("solve_force_planned", |bch| {
        bch.iter(|| planned.solve_force(black_box(1000.0)).expect("valid"))
    });
    g.finish();
}

fn bench_subsurface(c: &mut Criterion) {
    use kontakt::hertz::subsurface::{axis_stress_peaks, line_stress_peaks};
    let mut g = c.benchmark_group("subsurface");
    // Peak search on the load axis (maximum shear and von Mises with their depths).
    g.bench_function("peaks_elliptical_b_over_a_0.2", |bch| {
        bch.iter(|| axis_stress_peaks(black_box(2000.0), black_box(1.0), black_box(0.2), 0.3))
    });
    g.bench_function("peaks_circular", |bch| {
        bch.iter(|| axis_stress_peaks(black_box(2000.0), black_box(1.0), black_box(1.0), 0.3))
    });
    g.bench_function("peaks_line", |bch| {
        bch.iter(|| line_stress_peaks(black_box(2000.0), black_box(0.1), 0.3))
    });
    g.finish();
}

criterion_group!(benches, bench_point, bench_subsurface);
criterion_main!(benches);
