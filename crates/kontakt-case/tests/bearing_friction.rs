//! The friction section of a bearing case (issue 29 §1-2): `[operating]`, `[lubricant]`,
//! `[friction]` and `[catalogue]` of a bearing case, the report's `friction` section, and
//! errors that name the key.

#![allow(clippy::unwrap_used)] // tests: a panic is a failure with its message

#[path = "support/bearing_run.rs"]
mod bearing_run;

use bearing_run::{example, run};

/// The ring speed of the friction tests (the case's one `[speed]` table).
const SPEED: &str = "\n[speed]\ninner_rpm = 1500.0\n";

/// The operating point and oil but for the speed.
const RIB_OIL: &str = r#"
[operating]
supply = "circulating"

[lubricant]
iso_vg = 68
density_kg_m3 = 860.0
alpha_per_mpa = 0.02
temperature_c = 70.0
roughness_mm = [0.0002, 0.0002]
"#;

fn rel(a: f64, b: f64) -> f64 {
    (a / b - 1.0).abs()
}

/// The 32008 X example: the shares add up to the torque, the power balances it, the SKF
/// torque is beside it (875.7 N·mm at ν = 44.59 mm²/s, the catalogue model's own value),
/// the per-roller table sums to the raceway shares.
#[test]
fn the_32008x_example_reports_its_friction_beside_skf() {
    let r = run(&example("bearing_32008x_friction.toml")).unwrap();
    let f = r.friction.as_ref().unwrap();
    let shares = f.cone_rolling_nmm
        + f.cone_sliding_nmm
        + f.cup_rolling_nmm
        + f.cup_sliding_nmm
        + f.rib_nmm
        + f.drag_nmm;
    assert!(rel(shares, f.total_nmm) < 1e-12);
    let w = f.inner_rpm * std::f64::consts::PI / 30.0;
    assert!(rel(f.inner_ring_nmm * w * 1e-3, f.power_w) < 1e-12);
    let rollers: f64 = f.rollers.iter().map(|r| r.torque_nmm).sum();
    assert!(rel(rollers, f.total_nmm) < 1e-12);
    assert_eq!(f.rollers.len(), 23);
    // the speed is [speed]'s; the ISO model solved its loads without centrifugal force and
    // says so first
    assert_eq!((f.inner_rpm, f.outer_rpm), (1000.0, 0.0));
    assert_eq!(r.ring_speeds_rpm, Some([1000.0, 0.0]));
    assert!(
        r.warnings[0].contains("without the rollers' centrifugal force")
            && r.warnings[0].contains("roller_model = \"rib_contact\""),
        "{:?}",
        r.warnings
    );
    let skf = f.catalogue.skf_total_nmm.unwrap();
    println!(
        "32008 X at 1000 r/min: {:.1} N·mm (cone {:.1}, cup {:.1}), SKF {skf:.1}",
        f.total_nmm,
        f.cone_rolling_nmm + f.cone_sliding_nmm,
        f.cup_rolling_nmm + f.cup_sliding_nmm
    );
    assert!((skf - 875.74).abs() < 0.05, "{skf}");
    assert!(f.total_nmm > 0.0 && f.rib_nmm == 0.0);
    assert!(
        f.warnings
            .iter()
            .any(|w| w.contains("rib friction not computed"))
    );
    // JSON carries it
    let json = serde_json::to_value(&r).unwrap();
    assert!(json["friction"]["total_nmm"].as_f64().unwrap() > 0.0);
    // without [operating] there is no friction section
    let plain = run(&example("bearing_32008x.toml")).unwrap();
    assert!(plain.friction.is_none());
}

/// The rib-contact TRB: the rib share is there, the starting torque at standstill is
/// finite (no NaN) and has no power.
#[test]
fn rib_contact_bearing_has_a_rib_share_and_a_starting_torque() {
    let base = example("bearing_rib_contact_60mm.toml");
    let r = run(&format!("{base}\n{RIB_OIL}{SPEED}")).unwrap();
    // the rib-contact model's rollers carry their centrifugal force at [speed]
    let fc = r.rollers().unwrap().roller_loads[0].centrifugal_force_n;
    assert!(fc.unwrap() > 0.0, "{fc:?}");
    assert!(r.warnings.iter().all(|w| !w.contains("centrifugal")));
    let f = r.friction.unwrap();
    assert_eq!(f.inner_rpm, 1500.0);
    assert!(f.rib_nmm > 0.0 && f.rib_power_w > 0.0);
    // under combined load Aihara is not computed (pure axial load only)
    assert!(f.catalogue.aihara_total_nmm.is_none());
    let axial = run(&format!("{base}\n{RIB_OIL}{SPEED}").replace(
        "force_n = [6000.0, 0.0, 15000.0]",
        "force_n = [0.0, 0.0, 15000.0]",
    ))
    .unwrap()
    .friction
    .unwrap();
    let aihara = axial.catalogue.aihara_total_nmm.unwrap();
    assert!(aihara > axial.catalogue.aihara_rolling_nmm.unwrap());
    println!(
        "rib-contact TRB, 15 kN axial, 1500 r/min: {:.1} N·mm (rib {:.1}), Aihara {aihara:.1}",
        axial.total_nmm, axial.rib_nmm
    );
    assert!(f.rollers.iter().all(|r| r.rib_w >= 0.0));
    let s = run(&format!(
        "{base}\n{RIB_OIL}{}",
        SPEED.replace("1500.0", "0.0")
    ))
    .unwrap();
    let s = s.friction.unwrap();
    assert!(s.starting && s.total_nmm.is_finite() && s.total_nmm > 0.0);
    assert_eq!(s.power_w, 0.0);
    assert!(s.rib_nmm > 0.0);
}

/// Bad input: one line naming the key.
#[test]
fn bad_friction_input_names_the_key() {
    let base = example("bearing_32008x_friction.toml");
    for (from, to, key) in [
        // the ring speeds are [speed]'s alone: [operating] has none
        (
            "supply = \"circulating\"",
            "supply = \"circulating\"\ninner_rpm = 1000.0",
            "operating.inner_rpm",
        ),
        ("inner_rpm = 1000.0", "inner_rpm = inf", "speed.inner_rpm"),
        (
            "sweep_inner_rpm = [0.0,",
            "sweep_inner_rpm = [2e5,",
            "operating.sweep_inner_rpm",
        ),
        (
            "supply = \"circulating\"",
            "supply = \"oil_bath\"",
            "operating.oil_level_mm",
        ),
        (
            "temperature_c = 55.0",
            "temperature_c = 400.0",
            "lubricant.temperature_c",
        ),
        (
            "skf_series = \"320 X\"",
            "skf_series = \"999\"",
            "catalogue.skf_series",
        ),
        ("y = 1.6\n", "", "catalogue.y"),
        (
            "supply = \"circulating\"",
            "supply = \"circulating\"\ndrag = \"schaeffler_m0\"",
            "operating.drag",
        ),
        ("[lubricant]", "[lubricant_x]", "lubricant"),
    ] {
        let text = base.replace(from, to);
        assert_ne!(text, base, "{from}");
        let e = run(&text).unwrap_err().to_string();
        assert!(e.contains(key), "{key}: {e}");
        println!("{key}: {e}");
    }
    let bath = base.replace(
        "supply = \"circulating\"",
        "supply = \"oil_bath\"\noil_level_mm = 40.0",
    );
    // above the bearing's centre (30.15 mm): refused with the range
    let e = run(&bath).unwrap_err().to_string();
    assert!(
        e.contains("operating.oil_level_mm") && e.contains("0..=30.15 mm"),
        "{e}"
    );
    let e = run(&bath.replace("oil_level_mm = 40.0", "oil_level_mm = -1.0"))
        .unwrap_err()
        .to_string();
    assert!(e.contains("operating.oil_level_mm"), "{e}");
    // Ball bearings have their friction section (tests/bearing_friction_ball.rs).
    let ball = example("bearing_6205.toml");
    let f = run(&format!("{ball}\n{RIB_OIL}{SPEED}"))
        .unwrap()
        .friction
        .unwrap();
    assert!(!f.balls.is_empty() && f.total_nmm > 0.0);
}

/// The 32008 X example's speed sweep over Manjunath et al.'s (2023) speeds (0, 200-2200
/// r/min): each row is the single-point result at that speed (1e-12); the torque breakdown
/// beside SKF 2004 and Aihara (1987, rolling part) recorded in docs/bearing-friction.md §6;
/// the raceway torque grows with speed (the rolling resistance).
#[test]
fn the_32008x_over_speed_beside_the_catalogue_models() {
    let base = example("bearing_32008x_friction.toml");
    let sweep = run(&base).unwrap().friction.unwrap().speed_sweep;
    assert_eq!(sweep.len(), 8);
    let mut last = 0.0;
    println!("n r/min | cone | cup | total | SKF (rolling, sliding) | Aihara rolling | min Λ");
    for row in &sweep {
        let text = base.replace(
            "inner_rpm = 1000.0",
            &format!("inner_rpm = {:.1}", row.inner_rpm),
        );
        let f = run(&text).unwrap().friction.unwrap();
        assert!(rel(f.total_nmm, row.total_nmm) < 1e-12);
        let c = &f.catalogue;
        println!(
            "{} | {:.1} | {:.1} | {:.1} | {:.1} ({:.1}, {:.1}) | {:?} | {:?}",
            row.inner_rpm,
            row.cone_nmm,
            row.cup_nmm,
            row.total_nmm,
            c.skf_total_nmm.unwrap(),
            c.skf_rolling_nmm.unwrap(),
            c.skf_sliding_nmm.unwrap(),
            c.aihara_rolling_nmm,
            f.min_lambda
        );
        if row.inner_rpm > 0.0 {
            assert!(row.total_nmm > last);
            assert_eq!(row.aihara_nmm, c.aihara_rolling_nmm);
        } else {
            assert!(f.starting && row.total_nmm.is_finite());
        }
        last = row.total_nmm;
    }
}

/// A cylindrical roller bearing: its rollers do not slide (§1), so all its raceway torque
/// is rolling resistance; a thrust bearing with `[operating]` is an error naming the table.
#[test]
fn cylindrical_bearing_rolls_without_sliding_and_thrust_is_refused() {
    let r = run(&format!(
        "{}\n{RIB_OIL}{SPEED}",
        example("bearing_nu_crb.toml")
    ))
    .unwrap();
    let f = r.friction.unwrap();
    assert!(f.total_nmm > 0.0);
    assert!(
        f.sliding_power_w.abs() <= 1e-12 * f.power_w,
        "{}",
        f.sliding_power_w
    );
    assert_eq!(f.rib_nmm, 0.0);
    let e = run(&format!(
        "{}\n{RIB_OIL}",
        example("bearing_81107_thrust.toml")
    ))
    .unwrap_err()
    .to_string();
    assert!(e.contains("operating"), "{e}");
}

/// `operating.rib_pressure`: the rib-contact TRB's rib share with the PimP and the
/// half-space pressure fields, beside Hertz's (the library test `rib_share_equals_the_rib_
/// friction_study` checks each against `kontakt friction` to 1e-9); the raceways do not
/// change; a cylindrical bearing's ribs refuse anything but Hertz, naming the key.
#[test]
fn the_rib_pressure_model_is_the_cases_choice() {
    let base = format!(
        "{}\n{RIB_OIL}{SPEED}",
        example("bearing_rib_contact_60mm.toml")
    );
    let with = |model: &str| {
        run(&base.replace(
            "[operating]\n",
            &format!("[operating]\nrib_pressure = \"{model}\"\n"),
        ))
        .unwrap()
        .friction
        .unwrap()
    };
    let hertz = run(&base).unwrap().friction.unwrap();
    assert_eq!(with("hertz"), hertz);
    for model in ["pimp", "halfspace"] {
        let f = with(model);
        println!(
            "{model}: rib {:.4} N·mm, Hertz {:.4}",
            f.rib_nmm, hertz.rib_nmm
        );
        assert!(f.rib_nmm > 0.0 && f.rib_nmm != hertz.rib_nmm, "{model}");
        assert!(rel(f.rib_nmm, hertz.rib_nmm) < 0.05, "{model}");
        let raceways = |f: &kontakt_case::bearing_friction::FrictionReport| {
            f.cone_rolling_nmm + f.cone_sliding_nmm + f.cup_rolling_nmm + f.cup_sliding_nmm
        };
        assert_eq!(raceways(&f), raceways(&hertz), "{model}");
    }
    let crb = format!(
        "{}\n{}{SPEED}",
        example("bearing_nj_crb_rib_contact.toml"),
        RIB_OIL.replace("[operating]\n", "[operating]\nrib_pressure = \"pimp\"\n")
    );
    let err = run(&crb).unwrap_err().to_string();
    assert!(
        err.contains("operating.rib_pressure") && err.contains("pimp"),
        "{err}"
    );
}
