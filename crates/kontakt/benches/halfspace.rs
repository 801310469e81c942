//! Half-space solver benchmarks (issue 4): the FFT elastic operator, a full cold Hertz
//! solve at growing grids, and the multi-body path (cold and warm-started solves on a
//! 64 × 64 grid). Iteration counts are printed once to stderr outside criterion.
//! Figures are recorded in docs/halfspace-validation.md.
//!
//! Sample sizes are small so that the whole run takes a few minutes:
//! `cargo bench -p kontakt --bench halfspace`.

use criterion::{BenchmarkId, Criterion, SamplingMode, criterion_group, criterion_main};
use kontakt::geometry::Grid2;
use kontakt::geometry::RelativeCurvature;
use kontakt::halfspace::{
    Bem, BemOptions, Boundary, Control, ElasticOperator, HalfSpacePlan, HalfSpaceSolver,
    SolveReport, SolverOptions, Start,
};
use kontakt::material::{ElasticMaterial, effective_modulus};
use kontakt::pimp::QuadraticGap;
use std::hint::black_box;
use std::sync::Arc;
use std::time::Duration;

/// Sphere R = 10 mm on a plane, steel, 300 N: Hertz a, delta.
const RADIUS: f64 = 10.0;
const LOAD: f64 = 300.0;

fn e_star() -> f64 {
    effective_modulus(&ElasticMaterial::STEEL, &ElasticMaterial::STEEL)
}

/// Hertz contact radius \[mm\] of the reference sphere.
fn hertz_radius() -> f64 {
    (3.0 * LOAD * RADIUS / (4.0 * e_star())).cbrt()
}

fn sphere_gap(grid: &Grid2, shift_x: f64) -> Vec<f64> {
    grid.points()
        .map(|(x, y)| ((x - shift_x).powi(2) + y * y) / (2.0 * RADIUS))
        .collect()
}

/// A square `n × n` grid of half-width `half` \[mm\].
fn grid(n: usize, half: f64) -> Grid2 {
    Grid2::centered(half, half, n, n).expect("grid")
}

fn solver(g: Grid2, tolerance: f64, threads: Option<usize>) -> HalfSpaceSolver {
    HalfSpaceSolver::new(
        g,
        e_star(),
        SolverOptions {
            tolerance,
            threads,
            ..SolverOptions::default()
        },
    )
    .expect("solver")
}

fn pseudo_random(n: usize) -> Vec<f64> {
    let mut s = 0x9e37_79b9_7f4a_7c15u64;
    (0..n)
        .map(|_| {
            s = s
                .wrapping_mul(6_364_136_223_846_793_005)
                .wrapping_add(1_442_695_040_888_963_407);
            (s >> 11) as f64 / (1u64 << 53) as f64
        })
        .collect()
}

fn bench_operator(c: &mut Criterion) {
    let mut group = c.benchmark_group("halfspace_operator");
    group.sample_size(10);
    group.warm_up_time(Duration::from_millis(500));
    group.measurement_time(Duration::from_secs(2));
    group.sampling_mode(SamplingMode::Flat);
    for n in [64usize, 128, 256, 512, 1024] {
        let g = grid(n, 0.5);
        let p = pseudo_random(g.len());
        let mut u = vec![0.0; g.len()];
        for threads in [1usize, 2] {
            let mut op =
                ElasticOperator::new(&g, e_star(), Boundary::Free, Some(threads)).expect("op");
            if threads == 1 {
                eprintln!(
                    "operator {n}x{n}: plan holds {:.1} MiB",
                    op.memory_bytes() as f64 / (1 << 20) as f64
                );
            }
            group.bench_with_input(
                BenchmarkId::new(format!("apply_free_{threads}_threads"), n),
                &n,
                |b, _| b.iter(|| op.apply(black_box(&p), black_box(&mut u)).expect("apply")),
            );
        }
    }
    group.finish();
}

fn print_report(what: &str, r: &SolveReport) {
    eprintln!(
        "{what}: {} iterations, {} FFT applications, residual {:.1e}, converged {}",
        r.iterations, r.applications, r.residual, r.converged
    );
}

fn bench_hertz_solve(c: &mut Criterion) {
    let a = hertz_radius();
    let mut group = c.benchmark_group("halfspace_hertz_cold_solve");
    group.sample_size(10);
    group.warm_up_time(Duration::from_millis(500));
    group.measurement_time(Duration::from_secs(3));
    group.sampling_mode(SamplingMode::Flat);
    for n in [64usize, 128, 256, 512] {
        // "fill": the domain is 1.25 times the contact diameter (n / 1.25 cells across
        // the contact); "8a": the domain is 8a wide (n / 4 cells across).
        for (label, half) in [("fill", 0.625 * 2.0 * a), ("8a", 4.0 * a)] {
            let g = grid(n, half);
            let gap = sphere_gap(&g, 0.0);
            let mut s = solver(g, 1e-8, Some(1));
            let r = s
                .solve(&gap, Control::Force(LOAD), Start::Cold)
                .expect("solve");
            print_report(&format!("cold Hertz solve {label} {n}x{n}"), &r);
            group.bench_with_input(
                BenchmarkId::new(format!("domain_{label}_1_thread"), n),
                &n,
                |b, _| {
                    b.iter(|| {
                        s.solve(black_box(&gap), Control::Force(LOAD), Start::Cold)
                            .expect("solve")
                    })
                },
            );
        }
    }
    // The planning cost (FFT plans, kernel spectrum, work arrays) of the largest grid.
    let g = grid(512, 1.25 * a);
    group.bench_function("plan_512", |b| {
        b.iter(|| solver(black_box(g), 1e-8, Some(1)))
    });
    group.finish();
}

fn bench_multibody(c: &mut Criterion) {
    let a = hertz_radius();
    let g = grid(64, 1.25 * a);
    let gap0 = sphere_gap(&g, 0.0);
    let shifted = sphere_gap(&g, 0.01 * a);
    let tol = 1e-6;
    let loads = [LOAD, 1.01 * LOAD];
    let gaps = [&gap0, &shifted];

    // Iteration counts, once.
    let mut s = solver(g, tol, Some(1));
    let r = s
        .solve(&gap0, Control::Force(LOAD), Start::Cold)
        .expect("solve");
    print_report("multibody 64x64 cold", &r);
    let r = s
        .solve(&gap0, Control::Force(1.01 * LOAD), Start::Warm)
        .expect("solve");
    print_report("multibody 64x64 warm after load +1 %", &r);
    let r = s
        .solve(&gap0, Control::Force(1.01 * LOAD), Start::Cold)
        .expect("solve");
    print_report("multibody 64x64 cold at load +1 %", &r);
    let r = s
        .solve(&shifted, Control::Force(1.01 * LOAD), Start::Warm)
        .expect("solve");
    print_report("multibody 64x64 warm after pose 1 % of a", &r);
    let r = s
        .solve(&shifted, Control::Force(1.01 * LOAD), Start::Cold)
        .expect("solve");
    print_report("multibody 64x64 cold on the shifted gap", &r);

    let mut group = c.benchmark_group("halfspace_multibody_64");
    group.sample_size(20);
    group.warm_up_time(Duration::from_millis(500));
    group.measurement_time(Duration::from_secs(2));
    let mut s = solver(g, tol, Some(1));
    group.bench_function("cold", |b| {
        b.iter(|| {
            s.solve(black_box(&gap0), Control::Force(LOAD), Start::Cold)
                .expect("solve")
        })
    });
    // Alternate between two loads (two poses) so that every iteration is a genuine
    // warm start from the other state's solution.
    let mut s = solver(g, tol, Some(1));
    s.solve(&gap0, Control::Force(LOAD), Start::Cold)
        .expect("solve");
    let mut k = 0usize;
    group.bench_function("warm_load_1_percent", |b| {
        b.iter(|| {
            k += 1;
            s.solve(black_box(&gap0), Control::Force(loads[k % 2]), Start::Warm)
                .expect("solve")
        })
    });
    let mut s = solver(g, tol, Some(1));
    s.solve(&gap0, Control::Force(LOAD), Start::Cold)
        .expect("solve");
    let mut k = 0usize;
    group.bench_function("warm_pose_1_percent", |b| {
        b.iter(|| {
            k += 1;
            s.solve(black_box(gaps[k % 2]), Control::Force(LOAD), Start::Warm)
                .expect("solve")
        })
    });
    group.finish();
}

/// `Bem::solve_force` called again and again on one `Bem` (the sphere of the other benches,
/// 64 × 64 cells, adaptive domain, one thread): since issue 10 the grids of the adaptive
/// rounds are planned on the first call only.
fn bench_bem_repeated(c: &mut Criterion) {
    let sphere = RelativeCurvature::from_radii([RADIUS, RADIUS], [f64::INFINITY; 2], 0.0)
        .expect("curvature");
    let gap = QuadraticGap::new(sphere);
    let bem = Bem::new(
        ElasticMaterial::STEEL,
        ElasticMaterial::STEEL,
        BemOptions {
            threads: Some(1),
            ..BemOptions::default()
        },
    )
    .expect("bem");
    let s = bem.solve_force(&gap, LOAD).expect("solve");
    eprintln!(
        "bem sphere 64x64: {} rounds, {} iterations",
        s.grid_rounds, s.report.iterations
    );
    let mut group = c.benchmark_group("halfspace_bem_repeated");
    group.sample_size(20);
    group.warm_up_time(Duration::from_millis(500));
    group.measurement_time(Duration::from_secs(2));
    group.bench_function("solve_force_sphere_64", |b| {
        b.iter(|| bem.solve_force(black_box(&gap), LOAD).expect("solve"))
    });
    group.finish();
}

/// Bodies of a multi-body model on one grid (four rollers, 64 × 64 cells, one thread):
/// building their solvers, and one time step of warm-started solves.
const BODIES: usize = 4;

fn bodies(g: Grid2, tol: f64) -> Vec<HalfSpaceSolver> {
    let options = SolverOptions {
        tolerance: tol,
        threads: Some(1),
        ..SolverOptions::default()
    };
    let plan = HalfSpacePlan::new(&g, e_star(), options.boundary, options.threads).expect("plan");
    (0..BODIES)
        .map(|_| HalfSpaceSolver::with_plan(Arc::clone(&plan), options).expect("solver"))
        .collect()
}

fn bench_multibody_shared(c: &mut Criterion) {
    let a = hertz_radius();
    let g = grid(64, 1.25 * a);
    let gaps: Vec<Vec<f64>> = (0..BODIES)
        .map(|k| sphere_gap(&g, 0.01 * a * k as f64))
        .collect();
    let tol = 1e-6;
    let loads = [LOAD, 1.01 * LOAD];
    let mut group = c.benchmark_group("halfspace_multibody_shared_64");
    group.sample_size(20);
    group.warm_up_time(Duration::from_millis(500));
    group.measurement_time(Duration::from_secs(2));
    group.bench_function("setup_4_bodies", |b| b.iter(|| bodies(black_box(g), tol)));
    let mut solvers = bodies(g, tol);
    for (s, gap) in solvers.iter_mut().zip(&gaps) {
        s.solve(gap, Control::Force(LOAD), Start::Cold)
            .expect("solve");
    }
    let mut k = 0usize;
    group.bench_function("warm_step_4_bodies", |b| {
        b.iter(|| {
            k += 1;
            for (s, gap) in solvers.iter_mut().zip(&gaps) {
                black_box(
                    s.solve(black_box(gap), Control::Force(loads[k % 2]), Start::Warm)
                        .expect("solve"),
                );
            }
        })
    });
    group.finish();
}

criterion_group!(
    benches,
    bench_operator,
    bench_hertz_solve,
    bench_multibody,
    bench_bem_repeated,
    bench_multibody_shared
);
criterion_main!(benches);
