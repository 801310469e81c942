//! Unknown keys are errors in every table of every schema (issue 30, items 2 and 9).
//!
//! serde's `deny_unknown_fields` misses some tables (a unit variant of an internally tagged
//! enum took `[geometry.rib] shape = "cone"` with any other keys), and inside a tagged table
//! its errors lost the table's path (`geometry.eccentricty_mm` for
//! `geometry.face.eccentricty_mm`). This test walks every table of every example case file,
//! the sweep files, the C API's element cases and one case for every variant of every tagged
//! table, puts an unknown key into it and requires an error naming the full key path.

#![allow(clippy::unwrap_used)] // tests: a panic is a failure with its message

use kontakt::Error;
use kontakt_case::{Case, ElementCase, Sweep};
use std::path::{Path, PathBuf};
use toml::{Table, Value};

fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../..")
}

fn read(path: &Path) -> Table {
    toml::from_str(&std::fs::read_to_string(path).unwrap()).unwrap()
}

/// `doc` with the table at `path` (dotted, no arrays) replaced by the TOML `snippet`.
fn with(doc: &Table, path: &str, snippet: &str) -> Table {
    let mut doc = doc.clone();
    let (parent, last) = path.rsplit_once('.').unwrap_or(("", path));
    let mut t = &mut doc;
    for k in parent.split('.').filter(|k| !k.is_empty()) {
        t = t.get_mut(k).unwrap().as_table_mut().unwrap();
    }
    t.insert(last.into(), Value::Table(toml::from_str(snippet).unwrap()));
    doc
}

/// Every table's path in `v` (`geometry.face`, `parameter[1]`), the root as "".
fn tables(v: &Value, path: String, out: &mut Vec<String>) {
    match v {
        Value::Table(t) => {
            out.push(path.clone());
            for (k, x) in t {
                let p = if path.is_empty() {
                    k.clone()
                } else {
                    format!("{path}.{k}")
                };
                tables(x, p, out);
            }
        }
        Value::Array(a) => {
            for (i, x) in a.iter().enumerate() {
                tables(x, format!("{path}[{i}]"), out);
            }
        }
        _ => {}
    }
}

/// The table at `path` as [`tables`] spells it.
fn table_at<'a>(doc: &'a mut Table, path: &str) -> &'a mut Table {
    let mut v = doc;
    for step in path.split('.').filter(|s| !s.is_empty()) {
        let (key, index) = match step.split_once('[') {
            Some((k, i)) => (k, Some(i.trim_end_matches(']').parse::<usize>().unwrap())),
            None => (step, None),
        };
        let x = v.get_mut(key).unwrap();
        v = match index {
            Some(i) => x.as_array_mut().unwrap()[i].as_table_mut().unwrap(),
            None => x.as_table_mut().unwrap(),
        };
    }
    v
}

#[derive(Clone, Copy)]
enum Schema {
    Case,
    Element,
    Sweep,
}

/// The reader's error on `text` as (key, message); `None` when it reads.
fn reader_error(schema: Schema, text: &str, dir: &Path) -> Option<(String, String)> {
    let err = match schema {
        Schema::Case => Case::from_toml_str(text).err(),
        Schema::Element => ElementCase::from_toml_str(text).err(),
        Schema::Sweep => {
            return Sweep::from_toml_str(text, dir)
                .err()
                .map(|e| (String::new(), e.to_string()));
        }
    }?;
    match err {
        Error::CaseFile { key, message, .. } => Some((key.into_owned(), message)),
        other => Some((String::new(), other.to_string())),
    }
}

/// Every table of `doc`, given an unknown key, is refused with its full path; `doc`
/// itself reads. Returns the number of tables tried.
fn check(label: &str, schema: Schema, doc: &Table, dir: &Path, wrong: &mut Vec<String>) -> usize {
    let text = toml::to_string(doc).unwrap();
    if let Some((_, m)) = reader_error(schema, &text, dir) {
        wrong.push(format!("{label}: does not read: {m}"));
        return 0;
    }
    let mut paths = Vec::new();
    tables(&Value::Table(doc.clone()), String::new(), &mut paths);
    for path in &paths {
        let mut bad = doc.clone();
        table_at(&mut bad, path).insert("typo_key".into(), Value::Integer(5));
        let full = if path.is_empty() {
            "typo_key".to_string()
        } else {
            format!("{path}.typo_key")
        };
        let text = toml::to_string(&bad).unwrap();
        match reader_error(schema, &text, dir) {
            None => wrong.push(format!("{label}: `{full}` accepted")),
            Some((key, m)) => {
                let named = match schema {
                    Schema::Sweep => {
                        m.contains(&format!("`{full}`"))
                            || m.contains(&format!("`{}`", full.trim_start_matches("base.")))
                    }
                    _ => key == full && m.contains(&format!("unknown key `{full}`")),
                };
                if !named {
                    wrong.push(format!("{label}: `{full}`: key `{key}`: {m}"));
                }
            }
        }
    }
    paths.len()
}

#[test]
fn every_table_refuses_an_unknown_key_with_its_full_path() {
    let examples = root().join("examples");
    let mut wrong = Vec::new();
    let mut tried = 0;
    let mut files: Vec<PathBuf> = std::fs::read_dir(&examples)
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|x| x == "toml"))
        .collect();
    files.sort();
    assert!(files.len() >= 16, "{files:?}");
    for file in &files {
        let label = file.file_name().unwrap().to_string_lossy().to_string();
        tried += check(&label, Schema::Case, &read(file), &examples, &mut wrong);
    }
    for name in ["hertz_load.toml", "pimp_roller_rib.toml"] {
        let dir = examples.join("sweeps");
        let doc = read(&dir.join(name));
        tried += check(name, Schema::Sweep, &doc, &dir, &mut wrong);
        // An inline base case: its tables too.
        let mut inline = doc.clone();
        let base = inline["base"].as_str().unwrap().to_string();
        inline.insert("base".into(), Value::Table(read(&dir.join(base))));
        tried += check(
            &format!("{name} inline"),
            Schema::Sweep,
            &inline,
            &dir,
            &mut wrong,
        );
    }
    for name in ["element_ball_on_flat.toml", "element_roller_rib.toml"] {
        let file = root().join("crates/kontakt-capi/examples").join(name);
        tried += check(name, Schema::Element, &read(&file), &examples, &mut wrong);
    }

    // Every variant of every tagged table.
    let pimp = read(&examples.join("pimp_sphere_on_torus.toml"));
    let face_rib = [
        ("sphere", "radius_mm = 57.0", "cone", ""),
        (
            "torus",
            "radius_mm = 14.0\neccentricity_mm = 2.0",
            "torus",
            "radius_mm = 30.0",
        ),
    ];
    for (face, face_keys, rib, rib_keys) in face_rib {
        let geometry = format!(
            "kind = \"roller_rib\"\ncontact_height_mm = 2.75\n\
             [face]\nshape = \"{face}\"\n{face_keys}\n[rib]\nshape = \"{rib}\"\n{rib_keys}\n\
             [bearing]\nbore_mm = 60.0\noutside_diameter_mm = 110.0\nroller_half_angle_deg = 3.0\n\
             roller_large_end_radius_mm = 5.5\ninner_raceway_radius_mm = 35.0\n"
        );
        let doc = with(&pimp, "geometry", &geometry);
        tried += check(
            &format!("pimp face {face}, rib {rib}"),
            Schema::Case,
            &doc,
            &examples,
            &mut wrong,
        );
        let element = with(
            &read(&root().join("crates/kontakt-capi/examples/element_roller_rib.toml")),
            "geometry",
            &geometry,
        );
        tried += check(
            &format!("element face {face}, rib {rib}"),
            Schema::Element,
            &element,
            &examples,
            &mut wrong,
        );
    }
    let doc = with(
        &pimp,
        "geometry",
        "kind = \"hertz\"\nradii1_mm = [10.0, 10.0]\nradii2_mm = [inf, inf]\nangle_deg = 0.0",
    );
    tried += check(
        "pimp geometry hertz",
        Schema::Case,
        &doc,
        &examples,
        &mut wrong,
    );
    let traction = read(&examples.join("traction_twin_disc.toml"));
    for geometry in [
        "kind = \"ellipse\"\nsemi_axes_mm = [0.5, 0.3]",
        "kind = \"line\"\nradii_mm = [20.0, 20.0]\nlength_mm = 10.0",
    ] {
        let doc = with(&traction, "geometry", geometry);
        tried += check(
            &format!("traction {geometry}"),
            Schema::Case,
            &doc,
            &examples,
            &mut wrong,
        );
    }
    let rough = read(&examples.join("rough_self_affine.toml"));
    let doc = with(
        &rough,
        "surface",
        "kind = \"map\"\nfile = \"heights.csv\"\nspacing_mm = [0.001, 0.001]",
    );
    tried += check(
        "rough surface map",
        Schema::Case,
        &doc,
        &examples,
        &mut wrong,
    );

    assert!(tried > 150, "tables tried: {tried}");
    assert!(
        wrong.is_empty(),
        "{} tables:\n{}",
        wrong.len(),
        wrong.join("\n")
    );
}

/// The four messages of issue 30, item 9: the subtable's path, the table's keys.
#[test]
fn errors_inside_tagged_tables_name_the_full_path() {
    let base = "method = \"pimp\"\n[body1]\ne_mpa = 210000.0\nnu = 0.3\n[body2]\n\
                e_mpa = 210000.0\nnu = 0.3\n[load]\nforce_n = 250.0\n[geometry]\n\
                kind = \"roller_rib\"\n";
    let error = |geometry: &str| match Case::from_toml_str(&format!("{base}{geometry}")) {
        Err(Error::CaseFile { line, key, message }) => (line, key.into_owned(), message),
        other => panic!("{geometry}: expected a case-file error, got {other:?}"),
    };
    let torus_face = "[geometry.face]\nshape = \"torus\"\nradius_mm = 14.0\n";
    let cases = [
        (
            format!("{torus_face}eccentricty_mm = 2.0\n[geometry.rib]\nshape = \"cone\"\n"),
            Some(15),
            "geometry.face.eccentricty_mm",
            "unknown key `geometry.face.eccentricty_mm`; [geometry.face] takes `radius_mm` or `eccentricity_mm`",
        ),
        (
            "pairing = \"torus-torus-14\"\n[geometry.bearing]\nbore_mm = 60.0\ntypo = 3\n".to_string(),
            Some(15),
            "geometry.bearing.typo",
            "unknown key `geometry.bearing.typo`; [geometry.bearing] takes `bore_mm`, ",
        ),
        (
            "[geometry.face]\nradius_mm = 14.0\n[geometry.rib]\nshape = \"cone\"\n".to_string(),
            Some(12),
            "geometry.face.shape",
            "missing key `geometry.face.shape`",
        ),
        (
            "face = 5\nrib.shape = \"cone\"\n".to_string(),
            Some(12),
            "geometry.face",
            "`geometry.face`: integer `5`, expected a table",
        ),
        // A key valid in one table and unknown in its neighbour; a missing key where
        // several tables lack it: the one the schema asks for.
        (
            "[geometry.bearing]\nradius_mm = 3.0\n[geometry.face]\nshape = \"sphere\"\n\
             radius_mm = 14.0\n[geometry.rib]\nshape = \"cone\"\n"
                .to_string(),
            Some(13),
            "geometry.bearing.radius_mm",
            "unknown key `geometry.bearing.radius_mm`; [geometry.bearing] takes `bore_mm`, ",
        ),
        (
            "[geometry.bearing]\nbore_mm = 60.0\noutside_diameter_mm = 110.0\n\
             roller_half_angle_deg = 3.0\nroller_large_end_radius_mm = 5.5\n\
             inner_raceway_radius_mm = 35.0\n[geometry.face]\nradius_mm = 14.0\n\
             [geometry.rib]\nshape = \"cone\"\n"
                .to_string(),
            Some(18),
            "geometry.face.shape",
            "missing key `geometry.face.shape`",
        ),
        // Inline tables and dotted keys are tables too.
        (
            "face = { shape = \"torus\", radius_mm = 14.0, eccentricity_mm = \"2\" }\nrib.shape = \"cone\"\n".to_string(),
            Some(12),
            "geometry.face.eccentricity_mm",
            "`geometry.face.eccentricity_mm`: string \"2\", expected a number",
        ),
        (
            "face = { shape = \"sphere\", radius_mm = 14.0 }\nrib.shape = \"cone\"\nrib.angle_deg = 80.0\n".to_string(),
            Some(14),
            "geometry.rib.angle_deg",
            "unknown key `geometry.rib.angle_deg`; [geometry.rib] takes `shape`",
        ),
    ];
    for (geometry, line, key, message) in cases {
        let (l, k, m) = error(&geometry);
        assert_eq!((l, k.as_str()), (line, key), "{geometry}: {m}");
        assert!(m.starts_with(message), "{geometry}:\n{m}\nnot\n{message}");
        assert!(!m.contains("enum") && !m.contains("struct"), "{m}");
    }
}

/// A misspelt key holding an array, in an array of tables, is named by its own path (not
/// `parameter[1].valus[0].valus`), and an untagged value says what it takes.
#[test]
fn keys_in_arrays_of_tables_and_untagged_values() {
    let dir = root().join("examples");
    let sweep = |text: &str| Sweep::from_toml_str(text, &dir).unwrap_err().to_string();
    let base =
        "base = \"ball_on_flat.toml\"\n[[parameter]]\nkey = \"load.force_n\"\nvalues = [1.0]\n";
    let m = sweep(&format!(
        "{base}[[parameter]]\nkey = \"load.force_n\"\nvalus = [1.0]\n"
    ));
    assert!(
        m.contains("line 7: unknown key `parameter[1].valus`; [parameter[1]] takes `key`, "),
        "{m}"
    );
    let m = sweep("base = 5\n");
    assert!(
        m.contains("`base`: expected a case file's path (a string) or an inline table"),
        "{m}"
    );
    let m = sweep(&base.replace("key = \"load.force_n\"", "key = 5"));
    assert!(m.contains("`parameter[0].key`: expected a key path"), "{m}");
}
