//! Parameter sweeps: `kontakt_case::Sweep` chunk by chunk, for `kontakt.sweep` (local or on a
//! Dask cluster, python/kontakt/sweep.py). The chunk files, the manifest and the combined
//! table are the CLI's (`kontakt sweep`, docs/sweep.md): a sweep started from either side
//! resumes from the other.

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
fn with_fields(sweep: CaseSweep, fields: Option<&str>) -> PyResult<Sweep> {
    let fields = match fields {
        None => return Ok(Sweep { inner: sweep }),
        Some("none") => Fields::None,
        Some("npy") => Fields::Npy,
        Some(other) => {
            return Err(crate::errors::invalid(
                "fields",
                other,
                "\"none\" or \"npy\"",
            ));
        }
    };
    let inner = sweep.with_fields(fields).map_err(sweep_err)?;
    Ok(Sweep { inner })
}

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
    fn from_file(path: PathBuf, max_cases: Option<u64>, fields: Option<&str>) -> PyResult<Self> {
        let inner = CaseSweep::from_path_with_limit(&path, max_cases).map_err(sweep_err)?;
        with_fields(inner, fields)
    }

    /// A sweep from TOML text; relative paths in it are relative to `base_dir`.
    #[staticmethod]
    #[pyo3(signature = (text, base_dir = PathBuf::from("."), max_cases = None, fields = None))]
    fn from_toml(
        text: &str,
        base_dir: PathBuf,
        max_cases: Option<u64>,
        fields: Option<&str>,
    ) -> PyResult<Self> {
        let inner =
            CaseSweep::from_toml_str_with_limit(text, &base_dir, max_cases).map_err(sweep_err)?;
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
    fn chunk_range(&self, index: u64) -> PyResult<(u64, u64)> {
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
    fn prepare(&self, out_dir: PathBuf) -> PyResult<()> {
        self.inner.prepare(&out_dir).map_err(sweep_err)
    }

    /// Indices of the chunks not yet in `out_dir`, ascending.
    fn missing_chunks(&self, out_dir: PathBuf) -> PyResult<Vec<u64>> {
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
        index: u64,
        out_dir: PathBuf,
        threads: Option<usize>,
    ) -> PyResult<Bound<'py, PyDict>> {
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
    #[pyo3(signature = (out_dir, format = "parquet"))]
    fn combine(&self, py: Python<'_>, out_dir: PathBuf, format: &str) -> PyResult<String> {
        let format = match format {
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
