//! Steady rolling with partial slip on the half-space grid: tangential tractions with
//! Coulomb friction under a given pressure for given creepages and spin (Kalker's exact
//! theory, discretised as in Kalker 1990 ch. 5).
//!
//! # Formula
//! The contact rolls in `+x` at speed `V`; material enters at the leading edge (large
//! `x`) and leaves at the trailing edge. With the longitudinal and lateral creepages
//! `ξ`, `η` \[-\] and the spin `φ` \[1/mm\], the rigid slip per unit rolling distance is
//! `ω = (ξ − φ y, η + φ x)` and the slip (slip velocity over `V`, dimensionless) is
//! `S = ω − ∂u/∂x` with `u = A τ` the displacement difference of
//! [`super::TangentialOperator`]. Coulomb's law per loaded cell: `|τ_i| <= μ p_i`; stick
//! `S_i = 0`; slip `τ_i = −μ p_i S_i/|S_i|`. Forces on body 1: `F = Σ τ ΔA` \[N\], spin
//! moment `M_z = Σ (x τ_y − y τ_x) ΔA` \[N·mm\] about the grid origin.
//!
//! # Discretisation
//! Kalker's discretisation with the rolling step equal to one cell (the grid is aligned
//! with the rolling direction): the material at cell `i` comes from cell `i + 1`
//! (upwind), and the steady slip distance per cell is
//!
//! ```text
//! s_i = ω_i dx + u_i − u_{i+1}  [mm],   s = ω dx + (I − S) A τ,   S_i = s_i/dx,
//! ```
//!
//! `S` the shift by one cell in `+x`.
//!
//! # Solvers ([`SteadyOptions::method`])
//! - [`SteadyMethod::Newton`] (default): a semismooth Newton method on the projection
//!   form of Coulomb's law `F(τ) = τ − P(τ − r s(τ)) = 0` (`P` the projection onto each
//!   cell's disc `|τ_i| <= μ p_i`, `r` \[MPa/mm\] the inverse of the operator's
//!   diagonal), each linear system by restarted GMRES whose product is one FFT
//!   application of `(I − S) A` and whose preconditioner is the exact Jacobian of each
//!   grid row (LU per row). Backtracking on `|F|`; the warm start is the last tractions
//!   (scaled by `λ` when the creepage is `λ` times the last one). Derivation and
//!   measured speed: docs/rolling.md §5.1.
//! - [`SteadyMethod::Marching`] (the reference): Kalker's transient steps marched to the
//!   steady state: each step is a shift problem with the per-cell rigid term
//!   `ω_i dx − u'_{i+1}` (`u'` the previous step's displacements), solved by the convex
//!   minimisation of [`super::ShiftSolver`]; from zero traction until the tractions stop
//!   changing (about the cells along `x` in steps, seconds at 32 × 32).
//!
//! **Convergence criterion, Newton.** `max_i |F_i| <= tolerance · r · max_i |ω_i| dx`:
//! in a stick cell the slip, in a slip cell the traction's distance from the Coulomb
//! traction expressed as a slip, relative to the largest rigid slip (default `1e-8`).
//! The status reports the Newton iterations and that relative residual; the solution
//! also counts the FFT applications and GMRES iterations. Reaching
//! `max_newton_iterations` or `max_iterations` FFT applications is
//! [`Termination::MaxIterations`] (the tractions are then those of the last iterate,
//! projected onto the discs: finite, within the bounds).
//!
//! **Convergence criterion, marching.** Each step to the shift solver's criterion (stick
//! holds to a fraction of `max |ω| dx`: 1e-3 in the first step, then 0.1 times the last
//! step's relative traction change, never below `tolerance`); steady when the largest
//! change of traction over one step is `<= steady_tolerance · μ max p` and the step was
//! solved to `tolerance`. The status reports the steps (its `iterations`) and that
//! change.
//!
//! # Assumptions
//! Quasi-identical bodies (`K = 0`; dissimilar bodies through the extra rigid slip of
//! [`SteadySolver::solve_with_rigid_slip`], see [`super::CoupledSteadySolver`]), the
//! pressure given and constant, constant `μ`,
//! small creepages (linear kinematics), the column of cells at the leading edge unloaded
//! (the upwind cell of every loaded cell is on the grid).
//!
//! # References
//! Kalker, *Three-dimensional elastic bodies in rolling contact* (1990), ch. 2 and 5;
//! Johnson (1985) §8; Alart & Curnier (1991), Qi & Sun (1993) (semismooth Newton);
//! Saad & Schultz (1986) (GMRES).

use super::newton::{NewtonSettings, SteadyNewton};
use super::shift::{CellState, ShiftSolver, project};
use crate::error::{Error, Result};
use crate::geometry::Grid2;
use crate::solve::{SolveStatus, Termination};
use crate::tangential::{Creepage, KalkerMaterial};
use crate::units::{Newton, NewtonMillimetre};

/// The tolerance of the first rolling step's shift problem (relative, as `tolerance`).
const INITIAL_STEP_TOLERANCE: f64 = 1e-3;

/// A step's tolerance is this times the last step's relative traction change.
const STEP_TOLERANCE_FACTOR: f64 = 0.1;

/// The method of [`SteadySolver::solve`].
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
#[cfg_attr(
    feature = "serde",
    derive(serde::Serialize, serde::Deserialize, schemars::JsonSchema)
)]
#[cfg_attr(feature = "serde", serde(rename_all = "snake_case"))]
pub enum SteadyMethod {
    /// Semismooth Newton on the steady equations, GMRES with the row-block
    /// preconditioner (the default; see the module docs).
    #[default]
    Newton,
    /// Kalker's transient rolling steps marched to the steady state (the reference,
    /// slow: seconds at 32 × 32 cells).
    Marching,
}

/// Tolerances and limits of [`SteadySolver::solve`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SteadyOptions {
    /// Relative tolerance, on the slip in stick cells relative to `max |ω| dx` (Newton:
    /// the residual of the steady equations; marching: each step's shift problem).
    /// Default 1e-8.
    pub tolerance: f64,
    /// Newton: most FFT applications of `A` in all; marching: most FFT iterations per
    /// step. Default 20 000.
    pub max_iterations: usize,
    /// Marching only: steady when the largest traction change of a step is below this
    /// times `μ max p`. Default 1e-7.
    pub steady_tolerance: f64,
    /// Marching only: most rolling steps. Default 2000.
    pub max_steps: usize,
    /// The method. Default [`SteadyMethod::Newton`].
    pub method: SteadyMethod,
    /// Newton only: most Newton iterations. Default 100.
    pub max_newton_iterations: usize,
}

impl Default for SteadyOptions {
    fn default() -> Self {
        SteadyOptions {
            tolerance: 1e-8,
            max_iterations: 20_000,
            steady_tolerance: 1e-7,
            max_steps: 2000,
            method: SteadyMethod::Newton,
            max_newton_iterations: 100,
        }
    }
}

/// The solution of a steady rolling problem.
#[derive(Debug, Clone, PartialEq)]
pub struct SteadySolution {
    /// Tractions `τ_x` on body 1 \[MPa\], row-major, x fastest.
    pub traction_x: Vec<f64>,
    /// Tractions `τ_y` on body 1 \[MPa\].
    pub traction_y: Vec<f64>,
    /// Slip `S_x` per unit rolling distance \[-\]; zero in stick and exterior cells.
    pub slip_x: Vec<f64>,
    /// Slip `S_y` \[-\].
    pub slip_y: Vec<f64>,
    /// State of each cell.
    pub state: Vec<CellState>,
    /// Creep force on body 1 `[F_x, F_y]` \[N\].
    pub force: [Newton; 2],
    /// Spin moment on body 1 about the grid origin \[N·mm\].
    pub spin_moment: NewtonMillimetre,
    /// Normal force `Σ p ΔA` \[N\].
    pub normal_force: Newton,
    /// Cells in stick.
    pub stick_cells: usize,
    /// Cells in slip.
    pub slip_cells: usize,
    /// FFT applications of `A` (Newton: residuals and GMRES products; marching: the
    /// iterations over all steps).
    pub fft_iterations: usize,
    /// GMRES iterations over all Newton iterations (0 for marching).
    pub linear_iterations: usize,
    /// Newton: termination, Newton iterations and the final relative residual (see the
    /// module docs). Marching: termination (converged: steady, and every step
    /// converged), rolling steps, and the last step's traction change relative to
    /// `μ max p`.
    pub status: SolveStatus,
}

/// A steady-rolling solver on one grid (rolling along `+x`): the shift solver's operator
/// and work arrays, and the last tractions (the warm start of the next solve).
#[derive(Debug)]
pub struct SteadySolver {
    core: ShiftSolver,
    newton: SteadyNewton,
    grid: Grid2,
    /// The previous step's displacements \[mm\].
    last: [Vec<f64>; 2],
    /// The previous step's tractions \[MPa\].
    before: [Vec<f64>; 2],
    /// The creepage and `μ` of the stored tractions (`None` after a reset).
    warm: Option<(Creepage, f64)>,
    /// The tractions \[MPa\] of the solve before the last, and its creepage, when both
    /// lie on one ray of creepages with the last (the secant predictor's first point).
    older: [Vec<f64>; 2],
    older_creep: Option<Creepage>,
}

/// `λ > 0` with `new = λ old` (the three creepages parallel to 1e-9), else `None`.
fn creep_ratio(old: Creepage, new: Creepage) -> Option<f64> {
    let a = [old.longitudinal, old.lateral, old.spin];
    let b = [new.longitudinal, new.lateral, new.spin];
    let aa: f64 = a.iter().map(|v| v * v).sum();
    let ab: f64 = a.iter().zip(&b).map(|(x, y)| x * y).sum();
    let bb: f64 = b.iter().map(|v| v * v).sum();
    if !(aa > 0.0 && bb > 0.0 && ab > 0.0 && aa.is_finite() && bb.is_finite()) {
        return None;
    }
    let lambda = ab / aa;
    let parallel = a
        .iter()
        .zip(&b)
        .all(|(x, y)| (y - lambda * x).abs() <= 1e-9 * bb.sqrt());
    (parallel && lambda.is_finite()).then_some(lambda)
}

impl SteadySolver {
    /// A solver for `grid` \[mm\] and the combined constants (`threads` as for
    /// [`crate::halfspace::HalfSpacePlan::new`]).
    ///
    /// # Errors
    /// [`Error::InvalidInput`] for constants out of range, `threads` out of range, or a
    /// grid with fewer than 2 cells along `x`.
    pub fn new(grid: &Grid2, material: KalkerMaterial, threads: Option<usize>) -> Result<Self> {
        if grid.nx() < 2 {
            return Err(Error::invalid("nx", grid.nx(), "at least 2 cells along x"));
        }
        let core = ShiftSolver::new(grid, material, threads)?;
        let n = grid.len();
        let newton = SteadyNewton::new(
            grid.nx(),
            grid.ny(),
            grid.dx(),
            grid.dy(),
            material.shear_modulus,
            material.poisson_ratio,
        );
        Ok(SteadySolver {
            core,
            newton,
            grid: *grid,
            last: [vec![0.0; n], vec![0.0; n]],
            before: [vec![0.0; n], vec![0.0; n]],
            warm: None,
            older: [vec![0.0; n], vec![0.0; n]],
            older_creep: None,
        })
    }

    /// Forget the last tractions: the next solve starts from zero traction.
    pub fn reset(&mut self) {
        self.core.reset();
        self.warm = None;
        self.older_creep = None;
    }

    /// Solve for the cell pressures `pressure` \[MPa\] (row-major, x fastest, `>= 0`),
    /// friction coefficient `mu` and the creepages, from the last tractions.
    ///
    /// Not converging is not an error: see the solution's `status`.
    ///
    /// # Errors
    /// [`Error::InvalidInput`] for a pressure of the wrong length, negative or not finite,
    /// without a loaded cell or loaded in the leading-edge column; `mu` not finite and > 0;
    /// creepages not finite; options out of range.
    pub fn solve(
        &mut self,
        pressure: &[f64],
        mu: f64,
        creepage: Creepage,
        options: &SteadyOptions,
    ) -> Result<SteadySolution> {
        self.solve_inner(pressure, mu, creepage, None, options)
    }

    /// As [`SteadySolver::solve`], with an extra rigid slip per cell: the slip distance
    /// over one rolling step (one cell) becomes
    ///
    /// ```text
    /// s_i = ω_i dx + e_i + u_i − u_{i+1}   [mm],
    /// ```
    ///
    /// `e = [e_x, e_y]` \[mm\] (row-major, x fastest, `nx·ny` values each; values in
    /// unloaded cells are ignored). For dissimilar bodies `e_i = (A_t p)_i − (A_t p)_{i+1}`,
    /// the upwind difference of the pressure's tangential displacement (docs/rolling.md
    /// §9.3, [`super::CoupledSteadySolver`]). Both methods take it. The rigid slip scale
    /// of the convergence criterion is then `max_i |ω_i dx + e_i|` over the loaded cells;
    /// along a creep curve the warm start is not scaled (the extra slip does not scale
    /// with the creepage).
    ///
    /// Not converging is not an error: see the solution's `status`.
    ///
    /// # Errors
    /// As [`SteadySolver::solve`], and [`Error::InvalidInput`] for an extra slip of the
    /// wrong length or not finite.
    pub fn solve_with_rigid_slip(
        &mut self,
        pressure: &[f64],
        mu: f64,
        creepage: Creepage,
        extra_slip: [&[f64]; 2],
        options: &SteadyOptions,
    ) -> Result<SteadySolution> {
        let n = self.grid.len();
        for (field, e) in [
            ("extra_slip[0]", extra_slip[0]),
            ("extra_slip[1]", extra_slip[1]),
        ] {
            if e.len() != n {
                return Err(Error::invalid(
                    field,
                    format!("{} values", e.len()),
                    format!("{n} values ({} x {} grid)", self.grid.nx(), self.grid.ny()),
                ));
            }
            if let Some(v) = e.iter().find(|v| !v.is_finite()) {
                return Err(Error::invalid(field, v, "finite slip distances in mm"));
            }
        }
        self.solve_inner(pressure, mu, creepage, Some(extra_slip), options)
    }

    /// The solve, with the optional extra rigid slip (`None`: exactly the operations of
    /// the solver without it).
    fn solve_inner(
        &mut self,
        pressure: &[f64],
        mu: f64,
        creepage: Creepage,
        extra: Option<[&[f64]; 2]>,
        options: &SteadyOptions,
    ) -> Result<SteadySolution> {
        let (nx, ny) = (self.grid.nx(), self.grid.ny());
        let n = nx * ny;
        if pressure.len() != n {
            return Err(Error::invalid(
                "pressure",
                format!("{} values", pressure.len()),
                format!("{n} values ({nx} x {ny} grid)"),
            ));
        }
        if let Some(p) = pressure.iter().find(|p| !(p.is_finite() && **p >= 0.0)) {
            return Err(Error::invalid(
                "pressure",
                p,
                "finite cell pressures >= 0 MPa",
            ));
        }
        if (0..ny).any(|j| pressure[j * nx + nx - 1] > 0.0) {
            return Err(Error::invalid(
                "pressure",
                "a loaded cell in the leading-edge column (i = nx - 1)",
                "a grid that extends beyond the contact's leading edge (+x)",
            ));
        }
        crate::tangential::check_friction(mu)?;
        creepage.validate()?;
        for (field, v) in [
            ("tolerance", options.tolerance),
            ("steady_tolerance", options.steady_tolerance),
        ] {
            if !(v.is_finite() && v > 0.0 && v < 1.0) {
                return Err(Error::invalid(field, v, "0 < tolerance < 1"));
            }
        }
        for (field, v) in [
            ("max_iterations", options.max_iterations),
            ("max_steps", options.max_steps),
            ("max_newton_iterations", options.max_newton_iterations),
        ] {
            if v == 0 {
                return Err(Error::invalid(field, v, "at least 1"));
            }
        }
        let area = self.grid.cell_area();
        let normal_force = pressure.iter().sum::<f64>() * area;
        if !(normal_force > 0.0) {
            return Err(Error::invalid(
                "pressure",
                "no cell with p > 0",
                "a pressure field with contact (some cell p > 0 MPa)",
            ));
        }
        let p_max = pressure.iter().fold(0.0f64, |a, p| a.max(*p));
        for (b, p) in self.core.bound.iter_mut().zip(pressure) {
            *b = mu * p;
        }
        let dx = self.grid.dx();
        let omega = |i: usize, j: usize, g: &Grid2| {
            [
                creepage.longitudinal - creepage.spin * g.y(j),
                creepage.lateral + creepage.spin * g.x(i),
            ]
        };
        // The rigid slip scale max |ω| dx over the loaded cells.
        let mut scale: f64 = 0.0;
        for j in 0..ny {
            for i in 0..nx {
                let c = j * nx + i;
                if pressure[c] > 0.0 {
                    let w = omega(i, j, &self.grid);
                    scale = match extra {
                        None => scale.max(w[0].hypot(w[1]) * dx),
                        Some([ex, ey]) => scale.max((w[0] * dx + ex[c]).hypot(w[1] * dx + ey[c])),
                    };
                }
            }
        }
        if options.method == SteadyMethod::Newton {
            // Warm start along a creep curve (the creepage a positive multiple λ of the
            // last one, same μ, no extra slip): the secant through the last two
            // solutions on that ray (creepages s₀ < s₁ -> s₂ = λ s₁:
            // τ₁ + (s₂ − s₁)/(s₁ − s₀) (τ₁ − τ₀)), or, with one solution, the secant
            // through zero traction (τ₁ scaled by λ, exact while all cells stick); the
            // solver projects them onto the discs.
            let mut older_creep = None;
            if let Some((c1, mu1)) = self.warm
                && extra.is_none()
                && mu1 == mu
                && let Some(lambda) = creep_ratio(c1, creepage)
            {
                // c1 = l0 c0: the steps in units of s₀ are s₁ − s₀ = l0 − 1 and
                // s₂ − s₁ = l0 (λ − 1).
                let secant = self
                    .older_creep
                    .and_then(|c0| creep_ratio(c0, c1))
                    .filter(|l0| (l0 - 1.0).abs() > 1e-9)
                    .map(|l0| l0 * (lambda - 1.0) / (l0 - 1.0));
                for (t, o) in self.core.tau.iter_mut().zip(self.older.iter_mut()) {
                    for (t1, t0) in t.iter_mut().zip(o.iter_mut()) {
                        let v = *t1;
                        *t1 = match secant {
                            Some(r) => v + r * (v - *t0),
                            None => v * lambda,
                        };
                        *t0 = v;
                    }
                }
                older_creep = Some(c1);
            }
            // With an extra slip the tractions are not proportional to the creepage.
            self.older_creep = older_creep;
            self.warm = extra.is_none().then_some((creepage, mu));
            let grid = self.grid;
            let rigid = |c: usize| {
                let w = omega(c % nx, c / nx, &grid);
                match extra {
                    None => [w[0] * dx, w[1] * dx],
                    Some([ex, ey]) => [w[0] * dx + ex[c], w[1] * dx + ey[c]],
                }
            };
            let (termination, iterations, residual, fft, linear) = if scale > 0.0 {
                let settings = NewtonSettings {
                    tolerance: options.tolerance,
                    max_newton: options.max_newton_iterations,
                    max_fft: options.max_iterations,
                };
                let (bound, tau) = self.core.bound_and_tractions();
                let out = self
                    .newton
                    .solve(bound, rigid, tau, &mut self.last, scale, &settings);
                (
                    out.termination,
                    out.newton,
                    out.residual,
                    out.fft,
                    out.gmres,
                )
            } else {
                // No creepage: no traction.
                for t in self.core.tau.iter_mut() {
                    t.fill(0.0);
                }
                (Termination::Converged, 0, 0.0, 0, 0)
            };
            // `last` holds the slip distances s [mm] of the loaded cells.
            return Ok(self.collect(
                scale,
                normal_force,
                |s: &Self, k| [s.last[0][k] / dx, s.last[1][k] / dx],
                fft,
                linear,
                SolveStatus::new(termination, iterations, residual),
            ));
        }
        // The warm start, projected onto the new discs, and its displacements.
        {
            let core = &mut self.core;
            for c in 0..n {
                (core.tau[0][c], core.tau[1][c]) =
                    project(core.tau[0][c], core.tau[1][c], core.bound[c]);
            }
        }
        self.core.displacements(&mut self.last)?;
        let mut termination = Termination::MaxIterations;
        let (mut steps, mut fft, mut change) = (0, 0, f64::INFINITY);
        // Inexact steps while far from the steady state: the step tolerance follows the
        // change of the last step (down to `tolerance`), so early steps are cheap.
        let mut inner_tolerance = options.tolerance.max(INITIAL_STEP_TOLERANCE);
        for step in 1..=options.max_steps {
            steps = step;
            for k in 0..2 {
                self.before[k].copy_from_slice(&self.core.tau[k]);
            }
            // Rigid term of this step: ω dx − u'(upstream cell).
            for j in 0..ny {
                for i in 0..nx {
                    let c = j * nx + i;
                    let w = omega(i, j, &self.grid);
                    let up = if i + 1 < nx { c + 1 } else { c };
                    self.core.rigid[0][c] = w[0] * dx - self.last[0][up];
                    self.core.rigid[1][c] = w[1] * dx - self.last[1][up];
                    if let Some([ex, ey]) = extra {
                        self.core.rigid[0][c] += ex[c];
                        self.core.rigid[1][c] += ey[c];
                    }
                }
            }
            let inner = self
                .core
                .inner_rigid(scale, inner_tolerance, options.max_iterations);
            fft += inner.iterations;
            if inner.termination != Termination::Converged {
                termination = inner.termination;
                break;
            }
            // The displacements of this step (the next step's u').
            self.core.displacements(&mut self.last)?;
            change = (0..n)
                .map(|c| {
                    (self.core.tau[0][c] - self.before[0][c])
                        .hypot(self.core.tau[1][c] - self.before[1][c])
                })
                .fold(0.0, f64::max)
                / (mu * p_max);
            if !change.is_finite() {
                termination = Termination::Diverged;
                break;
            }
            if change <= options.steady_tolerance && inner_tolerance <= options.tolerance {
                termination = Termination::Converged;
                break;
            }
            inner_tolerance = options
                .tolerance
                .max(inner_tolerance.min(STEP_TOLERANCE_FACTOR * change));
        }
        let status = SolveStatus::new(termination, steps, change);
        Ok(self.collect(
            scale,
            normal_force,
            |s: &Self, k| {
                [
                    (s.core.rigid[0][k] + s.last[0][k]) / dx,
                    (s.core.rigid[1][k] + s.last[1][k]) / dx,
                ]
            },
            fft,
            0,
            status,
        ))
    }

    /// The solution from the stored tractions; `slip(self, cell)` is the slip per unit
    /// rolling distance of a slipping cell.
    fn collect(
        &self,
        scale: f64,
        normal_force: f64,
        slip: impl Fn(&Self, usize) -> [f64; 2],
        fft: usize,
        linear: usize,
        status: SolveStatus,
    ) -> SteadySolution {
        let (nx, ny) = (self.grid.nx(), self.grid.ny());
        let n = nx * ny;
        let area = self.grid.cell_area();
        let mut state = vec![CellState::Exterior; n];
        let (mut slip_x, mut slip_y) = (vec![0.0; n], vec![0.0; n]);
        let (mut stick_cells, mut slip_cells) = (0, 0);
        let (mut fx, mut fy, mut mz) = (0.0, 0.0, 0.0);
        let core = &self.core;
        for j in 0..ny {
            for i in 0..nx {
                let k = j * nx + i;
                let b = core.bound[k];
                if b <= 0.0 {
                    continue;
                }
                let (tx, ty) = (core.tau[0][k], core.tau[1][k]);
                fx += tx * area;
                fy += ty * area;
                mz += (self.grid.x(i) * ty - self.grid.y(j) * tx) * area;
                if tx.hypot(ty) >= b * (1.0 - 1e-9) && scale > 0.0 {
                    state[k] = CellState::Slip;
                    slip_cells += 1;
                    [slip_x[k], slip_y[k]] = slip(self, k);
                } else {
                    state[k] = CellState::Stick;
                    stick_cells += 1;
                }
            }
        }
        SteadySolution {
            traction_x: core.tau[0].clone(),
            traction_y: core.tau[1].clone(),
            slip_x,
            slip_y,
            state,
            force: [fx, fy],
            spin_moment: mz,
            normal_force,
            stick_cells,
            slip_cells,
            fft_iterations: fft,
            linear_iterations: linear,
            status,
        }
    }
}
