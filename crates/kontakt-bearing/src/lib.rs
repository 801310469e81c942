//! # kontakt-bearing — whole rolling bearings on kontakt's contacts
//!
//! The system level above the single contact of [`kontakt`]: roller and raceway
//! [`profile`]s, the closed-form [`load_zone`] integrals of Sjövall (1933), the internal
//! [`geometry`] of roller and ball bearings as validated data, the quasi-static ring
//! [`equilibrium`] of roller bearings and the [`ball_equilibrium`] of deep-groove and
//! angular-contact ball bearings, in five degrees of freedom with the stiffness matrix.
//! The catalogue [`friction`] models (SKF 2004, Schaeffler, Aihara 1987) give the whole
//! bearing's friction torque as the catalogues do.
//!
//! ## Quick example
//! A cylindrical roller bearing (14 rollers 10 × 12 mm on a 60 mm pitch circle, ISO/TS 16281
//! roller profile, 10 µm diametral clearance) under a radial load of 10 kN:
//! ```
//! use kontakt_bearing::equilibrium::{RingLoad, RollerBearingSolver};
//! use kontakt_bearing::geometry::RollerBearing;
//! let mut bearing = RollerBearing::cylindrical(60.0, 14, 10.0, 12.0);
//! bearing.clearance_mm = 0.01;
//! let mut solver = RollerBearingSolver::new(bearing)?;
//! let sol = solver.solve(&RingLoad::forces([10_000.0, 0.0, 0.0, 0.0, 0.0]))?;
//! assert!(sol.status.converged());
//! let eps = sol.load_zone.expect("a radial load has a load zone");
//! assert!(eps > 0.3 && eps < 0.5); // less than half the ring carries load
//! // the most loaded roller, and its slice loads along the roller (N)
//! let q_max = sol.max_roller_load_n;
//! assert!(q_max > 4.08 * 10_000.0 / 14.0);
//! let slices = &solver.slice_loads()[..solver.slice_positions().len()];
//! assert!((slices.iter().sum::<f64>() - solver.roller_loads()[0].outer_n).abs() < 1e-9);
//! # Ok::<(), kontakt::Error>(())
//! ```
//!
//! Units and signs follow [`kontakt`]'s conventions: millimetre, newton, megapascal
//! (N/mm²), radian; moments in N·mm. The derivation of the equations, the frames and what
//! is not modelled are in `docs/bearing-model.md`.
#![forbid(unsafe_code)]

pub mod ball_equilibrium;
pub mod ball_speed;
pub mod equilibrium;
pub mod friction;
pub mod geometry;
pub mod life;
pub mod load_zone;
mod newton;
pub mod profile;
pub mod roller_equilibrium;
pub mod roller_speed;
pub mod speed;
pub mod stress;
#[cfg(test)]
mod test_support;

pub use kontakt::{Error, Result};
