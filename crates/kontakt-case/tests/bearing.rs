//! Whole-bearing cases (`method = "bearing"`): the report's per-roller loads balance the
//! applied load, its JSON round-trips, and errors name the case keys in the file's units.

#![allow(clippy::unwrap_used)] // tests: a panic is a failure with its message

use kontakt_case::{BearingReport, Case, Outcome};
use std::path::PathBuf;

fn examples() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../../examples")
}

fn run(text: &str) -> kontakt::Result<BearingReport> {
    match Case::from_toml_str(text)?.run(&examples())? {
        Outcome::Bearing(r) => Ok(*r),
        other => panic!(
            "not a bearing outcome: {}",
            serde_json::to_string(&other).unwrap()
        ),
    }
}

fn example(name: &str) -> String {
    std::fs::read_to_string(examples().join(name)).unwrap()
}

const EXAMPLES: [&str; 4] = [
    "bearing_nu_crb.toml",
    "bearing_32008x.toml",
    "bearing_32216.toml",
    "bearing_81107_thrust.toml",
];

/// Every example: the rollers' loads along their raceway normals,
/// `Σ Q_j (cos α cos ψ_j, cos α sin ψ_j, sin α)`, equal the applied force to 1e-9 of its
/// magnitude (the solver's residual is 1e-11); the slices of the most loaded roller sum
/// to its load; the roller table has Z rows and the stiffness matrix is symmetric.
#[test]
fn roller_loads_balance_the_applied_load() {
    for name in EXAMPLES {
        let r = run(&example(name)).unwrap();
        let (sa, ca) = r.contact_angle_deg.to_radians().sin_cos();
        let mut f = [0.0; 3];
        for row in &r.roller_loads {
            let (s, c) = row.azimuth_deg.to_radians().sin_cos();
            f[0] += row.outer_load_n * ca * c;
            f[1] += row.outer_load_n * ca * s;
            f[2] += row.outer_load_n * sa;
        }
        let case: toml::Table = toml::from_str(&example(name)).unwrap();
        let applied: Vec<f64> = case["load"]["force_n"]
            .as_array()
            .unwrap()
            .iter()
            .map(|v| v.as_float().unwrap())
            .collect();
        let scale = applied.iter().fold(0.0, |m: f64, x| m.max(x.abs()));
        for i in 0..3 {
            assert!(
                (f[i] - applied[i]).abs() <= 1e-9 * scale,
                "{name}: F[{i}] = {} from the rollers, {} applied",
                f[i],
                applied[i]
            );
        }
        assert_eq!(r.roller_loads.len(), r.rollers, "{name}");
        let m = &r.most_loaded_roller;
        let q: f64 = m.load_n.iter().sum();
        let q_o = r.roller_loads[m.roller].outer_load_n;
        assert!((q - q_o).abs() <= 1e-12 * q_o, "{name}: {q} vs {q_o}");
        assert_eq!(q_o, r.max_roller_load_n, "{name}");
        for i in 0..5 {
            for j in 0..5 {
                let (a, b) = (r.stiffness_matrix[i][j], r.stiffness_matrix[j][i]);
                let big = r.stiffness_matrix[i][i]
                    .abs()
                    .max(r.stiffness_matrix[j][j].abs());
                assert!((a - b).abs() <= 1e-9 * big, "{name}: K[{i}][{j}]");
            }
        }
        assert!(r.warnings.is_empty(), "{name}: {:?}", r.warnings);
    }
}

/// The JSON report round-trips: written and read back it is the same document, and its numbers are the report's to the last bit that JSON keeps (1e-15).
#[test]
fn json_round_trips() {
    let r = run(&example("bearing_32216.toml")).unwrap();
    let text = serde_json::to_string(&r).unwrap();
    let v: serde_json::Value = serde_json::from_str(&text).unwrap();
    assert_eq!(v, serde_json::to_value(&r).unwrap());
    let q = v["roller_loads"][3]["outer_load_n"].as_f64().unwrap();
    let ours = r.roller_loads[3].outer_load_n;
    assert!((q - ours).abs() <= 1e-15 * ours);
    let k = v["stiffness_matrix"][0][0].as_f64().unwrap();
    assert!((k - r.stiffness_matrix[0][0]).abs() <= 1e-15 * k);
    assert_eq!(v["schema_version"], 1);
    assert_eq!(v["stiffness_dofs"][3], "tilt_x_rad");
}

/// Errors name the case key with the value as typed: the cone angle in degrees against the
/// cup angle in degrees (the library's range is in rad: it read `cup angle
/// contact_angle_rad = 0.279... deg` before the case layer said it in the file's units); a
/// cup angle on a cylindrical bearing; a tapered bearing without its angles; a force on a
/// degree of freedom that is also prescribed.
#[test]
fn errors_name_the_case_key_in_its_units() {
    let text = example("bearing_32216.toml");
    let e = run(&text.replace("cone_angle_deg = 11.7", "cone_angle_deg = 20.0")).unwrap_err();
    assert_eq!(e.field(), Some("bearing.cone_angle_deg"), "{e}");
    assert!(e.to_string().contains("cup_angle_deg = 16 deg"), "{e}");
    let e = run(&text.replace("cup_angle_deg = 16.0", "cup_angle_deg = 95.0")).unwrap_err();
    assert_eq!(e.field(), Some("bearing.cup_angle_deg"), "{e}");
    assert!(e.to_string().contains("= 95:"), "{e}");
    let e = run(&text.replace("cup_angle_deg = 16.0\n", "")).unwrap_err();
    assert_eq!(e.field(), Some("bearing.cup_angle_deg"), "{e}");
    let crb = example("bearing_nu_crb.toml");
    let e = run(&crb.replace("rollers = 14", "rollers = 14\ncup_angle_deg = 10.0")).unwrap_err();
    assert_eq!(e.field(), Some("bearing.cup_angle_deg"), "{e}");
    let e = run(&crb.replace("[load.prescribed]", "[load.prescribed]\ndx_mm = 0.01")).unwrap_err();
    assert_eq!(e.field(), Some("load.force_n[0]"), "{e}");
    // 101 rollers × 10001 slices: past the limit of the whole bearing
    let e = run(&crb
        .replace("slices = 31", "slices = 10001")
        .replace("rollers = 14", "rollers = 101")
        .replace("roller_diameter_mm = 11.0", "roller_diameter_mm = 1.0"))
    .unwrap_err();
    assert_eq!(e.field(), Some("bearing.slices"), "{e}");
}

/// Prescribed displacements: the CRB pushed by the displacement the force case found
/// returns that force (the round trip force → displacement → force, 1e-9).
#[test]
fn prescribed_displacement_returns_the_force() {
    let crb = example("bearing_nu_crb.toml");
    let r = run(&crb).unwrap();
    let dx = r.displacement_mm[0];
    let text = crb
        .replace("force_n = [10000.0, 0.0, 0.0]", "force_n = [0.0, 0.0, 0.0]")
        .replace(
            "[load.prescribed]",
            &format!("[load.prescribed]\ndx_mm = {dx:e}"),
        );
    let p = run(&text).unwrap();
    assert!(
        (p.force_n[0] - 10_000.0).abs() < 1e-9 * 10_000.0,
        "{}",
        p.force_n[0]
    );
    assert_eq!(p.displacement_mm[0], dx);
}
