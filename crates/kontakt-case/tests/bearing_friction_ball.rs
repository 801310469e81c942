//! The friction section of a ball bearing case (issue 29 §1-2;
//! `kontakt_case::bearing_friction::ball`): the contact-based torque of every ball's inner
//! and outer contact beside the SKF 2004 ball bearing torque.

#![allow(clippy::unwrap_used)] // tests: a panic is a failure with its message

#[path = "support/bearing_run.rs"]
mod bearing_run;

use bearing_run::{example, run};

fn rel(a: f64, b: f64) -> f64 {
    (a / b - 1.0).abs()
}

/// The 6205 example at 3000 r/min: the shares add up to the torque (1e-12), the power
/// balances it (M Δω = P, 1e-12), the ball rows sum to the raceway shares; the torque beside
/// SKF 2004 (62 series, C0 = 7.8 kN), whose ratio is recorded (docs/VALIDATION.md; not
/// tuned); at standstill the sweep's first row is the starting torque, finite.
#[test]
fn the_6205_example_beside_skf() {
    let r = run(&example("bearing_6205_friction.toml")).unwrap();
    let f = r.friction.as_ref().unwrap();
    let shares = f.cone_rolling_nmm + f.cone_sliding_nmm + f.cup_rolling_nmm + f.cup_sliding_nmm;
    assert!(rel(shares + f.drag_nmm, f.total_nmm) < 1e-12);
    let dw = f.inner_rpm * std::f64::consts::PI / 30.0;
    assert!(rel(f.total_nmm * dw * 1e-3, f.power_w) < 1e-12);
    let balls: f64 = f.balls.iter().map(|b| b.torque_nmm).sum();
    assert!(rel(balls + f.drag_nmm, f.total_nmm) < 1e-12);
    let inner: f64 = f.balls.iter().map(|b| b.inner_sliding_w).sum();
    assert!(rel(inner * 1e3 / dw, f.cone_sliding_nmm) < 1e-12);
    assert_eq!(f.inner_ring_nmm, -f.outer_ring_nmm);
    assert_eq!(f.balls.len(), 9);
    // DGBB under radial load (α = 0): outer-race control leaves no spin anywhere, the
    // sliding is Heathcote's differential slip alone.
    for b in &f.balls {
        assert!(b.inner_spin_rad_s.abs() < 1e-9 && b.outer_spin_rad_s.abs() < 1e-9);
    }
    let skf = f.catalogue.skf_total_nmm.unwrap();
    let ratio = f.total_nmm / skf;
    println!(
        "6205, 2 kN radial, 3000 r/min, ν = {:.2} mm²/s: M = {:.3} N·mm (inner race {:.3}, outer race {:.3}), SKF 2004 {:.3} N·mm, ratio {:.4}, μ = {:.5}, Λ_min {:.3}",
        f.viscosity_mm2_s,
        f.total_nmm,
        f.cone_rolling_nmm + f.cone_sliding_nmm,
        f.cup_rolling_nmm + f.cup_sliding_nmm,
        skf,
        ratio,
        f.coefficient.unwrap(),
        f.min_lambda.unwrap()
    );
    assert!((ratio - 0.878).abs() < 0.005, "{ratio}");
    let start = &f.speed_sweep[0];
    assert_eq!(start.inner_rpm, 0.0);
    assert!(start.total_nmm.is_finite() && start.total_nmm > 0.0);
    assert!(start.min_lambda.is_none());
    for row in &f.speed_sweep {
        println!(
            "  {:7.0} r/min: {:8.3} N·mm, SKF {:8.3} N·mm",
            row.inner_rpm,
            row.total_nmm,
            row.skf_total_nmm.unwrap()
        );
    }
}

/// An angular contact ball bearing at speed under combined load: the balls' two contact
/// angles from the Jones model, spin at the inner contact and none at the outer
/// (outer-race control), the SKF 72 BECBP torque beside it.
#[test]
fn angular_contact_at_speed_spins_at_the_inner_race() {
    let text = r#"
name = "7205 B class at speed"
method = "bearing"

[bearing]
type = "angular_contact_ball"
pitch_diameter_mm = 38.5
balls = 12
ball_diameter_mm = 7.938
inner_osculation = 0.52
outer_osculation = 0.53
contact_angle_deg = 40.0

[speed]
inner_rpm = 10000.0

[load]
force_n = [500.0, 0.0, 2000.0]

[load.prescribed]
tilt_x_rad = 0.0
tilt_y_rad = 0.0

[operating]
supply = "circulating"

[lubricant]
iso_vg = 32
density_kg_m3 = 860.0
alpha_per_mpa = 0.02
temperature_c = 50.0
roughness_mm = [0.0001, 0.0001]

[catalogue]
bore_mm = 25.0
outer_mm = 52.0
width_mm = 15.0
skf_series = "72 BECBP"
"#;
    let f = run(text).unwrap().friction.unwrap();
    let loaded: Vec<_> = f.balls.iter().filter(|b| b.inner_load_n > 0.0).collect();
    assert!(!loaded.is_empty());
    for b in &loaded {
        assert!(b.outer_spin_rad_s.abs() < 1e-6 * b.inner_spin_rad_s.abs());
        assert!(b.inner_spin_rad_s.abs() > 100.0);
    }
    let skf = f.catalogue.skf_total_nmm.unwrap();
    println!(
        "7205 B, 500 N radial + 2 kN axial, 10 000 r/min: M = {:.3} N·mm (sliding {:.3}), SKF {:.3} N·mm",
        f.total_nmm,
        f.cone_sliding_nmm + f.cup_sliding_nmm,
        skf
    );
    assert!(f.total_nmm > 0.0 && skf > 0.0);
}

/// Bad input of the ball friction names the key.
#[test]
fn bad_ball_friction_input_names_the_key() {
    let base = example("bearing_6205_friction.toml");
    for (from, to, key) in [
        ("c0_n = 7800.0\n", "", "catalogue.c0_n"),
        ("c0_n = 7800.0", "c0_n = -1.0", "catalogue.c0_n"),
        (
            "skf_series = \"62\"",
            "skf_series = \"72 BECBP\"",
            "catalogue.skf_series",
        ),
        (
            "oil_level_mm = 4.0",
            "oil_level_mm = nan",
            "operating.oil_level_mm",
        ),
        ("inner_rpm = 3000.0", "inner_rpm = 1e9", "speed.inner_rpm"),
        (
            "temperature_c = 60.0",
            "temperature_c = 400.0",
            "lubricant.temperature_c",
        ),
        ("c0_n = 7800.0", "c0_nn = 7800.0", "c0_nn"),
    ] {
        let text = base.replace(from, to);
        assert_ne!(text, base, "{from}");
        let e = run(&text).unwrap_err().to_string();
        assert!(e.contains(key), "{key}: {e}");
        assert!(!e.contains('\n'), "{e}");
        println!("{key}: {e}");
    }
}

/// The friction sweeps reach ball bearings: over the oil temperature (same load
/// distribution) and over the radial load (re-solved); the rows at the example's 60 °C and
/// 2 kN are its single point (1e-12); the torque falls as the oil thins and grows with the
/// load.
#[test]
fn temperature_and_load_sweeps_of_a_ball_bearing() {
    let base = example("bearing_6205_friction.toml");
    let single = run(&base).unwrap().friction.unwrap().total_nmm;
    let sweep = |line: &str| {
        let text = base.replace(
            "sweep_inner_rpm = [0.0, 100.0, 300.0, 1000.0, 3000.0, 6000.0, 10000.0]",
            line,
        );
        assert_ne!(text, base);
        run(&text).unwrap().friction.unwrap()
    };
    let t = sweep("sweep_temperature_c = [40.0, 60.0, 80.0]").temperature_sweep;
    let l = sweep("sweep_radial_n = [500.0, 2000.0, 5000.0]").radial_load_sweep;
    for rows in [&t, &l] {
        assert_eq!(rows.len(), 3);
        assert!(rel(rows[1].total_nmm, single) < 1e-12);
    }
    assert!(t[0].total_nmm > t[1].total_nmm && t[1].total_nmm > t[2].total_nmm);
    assert!(l[0].total_nmm < l[1].total_nmm && l[1].total_nmm < l[2].total_nmm);
    assert_eq!(l[1].loaded_rollers, 3);
    println!(
        "40/60/80 °C: {:.2}/{:.2}/{:.2} N·mm; 0.5/2/5 kN: {:.2}/{:.2}/{:.2} N·mm",
        t[0].total_nmm,
        t[1].total_nmm,
        t[2].total_nmm,
        l[0].total_nmm,
        l[1].total_nmm,
        l[2].total_nmm
    );
}
