#![allow(clippy::unwrap_used)]
//! Issue 12: the FFT-preconditioned constrained conjugate gradients (Vollebregt 2014,
//! docs/halfspace.md §9) against the unpreconditioned iteration (Polonsky and Keer 1999):
//! the same answer to the solver tolerance on a Hertz sphere, an ellipse and non-Hertzian
//! gaps (a flat punch with rounded edges, two bumps), free and periodic, under load and
//! approach control, cold and warm; and fewer iterations at 64 × 64. Rerun with
//! `cargo test -p kontakt --test halfspace_precond -- --nocapture` to print the figures
//! recorded in docs/VALIDATION.md and docs/PERFORMANCE.md.

use kontakt::geometry::Grid2;
use kontakt::halfspace::{
    Boundary, Control, HalfSpaceSolver, Preconditioner, SolveReport, SolverOptions, Start,
};
use kontakt::hertz::{HertzPointContact, PointGeometry};
use kontakt::material::{ElasticMaterial, effective_modulus};
use std::f64::consts::PI;

const STEEL: ElasticMaterial = ElasticMaterial::STEEL;
const RADIUS: f64 = 10.0;
const LOAD: f64 = 300.0;

fn e_star() -> f64 {
    effective_modulus(&STEEL, &STEEL)
}

/// Hertz radius of the sphere R = 10 mm at 300 N.
fn hertz_radius() -> f64 {
    (3.0 * LOAD * RADIUS / (4.0 * e_star())).cbrt()
}

fn options(tolerance: f64, boundary: Boundary, preconditioner: Preconditioner) -> SolverOptions {
    SolverOptions {
        tolerance,
        threads: Some(1),
        boundary,
        preconditioner,
        ..SolverOptions::default()
    }
}

/// A square grid of `n` cells on `[-half, half]²`.
fn grid(n: usize, half: f64) -> Grid2 {
    Grid2::centered(half, half, n, n).unwrap()
}

fn sample(g: &Grid2, f: impl Fn(f64, f64) -> f64) -> Vec<f64> {
    g.points().map(|(x, y)| f(x, y)).collect()
}

/// One solve with each path; returns (unpreconditioned, preconditioned) reports and
/// pressures.
#[allow(clippy::type_complexity)]
fn both(
    g: Grid2,
    boundary: Boundary,
    tol: f64,
    gap: &[f64],
    control: Control,
) -> ((SolveReport, Vec<f64>), (SolveReport, Vec<f64>)) {
    let run = |pc| {
        let mut s = HalfSpaceSolver::new(g, e_star(), options(tol, boundary, pc)).unwrap();
        let r = s.solve(gap, control, Start::Cold).unwrap();
        assert!(r.status.converged(), "{pc:?}: {r:?}");
        (r, s.pressure().to_vec())
    };
    (run(Preconditioner::None), run(Preconditioner::Fft))
}

/// Largest pressure difference over the largest pressure.
fn p_diff(a: &[f64], b: &[f64]) -> f64 {
    let pmax = a.iter().copied().fold(0.0f64, f64::max);
    a.iter()
        .zip(b)
        .fold(0.0f64, |m, (x, y)| m.max((x - y).abs()))
        / pmax
}

fn report(name: &str, plain: &SolveReport, pre: &SolveReport, dp: f64) {
    eprintln!(
        "{name}: iterations {} -> {} (applications {} -> {}), p_max {:.6} / {:.6} MPa, \
         approach {:.6e} / {:.6e} mm, cells {} / {}, max |dp|/p_max {:.1e}",
        plain.status.iterations,
        pre.status.iterations,
        plain.applications,
        pre.applications,
        plain.max_pressure,
        pre.max_pressure,
        plain.approach,
        pre.approach,
        plain.contact_cells,
        pre.contact_cells,
        dp
    );
}

#[test]
fn explore() {
    let a = hertz_radius();
    let g = grid(64, 1.25 * a);
    let sphere = sample(&g, |x, y| (x * x + y * y) / (2.0 * RADIUS));
    for tol in [1e-6, 1e-8] {
        let ((rp, pp), (rq, pq)) = both(g, Boundary::Free, tol, &sphere, Control::Force(LOAD));
        report(&format!("sphere force {tol:e}"), &rp, &rq, p_diff(&pp, &pq));
        let d = rp.approach;
        let ((rp, pp), (rq, pq)) =
            both(g, Boundary::Free, tol, &sphere, Control::Approach(d));
        report(&format!("sphere approach {tol:e}"), &rp, &rq, p_diff(&pp, &pq));
    }
    // Ellipse b/a about 4.
    let ell = sample(&g, |x, y| x * x / (2.0 * RADIUS) + y * y / (2.0 * 0.12 * RADIUS));
    let ((rp, pp), (rq, pq)) = both(g, Boundary::Free, 1e-8, &ell, Control::Force(LOAD));
    report("ellipse force", &rp, &rq, p_diff(&pp, &pq));
    // Flat punch with rounded edges.
    let r0 = 0.5 * a;
    let punch = sample(&g, |x, y| {
        let r = x.hypot(y);
        if r < r0 { 0.0 } else { (r - r0).powi(2) / (2.0 * 0.2 * RADIUS) }
    });
    let ((rp, pp), (rq, pq)) = both(g, Boundary::Free, 1e-8, &punch, Control::Force(LOAD));
    report("punch force", &rp, &rq, p_diff(&pp, &pq));
    let ((rp, pp), (rq, pq)) =
        both(g, Boundary::Free, 1e-8, &punch, Control::Approach(rp.approach));
    report("punch approach", &rp, &rq, p_diff(&pp, &pq));
    // Two bumps.
    let bumps = sample(&g, |x, y| {
        let s = 0.45 * a;
        let b1 = ((x - s).powi(2) + y * y) / (2.0 * RADIUS);
        let b2 = ((x + s).powi(2) + y * y) / (2.0 * RADIUS) + 1e-4;
        b1.min(b2)
    });
    let ((rp, pp), (rq, pq)) = both(g, Boundary::Free, 1e-8, &bumps, Control::Force(LOAD));
    report("bumps force", &rp, &rq, p_diff(&pp, &pq));
    // Periodic wavy surface.
    let lam = 1.0;
    let gp = Grid2::new([0.0, lam], [0.0, lam], 64, 64).unwrap();
    let amp = 1e-3;
    let wavy = sample(&gp, |x, y| amp * (1.0 - (2.0 * PI * x / lam).cos() * (2.0 * PI * y / lam).cos()));
    for f in [20.0, 400.0] {
        let ((rp, pp), (rq, pq)) = both(gp, Boundary::Periodic, 1e-8, &wavy, Control::Force(f));
        report(&format!("wavy periodic force {f}"), &rp, &rq, p_diff(&pp, &pq));
    }
    // Warm steps as in the bench.
    for pc in [Preconditioner::None, Preconditioner::Fft] {
        let shifted = sample(&g, |x, y| ((x - 0.01 * a).powi(2) + y * y) / (2.0 * RADIUS));
        let mut s = HalfSpaceSolver::new(g, e_star(), options(1e-6, Boundary::Free, pc)).unwrap();
        let r0 = s.solve(&sphere, Control::Force(LOAD), Start::Cold).unwrap();
        let r1 = s.solve(&sphere, Control::Force(1.01 * LOAD), Start::Warm).unwrap();
        let r2 = s.solve(&shifted, Control::Force(1.01 * LOAD), Start::Warm).unwrap();
        let d = r2.approach;
        let r3 = s.solve(&shifted, Control::Approach(1.01 * d), Start::Warm).unwrap();
        let r4 = s.solve(&sphere, Control::Approach(1.01 * d), Start::Warm).unwrap();
        eprintln!(
            "{pc:?}: cold {} warm load {} warm pose {} warm approach-step {} warm approach-pose {}",
            r0.status.iterations, r1.status.iterations, r2.status.iterations, r3.status.iterations, r4.status.iterations
        );
    }
}
