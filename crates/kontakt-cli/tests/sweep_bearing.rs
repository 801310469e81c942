//! `kontakt sweep` of the bearing sweep examples (issue 28): every case solved, lifted-off
//! cases counted as solved, each row the `kontakt bearing` report of its case, the
//! columns those of docs/sweep.md.

#![allow(clippy::unwrap_used)] // test helpers: a panic is a test failure with its message

mod support;

use std::collections::HashMap;
use std::path::Path;
use support::{cell as num, run_json, sweep_csv, tempdir};

fn sweep(name: &str, out: &Path) -> (serde_json::Value, Vec<String>, Vec<HashMap<String, String>>) {
    let (v, rows) = sweep_csv(&support::example(&format!("sweeps/{name}")), out);
    let mut r = csv::Reader::from_path(out.join("results.csv")).unwrap();
    let header = r.headers().unwrap().iter().map(str::to_string).collect();
    (v, header, rows)
}

#[test]
fn trb_load_sweep_rows_are_the_bearing_reports() {
    let dir = tempdir("sweep_bearing", "trb");
    let (v, header, rows) = sweep("bearing_trb_loads.toml", &dir.join("out"));
    assert_eq!(v["cases"], 165);
    assert_eq!(v["cases_not_ok"], 0);
    assert_eq!(rows.len(), 165);
    // the columns of docs/sweep.md's bearing table, after case, the parameters, status, error
    let doc =
        std::fs::read_to_string(Path::new(env!("CARGO_MANIFEST_DIR")).join("../../docs/sweep.md"))
            .unwrap();
    for c in &header[6..] {
        assert!(
            doc.contains(&format!("| `{c}` |")),
            "{c} not in docs/sweep.md"
        );
    }
    // three rows against `kontakt bearing` of the same case (base with the row's values)
    let base = std::fs::read_to_string(support::example("bearing_32008x.toml")).unwrap();
    for i in [0usize, 57, 164] {
        let r = &rows[i];
        assert_eq!(r["status"], "ok", "{r:?}");
        let case = base
            .replace(
                "clearance_mm = 0.0",
                &format!("clearance_mm = {}", r["bearing.clearance_mm"]),
            )
            .replace(
                "force_n = [5000.0, 0.0, 3000.0]",
                &format!(
                    "force_n = [{}, 0.0, {}]",
                    r["load.force_n[0]"], r["load.force_n[2]"]
                ),
            );
        let p = dir.join(format!("case{i}.toml"));
        std::fs::write(&p, case).unwrap();
        let rep = run_json(&["bearing", p.to_str().unwrap()]);
        let q = rep["max_roller_load_n"].as_f64().unwrap();
        assert!((num(r, "max_element_load_n") - q).abs() <= 1e-9 * q, "{i}");
        let dz = rep["displacement_mm"][2].as_f64().unwrap();
        assert!(
            (num(r, "displacement_mm[2]") - dz).abs() <= 1e-9 * dz.abs(),
            "{i}"
        );
        let k = rep["stiffness_matrix"][2][2].as_f64().unwrap();
        assert!(
            (num(r, "stiffness_z_n_per_mm") - k).abs() <= 1e-8 * k,
            "{i}"
        );
    }
}

#[test]
fn crb_lift_off_rows_are_solved_with_zero_force() {
    let dir = tempdir("sweep_bearing", "crb");
    let (v, _, rows) = sweep("bearing_crb_lift_off.toml", &dir.join("out"));
    assert_eq!(v["cases"], 62);
    // lifted off is a result, not a failure
    assert_eq!(v["cases_not_ok"], 0);
    let lifted: Vec<_> = rows
        .iter()
        .filter(|r| r["status"] == "lifted_off")
        .collect();
    // dx = 0 .. 0.010 mm for both roller counts
    assert_eq!(lifted.len(), 22);
    for r in lifted {
        assert_eq!(num(r, "force_n[0]"), 0.0);
        assert_eq!(r["lifted_off"], "true");
        assert_eq!(r["error"], "");
    }
}
