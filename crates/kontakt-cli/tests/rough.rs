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

/// `kontakt rough CASE` must fail on bad input: exit status 2 and one line, returned.
fn refused(case: &std::path::Path) -> String {
    support::bad(&["rough", case.to_str().unwrap()])
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
        // Found by the fuzz harness: the memory estimate overflowed (a panic) before the
        // grid was checked; the grid is checked first.
        (
            "points = [256, 256]",
            "points = [9223372036854775806, 256]",
            "invalid surface.points[0] = 9223372036854775806",
        ),
    ] {
        assert!(base.contains(from), "{from}");
        let p = dir.join("bad.toml");
        std::fs::write(&p, base.replace(from, to)).unwrap();
        let err = refused(&p);
        assert!(err.contains(expect), "{to}: {err}");
    }
}

/// A wavy CSV map (`n` cells per wavelength, 8 rows) in `unit`s per mm of height `d_mm`,
/// with `header` lines before the numbers, and its case text.
fn wavy_case(dir: &std::path::Path, file: &str, header: &str, per_mm: f64, keys: &str) -> PathBuf {
    let (n, lambda, d) = (64usize, 1.0f64, 1e-3f64);
    let row: Vec<String> = (0..n)
        .map(|i| {
            let x = (i as f64 + 0.5) * lambda / n as f64;
            format!(
                "{:e}",
                per_mm * d * (2.0 * std::f64::consts::PI * x / lambda).cos()
            )
        })
        .collect();
    std::fs::write(
        dir.join(file),
        format!("{header}{}\n", vec![row.join(","); 8].join("\n")),
    )
    .unwrap();
    let dx = lambda / n as f64;
    let case = format!(
        "method = \"rough\"\n[surface]\nkind = \"map\"\nfile = \"{file}\"\nspacing_mm = [{dx:?}, {dx:?}]\n{keys}\n\
         [body1]\ne_mpa = 210000.0\nnu = 0.3\n[body2]\ne_mpa = 210000.0\nnu = 0.3\n\
         [load]\nmean_pressure_mpa = [50.0, 150.0]\n"
    );
    let p = dir.join(format!("{file}.toml"));
    std::fs::write(&p, case).unwrap();
    p
}

/// Issue 30 item 17: a profilometer's export (header lines, heights in µm) is read with
/// `unit = "um"` (or `scale`), the skipped header lines are counted in a warning, and the
/// rows equal those of the same surface in mm without a header.
#[test]
fn profilometer_export_with_header_and_microns() {
    let dir = tempdir("units");
    let plain = run_json(&[
        "rough",
        wavy_case(&dir, "mm.csv", "", 1.0, "").to_str().unwrap(),
    ]);
    assert_eq!(
        plain["warnings"].as_array().unwrap().len(),
        0,
        "{}",
        plain["warnings"]
    );
    let header = "Profilometer export,,\nx0,x1,x2\n";
    for (file, keys) in [
        ("um.csv", "unit = \"um\""),
        ("um2.csv", "unit = \"µm\""),
        ("scaled.csv", "scale = 1e-3"),
    ] {
        let v = run_json(&[
            "rough",
            wavy_case(&dir, file, header, 1e3, keys).to_str().unwrap(),
        ]);
        let w = v["warnings"].as_array().unwrap();
        assert_eq!(w.len(), 1, "{w:?}");
        assert!(
            w[0].as_str().unwrap().contains("skipped 2 header lines"),
            "{w:?}"
        );
        for (a, b) in v["rows"]
            .as_array()
            .unwrap()
            .iter()
            .zip(plain["rows"].as_array().unwrap())
        {
            let (pa, pb) = (num(&a["max_pressure_mpa"]), num(&b["max_pressure_mpa"]));
            assert!((pa / pb - 1.0).abs() < 1e-9, "{file}: {pa} vs {pb}");
            assert_eq!(a["area_fraction"], b["area_fraction"], "{file}");
        }
    }
    // Without the unit the heights are read as mm: 1000 times rougher, a different result.
    let v = run_json(&[
        "rough",
        wavy_case(&dir, "raw.csv", header, 1e3, "")
            .to_str()
            .unwrap(),
    ]);
    assert!(num(&v["rms_height_mm"]) > 100.0 * num(&plain["rms_height_mm"]));
    // Bad units and scales name the key.
    for (keys, expect) in [
        ("unit = \"inch\"", "invalid surface.unit = inch"),
        ("scale = 0.0", "invalid surface.scale = 0"),
        ("scale = -1.0", "invalid surface.scale = -1"),
    ] {
        let err = refused(&wavy_case(&dir, "bad.csv", "", 1.0, keys));
        assert!(err.contains(expect), "{keys}: {err}");
    }
}

/// Issue 30 item 17: a map that is not periodic (half a wavelength: the edges' heights
/// differ by 2 D) is named in a warning; the periodic map above has none.
#[test]
fn non_periodic_map_is_named() {
    let dir = tempdir("periodic");
    let n = 64usize;
    let row: Vec<String> = (0..n)
        .map(|i| {
            format!(
                "{:e}",
                1e-3 * (std::f64::consts::PI * (i as f64 + 0.5) / n as f64).cos()
            )
        })
        .collect();
    std::fs::write(dir.join("half.csv"), vec![row.join(","); 8].join("\n")).unwrap();
    let case = "method = \"rough\"\n[surface]\nkind = \"map\"\nfile = \"half.csv\"\n\
                spacing_mm = [0.015625, 0.015625]\n[body1]\ne_mpa = 210000.0\nnu = 0.3\n\
                [body2]\ne_mpa = 210000.0\nnu = 0.3\n[load]\nmean_pressure_mpa = [50.0]\n";
    std::fs::write(dir.join("half.toml"), case).unwrap();
    let v = run_json(&["rough", dir.join("half.toml").to_str().unwrap()]);
    let w = v["warnings"].as_array().unwrap();
    assert!(
        w.iter()
            .any(|w| w.as_str().unwrap().contains("the map is not periodic")),
        "{w:?}"
    );
}

/// Issue 30 item 17: the example's elastic pressures of 22 GPa on steel are flagged: above
/// 0.1 E* without a hardness, above `load.hardness_mpa` when given (in the text report
/// too); a bad hardness names the key.
#[test]
fn pressures_above_the_hardness_are_flagged() {
    let v = run_json(&["rough", example().to_str().unwrap()]);
    let w = v["warnings"].as_array().unwrap();
    assert_eq!(w.len(), 1, "{w:?}");
    assert!(
        w[0].as_str().unwrap().contains("0.1 E* = 11538 MPa"),
        "{w:?}"
    );
    let dir = tempdir("hardness");
    let base = std::fs::read_to_string(example()).unwrap();
    let p = dir.join("h.toml");
    let text = base.replace(
        "mean_pressure_mpa = [100.0, 200.0, 400.0, 800.0]",
        "mean_pressure_mpa = [100.0, 200.0, 400.0, 800.0]\nhardness_mpa = 7500.0",
    );
    std::fs::write(&p, &text).unwrap();
    let out = kontakt()
        .args(["rough", p.to_str().unwrap()])
        .output()
        .unwrap();
    let s = String::from_utf8(out.stdout).unwrap();
    assert!(
        s.contains("warning: the largest pressure exceeds load.hardness_mpa = 7500 MPa at 4 loads"),
        "{s}"
    );
    std::fs::write(&p, text.replace("7500.0", "-1.0")).unwrap();
    let err = refused(&p);
    assert!(err.contains("invalid load.hardness_mpa = -1"), "{err}");
}

/// Issue 30 item 6: files named by a case are read through one capped reader: `/dev/zero`
/// as a map fails at its first byte (it grew to 4 GB before), as `.npy` at its magic bytes,
/// a file over 1 GiB (sparse here) is refused from its size; one line, status 2.
#[cfg(unix)]
#[test]
fn map_files_are_capped() {
    let dir = tempdir("capped");
    let big = dir.join("big.csv");
    std::fs::File::create(&big)
        .unwrap()
        .set_len(kontakt_case::MAX_DATA_FILE_BYTES + 1)
        .unwrap();
    std::os::unix::fs::symlink("/dev/zero", dir.join("zero.npy")).unwrap_or_default();
    for (file, expect) in [
        ("/dev/zero", "NUL byte at offset 0"),
        ("zero.npy", "no .npy magic bytes"),
        ("big.csv", "larger than 1 GiB (1073741825 bytes)"),
        ("zero.xyz", "NUL byte at offset 0"),
    ] {
        if file == "zero.xyz" {
            std::os::unix::fs::symlink("/dev/zero", dir.join(file)).unwrap_or_default();
        }
        let spacing = if file.ends_with("xyz") {
            ""
        } else {
            "spacing_mm = [0.01, 0.01]"
        };
        let case = format!(
            "method = \"rough\"\n[surface]\nkind = \"map\"\nfile = \"{file}\"\n{spacing}\n\
             [body1]\ne_mpa = 210000.0\nnu = 0.3\n[body2]\ne_mpa = 210000.0\nnu = 0.3\n\
             [load]\nmean_pressure_mpa = [50.0]\n"
        );
        let p = dir.join("cap.toml");
        std::fs::write(&p, case).unwrap();
        let err = refused(&p);
        assert!(
            err.contains("surface.file") && err.contains(expect),
            "{file}: {err}"
        );
    }
    std::fs::remove_file(&big).unwrap();
}

/// Issue 30 item 7: the documented largest grid, 16384 x 16384, aborted the process on an
/// allocation failure (SIGABRT); its memory is estimated before anything is allocated and
/// refused in one line naming the key, the estimate and the budget (status 2, at once);
/// `solver.max_memory_gib` sets the budget (a small one refuses the example's 256²).
#[test]
fn grids_beyond_the_memory_budget_are_refused() {
    let dir = tempdir("memory");
    let base = std::fs::read_to_string(example()).unwrap();
    for (from, to, expect) in [
        (
            "points = [256, 256]",
            "points = [16384, 16384]",
            "invalid surface.points = [16384, 16384]: expected a grid whose estimated memory fits solver.max_memory_gib = 16 GiB; 16384 x 16384 cells need about 34.3 GiB (137 bytes per cell)",
        ),
        (
            "seed = 1",
            "seed = 1\n[solver]\nmax_memory_gib = 0.005",
            "invalid surface.points = [256, 256]: expected a grid whose estimated memory fits solver.max_memory_gib = 0.005 GiB; 256 x 256 cells need about 9.4 MiB (150 bytes per cell)",
        ),
        (
            "seed = 1",
            "seed = 1\n[solver]\nmax_memory_gib = -1.0",
            "invalid solver.max_memory_gib = -1",
        ),
    ] {
        let p = dir.join("big.toml");
        std::fs::write(&p, base.replace(from, to)).unwrap();
        let started = std::time::Instant::now();
        let err = refused(&p);
        assert!(err.contains(expect), "{to}: {err}");
        assert!(started.elapsed().as_secs_f64() < 5.0, "not refused at once");
    }
}
