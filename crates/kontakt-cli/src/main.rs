//! `kontakt`: the command-line interface of the kontakt contact-mechanics library.
//!
//! A thin shell: arguments are turned into the library's [`kontakt_case::CaseFile`], solved
//! by [`kontakt_case::run_case`] and printed as a table or as JSON. Nothing physical lives
//! here.
//!
//! Exit status: 0 success; 1 the computation failed (e.g. did not converge); 2 bad input
//! (invalid flag, field or file).

mod cli;
mod commands;
mod output;

#[cfg(test)]
mod fuzz;

use clap::Parser;
use std::io::Write;
use std::process::ExitCode;

fn main() -> ExitCode {
    let args = cli::Cli::parse();
    let mut stdout = std::io::stdout().lock();
    let result =
        commands::run(&args, &mut stdout).and_then(|()| stdout.flush().map_err(Into::into));
    match result {
        Ok(()) => ExitCode::SUCCESS,
        Err(err) => {
            // A closed pipe (`kontakt ... | head`) is not an error.
            if broken_pipe(&err) {
                return ExitCode::SUCCESS;
            }
            let code = exit_code(&err);
            eprintln!("error: {}", one_line(&format!("{err:#}")));
            ExitCode::from(code)
        }
    }
}

/// Whether the error is a closed output pipe, also when serde_json wrapped it.
fn broken_pipe(err: &anyhow::Error) -> bool {
    err.chain().any(|cause| {
        cause
            .downcast_ref::<std::io::Error>()
            .map(std::io::Error::kind)
            .or_else(|| {
                cause
                    .downcast_ref::<serde_json::Error>()
                    .and_then(serde_json::Error::io_error_kind)
            })
            == Some(std::io::ErrorKind::BrokenPipe)
    })
}

/// 2 for bad input, 1 for everything else.
fn exit_code(err: &anyhow::Error) -> u8 {
    for cause in err.chain() {
        if let Some(k) = cause.downcast_ref::<kontakt::Error>() {
            return match k {
                kontakt::Error::NotConverged { .. } => 1,
                _ => 2,
            };
        }
        if let Some(e) = cause.downcast_ref::<kontakt_case::SweepError>() {
            return if e.is_input() { 2 } else { 1 };
        }
        if cause.downcast_ref::<commands::InputError>().is_some() {
            return 2;
        }
    }
    1
}

fn one_line(s: &str) -> String {
    s.split_whitespace().collect::<Vec<_>>().join(" ")
}
