//! # kontakt-bearing — whole rolling bearings on kontakt's contacts
//!
//! The system level above the single contact of [`kontakt`]: roller and raceway
//! [`profile`]s, the closed-form [`load_zone`] integrals of Sjövall (1933), the internal
//! [`geometry`] of roller bearings as validated data and the quasi-static ring
//! [`equilibrium`] in five degrees of freedom with its stiffness matrix.
//!
//! Units and signs follow [`kontakt`]'s conventions: millimetre, newton, megapascal
//! (N/mm²), radian; moments in N·mm. The derivation of the equations, the frames and what
//! is not modelled are in `docs/bearing-model.md`.
#![forbid(unsafe_code)]

pub mod equilibrium;
pub mod geometry;
pub mod load_zone;
pub mod profile;

pub use kontakt::{Error, Result};
