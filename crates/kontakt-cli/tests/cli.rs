//! Behaviour of the `kontakt` binary: exit codes, one-line errors naming the flag or key,
//! JSON keys, and snapshots of the human output.

#![allow(clippy::unwrap_used)] // test helpers: a panic is a test failure with its message

use assert_cmd::Command;
use serde_json::Value;
use std::path::PathBuf;

fn kontakt() -> Command {
    Command::cargo_bin("kontakt").expect("binary built")
}

fn examples() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../../examples")
}

fn json(args: &[&str]) -> Value {
    let out = kontakt().args(args).arg("--json").output().expect("runs");
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    serde_json::from_slice(&out.stdout).expect("valid JSON")
}

/// Run, expect exit status 2 and exactly one stderr line; return it.
fn bad(args: &[&str]) -> String {
    let out = kontakt().args(args).output().expect("runs");
    assert_eq!(out.status.code(), Some(2), "args {args:?}");
    let err = String::from_utf8(out.stderr).expect("utf8");
    let lines: Vec<_> = err.lines().filter(|l| !l.trim().is_empty()).collect();
    assert_eq!(lines.len(), 1, "not one line: {err}");
    lines[0].to_string()
}

#[test]
fn hertz_json_has_the_stable_keys_and_right_values() {
    let v = json(&[
        "hertz",
        "--body1-radii",
        "6.35,6.35",
        "--body2-radii",
        "inf,inf",
        "--force",
        "100",
    ]);
    for key in [
        "semi_axes_mm",
        "max_pressure_mpa",
        "mean_pressure_mpa",
        "approach_mm",
        "contact_area_mm2",
        "stiffness_n_per_mm",
        "max_shear_stress_mpa",
        "max_shear_depth_mm",
        "e_star_mpa",
        "inputs",
        "kontakt_version",
        "schema_version",
    ] {
        assert!(v.get(key).is_some(), "missing {key}");
    }
    // Closed form: a = (3FR/4E*)^(1/3), p0 = 3F/(2 pi a^2).
    let e_star = 210_000.0 / 1.82;
    let a = (3.0f64 * 100.0 * 6.35 / (4.0 * e_star)).cbrt();
    let got_a = v["semi_axes_mm"][0].as_f64().unwrap();
    assert!((got_a / a - 1.0).abs() < 1e-12);
    let p0 = v["max_pressure_mpa"].as_f64().unwrap();
    assert!((p0 / (300.0 / (2.0 * std::f64::consts::PI * a * a)) - 1.0).abs() < 1e-12);
    // Huber: tau_max = 0.31 p0 near z = 0.48 a for nu = 0.3.
    let tau = v["max_shear_stress_mpa"].as_f64().unwrap();
    assert!((tau / p0 - 0.31).abs() < 0.005);
    assert_eq!(v["inputs"]["body2_radii_mm"][0], "inf");
    assert_eq!(v["kontakt_version"], env!("CARGO_PKG_VERSION"));
}

#[test]
fn hertz_by_approach_round_trips() {
    let by_force = json(&[
        "hertz",
        "--body1-radii",
        "10,20",
        "--body2-radii",
        "30,-80",
        "--angle-deg",
        "30",
        "--force",
        "500",
    ]);
    let delta = by_force["approach_mm"].as_f64().unwrap().to_string();
    let by_delta = json(&[
        "hertz",
        "--body1-radii",
        "10,20",
        "--body2-radii",
        "30,-80",
        "--angle-deg",
        "30",
        "--approach",
        &delta,
    ]);
    let f = by_delta["force_n"].as_f64().unwrap();
    assert!((f / 500.0 - 1.0).abs() < 1e-12, "{f}");
}

#[test]
fn bad_flags_name_the_flag_value_and_range() {
    let base = ["hertz", "--body1-radii", "5,5", "--body2-radii", "inf,inf"];
    let with = |extra: &[&str]| {
        let mut v: Vec<&str> = base.to_vec();
        v.extend_from_slice(extra);
        bad(&v)
    };
    assert_eq!(
        with(&["--force", "100", "--nu1", "0.7"]),
        "error: invalid --nu1 = 0.7: expected -1 < nu <= 0.5"
    );
    assert!(with(&["--force", "100", "--e2", "-5"]).starts_with("error: invalid --e2 = -5"));
    assert!(with(&["--force", "-1"]).starts_with("error: invalid --force = -1"));
    assert!(with(&["--approach", "0"]).starts_with("error: invalid --approach = 0"));
    assert!(
        with(&["--force", "1", "--yield-stress", "0"])
            .starts_with("error: invalid --yield-stress = 0")
    );
    assert!(with(&["--force", "nan"]).contains("--force"));
    // A ball that does not fit its groove.
    let l = bad(&[
        "hertz",
        "--body1-radii",
        "5,5",
        "--body2-radii",
        "-4,-4",
        "--force",
        "10",
    ]);
    assert!(
        l.contains("--body1-radii/--body2-radii") && l.contains("conformal or separate"),
        "{l}"
    );
    let l = bad(&[
        "hertz",
        "--body1-radii",
        "5",
        "--body2-radii",
        "inf,inf",
        "--force",
        "10",
    ]);
    assert!(l.contains("--body1-radii") && l.contains("2 radii"), "{l}");
    let l = bad(&[
        "hertz",
        "--body1-radii",
        "0,5",
        "--body2-radii",
        "inf,inf",
        "--force",
        "10",
    ]);
    assert!(l.starts_with("error: invalid --body1-radii"), "{l}");
    // Parallel cylinders are a line contact.
    let l = bad(&[
        "hertz",
        "--body1-radii",
        "inf,5",
        "--body2-radii",
        "inf,7",
        "--force",
        "10",
    ]);
    assert!(l.contains("line contact"), "{l}");
    // clap's own usage errors also exit 2 (missing load).
    let out = kontakt().args(base).output().unwrap();
    assert_eq!(out.status.code(), Some(2));
}

#[test]
fn help_states_units_and_ranges() {
    let out = kontakt().args(["hertz", "--help"]).output().unwrap();
    let help = String::from_utf8(out.stdout).unwrap();
    for s in [
        "[mm]",
        "[MPa]",
        "[N]",
        "[deg]",
        "-1 < nu <= 0.5",
        "> 0",
        "inf",
    ] {
        assert!(help.contains(s), "help lacks {s}");
    }
}

#[test]
fn every_example_solves() {
    let mut n = 0;
    for entry in std::fs::read_dir(examples()).unwrap() {
        let path = entry.unwrap().path();
        if path.extension().is_some_and(|e| e == "toml") {
            let v = json(&["solve", path.to_str().unwrap()]);
            // Friction and rough reports carry the pressure per row (model × speed, load);
            // impact reports in their normal impact; a whole bearing (the ISO/TS 16281 slice
            // law) gives roller loads, its contact pressures are a later step of issue 28; a
            // ball bearing gives the Hertz pressure of its most loaded ball.
            let p = v["max_pressure_mpa"]
                .as_f64()
                .or_else(|| v["rows"][0]["max_pressure_mpa"].as_f64())
                .or_else(|| v["normal"]["max_pressure_mpa"].as_f64())
                .or_else(|| v["max_roller_load_n"].as_f64())
                .or_else(|| v["max_inner_pressure_mpa"].as_f64());
            assert!(p.unwrap() > 0.0, "{}", path.display());
            n += 1;
        }
    }
    assert!(n >= 6);
}

#[test]
fn bad_case_files_fail_with_one_line() {
    let dir = tempdir();
    let write = |name: &str, text: &str| {
        let p = dir.join(name);
        std::fs::write(&p, text).unwrap();
        p.to_str().unwrap().to_string()
    };
    let good = std::fs::read_to_string(examples().join("ball_on_flat.toml")).unwrap();
    let p = write("nu.toml", &good.replacen("nu = 0.3", "nu = 0.7", 1));
    let l = bad(&["solve", &p]);
    assert!(
        l.ends_with("invalid body1.nu = 0.7: expected -1 < nu <= 0.5"),
        "{l}"
    );
    let p = write("typo.toml", &good.replace("force_n", "forse_n"));
    let l = bad(&["solve", &p]);
    assert!(l.contains("forse_n") && l.contains("line"), "{l}");
    let p = write(
        "two.toml",
        &good.replace("force_n = 100.0", "force_n = 100.0\napproach_mm = 0.01"),
    );
    let l = bad(&["solve", &p]);
    assert!(l.contains("exactly one of force_n"), "{l}");
    let l = bad(&["solve", dir.join("missing.toml").to_str().unwrap()]);
    assert!(l.contains("cannot read case file"), "{l}");
    // A table of the other method (PimP's options in a half-space case and back) is
    // refused, as an unknown key is.
    let bem = std::fs::read_to_string(examples().join("bem_torus_torus.toml")).unwrap();
    let p = write(
        "bem_pimp.toml",
        &format!("{bem}\n[pimp]\nmode = \"published\"\n"),
    );
    let l = bad(&["solve", &p]);
    assert!(
        l.contains("invalid pimp") && l.contains("method = \"bem\""),
        "{l}"
    );
    let pimp = std::fs::read_to_string(examples().join("pimp_sphere_on_torus.toml")).unwrap();
    let p = write(
        "pimp_bem.toml",
        &format!("{pimp}\n[bem]\ncells = [32, 32]\n"),
    );
    let l = bad(&["solve", &p]);
    assert!(
        l.contains("invalid bem") && l.contains("method = \"pimp\""),
        "{l}"
    );
}

#[test]
fn human_output_snapshots() {
    let out = kontakt()
        .args([
            "solve",
            examples().join("ball_inner_race.toml").to_str().unwrap(),
        ])
        .output()
        .unwrap();
    assert!(out.status.success());
    insta::assert_snapshot!(
        "ball_inner_race_table",
        String::from_utf8(out.stdout).unwrap()
    );
}

/// The README's main command: the roller-end/rib study writes its report folder.
#[test]
fn demo_writes_the_report() {
    let dir = tempdir().join("demo");
    let out = kontakt()
        .args(["demo", "--out", dir.to_str().unwrap()])
        .output()
        .unwrap();
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let stdout = String::from_utf8(out.stdout).unwrap();
    for name in ["sphere-cone-29", "torus-torus-28"] {
        assert!(stdout.contains(name), "{stdout}");
    }
    assert!(stdout.contains("Report written to"));
    let md = std::fs::read_to_string(dir.join("report.md")).unwrap();
    assert!(md.contains("torus-cone-14_400N.png"));
    for file in [
        "results.csv",
        "max_pressure.png",
        "contact_area.png",
        "torus-torus-14_400N.png",
    ] {
        let len = std::fs::metadata(dir.join(file)).unwrap().len();
        assert!(len > 1000, "{file}: {len} bytes");
    }
    // 8 pairings x 2 modes x 7 loads + header.
    let csv = std::fs::read_to_string(dir.join("results.csv")).unwrap();
    assert_eq!(csv.lines().count(), 8 * 2 * 7 + 1);
    // The summary line counts exactly the files on disk (it once said "2 plots" for 3).
    let names: Vec<String> = std::fs::read_dir(&dir)
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .collect();
    let count = |f: &dyn Fn(&str) -> bool| names.iter().filter(|n| f(n)).count();
    let pngs = count(&|n| n.ends_with(".png"));
    let maps = count(&|n| n.ends_with("_400N.png"));
    let friction_maps = count(&|n| n.starts_with("friction_") && n.ends_with(".png"))
        - count(&|n| {
            [
                "friction_torque.png",
                "friction_coefficient.png",
                "friction_model_ratio.png",
            ]
            .contains(&n)
        });
    let plots = pngs - maps - friction_maps;
    let csvs = count(&|n| n.ends_with(".csv"));
    let last = stdout.lines().last().unwrap();
    let expected = format!(
        "with {pngs} pictures ({maps} pressure maps, {plots} plots, {friction_maps} friction maps) and {csvs} tables"
    );
    assert!(
        last.contains(&expected),
        "{last}\nexpected: {expected}\nfiles: {names:?}"
    );
    assert_eq!(
        (maps, plots, friction_maps, csvs),
        (8, 12, 2, 3),
        "{names:?}"
    );
    // the whole-bearing section: the TRB's and the ball bearing's pictures and tables
    for file in [
        "bearing_32008x_loads.png",
        "bearing_32008x_elements.png",
        "bearing_32008x_slices.png",
        "bearing_32008x_map.png",
        "bearing_6205_loads.png",
        "bearing_6205_elements.png",
    ] {
        assert!(
            md.contains(&format!("]({file})")),
            "{file} not in report.md"
        );
    }
    assert!(md.contains("## Whole bearings") && md.contains("Q_rib N") && md.contains("p_out MPa"));
    assert!(
        stdout.contains("32008 X class TRB (Liu 2022): 23 rollers"),
        "{stdout}"
    );
    assert_eq!(names.len(), pngs + csvs + 1, "{names:?}");
}

/// A PimP case: JSON keys, CSV of the field, SVG map; and its bad-input paths.
#[test]
fn pimp_case_outputs_and_errors() {
    let dir = tempdir().join("pimp");
    std::fs::create_dir_all(&dir).unwrap();
    let case = examples().join("roller_rib_torus_torus.toml");
    let (csv, map) = (dir.join("p.csv"), dir.join("p.svg"));
    let v = json(&[
        "solve",
        case.to_str().unwrap(),
        "--csv",
        csv.to_str().unwrap(),
        "--map",
        map.to_str().unwrap(),
    ]);
    assert_eq!(v["method"], "pimp");
    for key in [
        "patches",
        "grid",
        "iterations",
        "max_pressure_mpa",
        "contact_area_mm2",
        "approach_mm",
        "semi_axes_mm",
    ] {
        assert!(!v[key].is_null(), "missing {key}");
    }
    assert_eq!(v["patches"], 1);
    let rows = std::fs::read_to_string(&csv).unwrap().lines().count();
    assert_eq!(rows, 64 * 64 + 1);
    assert!(
        std::fs::read_to_string(&map)
            .unwrap()
            .contains("pressure [MPa]")
    );
    // Bad: unknown pairing, map with a bad extension, Hertz case with --map.
    let bad_case = dir.join("bad.toml");
    std::fs::write(
        &bad_case,
        std::fs::read_to_string(&case)
            .unwrap()
            .replace("torus-torus-14", "torus-torus-99"),
    )
    .unwrap();
    let e = bad(&["solve", bad_case.to_str().unwrap()]);
    assert!(
        e.contains("geometry.pairing") && e.contains("torus-torus-14"),
        "{e}"
    );
    let e = bad(&[
        "solve",
        case.to_str().unwrap(),
        "--map",
        dir.join("p.gif").to_str().unwrap(),
    ]);
    assert!(e.contains("gif") || e.contains("extension"), "{e}");
    let e = bad(&[
        "solve",
        examples().join("ball_on_flat.toml").to_str().unwrap(),
        "--map",
        map.to_str().unwrap(),
    ]);
    assert!(e.contains("pimp"), "{e}");
}

#[test]
fn stdin_case() {
    let text = std::fs::read_to_string(examples().join("roller_line.toml")).unwrap();
    let out = kontakt()
        .args(["solve", "-", "--json"])
        .write_stdin(text)
        .output()
        .unwrap();
    assert!(out.status.success());
    let v: Value = serde_json::from_slice(&out.stdout).unwrap();
    assert_eq!(v["kind"], "line");
}

/// A fresh folder per call: the tests of this file run in parallel in one process, and
/// some remove their folder when done.
fn tempdir() -> PathBuf {
    static NEXT: std::sync::atomic::AtomicUsize = std::sync::atomic::AtomicUsize::new(0);
    let n = NEXT.fetch_add(1, std::sync::atomic::Ordering::Relaxed);
    let d = std::env::temp_dir().join(format!("kontakt-cli-test-{}-{n}", std::process::id()));
    std::fs::create_dir_all(&d).expect("temp dir");
    d
}

/// Validity guards of a Hertz result (issue 14): a contact large against a body's radius
/// carries a warning in JSON and text, a contact wider than the body's radius (a
/// near-conformal groove, a hundredfold overload) and a result beyond f64 are refused with
/// exit status 2, and a plain case has an empty `warnings` array.
#[test]
fn hertz_results_outside_the_theory_warn_or_are_refused() {
    let ball = |groove: &'static str, force: &'static str| {
        [
            "hertz",
            "--body1-radii",
            "3.969,3.969",
            "--body2-radii",
            groove,
            "--force",
            force,
        ]
    };
    // The 6205 inner-race contact at 1000 N: a / R_ball = 0.33 < 0.4, no warning.
    let v = json(&ball("15.281,-4.128", "1000"));
    assert_eq!(v["warnings"], serde_json::json!([]));
    // Ten times the load: a / R_ball = 0.71, the quadratic gap 14.9 % low at the edge.
    let v = json(&ball("15.281,-4.128", "10000"));
    let w = v["warnings"].as_array().unwrap();
    assert_eq!(w.len(), 1, "{w:?}");
    assert!(
        w[0].as_str().unwrap().contains("0.71 of body 1's radius"),
        "{w:?}"
    );
    let text = kontakt()
        .args(ball("15.281,-4.128", "10000"))
        .output()
        .unwrap();
    assert!(text.status.success());
    assert!(String::from_utf8_lossy(&text.stdout).contains("  warning: contact size:"));
    // A groove conforming to within 1 µm, and a hundredfold overload: refused.
    for (groove, force) in [("15.281,-3.970", "1000"), ("15.281,-4.128", "100000")] {
        let e = bad(&ball(groove, force));
        assert!(
            e.contains("--body1-radii") && e.contains("times body 1's radius"),
            "{e}"
        );
    }
    // Overflow: a stiffness beyond f64 is an error naming the quantity, never inf or null.
    let e = bad(&[
        "hertz",
        "--body1-radii",
        "1e-300,1e-300",
        "--body2-radii",
        "inf,inf",
        "--approach",
        "1e-303",
    ]);
    assert!(
        e.contains("--approach = 1e-303") && e.contains("double precision"),
        "{e}"
    );
    let e = bad(&[
        "hertz",
        "--body1-radii",
        "10,10",
        "--body2-radii",
        "inf,inf",
        "--force",
        "100",
        "--yield-stress",
        "1e200",
    ]);
    assert!(e.contains("first_yield_load_n = inf is beyond"), "{e}");
}

/// One error style (issue 14): clap's own errors are one line with exit status 2 and the
/// flag's unit and range; an output that cannot be written is exit status 1 whichever flag
/// named it, with the path once and the operating system's reason once.
#[test]
fn usage_errors_are_one_line_and_output_failures_exit_1() {
    let radii = ["hertz", "--body1-radii", "5,5", "--body2-radii", "inf,inf"];
    let e = bad(&[&radii[..], &["--force", "abc"]].concat());
    assert!(
        e.contains("'abc'") && e.contains("expected: Normal force [N], > 0"),
        "{e}"
    );
    let e = bad(&["hertz", "--bogus"]);
    assert!(
        e.contains("'--bogus'") && e.contains("usage: kontakt hertz"),
        "{e}"
    );
    let e = bad(&["solve"]);
    assert!(e.contains("<CASE.toml>"), "{e}");
    let long = format!("{}x", "9".repeat(499));
    let e = bad(&[&radii[..], &["--force", &long]].concat());
    assert!(e.contains("(500 characters)") && e.len() < 300, "{e}");
    let ex = examples();
    let (roller, wavy, traction) = (
        ex.join("roller_rib_torus_torus.toml"),
        ex.join("bem_wavy_map.toml"),
        ex.join("traction_ball_all_models.toml"),
    );
    let p = |p: &PathBuf| p.to_str().unwrap().to_string();
    for args in [
        vec![
            "solve".into(),
            p(&roller),
            "--map".into(),
            "/nonexistent/p.png".into(),
        ],
        vec![
            "solve".into(),
            p(&wavy),
            "--csv".into(),
            "/nonexistent/p.csv".into(),
        ],
        vec![
            "traction".into(),
            p(&traction),
            "--plot".into(),
            "/nonexistent/t.png".into(),
        ],
        vec![
            "traction".into(),
            p(&traction),
            "--csv".into(),
            "/nonexistent/t.csv".into(),
        ],
        vec!["mbs".into(), "--out".into(), "/proc/kontakt-test".into()],
    ] {
        let out = kontakt().args(&args).output().unwrap();
        assert_eq!(out.status.code(), Some(1), "{args:?}");
        let err = String::from_utf8(out.stderr).unwrap();
        assert_eq!(err.lines().count(), 1, "{err}");
        assert_eq!(err.matches("(os error 2)").count(), 1, "{err}");
    }
}

/// Resource limits (issue 14): a case file over 16 MiB is refused after reading at most
/// 16 MiB + 1 byte (also from standard input), a binary file is named as such, and a thread
/// count above `kontakt::MAX_THREADS` is an error before any pool is built.
#[test]
fn oversized_binary_and_thread_limits() {
    let dir = tempdir();
    let big = dir.join("big.toml");
    std::fs::write(&big, vec![b'#'; 17 << 20]).unwrap();
    let e = bad(&["solve", big.to_str().unwrap()]);
    assert!(e.contains("larger than 16 MiB"), "{e}");
    let out = kontakt()
        .arg("solve")
        .arg("-")
        .write_stdin(vec![b'#'; 17 << 20])
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&out.stderr).contains("<stdin> is larger than 16 MiB"));
    let bin = dir.join("bin.toml");
    std::fs::write(&bin, [0xff, 0xfe, b'[', b'a', b']']).unwrap();
    let e = bad(&["solve", bin.to_str().unwrap()]);
    assert!(e.contains("not UTF-8 text") && e.contains("binary"), "{e}");
    let case = dir.join("bem.toml");
    let text = std::fs::read_to_string(examples().join("bem_torus_torus.toml")).unwrap();
    std::fs::write(&case, text.replace("[bem]", "[bem]\nthreads = 100000")).unwrap();
    let e = bad(&["solve", case.to_str().unwrap()]);
    assert!(e.contains("100000") && e.contains("256"), "{e}");
    let _ = std::fs::remove_dir_all(&dir);
}

/// Progress bars (issue 14) are drawn only on a terminal: a piped run of a long command
/// writes nothing to standard error.
#[test]
fn long_runs_are_quiet_when_piped() {
    let dir = tempdir();
    let out = kontakt()
        .args(["validate", "--out", dir.to_str().unwrap()])
        .output()
        .unwrap();
    assert!(out.status.success());
    assert!(
        out.stderr.is_empty(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let _ = std::fs::remove_dir_all(&dir);
}

/// PimP and half-space cases outside the half-space model's size limit
/// (`kontakt::field::validity`): the 6205 inner-race contact warns at ten times its load
/// (JSON `warnings`, text `warning:` lines), a groove conforming to within 1 µm and a
/// contact running over the roller's end face are refused with status 2 and the case-file
/// key.
#[test]
fn pimp_and_bem_results_outside_the_model_warn_or_are_refused() {
    let dir = tempdir().join("zone-validity");
    std::fs::create_dir_all(&dir).unwrap();
    let groove_case = |method: &str, groove: &str, force: &str| {
        let options = if method == "pimp" {
            "[pimp]\ncells = [48, 48]"
        } else {
            "[bem]\ncells = [48, 48]\nthreads = 1"
        };
        let path = dir.join(format!("{method}-{groove}-{force}.toml"));
        std::fs::write(
            &path,
            format!(
                "method = \"{method}\"\n[geometry]\nkind = \"hertz\"\nradii1_mm = [3.969, 3.969]\n\
                 radii2_mm = [15.281, {groove}]\n{options}\n[body1]\ne_mpa = 210000.0\nnu = 0.3\n\
                 [body2]\ne_mpa = 210000.0\nnu = 0.3\n[load]\nforce_n = {force}\n"
            ),
        )
        .unwrap();
        path.to_str().unwrap().to_string()
    };
    for method in ["pimp", "bem"] {
        let v = json(&["solve", &groove_case(method, "-4.128", "1000")]);
        assert_eq!(v["warnings"], serde_json::json!([]), "{method}");
        let heavy = groove_case(method, "-4.128", "10000");
        let v = json(&["solve", &heavy]);
        let w = v["warnings"].as_array().unwrap();
        assert_eq!(w.len(), 1, "{method}: {w:?}");
        assert!(
            w[0].as_str()
                .unwrap()
                .contains("of body 1's radius of curvature 3.969 mm"),
            "{method}: {w:?}"
        );
        let text = kontakt().args(["solve", &heavy]).output().unwrap();
        assert!(text.status.success(), "{method}");
        assert!(
            String::from_utf8_lossy(&text.stdout).contains("  warning: contact size:"),
            "{method}"
        );
        let e = bad(&["solve", &groove_case(method, "-3.970", "1000")]);
        assert!(
            e.contains("geometry.radii1_mm") && e.contains("times body 1's radius"),
            "{method}: {e}"
        );
    }
    // The roller end face ends 0.1 mm beyond a contact at 5.4 mm from the roller axis.
    let rib = dir.join("roller-edge.toml");
    std::fs::write(
        &rib,
        "method = \"pimp\"\n[geometry]\nkind = \"roller_rib\"\npairing = \"torus-torus-14\"\n\
         contact_height_mm = 5.4\n[pimp]\ncells = [48, 48]\n[body1]\ne_mpa = 210000.0\nnu = 0.3\n\
         [body2]\ne_mpa = 210000.0\nnu = 0.3\n[load]\nforce_n = 250.0\n",
    )
    .unwrap();
    let e = bad(&["solve", rib.to_str().unwrap()]);
    assert!(
        e.contains("geometry.bearing.roller_large_end_radius_mm")
            && e.contains("larger than the face"),
        "{e}"
    );
}

/// A temporary copy of example `file` with each `(from, to)` of `edits` replaced.
fn edited_example(file: &str, edits: &[(&str, &str)], tag: &str) -> PathBuf {
    let mut text = std::fs::read_to_string(examples().join(file)).unwrap();
    for (from, to) in edits {
        assert!(text.contains(from), "{from}");
        text = text.replace(from, to);
    }
    let p = std::env::temp_dir().join(format!("kontakt-cli-{}-{tag}.toml", std::process::id()));
    std::fs::write(&p, text).unwrap();
    p
}

/// Issue 30 item 3: the subcommands that bypassed the size check (traction, mindlin,
/// impact, friction) print the `warning:` line in the band 0.4-1 and refuse beyond it with
/// exit status 2 naming the key, as `kontakt solve` does on the same file.
#[test]
fn every_subcommand_warns_and_refuses_an_oversize_contact() {
    for (command, file, from, warn, refuse, key) in [
        (
            "mindlin",
            "mindlin_fretting.toml",
            "force_n = 100.0",
            "force_n = 1e6",
            "force_n = 1e8",
            "geometry.radii1_mm",
        ),
        (
            "traction",
            "traction_twin_disc.toml",
            "force_n = 1000.0",
            "force_n = 1e8",
            "force_n = 1e9",
            "geometry.radii1_mm",
        ),
        (
            "impact",
            "impact_oblique.toml",
            "speed_mm_per_s = 1000.0",
            "speed_mm_per_s = 1e6",
            "speed_mm_per_s = 1e7",
            "sphere.radius_mm",
        ),
        (
            "friction",
            "rib_friction.toml",
            "axial_n = 15000.0",
            "axial_n = 6e6",
            "axial_n = 1e8",
            "geometry.bearing.roller_large_end_radius_mm",
        ),
    ] {
        let p = edited_example(file, &[(from, warn)], command);
        for sub in [command, "solve"] {
            let out = kontakt().arg(sub).arg(&p).output().unwrap();
            assert!(
                out.status.success(),
                "{sub} {file}: {}",
                String::from_utf8_lossy(&out.stderr)
            );
            let text = String::from_utf8(out.stdout).unwrap();
            assert!(
                text.lines().any(|l| l.starts_with("  warning: ")
                    && (l.contains("contact size") || l.contains("face edge"))),
                "{sub} {file}: {text}"
            );
        }
        let p = edited_example(file, &[(from, refuse)], command);
        for sub in [command, "solve"] {
            let line = bad(&[sub, p.to_str().unwrap()]);
            assert!(line.contains(&format!(": {key}: ")), "{sub} {file}: {line}");
        }
    }
}

/// Issue 30 item 4: `kontakt mindlin` goes through the report's finiteness check (mu =
/// 1e301 printed "inf N mm" and wrote null in JSON): exit status 2 naming the key, in
/// text and JSON.
#[test]
fn mindlin_refuses_an_overflowing_report() {
    let p = edited_example(
        "mindlin_fretting.toml",
        &[
            ("mu = 0.3", "mu = 1e300"),
            ("amplitude_n = 20.0", "amplitude_n = 1e301"),
        ],
        "mindlin-inf",
    );
    for json in [false, true] {
        let mut args = vec!["mindlin", p.to_str().unwrap()];
        if json {
            args.push("--json");
        }
        let line = bad(&args);
        assert!(
            line.contains("dissipated_energy_per_cycle_nmm: the result is inf"),
            "{line}"
        );
    }
}

/// Issue 30 item 12: numbers beyond the tables' range print in exponent form (mu = 1e150
/// printed 151 digits), and a full disk names the file or standard output (exit 1).
#[test]
fn extreme_numbers_and_full_disks() {
    let p = edited_example(
        "mindlin_fretting.toml",
        &[
            ("mu = 0.3", "mu = 1e150"),
            ("amplitude_n = 20.0", "amplitude_n = 1e151"),
        ],
        "mindlin-big",
    );
    let out = kontakt().arg("mindlin").arg(&p).output().unwrap();
    let text = String::from_utf8(out.stdout).unwrap();
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    assert!(text.contains("mu = 1e150"), "{text}");
    assert!(text.lines().all(|l| l.chars().count() < 200), "{text}");
    if !std::path::Path::new("/dev/full").exists() {
        return;
    }
    let mindlin = examples().join("mindlin_fretting.toml");
    let out = kontakt()
        .arg("mindlin")
        .arg(&mindlin)
        .args(["--csv", "/dev/full"])
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(1));
    let err = String::from_utf8(out.stderr).unwrap();
    assert!(err.contains("cannot write /dev/full: "), "{err}");
    let full = std::fs::OpenOptions::new()
        .write(true)
        .open("/dev/full")
        .unwrap();
    let out = std::process::Command::new(assert_cmd::cargo::cargo_bin("kontakt"))
        .arg("mindlin")
        .arg(&mindlin)
        .stdout(full)
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(1));
    let err = String::from_utf8(out.stderr).unwrap();
    assert!(err.contains("cannot write standard output: "), "{err}");
}
