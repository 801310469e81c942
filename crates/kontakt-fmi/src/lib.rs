//! # kontakt-fmi — kontakt's elements as FMUs (FMI 2.0)
//!
//! The shared library of this crate is the binary of an FMU (Functional Mock-up Unit,
//! FMI 2.0) of a kontakt case: the **bearing element** of a bearing case
//! (`method = "bearing"`, [`kontakt_case::bearing_model::BearingElement`]) or the
//! **contact element** of an element case (`method = "element"`,
//! [`kontakt::element::ContactElement`]). `kontakt fmu CASE.toml -o case.fmu` packs it with
//! the case (in `resources/case.toml`) and the model description written from the case;
//! docs/fmi.md documents the variables, frames, signs and units and how to load the FMU.
//!
//! - Model exchange **without continuous states, with direct feedthrough** (the host's
//!   integrator steps the contact; the outputs are a function of the inputs), and
//!   co-simulation from the same binary.
//! - [`fmi2`]: the exported `fmi2*` functions, a thin layer over [`instance`] and
//!   [`model`]; every call runs under `catch_unwind`, every status other than `fmi2OK` is
//!   logged naming the variable: `fmi2Error` for bad input (a non-finite value, an unknown
//!   value reference, an illegal call), `fmi2Discard` for a state beyond the model's
//!   validity.
//! - [`variables`]: the variable tables (one row per variable).
//! - [`description`]: `modelDescription.xml` and the GUID; [`archive`]: the FMU zip.
//!
//! Units: mm, N, N·mm, mm/s, rad/s, W (declared in the model description's
//! `UnitDefinitions`).

#![allow(unsafe_code)] // the C boundary: raw pointers in, raw pointers out (fmi2.rs)

pub mod archive;
pub mod description;
pub mod fmi2;
pub mod instance;
pub mod model;
pub mod variables;
