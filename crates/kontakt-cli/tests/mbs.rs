//! `kontakt mbs`: the motion study writes its CSV and plots, agrees with itself (the
//! contact-point migration is geometry: the same for every back-end; the rib load of the
//! tilt and skew phases is the requested one), and bad flags are one line with exit status 2.

#![allow(clippy::unwrap_used)] // test helpers: a panic is a test failure with its message

use assert_cmd::Command;
use serde_json::Value;

fn kontakt() -> Command {
    Command::cargo_bin("kontakt").expect("binary built")
}

#[test]
fn motion_study_writes_samples_and_plots() {
    let dir = std::env::temp_dir().join(format!("kontakt-mbs-test-{}", std::process::id()));
    let out = kontakt()
        .args([
            "mbs",
            "--steps",
            "3",
            "--backends",
            "hertz,pimp",
            "--out",
            dir.to_str().unwrap(),
            "--json",
        ])
        .output()
        .unwrap();
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let samples: Value = serde_json::from_slice(&out.stdout).unwrap();
    let samples = samples.as_array().unwrap();
    assert_eq!(samples.len(), 2 * 3 * 3); // back-ends × phases × steps
    for s in samples.iter().filter(|s| s["phase"] != "load") {
        assert!((s["force_n"].as_f64().unwrap() / 250.0 - 1.0).abs() < 1e-9);
    }
    let at = |backend: &str, i: usize| {
        &samples
            .iter()
            .filter(|s| s["backend"] == backend)
            .nth(i)
            .unwrap()["migration_x_mm"]
    };
    // The same geometry: the loaded poses differ only by the back-ends' approaches
    // (≈ 0.1 µm), so the contact points agree to 1e-6 mm.
    for i in 0..9 {
        let h = at("hertz", i).as_f64().unwrap();
        let p = at("pimp", i).as_f64().unwrap();
        assert!((h - p).abs() < 1e-6, "{h} vs {p}");
    }
    let csv = std::fs::read_to_string(dir.join("mbs.csv")).unwrap();
    assert_eq!(csv.lines().count(), 1 + 18);
    for f in [
        "mbs_load.png",
        "mbs_tilt_migration.png",
        "mbs_skew_pressure.png",
    ] {
        let bytes = std::fs::read(dir.join(f)).unwrap();
        assert_eq!(&bytes[..8], b"\x89PNG\r\n\x1a\n", "{f}");
    }
}

#[test]
fn bad_flags_are_one_line_with_exit_2() {
    for (args, flag) in [
        (vec!["mbs", "--force", "-1"], "--force"),
        (vec!["mbs", "--angle-deg", "5"], "--angle-deg"),
        (vec!["mbs", "--steps", "1"], "--steps"),
        (vec!["mbs", "--pairing", "nope"], "--pairing"),
        (vec!["mbs", "--backends", "fem"], "--backends"),
    ] {
        let out = kontakt()
            .args(&args)
            .args([
                "--out",
                std::env::temp_dir()
                    .join("kontakt-mbs-bad")
                    .to_str()
                    .unwrap(),
            ])
            .output()
            .unwrap();
        assert_eq!(out.status.code(), Some(2), "{args:?}");
        let err = String::from_utf8(out.stderr).unwrap();
        assert_eq!(
            err.lines().filter(|l| !l.trim().is_empty()).count(),
            1,
            "{err}"
        );
        assert!(err.contains(flag), "{err}");
    }
}
