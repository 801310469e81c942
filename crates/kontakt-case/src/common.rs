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
/// the full key path (`geometry.face.radius_mm`) and a message in the schema's words. Keys
/// that the schema does not hold are refused (see [`check_consumed`]), in every table.
pub(crate) fn parse_toml<T: serde::de::DeserializeOwned + Serialize>(text: &str) -> Result<T> {
    let value: T = toml::from_str(text).map_err(|e| case_file_error::<T>(text, &e))?;
    let table: toml::Table = toml::from_str(text).map_err(|e| case_file_error::<T>(text, &e))?;
    check_consumed(&table, &value, Some(text))?;
    Ok(value)
}

/// [`parse_toml`] for an already parsed table (a sweep's edited base case): the same
/// messages, without line numbers.
pub(crate) fn parse_table<T: serde::de::DeserializeOwned + Serialize>(
    table: toml::Table,
) -> Result<T> {
    let value: T = table
        .clone()
        .try_into()
        .map_err(|e: toml::de::Error| located_error::<T>(&table, None, &e))?;
    check_consumed(&table, &value, None)?;
    Ok(value)
}

/// Refuse a key of `input` that the parsed `value` does not hold.
///
/// serde's `deny_unknown_fields` does not reach every table: a unit variant of an
/// internally tagged enum (`[geometry.rib] shape = "cone"`) takes any keys beside its tag,
/// and a struct without the attribute skips them. Serializing what was read and comparing
/// its keys with the file's closes the gap structurally: whatever the schema did not
/// consume is an unknown key, named by its full path with the keys its table takes.
/// (A schema whose value cannot be serialized as TOML is not checked here; every case
/// schema can, which the key-walk test proves.)
fn check_consumed<T: Serialize>(input: &toml::Table, value: &T, text: Option<&str>) -> Result<()> {
    let Ok(toml::Value::Table(read)) = toml::Value::try_from(value) else {
        return Ok(());
    };
    let mut path = Vec::new();
    let Some((path, takes)) = unconsumed(input, &read, &mut path) else {
        return Ok(());
    };
    let place = match path.split_last() {
        Some((_, parent)) if !parent.is_empty() => format!("[{}]", show_path(parent)),
        _ => "the top level".to_string(),
    };
    let takes = if takes.is_empty() {
        "no other keys".to_string()
    } else {
        takes
            .iter()
            .map(|k| format!("`{k}`"))
            .collect::<Vec<_>>()
            .join(", ")
    };
    let shown = show_path(&path);
    Err(Error::CaseFile {
        line: text.and_then(|t| SpanIndex::new(t).line_of(&path)),
        key: shown.clone().into(),
        message: one_line_text(&format!("unknown key `{shown}`; {place} takes {takes}")),
    })
}

/// The first key path of `input` missing from `read`, with the keys of its table in `read`.
fn unconsumed(
    input: &toml::Table,
    read: &toml::Table,
    path: &mut Vec<Seg>,
) -> Option<(Vec<Seg>, Vec<String>)> {
    for (k, v) in input {
        path.push(Seg::Key(k.clone()));
        let Some(r) = read.get(k) else {
            return Some((path.clone(), read.keys().cloned().collect()));
        };
        if let Some(found) = unconsumed_value(v, r, path) {
            return Some(found);
        }
        path.pop();
    }
    None
}

fn unconsumed_value(
    v: &toml::Value,
    r: &toml::Value,
    path: &mut Vec<Seg>,
) -> Option<(Vec<Seg>, Vec<String>)> {
    match (v, r) {
        (toml::Value::Table(v), toml::Value::Table(r)) => unconsumed(v, r, path),
        (toml::Value::Array(v), toml::Value::Array(r)) => {
            for (i, (v, r)) in v.iter().zip(r).enumerate() {
                path.push(Seg::Index(i));
                if let Some(found) = unconsumed_value(v, r, path) {
                    return Some(found);
                }
                path.pop();
            }
            None
        }
        _ => None,
    }
}

/// One step of a key path: a table key or an array index.
#[derive(Debug, Clone, PartialEq)]
enum Seg {
    Key(String),
    Index(usize),
}

/// A key path as a case file spells it: `geometry.face.radius_mm`, `parameter[1].key`.
fn show_path(path: &[Seg]) -> String {
    let mut s = String::new();
    for seg in path {
        match seg {
            Seg::Key(k) if s.is_empty() => s.push_str(k),
            Seg::Key(k) => {
                s.push('.');
                s.push_str(k);
            }
            Seg::Index(i) => s.push_str(&format!("[{i}]")),
        }
    }
    s
}

/// Where each key and value of a TOML text stands: key path, the key's span and the
/// value's span (inline tables, dotted keys and arrays of tables included).
struct SpanIndex<'t> {
    text: &'t str,
    entries: Vec<(Vec<Seg>, std::ops::Range<usize>, std::ops::Range<usize>)>,
}

impl<'t> SpanIndex<'t> {
    fn new(text: &'t str) -> Self {
        let mut entries = Vec::new();
        if let Ok(doc) = toml::de::DeTable::parse(text) {
            index_table(doc.get_ref(), &mut Vec::new(), &mut entries);
        }
        SpanIndex { text, entries }
    }

    /// The deepest key path whose key or value holds `offset`.
    fn path_at(&self, offset: usize) -> Option<Vec<Seg>> {
        let holds =
            |r: &std::ops::Range<usize>| r.start <= offset && offset < r.end.max(r.start + 1);
        self.entries
            .iter()
            .filter(|(_, k, v)| holds(k) || holds(v))
            .max_by_key(|(p, _, _)| p.len())
            .map(|(p, _, _)| p.clone())
    }

    /// The line (1-based) of the key at `path`, or of the nearest table above it.
    fn line_of(&self, path: &[Seg]) -> Option<usize> {
        (0..=path.len()).rev().find_map(|n| {
            let (_, k, _) = self.entries.iter().find(|(p, _, _)| p == &path[..n])?;
            Some(line_at(self.text, k.start))
        })
    }
}

fn index_table(
    table: &toml::de::DeTable<'_>,
    path: &mut Vec<Seg>,
    out: &mut Vec<(Vec<Seg>, std::ops::Range<usize>, std::ops::Range<usize>)>,
) {
    for (k, v) in table.iter() {
        path.push(Seg::Key(k.get_ref().to_string()));
        out.push((path.clone(), k.span(), v.span()));
        match v.get_ref() {
            toml::de::DeValue::Table(t) => index_table(t, path, out),
            toml::de::DeValue::Array(a) => {
                for (i, e) in a.iter().enumerate() {
                    path.push(Seg::Index(i));
                    // An element has no key of its own: only its value's span is its.
                    out.push((path.clone(), e.span(), e.span()));
                    if let toml::de::DeValue::Table(t) = e.get_ref() {
                        index_table(t, path, out);
                    }
                    path.pop();
                }
            }
            _ => {}
        }
        path.pop();
    }
}

/// The line (1-based) of byte `offset` in `text`.
fn line_at(text: &str, offset: usize) -> usize {
    text[..offset.min(text.len())].matches('\n').count() + 1
}

/// [`Error::CaseFile`] from a TOML reader's error on `text`, read as a `T`.
///
/// A file that is not TOML at all says so ("not valid TOML: ..."). Otherwise the error is
/// about the schema, and the key path is found as described at [`located_error`].
pub(crate) fn case_file_error<T: serde::de::DeserializeOwned>(
    text: &str,
    e: &toml::de::Error,
) -> Error {
    match text.parse::<toml::Table>() {
        Err(_) => Error::CaseFile {
            line: e.span().map(|s| line_at(text, s.start)),
            key: "case".into(),
            message: one_line_text(&format!("not valid TOML: {}", e.message().trim())),
        },
        Ok(table) => located_error::<T>(&table, Some(text), e),
    }
}

/// Control characters escaped, so that a message quoting the file's strings
/// (`kind = "a\nb"`, found by fuzzing) stays on one line.
fn one_line_text(message: &str) -> String {
    if message.chars().any(char::is_control) {
        message.chars().flat_map(char::escape_default).collect()
    } else {
        message.to_string()
    }
}

/// [`Error::CaseFile`] for the reader's error `e` on the document `doc` (with its `text`
/// when there is one, for the line).
///
/// The reader's position names the key only where serde read the value directly. Inside a
/// tagged table (`[geometry]` by its `kind`, `[geometry.face]` by its `shape`) serde reads
/// the whole table first and its error points at the table. The key is then found by
/// asking the schema: the table holding the unknown key whose removal changes the error,
/// the table lacking the missing key where adding it does, the value whose removal does.
/// serde's wording ("field", "f64") becomes the schema's ("key", "a number").
fn located_error<T: serde::de::DeserializeOwned>(
    doc: &toml::Table,
    text: Option<&str>,
    e: &toml::de::Error,
) -> Error {
    let index = text.map(SpanIndex::new);
    let at = match (&index, e.span()) {
        (Some(index), Some(span)) => index.path_at(span.start).unwrap_or_default(),
        _ => Vec::new(),
    };
    let message = e.message().trim();
    let trial = |d: &toml::Table| -> Option<String> {
        d.clone()
            .try_into::<T>()
            .err()
            .map(|e: toml::de::Error| e.message().trim().to_string())
    };
    let unknown = message
        .strip_prefix("unknown field ")
        .map(|rest| split_expected(rest));
    let missing = message
        .strip_prefix("missing field ")
        .map(|rest| rest.trim().trim_matches('`'));
    let path = match (unknown, missing) {
        (Some((name, _)), _) => {
            let name = name.trim_matches('`');
            if matches!(at.last(), Some(Seg::Key(k)) if k == name) {
                at.clone()
            } else {
                find_unknown(doc, &at, name, &trial)
            }
        }
        (_, Some(name)) => find_missing(doc, &at, name, &trial),
        _ => find_bad_value(doc, &at, message, &trial),
    };
    let shown = if path.is_empty() {
        "case".to_string()
    } else {
        show_path(&path)
    };
    let message = if let Some((_, valid)) = unknown {
        let place = match path.split_last() {
            Some((_, parent)) if !parent.is_empty() => format!("[{}]", show_path(parent)),
            _ => "the top level".to_string(),
        };
        let takes = valid.unwrap_or("no keys");
        format!("unknown key `{shown}`; {place} takes {takes}")
    } else if missing.is_some() {
        format!("missing key `{shown}`")
    } else if let Some(rest) = message.strip_prefix("unknown variant ") {
        let (name, valid) = rest
            .split_once(", expected ")
            .unwrap_or((rest, "another value"));
        format!("`{shown}` = {name}: expected {valid}")
    } else {
        format!("`{shown}`: {}", schema_words(message))
    };
    Error::CaseFile {
        line: index
            .as_ref()
            .and_then(|i| i.line_of(&path))
            .or_else(|| text.zip(e.span()).map(|(t, s)| line_at(t, s.start))),
        key: shown.into(),
        message: one_line_text(&message),
    }
}

/// The value at `path` in `doc`.
fn node_mut<'a>(doc: &'a mut toml::Table, path: &[Seg]) -> Option<&'a mut toml::Value> {
    let (Seg::Key(first), rest) = path.split_first()? else {
        return None;
    };
    let mut v = doc.get_mut(first)?;
    for seg in rest {
        v = match (seg, v) {
            (Seg::Key(k), toml::Value::Table(t)) => t.get_mut(k)?,
            (Seg::Index(i), toml::Value::Array(a)) => a.get_mut(*i)?,
            _ => return None,
        };
    }
    Some(v)
}

/// The table at `path` (the document itself for the empty path).
fn table_mut<'a>(doc: &'a mut toml::Table, path: &[Seg]) -> Option<&'a mut toml::Table> {
    if path.is_empty() {
        return Some(doc);
    }
    node_mut(doc, path)?.as_table_mut()
}

/// The values of a document that are not tables, with their paths.
type Leaves = Vec<(Vec<Seg>, toml::Value)>;

/// Every table path in `doc` at or below `at`, and every other value's path (leaves),
/// deepest first (then in the document's order).
fn below(doc: &toml::Table, at: &[Seg]) -> (Vec<Vec<Seg>>, Leaves) {
    fn walk(v: &toml::Value, path: &mut Vec<Seg>, tables: &mut Vec<Vec<Seg>>, leaves: &mut Leaves) {
        match v {
            toml::Value::Table(t) => {
                tables.push(path.clone());
                for (k, x) in t {
                    path.push(Seg::Key(k.clone()));
                    walk(x, path, tables, leaves);
                    path.pop();
                }
            }
            toml::Value::Array(a) if a.iter().any(toml::Value::is_table) => {
                for (i, x) in a.iter().enumerate() {
                    path.push(Seg::Index(i));
                    walk(x, path, tables, leaves);
                    path.pop();
                }
            }
            other => leaves.push((path.clone(), other.clone())),
        }
    }
    let mut doc = doc.clone();
    let (mut tables, mut leaves) = (Vec::new(), Vec::new());
    if let Some(v) = node_mut(&mut doc, at) {
        walk(v, &mut at.to_vec(), &mut tables, &mut leaves);
    } else {
        walk(
            &toml::Value::Table(doc),
            &mut Vec::new(),
            &mut tables,
            &mut leaves,
        );
    }
    tables.sort_by_key(|p| std::cmp::Reverse(p.len()));
    leaves.sort_by_key(|(p, _)| std::cmp::Reverse(p.len()));
    (tables, leaves)
}

/// The path of the unknown key `name` at or below `at`: the one table holding it, or the
/// one whose removal of it changes the error.
fn find_unknown(
    doc: &toml::Table,
    at: &[Seg],
    name: &str,
    trial: &dyn Fn(&toml::Table) -> Option<String>,
) -> Vec<Seg> {
    let (tables, _) = below(doc, at);
    let holding: Vec<_> = tables
        .into_iter()
        .filter(|t| table_mut(&mut doc.clone(), t).is_some_and(|t| t.contains_key(name)))
        .collect();
    if let [only] = holding.as_slice() {
        let mut path = only.clone();
        path.push(Seg::Key(name.to_string()));
        return path;
    }
    let before = trial(doc);
    let changed = |after: &Option<String>| after != &before;
    find_table(
        doc,
        at,
        name,
        &|t| t.remove(name).is_some(),
        &changed,
        trial,
    )
}

/// The path of the missing key `name` at or below `at`: the table lacking it where adding
/// it changes the error (to anything but "unknown field").
fn find_missing(
    doc: &toml::Table,
    at: &[Seg],
    name: &str,
    trial: &dyn Fn(&toml::Table) -> Option<String>,
) -> Vec<Seg> {
    let before = trial(doc);
    let refused = format!("unknown field `{name}`");
    let add = |t: &mut toml::Table| {
        t.insert(name.to_string(), toml::Value::String(String::new()))
            .is_none()
    };
    let changed = |after: &Option<String>| {
        after != &before && !after.as_ref().is_some_and(|m| m.starts_with(&refused))
    };
    // A missing key belongs to a table: when the error's span points at a value (the
    // line of `method = "bearing"` for a missing `[bearing]`), look from its table.
    let mut at = at.to_vec();
    while !at.is_empty() && table_mut(&mut doc.clone(), &at).is_none() {
        at.pop();
    }
    find_table(doc, &at, name, &add, &changed, trial)
}

/// `name`'s path in the first table at or below `at` (deepest first) where `edit` applies
/// and the error of the edited document passes `changed`; at `at` when there is none.
fn find_table(
    doc: &toml::Table,
    at: &[Seg],
    name: &str,
    edit: &dyn Fn(&mut toml::Table) -> bool,
    changed: &dyn Fn(&Option<String>) -> bool,
    trial: &dyn Fn(&toml::Table) -> Option<String>,
) -> Vec<Seg> {
    let (tables, _) = below(doc, at);
    let found = tables.into_iter().find(|t| {
        let mut d = doc.clone();
        table_mut(&mut d, t).is_some_and(edit) && changed(&trial(&d))
    });
    let mut path = found.unwrap_or_else(|| at.to_vec());
    path.push(Seg::Key(name.to_string()));
    path
}

/// The path of the value at or below `at` that `message` is about: the values the message
/// quotes first, the one whose removal changes the error.
fn find_bad_value(
    doc: &toml::Table,
    at: &[Seg],
    message: &str,
    trial: &dyn Fn(&toml::Table) -> Option<String>,
) -> Vec<Seg> {
    let (_, mut leaves) = below(doc, at);
    if leaves.len() <= 1 && !matches!(node_mut(&mut doc.clone(), at), Some(toml::Value::Table(_))) {
        return at.to_vec();
    }
    // the value serde quotes is before ", expected ...": a valid name listed after it
    // (`slice_model = "fem"`: expected `iso` or `coupled`) is not the bad value
    let message = message
        .split_once(", expected ")
        .map_or(message, |(m, _)| m);
    let quoted = |v: &toml::Value| match v {
        toml::Value::String(s) => {
            message.contains(&format!("{s:?}")) || message.contains(&format!("`{s}`"))
        }
        toml::Value::Integer(i) => message.contains(&format!("`{i}`")),
        toml::Value::Float(x) => {
            message.contains(&format!("`{x}`")) || message.contains(&format!("`{x:?}`"))
        }
        toml::Value::Boolean(b) => message.contains(&format!("`{b}`")),
        toml::Value::Array(_) => message.contains("sequence"),
        _ => false,
    };
    leaves.sort_by_key(|(_, v)| !quoted(v));
    let before = trial(doc);
    leaves
        .into_iter()
        .map(|(p, _)| p)
        .find(|p| {
            let mut d = doc.clone();
            let removed = match p.split_last() {
                Some((Seg::Key(k), parent)) => table_mut(&mut d, parent).and_then(|t| t.remove(k)),
                _ => None,
            };
            removed.is_some() && trial(&d) != before
        })
        .unwrap_or_else(|| at.to_vec())
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
    let mut m = message
        .replace("invalid type: ", "")
        .replace("invalid value: ", "")
        .replace("expected f64", "expected a number")
        .replace("expected usize", "expected a whole number >= 0")
        .replace("expected u64", "expected a whole number >= 0")
        .replace("expected u32", "expected a whole number >= 0")
        .replace("expected i64", "expected a whole number")
        .replace("expected a boolean", "expected true or false")
        .replace("expected a sequence", "expected an array")
        .replace("sequence", "array")
        .replace("map,", "table,");
    // serde names the Rust type of a table ("expected internally tagged enum FaceShape",
    // "expected struct MaterialSpec"): a case file has tables.
    for prefix in ["expected internally tagged enum ", "expected struct "] {
        if let Some(i) = m.find(prefix) {
            let end = m[i + prefix.len()..]
                .find(|c: char| !c.is_alphanumeric() && c != '_')
                .map_or(m.len(), |j| i + prefix.len() + j);
            m.replace_range(i..end, "expected a table");
        }
    }
    m
}

/// `[body1]` / `[body2]`: the elastic constants.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize, schemars::JsonSchema)]
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

/// An error about the library's angle `field` \[rad\], said as the case file's key `key` in
/// degrees: the value the file gives and the range in degrees. (`half_angle_deg = 90` was
/// reported as `1.5707963267948966` against a range in radians, found by probing.)
pub(crate) fn in_degrees(e: Error, field: &str, key: &str, typed_deg: f64) -> Error {
    match e {
        Error::InvalidInput {
            field: f, expected, ..
        } if f == field => Error::invalid(key.to_string(), typed_deg, degrees_text(&expected)),
        other => other,
    }
}

/// A range in radians (`(0, pi/2) rad`, `a finite angle [rad]`) in degrees.
fn degrees_text(text: &str) -> String {
    let mut out = text
        .replace("pi/2", "90")
        .replace("2 pi", "360")
        .replace("pi", "180")
        .replace("[rad]", "[deg]");
    // " rad" as a word ("rad," "rad)" or at the end), not the start of "radius".
    let mut i = 0;
    while let Some(j) = out[i..].find(" rad") {
        let at = i + j;
        let after = out[at + 4..].chars().next();
        if after.is_none_or(|c| !c.is_alphabetic()) {
            out.replace_range(at..at + 4, " deg");
        }
        i = at + 4;
    }
    out
}
