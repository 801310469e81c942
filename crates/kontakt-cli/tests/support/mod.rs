//! What the command tests of one case method share: the binary, the example files, a
//! fresh folder per test, JSON runs and one-line input errors. (`mod support;` in a test
//! file; not every test uses every helper.)

#![allow(dead_code, clippy::unwrap_used)] // test helpers: a panic is a test failure with its message

use assert_cmd::Command;
use serde_json::Value;
use std::path::PathBuf;

/// The `kontakt` binary of this build.
pub fn kontakt() -> Command {
    Command::cargo_bin("kontakt").expect("binary built")
}

/// The repository's `examples/` file `name`.
pub fn example(name: &str) -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .join("../../examples")
        .join(name)
}

/// A fresh folder per test: `<tmp>/kontakt-<group>-test-<pid>-<name>`.
pub fn tempdir(group: &str, name: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!(
        "kontakt-{group}-test-{}-{name}",
        std::process::id()
    ));
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(&d).unwrap();
    d
}

/// Run with `--json`, expect success, return the document.
pub fn run_json(args: &[&str]) -> Value {
    let out = kontakt().args(args).arg("--json").output().unwrap();
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    serde_json::from_slice(&out.stdout).unwrap()
}

/// A JSON number.
pub fn num(v: &Value) -> f64 {
    v.as_f64().unwrap_or_else(|| panic!("not a number: {v}"))
}

/// Run, expect exit status 2 and exactly one stderr line; return it.
pub fn bad(args: &[&str]) -> String {
    let out = kontakt().args(args).output().unwrap();
    let err = String::from_utf8(out.stderr).unwrap();
    assert_eq!(out.status.code(), Some(2), "args {args:?}: {err}");
    let lines: Vec<_> = err.lines().filter(|l| !l.trim().is_empty()).collect();
    assert_eq!(lines.len(), 1, "not one line: {err}");
    lines[0].to_string()
}

/// The rows of a CSV file (a sweep's results.csv) as maps column → text.
pub fn read_csv(path: &std::path::Path) -> Vec<std::collections::HashMap<String, String>> {
    let mut r = csv::Reader::from_path(path).unwrap();
    let header: Vec<String> = r.headers().unwrap().iter().map(str::to_string).collect();
    r.records()
        .map(|rec| {
            header
                .iter()
                .cloned()
                .zip(rec.unwrap().iter().map(str::to_string))
                .collect()
        })
        .collect()
}

/// Run the sweep `file` into `out` as CSV: the JSON summary and the rows.
pub fn sweep_csv(
    file: &std::path::Path,
    out: &std::path::Path,
) -> (Value, Vec<std::collections::HashMap<String, String>>) {
    let v = run_json(&[
        "sweep",
        file.to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
        "--format",
        "csv",
    ]);
    (v, read_csv(&out.join("results.csv")))
}

/// A CSV row's value of `key` as a number.
pub fn cell(row: &std::collections::HashMap<String, String>, key: &str) -> f64 {
    row[key]
        .parse()
        .unwrap_or_else(|_| panic!("{key} = {:?}", row[key]))
}
