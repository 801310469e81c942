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
mod error;
mod output;
mod render;

#[cfg(test)]
mod fuzz;

use clap::{CommandFactory, Parser};
use std::io::Write;
use std::process::ExitCode;

fn main() -> ExitCode {
    let args = match cli::Cli::try_parse() {
        Ok(args) => args,
        Err(e) => return usage_error(&e),
    };
    let mut stdout = StandardOutput(std::io::stdout().lock());
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
            eprintln!("error: {}", one_line(&chain_message(&err)));
            ExitCode::from(code)
        }
    }
}

/// Standard output whose write errors name it ("cannot write standard output: No space
/// left on device"), as the files' errors name the file; the error's kind is kept (a
/// closed pipe stays a closed pipe).
struct StandardOutput<W>(W);

impl<W: Write> StandardOutput<W> {
    fn label(e: std::io::Error) -> std::io::Error {
        std::io::Error::new(e.kind(), format!("cannot write standard output: {e}"))
    }
}

impl<W: Write> Write for StandardOutput<W> {
    fn write(&mut self, buf: &[u8]) -> std::io::Result<usize> {
        self.0.write(buf).map_err(Self::label)
    }

    fn flush(&mut self) -> std::io::Result<()> {
        self.0.flush().map_err(Self::label)
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

/// The error and its causes joined by ": ", skipping a cause that an outer message already
/// quotes (thiserror messages that print their source, e.g. "cannot write plot file X: No
/// such file or directory", would otherwise repeat it).
fn chain_message(err: &anyhow::Error) -> String {
    let mut message = String::new();
    for cause in err.chain() {
        let text = cause.to_string();
        if message.contains(&text) {
            continue;
        }
        if !message.is_empty() {
            message.push_str(": ");
        }
        message.push_str(&text);
    }
    message
}

/// 2 for bad input, 1 for everything else (a solver that did not converge, an output file
/// that cannot be written).
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
        if let Some(e) = cause.downcast_ref::<kontakt_plot::PlotError>() {
            return match e {
                kontakt_plot::PlotError::Io { .. } | kontakt_plot::PlotError::Drawing(_) => 1,
                _ => 2,
            };
        }
    }
    1
}

/// clap's own errors (unknown flag, unparsable number, missing argument) in the library's
/// style: one line, exit status 2, with the flag's help text (its unit and valid range)
/// for a value that did not parse, and the usage line. Help and version requests print
/// as clap prints them.
fn usage_error(e: &clap::Error) -> ExitCode {
    use clap::error::{ContextKind, ContextValue, ErrorKind};
    if matches!(
        e.kind(),
        ErrorKind::DisplayHelp
            | ErrorKind::DisplayVersion
            | ErrorKind::DisplayHelpOnMissingArgumentOrSubcommand
    ) {
        // Help on stdout (exit 0), or on stderr when a subcommand is missing (exit 2).
        let _ = e.print();
        return ExitCode::from(u8::try_from(e.exit_code()).unwrap_or(2));
    }
    let text = e.to_string();
    let mut line = text
        .lines()
        .map(str::trim)
        .filter(|l| !l.is_empty() && !l.starts_with("For more information"))
        .map(|l| l.strip_prefix("error: ").unwrap_or(l))
        .map(|l| l.replacen("Usage: ", "usage: ", 1))
        .collect::<Vec<_>>()
        .join("; ")
        .replace(":;", ":");
    if let Some(ContextValue::String(value)) = e.get(ContextKind::InvalidValue)
        && value.chars().count() > 60
    {
        let short: String = value.chars().take(40).collect();
        line = line.replace(
            value.as_str(),
            &format!("{short}… ({} characters)", value.chars().count()),
        );
    }
    if let Some(ContextValue::String(arg)) = e.get(ContextKind::InvalidArg)
        && let Some(help) = flag_help(arg)
    {
        line.push_str(&format!("; expected: {help}"));
    }
    eprintln!("error: {}", one_line(&line));
    ExitCode::from(2)
}

/// The help text of the flag `arg` (`--force <N>`) of the subcommand on the command line.
fn flag_help(arg: &str) -> Option<String> {
    let long = arg.strip_prefix("--")?.split([' ', '=']).next()?;
    let sub = std::env::args().nth(1)?;
    let command = cli::Cli::command();
    let sub = command.find_subcommand(&sub)?;
    let flag = sub.get_arguments().find(|a| a.get_long() == Some(long))?;
    Some(one_line(&flag.get_help()?.to_string()))
}

fn one_line(s: &str) -> String {
    s.split_whitespace().collect::<Vec<_>>().join(" ")
}
