//! Running a bearing case text and reading an example, for the bearing tests
//! (`#[path = "support/bearing_run.rs"] mod bearing_run;`). `tests/bearing.rs` and
//! `tests/bearing_rib_contact.rs` hold their own copies of these from before.
#![allow(clippy::unwrap_used)] // tests: a panic is a failure with its message
#![allow(dead_code)] // each including test uses a part

use kontakt_case::{BearingReport, Case, Outcome};
use std::path::PathBuf;

/// The repository's examples folder.
pub fn examples() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../../examples")
}

/// Run a bearing case text (paths relative to the examples).
pub fn run(text: &str) -> kontakt::Result<BearingReport> {
    match Case::from_toml_str(text)?.run(&examples())? {
        Outcome::Bearing(r) => Ok(*r),
        _ => panic!("not a bearing outcome"),
    }
}

/// The text of the example `name`.
pub fn example(name: &str) -> String {
    std::fs::read_to_string(examples().join(name)).unwrap()
}
