//! Walking a TOML case file for the key tests: its numeric leaves, setting one, and whether
//! an error's field names a key of the file. Shared by `keys.rs`, `element_case.rs` and `validity.rs`
//! (`#[path = "support/toml_keys.rs"] mod toml_keys;`).
#![allow(clippy::unwrap_used)] // tests: a panic is a failure with its message

use std::path::PathBuf;
use toml::Value;

/// The `*.toml` files of `dir`, sorted.
pub fn toml_files(dir: &std::path::Path) -> Vec<PathBuf> {
    let mut files: Vec<PathBuf> = std::fs::read_dir(dir)
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|x| x == "toml"))
        .collect();
    files.sort();
    files
}

/// The example case files, `examples/*.toml`, sorted.
#[allow(dead_code)] // not every test that includes this module walks the examples
pub fn example_files() -> Vec<PathBuf> {
    toml_files(&PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../../examples"))
}

/// Every numeric leaf of `v` as a path of keys and array indices.
pub fn leaves(v: &Value, path: &mut Vec<String>, out: &mut Vec<Vec<String>>) {
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

pub fn set(v: &mut Value, path: &[String], new: Value) {
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
pub fn names_a_key(doc: &Value, field: &str) -> bool {
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
