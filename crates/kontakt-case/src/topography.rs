//! Measured topographies whose files carry their own grid: plain `x y z` point lists
//! (`.xyz`) and the ASCII Surface Data File of ISO 25178-71 (`.sdf`, the format of Blunt
//! and Jiang's SDF, exported by most profilometer and interferometer software). CSV
//! matrices and `.npy` arrays carry no spacing; they are read by [`crate::maps`].
//!
//! - `.xyz`: one point per line, `x y z` separated by spaces, tabs, commas or `;`, in mm
//!   (or the case's `unit`); `#` starts a comment; leading lines that do not start with a
//!   number are a header and skipped (counted). The points must form a complete uniform grid (any order): the
//!   distinct `x` and `y` values are the grid's columns and rows, equally spaced to 1e-6
//!   of a cell, every node given exactly once.
//! - `.sdf`: the ASCII variant (first line `aBCR-1.0`): `key = value` header lines
//!   (`NumPoints`, `NumProfiles`, `Xscale`, `Yscale`, `Zscale` in metres, ...), a line
//!   `*`, then `NumPoints × NumProfiles` values profile by profile (x fastest), each
//!   multiplied by `Zscale`, then `*`. Lengths are converted from metres to mm. The binary
//!   variant (`bBCR`) is refused with a message.
//!
//! Both give heights (the surface, `z` up) as a [`GapMap`] of [`MapKind::Height`].

use kontakt::gap::{GapMap, MapKind};
use kontakt::{Error, Result};
use std::io::BufRead;
use std::path::Path;

/// Whether `path` names a topography that carries its own grid (`.xyz` or `.sdf`).
pub fn carries_grid(path: &Path) -> bool {
    path.extension()
        .and_then(|e| e.to_str())
        .is_some_and(|e| e.eq_ignore_ascii_case("xyz") || e.eq_ignore_ascii_case("sdf"))
}

/// Read a `.xyz` or `.sdf` topography as heights \[mm\].
///
/// The file is read while streaming through [`crate::files`] (at most
/// [`crate::files::MAX_DATA_FILE_BYTES`], no NUL byte). In an `.xyz` file, leading lines whose
/// first field is not a number (a profilometer's column titles, `x0 y0 z0`, `X [µm]`) are
/// skipped; their count is [`Topography::skipped_lines`]. `xyz_to_mm` converts the `.xyz`
/// file's lengths (x, y and z) to mm (1 for mm, 1e-3 for µm); an `.sdf` file gives its own
/// scales in metres.
///
/// # Errors
/// [`Error::InvalidInput`] naming `surface.file` with the file and what is wrong: an
/// unreadable file, a file over the size limit or with a NUL byte, a line that is not three
/// numbers (named), a grid with a missing or repeated node or unequal spacing, an SDF header
/// without a needed key, a value count that is not `NumPoints × NumProfiles`, a binary SDF.
pub fn read_topography(path: &Path, xyz_to_mm: f64) -> Result<Topography> {
    let err = |why: String| Error::invalid("surface.file", path.display(), why);
    let reader = crate::files::open(path, crate::files::MAX_DATA_FILE_BYTES, true)
        .map_err(|e| err(format!("a readable file ({e})")))?;
    let is_sdf = path
        .extension()
        .and_then(|e| e.to_str())
        .is_some_and(|e| e.eq_ignore_ascii_case("sdf"));
    let ((nx, ny, spacing, values), skipped_lines) = if is_sdf {
        (parse_sdf(reader).map_err(err)?, 0)
    } else {
        parse_xyz(reader, xyz_to_mm).map_err(err)?
    };
    let map = GapMap::new(nx, ny, spacing, values, MapKind::Height)
        .map_err(|e| e.map_field(|_| "surface.file".into()))?;
    Ok(Topography { map, skipped_lines })
}

/// A topography read by [`read_topography`].
#[derive(Debug, Clone, PartialEq)]
pub struct Topography {
    /// The heights as a map (values: the gap `max(z) - z`) \[mm\].
    pub map: GapMap,
    /// Leading lines skipped as a header (not starting with a number).
    pub skipped_lines: usize,
}

/// Whether a text line starts with something that is not a number: a header line of a
/// profilometer's export (`x0,y0,z0`, `X [µm]; Y [µm]; Z [nm]`, `Width: 1 mm`). Such lines
/// are skipped before the first line of numbers; after it, they are errors.
pub(crate) fn is_header_line(line: &str) -> bool {
    line.split(|c: char| c.is_whitespace() || c == ',' || c == ';')
        .find(|f| !f.is_empty())
        .is_some_and(|f| f.parse::<f64>().is_err())
}

/// The lines of a capped reader, the reader's errors as messages.
fn lines(reader: impl BufRead) -> impl Iterator<Item = std::result::Result<String, String>> {
    reader
        .lines()
        .map(|l| l.map_err(|e| format!("a readable text file ({e})")))
}

type Grid = (usize, usize, [f64; 2], Vec<f64>);

fn parse_xyz(reader: impl BufRead, to_mm: f64) -> std::result::Result<(Grid, usize), String> {
    let mut points = Vec::new();
    let mut skipped = 0;
    for (k, line) in lines(reader).enumerate() {
        let line = line?;
        let line = line.split('#').next().unwrap_or_default().trim();
        if line.is_empty() {
            continue;
        }
        if points.is_empty() && is_header_line(line) {
            skipped += 1;
            continue;
        }
        let fields: Vec<&str> = line
            .split(|c: char| c.is_whitespace() || c == ',' || c == ';')
            .filter(|f| !f.is_empty())
            .collect();
        let nums: Vec<f64> = fields
            .iter()
            .filter_map(|f| f.parse::<f64>().ok())
            .map(|v| v * to_mm)
            .collect();
        if fields.len() != 3 || nums.len() != 3 || nums.iter().any(|v| !v.is_finite()) {
            return Err(format!(
                "an .xyz file of lines `x y z` (three finite numbers); line {} is `{line}`",
                k + 1
            ));
        }
        points.push([nums[0], nums[1], nums[2]]);
    }
    if points.is_empty() {
        return Err(format!(
            "an .xyz file with lines of numbers `x y z`; it has none ({skipped} header lines)"
        ));
    }
    let axis = |c: usize| -> std::result::Result<(f64, f64, usize), String> {
        let mut v: Vec<f64> = points.iter().map(|p| p[c]).collect();
        v.sort_by(f64::total_cmp);
        v.dedup();
        let n = v.len();
        if n < 2 {
            return Err(format!(
                "an .xyz grid with at least 2 distinct {} values; it has {n}",
                if c == 0 { "x" } else { "y" }
            ));
        }
        let step = (v[n - 1] - v[0]) / (n - 1) as f64;
        if let Some(i) = (0..n).find(|&i| (v[i] - (v[0] + i as f64 * step)).abs() > 1e-6 * step) {
            return Err(format!(
                "a uniform .xyz grid; the {} values are not equally spaced near {} mm",
                if c == 0 { "x" } else { "y" },
                v[i]
            ));
        }
        Ok((v[0], step, n))
    };
    let (x0, dx, nx) = axis(0)?;
    let (y0, dy, ny) = axis(1)?;
    let mut values = vec![f64::NAN; nx * ny];
    for p in &points {
        let i = ((p[0] - x0) / dx).round() as usize;
        let j = ((p[1] - y0) / dy).round() as usize;
        let slot = &mut values[j * nx + i];
        if !slot.is_nan() {
            return Err(format!(
                "each grid node once; ({}, {}) mm is given twice",
                p[0], p[1]
            ));
        }
        *slot = p[2];
    }
    if let Some(k) = values.iter().position(|v| v.is_nan()) {
        return Err(format!(
            "a complete grid; the node ({}, {}) mm of the {nx} x {ny} grid is missing",
            x0 + (k % nx) as f64 * dx,
            y0 + (k / nx) as f64 * dy
        ));
    }
    Ok(((nx, ny, [dx, dy], values), skipped))
}

fn parse_sdf(reader: impl BufRead) -> std::result::Result<Grid, String> {
    let mut lines = lines(reader);
    let first = lines.next().transpose()?.unwrap_or_default();
    let first = first.trim();
    if first.starts_with("bBCR") {
        return Err(
            "an ASCII SDF (aBCR-1.0); this is the binary variant (bBCR): export ASCII".into(),
        );
    }
    if !first.starts_with("aBCR") {
        return Err(format!(
            "an ISO 25178-71 SDF whose first line is `aBCR-1.0`; it is `{first}`"
        ));
    }
    let mut header = std::collections::HashMap::new();
    let mut in_data = false;
    let mut values = Vec::new();
    for line in lines {
        let line = line?;
        let line = line.trim();
        if line == "*" {
            if in_data {
                break;
            }
            in_data = true;
            continue;
        }
        if in_data {
            for f in line.split_whitespace() {
                let v: f64 = f.parse().map_err(|_| {
                    format!(
                        "numbers in the data section; value {} is `{f}`",
                        values.len() + 1
                    )
                })?;
                values.push(v);
            }
        } else if let Some((k, v)) = line.split_once('=') {
            header.insert(k.trim().to_ascii_lowercase(), v.trim().to_string());
        }
    }
    let get = |key: &str| -> std::result::Result<f64, String> {
        header
            .get(&key.to_ascii_lowercase())
            .and_then(|v| v.parse::<f64>().ok())
            .filter(|v| v.is_finite())
            .ok_or_else(|| format!("an SDF header with a numeric `{key}`"))
    };
    let (nx, ny) = (get("NumPoints")?, get("NumProfiles")?);
    if !(nx >= 2.0 && ny >= 2.0 && nx.fract() == 0.0 && ny.fract() == 0.0 && nx * ny <= 1e9) {
        return Err(format!(
            "NumPoints and NumProfiles of at least 2 each; they are {nx} and {ny}"
        ));
    }
    let (nx, ny) = (nx as usize, ny as usize);
    let (xs, ys, zs) = (get("Xscale")?, get("Yscale")?, get("Zscale")?);
    if !(xs > 0.0 && ys > 0.0 && zs > 0.0) {
        return Err(format!(
            "positive Xscale, Yscale, Zscale; they are {xs}, {ys}, {zs}"
        ));
    }
    if values.len() != nx * ny {
        return Err(format!(
            "NumPoints x NumProfiles = {} values; the data section holds {}",
            nx * ny,
            values.len()
        ));
    }
    let to_mm = 1e3;
    let values = values.into_iter().map(|v| v * zs * to_mm).collect();
    Ok((nx, ny, [xs * to_mm, ys * to_mm], values))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn write(name: &str, text: &str) -> std::path::PathBuf {
        let dir = std::env::temp_dir().join(format!("kontakt-topography-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap_or_default();
        let p = dir.join(name);
        std::fs::write(&p, text).unwrap_or_default();
        p
    }

    /// A 3 x 2 grid in shuffled order: spacing and values in place (heights become the gap
    /// max(z) - z).
    #[test]
    fn xyz_grid_in_any_order() {
        let p = write(
            "a.xyz",
            "# x y z\n0.2 0.0 3\n0 0 1\n0.1,0.0,2\n0 0.5 4\n0.1 0.5 5\n0.2\t0.5\t6\n",
        );
        let m = read_topography(&p, 1.0).map(|t| t.map);
        assert!(m.is_ok(), "{m:?}");
        if let Ok(m) = m {
            assert_eq!((m.grid().nx(), m.grid().ny()), (3, 2));
            assert!((m.grid().dx() - 0.1).abs() < 1e-12 && (m.grid().dy() - 0.5).abs() < 1e-12);
            assert_eq!(m.values(), &[5.0, 4.0, 3.0, 2.0, 1.0, 0.0]);
        }
    }

    #[test]
    fn xyz_errors_name_the_problem() {
        for (text, expect) in [
            ("0 0 1\n1 0 2\n0 1 3\n", "is missing"),
            ("0 0 1\n1 0 2\n0 1 3\n1 1 4\n1 1 5\n", "given twice"),
            (
                "0 0 1\n1 0 2\n3 0 2\n0 1 3\n1 1 4\n3 1 5\n",
                "not equally spaced",
            ),
            ("0 0 1\n1 0 nan\n", "line 2"),
            ("0 0\n", "line 1"),
        ] {
            let e = read_topography(&write("b.xyz", text), 1.0)
                .map(|_| ())
                .unwrap_err();
            let m = e.to_string();
            assert!(
                m.contains("surface.file") && m.contains(expect),
                "{text:?}: {m}"
            );
        }
    }

    /// An ASCII SDF of 3 points x 2 profiles with scales in metres: spacing and heights
    /// in mm.
    #[test]
    fn sdf_ascii_with_scales() {
        let text = "aBCR-1.0\nManufacID = kontakt\nNumPoints = 3\nNumProfiles = 2\n\
                    Xscale = 1.0E-6\nYscale = 2.0E-6\nZscale = 1.0E-9\nZresolution = -1\n\
                    Compression = 0\nDataType = 7\nCheckType = 0\n*\n1 2 3\n4 5 6\n*\n";
        let m = read_topography(&write("c.sdf", text), 1.0).map(|t| t.map);
        assert!(m.is_ok(), "{m:?}");
        if let Ok(m) = m {
            assert_eq!((m.grid().nx(), m.grid().ny()), (3, 2));
            assert!((m.grid().dx() - 1e-3).abs() < 1e-15 && (m.grid().dy() - 2e-3).abs() < 1e-15);
            // heights 1..6 nm = 1e-6..6e-6 mm; gap = max - z
            let expect = [5e-6, 4e-6, 3e-6, 2e-6, 1e-6, 0.0];
            for (a, b) in m.values().iter().zip(expect) {
                assert!((a - b).abs() < 1e-18, "{a} vs {b}");
            }
        }
        for (text, expect) in [
            ("bBCR-1.0\n", "binary"),
            (
                "aBCR-1.0\nNumPoints = 3\nNumProfiles = 2\nXscale = 1\nYscale = 1\nZscale = 1\n*\n1 2 3 4 5\n*\n",
                "holds 5",
            ),
            (
                "aBCR-1.0\nNumPoints = 3\nXscale = 1\n*\n1\n*\n",
                "NumProfiles",
            ),
            (
                "aBCR-1.0\nNumPoints = 2\nNumProfiles = 2\nXscale = 1\nYscale = 1\nZscale = 1\n*\n1 2 BAD 4\n*\n",
                "value 3 is `BAD`",
            ),
        ] {
            let e = read_topography(&write("d.sdf", text), 1.0)
                .map(|_| ())
                .unwrap_err();
            let m = e.to_string();
            assert!(
                m.contains("surface.file") && m.contains(expect),
                "{text:?}: {m}"
            );
        }
    }
}
