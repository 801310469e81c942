//! Refactoring guard: every example's JSON report, the demo's `results.csv` and the
//! `hertz --json` report of the README are compared with baselines recorded before the
//! code was reorganised (`tests/reports/`). Values must be *identical* (bit for bit, as
//! serde_json prints them); a report may only gain keys that are listed in `reports/new_keys.txt`
//! (such as a solver's termination status). The validation study's CSV is compared the
//! same way by `.ci/run` (it takes a minute in the test profile).
//!
//! To record new baselines after a deliberate change of results, run with
//! `KONTAKT_BLESS=1` and say why in the commit.

#![allow(clippy::unwrap_used)] // test helpers: a panic is a test failure with its message

use assert_cmd::Command;
use serde_json::Value;
use std::path::{Path, PathBuf};

/// Keys that a report may gain over its baseline (anywhere in the tree).
/// The keys a report may gain over its baseline, shared with the Python comparison.
const NEW_KEYS_FILE: &str = include_str!("reports/new_keys.txt");

fn new_keys() -> impl Iterator<Item = &'static str> {
    NEW_KEYS_FILE
        .lines()
        .map(str::trim)
        .filter(|l| !l.is_empty() && !l.starts_with('#'))
}

fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../..")
}

fn baselines() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("tests/reports")
}

fn bless() -> bool {
    std::env::var_os("KONTAKT_BLESS").is_some()
}

fn run(args: &[&str], cwd: &Path) -> Vec<u8> {
    let out = Command::cargo_bin("kontakt")
        .expect("binary built")
        .args(args)
        .current_dir(cwd)
        .output()
        .expect("runs");
    assert!(
        out.status.success(),
        "kontakt {args:?}: {}",
        String::from_utf8_lossy(&out.stderr)
    );
    out.stdout
}

/// `new` must hold every key of `old` with an identical value; extra keys only from `new_keys()`.
fn superset(old: &Value, new: &Value, path: &str, errors: &mut Vec<String>) {
    match (old, new) {
        (Value::Object(o), Value::Object(n)) => {
            for (k, v) in o {
                match n.get(k) {
                    Some(nv) => superset(v, nv, &format!("{path}.{k}"), errors),
                    None => errors.push(format!("{path}.{k}: missing")),
                }
            }
            for k in n.keys() {
                if !o.contains_key(k) && !new_keys().any(|x| x == k) {
                    errors.push(format!("{path}.{k}: new key not in reports/new_keys.txt"));
                }
            }
        }
        (Value::Array(o), Value::Array(n)) => {
            if o.len() != n.len() {
                errors.push(format!("{path}: length {} -> {}", o.len(), n.len()));
            } else {
                for (i, (a, b)) in o.iter().zip(n).enumerate() {
                    superset(a, b, &format!("{path}[{i}]"), errors);
                }
            }
        }
        (a, b) if a == b => {}
        (a, b) => errors.push(format!("{path}: {a} -> {b}")),
    }
}

fn check_json(name: &str, stdout: &[u8]) {
    let file = baselines().join(format!("{name}.json"));
    let new: Value = serde_json::from_slice(stdout).expect("valid JSON");
    if bless() {
        std::fs::write(&file, serde_json::to_string_pretty(&new).unwrap()).unwrap();
        return;
    }
    let old: Value = serde_json::from_str(
        &std::fs::read_to_string(&file).unwrap_or_else(|e| panic!("{}: {e}", file.display())),
    )
    .unwrap();
    let mut errors = Vec::new();
    superset(&old, &new, name, &mut errors);
    assert!(
        errors.is_empty(),
        "{name}: report changed:\n{}",
        errors.join("\n")
    );
}

#[test]
fn every_example_report_is_unchanged() {
    let mut examples: Vec<PathBuf> = std::fs::read_dir(root().join("examples"))
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|x| x == "toml"))
        .collect();
    examples.sort();
    assert!(examples.len() >= 12, "examples found: {}", examples.len());
    for path in examples {
        let stem = path.file_stem().unwrap().to_str().unwrap().to_string();
        let out = run(&["solve", path.to_str().unwrap(), "--json"], &root());
        check_json(&format!("solve_{stem}"), &out);
    }
}

#[test]
fn readme_hertz_report_is_unchanged() {
    let out = run(
        &[
            "hertz",
            "--body1-radii",
            "3.969,3.969",
            "--body2-radii",
            "15.281,-4.128",
            "--force",
            "1000",
            "--yield-stress",
            "1800",
            "--json",
        ],
        &root(),
    );
    check_json("hertz_readme", &out);
}

#[test]
fn demo_results_are_unchanged() {
    let dir = std::env::temp_dir().join(format!("kontakt-reports-demo-{}", std::process::id()));
    run(&["demo", "--out", dir.to_str().unwrap()], &root());
    for file in ["results.csv", "traction.csv"] {
        let new = std::fs::read_to_string(dir.join(file)).unwrap();
        let base = baselines().join(format!("demo_{file}"));
        if bless() {
            std::fs::write(&base, &new).unwrap();
            continue;
        }
        let old = std::fs::read_to_string(&base).unwrap();
        for (i, (a, b)) in old.lines().zip(new.lines()).enumerate() {
            assert_eq!(a, b, "demo {file} line {}", i + 1);
        }
        assert_eq!(old.lines().count(), new.lines().count(), "demo {file} rows");
    }
    let _ = std::fs::remove_dir_all(&dir);
}
