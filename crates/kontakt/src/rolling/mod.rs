//! Exact (Kalker) tangential contact on the half-space grid: Cerruti's influence
//! coefficients, the FFT tangential operator, the shift (Cattaneo) problem and steady
//! rolling with Coulomb friction. The first step of issue 17.
//!
//! - [`influence`]: the displacement differences `u_x`, `u_y` \[mm\] per unit uniform
//!   tangential traction \[MPa\] on a rectangular cell, in closed form (Cerruti's point-force
//!   solution integrated over the cell), for quasi-identical bodies.
//! - [`TangentialOperator`]: `u = A τ` by FFT on the free-boundary plans of
//!   [`crate::halfspace`], for Kalker's combined `G`, `ν` ([`KalkerMaterial`]);
//!   [`difference_parameter`]: Kalker's `K` (neglected by the solvers of quasi-identical
//!   bodies, coupled by [`CoupledShiftSolver`] and [`CoupledSteadySolver`]).
//! - [`ShiftSolver`]: tractions, stick/slip map and slip for a given pressure and
//!   friction coefficient under a prescribed rigid shift or total tangential force,
//!   accelerated projected gradients with a stated residual and a
//!   [`crate::solve::SolveStatus`].
//! - [`SteadySolver`]: steady rolling for given creepages and spin (`S = ω − ∂u/∂x`,
//!   upwind, the rolling step one cell), by a semismooth Newton method with GMRES on the
//!   steady equations (default) or Kalker's transient steps marched to the steady state
//!   ([`SteadyMethod`]); creep forces, spin moment, stick/slip map and slip.
//! - [`CoupledShiftSolver`]: the shift problem of dissimilar bodies (Kalker's
//!   difference parameter `K ≠ 0`), the normal and tangential problems coupled through
//!   [`CouplingOperator`] and solved by an outer loop along a loading history (Spence's
//!   compression with friction is the special case without shift).
//! - [`CoupledSteadySolver`]: steady rolling of dissimilar bodies, the normal problem and
//!   steady rolling coupled by the same outer loop (the pressure's tangential
//!   displacement an extra rigid slip of [`SteadySolver::solve_with_rigid_slip`]), under
//!   prescribed creepages or a prescribed longitudinal force ([`SteadyLoad`]; `F_x = 0`:
//!   the free-rolling creepage).
//! - [`KalkerExact`]: the traction model `kalker_exact` — a steady solver planned on a
//!   Hertz ellipse or on any pressure field (the half-space solver's, PimP's: resampled
//!   onto a grid along the rolling direction), evaluated along a creep curve with warm
//!   starts, each point with its status (`kontakt traction`, docs/tangential.md §11);
//!   on a Hertz ellipse, dissimilar bodies as an option
//!   ([`KalkerExactOptions::coupling`]: [`CoupledSteadySolver`] on the Hertz gap, and
//!   the free-rolling creepage [`KalkerExact::free_rolling`]).
//!
//! Method and validation: docs/rolling.md (§10 for the traction model, §11 for steady
//! rolling of dissimilar bodies).
//!
//! Units: mm, N, MPa throughout.

mod coupled;
mod coupled_steady;
mod cross;
mod curve;
pub mod influence;
mod newton;
mod operator;
mod outer;
mod shift;
mod steady;
mod steady_fft;

pub use crate::tangential::KalkerMaterial;
pub use coupled::{CoupledOptions, CoupledShiftSolver, CoupledSolution};
pub use coupled_steady::{
    CoupledSteadyOptions, CoupledSteadySolution, CoupledSteadySolver, SteadyLoad,
};
pub use cross::CouplingOperator;
pub use curve::{ExactPoint, KalkerExact, KalkerExactOptions};
pub use operator::{TangentialOperator, difference_parameter};
pub use shift::{CellState, ShiftLoad, ShiftOptions, ShiftSolution, ShiftSolver};
pub use steady::{SteadyMethod, SteadyOptions, SteadySolution, SteadySolver};
