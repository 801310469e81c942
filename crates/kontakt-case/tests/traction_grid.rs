//! The `kalker_exact` grid warnings of a traction case (issue 30 item 5): with spin the
//! creep force converges slowly in the grid (docs/rolling.md §6.1), so a grid below
//! `KalkerExactOptions::SPIN_ELEMENTS` cells across the contact gets a warning; without
//! spin, or on a fine grid, none.

#![allow(clippy::unwrap_used)] // tests: a panic is a failure with its message

use kontakt_case::traction_case::{TractionCase, run_traction_case};

fn warnings(exact: &str, creepage: &str) -> Vec<String> {
    let text = format!(
        "method = \"traction\"\nmodels = [\"kalker_exact\"]\n\
         [geometry]\nkind = \"ellipse\"\nsemi_axes_mm = [0.3, 0.15]\n\
         [body1]\ne_mpa = 210000.0\nnu = 0.3\n[body2]\ne_mpa = 210000.0\nnu = 0.3\n\
         [load]\nforce_n = 1000.0\n[friction]\nmu = 0.3\n[creepage]\n{creepage}\n\
         [kalker_exact]\n{exact}\n"
    );
    let case = TractionCase::from_toml_str(&text).unwrap();
    let report = run_traction_case(&case).unwrap();
    report.warnings
}

fn spin_warning(w: &[String]) -> bool {
    w.iter()
        .any(|l| l.contains("with spin") && l.contains("[64, 64]"))
}

#[test]
fn spin_on_a_coarse_grid_warns() {
    let spin = "max = 0.001\npoints = 2\nlateral = -0.0006\nspin_per_mm = 0.01";
    let w = warnings("", spin);
    assert!(spin_warning(&w), "{w:?}");
    assert!(spin_warning(&warnings("elements = [64, 32]", spin)));
    // Fine enough, or no spin: no warning.
    let w = warnings("elements = [64, 64]", spin);
    assert!(!spin_warning(&w), "{w:?}");
    let w = warnings("", "max = 0.001\npoints = 2\nlateral = -0.0006");
    assert!(w.is_empty(), "{w:?}");
    // Below 16 cells the coarse-grid warning of every case is the one that speaks.
    let w = warnings("elements = [12, 12]", spin);
    assert!(
        !spin_warning(&w) && w.iter().any(|l| l.contains("below 16")),
        "{w:?}"
    );
}
