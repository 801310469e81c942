//! Gap and height maps from files: CSV (one grid row per line) or NumPy `.npy`
//! (float64 or float32, 2-D, C order). The map itself, [`GapMap`], lives in the core
//! library; this is the file format layer. Files are read through [`crate::files`], at most
//! [`crate::files::MAX_DATA_FILE_BYTES`] (1 GiB); CSV is parsed while streaming.

use kontakt::gap::{GapMap, MapKind};
use kontakt::{Error, Result};
use std::path::Path;

/// Read a map from a CSV file (one grid row per line, `y` down the file, `x` across,
/// comma-separated numbers; leading lines that do not start with a number are a header,
/// skipped and counted) or a `.npy` file (a 2-D float64 or float32 array of shape
/// `(ny, nx)`, C order), with cell spacing `spacing` \[mm\]; the file's values are
/// multiplied by `to_mm` (1 for mm, 1e-3 for µm).
///
/// # Errors
/// [`Error::InvalidInput`] naming the file for an unreadable or malformed file, a file
/// larger than [`crate::files::MAX_DATA_FILE_BYTES`], a CSV file with a NUL byte (binary), a
/// `.npy` file without its magic bytes, a ragged CSV row (named), or the errors of
/// [`GapMap::new`].
pub fn read_gap_map(path: &Path, spacing: [f64; 2], kind: MapKind, to_mm: f64) -> Result<MapFile> {
    let file_err = |why: String| {
        // The readers' messages may span lines (the .npy header parser draws a caret
        // under the bad character): one line, as every error.
        let why = why.split_whitespace().collect::<Vec<_>>().join(" ");
        Error::invalid(
            "gap_map.file",
            path.display(),
            format!("a readable CSV or .npy gap map of at most 1 GiB ({why})"),
        )
    };
    let is_npy = path
        .extension()
        .is_some_and(|e| e.eq_ignore_ascii_case("npy"));
    let reader =
        crate::files::open(path, crate::files::MAX_DATA_FILE_BYTES, !is_npy).map_err(file_err)?;
    let ((nx, ny, mut values), skipped_lines) = if is_npy {
        let array = read_npy(&read_npy_bytes(reader).map_err(file_err)?).map_err(file_err)?;
        (array, 0)
    } else {
        read_csv(reader).map_err(file_err)?
    };
    if to_mm != 1.0 {
        values.iter_mut().for_each(|v| *v *= to_mm);
    }
    let map = GapMap::new(nx, ny, spacing, values, kind)?;
    Ok(MapFile { map, skipped_lines })
}

/// A map read by [`read_gap_map`].
#[derive(Debug, Clone, PartialEq)]
pub struct MapFile {
    /// The map \[mm\].
    pub map: GapMap,
    /// Leading lines of a CSV file skipped as a header (not starting with a number).
    pub skipped_lines: usize,
}

/// The bytes of a `.npy` file, after its magic bytes are checked (a file of zeros or text
/// fails after six bytes, not after the size limit); `reader` is capped by its caller.
fn read_npy_bytes(mut reader: impl std::io::Read) -> std::result::Result<Vec<u8>, String> {
    let mut bytes = vec![0u8; 6];
    let magic = reader.read_exact(&mut bytes).is_ok() && bytes == b"\x93NUMPY";
    if !magic {
        return Err("no .npy magic bytes \\x93NUMPY at the start of the file".into());
    }
    reader.read_to_end(&mut bytes).map_err(|e| e.to_string())?;
    Ok(bytes)
}

/// The report's note for `n` skipped header lines of the file named by `key`, if any.
pub fn skipped_note(key: &str, n: usize) -> Option<String> {
    (n > 0).then(|| {
        format!(
            "{key}: skipped {n} header line{} before the first line of numbers",
            if n == 1 { "" } else { "s" }
        )
    })
}

type Csv = ((usize, usize, Vec<f64>), usize);

fn read_csv(bytes: impl std::io::Read) -> std::result::Result<Csv, String> {
    let mut reader = csv::ReaderBuilder::new()
        .has_headers(false)
        .trim(csv::Trim::All)
        .comment(Some(b'#'))
        .flexible(true)
        .from_reader(bytes);
    let mut values = Vec::new();
    let mut nx = 0;
    let mut ny = 0;
    let mut skipped = 0;
    for (row, record) in reader.records().enumerate() {
        let record = record.map_err(|e| match e.kind() {
            csv::ErrorKind::Io(io) => io.to_string(),
            _ => e.to_string(),
        })?;
        if record.iter().all(str::is_empty) {
            continue;
        }
        if ny == 0
            && crate::topography::is_header_line(&record.iter().collect::<Vec<_>>().join(","))
        {
            skipped += 1;
            continue;
        }
        if ny == 0 {
            nx = record.len();
        } else if record.len() != nx {
            return Err(decimal_commas(&record, row).unwrap_or_else(|| {
                format!(
                    "row {} has {} values, the first row {nx}",
                    row + 1,
                    record.len()
                )
            }));
        }
        for (col, field) in record.iter().enumerate() {
            let v: f64 = field.parse().map_err(|_| {
                decimal_commas(&record, row).unwrap_or_else(|| {
                    format!(
                        "row {}, column {}: `{field}` is not a number",
                        row + 1,
                        col + 1
                    )
                })
            })?;
            values.push(v);
        }
        ny += 1;
    }
    Ok(((nx, ny, values), skipped))
}

/// The message for a row written with decimal commas and `;`, tab or space between the
/// numbers (a spreadsheet's export in many locales), which the comma-separated reader would
/// otherwise split inside the numbers; `None` when the row is not of that kind.
fn decimal_commas(record: &csv::StringRecord, row: usize) -> Option<String> {
    let line = record.iter().collect::<Vec<_>>().join(",");
    let separator = [';', '\t', ' '].into_iter().find(|&c| line.contains(c))?;
    let numbers: Vec<&str> = line
        .split(separator)
        .map(str::trim)
        .filter(|f| !f.is_empty())
        .collect();
    let all_numbers = numbers
        .iter()
        .all(|f| f.replace(',', ".").parse::<f64>().is_ok());
    (line.contains(',') && all_numbers).then(|| {
        format!(
            "row {} reads as numbers with decimal commas separated by {} (`{}`): write the map \
             with decimal points and commas between the numbers, or save it as .npy",
            row + 1,
            match separator {
                ';' => "`;`",
                '\t' => "tabs",
                _ => "spaces",
            },
            numbers.first().copied().unwrap_or_default()
        )
    })
}

fn read_npy(bytes: &[u8]) -> std::result::Result<(usize, usize, Vec<f64>), String> {
    check_npy_shape(bytes)?;
    let npy = npyz::NpyFile::new(bytes).map_err(|e| e.to_string())?;
    let shape = npy.shape().to_vec();
    if shape.len() != 2 {
        return Err(format!(
            "a 2-D array is needed, the file holds shape {shape:?}"
        ));
    }
    if npy.order() != npyz::Order::C {
        return Err("the array must be in C order (numpy's default)".into());
    }
    let (ny, nx) = (shape[0] as usize, shape[1] as usize);
    let dtype = npy.dtype();
    let values = match npy.into_vec::<f64>() {
        Ok(v) => v,
        Err(_) => npyz::NpyFile::new(bytes)
            .and_then(|f| f.into_vec::<f32>())
            .map_err(|_| {
                // The dtype as numpy writes it (`<i8`), not the reader's Rust debug dump
                // (`Plain(TypeStr { .. })`, found by probing).
                let found = match &dtype {
                    npyz::DType::Plain(t) => t.to_string(),
                    other => {
                        let d: String = other.descr().chars().take(60).collect();
                        format!("the structured dtype {d}")
                    }
                };
                format!(
                    "float64 or float32 values are needed (dtype <f8, >f8, <f4 or >f4), the \
                     file holds {found}"
                )
            })?
            .into_iter()
            .map(f64::from)
            .collect(),
    };
    Ok((nx, ny, values))
}

/// Check the shape in a `.npy` header against the data the file holds, before the reader
/// sees it: a shape whose product overflows 64 bits (the reader would overflow) or that
/// needs more values than the file has bytes (a truncated file, or a header claiming a huge
/// array) is refused here. Headers this cannot read are left to the reader's own errors.
fn check_npy_shape(bytes: &[u8]) -> std::result::Result<(), String> {
    if bytes.len() < 10 || !bytes.starts_with(b"\x93NUMPY") {
        return Ok(());
    }
    let (len, start) = if bytes[6] == 1 {
        (u16::from_le_bytes([bytes[8], bytes[9]]) as usize, 10usize)
    } else if bytes.len() >= 12 {
        let l = u32::from_le_bytes([bytes[8], bytes[9], bytes[10], bytes[11]]);
        (l as usize, 12)
    } else {
        return Ok(());
    };
    let Some(header) = bytes.get(start..start.saturating_add(len)) else {
        return Ok(());
    };
    let header = String::from_utf8_lossy(header);
    let Some(after) = header
        .find("'shape'")
        .or_else(|| header.find("\"shape\""))
        .map(|i| &header[i + 7..])
    else {
        return Ok(());
    };
    let Some(dims) = after
        .split_once('(')
        .and_then(|(_, rest)| rest.split_once(')'))
        .map(|(dims, _)| dims)
    else {
        return Ok(());
    };
    // The product of the non-zero dimensions bounds every partial product the reader
    // forms (its strides), also when a zero makes the array empty.
    let mut nonzero: u64 = 1;
    let mut empty = false;
    let mut shown = Vec::new();
    for d in dims.split(',').map(str::trim).filter(|d| !d.is_empty()) {
        let Ok(n) = d.parse::<u64>() else {
            return Ok(());
        };
        shown.push(d.to_string());
        empty |= n == 0;
        nonzero = nonzero
            .checked_mul(n.max(1))
            .ok_or_else(|| format!("the header's shape ({dims}) has more than 2^64 values"))?;
    }
    let count = if empty { 0 } else { nonzero };
    let data = bytes.len() - start - len;
    if count > data as u64 {
        return Err(format!(
            "the file is truncated or its header is wrong: shape ({}) needs {count} values, the file holds {data} bytes of data",
            shown.join(", ")
        ));
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn csv_rows_and_errors() {
        let ((nx, ny, v), skipped) = read_csv(&b"1, 2, 3\n4,5,6\n"[..]).unwrap();
        assert_eq!((nx, ny, skipped), (3, 2, 0));
        assert_eq!(v, vec![1.0, 2.0, 3.0, 4.0, 5.0, 6.0]);
        // A profilometer's header lines before the numbers are skipped and counted; the
        // same line after the first row of numbers is an error.
        let ((nx, ny, v), skipped) = read_csv(&b"Height map\nx0, x1\n1, 2\n3, 4\n"[..]).unwrap();
        assert_eq!((nx, ny, skipped, v), (2, 2, 2, vec![1.0, 2.0, 3.0, 4.0]));
        let e = read_csv(&b"1, 2\nx0, x1\n"[..]).unwrap_err();
        assert!(e.contains("`x0` is not a number"), "{e}");
        let e = read_csv(&b"1,2,3\n4,5\n"[..]).unwrap_err();
        assert!(e.contains("row 2 has 2 values"), "{e}");
        let e = read_csv(&b"1,x\n"[..]).unwrap_err();
        assert!(e.contains("`x` is not a number"), "{e}");
        // Decimal commas (a spreadsheet's export) are named as such, whatever the separator.
        for text in [
            &b"0,25;0,5;1\n0,75;1;1,25\n"[..],
            b"0,25\t0,5\n1\t2\n",
            b"0,5 1,5\n",
        ] {
            let e = read_csv(text).unwrap_err();
            assert!(e.contains("decimal commas") && e.contains("row 1"), "{e}");
        }
        // Other separators without decimal commas keep the plain message.
        let e = read_csv(&b"1;x\n"[..]).unwrap_err();
        assert!(e.contains("`1;x` is not a number"), "{e}");
    }

    /// A `.npy` file as numpy writes it (format 1.0).
    fn npy_bytes(descr: &str, shape: &str, data: &[u8]) -> Vec<u8> {
        npy_bytes_literal(&format!("'{descr}'"), shape, data)
    }

    /// [`npy_bytes`] with the dtype as a Python literal (a structured dtype is a list).
    fn npy_bytes_literal(descr: &str, shape: &str, data: &[u8]) -> Vec<u8> {
        let dict = format!("{{'descr': {descr}, 'fortran_order': False, 'shape': {shape}, }}");
        let mut header = dict.into_bytes();
        while (10 + header.len() + 1) % 64 != 0 {
            header.push(b' ');
        }
        header.push(b'\n');
        let mut out = b"\x93NUMPY\x01\x00".to_vec();
        out.extend_from_slice(&(header.len() as u16).to_le_bytes());
        out.extend_from_slice(&header);
        out.extend_from_slice(data);
        out
    }

    #[test]
    fn npy_float64_and_float32_and_errors() {
        let v64: Vec<u8> = [1.0f64, 2.0, 3.0, 4.0, 5.0, 6.0]
            .iter()
            .flat_map(|v| v.to_le_bytes())
            .collect();
        let (nx, ny, v) = read_npy(&npy_bytes("<f8", "(2, 3)", &v64)).unwrap();
        assert_eq!((nx, ny), (3, 2));
        assert_eq!(v, vec![1.0, 2.0, 3.0, 4.0, 5.0, 6.0]);
        let v32: Vec<u8> = [0.5f32, 1.5, 2.5, 3.5]
            .iter()
            .flat_map(|v| v.to_le_bytes())
            .collect();
        let (nx, ny, v) = read_npy(&npy_bytes("<f4", "(2, 2)", &v32)).unwrap();
        assert_eq!((nx, ny), (2, 2));
        assert_eq!(v, vec![0.5, 1.5, 2.5, 3.5]);
        let e = read_npy(&npy_bytes("<f8", "(6,)", &v64)).unwrap_err();
        assert!(e.contains("2-D"), "{e}");
        let ints: Vec<u8> = [1i64, 2].iter().flat_map(|v| v.to_le_bytes()).collect();
        let e = read_npy(&npy_bytes("<i8", "(1, 2)", &ints)).unwrap_err();
        assert_eq!(
            e,
            "float64 or float32 values are needed (dtype <f8, >f8, <f4 or >f4), the file \
             holds <i8"
        );
        // A structured array: its dtype in numpy's words, on one line.
        let e = read_npy(&npy_bytes_literal(
            "[('x', '<i8'), ('y', '<i8')]",
            "(1, 1)",
            &ints,
        ))
        .unwrap_err();
        assert!(
            e.ends_with("the file holds the structured dtype [('x', '<i8'), ('y', '<i8'), ]"),
            "{e}"
        );
    }

    /// Found by the fuzz harness (tests/fuzz.rs): a header whose shape overflows 64 bits
    /// made the `.npy` reader panic (multiply with overflow); a header claiming a huge
    /// shape over a few bytes of data is a truncated file, refused before any allocation.
    #[test]
    fn npy_header_shape_overflow_and_truncation() {
        let e = read_npy(&npy_bytes("<f8", "(4294967296, 4294967296)", &[])).unwrap_err();
        assert!(e.contains("more than 2^64 values"), "{e}");
        let e = read_npy(&npy_bytes("<f8", "(18446744073709551615, 2)", &[0; 16])).unwrap_err();
        assert!(e.contains("more than 2^64 values"), "{e}");
        let e = read_npy(&npy_bytes("<f8", "(0, 2, 18446744073709551615)", &[])).unwrap_err();
        assert!(e.contains("more than 2^64 values"), "{e}");
        let e = read_npy(&npy_bytes("<f8", "(100000, 100000)", &[0; 64])).unwrap_err();
        assert!(
            e.contains("truncated") && e.contains("(100000, 100000)"),
            "{e}"
        );
        let v64: Vec<u8> = [1.0f64, 2.0].iter().flat_map(|v| v.to_le_bytes()).collect();
        assert!(read_npy(&npy_bytes("<f8", "(1, 2)", &v64)).is_ok());
    }

    /// Found by the fuzz harness: a `.npy` header that is not a Python literal gave an
    /// error of several lines (the parser's caret drawing); it is one line.
    #[test]
    fn npy_bad_header_is_one_line() {
        let path = std::env::temp_dir().join(format!(
            "kontakt-case-badheader-{}-{:?}.npy",
            std::process::id(),
            std::thread::current().id()
        ));
        std::fs::write(&path, npy_bytes("[('a', '<f8')]", "()", &[0; 8])).unwrap();
        let e = read_gap_map(&path, [0.01, 0.01], MapKind::Gap, 1.0).unwrap_err();
        std::fs::remove_file(&path).unwrap();
        let m = e.to_string();
        assert_eq!(e.field(), Some("gap_map.file"));
        assert!(!m.contains('\n') && m.contains("syntax error"), "{m}");
    }

    /// Found by fuzzing: a cell size of 1e308 mm over a 2 x 2 map overflowed the map's
    /// extent and the error named the grid's `y_range`; it names the spacing.
    #[test]
    fn huge_spacing_names_the_spacing() {
        let path = std::env::temp_dir().join(format!(
            "kontakt-case-spacing-{}-{:?}.csv",
            std::process::id(),
            std::thread::current().id()
        ));
        std::fs::write(&path, "0.1, 0.0\n0.0, 0.1\n").unwrap();
        let e = read_gap_map(&path, [0.01, 1e308], MapKind::Gap, 1.0).unwrap_err();
        std::fs::remove_file(&path).unwrap();
        assert_eq!(e.field(), Some("spacing[1]"), "{e}");
    }

    /// Issue 30 item 6: `/dev/zero` as a gap map grew to 4 GB before failing; through the
    /// capped reader it fails at its first byte as CSV and at its magic bytes as `.npy`.
    #[cfg(unix)]
    #[test]
    fn dev_zero_as_a_map_fails_at_once() {
        let e = read_gap_map(Path::new("/dev/zero"), [0.01, 0.01], MapKind::Gap, 1.0)
            .unwrap_err()
            .to_string();
        assert!(
            e.contains("gap_map.file") && e.contains("NUL byte at offset 0"),
            "{e}"
        );
        let link = std::env::temp_dir().join(format!("kontakt-zero-{}.npy", std::process::id()));
        std::os::unix::fs::symlink("/dev/zero", &link).unwrap();
        let e = read_gap_map(&link, [0.01, 0.01], MapKind::Gap, 1.0)
            .unwrap_err()
            .to_string();
        std::fs::remove_file(&link).unwrap();
        assert!(e.contains("no .npy magic bytes"), "{e}");
    }

    #[test]
    fn files_that_cannot_be_read_name_the_file_and_the_row() {
        let path = std::env::temp_dir().join(format!(
            "kontakt-case-ragged-{}-{:?}.csv",
            std::process::id(),
            std::thread::current().id()
        ));
        std::fs::write(&path, "0.1, 0.0, 0.1\n0.0, 0.0\n0.1, 0.0, 0.1\n").unwrap();
        let e = read_gap_map(&path, [0.01, 0.01], MapKind::Gap, 1.0).unwrap_err();
        std::fs::remove_file(&path).unwrap();
        assert_eq!(e.field(), Some("gap_map.file"));
        assert!(e.to_string().contains("row 2 has 2 values"), "{e}");
        // A file that does not exist.
        let e = read_gap_map(&path, [0.01, 0.01], MapKind::Gap, 1.0).unwrap_err();
        assert_eq!(e.field(), Some("gap_map.file"));
    }
}
