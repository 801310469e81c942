//! Generators of the fuzz harness (docs/RELIABILITY.md): structure-aware mutations of TOML
//! case files (a value replaced by a hostile one, a key dropped or added, an array grown or
//! cut), text-level mutations, and the number of cases per target. Shared by
//! `kontakt-case/tests/fuzz.rs` and `kontakt-capi/tests/fuzz.rs`
//! (`#[path = ".../support/fuzz_gen.rs"] mod fuzz_gen;`).
#![allow(clippy::unwrap_used)] // tests: a panic is a failure with its message
#![allow(dead_code)] // each including test uses a part

use proptest::prelude::*;
use proptest::test_runner::{Config, FileFailurePersistence};
use toml::Value;

/// The number of generated inputs of a target: `KONTAKT_FUZZ_CASES` when set (the long
/// runs), otherwise `default` (sized for CI's debug test run).
pub fn cases(default: u32) -> u32 {
    std::env::var("KONTAKT_FUZZ_CASES")
        .ok()
        .and_then(|s| s.trim().parse().ok())
        .unwrap_or(default)
}

/// proptest's configuration for a target: `cases(default)` inputs, no failure files
/// (every failure found becomes a named regression test instead), shrinking bounded.
pub fn config(default: u32) -> Config {
    Config {
        cases: cases(default),
        failure_persistence: Some(Box::new(FileFailurePersistence::Off)),
        max_shrink_iters: 2000,
        max_shrink_time: 60_000,
        ..Config::default()
    }
}

/// Floats a hostile or careless user writes: non-finite, signed zeros, subnormals, the
/// extremes of f64, and ordinary values of either sign.
pub fn float() -> impl Strategy<Value = f64> {
    prop_oneof![
        Just(f64::NAN),
        Just(f64::INFINITY),
        Just(f64::NEG_INFINITY),
        Just(0.0),
        Just(-0.0),
        Just(5e-324),
        Just(f64::MIN_POSITIVE),
        Just(1e-300),
        Just(1e300),
        Just(-1e300),
        Just(f64::MAX),
        Just(f64::MIN),
        Just(1e-9),
        Just(0.5),
        Just(1.0),
        Just(-1.0),
        any::<f64>(),
        -1e4..1e4f64,
        -2.0..2.0f64,
    ]
}

/// Integers: the edges of sizes and counts, and the extremes of i64. Sizes between 65
/// and 4096 (valid but slow to solve) are left out so that one input runs in milliseconds;
/// 4097 and above exercise the size limits.
pub fn integer() -> impl Strategy<Value = i64> {
    prop_oneof![
        Just(0i64),
        Just(-1),
        Just(1),
        Just(2),
        Just(3),
        Just(7),
        Just(8),
        Just(4097),
        Just(1 << 31),
        Just(1 << 40),
        Just(i64::MAX),
        Just(i64::MIN),
        Just(1_000_000_000),
        0..40i64,
    ]
}

/// Strings: names of the schema's choices, empty, long, non-ASCII, control characters.
pub fn string() -> impl Strategy<Value = String> {
    prop_oneof![
        prop::sample::select(vec![
            "",
            "hertz",
            "pimp",
            "bem",
            "traction",
            "friction",
            "element",
            "point",
            "line",
            "roller_rib",
            "surfaces",
            "map",
            "hertz",
            "corrected",
            "published",
            "gap",
            "height",
            "free",
            "periodic",
            "von_mises",
            "tresca",
            "log",
            "linear",
            "grid",
            "points",
            "carter",
            "kalker_linear",
            "fastsim",
            "asperity",
            "halfspace",
            "mixed",
            "coulomb",
            "sphere",
            "plane",
            "torus",
            "cylinder",
            "cone",
            "torus-torus-14",
            "sphere-torus-57",
            "parabolic",
            "elliptic",
            "nan",
            "inf",
            "δ😀\u{202e}",
            "a\nb",
            "\0",
            "../../../../../../etc/passwd",
            "/",
            ".",
            "data/wavy_sphere_gap.csv",
        ])
        .prop_map(str::to_string),
        "[a-z_]{0,12}",
        any::<String>(),
        Just("x".repeat(5000)),
    ]
}

/// A TOML value of any type, nested one level at most.
pub fn value() -> impl Strategy<Value = Value> {
    let leaf = prop_oneof![
        4 => float().prop_map(Value::Float),
        3 => integer().prop_map(Value::Integer),
        2 => string().prop_map(Value::String),
        1 => any::<bool>().prop_map(Value::Boolean),
    ];
    prop_oneof![
        6 => leaf.clone(),
        2 => prop::collection::vec(leaf.clone(), 0..5).prop_map(Value::Array),
        1 => Just(Value::Table(toml::Table::new())),
        1 => prop::collection::vec(leaf, 0..3).prop_map(|v| {
            Value::Table(
                v.into_iter()
                    .enumerate()
                    .map(|(i, x)| (["mu", "cells", "force_n", "x"][i % 4].to_string(), x))
                    .collect(),
            )
        }),
    ]
}

/// One structure-aware edit of a TOML document. Paths are chosen by index into the
/// document's own paths (modulo their number), so every edit applies.
#[derive(Debug, Clone)]
pub enum Edit {
    /// Replace the value at a path (a leaf, an array or a table) by another.
    Set(usize, Value),
    /// Scale a number at a path (keeps the type; integers saturate).
    Scale(usize, f64),
    /// Replace a number by another of its type (float by float, integer by integer), the
    /// edit that reaches the solvers; the path picks among the numbers only.
    Number(usize, f64, i64),
    /// Drop the key or array element at a path.
    Remove(usize),
    /// Add a key (a known key name or a made-up one) to a table.
    Add(usize, String, Value),
    /// Grow an array by repeating its last element, or cut it to one element.
    Resize(usize, bool),
}

/// Key names of every schema, to add where they do not belong.
pub const KEYS: &[&str] = &[
    "name",
    "method",
    "models",
    "kind",
    "angle_deg",
    "radii_mm",
    "e_mpa",
    "nu",
    "force_n",
    "approach_mm",
    "stress_mpa",
    "criterion",
    "length_mm",
    "pairing",
    "cells",
    "mode",
    "file",
    "spacing_mm",
    "values",
    "boundary",
    "shape",
    "radius_mm",
    "origin_mm",
    "axis",
    "major_mm",
    "minor_mm",
    "mu",
    "max",
    "points",
    "elements",
    "pressure",
    "count",
    "min_rpm",
    "max_rpm",
    "spacing",
    "iso_vg",
    "backend",
    "max_approach_ratio",
    "threads",
    "tolerance",
    "max_iterations",
    "chunk_size",
    "max_cases",
    "base",
    "key",
    "start",
    "stop",
    "unknown_key",
];

pub fn edit() -> impl Strategy<Value = Edit> {
    prop_oneof![
        4 => (any::<usize>(), value()).prop_map(|(p, v)| Edit::Set(p, v)),
        8 => (any::<usize>(), float(), integer()).prop_map(|(p, f, i)| Edit::Number(p, f, i)),
        2 => (any::<usize>(), prop_oneof![Just(0.0), Just(-1.0), Just(1e-3), Just(1e3), Just(1e12), Just(1e-12), Just(-1e300), Just(1.000001)])
            .prop_map(|(p, f)| Edit::Scale(p, f)),
        2 => any::<usize>().prop_map(Edit::Remove),
        1 => (any::<usize>(), prop::sample::select(KEYS).prop_map(str::to_string), value())
            .prop_map(|(p, k, v)| Edit::Add(p, k, v)),
        1 => (any::<usize>(), any::<bool>()).prop_map(|(p, g)| Edit::Resize(p, g)),
    ]
}

/// A step of a path: a table key or an array index.
#[derive(Debug, Clone)]
enum Step {
    Key(String),
    Index(usize),
}

fn paths(v: &Value, path: &mut Vec<Step>, out: &mut Vec<Vec<Step>>) {
    out.push(path.clone());
    match v {
        Value::Table(t) => {
            for (k, x) in t {
                path.push(Step::Key(k.clone()));
                paths(x, path, out);
                path.pop();
            }
        }
        Value::Array(a) => {
            for (i, x) in a.iter().enumerate() {
                path.push(Step::Index(i));
                paths(x, path, out);
                path.pop();
            }
        }
        _ => {}
    }
}

fn at<'a>(v: &'a mut Value, path: &[Step]) -> &'a mut Value {
    match path.split_first() {
        None => v,
        Some((Step::Key(k), rest)) => at(v.as_table_mut().unwrap().get_mut(k).unwrap(), rest),
        Some((Step::Index(i), rest)) => at(&mut v.as_array_mut().unwrap()[*i], rest),
    }
}

fn get<'a>(v: &'a Value, path: &[Step]) -> &'a Value {
    match path.split_first() {
        None => v,
        Some((Step::Key(k), rest)) => get(&v.as_table().unwrap()[k], rest),
        Some((Step::Index(i), rest)) => get(&v.as_array().unwrap()[*i], rest),
    }
}

/// Apply `edits` to the document `doc` in order.
pub fn apply(doc: &mut Value, edits: &[Edit]) {
    for e in edits {
        let mut all = Vec::new();
        paths(doc, &mut Vec::new(), &mut all);
        let pick = |i: usize| all[i % all.len()].clone();
        match e {
            Edit::Set(i, v) => {
                let p = pick(*i);
                if !p.is_empty() {
                    *at(doc, &p) = v.clone();
                }
            }
            Edit::Scale(i, f) => {
                let p = pick(*i);
                let x = at(doc, &p);
                match x {
                    Value::Float(y) => *y *= f,
                    Value::Integer(n) => *n = (*n as f64 * f) as i64,
                    _ => {}
                }
            }
            Edit::Number(i, f, n) => {
                let numbers: Vec<_> = all
                    .iter()
                    .filter(|p| matches!(get(doc, p), Value::Float(_) | Value::Integer(_)))
                    .cloned()
                    .collect();
                if let Some(p) = numbers.get(i % numbers.len().max(1)) {
                    match at(doc, p) {
                        Value::Float(y) => *y = *f,
                        Value::Integer(y) => *y = *n,
                        _ => {}
                    }
                }
            }
            Edit::Remove(i) => {
                let p = pick(*i);
                if let Some((last, parent)) = p.split_last() {
                    match (at(doc, parent), last) {
                        (Value::Table(t), Step::Key(k)) => {
                            t.remove(k);
                        }
                        (Value::Array(a), Step::Index(j)) => {
                            a.remove(*j);
                        }
                        _ => {}
                    }
                }
            }
            Edit::Add(i, k, v) => {
                let p = pick(*i);
                if let Value::Table(t) = at(doc, &p) {
                    t.insert(k.clone(), v.clone());
                }
            }
            Edit::Resize(i, grow) => {
                let p = pick(*i);
                if let Value::Array(a) = at(doc, &p) {
                    if *grow {
                        if let Some(last) = a.last().cloned() {
                            a.push(last);
                        }
                    } else {
                        a.truncate(1);
                    }
                }
            }
        }
    }
}

/// TOML text of `doc`; `None` when the writer cannot write it (e.g. a table inside an
/// array of values after an edit).
pub fn to_text(doc: &Value) -> Option<String> {
    match doc {
        Value::Table(t) => toml::to_string(t).ok(),
        _ => None,
    }
}

/// A text-level edit: bytes of TOML syntax or hostile numbers spliced in at a position.
pub fn splice() -> impl Strategy<Value = (usize, usize, String)> {
    (
        any::<usize>(),
        0..8usize,
        prop_oneof![
            prop::sample::select(vec![
                "[",
                "]",
                "[[",
                "]]",
                "=",
                "\"",
                "'",
                "\n",
                "#",
                ",",
                ".",
                "{",
                "}",
                " = nan",
                "= inf",
                "= -inf",
                "1e999",
                "-0.0",
                "99999999999999999999999",
                "0x7fffffffffffffff",
                "[load]\nforce_n = 1.0\n",
                "[body1]\n",
                "\n[contact]\n",
                "\u{feff}",
                "δ",
                "\r\n",
                "\"\"\"",
                "5e-324",
                "-1",
                "true",
                "[]",
                "[1,2,3]",
                "= [inf, nan]",
            ])
            .prop_map(str::to_string),
            any::<String>(),
        ],
    )
}

/// Replace `len` bytes of `text` at `pos` (both taken modulo the text, moved to character
/// boundaries) by `with`.
pub fn splice_text(text: &str, pos: usize, len: usize, with: &str) -> String {
    let mut start = pos % (text.len() + 1);
    while !text.is_char_boundary(start) {
        start -= 1;
    }
    let mut end = (start + len).min(text.len());
    while !text.is_char_boundary(end) {
        end += 1;
    }
    format!("{}{with}{}", &text[..start], &text[end..])
}

/// Whether a number anywhere in `v` (a report as TOML values) is NaN or infinite; the
/// path of the first one.
pub fn non_finite(v: &Value, path: &str) -> Option<String> {
    match v {
        Value::Float(x) if !x.is_finite() => Some(format!("{path} = {x}")),
        Value::Table(t) => t
            .iter()
            .find_map(|(k, x)| non_finite(x, &format!("{path}.{k}"))),
        Value::Array(a) => a
            .iter()
            .enumerate()
            .find_map(|(i, x)| non_finite(x, &format!("{path}[{i}]"))),
        _ => None,
    }
}
