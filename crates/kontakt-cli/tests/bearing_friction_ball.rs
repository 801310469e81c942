//! `kontakt bearing` on a ball bearing with `[operating]`: the friction section (inner and
//! outer race shares) in the text, the JSON and a per-ball CSV; an input error names the key
//! (exit 2).

#![allow(clippy::unwrap_used)] // test helpers: a panic is a test failure with its message

mod support;

use support::{bad, kontakt, run_json};

#[test]
fn ball_friction_in_text_json_and_csv() {
    let path = support::example("bearing_6205_friction.toml");
    let path = path.to_str().unwrap();
    let dir = support::tempdir("bearing_friction_ball", "csv");
    let csv = dir.join("balls.csv");
    let out = kontakt()
        .args(["bearing", path, "--csv", csv.to_str().unwrap()])
        .output()
        .unwrap();
    let text = String::from_utf8(out.stdout).unwrap();
    assert!(text.contains("friction at 3000/0 r/min"), "{text}");
    assert!(
        text.contains("inner race") && text.contains("outer race"),
        "{text}"
    );
    assert!(text.contains("SKF 2004: 44.87 N·mm"), "{text}");
    let rows = support::read_csv(&dir.join("balls.friction.csv"));
    assert_eq!(rows.len(), 9);
    assert!(rows[0].contains_key("inner_sliding_w"));
    let v = run_json(&["bearing", path]);
    assert!(v["friction"]["total_nmm"].as_f64().unwrap() > 0.0);
    assert_eq!(v["friction"]["balls"].as_array().unwrap().len(), 9);
    let p = dir.join("case.toml");
    let case = std::fs::read_to_string(support::example("bearing_6205_friction.toml")).unwrap();
    std::fs::write(&p, case.replace("c0_n = 7800.0", "c0_n = 0.0")).unwrap();
    let line = bad(&["bearing", p.to_str().unwrap()]);
    assert!(line.contains("catalogue.c0_n"), "{line}");
}
