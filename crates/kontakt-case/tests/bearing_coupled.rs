//! `[bearing] slice_model = "coupled"`: the coupled-slice option through the case schema,
//! its report keys (the pressure along every roller), the default left as it was, and a
//! bad value named.

#![allow(clippy::unwrap_used)] // tests: a panic is a failure with its message

use kontakt_case::{BearingReport, Case, Outcome};
use std::path::PathBuf;

fn examples() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../../examples")
}

fn run(text: &str) -> kontakt::Result<BearingReport> {
    match Case::from_toml_str(text)?.run(&examples())? {
        Outcome::Bearing(r) => Ok(*r),
        _ => panic!("not a bearing outcome"),
    }
}

/// The 32216 example with `slice_model = value` in `[bearing]`.
fn example_32216(value: Option<&str>) -> String {
    let text = std::fs::read_to_string(examples().join("bearing_32216.toml")).unwrap();
    match value {
        Some(v) => text.replace(
            "slices = 31\n",
            &format!("slices = 31\nslice_model = {v}\n"),
        ),
        None => text,
    }
}

#[test]
fn coupled_slices_report_the_pressure_along_every_roller() {
    let report = run(&example_32216(Some("\"coupled\""))).unwrap();
    assert!(report.solver.converged);
    let r = report.rollers().unwrap();
    let map = r.slice_pressure_mpa.as_ref().unwrap();
    assert_eq!(map.len(), 16);
    assert!(map.iter().all(|row| row.len() == 31));
    // the rollers balance the applied force (20 kN radial, 10 kN axial)
    let (sa, ca) = r.contact_angle_deg.to_radians().sin_cos();
    let mut f = [0.0; 3];
    for row in &r.roller_loads {
        let (s, c) = row.azimuth_deg.to_radians().sin_cos();
        f[0] += row.outer_load_n * ca * c;
        f[1] += row.outer_load_n * ca * s;
        f[2] += row.outer_load_n * sa;
        assert!(row.max_pressure_mpa.is_some());
    }
    for (i, want) in [20_000.0, 0.0, 10_000.0].iter().enumerate() {
        assert!((f[i] - want).abs() <= 1e-9 * 20_000.0, "F[{i}] = {}", f[i]);
    }
    // the largest pressure is the map's, and the most loaded roller's slices are in it
    let pmax = r.max_pressure_mpa.unwrap();
    let from_map = map.iter().flatten().copied().fold(0.0, f64::max);
    assert_eq!(pmax, from_map);
    let most = &r.most_loaded_roller;
    let inner = most.inner_pressure_mpa.as_ref().unwrap();
    let outer = most.outer_pressure_mpa.as_ref().unwrap();
    for k in 0..31 {
        assert_eq!(map[most.roller][k], inner[k].max(outer[k]));
    }
    // the inner raceway (the smaller radius) has the higher pressure, about 1.4 GPa here
    assert!(inner[15] > outer[15] && inner[15] > 1000.0 && inner[15] < 2000.0);
    let json = serde_json::to_string(&report).unwrap();
    assert!(json.contains("\"slice_pressure_mpa\""));
}

#[test]
fn the_default_is_the_iso_slice_law_and_reports_as_before() {
    let default = run(&example_32216(None)).unwrap();
    let iso = run(&example_32216(Some("\"iso\""))).unwrap();
    assert_eq!(
        serde_json::to_string(&default).unwrap(),
        serde_json::to_string(&iso).unwrap()
    );
    let json = serde_json::to_string(&default).unwrap();
    assert!(!json.contains("pressure_mpa"), "{json}");
    // the coupled roller loads near the ISO ones (the same mean approach law)
    let coupled = run(&example_32216(Some("\"coupled\""))).unwrap();
    let (a, b) = (
        iso.rollers().unwrap().max_roller_load_n,
        coupled.rollers().unwrap().max_roller_load_n,
    );
    assert!((b / a - 1.0).abs() < 0.05, "{a} vs {b}");
}

#[test]
fn a_bad_slice_model_is_named() {
    let e = run(&example_32216(Some("\"fem\"")))
        .unwrap_err()
        .to_string();
    assert!(e.contains("slice_model"), "{e}");
    assert!(e.contains("iso") && e.contains("coupled"), "{e}");
    let e = run(&example_32216(Some("3"))).unwrap_err().to_string();
    assert!(e.contains("slice_model"), "{e}");
}
