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

/// A JSON object written as TOML text.
///
/// # Errors
/// 400 when the object holds what TOML cannot (a `null`, mixed arrays TOML refuses).
pub fn toml_of_json(case: &serde_json::Value) -> Result<String, ApiError> {
    let table: toml::Table = serde::Deserialize::deserialize(case)
        .map_err(|e| ApiError::bad_request(format!("case: not a TOML table: {e}")))?;
    toml::to_string(&table)
        .map_err(|e| ApiError::bad_request(format!("case: cannot be written as TOML: {e}")))
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
            let message = match Case::from_toml_str(text) {
                Err(e) => e.to_string(),
                Ok(_) => "case: not a TOML document".to_string(),
            };
            return Err(ApiError::bad_request(message));
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

/// The case's tables as JSON (what a form fills itself from).
///
/// # Errors
/// 500 if a TOML value has no JSON form (none of the case schemas has one).
pub fn json_of_table(table: &toml::Table) -> Result<serde_json::Value, ApiError> {
    serde_json::to_value(table).map_err(|e| {
        ApiError::new(
            axum::http::StatusCode::INTERNAL_SERVER_ERROR,
            "internal",
            format!("case: no JSON form: {e}"),
        )
    })
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
        assert!(toml_of_json(&serde_json::json!({"a": null})).is_err());
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
