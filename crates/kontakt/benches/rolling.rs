//! Criterion benchmarks of exact steady rolling (issue 17, "Speed"): the semismooth
//! Newton solver (the default of `SteadySolver::solve`) against Kalker's transient
//! marching (`SteadyMethod::Marching`, the reference) on a 35 × 35 Hertz circle and an
//! ellipse (a/b = 0.5), in the linear range, the knee, saturation and with spin; a
//! 50-point creep curve with warm starts; the growth with the grid. The FFT applications
//! and Newton/GMRES iterations of each case are printed once (stderr). Figures in
//! docs/PERFORMANCE.md, "Exact steady rolling (issue 17)".

use criterion::{Criterion, criterion_group, criterion_main};
use kontakt::geometry::Grid2;
use kontakt::rolling::{SteadyMethod, SteadyOptions, SteadySolution, SteadySolver};
use kontakt::tangential::{ContactEllipse, Creepage, KalkerMaterial};
use std::hint::black_box;
use std::time::Duration;

const P0: f64 = 1500.0; // MPa
const MU: f64 = 0.3;
const MATERIAL: KalkerMaterial = KalkerMaterial {
    shear_modulus: 80_000.0,
    poisson_ratio: 0.25,
};

/// A Hertz pressure on `n × n` cells for semi-axes `a` (rolling, x) and `b` \[mm\]: the
/// grid covers `±a(1 + 2/n)`, `±b(1 + 2/n)` (the leading-edge column unloaded).
fn hertz(a: f64, b: f64, n: usize) -> (Grid2, Vec<f64>) {
    let f = 1.0 + 2.0 / n as f64;
    let grid = Grid2::centered(a * f, b * f, n, n).expect("valid grid");
    // The ellipse whose peak pressure is P0: P = 2π a b P0 / 3.
    let e = ContactEllipse::new(a, b, 2.0 * std::f64::consts::PI * a * b * P0 / 3.0)
        .expect("valid ellipse");
    let p = grid.points().map(|(x, y)| e.pressure_at(x, y)).collect();
    (grid, p)
}

/// The creepage at which the linear force would reach μP for a circle of radius a:
/// μ P/(G a² C11) with P = 2π a² p0/3, C11 = 4.12 (ν = 0.25).
fn xi_lin() -> f64 {
    MU * 2.0 * std::f64::consts::PI * P0 / (3.0 * MATERIAL.shear_modulus * 4.12)
}

fn cases(a: f64) -> Vec<(&'static str, Creepage)> {
    let x = xi_lin();
    vec![
        ("linear", Creepage::longitudinal(0.1 * x)),
        ("knee", Creepage::longitudinal(1.0 * x)),
        ("saturated", Creepage::longitudinal(5.0 * x)),
        (
            "spin",
            Creepage {
                longitudinal: 0.5 * x,
                lateral: 0.3 * x,
                spin: 0.5 * x / a,
            },
        ),
    ]
}

fn options(method: SteadyMethod) -> SteadyOptions {
    SteadyOptions {
        method,
        ..SteadyOptions::default()
    }
}

fn report(label: &str, s: &SteadySolution) {
    eprintln!(
        "{label}: F/muP [{:.6}, {:.6}], stick {} slip {}, {:?} after {} iterations \
         (residual {:.1e}), {} FFT applications, {} GMRES iterations",
        s.force[0] / (MU * s.normal_force),
        s.force[1] / (MU * s.normal_force),
        s.stick_cells,
        s.slip_cells,
        s.status.termination,
        s.status.iterations,
        s.status.residual,
        s.fft_iterations,
        s.linear_iterations
    );
}

fn cold(solver: &mut SteadySolver, p: &[f64], c: Creepage, o: &SteadyOptions) -> SteadySolution {
    solver.reset();
    solver.solve(p, MU, c, o).expect("valid input")
}

fn bench_points(c: &mut Criterion) {
    for (shape, a, b) in [("circle", 0.5, 0.5), ("ellipse", 0.25, 0.5)] {
        let (grid, p) = hertz(a, b, 35);
        let mut solver = SteadySolver::new(&grid, MATERIAL, Some(1)).expect("valid");
        let mut g = c.benchmark_group(format!("steady_35_{shape}"));
        for (name, creep) in cases(a) {
            let o = options(SteadyMethod::Newton);
            report(
                &format!("{shape} {name} newton"),
                &cold(&mut solver, &p, creep, &o),
            );
            g.bench_function(format!("newton_{name}"), |bch| {
                bch.iter(|| cold(&mut solver, &p, black_box(creep), &o))
            });
        }
        g.finish();
    }
}

fn bench_marching(c: &mut Criterion) {
    let (grid, p) = hertz(0.5, 0.5, 35);
    let mut solver = SteadySolver::new(&grid, MATERIAL, Some(1)).expect("valid");
    let mut g = c.benchmark_group("steady_35_circle_marching");
    g.sample_size(10);
    g.warm_up_time(Duration::from_millis(100));
    g.measurement_time(Duration::from_secs(1));
    for (name, creep) in cases(0.5) {
        let o = options(SteadyMethod::Marching);
        report(
            &format!("circle {name} marching"),
            &cold(&mut solver, &p, creep, &o),
        );
        g.bench_function(format!("marching_{name}"), |bch| {
            bch.iter(|| cold(&mut solver, &p, black_box(creep), &o))
        });
    }
    g.finish();
}

/// 50 creepage points from 0.02 to 3 times the linear saturation creepage, each warm
/// started from the last.
fn curve(solver: &mut SteadySolver, p: &[f64], o: &SteadyOptions) -> (f64, usize) {
    solver.reset();
    let x = xi_lin();
    let (mut f, mut fft) = (0.0, 0);
    for k in 0..50 {
        let xi = x * (0.02 + 2.98 * k as f64 / 49.0);
        let s = solver
            .solve(p, MU, Creepage::longitudinal(xi), o)
            .expect("valid input");
        f += s.force[0];
        fft += s.fft_iterations;
    }
    (f, fft)
}

fn bench_curve(c: &mut Criterion) {
    let mut g = c.benchmark_group("steady_35_curve50");
    g.sample_size(10);
    for (shape, a, b) in [("circle", 0.5, 0.5), ("ellipse", 0.25, 0.5)] {
        let (grid, p) = hertz(a, b, 35);
        let mut solver = SteadySolver::new(&grid, MATERIAL, Some(1)).expect("valid");
        let o = options(SteadyMethod::Newton);
        let (_, fft) = curve(&mut solver, &p, &o);
        eprintln!("{shape} 50-point warm curve: {fft} FFT applications");
        g.bench_function(format!("newton_warm_{shape}"), |bch| {
            bch.iter(|| curve(&mut solver, &p, &o))
        });
    }
    g.finish();
}

fn bench_grids(c: &mut Criterion) {
    let mut g = c.benchmark_group("steady_knee_grid");
    g.sample_size(10);
    let knee = Creepage::longitudinal(xi_lin());
    for n in [11, 15, 25, 35, 64] {
        let (grid, p) = hertz(0.5, 0.5, n);
        let mut solver = SteadySolver::new(&grid, MATERIAL, Some(1)).expect("valid");
        let o = options(SteadyMethod::Newton);
        report(
            &format!("knee {n}x{n} newton"),
            &cold(&mut solver, &p, knee, &o),
        );
        g.bench_function(format!("newton_{n}"), |bch| {
            bch.iter(|| cold(&mut solver, &p, knee, &o))
        });
        if n <= 25 {
            let o = options(SteadyMethod::Marching);
            report(
                &format!("knee {n}x{n} marching"),
                &cold(&mut solver, &p, knee, &o),
            );
            g.bench_function(format!("marching_{n}"), |bch| {
                bch.iter(|| cold(&mut solver, &p, knee, &o))
            });
        }
    }
    g.finish();
}

/// One application of the tangential operator `u = A τ` (four FFT convolutions).
fn bench_operator(c: &mut Criterion) {
    let mut g = c.benchmark_group("tangential_operator");
    for n in [35, 64] {
        let (grid, p) = hertz(0.5, 0.5, n);
        let mut op =
            kontakt::rolling::TangentialOperator::new(&grid, MATERIAL, Some(1)).expect("valid");
        let (mut ux, mut uy) = (vec![0.0; p.len()], vec![0.0; p.len()]);
        g.bench_function(format!("apply_{n}"), |bch| {
            bch.iter(|| {
                op.apply(black_box(&p), &p, &mut ux, &mut uy)
                    .expect("valid")
            })
        });
    }
    g.finish();
}

criterion_group!(
    benches,
    bench_operator,
    bench_points,
    bench_curve,
    bench_grids,
    bench_marching
);
criterion_main!(benches);
