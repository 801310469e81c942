//! Parameter sweeps: `kontakt_case::Sweep` chunk by chunk, for `kontakt.sweep` (local or on a
//! Dask cluster, python/kontakt/sweep.py). The chunk files, the manifest and the combined
//! table are the CLI's (`kontakt sweep`, docs/sweep.md): a sweep started from either side
//! resumes from the other.

use crate::args;
use crate::errors::input_error;
use kontakt_case::sweep::{Fields, OutputFormat};
use kontakt_case::{Sweep as CaseSweep, SweepError};
use pyo3::exceptions::{PyOSError, PyRuntimeError};
use pyo3::prelude::*;
use pyo3::types::PyDict;
use std::path::PathBuf;

/// A sweep error as a Python exception: bad input (the sweep file, a key, an output
/// directory holding another sweep) is `InputError` with `field = "sweep"`; a file that
/// cannot be read or written is `OSError`; a table that cannot be written is
/// `RuntimeError`.
fn sweep_err(e: SweepError) -> PyErr {
    let message = e.to_string();
    match e {
        SweepError::Input(m) => input_error("sweep", "", &m, message),
        SweepError::Io { .. } => PyOSError::new_err(message),
        _ => PyRuntimeError::new_err(message),
    }
}

/// `sweep` storing `fields` (`None`: the sweep file's choice).
fn with_fields(sweep: CaseSweep, fields: Option<String>) -> PyResult<Sweep> {
    let fields = match fields.as_deref() {
        None => return Ok(Sweep { inner: sweep }),
        Some("none") => Fields::None,
        Some("npy") => Fields::Npy,
        Some(other) => {
            return Err(crate::errors::invalid("fields", other, FIELDS));
        }
    };
    let inner = sweep.with_fields(fields).map_err(sweep_err)?;
    Ok(Sweep { inner })
}

const FIELDS: &str = "\"none\" or \"npy\"";
const MAX_CASES: &str = "a case count >= 1";

/// A parameter sweep (docs/sweep.md): a base case and parameters by their case keys, a full
/// grid or given points, split into chunks of `chunk_size` cases. Units are the case
/// file's (mm, N, MPa; degrees in case files).
#[pyclass(frozen, module = "kontakt._kontakt")]
pub struct Sweep {
    inner: CaseSweep,
}

#[pymethods]
impl Sweep {
    /// Read a sweep file (TOML; relative paths in it are relative to the file).
    /// `max_cases` raises the refusal threshold (default 10 000 000 cases); `fields`
    /// (`"none"` or `"npy"`) replaces the file's `fields`.
    #[staticmethod]
    #[pyo3(signature = (path, max_cases = None, fields = None))]
    fn from_file(
        path: &Bound<'_, PyAny>,
        max_cases: Option<&Bound<'_, PyAny>>,
        fields: Option<&Bound<'_, PyAny>>,
    ) -> PyResult<Self> {
        let path = args::path(path, "path")?;
        let max_cases = args::opt_count(max_cases, "max_cases", MAX_CASES)?;
        let fields = args::opt_text(fields, "fields", FIELDS)?;
        let inner = CaseSweep::from_path_with_limit(&path, max_cases).map_err(sweep_err)?;
        with_fields(inner, fields)
    }

    /// A sweep from TOML text; relative paths in it are relative to `base_dir`.
    #[staticmethod]
    #[pyo3(
        signature = (text, base_dir = None, max_cases = None, fields = None),
        text_signature = "(text, base_dir='.', max_cases=None, fields=None)"
    )]
    fn from_toml(
        text: &Bound<'_, PyAny>,
        base_dir: Option<&Bound<'_, PyAny>>,
        max_cases: Option<&Bound<'_, PyAny>>,
        fields: Option<&Bound<'_, PyAny>>,
    ) -> PyResult<Self> {
        let text = args::text(text, "text", "a sweep as TOML text")?;
        let base_dir = args::opt_path(base_dir, "base_dir")?.unwrap_or_else(|| PathBuf::from("."));
        let max_cases = args::opt_count(max_cases, "max_cases", MAX_CASES)?;
        let fields = args::opt_text(fields, "fields", FIELDS)?;
        let inner =
            CaseSweep::from_toml_str_with_limit(&text, &base_dir, max_cases).map_err(sweep_err)?;
        with_fields(inner, fields)
    }

    /// Which fields the sweep stores besides its table: `"none"` or `"npy"` (one `.npy`
    /// per case and field in `out_dir/fields/chunk-NNNNNN/`, float64, shape `[ny, nx]`).
    #[getter]
    fn fields(&self) -> &'static str {
        self.inner.fields().as_str()
    }

    fn __len__(&self) -> usize {
        usize::try_from(self.inner.len()).unwrap_or(usize::MAX)
    }

    /// Cases per chunk.
    #[getter]
    fn chunk_size(&self) -> u64 {
        self.inner.chunk_size()
    }

    /// Number of chunks.
    #[getter]
    fn chunk_count(&self) -> u64 {
        self.inner.chunk_count()
    }

    /// The hash of the normalised sweep definition (recorded in `OUT/sweep.json`).
    #[getter]
    fn hash(&self) -> &str {
        self.inner.hash()
    }

    /// Case indices `[start, stop)` of chunk `index`.
    fn chunk_range(&self, index: &Bound<'_, PyAny>) -> PyResult<(u64, u64)> {
        let valid = format!("0 <= index < {}", self.inner.chunk_count());
        let index = args::count(index, "index", &valid)?;
        if index >= self.inner.chunk_count() {
            return Err(crate::errors::invalid(
                "index",
                index,
                &format!("0 <= index < {}", self.inner.chunk_count()),
            ));
        }
        let r = self.inner.chunk_range(index);
        Ok((r.start, r.end))
    }

    /// Create `out_dir` for this sweep (its manifest and `chunks/`), or check that the
    /// directory holds this sweep; a directory holding another sweep is an `InputError`.
    fn prepare(&self, out_dir: &Bound<'_, PyAny>) -> PyResult<()> {
        let out_dir = args::path(out_dir, "out_dir")?;
        self.inner.prepare(&out_dir).map_err(sweep_err)
    }

    /// Indices of the chunks not yet in `out_dir`, ascending.
    fn missing_chunks(&self, out_dir: &Bound<'_, PyAny>) -> PyResult<Vec<u64>> {
        let out_dir = args::path(out_dir, "out_dir")?;
        self.inner.missing_chunks(&out_dir).map_err(sweep_err)
    }

    /// Run chunk `index` (its cases in parallel on `threads` threads, default all local
    /// cores, without the GIL) and write `out_dir/chunks/chunk-NNNNNN.parquet` atomically.
    /// Safe to run twice and from several processes. Returns `{"index", "cases", "not_ok",
    /// "path", "seconds"}`.
    #[pyo3(signature = (index, out_dir, threads = None))]
    fn run_chunk<'py>(
        &self,
        py: Python<'py>,
        index: &Bound<'py, PyAny>,
        out_dir: &Bound<'py, PyAny>,
        threads: Option<&Bound<'py, PyAny>>,
    ) -> PyResult<Bound<'py, PyDict>> {
        let valid = format!("0 <= index < {}", self.inner.chunk_count());
        let index = args::count(index, "index", &valid)?;
        let out_dir = args::path(out_dir, "out_dir")?;
        let threads = args::opt_size(threads, "threads", &format!("1..={}", kontakt::MAX_THREADS))?;
        if let Some(t) = threads.filter(|&t| t == 0 || t > kontakt::MAX_THREADS) {
            return Err(crate::errors::invalid(
                "threads",
                t,
                &format!("1..={}", kontakt::MAX_THREADS),
            ));
        }
        let s = py
            .detach(|| match threads {
                None => self.inner.run_chunk(index, &out_dir),
                Some(t) => self.inner.run_chunk_threads(index, &out_dir, t),
            })
            .map_err(sweep_err)?;
        let d = PyDict::new(py);
        d.set_item("index", s.index)?;
        d.set_item("cases", s.cases)?;
        d.set_item("not_ok", s.not_ok)?;
        d.set_item("path", s.path.display().to_string())?;
        d.set_item("seconds", s.seconds)?;
        Ok(d)
    }

    /// Combine all chunks of `out_dir` into `results.parquet` (`format="parquet"`) or
    /// `results.csv` (`format="csv"`), each case once, in case order; returns the path. A
    /// missing chunk is an `InputError` naming it.
    #[pyo3(
        signature = (out_dir, format = None),
        text_signature = "($self, out_dir, format='parquet')"
    )]
    fn combine(
        &self,
        py: Python<'_>,
        out_dir: &Bound<'_, PyAny>,
        format: Option<&Bound<'_, PyAny>>,
    ) -> PyResult<String> {
        let out_dir = args::path(out_dir, "out_dir")?;
        let format = args::text_or(format, "format", "\"parquet\" or \"csv\"", "parquet")?;
        let format = match format.as_str() {
            "parquet" => OutputFormat::Parquet,
            "csv" => OutputFormat::Csv,
            other => {
                return Err(crate::errors::invalid(
                    "format",
                    other,
                    "\"parquet\" or \"csv\"",
                ));
            }
        };
        let s = py
            .detach(|| self.inner.combine(&out_dir, format))
            .map_err(sweep_err)?;
        Ok(s.path.display().to_string())
    }
}
