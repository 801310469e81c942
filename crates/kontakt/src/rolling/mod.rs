//! Exact (Kalker) tangential contact on the half-space grid: Cerruti's influence
//! coefficients, the FFT tangential operator, the shift (Cattaneo) problem and steady
//! rolling with Coulomb friction. The first step of issue 17.
//!
//! - [`influence`]: the displacement differences `u_x`, `u_y` \[mm\] per unit uniform
//!   tangential traction \[MPa\] on a rectangular cell, in closed form (Cerruti's point-force
//!   solution integrated over the cell), for quasi-identical bodies.
//! - [`TangentialOperator`]: `u = A τ` by FFT on the free-boundary plans of
//!   [`crate::halfspace`], for Kalker's combined `G`, `ν` ([`KalkerMaterial`]);
//!   [`difference_parameter`]: Kalker's `K`, which is neglected.
//! - [`ShiftSolver`]: tractions, stick/slip map and slip for a given pressure and
//!   friction coefficient under a prescribed rigid shift or total tangential force,
//!   accelerated projected gradients with a stated residual and a
//!   [`crate::solve::SolveStatus`].
//! - [`SteadySolver`]: steady rolling for given creepages and spin (`S = ω − ∂u/∂x`,
//!   upwind, the rolling step one cell), as Kalker's transient steps marched to the
//!   steady state; creep forces, spin moment, stick/slip map and slip.
//! - [`KalkerExact`]: the traction model `kalker_exact` — a steady solver planned on a
//!   Hertz ellipse, evaluated along a creep curve with warm starts, each point with its
//!   status (`kontakt traction`, docs/tangential.md §11).
//!
//! Not yet here: the normal-tangential coupling of dissimilar bodies (`K ≠ 0`), the
//! speed targets of issue 17, Carter's and Kalker's published creep curves as tests, and
//! the `kontakt traction` model. Method and validation: docs/rolling.md.
//!
//! Units: mm, N, MPa throughout.

mod curve;
pub mod influence;
mod operator;
mod shift;
mod steady;

pub use crate::tangential::KalkerMaterial;
pub use curve::{ExactPoint, KalkerExact, KalkerExactOptions};
pub use operator::{TangentialOperator, difference_parameter};
pub use shift::{CellState, ShiftLoad, ShiftOptions, ShiftSolution, ShiftSolver};
pub use steady::{SteadyOptions, SteadySolution, SteadySolver};
