//! `kontakt traction`: JSON keys and values against the closed forms, CSV and plot files,
//! the human table, `kontakt solve` of a traction case, and one-line errors naming the key.

#![allow(clippy::unwrap_used)] // test helpers: a panic is a test failure with its message

use assert_cmd::Command;
use serde_json::Value;
use std::path::PathBuf;

fn kontakt() -> Command {
    Command::cargo_bin("kontakt").expect("binary built")
}

fn example() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../../examples/traction_twin_disc.toml")
}

fn tempdir() -> PathBuf {
    let d = std::env::temp_dir().join(format!("kontakt-traction-test-{}", std::process::id()));
    std::fs::create_dir_all(&d).expect("temp dir");
    d
}

fn run_json(args: &[&str]) -> Value {
    let out = kontakt().args(args).arg("--json").output().expect("runs");
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    serde_json::from_slice(&out.stdout).expect("valid JSON")
}

/// Run, expect exit status 2 and exactly one stderr line; return it.
fn bad(args: &[&str]) -> String {
    let out = kontakt().args(args).output().expect("runs");
    assert_eq!(out.status.code(), Some(2), "args {args:?}");
    let err = String::from_utf8(out.stderr).expect("utf8");
    let lines: Vec<_> = err.lines().filter(|l| !l.trim().is_empty()).collect();
    assert_eq!(lines.len(), 1, "not one line: {err}");
    lines[0].to_string()
}

/// The example's curves: Carter against its closed form, Kalker linear a straight line
/// through its saturation creepage, FASTSIM between 0 and 1 and saturated at the end.
/// Tolerances 1e-9 (closed forms re-evaluated from the reported inputs).
#[test]
fn example_json_matches_closed_forms() {
    let v = run_json(&["traction", example().to_str().unwrap()]);
    assert_eq!(v["method"], "traction");
    assert_eq!(v["geometry"], "hertz");
    assert_eq!(v["schema_version"], 1);
    let xs: Vec<f64> = v["creepage"]
        .as_array()
        .unwrap()
        .iter()
        .map(|x| x.as_f64().unwrap())
        .collect();
    assert_eq!(xs.len(), 121);
    assert!((xs[120] - 0.006).abs() < 1e-15);
    let curve = |name: &str| -> Vec<f64> {
        let c = v["curves"]
            .as_array()
            .unwrap()
            .iter()
            .find(|c| c["model"] == name)
            .unwrap_or_else(|| panic!("no curve {name}"));
        c["normalized_force"]
            .as_array()
            .unwrap()
            .iter()
            .map(|x| x.as_f64().unwrap())
            .collect()
    };
    // Carter: 1 - (1 - xi/xi_s)^2, xi_s = 2 mu p0/E*.
    let (mu, p0, es) = (
        v["mu"].as_f64().unwrap(),
        v["max_pressure_mpa"].as_f64().unwrap(),
        v["e_star_mpa"].as_f64().unwrap(),
    );
    let xs_c = v["carter_saturation_creepage"].as_f64().unwrap();
    assert!((xs_c - 2.0 * mu * p0 / es).abs() < 1e-15);
    for (x, f) in xs.iter().zip(curve("carter")) {
        let s = (x / xs_c).min(1.0);
        assert!((f - (1.0 - (1.0 - s) * (1.0 - s))).abs() < 1e-9, "xi={x}");
    }
    // Kalker linear: xi/xi_k, unclipped.
    let xk = v["kalker_saturation_creepage"].as_f64().unwrap();
    let k = curve("kalker_linear");
    for (x, f) in xs.iter().zip(&k) {
        assert!((f - x / xk).abs() < 1e-9);
    }
    assert!(k[120] > 4.0, "unclipped beyond saturation");
    // FASTSIM: monotone, bounded, saturated at the end, below the linear theory.
    let f = curve("fastsim");
    assert_eq!(f[0], 0.0);
    assert!(f.windows(2).all(|w| w[1] >= w[0] - 1e-12));
    assert!((f[120] - 1.0).abs() < 1e-9);
    assert!(f.iter().zip(&k).skip(1).all(|(a, b)| a < b));
    assert_eq!(v["fastsim_elements"], serde_json::json!([50, 50]));
    let c11 = v["creep_coefficients"]["c11"].as_f64().unwrap();
    assert!(c11 > 3.4 && c11 < 4.3, "a/b < 1 at nu = 0.3: {c11}");
}

/// CSV with every point and one column per model; PNG and SVG plots; the human table.
#[test]
fn csv_plot_and_table() {
    let dir = tempdir();
    let csv = dir.join("curves.csv");
    let png = dir.join("curves.png");
    let svg = dir.join("curves.svg");
    let out = kontakt()
        .args([
            "traction",
            example().to_str().unwrap(),
            "--csv",
            csv.to_str().unwrap(),
            "--plot",
            png.to_str().unwrap(),
        ])
        .output()
        .unwrap();
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let table = String::from_utf8(out.stdout).unwrap();
    for s in [
        "traction curves F_T/(mu F_N)",
        "a = 0.29903 mm (rolling)",
        "Kalker C11",
        "creepage         carter  kalker_linear        fastsim",
        "--csv writes all",
    ] {
        assert!(table.contains(s), "table lacks {s:?}:\n{table}");
    }
    let text = std::fs::read_to_string(&csv).unwrap();
    let mut lines = text.lines();
    assert_eq!(
        lines.next().unwrap(),
        "creepage,carter_ft_over_mu_fn,kalker_linear_ft_over_mu_fn,fastsim_ft_over_mu_fn"
    );
    assert_eq!(lines.count(), 121);
    assert!(std::fs::metadata(&png).unwrap().len() > 10_000);
    let out = kontakt()
        .args([
            "traction",
            example().to_str().unwrap(),
            "--plot",
            svg.to_str().unwrap(),
        ])
        .output()
        .unwrap();
    assert!(out.status.success());
    let svg = std::fs::read_to_string(&svg).unwrap();
    assert!(svg.contains("FASTSIM") && svg.contains("Kalker linear (to saturation)"));
}

/// `kontakt solve` runs a traction case too (table or JSON), and points to `traction` for
/// the files.
#[test]
fn solve_dispatches_traction_cases() {
    let v = run_json(&["solve", example().to_str().unwrap()]);
    assert_eq!(v["method"], "traction");
    assert!(v["max_pressure_mpa"].as_f64().unwrap() > 0.0);
    let l = bad(&["solve", example().to_str().unwrap(), "--csv", "x.csv"]);
    assert!(l.contains("kontakt traction"), "{l}");
}

/// Line contact (Carter only) and an explicit ellipse.
#[test]
fn line_and_ellipse_geometries() {
    let dir = tempdir();
    let base = std::fs::read_to_string(example()).unwrap();
    let line = base
        .replace(
            "kind = \"hertz\"\nradii1_mm = [20.0, 50.0]    # [circumferential (rolling), crown]\nradii2_mm = [20.0, inf]     # cylindrical disc\nangle_deg = 0.0",
            "kind = \"line\"\nradii_mm = [20.0, 20.0]\nlength_mm = 10.0",
        )
        .replace(
            "models = [\"carter\", \"kalker_linear\", \"fastsim\"]",
            "models = [\"carter\"]",
        );
    assert_ne!(line, base);
    let p = dir.join("line.toml");
    std::fs::write(&p, &line).unwrap();
    let v = run_json(&["traction", p.to_str().unwrap()]);
    assert_eq!(v["geometry"], "line");
    assert!((v["line_load_n_per_mm"].as_f64().unwrap() - 100.0).abs() < 1e-12);
    // Carter for cylinders: xi_s = mu a/R, R = 10 mm.
    let a = v["semi_axes_mm"][0].as_f64().unwrap();
    let xs = v["carter_saturation_creepage"].as_f64().unwrap();
    assert!((xs - 0.1 * a / 10.0).abs() < 1e-12 * xs.max(1.0));
    assert!(v["creep_coefficients"].is_null());
    // Kalker's models need an ellipse.
    let p = dir.join("line_fastsim.toml");
    std::fs::write(
        &p,
        line.replace("models = [\"carter\"]", "models = [\"fastsim\"]"),
    )
    .unwrap();
    let l = bad(&["traction", p.to_str().unwrap()]);
    assert!(l.contains("invalid models = fastsim"), "{l}");
    // Explicit ellipse.
    let p = dir.join("ellipse.toml");
    std::fs::write(
        &p,
        base.replace(
            "kind = \"hertz\"\nradii1_mm = [20.0, 50.0]    # [circumferential (rolling), crown]\nradii2_mm = [20.0, inf]     # cylindrical disc\nangle_deg = 0.0",
            "kind = \"ellipse\"\nsemi_axes_mm = [0.3, 0.3]",
        ),
    )
    .unwrap();
    let v = run_json(&["traction", p.to_str().unwrap()]);
    assert_eq!(v["geometry"], "ellipse");
    assert!((v["creep_coefficients"]["c11"].as_f64().unwrap() - 4.300).abs() < 5e-4);
}

/// Bad input: one line, exit status 2, naming the case key.
#[test]
fn bad_cases_name_the_key() {
    let dir = tempdir();
    let base = std::fs::read_to_string(example()).unwrap();
    let write = |name: &str, text: String| {
        assert_ne!(text, base, "{name}: replacement did not apply");
        let p = dir.join(name);
        std::fs::write(&p, text).unwrap();
        p.to_str().unwrap().to_string()
    };
    let p = write("mu.toml", base.replace("mu = 0.1", "mu = 0.0"));
    let l = bad(&["traction", &p]);
    assert!(l.contains("invalid friction.mu = 0"), "{l}");
    let p = write(
        "force.toml",
        base.replace("force_n = 1000.0", "force_n = 0.0"),
    );
    let l = bad(&["traction", &p]);
    assert!(l.contains("invalid load.force_n = 0"), "{l}");
    let p = write("max.toml", base.replace("max = 0.006", "max = nan"));
    let l = bad(&["traction", &p]);
    assert!(l.contains("invalid creepage.max = NaN"), "{l}");
    let p = write("nu.toml", base.replacen("nu = 0.3", "nu = 0.7", 1));
    let l = bad(&["traction", &p]);
    assert!(l.contains("invalid body1.nu = 0.7"), "{l}");
    let p = write(
        "grid.toml",
        base.replace("elements = [50, 50]", "elements = [50, 0]"),
    );
    let l = bad(&["traction", &p]);
    assert!(l.contains("invalid fastsim.elements[1] = 0"), "{l}");
    let p = write("model.toml", base.replace("\"fastsim\"]", "\"fastsimm\"]"));
    let l = bad(&["traction", &p]);
    assert!(l.contains("fastsimm") && l.contains("line"), "{l}");
    let p = write(
        "oblique.toml",
        base.replace("angle_deg = 0.0", "angle_deg = 30.0"),
    );
    let l = bad(&["traction", &p]);
    assert!(
        l.contains("geometry.angle_deg") && l.contains("along an axis"),
        "{l}"
    );
    let l = bad(&["traction", dir.join("missing.toml").to_str().unwrap()]);
    assert!(l.contains("cannot read case file"), "{l}");
}

/// The asperity model of `kontakt::traction` on a circular contact (sphere on flat):
/// zero at zero creepage, monotone, 1 once every asperity slides; refused on an ellipse.
#[test]
fn asperity_model_on_a_circular_contact() {
    let dir = tempdir();
    let base = std::fs::read_to_string(example()).unwrap();
    let sphere = base
        .replace(
            "radii1_mm = [20.0, 50.0]    # [circumferential (rolling), crown]\nradii2_mm = [20.0, inf]     # cylindrical disc",
            "radii1_mm = [10.0, 10.0]\nradii2_mm = [inf, inf]",
        )
        .replace(
            "models = [\"carter\", \"kalker_linear\", \"fastsim\"]",
            "models = [\"fastsim\", \"asperity\"]",
        )
        .replace("max = 0.006", "max = 0.05")
        + "\n[asperity]\nasperity_radii_mm = [0.02, 0.02]\nperiod_mm = 0.05\n";
    let p = dir.join("sphere_asperity.toml");
    std::fs::write(&p, &sphere).unwrap();
    let v = run_json(&["traction", p.to_str().unwrap()]);
    let curves = v["curves"].as_array().unwrap();
    assert_eq!(curves[1]["model"], "asperity");
    let f: Vec<f64> = curves[1]["normalized_force"]
        .as_array()
        .unwrap()
        .iter()
        .map(|x| x.as_f64().unwrap())
        .collect();
    assert_eq!(f[0], 0.0);
    assert!(f.windows(2).all(|w| w[1] >= w[0] - 1e-12));
    assert!((f[f.len() - 1] - 1.0).abs() < 1e-9, "{}", f[f.len() - 1]);
    assert!(v["asperities"].as_u64().unwrap() > 50);
    // Without [asperity], and on the elliptical twin-disc contact: one-line errors.
    let p = dir.join("no_table.toml");
    std::fs::write(&p, sphere.split("[asperity]").next().unwrap()).unwrap();
    assert!(bad(&["traction", p.to_str().unwrap()]).contains("invalid asperity = missing"));
    let p = dir.join("ellipse_asperity.toml");
    std::fs::write(
        &p,
        base.replace("\"fastsim\"]", "\"fastsim\", \"asperity\"]")
            + "\n[asperity]\nasperity_radii_mm = [0.02, 0.02]\nperiod_mm = 0.05\n",
    )
    .unwrap();
    let l = bad(&["traction", p.to_str().unwrap()]);
    assert!(l.contains("invalid models = asperity on an ellipse"), "{l}");
}

/// The case text of a circular contact (a = b = 0.3 mm, 1000 N, mu = 0.1, steel) with
/// Kalker's linear theory and FASTSIM and the given `[creepage]` table.
fn combined_case(creepage: &str, models: &str) -> PathBuf {
    let text = format!(
        "method = \"traction\"\nmodels = [{models}]\n[geometry]\nkind = \"ellipse\"\nsemi_axes_mm = [0.3, 0.3]\n\
         [body1]\ne_mpa = 210000.0\nnu = 0.3\n[body2]\ne_mpa = 210000.0\nnu = 0.3\n\
         [load]\nforce_n = 1000.0\n[friction]\nmu = 0.1\n[creepage]\n{creepage}\n\
         [fastsim]\nelements = [60, 60]\n"
    );
    let name = format!("combined-{:016x}.toml", fnv(&text));
    let p = tempdir().join(name);
    std::fs::write(&p, text).unwrap();
    p
}

fn fnv(s: &str) -> u64 {
    s.bytes().fold(0xcbf2_9ce4_8422_2325, |h, b| {
        (h ^ u64::from(b)).wrapping_mul(0x100_0000_01b3)
    })
}

fn forces(v: &Value, model: &str) -> [Vec<f64>; 3] {
    let c = v["curves"]
        .as_array()
        .unwrap()
        .iter()
        .find(|c| c["model"] == model)
        .unwrap();
    let list = |k: &str| -> Vec<f64> {
        c["forces"][k]
            .as_array()
            .map(|a| a.iter().map(|x| x.as_f64().unwrap()).collect())
            .unwrap_or_default()
    };
    [
        list("longitudinal_force_n"),
        list("lateral_force_n"),
        list("spin_moment_nmm"),
    ]
}

/// Lateral and spin creepage (issue 16, item 5): at small creepages FASTSIM's forces equal
/// Kalker's linear theory, whose coefficients FASTSIM's flexibilities are built from (within
/// 2 % on a 60 x 60 grid); the spin moment opposes the spin; at a large lateral creepage
/// FASTSIM's force saturates at mu F_N (1e-9), in the direction (C11 xi, C22 eta); Carter, a longitudinal
/// theory, refuses lateral creepage naming the key.
#[test]
fn lateral_and_spin_creepage_give_forces_in_both_directions() {
    let both = "\"kalker_linear\", \"fastsim\"";
    // Small lateral creepage, small longitudinal creepages.
    let v = run_json(&[
        "traction",
        combined_case("max = 1e-5\npoints = 3\nlateral = 1e-5", both)
            .to_str()
            .unwrap(),
    ]);
    assert_eq!(v["lateral_creepage"], 1e-5);
    let [kx, ky, km] = forces(&v, "kalker_linear");
    let [fx, fy, fm] = forces(&v, "fastsim");
    assert!(km.is_empty() && fm.len() == 3);
    for i in 1..3 {
        assert!(
            (fx[i] / kx[i] - 1.0).abs() < 0.02,
            "Fx {} vs {}",
            fx[i],
            kx[i]
        );
    }
    for i in 0..3 {
        assert!(
            ky[i] < 0.0 && (fy[i] / ky[i] - 1.0).abs() < 0.02,
            "Fy {} vs {}",
            fy[i],
            ky[i]
        );
    }
    // Small spin alone: the lateral force of spin, C23.
    let v = run_json(&[
        "traction",
        combined_case("max = 1e-6\npoints = 2\nspin_per_mm = 1e-4", both)
            .to_str()
            .unwrap(),
    ]);
    let [_, ky, _] = forces(&v, "kalker_linear");
    let [_, fy, fm] = forces(&v, "fastsim");
    assert!(
        (fy[0] / ky[0] - 1.0).abs() < 0.02,
        "spin Fy {} vs {}",
        fy[0],
        ky[0]
    );
    assert!(fm[0] < 0.0, "Mz {} should oppose a positive spin", fm[0]);
    // Large lateral creepage: full sliding, |F| = mu F_N = 100 N.
    let v = run_json(&[
        "traction",
        combined_case("max = 0.5\npoints = 5\nlateral = 1.0", "\"fastsim\"")
            .to_str()
            .unwrap(),
    ]);
    let [fx, fy, _] = forces(&v, "fastsim");
    for i in 0..5 {
        let f = fx[i].hypot(fy[i]);
        assert!((f - 100.0).abs() < 1e-9 * 100.0, "|F| = {f}");
    }
    // In full sliding FASTSIM clips the traction increment (xi/L1, eta/L2), whose
    // flexibilities are L ~ 1/C: its force points along (C11 xi, C22 eta), not along the
    // creepage (Kalker's simplified theory; docs/tangential.md). At xi = 0.01 and 0.5:
    let c = &v["creep_coefficients"];
    let ratio = c["c11"].as_f64().unwrap() / c["c22"].as_f64().unwrap();
    assert!(ratio > 1.05, "{ratio}");
    for (i, xi) in [(1, 0.125), (4, 0.5)] {
        let r = fx[i] / fy[i] / (xi * ratio);
        assert!(
            (r - 1.0).abs() < 1e-3,
            "point {i}: Fx/Fy {} against {}",
            fx[i] / fy[i],
            xi * ratio
        );
    }
    // Carter takes no lateral creepage.
    let l = bad(&[
        "traction",
        combined_case("max = 0.001\nlateral = 1e-4", "\"carter\"")
            .to_str()
            .unwrap(),
    ]);
    assert!(
        l.contains("invalid creepage.lateral = 0.0001") && l.contains("fastsim"),
        "{l}"
    );
}

/// A line contact given by its half-width or by its load per length (issue 16, item 5):
/// the strip of the Hertz half-width of two cylinders under the same line load is the same
/// Carter contact (p0 and saturation creepage to 1e-12); `line_load_n_per_mm = 100` with a
/// 10 mm length is `force_n = 1000`; contradictory or misplaced keys are one-line errors.
#[test]
fn line_contact_by_half_width_or_line_load() {
    let dir = tempdir();
    let base = std::fs::read_to_string(example()).unwrap().replace(
        "models = [\"carter\", \"kalker_linear\", \"fastsim\"]",
        "models = [\"carter\"]",
    );
    let geometry = "kind = \"hertz\"\nradii1_mm = [20.0, 50.0]    # [circumferential (rolling), crown]\nradii2_mm = [20.0, inf]     # cylindrical disc\nangle_deg = 0.0";
    assert!(base.contains(geometry));
    let write = |name: &str, geometry_text: &str, load: &str| {
        let p = dir.join(name);
        let text = base
            .replace(geometry, geometry_text)
            .replace("force_n = 1000.0", load);
        std::fs::write(&p, text).unwrap();
        p
    };
    let radii = write(
        "line_radii.toml",
        "kind = \"line\"\nradii_mm = [20.0, 20.0]\nlength_mm = 10.0",
        "force_n = 1000.0",
    );
    let r = run_json(&["traction", radii.to_str().unwrap()]);
    let a = r["semi_axes_mm"][0].as_f64().unwrap();
    let strip = write(
        "line_strip.toml",
        &format!("kind = \"line\"\nhalf_width_mm = {a:?}\nlength_mm = 10.0"),
        "line_load_n_per_mm = 100.0",
    );
    let s = run_json(&["traction", strip.to_str().unwrap()]);
    assert_eq!(s["force_n"], 1000.0);
    assert_eq!(s["line_load_n_per_mm"], 100.0);
    for key in ["max_pressure_mpa", "carter_saturation_creepage"] {
        let (x, y) = (r[key].as_f64().unwrap(), s[key].as_f64().unwrap());
        assert!((x / y - 1.0).abs() < 1e-12, "{key}: {x} vs {y}");
    }
    let both = write(
        "line_both.toml",
        "kind = \"line\"\nradii_mm = [20.0, 20.0]\nhalf_width_mm = 0.1\nlength_mm = 10.0",
        "force_n = 1000.0",
    );
    let l = bad(&["traction", both.to_str().unwrap()]);
    assert!(
        l.contains("invalid geometry = both radii_mm and half_width_mm"),
        "{l}"
    );
    let point_line_load = write("point_q.toml", geometry, "line_load_n_per_mm = 100.0");
    let l = bad(&["traction", point_line_load.to_str().unwrap()]);
    assert!(l.contains("invalid load.line_load_n_per_mm = 100"), "{l}");
    let no_load = write("no_load.toml", geometry, "");
    let l = bad(&["traction", no_load.to_str().unwrap()]);
    assert!(l.contains("invalid load = neither"), "{l}");
}

/// A small `kalker_exact` case: a circle on a coarse grid (16 cells across) and few
/// points, so that the test stays quick while the steady solver is slow.
fn exact_case(extra: &str, creepage: &str) -> PathBuf {
    let text = format!(
        "method = \"traction\"\nmodels = [\"kalker_linear\", \"fastsim\", \"kalker_exact\"]\n\
         [geometry]\nkind = \"ellipse\"\nsemi_axes_mm = [0.3, 0.3]\n\
         [body1]\ne_mpa = 210000.0\nnu = 0.3\n[body2]\ne_mpa = 210000.0\nnu = 0.3\n\
         [load]\nforce_n = 1000.0\n[friction]\nmu = 0.1\n[creepage]\n{creepage}\n\
         [kalker_exact]\n{extra}\n"
    );
    let name = format!("exact-{:016x}.toml", fnv(&text));
    let p = tempdir().join(name);
    std::fs::write(&p, text).unwrap();
    p
}

/// `kalker_exact` in the JSON report: its curve with the solver record (converged at
/// every point, stick fraction from 1 down to 0), zero at zero creepage, below the linear
/// theory, monotone, and 1 in full sliding (1e-3); in the table with its grid line; in
/// the plot's legend.
#[test]
fn kalker_exact_curve_in_json_table_and_plot() {
    let case = exact_case("elements = [16, 16]", "max = 0.018\npoints = 7");
    let v = run_json(&["traction", case.to_str().unwrap()]);
    let c = v["curves"]
        .as_array()
        .unwrap()
        .iter()
        .find(|c| c["model"] == "kalker_exact")
        .expect("kalker_exact curve");
    let f: Vec<f64> = c["normalized_force"]
        .as_array()
        .unwrap()
        .iter()
        .map(|x| x.as_f64().unwrap())
        .collect();
    let x = &c["exact"];
    assert_eq!(x["converged"], true);
    assert_eq!(x["elements"], serde_json::json!([16, 16]));
    assert_eq!(x["not_converged"].as_array().unwrap().len(), 0);
    let status = x["status"].as_array().unwrap();
    assert_eq!(status.len(), 7);
    assert!(status.iter().all(|s| s["termination"] == "converged"));
    let stick: Vec<f64> = x["stick_fraction"]
        .as_array()
        .unwrap()
        .iter()
        .map(|s| s.as_f64().unwrap())
        .collect();
    assert_eq!(stick[0], 1.0);
    assert_eq!(stick[6], 0.0);
    assert_eq!(f[0], 0.0);
    assert!(f.windows(2).all(|w| w[1] > w[0] - 1e-9), "{f:?}");
    // Full sliding: 1 to 1e-3 (measured 0.99982: with nu > 0 the slip turns slightly
    // out of x, so |F| = mu F_N but F_x is a little less; CONTACT's curves show the same).
    assert!((f[6] - 1.0).abs() < 1e-3 && f[6] < 1.0, "{f:?}");
    // Below its tangent (the linear theory), above half of it at u = 0.94.
    let linear = v["curves"][0]["normalized_force"][1].as_f64().unwrap();
    assert!(
        f[1] < linear && f[1] > 0.5 * linear,
        "{} vs linear {linear}",
        f[1]
    );
    assert!(v.get("warnings").is_none(), "{v}");
    // The table names the model and its grid; the plot carries it in the legend.
    let dir = tempdir();
    let svg = dir.join("exact.svg");
    let out = kontakt()
        .args(["traction", case.to_str().unwrap(), "--plot"])
        .arg(&svg)
        .output()
        .unwrap();
    assert!(out.status.success());
    let text = String::from_utf8(out.stdout).unwrap();
    assert!(text.contains("kalker_exact"), "{text}");
    assert!(
        text.contains(
            "Kalker exact grid 16 x 16 cells across the contact; converged at all 7 points"
        ),
        "{text}"
    );
    let drawn = std::fs::read_to_string(&svg).unwrap();
    assert!(drawn.contains("Kalker exact"), "legend");
}

/// With lateral creepage and spin the exact model reports forces and the spin moment;
/// the lateral force opposes the lateral creepage.
#[test]
fn kalker_exact_with_lateral_creepage_and_spin() {
    let case = exact_case(
        "elements = [16, 16]",
        "max = 0.001\npoints = 2\nlateral = 0.0005\nspin_per_mm = 0.001",
    );
    let v = run_json(&["traction", case.to_str().unwrap()]);
    let [fx, fy, mz] = forces(&v, "kalker_exact");
    assert_eq!((fx.len(), fy.len(), mz.len()), (2, 2, 2));
    assert!(fy.iter().all(|f| *f < 0.0), "{fy:?}");
    assert!(
        fx[1] < 0.0 && fx[0].abs() < 1e-6 * fx[1].abs().max(1.0),
        "{fx:?}"
    );
    // |F| <= mu F_N.
    for i in 0..2 {
        assert!(fx[i].hypot(fy[i]) <= 100.0 * (1.0 + 1e-6));
    }
}

/// Bad input through the case: a grid too coarse to resolve the slip area, zero rolling
/// steps, friction <= 0, a non-finite lateral creepage, a line contact: one line, exit 2,
/// naming the key. A point that does not converge: reported (status, `not_converged`,
/// a warning and `*` in the table), exit status 0.
#[test]
fn kalker_exact_bad_input_and_unconverged_points() {
    let pts = "max = 0.002\npoints = 2";
    let l = bad(&[
        "traction",
        exact_case("elements = [4, 16]", pts).to_str().unwrap(),
    ]);
    assert!(
        l.contains("invalid kalker_exact.elements[0] = 4") && l.contains("slip area"),
        "{l}"
    );
    let l = bad(&[
        "traction",
        exact_case("max_iterations = 0", pts).to_str().unwrap(),
    ]);
    assert!(l.contains("invalid kalker_exact.max_iterations = 0"), "{l}");
    let l = bad(&[
        "traction",
        exact_case("elements = [16, 16]", "max = 0.002\npoints = 1002")
            .to_str()
            .unwrap(),
    ]);
    assert!(
        l.contains("invalid creepage.points = 1002") && l.contains("kalker_exact"),
        "{l}"
    );
    let l = bad(&[
        "traction",
        exact_case("elements = [16, 16]", "max = 0.002\nlateral = nan")
            .to_str()
            .unwrap(),
    ]);
    assert!(l.contains("invalid creepage.lateral = NaN"), "{l}");
    let p = exact_case("elements = [16, 16]", pts);
    let text = std::fs::read_to_string(&p)
        .unwrap()
        .replace("mu = 0.1", "mu = -0.1");
    std::fs::write(&p, text).unwrap();
    let l = bad(&["traction", p.to_str().unwrap()]);
    assert!(l.contains("invalid friction.mu = -0.1"), "{l}");
    let line = tempdir().join("exact-line.toml");
    let text = "method = \"traction\"\nmodels = [\"kalker_exact\"]\n[geometry]\nkind = \"line\"\n\
                half_width_mm = 0.2\nlength_mm = 10.0\n[body1]\ne_mpa = 210000.0\nnu = 0.3\n\
                [body2]\ne_mpa = 210000.0\nnu = 0.3\n[load]\nforce_n = 1000.0\n\
                [friction]\nmu = 0.1\n[creepage]\nmax = 0.002\n";
    std::fs::write(&line, text).unwrap();
    let l = bad(&["traction", line.to_str().unwrap()]);
    assert!(l.contains("invalid models = kalker_exact"), "{l}");
    // One Newton iteration: not converged, reported.
    let case = exact_case(
        "elements = [8, 8]\nmax_iterations = 1",
        "max = 0.002\npoints = 2",
    );
    let v = run_json(&["traction", case.to_str().unwrap()]);
    let x = &v["curves"][2]["exact"];
    assert_eq!(x["converged"], false);
    assert_eq!(x["not_converged"], serde_json::json!([1]));
    assert_eq!(x["status"][1]["termination"], "max_iterations");
    let w = v["warnings"].as_array().unwrap();
    assert!(
        w.iter().any(|w| w
            .as_str()
            .unwrap()
            .contains("1 of 2 points did not converge")),
        "{w:?}"
    );
    assert!(
        w.iter()
            .any(|w| w.as_str().unwrap().contains("8 x 8 cells")),
        "{w:?}"
    );
    let out = kontakt()
        .args(["traction", case.to_str().unwrap()])
        .output()
        .unwrap();
    assert!(out.status.success());
    let text = String::from_utf8(out.stdout).unwrap();
    assert!(text.contains("NOT converged at 1 of 2 points"), "{text}");
    assert!(
        text.contains("*\n") && text.contains("warning: kalker_exact"),
        "{text}"
    );
}

/// `--map`: kalker_exact's stick/slip map at one point (PNG and SVG written; the SVG
/// names the stick area and the ellipse); without kalker_exact in the models, or with a
/// non-finite `--map-creepage`, one line and exit 2.
#[test]
fn kalker_exact_stick_slip_map() {
    let case = exact_case("elements = [16, 16]", "max = 0.004\npoints = 3");
    let dir = tempdir();
    let (png, svg) = (dir.join("map.png"), dir.join("map.svg"));
    for (path, extra) in [(&png, None), (&svg, Some("0.001"))] {
        let mut cmd = kontakt();
        cmd.args(["traction", case.to_str().unwrap(), "--map"])
            .arg(path);
        if let Some(xi) = extra {
            cmd.args(["--map-creepage", xi]);
        }
        let out = cmd.output().unwrap();
        assert!(
            out.status.success(),
            "{}",
            String::from_utf8_lossy(&out.stderr)
        );
        assert!(std::fs::metadata(path).unwrap().len() > 1000);
    }
    let drawn = std::fs::read_to_string(&svg).unwrap();
    assert!(drawn.contains("stick (adhesion) area"), "legend");
    assert!(drawn.contains("xi = 1.0000e-3"), "title names the creepage");
    let l = bad(&[
        "traction",
        example().to_str().unwrap(),
        "--map",
        dir.join("no.png").to_str().unwrap(),
    ]);
    assert!(
        l.contains("invalid models") && l.contains("kalker_exact"),
        "{l}"
    );
    let l = bad(&[
        "traction",
        case.to_str().unwrap(),
        "--map",
        png.to_str().unwrap(),
        "--map-creepage",
        "nan",
    ]);
    assert!(l.contains("--map-creepage"), "{l}");
}

/// A `kalker_exact` case of an aluminium sphere (R = 10 mm) on a steel plane, 300 N,
/// mu = 0.3, 16 cells across (Kalker's K = 0.100).
fn dissimilar_case(extra: &str, creepage: &str) -> PathBuf {
    let text = format!(
        "method = \"traction\"\nmodels = [\"kalker_linear\", \"kalker_exact\"]\n\
         [geometry]\nkind = \"hertz\"\nradii1_mm = [10.0, 10.0]\nradii2_mm = [inf, inf]\n\
         [body1]\ne_mpa = 60260.0\nnu = 0.31\n[body2]\ne_mpa = 209920.0\nnu = 0.28\n\
         [load]\nforce_n = 300.0\n[friction]\nmu = 0.3\n[creepage]\n{creepage}\n\
         [kalker_exact]\nelements = [16, 16]\n{extra}\n"
    );
    let name = format!("dissimilar-{:016x}.toml", fnv(&text));
    let p = tempdir().join(name);
    std::fs::write(&p, text).unwrap();
    p
}

/// `[kalker_exact] coupling`: off, dissimilar materials give a warning naming K (JSON and
/// table) and no free-rolling creepage; on, the JSON record says so and gives the
/// free-rolling creepage (negative: body 1 the more compliant, K > 0), the table prints
/// it, the curve converges and reaches mu F_N (1e-3); equal materials with the coupling
/// on: no warning and no coupling record. A bad value: exit 2, one line naming the key.
#[test]
fn kalker_exact_coupling_for_dissimilar_materials() {
    let pts = "max = 0.05\npoints = 3";
    let off = run_json(&["traction", dissimilar_case("", pts).to_str().unwrap()]);
    let k = off["difference_parameter"].as_f64().unwrap();
    assert!((k - 0.1002).abs() < 1e-4, "K = {k}");
    let w = off["warnings"].as_array().unwrap();
    assert!(
        w.iter().any(|w| {
            let w = w.as_str().unwrap();
            w.contains("K = 1.0019e-1") && w.contains("neglected by kalker_linear, kalker_exact")
        }),
        "{w:?}"
    );
    let x = &off["curves"][1]["exact"];
    assert!(x.get("coupling").is_none() && x.get("free_rolling_creepage").is_none());
    let text = String::from_utf8(
        kontakt()
            .args(["traction", dissimilar_case("", pts).to_str().unwrap()])
            .output()
            .unwrap()
            .stdout,
    )
    .unwrap();
    assert!(
        text.contains("Kalker's difference parameter K = 1.0019e-1")
            && text.contains("warning: Kalker's difference parameter K = 1.0019e-1"),
        "{text}"
    );

    let case = dissimilar_case("coupling = true", pts);
    let on = run_json(&["traction", case.to_str().unwrap()]);
    let x = &on["curves"][1]["exact"];
    assert_eq!(x["coupling"], true);
    assert_eq!(x["converged"], true);
    let free = x["free_rolling_creepage"].as_f64().unwrap();
    // Measured: -1.4293e-3 (as CoupledSteadySolver on this contact).
    assert!(free < -1e-3 && free > -2e-3, "{free}");
    let f: Vec<f64> = on["curves"][1]["normalized_force"]
        .as_array()
        .unwrap()
        .iter()
        .map(|v| v.as_f64().unwrap())
        .collect();
    // At zero creepage the pressure's slip already pulls (F_T > 0 for xi_free < 0).
    assert!(f[0] > 0.0 && (f[2] - 1.0).abs() < 1e-3, "{f:?}");
    let w = on["warnings"].as_array().unwrap();
    assert!(
        w.iter()
            .any(|w| w.as_str().unwrap().contains("neglected by kalker_linear:")),
        "{w:?}"
    );
    let text = String::from_utf8(
        kontakt()
            .args(["traction", case.to_str().unwrap()])
            .output()
            .unwrap()
            .stdout,
    )
    .unwrap();
    assert!(
        text.contains(
            "Kalker exact coupled through K = 1.0019e-1: free-rolling creepage -1.4293e-3"
        ),
        "{text}"
    );

    // Equal materials, coupling on: the uncoupled model, no K in the table.
    let same = exact_case(
        "elements = [16, 16]\ncoupling = true",
        "max = 0.002\npoints = 2",
    );
    let v = run_json(&["traction", same.to_str().unwrap()]);
    assert_eq!(v["difference_parameter"], 0.0);
    assert!(v.get("warnings").is_none(), "{v}");
    assert!(v["curves"][2]["exact"].get("coupling").is_none());

    let l = bad(&[
        "traction",
        dissimilar_case("coupling = 1", pts).to_str().unwrap(),
    ]);
    assert!(l.contains("kalker_exact.coupling"), "{l}");

    // The hybrid bearing of examples/ceramic_ball.toml (silicon nitride ball, E = 310
    // GPa, nu = 0.26, on steel): K = -2.56e-2, neglected by the default models.
    let text = std::fs::read_to_string(dissimilar_case("", pts))
        .unwrap()
        .replace("models = [\"kalker_linear\", \"kalker_exact\"]\n", "")
        .replace("e_mpa = 60260.0\nnu = 0.31", "e_mpa = 310000.0\nnu = 0.26")
        .replace("e_mpa = 209920.0\nnu = 0.28", "e_mpa = 210000.0\nnu = 0.3");
    let hybrid = tempdir().join("hybrid.toml");
    std::fs::write(&hybrid, text).unwrap();
    let v = run_json(&["traction", hybrid.to_str().unwrap()]);
    let k = v["difference_parameter"].as_f64().unwrap();
    assert!((k + 0.0256).abs() < 1e-3, "K = {k}");
    let w = v["warnings"].as_array().unwrap();
    assert!(
        w.iter().any(|w| w
            .as_str()
            .unwrap()
            .contains("neglected by carter, kalker_linear, fastsim")),
        "{w:?}"
    );
}
