#![allow(clippy::unwrap_used)] // test helpers: a panic is a test failure with its message
//! `kontakt schema` prints the case schema: the library's `case_schema()`, byte for byte
//! the checked-in `docs/kontakt-case.schema.json` (which kontakt-case's `case_schema` test
//! keeps up to date).

mod support;

use support::kontakt;

#[test]
fn schema_prints_the_checked_in_case_schema() {
    let out = kontakt().arg("schema").output().unwrap();
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let printed = String::from_utf8(out.stdout).unwrap();
    let value: serde_json::Value = serde_json::from_str(&printed).unwrap();
    assert_eq!(value, kontakt_case::case_schema());
    assert_eq!(
        value["oneOf"].as_array().unwrap().len(),
        kontakt_case::Case::METHODS.len()
    );
    let file = std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../../docs/kontakt-case.schema.json");
    assert_eq!(printed, std::fs::read_to_string(file).unwrap());
}

#[test]
fn schema_takes_no_arguments() {
    let out = kontakt().args(["schema", "extra"]).output().unwrap();
    assert_eq!(out.status.code(), Some(2));
}
