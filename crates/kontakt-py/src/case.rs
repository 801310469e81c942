//! Cases of any method through the case layer's one dispatch, `kontakt_case::Case::run`.

use crate::args;
use crate::errors::{invalid, to_py};
use kontakt::field::NormalSolution;
use kontakt_case::{Case, Outcome};
use numpy::ndarray::Array2;
use numpy::{IntoPyArray, PyArray1, PyArray2};
use pyo3::prelude::*;
use pyo3::types::{PyBool, PyDict, PyFloat, PyInt, PyList, PyString, PyTuple};
use std::path::{Path, PathBuf};

/// `value` serialised as the CLI writes it (serde_json), parsed by Python's `json`: the
/// same keys and the same numbers as `kontakt ... --json`.
pub fn json_to_py<'py>(
    py: Python<'py>,
    value: &impl serde::Serialize,
) -> PyResult<Bound<'py, PyAny>> {
    let text = serde_json::to_string(value)
        .map_err(|e| pyo3::exceptions::PyRuntimeError::new_err(format!("report: {e}")))?;
    py.import("json")?.call_method1("loads", (text,))
}

/// The fields of a solved case on its grid: cell centres and per-cell arrays `(ny, nx)`.
#[derive(Clone)]
pub struct Fields {
    pub x: Vec<f64>,
    pub y: Vec<f64>,
    pub pressure: Array2<f64>,
    pub displacement: Option<Array2<f64>>,
    pub gap: Option<Array2<f64>>,
}

fn grid_array(nx: usize, ny: usize, v: &[f64]) -> Array2<f64> {
    Array2::from_shape_vec((ny, nx), v.to_vec())
        .unwrap_or_else(|_| Array2::from_elem((ny, nx), f64::NAN))
}

impl Fields {
    pub fn of<D>(s: &NormalSolution<D>, displacement: Option<&[f64]>, gap: Option<&[f64]>) -> Self {
        let g = &s.grid;
        let (nx, ny) = (g.nx(), g.ny());
        Fields {
            x: (0..nx).map(|i| g.x(i)).collect(),
            y: (0..ny).map(|j| g.y(j)).collect(),
            pressure: grid_array(nx, ny, &s.pressure),
            displacement: displacement.map(|d| grid_array(nx, ny, d)),
            gap: gap.map(|d| grid_array(nx, ny, d)),
        }
    }
}

/// What a case gives: the report (the CLI's JSON record, `to_dict()`) and, for the field
/// methods (pimp, bem), the fields per cell as arrays of shape (ny, nx) with the cell
/// centres `x`, `y` [mm]: `pressure` [MPa]; for bem also `displacement` and `gap` [mm].
#[pyclass(frozen, module = "kontakt._kontakt")]
pub struct CaseResult {
    method: &'static str,
    report: String,
    fields: Option<Fields>,
    warnings: Vec<String>,
}

fn array2<'py>(py: Python<'py>, a: &Option<Array2<f64>>) -> Option<Bound<'py, PyArray2<f64>>> {
    a.as_ref().map(|a| a.clone().into_pyarray(py))
}

#[pymethods]
impl CaseResult {
    /// The case's method: "hertz", "pimp", "bem", "traction" or "friction".
    #[getter]
    fn method(&self) -> &'static str {
        self.method
    }
    /// Cell centres along x [mm] (field methods), else None.
    #[getter]
    fn x<'py>(&self, py: Python<'py>) -> Option<Bound<'py, PyArray1<f64>>> {
        self.fields.as_ref().map(|f| PyArray1::from_slice(py, &f.x))
    }
    /// Cell centres along y [mm] (field methods), else None.
    #[getter]
    fn y<'py>(&self, py: Python<'py>) -> Option<Bound<'py, PyArray1<f64>>> {
        self.fields.as_ref().map(|f| PyArray1::from_slice(py, &f.y))
    }
    /// Pressure per cell [MPa], shape (ny, nx) (field methods), else None.
    #[getter]
    fn pressure<'py>(&self, py: Python<'py>) -> Option<Bound<'py, PyArray2<f64>>> {
        self.fields
            .as_ref()
            .map(|f| f.pressure.clone().into_pyarray(py))
    }
    /// Elastic displacement per cell [mm] (bem), else None.
    #[getter]
    fn displacement<'py>(&self, py: Python<'py>) -> Option<Bound<'py, PyArray2<f64>>> {
        self.fields
            .as_ref()
            .and_then(|f| array2(py, &f.displacement))
    }
    /// Undeformed gap per cell [mm] (bem; +inf where the bodies cannot meet), else None.
    #[getter]
    fn gap<'py>(&self, py: Python<'py>) -> Option<Bound<'py, PyArray2<f64>>> {
        self.fields.as_ref().and_then(|f| array2(py, &f.gap))
    }
    /// Where the result is outside the method's comfortable range (the report's
    /// `warnings`: a contact large against a body's radius of curvature or near the edge
    /// of a face, a pressure above first yield); empty when none applies.
    #[getter]
    fn warnings(&self) -> Vec<String> {
        self.warnings.clone()
    }
    /// The report as a JSON string, exactly as `kontakt solve --json` writes it (compact).
    fn to_json(&self) -> &str {
        &self.report
    }
    /// The report as a dict with the CLI's JSON keys.
    fn to_dict<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        py.import("json")?
            .call_method1("loads", (self.report.as_str(),))
    }
    /// One line: the method, the case's name, the report's main numbers (those of
    /// `SUMMARY` it has), the length of its tables and the warnings, e.g.
    /// `CaseResult(method="hertz", name="ball on flat", force_n=100, max_pressure_mpa=1855.6,
    /// semi_axes_mm=[0.160409, 0.160409], ..., warnings=[])`.
    fn __repr__(&self) -> String {
        summary(self.method, &self.report, &self.warnings)
    }
}

/// The report keys `repr(CaseResult)` shows when present and not null, in this order:
/// the load, the peak pressure and the contact's size for the contact methods, the
/// characteristic numbers of the others (mindlin, impact, rough, friction).
const SUMMARY: &[&str] = &[
    "force_n",
    "line_load_n_per_mm",
    "axial_load_n",
    "rollers",
    "max_pressure_mpa",
    "semi_axes_mm",
    "approach_mm",
    "contact_area_mm2",
    "mu",
    "limit_force_n",
    "stick_ratio",
    "dissipated_energy_per_cycle_nmm",
    "rms_height_mm",
    "mass_t",
];

/// The report keys holding tables; `repr(CaseResult)` gives their length.
const TABLES: &[&str] = &["rows", "curves", "creepage"];

/// A number with 6 significant digits, without trailing zeros.
fn short(x: f64) -> String {
    if x == 0.0 || !x.is_finite() {
        return format!("{x}");
    }
    let magnitude = x.abs().log10().floor();
    if !(-4.0..6.0).contains(&magnitude) {
        return format!("{x:.5e}");
    }
    // 0..=9 decimals: magnitude is in -4..6
    let decimals = (5.0 - magnitude) as usize;
    let s = format!("{x:.decimals$}");
    if s.contains('.') {
        s.trim_end_matches('0').trim_end_matches('.').to_string()
    } else {
        s
    }
}

fn short_json(v: &serde_json::Value) -> String {
    match v {
        serde_json::Value::Number(n) => n.as_f64().map_or_else(|| n.to_string(), short),
        serde_json::Value::Array(a) => {
            let items: Vec<String> = a.iter().map(short_json).collect();
            format!("[{}]", items.join(", "))
        }
        other => other.to_string(),
    }
}

/// `repr(CaseResult)`: see `CaseResult::__repr__`.
fn summary(method: &str, report: &str, warnings: &[String]) -> String {
    let mut parts = vec![format!("method={method:?}")];
    if let Ok(serde_json::Value::Object(r)) = serde_json::from_str::<serde_json::Value>(report) {
        if let Some(serde_json::Value::String(name)) = r.get("name") {
            parts.push(format!("name={name:?}"));
        }
        for key in SUMMARY {
            match r.get(*key) {
                None | Some(serde_json::Value::Null) => {}
                Some(v) => parts.push(format!("{key}={}", short_json(v))),
            }
        }
        for key in TABLES {
            if let Some(serde_json::Value::Array(a)) = r.get(*key) {
                parts.push(format!("{key}=<{} entries>", a.len()));
            }
        }
    }
    parts.push(format!("warnings={warnings:?}"));
    format!("CaseResult({})", parts.join(", "))
}

fn result(case: &Case, outcome: Outcome) -> PyResult<CaseResult> {
    let report = serde_json::to_string(&outcome)
        .map_err(|e| pyo3::exceptions::PyRuntimeError::new_err(format!("report: {e}")))?;
    let fields = match &outcome {
        Outcome::Pimp(o) => Some(Fields::of(&o.solution, None, None)),
        Outcome::Bem(o) => Some(Fields::of(
            &o.solution,
            Some(&o.solution.detail.displacement),
            Some(&o.solution.detail.gap),
        )),
        _ => None,
    };
    Ok(CaseResult {
        method: case.method(),
        warnings: outcome.warnings().to_vec(),
        report,
        fields,
    })
}

/// Parse and run `text` with the GIL released.
fn run_text(py: Python<'_>, text: &str, base_dir: PathBuf) -> PyResult<CaseResult> {
    run_parsed(py, Case::from_toml_str(text).map_err(to_py)?, base_dir)
}

/// Run a case parsed from a dict's TOML text: a schema error names the key, not a line of
/// a text the user never saw.
fn run_dict_text(py: Python<'_>, text: &str, base_dir: PathBuf) -> PyResult<CaseResult> {
    run_parsed(py, parse_dict_text(text)?, base_dir)
}

/// Parse a case from a dict's TOML text: a schema error names the key, not a line.
pub fn parse_dict_text(text: &str) -> PyResult<Case> {
    Case::from_toml_str(text).map_err(|e| match e {
        kontakt::Error::CaseFile { key, message, .. } => to_py(kontakt::Error::CaseFile {
            line: None,
            key,
            message,
        }),
        other => to_py(other),
    })
}

/// Run a parsed case with the GIL released.
fn run_parsed(py: Python<'_>, case: Case, base_dir: PathBuf) -> PyResult<CaseResult> {
    let outcome = py.detach(|| case.run(&base_dir)).map_err(to_py)?;
    result(&case, outcome)
}

/// Run a case given as TOML text (any method of docs/case-schema.md); relative file paths
/// in it (gap maps) are resolved against `base_dir` (default: the working directory).
#[pyfunction]
#[pyo3(signature = (text, base_dir = None))]
pub fn run_toml(
    py: Python<'_>,
    text: &Bound<'_, PyAny>,
    base_dir: Option<&Bound<'_, PyAny>>,
) -> PyResult<CaseResult> {
    let text = args::text(text, "text", "a case as TOML text")?;
    let base_dir = args::opt_path(base_dir, "base_dir")?;
    run_text(py, &text, base_dir.unwrap_or_else(|| PathBuf::from(".")))
}

/// Run a case file (TOML); paths in it are relative to its folder, as for `kontakt solve`.
#[pyfunction]
pub fn run_file(py: Python<'_>, path: &Bound<'_, PyAny>) -> PyResult<CaseResult> {
    let path = args::path(path, "path")?;
    let text = kontakt_case::read_case_file(&path).map_err(to_py)?;
    let base = path
        .parent()
        .map_or_else(|| PathBuf::from("."), Path::to_path_buf);
    run_text(py, &text, base)
}

/// Run a case given as a dict with the keys of a case file (nested dicts for tables;
/// degrees, mm, N, MPa as in the files; `float("inf")` for a flat radius).
#[pyfunction]
#[pyo3(signature = (case, base_dir = None))]
pub fn run_case(
    py: Python<'_>,
    case: &Bound<'_, PyAny>,
    base_dir: Option<&Bound<'_, PyAny>>,
) -> PyResult<CaseResult> {
    let text = dict_toml(case, "case")?;
    let base_dir = args::opt_path(base_dir, "base_dir")?;
    run_dict_text(py, &text, base_dir.unwrap_or_else(|| PathBuf::from(".")))
}

/// The TOML text of a case or sweep given as a dict (nested dicts for tables, lists of
/// dicts for arrays of tables; `None` values are left out): what `run` and `sweep` do with
/// a dict, and a way to save one as a file.
#[pyfunction]
pub fn to_toml(definition: &Bound<'_, PyAny>) -> PyResult<String> {
    dict_toml(definition, "definition")
}

/// `v`, a dict named `name`, as TOML text.
pub fn dict_toml(v: &Bound<'_, PyAny>, name: &str) -> PyResult<String> {
    if !v.is_instance_of::<PyDict>() {
        return Err(args::wrong_type(
            name,
            v,
            "a dict with the keys of a case file",
        ));
    }
    let table = match Converter::default().value(v, name, 0)? {
        toml::Value::Table(t) => t,
        _ => return Err(invalid(name, "not a table", "a dict")),
    };
    toml::to_string(&table).map_err(|e| invalid(name, e, "a dict that TOML can represent"))
}

/// How deep a case dict may nest: case files nest three or four tables deep, so 64 is
/// far beyond any real case and far below the stack a recursive conversion can use.
pub const MAX_DEPTH: usize = 64;

/// Python values to TOML values, refusing a dict or list that contains itself (Python
/// allows it; converting it recursed until the stack overflowed and the interpreter died
/// with SIGSEGV) and nesting deeper than `MAX_DEPTH`, naming the key path.
#[derive(Default)]
struct Converter {
    /// The containers being converted, outermost first, by identity, with their key paths.
    open: Vec<(usize, String)>,
}

impl Converter {
    /// `v` as a TOML value; `key` is its path (`case.geometry.radii_mm[0]`) for errors.
    fn value(&mut self, v: &Bound<'_, PyAny>, key: &str, depth: usize) -> PyResult<toml::Value> {
        if v.is_instance_of::<PyBool>() {
            return Ok(toml::Value::Boolean(v.extract()?));
        }
        if v.is_instance_of::<PyInt>() {
            return Ok(toml::Value::Integer(v.extract().map_err(|_| {
                invalid(key, v, "an integer that fits in 64 bits")
            })?));
        }
        if v.is_instance_of::<PyFloat>() {
            return Ok(toml::Value::Float(v.extract()?));
        }
        if v.is_instance_of::<PyString>() {
            return Ok(toml::Value::String(v.extract()?));
        }
        let is_dict = v.is_instance_of::<PyDict>();
        if is_dict || v.is_instance_of::<PyList>() || v.is_instance_of::<PyTuple>() {
            let id = v.as_ptr() as usize;
            if let Some((_, outer)) = self.open.iter().find(|(o, _)| *o == id) {
                return Err(invalid(
                    key,
                    format!("{outer} itself"),
                    "a value, not a dict or list that contains itself",
                ));
            }
            if depth >= MAX_DEPTH {
                return Err(invalid(
                    key,
                    format!(
                        "a {} nested {depth} deep",
                        if is_dict { "dict" } else { "list" }
                    ),
                    &format!("tables and lists nested at most {MAX_DEPTH} deep"),
                ));
            }
            self.open.push((id, key.to_string()));
            let out = if is_dict {
                self.table(v.cast::<PyDict>()?, key, depth)
            } else {
                self.array(v, key, depth)
            };
            self.open.pop();
            return out;
        }
        // NumPy scalars and arrays: through their Python equivalents.
        if v.hasattr("tolist")? {
            let plain = v.call_method0("tolist")?;
            if !plain.is(v) {
                return self.value(&plain, key, depth);
            }
        }
        Err(invalid(
            key,
            v.get_type().name()?,
            "a bool, int, float, str, list, tuple or dict",
        ))
    }

    fn table(&mut self, d: &Bound<'_, PyDict>, key: &str, depth: usize) -> PyResult<toml::Value> {
        let mut t = toml::Table::new();
        for (k, val) in d.iter() {
            let k: String = k.extract().map_err(|_| invalid(key, &k, "string keys"))?;
            if val.is_none() {
                continue; // an absent optional key
            }
            let sub = format!("{key}.{k}");
            t.insert(k, self.value(&val, &sub, depth + 1)?);
        }
        Ok(toml::Value::Table(t))
    }

    fn array(&mut self, v: &Bound<'_, PyAny>, key: &str, depth: usize) -> PyResult<toml::Value> {
        let items: Vec<Bound<'_, PyAny>> = v.extract()?;
        items
            .iter()
            .enumerate()
            .map(|(i, x)| self.value(x, &format!("{key}[{i}]"), depth + 1))
            .collect::<PyResult<Vec<_>>>()
            .map(toml::Value::Array)
    }
}
