//! The fast steady rolling solver (issue 17, "Speed"): semismooth Newton with GMRES
//! (`SteadyMethod::Newton`, the default) against Kalker's transient marching
//! (`SteadyMethod::Marching`, the reference) on the same discrete equations: small
//! creepage, the knee, saturation, spin and a long ellipse; its status when it cannot
//! converge; warm starts along a creep curve; no allocation per solve.
//!
//! Both methods solve the same discretisation (upwind difference, rolling step one
//! cell), so they must agree to their tolerances, not to a discretisation error. The
//! marching runs with tightened tolerances here (its steady criterion is a traction
//! change per step, which overstates the accuracy when the decay is slow).

#![allow(clippy::unwrap_used)] // test helpers: a panic is a test failure with its message

use kontakt::geometry::Grid2;
use kontakt::rolling::{CellState, SteadyMethod, SteadyOptions, SteadySolution, SteadySolver};
use kontakt::solve::Termination;
use kontakt::tangential::{ContactEllipse, Creepage, KalkerMaterial};

#[path = "support/counting_alloc.rs"]
mod counting_alloc;

const A: f64 = 0.5; // contact radius [mm]
const P0: f64 = 1500.0; // peak pressure [MPa]
const MU: f64 = 0.3;
const MATERIAL: KalkerMaterial = KalkerMaterial {
    shear_modulus: 80_000.0,
    poisson_ratio: 0.25,
};

/// Hertz pressure for semi-axes `a` (rolling, x) and `b` \[mm\] on `nx × ny` cells over
/// `±a(1 + 2/nx)`, `±b(1 + 2/ny)` (the leading-edge column unloaded).
fn hertz(a: f64, b: f64, nx: usize, ny: usize) -> (Grid2, Vec<f64>) {
    let (hx, hy) = (a * (1.0 + 2.0 / nx as f64), b * (1.0 + 2.0 / ny as f64));
    let grid = Grid2::centered(hx, hy, nx, ny).unwrap();
    // The ellipse whose peak pressure is P0: P = 2π a b P0 / 3.
    let e = ContactEllipse::new(a, b, 2.0 * std::f64::consts::PI * a * b * P0 / 3.0).unwrap();
    let p = grid.points().map(|(x, y)| e.pressure_at(x, y)).collect();
    (grid, p)
}

/// The creepage at which the linear force of the circle reaches μP (C11 = 4.12).
fn xi_lin() -> f64 {
    MU * 2.0 * std::f64::consts::PI * P0 / (3.0 * MATERIAL.shear_modulus * 4.12)
}

fn marching() -> SteadyOptions {
    SteadyOptions {
        method: SteadyMethod::Marching,
        tolerance: 1e-10,
        steady_tolerance: 1e-10,
        max_steps: 20_000,
        ..SteadyOptions::default()
    }
}

/// Newton and marching from zero traction; both must converge.
fn both(
    grid: &Grid2,
    p: &[f64],
    c: Creepage,
    newton_options: &SteadyOptions,
) -> (SteadySolution, SteadySolution) {
    let mut solver = SteadySolver::new(grid, MATERIAL, Some(1)).unwrap();
    let t = std::time::Instant::now();
    let n = solver.solve(p, MU, c, newton_options).unwrap();
    let tn = t.elapsed();
    solver.reset();
    let t = std::time::Instant::now();
    let m = solver.solve(p, MU, c, &marching()).unwrap();
    println!(
        "{c:?}: Newton F {:?} ({} iterations, {} FFT, {tn:?}); marching F {:?} ({} steps, \
         {} FFT, {:?}); slip cells {} vs {}",
        n.force,
        n.status.iterations,
        n.fft_iterations,
        m.force,
        m.status.iterations,
        m.fft_iterations,
        t.elapsed(),
        n.slip_cells,
        m.slip_cells
    );
    n.status.require_converged("newton").unwrap();
    m.status.require_converged("marching").unwrap();
    (n, m)
}

/// Forces and spin moment within `rel` of the force scale `|F_marching|`, and the
/// stick/slip maps differing in at most `cells` cells.
fn agree(n: &SteadySolution, m: &SteadySolution, rel: f64, cells: usize) {
    let scale = m.force[0].hypot(m.force[1]);
    for k in 0..2 {
        assert!(
            (n.force[k] - m.force[k]).abs() <= rel * scale,
            "F[{k}] {} vs {}",
            n.force[k],
            m.force[k]
        );
    }
    // The moment arm is at most the radius of the contact's grid (about 0.53 mm).
    assert!(
        (n.spin_moment - m.spin_moment).abs() <= rel * scale * A,
        "Mz {} vs {}",
        n.spin_moment,
        m.spin_moment
    );
    let differ = n.state.iter().zip(&m.state).filter(|(a, b)| a != b).count();
    assert!(differ <= cells, "{differ} cells differ in state");
    assert!(
        n.traction_x
            .iter()
            .chain(&n.traction_y)
            .chain(&n.slip_x)
            .chain(&n.slip_y)
            .all(|v| v.is_finite())
    );
}

#[test]
fn newton_agrees_with_marching_on_the_circle() {
    let (grid, p) = hertz(A, A, 16, 16);
    let x = xi_lin();
    let o = SteadyOptions::default();
    // Small creepage (F about 3.5e-3 μP, all stick): forces to 1e-6.
    let (n, m) = both(&grid, &p, Creepage::longitudinal(1e-5), &o);
    agree(&n, &m, 1e-6, 0);
    assert_eq!(n.slip_cells, 0);
    // The knee (ξ at the linear saturation creepage: F ≈ 0.76 μP, half the cells slip).
    let (n, m) = both(&grid, &p, Creepage::longitudinal(x), &o);
    agree(&n, &m, 1e-6, 0);
    assert!(n.slip_cells > 40 && n.stick_cells > 40, "{n:?}");
    // Saturation: all slip, F = μP to the spread of the slip direction.
    let (n, m) = both(&grid, &p, Creepage::longitudinal(5.0 * x), &o);
    agree(&n, &m, 1e-6, 0);
    assert_eq!(n.stick_cells, 0);
    // Spin with longitudinal and lateral creepage.
    let spin = Creepage {
        longitudinal: 0.5 * x,
        lateral: 0.3 * x,
        spin: 0.5 * x / A,
    };
    let (n, m) = both(&grid, &p, spin, &o);
    agree(&n, &m, 1e-6, 0);
    assert!(n.spin_moment.abs() > 0.0 && n.force[1].abs() > 0.1 * n.force[0].abs());
}

#[test]
fn newton_agrees_with_marching_on_a_long_ellipse() {
    // a/b = 0.2 (a along the rolling direction), 12 × 24 cells, at the knee of the
    // strips' curve (ξ = 0.5 ξ_s with Carter's ξ_s = 2 μ p0/E*).
    let (a, b) = (0.1, 0.5);
    let (grid, p) = hertz(a, b, 12, 24);
    let e_star = MATERIAL.shear_modulus / (1.0 - MATERIAL.poisson_ratio);
    let xi = 0.5 * 2.0 * MU * P0 / e_star;
    let (n, m) = both(
        &grid,
        &p,
        Creepage::longitudinal(xi),
        &SteadyOptions::default(),
    );
    agree(&n, &m, 1e-6, 0);
    assert!(n.slip_cells > 20 && n.stick_cells > 20, "{n:?}");
}

#[test]
fn newton_reports_non_convergence() {
    let (grid, p) = hertz(A, A, 16, 16);
    let mut solver = SteadySolver::new(&grid, MATERIAL, Some(1)).unwrap();
    let c = Creepage::longitudinal(xi_lin());
    // One Newton iteration is not enough at the knee from zero traction.
    let s = solver
        .solve(
            &p,
            MU,
            c,
            &SteadyOptions {
                max_newton_iterations: 1,
                ..SteadyOptions::default()
            },
        )
        .unwrap();
    assert_eq!(s.status.termination, Termination::MaxIterations);
    assert_eq!(s.status.iterations, 1);
    assert!(s.status.residual > 1e-8 && s.status.residual.is_finite());
    assert!(s.traction_x.iter().chain(&s.slip_x).all(|v| v.is_finite()));
    // A budget of 3 FFT applications stops inside the first GMRES solve.
    solver.reset();
    let s = solver
        .solve(
            &p,
            MU,
            c,
            &SteadyOptions {
                max_iterations: 3,
                ..SteadyOptions::default()
            },
        )
        .unwrap();
    assert_eq!(s.status.termination, Termination::MaxIterations);
    assert!(s.fft_iterations <= 4, "{}", s.fft_iterations);
    assert!(
        s.traction_x
            .iter()
            .chain(&s.traction_y)
            .all(|v| v.is_finite())
    );
    // The tractions within the bounds always.
    for ((tx, ty), pc) in s.traction_x.iter().zip(&s.traction_y).zip(&p) {
        assert!(tx.hypot(*ty) <= MU * pc * (1.0 + 1e-12));
    }
    // A zero limit is bad input.
    let e = solver
        .solve(
            &p,
            MU,
            c,
            &SteadyOptions {
                max_newton_iterations: 0,
                ..SteadyOptions::default()
            },
        )
        .unwrap_err();
    assert_eq!(e.field(), Some("max_newton_iterations"));
    // No creepage: no traction, converged at once.
    let s = solver
        .solve(&p, MU, Creepage::default(), &SteadyOptions::default())
        .unwrap();
    assert!(s.status.converged());
    assert!(s.traction_x.iter().all(|t| *t == 0.0));
    assert!(s.state.iter().all(|c| *c != CellState::Slip));
}

#[test]
fn warm_starts_along_a_creep_curve() {
    // 12 points from 0.05 to 2.5 ξ_lin on 16²: warm-started solves agree with cold ones
    // and need fewer FFT applications in all.
    let (grid, p) = hertz(A, A, 16, 16);
    let x = xi_lin();
    let o = SteadyOptions::default();
    let mut warm = SteadySolver::new(&grid, MATERIAL, Some(1)).unwrap();
    let mut cold = SteadySolver::new(&grid, MATERIAL, Some(1)).unwrap();
    let (mut fft_warm, mut fft_cold) = (0, 0);
    let mut last = 0.0;
    for k in 0..12 {
        let c = Creepage::longitudinal(x * (0.05 + 2.45 * k as f64 / 11.0));
        let w = warm.solve(&p, MU, c, &o).unwrap();
        cold.reset();
        let s = cold.solve(&p, MU, c, &o).unwrap();
        assert!(w.status.converged() && s.status.converged());
        assert!(
            (w.force[0] - s.force[0]).abs() <= 1e-6 * s.force[0].abs(),
            "{} vs {}",
            w.force[0],
            s.force[0]
        );
        // The creep curve rises monotonically towards μP.
        let f = -w.force[0] / (MU * w.normal_force);
        assert!(f > last && f <= 1.0, "{f} after {last}");
        last = f;
        fft_warm += w.fft_iterations;
        fft_cold += s.fft_iterations;
    }
    println!("12-point curve: {fft_warm} FFT warm, {fft_cold} cold");
    // Measured 0.67 (16², 12 points).
    assert!(
        (fft_warm as f64) < 0.85 * fft_cold as f64,
        "{fft_warm} vs {fft_cold}"
    );
}

#[test]
fn no_allocation_per_solve_after_the_first() {
    let (grid, p) = hertz(A, A, 16, 16);
    let mut solver = SteadySolver::new(&grid, MATERIAL, Some(1)).unwrap();
    let o = SteadyOptions::default();
    let c = Creepage::longitudinal(xi_lin());
    solver.solve(&p, MU, c, &o).unwrap();
    solver.reset();
    let (s, count) = counting_alloc::allocations(|| solver.solve(&p, MU, c, &o).unwrap());
    // The solution's own seven fields (tractions, slips, states) and nothing else.
    assert!(count <= 7, "{count} allocations");
    assert!(s.status.converged());
}
