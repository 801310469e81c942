//! Geometry: principal curvatures of contacting bodies, their relative curvature, and
//! sampling grids.
//!
//! The analytic surfaces of the PimP method (plane, sphere, cone, torus, surfaces of
//! revolution) with ray casting will live here too, one file per surface.

pub mod curvature;
pub mod grid;

pub use curvature::RelativeCurvature;
pub use grid::Grid2;
