//! The FMU file: a zip archive (PKWARE APPNOTE 6.3: stored entries, CRC-32) holding
//! `modelDescription.xml`, `binaries/<platform>/kontakt_fmi.<ext>` and
//! `resources/case.toml`. Entries are stored, not compressed (the archive is written
//! without a compression library); the timestamps are fixed, so the same case and binary
//! give the same bytes.

use crate::description::{MODEL_IDENTIFIER, model_description};
use crate::fmi2::CASE_FILE;
use crate::model::Kind;
use kontakt::Result;

/// The FMI 2.0 platform folder and the shared-library extension of this build's target
/// (`linux64`/`so`, `darwin64`/`dylib`, `win64`/`dll`).
pub fn platform() -> (&'static str, &'static str) {
    if cfg!(target_os = "windows") {
        ("win64", "dll")
    } else if cfg!(target_os = "macos") {
        ("darwin64", "dylib")
    } else {
        ("linux64", "so")
    }
}

/// The binary's path inside the FMU.
pub fn binary_path() -> String {
    let (platform, ext) = platform();
    format!("binaries/{platform}/{MODEL_IDENTIFIER}.{ext}")
}

/// The file name cargo gives the FMU's shared library on this platform
/// (`libkontakt_fmi.so`).
pub fn library_file_name() -> String {
    let (_, ext) = platform();
    let prefix = if cfg!(target_os = "windows") {
        ""
    } else {
        "lib"
    };
    format!("{prefix}{MODEL_IDENTIFIER}.{ext}")
}

/// CRC-32 (IEEE 802.3, reflected, polynomial 0xEDB88320) of `data`.
pub fn crc32(data: &[u8]) -> u32 {
    let mut table = [0u32; 256];
    for (i, t) in table.iter_mut().enumerate() {
        let mut c = i as u32;
        for _ in 0..8 {
            c = if c & 1 != 0 {
                0xEDB8_8320 ^ (c >> 1)
            } else {
                c >> 1
            };
        }
        *t = c;
    }
    let mut c = !0u32;
    for &b in data {
        c = table[((c ^ u32::from(b)) & 0xFF) as usize] ^ (c >> 8);
    }
    !c
}

/// A zip archive of stored entries `(name, bytes)`.
///
/// # Errors
/// [`kontakt::Error::InvalidInput`] (field `archive`) for an entry or an archive beyond
/// the 4 GiB of a zip without the ZIP64 extension.
pub fn zip(entries: &[(&str, &[u8])]) -> Result<Vec<u8>> {
    let too_big = || kontakt::Error::invalid("archive", "> 4 GiB", "an FMU below 4 GiB");
    let mut out = Vec::new();
    let mut central = Vec::new();
    // 1980-01-01 00:00 in MS-DOS time and date
    let (time, date) = (0u16, (1 << 5) | 1u16);
    for (name, data) in entries {
        let offset = u32::try_from(out.len()).map_err(|_| too_big())?;
        let size = u32::try_from(data.len()).map_err(|_| too_big())?;
        let crc = crc32(data);
        let name_len = name.len() as u16;
        // local file header
        out.extend_from_slice(&0x0403_4b50u32.to_le_bytes());
        for v in [20u16, 0, 0, time, date] {
            out.extend_from_slice(&v.to_le_bytes());
        }
        for v in [crc, size, size] {
            out.extend_from_slice(&v.to_le_bytes());
        }
        out.extend_from_slice(&name_len.to_le_bytes());
        out.extend_from_slice(&0u16.to_le_bytes());
        out.extend_from_slice(name.as_bytes());
        out.extend_from_slice(data);
        // central directory header (made by version 2.0, Unix; file mode 0644)
        central.extend_from_slice(&0x0201_4b50u32.to_le_bytes());
        for v in [0x0314u16, 20, 0, 0, time, date] {
            central.extend_from_slice(&v.to_le_bytes());
        }
        for v in [crc, size, size] {
            central.extend_from_slice(&v.to_le_bytes());
        }
        for v in [name_len, 0, 0, 0, 0] {
            central.extend_from_slice(&v.to_le_bytes());
        }
        central.extend_from_slice(&(0o100644u32 << 16).to_le_bytes());
        central.extend_from_slice(&offset.to_le_bytes());
        central.extend_from_slice(name.as_bytes());
    }
    let start = u32::try_from(out.len()).map_err(|_| too_big())?;
    let length = central.len() as u32;
    out.extend_from_slice(&central);
    let n = entries.len() as u16;
    out.extend_from_slice(&0x0605_4b50u32.to_le_bytes());
    for v in [0u16, 0, n, n] {
        out.extend_from_slice(&v.to_le_bytes());
    }
    out.extend_from_slice(&length.to_le_bytes());
    out.extend_from_slice(&start.to_le_bytes());
    out.extend_from_slice(&0u16.to_le_bytes());
    Ok(out)
}

/// The FMU of a case text with the shared library `library` (the bytes of
/// `libkontakt_fmi.so` of this build): model description, binary, case; and which
/// element it is.
///
/// # Errors
/// Those of [`model_description`] (the case's, named by its key) and [`zip`].
pub fn fmu(case: &str, library: &[u8]) -> Result<(Vec<u8>, Kind)> {
    let (description, kind) = model_description(case)?;
    let binary = binary_path();
    let resource = format!("resources/{CASE_FILE}");
    zip(&[
        ("modelDescription.xml", description.as_bytes()),
        (&binary, library),
        (&resource, case.as_bytes()),
    ])
    .map(|bytes| (bytes, kind))
}
