//! `kontakt bearing CASE.toml`: the load distribution of a whole roller bearing (a
//! `method = "bearing"` case): ring displacement and tilt, the load of every roller, the
//! slices of the most loaded one and the 5 × 5 stiffness matrix, as a table, JSON and a
//! per-roller CSV, and plots of the load distribution and of the most loaded roller. The physics is `kontakt_case::run_bearing_case`.

use crate::cli::BearingArgs;
use crate::output::Num;
use anyhow::{Context, Result};
use kontakt_case::{BearingCase, BearingReport, run_bearing_case};
use kontakt_plot::{LinePlot, LineStyle, PALETTE, Series};
use std::io::Write;
use std::path::Path;

/// Run the subcommand.
pub fn run(args: &BearingArgs, out: &mut impl Write) -> Result<()> {
    let (label, text) = args.input.read("bearing")?;
    let case = BearingCase::from_toml_str(&text).with_context(|| label.clone())?;
    let report = run_bearing_case(&case).with_context(|| label.clone())?;
    if let Some(path) = &args.csv {
        write_csv(path, &report)?;
    }
    if let Some(path) = &args.plot {
        write_load_plot(path, &report)?;
    }
    if let Some(path) = &args.slice_plot {
        write_slice_plot(path, &report)?;
    }
    print_report(out, &report, args.input.json)
}

/// The report as text or as pretty JSON.
pub fn print_report(out: &mut impl Write, r: &BearingReport, json: bool) -> Result<()> {
    if json {
        return crate::output::print_json(out, r);
    }
    let name = crate::output::name_suffix(r.name.as_deref());
    writeln!(
        out,
        "kontakt {} — {} roller bearing{name}",
        r.kontakt_version, r.bearing_type
    )?;
    let angles = if r.bearing_type == "tapered" {
        format!(
            ", cup {:.2} deg, cone {:.2} deg",
            Num(r.contact_angle_deg),
            Num(r.cone_angle_deg)
        )
    } else {
        String::new()
    };
    writeln!(
        out,
        "  {} rollers × {} slices{angles} (ISO/TS 16281 slice law)",
        r.rollers, r.slices
    )?;
    let f = r.force_n.iter().chain(&r.moment_nmm);
    let scale = f.fold(0.0, |m: f64, x| m.max(x.abs()));
    let [fx, fy, fz] = r.force_n.map(|x| clean(x, scale));
    let [mx, my] = r.moment_nmm.map(|x| clean(x, scale));
    writeln!(
        out,
        "  load carried: F = [{fx:.1}, {fy:.1}, {fz:.1}] N, M = [{mx:.1}, {my:.1}] N mm"
    )?;
    let u = r.displacement_mm.iter().chain(&r.tilt_rad);
    let scale = u.fold(0.0, |m: f64, x| m.max(x.abs()));
    let [dx, dy, dz] = r.displacement_mm.map(|x| clean(x, scale));
    let [tx, ty] = r.tilt_rad.map(|x| clean(x, scale));
    writeln!(
        out,
        "  inner ring:   δ = [{dx:.6}, {dy:.6}, {dz:.6}] mm, θ = [{tx:.6}, {ty:.6}] rad"
    )?;
    let s = &r.solver;
    writeln!(
        out,
        "  solver:       {} after {} iterations (residual {:.1e})",
        s.termination, s.iterations, s.residual
    )?;
    let eps = r
        .load_zone_epsilon
        .map_or_else(|| "-".to_string(), |e| format!("{:.4}", Num(e)));
    writeln!(
        out,
        "  load zone ε = {eps}; largest roller load {:.1} N, largest load per length {:.1} N/mm",
        Num(r.max_roller_load_n),
        Num(r.max_load_per_length_n_per_mm)
    )?;
    writeln!(out)?;
    writeln!(
        out,
        "  {:>6} {:>10} {:>10} {:>10} {:>10} {:>12}",
        "ψ deg", "Q_in N", "Q_out N", "Q_rib N", "q_max N/mm", "approach mm"
    )?;
    for row in &r.roller_loads {
        writeln!(
            out,
            "  {:>6.1} {:>10.1} {:>10.1} {:>10.1} {:>10.1} {:>12.6}",
            Num(row.azimuth_deg),
            Num(row.inner_load_n),
            Num(row.outer_load_n),
            Num(row.rib_load_n),
            Num(row.max_load_per_length_n_per_mm),
            Num(row.approach_mm)
        )?;
    }
    writeln!(out)?;
    writeln!(
        out,
        "  stiffness matrix (rows F_x F_y F_z M_x M_y; columns x y z θx θy;"
    )?;
    writeln!(out, "  N/mm, N/rad; N, N mm/rad):")?;
    let scale = r
        .stiffness_matrix
        .iter()
        .flatten()
        .fold(0.0, |m: f64, x| m.max(x.abs()));
    for row in &r.stiffness_matrix {
        let cells: Vec<String> = row
            .iter()
            .map(|&k| format!("{:>12.4e}", clean(k, scale).0))
            .collect();
        writeln!(out, "  {}", cells.join(" "))?;
    }
    crate::output::print_warnings(out, &r.warnings)
}

/// `x` for the table, with round-off below 1e-9 of the group's largest magnitude `scale`
/// shown as 0 (a 1e-13 N reaction of a symmetric load); the JSON keeps the raw numbers.
fn clean(x: f64, scale: f64) -> Num {
    Num(if x.abs() < 1e-9 * scale { 0.0 } else { x })
}

/// One row per roller: the report's `roller_loads` keys.
pub fn write_csv(path: &Path, r: &BearingReport) -> Result<()> {
    let mut w = crate::commands::CsvFile::create(path)?;
    for row in &r.roller_loads {
        w.serialize(row)?;
    }
    w.finish()
}

/// A line plot of `series` into `path` (checked format, the error names the file).
fn draw(path: &Path, title: &str, axes: [&str; 2], series: &[Series]) -> Result<()> {
    kontakt_plot::Format::from_path(path)
        .map_err(|e| crate::commands::InputError(e.to_string()))?;
    kontakt_plot::line_plot(
        path,
        &LinePlot {
            title,
            x_label: axes[0],
            y_label: axes[1],
            series,
            x_log: false,
            y_from_zero: true,
        },
        (900, 600),
    )
    .with_context(|| format!("drawing {}", path.display()))
}

/// The load distribution: every roller's raceway load (and rib load) against its azimuth.
pub fn write_load_plot(path: &Path, r: &BearingReport) -> Result<()> {
    let mut rows: Vec<_> = r.roller_loads.iter().collect();
    rows.sort_by(|a, b| a.azimuth_deg.total_cmp(&b.azimuth_deg));
    let outer: Vec<(f64, f64)> = rows
        .iter()
        .map(|w| (w.azimuth_deg, w.outer_load_n))
        .collect();
    let rib: Vec<(f64, f64)> = rows.iter().map(|w| (w.azimuth_deg, w.rib_load_n)).collect();
    let mut series = vec![Series {
        label: "outer raceway load",
        points: &outer,
        color: PALETTE[0],
        style: LineStyle::Markers,
    }];
    if r.bearing_type == "tapered" {
        series.push(Series {
            label: "rib load",
            points: &rib,
            color: PALETTE[1],
            style: LineStyle::Markers,
        });
    }
    let eps = r
        .load_zone_epsilon
        .map_or_else(String::new, |e| format!(", ε = {e:.3}"));
    let title = format!(
        "{}: {} rollers{eps}",
        r.name.as_deref().unwrap_or("roller loads"),
        r.rollers
    );
    draw(
        path,
        &title,
        ["azimuth ψ [deg]", "roller load [N]"],
        &series,
    )
}

/// The load per unit length along the most loaded roller, slice by slice.
pub fn write_slice_plot(path: &Path, r: &BearingReport) -> Result<()> {
    let m = &r.most_loaded_roller;
    let points: Vec<(f64, f64)> = m
        .position_mm
        .iter()
        .zip(&m.load_per_length_n_per_mm)
        .map(|(x, q)| (*x, *q))
        .collect();
    let series = [Series {
        label: "",
        points: &points,
        color: PALETTE[0],
        style: LineStyle::Solid,
    }];
    let title = format!(
        "{}: roller {} at ψ = {:.1}°, Q = {:.0} N",
        r.name.as_deref().unwrap_or("most loaded roller"),
        m.roller,
        r.roller_loads[m.roller].azimuth_deg,
        r.max_roller_load_n
    );
    draw(
        path,
        &title,
        ["position along the roller [mm]", "load per length [N/mm]"],
        &series,
    )
}
