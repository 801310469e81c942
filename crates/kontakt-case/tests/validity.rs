//! The one validity check of every method (issue 30 item 3): a contact as large as a body's
//! radius of curvature is refused naming the case key, one between 0.4 and 1 of it
//! carries a warning, in every method that produces a contact, through `Case::run` and
//! through the method's own public runner (what the CLI subcommands and the Python
//! package call).

#![allow(clippy::unwrap_used)] // tests: a panic is a failure with its message

use kontakt_case::validity::Checked;
use kontakt_case::{Case, Outcome};
use std::path::{Path, PathBuf};
use toml::Value;

#[path = "support/toml_keys.rs"]
#[allow(dead_code)] // only the examples' listing is used here
mod toml_keys;
use toml_keys::example_files;

fn examples() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../../examples")
}

/// The example `file` with the dotted keys of `edits` set.
fn edited(file: &str, edits: &[(&str, Value)]) -> toml::Table {
    let text = std::fs::read_to_string(examples().join(file)).unwrap();
    let mut table: toml::Table = toml::from_str(&text).unwrap();
    for (path, value) in edits {
        let mut t = &mut table;
        let parts: Vec<&str> = path.split('.').collect();
        for p in &parts[..parts.len() - 1] {
            t = t.get_mut(*p).unwrap().as_table_mut().unwrap();
        }
        t.insert(parts[parts.len() - 1].to_string(), value.clone());
    }
    table
}

/// One method's case: the example, the edits that make it one of that model, the key
/// that carries the load, a load in the warning band, a load beyond the limit, the key a
/// refusal must name and the text its warning must hold.
struct Row {
    method: &'static str,
    file: &'static str,
    edits: Vec<(&'static str, Value)>,
    load_key: &'static str,
    warn: f64,
    refuse: f64,
    key: &'static str,
    warning: &'static str,
}

fn models(m: &str) -> (&'static str, Value) {
    ("models", Value::Array(vec![Value::String(m.into())]))
}

fn rows() -> Vec<Row> {
    let friction = |m: &str| Row {
        method: "friction",
        file: "rib_friction.toml",
        edits: vec![
            models(m),
            ("speed.points", Value::Integer(2)),
            ("speed.max_rpm", Value::Float(500.0)),
        ],
        load_key: "load.axial_n",
        warn: 6e6,
        refuse: 1e8,
        key: "geometry.bearing.roller_large_end_radius_mm",
        warning: "rib contact at the largest rib load",
    };
    let traction = |m: &str| Row {
        method: "traction",
        file: "traction_twin_disc.toml",
        edits: vec![models(m), ("creepage.points", Value::Integer(5))],
        load_key: "load.force_n",
        warn: 1e8,
        refuse: 1e9,
        key: "geometry.radii1_mm",
        warning: "contact size",
    };
    vec![
        Row {
            method: "hertz",
            file: "ball_on_flat.toml",
            edits: vec![],
            load_key: "load.force_n",
            warn: 1e6,
            refuse: 1e8,
            key: "body1.radii_mm",
            warning: "contact size",
        },
        Row {
            method: "pimp",
            file: "pimp_sphere_on_torus.toml",
            edits: vec![],
            load_key: "load.force_n",
            warn: 1e7,
            refuse: 1e9,
            key: "geometry.body2",
            warning: "contact size",
        },
        traction("carter"),
        traction("kalker_linear"),
        traction("fastsim"),
        Row {
            method: "traction",
            file: "traction_twin_disc.toml",
            edits: vec![
                models("carter"),
                ("creepage.points", Value::Integer(5)),
                (
                    "geometry",
                    Value::Table(
                        toml::from_str("kind = \"line\"\nradii_mm = [10.0, inf]\nlength_mm = 10.0")
                            .unwrap(),
                    ),
                ),
            ],
            load_key: "load.force_n",
            warn: 3e6,
            refuse: 1e8,
            key: "geometry.radii_mm[0]",
            warning: "contact size",
        },
        Row {
            method: "mindlin",
            file: "mindlin_fretting.toml",
            edits: vec![],
            load_key: "load.force_n",
            warn: 1e6,
            refuse: 1e8,
            key: "geometry.radii1_mm",
            warning: "contact size",
        },
        Row {
            method: "impact",
            file: "impact_oblique.toml",
            edits: vec![],
            load_key: "impact.speed_mm_per_s",
            warn: 1e6,
            refuse: 1e7,
            key: "sphere.radius_mm",
            warning: "impact, at the largest approach: contact size",
        },
        friction("hertz"),
        friction("pimp"),
        friction("halfspace"),
    ]
}

/// The case of `row` at `load`, run by `Case::run` and by the method's public runner; both
/// must agree.
fn run(row: &Row, load: f64) -> kontakt::Result<Outcome> {
    let mut edits = row.edits.clone();
    edits.push((row.load_key, Value::Float(load)));
    let case = Case::from_toml_table(edits_table(row.file, &edits)).unwrap();
    assert_eq!(case.method(), row.method);
    let by_case = case.run(&examples());
    let by_runner = public_runner(&case);
    assert_eq!(
        by_case
            .as_ref()
            .map(|o| o.warnings().to_vec())
            .map_err(|e| e.to_string()),
        by_runner.map_err(|e| e.to_string()),
        "{} at {load}: Case::run and the public runner differ",
        row.method
    );
    by_case
}

fn edits_table(file: &str, edits: &[(&str, Value)]) -> toml::Table {
    edited(file, edits)
}

/// The warnings of the method's own public runner (the CLI subcommands call these).
fn public_runner(case: &Case) -> kontakt::Result<Vec<String>> {
    use kontakt_case::*;
    Ok(match case {
        Case::Hertz(c) => run_case(c)?.warnings,
        Case::Pimp(c) => run_pimp_case(c)?.report.warnings,
        Case::Bem(c) => run_bem_case(c, &examples())?.report.warnings,
        Case::Traction(c) => run_traction_case(c)?.warnings,
        Case::Friction(c) => run_friction_case(c)?.report.warnings,
        Case::Mindlin(c) => run_mindlin_case(c)?.warnings,
        Case::Impact(c) => run_impact_case(c)?.warnings,
        Case::Rough(c) => {
            run_rough_case(c, &examples())?;
            Vec::new()
        }
        Case::Bearing(c) => kontakt_case::run_bearing_case(c)?.warnings,
    })
}

#[test]
fn every_method_warns_and_refuses_an_oversize_contact() {
    for row in rows() {
        let label = format!("{} {:?}", row.method, row.edits.first().map(|e| &e.1));
        let ok = run(&row, row.warn);
        assert!(ok.is_ok(), "{label} at {}: {ok:?}", row.warn);
        let ok = ok.unwrap();
        assert!(
            ok.warnings().iter().any(|w| w.starts_with(row.warning)),
            "{label} at {}: no size warning in {:?}",
            row.warn,
            ok.warnings()
        );
        let e = run(&row, row.refuse).map(|_| ()).unwrap_err();
        assert_eq!(e.field(), Some(row.key), "{label}: {e}");
        assert!(!e.to_string().contains('\n'), "{e}");
    }
}

/// Every method's example goes through the check: the runners that produce a contact
/// record it (a model that recorded none would skip the size check), and `Case::run` is
/// where the check is applied. Only a periodic rough surface (no curvature) and a
/// contact given without the bodies' radii (a gap map) have none.
#[test]
fn every_outcome_variant_records_its_contacts() {
    let mut seen = std::collections::BTreeSet::new();
    let files = example_files();
    for file in files {
        let text = std::fs::read_to_string(&file).unwrap();
        let case = Case::from_toml_str(&text).unwrap();
        let outcome = case.run(Path::new(&examples())).unwrap();
        seen.insert(case.method());
        let contacts = outcome.contacts().len();
        // a periodic rough surface sizes no contact (a ball bearing sizes the Hertz
        // contacts of its most loaded ball, a roller bearing the Hertz line contacts of its
        // most loaded roller's most loaded slices)
        let without = case.method() == "rough" || text.contains("kind = \"map\"");
        assert_eq!(
            contacts == 0,
            without,
            "{}: {contacts} contacts recorded",
            file.display()
        );
        for c in outcome.contacts() {
            assert!(
                c.ratio() > 0.0 && c.ratio() < 0.4,
                "{}: {c:?}",
                file.display()
            );
        }
    }
    // Every method has an example, so every Outcome variant was run through the check.
    assert_eq!(
        seen.into_iter().collect::<Vec<_>>(),
        [
            "bearing", "bem", "friction", "hertz", "impact", "mindlin", "pimp", "rough", "traction"
        ]
    );
}

/// Issue 30 item 4: `kontakt mindlin` runs `run_mindlin_case`, which goes through the
/// same check as `Case::run`: mu = 1e300 overflows the closed form and is refused naming
/// the report key (it printed "inf N mm" and wrote null). The loop area agrees with the
/// closed form (Mindlin and Deresiewicz 1953) to the trapezoidal rule's 0.07 % at 41
/// points, over the accepted range of Q*/(mu P) down to 1e-8 and at mu = 1e150; below
/// 1e-8 (mu = 1e150 with Q* = 20 N: 1e-18 N mm of rounding noise against 6e-154) the
/// amplitude is refused with its range.
#[test]
fn mindlin_report_is_finite_and_its_loop_area_matches_the_closed_form() {
    let case = |mu: f64, q: f64| {
        let t = edited(
            "mindlin_fretting.toml",
            &[
                ("friction.mu", Value::Float(mu)),
                ("tangential.amplitude_n", Value::Float(q)),
            ],
        );
        let Case::Mindlin(c) = Case::from_toml_table(t).unwrap() else {
            panic!("not a mindlin case")
        };
        kontakt_case::run_mindlin_case(&c)
    };
    let e = case(1e300, 1e301).unwrap_err();
    assert!(e.to_string().contains("inf"), "{e}");
    assert_eq!(e.field(), Some("dissipated_energy_per_cycle_nmm"), "{e}");
    for (mu, q) in [
        (0.3, 20.0),
        (0.3, 30.0 * 1e-8),
        (1e150, 1e151),
        (1e150, 1e144),
    ] {
        let r = case(mu, q).unwrap();
        let rel = r.loop_energy_nmm / r.dissipated_energy_per_cycle_nmm - 1.0;
        assert!(rel.abs() < 7e-4, "mu {mu}, Q* {q}: {rel:e}");
    }
    let e = case(1e150, 20.0).unwrap_err();
    assert_eq!(e.field(), Some("tangential.amplitude_n"), "{e}");
    assert!(e.to_string().contains("1e-8 mu P"), "{e}");
}

/// Issue 30 item 12: finite but absurd inputs that the field solvers iterated on until
/// "did not converge (residual NaN/inf)" (exit status 1) are input errors naming the key
/// and the range (exit status 2): the half-space solver's scales (modulus, cell size,
/// pressure and displacement scale within 1e-100..1e100) and a PimP or half-space load
/// whose Hertz approach the gap of the placed surfaces cannot resolve.
#[test]
fn absurd_inputs_of_the_field_solvers_are_input_errors() {
    for (file, key, value, named) in [
        (
            "bem_wavy_map.toml",
            "body1.e_mpa",
            1e-300,
            "body1.e_mpa, body2.e_mpa",
        ),
        ("bem_wavy_map.toml", "load.force_n", 1e300, "load.force_n"),
        (
            "bem_wavy_map.toml",
            "geometry.spacing_mm",
            1e-300,
            "geometry.spacing_mm[0]",
        ),
        (
            "pimp_sphere_on_torus.toml",
            "load.force_n",
            1e-30,
            "load.force_n",
        ),
        (
            "roller_rib_torus_torus.toml",
            "load.force_n",
            1e-150,
            "load.force_n",
        ),
        (
            "bem_torus_torus.toml",
            "load.force_n",
            1e-150,
            "load.force_n",
        ),
        ("rough_self_affine.toml", "surface.size_mm", 1e-300, ""),
    ] {
        let v = if key.ends_with("spacing_mm") || key.ends_with("size_mm") {
            Value::Array(vec![Value::Float(value), Value::Float(value)])
        } else {
            Value::Float(value)
        };
        let case = Case::from_toml_table(edited(file, &[(key, v)])).unwrap();
        let e = case.run(&examples()).map(|_| ()).unwrap_err();
        assert!(
            matches!(e, kontakt::Error::InvalidInput { .. }),
            "{file} {key} = {value:e}: {e}"
        );
        if !named.is_empty() {
            assert_eq!(e.field(), Some(named), "{e}");
        }
    }
}
