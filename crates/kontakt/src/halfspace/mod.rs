//! The coupled elastic half-space solver: FFT boundary elements (seed 003 §5).
//!
//! PimP's springs are independent: a cell's pressure depends on its own overlap only, so
//! the bodies' flattening around the contact is missed (seed 000 §4 asks for "coupling the
//! spring elements"). Here every cell's pressure displaces every other cell, through
//! Love's influence coefficients for uniform pressure on a rectangle ([`influence`]), and
//! the contact is solved as the complementarity problem of seed 003 eqs 28a/b:
//!
//! ```text
//! g_i = h_i + Σ_j C_ij p_j - δ  >= 0,   p_i >= 0,   p_i g_i = 0,   Σ p_i ΔA = F,
//! ```
//!
//! with `h` the undeformed gap \[mm\], `p` the pressure \[MPa\], `δ` the rigid approach
//! \[mm\] and `F` the normal force \[N\].
//!
//! - [`ElasticOperator`]: `u = C p` by FFT with zero padding (free boundary) or periodic,
//!   planned once, no allocation per application, threads via rayon.
//! - [`HalfSpaceSolver`]: Polonsky and Keer's constrained conjugate gradients under load
//!   or displacement control, a Hertz-like cold start, warm starts for the multi-body time
//!   step, and a stated residual; non-convergence is a status in [`SolveReport`].
//! - [`Bem`]: the solver on any [`crate::pimp::GapSource`] (PimP's substitute geometry,
//!   the Hertz gap, two placed surfaces) with a domain that adapts to the contact, or on
//!   a user [`GapMap`] (CSV or `.npy`).
//!
//! Derivations, conventions and the memory budget: docs/halfspace.md.

mod contact;
mod gapmap;
pub mod influence;
mod operator;
mod planner;
mod solver;

pub use contact::{Bem, BemOptions, BemSolution, MIN_CELLS_ACROSS};
pub use gapmap::{GapMap, MapKind};
pub use operator::{Boundary, ElasticOperator, HalfSpacePlan, OperatorScratch};
pub use planner::HalfSpacePlanner;
pub use solver::{Control, HalfSpaceSolver, SolveReport, SolverOptions, Start};
