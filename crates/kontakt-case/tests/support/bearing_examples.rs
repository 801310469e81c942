//! The bearing examples of `examples/` for the bearing case tests: their folder, one's text,
//! and a case text run to its report. Shared by `bearing.rs`, `bearing_rib_contact.rs` and
//! `bearing_roller_speed.rs` (`#[path = "support/bearing_examples.rs"] mod bearing_examples;`).
#![allow(clippy::unwrap_used, dead_code)] // tests: a panic is a failure with its message

use kontakt_case::{BearingReport, Case, Outcome};
use std::path::PathBuf;

/// The repository's `examples/` folder.
pub fn examples() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../../examples")
}

/// Run a bearing case's text (relative paths from `examples/`) to its report.
pub fn run(text: &str) -> kontakt::Result<BearingReport> {
    match Case::from_toml_str(text)?.run(&examples())? {
        Outcome::Bearing(r) => Ok(*r),
        other => panic!(
            "not a bearing outcome: {}",
            serde_json::to_string(&other).unwrap()
        ),
    }
}

/// The text of the example `name`.
pub fn example(name: &str) -> String {
    std::fs::read_to_string(examples().join(name)).unwrap()
}
