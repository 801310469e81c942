//! The shift (Cattaneo) problem of dissimilar bodies: normal and tangential contact
//! coupled through Kalker's difference parameter `K`, solved by an outer loop
//! (Kalker's "Panagiotopoulos process", as in Vollebregt's CONTACT).
//!
//! # Formula
//! For bodies of different materials the tangential tractions `τ` \[MPa\] on body 1
//! displace the surfaces normally and the pressure `p` \[MPa\] displaces them
//! tangentially ([`super::CouplingOperator`]):
//!
//! ```text
//! gap:   g = h + C p + A_n τ - δ_n >= 0,   p >= 0,   p g = 0          (normal)
//! slip:  s = Δδ + A τ + A_t p - u'        |τ| <= μ p, Coulomb (§1)   (tangential)
//! ```
//!
//! with `h` the undeformed gap \[mm\], `C` Love's and `A` Cerruti's operators, `A_n` and
//! `A_t = A_nᵀ` (Betti) the coupling, `Δδ` \[mm\] the rigid shift since the previous load step
//! and `u'` \[mm\] the tangential displacement difference at the previous step: the slip
//! is the displacement of body 1 relative to body 2 over one step of a quasi-static
//! loading history (Kalker 1990 §2.2; "shift transient" in CONTACT). The first step
//! starts from the unloaded state (`u' = 0`).
//!
//! **Outer loop.** Starting from the previous step's tractions: (1) the normal problem
//! for the gap `h + A_n τ` (the half-space solver, [`crate::halfspace::HalfSpaceSolver`],
//! warm-started); (2) the tangential problem for that pressure with `A_t p - u' + Δδ` as
//! a per-cell rigid slip (the shift solver's iteration, warm-started); repeated until
//! the change of all tractions `(p, τ)` over one pass is at most `tolerance` times their
//! norm (Euclidean over the cells, as CONTACT's criterion). For `K = 0` the coupling
//! vanishes and one pass is exact. The status reports the outer termination:
//! `MaxIterations` at `max_outer`, `Stagnated` when the change has not reached a new low
//! in `patience` passes, an inner solver's failure as its own termination.
//!
//! # Assumptions
//! Homogeneous, isotropic, linear elastic half-spaces (free boundary), Coulomb friction
//! with one coefficient, quasi-static loading in the steps the caller gives, small
//! displacements (the grid does not move with the bodies).
//!
//! # References
//! - Kalker, *Three-dimensional elastic bodies in rolling contact* (1990), §1.6, §2.2,
//!   §5.3 (Spence's problem as a test case).
//! - Spence (1975), *J. Elasticity* 5, 297-319 (the Hertz contact problem with finite
//!   friction).
//! - Johnson, *Contact Mechanics* (1985), §3.2-3.3, §5.4.
//! - Vollebregt, CONTACT user guide (the Panagiotopoulos process, example
//!   `spence35`).

use super::outer::{CoupledParts, OuterLimits, OuterLoop, combined_constants, run_outer};
use super::shift::{CellState, ShiftLoad, ShiftOptions, ShiftSolver};
use crate::error::{Error, Result};
use crate::geometry::Grid2;
use crate::halfspace::{Control, SolveReport, SolverOptions};
use crate::material::ElasticMaterial;
use crate::solve::{SolveStatus, Termination};
use crate::tangential::KalkerMaterial;
use crate::units::{Millimetre, Newton};

/// Options of [`CoupledShiftSolver`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CoupledOptions {
    /// Outer tolerance: the change of the tractions `(p, τ)` over one pass in the
    /// Euclidean norm over all cells, relative to their norm (as CONTACT's
    /// `|P_k - P_k-1| <= ε |P_k|`). In (0, 1); default 1e-6.
    pub tolerance: f64,
    /// Most outer passes per step, >= 1 (default 30).
    pub max_outer: usize,
    /// Passes without a new lowest change before the loop stops as stagnated, >= 1
    /// (default 5).
    pub patience: usize,
    /// Include the coupling (default `true`). `false` treats the bodies as
    /// quasi-identical (`K = 0`): one pass, normal and tangential problems decoupled.
    pub coupling: bool,
    /// The tangential solver's tolerances (its `tolerance` refers to the largest rigid
    /// slip of the step) and, under force control, its shift iteration.
    pub shift: ShiftOptions,
    /// The normal solver's options (its tolerance should be below `tolerance`; default:
    /// the half-space solver's defaults on one thread, which the tangential solver also
    /// uses).
    pub normal: SolverOptions,
}

impl Default for CoupledOptions {
    fn default() -> Self {
        CoupledOptions {
            tolerance: 1e-6,
            max_outer: 30,
            patience: 5,
            coupling: true,
            shift: ShiftOptions::default(),
            normal: SolverOptions {
                threads: Some(1),
                ..SolverOptions::default()
            },
        }
    }
}

impl CoupledOptions {
    /// Check every option.
    ///
    /// # Errors
    /// [`Error::InvalidInput`] naming the option.
    pub fn validate(&self) -> Result<()> {
        for (name, v) in [
            ("tolerance", self.tolerance),
            ("shift.tolerance", self.shift.tolerance),
            ("shift.force_tolerance", self.shift.force_tolerance),
        ] {
            if !(v.is_finite() && v > 0.0 && v < 1.0) {
                return Err(Error::invalid(name, v, "0 < tolerance < 1"));
            }
        }
        for (name, v) in [
            ("max_outer", self.max_outer),
            ("patience", self.patience),
            ("shift.max_iterations", self.shift.max_iterations),
            ("shift.max_shifts", self.shift.max_shifts),
        ] {
            if v == 0 {
                return Err(Error::invalid(name, v, "at least 1"));
            }
        }
        self.normal.validate()
    }
}

/// The solution of one load step of [`CoupledShiftSolver`].
#[derive(Debug, Clone, PartialEq)]
pub struct CoupledSolution {
    /// Pressure \[MPa\], row-major, x fastest.
    pub pressure: Vec<f64>,
    /// Tractions `τ_x` on body 1 \[MPa\].
    pub traction_x: Vec<f64>,
    /// Tractions `τ_y` on body 1 \[MPa\].
    pub traction_y: Vec<f64>,
    /// Tangential displacement difference `u_x = (A τ + A_t p)_x` \[mm\] (body 1 minus
    /// body 2), including the pressure's part.
    pub displacement_x: Vec<f64>,
    /// Tangential displacement difference `u_y` \[mm\].
    pub displacement_y: Vec<f64>,
    /// The tractions' normal displacement sum `A_n τ` \[mm\] (positive: opens the gap).
    pub coupling_gap: Vec<f64>,
    /// Slip over the step `Δδ + u - u'` \[mm\], x component; zero in stick and exterior
    /// cells.
    pub slip_x: Vec<f64>,
    /// Slip over the step, y component \[mm\].
    pub slip_y: Vec<f64>,
    /// State of each cell (exterior: no pressure).
    pub state: Vec<CellState>,
    /// Total tangential force on body 1 \[N\].
    pub force: [Newton; 2],
    /// Normal force `Σ p ΔA` \[N\].
    pub normal_force: Newton,
    /// Rigid normal approach \[mm\] (from the zero level of the gap `h + A_n τ`).
    pub approach: Millimetre,
    /// The total rigid shift of body 1 \[mm\] (prescribed, or found under force control).
    pub shift: [Millimetre; 2],
    /// Cells with pressure.
    pub contact_cells: usize,
    /// Cells in stick.
    pub stick_cells: usize,
    /// Cells in slip.
    pub slip_cells: usize,
    /// Kalker's difference parameter used (0 when the coupling is off).
    pub difference_parameter: f64,
    /// Inner iterations of the tangential solver (FFT applications) over all passes.
    pub tangential_iterations: usize,
    /// The last normal solve's report.
    pub normal_report: SolveReport,
    /// The outer loop: termination, passes, and the last relative change (0 after the
    /// single pass of uncoupled bodies; when an inner solver failed, its residual).
    pub status: SolveStatus,
}

/// Load steps of the shift problem of two (possibly dissimilar) bodies on one grid, with
/// the normal problem solved in the same loop (see the module docs). Keeps the previous
/// step's displacements: call [`CoupledShiftSolver::step`] along a loading history, and
/// [`CoupledShiftSolver::reset`] to start again from the unloaded state.
#[derive(Debug)]
pub struct CoupledShiftSolver {
    grid: Grid2,
    options: CoupledOptions,
    k: f64,
    tang: ShiftSolver,
    /// The normal solver, the coupling operator and the outer loop's work arrays.
    outer: OuterLoop,
    /// Tangential displacement difference at the end of the previous step \[mm\].
    prev_u: [Vec<f64>; 2],
    prev_shift: [f64; 2],
    /// The per-cell base slip `A_t p − u'` \[mm\] of the pass.
    base: [Vec<f64>; 2],
    /// The last tangential solve's relative residual.
    inner_residual: f64,
}

impl CoupledParts for CoupledShiftSolver {
    fn parts(&mut self) -> (&mut OuterLoop, [&[f64]; 2]) {
        let [tx, ty] = &self.tang.tau;
        (&mut self.outer, [tx, ty])
    }
}

impl CoupledShiftSolver {
    /// A solver for `grid` \[mm\], body 1 and body 2 (body 1 carries the tractions
    /// `τ`; either may be rigid, not both) and `options`.
    ///
    /// # Errors
    /// [`Error::InvalidInput`] for two rigid bodies or options out of range.
    pub fn new(
        grid: &Grid2,
        body1: &ElasticMaterial,
        body2: &ElasticMaterial,
        options: CoupledOptions,
    ) -> Result<Self> {
        options.validate()?;
        let (material, k) = combined_constants(body1, body2, options.coupling)?;
        Self::from_constants(grid, material, k, options)
    }

    /// A solver from Kalker's combined constants `material` and difference parameter
    /// `k` (`|K| <= 0.5`) directly.
    ///
    /// # Errors
    /// [`Error::InvalidInput`] for constants or options out of range.
    pub fn from_constants(
        grid: &Grid2,
        material: KalkerMaterial,
        k: f64,
        options: CoupledOptions,
    ) -> Result<Self> {
        options.validate()?;
        let (k, outer) = OuterLoop::new(grid, material, k, options.coupling, options.normal)?;
        let tang = ShiftSolver::new(grid, material, options.normal.threads)?;
        let n = grid.len();
        let z2 = || [vec![0.0; n], vec![0.0; n]];
        Ok(CoupledShiftSolver {
            grid: *grid,
            options,
            k,
            tang,
            outer,
            prev_u: z2(),
            prev_shift: [0.0; 2],
            base: z2(),
            inner_residual: 0.0,
        })
    }

    /// Kalker's difference parameter in use (0 with the coupling off).
    pub fn difference_parameter(&self) -> f64 {
        self.k
    }

    /// Forget the loading history: the next step starts from the unloaded state.
    pub fn reset(&mut self) {
        self.tang.reset();
        for v in self.prev_u.iter_mut() {
            v.fill(0.0);
        }
        self.prev_shift = [0.0; 2];
    }

    /// One load step: the undeformed gap `gap` \[mm\] (row-major, x fastest; `+inf`
    /// where the bodies cannot meet), the normal `control` (force \[N\] or approach
    /// \[mm\]), the friction coefficient `mu` and the tangential `load` (the total rigid
    /// shift \[mm\] or total tangential force \[N\] on body 1 at the end of the step).
    /// The slip is measured from the previous step (or the unloaded state).
    ///
    /// Not converging is not an error: see the solution's `status`.
    ///
    /// # Errors
    /// [`Error::InvalidInput`] for a gap of the wrong length or NaN, a normal load not
    /// finite and > 0, `mu` not finite and > 0, a shift or force not finite, a force
    /// `|F| >= μ P`; [`Error::Geometry`] when the bodies do not touch.
    pub fn step(
        &mut self,
        gap: &[f64],
        control: Control,
        mu: f64,
        load: ShiftLoad,
    ) -> Result<CoupledSolution> {
        crate::tangential::check_friction(mu)?;
        match load {
            ShiftLoad::Shift(d) if !(d[0].is_finite() && d[1].is_finite()) => {
                return Err(Error::invalid(
                    "shift",
                    format!("[{}, {}]", d[0], d[1]),
                    "a finite shift in mm",
                ));
            }
            ShiftLoad::Force(f) if !(f[0].is_finite() && f[1].is_finite()) => {
                return Err(Error::invalid(
                    "force",
                    format!("[{}, {}]", f[0], f[1]),
                    "a finite tangential force in N",
                ));
            }
            _ => {}
        }
        OuterLoop::check_gap(&self.grid, gap)?;
        let opts = self.options;
        let limits = OuterLimits {
            tolerance: opts.tolerance,
            patience: opts.patience,
            max_outer: opts.max_outer,
        };
        let area = self.grid.cell_area();
        let mut shift = self.prev_shift;
        let mut tang_iters = 0;
        let (report, status) = run_outer(self, gap, control, limits, |s| {
            // (2) The tangential problem for this pressure.
            s.outer.pressure_displacement()?;
            let p = s.outer.normal.pressure();
            let normal_force = p.iter().sum::<f64>() * area;
            for (b, pv) in s.tang.bound.iter_mut().zip(p) {
                *b = mu * pv;
            }
            for k in 0..2 {
                for ((b, up), u0) in s.base[k].iter_mut().zip(&s.outer.up[k]).zip(&s.prev_u[k]) {
                    *b = up - u0;
                }
            }
            let inner = match load {
                ShiftLoad::Shift(d) => {
                    shift = d;
                    let dd = [d[0] - s.prev_shift[0], d[1] - s.prev_shift[1]];
                    s.tangential(dd)
                }
                ShiftLoad::Force(f) => {
                    let limit = mu * normal_force;
                    let fm = f[0].hypot(f[1]);
                    if !(fm < limit) {
                        return Err(Error::invalid(
                            "force",
                            format!("[{}, {}]", f[0], f[1]),
                            format!(
                                "|F| < mu P = {limit:e} N (at mu P the contact slides and \
                                 the shift is undetermined)"
                            ),
                        ));
                    }
                    let (dd, inner) = s.force_control(f, limit);
                    shift = [s.prev_shift[0] + dd[0], s.prev_shift[1] + dd[1]];
                    inner
                }
            };
            tang_iters += inner.1;
            Ok((inner.0 != Termination::Converged).then_some((inner.0, s.inner_residual)))
        })?;
        Ok(self.finish(shift, mu, tang_iters, report, status))
    }

    /// The tangential solve for the shift increment `dd` \[mm\] on top of the stored
    /// per-cell base slip; returns the inner termination and iterations.
    fn tangential(&mut self, dd: [f64; 2]) -> (Termination, usize) {
        let mut scale: f64 = 0.0;
        for i in 0..self.grid.len() {
            let (rx, ry) = (self.base[0][i] + dd[0], self.base[1][i] + dd[1]);
            self.tang.rigid[0][i] = rx;
            self.tang.rigid[1][i] = ry;
            if self.tang.bound[i] > 0.0 {
                scale = scale.max(rx.hypot(ry));
            }
        }
        let o = self.options.shift;
        let inner = self.tang.inner_rigid(scale, o.tolerance, o.max_iterations);
        self.inner_residual = inner.residual;
        (inner.termination, inner.iterations)
    }

    /// Force control: the shift increment `-σ F̂` with `σ` by the Illinois method on
    /// `F̂·ΣτΔA = |F|` (monotone in `σ`), bracketed by doubling steps away from `σ = 0`.
    /// `F = 0` is sought along `x`. Returns the increment, the termination and the inner
    /// iterations.
    fn force_control(&mut self, f: [f64; 2], limit: f64) -> ([f64; 2], (Termination, usize)) {
        let o = self.options.shift;
        let area = self.grid.cell_area();
        let fm = f[0].hypot(f[1]);
        let dir = if fm > 0.0 {
            [f[0] / fm, f[1] / fm]
        } else {
            [1.0, 0.0]
        };
        let shift_of = |sigma: f64| [-sigma * dir[0], -sigma * dir[1]];
        let mut total = 0;
        let mut evals = 0;
        // g(σ) = (force along F̂) - |F| and the inner termination.
        let mut eval = |s: &mut Self, sigma: f64, total: &mut usize| {
            let (term, it) = s.tangential(shift_of(sigma));
            *total += it;
            evals += 1;
            let fx: f64 = s.tang.tau[0].iter().sum::<f64>() * area;
            let fy: f64 = s.tang.tau[1].iter().sum::<f64>() * area;
            (fx * dir[0] + fy * dir[1] - fm, term, evals)
        };
        // Step scale: the largest compliance times the mean traction μP/area of the
        // loaded cells (an over-estimate of the shift that saturates the contact).
        let loaded = self.tang.bound.iter().filter(|b| **b > 0.0).count().max(1) as f64;
        let h = self.tang.operator().spectral_bound() * limit / (loaded * area);
        let (g0, t0, _) = eval(self, 0.0, &mut total);
        if (g0 / limit).abs() <= o.force_tolerance || t0 != Termination::Converged {
            return ([0.0; 2], (t0, total));
        }
        let sign = if g0 < 0.0 { 1.0 } else { -1.0 };
        let mut step = h;
        let mut prev = (0.0, g0);
        let mut sigma;
        let mut g;
        loop {
            sigma = sign * step;
            let (gv, term, k) = eval(self, sigma, &mut total);
            g = gv;
            if term != Termination::Converged {
                return (shift_of(sigma), (term, total));
            }
            if (g < 0.0) != (g0 < 0.0) {
                break;
            }
            if k >= o.max_shifts {
                return (shift_of(sigma), (Termination::MaxIterations, total));
            }
            prev = (sigma, g);
            step *= 2.0;
        }
        let (mut lo, mut hi) = if g0 < 0.0 {
            (prev, (sigma, g))
        } else {
            ((sigma, g), prev)
        };
        let mut side = 0i8;
        let mut k = 0;
        while (g / limit).abs() > o.force_tolerance {
            if k >= o.max_shifts {
                return (shift_of(sigma), (Termination::MaxIterations, total));
            }
            let s = (lo.0 * hi.1 - hi.0 * lo.1) / (hi.1 - lo.1);
            sigma = if s > lo.0 && s < hi.0 {
                s
            } else {
                0.5 * (lo.0 + hi.0)
            };
            let (gv, term, kk) = eval(self, sigma, &mut total);
            g = gv;
            k = kk;
            if term != Termination::Converged {
                return (shift_of(sigma), (term, total));
            }
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
        (shift_of(sigma), (Termination::Converged, total))
    }

    /// Collect the solution and store the step's displacements as the next step's
    /// history.
    fn finish(
        &mut self,
        shift: [f64; 2],
        mu: f64,
        tangential_iterations: usize,
        report: SolveReport,
        status: SolveStatus,
    ) -> CoupledSolution {
        let n = self.grid.len();
        let area = self.grid.cell_area();
        let p = self.outer.normal.pressure().to_vec();
        // u = A τ + A_t p.
        let mut u = [vec![0.0; n], vec![0.0; n]];
        self.tang
            .displacements(&mut u)
            .expect("invariant: lengths match the grid");
        let [tx, ty] = &self.tang.tau;
        let coupling_gap = self.outer.final_fields([tx, ty]);
        if self.outer.cross.is_some() {
            for (uk, upk) in u.iter_mut().zip(&self.outer.up) {
                for (a, b) in uk.iter_mut().zip(upk) {
                    *a += b;
                }
            }
        }
        let dd = [shift[0] - self.prev_shift[0], shift[1] - self.prev_shift[1]];
        let mut state = vec![CellState::Exterior; n];
        let (mut slip_x, mut slip_y) = (vec![0.0; n], vec![0.0; n]);
        let (mut stick_cells, mut slip_cells, mut contact_cells) = (0, 0, 0);
        for i in 0..n {
            let b = mu * p[i];
            if b <= 0.0 {
                continue;
            }
            contact_cells += 1;
            let m = self.tang.tau[0][i].hypot(self.tang.tau[1][i]);
            let sx = dd[0] + u[0][i] - self.prev_u[0][i];
            let sy = dd[1] + u[1][i] - self.prev_u[1][i];
            if m >= b * (1.0 - 1e-9) && (sx != 0.0 || sy != 0.0) {
                state[i] = CellState::Slip;
                slip_cells += 1;
                slip_x[i] = sx;
                slip_y[i] = sy;
            } else {
                state[i] = CellState::Stick;
                stick_cells += 1;
            }
        }
        let force = [
            self.tang.tau[0].iter().sum::<f64>() * area,
            self.tang.tau[1].iter().sum::<f64>() * area,
        ];
        for (prev, uk) in self.prev_u.iter_mut().zip(&u) {
            prev.copy_from_slice(uk);
        }
        self.prev_shift = shift;
        let [ux, uy] = u;
        CoupledSolution {
            normal_force: p.iter().sum::<f64>() * area,
            pressure: p,
            traction_x: self.tang.tau[0].clone(),
            traction_y: self.tang.tau[1].clone(),
            displacement_x: ux,
            displacement_y: uy,
            coupling_gap,
            slip_x,
            slip_y,
            state,
            force,
            approach: report.approach,
            shift,
            contact_cells,
            stick_cells,
            slip_cells,
            difference_parameter: self.k,
            tangential_iterations,
            normal_report: report,
            status,
        }
    }
}
