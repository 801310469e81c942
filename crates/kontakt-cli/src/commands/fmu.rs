//! `kontakt fmu CASE.toml -o case.fmu`: the element of a case as an FMU (FMI 2.0). The
//! model description is written from the case (bearing element or contact element by its
//! method); the binary is the shared library of crates/kontakt-fmi, found by `--library`,
//! `$KONTAKT_FMI_LIBRARY` or next to this executable (docs/fmi.md, "Building an FMU").

use crate::cli::FmuArgs;
use crate::commands::{InputError, cannot_write, read_case};
use anyhow::{Context, Result};
use std::io::Write;
use std::path::{Path, PathBuf};

/// The FMU library: the flag's, the environment's, or the newest next to this executable.
fn library(flag: Option<&Path>) -> Result<PathBuf> {
    let name = kontakt_fmi::archive::library_file_name();
    if let Some(path) = flag {
        return if path.is_file() {
            Ok(path.to_path_buf())
        } else {
            Err(InputError(format!(
                "--library {}: no such file (the shared library {name} of crates/kontakt-fmi)",
                path.display()
            ))
            .into())
        };
    }
    if let Some(path) = std::env::var_os("KONTAKT_FMI_LIBRARY") {
        let path = PathBuf::from(path);
        return if path.is_file() {
            Ok(path)
        } else {
            Err(InputError(format!(
                "KONTAKT_FMI_LIBRARY={}: no such file (the shared library {name} of crates/kontakt-fmi)",
                path.display()
            ))
            .into())
        };
    }
    let exe = std::env::current_exe().ok();
    let dir = exe.as_deref().and_then(Path::parent);
    // `cargo build` copies the library to the profile folder, `cargo test` leaves it in
    // deps/ only: take the newer of the two.
    let newest = dir
        .into_iter()
        .flat_map(|d| [d.join(&name), d.join("deps").join(&name)])
        .filter_map(|p| Some((p.metadata().ok()?.modified().ok()?, p)))
        .max_by_key(|(t, _)| *t)
        .map(|(_, p)| p);
    newest.ok_or_else(|| {
        InputError(format!(
            "the FMU binary {name} is not next to this executable ({}): build it with \
             `cargo build --workspace` (or --release), or give it with --library FILE or \
             KONTAKT_FMI_LIBRARY",
            dir.map(|d| d.display().to_string()).unwrap_or_default()
        ))
        .into()
    })
}

/// Write the FMU of `args.case` to `args.out`.
pub fn run(args: &FmuArgs, out: &mut impl Write) -> Result<()> {
    let (label, text) = read_case(&args.case)?;
    let lib = library(args.library.as_deref())?;
    let bytes = std::fs::read(&lib).map_err(|e| InputError(format!("{}: {e}", lib.display())))?;
    let (fmu, kind) = kontakt_fmi::archive::fmu(&text, &bytes).with_context(|| label.clone())?;
    std::fs::write(&args.out, &fmu).map_err(|e| cannot_write("write", &args.out, e))?;
    let kind = match kind {
        kontakt_fmi::model::Kind::Bearing => "bearing element",
        kontakt_fmi::model::Kind::Contact => "contact element",
    };
    writeln!(
        out,
        "wrote {} ({kind} of {label}, FMI 2.0 model exchange and co-simulation, {} MB; binary {})",
        args.out.display(),
        fmu.len() / 1_000_000,
        lib.display()
    )?;
    Ok(())
}
