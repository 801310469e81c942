//! Parameter sweeps: one base case (any method of [`Case`]) and parameters given by their
//! dotted key paths into it, expanded as a full grid or as zipped points, run chunk by
//! chunk into Parquet files that a rerun resumes (schema and layout: `docs/sweep.md`).
//!
//! ```toml
//! mode = "grid"                       # or "points": the i-th value of every parameter
//! base = "../ball_on_flat.toml"       # a case file (relative to this file), or an inline [base] table
//! chunk_size = 4096                   # cases per chunk file (1..=10 000 000)
//! fields = "none"                     # or "npy": every case's fields as .npy files too
//!
//! [[parameter]]
//! key = "load.force_n"                # N
//! start = 10.0
//! stop = 1000.0
//! count = 100
//! spacing = "log"                     # or "linear" (default)
//!
//! [[parameter]]
//! key = ["body1.radii_mm[0]", "body1.radii_mm[1]"]   # one value set at several keys (mm)
//! name = "ball_radius_mm"             # the column name (default: the first key)
//! values = [3.0, 5.0, 6.35]
//! ```
//!
//! A case is built by editing the parsed base table (no TOML text per case) and read with
//! [`Case::from_toml_table`]; its report's scalars become one row (see [`table`]).
//!
//! The API is made for a driver that runs chunks on its own workers (Python/Dask):
//! [`Sweep::from_path`], [`Sweep::len`], [`Sweep::chunk_count`], [`Sweep::chunk_range`],
//! [`Sweep::missing_chunks`], [`Sweep::run_chunk`] (writes one chunk atomically),
//! [`Sweep::combine`]; [`Sweep::run_local`] does all of it on the local cores.
//!
//! A whole-bearing base case (`method = "bearing"`) runs through a planned solver with
//! warm starts and gives a fixed set of numeric columns: see [`bearing`].

pub mod bearing;
mod store;
pub mod table;

pub use store::{
    ChunkSummary, CombineSummary, FIELDS_DIR, LocalOptions, LocalSummary, OutputFormat, Progress,
};

use crate::case::Case;
use crate::common::case_file_error;
use serde::Deserialize;
use std::fmt::Write as _;
use std::ops::Range;
use std::path::{Path, PathBuf};

/// Cases per chunk file when the sweep file does not say.
pub const DEFAULT_CHUNK_SIZE: u64 = 4096;
/// Largest `chunk_size` accepted.
pub const MAX_CHUNK_SIZE: u64 = 10_000_000;
/// Largest number of cases run without `max_cases` raised in the sweep file (or
/// `--max-cases`).
pub const DEFAULT_MAX_CASES: u64 = 10_000_000;
/// Most worker threads of [`Sweep::run_local`]: the library's bound.
pub use kontakt::MAX_THREADS;

/// What can go wrong with a sweep.
#[derive(Debug, thiserror::Error)]
pub enum SweepError {
    /// Bad input: the sweep file, a parameter, the base case, or an output directory that
    /// holds a different sweep. One line naming the key, the value and what is valid.
    #[error("{0}")]
    Input(String),
    /// Reading or writing a file failed.
    #[error("{}: {source}", path.display())]
    Io {
        /// The file or directory.
        path: PathBuf,
        /// The operating system's error.
        source: std::io::Error,
    },
    /// A Parquet or Arrow table could not be written or read.
    #[error("{}: {message}", path.display())]
    Table {
        /// The file.
        path: PathBuf,
        /// The Parquet/Arrow library's message.
        message: String,
    },
}

impl SweepError {
    /// Whether the error is bad input (exit status 2 in the CLI) rather than a failure of
    /// the run (exit status 1).
    pub fn is_input(&self) -> bool {
        matches!(self, SweepError::Input(_))
    }

    pub(crate) fn io(path: &Path, source: std::io::Error) -> Self {
        SweepError::Io {
            path: path.to_path_buf(),
            source,
        }
    }
}

/// Result type of the sweep API.
pub type SweepResult<T> = std::result::Result<T, SweepError>;

fn input(msg: impl Into<String>) -> SweepError {
    // Messages quote the file's strings (a key path `"a\nb"`, found by fuzzing): control
    // characters are escaped so that the message stays on one line.
    let msg: String = msg.into();
    if msg.chars().any(char::is_control) {
        SweepError::Input(msg.chars().flat_map(char::escape_default).collect())
    } else {
        SweepError::Input(msg)
    }
}

/// How the parameters combine.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum SweepMode {
    /// Every combination; the last parameter varies fastest.
    #[default]
    Grid,
    /// The i-th value of every parameter together (all of one length).
    Points,
}

impl SweepMode {
    fn as_str(self) -> &'static str {
        match self {
            SweepMode::Grid => "grid",
            SweepMode::Points => "points",
        }
    }
}

/// Which fields a sweep stores besides its table (`fields` in the sweep file, `--fields`
/// on the command line).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Fields {
    /// The table only (the default): scalars are what most sweeps need.
    #[default]
    None,
    /// Also every field of every case as a NumPy `.npy` file (little-endian float64, shape
    /// `[ny, nx]`, C order): `OUT/fields/chunk-000042/case-000000042-pressure.npy`; see
    /// [`crate::Outcome::fields`] for which methods have which fields.
    Npy,
}

impl Fields {
    /// The name in the sweep file: `none` or `npy`.
    pub fn as_str(self) -> &'static str {
        match self {
            Fields::None => "none",
            Fields::Npy => "npy",
        }
    }
}

/// Spacing of a range.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Spacing {
    /// Equal steps.
    #[default]
    Linear,
    /// Equal ratios (start and stop > 0).
    Log,
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
struct SweepSpec {
    #[serde(default)]
    name: Option<String>,
    #[serde(default)]
    mode: SweepMode,
    base: BaseSpec,
    #[serde(default)]
    chunk_size: Option<i64>,
    #[serde(default)]
    max_cases: Option<i64>,
    #[serde(default)]
    fields: Fields,
    #[serde(default, rename = "parameter")]
    parameters: Vec<ParameterSpec>,
}

#[derive(Debug, Deserialize)]
#[serde(
    untagged,
    expecting = "expected a case file's path (a string) or an inline table of the base case"
)]
enum BaseSpec {
    Path(String),
    Inline(toml::Table),
}

#[derive(Debug, Deserialize)]
#[serde(
    untagged,
    expecting = "expected a key path (a string) or an array of key paths"
)]
enum KeySpec {
    One(String),
    Many(Vec<String>),
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
struct ParameterSpec {
    key: KeySpec,
    #[serde(default)]
    name: Option<String>,
    #[serde(default)]
    values: Option<Vec<toml::Value>>,
    #[serde(default)]
    start: Option<f64>,
    #[serde(default)]
    stop: Option<f64>,
    #[serde(default)]
    count: Option<i64>,
    #[serde(default)]
    spacing: Option<Spacing>,
}

/// One step of a key path: a table key or an array index.
#[derive(Debug, Clone, PartialEq, Eq)]
enum Segment {
    Key(String),
    Index(usize),
}

/// A parsed key path, e.g. `body1.radii_mm[0]`.
#[derive(Debug, Clone, PartialEq, Eq)]
struct KeyPath {
    text: String,
    segments: Vec<Segment>,
}

impl KeyPath {
    fn parse(text: &str, field: &str) -> SweepResult<Self> {
        let bad = || {
            input(format!(
                "invalid {field} = \"{text}\": expected a dotted key path into the base case, e.g. \"load.force_n\" or \"body1.radii_mm[0]\""
            ))
        };
        let mut segments = Vec::new();
        for part in text.split('.') {
            let (name, mut rest) = match part.find('[') {
                Some(p) => (&part[..p], &part[p..]),
                None => (part, ""),
            };
            if name.is_empty()
                || !name
                    .chars()
                    .all(|c| c.is_ascii_alphanumeric() || c == '_' || c == '-')
            {
                return Err(bad());
            }
            segments.push(Segment::Key(name.to_string()));
            while !rest.is_empty() {
                let close = rest.find(']').ok_or_else(bad)?;
                let index: usize = rest[1..close].parse().map_err(|_| bad())?;
                segments.push(Segment::Index(index));
                rest = &rest[close + 1..];
                if !rest.is_empty() && !rest.starts_with('[') {
                    return Err(bad());
                }
            }
        }
        Ok(KeyPath {
            text: text.to_string(),
            segments,
        })
    }

    /// Set `value` at this path in `table`, creating missing tables on the way.
    fn set(&self, table: &mut toml::Table, value: toml::Value) -> Result<(), String> {
        let Some((Segment::Key(first), rest)) = self.segments.split_first() else {
            return Err("the path must start with a key".into());
        };
        if rest.is_empty() {
            table.insert(first.clone(), value);
            return Ok(());
        }
        let mut here = table
            .entry(first.clone())
            .or_insert_with(|| toml::Value::Table(toml::Table::new()));
        let mut walked = first.clone();
        for (k, seg) in rest.iter().enumerate() {
            let last = k + 1 == rest.len();
            match seg {
                Segment::Key(name) => {
                    let toml::Value::Table(t) = here else {
                        return Err(format!("`{walked}` is not a table in the base case"));
                    };
                    if last {
                        t.insert(name.clone(), value);
                        return Ok(());
                    }
                    here = t
                        .entry(name.clone())
                        .or_insert_with(|| toml::Value::Table(toml::Table::new()));
                    walked.push('.');
                    walked.push_str(name);
                }
                Segment::Index(i) => {
                    let toml::Value::Array(a) = here else {
                        return Err(format!("`{walked}` is not an array in the base case"));
                    };
                    let len = a.len();
                    let slot = a.get_mut(*i).ok_or_else(|| {
                        format!("`{walked}` has {len} elements in the base case, no index {i}")
                    })?;
                    if last {
                        *slot = value;
                        return Ok(());
                    }
                    here = slot;
                    let _ = write!(walked, "[{i}]");
                }
            }
        }
        Ok(())
    }
}

/// The values of one parameter, computed on demand (a range of 10⁷ points is not stored).
#[derive(Debug, Clone, PartialEq)]
pub enum Values {
    /// `count` values from `start` to `stop` (both included) in equal steps.
    Linear {
        /// First value.
        start: f64,
        /// Last value.
        stop: f64,
        /// Number of values, >= 1.
        count: u64,
    },
    /// `count` values from `start` to `stop` (both included, > 0) in equal ratios.
    Log {
        /// First value.
        start: f64,
        /// Last value.
        stop: f64,
        /// Number of values, >= 1.
        count: u64,
    },
    /// The given values (any TOML values).
    List(Vec<toml::Value>),
}

impl Values {
    /// Number of values.
    pub fn len(&self) -> u64 {
        match self {
            Values::Linear { count, .. } | Values::Log { count, .. } => *count,
            Values::List(v) => v.len() as u64,
        }
    }

    /// Whether there are no values (never for a validated sweep).
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }

    /// The j-th value (`j < len()`); the last value of a range is `stop` exactly.
    pub fn get(&self, j: u64) -> toml::Value {
        match self {
            Values::Linear { start, stop, count } => {
                toml::Value::Float(range_point(*start, *stop, *count, j, |a, b, j, m| {
                    a + (b - a) * j / m
                }))
            }
            Values::Log { start, stop, count } => {
                toml::Value::Float(range_point(*start, *stop, *count, j, |a, b, j, m| {
                    (a.ln() + (b.ln() - a.ln()) * j / m).exp()
                }))
            }
            Values::List(v) => v
                .get(usize::try_from(j).unwrap_or(usize::MAX))
                .cloned()
                .unwrap_or(toml::Value::Boolean(false)),
        }
    }
}

/// Point `j` of `count` from `start` to `stop`: the ends exactly, between them
/// `f(start, stop, j, count - 1)` (a step times `j` before the division, so that
/// 100..3000 in 30 points gives 1800, not 1799.9999999999998).
fn range_point(
    start: f64,
    stop: f64,
    count: u64,
    j: u64,
    f: impl Fn(f64, f64, f64, f64) -> f64,
) -> f64 {
    if j == 0 || count < 2 {
        start
    } else if j + 1 == count {
        stop
    } else {
        f(start, stop, j as f64, (count - 1) as f64)
    }
}

/// The column type of a parameter's values.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ValueKind {
    /// Floats (ranges; lists of numbers with a float among them).
    Float,
    /// Integers only.
    Integer,
    /// Booleans only.
    Boolean,
    /// Strings only, or mixed or structured values (written as TOML text).
    Text,
}

/// One swept parameter.
#[derive(Debug, Clone, PartialEq)]
pub struct Parameter {
    /// Column name (`name`, or the first key).
    pub name: String,
    keys: Vec<KeyPath>,
    /// The values.
    pub values: Values,
    /// Column type.
    pub kind: ValueKind,
}

impl Parameter {
    /// The key paths this parameter sets (all to the same value).
    pub fn keys(&self) -> Vec<&str> {
        self.keys.iter().map(|k| k.text.as_str()).collect()
    }
}

/// A parsed, validated parameter sweep. Cheap to share between threads (`Sync`).
#[derive(Debug, Clone)]
pub struct Sweep {
    name: Option<String>,
    mode: SweepMode,
    base: toml::Table,
    base_dir: PathBuf,
    parameters: Vec<Parameter>,
    /// Grid strides: index of parameter p = (case / strides[p]) % len_p.
    strides: Vec<u64>,
    len: u64,
    chunk_size: u64,
    fields: Fields,
    definition: String,
    hash: String,
    /// A bearing base case: how the parameters reach the planned solver
    /// ([`bearing`]); `None` for the other methods.
    bearing: Option<bearing::BearingPlan>,
}

impl Sweep {
    /// Read a sweep file; a relative `base` path is taken from the file's folder.
    ///
    /// # Errors
    /// [`SweepError::Io`] when the file cannot be read, [`SweepError::Input`] as
    /// [`Sweep::from_toml_str`].
    pub fn from_path(path: &Path) -> SweepResult<Self> {
        Self::from_path_with_limit(path, None)
    }

    /// Parse a sweep from TOML text; `base_dir` resolves a relative `base` path (and,
    /// for an inline base case, the case's own relative paths such as gap maps).
    ///
    /// # Errors
    /// [`SweepError::Input`] naming the key for: malformed TOML or unknown keys, a
    /// parameter key the base case does not have (or the case reader rejects), an empty
    /// or invalid range, lists of unequal length in `points` mode, and more cases than
    /// `max_cases` (default [`DEFAULT_MAX_CASES`]), counted before anything is allocated.
    pub fn from_toml_str(text: &str, base_dir: &Path) -> SweepResult<Self> {
        Self::from_toml_str_with_limit(text, base_dir, None)
    }

    /// As [`Sweep::from_toml_str`], with `max_cases` (when `Some`) replacing the sweep
    /// file's limit.
    ///
    /// # Errors
    /// As [`Sweep::from_toml_str`].
    pub fn from_toml_str_with_limit(
        text: &str,
        base_dir: &Path,
        max_cases: Option<u64>,
    ) -> SweepResult<Self> {
        let spec: SweepSpec = toml::from_str(text).map_err(|e| {
            input(format!(
                "sweep file: {}",
                case_file_error::<SweepSpec>(text, &e)
            ))
        })?;
        Self::from_spec(spec, base_dir, max_cases)
    }

    /// As [`Sweep::from_path`], with `max_cases` (when `Some`) replacing the file's limit.
    ///
    /// # Errors
    /// As [`Sweep::from_path`].
    pub fn from_path_with_limit(path: &Path, max_cases: Option<u64>) -> SweepResult<Self> {
        let text = crate::read_case_file(path).map_err(|e| input(e.to_string()))?;
        let dir = match path.parent() {
            Some(d) if !d.as_os_str().is_empty() => d,
            _ => Path::new("."),
        };
        Self::from_toml_str_with_limit(&text, dir, max_cases).map_err(|e| match e {
            SweepError::Input(m) => SweepError::Input(format!("{}: {m}", path.display())),
            other => other,
        })
    }

    fn from_spec(spec: SweepSpec, dir: &Path, max_override: Option<u64>) -> SweepResult<Self> {
        let (base, base_dir) = match spec.base {
            BaseSpec::Inline(t) => (t, dir.to_path_buf()),
            BaseSpec::Path(p) => {
                let path = dir.join(&p);
                let text = crate::read_case_file(&path)
                    .map_err(|e| input(format!("invalid base = \"{p}\": {e}")))?;
                let table: toml::Table = toml::from_str(&text).map_err(|e| {
                    input(format!(
                        "invalid base = \"{p}\": {}: {}",
                        path.display(),
                        case_file_error::<toml::Table>(&text, &e)
                    ))
                })?;
                let parent = path.parent().unwrap_or(Path::new(".")).to_path_buf();
                (table, parent)
            }
        };
        let base_case = Case::from_toml_table(base.clone())
            .map_err(|e| input(format!("invalid base case: {e}")))?;

        let chunk_size = match spec.chunk_size {
            None => DEFAULT_CHUNK_SIZE,
            Some(c) if c >= 1 && (c as u64) <= MAX_CHUNK_SIZE => c as u64,
            Some(c) => {
                return Err(input(format!(
                    "invalid chunk_size = {c}: expected 1..={MAX_CHUNK_SIZE} cases"
                )));
            }
        };
        let max_cases = match (max_override, spec.max_cases) {
            (Some(m), _) => m,
            (None, None) => DEFAULT_MAX_CASES,
            (None, Some(m)) if m >= 1 => m as u64,
            (None, Some(m)) => {
                return Err(input(format!("invalid max_cases = {m}: expected >= 1")));
            }
        };
        if spec.parameters.is_empty() {
            return Err(input(
                "invalid parameter: none given: expected at least one [[parameter]] with key and values or start/stop/count",
            ));
        }

        let mut parameters = Vec::with_capacity(spec.parameters.len());
        for (i, p) in spec.parameters.into_iter().enumerate() {
            parameters.push(parameter(i, p)?);
        }
        for (i, p) in parameters.iter().enumerate() {
            if ["case", "status", "error"].contains(&p.name.as_str())
                || parameters[..i].iter().any(|q| q.name == p.name)
            {
                return Err(input(format!(
                    "invalid parameter[{i}].name = \"{}\": expected a column name not used by another parameter nor `case`, `status`, `error`",
                    p.name
                )));
            }
        }

        // Count before anything per case exists.
        let counts: Vec<u64> = parameters.iter().map(|p| p.values.len()).collect();
        let len = match spec.mode {
            SweepMode::Grid => counts
                .iter()
                .try_fold(1u64, |acc, &n| acc.checked_mul(n))
                .unwrap_or(u64::MAX),
            SweepMode::Points => {
                let n = counts[0];
                if let Some((i, m)) = counts.iter().enumerate().find(|(_, m)| **m != n) {
                    return Err(input(format!(
                        "invalid parameter[{i}]: {m} values, parameter[0] has {n}: mode = \"points\" needs lists and ranges of one length"
                    )));
                }
                n
            }
        };
        if len > max_cases {
            let shape = counts
                .iter()
                .map(u64::to_string)
                .collect::<Vec<_>>()
                .join(" x ");
            let shown = if len == u64::MAX {
                "more than 2^64".to_string()
            } else {
                len.to_string()
            };
            return Err(input(format!(
                "sweep has {shown} cases ({} of {shape}), above max_cases = {max_cases}: raise max_cases in the sweep file (or --max-cases) if that is meant",
                spec.mode.as_str()
            )));
        }
        let mut strides = vec![1u64; parameters.len()];
        if spec.mode == SweepMode::Grid {
            for p in (0..parameters.len().saturating_sub(1)).rev() {
                strides[p] = strides[p + 1] * counts[p + 1];
            }
        }

        let mut sweep = Sweep {
            name: spec.name,
            mode: spec.mode,
            base,
            base_dir,
            parameters,
            strides,
            len,
            chunk_size,
            fields: Fields::None,
            definition: String::new(),
            hash: String::new(),
            bearing: None,
        };
        if base_case.method() == "bearing" {
            sweep.bearing = Some(bearing::BearingPlan::new(&sweep));
        }
        sweep.check_keys(base_case.method())?;
        sweep.with_fields(spec.fields)
    }

    /// The same sweep storing `fields` (replacing the sweep file's `fields`). Storing
    /// fields is part of the definition: its hash changes, so an output directory written
    /// without fields is not resumed with them, nor the other way round.
    ///
    /// # Errors
    /// [`SweepError::Input`] for `Fields::Npy` on a method without fields (`hertz`,
    /// `traction`).
    pub fn with_fields(mut self, fields: Fields) -> SweepResult<Self> {
        if fields != Fields::None {
            let method = Case::from_toml_table(self.base.clone())
                .map(|c| c.method())
                .unwrap_or("?");
            if !matches!(method, "pimp" | "bem" | "rough") {
                return Err(input(format!(
                    "invalid fields = \"{}\": a {method} case has no field in its rows' grid (the pressure of hertz and traction cases is a closed form); expected \"none\", or a pimp, bem or rough base case",
                    fields.as_str()
                )));
            }
        }
        self.fields = fields;
        self.definition = self.normalised_definition();
        self.hash = format!("fnv1a128:{:032x}", fnv1a128(self.definition.as_bytes()));
        Ok(self)
    }

    /// Which fields the sweep stores besides its table.
    pub fn fields(&self) -> Fields {
        self.fields
    }

    /// Check every parameter against the case reader: each list value (a range: its ends)
    /// set together with the other parameters' first values must read as a case.
    fn check_keys(&self, method: &str) -> SweepResult<()> {
        let firsts: Vec<toml::Value> = self.parameters.iter().map(|p| p.values.get(0)).collect();
        // Each parameter alone at its first value first, so that an unknown key is blamed
        // on its own parameter, not on the one being probed below.
        for (k, q) in self.parameters.iter().enumerate() {
            let mut table = self.base.clone();
            for key in &q.keys {
                key.set(&mut table, firsts[k].clone()).map_err(|m| {
                    input(format!(
                        "invalid parameter[{k}].key = \"{}\": {m}",
                        key.text
                    ))
                })?;
            }
            if let Err(e) = Case::from_toml_table(table) {
                let keys = q.keys().join("\", \"");
                return Err(input(format!(
                    "invalid parameter[{k}].key = \"{keys}\" with value {}: not accepted by the {method} case reader: {e}",
                    firsts[k]
                )));
            }
        }
        for (i, p) in self.parameters.iter().enumerate() {
            let probes: Vec<u64> = match &p.values {
                Values::List(v) => (0..v.len() as u64).collect(),
                _ => vec![0, p.values.len() - 1],
            };
            for j in probes {
                let mut table = self.base.clone();
                for (k, q) in self.parameters.iter().enumerate() {
                    let v = if k == i {
                        p.values.get(j)
                    } else {
                        firsts[k].clone()
                    };
                    for key in &q.keys {
                        key.set(&mut table, v.clone()).map_err(|m| {
                            input(format!(
                                "invalid parameter[{k}].key = \"{}\": {m}",
                                key.text
                            ))
                        })?;
                    }
                }
                if let Err(e) = Case::from_toml_table(table) {
                    let keys = p.keys().join("\", \"");
                    return Err(input(format!(
                        "invalid parameter[{i}].key = \"{keys}\" with value {}: not accepted by the {method} case reader: {e}",
                        p.values.get(j)
                    )));
                }
            }
        }
        Ok(())
    }

    /// The definition the hash covers: mode, chunk size, the parameters and the base case
    /// contents, with keys sorted and floats written exactly.
    fn normalised_definition(&self) -> String {
        let mut s = String::new();
        let _ = write!(
            s,
            "kontakt-sweep 1\nmode = {}\nchunk_size = {}\n",
            self.mode.as_str(),
            self.chunk_size
        );
        // Written only when set, so that the hashes of sweeps without fields stay as they were.
        if self.fields != Fields::None {
            let _ = writeln!(s, "fields = {}", self.fields.as_str());
        }
        // A bearing sweep's rows are the fixed bearing columns: a folder written before
        // (the report flattened) is another sweep, not resumed with other columns.
        if self.bearing.is_some() {
            let _ = writeln!(s, "rows = bearing 1");
        }
        for p in &self.parameters {
            let _ = write!(s, "parameter {} keys [{}] ", p.name, p.keys().join(", "));
            match &p.values {
                Values::Linear { start, stop, count } => {
                    let _ = writeln!(s, "linear {start:?} {stop:?} {count}");
                }
                Values::Log { start, stop, count } => {
                    let _ = writeln!(s, "log {start:?} {stop:?} {count}");
                }
                Values::List(v) => {
                    s.push_str("list [");
                    for x in v {
                        canonical(x, &mut s);
                        s.push(',');
                    }
                    s.push_str("]\n");
                }
            }
        }
        s.push_str("base ");
        canonical(&toml::Value::Table(self.base.clone()), &mut s);
        s.push('\n');
        s
    }

    /// The sweep's name (`name` in the sweep file).
    pub fn name(&self) -> Option<&str> {
        self.name.as_deref()
    }

    /// Grid or points.
    pub fn mode(&self) -> SweepMode {
        self.mode
    }

    /// The swept parameters, in the sweep file's order.
    pub fn parameters(&self) -> &[Parameter] {
        &self.parameters
    }

    /// The base case as parsed.
    pub fn base(&self) -> &toml::Table {
        &self.base
    }

    /// The folder that relative paths of the cases (gap maps) are taken from.
    pub fn base_dir(&self) -> &Path {
        &self.base_dir
    }

    /// Number of cases.
    pub fn len(&self) -> u64 {
        self.len
    }

    /// Whether the sweep has no case (never: empty ranges are refused).
    pub fn is_empty(&self) -> bool {
        self.len == 0
    }

    /// Cases per chunk (the last chunk may hold fewer).
    pub fn chunk_size(&self) -> u64 {
        self.chunk_size
    }

    /// Number of chunks, `ceil(len / chunk_size)`.
    pub fn chunk_count(&self) -> u64 {
        self.len.div_ceil(self.chunk_size)
    }

    /// The case indices of chunk `i` (empty for `i >= chunk_count()`).
    pub fn chunk_range(&self, i: u64) -> Range<u64> {
        let start = i.saturating_mul(self.chunk_size).min(self.len);
        let end = start.saturating_add(self.chunk_size).min(self.len);
        start..end
    }

    /// Hash of the normalised definition (`fnv1a128:` and 32 hex digits); a directory
    /// holding chunks of another hash is refused.
    pub fn hash(&self) -> &str {
        &self.hash
    }

    /// The normalised definition that [`Sweep::hash`] covers (text, one item a line).
    pub fn definition(&self) -> &str {
        &self.definition
    }

    /// The parameter values of case `index` (`index < len()`), in parameter order.
    pub fn values(&self, index: u64) -> Vec<toml::Value> {
        self.parameters
            .iter()
            .enumerate()
            .map(|(p, param)| param.values.get(self.value_index(p, index)))
            .collect()
    }

    fn value_index(&self, p: usize, index: u64) -> u64 {
        match self.mode {
            SweepMode::Grid => (index / self.strides[p]) % self.parameters[p].values.len(),
            SweepMode::Points => index,
        }
    }

    /// The case table of case `index`: the base with every parameter set.
    ///
    /// # Errors
    /// [`SweepError::Input`] for `index >= len()`.
    pub fn case_table(&self, index: u64) -> SweepResult<toml::Table> {
        if index >= self.len {
            return Err(input(format!(
                "invalid case index = {index}: expected 0..{}",
                self.len
            )));
        }
        let mut table = self.base.clone();
        for (p, param) in self.parameters.iter().enumerate() {
            let v = param.values.get(self.value_index(p, index));
            for key in &param.keys {
                // The paths were set on this base when the sweep was read.
                key.set(&mut table, v.clone()).map_err(input)?;
            }
        }
        Ok(table)
    }

    /// The case of index `index`, read by the case reader.
    ///
    /// # Errors
    /// [`SweepError::Input`] for an index out of range or a case the reader refuses.
    pub fn case(&self, index: u64) -> SweepResult<Case> {
        Case::from_toml_table(self.case_table(index)?)
            .map_err(|e| input(format!("case {index}: {e}")))
    }
}

fn parameter(i: usize, p: ParameterSpec) -> SweepResult<Parameter> {
    let key_texts = match p.key {
        KeySpec::One(k) => vec![k],
        KeySpec::Many(ks) => ks,
    };
    if key_texts.is_empty() {
        return Err(input(format!(
            "invalid parameter[{i}].key = []: expected a key path or a non-empty list of them"
        )));
    }
    let keys = key_texts
        .iter()
        .map(|k| KeyPath::parse(k, &format!("parameter[{i}].key")))
        .collect::<SweepResult<Vec<_>>>()?;
    let name = p.name.unwrap_or_else(|| key_texts[0].clone());
    let range_given = p.start.is_some() || p.stop.is_some() || p.count.is_some();
    let values = match (p.values, range_given) {
        (Some(_), true) => {
            return Err(input(format!(
                "invalid parameter[{i}]: both values and start/stop/count: expected one of them"
            )));
        }
        (None, false) => {
            return Err(input(format!(
                "invalid parameter[{i}]: no values: expected values = [...] or start, stop and count"
            )));
        }
        (Some(v), false) => {
            if v.is_empty() {
                return Err(input(format!(
                    "invalid parameter[{i}].values = []: expected at least one value"
                )));
            }
            if p.spacing.is_some() {
                return Err(input(format!(
                    "invalid parameter[{i}].spacing: only for a range (start, stop, count)"
                )));
            }
            Values::List(v)
        }
        (None, true) => {
            let (Some(start), Some(stop), Some(count)) = (p.start, p.stop, p.count) else {
                return Err(input(format!(
                    "invalid parameter[{i}]: a range needs start, stop and count (given: {}{}{})",
                    if p.start.is_some() { "start " } else { "" },
                    if p.stop.is_some() { "stop " } else { "" },
                    if p.count.is_some() { "count" } else { "" },
                )));
            };
            if count < 1 {
                return Err(input(format!(
                    "invalid parameter[{i}].count = {count}: expected >= 1 (an empty range has no case)"
                )));
            }
            for (what, x) in [("start", start), ("stop", stop)] {
                if !x.is_finite() {
                    return Err(input(format!(
                        "invalid parameter[{i}].{what} = {x}: expected a finite number"
                    )));
                }
            }
            let count = count as u64;
            match p.spacing.unwrap_or_default() {
                Spacing::Linear => Values::Linear { start, stop, count },
                Spacing::Log => {
                    for (what, x) in [("start", start), ("stop", stop)] {
                        if !(x > 0.0) {
                            return Err(input(format!(
                                "invalid parameter[{i}].{what} = {x}: expected > 0 for spacing = \"log\""
                            )));
                        }
                    }
                    Values::Log { start, stop, count }
                }
            }
        }
    };
    let kind = match &values {
        Values::Linear { .. } | Values::Log { .. } => ValueKind::Float,
        Values::List(v) => {
            if v.iter().all(|x| x.is_integer()) {
                ValueKind::Integer
            } else if v.iter().all(|x| x.is_integer() || x.is_float()) {
                ValueKind::Float
            } else if v.iter().all(toml::Value::is_bool) {
                ValueKind::Boolean
            } else {
                ValueKind::Text
            }
        }
    };
    Ok(Parameter {
        name,
        keys,
        values,
        kind,
    })
}

/// A TOML value written with sorted keys and exact floats (`{:?}`: inf, NaN, all digits).
fn canonical(v: &toml::Value, s: &mut String) {
    match v {
        toml::Value::String(x) => {
            let _ = write!(s, "{x:?}");
        }
        toml::Value::Integer(x) => {
            let _ = write!(s, "{x}i");
        }
        toml::Value::Float(x) => {
            let _ = write!(s, "{x:?}f");
        }
        toml::Value::Boolean(x) => {
            let _ = write!(s, "{x}");
        }
        toml::Value::Datetime(x) => {
            let _ = write!(s, "{x}");
        }
        toml::Value::Array(a) => {
            s.push('[');
            for x in a {
                canonical(x, s);
                s.push(',');
            }
            s.push(']');
        }
        toml::Value::Table(t) => {
            let mut keys: Vec<&String> = t.keys().collect();
            keys.sort();
            s.push('{');
            for k in keys {
                let _ = write!(s, "{k:?}=");
                canonical(&t[k], s);
                s.push(',');
            }
            s.push('}');
        }
    }
}

/// FNV-1a, 128 bits: a stable hash (unlike std's) for recognising a sweep definition.
fn fnv1a128(bytes: &[u8]) -> u128 {
    const OFFSET: u128 = 0x6c62_272e_07bb_0142_62b8_2175_6295_c58d;
    const PRIME: u128 = 0x0000_0000_0100_0000_0000_0000_0000_013b;
    bytes
        .iter()
        .fold(OFFSET, |h, &b| (h ^ u128::from(b)).wrapping_mul(PRIME))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Found by fuzzing: a parameter key with a line break gave a message of two lines.
    #[test]
    fn line_break_in_a_key_is_escaped() {
        let text =
            "base = \"../ball_on_flat.toml\"\n[[parameter]]\nkey = \"a\\nb\"\nvalues = [1.0]\n";
        let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../examples/sweeps");
        let m = Sweep::from_toml_str(text, &dir).unwrap_err().to_string();
        assert!(!m.contains('\n') && m.contains("a\\nb"), "{m}");
    }

    const BASE: &str = r#"
[base]
[base.contact]
kind = "point"
[base.body1]
radii_mm = [6.35, 6.35]
e_mpa = 210000.0
nu = 0.3
[base.body2]
radii_mm = [inf, inf]
e_mpa = 210000.0
nu = 0.3
[base.load]
force_n = 100.0
"#;

    fn sweep(params: &str) -> SweepResult<Sweep> {
        Sweep::from_toml_str(&format!("{params}\n{BASE}"), Path::new("."))
    }

    fn err(params: &str) -> String {
        match sweep(params) {
            Err(e) => e.to_string(),
            Ok(s) => panic!("accepted, {} cases", s.len()),
        }
    }

    #[test]
    fn grid_order_last_parameter_fastest() {
        let s = sweep(
            "[[parameter]]\nkey = \"load.force_n\"\nvalues = [1.0, 2.0]\n\
             [[parameter]]\nkey = \"body1.e_mpa\"\nstart = 1.0\nstop = 3.0\ncount = 3\n",
        )
        .unwrap();
        assert_eq!(s.len(), 6);
        let v: Vec<(f64, f64)> = (0..6)
            .map(|i| {
                let v = s.values(i);
                (v[0].as_float().unwrap(), v[1].as_float().unwrap())
            })
            .collect();
        assert_eq!(
            v,
            [(1., 1.), (1., 2.), (1., 3.), (2., 1.), (2., 2.), (2., 3.)]
        );
        let case = s.case_table(4).unwrap();
        assert_eq!(case["body1"]["e_mpa"].as_float(), Some(2.0));
        assert_eq!(case["load"]["force_n"].as_float(), Some(2.0));
    }

    /// Issue 30, item 16: a linear range's points are whole steps (`j * (b - a) / m`, not
    /// `(b - a) * (j / m)`, which gave 1799.9999999999998 for 1800).
    #[test]
    fn linear_range_points_are_exact_steps() {
        let s = sweep(
            "[[parameter]]\nkey = \"load.force_n\"\nstart = 100.0\nstop = 3000.0\ncount = 30\n",
        )
        .unwrap();
        let v: Vec<f64> = (0..30)
            .map(|i| s.values(i)[0].as_float().unwrap())
            .collect();
        let want: Vec<f64> = (1..=30).map(|i| 100.0 * f64::from(i)).collect();
        assert_eq!(v, want);
    }

    #[test]
    fn log_range_ends_exact_and_ratio_constant() {
        let s = sweep(
            "[[parameter]]\nkey = \"load.force_n\"\nstart = 10.0\nstop = 1000.0\ncount = 5\nspacing = \"log\"\n",
        )
        .unwrap();
        let f: Vec<f64> = (0..5).map(|i| s.values(i)[0].as_float().unwrap()).collect();
        assert_eq!(f[0], 10.0);
        assert_eq!(f[4], 1000.0);
        for w in f.windows(2) {
            assert!((w[1] / w[0] - 10f64.sqrt()).abs() < 1e-12, "{f:?}");
        }
    }

    #[test]
    fn indexed_keys_and_several_keys_per_parameter() {
        let s = sweep(
            "[[parameter]]\nkey = [\"body1.radii_mm[0]\", \"body1.radii_mm[1]\"]\nname = \"r\"\nvalues = [3.0, 4.0]\n",
        )
        .unwrap();
        let t = s.case_table(1).unwrap();
        assert_eq!(
            t["body1"]["radii_mm"].as_array().unwrap(),
            &vec![toml::Value::Float(4.0), toml::Value::Float(4.0)]
        );
        assert_eq!(s.parameters()[0].name, "r");
    }

    #[test]
    fn points_mode_zips() {
        let s = sweep(
            "mode = \"points\"\n[[parameter]]\nkey = \"load.force_n\"\nvalues = [1.0, 2.0, 3.0]\n\
             [[parameter]]\nkey = \"body1.nu\"\nvalues = [0.1, 0.2, 0.3]\n",
        )
        .unwrap();
        assert_eq!(s.len(), 3);
        assert_eq!(
            s.values(2),
            [toml::Value::Float(3.0), toml::Value::Float(0.3)]
        );
        let e = err(
            "mode = \"points\"\n[[parameter]]\nkey = \"load.force_n\"\nvalues = [1.0, 2.0]\n\
             [[parameter]]\nkey = \"body1.nu\"\nvalues = [0.1]\n",
        );
        assert!(
            e.contains("parameter[1]") && e.contains("one length"),
            "{e}"
        );
    }

    #[test]
    fn optional_keys_absent_from_the_base_are_accepted() {
        // `contact.angle_deg` defaults to 0 and is not in the base; `yield.stress_mpa`
        // creates the optional [yield] table.
        let s = sweep(
            "[[parameter]]\nkey = \"contact.angle_deg\"\nvalues = [0.0, 30.0]\n\
             [[parameter]]\nkey = \"yield.stress_mpa\"\nvalues = [1500.0]\n",
        )
        .unwrap();
        assert_eq!(s.len(), 2);
    }

    #[test]
    fn bad_input_is_named() {
        let e = err("[[parameter]]\nkey = \"load.forse_n\"\nvalues = [1.0]\n");
        assert!(e.contains("parameter[0].key = \"load.forse_n\""), "{e}");
        assert!(e.contains("forse_n"), "{e}");
        let e = err("[[parameter]]\nkey = \"body1.radii_mm[2]\"\nvalues = [1.0]\n");
        assert!(e.contains("no index 2"), "{e}");
        let e = err("[[parameter]]\nkey = \"load.force_n\"\nstart = 1.0\nstop = 2.0\ncount = 0\n");
        assert!(e.contains("parameter[0].count = 0"), "{e}");
        let e = err("[[parameter]]\nkey = \"load.force_n\"\nvalues = []\n");
        assert!(e.contains("parameter[0].values = []"), "{e}");
        let e = err("[[parameter]]\nkey = \"load.force_n\"\nvalues = [\"heavy\"]\n");
        assert!(e.contains("load.force_n") && e.contains("heavy"), "{e}");
        let e = err(
            "[[parameter]]\nkey = \"load.force_n\"\nstart = 0.0\nstop = 2.0\ncount = 3\nspacing = \"log\"\n",
        );
        assert!(e.contains("parameter[0].start = 0"), "{e}");
        let e = err("[[parameter]]\nkey = \"load..force_n\"\nvalues = [1.0]\n");
        assert!(e.contains("dotted key path"), "{e}");
        let e = err("chunk_size = 0\n[[parameter]]\nkey = \"load.force_n\"\nvalues = [1.0]\n");
        assert!(e.contains("chunk_size = 0"), "{e}");
    }

    #[test]
    fn case_count_is_checked_before_anything_is_built() {
        // 10^5 x 10^5 x 10^5 = 10^15 cases: refused at once, nothing allocated per case.
        let p = "[[parameter]]\nkey = \"load.force_n\"\nstart = 1.0\nstop = 2.0\ncount = 100000\n";
        let e = err(&format!(
            "{p}{}{}",
            p.replace("load.force_n", "body1.e_mpa"),
            p.replace("load.force_n", "body2.e_mpa")
        ));
        assert!(
            e.contains("1000000000000000 cases") && e.contains("max_cases = 10000000"),
            "{e}"
        );
        // A raised limit lets 2 x 10^7 pass.
        let s = sweep(&format!(
            "max_cases = 20000000\n{}{}",
            p.replace("100000", "20000000"),
            ""
        ))
        .unwrap();
        assert_eq!(s.len(), 20_000_000);
        assert_eq!(s.chunk_count(), 20_000_000u64.div_ceil(DEFAULT_CHUNK_SIZE));
        assert_eq!(s.chunk_range(s.chunk_count() - 1).end, 20_000_000);
    }

    #[test]
    fn hash_ignores_key_order_and_sees_every_value() {
        let a = sweep("[[parameter]]\nkey = \"load.force_n\"\nvalues = [1.0, 2.0]\n").unwrap();
        let reordered = format!(
            "[[parameter]]\nkey = \"load.force_n\"\nvalues = [1.0, 2.0]\n{}",
            BASE.replace("e_mpa = 210000.0\nnu = 0.3", "nu = 0.3\ne_mpa = 210000.0")
        );
        let b = Sweep::from_toml_str(&reordered, Path::new(".")).unwrap();
        assert_eq!(a.hash(), b.hash());
        let c = sweep("[[parameter]]\nkey = \"load.force_n\"\nvalues = [1.0, 2.000001]\n").unwrap();
        assert_ne!(a.hash(), c.hash());
        let d = Sweep::from_toml_str(
            &format!(
                "[[parameter]]\nkey = \"load.force_n\"\nvalues = [1.0, 2.0]\n{}",
                BASE.replace("[inf, inf]", "[inf, 1e9]")
            ),
            Path::new("."),
        )
        .unwrap();
        assert_ne!(a.hash(), d.hash());
    }
}
