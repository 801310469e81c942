//! Fuzz harness of the command line, in-process (docs/RELIABILITY.md): generated argument
//! vectors parsed by the real parser ([`Cli`]) and, for the commands that write no folder
//! (`hertz`, `solve`, `traction`, `friction`), dispatched by [`commands::run`] into a buffer.
//! `tests/fuzz.rs` spawns the binary on a bounded number of them.
//!
//! Properties: never a panic; a parser error has exit status 2 (0 for `--help` and
//! `--version`); a failed run has status 2 (bad input) or 1 and a non-empty message; what a
//! run prints holds no NaN or infinity. `KONTAKT_FUZZ_CASES=N` sets the number of inputs.

#![allow(clippy::unwrap_used)] // tests: a panic is a failure with its message

use crate::cli::Cli;
use crate::commands;
use clap::Parser;
use proptest::prelude::*;
use proptest::test_runner::{Config, FileFailurePersistence};

fn config(default: u32) -> Config {
    Config {
        cases: std::env::var("KONTAKT_FUZZ_CASES")
            .ok()
            .and_then(|s| s.trim().parse().ok())
            .unwrap_or(default),
        failure_persistence: Some(Box::new(FileFailurePersistence::Off)),
        max_shrink_iters: 2000,
        ..Config::default()
    }
}

fn example(name: &str) -> String {
    format!("{}/../../examples/{name}", env!("CARGO_MANIFEST_DIR"))
}

/// A word of an argument vector: subcommands, every flag, values of every kind.
pub fn word() -> impl Strategy<Value = String> {
    let flags = prop::sample::select(vec![
        "--body1-radii",
        "--body2-radii",
        "--angle-deg",
        "--e1",
        "--nu1",
        "--e2",
        "--nu2",
        "--force",
        "--approach",
        "--yield-stress",
        "--criterion",
        "--json",
        "--csv",
        "--map",
        "--plot",
        "--stribeck",
        "--density",
        "--out",
        "--cells",
        "--pairing",
        "--rpm",
        "--steps",
        "--backends",
        "--format",
        "--threads",
        "--max-cases",
        "--quiet",
        "--help",
        "--version",
        "-h",
        "-V",
        "--",
        "-",
        "--force=",
        "--e1=-1",
        "--body1-radii=1,1",
        "--unknown",
    ])
    .prop_map(str::to_string);
    let numbers = prop::sample::select(vec![
        "0",
        "-0",
        "1",
        "-1",
        "10",
        "10,10",
        "inf,inf",
        "-inf",
        "inf",
        "nan",
        "NaN",
        "1e308",
        "1e309",
        "-1e309",
        "5e-324",
        "1e-300",
        "0.5",
        "1,",
        ",",
        ",,",
        "1,2,3",
        "0x10",
        "1_000",
        "99999999999999999999",
        "1.5.5",
        " 1",
        "",
        "1,nan",
        "inf,-inf",
        "1e300,1e300",
        "von-mises",
        "tresca",
        "parquet",
        "csv",
        "hertz,pimp",
        "δ",
    ])
    .prop_map(str::to_string);
    let number = fuzz_float().prop_map(|x| x.to_string());
    prop_oneof![
        4 => flags,
        4 => numbers,
        2 => number,
        1 => any::<String>(),
    ]
}

fn fuzz_float() -> impl Strategy<Value = f64> {
    prop_oneof![
        Just(f64::NAN),
        Just(f64::INFINITY),
        Just(f64::NEG_INFINITY),
        Just(-0.0),
        Just(5e-324),
        Just(1e-300),
        Just(1e300),
        any::<f64>(),
        -1e4..1e4f64,
    ]
}

/// An argument vector: a subcommand (or none, or a wrong one) and words.
pub fn argv() -> impl Strategy<Value = Vec<String>> {
    let command = prop::sample::select(vec![
        "hertz", "hertz", "hertz", "solve", "traction", "friction", "demo", "validate", "mbs",
        "sweep", "bearing", "help", "", "solv",
    ]);
    (command, prop::collection::vec(word(), 0..12), 0..5usize).prop_map(|(c, words, file)| {
        let mut v = vec!["kontakt".to_string()];
        if !c.is_empty() {
            v.push(c.to_string());
        }
        if matches!(c, "solve" | "traction" | "friction" | "sweep" | "bearing") {
            let f = [
                example("ball_on_flat.toml"),
                example("traction_twin_disc.toml"),
                example("nonexistent.toml"),
                example("data/wavy_sphere_gap.csv"),
                example("bearing_32216.toml"),
            ];
            v.push(f[file].clone());
        }
        v.extend(words);
        v
    })
}

/// Whether running `cli` in-process is cheap and writes nothing outside the temp folder.
fn runnable(args: &[String]) -> bool {
    let cmd = args.get(1).map(String::as_str);
    matches!(cmd, Some("hertz" | "solve" | "traction" | "bearing"))
        && !args.iter().any(|a| {
            [
                "--csv",
                "--map",
                "--plot",
                "--stribeck",
                "--density",
                "--out",
            ]
            .iter()
            .any(|f| a.starts_with(f))
        })
}

/// Parse and, where cheap, run `args`; check the properties.
pub fn check(args: &[String]) {
    match Cli::try_parse_from(args) {
        Err(e) => {
            let code = e.exit_code();
            // A missing subcommand shows the help as a usage error (status 2).
            let help = matches!(
                e.kind(),
                clap::error::ErrorKind::DisplayHelp | clap::error::ErrorKind::DisplayVersion
            );
            assert_eq!(code, if help { 0 } else { 2 }, "{args:?}: {e}");
            assert!(!e.to_string().trim().is_empty(), "{args:?}");
        }
        Ok(cli) => {
            if !runnable(args) {
                return;
            }
            let mut out = Vec::new();
            match commands::run(&cli, &mut out) {
                Err(err) => {
                    let code = crate::exit_code(&err);
                    let message = crate::one_line(&format!("{err:#}"));
                    assert!(!message.is_empty(), "{args:?}");
                    assert!(code == 1 || code == 2, "{args:?}: {code}");
                }
                Ok(()) => {
                    let text = String::from_utf8(out).unwrap();
                    // `inf` is how the reports write a flat body's radius (a string in
                    // JSON): look for NaN, and for valid JSON where JSON was asked for.
                    let found = text
                        .split(|c: char| !c.is_alphanumeric())
                        .any(|w| w == "NaN");
                    assert!(!found, "{args:?}: NaN in the output:\n{text}");
                    if args.iter().any(|a| a == "--json") {
                        let v: std::result::Result<serde_json::Value, _> =
                            serde_json::from_str(&text);
                        assert!(v.is_ok(), "{args:?}: not JSON:\n{text}");
                    }
                }
            }
        }
    }
}

proptest! {
    #![proptest_config(config(10_000))]

    /// Argument vectors, parsed in-process and run where cheap.
    #[test]
    fn argument_vectors(args in argv()) {
        check(&args);
    }

    /// `hertz` with every flag given a hostile number.
    #[test]
    fn hertz_numbers(r1 in (fuzz_float(), fuzz_float()), r2 in (fuzz_float(), fuzz_float()),
                     e1 in fuzz_float(), nu1 in fuzz_float(), f in fuzz_float(), y in fuzz_float(),
                     angle in fuzz_float(), approach in any::<bool>(), json in any::<bool>()) {
        let mut args: Vec<String> = vec![
            "kontakt".into(), "hertz".into(),
            format!("--body1-radii={},{}", r1.0, r1.1),
            format!("--body2-radii={},{}", r2.0, r2.1),
            format!("--e1={e1}"), format!("--nu1={nu1}"),
            format!("--angle-deg={angle}"), format!("--yield-stress={y}"),
            format!("{}={f}", if approach { "--approach" } else { "--force" }),
        ];
        if json {
            args.push("--json".into());
        }
        check(&args);
    }
}
