//! The coupled elastic half-space solver: FFT boundary elements (Johnson 1982, §5).
//!
//! PimP's springs are independent: a cell's pressure depends on its own overlap only, so
//! the bodies' flattening around the contact is missed (Wirsching et al. 2020, §4, ask for
//! "coupling the spring elements"). Here every cell's pressure displaces every other cell, through
//! Love's influence coefficients for uniform pressure on a rectangle ([`influence`]), and
//! the contact is solved as the complementarity problem of Johnson (1982) eqs 28a/b:
//!
//! ```text
//! g_i = h_i + Σ_j C_ij p_j - δ  >= 0,   p_i >= 0,   p_i g_i = 0,   Σ p_i ΔA = F,
//! ```
//!
//! with `h` the undeformed gap \[mm\], `p` the pressure \[MPa\], `δ` the rigid approach
//! \[mm\] and `F` the normal force \[N\].
//!
//! - [`HalfSpacePlan`]: `u = C p` \[mm\] for `p` \[MPa\] by FFT with zero padding (free
//!   boundary) or periodic. Immutable and `Send + Sync`: FFT plans, kernel spectrum,
//!   thread pool, shared behind `Arc`. It is applied with a caller-owned
//!   [`OperatorScratch`] (`apply_with_scratch`, no allocation per application), in the
//!   style of RustFFT's planner → plan → execute-with-scratch.
//! - [`HalfSpacePlanner`]: caches plans by cells, spacing, boundary, E* and threads, so
//!   equal grids share one `Arc<HalfSpacePlan>`. [`ElasticOperator`] is a plan with a
//!   scratch of its own.
//! - [`HalfSpaceSolver`]: Polonsky and Keer's constrained conjugate gradients under load
//!   or displacement control, a Hertz-like cold start, warm starts for the multi-body time
//!   step, and a stated residual; non-convergence is a status in [`SolveReport`]. It
//!   plans for itself ([`HalfSpaceSolver::new`]) or takes a shared plan
//!   ([`HalfSpaceSolver::with_plan`]); its scratch and state are its own.
//! - [`Bem`]: the solver on any [`crate::gap::GapSource`] (PimP's substitute geometry,
//!   the Hertz gap, two placed surfaces) with a domain that adapts to the contact, or on
//!   a user [`GapMap`] (CSV or `.npy`). It plans each domain once through its planner.
//!
//! Derivations, conventions and the memory budget: docs/halfspace.md.

mod contact;
pub mod influence;
mod operator;
mod planner;
mod solver;

pub use crate::field::domain::MIN_CELLS_ACROSS;
pub use crate::gap::{GapMap, MapKind};
pub use contact::{Bem, BemOptions, BemSolution, HalfSpaceDetail, ZoneEstimate};
pub use operator::{Boundary, ElasticOperator, HalfSpacePlan, OperatorScratch};
pub(crate) use operator::{PaddedFfts, Parity};
pub use planner::HalfSpacePlanner;
pub(crate) use solver::smallest;
pub use solver::{
    Control, HalfSpaceSolver, Preconditioner, SCALE_RANGE, SolveReport, SolverOptions, Start,
    check_scales,
};
