//! `[bearing] roller_model = "rib_contact"` (docs/bearing-model.md §15): the rib study's
//! bearing under its axial load gives the rib study's 2-D roller loads to 1e-9 with every
//! roller in its own balance; the combined-load example balances its load; the new keys
//! pass the unknown-key and finiteness checks and bad input is named by its case key.

#![allow(clippy::unwrap_used)] // tests: a panic is a failure with its message

use kontakt::bearing::{RollerRib, RollerRibSpec, TaperedKinematics, roller_loads};

#[path = "support/bearing_examples.rs"]
mod bearing_examples;
use bearing_examples::{example, run};

/// The rib study's bearing case with the rib contact in the loop.
fn rib_study_with_rib_contact() -> String {
    example("bearing_rib_study_60mm.toml").replace(
        "slices = 31\n",
        "slices = 31\nroller_model = \"rib_contact\"\n\n[bearing.rib_contact]\npairing = \"sphere-torus-57\"\n",
    )
}

/// Pure axial load: every roller's cup, cone and rib load equal
/// `kontakt::bearing::roller_loads` on the rib study's own pair to 1e-9; every roller tilts
/// and reports its rib pressure; the ISO report of the same file is unchanged in keys.
#[test]
fn pure_axial_load_gives_the_rib_studys_roller_loads() {
    let text = rib_study_with_rib_contact();
    assert_ne!(text, example("bearing_rib_study_60mm.toml"));
    let report = run(&text).unwrap();
    let pair = RollerRib::new(RollerRibSpec::builtin("sphere-torus-57").unwrap()).unwrap();
    let k = TaperedKinematics::of_roller_rib(&pair, 0.0, 0.0).unwrap();
    let want = roller_loads(&k, &pair.contact.normal.into_inner(), 15_000.0, 17, 0.0).unwrap();
    let r = report.rollers().unwrap();
    assert_eq!(r.roller_model, Some("rib_contact"));
    let rel = |a: f64, b: f64| (a - b).abs() / b;
    let mut worst: f64 = 0.0;
    for row in &r.roller_loads {
        worst = worst
            .max(rel(row.outer_load_n, want.outer_raceway))
            .max(rel(row.inner_load_n, want.inner_raceway))
            .max(rel(row.rib_load_n, want.rib));
        assert!(row.roller_tilt_rad.unwrap().abs() > 0.0);
        assert!(row.rib_max_pressure_mpa.unwrap() > 100.0);
        assert_eq!(row.skew_moment_nmm, Some(0.0));
    }
    eprintln!(
        "rib {:.6} N (2-D {:.6} N), largest deviation {worst:.2e}, tilt {:.4e} rad, p_rib {:.1} MPa",
        r.roller_loads[0].rib_load_n,
        want.rib,
        r.roller_loads[0].roller_tilt_rad.unwrap(),
        r.roller_loads[0].rib_max_pressure_mpa.unwrap()
    );
    assert!(worst < 1e-9, "{worst:e}");
    let cone = r.most_loaded_roller.inner_load_n.as_ref().unwrap();
    assert!(
        (cone.iter().sum::<f64>() - r.roller_loads[r.most_loaded_roller.roller].inner_load_n).abs()
            < 1e-9 * want.inner_raceway
    );
    // the ISO report has none of the new keys
    let iso = serde_json::to_value(run(&example("bearing_rib_study_60mm.toml")).unwrap()).unwrap();
    for key in ["roller_model", "max_rib_pressure_mpa", "rib_normal_deg"] {
        assert!(iso.get(key).is_none(), "{key}");
    }
    assert!(iso["roller_loads"][0].get("roller_tilt_rad").is_none());
}

/// The combined-load example: the rollers' cone and rib forces carry the applied force to
/// 1e-9, the loads vary around the ring, the most loaded roller is at ψ = 0.
#[test]
fn the_combined_load_example_balances_its_load() {
    let report = run(&example("bearing_rib_contact_60mm.toml")).unwrap();
    let r = report.rollers().unwrap();
    let (sa, ca) = r.contact_angle_deg.to_radians().sin_cos();
    let mut f = [0.0; 3];
    for row in &r.roller_loads {
        let (s, c) = row.azimuth_deg.to_radians().sin_cos();
        f[0] += row.outer_load_n * ca * c;
        f[1] += row.outer_load_n * ca * s;
        f[2] += row.outer_load_n * sa;
    }
    for (i, applied) in [6000.0, 0.0, 15000.0].iter().enumerate() {
        assert!((f[i] - applied).abs() <= 1e-9 * 15000.0, "{i}: {}", f[i]);
    }
    assert_eq!(r.most_loaded_roller.roller, 0);
    assert!(r.roller_loads[0].rib_load_n > 1.5 * r.roller_loads[8].rib_load_n);
    assert!(r.max_rib_pressure_mpa.unwrap() > 0.0);
    assert!((r.rib_normal_deg.unwrap() - 109.716252089).abs() < 1e-8);
}

/// Bad input, one error naming the case key.
#[test]
fn bad_input_is_named_by_its_case_key() {
    let text = rib_study_with_rib_contact();
    let err = |t: &str| run(t).unwrap_err().to_string();
    let e = err(&text.replace("rib_angle_deg = 109.716252089", "rib_angle_deg = 110.0"));
    assert!(e.starts_with("invalid bearing.rib_angle_deg = 110"), "{e}");
    let e = err(&text.replace(
        "pairing = \"sphere-torus-57\"",
        "pairing = \"sphere-torus-58\"",
    ));
    assert!(e.starts_with("invalid bearing.rib_contact.pairing"), "{e}");
    let e = err(&text.replace(
        "pairing = \"sphere-torus-57\"",
        "pairing = \"sphere-torus-57\"\ncontact_height_mm = 9.0",
    ));
    assert!(
        e.starts_with("invalid bearing.rib_contact.contact_height_mm = 9"),
        "{e}"
    );
    let e = err(&text.replace(
        "pairing = \"sphere-torus-57\"",
        "pairing = \"sphere-torus-57\"\nheight_mm = 1.0",
    ));
    assert!(e.contains("height_mm"), "{e}");
    let e = err(&text.replace(
        "pairing = \"sphere-torus-57\"",
        "face = { shape = \"sphere\", radius_mm = 57.0 }\nrib = { shape = \"cone\" }",
    ));
    assert!(e.contains("bearing.rib_contact.contact_height_mm"), "{e}");
    let e = err(&text.replace(
        "\n[bearing.rib_contact]\npairing = \"sphere-torus-57\"\n",
        "\n",
    ));
    assert!(e.contains("bearing.rib_contact"), "{e}");
    let e = err(&example("bearing_rib_study_60mm.toml").replace(
        "slices = 31\n",
        "slices = 31\n\n[bearing.rib_contact]\npairing = \"sphere-torus-57\"\n",
    ));
    assert!(e.starts_with("invalid bearing.rib_contact"), "{e}");
    let thrust = example("bearing_81107_thrust.toml").replacen(
        "[bearing]\n",
        "[bearing]\nroller_model = \"rib_contact\"\n",
        1,
    );
    let e = err(&thrust);
    assert!(
        e.starts_with("invalid bearing.roller_model = rib_contact"),
        "{e}"
    );
    let e = err(&text.replace("roller_model = \"rib_contact\"", "roller_model = \"ribs\""));
    assert!(e.contains("roller_model"), "{e}");
}

/// The NJ example: the cone loads and the inner ring ribs' radial components (`sin λ`)
/// carry the radial force, the inner ring ribs' axial components (`cos λ`) the axial one, each roller's inner and outer rib
/// loads are equal (the raceways take no axial force); NU and N refuse the axial load,
/// NJ a negative one, naming `load.force_n[2]`.
#[test]
fn the_nj_example_carries_its_axial_load_on_the_ribs() {
    let text = example("bearing_nj_crb_rib_contact.toml");
    let report = run(&text).unwrap();
    let r = report.rollers().unwrap();
    let sin_lambda = 3.5_f64 / 60.0;
    let cos_lambda = (1.0 - sin_lambda * sin_lambda).sqrt();
    let (mut fx, mut fz) = (0.0, 0.0);
    for row in &r.roller_loads {
        // the cone and the inner ring's rib (its normal leans by λ) push the inner ring
        let radial = row.inner_load_n + row.rib_load_n * sin_lambda;
        fx += radial * row.azimuth_deg.to_radians().cos();
        fz += row.rib_load_n * cos_lambda;
        let outer = row.outer_rib_load_n.unwrap();
        assert!((outer - row.rib_load_n).abs() <= 1e-9 * 1500.0);
    }
    assert!((fx - 10_000.0).abs() <= 1e-9 * 10_000.0, "{fx}");
    assert!((fz - 1_500.0).abs() <= 1e-9 * 10_000.0, "{fz}");
    assert_eq!(r.rib_normal_deg, None);
    let err = |t: &str| run(t).unwrap_err().to_string();
    for arr in ["nu", "n"] {
        let e = err(&text.replace("arrangement = \"nj\"", &format!("arrangement = \"{arr}\"")));
        assert!(
            e.starts_with("invalid load.force_n[2] = 1500: expected 0: an N"),
            "{e}"
        );
    }
    let e = err(&text.replace("1500.0]", "-1500.0]"));
    assert!(e.starts_with("invalid load.force_n[2] = -1500"), "{e}");
    let e = err(&text.replace("end_play_mm = 0.02\n", ""));
    assert!(e.contains("bearing.rib_contact.end_play_mm"), "{e}");
    let e = err(&text.replace("contact_height_mm = 3.5", "contact_height_mm = 6.0"));
    assert!(
        e.starts_with("invalid bearing.rib_contact.contact_height_mm = 6"),
        "{e}"
    );
    // tapered keys on a cylindrical bearing and back
    let e = err(&text.replace(
        "arrangement = \"nj\"",
        "arrangement = \"nj\"\npairing = \"sphere-torus-57\"",
    ));
    assert!(e.starts_with("invalid bearing.rib_contact.pairing"), "{e}");
    let e = err(&rib_study_with_rib_contact().replace(
        "pairing = \"sphere-torus-57\"",
        "pairing = \"sphere-torus-57\"\nend_play_mm = 0.01",
    ));
    assert!(
        e.starts_with("invalid bearing.rib_contact.end_play_mm"),
        "{e}"
    );
}
