//! `[bearing] boundary`: a whole-bearing case from its boundary dimensions
//! (`kontakt_case::bearing_design`, the rules in `kontakt_bearing::geometry::design`).
//!
//! - The representative examples (6205, 7205 B, NU 208, 81107) rebuilt from `boundary`
//!   with only what the rules do not give (clearance, the balls' 7.938 mm as the files
//!   round the generated 7.9375 mm, the 7205's groove radii, the loads) give the examples'
//!   reports exactly.
//! - The published TRBs (32008 X, 32216) from `boundary` and e solve; the file's keys win
//!   over the generated ones.
//! - Bad boundaries are one error naming `bearing.boundary.<key>`.

#![allow(clippy::unwrap_used)] // tests: a panic is a failure with its message

use kontakt_case::{Case, Outcome};
use std::path::PathBuf;

/// The keys the rules generate for a tapered bearing.
const TAPERED: [&str; 6] = [
    "pitch_diameter_mm",
    "rollers",
    "roller_diameter_mm",
    "roller_length_mm",
    "cup_angle_deg",
    "cone_angle_deg",
];

/// The keys the rules generate for a cylindrical or thrust bearing.
const ROLLER: [&str; 4] = [
    "pitch_diameter_mm",
    "rollers",
    "roller_diameter_mm",
    "roller_length_mm",
];

fn examples() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../../examples")
}

fn report(text: &str) -> serde_json::Value {
    let out = Case::from_toml_str(text).unwrap().run(&examples()).unwrap();
    let Outcome::Bearing(r) = out else {
        panic!("not a bearing outcome")
    };
    let mut v = serde_json::to_value(&r).unwrap();
    let o = v.as_object_mut().unwrap();
    o.remove("name");
    o.remove("inputs");
    v
}

fn example(name: &str) -> String {
    std::fs::read_to_string(examples().join(name)).unwrap()
}

/// The `[bearing]` keys of `name` that the rules generate, replaced by `boundary`.
fn from_boundary(name: &str, keys: &[&str], boundary: &str) -> String {
    let text = example(name);
    let mut out = String::new();
    for line in text.lines() {
        let key = line.split('=').next().unwrap_or("").trim();
        if keys.contains(&key) {
            continue;
        }
        out.push_str(line);
        out.push('\n');
        if line.trim() == "[bearing]" {
            out.push_str(&format!("boundary = {boundary}\n"));
        }
    }
    out
}

#[test]
fn the_representative_examples_come_back_from_their_boundary_dimensions() {
    for (name, keys, boundary) in [
        (
            "bearing_6205.toml",
            &[
                "pitch_diameter_mm",
                "balls",
                "inner_osculation",
                "outer_osculation",
            ][..],
            "{ d_mm = 25.0, D_mm = 52.0, B_mm = 15.0 }",
        ),
        (
            "bearing_7205.toml",
            &["pitch_diameter_mm", "balls", "contact_angle_deg"][..],
            "{ d_mm = 25.0, D_mm = 52.0, B_mm = 15.0 }",
        ),
        (
            "bearing_nu_crb.toml",
            &ROLLER[..],
            "{ d_mm = 40.0, D_mm = 80.0, B_mm = 18.0 }",
        ),
        (
            "bearing_81107_thrust.toml",
            &ROLLER[..],
            "{ d_mm = 35.0, D_mm = 52.0, B_mm = 12.0 }",
        ),
    ] {
        let text = from_boundary(name, keys, boundary);
        for k in keys {
            assert!(
                !text.contains(&format!("\n{k} =")),
                "{name}: {k} still there"
            );
        }
        assert_eq!(report(&example(name)), report(&text), "{name}");
    }
}

/// The published TRBs from their boundary dimensions and e: they solve; given keys win
/// (32008 X with Liu's 23 rollers of 6.4885 mm keeps them, and its cone angle follows from
/// them by the common apex).
#[test]
fn published_trbs_from_boundary_solve_and_given_keys_win() {
    let base = example("bearing_32008x.toml");
    let generated = from_boundary(
        "bearing_32008x.toml",
        &TAPERED,
        "{ d_mm = 40.0, D_mm = 68.0, B_mm = 19.0, e = 0.38 }",
    );
    let r = report(&generated);
    eprintln!(
        "32008 X generated: {}",
        serde_json::to_string(&r["solver"]).unwrap()
    );
    assert!(r["solver"]["converged"].as_bool().unwrap());
    let given = generated.replace(
        "boundary =",
        "rollers = 23\nroller_diameter_mm = 6.4885\nboundary =",
    );
    let Case::Bearing(case) = Case::from_toml_str(&given).unwrap() else {
        panic!()
    };
    let kontakt_case::bearing_case::BearingSpec::Tapered(s) = &case.bearing else {
        panic!()
    };
    assert_eq!((s.rollers, s.roller_diameter_mm), (23, 6.4885));
    let (a, ai) = (s.cup_angle_deg.unwrap(), s.cone_angle_deg.unwrap());
    assert!((a - (0.38f64 / 1.5).atan().to_degrees()).abs() < 1e-12);
    eprintln!("32008 X with Liu's rollers: cone angle {ai:.4} deg (Liu 11.17)");
    assert!((ai - 11.17).abs() < 0.1, "{ai}");
    // the whole file's keys and the boundary together: the file wins everywhere
    let both = base.replace(
        "[bearing]\n",
        "[bearing]\nboundary = { d_mm = 40.0, D_mm = 68.0, B_mm = 19.0, e = 0.38 }\n",
    );
    assert_eq!(report(&both), report(&base));
    let r = report(&from_boundary(
        "bearing_32216.toml",
        &TAPERED,
        "{ d_mm = 80.0, D_mm = 140.0, B_mm = 33.0, e = 0.43 }",
    ));
    assert!(r["solver"]["converged"].as_bool().unwrap());
}

/// A sweep edits the table: the boundary is expanded there too.
#[test]
fn a_table_with_a_boundary_reads_as_the_text() {
    let text = from_boundary(
        "bearing_nu_crb.toml",
        &ROLLER[..],
        "{ d_mm = 40.0, D_mm = 80.0, B_mm = 18.0 }",
    );
    let table: toml::Table = toml::from_str(&text).unwrap();
    let a = Case::from_toml_table(table).unwrap();
    let b = Case::from_toml_str(&text).unwrap();
    assert_eq!(format!("{a:?}"), format!("{b:?}"));
}

#[test]
fn bad_boundaries_are_one_line_naming_the_key() {
    let base = from_boundary(
        "bearing_32008x.toml",
        &TAPERED,
        "{ d_mm = 40.0, D_mm = 68.0, B_mm = 19.0, e = 0.38 }",
    );
    for (from, to, key) in [
        ("e = 0.38 }", "}", "bearing.boundary.e"),
        ("D_mm = 68.0", "D_mm = 30.0", "bearing.boundary.D_mm"),
        ("d_mm = 40.0", "d_mm = -1.0", "bearing.boundary.d_mm"),
        ("B_mm = 19.0", "B_mm = 0.0", "bearing.boundary.B_mm"),
        ("e = 0.38", "e = 0.38, x_mm = 1.0", "bearing.boundary"),
        ("d_mm = 40.0", "d_mm = \"40\"", "bearing.boundary"),
    ] {
        let text = base.replace(from, to);
        assert_ne!(text, base);
        let e = Case::from_toml_str(&text).unwrap_err();
        let msg = e.to_string();
        assert!(msg.contains(key), "{key}: {msg}");
        assert!(!msg.contains('\n'), "{msg}");
    }
}
