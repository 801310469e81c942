//! Friction of a lubricated contact over its pressure field: the mixed-friction law per
//! cell ([`law`]) and its integral over any [`crate::field::NormalSolution`] ([`integral`]):
//! friction force, moments and dissipated power.
//!
//! ```
//! use kontakt::friction::{FilmState, FrictionLaw, grid_friction};
//! use kontakt::geometry::{Grid2, VelocityField};
//!
//! // A uniform pressure of 100 MPa on 1 mm², sliding at 200 mm/s along x.
//! let grid = Grid2::centered(0.5, 0.5, 8, 8)?;
//! let pressure = vec![100.0; grid.len()];
//! let field = VelocityField {
//!     sliding: [[200.0, 0.0], [0.0, 0.0], [0.0, 0.0]],
//!     entrainment: [[1000.0, 0.0], [0.0, 0.0], [0.0, 0.0]],
//! };
//! let law = FrictionLaw::coulomb(0.1)?.with_film(&FilmState::dry())?;
//! let f = grid_friction(&grid, &pressure, &field, &law)?;
//! assert!((f.normal_force - 100.0).abs() < 1e-9); // N
//! assert!((f.force[0] + 10.0).abs() < 1e-3); // N, against the sliding
//! assert!((f.power - 10.0 * 0.2).abs() < 1e-3); // W = 10 N at 0.2 m/s
//! # Ok::<(), kontakt::error::Error>(())
//! ```
//!
//! Units: mm, N, MPa, mm/s, MPa·s; moments in N·mm; power in W. Derivations:
//! docs/friction.md.

pub mod ellipse;
pub mod integral;
pub mod law;

pub use ellipse::{
    EllipseRule, HertzFrictionRules, ellipse_friction, ellipse_friction_curved,
    sliding_pole_radius, sliding_smoothness,
};
pub use integral::{
    BINNED_TOLERANCE, BLOCK_SHAPES, ContactFriction, GridFriction, binning_blocks, binning_error,
    block_error, contact_friction, grid_friction, grid_friction_binned, power_density,
    pressure_sliding,
};
pub use law::{CellLaw, FilmState, FluidShear, FrictionLaw, LoadSharing, REGULARISATION_SPEED};
