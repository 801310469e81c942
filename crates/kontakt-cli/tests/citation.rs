//! `CITATION.cff` (issue 32 item 5) says what the workspace's Cargo.toml says: the version,
//! the licences and the repository. (Its form is validated by `cffconvert --validate` in
//! tools/test.)

#![allow(clippy::unwrap_used)] // tests: a panic is a failure with its message

/// The value of the top-level key `key` of the CITATION.cff text (one line, quotes off).
fn value<'a>(cff: &'a str, key: &str) -> &'a str {
    cff.lines()
        .find_map(|l| l.strip_prefix(key)?.strip_prefix(':'))
        .unwrap_or_else(|| panic!("CITATION.cff has no `{key}`"))
        .trim()
        .trim_matches('"')
}

/// The items of the top-level list `key`.
fn list<'a>(cff: &'a str, key: &str) -> Vec<&'a str> {
    cff.lines()
        .skip_while(|l| *l != format!("{key}:"))
        .skip(1)
        .map_while(|l| l.strip_prefix("  - "))
        .collect()
}

#[test]
fn citation_matches_the_workspace() {
    let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../../CITATION.cff");
    let cff = std::fs::read_to_string(path).unwrap();
    assert_eq!(value(&cff, "version"), env!("CARGO_PKG_VERSION"));
    assert_eq!(value(&cff, "repository-code"), env!("CARGO_PKG_REPOSITORY"));
    assert_eq!(
        list(&cff, "license").join(" OR "),
        env!("CARGO_PKG_LICENSE"),
        "CITATION.cff lists the licences of `license` in Cargo.toml"
    );
    assert_eq!(value(&cff, "cff-version"), "1.2.0");
}
