//! The rib study's bearing (`examples/rib_friction.toml`: 60 mm bore, 17 rollers, 15 kN
//! axial) as a whole-bearing case (`examples/bearing_rib_study_60mm.toml`): the case's
//! per-roller raceway and rib loads equal the rib study's 2-D roller balance
//! (`kontakt::bearing::roller_loads`), its numbers unchanged.

#![allow(clippy::unwrap_used)] // tests: a panic is a failure with its message

use kontakt::bearing::{RollerRib, RollerSet, TaperedKinematics, roller_loads};
use kontakt_bearing::geometry::RollerBearing;
use kontakt_case::friction_case::FrictionCase;
use kontakt_case::pimp_case::roller_rib_from_spec;
use kontakt_case::{Case, Outcome};
use std::path::PathBuf;

fn examples() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../../examples")
}

/// The rib study as it builds itself: the case file read, the roller/rib pair built.
fn rib_study() -> (FrictionCase, RollerRib) {
    let text = std::fs::read_to_string(examples().join("rib_friction.toml")).unwrap();
    let case: FrictionCase = toml::from_str(&text).unwrap();
    let (_, pair) = roller_rib_from_spec(&case.geometry).unwrap().unwrap();
    (case, pair)
}

/// The whole-bearing data of the rib study's construction: the one mapping the friction
/// case uses too (`RollerBearing::of_roller_rib`).
struct Derived {
    pitch_diameter: f64,
    roller_diameter: f64,
    cup_deg: f64,
    cone_deg: f64,
    rib_deg: f64,
}

fn derived(pair: &RollerRib, rollers: &RollerSet) -> Derived {
    let b = RollerBearing::of_roller_rib(pair, rollers).unwrap();
    Derived {
        pitch_diameter: b.pitch_diameter_mm,
        roller_diameter: b.roller_diameter_mm,
        cup_deg: b.contact_angle_rad.to_degrees(),
        cone_deg: b.cone_angle_rad.to_degrees(),
        rib_deg: b.rib_angle_rad.unwrap().to_degrees(),
    }
}

/// The example's text.
fn example() -> String {
    std::fs::read_to_string(examples().join("bearing_rib_study_60mm.toml")).unwrap()
}

/// The largest relative difference, over every roller and its outer, inner and rib load,
/// between the bearing case `text` and the rib study's 2-D balance at zero speed (the
/// case is static: no centrifugal force).
fn deviation_from_the_rib_study(text: &str) -> f64 {
    let (case, pair) = rib_study();
    let k = TaperedKinematics::of_roller_rib(&pair, 0.0, 0.0).unwrap();
    let study = roller_loads(
        &k,
        &pair.contact.normal.into_inner(),
        case.load.axial_n,
        case.rollers.count,
        0.0,
    )
    .unwrap();
    let report = match Case::from_toml_str(text).unwrap().run(&examples()).unwrap() {
        Outcome::Bearing(r) => r,
        _ => panic!("not a bearing outcome"),
    };
    let rows = &report.rollers().unwrap().roller_loads;
    assert_eq!(rows.len(), case.rollers.count);
    let rel = |a: f64, b: f64| (a - b).abs() / b.abs();
    rows.iter()
        .flat_map(|r| {
            [
                rel(r.outer_load_n, study.outer_raceway),
                rel(r.inner_load_n, study.inner_raceway),
                rel(r.rib_load_n, study.rib),
            ]
        })
        .fold(0.0, f64::max)
}

/// Every roller's outer, inner and rib load of `examples/bearing_rib_study_60mm.toml`
/// equals the rib study's (`roller_loads` on the rib study's own geometry and axial load)
/// to 1e-9 relative: the file's rounded angles (1e-9°) move the loads by far less.
#[test]
fn the_rib_study_bearing_carries_the_rib_studys_roller_loads() {
    let dev = deviation_from_the_rib_study(&example());
    eprintln!("largest relative deviation: {dev:.3e}");
    assert!(dev < 1e-9, "{dev:e}");
}

/// The comparison can fail: a cup angle 0.1° off moves the loads by far more than 1e-9.
#[test]
fn a_cup_angle_off_by_a_tenth_of_a_degree_is_caught() {
    let text = example().replace(
        "cup_angle_deg = 25.481595648",
        "cup_angle_deg = 25.581595648",
    );
    assert_ne!(text, example());
    let dev = deviation_from_the_rib_study(&text);
    eprintln!("cup angle +0.1 deg: largest relative deviation {dev:.3e}");
    assert!(dev > 1e-4, "{dev:e}");
}

/// The file's numbers are the rib study's construction, rounded as written: angles to
/// 1e-9°, diameters to 1e-6 mm; the count, length and axial load exact.
#[test]
fn the_example_states_the_rib_studys_geometry() {
    let (case, pair) = rib_study();
    let d = derived(&pair, &case.rollers);
    let file: toml::Table = toml::from_str(&example()).unwrap();
    let b = file["bearing"].as_table().unwrap();
    let num = |k: &str| b[k].as_float().unwrap();
    for (key, built, step) in [
        ("pitch_diameter_mm", d.pitch_diameter, 1e-6),
        ("roller_diameter_mm", d.roller_diameter, 1e-6),
        ("cup_angle_deg", d.cup_deg, 1e-9),
        ("cone_angle_deg", d.cone_deg, 1e-9),
        ("rib_angle_deg", d.rib_deg, 1e-9),
        ("roller_length_mm", case.rollers.length, 0.0),
    ] {
        assert!(
            (num(key) - built).abs() <= 0.5 * step + 1e-12 * built,
            "{key}: {} in the file, {built:.12} built",
            num(key)
        );
    }
    assert_eq!(
        b["rollers"].as_integer().unwrap(),
        case.rollers.count as i64
    );
    let force = file["load"]["force_n"].as_array().unwrap();
    let f: Vec<f64> = force.iter().map(|v| v.as_float().unwrap()).collect();
    assert_eq!(f, [0.0, 0.0, case.load.axial_n]);
}
