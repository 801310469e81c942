//! The case of a request: TOML text or a JSON object, turned into the TOML text that
//! `kontakt solve` would read, and checked by the case parser before anything runs.

use crate::error::ApiError;
use kontakt_case::Case;

/// What the case text was written from: the user's TOML, or a JSON object (whose errors
/// then have no line: the line would be one of the TOML the server wrote).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Source {
    /// TOML text as the user wrote it.
    Toml,
    /// A JSON object written as TOML by the server.
    Json,
}

/// A case as the API receives it, `"case": "<TOML text>"` or `"case": {...}`, as TOML text.
///
/// # Errors
/// 400 for a JSON value that is neither (or an object TOML cannot hold, such as `null`).
pub fn case_text(case: &serde_json::Value) -> Result<(String, Source), ApiError> {
    match case {
        serde_json::Value::String(text) => Ok((text.clone(), Source::Toml)),
        serde_json::Value::Object(_) => Ok((toml_of_json(case)?, Source::Json)),
        _ => Err(ApiError::bad_request(
            "case: expected the case file's TOML text (a string) or its tables (a JSON object)",
        )),
    }
}

/// A JSON object written as TOML text ([`toml_of_json_value`]).
///
/// # Errors
/// 400 when the object holds what TOML cannot (a `null`).
pub fn toml_of_json(case: &serde_json::Value) -> Result<String, ApiError> {
    let toml::Value::Table(table) = toml_of_json_value(case, "case")? else {
        return Err(ApiError::bad_request("case: expected a JSON object"));
    };
    toml::to_string(&table)
        .map_err(|e| ApiError::bad_request(format!("case: cannot be written as TOML: {e}")))
}

/// A JSON value as TOML: numbers without a fraction or exponent are integers, others
/// floats; the strings `"inf"`, `"+inf"`, `"-inf"` and `"nan"` are TOML's special floats
/// (JSON has none; [`json_of_table`] writes them so).
///
/// # Errors
/// 400 for a `null` (TOML has none), named by its path in the case.
pub fn toml_of_json_value(v: &serde_json::Value, path: &str) -> Result<toml::Value, ApiError> {
    use serde_json::Value as J;
    Ok(match v {
        J::Null => {
            return Err(ApiError::bad_request(format!(
                "{path}: null has no TOML form (leave the key out instead)"
            )));
        }
        J::Bool(b) => toml::Value::Boolean(*b),
        J::Number(n) => match n.as_i64() {
            Some(i) => toml::Value::Integer(i),
            None => toml::Value::Float(n.as_f64().unwrap_or(f64::NAN)),
        },
        J::String(s) => match s.as_str() {
            "inf" | "+inf" => toml::Value::Float(f64::INFINITY),
            "-inf" => toml::Value::Float(f64::NEG_INFINITY),
            "nan" | "+nan" | "-nan" => toml::Value::Float(f64::NAN),
            _ => toml::Value::String(s.clone()),
        },
        J::Array(items) => toml::Value::Array(
            items
                .iter()
                .enumerate()
                .map(|(i, x)| toml_of_json_value(x, &format!("{path}[{i}]")))
                .collect::<Result<_, _>>()?,
        ),
        J::Object(map) => toml::Value::Table(
            map.iter()
                .map(|(k, x)| {
                    let p = if path == "case" {
                        k.clone()
                    } else {
                        format!("{path}.{k}")
                    };
                    Ok((k.clone(), toml_of_json_value(x, &p)?))
                })
                .collect::<Result<_, ApiError>>()?,
        ),
    })
}

/// Parse the case as `kontakt solve` does: the same schema, unknown keys refused with the
/// same message. A text that is not TOML at all is a malformed body (400, with the
/// parser's message); a TOML document the schema refuses is an input error (422). Cases
/// that name a file on disk are refused: the server reads no files.
///
/// # Errors
/// 400 or 422 as above.
pub fn parse_case(text: &str, source: Source) -> Result<(Case, toml::Table), ApiError> {
    let table = match text.parse::<toml::Table>() {
        Ok(t) => t,
        Err(_) => {
            // The case reader's message (line and key) for the syntax error.
            let mut e = match Case::from_toml_str(text) {
                Err(e) => ApiError::from_case(&e),
                Ok(_) => ApiError::bad_request("case: not a TOML document"),
            };
            e.status = axum::http::StatusCode::BAD_REQUEST;
            return Err(e);
        }
    };
    let case = Case::from_toml_str(text).map_err(|e| match (source, e) {
        (
            Source::Json,
            kontakt::Error::CaseFile {
                line: Some(_),
                key,
                message,
            },
        ) => ApiError::from_case(&kontakt::Error::CaseFile {
            line: None,
            key,
            message,
        }),
        (_, e) => ApiError::from_case(&e),
    })?;
    if let Some(key) = file_key(&table, "") {
        return Err(ApiError {
            field: Some(key.clone()),
            expected: Some("a case without files (the geometry or surface given inline)".into()),
            ..ApiError::new(
                axum::http::StatusCode::UNPROCESSABLE_ENTITY,
                "input",
                format!(
                    "{key}: kontakt serve reads no files; run cases with height or gap maps \
                     with `kontakt solve` on the command line"
                ),
            )
        });
    }
    Ok((case, table))
}

/// The first key named `file` (a height or gap map on disk), with its full path.
fn file_key(table: &toml::Table, prefix: &str) -> Option<String> {
    for (key, value) in table {
        let path = if prefix.is_empty() {
            key.clone()
        } else {
            format!("{prefix}.{key}")
        };
        if key == "file" || key.ends_with("_file") {
            return Some(path);
        }
        let found = match value {
            toml::Value::Table(t) => file_key(t, &path),
            toml::Value::Array(items) => items.iter().enumerate().find_map(|(i, v)| match v {
                toml::Value::Table(t) => file_key(t, &format!("{path}[{i}]")),
                _ => None,
            }),
            _ => None,
        };
        if found.is_some() {
            return found;
        }
    }
    None
}

/// The case's tables as JSON (what a form fills itself from): TOML's special floats
/// (`inf`, `nan`) become the strings `"inf"`, `"-inf"`, `"nan"`, dates their TOML text.
pub fn json_of_table(table: &toml::Table) -> serde_json::Value {
    serde_json::Value::Object(
        table
            .iter()
            .map(|(k, v)| (k.clone(), json_of_toml(v)))
            .collect(),
    )
}

fn json_of_toml(v: &toml::Value) -> serde_json::Value {
    use serde_json::Value as J;
    match v {
        toml::Value::String(s) => J::String(s.clone()),
        toml::Value::Integer(i) => J::from(*i),
        toml::Value::Float(x) if x.is_nan() => J::String("nan".into()),
        toml::Value::Float(x) if x.is_infinite() => {
            J::String(if *x > 0.0 { "inf" } else { "-inf" }.into())
        }
        toml::Value::Float(x) => J::from(*x),
        toml::Value::Boolean(b) => J::Bool(*b),
        toml::Value::Datetime(d) => J::String(d.to_string()),
        toml::Value::Array(items) => J::Array(items.iter().map(json_of_toml).collect()),
        toml::Value::Table(t) => json_of_table(t),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn file_keys_are_found_with_their_path() {
        let t: toml::Table = "a = 1\n[geometry]\nfile = \"x.csv\"\n".parse().unwrap();
        assert_eq!(file_key(&t, "").as_deref(), Some("geometry.file"));
        let t: toml::Table = "[[s]]\nx = 1\n[[s]]\nmap_file = \"y\"\n".parse().unwrap();
        assert_eq!(file_key(&t, "").as_deref(), Some("s[1].map_file"));
        let t: toml::Table = "[geometry]\nfiles = 2\n".parse().unwrap();
        assert_eq!(file_key(&t, ""), None);
    }

    #[test]
    fn json_cases_become_toml() {
        let v = serde_json::json!({"method": "hertz", "load": {"force_n": 100}});
        let text = toml_of_json(&v).unwrap();
        let t: toml::Table = text.parse().unwrap();
        assert_eq!(t["load"]["force_n"].as_integer(), Some(100));
        // Infinite radii (a flat) survive TOML -> JSON -> TOML.
        let t: toml::Table = "r = [inf, -inf, 1.5]\nn = 3\n".parse().unwrap();
        let j = json_of_table(&t);
        assert_eq!(j["r"], serde_json::json!(["inf", "-inf", 1.5]));
        let back: toml::Table = toml_of_json(&j).unwrap().parse().unwrap();
        assert_eq!(back, t);
        // An integer where the schema takes a float is read as the float.
        let text = toml_of_json(&serde_json::json!({
            "method": "hertz",
            "contact": {"kind": "point"},
            "body1": {"radii_mm": [10, 10], "e_mpa": 210000, "nu": 0.3},
            "body2": {"radii_mm": ["inf", "inf"], "e_mpa": 210000, "nu": 0.3},
            "load": {"force_n": 100}
        }))
        .unwrap();
        parse_case(&text, Source::Json).unwrap();
        let err = toml_of_json(&serde_json::json!({"a": {"b": [1, null]}})).unwrap_err();
        assert!(err.message.starts_with("a.b[1]: null"), "{}", err.message);
        assert!(case_text(&serde_json::json!(3)).is_err());
        let err = parse_case("method = \"hertz\"\nbogus = 1\n", Source::Json).unwrap_err();
        assert!(
            err.message.starts_with("unknown key `bogus`"),
            "{}",
            err.message
        );
        let err = parse_case("method = \"hertz\"\nbogus = 1\n", Source::Toml).unwrap_err();
        assert!(
            err.message.starts_with("line 2: unknown key `bogus`"),
            "{}",
            err.message
        );
    }
}
