//! Compile and run a C program of `examples/c/` against `include/kontakt.h` and the static
//! library that `cargo test` builds next to the test (`target/<profile>/libkontakt_capi.a`),
//! with the system C compiler (`cc`, or `$CC`); parse its `== label` sections of
//! `key value...` lines. Shared by the tests of the C examples.

#![allow(dead_code)] // each test uses what it needs

use std::collections::BTreeMap;
use std::ffi::OsStr;
use std::path::{Path, PathBuf};
use std::process::Command;

/// `target/<profile>`: a test runs from `target/<profile>/deps`.
fn profile_dir() -> PathBuf {
    let exe = std::env::current_exe().unwrap();
    exe.parent().unwrap().parent().unwrap().to_path_buf()
}

/// The newest of the static libraries cargo leaves in the profile: `cargo test` writes
/// `deps/libkontakt_capi.a`, `cargo build` also copies one to the profile directory, which a
/// later `cargo test` does not refresh (a stale copy lacks the newest functions).
fn static_lib() -> PathBuf {
    let dir = profile_dir();
    let newest = [
        dir.join("libkontakt_capi.a"),
        dir.join("deps/libkontakt_capi.a"),
    ]
    .into_iter()
    .filter_map(|p| Some((p.metadata().ok()?.modified().ok()?, p)))
    .max_by_key(|(t, _)| *t);
    if let Some((_, p)) = newest {
        return p;
    }
    panic!(
        "no libkontakt_capi.a in {} (cargo test -p kontakt-capi builds it with the library)",
        dir.display()
    );
}

/// Compile `examples/c/<source>` (C99, all warnings as errors), run it with `args`; its
/// standard output.
pub fn run_c_program(source: &str, args: &[&OsStr]) -> String {
    let crate_dir = Path::new(env!("CARGO_MANIFEST_DIR"));
    let stem = source.trim_end_matches(".c");
    let exe = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join(format!("kontakt_c_{stem}"));
    let cc = std::env::var("CC").unwrap_or_else(|_| "cc".into());
    let out = Command::new(&cc)
        .args(["-std=c99", "-Wall", "-Wextra", "-Werror", "-O1"])
        .arg("-I")
        .arg(crate_dir.join("include"))
        .arg(crate_dir.join("examples/c").join(source))
        .arg(static_lib())
        .args(["-lpthread", "-ldl", "-lm"])
        .arg("-o")
        .arg(&exe)
        .output()
        .unwrap_or_else(|e| panic!("cannot run the C compiler `{cc}`: {e}"));
    assert!(
        out.status.success(),
        "{cc} failed:\n{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let run = Command::new(&exe).args(args).output().unwrap();
    let stdout = String::from_utf8(run.stdout).unwrap();
    assert!(
        run.status.success(),
        "the example failed:\n{stdout}\n{}",
        String::from_utf8_lossy(&run.stderr)
    );
    stdout
}

/// One section's printed lines: key → the rest of the line.
pub type Section = BTreeMap<String, String>;

/// The `== label` sections of a program's output.
pub fn sections(stdout: &str) -> BTreeMap<String, Section> {
    let mut all = BTreeMap::new();
    let mut current: Option<(String, Section)> = None;
    for line in stdout.lines() {
        if let Some(label) = line.strip_prefix("== ") {
            if let Some((l, s)) = current.take() {
                all.insert(l, s);
            }
            current = Some((label.to_string(), Section::new()));
        } else if let Some((_, s)) = current.as_mut() {
            let (k, v) = line.split_once(' ').unwrap_or((line, ""));
            s.insert(k.to_string(), v.to_string());
        }
    }
    if let Some((l, s)) = current {
        all.insert(l, s);
    }
    all
}

/// The numbers of `key` in a section.
pub fn numbers(s: &Section, key: &str) -> Vec<f64> {
    s.get(key)
        .unwrap_or_else(|| panic!("no `{key}` in {s:?}"))
        .split_whitespace()
        .map(|x| x.parse().unwrap())
        .collect()
}
