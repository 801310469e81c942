//! The output directory of a sweep: the manifest, the chunk files, running chunks and
//! combining them.
//!
//! ```text
//! OUT/sweep.json                  manifest: hash of the normalised definition, counts, parameters
//! OUT/chunks/chunk-000042.parquet the rows of chunk 42 (cases 42·chunk_size ..), written to a
//!                                 temporary file and renamed: a chunk file is complete or absent
//! OUT/results.parquet | .csv      every case once, in case order (after the last chunk)
//! ```

use super::table::{self, CASE_COLUMN, Row, STATUS_COLUMN, Status};
use super::{Fields, MAX_THREADS, Sweep, SweepError, SweepResult, input};
use crate::case::Case;
use arrow_array::{Array, ArrayRef, RecordBatch, StringArray, UInt64Array};
use arrow_schema::{DataType, Field, Schema};
use parquet::arrow::ArrowWriter;
use parquet::arrow::arrow_reader::ParquetRecordBatchReaderBuilder;
use parquet::basic::Compression;
use parquet::file::properties::WriterProperties;
use rayon::prelude::*;
use std::fs::File;
use std::io::Write as _;
use std::path::{Path, PathBuf};
use std::sync::Arc;
use std::sync::atomic::{AtomicU64, Ordering};
use std::time::Instant;

/// The manifest's file name in the output directory.
pub const MANIFEST: &str = "sweep.json";
/// The folder of the chunk files in the output directory.
pub const CHUNKS_DIR: &str = "chunks";
/// The folder of the fields (`fields = "npy"`) in the output directory.
pub const FIELDS_DIR: &str = "fields";

/// The file of field `name` of case `index` in its chunk's fields folder.
fn field_file_name(index: u64, name: &str) -> String {
    format!("case-{index:09}-{name}.npy")
}

/// Write `field` as a NumPy `.npy` file: little-endian float64, shape `[ny, nx]`, C order
/// (row `j` is `y(j)`, column `i` is `x(i)`).
fn write_npy(path: &Path, field: &crate::FieldView<'_>) -> SweepResult<()> {
    use npyz::WriterBuilder as _;
    let write = || -> std::io::Result<()> {
        let file = std::io::BufWriter::new(File::create(path)?);
        let shape = [field.grid.ny() as u64, field.grid.nx() as u64];
        let little_f8: npyz::TypeStr = "<f8"
            .parse()
            .map_err(|e| std::io::Error::other(format!("{e}")))?;
        let mut w = npyz::WriteOptions::new()
            .dtype(npyz::DType::Plain(little_f8))
            .shape(&shape)
            .writer(file)
            .begin_nd()?;
        w.extend(field.values.iter().copied())?;
        w.finish()
    };
    write().map_err(|e| SweepError::io(path, e))
}

/// A rayon pool of `threads` threads (0: the available cores, at most [`MAX_THREADS`]).
fn thread_pool(threads: usize, out_dir: &Path) -> SweepResult<(usize, rayon::ThreadPool)> {
    let threads = match threads {
        0 => std::thread::available_parallelism()
            .map(usize::from)
            .unwrap_or(1)
            .min(MAX_THREADS),
        t if t <= MAX_THREADS => t,
        t => {
            return Err(input(format!(
                "invalid threads = {t}: expected 1..={MAX_THREADS}"
            )));
        }
    };
    let pool = rayon::ThreadPoolBuilder::new()
        .num_threads(threads)
        .build()
        .map_err(|e| table_err(out_dir, format!("thread pool: {e}")))?;
    Ok((threads, pool))
}

/// A row for an error that cannot happen (a case evaluated without writing files).
fn unreachable_row(error: String) -> Row {
    Row {
        status: Status::Failed,
        error: Some(error),
        outputs: Vec::new(),
    }
}

/// Format of the combined results.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum OutputFormat {
    /// `results.parquet` (the chunks' own format; typed columns).
    #[default]
    Parquet,
    /// `results.csv` (header line; empty field for a missing value; floats exact).
    Csv,
}

impl OutputFormat {
    /// The combined file's name.
    pub fn file_name(self) -> &'static str {
        match self {
            OutputFormat::Parquet => "results.parquet",
            OutputFormat::Csv => "results.csv",
        }
    }
}

/// What [`Sweep::run_chunk`] did.
#[derive(Debug, Clone, PartialEq)]
pub struct ChunkSummary {
    /// Chunk index.
    pub index: u64,
    /// Cases in the chunk.
    pub cases: u64,
    /// Cases whose status is not `ok`.
    pub not_ok: u64,
    /// The chunk file written.
    pub path: PathBuf,
    /// Wall-clock time \[s\].
    pub seconds: f64,
}

/// What [`Sweep::combine`] wrote.
#[derive(Debug, Clone, PartialEq)]
pub struct CombineSummary {
    /// The combined file.
    pub path: PathBuf,
    /// Rows written (= cases).
    pub rows: u64,
    /// Rows whose status is not `ok`.
    pub not_ok: u64,
    /// Column names, in order.
    pub columns: Vec<String>,
}

/// Progress of [`Sweep::run_local`], reported after every case.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Progress {
    /// Cases done, counting those of chunks found complete.
    pub cases_done: u64,
    /// Cases of the sweep.
    pub cases_total: u64,
}

/// Options of [`Sweep::run_local`].
#[derive(Clone, Copy, Default)]
pub struct LocalOptions<'a> {
    /// Worker threads, 1..=[`MAX_THREADS`]; 0: the available cores (at most `MAX_THREADS`).
    pub threads: usize,
    /// Format of the combined results.
    pub format: OutputFormat,
    /// Called after every case (from the worker threads).
    pub progress: Option<&'a (dyn Fn(Progress) + Sync)>,
}

/// What [`Sweep::run_local`] did.
#[derive(Debug, Clone, PartialEq)]
pub struct LocalSummary {
    /// Chunks of the sweep.
    pub chunks: u64,
    /// Chunks computed by this run.
    pub chunks_computed: u64,
    /// Chunks found complete in the directory and not recomputed.
    pub chunks_reused: u64,
    /// Cases computed by this run.
    pub cases_computed: u64,
    /// Worker threads used.
    pub threads: usize,
    /// Wall-clock time computing the chunks \[s\].
    pub seconds_computing: f64,
    /// Wall-clock time combining \[s\].
    pub seconds_combining: f64,
    /// The combined results.
    pub combined: CombineSummary,
}

fn table_err(path: &Path, e: impl std::fmt::Display) -> SweepError {
    SweepError::Table {
        path: path.to_path_buf(),
        message: e.to_string(),
    }
}

static TEMP_COUNTER: AtomicU64 = AtomicU64::new(0);

/// Write `path` through a temporary file in the same folder, synced and renamed: a reader
/// (or a rerun after a kill) sees the complete file or none.
fn write_atomic(path: &Path, write: impl FnOnce(File) -> Result<File, String>) -> SweepResult<()> {
    let dir = path.parent().unwrap_or(Path::new("."));
    let name = path
        .file_name()
        .map(|n| n.to_string_lossy().into_owned())
        .unwrap_or_default();
    let temp = dir.join(format!(
        ".{name}.{}-{}.tmp",
        std::process::id(),
        TEMP_COUNTER.fetch_add(1, Ordering::Relaxed)
    ));
    let file = File::create(&temp).map_err(|e| SweepError::io(&temp, e))?;
    let result = write(file).and_then(|f| f.sync_all().map_err(|e| e.to_string()));
    if let Err(message) = result {
        let _ = std::fs::remove_file(&temp);
        return Err(table_err(path, message));
    }
    std::fs::rename(&temp, path).map_err(|e| {
        let _ = std::fs::remove_file(&temp);
        SweepError::io(path, e)
    })
}

fn writer_properties() -> WriterProperties {
    WriterProperties::builder()
        .set_compression(Compression::SNAPPY)
        .build()
}

impl Sweep {
    /// The file of chunk `index` in `out_dir`: `chunks/chunk-000042.parquet`.
    pub fn chunk_path(&self, out_dir: &Path, index: u64) -> PathBuf {
        out_dir
            .join(CHUNKS_DIR)
            .join(format!("chunk-{index:06}.parquet"))
    }

    fn manifest(&self) -> serde_json::Value {
        serde_json::json!({
            "format": "kontakt-sweep",
            "format_version": 1,
            "hash": self.hash(),
            "kontakt_version": kontakt::VERSION,
            "name": self.name(),
            "mode": self.mode().as_str(),
            "cases": self.len(),
            "chunk_size": self.chunk_size(),
            "chunks": self.chunk_count(),
            "parameters": self.parameters().iter().map(|p| serde_json::json!({
                "name": p.name,
                "keys": p.keys(),
                "count": p.values.len(),
            })).collect::<Vec<_>>(),
            "definition": self.definition(),
        })
    }

    /// Whether `out_dir` holds this sweep (`Some(true)`), another one (an error), or none
    /// yet (`Some(false)`: no manifest).
    fn check_manifest(&self, out_dir: &Path) -> SweepResult<bool> {
        let path = out_dir.join(MANIFEST);
        // The manifest is this program's own file, read through the same capped reader.
        let read = std::fs::File::open(&path).and_then(|f| {
            let mut text = String::new();
            std::io::Read::read_to_string(
                &mut crate::files::Capped::new(f, crate::files::MAX_DATA_FILE_BYTES, true),
                &mut text,
            )
            .map(|_| text)
        });
        let text = match read {
            Ok(t) => t,
            Err(e) if e.kind() == std::io::ErrorKind::NotFound => {
                let chunks = out_dir.join(CHUNKS_DIR);
                let has_chunks = std::fs::read_dir(&chunks)
                    .map(|mut d| d.any(|e| e.is_ok()))
                    .unwrap_or(false);
                if has_chunks {
                    return Err(input(format!(
                        "output directory {} has chunk files but no {MANIFEST}: it does not hold this sweep; use another directory or remove it",
                        out_dir.display()
                    )));
                }
                return Ok(false);
            }
            Err(e) => return Err(SweepError::io(&path, e)),
        };
        let hash = serde_json::from_str::<serde_json::Value>(&text)
            .ok()
            .and_then(|v| v["hash"].as_str().map(str::to_string));
        match hash {
            Some(h) if h == self.hash() => Ok(true),
            Some(h) => Err(input(format!(
                "output directory {} holds a different sweep ({MANIFEST} has hash {h}, this sweep is {}): use another directory, or remove it to start over",
                out_dir.display(),
                self.hash()
            ))),
            None => Err(input(format!(
                "output directory {}: {} is not a kontakt sweep manifest; use another directory",
                out_dir.display(),
                path.display()
            ))),
        }
    }

    /// Make `out_dir` ready for this sweep: create it and `chunks/`, write the manifest,
    /// or check that the manifest there is this sweep's.
    ///
    /// # Errors
    /// [`SweepError::Input`] when the directory holds a different sweep (the message
    /// names the directory and both hashes); [`SweepError::Io`] when it cannot be written.
    pub fn prepare(&self, out_dir: &Path) -> SweepResult<()> {
        let chunks = out_dir.join(CHUNKS_DIR);
        if self.check_manifest(out_dir)? {
            return std::fs::create_dir_all(&chunks).map_err(|e| SweepError::io(&chunks, e));
        }
        std::fs::create_dir_all(&chunks).map_err(|e| SweepError::io(&chunks, e))?;
        let text = serde_json::to_string_pretty(&self.manifest())
            .map_err(|e| table_err(&out_dir.join(MANIFEST), e))?;
        write_atomic(&out_dir.join(MANIFEST), |mut f| {
            f.write_all(text.as_bytes()).map_err(|e| e.to_string())?;
            f.write_all(b"\n").map_err(|e| e.to_string())?;
            Ok(f)
        })
    }

    /// Indices of the chunks without a file in `out_dir` (all of them when the directory
    /// holds no sweep yet), ascending.
    ///
    /// # Errors
    /// As [`Sweep::prepare`], when the directory holds a different sweep.
    pub fn missing_chunks(&self, out_dir: &Path) -> SweepResult<Vec<u64>> {
        let known = self.check_manifest(out_dir)?;
        Ok((0..self.chunk_count())
            .filter(|&i| !known || !self.chunk_path(out_dir, i).is_file())
            .collect())
    }

    /// Run case `index` (never panics: a panic of a solver becomes status `panic`): its
    /// report flattened, as a chunk's rows are but for a bearing sweep, whose chunks hold
    /// the bearing columns of [`super::bearing::COLUMNS`] (a warm-started solve).
    pub fn evaluate(&self, index: u64) -> Row {
        // Without a fields folder nothing is written, so nothing can fail.
        self.evaluate_case(index, None)
            .unwrap_or_else(|e| unreachable_row(e.to_string()))
    }

    /// Run case `index`; with `fields_dir`, write its fields there as
    /// `case-NNNNNNNNN-<name>.npy` (an error only when a file cannot be written).
    fn evaluate_case(&self, index: u64, fields_dir: Option<&Path>) -> SweepResult<Row> {
        let fail = |status, error: String| Row {
            status,
            error: Some(error),
            outputs: Vec::new(),
        };
        let case = match self
            .case_table(index)
            .and_then(|t| Case::from_toml_table(t).map_err(|e| input(e.to_string())))
        {
            Ok(c) => c,
            Err(e) => return Ok(fail(Status::Invalid, e.to_string())),
        };
        let run =
            std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| case.run(self.base_dir())));
        Ok(match run {
            Ok(Ok(outcome)) => match serde_json::to_value(&outcome) {
                Ok(v) => {
                    if let Some(dir) = fields_dir {
                        for field in outcome.fields() {
                            write_npy(&dir.join(field_file_name(index, field.name)), &field)?;
                        }
                    }
                    Row {
                        status: if outcome.warnings().is_empty() {
                            Status::Ok
                        } else {
                            Status::Warning
                        },
                        error: None,
                        outputs: table::flatten(&v),
                    }
                }
                Err(e) => fail(Status::Failed, format!("report: {e}")),
            },
            Ok(Err(e @ kontakt::Error::NotConverged { .. })) => fail(Status::Failed, e.to_string()),
            Ok(Err(e)) => fail(Status::Invalid, e.to_string()),
            Err(payload) => {
                let msg = payload
                    .downcast_ref::<&str>()
                    .map(|s| (*s).to_string())
                    .or_else(|| payload.downcast_ref::<String>().cloned())
                    .unwrap_or_else(|| "unknown panic".into());
                fail(Status::Panic, format!("panic: {msg}"))
            }
        })
    }

    /// The table of chunk `index` (computed in parallel on the current rayon pool, in
    /// case order; `on_case` after each case) and its number of cases not solved. With
    /// `fields_dir` each case's fields are written there (not for a bearing sweep, which
    /// has no fields).
    fn chunk_batch_and_not_ok(
        &self,
        index: u64,
        fields_dir: Option<&Path>,
        on_case: &(dyn Fn() + Sync),
        path: &Path,
    ) -> SweepResult<(RecordBatch, u64, u64)> {
        let first = self.chunk_range(index).start;
        if let Some(plan) = &self.bearing {
            let rows = self.bearing_rows(plan, self.chunk_range(index), on_case);
            let not_ok = rows.iter().filter(|r| !r.status.solved()).count() as u64;
            let batch = table::bearing_batch(self, first, &rows).map_err(|m| table_err(path, m))?;
            return Ok((batch, rows.len() as u64, not_ok));
        }
        let rows = self.chunk_rows(index, fields_dir, on_case)?;
        let not_ok = rows.iter().filter(|r| !r.status.solved()).count() as u64;
        let batch = table::chunk_batch(self, first, &rows).map_err(|m| table_err(path, m))?;
        Ok((batch, rows.len() as u64, not_ok))
    }

    /// The rows of chunk `index`, computed in parallel on the current rayon pool, in
    /// case order; `on_case` is called after each case. With `fields_dir` each case's
    /// fields are written there.
    fn chunk_rows(
        &self,
        index: u64,
        fields_dir: Option<&Path>,
        on_case: &(dyn Fn() + Sync),
    ) -> SweepResult<Vec<Row>> {
        self.chunk_range(index)
            .into_par_iter()
            .map(|i| {
                let row = self.evaluate_case(i, fields_dir);
                on_case();
                row
            })
            .collect()
    }

    /// The folder of chunk `index`'s fields in `out_dir`: `fields/chunk-000042`.
    pub fn fields_dir(&self, out_dir: &Path, index: u64) -> PathBuf {
        out_dir.join(FIELDS_DIR).join(format!("chunk-{index:06}"))
    }

    /// The table of chunk `index`, computed in memory (no file): for a driver that keeps
    /// the rows itself.
    ///
    /// # Errors
    /// [`SweepError::Input`] for `index >= chunk_count()`.
    pub fn chunk_table(&self, index: u64) -> SweepResult<RecordBatch> {
        self.check_chunk_index(index)?;
        let (batch, _, _) =
            self.chunk_batch_and_not_ok(index, None, &|| {}, Path::new("<memory>"))?;
        Ok(batch)
    }

    fn check_chunk_index(&self, index: u64) -> SweepResult<()> {
        if index >= self.chunk_count() {
            return Err(input(format!(
                "invalid chunk index = {index}: expected 0..{}",
                self.chunk_count()
            )));
        }
        Ok(())
    }

    /// Run chunk `index` and write `OUT/chunks/chunk-NNNNNN.parquet` atomically (an
    /// existing file is replaced with the same content). Cases run in parallel on the
    /// current rayon pool. Safe to call from several processes for different chunks.
    ///
    /// # Errors
    /// An index out of range or a directory holding a different sweep
    /// ([`SweepError::Input`]); a file that cannot be written.
    pub fn run_chunk(&self, index: u64, out_dir: &Path) -> SweepResult<ChunkSummary> {
        self.check_chunk_index(index)?;
        self.prepare(out_dir)?;
        self.run_chunk_prepared(index, out_dir, &|| {})
    }

    /// As [`Sweep::run_chunk`], on a pool of its own of `threads` threads (0: the available
    /// cores) instead of the current rayon pool: for a driver whose workers each own a
    /// share of the cores (a Dask worker with `nthreads`), so that they do not
    /// oversubscribe the machine.
    ///
    /// # Errors
    /// As [`Sweep::run_chunk`], and `threads` above [`MAX_THREADS`].
    pub fn run_chunk_threads(
        &self,
        index: u64,
        out_dir: &Path,
        threads: usize,
    ) -> SweepResult<ChunkSummary> {
        let (_, pool) = thread_pool(threads, out_dir)?;
        pool.install(|| self.run_chunk(index, out_dir))
    }

    fn run_chunk_prepared(
        &self,
        index: u64,
        out_dir: &Path,
        on_case: &(dyn Fn() + Sync),
    ) -> SweepResult<ChunkSummary> {
        let start = Instant::now();
        // Fields first, into a temporary folder renamed into place before the chunk file is
        // written: a chunk file on disk means its fields are complete too.
        let fields = match self.fields() {
            Fields::None => None,
            Fields::Npy => Some(self.fields_dir(out_dir, index)),
        };
        let temp = fields.as_ref().map(|dir| {
            dir.with_file_name(format!(
                ".chunk-{index:06}.{}-{}.tmp",
                std::process::id(),
                TEMP_COUNTER.fetch_add(1, Ordering::Relaxed)
            ))
        });
        if let Some(t) = &temp {
            std::fs::create_dir_all(t).map_err(|e| SweepError::io(t, e))?;
        }
        let path = self.chunk_path(out_dir, index);
        let (batch, cases, not_ok) =
            match self.chunk_batch_and_not_ok(index, temp.as_deref(), on_case, &path) {
                Ok(r) => r,
                Err(e) => {
                    if let Some(t) = &temp {
                        let _ = std::fs::remove_dir_all(t);
                    }
                    return Err(e);
                }
            };
        if let (Some(t), Some(dir)) = (&temp, &fields) {
            // A folder left by a run killed between this rename and the chunk file.
            if dir.exists() {
                std::fs::remove_dir_all(dir).map_err(|e| SweepError::io(dir, e))?;
            }
            std::fs::rename(t, dir).map_err(|e| SweepError::io(dir, e))?;
        }
        write_atomic(&path, |file| {
            let mut w = ArrowWriter::try_new(file, batch.schema(), Some(writer_properties()))
                .map_err(|e| e.to_string())?;
            w.write(&batch).map_err(|e| e.to_string())?;
            w.into_inner().map_err(|e| e.to_string())
        })?;
        Ok(ChunkSummary {
            index,
            cases,
            not_ok,
            path,
            seconds: start.elapsed().as_secs_f64(),
        })
    }

    /// Combine every chunk of `out_dir` into `OUT/results.parquet` or `OUT/results.csv`
    /// (atomically): each case exactly once, in case order. The columns are the union over
    /// the chunks (a value a chunk lacks is missing); a column that is integer in one chunk
    /// and float in another becomes float, one with text becomes text.
    ///
    /// # Errors
    /// [`SweepError::Input`] when chunks are missing (named) or the directory holds
    /// another sweep; [`SweepError::Table`] when a chunk does not hold the cases its
    /// index says, or cannot be read.
    pub fn combine(&self, out_dir: &Path, format: OutputFormat) -> SweepResult<CombineSummary> {
        let missing = self.missing_chunks(out_dir)?;
        if !missing.is_empty() {
            let shown: Vec<String> = missing.iter().take(5).map(u64::to_string).collect();
            return Err(input(format!(
                "output directory {}: {} of {} chunks missing ({}{}): run the sweep again to compute them",
                out_dir.display(),
                missing.len(),
                self.chunk_count(),
                shown.join(", "),
                if missing.len() > 5 { ", ..." } else { "" }
            )));
        }
        // Pass 1: the union of the chunks' columns, from the files' footers.
        let mut fields: Vec<(String, DataType)> = Vec::new();
        for i in 0..self.chunk_count() {
            let path = self.chunk_path(out_dir, i);
            let file = File::open(&path).map_err(|e| SweepError::io(&path, e))?;
            let builder =
                ParquetRecordBatchReaderBuilder::try_new(file).map_err(|e| table_err(&path, e))?;
            for f in builder.schema().fields() {
                match fields.iter_mut().find(|(n, _)| n == f.name()) {
                    Some((_, ty)) => *ty = table::unify(ty, f.data_type()),
                    None => fields.push((f.name().clone(), f.data_type().clone())),
                }
            }
        }
        let schema = Arc::new(Schema::new(
            fields
                .iter()
                .map(|(n, t)| Field::new(n, t.clone(), n != CASE_COLUMN && n != STATUS_COLUMN))
                .collect::<Vec<_>>(),
        ));
        let out = out_dir.join(format.file_name());
        let mut rows = 0u64;
        let mut not_ok = 0u64;
        write_atomic(&out, |file| {
            let mut sink = match format {
                OutputFormat::Parquet => Sink::Parquet(
                    ArrowWriter::try_new(file, schema.clone(), Some(writer_properties()))
                        .map_err(|e| e.to_string())?,
                ),
                OutputFormat::Csv => {
                    let mut w = csv::Writer::from_writer(file);
                    w.write_record(fields.iter().map(|(n, _)| n.as_str()))
                        .map_err(|e| e.to_string())?;
                    Sink::Csv(w)
                }
            };
            for i in 0..self.chunk_count() {
                let path = self.chunk_path(out_dir, i);
                let expected = self.chunk_range(i);
                let mut next = expected.start;
                let file = File::open(&path).map_err(|e| format!("{}: {e}", path.display()))?;
                let reader = ParquetRecordBatchReaderBuilder::try_new(file)
                    .and_then(|b| b.build())
                    .map_err(|e| format!("{}: {e}", path.display()))?;
                for batch in reader {
                    let batch = batch.map_err(|e| format!("{}: {e}", path.display()))?;
                    let cases = batch
                        .column_by_name(CASE_COLUMN)
                        .and_then(|c| c.as_any().downcast_ref::<UInt64Array>())
                        .ok_or_else(|| format!("{}: no `case` column", path.display()))?;
                    for c in cases.values().iter() {
                        // A case with a list of rows (friction, rough) has several table
                        // rows in a run: a repeat of the case just seen.
                        if *c + 1 == next && next > expected.start {
                            continue;
                        }
                        if *c != next || next >= expected.end {
                            return Err(format!(
                                "{}: case {c} where case {next} was expected (chunk {i} holds cases {}..{}): delete the file and run the sweep again",
                                path.display(),
                                expected.start,
                                expected.end
                            ));
                        }
                        next += 1;
                    }
                    let columns: Vec<ArrayRef> = fields
                        .iter()
                        .map(|(n, ty)| match batch.column_by_name(n) {
                            Some(a) => table::conform(a, ty),
                            None => arrow_array::new_null_array(ty, batch.num_rows()),
                        })
                        .collect();
                    if let Some(s) = batch
                        .column_by_name(STATUS_COLUMN)
                        .and_then(|c| c.as_any().downcast_ref::<StringArray>())
                    {
                        not_ok += s
                            .iter()
                            .filter(|v| !matches!(v, Some("ok" | "warning" | "lifted_off")))
                            .count() as u64;
                    }
                    rows += batch.num_rows() as u64;
                    let batch = RecordBatch::try_new(schema.clone(), columns)
                        .map_err(|e| format!("{}: {e}", path.display()))?;
                    sink.write(&batch)?;
                }
                if next != expected.end {
                    return Err(format!(
                        "{}: holds cases {}..{next}, chunk {i} is cases {}..{}: delete the file and run the sweep again",
                        path.display(),
                        expected.start,
                        expected.start,
                        expected.end
                    ));
                }
            }
            sink.finish()
        })?;
        Ok(CombineSummary {
            path: out,
            rows,
            not_ok,
            columns: fields.into_iter().map(|(n, _)| n).collect(),
        })
    }

    /// Run the sweep on the local cores: check or write the manifest, compute the missing
    /// chunks in order (the cases of a chunk in parallel), then [`Sweep::combine`]. A rerun
    /// into the same directory computes only the chunks not yet there. One local run per
    /// directory at a time (temporary files of an earlier, killed run are removed).
    ///
    /// # Errors
    /// `threads` above [`MAX_THREADS`] or a directory holding another sweep
    /// ([`SweepError::Input`]); files that cannot be written.
    pub fn run_local(
        &self,
        out_dir: &Path,
        options: LocalOptions<'_>,
    ) -> SweepResult<LocalSummary> {
        let (threads, pool) = thread_pool(options.threads, out_dir)?;
        self.prepare(out_dir)?;
        // Temporary files and field folders left by a killed run.
        for dir in [out_dir.join(CHUNKS_DIR), out_dir.join(FIELDS_DIR)] {
            if let Ok(entries) = std::fs::read_dir(&dir) {
                for e in entries.flatten() {
                    if e.file_name().to_string_lossy().ends_with(".tmp") {
                        let path = e.path();
                        let _ = if path.is_dir() {
                            std::fs::remove_dir_all(path)
                        } else {
                            std::fs::remove_file(path)
                        };
                    }
                }
            }
        }
        let missing = self.missing_chunks(out_dir)?;
        let todo: u64 = missing
            .iter()
            .map(|&i| {
                let r = self.chunk_range(i);
                r.end - r.start
            })
            .sum();
        let done = AtomicU64::new(self.len() - todo);
        let report = |d: u64| {
            if let Some(p) = options.progress {
                p(Progress {
                    cases_done: d,
                    cases_total: self.len(),
                });
            }
        };
        report(done.load(Ordering::Relaxed));
        let on_case = || report(done.fetch_add(1, Ordering::Relaxed) + 1);
        let start = Instant::now();
        for &i in &missing {
            pool.install(|| self.run_chunk_prepared(i, out_dir, &on_case))?;
        }
        let seconds_computing = start.elapsed().as_secs_f64();
        let start = Instant::now();
        let combined = self.combine(out_dir, options.format)?;
        Ok(LocalSummary {
            chunks: self.chunk_count(),
            chunks_computed: missing.len() as u64,
            chunks_reused: self.chunk_count() - missing.len() as u64,
            cases_computed: todo,
            threads,
            seconds_computing,
            seconds_combining: start.elapsed().as_secs_f64(),
            combined,
        })
    }
}

enum Sink {
    Parquet(ArrowWriter<File>),
    Csv(csv::Writer<File>),
}

impl Sink {
    fn write(&mut self, batch: &RecordBatch) -> Result<(), String> {
        match self {
            Sink::Parquet(w) => w.write(batch).map_err(|e| e.to_string()),
            Sink::Csv(w) => {
                let columns = batch.columns();
                let mut record: Vec<String> = vec![String::new(); columns.len()];
                for r in 0..batch.num_rows() {
                    for (slot, c) in record.iter_mut().zip(columns) {
                        *slot = table::text_at(c, r).unwrap_or_default();
                    }
                    w.write_record(&record).map_err(|e| e.to_string())?;
                }
                Ok(())
            }
        }
    }

    fn finish(self) -> Result<File, String> {
        match self {
            Sink::Parquet(w) => w.into_inner().map_err(|e| e.to_string()),
            Sink::Csv(w) => w.into_inner().map_err(|e| e.to_string()),
        }
    }
}
