//! `kontakt rough CASE.toml`: a periodic rough surface pressed against a flat at several
//! nominal pressures (a `method = "rough"` case): the real contact area, κ, Persson's
//! area, patches and the mean gap per load, as a table, JSON, CSV, an area-load plot and a
//! pressure map at the highest load. The physics is `kontakt_case::run_rough_case`.

use crate::cli::RoughArgs;
use crate::render::{MapNotes, write_map};
use anyhow::{Context, Result};
use kontakt_case::rough_case::{RoughCase, RoughReport, run_rough_case};
use kontakt_plot::{LinePlot, LineStyle, PALETTE, Series};
use std::io::Write;
use std::path::Path;

/// Run the subcommand.
pub fn run(args: &RoughArgs, out: &mut impl Write) -> Result<()> {
    let (label, text) = args.input.read("rough")?;
    let case = RoughCase::from_toml_str(&text).with_context(|| label.clone())?;
    let base = args.input.base_dir();
    let outcome = run_rough_case(&case, base).with_context(|| label.clone())?;
    let r = &outcome.report;
    if let Some(path) = &args.csv {
        write_csv(path, r)?;
    }
    if let Some(path) = &args.plot {
        write_plot(path, r)?;
    }
    if let Some(path) = &args.map {
        let last = r.rows.last().map_or(0.0, |row| row.mean_pressure_mpa);
        let title = format!(
            "{}: mean pressure {last} MPa, A/A0 = {:.2} %",
            r.name.as_deref().unwrap_or("rough contact"),
            100.0 * r.rows.last().map_or(0.0, |row| row.area_fraction)
        );
        let notes = MapNotes::plain();
        write_map(path, &outcome.grid, &outcome.pressure, &title, &[], &notes)?;
    }
    print_report(out, r, args.input.json)
}

/// The report as a table or as pretty JSON.
pub fn print_report(out: &mut impl Write, r: &RoughReport, json: bool) -> Result<()> {
    if json {
        return crate::output::print_json(out, r);
    }
    let name = crate::output::name_suffix(r.name.as_deref());
    writeln!(out, "kontakt {} — rough contact{name}", r.kontakt_version)?;
    writeln!(
        out,
        "  surface ({}): {} x {} cells of {:.4e} x {:.4e} mm, rms height {:.4e} mm, rms slope {:.4}; E* = {:.1} MPa",
        r.surface,
        r.points[0],
        r.points[1],
        r.spacing_mm[0],
        r.spacing_mm[1],
        r.rms_height_mm,
        crate::output::Num(r.rms_slope),
        crate::output::Num(r.e_star_mpa)
    )?;
    writeln!(
        out,
        "  {:>12} {:>12} {:>10} {:>8} {:>10} {:>12} {:>8} {:>12} {:>6}",
        "p [MPa]",
        "p/(E* h')",
        "A/A0",
        "kappa",
        "Persson",
        "p_max [MPa]",
        "patches",
        "gap [mm]",
        "iter"
    )?;
    let num = crate::output::Num;
    for row in &r.rows {
        writeln!(
            out,
            "  {:>12.4} {:>12.5} {:>10.5} {:>8.4} {:>10.5} {:>12.1} {:>8} {:>12.4e} {:>6}",
            num(row.mean_pressure_mpa),
            num(row.reduced_pressure),
            num(row.area_fraction),
            num(row.kappa),
            num(row.persson_area_fraction),
            num(row.max_pressure_mpa),
            row.patches,
            row.mean_gap_mm,
            row.iterations
        )?;
    }
    writeln!(
        out,
        "  kappa = (A/A0)/(p/(E* h')): about 2 for numerical solvers (Hyun et al. 2004), sqrt(8/pi) = 1.60 in Persson's theory"
    )?;
    for w in &r.warnings {
        writeln!(out, "  warning: {w}")?;
    }
    Ok(())
}

/// One line per load.
pub fn write_csv(path: &Path, r: &RoughReport) -> Result<()> {
    let mut w = crate::commands::CsvFile::create(path)?;
    for row in &r.rows {
        w.serialize(row)?;
    }
    w.finish()?;
    Ok(())
}

/// A/A0 against p/(E* h'): the solver's points and Persson's curve.
pub fn write_plot(path: &Path, r: &RoughReport) -> Result<()> {
    kontakt_plot::Format::from_path(path)
        .map_err(|e| crate::commands::InputError(e.to_string()))?;
    let ours: Vec<(f64, f64)> = r
        .rows
        .iter()
        .map(|row| (row.reduced_pressure, row.area_fraction))
        .collect();
    let top = ours.last().map_or(0.0, |p| p.0);
    let persson: Vec<(f64, f64)> = (0..=100)
        .map(|i| {
            let x = top * i as f64 / 100.0;
            (x, kontakt::rough::persson_area_fraction(x, 1.0, 1.0))
        })
        .collect();
    let kappa2: Vec<(f64, f64)> = vec![(0.0, 0.0), (top, 2.0 * top)];
    let series = [
        Series {
            label: "half-space solver",
            points: &ours,
            color: PALETTE[0],
            style: LineStyle::Markers,
        },
        Series {
            label: "Persson (erf)",
            points: &persson,
            color: PALETTE[1],
            style: LineStyle::Solid,
        },
        Series {
            label: "κ = 2",
            points: &kappa2,
            color: PALETTE[2],
            style: LineStyle::Dashed,
        },
    ];
    let title = format!(
        "{}: real contact area",
        r.name.as_deref().unwrap_or("rough contact")
    );
    kontakt_plot::line_plot(
        path,
        &LinePlot {
            title: &title,
            x_label: "mean pressure / (E* h'rms) [-]",
            y_label: "A / A0 [-]",
            series: &series,
            x_log: false,
            y_from_zero: false,
        },
        (900, 600),
    )
    .with_context(|| format!("drawing {}", path.display()))
}
