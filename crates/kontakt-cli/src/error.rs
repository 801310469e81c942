//! The CLI's own errors: bad input it detects itself (exit status 2) and output files it
//! cannot write (exit status 1). Below `commands` and `render`, which both report them.

/// Bad input detected by the CLI itself (unreadable file).
#[derive(Debug, thiserror::Error)]
#[error("{0}")]
pub struct InputError(pub String);

/// An output file or folder that cannot be written: a runtime failure (exit status 1),
/// whichever flag named it (`--csv`, `--map`, `--plot`, `--out`).
pub fn cannot_write(
    what: &str,
    path: &std::path::Path,
    e: impl std::fmt::Display,
) -> anyhow::Error {
    anyhow::anyhow!("cannot {what} {}: {e}", path.display())
}
