#![allow(clippy::unwrap_used)] // test helpers: a panic is a test failure with its message
//! Your own roller end/rib pairing in a case file (issue 30 item 14): the rib given by its
//! angle, `[geometry.face]`, `[geometry.rib]` and `[geometry.bearing]`.

use kontakt_case::{Case, Outcome};
use std::path::Path;

const CASE: &str = r#"method = "pimp"
[geometry]
kind = "roller_rib"
pairing = "sphere-torus-57"
[pimp]
cells = [48, 48]
[body1]
e_mpa = 210000.0
nu = 0.3
[body2]
e_mpa = 210000.0
nu = 0.3
[load]
force_n = 250.0
"#;

fn run(text: &str) -> kontakt::Result<kontakt_case::pimp_case::PimpReport> {
    match Case::from_toml_str(text)?.run(Path::new("."))? {
        Outcome::Pimp(o) => Ok(o.report),
        other => panic!("not a PimP outcome: {other:?}"),
    }
}

/// The rib angle the 2.75 mm construction builds (its report's `rib_angle_deg`), given as
/// `rib_angle_deg`, gives the same report to 1e-9; with an explicit face and rib table as
/// well; both `contact_height_mm` and `rib_angle_deg` is an error naming the key; an angle
/// that puts the contact below the roller axis names `geometry.rib_angle_deg`.
#[test]
fn rib_angle_key_reproduces_the_height() {
    let base = run(CASE).unwrap();
    let alpha = base.rib_angle_deg.unwrap();
    let by_angle = run(&CASE.replace(
        "pairing = \"sphere-torus-57\"",
        &format!("pairing = \"sphere-torus-57\"\nrib_angle_deg = {alpha:?}"),
    ))
    .unwrap();
    let explicit = run(&CASE.replace(
        "pairing = \"sphere-torus-57\"",
        &format!(
            "rib_angle_deg = {alpha:?}\nface = {{ shape = \"sphere\", radius_mm = 57.0 }}\n\
             rib = {{ shape = \"torus\", radius_mm = 30.0 }}"
        ),
    ))
    .unwrap();
    for r in [&by_angle, &explicit] {
        assert!((r.max_pressure_mpa / base.max_pressure_mpa - 1.0).abs() < 1e-9);
        assert!((r.contact_area_mm2 / base.contact_area_mm2 - 1.0).abs() < 1e-9);
        assert!((r.rib_angle_deg.unwrap() - alpha).abs() < 1e-9);
    }
    let e = run(&CASE.replace(
        "pairing = \"sphere-torus-57\"",
        "pairing = \"sphere-torus-57\"\nrib_angle_deg = 90.0\ncontact_height_mm = 2.0",
    ))
    .unwrap_err();
    assert_eq!(e.field(), Some("geometry.rib_angle_deg"), "{e}");
    let e = run(&CASE.replace(
        "pairing = \"sphere-torus-57\"",
        "pairing = \"sphere-torus-57\"\nrib_angle_deg = 80.0",
    ))
    .unwrap_err();
    assert_eq!(e.field(), Some("geometry.rib_angle_deg"), "{e}");
}

/// `[geometry.bearing]`'s bore and outside diameter check that the roller fits the section:
/// an outside diameter inside the roller's cup-side edge is refused.
#[test]
fn outside_diameter_checks_that_the_roller_fits() {
    let bearing = "[geometry.bearing]\nbore_mm = 60.0\nouter\nroller_half_angle_deg = 3.0\n\
                   roller_large_end_radius_mm = 5.5\ninner_raceway_radius_mm = 35.0\n";
    let with = |d: f64| {
        CASE.replace(
            "[pimp]",
            &format!(
                "{}[pimp]",
                bearing.replace("outer", &format!("outside_diameter_mm = {d:?}"))
            ),
        )
    };
    assert!(run(&with(110.0)).is_ok());
    let e = run(&with(80.0)).unwrap_err();
    assert!(
        e.to_string()
            .contains("the roller must fit inside the outside diameter"),
        "{e}"
    );
}
