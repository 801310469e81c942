//! `kontakt bearing` / `kontakt solve` with a load or temperature sweep in `[operating]`:
//! the rows in the text, the JSON and `<stem>.friction_sweep.csv`; the friction section's
//! bad input is one line naming the key, the value and the range (exit 2).

#![allow(clippy::unwrap_used)] // test helpers: a panic is a test failure with its message

mod support;

use support::{bad, kontakt, run_json};

#[test]
fn radial_sweep_in_text_json_and_csv() {
    let path = support::example("bearing_32216_friction.toml");
    let path = path.to_str().unwrap();
    let dir = support::tempdir("bearing_friction_sweeps", "csv");
    let csv = dir.join("rollers.csv");
    let out = kontakt()
        .args(["bearing", path, "--csv", csv.to_str().unwrap()])
        .output()
        .unwrap();
    assert!(out.status.success());
    let text = String::from_utf8(out.stdout).unwrap();
    assert!(text.contains("radial_n sweep (N·mm)"), "{text}");
    let rows = support::read_csv(&dir.join("rollers.friction_sweep.csv"));
    assert_eq!(rows.len(), 9);
    assert_eq!(rows[8]["loaded_rollers"], "11");
    assert_eq!(rows[0]["loaded_rollers"], "16");
    // the speed sweep's rows go to the same file, with the same columns
    let speed = support::example("bearing_32008x_friction.toml");
    let speed_csv = dir.join("speed.csv");
    let out = kontakt()
        .args([
            "bearing",
            speed.to_str().unwrap(),
            "--csv",
            speed_csv.to_str().unwrap(),
        ])
        .output()
        .unwrap();
    assert!(out.status.success());
    let speed_rows = support::read_csv(&dir.join("speed.friction_sweep.csv"));
    assert_eq!(speed_rows.len(), 8);
    assert_eq!(speed_rows[1]["inner_rpm"], "200.0");
    assert_eq!(speed_rows[1]["loaded_rollers"], "23");
    assert_eq!(speed_rows[0].keys().len(), rows[0].keys().len());
    let v = run_json(&["solve", path]);
    assert_eq!(
        v["friction"]["radial_load_sweep"].as_array().unwrap().len(),
        9
    );
}

#[test]
fn friction_bad_input_is_one_line_with_the_range() {
    let dir = support::tempdir("bearing_friction_sweeps", "errors");
    let text = std::fs::read_to_string(support::example("bearing_32216_friction.toml")).unwrap();
    for (from, to, key, range) in [
        (
            "oil_level_mm = 8.5",
            "oil_level_mm = 80.0",
            "operating.oil_level_mm = 80",
            "0..=62.42 mm",
        ),
        (
            "sweep_radial_n = [",
            "sweep_temperature_c = [50.0, 200.0]\nsweep_x = [",
            "operating.sweep_x",
            "",
        ),
        (
            "sweep_radial_n = [",
            "sweep_temperature_c = [50.0, 200.0]\nsweep_radial_n = [",
            "operating",
            "one sweep at a time",
        ),
        (
            "sweep_radial_n = [1000.0,",
            "sweep_temperature_c = [200.0]\n#",
            "operating.sweep_temperature_c = 200",
            "-20..=150 °C",
        ),
        (
            "temperature_c = 50.0",
            "temperature_c = -40.0",
            "lubricant.temperature_c = -40",
            "-20..=150 °C",
        ),
        (
            "sweep_radial_n = [1000.0,",
            "sweep_radial_n = [-1.0,",
            "operating.sweep_radial_n = -1",
            ">= 0 N",
        ),
    ] {
        let p = dir.join("case.toml");
        let changed = text.replace(from, to);
        assert_ne!(changed, text, "{from}");
        std::fs::write(&p, changed).unwrap();
        let line = bad(&["solve", p.to_str().unwrap()]);
        assert!(line.contains(key) && line.contains(range), "{key}: {line}");
    }
}

/// Results with a warning, not errors, through `kontakt solve`: zero speed (the starting
/// torque), an oil temperature outside the viscosity data, films outside the fit.
#[test]
fn friction_warnings_through_solve() {
    let dir = support::tempdir("bearing_friction_sweeps", "warnings");
    let text = std::fs::read_to_string(support::example("bearing_32008x_friction.toml")).unwrap();
    let p = dir.join("case.toml");
    std::fs::write(
        &p,
        text.replace("inner_rpm = 1000.0", "inner_rpm = 0.0")
            .replace("temperature_c = 55.0", "temperature_c = 10.0"),
    )
    .unwrap();
    let v = run_json(&["solve", p.to_str().unwrap()]);
    let f = &v["friction"];
    assert_eq!(f["starting"], true);
    assert!(f["total_nmm"].as_f64().unwrap() > 0.0);
    let warnings = f["warnings"].to_string();
    assert!(warnings.contains("starting torque"), "{warnings}");
    assert!(
        warnings.contains(
            "lubricant.temperature_c = 10 °C is outside the oil's viscosity data (40-100 °C"
        ),
        "{warnings}"
    );
    let v = run_json(&[
        "solve",
        support::example("bearing_32216_friction.toml")
            .to_str()
            .unwrap(),
    ]);
    let warnings = v["friction"]["warnings"].to_string();
    assert!(
        warnings.contains("outside the Dowson-Higginson film fit (its range: Moes M >= 10")
            && warnings.contains("farthest: roller"),
        "{warnings}"
    );
}
