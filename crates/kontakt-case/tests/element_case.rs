//! Element cases (`method = "element"`): the roller/rib and surfaces geometries build the
//! same element as the library's own constructors (same evaluation, bit for bit), the
//! defaults (steel, Coulomb 0.1, dry, no damping, 1 %), the friction keys of the friction
//! cases, and errors named by case-file keys — including every number of the element case
//! files in `crates/kontakt-capi/examples/` mutated to invalid values.

#![allow(clippy::unwrap_used)] // tests: a panic is a failure with its message

use kontakt::bearing::{RollerRib, RollerRibSpec};
use kontakt::element::{Backend, ContactElement, ContactStatus, ElementSpec};
use kontakt::geometry::{Material, PlacedSurface, Surface, Twist};
use kontakt::hertz::{HertzPointContact, PointGeometry};
use kontakt::material::ElasticMaterial;
use kontakt::pimp::PimpOptions;
use kontakt_case::element_case::{ElementCase, element_from_case, element_from_toml};
use nalgebra::{Isometry3, Translation3, UnitQuaternion};
use std::path::PathBuf;
use toml::Value;

#[path = "support/toml_keys.rs"]
mod toml_keys;
use toml_keys::{leaves, names_a_key, set};

const ROLLER_RIB: &str = r#"
method = "element"
[geometry]
kind = "roller_rib"
pairing = "torus-torus-14"
[element]
backend = "pimp"
"#;

const BALL: &str = r#"
method = "element"
[geometry]
kind = "surfaces"
[geometry.body1]
shape = "sphere"
radius_mm = 10.0
[geometry.body2]
shape = "plane"
[element]
backend = "hertz"
"#;

fn field_of(text: &str) -> String {
    match element_from_toml(text) {
        Ok(_) => panic!("accepted:\n{text}"),
        Err(e) => {
            println!("{e}");
            e.field().unwrap_or("").to_string()
        }
    }
}

/// The roller/rib case builds the element of `RollerRib`'s face and rib (body frames =
/// the bearing frame): pressed 4 µm along the contact normal, both give the same result.
#[test]
fn roller_rib_case_is_the_library_pairing() {
    let rr = RollerRib::new(RollerRibSpec::builtin("torus-torus-14").unwrap()).unwrap();
    let mut spec = ElementSpec::new(rr.face.clone(), rr.rib.clone()).unwrap();
    spec.backend = Backend::Pimp(PimpOptions::default());
    let mut direct = ContactElement::new(spec.clone()).unwrap();
    let case = ElementCase::from_toml_str(ROLLER_RIB).unwrap();
    assert_eq!(case.spec().unwrap(), spec);
    let mut from_case = element_from_case(&case).unwrap();
    let n = rr.contact.normal.into_inner();
    let pose1 = Isometry3::from_parts(Translation3::from(-n * 0.004), UnitQuaternion::identity());
    let id = Isometry3::identity();
    let z = Twist::zero();
    let a = direct.evaluate(&pose1, &id, &z, &z).unwrap();
    let b = from_case.evaluate(&pose1, &id, &z, &z).unwrap();
    assert_eq!(a, b);
    assert_eq!(b.status, ContactStatus::Contact);
    assert!((b.approach - 0.004).abs() < 1e-9);
}

/// Surfaces in their bodies' frames; the defaults: steel, Hertz at the contact point,
/// Coulomb μ = 0.1, dry, no damping, validity 1 %. The force is Hertz's closed form.
#[test]
fn surfaces_case_and_defaults() {
    let case = ElementCase::from_toml_str(BALL).unwrap();
    let spec = case.spec().unwrap();
    let expected = ElementSpec::new(
        PlacedSurface::new(
            Surface::sphere(10.0, Material::Inside).unwrap(),
            Isometry3::identity(),
        )
        .unwrap(),
        PlacedSurface::new(Surface::plane(Material::Inside), Isometry3::identity()).unwrap(),
    )
    .unwrap();
    assert_eq!(spec, expected);
    let mut e = element_from_case(&case).unwrap();
    let r = e
        .evaluate(
            &Isometry3::translation(0.0, 0.0, 10.0 - 0.005),
            &Isometry3::identity(),
            &Twist::zero(),
            &Twist::zero(),
        )
        .unwrap();
    let steel = ElasticMaterial::STEEL;
    let f = HertzPointContact::new(PointGeometry::sphere_on_flat(10.0).unwrap(), steel, steel)
        .unwrap()
        .force_from_approach(0.005)
        .unwrap();
    assert!((r.normal_force - f).abs() < 1e-9 * f);
}

/// The optional tables reach the spec: materials, friction keys (as the friction cases
/// read them), film, damping, cells, mode and the validity limit.
#[test]
fn optional_tables_reach_the_spec() {
    let text = format!(
        "{BALL}cells = [32, 48]\nmax_approach_ratio = 0.02\n\
         [body1]\ne_mpa = 300000.0\nnu = 0.26\n\
         [friction]\npreset = \"mixed\"\nmu = 0.12\n\
         [film]\nthickness_mm = 0.0002\nlambda = 1.5\nviscosity_mpa_s = 2e-8\nalpha_per_mpa = 0.02\n\
         [damping]\ncoefficient_n_s_per_mm = 2.0\nramp_mm = 0.001\n"
    )
    .replace("backend = \"hertz\"", "backend = \"halfspace\"");
    let spec = ElementCase::from_toml_str(&text).unwrap().spec().unwrap();
    assert_eq!(
        spec.material1,
        ElasticMaterial::new(300000.0, 0.26).unwrap()
    );
    assert_eq!(spec.material2, ElasticMaterial::STEEL);
    match spec.backend {
        Backend::HalfSpace(o) => assert_eq!(o.cells, [32, 48]),
        other => panic!("{other:?}"),
    }
    assert_eq!(spec.max_approach_ratio, 0.02);
    assert_eq!(spec.friction.boundary_coefficient, 0.12);
    assert_eq!(spec.film.lambda, 1.5);
    let d = spec.damping.unwrap();
    assert_eq!((d.coefficient, d.ramp), (2.0, 0.001));
    ContactElement::new(spec).unwrap();
}

/// Bad input: each error names its case-file key.
#[test]
fn errors_name_case_keys() {
    let cases: Vec<(String, &str)> = vec![
        (BALL.replace("\"element\"", "\"pimp\""), "method"),
        (BALL.replace("\"hertz\"", "\"fem\""), "element.backend"),
        (format!("{BALL}colour = 1\n"), "element.colour"),
        (format!("{BALL}cells = [64, 64]\n"), "element.cells"),
        // A key of another shape (a cone's half-angle on the sphere) is refused.
        (
            BALL.replace("radius_mm = 10.0", "radius_mm = 10.0\nhalf_angle_deg = 5.0"),
            "geometry.body1.half_angle_deg",
        ),
        (
            BALL.replace("shape = \"plane\"", "shape = \"plane\"\nminor_mm = 1.0"),
            "geometry.body2.minor_mm",
        ),
        (format!("{BALL}mode = \"published\"\n"), "element.mode"),
        (
            format!("{BALL}max_approach_ratio = -1.0\n"),
            "element.max_approach_ratio",
        ),
        (
            ROLLER_RIB.replace("backend = \"pimp\"", "backend = \"pimp\"\ncells = [4, 64]"),
            "element.cells[0]",
        ),
        (
            ROLLER_RIB.replace("torus-torus-14", "torus-torus-99"),
            "geometry.pairing",
        ),
        (
            BALL.replace("radius_mm = 10.0", "radius_mm = -1.0"),
            "geometry.body1.radius_mm",
        ),
        (
            BALL.replace(
                "kind = \"surfaces\"",
                "kind = \"surfaces\"\nguess_mm = [0.0, 0.0, 0.0]",
            ),
            "geometry.guess_mm",
        ),
        (
            "method = \"element\"\n[geometry]\nkind = \"hertz\"\nradii1_mm = [1.0, 1.0]\n\
             radii2_mm = [1.0, 1.0]\n[element]\nbackend = \"hertz\"\n"
                .to_string(),
            "geometry.kind",
        ),
        (
            format!("{BALL}[body2]\ne_mpa = 1.0\nnu = 0.7\n"),
            "body2.nu",
        ),
        (format!("{BALL}[friction]\nmu = 2.0\n"), "friction.mu"),
        (
            format!(
                "{BALL}[film]\nthickness_mm = 0.0\nlambda = 0.0\nviscosity_mpa_s = 0.0\n\
                 alpha_per_mpa = 0.0\n"
            ),
            "film.viscosity_mpa_s",
        ),
        (
            format!("{BALL}[damping]\ncoefficient_n_s_per_mm = -1.0\nramp_mm = 0.001\n"),
            "damping.coefficient_n_s_per_mm",
        ),
        (
            format!("{BALL}[damping]\ncoefficient_n_s_per_mm = 1.0\nramp_mm = 0.0\n"),
            "damping.ramp_mm",
        ),
    ];
    for (text, key) in cases {
        assert_eq!(field_of(&text), key, "{text}");
    }
}

fn capi_examples() -> Vec<PathBuf> {
    let files = toml_keys::toml_files(
        &PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../kontakt-capi/examples"),
    );
    assert!(!files.is_empty());
    files
}

/// The element case files parse and plan; every number in them set to an invalid value
/// (NaN, −1, 0, 1e300 for floats; 0 and 100000 for integers) is either accepted or
/// refused with an error naming a key that exists in that file.
#[test]
fn example_files_and_mutated_keys() {
    for file in capi_examples() {
        let text = std::fs::read_to_string(&file).unwrap();
        element_from_toml(&text).unwrap_or_else(|e| panic!("{}: {e}", file.display()));
        let doc: Value = toml::from_str(&text).unwrap();
        let mut paths = Vec::new();
        leaves(&doc, &mut Vec::new(), &mut paths);
        assert!(!paths.is_empty());
        for path in paths {
            let original = {
                let mut v = &doc;
                for p in &path {
                    v = match p.strip_prefix('[') {
                        Some(i) => &v.as_array().unwrap()
                            [i.trim_end_matches(']').parse::<usize>().unwrap()],
                        None => &v.as_table().unwrap()[p],
                    };
                }
                v.clone()
            };
            let bad: Vec<Value> = match original {
                Value::Integer(_) => vec![Value::Integer(0), Value::Integer(100_000)],
                _ => vec![
                    Value::Float(f64::NAN),
                    Value::Float(-1.0),
                    Value::Float(0.0),
                    Value::Float(1e300),
                ],
            };
            for new in bad {
                let mut m = doc.clone();
                set(&mut m, &path, new.clone());
                let mutated = toml::to_string(&m).unwrap();
                let Err(e) = element_from_toml(&mutated) else {
                    continue;
                };
                for key in e.field().into_iter().flat_map(|f| f.split(", ")) {
                    assert!(
                        key == "case" || names_a_key(&m, key),
                        "{}: {} = {new}: error names `{key}`, not a key of the file: {e}",
                        file.display(),
                        path.join(".")
                    );
                }
            }
        }
    }
}
