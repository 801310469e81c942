//! The rows of the cases and the Arrow tables of a chunk.
//!
//! A row is: `case` (the case index), the swept parameters (one column each, named as in
//! the sweep file), `status` (`ok`, `warning`: solved with warnings in the report's
//! `warnings`, `invalid`: the case reader or the method refused an
//! input, `failed`: a solver did not converge, `panic`: a bug, `lifted_off`: a bearing
//! whose elements all lifted off, solved with zero force), `error` (the one-line
//! message, null when ok), then the case's report flattened:
//! - nested objects give dotted names (`status.residual`, `hertz.max_pressure_mpa`);
//! - arrays of at most [`MAX_ARRAY_LEN`] elements give indexed names (`semi_axes_mm[0]`,
//!   `extents_mm[1][0]`); longer arrays (curves) are left out;
//! - numbers, booleans and strings are kept, `null` is a missing value;
//! - `kontakt_version`, `schema_version` and the `inputs` echo are left out (the
//!   parameters and the base case in `sweep.json` say what was run).
//!
//! A case gives one row, except a report with a `rows` list of objects (a friction case:
//! one per pressure model and speed; a rough case: one per load), which gives one row per
//! element, long and numeric: the element's keys as columns (`model`, `speed_rpm`,
//! `coefficient`, ...), then the keys of any other list of objects in the report
//! (a friction case's `model_difference`) whose shared keys (`speed_rpm`, `model`) match
//! the element, then the report's other scalars, repeated on every row.
//!
//! Units are those of the report keys (`_mm`, `_n`, `_mpa`, ...): mm, N, MPa.

use super::{Parameter, ValueKind};
use arrow_array::{
    Array, ArrayRef, BooleanArray, Float64Array, Int64Array, RecordBatch, StringArray, UInt64Array,
};
use arrow_schema::{DataType, Field, Schema};
use std::collections::HashMap;
use std::sync::Arc;

/// Arrays longer than this are not flattened into columns.
pub const MAX_ARRAY_LEN: usize = 8;

/// Report keys left out of the rows.
const SKIPPED: [&str; 3] = ["kontakt_version", "schema_version", "inputs"];

/// Names of the fixed columns.
pub const CASE_COLUMN: &str = "case";
/// Status column: `ok`, `warning`, `invalid`, `failed` or `panic`.
pub const STATUS_COLUMN: &str = "status";
/// Error message column (null when ok).
pub const ERROR_COLUMN: &str = "error";

/// How a case ended.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Status {
    /// Solved.
    Ok,
    /// Solved, with warnings (the report's `warnings`: a result outside the model's
    /// comfortable range, such as a contact large against the bodies).
    Warning,
    /// The case reader or the method refused an input (the message names the key).
    Invalid,
    /// A computation failed at run time (did not converge).
    Failed,
    /// A bug: the solver panicked; the sweep goes on.
    Panic,
    /// Solved, and every rolling element of a bearing lifted off: zero force (a bearing
    /// sweep's case whose load or prescribed displacement leaves the clearance open).
    LiftedOff,
}

impl Status {
    /// Whether the case was solved (`ok`, `warning` or `lifted_off`).
    pub fn solved(self) -> bool {
        matches!(self, Status::Ok | Status::Warning | Status::LiftedOff)
    }

    /// The status column's text.
    pub fn as_str(self) -> &'static str {
        match self {
            Status::Ok => "ok",
            Status::Warning => "warning",
            Status::Invalid => "invalid",
            Status::Failed => "failed",
            Status::Panic => "panic",
            Status::LiftedOff => "lifted_off",
        }
    }
}

/// One scalar of a report.
#[derive(Debug, Clone, PartialEq)]
pub enum Cell {
    /// Missing (`null` in the report).
    Null,
    /// A float.
    F64(f64),
    /// An integer.
    I64(i64),
    /// A boolean.
    Bool(bool),
    /// A string.
    Str(String),
}

/// What one case gives.
#[derive(Debug, Clone, PartialEq)]
pub struct Row {
    /// How the case ended.
    pub status: Status,
    /// The error message (none when ok).
    pub error: Option<String>,
    /// The report's scalars by flattened name, in the report's order: one list per table
    /// row the case gives (see the module docs); none for a case that is not ok, which
    /// still gives one table row.
    pub outputs: Vec<Vec<(String, Cell)>>,
}

impl Row {
    /// The number of table rows of this case (at least 1).
    pub fn table_rows(&self) -> usize {
        self.outputs.len().max(1)
    }
}

/// The report key whose list of objects gives one table row per element.
pub const ROWS_KEY: &str = "rows";

fn is_object_list(v: &serde_json::Value) -> bool {
    matches!(v, serde_json::Value::Array(a) if !a.is_empty() && a.iter().all(serde_json::Value::is_object))
}

/// Flatten a report (as JSON) into named scalars, one list per table row (rules: module
/// docs).
pub fn flatten(report: &serde_json::Value) -> Vec<Vec<(String, Cell)>> {
    use serde_json::Value as J;
    let J::Object(map) = report else {
        return vec![Vec::new()];
    };
    let rows = map.get(ROWS_KEY).filter(|v| is_object_list(v));
    let mut common = Vec::with_capacity(48);
    let mut joined: Vec<&J> = Vec::new();
    let mut name = String::with_capacity(64);
    for (k, v) in map {
        if SKIPPED.contains(&k.as_str()) {
            continue;
        }
        if rows.is_some() && is_object_list(v) {
            if k != ROWS_KEY {
                joined.push(v);
            }
            continue;
        }
        name.clear();
        name.push_str(k);
        walk(v, &mut name, &mut common);
    }
    let Some(J::Array(rows)) = rows else {
        return vec![common];
    };
    // The keys that identify a row (those the joined lists match on: `model`,
    // `speed_rpm`) come first.
    let first = rows.first().and_then(J::as_object);
    let mut keys_first: Vec<&String> = joined
        .iter()
        .filter_map(|l| l.as_array()?.first()?.as_object())
        .flat_map(|o| o.keys())
        .filter(|k| first.is_some_and(|r| r.contains_key(*k)))
        .collect();
    keys_first.sort_unstable();
    keys_first.dedup();
    let mut out = Vec::with_capacity(rows.len());
    for row in rows.iter().filter_map(J::as_object) {
        let mut cells = Vec::with_capacity(common.len() + row.len() + 4);
        let ordered = keys_first
            .iter()
            .filter_map(|k| row.get_key_value(k.as_str()))
            .chain(row.iter().filter(|(k, _)| !keys_first.contains(k)));
        for (k, v) in ordered {
            name.clear();
            name.push_str(k);
            walk(v, &mut name, &mut cells);
        }
        for list in &joined {
            for other in list
                .as_array()
                .into_iter()
                .flatten()
                .filter_map(J::as_object)
            {
                let mut shared = other
                    .iter()
                    .filter(|(k, _)| row.contains_key(*k))
                    .peekable();
                if shared.peek().is_none() || !shared.all(|(k, v)| row.get(k) == Some(v)) {
                    continue;
                }
                for (k, v) in other.iter().filter(|(k, _)| !row.contains_key(*k)) {
                    name.clear();
                    name.push_str(k);
                    walk(v, &mut name, &mut cells);
                }
            }
        }
        for (k, c) in &common {
            if !cells.iter().any(|(n, _)| n == k) {
                cells.push((k.clone(), c.clone()));
            }
        }
        out.push(cells);
    }
    out
}

fn walk(v: &serde_json::Value, name: &mut String, out: &mut Vec<(String, Cell)>) {
    use serde_json::Value as J;
    let cell = match v {
        J::Null => Cell::Null,
        J::Bool(b) => Cell::Bool(*b),
        J::Number(n) => match n.as_i64() {
            Some(i) if !n.is_f64() => Cell::I64(i),
            _ => Cell::F64(n.as_f64().unwrap_or(f64::NAN)),
        },
        J::String(s) => Cell::Str(s.clone()),
        J::Array(a) => {
            if a.len() <= MAX_ARRAY_LEN {
                let len = name.len();
                for (i, x) in a.iter().enumerate() {
                    use std::fmt::Write as _;
                    let _ = write!(name, "[{i}]");
                    walk(x, name, out);
                    name.truncate(len);
                }
            }
            return;
        }
        J::Object(m) => {
            let len = name.len();
            for (k, x) in m {
                name.push('.');
                name.push_str(k);
                walk(x, name, out);
                name.truncate(len);
            }
            return;
        }
    };
    out.push((name.clone(), cell));
}

/// The Arrow type of a column of cells; `None` when every cell is null.
fn column_type(cells: &[Cell]) -> Option<DataType> {
    let (mut f, mut i, mut b, mut s, mut s_numeric) = (false, false, false, false, true);
    for c in cells {
        match c {
            Cell::Null => {}
            Cell::F64(_) => f = true,
            Cell::I64(_) => i = true,
            Cell::Bool(_) => b = true,
            Cell::Str(t) => {
                s = true;
                s_numeric &= t.parse::<f64>().is_ok();
            }
        }
    }
    Some(match (f, i, b, s) {
        (false, false, false, false) => return None,
        (_, _, _, true) if (f || i || b) && s_numeric => DataType::Float64,
        (_, _, _, true) => DataType::Utf8,
        (false, true, false, false) => DataType::Int64,
        (false, false, true, false) => DataType::Boolean,
        _ => DataType::Float64,
    })
}

fn cell_f64(c: &Cell) -> Option<f64> {
    match c {
        Cell::Null => None,
        Cell::F64(x) => Some(*x),
        Cell::I64(x) => Some(*x as f64),
        Cell::Bool(x) => Some(f64::from(u8::from(*x))),
        Cell::Str(t) => t.parse().ok(),
    }
}

fn cell_text(c: &Cell) -> Option<String> {
    match c {
        Cell::Null => None,
        Cell::F64(x) => Some(format!("{x:?}")),
        Cell::I64(x) => Some(x.to_string()),
        Cell::Bool(x) => Some(x.to_string()),
        Cell::Str(t) => Some(t.clone()),
    }
}

fn cells_to_array(cells: &[Cell], ty: &DataType) -> ArrayRef {
    match ty {
        DataType::Int64 => Arc::new(Int64Array::from(
            cells
                .iter()
                .map(|c| match c {
                    Cell::I64(x) => Some(*x),
                    _ => None,
                })
                .collect::<Vec<_>>(),
        )),
        DataType::Boolean => Arc::new(BooleanArray::from(
            cells
                .iter()
                .map(|c| match c {
                    Cell::Bool(x) => Some(*x),
                    _ => None,
                })
                .collect::<Vec<_>>(),
        )),
        DataType::Utf8 => Arc::new(StringArray::from(
            cells.iter().map(cell_text).collect::<Vec<_>>(),
        )),
        _ => Arc::new(Float64Array::from(
            cells.iter().map(cell_f64).collect::<Vec<_>>(),
        )),
    }
}

fn parameter_array(
    p: &Parameter,
    values: impl Iterator<Item = toml::Value>,
) -> (DataType, ArrayRef) {
    match p.kind {
        ValueKind::Float => (
            DataType::Float64,
            Arc::new(Float64Array::from(
                values
                    .map(|v| v.as_float().or_else(|| v.as_integer().map(|i| i as f64)))
                    .collect::<Vec<_>>(),
            )),
        ),
        ValueKind::Integer => (
            DataType::Int64,
            Arc::new(Int64Array::from(
                values.map(|v| v.as_integer()).collect::<Vec<_>>(),
            )),
        ),
        ValueKind::Boolean => (
            DataType::Boolean,
            Arc::new(BooleanArray::from(
                values.map(|v| v.as_bool()).collect::<Vec<_>>(),
            )),
        ),
        ValueKind::Text => (
            DataType::Utf8,
            Arc::new(StringArray::from(
                values
                    .map(|v| match v {
                        toml::Value::String(s) => s,
                        other => other.to_string(),
                    })
                    .collect::<Vec<_>>(),
            )),
        ),
    }
}

/// The table of one chunk: `case`, the parameters, `status`, `error`, then every output
/// column that has at least one value in this chunk, in the order first met.
///
/// # Errors
/// The Arrow library's message (columns of unequal length: a bug).
pub fn chunk_batch(
    sweep: &super::Sweep,
    first_case: u64,
    rows: &[Row],
) -> Result<RecordBatch, String> {
    // The case of every table row, in order (a case with a list of rows repeats).
    let cases: Vec<u64> = rows
        .iter()
        .enumerate()
        .flat_map(|(k, r)| std::iter::repeat_n(first_case + k as u64, r.table_rows()))
        .collect();
    let n = cases.len();
    let repeat = |f: &dyn Fn(&Row) -> Option<String>| {
        rows.iter()
            .flat_map(|r| std::iter::repeat_n(f(r), r.table_rows()))
            .collect::<Vec<_>>()
    };
    let (mut fields, mut columns) = leading_columns(
        sweep,
        &cases,
        StringArray::from(repeat(&|r| Some(r.status.as_str().to_string()))),
        StringArray::from(repeat(&|r| r.error.clone())),
    );
    let reserved = reserved_names(sweep);

    // Output columns: union over the table rows, in the order first met.
    let mut index: HashMap<&str, usize> = HashMap::new();
    let mut names: Vec<&str> = Vec::new();
    let mut cells: Vec<Vec<Cell>> = Vec::new();
    // A case that is not ok has no outputs and one table row.
    let mut r = 0;
    for row in rows {
        for (k, outputs) in row.outputs.iter().enumerate() {
            for (name, cell) in outputs {
                let c = *index.entry(name.as_str()).or_insert_with(|| {
                    names.push(name.as_str());
                    cells.push(vec![Cell::Null; n]);
                    names.len() - 1
                });
                cells[c][r + k] = cell.clone();
            }
        }
        r += row.table_rows();
    }
    for (name, column) in names.iter().zip(&cells) {
        let Some(ty) = column_type(column) else {
            continue;
        };
        let name = if reserved.contains(name) {
            format!("result.{name}")
        } else {
            (*name).to_string()
        };
        columns.push(cells_to_array(column, &ty));
        fields.push(Field::new(name, ty, true));
    }
    RecordBatch::try_new(Arc::new(Schema::new(fields)), columns).map_err(|e| e.to_string())
}

/// The names an output column must not take: the parameters', `case`, `status`, `error`
/// (an output of that name is written as `result.<name>`).
fn reserved_names(sweep: &super::Sweep) -> Vec<&str> {
    sweep
        .parameters()
        .iter()
        .map(|p| p.name.as_str())
        .chain([CASE_COLUMN, STATUS_COLUMN, ERROR_COLUMN])
        .collect()
}

/// The columns every table starts with: `case`, the parameters, `status`, `error`.
fn leading_columns(
    sweep: &super::Sweep,
    cases: &[u64],
    status: StringArray,
    errors: StringArray,
) -> (Vec<Field>, Vec<ArrayRef>) {
    let mut fields = Vec::new();
    let mut columns: Vec<ArrayRef> = Vec::new();
    fields.push(Field::new(CASE_COLUMN, DataType::UInt64, false));
    columns.push(Arc::new(UInt64Array::from(cases.to_vec())));
    for (p, param) in sweep.parameters().iter().enumerate() {
        let (ty, array) = parameter_array(
            param,
            cases
                .iter()
                .map(|&i| param.values.get(sweep.value_index(p, i))),
        );
        fields.push(Field::new(param.name.clone(), ty, true));
        columns.push(array);
    }
    fields.push(Field::new(STATUS_COLUMN, DataType::Utf8, false));
    columns.push(Arc::new(status));
    fields.push(Field::new(ERROR_COLUMN, DataType::Utf8, true));
    columns.push(Arc::new(errors));
    (fields, columns)
}

/// The table of one chunk of a bearing sweep: the leading columns, then the bearing
/// columns of [`super::bearing::COLUMNS`], every one of them in every chunk.
///
/// # Errors
/// The Arrow library's message (columns of unequal length: a bug).
pub(crate) fn bearing_batch(
    sweep: &super::Sweep,
    first_case: u64,
    rows: &[super::bearing::BearingRow],
) -> Result<RecordBatch, String> {
    let cases: Vec<u64> = (first_case..first_case + rows.len() as u64).collect();
    let (mut fields, mut columns) = leading_columns(
        sweep,
        &cases,
        rows.iter()
            .map(|r| Some(r.status.as_str()))
            .collect::<StringArray>(),
        rows.iter()
            .map(|r| r.error.as_deref())
            .collect::<StringArray>(),
    );
    let reserved = reserved_names(sweep);
    for (name, array) in super::bearing::bearing_columns(rows) {
        let name = if reserved.contains(&name) {
            format!("result.{name}")
        } else {
            name.to_string()
        };
        fields.push(Field::new(name, array.data_type().clone(), true));
        columns.push(array);
    }
    RecordBatch::try_new(Arc::new(Schema::new(fields)), columns).map_err(|e| e.to_string())
}

/// The common type of one column over the chunks: equal types stay, integers and floats
/// (and booleans with numbers) become floats, anything with strings becomes strings.
pub(crate) fn unify(a: &DataType, b: &DataType) -> DataType {
    use DataType as D;
    match (a, b) {
        _ if a == b => a.clone(),
        (D::Utf8, _) | (_, D::Utf8) => D::Utf8,
        _ => D::Float64,
    }
}

/// `array` as `to` (see [`unify`]); the same array when it already is.
pub(crate) fn conform(array: &ArrayRef, to: &DataType) -> ArrayRef {
    if array.data_type() == to {
        return array.clone();
    }
    let n = array.len();
    match to {
        DataType::Utf8 => Arc::new(StringArray::from(
            (0..n).map(|i| text_at(array, i)).collect::<Vec<_>>(),
        )),
        _ => Arc::new(Float64Array::from(
            (0..n).map(|i| f64_at(array, i)).collect::<Vec<_>>(),
        )),
    }
}

fn f64_at(array: &ArrayRef, i: usize) -> Option<f64> {
    if array.is_null(i) {
        return None;
    }
    let any = array.as_any();
    if let Some(a) = any.downcast_ref::<Float64Array>() {
        Some(a.value(i))
    } else if let Some(a) = any.downcast_ref::<Int64Array>() {
        Some(a.value(i) as f64)
    } else if let Some(a) = any.downcast_ref::<UInt64Array>() {
        Some(a.value(i) as f64)
    } else if let Some(a) = any.downcast_ref::<BooleanArray>() {
        Some(f64::from(u8::from(a.value(i))))
    } else if let Some(a) = any.downcast_ref::<StringArray>() {
        a.value(i).parse().ok()
    } else {
        None
    }
}

/// The value at row `i` as text (floats exact, as Rust's `{:?}`: `1e-7`, `inf`, `NaN`);
/// none for null.
pub(crate) fn text_at(array: &ArrayRef, i: usize) -> Option<String> {
    if array.is_null(i) {
        return None;
    }
    let any = array.as_any();
    if let Some(a) = any.downcast_ref::<Float64Array>() {
        Some(format!("{:?}", a.value(i)))
    } else if let Some(a) = any.downcast_ref::<Int64Array>() {
        Some(a.value(i).to_string())
    } else if let Some(a) = any.downcast_ref::<UInt64Array>() {
        Some(a.value(i).to_string())
    } else if let Some(a) = any.downcast_ref::<BooleanArray>() {
        Some(a.value(i).to_string())
    } else {
        any.downcast_ref::<StringArray>()
            .map(|a| a.value(i).to_string())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn flatten_names_nested_and_short_arrays_only() {
        let v = serde_json::json!({
            "kontakt_version": "0.1.0", "schema_version": 1, "inputs": {"force_n": 1.0},
            "force_n": 100.0, "patches": 1, "mode": "corrected",
            "semi_axes_mm": [0.5, 0.25], "extents_mm": [[-1.0, 1.0], [-0.5, 0.5]],
            "status": {"termination": "converged", "residual": 1e-9},
            "curve": [0, 1, 2, 3, 4, 5, 6, 7, 8], "hertz": null, "ok": true
        });
        let cells = &flatten(&v)[0];
        let names: Vec<&str> = cells.iter().map(|(n, _)| n.as_str()).collect();
        for want in [
            "force_n",
            "patches",
            "mode",
            "semi_axes_mm[1]",
            "extents_mm[1][0]",
            "status.termination",
            "status.residual",
            "hertz",
            "ok",
        ] {
            assert!(names.contains(&want), "{want} not in {names:?}");
        }
        for skipped in [
            "kontakt_version",
            "schema_version",
            "inputs.force_n",
            "curve[0]",
        ] {
            assert!(!names.contains(&skipped), "{skipped} in {names:?}");
        }
        assert!(cells.contains(&("patches".into(), Cell::I64(1))));
        assert!(cells.contains(&("force_n".into(), Cell::F64(100.0))));
    }

    #[test]
    fn a_list_of_rows_gives_one_table_row_each_with_joined_lists() {
        let v = serde_json::json!({
            "kontakt_version": "0.1.0", "pairing": "p", "rollers": 17,
            "rows": [
                {"model": "hertz", "speed_rpm": 500.0, "torque": 2.0},
                {"model": "pimp", "speed_rpm": 500.0, "torque": 2.2}
            ],
            "model_difference": [{"model": "pimp", "speed_rpm": 500.0, "torque_vs_hertz": 1.1}],
            "warnings": []
        });
        let rows = flatten(&v);
        assert_eq!(rows.len(), 2);
        let names = |r: &[(String, Cell)]| r.iter().map(|(n, _)| n.clone()).collect::<Vec<_>>();
        assert_eq!(
            names(&rows[0]),
            ["model", "speed_rpm", "torque", "pairing", "rollers"]
        );
        assert_eq!(
            names(&rows[1]),
            [
                "model",
                "speed_rpm",
                "torque",
                "torque_vs_hertz",
                "pairing",
                "rollers"
            ]
        );
        assert!(rows[1].contains(&("torque_vs_hertz".into(), Cell::F64(1.1))));
        // without a `rows` list: one row, a short list of objects flattened with indices
        let one = flatten(&serde_json::json!({"a": [{"b": 1}], "c": 2.0}));
        assert_eq!(one.len(), 1);
        assert_eq!(names(&one[0]), ["a[0].b", "c"]);
    }

    #[test]
    fn column_types_resolve() {
        use Cell as C;
        assert_eq!(column_type(&[C::Null, C::Null]), None);
        assert_eq!(column_type(&[C::I64(1), C::Null]), Some(DataType::Int64));
        assert_eq!(
            column_type(&[C::I64(1), C::F64(0.5)]),
            Some(DataType::Float64)
        );
        assert_eq!(
            column_type(&[C::F64(1.0), C::Str("inf".into())]),
            Some(DataType::Float64)
        );
        assert_eq!(
            column_type(&[C::F64(1.0), C::Str("x".into())]),
            Some(DataType::Utf8)
        );
        assert_eq!(
            unify(&DataType::Int64, &DataType::Float64),
            DataType::Float64
        );
        assert_eq!(unify(&DataType::Int64, &DataType::Utf8), DataType::Utf8);
        let a: ArrayRef = Arc::new(Int64Array::from(vec![Some(2), None]));
        let f = conform(&a, &DataType::Float64);
        assert_eq!(f64_at(&f, 0), Some(2.0));
        assert!(f.is_null(1));
    }
}
