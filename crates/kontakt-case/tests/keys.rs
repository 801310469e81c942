//! Error fields are case-file keys, checked against the schema itself.
//!
//! The library names its own fields (`extent[0]`, `force`, `youngs_modulus`); the case
//! layer renames them to the keys of the case file (`pimp.extent_mm[0]`,
//! `load.force_n`, `body1.e_mpa`). A renamed library field must not slip through as a
//! key that no case file has. This test mutates every number in every example case to
//! invalid values, runs the case through `Case::run`, and requires every error that
//! names a field to name a key (or table) that exists in that case file, as serde reads
//! it: the schema is the one source of the names.

#![allow(clippy::unwrap_used)] // tests: a panic is a failure with its message

use kontakt_case::Case;
use std::path::PathBuf;
use toml::Value;

#[path = "support/toml_keys.rs"]
mod toml_keys;
use toml_keys::{example_files, leaves, names_a_key, set};

fn examples() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../../examples")
}

#[test]
fn every_error_names_a_key_of_the_case_file() {
    let files = example_files();
    let (mut runs, mut named, mut wrong) = (0, 0, Vec::new());
    for file in &files {
        let doc: Value = toml::from_str(&std::fs::read_to_string(file).unwrap()).unwrap();
        let mut paths = Vec::new();
        leaves(&doc, &mut Vec::new(), &mut paths);
        for path in paths {
            for bad in [
                Value::Float(-1.0),
                Value::Float(0.0),
                Value::Float(f64::NAN),
            ] {
                let mut case = doc.clone();
                set(&mut case, &path, bad.clone());
                let text = toml::to_string(&case).unwrap();
                let result = Case::from_toml_str(&text).and_then(|c| c.run(&examples()));
                runs += 1;
                let Err(e) = result else { continue };
                let Some(field) = e.field() else { continue };
                named += 1;
                // `case` is the parser's (TOML syntax, unknown key, wrong type).
                // A group of keys is named as a comma-separated list.
                if field == "case" || field.split(", ").all(|f| names_a_key(&case, f)) {
                    continue;
                }
                wrong.push(format!(
                    "{}: {} = {bad}: error names `{field}`: {e}",
                    file.file_name().unwrap().to_string_lossy(),
                    path.join(".").replace(".[", "[")
                ));
            }
        }
    }
    assert!(runs > 100 && named > 50, "runs {runs}, named {named}");
    assert!(
        wrong.is_empty(),
        "{} errors name no key of the case file:\n{}",
        wrong.len(),
        wrong.join("\n")
    );
}
