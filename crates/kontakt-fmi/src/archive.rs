//! The FMU file: a zip archive (the `zip` crate, deflated entries) holding
//! `modelDescription.xml`, `binaries/<platform>/kontakt_fmi.<ext>` and
//! `resources/case.toml`; the timestamps are fixed, so the same case and binary give the
//! same bytes.

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

/// A zip archive of the entries `(name, bytes)`, deflated, with fixed timestamps
/// (1980-01-01) and Unix mode 0644, so that the same entries give the same bytes.
///
/// # Errors
/// [`kontakt::Error::InvalidInput`] (field `archive`) if the zip writer fails (an entry
/// beyond what the format holds).
pub fn zip(entries: &[(&str, &[u8])]) -> Result<Vec<u8>> {
    use std::io::Write;
    let failed = |e: &dyn std::fmt::Display| {
        kontakt::Error::invalid("archive", e.to_string(), "an FMU the zip format can hold")
    };
    let options = zip::write::SimpleFileOptions::default()
        .compression_method(zip::CompressionMethod::Deflated)
        .last_modified_time(zip::DateTime::default())
        .unix_permissions(0o644)
        .large_file(entries.iter().any(|(_, d)| d.len() >= u32::MAX as usize));
    let mut writer = zip::ZipWriter::new(std::io::Cursor::new(Vec::new()));
    for (name, data) in entries {
        writer.start_file(*name, options).map_err(|e| failed(&e))?;
        writer.write_all(data).map_err(|e| failed(&e))?;
    }
    writer
        .finish()
        .map(std::io::Cursor::into_inner)
        .map_err(|e| failed(&e))
}

/// The FMU of a case text with the shared library `library` (the bytes of
/// `libkontakt_fmi.so` of this build): model description, binary, case; and which
/// element it is.
///
/// # Errors
/// Those of [`model_description`] (the case's, named by its key) and [`zip()`](fn@zip).
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
