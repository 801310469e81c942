//! Closed-form Hertz theory: the exact elliptical and circular point contact, line
//! contact, the classic approximations, subsurface stresses and first yield, impact and
//! JKR adhesion.
//!
//! All functions follow the crate-level *Conventions* (mm, N, MPa; convex radii positive;
//! tension-positive stresses). The analytic solutions here are pure functions with no
//! solver, I/O or plotting dependencies, so that both users and the numerical solvers'
//! tests can call them as references.

pub mod adhesion;
pub mod approximation;
mod elliptic;
pub mod impact;
pub mod line;
pub mod point;
pub mod point_stress;
pub mod subsurface;
pub mod validity;

pub use point::{HertzPointContact, HertzPointSolution, PointGeometry, curvature_ratio};
