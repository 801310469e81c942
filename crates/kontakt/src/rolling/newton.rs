//! The fast solver of the steady rolling equations: a semismooth Newton method on the
//! projection form of Coulomb's law, each linear system by restarted GMRES with the FFT
//! operator as its product and the exact line blocks (grid rows along the rolling
//! direction) of the Jacobian as its preconditioner.
//!
//! # Formula
//! Unknowns: the tractions `τ_i` \[MPa\] of the loaded cells (`g_i = μ p_i > 0`). With the
//! upwind difference (rolling step one cell) the slip distance per cell is
//!
//! ```text
//! s_i = ω_i dx + u_i − u_{i+1},   u = A τ,   i.e.  s = ω dx + B τ,  B = (I − S) A,
//! ```
//!
//! `S` the shift by one cell in `+x`. Coulomb's law is the fixed point of the projection
//! onto each cell's disc `|τ_i| <= g_i`, with a scalar `r` \[MPa/mm\]:
//!
//! ```text
//! F_i(τ) = τ_i − P_i(z_i) = 0,   z_i = τ_i − r s_i.
//! ```
//!
//! Stick (`|z_i| <= g_i`): `F_i = r s_i`; slip: `F_i = τ_i − g_i z_i/|z_i|`. A generalised
//! Jacobian, with `κ_i = g_i/|z_i| < 1`, `n_i = z_i/|z_i|`, `Π_i = I − n_i n_iᵀ`:
//!
//! ```text
//! stick:  dF_i = r (B dτ)_i
//! slip:   dF_i = (I − κ_i Π_i) dτ_i + κ_i r Π_i (B dτ)_i
//! ```
//!
//! `r = 1/b(0)` with `b(0)` the mean diagonal of `B` (`A(0, 0) − A(1, 0)`, `xx` and `yy`),
//! so `r s` is a traction of the size of `τ`.
//!
//! **Linear systems.** `J Δ = −F` by GMRES(m) with right preconditioning (Saad & Schultz
//! 1986). The product `J v` costs one FFT application of `A`. The preconditioner is the
//! block diagonal of `J` over grid rows: within a row `A_xy` vanishes (it is odd in `y`)
//! and `B` couples the cells of the row through `b(m) = A(m, 0) − A(m + 1, 0)`; each row's
//! block (`2 n_row` square) is factorised by LU with partial pivoting (renewed only when a
//! tenth of the row's cells changed between stick and slip). It captures the
//! rolling direction exactly (the upwind difference and its downstream tail, which made a
//! point Gauss-Seidel sweep diverge); only the coupling between rows is left to GMRES.
//! Inexact Newton: each GMRES solve to the relative tolerance
//! `η = min(0.1, max(ρ, 0.1 tol/ρ))`, `ρ` the current residual.
//!
//! **Globalisation.** Backtracking on `|F|₂` (halving the step, at most 6 times; the
//! last trial is taken if none decreases, so a cycling active set still ends at the
//! iteration limit rather than stalling).
//!
//! **Convergence criterion.** `max_i |F_i| / (r · max_i |ω_i| dx) <= tol`: in a stick cell
//! the slip, in a slip cell the traction's distance from `g n` expressed as a slip, each
//! relative to the largest rigid slip; the same measure as the marching solver's.
//!
//! # References
//! Alart & Curnier (1991) and Qi & Sun (1993) for the semismooth Newton method on the
//! projection form of frictional contact; Saad & Schultz (1986) for GMRES; Eisenstat &
//! Walker (1996) for the forcing terms; Kalker (1990) ch. 5 for the discretisation.

use super::influence::cerruti;
use super::shift::project;
use super::steady_fft::SteadyFft;
use crate::solve::Termination;

/// The Krylov dimension of the restarted GMRES.
const RESTART: usize = 40;

/// A row's factorisation is renewed when more than `1/REFACTOR_SHARE` of its cells
/// changed between stick and slip since it was factorised.
const REFACTOR_SHARE: usize = 10;

/// Most halvings of the Newton step in the line search.
const MAX_HALVINGS: usize = 6;

/// Limits and the tolerance of one Newton solve.
pub(super) struct NewtonSettings {
    /// Relative tolerance on the residual (see the module docs).
    pub(super) tolerance: f64,
    /// Most Newton iterations.
    pub(super) max_newton: usize,
    /// Most FFT applications of `A` in all.
    pub(super) max_fft: usize,
}

/// The outcome of one Newton solve.
#[derive(Debug, Clone, Copy)]
pub(super) struct NewtonOutcome {
    pub(super) termination: Termination,
    /// Newton iterations.
    pub(super) newton: usize,
    /// FFT applications of `A` (residuals and GMRES products).
    pub(super) fft: usize,
    /// GMRES iterations.
    pub(super) gmres: usize,
    /// The final relative residual.
    pub(super) residual: f64,
}

/// Work arrays of the Newton solver on one grid.
#[derive(Debug)]
pub(super) struct SteadyNewton {
    nx: usize,
    /// `B = (I − S) A` by FFT.
    op: SteadyFft,
    /// `b(m) = A(m, 0) − A(m + 1, 0)` for `xx` and `yy` \[mm/MPa\], index `m + nx`.
    bx: Vec<f64>,
    by: Vec<f64>,
    r: f64,
    /// Grid index of each unknown cell, row-major.
    cells: Vec<usize>,
    /// First unknown cell of each grid row (`ny + 1` entries).
    row_start: Vec<usize>,
    /// Offset of each row's LU block (`ny + 1` entries).
    blk_off: Vec<usize>,
    /// The row blocks' LU factors, in single precision (see [`Self::factor`]).
    lu: Vec<f32>,
    piv: Vec<usize>,
    /// One row block in double precision while it is built and factorised.
    block: Vec<f64>,
    /// One row's part of a vector in single precision (the preconditioner's solve).
    row32: Vec<f32>,
    /// The slip flag of each cell when its row was last factorised, and whether that
    /// factorisation is valid for the current cells.
    factored_slip: Vec<bool>,
    row_valid: Vec<bool>,
    /// The unknown cells of the previous solve (the factorisations are kept when the
    /// cells and bounds are unchanged).
    last_cells: Vec<usize>,
    /// Rows factorised (a count for the statistics).
    factorisations: usize,
    /// Per unknown cell: bound, slip flag, κ and n of the linearisation.
    g: Vec<f64>,
    slip: Vec<bool>,
    kappa: Vec<f64>,
    normal: Vec<[f64; 2]>,
    /// Vectors of length `2 N`, `[τ_x, τ_y]` per cell.
    rigid: Vec<f64>,
    tau: Vec<f64>,
    s: Vec<f64>,
    f: Vec<f64>,
    delta: Vec<f64>,
    trial: Vec<f64>,
    s_trial: Vec<f64>,
    f_trial: Vec<f64>,
    w: Vec<f64>,
    z: Vec<f64>,
    /// GMRES: basis `(m + 1) × 2N`, Hessenberg `(m + 1) × m`, rotations, right side.
    basis: Vec<f64>,
    /// The preconditioned vectors `z_j = M⁻¹ v_j` and their products `B z_j`.
    zbasis: Vec<f64>,
    bzbasis: Vec<f64>,
    /// `B Δ` of the last GMRES solution.
    bdelta: Vec<f64>,
    hess: Vec<f64>,
    cs: Vec<f64>,
    sn: Vec<f64>,
    gv: Vec<f64>,
    yv: Vec<f64>,
    /// Grid fields for the FFT product.
    grid_t: [Vec<f64>; 2],
    grid_u: [Vec<f64>; 2],
}

impl SteadyNewton {
    /// Work arrays for `nx × ny` cells of `dx × dy` \[mm\] and Kalker's combined `g`
    /// \[MPa\], `nu`.
    pub(super) fn new(nx: usize, ny: usize, dx: f64, dy: f64, g: f64, nu: f64) -> Self {
        let a = |m: isize| cerruti(m as f64 * dx, 0.0, dx, dy, g, nu);
        let (mut bx, mut by) = (vec![0.0; 2 * nx + 1], vec![0.0; 2 * nx + 1]);
        for k in 0..=2 * nx {
            let m = k as isize - nx as isize;
            let (c0, c1) = (a(m), a(m + 1));
            bx[k] = c0.xx - c1.xx;
            by[k] = c0.yy - c1.yy;
        }
        let r = 2.0 / (bx[nx] + by[nx]);
        let n = nx * ny;
        SteadyNewton {
            nx,
            op: SteadyFft::new(nx, ny, dx, dy, g, nu),
            bx,
            by,
            r,
            cells: Vec::with_capacity(n),
            row_start: vec![0; ny + 1],
            blk_off: vec![0; ny + 1],
            lu: Vec::new(),
            piv: Vec::new(),
            block: Vec::new(),
            row32: Vec::new(),
            factored_slip: Vec::with_capacity(n),
            row_valid: vec![false; ny],
            last_cells: Vec::with_capacity(n),
            factorisations: 0,
            g: Vec::with_capacity(n),
            slip: Vec::with_capacity(n),
            kappa: Vec::with_capacity(n),
            normal: Vec::with_capacity(n),
            rigid: Vec::new(),
            tau: Vec::new(),
            s: Vec::new(),
            f: Vec::new(),
            delta: Vec::new(),
            trial: Vec::new(),
            s_trial: Vec::new(),
            f_trial: Vec::new(),
            w: Vec::new(),
            z: Vec::new(),
            basis: Vec::new(),
            zbasis: Vec::new(),
            bzbasis: Vec::new(),
            bdelta: Vec::new(),
            hess: vec![0.0; (RESTART + 1) * RESTART],
            cs: vec![0.0; RESTART],
            sn: vec![0.0; RESTART],
            gv: vec![0.0; RESTART + 1],
            yv: vec![0.0; RESTART],
            grid_t: [vec![0.0; n], vec![0.0; n]],
            grid_u: [vec![0.0; n], vec![0.0; n]],
        }
    }

    /// Solve the steady equations for the bounds `bound` \[MPa\] (`μ p` per grid cell),
    /// the rigid slip `rigid(c)` = `ω dx` \[mm\] of grid cell `c`, from the tractions in
    /// `tau` (grid fields, the warm start), which receive the solution. `slip` receives
    /// the slip distance `s` \[mm\] of every loaded cell (0 elsewhere). `scale` \[mm\] is
    /// `max |ω| dx > 0`.
    #[allow(clippy::too_many_arguments)]
    pub(super) fn solve(
        &mut self,
        bound: &[f64],
        rigid: impl Fn(usize) -> [f64; 2],
        tau: &mut [Vec<f64>; 2],
        slip: &mut [Vec<f64>; 2],
        scale: f64,
        settings: &NewtonSettings,
    ) -> NewtonOutcome {
        let nx = self.nx;
        let ny = self.row_start.len() - 1;
        // The unknown cells, row by row, and the vectors' sizes (growing only).
        self.cells.clear();
        for j in 0..ny {
            self.row_start[j] = self.cells.len();
            self.blk_off[j] = 0;
            for i in 0..nx {
                if bound[j * nx + i] > 0.0 {
                    self.cells.push(j * nx + i);
                }
            }
        }
        self.row_start[ny] = self.cells.len();
        let mut off = 0;
        for j in 0..ny {
            self.blk_off[j] = off;
            let m = 2 * (self.row_start[j + 1] - self.row_start[j]);
            off += m * m;
        }
        self.blk_off[ny] = off;
        if self.lu.len() < off {
            self.lu.resize(off, 0.0);
        }
        let nc = self.cells.len();
        let len = 2 * nc;
        for v in [
            &mut self.rigid,
            &mut self.tau,
            &mut self.s,
            &mut self.f,
            &mut self.delta,
            &mut self.trial,
            &mut self.s_trial,
            &mut self.f_trial,
            &mut self.w,
            &mut self.z,
            &mut self.bdelta,
        ] {
            v.resize(len, 0.0);
        }
        if self.piv.len() < len {
            self.piv.resize(len, 0);
        }
        // The longest row's block and vector (grow only).
        let widest = (0..ny)
            .map(|j| 2 * (self.row_start[j + 1] - self.row_start[j]))
            .max()
            .unwrap_or(0);
        if self.block.len() < widest * widest {
            self.block.resize(widest * widest, 0.0);
        }
        if self.row32.len() < widest {
            self.row32.resize(widest, 0.0);
        }
        for b in [&mut self.basis, &mut self.zbasis, &mut self.bzbasis] {
            if b.len() < (RESTART + 1) * len {
                b.resize((RESTART + 1) * len, 0.0);
            }
        }
        self.g.clear();
        self.slip.clear();
        self.kappa.clear();
        self.normal.clear();
        for (k, &c) in self.cells.iter().enumerate() {
            let b = bound[c];
            self.g.push(b);
            self.slip.push(false);
            self.kappa.push(0.0);
            self.normal.push([0.0, 0.0]);
            let w = rigid(c);
            self.rigid[2 * k] = w[0];
            self.rigid[2 * k + 1] = w[1];
            let (tx, ty) = project(tau[0][c], tau[1][c], b);
            self.tau[2 * k] = tx;
            self.tau[2 * k + 1] = ty;
        }
        for f in self.grid_t.iter_mut() {
            f.fill(0.0);
        }
        // Keep the row factorisations while the loaded cells are the same.
        if self.cells != self.last_cells {
            self.row_valid.fill(false);
            self.last_cells.clear();
            self.last_cells.extend_from_slice(&self.cells);
            self.factored_slip.clear();
            self.factored_slip.resize(nc, false);
        }
        self.factorisations = 0;
        let mut fft = 0;
        let mut gmres_total = 0;
        let norm_scale = 1.0 / (self.r * scale);
        // F at the start.
        fft += 1;
        let mut residual = self.evaluate(false) * norm_scale;
        let mut merit = norm2(&self.f);
        let mut newton = 0;
        let termination = loop {
            if !residual.is_finite() {
                break Termination::Diverged;
            }
            if residual <= settings.tolerance {
                break Termination::Converged;
            }
            if newton >= settings.max_newton || fft >= settings.max_fft {
                break Termination::MaxIterations;
            }
            newton += 1;
            self.linearise();
            self.factor();
            // -F as the right side; GMRES for J Δ = -F.
            let eta = 0.1f64.min(residual.max(0.1 * settings.tolerance / residual));
            let budget = settings.max_fft.saturating_sub(fft).max(1);
            let (its, products) = self.gmres(eta, budget);
            gmres_total += its;
            fft += products;
            // Backtracking on |F|.
            let mut alpha = 1.0;
            let mut accepted = false;
            for halving in 0..=MAX_HALVINGS {
                // s is linear in τ: s(τ + αΔ) = s + α BΔ, no FFT.
                for k in 0..len {
                    self.trial[k] = self.tau[k] + alpha * self.delta[k];
                    self.s_trial[k] = self.s[k] + alpha * self.bdelta[k];
                }
                let r = self.residual_of(true);
                let m = norm2(&self.f_trial);
                if m <= (1.0 - 1e-4 * alpha) * merit || halving == MAX_HALVINGS || !m.is_finite() {
                    std::mem::swap(&mut self.tau, &mut self.trial);
                    std::mem::swap(&mut self.s, &mut self.s_trial);
                    std::mem::swap(&mut self.f, &mut self.f_trial);
                    residual = r * norm_scale;
                    merit = m;
                    accepted = true;
                    break;
                }
                alpha *= 0.5;
            }
            debug_assert!(accepted);
            if residual <= settings.tolerance {
                // Confirm with the slip evaluated afresh (the updates accumulate
                // round-off).
                fft += 1;
                residual = self.evaluate(false) * norm_scale;
                merit = norm2(&self.f);
            }
        };
        // The last projection τ ← P(τ − r s) = τ − F: slip cells exactly on their disc.
        for v in slip.iter_mut() {
            v.fill(0.0);
        }
        for t in tau.iter_mut() {
            t.fill(0.0);
        }
        for (k, &c) in self.cells.iter().enumerate() {
            let (fx, fy) = (self.f[2 * k], self.f[2 * k + 1]);
            let (tx, ty) = project(self.tau[2 * k] - fx, self.tau[2 * k + 1] - fy, self.g[k]);
            tau[0][c] = tx;
            tau[1][c] = ty;
            slip[0][c] = self.s[2 * k];
            slip[1][c] = self.s[2 * k + 1];
        }
        NewtonOutcome {
            termination,
            newton,
            fft,
            gmres: gmres_total,
            residual,
        }
    }

    /// `out = B v` (one FFT application).
    fn apply_b(
        op: &mut SteadyFft,
        cells: &[usize],
        grid_t: &mut [Vec<f64>; 2],
        grid_u: &mut [Vec<f64>; 2],
        v: &[f64],
        out: &mut [f64],
    ) {
        for (k, &c) in cells.iter().enumerate() {
            grid_t[0][c] = v[2 * k];
            grid_t[1][c] = v[2 * k + 1];
        }
        let [tx, ty] = &*grid_t;
        let [ux, uy] = grid_u;
        op.apply([tx, ty], [ux, uy]);
        for (k, &c) in cells.iter().enumerate() {
            out[2 * k] = ux[c];
            out[2 * k + 1] = uy[c];
        }
    }

    /// `s = ω dx + B τ` and `F(τ)` at `τ` (or at the trial point into the trial
    /// arrays); returns `max_i |F_i|`.
    fn evaluate(&mut self, trial: bool) -> f64 {
        let (tau, mut s, mut f) = if trial {
            (
                std::mem::take(&mut self.trial),
                std::mem::take(&mut self.s_trial),
                std::mem::take(&mut self.f_trial),
            )
        } else {
            (
                std::mem::take(&mut self.tau),
                std::mem::take(&mut self.s),
                std::mem::take(&mut self.f),
            )
        };
        let worst = self.evaluate_into(&tau, &mut s, &mut f);
        if trial {
            (self.trial, self.s_trial, self.f_trial) = (tau, s, f);
        } else {
            (self.tau, self.s, self.f) = (tau, s, f);
        }
        worst
    }

    fn evaluate_into(&mut self, tau: &[f64], s: &mut [f64], f: &mut [f64]) -> f64 {
        Self::apply_b(
            &mut self.op,
            &self.cells,
            &mut self.grid_t,
            &mut self.grid_u,
            tau,
            s,
        );
        for (a, w) in s.iter_mut().zip(&self.rigid) {
            *a += w;
        }
        self.residual_into(tau, s, f)
    }

    /// `F` at `τ` (or the trial point) from the stored `s`; returns `max_i |F_i|`.
    fn residual_of(&mut self, trial: bool) -> f64 {
        let (tau, s, mut f) = if trial {
            (
                std::mem::take(&mut self.trial),
                std::mem::take(&mut self.s_trial),
                std::mem::take(&mut self.f_trial),
            )
        } else {
            (
                std::mem::take(&mut self.tau),
                std::mem::take(&mut self.s),
                std::mem::take(&mut self.f),
            )
        };
        let worst = self.residual_into(&tau, &s, &mut f);
        if trial {
            (self.trial, self.s_trial, self.f_trial) = (tau, s, f);
        } else {
            (self.tau, self.s, self.f) = (tau, s, f);
        }
        worst
    }

    fn residual_into(&self, tau: &[f64], s: &[f64], f: &mut [f64]) -> f64 {
        let r = self.r;
        let mut worst: f64 = 0.0;
        for k in 0..self.cells.len() {
            let (sx, sy) = (s[2 * k], s[2 * k + 1]);
            let (tx, ty) = (tau[2 * k], tau[2 * k + 1]);
            let (px, py) = fast_project(tx - r * sx, ty - r * sy, self.g[k]);
            let (fx, fy) = (tx - px, ty - py);
            f[2 * k] = fx;
            f[2 * k + 1] = fy;
            worst = worst.max(fx * fx + fy * fy);
        }
        worst.sqrt()
    }

    /// The linearisation at the current `τ`, `s`: slip flags, `κ` and `n` per cell.
    fn linearise(&mut self) {
        let r = self.r;
        for k in 0..self.cells.len() {
            let zx = self.tau[2 * k] - r * self.s[2 * k];
            let zy = self.tau[2 * k + 1] - r * self.s[2 * k + 1];
            let m = (zx * zx + zy * zy).sqrt();
            let g = self.g[k];
            if m <= g {
                self.slip[k] = false;
            } else {
                self.slip[k] = true;
                let (nx_, ny_) = fast_project(zx, zy, 1.0);
                self.normal[k] = [nx_, ny_];
                self.kappa[k] = if m.is_finite() { g / m } else { 0.0 };
            }
        }
    }

    /// `out = J v` from `bv = B v` (per cell).
    fn jacobian_rows(&self, v: &[f64], bv: &[f64], out: &mut [f64]) {
        let r = self.r;
        for k in 0..self.cells.len() {
            let (wx, wy) = (bv[2 * k], bv[2 * k + 1]);
            if self.slip[k] {
                let [n0, n1] = self.normal[k];
                let kap = self.kappa[k];
                let (vx, vy) = (v[2 * k], v[2 * k + 1]);
                // Π a = a − n (n·a).
                let pv = n0 * vx + n1 * vy;
                let pw = n0 * wx + n1 * wy;
                let (pvx, pvy) = (vx - n0 * pv, vy - n1 * pv);
                let (pwx, pwy) = (wx - n0 * pw, wy - n1 * pw);
                out[2 * k] = vx - kap * pvx + kap * r * pwx;
                out[2 * k + 1] = vy - kap * pvy + kap * r * pwy;
            } else {
                out[2 * k] = r * wx;
                out[2 * k + 1] = r * wy;
            }
        }
    }

    /// Factorise the row blocks of the Jacobian (LU with partial pivoting) where more
    /// than `1/REFACTOR_SHARE` of the row's cells changed between stick and slip since
    /// its last factorisation (or the loaded cells changed). The other rows keep their
    /// factors and old slip directions: a preconditioner need not be exact, and the
    /// factorisations, `O(n_row³)` each, would otherwise dominate the cost.
    fn factor(&mut self) {
        let nx = self.nx;
        let r = self.r;
        let ny = self.row_start.len() - 1;
        for j in 0..ny {
            let (c0, c1) = (self.row_start[j], self.row_start[j + 1]);
            let nr = c1 - c0;
            if nr == 0 {
                continue;
            }
            let changed = (c0..c1)
                .filter(|&k| self.slip[k] != self.factored_slip[k])
                .count();
            let stale = !self.row_valid[j] || changed * REFACTOR_SHARE > nr;
            if !stale {
                continue;
            }
            self.row_valid[j] = true;
            self.factorisations += 1;
            for k in c0..c1 {
                self.factored_slip[k] = self.slip[k];
            }
            let m = 2 * nr;
            let blk = &mut self.block[..m * m];
            blk.fill(0.0);
            for p in 0..nr {
                let cp = c0 + p;
                let ip = self.cells[cp] % nx;
                let (row0, row1) = (2 * p * m, (2 * p + 1) * m);
                if self.slip[cp] {
                    let [n0, n1] = self.normal[cp];
                    let kap = self.kappa[cp];
                    let pi = [[1.0 - n0 * n0, -n0 * n1], [-n0 * n1, 1.0 - n1 * n1]];
                    for q in 0..nr {
                        let iq = self.cells[c0 + q] % nx;
                        let d = ip + nx - iq;
                        let (bx, by) = (self.bx[d], self.by[d]);
                        blk[row0 + 2 * q] = kap * r * pi[0][0] * bx;
                        blk[row0 + 2 * q + 1] = kap * r * pi[0][1] * by;
                        blk[row1 + 2 * q] = kap * r * pi[1][0] * bx;
                        blk[row1 + 2 * q + 1] = kap * r * pi[1][1] * by;
                    }
                    blk[row0 + 2 * p] += 1.0 - kap * pi[0][0];
                    blk[row0 + 2 * p + 1] -= kap * pi[0][1];
                    blk[row1 + 2 * p] -= kap * pi[1][0];
                    blk[row1 + 2 * p + 1] += 1.0 - kap * pi[1][1];
                } else {
                    for q in 0..nr {
                        let iq = self.cells[c0 + q] % nx;
                        let d = ip + nx - iq;
                        blk[row0 + 2 * q] = r * self.bx[d];
                        blk[row1 + 2 * q + 1] = r * self.by[d];
                    }
                }
            }
            lu_factor(blk, m, &mut self.piv[2 * c0..2 * c1]);
            // Stored in single precision, column by column, with the reciprocals of
            // U's diagonal: the triangular solves, most of a GMRES iteration, then run
            // as column updates on twice the lanes, without divisions. The solution is
            // not affected: GMRES keeps the preconditioned vectors (flexible GMRES), so
            // the preconditioner's round-off costs iterations at most, never accuracy.
            let dst = &mut self.lu[self.blk_off[j]..self.blk_off[j] + m * m];
            for c in 0..m {
                for r in 0..m {
                    let a = blk[r * m + c];
                    dst[c * m + r] = if r == c { (1.0 / a) as f32 } else { a as f32 };
                }
            }
        }
    }

    /// `v ← M⁻¹ v` with the row blocks.
    fn precondition(&mut self, v: &mut [f64]) {
        let ny = self.row_start.len() - 1;
        for j in 0..ny {
            let (c0, c1) = (self.row_start[j], self.row_start[j + 1]);
            let m = 2 * (c1 - c0);
            if m == 0 {
                continue;
            }
            let blk = &self.lu[self.blk_off[j]..self.blk_off[j] + m * m];
            let b = &mut self.row32[..m];
            for (d, x) in b.iter_mut().zip(&v[2 * c0..2 * c1]) {
                *d = *x as f32;
            }
            lu_solve(blk, m, &self.piv[2 * c0..2 * c1], b);
            for (x, d) in v[2 * c0..2 * c1].iter_mut().zip(b.iter()) {
                *x = f64::from(*d);
            }
        }
    }

    /// Restarted, right-preconditioned GMRES for `J Δ = −F` into `delta` (and `B Δ`
    /// into `bdelta`), from 0, to the relative tolerance `eta`; at most `budget`
    /// products. The preconditioned vectors and their `B` products are kept, so `Δ`,
    /// `B Δ` and the restart residual cost no further FFT. Returns (iterations,
    /// products).
    fn gmres(&mut self, eta: f64, budget: usize) -> (usize, usize) {
        let len = 2 * self.cells.len();
        self.delta[..len].fill(0.0);
        self.bdelta[..len].fill(0.0);
        let beta0 = norm2(&self.f);
        if !(beta0 > 0.0) {
            return (0, 0);
        }
        let target = eta * beta0;
        let mut products = 0;
        // The residual of the current Δ, in `w` (first: −F).
        for k in 0..len {
            self.w[k] = -self.f[k];
        }
        let mut beta = beta0;
        loop {
            for k in 0..len {
                self.basis[k] = self.w[k] / beta;
            }
            self.gv.fill(0.0);
            self.gv[0] = beta;
            let mut used = 0;
            for jcol in 0..RESTART {
                if products >= budget {
                    break;
                }
                // z_j = M⁻¹ v_j; B z_j; w = J z_j.
                let (zj, bzj) = (jcol * len..(jcol + 1) * len, jcol * len..(jcol + 1) * len);
                let mut z = std::mem::take(&mut self.zbasis);
                z[zj.clone()].copy_from_slice(&self.basis[jcol * len..(jcol + 1) * len]);
                self.precondition(&mut z[zj.clone()]);
                let mut bz = std::mem::take(&mut self.bzbasis);
                Self::apply_b(
                    &mut self.op,
                    &self.cells,
                    &mut self.grid_t,
                    &mut self.grid_u,
                    &z[zj.clone()],
                    &mut bz[bzj.clone()],
                );
                let mut w = std::mem::take(&mut self.w);
                self.jacobian_rows(&z[zj], &bz[bzj], &mut w);
                self.zbasis = z;
                self.bzbasis = bz;
                products += 1;
                // Modified Gram-Schmidt.
                for i in 0..=jcol {
                    let vi = &self.basis[i * len..(i + 1) * len];
                    let h = dot(&w, vi);
                    self.hess[i * RESTART + jcol] = h;
                    for (a, b) in w.iter_mut().zip(vi) {
                        *a -= h * b;
                    }
                }
                let hn = norm2(&w);
                self.hess[(jcol + 1) * RESTART + jcol] = hn;
                if hn > 0.0 {
                    let dst = &mut self.basis[(jcol + 1) * len..(jcol + 2) * len];
                    for (d, a) in dst.iter_mut().zip(&w) {
                        *d = a / hn;
                    }
                }
                self.w = w;
                // Givens rotations.
                for i in 0..jcol {
                    let (a, b) = (
                        self.hess[i * RESTART + jcol],
                        self.hess[(i + 1) * RESTART + jcol],
                    );
                    self.hess[i * RESTART + jcol] = self.cs[i] * a + self.sn[i] * b;
                    self.hess[(i + 1) * RESTART + jcol] = -self.sn[i] * a + self.cs[i] * b;
                }
                let (a, b) = (
                    self.hess[jcol * RESTART + jcol],
                    self.hess[(jcol + 1) * RESTART + jcol],
                );
                let d = a.hypot(b);
                let (c, s) = if d > 0.0 { (a / d, b / d) } else { (1.0, 0.0) };
                self.cs[jcol] = c;
                self.sn[jcol] = s;
                self.hess[jcol * RESTART + jcol] = d;
                self.hess[(jcol + 1) * RESTART + jcol] = 0.0;
                self.gv[jcol + 1] = -s * self.gv[jcol];
                self.gv[jcol] *= c;
                used = jcol + 1;
                if self.gv[jcol + 1].abs() <= target || hn == 0.0 || !d.is_finite() {
                    break;
                }
            }
            if used == 0 {
                break;
            }
            // y = H⁻¹ g (upper triangular); Δ += Z y, B Δ += (B Z) y.
            for i in (0..used).rev() {
                let mut acc = self.gv[i];
                for l in i + 1..used {
                    acc -= self.hess[i * RESTART + l] * self.yv[l];
                }
                let d = self.hess[i * RESTART + i];
                self.yv[i] = if d != 0.0 { acc / d } else { 0.0 };
            }
            for i in 0..used {
                let yi = self.yv[i];
                let zi = &self.zbasis[i * len..(i + 1) * len];
                for (a, b) in self.delta.iter_mut().zip(zi) {
                    *a += yi * b;
                }
                let bi = &self.bzbasis[i * len..(i + 1) * len];
                for (a, b) in self.bdelta.iter_mut().zip(bi) {
                    *a += yi * b;
                }
            }
            // The true residual w = −F − J Δ (from B Δ: no FFT).
            let mut w = std::mem::take(&mut self.w);
            self.jacobian_rows(&self.delta, &self.bdelta, &mut w);
            for (a, f) in w.iter_mut().zip(&self.f) {
                *a = -f - *a;
            }
            beta = norm2(&w);
            self.w = w;
            if beta <= target || products >= budget || !(beta > 0.0) {
                break;
            }
        }
        (products, products)
    }
}

/// [`project`] without `hypot` (its overflow care costs a fifth of the solve): the plain
/// square root where it is finite, [`project`] otherwise.
fn fast_project(x: f64, y: f64, b: f64) -> (f64, f64) {
    let m2 = x * x + y * y;
    if m2 <= b * b {
        return (x, y);
    }
    if !(m2.is_finite() && m2 > 1e-300) {
        return project(x, y, b);
    }
    let f = b / m2.sqrt();
    (x * f, y * f)
}

/// `a · b` with four partial sums (vectorisable; the order of a plain sum is fixed).
fn dot(a: &[f64], b: &[f64]) -> f64 {
    let n = a.len().min(b.len());
    let (a, b) = (&a[..n], &b[..n]);
    let mut acc = [0.0; 4];
    let (ca, cb) = (a.chunks_exact(4), b.chunks_exact(4));
    let (ra, rb) = (ca.remainder(), cb.remainder());
    for (x, y) in ca.zip(cb) {
        for k in 0..4 {
            acc[k] += x[k] * y[k];
        }
    }
    let tail: f64 = ra.iter().zip(rb).map(|(x, y)| x * y).sum();
    (acc[0] + acc[1]) + (acc[2] + acc[3]) + tail
}

fn norm2(a: &[f64]) -> f64 {
    dot(a, a).sqrt()
}

/// In-place LU with partial pivoting of the row-major `m × m` matrix `a`. A zero pivot
/// (a singular block) is replaced by 1, so the preconditioner stays defined.
fn lu_factor(a: &mut [f64], m: usize, piv: &mut [usize]) {
    for k in 0..m {
        let mut p = k;
        let mut best = a[k * m + k].abs();
        for i in k + 1..m {
            let v = a[i * m + k].abs();
            if v > best {
                best = v;
                p = i;
            }
        }
        piv[k] = p;
        if p != k {
            for c in 0..m {
                a.swap(k * m + c, p * m + c);
            }
        }
        let d = a[k * m + k];
        if d == 0.0 || !d.is_finite() {
            a[k * m + k] = 1.0;
            continue;
        }
        let inv = 1.0 / d;
        let (top, rest) = a.split_at_mut((k + 1) * m);
        let pivot_row = &top[k * m..(k + 1) * m];
        for i in 0..m - k - 1 {
            let row = &mut rest[i * m..(i + 1) * m];
            let l = row[k] * inv;
            row[k] = l;
            if l != 0.0 {
                for (a, p) in row[k + 1..].iter_mut().zip(&pivot_row[k + 1..]) {
                    *a -= l * p;
                }
            }
        }
    }
}

/// Solve in place with the factors of [`lu_factor`] as the preconditioner stores them:
/// single precision, column-major (`a[c * m + r]` = row `r`, column `c`), U's diagonal
/// as its reciprocals. Column updates (`b -= column · b_c`), no reductions.
fn lu_solve(a: &[f32], m: usize, piv: &[usize], b: &mut [f32]) {
    for (k, &p) in piv[..m].iter().enumerate() {
        b.swap(k, p);
    }
    // L y = b, unit diagonal.
    for c in 0..m {
        let bc = b[c];
        if bc != 0.0 {
            for (x, l) in b[c + 1..m].iter_mut().zip(&a[c * m + c + 1..(c + 1) * m]) {
                *x -= l * bc;
            }
        }
    }
    // U x = y.
    for c in (0..m).rev() {
        let bc = b[c] * a[c * m + c];
        b[c] = bc;
        if bc != 0.0 {
            for (x, u) in b[..c].iter_mut().zip(&a[c * m..c * m + c]) {
                *x -= u * bc;
            }
        }
    }
}
