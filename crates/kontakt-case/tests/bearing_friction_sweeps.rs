//! Friction sweeps against load and temperature (`operating.sweep_axial_n`,
//! `sweep_radial_n`, `sweep_temperature_c`; issue 29 §2) and the friction section's bad
//! input (issue 29, "Bad input"): each sweep row is the single-point case at that load or
//! temperature; errors name the key with its range.

#![allow(clippy::unwrap_used)] // tests: a panic is a failure with its message

#[path = "support/bearing_run.rs"]
mod bearing_run;

use bearing_run::{example, run};
use kontakt_case::bearing_friction::FrictionReport;
use kontakt_case::{BearingCase, BearingModel};

/// The friction section of a case text.
fn friction(text: &str) -> FrictionReport {
    run(text).unwrap().friction.unwrap()
}

fn rel(a: f64, b: f64) -> f64 {
    (a / b - 1.0).abs()
}

/// The 32008 X case with `sweep` in place of its speed sweep.
fn x32008(sweep: &str) -> String {
    let base = example("bearing_32008x_friction.toml");
    let text = base.replace(
        "sweep_inner_rpm = [0.0, 200.0, 400.0, 600.0, 1000.0, 1400.0, 1800.0, 2200.0]",
        sweep,
    );
    assert_ne!(text, base);
    text
}

/// The 32216 example's radial sweep (Wingertszahn et al. 2023 conditions): every row is a
/// cold solve of the case at that radial force (the warm-started Newton agrees to 1e-9);
/// the rollers that carry fall from 16 to 11 at 16 kN (Wingertszahn et al.'s Fig. 8: 11)
/// and the torque falls with them, while SKF 2004 rises with the load.
#[test]
fn the_32216_radial_sweep_resolves_each_load() {
    let base = example("bearing_32216_friction.toml");
    let f = friction(&base);
    let rows = &f.radial_load_sweep;
    assert_eq!(rows.len(), 9);
    assert!(f.speed_sweep.is_empty() && f.axial_load_sweep.is_empty());
    for r in rows {
        let text = base.replace(
            "force_n = [1000.0, 0.0, 6500.0]",
            &format!("force_n = [{:.1}, 0.0, 6500.0]", r.radial_load_n),
        );
        let single = friction(&text);
        assert!(rel(single.total_nmm, r.total_nmm) < 1e-9, "{r:?}");
        assert_eq!(single.loaded_rollers(), r.loaded_rollers);
        assert!(
            rel(
                single.catalogue.skf_total_nmm.unwrap(),
                r.skf_total_nmm.unwrap()
            ) < 1e-9
        );
        assert!(rel(r.cone_nmm + r.cup_nmm + r.rib_nmm + r.drag_nmm, r.total_nmm) < 1e-12);
        // the axial force is the one carried (to the Newton residual)
        assert!((r.axial_load_n - 6500.0).abs() < 1e-6);
        assert_eq!((r.inner_rpm, r.temperature_c), (2000.0, 50.0));
    }
    for w in rows.windows(2) {
        assert!(w[1].total_nmm < w[0].total_nmm, "{w:?}");
        assert!(w[1].skf_total_nmm > w[0].skf_total_nmm);
        assert!(w[1].loaded_rollers <= w[0].loaded_rollers);
    }
    assert_eq!(rows[0].loaded_rollers, 16);
    assert_eq!(rows[8].loaded_rollers, 11);
    // μ = M/(P d/2) with P = |(Fr, 0, Fa)| and d = 80 mm
    let p = 16000f64.hypot(6500.0);
    assert!(rel(rows[8].coefficient.unwrap(), rows[8].total_nmm / (p * 40.0)) < 1e-12);
    // the JSON carries the rows
    let json = serde_json::to_value(run(&base).unwrap()).unwrap();
    assert_eq!(
        json["friction"]["radial_load_sweep"][8]["loaded_rollers"],
        11
    );
}

/// An axial sweep of the 32008 X: each row is the single-point case (1e-9), the torque
/// rises with the axial load, every roller carries under pure axial load.
#[test]
fn an_axial_sweep_matches_the_single_points() {
    let text = x32008("sweep_axial_n = [2000.0, 6000.0, 12850.0, 20000.0]");
    let f = friction(&text);
    let rows = &f.axial_load_sweep;
    assert_eq!(rows.len(), 4);
    for r in rows {
        let single = friction(&text.replace(
            "force_n = [0.0, 0.0, 12850.0]",
            &format!("force_n = [0.0, 0.0, {:.1}]", r.axial_load_n),
        ));
        assert!(rel(single.total_nmm, r.total_nmm) < 1e-9, "{r:?}");
        assert_eq!(r.loaded_rollers, 23);
        assert!(r.aihara_nmm.is_some());
    }
    for w in rows.windows(2) {
        assert!(w[1].total_nmm > w[0].total_nmm);
    }
    // the row at the case's own load is the main point
    assert!(rel(rows[2].total_nmm, f.total_nmm) < 1e-9);
}

/// A temperature sweep on the 32008 X at 1000 r/min: each row is the case at that oil
/// temperature (1e-12; the load distribution does not depend on the oil), the viscosity
/// and the film fall with the temperature (a Stribeck-like curve at fixed speed), a
/// temperature outside the viscosity data (40-100 °C) warns once, naming the sweep key.
#[test]
fn a_temperature_sweep_follows_the_viscosity() {
    let text = x32008("sweep_temperature_c = [30.0, 40.0, 55.0, 70.0, 90.0]");
    let f = friction(&text);
    let rows = &f.temperature_sweep;
    assert_eq!(rows.len(), 5);
    for r in rows {
        let single = friction(&text.replace(
            "temperature_c = 55.0",
            &format!("temperature_c = {:.1}", r.temperature_c),
        ));
        assert!(rel(single.total_nmm, r.total_nmm) < 1e-12, "{r:?}");
        assert_eq!(single.viscosity_mm2_s, r.viscosity_mm2_s);
    }
    // ν(40 °C) is the oil's own ν40 (Walther line through the data)
    assert!(rel(rows[1].viscosity_mm2_s, 90.02) < 1e-6, "{rows:?}");
    for w in rows.windows(2) {
        assert!(w[1].viscosity_mm2_s < w[0].viscosity_mm2_s);
        assert!(w[1].min_lambda < w[0].min_lambda);
    }
    let outside: Vec<_> = f
        .warnings
        .iter()
        .filter(|w| w.contains("outside the oil's viscosity data"))
        .collect();
    assert_eq!(outside.len(), 1, "{:?}", f.warnings);
    assert!(outside[0].starts_with("operating.sweep_temperature_c = 30 °C: "));
    for r in rows {
        println!(
            "{} °C: ν {:.2} mm²/s, M {:.1} N·mm (cone {:.1}, cup {:.1}), Λ {:?}, SKF {:?}",
            r.temperature_c,
            r.viscosity_mm2_s,
            r.total_nmm,
            r.cone_nmm,
            r.cup_nmm,
            r.min_lambda,
            r.skf_total_nmm
        );
    }
}

/// A load sweep through [`BearingModel`] (the Python class's path) gives the same rows as
/// the case run, and the model's next solve starts from the main point, not the last row;
/// a solve whose load holds the swept displacement skips the sweep with a warning.
#[test]
fn a_load_sweep_through_the_bearing_model() {
    let case = BearingCase::from_toml_str(&example("bearing_32216_friction.toml")).unwrap();
    let mut model = BearingModel::new(&case).unwrap();
    let r = model.solve(&case.load).unwrap();
    let run_rows = friction(&example("bearing_32216_friction.toml")).radial_load_sweep;
    let rows = &r.friction.as_ref().unwrap().radial_load_sweep;
    for (a, b) in rows.iter().zip(&run_rows) {
        assert!(rel(a.total_nmm, b.total_nmm) < 1e-9);
    }
    assert_eq!(
        model.warm_start().unwrap()[0],
        r.displacement_mm[0],
        "the warm start is the main point's"
    );
    // a solve that holds the radial displacement (the element's way) skips the sweep, saying so
    let mut held = case.load;
    held.force_n = [0.0, 0.0, 6500.0];
    held.prescribed.dx_mm = Some(r.displacement_mm[0]);
    let h = model.solve(&held).unwrap();
    let f = h.friction.unwrap();
    assert!(f.radial_load_sweep.is_empty());
    assert!(
        f.warnings
            .iter()
            .any(|w| w.starts_with("operating.sweep_radial_n not run")),
        "{:?}",
        f.warnings
    );
}

/// Bad input of the sweeps and the friction section: one line naming the key, the value
/// and the range.
#[test]
fn bad_sweep_input_names_the_key() {
    for (sweep, key, range) in [
        (
            "sweep_axial_n = []",
            "operating.sweep_axial_n",
            "1 to 10000",
        ),
        (
            "sweep_radial_n = [-5.0]",
            "operating.sweep_radial_n",
            ">= 0 N",
        ),
        (
            "sweep_radial_n = [nan]",
            "operating.sweep_radial_n",
            ">= 0 N",
        ),
        ("sweep_axial_n = [inf]", "operating.sweep_axial_n", "finite"),
        (
            "sweep_temperature_c = [55.0, 400.0]",
            "operating.sweep_temperature_c",
            "-20..=150",
        ),
        (
            "sweep_inner_rpm = [100.0]\nsweep_axial_n = [100.0]",
            "operating",
            "one sweep at a time",
        ),
    ] {
        let e = run(&x32008(sweep)).unwrap_err().to_string();
        assert!(e.contains(key) && e.contains(range), "{sweep}: {e}");
        assert!(!e.contains('\n'));
        println!("{sweep}: {e}");
    }
    // a TRB cannot carry a radial load its axial load does not hold (Fz <= Fr tan α): the
    // point is left out with a warning naming it, the others are reported
    let f = friction(&x32008("sweep_radial_n = [1000.0, 60000.0, 2000.0]"));
    let rows: Vec<f64> = f
        .radial_load_sweep
        .iter()
        .map(|r| r.radial_load_n)
        .collect();
    assert_eq!(rows, [1000.0, 2000.0]);
    assert!(
        f.warnings.iter().any(|w| w.starts_with(
            "operating.sweep_radial_n = 60000 N: not solved, left out: invalid operating.sweep_radial_n"
        ) && w.contains("F_r tan(alpha)")),
        "{:?}",
        f.warnings
    );
    // an axial sweep on a prescribed axial displacement
    let text = x32008("sweep_axial_n = [1000.0]").replace(
        "force_n = [0.0, 0.0, 12850.0]",
        "force_n = [0.0, 0.0, 0.0]\n\n[load.prescribed]\ndz_mm = 0.01",
    );
    let e = run(&text).unwrap_err().to_string();
    assert!(e.contains("operating.sweep_axial_n"), "{e}");
}

/// Zero speed is the starting torque (boundary friction, no film), finite, with a warning,
/// not a division by zero; at a temperature outside the viscosity data the result warns
/// and stays finite; a film far outside the Dowson-Higginson fit (a thin oil at high
/// speed: Moes M far below 10) is a warning naming the contact and the fit's range, with
/// finite numbers.
#[test]
fn starting_torque_and_extrapolated_films_are_finite_with_warnings() {
    let base = example("bearing_32008x_friction.toml");
    let still: FrictionReport = friction(&base.replace("inner_rpm = 1000.0", "inner_rpm = 0.0"));
    assert!(still.starting && still.total_nmm.is_finite() && still.total_nmm > 0.0);
    assert!(still.warnings.iter().any(|w| w.contains("starting torque")));
    let cold = friction(&base.replace("temperature_c = 55.0", "temperature_c = 10.0"));
    assert!(
        cold.warnings
            .iter()
            .any(|w| w.starts_with("lubricant.temperature_c = 10 °C is outside")),
        "{:?}",
        cold.warnings
    );
    assert!(cold.total_nmm.is_finite());
    let fast = friction(
        &base
            .replace("inner_rpm = 1000.0", "inner_rpm = 90000.0")
            .replace(
                "force_n = [0.0, 0.0, 12850.0]",
                "force_n = [0.0, 0.0, 100.0]",
            ),
    );
    let w = fast
        .warnings
        .iter()
        .find(|w| w.contains("Dowson-Higginson"))
        .unwrap();
    assert!(
        w.contains("farthest: roller") && w.contains("Moes M >= 10") && w.contains("M ≈ 0.0"),
        "{w}"
    );
    assert!(fast.total_nmm.is_finite() && fast.min_lambda.unwrap().is_finite());
    println!("{w}");
}

/// The bearing element refuses an oil bath above the bearing's centre as the case does.
#[test]
fn the_element_refuses_an_oil_bath_above_the_centre() {
    let text = example("bearing_32216_friction.toml");
    let high = text.replace("oil_level_mm = 8.5", "oil_level_mm = 80.0");
    assert_ne!(high, text);
    let Err(e) = kontakt_case::bearing_model::BearingElement::from_toml(&high) else {
        panic!("an oil level of 80 mm was accepted")
    };
    let e = e.to_string();
    assert!(
        e.contains("operating.oil_level_mm") && e.contains("0..=62.42 mm"),
        "{e}"
    );
    assert!(kontakt_case::bearing_model::BearingElement::from_toml(&text).is_ok());
}
