//! The one reader of the files a case names: case and sweep files (TOML), a sweep's
//! `base` file, gap and height maps (CSV, `.npy`), topographies (`.xyz`, `.sdf`).
//!
//! Every such file is read through [`Capped`], which counts the bytes while reading
//! ([`std::io::Read::take`] semantics) and fails as soon as a file holds more than its
//! limit, whatever the file system says about its size (a device such as `/dev/zero`, a
//! pipe, a file that grows while read). Text formats are also refused at their first NUL
//! byte (a binary file or a device of zeros is not text), so `/dev/zero` as a map fails
//! after one buffer, not after the limit.
//!
//! Two limits:
//! - [`MAX_CASE_FILE_BYTES`] = 16 MiB for TOML (a case is a short file; its maps and tables
//!   are files of their own);
//! - [`MAX_DATA_FILE_BYTES`] = 1 GiB for maps and topographies. Sized for real maps: a
//!   4096 × 4096 CSV map of 20-character numbers is 4096² × 21 B ≈ 0.35 GB, the same map as
//!   `.xyz` lines (`x y z`, about 60 characters a line) ≈ 1.0 GB, as float64 `.npy`
//!   0.13 GB. Measured maps are rarely larger than 4096²; the half-space solver's memory
//!   budget (docs/halfspace.md) bounds the grids that can be solved anyway. CSV, `.xyz` and
//!   `.sdf` are parsed while streaming (the text is never held whole); `.npy` is read whole
//!   (its header gives the shape, checked against the bytes before the values are read).

use std::fmt::Write as _;
use std::io::{BufReader, Read};
use std::path::Path;

/// Largest case, sweep or `base` file read \[bytes\]: 16 MiB.
pub const MAX_CASE_FILE_BYTES: u64 = 16 * 1024 * 1024;

/// Largest gap map, height map or topography file read \[bytes\]: 1 GiB (see the module
/// documentation for the sizing).
pub const MAX_DATA_FILE_BYTES: u64 = 1 << 30;

/// A reader that yields at most `limit` bytes of `inner` and fails with
/// [`std::io::ErrorKind::InvalidData`] when `inner` holds more (at most `limit + 1` bytes
/// are read), or, for text, at the first NUL byte.
#[derive(Debug)]
pub struct Capped<R> {
    inner: R,
    limit: u64,
    read: u64,
    text: bool,
}

impl<R: Read> Capped<R> {
    /// Cap `inner` at `limit` bytes; `text` refuses NUL bytes.
    pub fn new(inner: R, limit: u64, text: bool) -> Self {
        Capped {
            inner,
            limit,
            read: 0,
            text,
        }
    }
}

impl<R: Read> Read for Capped<R> {
    fn read(&mut self, buf: &mut [u8]) -> std::io::Result<usize> {
        if buf.is_empty() {
            return Ok(0);
        }
        let left = self.limit - self.read;
        // One byte beyond the limit tells a file of exactly `limit` bytes from a larger one.
        let want = buf
            .len()
            .min(usize::try_from(left).unwrap_or(usize::MAX).max(1));
        let n = self.inner.read(&mut buf[..want])?;
        if left == 0 && n > 0 {
            return Err(std::io::Error::new(
                std::io::ErrorKind::InvalidData,
                TooLarge(self.limit),
            ));
        }
        if let Some(k) = buf[..n].iter().position(|&b| b == 0).filter(|_| self.text) {
            return Err(std::io::Error::new(
                std::io::ErrorKind::InvalidData,
                format!(
                    "not text: a NUL byte at offset {} (a binary file or a device?)",
                    self.read + k as u64
                ),
            ));
        }
        self.read += n as u64;
        Ok(n)
    }
}

/// The error inside the [`std::io::Error`] of a [`Capped`] reader whose file holds more
/// than its limit \[bytes\]; displayed as `larger than 16 MiB`.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct TooLarge(pub u64);

impl std::fmt::Display for TooLarge {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "larger than {}", size_label(self.0))
    }
}

impl std::error::Error for TooLarge {}

/// Whether `e` is a [`Capped`] reader's [`TooLarge`].
pub fn is_too_large(e: &std::io::Error) -> bool {
    e.get_ref().is_some_and(|inner| inner.is::<TooLarge>())
}

/// `16 MiB`, `1 GiB`, or the byte count.
fn size_label(bytes: u64) -> String {
    let mut s = String::new();
    match bytes {
        b if b >= 1 << 30 && b % (1 << 30) == 0 => write!(s, "{} GiB", b >> 30),
        b if b >= 1 << 20 && b % (1 << 20) == 0 => write!(s, "{} MiB", b >> 20),
        b => write!(s, "{b} bytes"),
    }
    .unwrap_or_default();
    s
}

/// Open `path` for buffered reading through [`Capped`].
///
/// # Errors
/// The message of the file system's error (no such file, permission), or `larger than
/// <limit>` for a regular file whose size exceeds the limit.
pub fn open(
    path: &Path,
    limit: u64,
    text: bool,
) -> Result<BufReader<Capped<std::fs::File>>, String> {
    let file = std::fs::File::open(path).map_err(|e| e.to_string())?;
    // A regular file's size is known: one over the limit is refused before any read (the
    // count while reading still holds for devices, pipes and growing files).
    if let Ok(meta) = file.metadata()
        && meta.is_file()
        && meta.len() > limit
    {
        return Err(format!("{} ({} bytes)", TooLarge(limit), meta.len()));
    }
    Ok(BufReader::new(Capped::new(file, limit, text)))
}

/// All bytes of `reader`, at most `limit` of them.
///
/// # Errors
/// A read error, `larger than <limit>`, or (for `text`) the offset of a NUL byte.
pub fn read_all(reader: impl Read, limit: u64, text: bool) -> Result<Vec<u8>, String> {
    let mut bytes = Vec::new();
    Capped::new(reader, limit, text)
        .read_to_end(&mut bytes)
        .map_err(|e| e.to_string())?;
    Ok(bytes)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn cap_counts_while_reading() {
        let data = [b'1'; 100];
        assert_eq!(read_all(&data[..], 100, true).map(|b| b.len()), Ok(100));
        let e = read_all(&data[..], 99, true).unwrap_err();
        assert_eq!(e, "larger than 99 bytes");
        let mut sink = Vec::new();
        let e = Capped::new(&data[..], 10, false)
            .read_to_end(&mut sink)
            .unwrap_err();
        assert!(is_too_large(&e) && sink.len() == 10, "{e}");
        let e = read_all(&data[..], 16 << 20, true).map(|b| b.len());
        assert_eq!(e, Ok(100));
        let e = read_all(std::io::repeat(b'1'), 1 << 20, false).unwrap_err();
        assert_eq!(e, "larger than 1 MiB");
        let e = read_all(&b"1,2\n3\x004"[..], 100, true).unwrap_err();
        assert!(e.contains("NUL byte at offset 5"), "{e}");
        assert!(read_all(&b"1\x00"[..], 100, false).is_ok());
    }

    /// `/dev/zero` as a text file fails at its first byte (it grew to 4 GB before).
    #[cfg(unix)]
    #[test]
    fn dev_zero_fails_at_once() {
        let mut r = open(Path::new("/dev/zero"), MAX_DATA_FILE_BYTES, true).unwrap();
        let mut s = String::new();
        let e = r.read_to_string(&mut s).unwrap_err().to_string();
        assert!(e.contains("NUL byte at offset 0"), "{e}");
        let e = read_all(std::fs::File::open("/dev/zero").unwrap(), 1 << 20, false).unwrap_err();
        assert_eq!(e, "larger than 1 MiB");
    }
}
