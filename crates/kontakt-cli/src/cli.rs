//! Command-line definitions (raw arguments). Validation happens in the library.

use clap::{Args, Parser, Subcommand};
use std::path::PathBuf;

/// Contact mechanics for rolling bearings. Units: mm, N, MPa.
#[derive(Debug, Parser)]
#[command(
    name = "kontakt",
    version,
    about,
    after_help = "Examples:\n  \
      kontakt hertz --body1-radii 10,10 --body2-radii inf,inf --force 500\n  \
      kontakt solve examples/roller_rib_torus_torus.toml --map p.png\n  \
      kontakt demo --out kontakt-demo\n  \
      kontakt validate --out kontakt-validate\n  \
      kontakt traction examples/traction_ball_all_models.toml --plot traction.png\n  \
      kontakt mindlin examples/mindlin_fretting.toml --plot loop.png\n  \
      kontakt impact examples/impact_oblique.toml\n  \
      kontakt rough examples/rough_self_affine.toml --plot area.png\n  \
      kontakt bearing examples/bearing_32216.toml --csv rollers.csv --plot loads.png\n  \
      kontakt friction examples/rib_friction.toml --plot torque.png\n  \
      kontakt mbs --out kontakt-mbs\n  \
      kontakt sweep examples/sweeps/hertz_load.toml --out kontakt-sweep\n  \
      kontakt fmu examples/bearing_32008x.toml -o bearing.fmu\n\n\
      Case files: docs/case-schema.md. Exit status: 0 success, 1 computation failed (e.g. not\n\
      converged, an unwritable file), 2 bad input.\n\
      Conventions: radii convex > 0, concave < 0, `inf` for flat; stresses tension positive."
)]
pub struct Cli {
    #[command(subcommand)]
    pub command: Command,
}

/// `kontakt solve`'s help line, naming every method of [`kontakt_case::Case::METHODS`] (the
/// list the dispatch runs), so that the help cannot drift from the code.
fn solve_about() -> String {
    format!(
        "Solve a case described in a TOML file, any method: {} (schema: docs/case-schema.md)",
        kontakt_case::Case::METHODS.join(", ")
    )
}

/// `kontakt traction`'s help line, naming every model of
/// [`kontakt_case::traction_case::TractionModel::ALL`].
fn traction_about() -> String {
    let models: Vec<&str> = kontakt_case::traction_case::TractionModel::ALL
        .iter()
        .map(|m| m.as_str())
        .collect();
    format!(
        "Traction curves F_T/(mu F_N) against the creepage (slide-to-roll ratio), models {} \
         (TOML case, method = \"traction\"; docs/case-schema.md)",
        models.join(", ")
    )
}

/// `kontakt friction`'s help line, naming every pressure model of
/// [`kontakt::bearing::rib_friction::PressureModel::ALL`].
fn friction_about() -> String {
    let models: Vec<&str> = kontakt::bearing::rib_friction::PressureModel::ALL
        .iter()
        .map(|m| m.as_str())
        .collect();
    format!(
        "Friction torque and power of the roller-end/rib contact of a tapered roller bearing \
         over a speed sweep: pressure models {}, lubricant film, mixed friction (TOML case, \
         method = \"friction\"; docs/case-schema.md)",
        models.join(", ")
    )
}

#[derive(Debug, Subcommand)]
pub enum Command {
    /// Hertz point-contact calculator (exact elliptical solution; the same as a case file
    /// with method = "hertz", docs/case-schema.md).
    Hertz(HertzArgs),
    #[command(about = solve_about())]
    Solve(SolveArgs),
    /// Run the roller-end/rib study (Wirsching et al. (2020) Table 1, 100-400 N) and write a report
    /// (Markdown, pressure maps, CSV) into a folder (docs/bearing.md, docs/pimp.md).
    Demo(DemoArgs),
    /// Compare PimP and Hertz with the coupled half-space solver for the roller-end/rib
    /// pairings (Wirsching et al. (2020) Figures 7-10) and write a report (Markdown, plots, CSV;
    /// docs/pimp.md, docs/halfspace.md); with --bearing: the whole-bearing friction torque
    /// against the measured datasets of validation/measured/ (docs/measured-torque.md).
    Validate(ValidateArgs),
    #[command(about = traction_about())]
    Traction(TractionArgs),
    /// Cattaneo-Mindlin partial slip of a Hertz contact under an oscillating tangential
    /// force: stick zone, shift, the Mindlin-Deresiewicz hysteresis loop and the energy
    /// dissipated per cycle (TOML case, method = "mindlin"; docs/case-schema.md).
    Mindlin(MindlinArgs),
    /// A sphere striking a flat: the Hertz normal impact and, with friction, the oblique
    /// rebound (rigid-body theory and the elastic analysis of Maw, Barber and Fawcett 1976)
    /// (TOML case, method = "impact"; docs/case-schema.md, docs/impact.md).
    Impact(ImpactArgs),
    /// A periodic rough surface (generated self-affine, or a measured height map) against a
    /// flat on the periodic half-space solver: real contact area, kappa, Persson's area,
    /// patches and mean gap per nominal pressure (TOML case, method = "rough";
    /// docs/case-schema.md, docs/rough.md).
    Rough(RoughArgs),
    /// The load distribution of a whole roller bearing (cylindrical, tapered, thrust) or ball
    /// bearing (deep groove, angular contact) under forces, moments or prescribed
    /// displacements: ring displacement and tilt, roller loads with the slices of the most
    /// loaded roller and the load zone, or ball loads with contact angles and Hertz
    /// pressures, 5 × 5 stiffness (TOML case, method = "bearing"; docs/case-schema.md,
    /// docs/bearing-model.md).
    Bearing(BearingArgs),
    #[command(about = friction_about())]
    Friction(FrictionArgs),
    /// Drive the contact element of one roller against the rib through a prescribed motion
    /// (load ramp, tilt and skew at constant load) with the Hertz, PimP and half-space
    /// back-ends: force, moment, contact-point migration, friction power, time per call
    /// (docs/mbs.md).
    Mbs(MbsArgs),
    /// Parameter sweep of a base case (any method with scalar results): a grid or zipped
    /// points of parameters given by their key paths, run in parallel, one row of scalars
    /// per case, resumable chunk files, combined into results.parquet or results.csv
    /// (schema: docs/sweep.md).
    Sweep(SweepArgs),
    /// Package the element of a case as an FMU (FMI 2.0, model exchange and co-simulation):
    /// a bearing case (method = "bearing") gives the bearing element, an element case
    /// (method = "element") the contact element (docs/fmi.md).
    Fmu(FmuArgs),
    /// Print the JSON Schema (draft 7) of the case files, derived from the case reader's
    /// types: every method's keys, their types, defaults and units; for validators and
    /// editors' completion (docs/case-schema.md, "JSON Schema").
    Schema,
    /// A local web calculator: an HTTP server on 127.0.0.1 with the calculator's pages and
    /// a JSON API over the case runner (the same validation, messages and JSON as `kontakt
    /// solve`); the first line printed is its URL (docs/serve.md).
    Serve(ServeArgs),
}

#[derive(Debug, Args)]
#[command(group(clap::ArgGroup::new("load").required(true).args(["force", "approach", "line_load"])))]
pub struct HertzArgs {
    /// Principal radii of body 1 [mm], "RX,RY": convex > 0, concave < 0, `inf` for flat
    /// (a line contact: one radius, "R").
    #[arg(
        long,
        value_name = "RX,RY",
        value_delimiter = ',',
        allow_hyphen_values = true,
        required = true
    )]
    pub body1_radii: Vec<f64>,
    /// Principal radii of body 2 [mm], "RX,RY": convex > 0, concave < 0, `inf` for flat
    /// (a line contact: one radius, "R").
    #[arg(
        long,
        value_name = "RX,RY",
        value_delimiter = ',',
        allow_hyphen_values = true,
        required = true
    )]
    pub body2_radii: Vec<f64>,
    /// Angle between the principal planes of the bodies [deg], finite.
    #[arg(
        long,
        value_name = "DEG",
        default_value_t = 0.0,
        allow_hyphen_values = true
    )]
    pub angle_deg: f64,
    /// Young's modulus of body 1 [MPa], > 0.
    #[arg(
        long,
        value_name = "MPA",
        default_value_t = 210_000.0,
        allow_hyphen_values = true
    )]
    pub e1: f64,
    /// Poisson's ratio of body 1, -1 < nu <= 0.5.
    #[arg(
        long,
        value_name = "NU",
        default_value_t = 0.3,
        allow_hyphen_values = true
    )]
    pub nu1: f64,
    /// Young's modulus of body 2 [MPa], > 0.
    #[arg(
        long,
        value_name = "MPA",
        default_value_t = 210_000.0,
        allow_hyphen_values = true
    )]
    pub e2: f64,
    /// Poisson's ratio of body 2, -1 < nu <= 0.5.
    #[arg(
        long,
        value_name = "NU",
        default_value_t = 0.3,
        allow_hyphen_values = true
    )]
    pub nu2: f64,
    /// Normal force [N], > 0 (or give --approach).
    #[arg(long, value_name = "N", allow_hyphen_values = true)]
    pub force: Option<f64>,
    /// Approach of distant points [mm], > 0 (or give --force).
    #[arg(long, value_name = "MM", allow_hyphen_values = true)]
    pub approach: Option<f64>,
    /// Line contact (parallel cylinders, one radius per body: --body1-radii R) of this
    /// length [mm], > 0; a case file's `[contact] kind = "line"`, `length_mm`.
    #[arg(long, value_name = "MM", allow_hyphen_values = true)]
    pub length: Option<f64>,
    /// Line contact loaded per unit length [N/mm], > 0 (instead of --force; --length then
    /// optional); a case file's `[load] line_load_n_per_mm`.
    #[arg(long, value_name = "N_PER_MM", allow_hyphen_values = true)]
    pub line_load: Option<f64>,
    /// Yield stress of the weaker body [MPa], > 0: reports the first-yield load.
    #[arg(long, value_name = "MPA", allow_hyphen_values = true)]
    pub yield_stress: Option<f64>,
    /// Yield criterion for --yield-stress.
    #[arg(long, value_enum, default_value_t = Criterion::VonMises)]
    pub criterion: Criterion,
    /// Print one JSON document instead of the table.
    #[arg(long)]
    pub json: bool,
}

#[derive(Debug, Clone, Copy, clap::ValueEnum)]
pub enum Criterion {
    VonMises,
    Tresca,
}

/// The case file that every case command reads, and its `--json` switch (one group,
/// flattened into each command's arguments).
#[derive(Debug, Args)]
pub struct CaseInput {
    /// Case file (TOML, of the method the command names; docs/case-schema.md), or `-` for
    /// standard input.
    #[arg(value_name = "CASE.toml")]
    pub case: PathBuf,
    /// Print one JSON document instead of the table or text.
    #[arg(long)]
    pub json: bool,
}

#[derive(Debug, Args)]
pub struct SolveArgs {
    /// PimP and BEM cases: write the fields to this CSV file (x_mm, y_mm, pressure_mpa;
    /// BEM adds displacement_mm and gap_mm).
    #[arg(long, value_name = "FILE.csv")]
    pub csv: Option<PathBuf>,
    /// PimP and BEM cases: draw the pressure map with the contact outline (.png or .svg).
    #[arg(long, value_name = "FILE.png|svg")]
    pub map: Option<PathBuf>,
    #[command(flatten)]
    pub input: CaseInput,
}

#[derive(Debug, Args)]
pub struct DemoArgs {
    /// Folder for the report (created if missing; files in it are overwritten).
    #[arg(long, value_name = "DIR", default_value = "kontakt-demo")]
    pub out: PathBuf,
    /// Print the results as JSON instead of the summary table.
    #[arg(long)]
    pub json: bool,
}

#[derive(Debug, Args)]
pub struct ValidateArgs {
    /// Folder for the report (created if missing; files in it are overwritten).
    #[arg(long, value_name = "DIR", default_value = "kontakt-validate")]
    pub out: PathBuf,
    /// Cells a side of the half-space grid, 12..=4096 (each contact spans at least 8).
    #[arg(long, value_name = "N", default_value_t = 64)]
    pub cells: usize,
    /// Print the results as JSON instead of the summary table.
    #[arg(long)]
    pub json: bool,
    /// Instead of the rib-contact study: the measured friction torque of whole bearings
    /// (validation/measured/) beside the SKF (2004) model at the same conditions and, where
    /// the internal geometry is known, the contact-based model with its breakdown (cone, cup,
    /// rib, drag) and a rib sensitivity study, as a table, CSVs, bearing_report.md and plots
    /// (torque in N·mm).
    #[arg(long, conflicts_with = "cells")]
    pub bearing: bool,
}

#[derive(Debug, Args)]
pub struct TractionArgs {
    /// Write every point to this CSV file (creepage, F_T/(mu F_N) per model).
    #[arg(long, value_name = "FILE.csv")]
    pub csv: Option<PathBuf>,
    /// Draw the traction curves (.png or .svg); Kalker linear up to saturation.
    #[arg(long, value_name = "FILE.png|svg")]
    pub plot: Option<PathBuf>,
    /// Draw kalker_exact's stick/slip map and traction magnitude at one creepage point
    /// (.png or .svg); needs "kalker_exact" in the case's models.
    #[arg(long, value_name = "FILE.png|svg")]
    pub map: Option<PathBuf>,
    /// Longitudinal creepage [-] of the --map point (default: the first curve point where
    /// kalker_exact reaches F_T/(mu F_N) = 0.5).
    #[arg(long, value_name = "XI", requires = "map", allow_hyphen_values = true)]
    pub map_creepage: Option<f64>,
    #[command(flatten)]
    pub input: CaseInput,
}

#[derive(Debug, Args)]
pub struct MindlinArgs {
    /// Write every point of the loading history to this CSV file (force_n, displacement_mm).
    #[arg(long, value_name = "FILE.csv")]
    pub csv: Option<PathBuf>,
    /// Draw the hysteresis loop, Q against the shift (.png or .svg).
    #[arg(long, value_name = "FILE.png|svg")]
    pub plot: Option<PathBuf>,
    #[command(flatten)]
    pub input: CaseInput,
}

#[derive(Debug, Args)]
pub struct BearingArgs {
    /// Write one row per roller to this CSV file (azimuth_deg, inner_load_n, outer_load_n,
    /// rib_load_n, max_load_per_length_n_per_mm, approach_mm), or one row per ball
    /// (azimuth_deg, load_n, contact_angle_deg, approach_mm, inner_max_pressure_mpa,
    /// outer_max_pressure_mpa).
    #[arg(long, value_name = "FILE.csv")]
    pub csv: Option<PathBuf>,
    /// Draw the load distribution as a polar diagram: every roller's or ball's load as a
    /// spoke at its azimuth, the radial load's direction and the loaded arc (.png or .svg).
    #[arg(long, value_name = "FILE.png|svg")]
    pub plot: Option<PathBuf>,
    /// Draw the load per length along the most loaded roller, slice by slice, with its mean
    /// (.png or .svg; roller bearings only).
    #[arg(long, value_name = "FILE.png|svg")]
    pub slice_plot: Option<PathBuf>,
    /// Draw every roller's or ball's load as a bar against its azimuth, with the rib load
    /// of a tapered roller bearing or the contact angle of a ball bearing below (.png or
    /// .svg).
    #[arg(long, value_name = "FILE.png|svg")]
    pub element_plot: Option<PathBuf>,
    /// Draw the load per length of every slice of every roller as a map: position along
    /// the roller × azimuth (.png or .svg; roller bearings only).
    #[arg(long, value_name = "FILE.png|svg")]
    pub map: Option<PathBuf>,
    #[command(flatten)]
    pub input: CaseInput,
}

#[derive(Debug, Args)]
pub struct ImpactArgs {
    #[command(flatten)]
    pub input: CaseInput,
}

#[derive(Debug, Args)]
pub struct RoughArgs {
    /// Write one row per load to this CSV file.
    #[arg(long, value_name = "FILE.csv")]
    pub csv: Option<PathBuf>,
    /// Draw the real contact area against the load, with Persson's theory (.png or .svg).
    #[arg(long, value_name = "FILE.png|svg")]
    pub plot: Option<PathBuf>,
    /// Draw the pressure at the highest load (.png or .svg).
    #[arg(long, value_name = "FILE.png|svg")]
    pub map: Option<PathBuf>,
    #[command(flatten)]
    pub input: CaseInput,
}

#[derive(Debug, Args)]
pub struct FrictionArgs {
    /// Write every row (model × speed) to this CSV file.
    #[arg(long, value_name = "FILE.csv")]
    pub csv: Option<PathBuf>,
    /// Draw the rib friction torque of the bearing against speed, per model (.png or .svg).
    #[arg(long, value_name = "FILE.png|svg")]
    pub plot: Option<PathBuf>,
    /// Draw the friction coefficient against speed (Stribeck curve), per model.
    #[arg(long, value_name = "FILE.png|svg")]
    pub stribeck: Option<PathBuf>,
    /// Draw the sliding velocity over the pressure map (first model, middle speed).
    #[arg(long, value_name = "FILE.png|svg")]
    pub map: Option<PathBuf>,
    /// Draw the friction-power density map (first model, middle speed).
    #[arg(long, value_name = "FILE.png|svg")]
    pub density: Option<PathBuf>,
    #[command(flatten)]
    pub input: CaseInput,
}

#[derive(Debug, Args)]
pub struct MbsArgs {
    /// Roller-end/rib pairing of Wirsching et al. (2020) Table 1.
    #[arg(long, default_value = "torus-torus-14")]
    pub pairing: String,
    /// Rib load during tilt and skew [N], > 0 (the load ramp runs from 0.2 to 1.6 times it).
    #[arg(
        long,
        value_name = "N",
        default_value_t = 250.0,
        allow_hyphen_values = true
    )]
    pub force: f64,
    /// Largest tilt and skew angle [deg], 0 < angle <= 2.
    #[arg(
        long,
        value_name = "DEG",
        default_value_t = 0.5,
        allow_hyphen_values = true
    )]
    pub angle_deg: f64,
    /// Inner-ring speed for the sliding velocities [r/min], 0..=100000.
    #[arg(
        long,
        value_name = "RPM",
        default_value_t = 1000.0,
        allow_hyphen_values = true
    )]
    pub rpm: f64,
    /// Samples per phase, 3..=1000.
    #[arg(long, value_name = "N", default_value_t = 21)]
    pub steps: usize,
    /// Back-ends, comma-separated: hertz, pimp, halfspace.
    #[arg(
        long,
        value_name = "LIST",
        value_delimiter = ',',
        default_value = "hertz,pimp,halfspace"
    )]
    pub backends: Vec<String>,
    /// Folder for mbs.csv and the plots (created if missing).
    #[arg(long, value_name = "DIR", default_value = "kontakt-mbs")]
    pub out: std::path::PathBuf,
    /// Print every sample as JSON instead of the summary table.
    #[arg(long)]
    pub json: bool,
}

#[derive(Debug, Clone, Copy, clap::ValueEnum)]
pub enum SweepFormat {
    Parquet,
    Csv,
}

#[derive(Debug, Clone, Copy, clap::ValueEnum)]
pub enum SweepFields {
    None,
    Npy,
}

#[derive(Debug, Args)]
pub struct SweepArgs {
    /// Sweep file (TOML; docs/sweep.md).
    #[arg(value_name = "SWEEP.toml")]
    pub sweep: PathBuf,
    /// Output folder: sweep.json, chunks/, results.parquet|csv. A rerun into the same
    /// folder computes only the missing chunks; a folder holding another sweep is refused.
    #[arg(long, value_name = "DIR", default_value = "kontakt-sweep")]
    pub out: PathBuf,
    /// Format of the combined results (the chunks are always Parquet).
    #[arg(long, value_enum, default_value_t = SweepFormat::Parquet)]
    pub format: SweepFormat,
    /// Worker threads, 1..=256 (default: the available cores).
    #[arg(long, value_name = "N")]
    pub threads: Option<usize>,
    /// Raise (or lower) the sweep file's limit on the number of cases (default 10000000).
    #[arg(long, value_name = "N")]
    pub max_cases: Option<u64>,
    /// Also store every case's fields (pimp: pressure; bem: pressure, displacement and
    /// gap) as .npy files in DIR/fields/ (default: the sweep file's
    /// `fields`, else none). Part of the sweep's identity: a folder is resumed only with
    /// the same choice.
    #[arg(long, value_enum, value_name = "none|npy")]
    pub fields: Option<SweepFields>,
    /// No progress bar.
    #[arg(long)]
    pub quiet: bool,
    /// Print a JSON summary instead of the text one (no progress bar).
    #[arg(long)]
    pub json: bool,
}

#[derive(Debug, Args)]
pub struct FmuArgs {
    /// The case: a bearing case (method = "bearing") or an element case (method = "element").
    pub case: PathBuf,
    /// The FMU file to write.
    #[arg(short = 'o', long, value_name = "FILE")]
    pub out: PathBuf,
    /// The FMU's binary, the shared library of crates/kontakt-fmi (libkontakt_fmi.so on
    /// Linux). Default: $KONTAKT_FMI_LIBRARY, else the one next to this executable (in
    /// its folder or its deps/ folder, as `cargo build` and `cargo test` leave it).
    #[arg(long, value_name = "FILE")]
    pub library: Option<PathBuf>,
}

#[derive(Debug, Args)]
pub struct ServeArgs {
    /// The port, 1..=65535; 0 picks a free one (the URL printed says which).
    #[arg(long, value_name = "N", default_value_t = 8080)]
    pub port: u16,
    /// Open the calculator in the desktop's browser (a failure to open is a warning).
    #[arg(long)]
    pub open: bool,
    /// The address to listen on. Default 127.0.0.1 (this machine only); another address
    /// (e.g. 0.0.0.0) lets other machines run solves on this one, and is warned about.
    #[arg(long, value_name = "ADDR", default_value = "127.0.0.1")]
    pub address: std::net::IpAddr,
    /// Longest solve of POST /api/run [s], 0.1..=86400; a longer one is stopped (its
    /// worker process killed) and answered 408. Jobs get ten times as long.
    #[arg(long, value_name = "S", default_value_t = 60.0)]
    pub time_limit: f64,
    /// Concurrent solves (worker processes), 1..=256; default: the number of cores (at
    /// least 2).
    #[arg(long, value_name = "N")]
    pub workers: Option<usize>,
    /// Internal: run as a worker process of a server (cases on standard input).
    #[arg(long, hide = true)]
    pub worker: bool,
}
