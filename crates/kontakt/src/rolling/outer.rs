//! The outer loop shared by the coupled solvers of dissimilar bodies
//! ([`super::CoupledShiftSolver`], [`super::CoupledSteadySolver`]): Kalker's
//! "Panagiotopoulos process" around the normal problem and a tangential problem.
//!
//! # Formula
//! One pass: (1) the normal problem for the gap `h + A_n τ` \[mm\] (the half-space solver,
//! warm-started); (2) the pressure's tangential displacement difference `A_t p` \[mm\],
//! which the caller's tangential problem takes as a rigid slip; (3) the change of the
//! pressure and tractions over the pass,
//!
//! ```text
//! change = ‖(p, τ)_k − (p, τ)_{k−1}‖₂ / ‖(p, τ)_k‖₂     (Euclidean over all cells),
//! ```
//!
//! and the loop's end: `Diverged` for a non-finite change, `Converged` when it is at
//! most `tolerance` after at least two passes, `Stagnated` after `patience` passes
//! without a new lowest change, `MaxIterations` at `max_outer` passes (tested in that
//! order). For `K = 0` (or the coupling off) there is no coupling operator and the
//! caller stops after one pass.
//!
//! # References
//! Kalker, *Three-dimensional elastic bodies in rolling contact* (1990), §1.6, §2.2;
//! Vollebregt, CONTACT user guide (the Panagiotopoulos process, its convergence
//! criterion).

use super::cross::CouplingOperator;
use super::operator::difference_parameter;
use crate::error::{Error, Result};
use crate::geometry::Grid2;
use crate::halfspace::{Control, HalfSpaceSolver, SolveReport, SolverOptions, Start};
use crate::material::ElasticMaterial;
use crate::solve::{SolveStatus, Termination};
use crate::tangential::KalkerMaterial;

/// Kalker's combined constants of two bodies and the difference parameter `K` in use
/// (0 when `coupling` is off): the start of the coupled solvers' `new`.
pub(super) fn combined_constants(
    body1: &ElasticMaterial,
    body2: &ElasticMaterial,
    coupling: bool,
) -> Result<(KalkerMaterial, f64)> {
    let material = KalkerMaterial::new(body1, body2)?;
    let k = if coupling {
        difference_parameter(body1, body2)?
    } else {
        0.0
    };
    Ok((material, k))
}

/// The limits of the outer loop (each solver's options, checked by them).
#[derive(Debug, Clone, Copy)]
pub(super) struct OuterLimits {
    /// The relative change of `(p, τ)` over a pass that ends the loop \[-\].
    pub(super) tolerance: f64,
    /// Passes without a new lowest change before the loop stops as stagnated.
    pub(super) patience: usize,
    /// Most passes.
    pub(super) max_outer: usize,
}

/// A coupled solver as the outer loop sees it.
pub(super) trait CoupledParts {
    /// Its outer loop and its current tractions `[τ_x, τ_y]` on body 1 \[MPa\].
    fn parts(&mut self) -> (&mut OuterLoop, [&[f64]; 2]);
}

/// The outer loop of the module docs for `solver`, on the undeformed gap `gap` \[mm\]
/// under the normal `control`: passes of (1) the normal problem, (2) `tangential`, the
/// solver's tangential problem for the pressure of (1) (in [`OuterLoop::normal`]), which
/// returns the termination and residual of a failed inner solve or `None`, (3) the change
/// and the end of the loop (one pass without coupling). Returns the last normal solve's
/// report and the loop's status: its termination, passes and last change (0 after the
/// single pass without coupling; a failed solve's own residual).
///
/// # Errors
/// The normal solver's, the coupling operator's and `tangential`'s.
pub(super) fn run_outer<S: CoupledParts>(
    solver: &mut S,
    gap: &[f64],
    control: Control,
    limits: OuterLimits,
    mut tangential: impl FnMut(&mut S) -> Result<Option<(Termination, f64)>>,
) -> Result<(SolveReport, SolveStatus)> {
    solver.parts().0.start();
    let mut passes = 0;
    loop {
        passes += 1;
        // (1) The normal problem with the tractions' normal displacement.
        let (outer, tau) = solver.parts();
        let report = outer.solve_normal(gap, tau, control)?;
        let st = report.status;
        if st.termination != Termination::Converged {
            return Ok((
                report,
                SolveStatus::new(st.termination, passes, st.residual),
            ));
        }
        // (2) The tangential problem for this pressure.
        if let Some((termination, residual)) = tangential(solver)? {
            return Ok((report, SolveStatus::new(termination, passes, residual)));
        }
        let (outer, tau) = solver.parts();
        if outer.cross.is_none() {
            return Ok((
                report,
                SolveStatus::new(Termination::Converged, passes, 0.0),
            ));
        }
        // (3) The change over the pass.
        if let (change, Some(termination)) = outer.after_pass(tau, passes, limits) {
            return Ok((report, SolveStatus::new(termination, passes, change)));
        }
    }
}

/// The normal solver, the coupling operator and the work arrays of the outer loop
/// (see the module docs).
#[derive(Debug)]
pub(super) struct OuterLoop {
    /// The normal problem on the grid, with Love's compliance of the two bodies.
    pub(super) normal: HalfSpaceSolver,
    /// The coupling operator when `K ≠ 0`.
    pub(super) cross: Option<CouplingOperator>,
    /// The pressure's tangential displacement difference `A_t p` \[mm\] of the last
    /// [`OuterLoop::pressure_displacement`].
    pub(super) up: [Vec<f64>; 2],
    /// The gap `h + A_n τ` \[mm\] and `A_n τ` \[mm\].
    gap: Vec<f64>,
    un: Vec<f64>,
    /// The last pass's pressure and tractions \[MPa\].
    old_p: Vec<f64>,
    old_tau: [Vec<f64>; 2],
    /// The lowest change so far and the passes since.
    best: f64,
    since_best: usize,
}

impl OuterLoop {
    /// The parts a coupled problem adds to its tangential solver, checked: `K` in use
    /// (0 when `coupling` is off), the normal solver on `grid` with Love's compliance of
    /// the two bodies (`1/E* = (1 − ν)/G` with Kalker's constants), and the coupling
    /// operator when `K ≠ 0`.
    ///
    /// # Errors
    /// [`Error::InvalidInput`] for constants out of range (`|K| > 0.5`, `G`, `ν`) or
    /// normal solver options out of range.
    pub(super) fn new(
        grid: &Grid2,
        material: KalkerMaterial,
        k: f64,
        coupling: bool,
        normal: SolverOptions,
    ) -> Result<(f64, Self)> {
        super::operator::check_material(&material)?;
        super::cross::check_difference(k)?;
        let k = if coupling { k } else { 0.0 };
        let e_star = material.shear_modulus / (1.0 - material.poisson_ratio);
        let solver = HalfSpaceSolver::new(*grid, e_star, normal)?;
        let cross = if k != 0.0 {
            Some(CouplingOperator::new(grid, material, k)?)
        } else {
            None
        };
        let n = grid.len();
        let z2 = || [vec![0.0; n], vec![0.0; n]];
        Ok((
            k,
            OuterLoop {
                normal: solver,
                cross,
                up: z2(),
                gap: vec![0.0; n],
                un: vec![0.0; n],
                old_p: vec![0.0; n],
                old_tau: z2(),
                best: f64::INFINITY,
                since_best: 0,
            },
        ))
    }

    /// Check the undeformed gap's length against the grid.
    ///
    /// # Errors
    /// [`Error::InvalidInput`] naming `gap`.
    pub(super) fn check_gap(grid: &Grid2, gap: &[f64]) -> Result<()> {
        let n = grid.len();
        if gap.len() != n {
            return Err(Error::invalid(
                "gap",
                format!("{} values", gap.len()),
                format!("{n} values ({} x {} grid)", grid.nx(), grid.ny()),
            ));
        }
        Ok(())
    }

    /// Start a solve: no lowest change yet.
    fn start(&mut self) {
        self.best = f64::INFINITY;
        self.since_best = 0;
    }

    /// Forget the last pass's pressure and tractions (the change of the next first pass
    /// is then measured from zero).
    pub(super) fn forget(&mut self) {
        self.old_p.fill(0.0);
        for v in self.old_tau.iter_mut() {
            v.fill(0.0);
        }
    }

    /// Step (1): the normal problem for the undeformed gap `gap` \[mm\] plus the
    /// tractions' normal displacement `A_n τ` (`tau` \[MPa\] on body 1), warm-started.
    ///
    /// # Errors
    /// The normal solver's ([`HalfSpaceSolver::solve`]).
    fn solve_normal(
        &mut self,
        gap: &[f64],
        tau: [&[f64]; 2],
        control: Control,
    ) -> Result<SolveReport> {
        let normal_gap: &[f64] = match &mut self.cross {
            Some(cross) => {
                let [tx, ty] = tau;
                cross.normal(tx, ty, &mut self.un)?;
                for ((g, h), u) in self.gap.iter_mut().zip(gap).zip(&self.un) {
                    *g = h + u;
                }
                &self.gap
            }
            None => gap,
        };
        self.normal.solve(normal_gap, control, Start::Warm)
    }

    /// Step (2): `A_t p` of the current pressure into [`OuterLoop::up`]; `false` (and
    /// nothing done) without coupling.
    ///
    /// # Errors
    /// The coupling operator's (lengths; cannot happen on the solver's own grid).
    pub(super) fn pressure_displacement(&mut self) -> Result<bool> {
        match &mut self.cross {
            Some(cross) => {
                let [ux, uy] = &mut self.up;
                cross.tangential(self.normal.pressure(), ux, uy)?;
                Ok(true)
            }
            None => Ok(false),
        }
    }

    /// Step (3): the relative change of `(p, τ)` over the pass, which becomes the last
    /// pass; and the loop's end after `passes` passes, if it ends (module docs).
    fn after_pass(
        &mut self,
        tau: [&[f64]; 2],
        passes: usize,
        limits: OuterLimits,
    ) -> (f64, Option<Termination>) {
        let p = self.normal.pressure();
        let (mut num, mut den) = (0.0, 0.0);
        let [tx, ty] = tau;
        let [ox, oy] = &self.old_tau;
        for (i, (pv, po)) in p.iter().zip(&self.old_p).enumerate() {
            let (dx, dy, dp) = (tx[i] - ox[i], ty[i] - oy[i], pv - po);
            num += dp * dp + dx * dx + dy * dy;
            den += pv * pv + tx[i] * tx[i] + ty[i] * ty[i];
        }
        let change = (num / den).sqrt();
        self.old_p.copy_from_slice(p);
        for (o, t) in self.old_tau.iter_mut().zip(tau) {
            o.copy_from_slice(t);
        }
        if !change.is_finite() {
            return (change, Some(Termination::Diverged));
        }
        if passes > 1 && change <= limits.tolerance {
            return (change, Some(Termination::Converged));
        }
        if change < self.best {
            self.best = change;
            self.since_best = 0;
        } else {
            self.since_best += 1;
            if self.since_best >= limits.patience {
                return (change, Some(Termination::Stagnated));
            }
        }
        if passes >= limits.max_outer {
            return (change, Some(Termination::MaxIterations));
        }
        (change, None)
    }

    /// The coupling fields of the final state: `A_t p` of the current pressure into
    /// [`OuterLoop::up`] and the tractions' normal displacement `A_n τ` \[mm\] (zeros
    /// without coupling).
    pub(super) fn final_fields(&mut self, tau: [&[f64]; 2]) -> Vec<f64> {
        let mut coupling_gap = vec![0.0; self.old_p.len()];
        if let Some(cross) = &mut self.cross {
            let [ux, uy] = &mut self.up;
            cross
                .tangential(self.normal.pressure(), ux, uy)
                .expect("invariant: lengths match the grid");
            let [tx, ty] = tau;
            cross
                .normal(tx, ty, &mut coupling_gap)
                .expect("invariant: lengths match the grid");
        }
        coupling_gap
    }
}
