//! The shift (Cattaneo) problem on the half-space grid: tangential tractions with
//! Coulomb friction under a given pressure for a rigid tangential shift or a total
//! tangential force.
//!
//! # Formula
//! On cells with pressure `p_i > 0` \[MPa\], friction coefficient `μ`, tractions `τ_i` on
//! body 1 \[MPa\], a rigid shift `δ` \[mm\] of body 1 relative to body 2 and the
//! displacement difference `u = A τ` \[mm\] ([`super::TangentialOperator`]), the slip is
//! `s_i = δ + u_i` and Coulomb's law is (Kalker 1990 §2.2)
//!
//! ```text
//! |τ_i| <= μ p_i;   stick: s_i = 0;   slip: τ_i = -μ p_i s_i/|s_i|.
//! ```
//!
//! With `A` symmetric positive definite this is the optimality condition of the convex
//! problem (Kalker's principle of minimum complementary energy for a shift)
//!
//! ```text
//! minimise  E(τ) = ½ τ·Aτ + δ·Σ τ_i   over  |τ_i| <= μ p_i,
//! ```
//!
//! whose gradient is the slip `s`. It is solved by accelerated projected gradients
//! (FISTA, Beck & Teboulle 2009) with gradient restart (O'Donoghue & Candès 2015): step
//! `1/L` with `L` the operator's [`super::TangentialOperator::spectral_bound`], the
//! projection onto each cell's disc. One FFT application of `A` per iteration; nothing is
//! allocated inside the iteration.
//!
//! **Convergence criterion.** The gradient mapping `G_i = (y_i - P(y_i - s_i/L))·L` \[mm\]
//! at the iterate `y`: in a stick cell it is the slip, in a slip cell the part of the slip
//! not along the traction bound. The iteration stops when `max_i |G_i| <= tol · |δ|`:
//! stick holds to a fraction `tol` of the shift. The status reports that relative
//! residual.
//!
//! **Force control.** For a prescribed force `F` on body 1 (`|F| < μ P`) the shift is
//! sought along `-F/|F|`, `δ = -σ F/|F|`, and the scalar `σ` by the Illinois
//! (regula falsi) method on `-F̂·ΣτΔA = |F|`, each inner solve warm-started from the
//! previous. The force residual is relative to `μ P`. Shift and force are parallel for a
//! contact symmetric about the force's direction (a circle, an ellipse loaded along an
//! axis); otherwise a small force component across `F` remains, which the solution
//! reports (its `force`).
//!
//! # Assumptions
//! Quasi-identical bodies (normal and tangential decoupled, see [`super::influence`]),
//! the pressure given and unchanged by the tractions, Coulomb friction with a constant
//! `μ`, uniform tractions per cell, quasi-static loading from zero traction (no loading
//! history).
//!
//! # References
//! - Cattaneo (1938); Mindlin (1949); Johnson, *Contact Mechanics* (1985) §7.1-7.2.
//! - Kalker, *Three-dimensional elastic bodies in rolling contact* (1990), ch. 2 and 5.
//! - Beck & Teboulle (2009), SIAM J. Imaging Sci. 2, 183-202 (FISTA); O'Donoghue &
//!   Candès (2015), Found. Comput. Math. 15, 715-732 (adaptive restart).

use super::operator::TangentialOperator;
use crate::error::{Error, Result};
use crate::geometry::Grid2;
use crate::solve::{SolveStatus, Termination};
use crate::tangential::KalkerMaterial;
use crate::units::{Millimetre, Newton};

/// What is prescribed in a shift problem.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum ShiftLoad {
    /// The rigid shift `[δ_x, δ_y]` \[mm\] of body 1 relative to body 2.
    Shift([Millimetre; 2]),
    /// The total tangential force `[F_x, F_y]` \[N\] on body 1, `|F| < μ P`.
    Force([Newton; 2]),
}

/// Tolerances and limits of [`ShiftSolver::solve`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ShiftOptions {
    /// Relative tolerance of the inner iteration: `max |G_i| <= tolerance · |δ|` (see the
    /// module docs). Default 1e-8.
    pub tolerance: f64,
    /// Most inner iterations (FFT applications) per shift. Default 20 000.
    pub max_iterations: usize,
    /// Force-control tolerance, relative to `μ P`. Default 1e-8.
    pub force_tolerance: f64,
    /// Most shifts tried under force control. Default 100.
    pub max_shifts: usize,
}

impl Default for ShiftOptions {
    fn default() -> Self {
        ShiftOptions {
            tolerance: 1e-8,
            max_iterations: 20_000,
            force_tolerance: 1e-8,
            max_shifts: 100,
        }
    }
}

/// The state of one cell of a tangential solution.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum CellState {
    /// No pressure: no traction.
    Exterior,
    /// Adhesion: `|τ| < μ p`, no slip.
    Stick,
    /// Slip: `|τ| = μ p`, traction opposite to the slip.
    Slip,
}

/// The solution of a shift problem.
#[derive(Debug, Clone, PartialEq)]
pub struct ShiftSolution {
    /// Tractions `τ_x` on body 1 \[MPa\], row-major, x fastest.
    pub traction_x: Vec<f64>,
    /// Tractions `τ_y` on body 1 \[MPa\].
    pub traction_y: Vec<f64>,
    /// Slip `s_x = δ_x + u_x` \[mm\]; zero in stick and exterior cells.
    pub slip_x: Vec<f64>,
    /// Slip `s_y` \[mm\]; zero in stick and exterior cells.
    pub slip_y: Vec<f64>,
    /// State of each cell.
    pub state: Vec<CellState>,
    /// Total tangential force on body 1 `Σ τ ΔA` \[N\].
    pub force: [Newton; 2],
    /// The rigid shift \[mm\] (prescribed, or found under force control).
    pub shift: [Millimetre; 2],
    /// The normal force `Σ p ΔA` \[N\] of the given pressure.
    pub normal_force: Newton,
    /// Cells in stick.
    pub stick_cells: usize,
    /// Cells in slip.
    pub slip_cells: usize,
    /// Shifts tried (1 under shift control).
    pub shifts: usize,
    /// Termination, total inner iterations, and the final residual: the inner relative
    /// residual, or under force control the larger of it and the force residual.
    pub status: SolveStatus,
}

/// A solver of shift problems on one grid: plans the tangential operator once and keeps
/// its work arrays and the last tractions (the warm start of the next solve).
#[derive(Debug)]
pub struct ShiftSolver {
    op: TangentialOperator,
    grid: Grid2,
    /// Traction bounds `μ p_i` \[MPa\].
    pub(super) bound: Vec<f64>,
    pub(super) tau: [Vec<f64>; 2],
    prev: [Vec<f64>; 2],
    y: [Vec<f64>; 2],
    pub(super) u: [Vec<f64>; 2],
    /// The rigid part of the slip per cell \[mm\]: the shift, or in a rolling step the
    /// rigid slip minus the previous displacement upstream.
    pub(super) rigid: [Vec<f64>; 2],
}

/// Inner iteration outcome.
pub(super) struct Inner {
    pub(super) termination: Termination,
    pub(super) iterations: usize,
    pub(super) residual: f64,
}

impl ShiftSolver {
    /// A solver for `grid` \[mm\] and the combined constants `material` (`threads` as for
    /// [`crate::halfspace::HalfSpacePlan::new`]).
    ///
    /// # Errors
    /// [`Error::InvalidInput`] for `threads` outside 1..=[`crate::MAX_THREADS`].
    pub fn new(grid: &Grid2, material: KalkerMaterial, threads: Option<usize>) -> Result<Self> {
        let op = TangentialOperator::new(grid, material, threads)?;
        let n = grid.len();
        let z = || [vec![0.0; n], vec![0.0; n]];
        Ok(ShiftSolver {
            op,
            grid: *grid,
            bound: vec![0.0; n],
            tau: z(),
            prev: z(),
            y: z(),
            u: z(),
            rigid: z(),
        })
    }

    /// The tangential operator.
    pub fn operator(&self) -> &TangentialOperator {
        &self.op
    }

    /// The traction bounds and the stored tractions, borrowed together.
    pub(super) fn bound_and_tractions(&mut self) -> (&[f64], &mut [Vec<f64>; 2]) {
        (&self.bound, &mut self.tau)
    }

    /// The displacements `A τ` \[mm\] of the stored tractions into `out`.
    pub(super) fn displacements(&mut self, out: &mut [Vec<f64>; 2]) -> Result<()> {
        let ShiftSolver { op, tau, .. } = self;
        let [ux, uy] = out;
        op.apply(&tau[0], &tau[1], ux, uy)
    }

    /// Forget the last tractions: the next solve starts from zero traction.
    pub fn reset(&mut self) {
        for t in &mut self.tau {
            t.fill(0.0);
        }
    }

    /// Solve the shift problem for the cell pressures `pressure` \[MPa\] (row-major, x
    /// fastest, `>= 0`), friction coefficient `mu` and the prescribed `load`, starting
    /// from the last solution's tractions (projected onto the new bounds).
    ///
    /// Not converging is not an error: see the solution's `status`.
    ///
    /// # Errors
    /// [`Error::InvalidInput`] for a pressure of the wrong length, negative or not
    /// finite, or without a loaded cell; `mu` not finite and > 0; a shift or force not
    /// finite; a force `|F| >= μ P` (the contact slides and the shift is undetermined);
    /// options out of range.
    pub fn solve(
        &mut self,
        pressure: &[f64],
        mu: f64,
        load: ShiftLoad,
        options: &ShiftOptions,
    ) -> Result<ShiftSolution> {
        let n = self.grid.len();
        if pressure.len() != n {
            return Err(Error::invalid(
                "pressure",
                format!("{} values", pressure.len()),
                format!("{n} values ({} x {} grid)", self.grid.nx(), self.grid.ny()),
            ));
        }
        if let Some(p) = pressure.iter().find(|p| !(p.is_finite() && **p >= 0.0)) {
            return Err(Error::invalid(
                "pressure",
                p,
                "finite cell pressures >= 0 MPa",
            ));
        }
        crate::tangential::check_friction(mu)?;
        if !(options.tolerance.is_finite() && options.tolerance > 0.0 && options.tolerance < 1.0) {
            return Err(Error::invalid(
                "tolerance",
                options.tolerance,
                "0 < tolerance < 1",
            ));
        }
        if !(options.force_tolerance.is_finite()
            && options.force_tolerance > 0.0
            && options.force_tolerance < 1.0)
        {
            return Err(Error::invalid(
                "force_tolerance",
                options.force_tolerance,
                "0 < force_tolerance < 1",
            ));
        }
        for (field, v) in [
            ("max_iterations", options.max_iterations),
            ("max_shifts", options.max_shifts),
        ] {
            if v == 0 {
                return Err(Error::invalid(field, v, "at least 1"));
            }
        }
        let area = self.grid.cell_area();
        let normal_force: f64 = pressure.iter().sum::<f64>() * area;
        if !(normal_force > 0.0) {
            return Err(Error::invalid(
                "pressure",
                "no cell with p > 0",
                "a pressure field with contact (some cell p > 0 MPa)",
            ));
        }
        for (b, p) in self.bound.iter_mut().zip(pressure) {
            *b = mu * p;
        }
        let limit = mu * normal_force;
        match load {
            ShiftLoad::Shift(d) => {
                if !(d[0].is_finite() && d[1].is_finite()) {
                    return Err(Error::invalid(
                        "shift",
                        format!("[{}, {}]", d[0], d[1]),
                        "a finite shift in mm",
                    ));
                }
                let inner = self.inner(d, options);
                Ok(self.solution(d, normal_force, 1, inner, None))
            }
            ShiftLoad::Force(f) => {
                let fm = f[0].hypot(f[1]);
                if !(f[0].is_finite() && f[1].is_finite() && fm < limit) {
                    return Err(Error::invalid(
                        "force",
                        format!("[{}, {}]", f[0], f[1]),
                        format!(
                            "a finite tangential force |F| < mu P = {limit:e} N (at mu P the \
                             contact slides)"
                        ),
                    ));
                }
                self.force_control(f, fm, limit, normal_force, options)
            }
        }
    }

    /// The Illinois iteration on the shift magnitude under force control.
    fn force_control(
        &mut self,
        f: [f64; 2],
        fm: f64,
        limit: f64,
        normal_force: f64,
        options: &ShiftOptions,
    ) -> Result<ShiftSolution> {
        let area = self.grid.cell_area();
        if fm == 0.0 {
            self.reset();
            let inner = self.inner([0.0, 0.0], options);
            return Ok(self.solution([0.0, 0.0], normal_force, 1, inner, Some(0.0)));
        }
        let dir = [f[0] / fm, f[1] / fm];
        let mut total = 0;
        let mut shifts = 0;
        // g(σ) = (force along F) - |F|, increasing in σ; g(0) = -|F|.
        let eval = |s: &mut Self, sigma: f64, total: &mut usize, shifts: &mut usize| {
            let d = [-sigma * dir[0], -sigma * dir[1]];
            let inner = s.inner(d, options);
            *total += inner.iterations;
            *shifts += 1;
            let fx: f64 = s.tau[0].iter().sum::<f64>() * area;
            let fy: f64 = s.tau[1].iter().sum::<f64>() * area;
            (fx * dir[0] + fy * dir[1] - fm, inner)
        };
        // First guess: the mean displacement along F under a uniform traction of total
        // F on the loaded cells (stick would need δ = -u).
        let loaded = self.bound.iter().filter(|b| **b > 0.0).count() as f64;
        let t0 = fm / (loaded * area);
        for (k, t) in self.y.iter_mut().enumerate() {
            for (v, b) in t.iter_mut().zip(&self.bound) {
                *v = if *b > 0.0 { t0 * dir[k] } else { 0.0 };
            }
        }
        {
            let [yx, yy] = &self.y;
            let [ux, uy] = &mut self.u;
            self.op
                .apply(yx, yy, ux, uy)
                .expect("invariant: lengths match the grid");
        }
        let mean: f64 = self
            .bound
            .iter()
            .enumerate()
            .filter(|(_, b)| **b > 0.0)
            .map(|(i, _)| self.u[0][i] * dir[0] + self.u[1][i] * dir[1])
            .sum::<f64>()
            / loaded;
        let mut lo = (0.0, -fm);
        let mut sigma = mean.abs().max(f64::MIN_POSITIVE);
        let (mut g, mut last) = eval(self, sigma, &mut total, &mut shifts);
        // Expand until the force is bracketed.
        while g < 0.0 && shifts < options.max_shifts && last.termination == Termination::Converged {
            lo = (sigma, g);
            sigma *= 2.0;
            (g, last) = eval(self, sigma, &mut total, &mut shifts);
        }
        let mut hi = (sigma, g);
        let mut side = 0i8;
        while (g / limit).abs() > options.force_tolerance
            && shifts < options.max_shifts
            && last.termination == Termination::Converged
        {
            let s = (lo.0 * hi.1 - hi.0 * lo.1) / (hi.1 - lo.1);
            sigma = if s > lo.0 && s < hi.0 {
                s
            } else {
                0.5 * (lo.0 + hi.0)
            };
            (g, last) = eval(self, sigma, &mut total, &mut shifts);
            if g < 0.0 {
                lo = (sigma, g);
                if side == -1 {
                    hi.1 *= 0.5;
                }
                side = -1;
            } else {
                hi = (sigma, g);
                if side == 1 {
                    lo.1 *= 0.5;
                }
                side = 1;
            }
        }
        let force_residual = (g / limit).abs();
        let inner = Inner {
            termination: if last.termination != Termination::Converged {
                last.termination
            } else if force_residual <= options.force_tolerance {
                Termination::Converged
            } else {
                Termination::MaxIterations
            },
            iterations: total,
            residual: last.residual,
        };
        let d = [-sigma * dir[0], -sigma * dir[1]];
        Ok(self.solution(d, normal_force, shifts, inner, Some(force_residual)))
    }

    /// FISTA with gradient restart for the shift `d`, from the stored tractions.
    fn inner(&mut self, d: [f64; 2], options: &ShiftOptions) -> Inner {
        for (r, dk) in self.rigid.iter_mut().zip(d) {
            r.fill(dk);
        }
        self.inner_rigid(d[0].hypot(d[1]), options.tolerance, options.max_iterations)
    }

    /// FISTA with gradient restart for the stored rigid slip `rigid` \[mm\] per cell,
    /// from the stored tractions; `scale` \[mm\] is the slip the tolerance refers to.
    pub(super) fn inner_rigid(
        &mut self,
        scale: f64,
        tolerance: f64,
        max_iterations: usize,
    ) -> Inner {
        let ShiftSolver {
            op,
            bound,
            tau,
            prev,
            y,
            u,
            rigid,
            ..
        } = self;
        if scale == 0.0 {
            for t in tau.iter_mut() {
                t.fill(0.0);
            }
            return Inner {
                termination: Termination::Converged,
                iterations: 0,
                residual: 0.0,
            };
        }
        let step = 1.0 / op.spectral_bound();
        // Start: the stored tractions, projected onto the discs.
        let [tx, ty] = tau;
        for ((x, yv), b) in tx.iter_mut().zip(ty.iter_mut()).zip(bound.iter()) {
            (*x, *yv) = project(*x, *yv, *b);
        }
        for k in 0..2 {
            y[k].copy_from_slice(&tau[k]);
            prev[k].copy_from_slice(&tau[k]);
        }
        let mut theta: f64 = 1.0;
        let mut residual = f64::INFINITY;
        for it in 1..=max_iterations {
            {
                let [yx, yy] = &*y;
                let [ux, uy] = &mut *u;
                op.apply(yx, yy, ux, uy)
                    .expect("invariant: lengths match the grid");
            }
            // τ_new = P(y - step·s), s = u + δ; gradient mapping and restart test.
            let mut gmax: f64 = 0.0;
            let mut restart = 0.0;
            for i in 0..bound.len() {
                let (sx, sy) = (u[0][i] + rigid[0][i], u[1][i] + rigid[1][i]);
                let (zx, zy) = project(y[0][i] - step * sx, y[1][i] - step * sy, bound[i]);
                let (gx, gy) = ((y[0][i] - zx) / step, (y[1][i] - zy) / step);
                gmax = gmax.max(gx.hypot(gy));
                restart += sx * (zx - prev[0][i]) + sy * (zy - prev[1][i]);
                tau[0][i] = zx;
                tau[1][i] = zy;
            }
            residual = gmax / scale;
            if !residual.is_finite() {
                return Inner {
                    termination: Termination::Diverged,
                    iterations: it,
                    residual,
                };
            }
            if residual <= tolerance {
                return Inner {
                    termination: Termination::Converged,
                    iterations: it,
                    residual,
                };
            }
            let beta = if restart > 0.0 {
                theta = 1.0;
                0.0
            } else {
                let next = 0.5 * (1.0 + (1.0 + 4.0 * theta * theta).sqrt());
                let beta = (theta - 1.0) / next;
                theta = next;
                beta
            };
            for k in 0..2 {
                for i in 0..bound.len() {
                    let t = tau[k][i];
                    y[k][i] = t + beta * (t - prev[k][i]);
                    prev[k][i] = t;
                }
            }
        }
        Inner {
            termination: Termination::MaxIterations,
            iterations: max_iterations,
            residual,
        }
    }

    /// Collect the solution for the stored tractions and the shift `d`.
    fn solution(
        &mut self,
        d: [f64; 2],
        normal_force: f64,
        shifts: usize,
        inner: Inner,
        force_residual: Option<f64>,
    ) -> ShiftSolution {
        let area = self.grid.cell_area();
        let n = self.grid.len();
        {
            let [tx, ty] = &self.tau;
            let [ux, uy] = &mut self.u;
            self.op
                .apply(tx, ty, ux, uy)
                .expect("invariant: lengths match the grid");
        }
        let mut state = vec![CellState::Exterior; n];
        let (mut slip_x, mut slip_y) = (vec![0.0; n], vec![0.0; n]);
        let (mut stick_cells, mut slip_cells) = (0, 0);
        for i in 0..n {
            let b = self.bound[i];
            if b <= 0.0 {
                continue;
            }
            let m = self.tau[0][i].hypot(self.tau[1][i]);
            if m >= b * (1.0 - 1e-9) && d != [0.0, 0.0] {
                state[i] = CellState::Slip;
                slip_cells += 1;
                slip_x[i] = self.u[0][i] + d[0];
                slip_y[i] = self.u[1][i] + d[1];
            } else {
                state[i] = CellState::Stick;
                stick_cells += 1;
            }
        }
        let force = [
            self.tau[0].iter().sum::<f64>() * area,
            self.tau[1].iter().sum::<f64>() * area,
        ];
        let residual = match force_residual {
            Some(f) => inner.residual.max(f),
            None => inner.residual,
        };
        ShiftSolution {
            traction_x: self.tau[0].clone(),
            traction_y: self.tau[1].clone(),
            slip_x,
            slip_y,
            state,
            force,
            shift: d,
            normal_force,
            stick_cells,
            slip_cells,
            shifts,
            status: SolveStatus::new(inner.termination, inner.iterations, residual),
        }
    }
}

/// The projection of `(x, y)` \[MPa\] onto the disc of radius `b >= 0`. A component
/// that overflowed to infinity (an absurd but finite shift or creepage) keeps its
/// direction: the result is always finite.
pub(super) fn project(x: f64, y: f64, b: f64) -> (f64, f64) {
    let m = x.hypot(y);
    if m <= b {
        return (x, y);
    }
    if !m.is_finite() {
        let unit = |v: f64| if v.is_infinite() { v.signum() } else { 0.0 };
        let (ux, uy) = (unit(x), unit(y));
        let n = ux.hypot(uy);
        return if n > 0.0 {
            (b * ux / n, b * uy / n)
        } else {
            (0.0, 0.0)
        };
    }
    let f = if m > 0.0 { b / m } else { 0.0 };
    (x * f, y * f)
}
