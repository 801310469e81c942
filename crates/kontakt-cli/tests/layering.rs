//! `tools/check-layering.sh` on the CLI crate (issue 30, item 21): the crate passes, and a
//! cycle between two sibling submodules, as `commands/friction.rs` and `commands/pimp.rs`
//! had, fails the check.

#![allow(clippy::unwrap_used)] // tests: a panic is a failure with its message

use std::path::{Path, PathBuf};
use std::process::Command;

fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../..")
}

fn check(krate: &Path) -> (bool, String) {
    let out = Command::new("bash")
        .arg(root().join("tools/check-layering.sh"))
        .arg(krate)
        .output()
        .unwrap();
    (
        out.status.success(),
        String::from_utf8_lossy(&out.stdout).into_owned(),
    )
}

#[test]
fn the_cli_crate_has_no_import_cycle() {
    let (ok, out) = check(Path::new("crates/kontakt-cli"));
    assert!(ok, "{out}");
    // file grain: the report lists each subcommand's file (its column is padded to the
    // longest module name, so match the name and the arrow, not the spacing)
    assert!(
        out.lines()
            .any(|l| l.trim_start().starts_with("commands/friction ") && l.contains("->")),
        "file grain: {out}"
    );
}

#[test]
fn a_cycle_between_sibling_subcommands_fails_the_check() {
    let dir = std::env::temp_dir().join(format!("kontakt-layering-{}", std::process::id()));
    let commands = dir.join("src/commands");
    std::fs::create_dir_all(&commands).unwrap();
    std::fs::write(dir.join("src/main.rs"), "mod commands;\nfn main() {}\n").unwrap();
    std::fs::write(
        commands.join("mod.rs"),
        "pub mod friction;\npub mod pimp;\npub struct InputError;\n",
    )
    .unwrap();
    // The old shape: friction drew with pimp's helpers, pimp's demo ran friction's study.
    std::fs::write(
        commands.join("friction.rs"),
        "use crate::commands::InputError;\npub fn demo_study() { crate::commands::pimp::axis_name(); }\n",
    )
    .unwrap();
    std::fs::write(
        commands.join("pimp.rs"),
        "use crate::commands::{InputError, friction::demo_study};\npub fn axis_name() {}\n",
    )
    .unwrap();
    let (ok, out) = check(&dir);
    std::fs::remove_dir_all(&dir).unwrap();
    assert!(!ok, "{out}");
    // the cycle is reported from whichever of the two the search reaches first
    assert!(
        out.contains("import cycle: commands/friction -> commands/pimp -> commands/friction")
            || out.contains("import cycle: commands/pimp -> commands/friction -> commands/pimp"),
        "{out}"
    );
}
