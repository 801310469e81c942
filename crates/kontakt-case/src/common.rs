//! What every schema shares: TOML parsing with errors that name the line, the schema
//! version of the reports, and the `[body1]`/`[body2]` material tables.

use kontakt::material::ElasticMaterial;
use kontakt::{Error, Result};
use serde::{Deserialize, Serialize};
use std::path::Path;

/// Version of the JSON result schema.
pub const SCHEMA_VERSION: u32 = 1;

use crate::files::MAX_CASE_FILE_BYTES;

/// The text of a case (or sweep) file at `path`, read with a size cap.
///
/// # Errors
/// [`Error::CaseFile`] with key `path`: a file that cannot be opened or read, is not UTF-8
/// text, or is larger than [`MAX_CASE_FILE_BYTES`] (checked while reading: nothing beyond
/// the cap is read, whatever the file system says).
pub fn read_case_file(path: &Path) -> Result<String> {
    let fail = |message: String| Error::CaseFile {
        line: None,
        key: "path".into(),
        message,
    };
    let file = std::fs::File::open(path)
        .map_err(|e| fail(format!("cannot read case file {}: {e}", one_line(path))))?;
    read_case_text(file, &one_line(path))
}

/// [`read_case_file`] for any reader (standard input): `label` names it in messages.
///
/// # Errors
/// As [`read_case_file`].
pub fn read_case_text(reader: impl std::io::Read, label: &str) -> Result<String> {
    use std::io::Read;
    let mut bytes = Vec::new();
    let read =
        crate::files::Capped::new(reader, MAX_CASE_FILE_BYTES, false).read_to_end(&mut bytes);
    if let Err(e) = read {
        if !crate::files::is_too_large(&e) {
            return Err(Error::CaseFile {
                line: None,
                key: "path".into(),
                message: format!("cannot read case file {label}: {e}"),
            });
        }
        return Err(Error::CaseFile {
            line: None,
            key: "path".into(),
            message: format!(
                "case file {label} is larger than 16 MiB (MAX_CASE_FILE_BYTES); a case is a \
                 short TOML file, with gap maps and tables in files of their own"
            ),
        });
    }
    String::from_utf8(bytes).map_err(|e| Error::CaseFile {
        line: None,
        key: "path".into(),
        message: format!(
            "case file {label} is not UTF-8 text (invalid byte at offset {}); is it a binary \
             file?",
            e.utf8_error().valid_up_to()
        ),
    })
}

/// Parse TOML into `T`, turning the reader's errors into [`Error::CaseFile`]: the line,
/// the key path as the file spells it and a message in the schema's words.
pub(crate) fn parse_toml<T: serde::de::DeserializeOwned>(text: &str) -> Result<T> {
    toml::from_str(text).map_err(|e| case_file_error(text, &e))
}

/// [`Error::CaseFile`] from a TOML reader's error on `text`.
///
/// A file that is not TOML at all says so ("not valid TOML: ..."). Otherwise the error is
/// about the schema, and the key path is rebuilt from the error's position: the table
/// header above it (`[contact]`, `[[loads]]`) and the key on its line. serde's wording
/// ("field", "f64") becomes the schema's ("key", "a number").
pub(crate) fn case_file_error(text: &str, e: &toml::de::Error) -> Error {
    match case_file_error_raw(text, e) {
        // The reader quotes the file's strings (`kind = "a\nb"`, found by fuzzing):
        // control characters are escaped so that the message stays on one line.
        Error::CaseFile { line, key, message } if message.chars().any(char::is_control) => {
            Error::CaseFile {
                line,
                key,
                message: message.chars().flat_map(char::escape_default).collect(),
            }
        }
        other => other,
    }
}

fn case_file_error_raw(text: &str, e: &toml::de::Error) -> Error {
    let (line, table, key) = match e.span() {
        Some(span) => locate(text, span.start.min(text.len())),
        None => (None, String::new(), None),
    };
    let message = e.message().trim();
    if text.parse::<toml::Table>().is_err() {
        return Error::CaseFile {
            line,
            key: "case".into(),
            message: format!("not valid TOML: {message}"),
        };
    }
    if e.span().is_none() {
        // No position (a case read from an edited table): the reader's message, in the
        // schema's words.
        return Error::CaseFile {
            line: None,
            key: "case".into(),
            message: schema_words(message).replace("field", "key"),
        };
    }
    let join = |table: &str, k: &str| {
        if table.is_empty() {
            k.to_string()
        } else {
            format!("{table}.{k}")
        }
    };
    let (key_path, message) = if let Some(rest) = message.strip_prefix("unknown field ") {
        let (name, valid) = split_expected(rest);
        let name = name.trim_matches('`');
        // An unknown table is reported at its own header: the key is the header's path and
        // the keys it could have been are its parent's.
        let parent = match (&key, table.rsplit_once('.')) {
            (None, Some((parent, last))) if last == name => parent,
            (None, None) if table == name => "",
            _ => table.as_str(),
        };
        let path = join(parent, name);
        let place = if parent.is_empty() {
            "the top level".to_string()
        } else {
            format!("[{parent}]")
        };
        let takes = valid.unwrap_or("no keys");
        (
            path.clone(),
            format!("unknown key `{path}`; {place} takes {takes}"),
        )
    } else if let Some(rest) = message.strip_prefix("missing field ") {
        let path = join(&table, rest.trim().trim_matches('`'));
        (path.clone(), format!("missing key `{path}`"))
    } else if let Some(rest) = message.strip_prefix("unknown variant ") {
        let (name, valid) = rest
            .split_once(", expected ")
            .unwrap_or((rest, "another value"));
        let path = key
            .as_deref()
            .map_or_else(|| table.clone(), |k| join(&table, k));
        (path.clone(), format!("`{path}` = {name}: expected {valid}"))
    } else {
        let path = key
            .as_deref()
            .map_or_else(|| table.clone(), |k| join(&table, k));
        let shown = if path.is_empty() {
            "case".to_string()
        } else {
            path
        };
        (
            shown.clone(),
            format!("`{shown}`: {}", schema_words(message)),
        )
    };
    Error::CaseFile {
        line,
        key: if key_path.is_empty() {
            "case".into()
        } else {
            key_path.into()
        },
        message,
    }
}

/// Split "`name`, expected one of `a`, `b`" into the name and "`a`, `b`".
fn split_expected(rest: &str) -> (&str, Option<&str>) {
    match rest.split_once(", expected ") {
        Some((name, valid)) => {
            let valid = valid.strip_prefix("one of ").unwrap_or(valid).trim();
            (name.trim(), (!valid.is_empty()).then_some(valid))
        }
        None => (
            rest.split_once(", there are no fields")
                .map_or(rest, |(n, _)| n)
                .trim(),
            None,
        ),
    }
}

/// serde's type names in the words of a case file.
fn schema_words(message: &str) -> String {
    message
        .replace("invalid type: ", "")
        .replace("expected f64", "expected a number")
        .replace("expected usize", "expected a whole number >= 0")
        .replace("expected u64", "expected a whole number >= 0")
        .replace("expected u32", "expected a whole number >= 0")
        .replace("expected i64", "expected a whole number")
        .replace("expected a boolean", "expected true or false")
}

/// The line (1-based), the table path of the header above `offset` (or on its line) and
/// the key written on `offset`'s line, if any.
fn locate(text: &str, offset: usize) -> (Option<usize>, String, Option<String>) {
    let start = text[..offset].rfind('\n').map_or(0, |i| i + 1);
    let line = text[..start].matches('\n').count() + 1;
    let this_line = text[start..].lines().next().unwrap_or("");
    let table = text[..start]
        .lines()
        .chain(std::iter::once(this_line))
        .filter_map(header)
        .next_back()
        .unwrap_or_default()
        .to_string();
    let key = this_line
        .split_once('=')
        .map(|(k, _)| k.trim().trim_matches('"').to_string())
        .filter(|k| !k.is_empty() && header(this_line).is_none());
    (Some(line), table, key)
}

/// The table path of a `[table]` or `[[array]]` header line.
fn header(line: &str) -> Option<&str> {
    let l = line.trim();
    let inner = l.strip_prefix("[[").or_else(|| l.strip_prefix('['))?;
    Some(inner.split(']').next().unwrap_or("").trim())
}

/// `[body1]` / `[body2]`: the elastic constants.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct MaterialSpec {
    /// Young's modulus \[MPa\], > 0.
    pub e_mpa: f64,
    /// Poisson's ratio, -1 < nu <= 0.5.
    pub nu: f64,
}

/// An elastic material from case-file values, errors named by their keys
/// (`body1.e_mpa`, `body2.nu`); shared by the Hertz and PimP schemas.
pub(crate) fn material_keys(e_mpa: f64, nu: f64, prefix: &str) -> Result<ElasticMaterial> {
    ElasticMaterial::new(e_mpa, nu).map_err(|e| {
        e.map_field(|f| {
            let key = match f {
                "youngs_modulus" => "e_mpa",
                "poisson_ratio" => "nu",
                other => other,
            };
            format!("{prefix}.{key}")
        })
    })
}

/// The material of a `[body1]`/`[body2]` table, errors named `{prefix}.e_mpa`, `{prefix}.nu`.
pub(crate) fn material(m: &MaterialSpec, prefix: &str) -> Result<ElasticMaterial> {
    material_keys(m.e_mpa, m.nu, prefix)
}

/// A path as messages quote it: line breaks and other control characters escaped (`\n`)
/// and a path longer than 80 characters shortened (`… (N characters)`), so that a message
/// stays one readable line (a path `"\n"` and a whole case text passed as a path, found by
/// the Python fuzz harness).
fn one_line(path: &Path) -> String {
    let shown: String = path
        .display()
        .to_string()
        .chars()
        .flat_map(|c| {
            let escaped: Vec<char> = if c.is_control() {
                c.escape_default().collect()
            } else {
                vec![c]
            };
            escaped
        })
        .collect();
    let n = shown.chars().count();
    if n > 80 {
        let head: String = shown.chars().take(60).collect();
        format!("{head}… ({n} characters)")
    } else {
        shown
    }
}
