//! # kontakt-case — case files, the runner and the reports of kontakt
//!
//! The layer between the physics library [`kontakt`] and its front ends (the `kontakt`
//! command, the Python package, parameter sweeps). Data flows one way:
//!
//! ```text
//! TOML case file ──parse──▶ Case ──Case::run──▶ kontakt (physics) ──▶ Outcome ──▶ JSON report
//! ```
//!
//! - [`Case`]: every schema (`method = "hertz" | "pimp" | "bem" | "traction" | "friction" |
//!   "mindlin" | "impact" | "rough" | "bearing"`), parsed
//!   from TOML with unknown keys refused; [`Case::run`] is the one dispatch that every
//!   front end calls.
//! - [`Outcome`]: the report (stable, unit-suffixed JSON keys, `schema_version`) plus,
//!   for the field methods, the full solution (pressure, displacement, gap per cell).
//! - [`BearingModel`]: a bearing case planned once and solved for many loads, warm-started
//!   from the last equilibrium (Python's `kontakt.Bearing`).
//! - [`case_schema`]: the JSON Schema of the case files, derived from the serde types.
//! - [`maps`]: gap and height maps from CSV or NumPy `.npy` files.
//! - [`files`]: the one size-capped reader of every file a case names.
//! - [`element_case`]: contact-element cases (`method = "element"`), not a [`Case`]: they
//!   describe a [`kontakt::element::ContactElement`] that a multi-body code evaluates at its
//!   own poses ([`element_from_case`]).
//!
//! Errors name the case-file key (`load.force_n`, `pimp.cells`, `body1.nu`), the value
//! and the valid range. Units: mm, N, MPa throughout. The schema is documented in
//! `docs/case-schema.md` and shown by the files in `examples/`.

pub mod bearing_case;
pub mod bearing_design;
pub mod bearing_friction;
pub mod bearing_model;
mod bearing_post;
pub mod bearing_rating;
pub mod bearing_rib;
pub mod bearing_slices;
pub mod bearing_validation;
pub mod bem_case;
pub mod case;
mod common;
pub mod element_case;
pub mod files;
pub mod friction_case;
pub mod hertz_case;
pub mod impact_case;
pub mod maps;
pub mod mindlin_case;
pub mod pimp_case;
pub mod rough_case;
pub mod schema;
pub mod sweep;
pub mod topography;
pub mod traction_case;
pub mod validity;

pub use bearing_case::{BearingCase, BearingReport, run_bearing_case};
pub use bearing_model::BearingModel;
pub use bem_case::{BemOutcome, run_bem_case, run_bem_case_on_map};
pub use case::{Case, CaseFile, FieldView, Outcome};
pub use common::{SCHEMA_VERSION, read_case_file, read_case_text};
pub use element_case::{ElementCase, element_from_case, element_from_toml};
pub use files::{MAX_CASE_FILE_BYTES, MAX_DATA_FILE_BYTES};
pub use friction_case::{FrictionCase, FrictionOutcome, FrictionReport, run_friction_case};
pub use hertz_case::{ContactReport, run_case};
pub use impact_case::{ImpactCase, ImpactReport, run_impact_case};
pub use mindlin_case::{MindlinCase, MindlinReport, run_mindlin_case};
pub use pimp_case::{PimpCase, PimpOutcome, PimpReport, run_pimp_case};
pub use rough_case::{RoughCase, RoughOutcome, RoughReport, run_rough_case};
pub use schema::case_schema;
pub use sweep::{Sweep, SweepError};
pub use traction_case::{
    ExactMap, MapPoint, TractionCase, TractionReport, run_traction_case, run_traction_case_with_map,
};
