//! Fuzz harness of the case layer (docs/RELIABILITY.md): generated inputs thrown at every
//! parser and entry point of `kontakt-case`: case files of every schema (`Case`), element
//! cases, sweep files and gap maps (CSV and `.npy`). Structure-aware mutations of the files
//! in `examples/` (values replaced by NaN, ±inf, subnormals, 1e±300, extreme integers,
//! wrong types, long or non-ASCII strings; keys dropped or added; arrays grown or cut),
//! text-level splices and random text.
//!
//! Properties: never a panic; every error has a non-empty one-line message; every report
//! that comes back holds finite numbers only.
//!
//! `KONTAKT_FUZZ_CASES=N` runs N inputs per target (the long runs of docs/RELIABILITY.md);
//! the defaults keep the debug test run of this file within about half a minute.

#![allow(clippy::unwrap_used)] // tests: a panic is a failure with its message

#[path = "support/fuzz_gen.rs"]
mod fuzz_gen;
#[path = "support/toml_keys.rs"]
#[allow(dead_code)] // only the listing of case files is used here
mod toml_keys;

use fuzz_gen::{Edit, apply, config, edit, non_finite, splice, splice_text, to_text};
use kontakt::gap::MapKind;
use kontakt_case::maps::read_gap_map;
use kontakt_case::{Case, Sweep, element_from_toml};
use proptest::prelude::*;
use std::path::{Path, PathBuf};
use toml::Value;

fn root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../..")
}

fn examples() -> PathBuf {
    root().join("examples")
}

/// The seeds: every case file in `examples/`, as TOML documents, with the grids and point
/// counts cut so that one run takes milliseconds in a debug build.
fn case_seeds() -> &'static [Value] {
    static SEEDS: std::sync::OnceLock<Vec<Value>> = std::sync::OnceLock::new();
    SEEDS.get_or_init(|| {
        let seeds = small_toml_files(&examples());
        assert!(seeds.len() >= 10, "{} seeds", seeds.len());
        seeds
    })
}

/// The `.toml` files of `dir`, sorted by name.
fn toml_paths(dir: &Path) -> Vec<PathBuf> {
    toml_keys::toml_files(dir)
}

/// Every `.toml` file of `dir`, sorted by name, parsed and cut by [`small`].
fn small_toml_files(dir: &Path) -> Vec<Value> {
    toml_paths(dir)
        .iter()
        .map(|f| {
            small(
                std::fs::read_to_string(f)
                    .unwrap()
                    .parse::<toml::Table>()
                    .unwrap(),
            )
        })
        .collect()
}

/// `doc` with smaller grids and fewer points (same schema, same keys).
fn small(mut t: toml::Table) -> Value {
    let cells = Value::Array(vec![Value::Integer(12), Value::Integer(12)]);
    for table in ["pimp", "bem", "element"] {
        if let Some(Value::Table(s)) = t.get_mut(table)
            && s.contains_key("cells")
        {
            s.insert("cells".into(), cells.clone());
        }
    }
    if let Some(Value::Table(s)) = t.get_mut("creepage") {
        s.insert("points".into(), Value::Integer(9));
    }
    for table in ["fastsim", "kalker_exact"] {
        if let Some(Value::Table(s)) = t.get_mut(table) {
            s.insert("elements".into(), Value::Array(vec![Value::Integer(8); 2]));
        }
    }
    if let Some(Value::Table(s)) = t.get_mut("speed") {
        s.insert("points".into(), Value::Integer(2));
    }
    if let Some(Value::Array(m)) = t.get_mut("models") {
        // the half-space model of the friction cases solves a grid per speed
        m.retain(|x| x.as_str() != Some("halfspace"));
    }
    Value::Table(t)
}

fn element_seeds() -> Vec<Value> {
    small_toml_files(&root().join("crates/kontakt-capi/examples"))
}

fn sweep_seeds() -> Vec<String> {
    ["hertz_load.toml", "pimp_roller_rib.toml"]
        .iter()
        .map(|f| std::fs::read_to_string(examples().join("sweeps").join(f)).unwrap())
        .collect()
}

/// An error's message: non-empty, one line.
fn check_message(what: &str, message: &str) {
    assert!(!message.trim().is_empty(), "{what}: empty error message");
    assert!(
        !message.contains('\n') && !message.contains('\r'),
        "{what}: error message of several lines: {message:?}"
    );
}

/// A report: no NaN or infinity among its numbers. (JSON writes null for them, so the
/// report is looked at as TOML values, which keep them; its strings may hold any text.)
fn check_report<T: serde::Serialize>(report: &T) {
    serde_json::to_string(report).unwrap();
    if let Ok(v) = Value::try_from(report)
        && let Some(at) = non_finite(&v, "report")
    {
        panic!("non-finite number in the report: {at}");
    }
}

/// Parse `text` as a case of any method; run it when it reads.
fn parse_and_run(text: &str) {
    match Case::from_toml_str(text) {
        Err(e) => check_message("Case::from_toml_str", &e.to_string()),
        Ok(case) => match case.run(&examples()) {
            Err(e) => check_message("Case::run", &e.to_string()),
            Ok(outcome) => check_report(&outcome),
        },
    }
}

fn mutated(seeds: &[Value], seed: usize, edits: &[Edit]) -> Option<String> {
    let mut doc = seeds[seed % seeds.len()].clone();
    apply(&mut doc, edits);
    to_text(&doc)
}

proptest! {
    #![proptest_config(config(10_000))]

    /// Case files of every schema, edited structurally, parsed and run.
    #[test]
    fn case_files_edited(seed in any::<usize>(), edits in prop::collection::vec(edit(), 1..4)) {
        if let Some(text) = mutated(case_seeds(), seed, &edits) {
            parse_and_run(&text);
        }
    }
}

proptest! {
    #![proptest_config(config(10_000))]

    /// Case files with text spliced in (broken syntax, duplicated tables, hostile numbers).
    #[test]
    fn case_files_spliced(seed in any::<usize>(), splices in prop::collection::vec(splice(), 1..4)) {
        let seeds = case_seeds();
        let mut text = to_text(&seeds[seed % seeds.len()]).unwrap();
        for (pos, len, with) in &splices {
            text = splice_text(&text, *pos, *len, with);
        }
        parse_and_run(&text);
    }

    /// Random text.
    #[test]
    fn case_files_random_text(text in any::<String>()) {
        parse_and_run(&text);
    }
}

proptest! {
    #![proptest_config(config(2_000))]

    /// Element cases (`method = "element"`), edited: planned, never a panic.
    #[test]
    fn element_cases_edited(seed in any::<usize>(), edits in prop::collection::vec(edit(), 1..4)) {
        if let Some(text) = mutated(&element_seeds(), seed, &edits)
            && let Err(e) = element_from_toml(&text)
        {
            check_message("element_from_toml", &e.to_string());
        }
    }

    /// Sweep files, edited (the parameters, the limits, the base path or an inline base):
    /// read, and the first and last cases run.
    #[test]
    fn sweep_files_edited(seed in any::<usize>(), inline in any::<bool>(), edits in prop::collection::vec(edit(), 1..4)) {
        let seeds = sweep_seeds();
        let mut doc = Value::Table(seeds[seed % seeds.len()].parse::<toml::Table>().unwrap());
        if inline {
            // the base case inline, small, so that the edits reach into it too
            let t = doc.as_table_mut().unwrap();
            let base = t["base"].as_str().unwrap().trim_start_matches("../").to_string();
            let i = case_seeds_names().iter().position(|n| *n == base).unwrap();
            t.insert("base".into(), case_seeds()[i].clone());
        }
        apply(&mut doc, &edits);
        let Some(text) = to_text(&doc) else { return Ok(()) };
        match Sweep::from_toml_str(&text, &examples().join("sweeps")) {
            Err(e) => check_message("Sweep::from_toml_str", &e.to_string()),
            Ok(sweep) => {
                for i in [0, sweep.len() - 1] {
                    match sweep.case(i) {
                        Err(e) => check_message("Sweep::case", &e.to_string()),
                        Ok(case) => match case.run(sweep.base_dir()) {
                            Err(e) => check_message("Case::run", &e.to_string()),
                            Ok(outcome) => check_report(&outcome),
                        },
                    }
                }
            }
        }
    }
}

fn case_seeds_names() -> Vec<String> {
    toml_paths(&examples())
        .iter()
        .map(|p| p.file_name().unwrap().to_string_lossy().into_owned())
        .collect()
}

/// A `.npy` file: the magic, a version, the header dictionary (free text here) and data.
fn npy(version: u8, dict: &str, data: &[u8]) -> Vec<u8> {
    let mut out = b"\x93NUMPY".to_vec();
    out.push(version);
    out.push(0);
    let mut header = dict.as_bytes().to_vec();
    header.push(b'\n');
    if version == 1 {
        out.extend_from_slice(&(header.len() as u16).to_le_bytes());
    } else {
        out.extend_from_slice(&(header.len() as u32).to_le_bytes());
    }
    out.extend_from_slice(&header);
    out.extend_from_slice(data);
    out
}

fn npy_file() -> impl Strategy<Value = Vec<u8>> {
    let descr = prop::sample::select(vec![
        "<f8",
        ">f8",
        "<f4",
        "<f2",
        "<i8",
        "<u1",
        "|b1",
        "<c16",
        "|O",
        "<U8",
        "[('a', '<f8')]",
        "",
    ]);
    let dim = prop_oneof![
        Just(0u64),
        Just(1),
        Just(2),
        Just(3),
        Just(8),
        Just(1 << 20),
        Just(1 << 32),
        Just(u64::MAX / 2),
        Just(u64::MAX),
        0..12u64,
    ];
    let shape = prop::collection::vec(dim, 0..4).prop_map(|d| {
        let inner: Vec<String> = d.iter().map(u64::to_string).collect();
        if inner.len() == 1 {
            format!("({},)", inner[0])
        } else {
            format!("({})", inner.join(", "))
        }
    });
    let data = prop_oneof![
        prop::collection::vec(any::<u8>(), 0..200),
        prop::collection::vec(fuzz_gen::float(), 0..40)
            .prop_map(|v| v.iter().flat_map(|x| x.to_le_bytes()).collect()),
    ];
    (
        prop_oneof![Just(1u8), Just(2), Just(3), Just(0), Just(9)],
        descr,
        any::<bool>(),
        shape,
        data,
        any::<usize>(),
    )
        .prop_map(|(version, descr, fortran, shape, data, cut)| {
            let f = if fortran { "True" } else { "False" };
            let mut bytes = npy(
                version,
                &format!("{{'descr': '{descr}', 'fortran_order': {f}, 'shape': {shape}, }}"),
                &data,
            );
            // sometimes truncated anywhere
            if cut % 4 == 0 {
                bytes.truncate(cut / 4 % (bytes.len() + 1));
            }
            bytes
        })
}

fn csv_file() -> impl Strategy<Value = Vec<u8>> {
    let cell = prop_oneof![
        fuzz_gen::float().prop_map(|x| x.to_string()),
        prop::sample::select(vec![
            "",
            " ",
            "nan",
            "NaN",
            "inf",
            "-inf",
            "1,5",
            "0,25",
            "1e999",
            "-0",
            "0x10",
            "\"1\"",
            "#",
            "δ",
            "1;2",
            "1\t2",
            "\u{feff}1",
        ])
        .prop_map(str::to_string),
    ];
    let row = prop::collection::vec(cell, 0..6);
    let sep = prop::sample::select(vec![",", ";", "\t", " ", ", "]);
    let nl = prop::sample::select(vec!["\n", "\r\n", "\r", ""]);
    prop_oneof![
        3 => (prop::collection::vec(row, 0..8), sep, nl).prop_map(|(rows, sep, nl)| {
            rows.iter()
                .map(|r| r.join(sep))
                .collect::<Vec<_>>()
                .join(nl)
                .into_bytes()
        }),
        1 => prop::collection::vec(any::<u8>(), 0..300),
    ]
}

/// A temporary file of this thread (overwritten by each input).
fn scratch(ext: &str) -> PathBuf {
    std::env::temp_dir().join(
        format!(
            "kontakt-fuzz-{}-{:?}.{ext}",
            std::process::id(),
            std::thread::current().id()
        )
        .replace(['(', ')'], ""),
    )
}

fn read_map(bytes: &[u8], ext: &str, spacing: [f64; 2], height: bool) {
    let path = scratch(ext);
    std::fs::write(&path, bytes).unwrap();
    let kind = if height {
        MapKind::Height
    } else {
        MapKind::Gap
    };
    let r = read_gap_map(&path, spacing, kind, 1.0);
    std::fs::remove_file(&path).unwrap();
    if let Err(e) = r {
        let m = e.to_string();
        check_message("read_gap_map", &m);
        assert!(
            m.contains("gap_map") || m.contains("spacing") || m.contains("map"),
            "the error names neither the file nor the field: {m}"
        );
    }
}

proptest! {
    #![proptest_config(config(10_000))]

    /// `.npy` gap maps: every dtype, order and shape (up to 2^64), truncated anywhere.
    #[test]
    fn gap_maps_npy(bytes in npy_file(), sx in fuzz_gen::float(), sy in fuzz_gen::float(), height in any::<bool>()) {
        read_map(&bytes, "npy", [sx, sy], height);
    }

    /// CSV gap maps: numbers, NaN and inf, decimal commas, other separators and line ends,
    /// random bytes.
    #[test]
    fn gap_maps_csv(bytes in csv_file(), height in any::<bool>()) {
        read_map(&bytes, "csv", [0.01, 0.01], height);
    }

    /// Random bytes under either extension.
    #[test]
    fn gap_maps_random_bytes(bytes in prop::collection::vec(any::<u8>(), 0..400), npy in any::<bool>()) {
        read_map(&bytes, if npy { "npy" } else { "csv" }, [0.01, 0.01], false);
    }
}
