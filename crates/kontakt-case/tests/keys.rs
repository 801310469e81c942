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

fn examples() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../../examples")
}

/// Every numeric leaf of `v` as a path of keys and array indices.
fn leaves(v: &Value, path: &mut Vec<String>, out: &mut Vec<Vec<String>>) {
    match v {
        Value::Table(t) => {
            for (k, x) in t {
                path.push(k.clone());
                leaves(x, path, out);
                path.pop();
            }
        }
        Value::Array(a) => {
            for (i, x) in a.iter().enumerate() {
                path.push(format!("[{i}]"));
                leaves(x, path, out);
                path.pop();
            }
        }
        Value::Float(_) | Value::Integer(_) => out.push(path.clone()),
        _ => {}
    }
}

fn set(v: &mut Value, path: &[String], new: Value) {
    let (head, rest) = path.split_first().unwrap();
    let next = if let Some(i) = head.strip_prefix('[') {
        let i: usize = i.trim_end_matches(']').parse().unwrap();
        &mut v.as_array_mut().unwrap()[i]
    } else {
        v.as_table_mut().unwrap().get_mut(head).unwrap()
    };
    if rest.is_empty() {
        *next = new;
    } else {
        set(next, rest, new);
    }
}

/// Whether `field` (dotted keys, `[i]` indices) names a key or table of `doc`.
fn names_a_key(doc: &Value, field: &str) -> bool {
    let mut v = doc;
    for part in field.split('.') {
        let (key, indices) = match part.find('[') {
            Some(i) => (&part[..i], &part[i..]),
            None => (part, ""),
        };
        match v.as_table().and_then(|t| t.get(key)) {
            Some(x) => v = x,
            None => return false,
        }
        for idx in indices.split('[').filter(|s| !s.is_empty()) {
            let i: usize = match idx.trim_end_matches(']').parse() {
                Ok(i) => i,
                Err(_) => return false,
            };
            match v.as_array().and_then(|a| a.get(i)) {
                Some(x) => v = x,
                None => return false,
            }
        }
    }
    true
}

#[test]
fn every_error_names_a_key_of_the_case_file() {
    let mut files: Vec<PathBuf> = std::fs::read_dir(examples())
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|x| x == "toml"))
        .collect();
    files.sort();
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
