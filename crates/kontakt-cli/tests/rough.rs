//! `kontakt rough`: a measured (here: written) height map of a sinusoidal surface against
//! Westergaard's closed form, the self-affine example (force, Persson's curve, trends),
//! `kontakt solve` of the same case, the output files, and one-line errors.

#![allow(clippy::unwrap_used)] // test helpers: a panic is a test failure with its message

mod support;

use std::path::PathBuf;
use support::{kontakt, num, run_json};

fn example() -> PathBuf {
    support::example("rough_self_affine.toml")
}

/// A fresh folder per test.
fn tempdir(name: &str) -> PathBuf {
    support::tempdir("rough", name)
}

/// A wavy surface z = D cos(2 pi x/lambda) as a CSV height map (128 cells per wavelength,
/// 8 rows: the periodic 2-D solver then solves the plane problem) against Westergaard's
/// solution (Johnson 1985 §13.2): p = p* sin²(pi a/lambda) with p* = pi E* D/lambda, so
/// the contact fraction 2a/lambda = (2/pi) arcsin(sqrt(p/p*)), within two cells (1/64),
/// and the crest pressure 2 sqrt(p p*) within 0.5 %; the map's rms height and slope; the same
/// surface read from an SDF
/// and an .xyz file gives the same rows.
#[test]
fn wavy_surface_against_westergaard() {
    let dir = tempdir("wavy");
    let (n, lambda, d) = (128usize, 1.0f64, 1e-3f64);
    let row: Vec<String> = (0..n)
        .map(|i| {
            // The crest at the map's left and right edges: one patch across the periodic
            // border.
            let x = (i as f64 + 0.5) * lambda / n as f64;
            format!("{:e}", d * (2.0 * std::f64::consts::PI * x / lambda).cos())
        })
        .collect();
    let csv = vec![row.join(","); 8].join("\n");
    std::fs::write(dir.join("wavy.csv"), csv).unwrap();
    let e_star = 210_000.0 / (2.0 * (1.0 - 0.09));
    let p_star = std::f64::consts::PI * e_star * d / lambda;
    let fractions = [0.1, 0.3, 0.6];
    let loads: Vec<String> = fractions
        .iter()
        .map(|f| format!("{:?}", f * p_star))
        .collect();
    let case = format!(
        "method = \"rough\"\n[surface]\nkind = \"map\"\nfile = \"wavy.csv\"\nspacing_mm = [{:?}, {:?}]\n\
         [body1]\ne_mpa = 210000.0\nnu = 0.3\n[body2]\ne_mpa = 210000.0\nnu = 0.3\n\
         [load]\nmean_pressure_mpa = [{}]\n",
        lambda / n as f64,
        lambda / n as f64,
        loads.join(", ")
    );
    std::fs::write(dir.join("wavy.toml"), case).unwrap();
    let v = run_json(&["rough", dir.join("wavy.toml").to_str().unwrap()]);
    assert_eq!(v["surface"], "map");
    // The map's roughness: rms height D/sqrt 2 (whole periods, 1e-12); rms slope by central
    // differences, the slope amplitude 2 pi D/lambda times sin(k dx)/(k dx), over sqrt 2 (1e-9).
    let k = 2.0 * std::f64::consts::PI / lambda;
    let kdx = k * lambda / n as f64;
    assert!((num(&v["rms_height_mm"]) / (d / 2f64.sqrt()) - 1.0).abs() < 1e-12);
    let slope = k * d * kdx.sin() / kdx / 2f64.sqrt();
    assert!(
        (num(&v["rms_slope"]) / slope - 1.0).abs() < 1e-9,
        "{}",
        v["rms_slope"]
    );
    assert!((num(&v["e_star_mpa"]) / e_star - 1.0).abs() < 1e-12);
    for (row, f) in v["rows"].as_array().unwrap().iter().zip(fractions) {
        let west = 2.0 / std::f64::consts::PI * f.sqrt().asin();
        let ours = num(&row["area_fraction"]);
        assert!(
            (ours - west).abs() < 2.0 / n as f64,
            "p/p* = {f}: {ours} vs {west}"
        );
        assert_eq!(row["patches"], 1);
        // The one patch is the whole contact: a band of width 2a over the map's height.
        let band = ours * lambda * 8.0 * lambda / n as f64;
        assert!((num(&row["largest_patch_area_mm2"]) / band - 1.0).abs() < 1e-12);
        // The crest pressure p(0) = 2 p/sin(pi a/lambda) = 2 sqrt(p p*), within 0.5 %.
        let crest = 2.0 * (f * p_star * p_star).sqrt();
        let pmax = num(&row["max_pressure_mpa"]);
        assert!(
            (pmax / crest - 1.0).abs() < 5e-3,
            "p/p* = {f}: p_max {pmax} vs {crest}"
        );
    }

    // The same surface as an ISO 25178-71 ASCII SDF (metres, heights in nm) and as an .xyz
    // point list (mm, shuffled rows): the same rows (areas exact, pressures 1e-9).
    let z: Vec<f64> = (0..n)
        .map(|i| {
            let x = (i as f64 + 0.5) * lambda / n as f64;
            d * (2.0 * std::f64::consts::PI * x / lambda).cos()
        })
        .collect();
    let dx = lambda / n as f64;
    let mut sdf = format!(
        "aBCR-1.0\nManufacID = kontakt test\nNumPoints = {n}\nNumProfiles = 8\nXscale = {:e}\nYscale = {:e}\nZscale = 1.0E-9\nZresolution = -1\nCompression = 0\nDataType = 7\nCheckType = 0\n*\n",
        dx * 1e-3,
        dx * 1e-3
    );
    let mut xyz = String::from("# x y z [mm]\n");
    for j in (0..8).rev() {
        for (i, zi) in z.iter().enumerate() {
            xyz.push_str(&format!(
                "{:e} {:e} {:e}\n",
                i as f64 * dx,
                j as f64 * dx,
                zi
            ));
        }
    }
    for _ in 0..8 {
        let row: Vec<String> = z.iter().map(|v| format!("{:e}", v * 1e6)).collect();
        sdf.push_str(&row.join(" "));
        sdf.push('\n');
    }
    sdf.push_str("*\n");
    std::fs::write(dir.join("wavy.sdf"), sdf).unwrap();
    std::fs::write(dir.join("wavy.xyz"), xyz).unwrap();
    let csv_case = std::fs::read_to_string(dir.join("wavy.toml")).unwrap();
    let spacing_line = format!("spacing_mm = [{dx:?}, {dx:?}]\n");
    assert!(csv_case.contains(&spacing_line));
    for file in ["wavy.sdf", "wavy.xyz"] {
        let text = csv_case
            .replace("wavy.csv", file)
            .replace(&spacing_line, "");
        std::fs::write(dir.join("other.toml"), text).unwrap();
        let w = run_json(&["rough", dir.join("other.toml").to_str().unwrap()]);
        for (a, b) in w["rows"]
            .as_array()
            .unwrap()
            .iter()
            .zip(v["rows"].as_array().unwrap())
        {
            assert_eq!(a["area_fraction"], b["area_fraction"], "{file}");
            let (pa, pb) = (num(&a["max_pressure_mpa"]), num(&b["max_pressure_mpa"]));
            assert!((pa / pb - 1.0).abs() < 1e-9, "{file}: {pa} vs {pb}");
        }
    }
}

/// The example: the force is the nominal pressure times the cell (1e-12), the area and the
/// number of patches grow and the mean gap falls with the load, kappa lies above Persson's
/// sqrt(8/pi) and within [1.9, 2.8] (a 256² cell of only 32 short wavelengths: the test of
/// kontakt::rough holds the tighter band on 512²), Persson's column is erf(sqrt 2 x)
/// (its series to x⁷, 1e-9); `kontakt solve` prints the same record; --csv, --plot and --map
/// write their files.
#[test]
fn example_rows_and_files() {
    let dir = tempdir("example");
    let (csv, png, map) = (dir.join("r.csv"), dir.join("a.png"), dir.join("m.png"));
    let v = run_json(&[
        "rough",
        example().to_str().unwrap(),
        "--csv",
        csv.to_str().unwrap(),
        "--plot",
        png.to_str().unwrap(),
        "--map",
        map.to_str().unwrap(),
    ]);
    assert_eq!(v, run_json(&["solve", example().to_str().unwrap()]));
    let rows = v["rows"].as_array().unwrap();
    assert_eq!(rows.len(), 4);
    let cell = 0.5 * 0.5;
    let persson = (8.0 / std::f64::consts::PI).sqrt();
    for w in rows.windows(2) {
        assert!(num(&w[1]["area_fraction"]) > num(&w[0]["area_fraction"]));
        assert!(num(&w[1]["mean_gap_mm"]) < num(&w[0]["mean_gap_mm"]));
    }
    for r in rows {
        let p = num(&r["mean_pressure_mpa"]);
        assert!((num(&r["force_n"]) / (p * cell) - 1.0).abs() < 1e-12);
        let k = num(&r["kappa"]);
        assert!(k > persson && (1.9..=2.8).contains(&k), "kappa {k}");
        let x = std::f64::consts::SQRT_2 * num(&r["reduced_pressure"]);
        let erf = 2.0 / std::f64::consts::PI.sqrt()
            * (x - x.powi(3) / 3.0 + x.powi(5) / 10.0 - x.powi(7) / 42.0);
        assert!((num(&r["persson_area_fraction"]) - erf).abs() < 1e-9);
    }
    assert_eq!(std::fs::read_to_string(&csv).unwrap().lines().count(), 5);
    for f in [&png, &map] {
        assert!(
            std::fs::metadata(f).unwrap().len() > 10_000,
            "{}",
            f.display()
        );
    }
}

/// Bad input: one line naming the key, exit status 2.
#[test]
fn bad_cases_name_the_key() {
    let dir = tempdir("bad");
    let base = std::fs::read_to_string(example()).unwrap();
    for (from, to, expect) in [
        ("hurst = 0.8", "hurst = 1.2", "invalid surface.hurst = 1.2"),
        (
            "short_cutoff_mm = 0.015625",
            "short_cutoff_mm = 0.001",
            "invalid surface.short_cutoff_mm",
        ),
        (
            "rms_slope = 0.1",
            "rms_slope = -0.1",
            "invalid surface.rms_slope",
        ),
        ("rms_slope = 0.1", "", "invalid surface = neither"),
        (
            "[100.0, 200.0, 400.0, 800.0]",
            "[100.0, 50.0]",
            "invalid load.mean_pressure_mpa[1] = 50",
        ),
        (
            "[100.0, 200.0, 400.0, 800.0]",
            "[-1.0]",
            "load.mean_pressure_mpa[0]",
        ),
        (
            "points = [256, 256]",
            "points = [255, 256]",
            "invalid surface.points[0] = 255",
        ),
    ] {
        assert!(base.contains(from), "{from}");
        let p = dir.join("bad.toml");
        std::fs::write(&p, base.replace(from, to)).unwrap();
        let out = kontakt()
            .args(["rough", p.to_str().unwrap()])
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
