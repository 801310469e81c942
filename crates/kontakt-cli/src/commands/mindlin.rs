//! `kontakt mindlin CASE.toml`: Cattaneo-Mindlin partial slip of a Hertz contact under an
//! oscillating tangential force (a `method = "mindlin"` case): the stick zone and shift at
//! the amplitude, the energy dissipated per cycle and the Mindlin-Deresiewicz hysteresis
//! loop, as a table, JSON, CSV and a plot. The physics is `kontakt_case::run_mindlin_case`.

use crate::cli::MindlinArgs;
use anyhow::{Context, Result};
use kontakt_case::{MindlinCase, MindlinReport, run_mindlin_case};
use kontakt_plot::{LinePlot, LineStyle, PALETTE, Series};
use std::io::Write;
use std::path::Path;

/// Run the subcommand.
pub fn run(args: &MindlinArgs, out: &mut impl Write) -> Result<()> {
    let (label, text) = args.input.read("mindlin")?;
    let case = MindlinCase::from_toml_str(&text).with_context(|| label.clone())?;
    let report = run_mindlin_case(&case).with_context(|| label.clone())?;
    if let Some(path) = &args.csv {
        write_csv(path, &report)?;
    }
    if let Some(path) = &args.plot {
        write_plot(path, &report)?;
    }
    print_report(out, &report, args.input.json)
}

/// The report as text or as pretty JSON.
pub fn print_report(out: &mut impl Write, r: &MindlinReport, json: bool) -> Result<()> {
    if json {
        return crate::output::print_json(out, r);
    }
    let name = crate::output::name_suffix(r.name.as_deref());
    writeln!(
        out,
        "kontakt {} — Cattaneo-Mindlin partial slip{name}",
        r.kontakt_version
    )?;
    let n = crate::output::Num;
    let [a, b] = r.semi_axes_mm.map(n);
    writeln!(
        out,
        "  contact ({}): a = {a:.5} mm, b = {b:.5} mm, p0 = {:.1} MPa, F_N = {} N, mu = {}",
        r.geometry,
        n(r.max_pressure_mpa),
        n(r.force_n),
        n(r.mu)
    )?;
    writeln!(
        out,
        "  tangential force Q* = {} N at {} deg from a: Q*/(mu F_N) = {:.4} (slides at {:.4} N)",
        n(r.amplitude_n),
        n(r.load_angle_deg),
        n(r.load_fraction),
        n(r.limit_force_n)
    )?;
    let [sa, sb] = r.stick_semi_axes_mm.map(n);
    writeln!(
        out,
        "  stick zone: a' = {sa:.5} mm, b' = {sb:.5} mm (c/a = {:.4})",
        n(r.stick_ratio)
    )?;
    writeln!(
        out,
        "  shift at Q*: {:.6e} mm; at sliding: {:.6e} mm; initial stiffness {:.5e} N/mm",
        r.displacement_at_amplitude_mm, r.slip_displacement_mm, r.tangential_stiffness_n_per_mm
    )?;
    writeln!(
        out,
        "  energy dissipated per cycle: {:.6e} N mm (closed form), {:.6e} N mm (loop area)",
        r.dissipated_energy_per_cycle_nmm, r.loop_energy_nmm
    )?;
    crate::output::print_warnings(out, &r.warnings)
}

/// Every point of the loading history: `force_n`, `displacement_mm`.
pub fn write_csv(path: &Path, r: &MindlinReport) -> Result<()> {
    let mut w = crate::commands::CsvFile::create(path)?;
    w.record(["force_n", "displacement_mm"])?;
    for (q, d) in r.loop_force_n.iter().zip(&r.loop_displacement_mm) {
        w.record([format!("{q:.8e}"), format!("{d:.8e}")])?;
    }
    w.finish()?;
    Ok(())
}

/// The hysteresis loop: Q against the shift, in µm.
pub fn write_plot(path: &Path, r: &MindlinReport) -> Result<()> {
    kontakt_plot::Format::from_path(path)
        .map_err(|e| crate::commands::InputError(e.to_string()))?;
    let points: Vec<(f64, f64)> = r
        .loop_displacement_mm
        .iter()
        .zip(&r.loop_force_n)
        .map(|(d, q)| (1e3 * d, *q))
        .collect();
    let label = format!("Q* = {} N", r.amplitude_n);
    let series = [Series {
        label: &label,
        points: &points,
        color: PALETTE[0],
        style: LineStyle::Solid,
    }];
    let title = format!(
        "{}: Fₙ = {} N, μ = {}, {:.3e} N·mm per cycle",
        r.name.as_deref().unwrap_or("Mindlin-Deresiewicz loop"),
        r.force_n,
        r.mu,
        r.dissipated_energy_per_cycle_nmm
    );
    kontakt_plot::line_plot(
        path,
        &LinePlot {
            title: &title,
            x_label: "tangential displacement δ [µm]",
            y_label: "tangential force Q [N]",
            series: &series,
            x_log: false,
            y_from_zero: false,
        },
        (900, 600),
    )
    .with_context(|| format!("drawing {}", path.display()))
}
