//! The JSON Schema of the case files (`kontakt_case::case_schema`, issue 32 item 5): the
//! checked-in copy `docs/kontakt-case.schema.json` is up to date, every example case
//! validates against it, and the schema and the case reader agree on what they refuse.
//!
//! Agreement is tested by edits of every example case: an unknown key in every table,
//! every key removed in turn, and every value replaced by one of the wrong type. Each
//! edited case is given to the reader (`Case::from_toml_table`) and to the validator; the
//! two must answer alike. (The schema checks keys and types; the ranges of the values are
//! the runners' checks, which these edits do not reach.)
//!
//! Refresh the checked-in schema with
//! `KONTAKT_BLESS=1 cargo test --workspace --test case_schema`.

#![allow(clippy::unwrap_used)] // tests: a panic is a failure with its message

#[allow(dead_code)] // this test walks the examples only
#[path = "support/toml_keys.rs"]
mod toml_keys;

use kontakt_case::{Case, case_schema};
use std::path::{Path, PathBuf};
use toml::{Table, Value};

fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../..")
}

/// The example case files, `examples/*.toml`, sorted.
fn examples() -> Vec<PathBuf> {
    let files = toml_keys::example_files();
    assert!(files.len() >= 30, "examples/*.toml: {} files", files.len());
    files
}

fn read(path: &Path) -> Table {
    toml::from_str(&std::fs::read_to_string(path).unwrap()).unwrap()
}

/// A TOML value as JSON, the way a validator sees a case file: JSON has no infinity, so
/// `±inf` (a flat body's radius) stands as `±f64::MAX`; dates as strings.
fn json(v: &Value) -> serde_json::Value {
    use serde_json::Value as J;
    match v {
        Value::String(s) => J::String(s.clone()),
        Value::Integer(i) => J::from(*i),
        Value::Float(x) if x.is_infinite() => J::from(f64::MAX.copysign(*x)),
        Value::Float(x) => serde_json::Number::from_f64(*x).map_or(J::Null, J::Number),
        Value::Boolean(b) => J::Bool(*b),
        Value::Datetime(d) => J::String(d.to_string()),
        Value::Array(a) => J::Array(a.iter().map(json).collect()),
        Value::Table(t) => J::Object(t.iter().map(|(k, x)| (k.clone(), json(x))).collect()),
    }
}

fn validator() -> jsonschema::Validator {
    jsonschema::draft7::new(&case_schema()).unwrap()
}

/// The validator's messages for `case`, empty when it validates: for a `oneOf` (the
/// `method` branches, the variants of a tagged table) the messages of its branches, less
/// those of a tag (`method`, `type`, `kind`, ...) that does not match.
fn schema_errors(validator: &jsonschema::Validator, case: &Table) -> Vec<String> {
    let mut out = Vec::new();
    for e in validator.iter_errors(&json(&Value::Table(case.clone()))) {
        messages(&e, &mut out);
    }
    out
}

fn messages(e: &jsonschema::ValidationError<'_>, out: &mut Vec<String>) {
    use jsonschema::error::ValidationErrorKind as K;
    match e.kind() {
        K::OneOfNotValid { context } | K::AnyOf { context } => {
            let before = out.len();
            for e in context.iter().flatten() {
                if !matches!(e.kind(), K::Constant { .. } | K::Enum { .. }) {
                    messages(e, out);
                }
            }
            if out.len() == before {
                out.push(format!("{}: {e}", e.instance_path()));
            }
        }
        _ => out.push(format!("{}: {e}", e.instance_path())),
    }
}

/// The reader's error for `case`, `None` when it reads.
fn reader_error(case: &Table) -> Option<String> {
    Case::from_toml_table(case.clone())
        .err()
        .map(|e| e.to_string())
}

#[test]
fn schema_file_is_up_to_date() {
    let generated = serde_json::to_string_pretty(&case_schema()).unwrap() + "\n";
    let path = root().join("docs/kontakt-case.schema.json");
    if std::env::var_os("KONTAKT_BLESS").is_some() {
        std::fs::write(&path, &generated).unwrap();
        return;
    }
    let committed = std::fs::read_to_string(&path).unwrap_or_default();
    if committed == generated {
        return;
    }
    // Name the definitions (or the top-level keys) that differ.
    let old: serde_json::Value = serde_json::from_str(&committed).unwrap_or_default();
    let new = case_schema();
    let differs = |a: &serde_json::Value, b: &serde_json::Value| -> Vec<String> {
        let (a, b) = (a.as_object(), b.as_object());
        let keys: std::collections::BTreeSet<&String> =
            a.into_iter().chain(b).flat_map(|o| o.keys()).collect();
        keys.into_iter()
            .filter(|k| a.and_then(|o| o.get(*k)) != b.and_then(|o| o.get(*k)))
            .cloned()
            .collect()
    };
    let mut changed = differs(&old["definitions"], &new["definitions"]);
    if changed.is_empty() {
        changed = differs(&old, &new);
    }
    panic!(
        "docs/kontakt-case.schema.json is out of date with the case types (changed: {}). \
         Refresh it with: KONTAKT_BLESS=1 cargo test --workspace --test case_schema",
        if changed.is_empty() {
            "its text".to_string()
        } else {
            changed.join(", ")
        }
    );
}

#[test]
fn every_example_case_validates() {
    let validator = validator();
    let mut wrong = Vec::new();
    for path in examples() {
        let case = read(&path);
        let name = path.file_name().unwrap().to_string_lossy().to_string();
        if let Some(e) = reader_error(&case) {
            wrong.push(format!("{name}: the reader refuses it: {e}"));
        }
        for e in schema_errors(&validator, &case) {
            wrong.push(format!("{name}: {e}"));
        }
    }
    assert!(wrong.is_empty(), "{}", wrong.join("\n"));
}

/// One edit of a case: where, what, and the edited case.
struct Edit {
    what: String,
    case: Table,
}

/// Every table and array element of `v` at `path`, with a closure that edits it.
fn walk(v: &Value, path: &mut Vec<String>, out: &mut Vec<(Vec<String>, Value)>) {
    out.push((path.clone(), v.clone()));
    match v {
        Value::Table(t) => {
            for (k, x) in t {
                path.push(k.clone());
                walk(x, path, out);
                path.pop();
            }
        }
        Value::Array(a) => {
            for (i, x) in a.iter().enumerate() {
                path.push(format!("[{i}]"));
                walk(x, path, out);
                path.pop();
            }
        }
        _ => {}
    }
}

/// The value at `path` in `v`, mutably.
fn at<'a>(v: &'a mut Value, path: &[String]) -> &'a mut Value {
    path.iter().fold(v, |v, step| match step.strip_prefix('[') {
        Some(i) => {
            &mut v.as_array_mut().unwrap()[i.trim_end_matches(']').parse::<usize>().unwrap()]
        }
        None => v.as_table_mut().unwrap().get_mut(step).unwrap(),
    })
}

/// A value of another type than `v`.
fn wrong_type(v: &Value) -> Value {
    match v {
        Value::String(_) => Value::Integer(7),
        Value::Table(_) | Value::Array(_) => Value::Boolean(true),
        _ => Value::String("seven".into()),
    }
}

/// The edits of `case`: an unknown key in every table, every key removed, every value of
/// the wrong type.
fn edits(case: &Table) -> Vec<Edit> {
    let root = Value::Table(case.clone());
    let mut nodes = Vec::new();
    walk(&root, &mut Vec::new(), &mut nodes);
    let mut out = Vec::new();
    let edit = |what: String, f: &dyn Fn(&mut Value)| {
        let mut v = root.clone();
        f(&mut v);
        Edit {
            what,
            case: v.as_table().unwrap().clone(),
        }
    };
    for (path, v) in &nodes {
        let shown = path.join(".").replace(".[", "[");
        if v.is_table() {
            out.push(edit(format!("unknown key in [{shown}]"), &|r| {
                at(r, path)
                    .as_table_mut()
                    .unwrap()
                    .insert("typo_key".into(), Value::Integer(5));
            }));
        }
        let Some((last, parent)) = path.split_last() else {
            continue;
        };
        if !last.starts_with('[') {
            out.push(edit(format!("{shown} removed"), &|r| {
                at(r, parent).as_table_mut().unwrap().remove(last);
            }));
        }
        out.push(edit(format!("{shown} of the wrong type"), &|r| {
            *at(r, path) = wrong_type(v);
        }));
    }
    out
}

/// The schema and the reader agree on every edit of every example: both take it or both
/// refuse it. The three kinds of edit are each refused somewhere (so the test can fail
/// both ways).
#[test]
fn schema_and_reader_agree_on_every_edit_of_the_examples() {
    let validator = validator();
    let mut disagree = Vec::new();
    let (mut tried, mut refused) = (0, 0);
    for path in examples() {
        let name = path.file_name().unwrap().to_string_lossy().to_string();
        for edit in edits(&read(&path)) {
            tried += 1;
            let reader = reader_error(&edit.case);
            let schema = schema_errors(&validator, &edit.case);
            refused += usize::from(reader.is_some());
            match (reader, schema.is_empty()) {
                (None, false) => disagree.push(format!(
                    "{name}, {}: the reader takes it, the schema refuses it: {}",
                    edit.what,
                    schema.join("; ")
                )),
                (Some(e), true) => disagree.push(format!(
                    "{name}, {}: the schema takes it, the reader refuses it: {e}",
                    edit.what
                )),
                _ => {}
            }
        }
    }
    assert!(
        disagree.is_empty(),
        "{} of {tried} edits:\n{}",
        disagree.len(),
        disagree.join("\n")
    );
    assert!(
        tried > 1000 && refused > tried / 2,
        "{refused} of {tried} refused"
    );
}

/// The three refusals the issue names, on the Hertz example: each refused by the schema
/// (with a message naming the key) and by the reader.
#[test]
fn unknown_wrong_type_and_missing_keys_are_refused_by_both() {
    let validator = validator();
    let base = read(&root().join("examples/ball_on_flat.toml"));
    assert!(schema_errors(&validator, &base).is_empty());
    let edit = |f: &dyn Fn(&mut Table)| {
        let mut c = base.clone();
        f(&mut c);
        c
    };
    let cases = [
        (
            "unknown key body1.youngs_modulus",
            edit(&|c| {
                c["body1"]
                    .as_table_mut()
                    .unwrap()
                    .insert("youngs_modulus".into(), Value::Float(2e5));
            }),
            "youngs_modulus",
        ),
        (
            "wrong type body1.e_mpa",
            edit(&|c| {
                c["body1"]
                    .as_table_mut()
                    .unwrap()
                    .insert("e_mpa".into(), Value::String("steel".into()));
            }),
            "steel",
        ),
        (
            "missing body2",
            edit(&|c| {
                c.remove("body2");
            }),
            "body2",
        ),
    ];
    for (what, case, named) in cases {
        let errors = schema_errors(&validator, &case);
        assert!(!errors.is_empty(), "{what}: the schema takes it");
        assert!(
            errors.iter().any(|e| e.contains(named)),
            "{what}: {errors:?}"
        );
        assert!(reader_error(&case).is_some(), "{what}: the reader takes it");
    }
}

/// `method` dispatches as the reader does: absent reads as Hertz, an unknown method is
/// refused, and a Hertz case named `"pimp"` is refused by both.
#[test]
fn method_is_the_tagged_union_of_the_reader() {
    let schema = case_schema();
    let methods: Vec<&str> = schema["oneOf"]
        .as_array()
        .unwrap()
        .iter()
        .map(|b| b["properties"]["method"]["enum"][0].as_str().unwrap())
        .collect();
    assert_eq!(methods, Case::METHODS);
    let validator = validator();
    let mut base = read(&root().join("examples/ball_on_flat.toml"));
    base.remove("method");
    assert!(schema_errors(&validator, &base).is_empty());
    assert!(reader_error(&base).is_none());
    for method in ["pimp", "element", "hertzz"] {
        let mut case = base.clone();
        case.insert("method".into(), Value::String(method.into()));
        assert!(!schema_errors(&validator, &case).is_empty(), "{method}");
        assert!(reader_error(&case).is_some(), "{method}");
    }
}

/// The doc comments reach the schema with their units, brackets unescaped; the serde
/// defaults and `deny_unknown_fields` too.
#[test]
fn descriptions_units_defaults_and_closed_tables() {
    let schema = case_schema();
    let defs = &schema["definitions"];
    let body = &defs["BodySpec"];
    assert_eq!(body["additionalProperties"], false);
    assert_eq!(
        body["required"],
        serde_json::json!(["radii_mm", "e_mpa", "nu"])
    );
    let e = body["properties"]["e_mpa"]["description"].as_str().unwrap();
    assert!(e.contains("[MPa]") && !e.contains('\\'), "{e}");
    let angle = &defs["ContactSpec"]["properties"]["angle_deg"];
    assert!(angle["description"].as_str().unwrap().contains("[deg]"));
    assert_eq!(angle["default"], 0.0);
    let text = serde_json::to_string(&schema).unwrap();
    assert!(!text.contains("\\\\["), "an escaped bracket is left");
}

/// A `[bearing] boundary` makes the keys it generates optional, as the reader does: the
/// boundary example validates, and without its boundary both refuse it.
#[test]
fn boundary_generates_the_keys_it_makes_optional() {
    let validator = validator();
    let case = read(&root().join("examples/bearing_32008x_from_boundary.toml"));
    assert!(case["bearing"].get("pitch_diameter_mm").is_none());
    assert!(schema_errors(&validator, &case).is_empty());
    let mut without = case.clone();
    without["bearing"]
        .as_table_mut()
        .unwrap()
        .remove("boundary");
    let errors = schema_errors(&validator, &without);
    assert!(!errors.is_empty());
    assert!(reader_error(&without).is_some());
}

/// A default written out is taken by both: `roller_model = "iso"` (the reader once refused
/// it as an unknown key, because the key was not serialized at its default and the
/// unknown-key check compares the file with what was read).
#[test]
fn a_default_written_out_is_taken_by_both() {
    let validator = validator();
    let mut case = read(&root().join("examples/bearing_32008x.toml"));
    let bearing = case["bearing"].as_table_mut().unwrap();
    bearing.insert("roller_model".into(), Value::String("iso".into()));
    bearing.insert("slice_model".into(), Value::String("iso".into()));
    assert!(schema_errors(&validator, &case).is_empty());
    assert_eq!(reader_error(&case), None);
}
