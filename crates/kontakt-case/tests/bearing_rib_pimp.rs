//! `[bearing.rib_contact] model = "pimp"` (docs/bearing-model.md §15.7): the case runs the
//! library's PimP rib law, reports it and its pressure; the key passes the unknown-key
//! check and bad input is named by its case key.

#![allow(clippy::unwrap_used)] // tests: a panic is a failure with its message

use kontakt_bearing::equilibrium::RingLoad;
use kontakt_bearing::geometry::RollerBearing;
use kontakt_bearing::roller_equilibrium::{RibContact, RibContactSolver, RibModel, RibTableRange};
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

/// The combined-load rib-contact example with the pairing `pairing` and `extra` lines in
/// `[bearing.rib_contact]`.
fn case(pairing: &str, extra: &str) -> String {
    let text = std::fs::read_to_string(examples().join("bearing_rib_contact_60mm.toml")).unwrap();
    text.replace(
        "pairing = \"sphere-torus-57\"\n",
        &format!("pairing = \"{pairing}\"\n{extra}"),
    )
    .replace("rib_angle_deg = 109.716252089\n", "")
}

/// With torus-cone-28 (a pair far from Hertz's ellipse) the report's rib pressure is the
/// library's PimP balance's, about 36 % above Hertz's; the rib loads barely change; the
/// report names the model.
#[test]
fn the_pimp_rib_model_is_run_and_reported() {
    let hertz = run(&case("torus-cone-28", "")).unwrap();
    let pimp = run(&case("torus-cone-28", "model = \"pimp\"\n")).unwrap();
    let explicit = run(&case("torus-cone-28", "model = \"hertz\"\n")).unwrap();
    let (h, p) = (hertz.rollers().unwrap(), pimp.rollers().unwrap());
    assert_eq!(h.rib_model, Some("hertz"));
    assert_eq!(p.rib_model, Some("pimp"));
    assert_eq!(
        explicit.rollers().unwrap().max_rib_pressure_mpa,
        h.max_rib_pressure_mpa
    );
    // the library's PimP balance of the same bearing and load
    let spec = kontakt::bearing::RollerRibSpec::builtin("torus-cone-28").unwrap();
    let mut b = RollerBearing::tapered(
        74.141904,
        17,
        10.161476,
        16.0,
        25.481595648_f64.to_radians(),
        19.481595648_f64.to_radians(),
    );
    b.slices = 31;
    let mut s = RibContactSolver::new(
        b,
        RibContact {
            face: spec.face,
            rib: spec.rib,
            contact_height_mm: spec.contact_height,
        },
    )
    .unwrap();
    s.set_rib_model(RibModel::Pimp, &RibTableRange::default())
        .unwrap();
    s.solve(&RingLoad::forces([6000.0, 0.0, 15000.0, 0.0, 0.0]).with_tilts_held())
        .unwrap();
    let want = s.max_rib_pressure_mpa();
    let got = p.max_rib_pressure_mpa.unwrap();
    assert!((got / want - 1.0).abs() < 1e-9, "{got} vs {want}");
    let ratio = got / h.max_rib_pressure_mpa.unwrap();
    assert!(
        ratio > 1.3 && ratio < 1.45,
        "PimP/Hertz rib pressure {ratio}"
    );
    for (a, c) in h.roller_loads.iter().zip(&p.roller_loads) {
        assert!((a.rib_load_n / c.rib_load_n - 1.0).abs() < 1e-3);
        assert!(c.rib_max_pressure_mpa.unwrap() > a.rib_max_pressure_mpa.unwrap());
    }
}

/// Bad input, one error naming the case key.
#[test]
fn a_bad_rib_model_is_named_by_its_case_key() {
    let e = run(&case("sphere-torus-57", "model = \"fem\"\n"))
        .unwrap_err()
        .to_string();
    assert!(e.contains("bearing.rib_contact.model"), "{e}");
    assert!(e.contains("hertz") && e.contains("pimp"), "{e}");
    // a cylindrical bearing's ribs are Hertz's only
    let crb = std::fs::read_to_string(examples().join("bearing_nj_crb_rib_contact.toml")).unwrap();
    let crb = crb.replace(
        "[bearing.rib_contact]\n",
        "[bearing.rib_contact]\nmodel = \"pimp\"\n",
    );
    let e = run(&crb).unwrap_err().to_string();
    assert!(
        e.starts_with("invalid bearing.rib_contact.model = pimp"),
        "{e}"
    );
    assert!(run(&crb.replace("model = \"pimp\"", "model = \"hertz\"")).is_ok());
}
