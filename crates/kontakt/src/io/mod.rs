//! Case files (TOML) and result reports (JSON) with stable, unit-suffixed keys.
//!
//! The CLI and the Python bindings are thin shells over [`case::CaseFile`] →
//! [`run_case`] → [`report::ContactReport`]. The schema is documented in
//! `docs/case-schema.md` and shown by the files in `examples/`.

pub mod bem_case;
pub mod case;
pub mod pimp_case;
pub mod report;
pub mod traction_case;

pub use bem_case::{BemOutcome, run_bem_case};
pub use case::{Case, CaseFile};
pub use pimp_case::{PimpCase, PimpOutcome, PimpReport, run_pimp_case};
pub use report::{ContactReport, run_case};
pub use traction_case::{TractionCase, TractionReport, run_traction_case};
