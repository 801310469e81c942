//! `kontakt impact`: the normal impact against Hertz's closed form (Johnson 1982 eqs
//! 36-38), the oblique rebound's regimes (rigid rolling 5u1/7, gross sliding
//! psi2 = psi1 - 4 chi), `kontakt solve` of the same case, and one-line errors.

#![allow(clippy::unwrap_used)] // test helpers: a panic is a test failure with its message

mod support;

use std::path::PathBuf;
use support::{kontakt, num, run_json};

fn example() -> PathBuf {
    support::example("impact_oblique.toml")
}

/// A fresh folder per test.
fn tempdir(name: &str) -> PathBuf {
    support::tempdir("impact", name)
}

/// The example with some lines replaced, written to a file.
fn variant(dir: &std::path::Path, name: &str, edits: &[(&str, &str)]) -> PathBuf {
    let mut text = std::fs::read_to_string(example()).unwrap();
    for (from, to) in edits {
        assert!(text.contains(from), "{from}");
        text = text.replace(from, to);
    }
    let p = dir.join(name);
    std::fs::write(&p, text).unwrap();
    p
}

/// Normal impact without friction: Hertz's closed form with the sphere's mass and radius,
/// delta* = (15 m V²/(16 E* sqrt R))^(2/5), F* = (4/3) E* sqrt(R) delta*^(3/2),
/// T = 2.9432 delta*/V (Johnson 1982 eqs 36-38; 1e-4, the coefficient's digits).
#[test]
fn normal_impact_against_hertz() {
    let dir = tempdir("normal");
    let p = variant(
        &dir,
        "normal.toml",
        &[
            ("angle_deg = 30.0", "angle_deg = 0.0"),
            ("[friction]\nmu = 0.3\nrestitution = 1.0\n", ""),
        ],
    );
    let v = run_json(&["impact", p.to_str().unwrap()]);
    assert!(v["rigid"].is_null() && v["elastic"].is_null());
    let (r, e_star, vel) = (5.0_f64, num(&v["e_star_mpa"]), 1000.0);
    let m = 4.0 / 3.0 * std::f64::consts::PI * r.powi(3) * 7.85e-9;
    assert!((num(&v["mass_t"]) / m - 1.0).abs() < 1e-12);
    let d = (15.0 * m * vel * vel / (16.0 * e_star * r.sqrt())).powf(0.4);
    let n = &v["normal"];
    assert!((num(&n["max_approach_mm"]) / d - 1.0).abs() < 1e-10);
    let f = 4.0 / 3.0 * e_star * r.sqrt() * d.powf(1.5);
    assert!((num(&n["max_force_n"]) / f - 1.0).abs() < 1e-10);
    let t = 2.9432 * d / vel;
    assert!(
        (num(&n["contact_duration_s"]) / t - 1.0).abs() < 1e-4,
        "{} vs {t}",
        n["contact_duration_s"]
    );
}

/// The example (30 deg, no spin, mu = 0.3): the contact point stops (w1 = u1 < 7 mu V), the
/// rigid sphere leaves rolling with u2 = 5 u1/7 and omega2 = -u2/R (1e-9); the elastic
/// analysis has psi1 = kappa w1/(mu V) (1e-12) and a partial-slip rebound; at 80 deg the
/// contact slides throughout in both: rigid w2 = w1 - 7 mu V (e = 1, 1e-9), elastic
/// psi2 = psi1 - 4 chi (1e-6). `kontakt solve` prints the same record.
#[test]
fn oblique_rebound_regimes() {
    let v = run_json(&["impact", example().to_str().unwrap()]);
    assert_eq!(v, run_json(&["solve", example().to_str().unwrap()]));
    let (u1, vn) = (
        num(&v["tangential_velocity_mm_per_s"]),
        num(&v["normal"]["normal_speed_mm_per_s"]),
    );
    assert!((u1 - 500.0).abs() < 1e-9 && (vn - 1000.0 * 30f64.to_radians().cos()).abs() < 1e-9);
    let rg = &v["rigid"];
    assert_eq!(rg["regime"], "sliding_then_rolling");
    let u2 = num(&rg["tangential_velocity_mm_per_s"]);
    assert!((u2 - 5.0 / 7.0 * u1).abs() < 1e-9);
    assert!((num(&rg["angular_velocity_rad_per_s"]) + u2 / 5.0).abs() < 1e-9);
    let el = &v["elastic"];
    let (kappa, chi) = (num(&v["kappa"]), num(&v["chi"]));
    assert!((num(&el["psi1"]) - kappa * u1 / (0.3 * vn)).abs() < 1e-12);
    assert_eq!(el["slid_throughout"], false);
    // chi = (kappa/2)(1 + R²/k²) with k² = 2R²/5 for the solid sphere.
    assert!((chi - 1.75 * kappa).abs() < 1e-12);

    let dir = tempdir("steep");
    let p = variant(
        &dir,
        "steep.toml",
        &[("angle_deg = 30.0", "angle_deg = 80.0")],
    );
    let v = run_json(&["impact", p.to_str().unwrap()]);
    let vn = num(&v["normal"]["normal_speed_mm_per_s"]);
    let w1 = num(&v["peripheral_velocity_mm_per_s"]);
    assert_eq!(v["rigid"]["regime"], "gross_sliding");
    assert!(
        (num(&v["rigid"]["peripheral_velocity_mm_per_s"]) - (w1 - 7.0 * 0.3 * vn)).abs()
            < 1e-9 * w1
    );
    let el = &v["elastic"];
    assert_eq!(el["slid_throughout"], true);
    let (psi1, psi2) = (num(&el["psi1"]), num(&el["psi2"]));
    assert!(
        (psi2 - (psi1 - 4.0 * num(&v["chi"]))).abs() < 1e-6,
        "{psi1} {psi2}"
    );
}

/// Bad input: one line naming the key, exit status 2.
#[test]
fn bad_cases_name_the_key() {
    let dir = tempdir("bad");
    for (from, to, expect) in [
        (
            "speed_mm_per_s = 1000.0",
            "speed_mm_per_s = 0.0",
            "impact.speed_mm_per_s",
        ),
        (
            "speed_mm_per_s = 1000.0",
            "speed_mm_per_s = nan",
            "impact.speed_mm_per_s",
        ),
        (
            "angle_deg = 30.0",
            "angle_deg = 90.0",
            "invalid impact.angle_deg = 90",
        ),
        ("mu = 0.3", "mu = 0.0", "friction.mu"),
        (
            "restitution = 1.0",
            "restitution = 1.5",
            "friction.restitution",
        ),
        ("radius_mm = 5.0", "radius_mm = -5.0", "sphere.radius_mm"),
        (
            "density_t_per_mm3 = 7.85e-9",
            "density_t_per_mm3 = 7.85e-9\nmass_t = 1e-6",
            "invalid sphere = both",
        ),
        (
            "[friction]\nmu = 0.3\nrestitution = 1.0\n",
            "",
            "invalid friction = missing",
        ),
    ] {
        let p = variant(&dir, "bad.toml", &[(from, to)]);
        let out = kontakt()
            .args(["impact", p.to_str().unwrap()])
            .output()
            .unwrap();
        let err = String::from_utf8(out.stderr).unwrap();
        assert_eq!(out.status.code(), Some(2), "{to}: {err}");
        assert_eq!(
            err.lines().filter(|l| !l.trim().is_empty()).count(),
            1,
            "{err}"
        );
        assert!(err.contains(expect), "{to}: {err}");
    }
}
