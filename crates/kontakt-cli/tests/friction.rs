//! `kontakt friction`: the example case's JSON (power balance, model ratios, monotone
//! Stribeck fall at low speed), CSV and plot files, the human table, `kontakt solve` of a
//! friction case, and one-line errors naming the key with exit status 2.

#![allow(clippy::unwrap_used)] // test helpers: a panic is a test failure with its message

use assert_cmd::Command;
use serde_json::Value;
use std::path::PathBuf;

fn kontakt() -> Command {
    Command::cargo_bin("kontakt").expect("binary built")
}

fn example() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../../examples/rib_friction.toml")
}

fn tempdir() -> PathBuf {
    let d = std::env::temp_dir().join(format!("kontakt-friction-test-{}", std::process::id()));
    std::fs::create_dir_all(&d).expect("temp dir");
    d
}

/// A small variant of the example (two speeds, PimP and Hertz) as TOML text.
fn small_case(edit: impl FnOnce(&mut toml::Table)) -> String {
    let mut t: toml::Table = toml::from_str(&std::fs::read_to_string(example()).unwrap()).unwrap();
    t.insert(
        "models".into(),
        toml::Value::Array(vec!["pimp".into(), "hertz".into()]),
    );
    let mut speed = toml::Table::new();
    speed.insert(
        "rpm".into(),
        toml::Value::Array(vec![100.0.into(), 2000.0.into()]),
    );
    t.insert("speed".into(), toml::Value::Table(speed));
    edit(&mut t);
    toml::to_string(&t).unwrap()
}

fn run_stdin(text: &str, args: &[&str]) -> std::process::Output {
    kontakt()
        .args(args)
        .write_stdin(text.to_string())
        .output()
        .expect("runs")
}

/// Run, expect exit status 2 and exactly one stderr line; return it.
fn bad(text: &str) -> String {
    let out = run_stdin(text, &["friction", "-"]);
    assert_eq!(
        out.status.code(),
        Some(2),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let err = String::from_utf8(out.stderr).expect("utf8");
    let lines: Vec<_> = err.lines().filter(|l| !l.trim().is_empty()).collect();
    assert_eq!(lines.len(), 1, "not one line: {err}");
    lines[0].to_string()
}

/// The report's own consistency: bearing power = Z × contact power; bearing torque =
/// bearing power / ω_i (W → N·mm/s: ×1000); the coefficient falls with speed while the
/// asperity share is large (the Stribeck branch); the model ratios are torque quotients;
/// no NaN (JSON has none by construction: every number parses).
#[test]
fn example_report_is_consistent() {
    let out = kontakt()
        .args(["friction", example().to_str().unwrap(), "--json"])
        .output()
        .unwrap();
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let r: Value = serde_json::from_slice(&out.stdout).unwrap();
    let z = r["rollers"].as_f64().unwrap();
    let rows = r["rows"].as_array().unwrap();
    assert_eq!(rows.len(), 18); // 3 models × 6 speeds
    for row in rows {
        let f = |k: &str| row[k].as_f64().unwrap();
        let w = f("speed_rpm") * std::f64::consts::PI / 30.0;
        assert!((f("bearing_power_w") - z * f("power_w")).abs() < 1e-9 * f("bearing_power_w"));
        assert!(
            (f("bearing_drag_torque_nmm") - f("bearing_power_w") * 1e3 / w).abs()
                < 1e-9 * f("bearing_drag_torque_nmm")
        );
        assert!(f("coefficient") > 0.0 && f("coefficient") <= 0.12 * 1.001);
    }
    let hertz: Vec<&Value> = rows.iter().filter(|r| r["model"] == "hertz").collect();
    assert!(hertz[0]["coefficient"].as_f64() > hertz[4]["coefficient"].as_f64());
    for d in r["model_difference"].as_array().unwrap() {
        let s = d["speed_rpm"].as_f64().unwrap();
        let m = d["model"].as_str().unwrap();
        let at = |model: &str| {
            rows.iter()
                .find(|x| x["model"] == model && x["speed_rpm"].as_f64() == Some(s))
                .unwrap()["bearing_drag_torque_nmm"]
                .as_f64()
                .unwrap()
        };
        let ratio = d["torque_vs_hertz"].as_f64().unwrap();
        assert!((ratio - at(m) / at("hertz")).abs() < 1e-12);
    }
}

/// Files: CSV with a header and one line per row; PNG plots and maps (PNG signature).
#[test]
fn csv_plots_and_maps_are_written() {
    let dir = tempdir();
    let files = [
        "rows.csv",
        "torque.png",
        "mu.png",
        "sliding.png",
        "density.svg",
    ];
    let p: Vec<String> = files
        .iter()
        .map(|f| dir.join(f).display().to_string())
        .collect();
    let out = run_stdin(
        &small_case(|_| {}),
        &[
            "friction",
            "-",
            "--csv",
            &p[0],
            "--plot",
            &p[1],
            "--stribeck",
            &p[2],
            "--map",
            &p[3],
            "--density",
            &p[4],
        ],
    );
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let csv = std::fs::read_to_string(&p[0]).unwrap();
    assert_eq!(csv.lines().count(), 1 + 4);
    assert!(csv.starts_with("pairing,model,speed_rpm,"));
    for png in &p[1..4] {
        let bytes = std::fs::read(png).unwrap();
        assert_eq!(&bytes[..8], b"\x89PNG\r\n\x1a\n", "{png}");
    }
    let svg = std::fs::read_to_string(&p[4]).unwrap();
    assert!(svg.contains("<svg"));
    let table = String::from_utf8(out.stdout).unwrap();
    assert!(table.contains("pressure model: pimp") && table.contains("pimp/hertz"));
}

/// `kontakt solve` runs a friction case (JSON); field flags are refused with a pointer to
/// `kontakt friction`.
#[test]
fn solve_runs_a_friction_case() {
    let out = run_stdin(&small_case(|_| {}), &["solve", "-", "--json"]);
    assert!(out.status.success());
    let r: Value = serde_json::from_slice(&out.stdout).unwrap();
    assert_eq!(r["method"], "friction");
    let out = run_stdin(&small_case(|_| {}), &["solve", "-", "--map", "x.png"]);
    assert_eq!(out.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&out.stderr).contains("kontakt friction"));
}

/// Bad input: one line, exit status 2, naming the key.
#[test]
fn bad_input_names_the_key() {
    let set = |table: &'static str, key: &'static str, v: toml::Value| {
        small_case(move |t| {
            t.get_mut(table)
                .and_then(|x| x.as_table_mut())
                .unwrap()
                .insert(key.into(), v);
        })
    };
    for (text, key) in [
        (set("load", "axial_n", (-5.0).into()), "load.axial_n"),
        (set("rollers", "count", 2.into()), "rollers.count"),
        (
            set("lubricant", "temperature_c", 400.0.into()),
            "lubricant.temperature_c",
        ),
        (
            set("lubricant", "alpha_per_mpa", (-0.02).into()),
            "lubricant.alpha_per_mpa",
        ),
        (
            set(
                "lubricant",
                "roughness_mm",
                toml::Value::Array(vec![(-1.0).into(), 0.0002.into()]),
            ),
            "lubricant.roughness_mm",
        ),
        (set("friction", "mu", 3.0.into()), "friction.mu"),
        (
            set("friction", "regularisation_speed_mm_s", (-1.0).into()),
            "friction.regularisation_speed_mm_s",
        ),
        (
            set("speed", "rpm", toml::Value::Array(vec![0.0.into()])),
            "speed.rpm",
        ),
    ] {
        let line = bad(&text);
        assert!(line.contains(key), "{key}: {line}");
    }
    let pimp = PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .join("../../examples/roller_rib_torus_torus.toml");
    let line = bad(&std::fs::read_to_string(pimp).unwrap());
    assert!(line.contains("method = \"friction\""), "{line}");
}

/// Combined load (issue 28 §5): `[load] radial_n` and `moment_nmm` beside `axial_n`; the
/// JSON's totals are the sums over its per-roller table, the rollers outside the load
/// zone have no rib load without the centrifugal force, the text shows every roller, and
/// a negative radial load is one line naming its key (exit status 2).
#[test]
fn combined_load_reports_every_roller_and_sums_them() {
    let text = small_case(|t| {
        let load = t["load"].as_table_mut().unwrap();
        load.insert("radial_n".into(), 30_000.0.into());
        load.insert("centrifugal".into(), false.into());
    });
    let out = run_stdin(&text, &["friction", "-", "--json"]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let r: Value = serde_json::from_slice(&out.stdout).unwrap();
    assert_eq!(r["radial_load_n"].as_f64(), Some(30_000.0));
    assert_eq!(r["bearing"]["closed_form"].as_bool(), Some(false));
    let table = r["roller_table"].as_array().unwrap();
    for row in r["rows"].as_array().unwrap() {
        let mine: Vec<&Value> = table
            .iter()
            .filter(|t| {
                t["pressure_model"] == row["model"] && t["inner_speed_rpm"] == row["speed_rpm"]
            })
            .collect();
        assert_eq!(mine.len(), 17);
        let sum = |k: &str| mine.iter().map(|t| t[k].as_f64().unwrap()).sum::<f64>();
        let f = |k: &str| row[k].as_f64().unwrap();
        assert!(
            (f("bearing_power_w") - sum("roller_power_w")).abs() < 1e-12 * f("bearing_power_w")
        );
        assert!(
            (f("rib_load_sum_n") - sum("roller_rib_load_n")).abs() < 1e-9 * f("rib_load_sum_n")
        );
        for t in &mine {
            let cup = t["cup_load_n"].as_f64().unwrap();
            assert_eq!(cup == 0.0, t["roller_rib_load_n"].as_f64() == Some(0.0));
        }
        assert!(row["rib_contacts"].as_u64().unwrap() < 17);
    }
    let out = run_stdin(&text, &["friction", "-"]);
    let s = String::from_utf8_lossy(&out.stdout);
    assert!(s.contains("every roller, pimp at 2000 rpm"), "{s}");
    assert!(s.contains("tilts held"), "{s}");
    let l = bad(&small_case(|t| {
        let load = t["load"].as_table_mut().unwrap();
        load.insert("radial_n".into(), (-5.0).into());
    }));
    assert!(l.contains("load.radial_n"), "{l}");
}
