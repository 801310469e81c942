#![allow(clippy::unwrap_used)]
//! The README's console blocks are the program's real output: every `$ kontakt ...` (or
//! `$ cargo run --release -p kontakt-cli -- ...`) line of a ```` ```console ```` block is run
//! in a scratch directory that holds the repository's `examples/`, and what it prints
//! (standard output, then standard error) must equal the lines that follow it in the README,
//! up to trailing spaces. A block line starting with `error:` expects exit status 2.
//! A block whose last line is `...` shows the first lines of a longer output: those must
//! equal the program's first lines. README blocks must therefore be deterministic: no timings.

use std::path::{Path, PathBuf};
use std::process::Command;

fn root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../..")
}

/// `(command arguments, expected output lines)` of every console block command.
fn console_commands(readme: &str) -> Vec<(Vec<String>, Vec<String>)> {
    let mut out = Vec::new();
    let mut in_block = false;
    let mut current: Option<(Vec<String>, Vec<String>)> = None;
    for line in readme.lines() {
        if !in_block {
            in_block = line.trim_start() == "```console";
            continue;
        }
        if line.trim_start().starts_with("```") {
            in_block = false;
            out.extend(current.take());
            continue;
        }
        if let Some(cmd) = line.strip_prefix("$ ") {
            out.extend(current.take());
            let args = cmd
                .strip_prefix("cargo run --release -p kontakt-cli -- ")
                .or_else(|| cmd.strip_prefix("kontakt "))
                .unwrap_or_else(|| panic!("README command not understood: {cmd}"));
            let args = args.split_whitespace().map(str::to_string).collect();
            current = Some((args, Vec::new()));
        } else if let Some((_, expected)) = current.as_mut() {
            expected.push(line.trim_end().to_string());
        }
    }
    out
}

#[test]
fn readme_console_blocks_are_real_output() {
    let readme = std::fs::read_to_string(root().join("README.md")).unwrap();
    let commands = console_commands(&readme);
    assert!(commands.len() >= 6, "{} console commands", commands.len());
    let dir = std::env::temp_dir().join(format!("kontakt-readme-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let examples = dir.join("examples");
    if !examples.exists() {
        std::os::unix::fs::symlink(root().join("examples").canonicalize().unwrap(), &examples)
            .unwrap();
    }
    let mut failures = Vec::new();
    for (args, expected) in &commands {
        let out = Command::new(env!("CARGO_BIN_EXE_kontakt"))
            .args(args)
            .current_dir(&dir)
            .output()
            .unwrap();
        let text = format!(
            "{}{}",
            String::from_utf8_lossy(&out.stdout),
            String::from_utf8_lossy(&out.stderr)
        );
        let actual: Vec<String> = text.lines().map(|l| l.trim_end().to_string()).collect();
        let wants_error = expected.first().is_some_and(|l| l.starts_with("error:"));
        let code = out.status.code();
        if wants_error != (code == Some(2)) || (!wants_error && code != Some(0)) {
            failures.push(format!("kontakt {}: exit status {code:?}", args.join(" ")));
        }
        // a block that ends in "..." shows the first lines of a long output
        let (expected, actual) = match expected.split_last() {
            Some((last, head)) if last == "..." => (head, &actual[..actual.len().min(head.len())]),
            _ => (&expected[..], &actual[..]),
        };
        if actual != expected {
            let first = actual
                .iter()
                .zip(expected)
                .position(|(a, e)| a != e)
                .unwrap_or(actual.len().min(expected.len()));
            failures.push(format!(
                "kontakt {}: line {} differs\n  README:  {:?}\n  program: {:?}\n  ({} lines printed, {} in the README)",
                args.join(" "),
                first + 1,
                expected.get(first),
                actual.get(first),
                actual.len(),
                expected.len()
            ));
        }
    }
    let _ = std::fs::remove_dir_all(&dir);
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}

#[test]
fn the_parser_reads_commands_and_their_output() {
    let text = "x\n```console\n$ kontakt a b\nline 1  \nline 2\n$ kontakt c\n```\n```console\n$ cargo run --release -p kontakt-cli -- d\n```\n";
    let c = console_commands(text);
    assert_eq!(c.len(), 3);
    assert_eq!(c[0].0, ["a", "b"]);
    assert_eq!(c[0].1, ["line 1", "line 2"]);
    assert!(c[1].1.is_empty());
    assert_eq!(c[2].0, ["d"]);
}

/// The examples that `kontakt --help` shows run as printed (in a scratch directory that
/// holds the repository's `examples/`), each exiting with status 0.
#[test]
fn help_examples_run() {
    let help = Command::new(env!("CARGO_BIN_EXE_kontakt"))
        .arg("--help")
        .output()
        .unwrap();
    let help = String::from_utf8(help.stdout).unwrap();
    let examples: Vec<&str> = help
        .lines()
        .skip_while(|l| !l.starts_with("Examples:"))
        .skip(1)
        .take_while(|l| !l.trim().is_empty())
        .map(str::trim)
        .collect();
    assert!(examples.len() >= 8, "{help}");
    let dir = std::env::temp_dir().join(format!("kontakt-help-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    std::os::unix::fs::symlink(
        root().join("examples").canonicalize().unwrap(),
        dir.join("examples"),
    )
    .unwrap();
    for line in &examples {
        let args: Vec<&str> = line
            .strip_prefix("kontakt ")
            .unwrap()
            .split_whitespace()
            .collect();
        let out = Command::new(env!("CARGO_BIN_EXE_kontakt"))
            .args(&args)
            .current_dir(&dir)
            .output()
            .unwrap();
        assert!(
            out.status.success(),
            "{line}: {}",
            String::from_utf8_lossy(&out.stderr)
        );
    }
    let _ = std::fs::remove_dir_all(&dir);
}

/// A case given to the wrong subcommand is named by its kind, with the subcommand that
/// runs it, and exits with status 2 (not an unknown-field error of the other schema).
#[test]
fn wrong_subcommand_names_the_case_kind() {
    let examples = root().join("examples");
    for (sub, file, kind, runner) in [
        ("traction", "ball_on_flat.toml", "hertz", "kontakt solve"),
        ("traction", "bem_torus_torus.toml", "bem", "kontakt solve"),
        (
            "traction",
            "rib_friction.toml",
            "friction",
            "kontakt friction",
        ),
        (
            "friction",
            "roller_rib_torus_torus.toml",
            "pimp",
            "kontakt solve",
        ),
        (
            "friction",
            "traction_twin_disc.toml",
            "traction",
            "kontakt traction",
        ),
    ] {
        let out = Command::new(env!("CARGO_BIN_EXE_kontakt"))
            .args([sub, examples.join(file).to_str().unwrap()])
            .output()
            .unwrap();
        let err = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(2), "{sub} {file}: {err}");
        assert!(
            err.contains(&format!("method = \"{kind}\" case"))
                && err.contains(runner)
                && err.lines().count() == 1,
            "{sub} {file}: {err}"
        );
    }
}
