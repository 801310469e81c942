//! `method = "bem"` cases and `kontakt validate`: JSON keys, CSV columns, report files,
//! and one-line errors for bad maps.

#![allow(clippy::unwrap_used)] // test helpers: a panic is a test failure with its message

use assert_cmd::Command;
use serde_json::Value;
use std::path::{Path, PathBuf};

fn kontakt() -> Command {
    Command::cargo_bin("kontakt").expect("binary built")
}

fn examples() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../../examples")
}

fn scratch(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("kontakt-cli-bem-{}-{name}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    dir
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

fn write_case(dir: &Path, map_file: &str, force: f64) -> PathBuf {
    let case = dir.join("case.toml");
    std::fs::write(
        &case,
        format!(
            "method = \"bem\"\n[geometry]\nkind = \"map\"\nfile = \"{map_file}\"\n\
             spacing_mm = [0.01, 0.01]\n[body1]\ne_mpa = 210000.0\nnu = 0.3\n\
             [body2]\ne_mpa = 210000.0\nnu = 0.3\n[load]\nforce_n = {force}\n"
        ),
    )
    .unwrap();
    case
}

#[test]
fn roller_rib_bem_json_matches_local_hertz_and_reports_the_solver() {
    let case = examples().join("bem_torus_torus.toml");
    let out = kontakt()
        .args(["solve", case.to_str().unwrap(), "--json"])
        .output()
        .unwrap();
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let v: Value = serde_json::from_slice(&out.stdout).unwrap();
    assert_eq!(v["method"], "bem");
    assert!(v["mode"].is_null());
    assert_eq!(v["solver"]["converged"], true);
    assert!(v["solver"]["residual"].as_f64().unwrap() <= 1e-8);
    // torus-torus-14 is nearly Hertzian: the coupled solver lands on local Hertz (2 %).
    let p = v["max_pressure_mpa"].as_f64().unwrap();
    let ph = v["hertz"]["max_pressure_mpa"].as_f64().unwrap();
    assert!((p / ph - 1.0).abs() < 0.02, "{p} vs Hertz {ph}");
    assert!((v["force_n"].as_f64().unwrap() - 250.0).abs() < 1e-9);
}

#[test]
fn map_case_writes_pressure_displacement_and_gap_columns() {
    let dir = scratch("csv");
    let csv = dir.join("fields.csv");
    let case = examples().join("bem_wavy_map.toml");
    let out = kontakt()
        .args([
            "solve",
            case.to_str().unwrap(),
            "--csv",
            csv.to_str().unwrap(),
        ])
        .output()
        .unwrap();
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let text = std::fs::read_to_string(&csv).unwrap();
    let mut lines = text.lines();
    assert_eq!(
        lines.next().unwrap(),
        "x_mm,y_mm,pressure_mpa,displacement_mm,gap_mm"
    );
    assert_eq!(lines.count(), 64 * 64);
    // The waviness splits the contact into separate bands.
    let stdout = String::from_utf8(out.stdout).unwrap();
    let patches = stdout.lines().find(|l| l.contains("patches")).unwrap();
    assert!(patches.trim().ends_with('3'), "{patches}");
}

#[test]
fn bad_maps_are_one_line_errors_naming_the_place() {
    let dir = scratch("bad");
    std::fs::write(dir.join("nan.csv"), "0,1,2\n1,nan,2\n2,1,0\n").unwrap();
    let e = bad(&["solve", write_case(&dir, "nan.csv", 1.0).to_str().unwrap()]);
    assert!(
        e.contains("geometry.file") && e.contains("row 2, column 2"),
        "{e}"
    );

    std::fs::write(dir.join("ragged.csv"), "0,1,2\n1,2\n").unwrap();
    let e = bad(&[
        "solve",
        write_case(&dir, "ragged.csv", 1.0).to_str().unwrap(),
    ]);
    assert!(e.contains("row 2 has 2 values"), "{e}");

    let e = bad(&[
        "solve",
        write_case(&dir, "missing.csv", 1.0).to_str().unwrap(),
    ]);
    assert!(e.contains("geometry.file"), "{e}");

    // A Hertz gap on a small map cannot carry 50 kN: the contact reaches the border.
    let mut rows = Vec::new();
    for j in 0..24 {
        let y = (j as f64 + 0.5 - 12.0) * 0.01;
        let row: Vec<String> = (0..24)
            .map(|i| {
                let x = (i as f64 + 0.5 - 12.0) * 0.01;
                format!("{:e}", (x * x + y * y) / 20.0)
            })
            .collect();
        rows.push(row.join(","));
    }
    std::fs::write(dir.join("sphere.csv"), rows.join("\n")).unwrap();
    let e = bad(&[
        "solve",
        write_case(&dir, "sphere.csv", 50_000.0).to_str().unwrap(),
    ]);
    assert!(e.contains("border"), "{e}");
}

#[test]
fn a_pimp_case_cannot_take_a_map() {
    let dir = scratch("pimp-map");
    let case = write_case(&dir, "x.csv", 1.0);
    let text = std::fs::read_to_string(&case)
        .unwrap()
        .replace("\"bem\"", "\"pimp\"");
    std::fs::write(&case, text).unwrap();
    let e = bad(&["solve", case.to_str().unwrap()]);
    assert!(e.contains("geometry.kind") && e.contains("bem"), "{e}");
}

#[test]
fn validate_writes_the_report_folder() {
    let dir = scratch("validate");
    let out = kontakt()
        .args([
            "validate",
            "--cells",
            "32",
            "--out",
            dir.to_str().unwrap(),
            "--json",
        ])
        .output()
        .unwrap();
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let v: Value = serde_json::from_slice(&out.stdout).unwrap();
    let pairings = v["pairings"].as_array().unwrap();
    assert_eq!(pairings.len(), 8);
    for p in pairings {
        assert_eq!(p["rows"].as_array().unwrap().len(), 7);
    }
    for f in [
        "report.md",
        "results.csv",
        "shape_torus-cone-28.png",
        "torus-torus_max_pressure.png",
    ] {
        assert!(dir.join(f).is_file(), "{f} missing");
    }
    let csv = std::fs::read_to_string(dir.join("results.csv")).unwrap();
    assert_eq!(csv.lines().count(), 1 + 8 * 7);
    assert!(bad(&["validate", "--cells", "4"]).contains("--cells"));
    // The table's last line counts exactly the pictures written.
    let dir = scratch("validate-table");
    let out = kontakt()
        .args(["validate", "--cells", "32", "--out", dir.to_str().unwrap()])
        .output()
        .unwrap();
    assert!(out.status.success());
    let stdout = String::from_utf8(out.stdout).unwrap();
    let names: Vec<String> = std::fs::read_dir(&dir)
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .collect();
    let plots = names
        .iter()
        .filter(|n| n.ends_with("_contact_area.png") || n.ends_with("_max_pressure.png"))
        .count();
    let maps = names.iter().filter(|n| n.starts_with("shape_")).count();
    assert_eq!((plots, maps, names.len()), (8, 8, 18), "{names:?}");
    let expected = format!(
        "report.md, results.csv and {} pictures ({plots} deviation plots, {maps} contact-shape maps)",
        plots + maps
    );
    assert!(
        stdout.lines().last().unwrap().ends_with(&expected),
        "{stdout}"
    );
}
