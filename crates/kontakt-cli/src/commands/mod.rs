//! Subcommands: turn arguments into library cases, run them, print.

use crate::cli::{Cli, Command, Criterion, HertzArgs};
use crate::output;
use anyhow::{Context, Result};
use kontakt::hertz::subsurface::YieldCriterion;
use kontakt_case::case::{
    BodySpec, CaseFile, ContactKind, ContactSpec, LoadSpec, Method, YieldSpec,
};
use kontakt_case::{Case, Outcome, run_case};

pub mod bearing;
pub mod bearing_demo;
pub mod bearing_plot;
pub mod bearing_rib;
pub mod fmu;
pub mod friction;
pub mod impact;
pub mod mbs;
pub mod mindlin;
pub mod pimp;
pub mod rough;
pub mod schema;
pub mod serve;
pub mod sweep;
pub mod traction;
pub mod validate;
pub mod validate_bearing;
use std::io::Write;

pub use crate::error::{InputError, cannot_write};

/// A progress indicator on standard error, shown only when standard error is a terminal
/// and the output is not JSON (`quiet`): a bar of `len` steps, or a spinner for `None`.
/// Piped or redirected runs stay silent.
pub fn progress(len: Option<u64>, template: &str, quiet: bool) -> Option<indicatif::ProgressBar> {
    use indicatif::{ProgressBar, ProgressDrawTarget, ProgressStyle};
    use std::io::IsTerminal;
    if quiet || !std::io::stderr().is_terminal() {
        return None;
    }
    let bar = ProgressBar::with_draw_target(len, ProgressDrawTarget::stderr());
    let style =
        ProgressStyle::with_template(template).unwrap_or_else(|_| ProgressStyle::default_bar());
    bar.set_style(style);
    if len.is_none() {
        bar.enable_steady_tick(std::time::Duration::from_millis(120));
    }
    Some(bar)
}

/// A CSV output file of any command: every failure (creating it, a record, the final
/// flush, a full disk) is an error naming the file (exit status 1), never an anonymous
/// "No space left on device". [`CsvFile::finish`] flushes it; a file dropped without it
/// may be incomplete.
pub struct CsvFile<'a> {
    path: &'a std::path::Path,
    w: csv::Writer<std::fs::File>,
}

impl<'a> CsvFile<'a> {
    /// Create (or truncate) `path`.
    pub fn create(path: &'a std::path::Path) -> Result<Self> {
        let w = csv::Writer::from_path(path).map_err(|e| cannot_write("write", path, e))?;
        Ok(CsvFile { path, w })
    }

    /// One record of fields.
    pub fn record<I, T>(&mut self, record: I) -> Result<()>
    where
        I: IntoIterator<Item = T>,
        T: AsRef<[u8]>,
    {
        self.w
            .write_record(record)
            .map_err(|e| cannot_write("write", self.path, e))
    }

    /// One record of a serializable row (a header first, from its field names).
    pub fn serialize(&mut self, row: impl serde::Serialize) -> Result<()> {
        self.w
            .serialize(row)
            .map_err(|e| cannot_write("write", self.path, e))
    }

    /// Flush the file: where a full disk shows.
    pub fn finish(mut self) -> Result<()> {
        self.w
            .flush()
            .map_err(|e| cannot_write("write", self.path, e))
    }
}

pub fn run(cli: &Cli, out: &mut impl Write) -> Result<()> {
    match &cli.command {
        Command::Hertz(args) => {
            let case = hertz_case(args);
            let report = run_case(&case).map_err(|e| e.map_field(flag_for_field))?;
            output::print_report(out, &report, args.json)
        }
        Command::Solve(args) => {
            let (label, text) = read_case(&args.input.case)?;
            let case = Case::from_toml_str(&text).with_context(|| label.clone())?;
            let wants_field = args.csv.is_some() || args.map.is_some();
            match case.method() {
                "hertz" if wants_field => {
                    return Err(InputError(format!(
                        "{label}: --csv and --map need a pressure field: use method = \"pimp\" or \"bem\""
                    ))
                    .into());
                }
                "friction" if wants_field => {
                    return Err(InputError(format!(
                        "{label}: friction cases write their tables and maps with `kontakt friction {label} --csv FILE --map FILE`"
                    ))
                    .into());
                }
                "impact" if wants_field => {
                    return Err(InputError(format!(
                        "{label}: --csv and --map need a pressure field: use method = \"pimp\" or \"bem\""
                    ))
                    .into());
                }
                "rough" if wants_field => {
                    return Err(InputError(format!(
                        "{label}: rough cases write their table and maps with `kontakt rough {label} --csv FILE --map FILE`"
                    ))
                    .into());
                }
                "mindlin" if wants_field => {
                    return Err(InputError(format!(
                        "{label}: mindlin cases write their loop with `kontakt mindlin {label} --csv FILE --plot FILE`"
                    ))
                    .into());
                }
                "bearing" if wants_field => {
                    return Err(InputError(format!(
                        "{label}: bearing cases write their per-roller table with `kontakt bearing {label} --csv FILE`"
                    ))
                    .into());
                }
                "traction" if wants_field => {
                    return Err(InputError(format!(
                        "{label}: traction cases write curves with `kontakt traction {label} --csv FILE --plot FILE`"
                    ))
                    .into());
                }
                _ => {}
            }
            // Relative paths in the case (gap maps) are relative to the case file.
            let base = args.input.base_dir();
            let name = match &case {
                Case::Pimp(c) | Case::Bem(c) => c.name.clone(),
                _ => None,
            };
            // A roller/rib map names its axes along and across the rib, as the demo's do.
            let axes = match &case {
                Case::Pimp(c) | Case::Bem(c) if args.map.is_some() => {
                    kontakt_case::pimp_case::bearing_axes(&c.geometry)
                        .with_context(|| label.clone())?
                }
                _ => None,
            };
            match case.run(base).with_context(|| label.clone())? {
                Outcome::Hertz(report) => output::print_report(out, &report, args.input.json),
                Outcome::Pimp(outcome) => {
                    let s = &outcome.solution;
                    if let Some(path) = &args.csv {
                        pimp::write_csv(path, &s.grid, &[("pressure_mpa", &s.pressure)])?;
                    }
                    if let Some(path) = &args.map {
                        let mode = outcome.report.mode.map_or("", |m| m.as_str());
                        let what = format!("PimP {mode}");
                        write_case_map(path, &outcome.report, s, (name.as_deref(), axes), &what)?;
                    }
                    pimp::print_report(out, &outcome.report, args.input.json)
                }
                Outcome::Bem(outcome) => {
                    let s = &outcome.solution;
                    if let Some(path) = &args.csv {
                        pimp::write_csv(
                            path,
                            &s.grid,
                            &[
                                ("pressure_mpa", &s.pressure),
                                ("displacement_mm", &s.detail.displacement),
                                ("gap_mm", &s.detail.gap),
                            ],
                        )?;
                    }
                    if let Some(path) = &args.map {
                        write_case_map(
                            path,
                            &outcome.report,
                            s,
                            (name.as_deref(), axes),
                            "coupled half-space",
                        )?;
                    }
                    pimp::print_report(out, &outcome.report, args.input.json)
                }
                Outcome::Traction(report) => traction::print_report(out, &report, args.input.json),
                Outcome::Friction(outcome) => {
                    friction::print_report(out, &outcome.report, args.input.json)
                }
                Outcome::Mindlin(report) => mindlin::print_report(out, &report, args.input.json),
                Outcome::Impact(report) => impact::print_report(out, &report, args.input.json),
                Outcome::Rough(outcome) => {
                    rough::print_report(out, &outcome.report, args.input.json)
                }
                Outcome::Bearing(report) => bearing::print_report(out, &report, args.input.json),
            }
        }
        Command::Demo(args) => pimp::demo(&args.out, out, args.json),
        Command::Validate(args) if args.bearing => {
            validate_bearing::validate_bearing(&args.out, out, args.json)
        }
        Command::Validate(args) => validate::validate(&args.out, args.cells, out, args.json),
        Command::Traction(args) => traction::run(args, out),
        Command::Mindlin(args) => mindlin::run(args, out),
        Command::Impact(args) => impact::run(args, out),
        Command::Rough(args) => rough::run(args, out),
        Command::Bearing(args) => bearing::run(args, out),
        Command::Friction(args) => friction::run(args, out),
        Command::Mbs(args) => mbs::run(args, out),
        Command::Sweep(args) => sweep::run(args, out),
        Command::Fmu(args) => fmu::run(args, out),
        Command::Schema => schema::run(out),
        Command::Serve(args) => serve::run(args, out),
    }
}

/// Read a case file for the subcommand `subcommand`, which runs `method = "{method}"`
/// cases: its label and text, or an input error that says which kind of case the file is
/// and which subcommand takes it (the method is read before the schema, so a Hertz case
/// given to `kontakt traction` is named as such, not reported as an unknown field).
pub fn read_case_for(
    path: &std::path::Path,
    method: &str,
    subcommand: &str,
) -> Result<(String, String)> {
    let (label, text) = read_case(path)?;
    let found = text
        .parse::<toml::Table>()
        .ok()
        .and_then(|t| t.get("method").and_then(|m| m.as_str().map(str::to_string)));
    if let Some(found) = found
        && found != method
    {
        let runner = match found.as_str() {
            "traction" => "kontakt traction (or kontakt solve)",
            "friction" => "kontakt friction (or kontakt solve)",
            "mindlin" => "kontakt mindlin (or kontakt solve)",
            "impact" => "kontakt impact (or kontakt solve)",
            "rough" => "kontakt rough (or kontakt solve)",
            "bearing" => "kontakt bearing (or kontakt solve)",
            _ => "kontakt solve",
        };
        return Err(InputError(format!(
            "{label} is a method = \"{found}\" case; `kontakt {subcommand}` runs method = \
             \"{method}\" cases: run this one with {runner}"
        ))
        .into());
    }
    Ok((label, text))
}

/// `--map` of a PimP or half-space case: the pressure map titled by the case's name (or
/// geometry), force and method, with the local Hertz ellipse; its axes named in the bearing
/// when `axes` gives them (a roller/rib geometry), else by the gap's principal frame.
fn write_case_map<D>(
    path: &std::path::Path,
    report: &kontakt_case::PimpReport,
    s: &kontakt::field::NormalSolution<D>,
    (name, axes): (Option<&str>, Option<[[f64; 3]; 2]>),
    what: &str,
) -> Result<()> {
    let title = format!(
        "{}, {:.0} N, {what}",
        name.unwrap_or(&report.geometry),
        report.force_n,
    );
    let hertz = report.hertz.as_ref().map(|h| h.semi_axes_mm);
    crate::render::write_map(
        path,
        &s.grid,
        &s.pressure,
        &title,
        &[],
        &match axes {
            Some(axes) => crate::render::MapNotes::in_bearing(axes, hertz),
            None => crate::render::MapNotes::principal(hertz),
        },
    )
}

impl crate::cli::CaseInput {
    /// The case file (or standard input) of a command that runs `method` cases, named
    /// like the command: its label and text (see [`read_case_for`]).
    ///
    /// # Errors
    /// As [`read_case_for`].
    pub fn read(&self, method: &str) -> Result<(String, String)> {
        read_case_for(&self.case, method, method)
    }

    /// The folder that relative paths in the case (gap and height maps) are resolved
    /// against: the case file's, the working folder for standard input.
    pub fn base_dir(&self) -> &std::path::Path {
        self.case
            .parent()
            .filter(|_| self.case.as_os_str() != "-")
            .unwrap_or(std::path::Path::new("."))
    }
}

/// Read a case file (or standard input for `-`): its label for messages and its text.
pub fn read_case(path: &std::path::Path) -> Result<(String, String)> {
    if path.as_os_str() == "-" {
        let text = kontakt_case::read_case_text(std::io::stdin(), "<stdin>")?;
        Ok(("<stdin>".to_string(), text))
    } else {
        Ok((
            path.display().to_string(),
            kontakt_case::read_case_file(path)?,
        ))
    }
}

fn hertz_case(a: &HertzArgs) -> CaseFile {
    CaseFile {
        name: None,
        method: Method::Hertz,
        contact: ContactSpec {
            // --length or --line-load make a line contact, as `kind = "line"` in a file.
            kind: if a.length.is_some() || a.line_load.is_some() {
                ContactKind::Line
            } else {
                ContactKind::Point
            },
            angle_deg: a.angle_deg,
            length_mm: a.length,
        },
        body1: BodySpec {
            radii_mm: a.body1_radii.clone(),
            e_mpa: a.e1,
            nu: a.nu1,
        },
        body2: BodySpec {
            radii_mm: a.body2_radii.clone(),
            e_mpa: a.e2,
            nu: a.nu2,
        },
        load: LoadSpec {
            force_n: a.force,
            approach_mm: a.approach,
            line_load_n_per_mm: a.line_load,
        },
        yield_check: a.yield_stress.map(|stress_mpa| YieldSpec {
            stress_mpa,
            criterion: match a.criterion {
                Criterion::VonMises => YieldCriterion::VonMises,
                Criterion::Tresca => YieldCriterion::Tresca,
            },
        }),
    }
}

/// Map case-file keys to the `hertz` subcommand's flags for error messages.
fn flag_for_field(field: &str) -> String {
    let flag = if field == "body1.radii_mm, body2.radii_mm" {
        "--body1-radii/--body2-radii"
    } else if field.starts_with("body1.radii") {
        "--body1-radii"
    } else if field.starts_with("body2.radii") {
        "--body2-radii"
    } else {
        match field {
            "body1.e_mpa" => "--e1",
            "body1.nu" => "--nu1",
            "body2.e_mpa" => "--e2",
            "body2.nu" => "--nu2",
            "load.force_n" => "--force",
            "load.approach_mm" => "--approach",
            "contact.angle_deg" => "--angle-deg",
            "contact.length_mm" => "--length",
            "load.line_load_n_per_mm" => "--line-load",
            "yield.stress_mpa" => "--yield-stress",
            "radii" => "--body1-radii/--body2-radii",
            other => other,
        }
    };
    flag.to_string()
}
