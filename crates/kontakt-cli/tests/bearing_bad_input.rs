//! Issue 28, "Bad input": a bearing the geometry does not allow, or a load the bearing
//! cannot carry, is one line naming the case key, the value and why (exit status 2), never
//! a run that does not converge (exit 1) nor a silent number; every element lifted off is
//! a result with zero force and a warning (exit 0).

#![allow(clippy::unwrap_used)] // test helpers: a panic is a test failure with its message

mod support;

use std::path::{Path, PathBuf};
use support::{bad, num, run_json};

/// The example `name` with its `[load]` tables replaced by `load` and `from` replaced by
/// `to` in the rest, written to `dir/file`.
fn case(dir: &Path, file: &str, name: &str, edits: &[(&str, &str)], load: &str) -> PathBuf {
    let text = std::fs::read_to_string(support::example(name)).unwrap();
    let mut head = text[..text.find("[load").unwrap()].to_string();
    for (from, to) in edits {
        assert!(head.contains(from), "{name}: {from}");
        head = head.replace(from, to);
    }
    let p = dir.join(file);
    std::fs::write(&p, format!("{head}{load}\n")).unwrap();
    p
}

/// One bad case: the example, its edits (from, to), its `[load]` tables, the error's start.
type BadCase<'a> = (&'a str, &'a [(&'a str, &'a str)], String, &'a str);

/// Each item of the list, with the error's start: the key, the value and the
/// reason. Those marked "was" ran before (a silent number, or exit 1 "did not converge").
#[test]
fn loads_and_geometries_a_bearing_cannot_take_are_named() {
    let dir = support::tempdir("bearing_bad_input", "named");
    let tilts_held = "[load.prescribed]\ntilt_x_rad = 0.0\ntilt_y_rad = 0.0";
    let cases: [BadCase; 10] = [
        // a roller longer than its raceway (was: solved silently)
        (
            "bearing_nu_crb.toml",
            &[(
                "[bearing.roller_profile]",
                "[bearing.inner_profile]\nkind = \"logarithmic_flat\"\ndrop_scale_mm = 0.001\nlength_mm = 10.9\n\n[bearing.roller_profile]",
            )],
            format!("[load]\nforce_n = [10000.0, 0.0, 0.0]\n{tilts_held}"),
            "invalid bearing.inner_profile.length_mm = 10.9: expected a profile that covers the roller's effective length L_we = 11 mm (length_mm >= 11; a roller longer than its raceway)",
        ),
        // a roller whose crowned length is shorter than the roller (was: solved silently)
        (
            "bearing_nu_crb.toml",
            &[(
                "kind = \"iso\"",
                "kind = \"lundberg\"\nload_n = 5000.0\nlength_mm = 10.8",
            )],
            format!("[load]\nforce_n = [10000.0, 0.0, 0.0]\n{tilts_held}"),
            "invalid bearing.roller_profile.length_mm = 10.8: expected a profile that covers",
        ),
        // an element that does not fit between the rings
        (
            "bearing_nu_crb.toml",
            &[("roller_diameter_mm = 11.0", "roller_diameter_mm = 70.0")],
            format!("[load]\nforce_n = [10000.0, 0.0, 0.0]\n{tilts_held}"),
            "bearing.roller_diameter_mm: a roller of diameter 70 mm does not fit between the rings",
        ),
        (
            "bearing_6205.toml",
            &[("balls = 9", "balls = 16")],
            format!("[load]\nforce_n = [2000.0, 0.0, 0.0]\n{tilts_held}"),
            "bearing.balls: 16 balls of diameter 7.938 mm do not fit",
        ),
        // a TRB with a zero cone angle
        (
            "bearing_32008x.toml",
            &[("cone_angle_deg = 11.17", "cone_angle_deg = 0.0")],
            format!("[load]\nforce_n = [5000.0, 0.0, 3000.0]\n{tilts_held}"),
            "invalid bearing.cone_angle_deg = 0: expected 0 < cone angle < cup_angle_deg = 14.17 deg",
        ),
        // an axial load on an NU bearing
        (
            "bearing_nu_crb.toml",
            &[],
            format!("[load]\nforce_n = [10000.0, 0.0, 500.0]\n{tilts_held}"),
            "invalid load.force_n[2] = 500: expected 0: a cylindrical roller bearing carries no axial load",
        ),
        // a pure radial load on a single TRB without an axial reaction
        (
            "bearing_32008x.toml",
            &[],
            format!("[load]\nforce_n = [5000.0, 0.0, 0.0]\n{tilts_held}"),
            "invalid load.force_n[2] = 0: expected an axial load > F_r tan(alpha)",
        ),
        // a moment on a single-row TRB with clearance and no axial load (was: exit 1,
        // "did not converge", no key named)
        (
            "bearing_32008x.toml",
            &[("clearance_mm = 0.0", "clearance_mm = 0.02")],
            "[load]\nmoment_nmm = [20000.0, 0.0]".to_string(),
            "invalid load.moment_nmm[0] = 20000: expected |M| < F_z (d_m/2 + L_we/(2 sin alpha)) = 0.000000 N mm: a single-row tapered roller bearing carries a moment only through its axial load",
        ),
        // a moment on a thrust bearing beyond what its axial load holds (was: exit 1)
        (
            "bearing_81107_thrust.toml",
            &[],
            "[load]\nforce_n = [0.0, 0.0, 100.0]\nmoment_nmm = [0.0, -2000000.0]".to_string(),
            "invalid load.moment_nmm[1] = -2000000: expected |M| < F_z (d_m/2 + L_we/(2 sin alpha)) = 2450.000000 N mm",
        ),
        // a radial load on an angular-contact ball bearing without axial load (was: exit 1)
        (
            "bearing_7205.toml",
            &[],
            format!("[load]\nforce_n = [2000.0, 0.0, 0.0]\n{tilts_held}"),
            "invalid load.force_n[2] = 0: expected an axial load > 0 N: a single-row angular-contact ball bearing carries a radial load only together with an axial load",
        ),
    ];
    for (k, (name, edits, load, want)) in cases.iter().enumerate() {
        let p = case(&dir, &format!("case{k}.toml"), name, edits, load);
        let e = bad(&["bearing", p.to_str().unwrap()]);
        assert!(
            e.contains(want),
            "{name} {edits:?} {load}:\n{e}\nwant: {want}"
        );
    }
    // a moment alone on an angular-contact ball bearing (was: exit 1)
    let p = case(
        &dir,
        "acbb_moment.toml",
        "bearing_7205.toml",
        &[],
        "[load]\nmoment_nmm = [20000.0, 0.0]",
    );
    let e = bad(&["bearing", p.to_str().unwrap()]);
    assert!(
        e.contains("invalid load.force_n[2] = 0: expected an axial load > 0 N: a single-row angular-contact ball bearing carries a moment only"),
        "{e}"
    );
}

/// Every element lifted off (a prescribed displacement inside the clearance, or no load):
/// a result with zero force and the warning, for a roller and a ball bearing.
#[test]
fn every_element_lifted_off_is_zero_force_and_a_warning() {
    let dir = support::tempdir("bearing_bad_input", "lifted");
    for (name, load, word) in [
        (
            "bearing_nu_crb.toml",
            "[load.prescribed]\ndx_mm = 0.005\ntilt_x_rad = 0.0\ntilt_y_rad = 0.0",
            "roller",
        ),
        (
            "bearing_nu_crb.toml",
            "[load]\nforce_n = [0.0, 0.0, 0.0]",
            "roller",
        ),
        (
            "bearing_6205.toml",
            "[load.prescribed]\ndx_mm = 0.005\ntilt_x_rad = 0.0\ntilt_y_rad = 0.0",
            "ball",
        ),
    ] {
        let p = case(&dir, "lifted.toml", name, &[], load);
        let v = run_json(&["bearing", p.to_str().unwrap()]);
        for i in 0..3 {
            assert_eq!(num(&v["force_n"][i]), 0.0, "{name} {load}: {v}");
        }
        let warnings = v["warnings"].to_string();
        assert!(
            warnings.contains(&format!("every {word} is lifted off")),
            "{name} {load}: {warnings}"
        );
    }
}
