//! `kontakt bearing`: the table of the examples, the JSON keys, `kontakt solve` of the same
//! case, the per-roller CSV, and one-line input errors naming the case key (exit 2).

#![allow(clippy::unwrap_used)] // test helpers: a panic is a test failure with its message

mod support;

use std::path::PathBuf;
use support::{bad, kontakt, num, run_json};

fn example(name: &str) -> PathBuf {
    support::example(name)
}

/// A case file: the example `name` with `from` replaced by `to`.
fn edited_example(dir: &std::path::Path, name: &str, from: &str, to: &str) -> PathBuf {
    let text = std::fs::read_to_string(example(name)).unwrap();
    assert!(text.contains(from), "{from}");
    let p = dir.join("case.toml");
    std::fs::write(&p, text.replace(from, to)).unwrap();
    p
}

/// Run `kontakt args`, which must succeed.
fn succeeds(args: &[&std::ffi::OsStr]) {
    let out = kontakt().args(args).output().unwrap();
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
}

/// The rows of the text table under the header line holding `header`.
fn table_rows(text: &str, header: &str) -> usize {
    text.lines()
        .skip_while(|l| !l.contains(header))
        .skip(1)
        .take_while(|l| !l.trim().is_empty())
        .count()
}

/// The text table of `kontakt bearing examples/<name>`, which must succeed.
fn table_of(name: &str) -> String {
    let out = kontakt()
        .args(["bearing", example(name).to_str().unwrap()])
        .output()
        .unwrap();
    assert!(out.status.success());
    String::from_utf8(out.stdout).unwrap()
}

/// The table: the header, the solver line and one row per roller (16 for the 32216).
#[test]
fn table_of_the_32216() {
    let out = kontakt()
        .args(["bearing", example("bearing_32216.toml").to_str().unwrap()])
        .output()
        .unwrap();
    assert!(out.status.success());
    let text = String::from_utf8(out.stdout).unwrap();
    assert!(text.contains("tapered roller bearing: 32216"), "{text}");
    assert!(text.contains("solver:       converged"), "{text}");
    assert!(text.contains("load zone ε = "), "{text}");
    assert_eq!(table_rows(&text, "Q_rib N"), 16, "{text}");
    assert!(text.contains("stiffness matrix"), "{text}");
}

/// The JSON keys (units in their names), `kontakt solve` giving the same document, and the
/// per-roller CSV with one row per roller and the report's keys as its header.
#[test]
fn json_keys_solve_and_csv() {
    let path = example("bearing_nu_crb.toml");
    let v = run_json(&["bearing", path.to_str().unwrap()]);
    for key in [
        "schema_version",
        "bearing_type",
        "displacement_mm",
        "tilt_rad",
        "force_n",
        "moment_nmm",
        "solver",
        "load_zone_epsilon",
        "max_roller_load_n",
        "roller_loads",
        "most_loaded_roller",
        "stiffness_matrix",
        "stiffness_units",
        "stiffness_dofs",
    ] {
        assert!(!v[key].is_null(), "{key} missing: {v}");
    }
    assert_eq!(v["method"], "bearing");
    assert_eq!(v["solver"]["termination"], "converged");
    assert_eq!(v["roller_loads"].as_array().unwrap().len(), 14);
    let row = &v["roller_loads"][0];
    for key in [
        "azimuth_deg",
        "inner_load_n",
        "outer_load_n",
        "rib_load_n",
        "max_load_per_length_n_per_mm",
        "approach_mm",
        "inner_max_pressure_mpa",
        "outer_max_pressure_mpa",
    ] {
        assert!(row[key].is_number(), "{key}: {row}");
    }
    // the pressures: a CRB's inner raceway is the more stressed (convex), and the static
    // safety from the pressure is (4000 MPa / p_max)^2
    let p_in = num(&v["max_inner_pressure_mpa"]);
    assert!(p_in > num(&v["max_outer_pressure_mpa"]) && p_in > 500.0);
    let rating = &v["rating"];
    assert_eq!(num(&rating["pressure_limit_mpa"]), 4000.0);
    let s0 = num(&rating["static_safety_from_pressure"]);
    assert!((s0 - (4000.0 / p_in).powi(2)).abs() < 1e-9 * s0, "{rating}");
    assert_eq!(v["stiffness_units"][0][0], "N/mm");
    assert_eq!(v["stiffness_units"][3][4], "N*mm/rad");
    assert!((num(&v["force_n"][0]) - 10_000.0).abs() < 1e-6);
    let solved = run_json(&["solve", path.to_str().unwrap()]);
    assert_eq!(solved, v);
    let dir = support::tempdir("bearing", "csv");
    let csv = dir.join("rollers.csv");
    let out = kontakt()
        .args(["bearing", path.to_str().unwrap(), "--csv"])
        .arg(&csv)
        .output()
        .unwrap();
    assert!(out.status.success());
    let text = std::fs::read_to_string(&csv).unwrap();
    let mut lines = text.lines();
    assert_eq!(
        lines.next().unwrap(),
        "azimuth_deg,inner_load_n,outer_load_n,rib_load_n,max_load_per_length_n_per_mm,approach_mm,inner_max_pressure_mpa,outer_max_pressure_mpa"
    );
    assert_eq!(lines.count(), 14);
    // `kontakt solve` has no per-roller CSV: an input error pointing at `kontakt bearing`
    let e = bad(&[
        "solve",
        path.to_str().unwrap(),
        "--csv",
        csv.to_str().unwrap(),
    ]);
    assert!(e.contains("kontakt bearing"), "{e}");
}

/// Input errors: one line, exit status 2, naming the key as the case file has it.
#[test]
fn input_errors_name_the_case_key() {
    let dir = support::tempdir("bearing", "errors");
    let crb_load = "force_n = [10000.0, 0.0, 0.0]";
    let both = format!("{crb_load}\nmoment_nmm = [5.0, 0.0]");
    // (example, replaced, by, the error names)
    let cases = [
        // a misspelt key
        (
            "bearing_32216.toml",
            "roller_diameter_mm = 17.0",
            "roller_diamter_mm = 17.0",
            "bearing.roller_diamter_mm",
        ),
        // a value out of range
        (
            "bearing_32216.toml",
            "roller_diameter_mm = 17.0",
            "roller_diameter_mm = -17.0",
            "bearing.roller_diameter_mm",
        ),
        // an angle, said in degrees
        (
            "bearing_32216.toml",
            "cone_angle_deg = 11.7",
            "cone_angle_deg = 20.0",
            "bearing.cone_angle_deg = 20",
        ),
        // an unknown profile key inside the tagged table
        (
            "bearing_32216.toml",
            "kind = \"iso\"",
            "kind = \"circular\"\nradius_mm = 500.0\nfoo = 1",
            "bearing.roller_profile.foo",
        ),
        // a radial load on a single TRB without enough axial load
        (
            "bearing_32216.toml",
            "force_n = [20000.0, 0.0, 10000.0]",
            "force_n = [20000.0, 0.0, 1000.0]",
            "load.force_n[2]",
        ),
        // an axial load on a cylindrical roller bearing
        (
            "bearing_nu_crb.toml",
            crb_load,
            "force_n = [10000.0, 0.0, 500.0]",
            "load.force_n[2] = 500: expected 0: a cylindrical",
        ),
        // a force and a prescribed displacement on the same degree of freedom
        ("bearing_nu_crb.toml", crb_load, &both, "load.moment_nmm[0]"),
        // a load rating out of range, an unknown rating key
        (
            "bearing_nu_crb.toml",
            "slices = 31",
            "slices = 31\n[bearing.rating]\ndynamic_n = -1.0",
            "bearing.rating.dynamic_n = -1",
        ),
        (
            "bearing_nu_crb.toml",
            "slices = 31",
            "slices = 31\n[bearing.rating]\ndynamic = 1.0",
            "bearing.rating.dynamic",
        ),
        (
            "bearing_6205.toml",
            "static_n = 7850.0",
            "static_n = 7850.0\nedge_stress_factor = true",
            "bearing.rating.edge_stress_factor",
        ),
    ];
    for (name, from, to, names) in cases {
        let p = edited_example(&dir, name, from, to);
        let e = bad(&["bearing", p.to_str().unwrap()]);
        assert!(e.contains(names), "{name} with {to}: {e}");
    }
    // a case of another method
    let e = bad(&[
        "bearing",
        example("mindlin_fretting.toml").to_str().unwrap(),
    ]);
    assert!(e.contains("kontakt mindlin"), "{e}");
}

/// `--plot` and `--slice-plot` write their images; a file of another kind is an input error
/// naming it (exit 2).
#[test]
fn plots_are_written() {
    let dir = support::tempdir("bearing", "plots");
    let (load, slices) = (dir.join("load.svg"), dir.join("slices.png"));
    succeeds(&[
        "bearing".as_ref(),
        example("bearing_32008x.toml").as_os_str(),
        "--plot".as_ref(),
        load.as_os_str(),
        "--slice-plot".as_ref(),
        slices.as_os_str(),
    ]);
    assert!(std::fs::read_to_string(&load).unwrap().contains("<svg"));
    assert!(std::fs::metadata(&slices).unwrap().len() > 1000);
    // the polar diagram names the loaded arc and the load; the bars and the map
    let svg = std::fs::read_to_string(&load).unwrap();
    for text in [
        "loaded arc",
        "radial load 5000 N",
        "roller load [N]",
        "0°",
        "180°",
    ] {
        assert!(svg.contains(text), "{text} not in the polar diagram");
    }
    let (bars, map) = (dir.join("bars.svg"), dir.join("map.svg"));
    succeeds(&[
        "bearing".as_ref(),
        example("bearing_32008x.toml").as_os_str(),
        "--element-plot".as_ref(),
        bars.as_os_str(),
        "--map".as_ref(),
        map.as_os_str(),
    ]);
    let svg = std::fs::read_to_string(&bars).unwrap();
    assert!(svg.contains("rib load [N]") && svg.contains("roller load [N]"));
    let svg = std::fs::read_to_string(&map).unwrap();
    assert!(svg.contains("load per length [N/mm]") && svg.contains("azimuth ψ [deg]"));
    let e = bad(&[
        "bearing",
        example("bearing_32008x.toml").to_str().unwrap(),
        "--plot",
        dir.join("load.gif").to_str().unwrap(),
    ]);
    assert!(e.contains("load.gif"), "{e}");
}

/// Ball bearings: the table (header, one row per ball), the JSON keys (the common ones,
/// `ball_loads` rows, no roller keys), the per-ball CSV, the load plot, and `--slice-plot`
/// refused as an input error naming the flag (exit 2, nothing solved).
#[test]
fn ball_bearing_table_json_csv_and_plots() {
    let dir = support::tempdir("bearing", "balls");
    let path = example("bearing_6205.toml");
    let text = table_of("bearing_6205.toml");
    assert!(
        text.contains("deep groove ball bearing: 6205 class DGBB"),
        "{text}"
    );
    assert!(text.contains("9 balls, free contact angle"), "{text}");
    assert!(text.contains("solver:       converged"), "{text}");
    assert!(text.contains("largest ball load"), "{text}");
    assert_eq!(table_rows(&text, "p_out MPa"), 9, "{text}");
    assert!(text.contains("stiffness matrix"), "{text}");

    let acbb = example("bearing_7205.toml");
    let v = run_json(&["bearing", acbb.to_str().unwrap()]);
    for key in [
        "schema_version",
        "bearing_type",
        "balls",
        "free_contact_angle_deg",
        "ball_stiffness_n_per_mm1_5",
        "displacement_mm",
        "tilt_rad",
        "force_n",
        "moment_nmm",
        "solver",
        "max_ball_load_n",
        "max_inner_pressure_mpa",
        "max_outer_pressure_mpa",
        "ball_loads",
        "stiffness_dofs",
        "stiffness_matrix",
        "stiffness_units",
    ] {
        assert!(v.get(key).is_some(), "{key} missing: {v}");
    }
    for key in ["rollers", "roller_loads", "most_loaded_roller", "slices"] {
        assert!(v.get(key).is_none(), "{key} in a ball report: {v}");
    }
    assert_eq!(v["bearing_type"], "angular_contact_ball");
    assert_eq!(v["ball_loads"].as_array().unwrap().len(), 12);
    let row = &v["ball_loads"][0];
    for key in [
        "azimuth_deg",
        "load_n",
        "contact_angle_deg",
        "approach_mm",
        "inner_max_pressure_mpa",
        "outer_max_pressure_mpa",
    ] {
        assert!(row.get(key).is_some(), "{key} missing: {row}");
    }
    assert!(num(&v["max_ball_load_n"]) > 0.0);
    let solved = run_json(&["solve", acbb.to_str().unwrap()]);
    assert_eq!(solved, v);

    let (csv, plot) = (dir.join("balls.csv"), dir.join("balls.svg"));
    succeeds(&[
        "bearing".as_ref(),
        acbb.as_os_str(),
        "--csv".as_ref(),
        csv.as_os_str(),
        "--plot".as_ref(),
        plot.as_os_str(),
    ]);
    let text = std::fs::read_to_string(&csv).unwrap();
    let mut lines = text.lines();
    assert_eq!(
        lines.next().unwrap(),
        "azimuth_deg,load_n,contact_angle_deg,approach_mm,inner_max_pressure_mpa,outer_max_pressure_mpa,inner_load_n,outer_load_n,inner_contact_angle_deg,outer_contact_angle_deg,centrifugal_force_n,gyroscopic_moment_nmm"
    );
    assert_eq!(lines.count(), 12);
    let svg = std::fs::read_to_string(&plot).unwrap();
    assert!(svg.contains("<svg") && svg.contains("ball load"), "{svg}");

    for flag in ["--slice-plot", "--map"] {
        let e = bad(&[
            "bearing",
            path.to_str().unwrap(),
            flag,
            dir.join("slices.png").to_str().unwrap(),
        ]);
        assert!(e.contains(flag) && e.contains("ball bearing"), "{e}");
        assert!(!dir.join("slices.png").exists());
    }
    // the ball loads and contact angles as bars
    let bars = dir.join("bars.svg");
    succeeds(&[
        "bearing".as_ref(),
        acbb.as_os_str(),
        "--element-plot".as_ref(),
        bars.as_os_str(),
    ]);
    let svg = std::fs::read_to_string(&bars).unwrap();
    assert!(svg.contains("contact angle α [deg]") && svg.contains("free contact angle"));

    // a ball that does not fit, named by its key (exit 2)
    let p = edited_example(&dir, "bearing_6205.toml", "balls = 9", "balls = 16");
    let e = bad(&["bearing", p.to_str().unwrap()]);
    assert!(e.contains("bearing.balls"), "{e}");
}

/// A ball bearing at speed (`[speed]`): the table shows both contacts' loads and angles,
/// the centrifugal force and the gyroscopic moment per ball and the load zone; the JSON
/// echoes the speeds; a speed on a roller bearing is an input error naming the key.
#[test]
fn ball_bearing_at_speed_table_and_json() {
    let path = example("bearing_7205_speed.toml");
    let text = table_of("bearing_7205_speed.toml");
    assert!(
        text.contains("speed: inner ring 15000 r/min, outer ring 0 r/min; outer-race control"),
        "{text}"
    );
    assert!(text.contains("load zone ε = 1."), "{text}");
    assert_eq!(table_rows(&text, "M_g N mm"), 12, "{text}");
    let v = run_json(&["bearing", path.to_str().unwrap()]);
    assert_eq!(v["ring_speeds_rpm"][0], 15_000.0);
    assert!(num(&v["ball_loads"][0]["centrifugal_force_n"]) > 10.0);
    assert!(num(&v["ball_loads"][0]["outer_contact_angle_deg"]) < 40.0);
    let dir = support::tempdir("bearing", "speed");
    // the ISO roller model at speed: solved without centrifugal force, with a warning
    let crb = edited_example(
        &dir,
        "bearing_nu_crb.toml",
        "[load]",
        "[speed]\ninner_rpm = 3000.0\n\n[load]",
    );
    let v = run_json(&["bearing", crb.to_str().unwrap()]);
    assert_eq!(v["ring_speeds_rpm"][0], 3000.0);
    let w = v["warnings"][0].as_str().unwrap();
    assert!(w.contains("roller_model = \"rib_contact\""), "{w}");
    // a thrust bearing at speed is refused, naming the key
    let thrust = edited_example(
        &dir,
        "bearing_81107_thrust.toml",
        "[load]",
        "[speed]\ninner_rpm = 3000.0\n\n[load]",
    );
    let msg = bad(&["bearing", thrust.to_str().unwrap()]);
    assert!(msg.contains("speed.inner_rpm"), "{msg}");
}

/// `[bearing.rating]`: with C and C0 the table and the JSON give the ISO 281 life, the
/// ISO 76 static safety and (rollers) the lamina life; a load above the static capacity is
/// a warning, not an error.
#[test]
fn rating_lives_and_static_safety() {
    let dir = support::tempdir("bearing", "rating");
    let p = edited_example(
        &dir,
        "bearing_nu_crb.toml",
        "slices = 31",
        "slices = 31\n[bearing.rating]\ndynamic_n = 60000.0\nstatic_n = 55000.0",
    );
    let v = run_json(&["bearing", p.to_str().unwrap()]);
    let r = &v["rating"];
    // a CRB: P = F_r, L10 = (C/P)^(10/3), s0 = C0/F_r
    assert!(
        (num(&r["equivalent_dynamic_load_n"]) - 10_000.0).abs() < 1e-6,
        "{r}"
    );
    assert!(
        (num(&r["l10_mrev"]) - 6f64.powf(10.0 / 3.0)).abs() < 1e-6,
        "{r}"
    );
    assert!((num(&r["static_safety"]) - 5.5).abs() < 1e-9, "{r}");
    assert!(
        num(&r["l10r_mrev"]) > 0.0 && num(&r["reference_load_n"]) > 0.0,
        "{r}"
    );
    assert!(v.get("warnings").is_none(), "{v}");
    let out = kontakt()
        .args(["bearing", p.to_str().unwrap()])
        .output()
        .unwrap();
    let text = String::from_utf8(out.stdout).unwrap();
    assert!(
        text.contains("L10 = ") && text.contains("L10r = "),
        "{text}"
    );
    assert!(text.contains("C0/P0 = 5.5"), "{text}");
    // 20 times the load: the pressure exceeds 4000 MPa and C0/P0 < 1, both warned
    let p = edited_example(
        &dir,
        "bearing_nu_crb.toml",
        "slices = 31",
        "slices = 31\n[bearing.rating]\ndynamic_n = 60000.0\nstatic_n = 55000.0",
    );
    let text = std::fs::read_to_string(&p).unwrap();
    std::fs::write(
        &p,
        text.replace("[10000.0, 0.0, 0.0]", "[200000.0, 0.0, 0.0]"),
    )
    .unwrap();
    let v = run_json(&["bearing", p.to_str().unwrap()]);
    let w = v["warnings"].to_string();
    assert!(
        w.contains("exceeds ISO 76's 4000 MPa") && w.contains("C0/P0"),
        "{w}"
    );
}

/// `[bearing.rib_contact] model = "pimp"`: the table names the PimP rib contact and its
/// pressure, the JSON says `rib_model = "pimp"`; the Hertz example says Hertz.
#[test]
fn the_rib_model_is_named_in_the_table_and_json() {
    let hertz = table_of("bearing_rib_contact_60mm.toml");
    assert!(hertz.contains("Hertz rib contact"), "{hertz}");
    let dir = support::tempdir("bearing", "rib_pimp");
    let p = edited_example(
        &dir,
        "bearing_rib_contact_60mm.toml",
        "contact_height_mm = 2.75\n",
        "contact_height_mm = 2.75\nmodel = \"pimp\"\n",
    );
    let out = kontakt()
        .args(["bearing", p.to_str().unwrap()])
        .output()
        .unwrap();
    assert!(out.status.success());
    let text = String::from_utf8(out.stdout).unwrap();
    assert!(text.contains("PimP rib contact"), "{text}");
    let json = run_json(&["bearing", p.to_str().unwrap()]);
    assert_eq!(json["rib_model"], "pimp");
    assert!(num(&json["max_rib_pressure_mpa"]) > 700.0);
}
