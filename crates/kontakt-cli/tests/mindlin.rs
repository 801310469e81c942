//! `kontakt mindlin`: the example against the Cattaneo-Mindlin closed forms (Johnson 1985
//! §7.1-7.3), the computed loop against the closed-form dissipated energy and its
//! convergence, `kontakt solve` of the same case, CSV and plot files, and one-line errors.

#![allow(clippy::unwrap_used)] // test helpers: a panic is a test failure with its message

mod support;

use serde_json::Value;
use std::path::PathBuf;
use support::{bad, run_json};

fn example() -> PathBuf {
    support::example("mindlin_fretting.toml")
}

/// A fresh folder per test.
fn tempdir(name: &str) -> PathBuf {
    support::tempdir("mindlin", name)
}

fn f(v: &Value, key: &str) -> f64 {
    v[key]
        .as_f64()
        .unwrap_or_else(|| panic!("{key}: {}", v[key]))
}

/// The example (a steel ball on a steel flat, circular contact) against the closed forms
/// for a circle, with G* from 1/G* = (2 - nu1)/G1 + (2 - nu2)/G2: stick radius
/// c/a = (1 - x)^(1/3), shift 3 mu P/(16 a G*) [1 - (1 - x)^(2/3)], sliding shift at x = 1,
/// energy per cycle 9 mu² P²/(10 a G*) [1 - (1 - x)^(5/3) - (5x/6)(1 + (1 - x)^(2/3))]
/// (Johnson 1985 §7.1-7.3), all to 1e-12 relative; the loop's area (trapezoids
/// over 41 points per branch) within 0.2 % of that energy and converging as h² (161 points:
/// at least 8 times closer); the last cycle ends where the first loading ended (Masing's
/// rule closes the loop, 1e-12).
#[test]
fn example_against_the_closed_forms() {
    let v = run_json(&["mindlin", example().to_str().unwrap()]);
    assert_eq!(v["method"], "mindlin");
    let (p, mu, q) = (f(&v, "force_n"), f(&v, "mu"), f(&v, "amplitude_n"));
    let a = v["semi_axes_mm"][0].as_f64().unwrap();
    assert_eq!(
        v["semi_axes_mm"][1].as_f64().unwrap(),
        a,
        "circular contact"
    );
    let nu = 0.3;
    let g = 210_000.0 / (2.0 * (1.0 + nu));
    let g_star = 1.0 / (2.0 * (2.0 - nu) / g);
    let x = q / (mu * p);
    let close = |ours: f64, theirs: f64, what: &str| {
        assert!(
            (ours / theirs - 1.0).abs() < 1e-12,
            "{what}: {ours} vs {theirs}"
        );
    };
    close(f(&v, "load_fraction"), x, "Q*/(mu P)");
    close(f(&v, "stick_ratio"), (1.0 - x).cbrt(), "c/a");
    let shift = |x: f64| 3.0 * mu * p / (16.0 * a * g_star) * (1.0 - (1.0 - x).powf(2.0 / 3.0));
    close(
        f(&v, "displacement_at_amplitude_mm"),
        shift(x),
        "shift at Q*",
    );
    close(
        f(&v, "slip_displacement_mm"),
        shift(1.0),
        "shift at sliding",
    );
    close(
        f(&v, "tangential_stiffness_n_per_mm"),
        8.0 * a * g_star,
        "stiffness",
    );
    let w = 9.0 * mu * mu * p * p / (10.0 * a * g_star)
        * (1.0 - (1.0 - x).powf(5.0 / 3.0) - 5.0 * x / 6.0 * (1.0 + (1.0 - x).powf(2.0 / 3.0)));
    let w_ours = f(&v, "dissipated_energy_per_cycle_nmm");
    assert!((w_ours / w - 1.0).abs() < 1e-10, "W {w_ours} vs {w}");
    let err41 = (f(&v, "loop_energy_nmm") / w - 1.0).abs();
    assert!(err41 < 2e-3, "loop area error {err41}");
    let qs = v["loop_force_n"].as_array().unwrap();
    let ds = v["loop_displacement_mm"].as_array().unwrap();
    assert_eq!(qs.len(), 41 + 2 * 40);
    let (q_end, d_end) = (qs[120].as_f64().unwrap(), ds[120].as_f64().unwrap());
    assert_eq!(q_end, q);
    assert!((d_end / ds[40].as_f64().unwrap() - 1.0).abs() < 1e-12);

    let dir = tempdir("fine");
    let fine = dir.join("fine.toml");
    let text = std::fs::read_to_string(example())
        .unwrap()
        .replace("points = 41", "points = 161");
    std::fs::write(&fine, text).unwrap();
    let v = run_json(&["mindlin", fine.to_str().unwrap()]);
    let err161 = (f(&v, "loop_energy_nmm") / w - 1.0).abs();
    assert!(
        err161 < err41 / 8.0,
        "no h² convergence: {err41} -> {err161}"
    );
}

/// `kontakt solve` gives the same record; `--csv` and `--plot` write their files.
#[test]
fn solve_csv_and_plot() {
    let dir = tempdir("files");
    let (csv, png) = (dir.join("loop.csv"), dir.join("loop.png"));
    let a = run_json(&[
        "mindlin",
        example().to_str().unwrap(),
        "--csv",
        csv.to_str().unwrap(),
        "--plot",
        png.to_str().unwrap(),
    ]);
    let b = run_json(&["solve", example().to_str().unwrap()]);
    assert_eq!(a, b);
    let text = std::fs::read_to_string(&csv).unwrap();
    assert_eq!(text.lines().next(), Some("force_n,displacement_mm"));
    assert_eq!(text.lines().count(), 1 + 121);
    assert!(std::fs::metadata(&png).unwrap().len() > 10_000);
}

/// Bad input: one line, exit status 2, naming the key.
#[test]
fn bad_cases_name_the_key() {
    let dir = tempdir("bad");
    let base = std::fs::read_to_string(example()).unwrap();
    for (from, to, expect) in [
        (
            "amplitude_n = 20.0",
            "amplitude_n = 31.0",
            "invalid tangential.amplitude_n = 31: expected 3e-7 N <= Q* <= mu P = 30 N",
        ),
        (
            "amplitude_n = 20.0",
            "amplitude_n = nan",
            "invalid tangential.amplitude_n = NaN",
        ),
        ("cycles = 1", "cycles = 0", "invalid tangential.cycles = 0"),
        ("points = 41", "points = 1", "invalid tangential.points = 1"),
        ("mu = 0.3", "mu = -0.3", "friction.mu"),
        (
            "kind = \"hertz\"\nradii1_mm = [6.35, 6.35]\nradii2_mm = [inf, inf]",
            "kind = \"line\"\nradii_mm = [6.35, inf]\nlength_mm = 10.0",
            "invalid geometry.kind = line",
        ),
    ] {
        assert!(base.contains(from), "{from}");
        let p = dir.join("bad.toml");
        std::fs::write(&p, base.replace(from, to)).unwrap();
        let l = bad(&["mindlin", p.to_str().unwrap()]);
        assert!(l.contains(expect), "{to}: {l}");
    }
    let l = bad(&[
        "mindlin",
        PathBuf::from(env!("CARGO_MANIFEST_DIR"))
            .join("../../examples/traction_twin_disc.toml")
            .to_str()
            .unwrap(),
    ]);
    assert!(l.contains("method = \"traction\" case"), "{l}");
}
