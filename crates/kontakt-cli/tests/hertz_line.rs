#![allow(clippy::unwrap_used)] // test helpers: a panic is a test failure with its message
//! `kontakt hertz` line contacts (issue 30 item 20): `--length` and `--line-load` build the
//! same case as a file's `[contact] kind = "line"`, `length_mm`, `[load]
//! line_load_n_per_mm`, so the flags give the file's report; bad values name the flag.

mod support;

use support::{bad, example, run_json};

/// The flags reproduce `kontakt solve examples/roller_line.toml` (every key but the name),
/// and the line load alone gives the same pressure and half-width (length-free results).
#[test]
fn line_flags_give_the_case_files_report() {
    let flags = run_json(&[
        "hertz",
        "--body1-radii",
        "3.25",
        "--body2-radii",
        "15.75",
        "--length",
        "8",
        "--force",
        "2000",
        "--yield-stress",
        "1800",
        "--criterion",
        "tresca",
    ]);
    let mut file = run_json(&["solve", example("roller_line.toml").to_str().unwrap()]);
    assert_eq!(flags["kind"], "line");
    file["name"] = flags["name"].clone();
    assert_eq!(flags, file);
    let by_load = run_json(&[
        "hertz",
        "--body1-radii",
        "3.25",
        "--body2-radii",
        "15.75",
        "--line-load",
        "250",
    ]);
    for key in ["max_pressure_mpa", "half_width_mm", "line_load_n_per_mm"] {
        assert_eq!(by_load[key], flags[key], "{key}");
    }
}

#[test]
fn line_flag_errors_name_the_flag() {
    let base = ["hertz", "--body1-radii", "3.25", "--body2-radii", "15.75"];
    for (extra, expect) in [
        (
            &["--length", "-8", "--force", "2000"][..],
            "invalid --length = -8",
        ),
        (&["--line-load", "0"][..], "invalid --line-load = 0"),
        (
            &["--line-load", "250", "--angle-deg", "3"][..],
            "invalid --angle-deg = 3",
        ),
        (
            &["--line-load", "250", "--force", "3"][..],
            "cannot be used with",
        ),
        (
            &["--force", "2000", "--line-load", "inf"][..],
            "cannot be used with",
        ),
    ] {
        let args: Vec<&str> = base.iter().copied().chain(extra.iter().copied()).collect();
        let e = bad(&args);
        assert!(e.contains(expect), "{extra:?}: {e}");
    }
    let e = bad(&[
        "hertz",
        "--body1-radii",
        "3.25,3",
        "--body2-radii",
        "15.75",
        "--length",
        "8",
        "--force",
        "10",
    ]);
    assert!(e.contains("invalid --body1-radii"), "{e}");
}
