//! Every error names what the user typed (issue 30, item 10): the flag or the case-file
//! key with the value as given, never a library field, a derived quantity or a value in
//! other units.

#![allow(clippy::unwrap_used)] // tests: a panic is a failure with its message

mod support;
use std::path::{Path, PathBuf};
use support::{bad, example, kontakt, tempdir};

/// A copy of the example `name` with `from` replaced by `to`, in a fresh folder.
fn edited(name: &str, from: &str, to: &str) -> PathBuf {
    let text = std::fs::read_to_string(example(name)).unwrap();
    assert!(text.contains(from), "{name} has no {from}");
    let dir = tempdir(
        "input-names",
        &format!("{}-{}", name.trim_end_matches(".toml"), to.len()),
    );
    let path = dir.join(name);
    std::fs::write(&path, text.replacen(from, to, 1)).unwrap();
    path
}

fn path(p: &Path) -> &str {
    p.to_str().unwrap()
}

const HERTZ: [&str; 5] = [
    "hertz",
    "--body1-radii",
    "10,10",
    "--body2-radii",
    "inf,inf",
];

/// `--e1 5e-324` (a subnormal modulus) overflowed the contact and was blamed on `--force`.
#[test]
fn a_subnormal_modulus_is_the_modulus() {
    for flag in ["--e1", "--e2"] {
        let mut args = HERTZ.to_vec();
        args.extend([flag, "5e-324", "--force", "500"]);
        let l = bad(&args);
        assert!(
            l.starts_with(&format!("error: invalid {flag} = 5e-324: ")),
            "{l}"
        );
    }
}

/// Every numeric flag of `kontakt hertz` (read from its help), set to values at and
/// beyond its range, fails naming a flag of the command (the CLI's counterpart of
/// kontakt-case's tests/keys.rs).
#[test]
fn hertz_errors_name_a_flag() {
    let help = kontakt().args(["hertz", "--help"]).output().unwrap();
    let help = String::from_utf8(help.stdout).unwrap();
    // `      --e1 <MPA>   Young's modulus ...`: the flags, and those that take a number.
    let options: Vec<(&str, bool)> = help
        .lines()
        .filter_map(|l| l.trim_start().strip_prefix("--"))
        .map(|l| {
            let mut words = l.split_whitespace();
            let flag = words.next().unwrap();
            let numeric = words.next().is_some_and(|v| v.starts_with('<'))
                && !l.contains("possible values")
                && !flag.ends_with("radii");
            (flag, numeric)
        })
        .collect();
    let flags: Vec<String> = options.iter().map(|(f, _)| format!("--{f}")).collect();
    let numeric: Vec<&String> = options
        .iter()
        .zip(&flags)
        .filter_map(|((_, n), f)| n.then_some(f))
        .collect();
    assert!(numeric.len() >= 8, "{numeric:?}");
    let mut tried = 0;
    for flag in numeric {
        for value in ["-1", "0", "nan", "inf", "5e-324", "1e308", "-1e308"] {
            let mut args = HERTZ.to_vec();
            args.extend([flag.as_str(), value]);
            // The load flags exclude each other: each is tried alone.
            if !["--force", "--approach", "--line-load"].contains(&flag.as_str()) {
                args.extend(["--force", "500"]);
            }
            let out = kontakt().args(&args).output().unwrap();
            if out.status.success() {
                continue;
            }
            tried += 1;
            let err = String::from_utf8(out.stderr).unwrap();
            assert_eq!(out.status.code(), Some(2), "{args:?}: {err}");
            let named = err
                .trim()
                .strip_prefix("error: invalid ")
                .or_else(|| err.trim().strip_prefix("error: "))
                .unwrap();
            let name = named.split([' ', ':']).next().unwrap();
            assert!(
                name.split('/').all(|f| flags.iter().any(|g| g == f)),
                "{args:?}: names `{name}`: {err}"
            );
        }
    }
    assert!(tried > 30, "{tried}");
}

/// `half_angle_deg = 90` was reported as 1.5707963267948966 against a range in radians.
#[test]
fn a_cone_half_angle_in_degrees() {
    let case = edited(
        "pimp_sphere_on_torus.toml",
        "shape = \"torus\"\nmajor_mm = 30.0\nminor_mm = 20.0",
        "shape = \"cone\"\nhalf_angle_deg = 90.0",
    );
    let l = bad(&["solve", path(&case)]);
    assert!(
        l.contains("invalid geometry.body2.half_angle_deg = 90: expected")
            && l.contains("(0, 90) deg"),
        "{l}"
    );
    assert!(!l.contains("1.57") && !l.contains("rad"), "{l}");
}

/// `rollers.count = 1e9` ended as "invalid speed": the rollers do not fit the ring.
#[test]
fn a_roller_count_that_cannot_fit_is_the_count() {
    for count in ["1000000000", "22"] {
        let case = edited(
            "rib_friction.toml",
            "count = 17",
            &format!("count = {count}"),
        );
        let l = bad(&["friction", path(&case)]);
        assert!(
            l.contains(&format!(
                "invalid rollers.count = {count}: expected at most 21 rollers"
            )),
            "{l}"
        );
    }
}

/// `kontakt mbs --force 1e9` answered with the element's internals (`bodies: ...`, "use
/// GapSampling::Exact"): it names `--force`.
#[test]
fn mbs_names_the_force() {
    let out = tempdir("input-names", "mbs");
    let l = bad(&["mbs", "--force", "1e9", "--out", path(&out)]);
    assert!(
        l.starts_with("error: invalid --force = 1000000000: expected a rib load"),
        "{l}"
    );
    assert!(!l.contains("GapSampling"), "{l}");
}

/// A creepage range of -1e308 to 1e308 made a NaN creepage (max - min overflowed) and
/// errors named points of the range; they name the bound.
#[test]
fn a_creepage_range_names_its_bound() {
    let case = edited(
        "traction_ball_all_models.toml",
        "max = 0.008",
        "max = 1e308\nmin = -1e308",
    );
    let l = bad(&["traction", path(&case)]);
    assert!(l.contains("invalid creepage.min = -1e308: expected"), "{l}");
    assert!(!l.contains("NaN"), "{l}");
    let case = edited(
        "traction_ball_all_models.toml",
        "max = 0.008",
        "max = 1e308",
    );
    let l = bad(&["traction", path(&case)]);
    assert!(l.contains("invalid creepage.max = 1e308: expected"), "{l}");
}

/// A list of choices given twice (`models = ["fastsim", "fastsim"]`, `--backends
/// hertz,hertz`) gave duplicate columns; every list goes through one check that names the
/// key or flag (issue 30, item 12).
#[test]
fn a_choice_given_twice_is_refused() {
    let case = edited(
        "traction_ball_all_models.toml",
        "models = [\"carter\", \"kalker_linear\", \"fastsim\", \"kalker_exact\", \"asperity\"]",
        "models = [\"fastsim\", \"carter\", \"fastsim\"]",
    );
    let l = bad(&["traction", path(&case)]);
    assert!(
        l.ends_with("invalid models = fastsim,carter,fastsim: expected each of carter, kalker_linear, fastsim, kalker_exact, asperity at most once (fastsim is given twice)"),
        "{l}"
    );
    let case = edited(
        "rib_friction.toml",
        "models = [\"hertz\", \"pimp\", \"halfspace\"]",
        "models = [\"pimp\", \"pimp\"]",
    );
    let l = bad(&["friction", path(&case)]);
    assert!(
        l.contains(
            "invalid models = pimp,pimp: expected each of hertz, pimp, halfspace at most once"
        ),
        "{l}"
    );
    let out = tempdir("input-names", "mbs2");
    let l = bad(&["mbs", "--backends", "hertz,hertz", "--out", path(&out)]);
    assert!(
        l.starts_with("error: invalid --backends = hertz,hertz: expected each of"),
        "{l}"
    );
}

/// `kontakt validate --cells 8` failed at its first pairing although the help said
/// 8..=4096: the range is what runs, 12..=4096, and 12 runs.
#[test]
fn validate_runs_at_its_documented_minimum() {
    let help = kontakt().args(["validate", "--help"]).output().unwrap();
    assert!(
        String::from_utf8(help.stdout)
            .unwrap()
            .contains("12..=4096")
    );
    for cells in ["8", "11"] {
        let l = bad(&["validate", "--cells", cells]);
        assert!(
            l.starts_with(&format!(
                "error: invalid --cells = {cells}: expected 12..=4096"
            )),
            "{l}"
        );
    }
    let out = tempdir("input-names", "validate");
    let run = kontakt()
        .args(["validate", "--cells", "12", "--out", path(&out)])
        .output()
        .unwrap();
    assert!(
        run.status.success(),
        "{}",
        String::from_utf8_lossy(&run.stderr)
    );
    std::fs::remove_dir_all(&out).unwrap();
}
