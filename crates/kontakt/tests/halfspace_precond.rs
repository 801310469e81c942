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

/// Both paths give the same answer: pressures to `1e-5 p_max` at a solver tolerance of
/// 1e-8 (the residual is an RMS gap relative to the displacement; the pressure field
/// follows to about the same relative size), the same loaded cells, and the force,
/// approach and largest pressure to 1e-6.
fn assert_agree(name: &str, plain: &(SolveReport, Vec<f64>), pre: &(SolveReport, Vec<f64>)) {
    let dp = p_diff(&plain.1, &pre.1);
    report(name, &plain.0, &pre.0, dp);
    assert!(dp < 1e-5, "{name}: pressures differ by {dp:e} of p_max");
    let (a, b) = (&plain.0, &pre.0);
    assert_eq!(a.contact_cells, b.contact_cells, "{name}: loaded cells");
    for (what, x, y) in [
        ("force", a.force, b.force),
        ("approach", a.approach, b.approach),
        ("max pressure", a.max_pressure, b.max_pressure),
    ] {
        assert!((x / y - 1.0).abs() < 1e-6, "{name}: {what} {x} vs {y}");
    }
}

/// The sphere R = 10 mm at 300 N on 64 × 64 cells over 2.5 Hertz radii.
fn sphere_case() -> (Grid2, Vec<f64>) {
    let a = hertz_radius();
    let g = grid(64, 1.25 * a);
    let gap = sample(&g, |x, y| (x * x + y * y) / (2.0 * RADIUS));
    (g, gap)
}

#[test]
fn hertz_sphere_same_answer_in_a_third_of_the_iterations() {
    let (g, gap) = sphere_case();
    let (plain, pre) = both(g, Boundary::Free, 1e-8, &gap, Control::Force(LOAD));
    assert_agree("Hertz sphere, load control", &plain, &pre);
    // Hertz: p0 = 3F/(2πa²), δ = a²/R, a from the loaded area (the existing tolerances
    // of tests/halfspace.rs at this resolution, about 51 cells across).
    let a = hertz_radius();
    let r = &pre.0;
    let p0 = 3.0 * LOAD / (2.0 * PI * a * a);
    let radius = (r.contact_area / PI).sqrt();
    let errors = [
        r.max_pressure / p0 - 1.0,
        radius / a - 1.0,
        r.approach / (a * a / RADIUS) - 1.0,
    ];
    eprintln!(
        "Hertz sphere, preconditioned: p0, a, δ errors {:.2e} {:.2e} {:.2e}",
        errors[0], errors[1], errors[2]
    );
    assert!(errors[0].abs() < 0.01, "p0 {:e}", errors[0]);
    assert!(errors[1].abs() < 0.02, "a {:e}", errors[1]);
    assert!(errors[2].abs() < 0.005, "δ {:e}", errors[2]);
    // 23 iterations unpreconditioned: the bound fails the old solver.
    assert!(plain.0.status.iterations > 20, "{:?}", plain.0.status);
    assert!(pre.0.status.iterations <= 8, "{:?}", pre.0.status);

    let (plain, pre) = both(
        g,
        Boundary::Free,
        1e-8,
        &gap,
        Control::Approach(plain.0.approach),
    );
    assert_agree("Hertz sphere, approach control", &plain, &pre);
    assert!(pre.0.status.iterations <= 12, "{:?}", pre.0.status);
    assert!(plain.0.status.iterations > 20, "{:?}", plain.0.status);
}

#[test]
fn ellipse_same_answer_fewer_iterations() {
    let a = hertz_radius();
    let g = grid(64, 1.25 * a);
    // b/a about 3 (curvature ratio 1/0.12).
    let gap = sample(&g, |x, y| {
        x * x / (2.0 * RADIUS) + y * y / (2.0 * 0.12 * RADIUS)
    });
    let (plain, pre) = both(g, Boundary::Free, 1e-8, &gap, Control::Force(LOAD));
    assert_agree("ellipse, load control", &plain, &pre);
    assert!(pre.0.status.iterations <= 16, "{:?}", pre.0.status);
    assert!(plain.0.status.iterations > 16, "{:?}", plain.0.status);
}

#[test]
fn rounded_flat_punch_same_answer_fewer_iterations() {
    let a = hertz_radius();
    let g = grid(64, 1.25 * a);
    let r0 = 0.5 * a;
    let gap = sample(&g, |x, y| {
        let r = x.hypot(y);
        if r < r0 {
            0.0
        } else {
            (r - r0).powi(2) / (2.0 * 0.2 * RADIUS)
        }
    });
    let (plain, pre) = both(g, Boundary::Free, 1e-8, &gap, Control::Force(LOAD));
    assert_agree("rounded flat punch, load control", &plain, &pre);
    assert!(pre.0.status.iterations <= 15, "{:?}", pre.0.status);
    let (plain, pre) = both(
        g,
        Boundary::Free,
        1e-8,
        &gap,
        Control::Approach(plain.0.approach),
    );
    assert_agree("rounded flat punch, approach control", &plain, &pre);
    assert!(pre.0.status.iterations <= 20, "{:?}", pre.0.status);
    assert!(plain.0.status.iterations > 30, "{:?}", plain.0.status);
}

#[test]
fn two_bumps_same_answer_fewer_iterations() {
    let a = hertz_radius();
    let g = grid(64, 1.25 * a);
    let s = 0.45 * a;
    let gap = sample(&g, |x, y| {
        let b1 = ((x - s).powi(2) + y * y) / (2.0 * RADIUS);
        let b2 = ((x + s).powi(2) + y * y) / (2.0 * RADIUS) + 1e-4;
        b1.min(b2)
    });
    let (plain, pre) = both(g, Boundary::Free, 1e-8, &gap, Control::Force(LOAD));
    assert_agree("two bumps, load control", &plain, &pre);
    assert!(pre.0.status.iterations <= 20, "{:?}", pre.0.status);
    assert!(plain.0.status.iterations > 30, "{:?}", plain.0.status);
}

#[test]
fn periodic_wavy_surface_same_answer_fewer_iterations() {
    let lam = 1.0;
    let g = Grid2::new([0.0, lam], [0.0, lam], 64, 64).unwrap();
    let amp = 1e-3;
    let gap = sample(&g, |x, y| {
        amp * (1.0 - (2.0 * PI * x / lam).cos() * (2.0 * PI * y / lam).cos())
    });
    // Partial contact (416 cells) and nearly full contact (3648 of 4096 cells).
    for (force, bound) in [(20.0, 12), (400.0, 14)] {
        let (plain, pre) = both(g, Boundary::Periodic, 1e-8, &gap, Control::Force(force));
        assert_agree(&format!("periodic wavy, {force} N"), &plain, &pre);
        assert!(pre.0.status.iterations <= bound, "{:?}", pre.0.status);
        assert!(plain.0.status.iterations > bound, "{:?}", plain.0.status);
    }
}

/// The multi-body steps of `benches/halfspace.rs` (`multibody`): 64 × 64, tolerance 1e-6,
/// warm after a 1 % load step and a pose step of 1 % of the Hertz radius, and the same
/// under approach control.
#[test]
fn warm_steps_at_64_cells_take_a_few_iterations() {
    let (g, sphere) = sphere_case();
    let a = hertz_radius();
    let shifted = sample(&g, |x, y| ((x - 0.01 * a).powi(2) + y * y) / (2.0 * RADIUS));
    let mut counts = Vec::new();
    let mut answers = Vec::new();
    for pc in [Preconditioner::None, Preconditioner::Fft] {
        let mut s = HalfSpaceSolver::new(g, e_star(), options(1e-6, Boundary::Free, pc)).unwrap();
        let mut its = Vec::new();
        let mut ps = Vec::new();
        let d = 7.3e-3;
        for (gap, control, start) in [
            (&sphere, Control::Force(LOAD), Start::Cold),
            (&sphere, Control::Force(1.01 * LOAD), Start::Warm),
            (&shifted, Control::Force(1.01 * LOAD), Start::Warm),
            (&shifted, Control::Approach(d), Start::Warm),
            (&shifted, Control::Approach(1.01 * d), Start::Warm),
            (&sphere, Control::Approach(1.01 * d), Start::Warm),
        ] {
            let r = s.solve(gap, control, start).unwrap();
            assert!(r.status.converged(), "{pc:?}: {r:?}");
            its.push(r.status.iterations);
            ps.push(s.pressure().to_vec());
        }
        eprintln!(
            "{pc:?}: iterations cold, warm load +1 %, warm pose 1 % of a, approach, approach +1 %, approach and pose: {its:?}"
        );
        counts.push(its);
        answers.push(ps);
    }
    for (k, (x, y)) in answers[0].iter().zip(&answers[1]).enumerate() {
        // Tolerance 1e-6: the pressures agree to about 1e-4 of p_max.
        let dp = p_diff(x, y);
        assert!(dp < 1e-3, "step {k}: pressures differ by {dp:e} of p_max");
    }
    // Unpreconditioned: [12, 11, 15, ...]; the bounds fail it.
    assert!(counts[1][1] <= 5 && counts[1][2] <= 6, "{:?}", counts[1]);
    assert!(counts[1][3..].iter().all(|&n| n <= 8), "{:?}", counts[1]);
    assert!(counts[0][1] > 5 && counts[0][2] > 6, "{:?}", counts[0]);
}

#[test]
fn shared_plans_and_threads_give_the_serial_answer() {
    // A threaded plan at 128 × 128 (the threshold for threads is 96 × 96): the
    // preconditioner runs on the operator's pool and gives the serial answer.
    let a = hertz_radius();
    let g = grid(128, 1.25 * a);
    let gap = sample(&g, |x, y| (x * x + y * y) / (2.0 * RADIUS));
    let mut answers = Vec::new();
    for threads in [Some(1), Some(2)] {
        let o = SolverOptions {
            threads,
            ..options(1e-8, Boundary::Free, Preconditioner::Fft)
        };
        let mut s = HalfSpaceSolver::new(g, e_star(), o).unwrap();
        let r = s.solve(&gap, Control::Force(LOAD), Start::Cold).unwrap();
        assert!(r.status.converged(), "{r:?}");
        answers.push((r, s.pressure().to_vec()));
    }
    let dp = p_diff(&answers[0].1, &answers[1].1);
    assert!(dp < 1e-9, "threaded vs serial {dp:e}");
    assert_eq!(
        answers[0].0.status.iterations,
        answers[1].0.status.iterations
    );
}

#[test]
fn options_choose_the_path() {
    assert_eq!(SolverOptions::default().preconditioner, Preconditioner::Fft);
    let (g, _) = sphere_case();
    let plain = HalfSpaceSolver::new(
        g,
        e_star(),
        options(1e-8, Boundary::Free, Preconditioner::None),
    )
    .unwrap();
    let pre = HalfSpaceSolver::new(
        g,
        e_star(),
        options(1e-8, Boundary::Free, Preconditioner::Fft),
    )
    .unwrap();
    // The preconditioner's plan, work arrays and two fields.
    assert!(pre.memory_bytes() > plain.memory_bytes());
}
