#![allow(clippy::unwrap_used)] // test helpers: a panic is a test failure with its message
//! Help and docs that cannot drift from the code (issue 30 item 19): `kontakt solve --help`
//! names every method `Case` runs, `traction --help` every traction model, `friction --help`
//! every pressure model (the help is built from the same lists), and the column count that
//! docs/sweep.md prints for its example is the program's.

mod support;

use kontakt::bearing::rib_friction::PressureModel;
use kontakt_case::Case;
use kontakt_case::traction_case::TractionModel;
use support::{kontakt, run_json};

fn help(command: &str) -> String {
    let out = kontakt().args([command, "--help"]).output().unwrap();
    assert!(out.status.success(), "{command} --help");
    String::from_utf8(out.stdout).unwrap()
}

#[test]
fn help_names_every_method_and_model() {
    let solve = help("solve");
    for m in Case::METHODS {
        assert!(solve.contains(m), "solve --help omits {m}: {solve}");
    }
    let traction = help("traction");
    for m in TractionModel::ALL {
        assert!(
            traction.contains(m.as_str()),
            "traction --help omits {}",
            m.as_str()
        );
    }
    let friction = help("friction");
    for m in PressureModel::ALL {
        assert!(
            friction.contains(m.as_str()),
            "friction --help omits {}",
            m.as_str()
        );
    }
}

/// docs/sweep.md's console block states the rows and columns of its example's results:
/// they are the program's.
#[test]
fn sweep_doc_counts_the_columns_the_program_writes() {
    let root = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../..");
    let doc = std::fs::read_to_string(root.join("docs/sweep.md")).unwrap();
    let line = doc
        .lines()
        .find(|l| l.starts_with("Results: hertz-load/results.parquet"))
        .unwrap();
    let out = support::tempdir("help", "sweep");
    let v = run_json(&[
        "sweep",
        root.join("examples/sweeps/hertz_load.toml")
            .to_str()
            .unwrap(),
        "--out",
        out.join("hertz-load").to_str().unwrap(),
    ]);
    let expect = format!(
        "({} rows, {} columns)",
        v["cases"],
        v["columns"].as_array().unwrap().len()
    );
    assert!(
        line.ends_with(&expect),
        "docs/sweep.md says `{line}`, the program {expect}"
    );
}
