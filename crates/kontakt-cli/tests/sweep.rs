//! `kontakt sweep`: results against the closed form, resumption after a kill, refusal of a
//! directory holding another sweep, one-line errors for bad sweep files.

#![allow(clippy::unwrap_used)] // test helpers: a panic is a test failure with its message

mod support;

use assert_cmd::Command;
use serde_json::Value;
use std::collections::HashMap;
use std::path::{Path, PathBuf};
use std::time::{Duration, Instant, SystemTime};
use support::{cell as num, read_csv, sweep_csv};

fn kontakt() -> Command {
    Command::cargo_bin("kontakt").expect("binary built")
}

fn examples() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../../examples")
}

/// A fresh folder per test.
fn tempdir(name: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("kontakt-sweep-test-{}-{name}", std::process::id()));
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(&d).unwrap();
    d
}

fn run_json(args: &[&str]) -> Value {
    let out = kontakt().args(args).arg("--json").output().unwrap();
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    serde_json::from_slice(&out.stdout).unwrap()
}

/// Run, expect exit status 2 and one stderr line; return it.
fn bad(args: &[&str]) -> String {
    let out = kontakt().args(args).output().unwrap();
    let err = String::from_utf8(out.stderr).unwrap();
    assert_eq!(out.status.code(), Some(2), "args {args:?}: {err}");
    let lines: Vec<_> = err.lines().filter(|l| !l.trim().is_empty()).collect();
    assert_eq!(lines.len(), 1, "not one line: {err}");
    lines[0].to_string()
}

const HERTZ_BASE: &str = r#"
[base]
[base.contact]
kind = "point"
[base.body1]
radii_mm = [6.35, 6.35]
e_mpa = 210000.0
nu = 0.3
[base.body2]
radii_mm = [inf, inf]
e_mpa = 210000.0
nu = 0.3
[base.load]
force_n = 100.0
"#;

#[test]
fn hertz_sweep_matches_the_closed_form_in_every_row() {
    let dir = tempdir("closed-form");
    let out = dir.join("out");
    let v = run_json(&[
        "sweep",
        examples().join("sweeps/hertz_load.toml").to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
        "--format",
        "csv",
        "--quiet",
    ]);
    assert_eq!(v["cases"], 600);
    assert_eq!(v["cases_not_ok"], 0);
    let rows = read_csv(&out.join("results.csv"));
    assert_eq!(rows.len(), 600);
    // Sphere of radius R on a flat, both steel: E* = E / (2 (1 - nu²)),
    // a = (3 F R / (4 E*))^(1/3), p0 = 3 F / (2 pi a²), delta = a² / R.
    let e_star = 210_000.0 / (2.0 * (1.0 - 0.3 * 0.3));
    let mut per_radius: HashMap<String, Vec<(f64, f64)>> = HashMap::new();
    for (i, row) in rows.iter().enumerate() {
        assert_eq!(row["case"], i.to_string(), "case order");
        // Above first yield (the base case's [yield]) the row is solved with a warning.
        let warned = row.get("warnings[0]").is_some_and(|w| !w.is_empty());
        assert_eq!(
            row["status"],
            if warned { "warning" } else { "ok" },
            "row {i}"
        );
        assert!(
            !warned || row["warnings[0]"].starts_with("first yield"),
            "{row:?}"
        );
        let r = num(row, "ball_radius_mm");
        let f = num(row, "load.force_n");
        assert_eq!(
            num(row, "force_n"),
            f,
            "row {i}: the report's force is the swept one"
        );
        let a = (3.0 * f * r / (4.0 * e_star)).cbrt();
        let p0 = 3.0 * f / (2.0 * std::f64::consts::PI * a * a);
        for (key, want) in [
            ("semi_axes_mm[0]", a),
            ("semi_axes_mm[1]", a),
            ("max_pressure_mpa", p0),
            ("approach_mm", a * a / r),
            ("e_star_mpa", e_star),
        ] {
            let got = num(row, key);
            assert!(
                ((got - want) / want).abs() < 1e-12,
                "row {i} (R = {r}, F = {f}): {key} = {got}, closed form {want}"
            );
        }
        per_radius
            .entry(row["ball_radius_mm"].clone())
            .or_default()
            .push((f, num(row, "max_pressure_mpa")));
    }
    // Within one radius, p0 ∝ F^(1/3), and the forces are log-spaced from 1 to 10^4 N.
    assert_eq!(per_radius.len(), 3);
    for points in per_radius.values() {
        assert_eq!(points.len(), 200);
        assert_eq!(points[0].0, 1.0);
        assert_eq!(points[199].0, 10_000.0);
        let (f0, p0) = points[0];
        for &(f, p) in points {
            let want = p0 * (f / f0).cbrt();
            assert!(
                ((p - want) / want).abs() < 1e-12,
                "F = {f}: p0 = {p}, {want}"
            );
        }
        for w in points.windows(2) {
            let ratio = w[1].0 / w[0].0;
            assert!((ratio - 10f64.powf(4.0 / 199.0)).abs() < 1e-12, "{ratio}");
        }
    }
}

#[test]
fn pimp_example_sweep_runs_both_modes() {
    let dir = tempdir("pimp");
    let out = dir.join("out");
    let v = run_json(&[
        "sweep",
        examples()
            .join("sweeps/pimp_roller_rib.toml")
            .to_str()
            .unwrap(),
        "--out",
        out.to_str().unwrap(),
        "--format",
        "csv",
    ]);
    assert_eq!(v["cases"], 14);
    assert_eq!(v["cases_not_ok"], 0);
    let rows = read_csv(&out.join("results.csv"));
    assert_eq!(rows.len(), 14);
    for mode in ["corrected", "published"] {
        let mine: Vec<_> = rows.iter().filter(|r| r["pimp.mode"] == mode).collect();
        assert_eq!(mine.len(), 7);
        for r in &mine {
            assert_eq!(r["mode"], mode);
            // The field's force is the swept load (PimP scales to equilibrium).
            let f = num(r, "load.force_n");
            assert!((num(r, "force_n") - f).abs() < 1e-6 * f, "{r:?}");
            assert_eq!(r["status.termination"], "converged");
        }
        for w in mine.windows(2) {
            assert!(num(w[1], "max_pressure_mpa") > num(w[0], "max_pressure_mpa"));
            assert!(num(w[1], "contact_area_mm2") > num(w[0], "contact_area_mm2"));
        }
    }
}

fn chunk_times(dir: &Path) -> HashMap<String, SystemTime> {
    std::fs::read_dir(dir.join("chunks"))
        .unwrap()
        .map(|e| e.unwrap())
        .filter(|e| {
            let n = e.file_name().to_string_lossy().into_owned();
            n.starts_with("chunk-") && n.ends_with(".parquet")
        })
        .map(|e| {
            (
                e.file_name().to_string_lossy().into_owned(),
                e.metadata().unwrap().modified().unwrap(),
            )
        })
        .collect()
}

#[test]
fn a_killed_sweep_resumes_with_the_missing_chunks_only() {
    let dir = tempdir("resume");
    let out = dir.join("out");
    // 60 x 1000 = 60 000 Hertz cases in 120 chunks of 500: a few seconds on one thread.
    let sweep = dir.join("sweep.toml");
    std::fs::write(
        &sweep,
        format!(
            "chunk_size = 500\n\
             [[parameter]]\nkey = \"body2.e_mpa\"\nstart = 70000.0\nstop = 400000.0\ncount = 60\n\
             [[parameter]]\nkey = \"load.force_n\"\nstart = 1.0\nstop = 1000.0\ncount = 1000\nspacing = \"log\"\n\
             {HERTZ_BASE}"
        ),
    )
    .unwrap();
    let bin = assert_cmd::cargo::cargo_bin("kontakt");
    let mut child = std::process::Command::new(&bin)
        .args(["sweep", sweep.to_str().unwrap(), "--out"])
        .arg(&out)
        .args(["--threads", "1", "--quiet"])
        .stdout(std::process::Stdio::null())
        .stderr(std::process::Stdio::null())
        .spawn()
        .unwrap();
    let start = Instant::now();
    loop {
        if out.join("chunks").is_dir() && chunk_times(&out).len() >= 3 {
            break;
        }
        assert!(
            start.elapsed() < Duration::from_secs(120),
            "no chunks after 120 s"
        );
        std::thread::sleep(Duration::from_millis(10));
    }
    child.kill().unwrap();
    child.wait().unwrap();
    let before = chunk_times(&out);
    assert!(before.len() >= 3);
    assert!(
        before.len() < 120,
        "the run finished before it was killed: make the sweep larger"
    );
    assert!(!out.join("results.parquet").exists());

    // The rerun computes only the missing chunks.
    let v = run_json(&[
        "sweep",
        sweep.to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
        "--format",
        "csv",
    ]);
    assert_eq!(v["chunks"], 120);
    assert_eq!(v["chunks_reused"], before.len());
    assert_eq!(v["chunks_computed"], 120 - before.len());
    assert_eq!(v["cases_computed"], 500 * (120 - before.len()));
    let after = chunk_times(&out);
    assert_eq!(after.len(), 120);
    for (name, t) in &before {
        assert_eq!(after[name], *t, "{name} was rewritten");
    }
    // No temporary file is left behind.
    let leftovers: Vec<_> = std::fs::read_dir(out.join("chunks"))
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .filter(|n| n.ends_with(".tmp"))
        .collect();
    assert!(leftovers.is_empty(), "{leftovers:?}");

    // Every case exactly once, in case order.
    let rows = read_csv(&out.join("results.csv"));
    assert_eq!(rows.len(), 60_000);
    for (i, row) in rows.iter().enumerate() {
        assert_eq!(row["case"], i.to_string());
        assert_eq!(row["status"], "ok");
    }
    // Grid order: the last parameter (force) varies fastest.
    assert_eq!(num(&rows[999], "load.force_n"), 1000.0);
    assert_eq!(num(&rows[1000], "load.force_n"), 1.0);
    assert_eq!(num(&rows[59_999], "body2.e_mpa"), 400_000.0);

    // A third run finds everything complete and recomputes nothing.
    let v = run_json(&[
        "sweep",
        sweep.to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
    ]);
    assert_eq!(v["chunks_computed"], 0);
    assert_eq!(v["cases_not_ok"], 0);
    assert!(out.join("results.parquet").is_file());
}

#[test]
fn a_directory_holding_another_sweep_is_refused() {
    let dir = tempdir("other");
    let out = dir.join("out");
    let write = |name: &str, forces: &str| {
        let p = dir.join(name);
        std::fs::write(
            &p,
            format!("[[parameter]]\nkey = \"load.force_n\"\nvalues = [{forces}]\n{HERTZ_BASE}"),
        )
        .unwrap();
        p
    };
    let a = write("a.toml", "1.0, 2.0");
    let b = write("b.toml", "1.0, 3.0");
    run_json(&["sweep", a.to_str().unwrap(), "--out", out.to_str().unwrap()]);
    let err = bad(&["sweep", b.to_str().unwrap(), "--out", out.to_str().unwrap()]);
    assert!(
        err.contains(out.to_str().unwrap()) && err.contains("different sweep"),
        "{err}"
    );
    // The first sweep's results are untouched, and it can be rerun.
    let v = run_json(&["sweep", a.to_str().unwrap(), "--out", out.to_str().unwrap()]);
    assert_eq!(v["chunks_computed"], 0);
}

#[test]
fn failing_cases_are_rows_not_crashes() {
    let dir = tempdir("failing");
    let out = dir.join("out");
    let p = dir.join("s.toml");
    std::fs::write(
        &p,
        format!(
            "[[parameter]]\nkey = \"load.force_n\"\nvalues = [100.0, -1.0, 200.0]\n{HERTZ_BASE}"
        ),
    )
    .unwrap();
    let (v, rows) = sweep_csv(&p, &out);
    assert_eq!(v["cases_not_ok"], 1);
    assert_eq!(rows[0]["status"], "ok");
    assert_eq!(rows[1]["status"], "invalid");
    assert!(rows[1]["error"].contains("load.force_n"), "{:?}", rows[1]);
    assert_eq!(rows[1]["max_pressure_mpa"], "");
    assert_eq!(rows[2]["status"], "ok");
}

#[test]
fn bad_sweep_files_fail_with_one_line_naming_the_key() {
    let dir = tempdir("bad");
    let out = dir.join("out");
    let cases = [
        (
            "[[parameter]]\nkey = \"load.forse_n\"\nvalues = [1.0]\n",
            "load.forse_n",
        ),
        (
            "[[parameter]]\nkey = \"load.force_n\"\nstart = 1.0\nstop = 2.0\ncount = 0\n",
            "parameter[0].count = 0",
        ),
        (
            "[[parameter]]\nkey = \"load.force_n\"\nstart = 1.0\nstop = 2.0\ncount = 100000\n\
             [[parameter]]\nkey = \"body1.e_mpa\"\nstart = 1.0\nstop = 2.0\ncount = 1000\n",
            "max_cases = 10000000",
        ),
        (
            "[[parameter]]\nkey = \"load.force_n\"\nvalue = [1.0]\n",
            "value",
        ),
    ];
    for (i, (params, want)) in cases.iter().enumerate() {
        let p = dir.join(format!("bad{i}.toml"));
        std::fs::write(&p, format!("{params}{HERTZ_BASE}")).unwrap();
        let err = bad(&["sweep", p.to_str().unwrap(), "--out", out.to_str().unwrap()]);
        assert!(err.contains(want), "{err}");
        assert!(err.contains(p.to_str().unwrap()), "names the file: {err}");
    }
    let p = dir.join("bad0.toml");
    let err = bad(&[
        "sweep",
        p.to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
        "--threads",
        "0",
    ]);
    assert!(err.contains("--threads = 0"), "{err}");
    assert!(!out.exists(), "nothing written for bad input");
}

/// Read a `.npy` file of float64: its shape and values.
fn read_npy(path: &Path) -> (Vec<u64>, Vec<f64>) {
    let bytes = std::fs::read(path).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
    let npy = npyz::NpyFile::new(&bytes[..]).unwrap();
    assert_eq!(npy.header().dtype().descr(), "'<f8'", "{}", path.display());
    let shape = npy.shape().to_vec();
    (shape, npy.into_vec::<f64>().unwrap())
}

/// `--fields npy`: one pressure file per case, shaped as the row's grid, whose integral is
/// the row's force and whose maximum is the row's peak; the choice is part of the sweep's
/// identity, and a method without fields is refused.
#[test]
fn fields_npy_stores_each_case_pressure_consistent_with_its_row() {
    let dir = tempdir("fields");
    let out = dir.join("out");
    let sweep = examples().join("sweeps/pimp_roller_rib.toml");
    let args = |extra: &[&str]| {
        let mut a = vec![
            "sweep".to_string(),
            sweep.to_str().unwrap().to_string(),
            "--out".into(),
            out.to_str().unwrap().to_string(),
            "--format".into(),
            "csv".into(),
        ];
        a.extend(extra.iter().map(|s| s.to_string()));
        a
    };
    let a = args(&["--fields", "npy"]);
    let v = run_json(&a.iter().map(String::as_str).collect::<Vec<_>>());
    assert_eq!(v["cases"], 14);
    assert!(v["fields"].as_str().unwrap().ends_with("fields"), "{v}");
    let rows = read_csv(&out.join("results.csv"));
    for r in &rows {
        let case: u64 = r["case"].parse().unwrap();
        let path = out.join(format!("fields/chunk-000000/case-{case:09}-pressure.npy"));
        let (shape, p) = read_npy(&path);
        let (nx, ny) = (num(r, "grid.cells[0]"), num(r, "grid.cells[1]"));
        assert_eq!(shape, vec![ny as u64, nx as u64]);
        let cell = num(r, "grid.cell_mm[0]") * num(r, "grid.cell_mm[1]");
        let force: f64 = p.iter().sum::<f64>() * cell;
        let f = num(r, "force_n");
        assert!(
            (force - f).abs() < 1e-9 * f,
            "case {case}: {force} against {f}"
        );
        let max = p.iter().copied().fold(f64::MIN, f64::max);
        assert_eq!(max, num(r, "max_pressure_mpa"), "case {case}");
        assert!(p.iter().all(|x| x.is_finite() && *x >= 0.0));
    }
    let files = std::fs::read_dir(out.join("fields/chunk-000000"))
        .unwrap()
        .count();
    assert_eq!(files, 14, "one file per case, no temporary left");

    // Rerunning without fields into the same folder is another sweep.
    let a = args(&["--fields", "none"]);
    let msg = bad(&a.iter().map(String::as_str).collect::<Vec<_>>());
    assert!(msg.contains("holds a different sweep"), "{msg}");

    // A Hertz case has no field.
    let hertz = dir.join("hertz.toml");
    std::fs::write(
        &hertz,
        format!("{HERTZ_BASE}\n[[parameter]]\nkey = \"load.force_n\"\nvalues = [1.0, 2.0]\n"),
    )
    .unwrap();
    let msg = bad(&[
        "sweep",
        hertz.to_str().unwrap(),
        "--out",
        dir.join("h").to_str().unwrap(),
        "--fields",
        "npy",
    ]);
    assert!(
        msg.contains("invalid fields = \"npy\"") && msg.contains("hertz"),
        "{msg}"
    );
}

/// A friction sweep is long and numeric (issue 30, item 16): one row per case × model ×
/// speed, the speed a number (a parameter on `speed.rpm` takes plain numbers), reported
/// exactly as given (1500, not 1500.0000000000002 from a round trip through rad/s), each
/// model's torque over Hertz's on its own row, and a failing case one row in its place.
#[test]
fn friction_sweep_has_one_numeric_row_per_case_model_and_speed() {
    let dir = tempdir("friction");
    let out = dir.join("out");
    let p = dir.join("s.toml");
    std::fs::write(
        &p,
        r#"
[[parameter]]
key = "speed.rpm"
values = [500.0, -1.0, 1500.0]

[base]
method = "friction"
models = ["hertz", "pimp"]
[base.geometry]
kind = "roller_rib"
pairing = "sphere-torus-57"
[base.load]
axial_n = 15000.0
[base.speed]
rpm = [1000.0]
"#,
    )
    .unwrap();
    let (v, rows) = sweep_csv(&p, &out);
    assert_eq!(v["cases_not_ok"], 1, "{v}");
    let cases: Vec<&str> = rows.iter().map(|r| r["case"].as_str()).collect();
    assert_eq!(cases, ["0", "0", "1", "2", "2"]);
    let columns = v["columns"].as_array().unwrap();
    assert!(
        columns.len() < 50
            && columns
                .iter()
                .all(|c| !c.as_str().unwrap().starts_with("rows[")),
        "wide columns: {columns:?}"
    );
    for (row, (case_speed, model)) in rows.iter().zip([
        ("500.0", "hertz"),
        ("500.0", "pimp"),
        ("-1.0", ""),
        ("1500.0", "hertz"),
        ("1500.0", "pimp"),
    ]) {
        assert_eq!(row["speed.rpm"], case_speed, "{row:?}");
        assert_eq!(row["model"], model, "{row:?}");
        if model.is_empty() {
            assert_eq!(row["status"], "invalid");
            assert!(row["error"].contains("speed.rpm"), "{row:?}");
            assert_eq!(row["bearing_drag_torque_nmm"], "");
            continue;
        }
        assert_eq!(row["status"], "ok");
        assert_eq!(row["speed_rpm"], case_speed, "exact speed: {row:?}");
        assert_eq!(row["pairing"], "sphere-torus-57");
        assert!(num(row, "bearing_drag_torque_nmm") > 0.0);
        assert!(num(row, "rib_load_n") > 0.0);
        if model == "pimp" {
            let ratio = num(row, "torque_vs_hertz");
            assert!((ratio - 1.0).abs() < 0.01, "{row:?}");
        } else {
            assert_eq!(row["torque_vs_hertz"], "", "{row:?}");
        }
    }
}

/// Issue 30 items 3 and 13: a case with a contact large against the ball (1e6 N on a
/// 6.35 mm ball, a = 0.54 R) has status `warning` and counts as solved; one beyond it
/// (1e8 N) is `invalid` naming the key; a sweep in which every case fails writes its table
/// and exits with status 1.
#[test]
fn warning_rows_and_a_sweep_whose_every_case_fails() {
    let dir = tempdir("all-fail");
    let sweep = |name: &str, values: &str| {
        let p = dir.join(format!("{name}.toml"));
        std::fs::write(
            &p,
            format!("[[parameter]]\nkey = \"load.force_n\"\nvalues = {values}\n{HERTZ_BASE}"),
        )
        .unwrap();
        let out = dir.join(name);
        let o = kontakt()
            .args(["sweep", p.to_str().unwrap(), "--out"])
            .arg(&out)
            .args(["--format", "csv", "--json"])
            .output()
            .unwrap();
        (o, read_csv(&out.join("results.csv")))
    };
    let (o, rows) = sweep("mixed", "[100.0, 1e6, 1e8]");
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let v: Value = serde_json::from_slice(&o.stdout).unwrap();
    assert_eq!(v["cases_not_ok"], 1);
    let status: Vec<&str> = rows.iter().map(|r| r["status"].as_str()).collect();
    assert_eq!(status, ["ok", "warning", "invalid"]);
    assert!(
        rows[1]["warnings[0]"].contains("contact size"),
        "{:?}",
        rows[1]
    );
    assert!(rows[2]["error"].contains("body1.radii_mm"), "{:?}", rows[2]);
    let (o, rows) = sweep("all-fail", "[-1.0, 1e8]");
    assert_eq!(o.status.code(), Some(1));
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(
        err.contains("every case of the sweep failed (2 of 2)"),
        "{err}"
    );
    assert_eq!(err.trim().lines().count(), 1, "{err}");
    assert_eq!(rows.len(), 2);
}

/// Issue 30 item 13: a sweep over `speed.rpm` of a friction case with a speed range says
/// that both were given (it said "neither a list nor a complete range").
#[test]
fn a_sweep_over_rpm_of_a_range_names_both() {
    let dir = tempdir("rpm");
    let p = dir.join("s.toml");
    std::fs::write(
        &p,
        format!(
            "base = {:?}\n[[parameter]]\nkey = \"speed.rpm\"\nvalues = [[500.0], [1000.0]]\n",
            examples().join("rib_friction.toml")
        ),
    )
    .unwrap();
    let out = dir.join("out");
    let o = kontakt()
        .args(["sweep", p.to_str().unwrap(), "--out"])
        .arg(&out)
        .args(["--format", "csv"])
        .output()
        .unwrap();
    assert_eq!(o.status.code(), Some(1));
    let rows = read_csv(&out.join("results.csv"));
    for r in rows {
        assert!(
            r["error"].contains("speed = rpm, min_rpm, max_rpm, points")
                && r["error"].contains("not both"),
            "{r:?}"
        );
    }
}
