//! `kontakt bearing` with `[operating]`: the friction section in the text, the JSON and a
//! per-roller CSV beside the roller loads; input errors name the key (exit 2).

#![allow(clippy::unwrap_used)] // test helpers: a panic is a test failure with its message

mod support;

use support::{bad, kontakt, run_json};

#[test]
fn friction_section_in_text_json_and_csv() {
    let path = support::example("bearing_32008x_friction.toml");
    let path = path.to_str().unwrap();
    let dir = support::tempdir("bearing_friction", "csv");
    let csv = dir.join("rollers.csv");
    let out = kontakt()
        .args(["bearing", path, "--csv", csv.to_str().unwrap()])
        .output()
        .unwrap();
    let text = String::from_utf8(out.stdout).unwrap();
    assert!(text.contains("friction at 1000/0 r/min"), "{text}");
    assert!(text.contains("SKF 2004: 875.74 N·mm"), "{text}");
    let rows = support::read_csv(&dir.join("rollers.friction.csv"));
    assert_eq!(rows.len(), 23);
    assert!(rows[0].contains_key("cone_rolling_w"));
    let v = run_json(&["bearing", path]);
    assert!(v["friction"]["total_nmm"].as_f64().unwrap() > 0.0);
}

#[test]
fn friction_input_errors_name_the_key() {
    let dir = support::tempdir("bearing_friction", "errors");
    let text = std::fs::read_to_string(support::example("bearing_32008x_friction.toml")).unwrap();
    for (from, to, key) in [
        ("inner_rpm = 1000.0", "inner_rpm = inf", "speed.inner_rpm"),
        (
            "supply = \"circulating\"",
            "supply = \"oil_bath\"",
            "operating.oil_level_mm",
        ),
        (
            "temperature_c = 55.0",
            "temperature_c = 300.0",
            "lubricant.temperature_c",
        ),
    ] {
        let p = dir.join("case.toml");
        std::fs::write(&p, text.replace(from, to)).unwrap();
        let line = bad(&["bearing", p.to_str().unwrap()]);
        assert!(line.contains(key), "{key}: {line}");
    }
}
