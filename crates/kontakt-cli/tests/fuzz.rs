//! Fuzz harness of the `kontakt` binary (docs/RELIABILITY.md): generated argument vectors
//! run as processes, a bounded number (spawning is slow; `src/fuzz.rs` parses and runs many
//! more in-process). Properties: the process exits with 0, 1 or 2, never by a panic (101)
//! or a signal; status 2 comes with a message on stderr.
//! `KONTAKT_FUZZ_SPAWNS=N` sets the number of processes.

#![allow(clippy::unwrap_used)] // tests: a panic is a failure with its message

use proptest::prelude::*;
use proptest::test_runner::{Config, FileFailurePersistence, TestRunner};
use std::process::Command;

fn word() -> impl Strategy<Value = String> {
    prop_oneof![
        prop::sample::select(vec![
            "--body1-radii",
            "--body2-radii",
            "--angle-deg",
            "--e1",
            "--nu2",
            "--force",
            "--approach",
            "--yield-stress",
            "--criterion",
            "--json",
            "--cells",
            "--steps",
            "--threads",
            "--max-cases",
            "--help",
            "-V",
            "0",
            "-1",
            "10,10",
            "inf,inf",
            "nan",
            "1e309",
            "5e-324",
            ",",
            "1,2,3",
            "tresca",
            "δ",
            "",
        ])
        .prop_map(str::to_string),
        any::<f64>().prop_map(|x| x.to_string()),
        any::<String>().prop_map(|s| s.replace('\0', "")),
    ]
}

#[test]
fn binary_argument_vectors() {
    let n = std::env::var("KONTAKT_FUZZ_SPAWNS")
        .ok()
        .and_then(|s| s.parse().ok())
        .unwrap_or(300);
    let mut runner = TestRunner::new(Config {
        cases: n,
        failure_persistence: Some(Box::new(FileFailurePersistence::Off)),
        max_shrink_iters: 200,
        ..Config::default()
    });
    let commands = prop::sample::select(vec!["hertz", "hertz", "solve", "traction", "bogus"]);
    runner
        .run(
            &(commands, prop::collection::vec(word(), 0..10)),
            |(command, words)| {
                let out = Command::new(env!("CARGO_BIN_EXE_kontakt"))
                    .arg(command)
                    .args(&words)
                    .env("NO_COLOR", "1")
                    .output()
                    .unwrap();
                let code = out.status.code();
                prop_assert!(
                    matches!(code, Some(0..=2)),
                    "{command} {words:?}: status {:?}\n{}",
                    out.status,
                    String::from_utf8_lossy(&out.stderr)
                );
                if code == Some(2) {
                    prop_assert!(!out.stderr.is_empty(), "{command} {words:?}: no message");
                }
                Ok(())
            },
        )
        .unwrap();
}
