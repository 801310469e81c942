//! Steady rolling of dissimilar bodies (Kalker's difference parameter `K ≠ 0`):
//! `rolling::CoupledSteadySolver` and the steady solver's extra rigid slip.
//!
//! References: Bentall & Johnson (1967) for the free-rolling creepage of dissimilar
//! rollers in complete slip (closed form, docs/rolling.md §11); Bufler (1959) for rolling
//! without slip; Vollebregt's CONTACT, example `bentall` (its input and reference
//! output: numbers only), for the grid-matched creepages, cell counts and peak
//! pressures; the exact limits `K = 0` and `coupling: false` (the steady solver itself).
//! Tolerances are stated at each assertion with the value measured when it was set
//! (docs/VALIDATION.md, "Exact rolling contact (Kalker)").
//!
//! Sign convention: CONTACT's example rolls in `−x` (`χ = 180°`), kontakt's steady
//! solver in `+x`. The two problems are mirror images in `x`: CONTACT's `ξ` and `F_x` are
//! minus ours; pressures, `K` and the cell counts are the same.

#![allow(clippy::unwrap_used)] // test helpers: a panic is a test failure with its message

#[path = "support/counting_alloc.rs"]
mod counting_alloc;

use kontakt::geometry::Grid2;
use kontakt::halfspace::Control;
use kontakt::material::ElasticMaterial;
use kontakt::rolling::{
    CellState, CoupledSteadyOptions, CoupledSteadySolution, CoupledSteadySolver, SteadyLoad,
    SteadyMethod, SteadyOptions, SteadySolver, difference_parameter,
};
use kontakt::solve::Termination;
use kontakt::tangential::{Creepage, KalkerMaterial};

/// CONTACT's `bentall`: normal force \[N\] on the 1000 mm strip (16.2019 N/mm, Hertz
/// half-width a = 0.1 mm for R = 25 mm).
const FN: f64 = 16_201.9;

/// Aluminium (G = 23 000 MPa, ν = 0.31), body 1.
fn aluminium() -> ElasticMaterial {
    ElasticMaterial::new(2.0 * 23_000.0 * 1.31, 0.31).unwrap()
}

/// Steel (G = 82 000 MPa, ν = 0.28), body 2.
fn steel() -> ElasticMaterial {
    ElasticMaterial::new(2.0 * 82_000.0 * 1.28, 0.28).unwrap()
}

/// CONTACT's grid: one strip of 216 cells of 0.001 mm × 1000 mm (x from −0.108 mm).
fn bentall_grid() -> Grid2 {
    Grid2::new([-0.108, 0.108], [-500.0, 500.0], 216, 1).unwrap()
}

/// The gap `x²/(2R)` with `R = 25` mm (CONTACT's `B1 = 0.02`).
fn bentall_gap(grid: &Grid2) -> Vec<f64> {
    grid.points().map(|(x, _)| 0.02 * x * x).collect()
}

/// The gap of CONTACT's `bentall` strip and a solver for aluminium on steel on its grid
/// (default options).
fn bentall_solver() -> (Vec<f64>, CoupledSteadySolver) {
    let grid = bentall_grid();
    let solver = CoupledSteadySolver::new(
        &grid,
        &aluminium(),
        &steel(),
        CoupledSteadyOptions::default(),
    )
    .unwrap();
    (bentall_gap(&grid), solver)
}

fn free_rolling(force: f64) -> SteadyLoad {
    SteadyLoad::LongitudinalForce {
        force,
        lateral: 0.0,
        spin: 0.0,
    }
}

fn p_max(s: &CoupledSteadySolution) -> f64 {
    s.pressure.iter().fold(0.0f64, |a, b| a.max(*b))
}

/// `θ*` with `θ + sin θ cos θ = π/4` (Newton's method).
fn theta_star() -> f64 {
    let mut t: f64 = 0.4;
    for _ in 0..50 {
        let f = t + t.sin() * t.cos() - std::f64::consts::FRAC_PI_4;
        t -= f / (2.0 * t.cos().powi(2));
    }
    t
}

#[test]
fn complete_slip_free_rolling_creepage_is_bentall_and_johnsons_closed_form() {
    let (al, st) = (aluminium(), steel());
    let m = KalkerMaterial::new(&al, &st).unwrap();
    let k = difference_parameter(&al, &st).unwrap();
    // CONTACT's user guide: K = 0.100, G = 35 924 MPa, ν = 0.3034.
    assert!((k - 0.1002).abs() < 1e-4, "K = {k}");
    assert!((m.shear_modulus - 35_924.0).abs() < 1.0);
    let (gap, mut s) = bentall_solver();
    let r = s
        .solve(&gap, Control::Force(FN), 1e-4, free_rolling(0.0))
        .unwrap();
    assert_eq!(
        r.status.termination,
        Termination::Converged,
        "{:?}",
        r.status
    );
    // Plane-strain Hertz: p0 = √(F' E*/(π R)), E* = G/(1 − ν) (Kalker's constants).
    let e_star = m.shear_modulus / (1.0 - m.poisson_ratio);
    let p0 = (FN / 1000.0 * e_star / (std::f64::consts::PI * 25.0)).sqrt();
    let theta = theta_star();
    assert!((theta - 0.4158).abs() < 1e-4 && (theta.cos() - 0.9148).abs() < 1e-4);
    // In our frame (rolling in +x) S_x = ξ + (2K/G) p with μ → 0: ξ_free < 0.
    let closed = -2.0 * k / m.shear_modulus * p0 * theta.cos();
    let xi = r.creepage.longitudinal;
    let err = (xi - closed) / closed;
    // Measured: ξ = −5.2603e-4 against −5.2630e-4 (−0.051 %; the sign change sits
    // between cells). Bound 0.3 %.
    assert!(err.abs() < 3e-3, "ξ = {xi:e}, closed form {closed:e}");
    // Complete slip: at most the cell at each sign change sticks (measured: 1 of 200).
    assert_eq!(r.contact_cells, 200);
    assert!(r.stick_cells <= 2, "{} stick cells", r.stick_cells);
    // F_x = 0 to the force tolerance (1e-8 μ F_N).
    assert!(r.force[0].abs() <= 1e-8 * 1e-4 * FN, "F_x = {}", r.force[0]);
    // The traction is −μp sgn(S): negative in the middle (S > 0, where (2K/G) p > −ξ),
    // positive towards both edges. (CONTACT's frame: positive in the middle.)
    let mid = gap.len() / 2;
    assert!(r.traction_x[mid] < 0.0 && r.traction_x[10] > 0.0 && r.traction_x[205] > 0.0);
}

/// One case of CONTACT's `bentall` reference output: `μ`, `F_x/(μ F_N)` on body 1 and
/// `ξ` (both in CONTACT's frame), adhesion and slip cells, contact cells, `p_max` \[MPa\].
struct Reference {
    mu: f64,
    fx: f64,
    xi: f64,
    stick: usize,
    slip: usize,
    contact: usize,
    p_max: f64,
}

#[test]
fn contact_example_bentall() {
    let refs = [
        // Minimal friction: complete slip (Bentall & Johnson 1967).
        Reference {
            mu: 1e-4,
            fx: 0.0,
            xi: 5.260e-4,
            stick: 1,
            slip: 199,
            contact: 200,
            p_max: 103.1,
        },
        // No slip (Bufler 1959).
        Reference {
            mu: 10.0,
            fx: 0.0,
            xi: 3.591e-4,
            stick: 200,
            slip: 0,
            contact: 200,
            p_max: 103.8,
        },
        Reference {
            mu: 0.05,
            fx: 0.0,
            xi: 4.294e-4,
            stick: 125,
            slip: 75,
            contact: 200,
            p_max: 103.6,
        },
        Reference {
            mu: 0.05,
            fx: 0.75,
            xi: 2.108e-4,
            stick: 36,
            slip: 164,
            contact: 200,
            p_max: 103.2,
        },
        Reference {
            mu: 0.05,
            fx: -0.75,
            xi: 5.392e-4,
            stick: 106,
            slip: 95,
            contact: 201,
            p_max: 103.3,
        },
    ];
    let (gap, mut s) = bentall_solver();
    let mut worst: f64 = 0.0;
    for c in &refs {
        // Each case from scratch, as CONTACT's (no initial estimate).
        s.reset();
        // Mirror: F_x and ξ change sign between CONTACT's frame and ours.
        let target = -c.fx * c.mu * FN;
        let r = s
            .solve(&gap, Control::Force(FN), c.mu, free_rolling(target))
            .unwrap();
        let tag = format!("μ = {}, F_x/μF_N = {}", c.mu, c.fx);
        assert_eq!(
            r.status.termination,
            Termination::Converged,
            "{tag}: {:?}",
            r.status
        );
        assert!((r.force[0] - target).abs() <= 1e-8 * c.mu * FN, "{tag}");
        let xi = -r.creepage.longitudinal;
        let err = (xi - c.xi) / c.xi;
        worst = worst.max(err.abs());
        // Measured: +0.0064 %, +0.0052 %, −0.0011 %, +0.0058 %, −0.0025 % against
        // CONTACT's four digits (whose rounding alone is up to 0.024 %). Bound 0.1 %.
        assert!(err.abs() < 1e-3, "{tag}: ξ = {xi:e}, CONTACT {:e}", c.xi);
        // Measured: the same counts in every case. Bound 2 cells.
        assert!(
            r.stick_cells.abs_diff(c.stick) <= 2 && r.slip_cells.abs_diff(c.slip) <= 2,
            "{tag}: {} stick, {} slip; CONTACT {}, {}",
            r.stick_cells,
            r.slip_cells,
            c.stick,
            c.slip
        );
        assert!(r.contact_cells.abs_diff(c.contact) <= 1, "{tag}");
        // Measured: +0.042 %, +0.006 %, +0.026 %, +0.023 %, −0.022 % from CONTACT's four
        // digits (103.1, 103.8, 103.6, 103.2, 103.3 MPa). Bound 0.1 %.
        let pm = p_max(&r);
        assert!(
            ((pm - c.p_max) / c.p_max).abs() < 1e-3,
            "{tag}: p_max = {pm}"
        );
        // The normal force balances (half-space solver tolerance).
        assert!((r.normal_force - FN).abs() < 1e-6 * FN, "{tag}");
    }
    assert!(worst < 1e-3);
}

#[test]
fn warm_start_repeats_the_solution_with_fewer_solves() {
    let (gap, mut s) = bentall_solver();
    let load = free_rolling(0.0);
    let cold = s.solve(&gap, Control::Force(FN), 0.05, load).unwrap();
    let warm = s.solve(&gap, Control::Force(FN), 0.05, load).unwrap();
    assert_eq!(warm.status.termination, Termination::Converged);
    // Measured: 24 steady solves cold, 4 warm; ξ the same to 1.6e-7 relative (the
    // outer tolerance is 1e-6). Bound 1e-6.
    assert!(
        warm.steady_solves < cold.steady_solves,
        "{} warm, {} cold",
        warm.steady_solves,
        cold.steady_solves
    );
    let (a, b) = (cold.creepage.longitudinal, warm.creepage.longitudinal);
    assert!(((a - b) / a).abs() < 1e-6, "{a:e} {b:e}");
    assert_eq!(cold.stick_cells, warm.stick_cells);
}

#[test]
fn a_warm_solve_allocates_only_its_solutions() {
    let (gap, mut s) = bentall_solver();
    let load = free_rolling(-0.3 * 0.05 * FN);
    s.solve(&gap, Control::Force(FN), 0.05, load).unwrap();
    let (r, count) =
        counting_alloc::allocations(|| s.solve(&gap, Control::Force(FN), 0.05, load).unwrap());
    assert_eq!(r.status.termination, Termination::Converged);
    // Each steady solve returns its solution (at most seven allocations, as the steady
    // solver's own test allows); the coupled solution adds three (pressure, coupling
    // gap, the pressure's displacement). Nothing per pass or per Newton iteration
    // besides. Measured: 23 for 4 steady solves (five vectors each, plus three).
    assert!(
        count <= 7 * r.steady_solves + 3,
        "{count} allocations for {} steady solves",
        r.steady_solves
    );
}

#[test]
fn prescribed_creepage_gives_the_force_that_force_control_prescribed() {
    // The free-rolling creepage, prescribed, gives F_x = 0 back.
    let grid = bentall_grid();
    let gap = bentall_gap(&grid);
    let opts = CoupledSteadyOptions::default();
    let mut s = CoupledSteadySolver::new(&grid, &aluminium(), &steel(), opts).unwrap();
    let free = s
        .solve(&gap, Control::Force(FN), 0.05, free_rolling(0.0))
        .unwrap();
    let mut t = CoupledSteadySolver::new(&grid, &aluminium(), &steel(), opts).unwrap();
    let r = t
        .solve(
            &gap,
            Control::Force(FN),
            0.05,
            SteadyLoad::Creepage(free.creepage),
        )
        .unwrap();
    assert_eq!(r.status.termination, Termination::Converged);
    // Measured: |F_x| = 4.4e-7 μF_N (the outer tolerance 1e-6 on the fields). Bound
    // 1e-4.
    assert!(r.force[0].abs() < 1e-4 * 0.05 * FN, "F_x = {}", r.force[0]);
    assert_eq!(r.stick_cells, free.stick_cells);
    // A larger creepage drives body 1 harder: F_x falls (Kalker's sign, F = −C ξ).
    let c = Creepage::longitudinal(free.creepage.longitudinal + 1e-4);
    let more = t
        .solve(&gap, Control::Force(FN), 0.05, SteadyLoad::Creepage(c))
        .unwrap();
    assert!(more.force[0] < -0.1 * 0.05 * FN);
}

/// A circular Hertz contact on `n × n` cells with an unloaded leading-edge column.
fn circle(n: usize) -> (Grid2, Vec<f64>) {
    let grid = Grid2::centered(0.6, 0.6, n, n).unwrap();
    // R = 10 mm: a ≈ 0.3-0.4 mm at the forces used below.
    let gap = grid.points().map(|(x, y)| (x * x + y * y) / 20.0).collect();
    (grid, gap)
}

#[test]
fn quasi_identical_bodies_and_coupling_off_reproduce_the_steady_solver_exactly() {
    let (grid, gap) = circle(16);
    let steel = ElasticMaterial::STEEL;
    let c = Creepage {
        longitudinal: 1e-3,
        lateral: -4e-4,
        spin: 1e-3,
    };
    let mu = 0.3;
    let cases = [
        (steel, steel, true),
        (aluminium(), ElasticMaterial::STEEL, false),
    ];
    for (b1, b2, coupling) in cases {
        let opts = CoupledSteadyOptions {
            coupling,
            ..CoupledSteadyOptions::default()
        };
        let mut s = CoupledSteadySolver::new(&grid, &b1, &b2, opts).unwrap();
        assert_eq!(s.difference_parameter(), 0.0);
        let r = s
            .solve(&gap, Control::Force(300.0), mu, SteadyLoad::Creepage(c))
            .unwrap();
        assert_eq!(r.status.termination, Termination::Converged);
        assert_eq!(r.status.iterations, 1, "one pass without coupling");
        assert!(r.stick_cells > 0 && r.slip_cells > 0);
        // The same pressure through the steady solver: identical tractions, bit for bit.
        let material = KalkerMaterial::new(&b1, &b2).unwrap();
        let mut steady = SteadySolver::new(&grid, material, Some(1)).unwrap();
        let q = steady
            .solve(&r.pressure, mu, c, &SteadyOptions::default())
            .unwrap();
        assert_eq!(q.traction_x, r.traction_x);
        assert_eq!(q.traction_y, r.traction_y);
        assert_eq!(q.state, r.state);
        assert_eq!(q.force, r.force);
        assert!(r.coupling_gap.iter().all(|v| *v == 0.0));
        // Force control: the creepage found gives the prescribed force through the
        // steady solver (to the force tolerance and the steady tolerance).
        let target = -0.5 * mu * r.normal_force;
        let f = s
            .solve(
                &gap,
                Control::Force(300.0),
                mu,
                SteadyLoad::LongitudinalForce {
                    force: target,
                    lateral: c.lateral,
                    spin: c.spin,
                },
            )
            .unwrap();
        assert_eq!(f.status.termination, Termination::Converged);
        steady.reset();
        let q = steady
            .solve(&f.pressure, mu, f.creepage, &SteadyOptions::default())
            .unwrap();
        // Measured: 5.6e-11 and 2.5e-11 of μF_N. Bound 1e-6.
        assert!(
            (q.force[0] - target).abs() < 1e-6 * mu * r.normal_force,
            "{} {}",
            q.force[0],
            target
        );
    }
}

#[test]
fn three_dimensional_free_rolling_is_symmetric_about_the_rolling_axis() {
    // Aluminium on steel, sphere R = 10 mm on a plane, F_N = 300 N (a ≈ 0.35 mm, 76
    // contact cells): free rolling converges, and the solution is the mirror image of
    // itself about y = 0 (τ_x, p even; τ_y odd; F_y = 0).
    let (grid, gap) = circle(16);
    let (nx, ny) = (grid.nx(), grid.ny());
    let mut xis = Vec::new();
    for mu in [1e-3, 0.3] {
        let mut s = CoupledSteadySolver::new(
            &grid,
            &aluminium(),
            &steel(),
            CoupledSteadyOptions::default(),
        )
        .unwrap();
        let r = s
            .solve(&gap, Control::Force(300.0), mu, free_rolling(0.0))
            .unwrap();
        assert_eq!(
            r.status.termination,
            Termination::Converged,
            "{:?}",
            r.status
        );
        let g = mu * p_max(&r);
        let mut asym: f64 = 0.0;
        for j in 0..ny {
            for i in 0..nx {
                let (a, b) = (j * nx + i, (ny - 1 - j) * nx + i);
                asym = asym
                    .max((r.traction_x[a] - r.traction_x[b]).abs())
                    .max((r.traction_y[a] + r.traction_y[b]).abs());
            }
        }
        // Measured: 2.8e-11 and 1.9e-10 of μ p_max; F_y 3e-13 and 2e-9 N. Bound 1e-8.
        assert!(asym < 1e-8 * g, "μ = {mu}: asymmetry {asym:e}");
        assert!(r.force[1].abs() < 1e-8 * mu * r.normal_force);
        assert!(r.force[0].abs() <= 1e-8 * mu * r.normal_force);
        // The pressure's slip (2K/G) p ~ 6e-3 here; the free-rolling creepage is negative
        // (body 1 the more compliant, K > 0) and smaller in magnitude with more friction.
        // Measured: −2.665e-3 (μ = 1e-3), −1.347e-3 (μ = 0.3).
        assert!(r.creepage.longitudinal < 0.0);
        xis.push(r.creepage.longitudinal);
        if mu > 0.1 {
            assert!(r.stick_cells > r.slip_cells);
        } else {
            assert_eq!(r.stick_cells, 0);
        }
    }
    assert!(xis[1].abs() < xis[0].abs(), "{xis:?}");
}

#[test]
fn a_uniform_extra_slip_is_a_creepage() {
    // s_i = ω dx + e + u_i − u_{i+1}: a uniform e_x is the creepage e_x/dx.
    let (grid, gap) = circle(14);
    let material = KalkerMaterial::new(&ElasticMaterial::STEEL, &ElasticMaterial::STEEL).unwrap();
    // A Hertz-like pressure on the cells (the gap's circle of radius 0.35 mm).
    let p: Vec<f64> = gap
        .iter()
        .map(|h| {
            let r = 1.0 - h * 20.0 / 0.35f64.powi(2);
            if r > 0.0 { 1500.0 * r.sqrt() } else { 0.0 }
        })
        .collect();
    let n = grid.len();
    let e = 4e-4 * grid.dx();
    let ex = vec![e; n];
    let ey = vec![-1e-4 * grid.dx(); n];
    for method in [SteadyMethod::Newton, SteadyMethod::Marching] {
        let opts = SteadyOptions {
            method,
            ..SteadyOptions::default()
        };
        let base = Creepage {
            longitudinal: 6e-4,
            lateral: 0.0,
            spin: 5e-4,
        };
        let mut a = SteadySolver::new(&grid, material, Some(1)).unwrap();
        let with = a
            .solve_with_rigid_slip(&p, 0.3, base, [&ex, &ey], &opts)
            .unwrap();
        let mut b = SteadySolver::new(&grid, material, Some(1)).unwrap();
        let shifted = Creepage {
            longitudinal: base.longitudinal + 4e-4,
            lateral: -1e-4,
            ..base
        };
        let plain = b.solve(&p, 0.3, shifted, &opts).unwrap();
        assert_eq!(with.status.termination, Termination::Converged);
        let fm = plain.force[0].hypot(plain.force[1]);
        // Measured: 0 (Newton, identical forces), 4.1e-10 (marching) relative. Bound
        // 1e-6.
        for k in 0..2 {
            assert!(
                (with.force[k] - plain.force[k]).abs() < 1e-6 * fm,
                "{method:?}: {:?} {:?}",
                with.force,
                plain.force
            );
        }
        assert_eq!(with.state, plain.state, "{method:?}");
    }
    // Bad extra slip: wrong length, not finite.
    let mut a = SteadySolver::new(&grid, material, Some(1)).unwrap();
    let c = Creepage::longitudinal(1e-3);
    let o = SteadyOptions::default();
    let e = a
        .solve_with_rigid_slip(&p, 0.3, c, [&ex[1..], &ey], &o)
        .unwrap_err();
    assert!(e.to_string().contains("extra_slip[0]"), "{e}");
    let mut bad = ey.clone();
    bad[3] = f64::NAN;
    let e = a
        .solve_with_rigid_slip(&p, 0.3, c, [&ex, &bad], &o)
        .unwrap_err();
    assert!(e.to_string().contains("extra_slip[1]"), "{e}");
}

#[test]
fn bad_input_is_refused_and_failures_are_statuses() {
    let grid = bentall_grid();
    let gap = bentall_gap(&grid);
    let (al, st) = (aluminium(), steel());
    let opts = CoupledSteadyOptions::default();
    let rigid = ElasticMaterial::RIGID;
    assert!(CoupledSteadySolver::new(&grid, &rigid, &rigid, opts).is_err());
    for (o, field) in [
        (
            CoupledSteadyOptions {
                tolerance: 0.0,
                ..opts
            },
            "tolerance",
        ),
        (
            CoupledSteadyOptions {
                force_tolerance: f64::NAN,
                ..opts
            },
            "force_tolerance",
        ),
        (
            CoupledSteadyOptions {
                max_outer: 0,
                ..opts
            },
            "max_outer",
        ),
        (
            CoupledSteadyOptions {
                max_force_iterations: 1,
                ..opts
            },
            "max_force_iterations",
        ),
    ] {
        let e = CoupledSteadySolver::new(&grid, &al, &st, o).unwrap_err();
        assert!(e.to_string().contains(field), "{e}");
    }
    let m = KalkerMaterial::new(&al, &st).unwrap();
    assert!(CoupledSteadySolver::from_constants(&grid, m, 0.7, opts).is_err());
    let one_column = Grid2::new([-0.1, 0.1], [-1.0, 1.0], 1, 4).unwrap();
    assert!(CoupledSteadySolver::new(&one_column, &al, &st, opts).is_err());

    let mut s = CoupledSteadySolver::new(&grid, &al, &st, opts).unwrap();
    let f = Control::Force(FN);
    let free = free_rolling(0.0);
    for mu in [0.0, -0.05, f64::NAN] {
        let e = s.solve(&gap, f, mu, free).unwrap_err();
        assert!(e.to_string().contains("friction_coefficient"), "{e}");
    }
    let e = s
        .solve(
            &gap,
            f,
            0.05,
            SteadyLoad::Creepage(Creepage::longitudinal(f64::NAN)),
        )
        .unwrap_err();
    assert!(e.to_string().contains("creepage.longitudinal"), "{e}");
    let e = s.solve(&gap, f, 0.05, free_rolling(f64::NAN)).unwrap_err();
    assert!(e.to_string().contains("force_x"), "{e}");
    let e = s
        .solve(
            &gap,
            f,
            0.05,
            SteadyLoad::LongitudinalForce {
                force: 0.0,
                lateral: f64::INFINITY,
                spin: 0.0,
            },
        )
        .unwrap_err();
    assert!(e.to_string().contains("creepage.lateral"), "{e}");
    // A force target at or beyond ±μF_N: one line naming the field, value and range.
    for target in [0.05 * FN, -0.06 * FN] {
        let e = s.solve(&gap, f, 0.05, free_rolling(target)).unwrap_err();
        let msg = e.to_string();
        assert!(
            msg.contains("force_x")
                && msg.contains(&format!("{target}"))
                && msg.contains("mu F_N")
                && !msg.contains('\n'),
            "{msg}"
        );
    }
    // The same under approach control, checked against the computed F_N (a circle:
    // approach 0.02 mm, F_N about 240 N).
    let (cgrid, cgap) = circle(16);
    let mut c = CoupledSteadySolver::new(&cgrid, &al, &st, opts).unwrap();
    let e = c
        .solve(&cgap, Control::Approach(0.02), 0.05, free_rolling(-1e3))
        .unwrap_err();
    assert!(e.to_string().contains("force_x"), "{e}");
    assert!(s.solve(&gap, Control::Force(f64::NAN), 0.05, free).is_err());
    assert!(s.solve(&gap[1..], f, 0.05, free).is_err());
    // A contact that reaches the leading-edge column (i = nx − 1).
    let shifted: Vec<f64> = grid
        .points()
        .map(|(x, _)| 0.02 * (x - 0.1).powi(2))
        .collect();
    let e = s.solve(&shifted, f, 0.05, free).unwrap_err();
    assert!(e.to_string().contains("leading-edge"), "{e}");

    // One pass cannot show convergence of a coupled problem: a status, not a panic.
    let mut one = CoupledSteadySolver::new(
        &grid,
        &al,
        &st,
        CoupledSteadyOptions {
            max_outer: 1,
            ..opts
        },
    )
    .unwrap();
    let r = one.solve(&gap, f, 0.05, free).unwrap();
    assert_eq!(r.status.termination, Termination::MaxIterations);
    assert!(r.status.residual.is_finite());
    assert!(r.traction_x.iter().all(|t| t.is_finite()));
    // A normal solve cut short: its status, the pressure, no steady solve.
    let mut normal = CoupledSteadySolver::new(
        &grid,
        &al,
        &st,
        CoupledSteadyOptions {
            normal: kontakt::halfspace::SolverOptions {
                max_iterations: 1,
                ..opts.normal
            },
            ..opts
        },
    )
    .unwrap();
    let r = normal.solve(&gap, f, 0.05, free).unwrap();
    assert_ne!(r.status.termination, Termination::Converged);
    assert!(r.steady_status.is_none() && r.status.residual.is_finite());
    assert!(r.pressure.iter().all(|p| p.is_finite()));
    // A creepage search cut short: its status and force residual.
    let mut short = CoupledSteadySolver::new(
        &grid,
        &al,
        &st,
        CoupledSteadyOptions {
            max_force_iterations: 2,
            ..opts
        },
    )
    .unwrap();
    let r = short.solve(&gap, f, 0.05, free).unwrap();
    assert_ne!(r.status.termination, Termination::Converged);
    assert!(r.status.residual.is_finite() && r.status.residual > 0.0);
    // A steady solve cut short: its status.
    let mut newton = CoupledSteadySolver::new(
        &grid,
        &al,
        &st,
        CoupledSteadyOptions {
            steady: SteadyOptions {
                max_newton_iterations: 1,
                ..SteadyOptions::default()
            },
            ..opts
        },
    )
    .unwrap();
    let r = newton
        .solve(
            &gap,
            f,
            0.05,
            SteadyLoad::Creepage(Creepage::longitudinal(-4e-4)),
        )
        .unwrap();
    assert_eq!(r.status.termination, Termination::MaxIterations);
    assert!(r.state.iter().all(|c| *c != CellState::Exterior) || r.contact_cells < 216);
}
