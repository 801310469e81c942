//! `kontakt traction CASE.toml`: traction curves `F_T/(mu F_N)` against the creepage
//! (slide-to-roll ratio) for the models of a `method = "traction"` case, as a table,
//! JSON, CSV and a plot. The physics is `kontakt_case::run_traction_case`.

use crate::cli::TractionArgs;
use crate::commands::InputError;
use anyhow::{Context, Result};
use kontakt_case::{ExactMap, MapPoint, TractionCase, TractionReport, run_traction_case_with_map};
use kontakt_plot::{Ellipse, FieldMap, LinePlot, LineStyle, Overlay, PALETTE, Series};
use std::io::Write;
use std::path::Path;

/// Most rows of the human table; `--csv` has every point.
const MAX_ROWS: usize = 21;

/// Run the subcommand.
pub fn run(args: &TractionArgs, out: &mut impl Write) -> Result<()> {
    let (label, text) = args.input.read("traction")?;
    let case = TractionCase::from_toml_str(&text).with_context(|| label.clone())?;
    let map = args
        .map
        .as_ref()
        .map(|_| args.map_creepage.map_or(MapPoint::Auto, MapPoint::Creepage));
    let (report, field) = run_traction_case_with_map(&case, map).with_context(|| label.clone())?;
    if let (Some(path), Some(field)) = (&args.map, &field) {
        write_map(path, field)?;
    }
    if let Some(path) = &args.csv {
        write_csv(path, &report)?;
    }
    if let Some(path) = &args.plot {
        write_plot(path, &report)?;
    }
    print_report(out, &report, args.input.json)
}

/// The report as a table (a subsample of the points) or as pretty JSON.
pub fn print_report(out: &mut impl Write, r: &TractionReport, json: bool) -> Result<()> {
    if json {
        return crate::output::print_json(out, r);
    }
    let name = crate::output::name_suffix(r.name.as_deref());
    writeln!(
        out,
        "kontakt {} — traction curves F_T/(mu F_N){name}",
        r.kontakt_version
    )?;
    let num = crate::output::Num;
    let [a, b] = r.semi_axes_mm.map(num);
    let axes = if r.geometry == "line" {
        format!("half-width a = {a:.5} mm, half-length {b:.4} mm")
    } else {
        format!("a = {a:.5} mm (rolling), b = {b:.5} mm")
    };
    writeln!(out, "  contact ({}): {axes}", r.geometry)?;
    let load = match r.line_load_n_per_mm {
        Some(q) => format!("F_N = {} N ({:.4} N/mm)", num(r.force_n), num(q)),
        None => format!("F_N = {} N", num(r.force_n)),
    };
    writeln!(
        out,
        "  {load}, p0 = {:.1} MPa, mu = {}",
        num(r.max_pressure_mpa),
        num(r.mu)
    )?;
    writeln!(
        out,
        "  E* = {:.1} MPa, Kalker G = {:.1} MPa, nu = {:.4}",
        num(r.e_star_mpa),
        num(r.shear_modulus_mpa),
        num(r.poisson_ratio)
    )?;
    if r.difference_parameter != 0.0 {
        writeln!(
            out,
            "  Kalker's difference parameter K = {:.4e} (dissimilar materials)",
            r.difference_parameter
        )?;
    }
    if let Some(c) = &r.creep_coefficients {
        writeln!(
            out,
            "  Kalker C11 = {:.4}, C22 = {:.4}, C23 = {:.4}",
            num(c.c11),
            num(c.c22),
            num(c.c23)
        )?;
    }
    let mut sat = format!(
        "  saturation creepage: Carter {:.4e}",
        r.carter_saturation_creepage
    );
    if let Some(k) = r.kalker_saturation_creepage {
        sat.push_str(&format!(", Kalker linear reaches 1 at {k:.4e}"));
    }
    writeln!(out, "{sat}")?;
    if let Some([nx, ny]) = r.fastsim_elements {
        writeln!(out, "  FASTSIM grid {nx} x {ny} elements")?;
    }
    for c in &r.curves {
        if let Some(x) = &c.exact {
            let state = if x.converged {
                format!("converged at all {} points", x.status.len())
            } else {
                format!(
                    "NOT converged at {} of {} points (marked *)",
                    x.not_converged.len(),
                    x.status.len()
                )
            };
            writeln!(
                out,
                "  Kalker exact grid {} x {} cells across the contact; {state}",
                x.elements[0], x.elements[1]
            )?;
            if x.coupling {
                let free = x
                    .free_rolling_creepage
                    .map_or_else(|| "-".to_string(), |f| format!("{f:.4e}"));
                writeln!(
                    out,
                    "  Kalker exact coupled through K = {:.4e}: free-rolling creepage {free}",
                    r.difference_parameter
                )?;
            }
        }
    }
    write!(out, "  {:>12}", "creepage")?;
    for c in &r.curves {
        write!(out, " {:>14}", c.model)?;
    }
    writeln!(out)?;
    let n = r.creepage.len();
    let step = n.div_ceil(MAX_ROWS).max(1);
    let rows = (0..n)
        .step_by(step)
        .chain((!(n - 1).is_multiple_of(step)).then_some(n - 1));
    for i in rows {
        write!(out, "  {:>12.6}", num(r.creepage[i]))?;
        for c in &r.curves {
            let bad = c
                .exact
                .as_ref()
                .is_some_and(|x| x.not_converged.contains(&i));
            if bad {
                write!(out, " {:>13.5}*", num(c.normalized_force[i]))?;
            } else {
                write!(out, " {:>14.5}", num(c.normalized_force[i]))?;
            }
        }
        writeln!(out)?;
    }
    if step > 1 {
        writeln!(
            out,
            "  (every {} of {n} points; --csv writes all; Kalker linear is unclipped)",
            ordinal(step)
        )?;
    }
    print_forces(out, r, step)?;
    for w in &r.warnings {
        writeln!(out, "  warning: {w}")?;
    }
    Ok(())
}

/// `2nd`, `3rd`, `5th`, `11th`, `21st`, ...
fn ordinal(n: usize) -> String {
    let suffix = match (n % 10, n % 100) {
        (_, 11..=13) => "th",
        (1, _) => "st",
        (2, _) => "nd",
        (3, _) => "rd",
        _ => "th",
    };
    format!("{n}{suffix}")
}

/// With lateral or spin creepage: the creep forces and the spin moment of each model that
/// computes them, at the same points as the curve table.
fn print_forces(out: &mut impl Write, r: &TractionReport, step: usize) -> Result<()> {
    let num = crate::output::Num;
    let with: Vec<_> = r
        .curves
        .iter()
        .filter_map(|c| c.forces.as_ref().map(|f| (c.model, f)))
        .collect();
    if with.is_empty() {
        return Ok(());
    }
    writeln!(
        out,
        "  creep forces on body 1 at lateral creepage {} and spin {} 1/mm (Fx, Fy in N, Mz in N mm)",
        num(r.lateral_creepage.unwrap_or(0.0)),
        num(r.spin_creepage_per_mm.unwrap_or(0.0))
    )?;
    write!(out, "  {:>12}", "creepage")?;
    for (model, f) in &with {
        write!(out, " {:>14} {:>14}", format!("{model} Fx"), "Fy")?;
        if f.spin_moment_nmm.is_some() {
            write!(out, " {:>14}", "Mz")?;
        }
    }
    writeln!(out)?;
    let n = r.creepage.len();
    let rows = (0..n)
        .step_by(step)
        .chain((!(n - 1).is_multiple_of(step)).then_some(n - 1));
    for i in rows {
        write!(out, "  {:>12.6}", num(r.creepage[i]))?;
        for (_, f) in &with {
            write!(
                out,
                " {:>14.5} {:>14.5}",
                num(f.longitudinal_force_n[i]),
                num(f.lateral_force_n[i])
            )?;
            if let Some(m) = &f.spin_moment_nmm {
                write!(out, " {:>14.5}", m[i])?;
            }
        }
        writeln!(out)?;
    }
    Ok(())
}

/// Every point: `creepage` and one column `<model>_ft_over_mu_fn` per model.
pub fn write_csv(path: &Path, r: &TractionReport) -> Result<()> {
    let mut w = crate::commands::CsvFile::create(path)?;
    let mut header = vec!["creepage".to_string()];
    header.extend(
        r.curves
            .iter()
            .map(|c| format!("{}_ft_over_mu_fn", c.model)),
    );
    // With lateral or spin creepage: the forces and moment of the models that give them.
    for c in &r.curves {
        if let Some(f) = &c.forces {
            header.push(format!("{}_fx_n", c.model));
            header.push(format!("{}_fy_n", c.model));
            if f.spin_moment_nmm.is_some() {
                header.push(format!("{}_mz_nmm", c.model));
            }
        }
    }
    w.record(&header)?;
    for (i, xi) in r.creepage.iter().enumerate() {
        let mut row = vec![format!("{xi:.8e}")];
        row.extend(
            r.curves
                .iter()
                .map(|c| format!("{:.8e}", c.normalized_force[i])),
        );
        for f in r.curves.iter().filter_map(|c| c.forces.as_ref()) {
            row.push(format!("{:.8e}", f.longitudinal_force_n[i]));
            row.push(format!("{:.8e}", f.lateral_force_n[i]));
            if let Some(m) = &f.spin_moment_nmm {
                row.push(format!("{:.8e}", m[i]));
            }
        }
        w.record(&row)?;
    }
    w.finish()?;
    Ok(())
}

/// The points of a curve with `|y| <= 1`, plus the crossings of `|y| = 1` between
/// neighbours: how the unbounded linear theory is drawn next to the saturating models.
fn clip_to_saturation(xs: &[f64], ys: &[f64]) -> Vec<(f64, f64)> {
    let mut pts = Vec::with_capacity(xs.len());
    for i in 0..xs.len() {
        let (x, y) = (xs[i], ys[i]);
        if i > 0 {
            let (x0, y0) = (xs[i - 1], ys[i - 1]);
            for bound in [-1.0, 1.0] {
                if (y0 - bound) * (y - bound) < 0.0 {
                    let t = (bound - y0) / (y - y0);
                    pts.push((x0 + t * (x - x0), bound));
                }
            }
        }
        if y.abs() <= 1.0 {
            pts.push((x, y));
        }
    }
    pts
}

/// Draw kalker_exact's traction magnitude at one point with its stick area outlined
/// over the Hertz ellipse.
pub fn write_map(path: &Path, m: &ExactMap) -> Result<()> {
    kontakt_plot::Format::from_path(path).map_err(|e| InputError(e.to_string()))?;
    let [xi, eta, phi] = m.creepage;
    let mut title = format!(
        "Kalker exact: xi = {xi:.4e}, F_T/(mu F_N) = {:.4}, stick {:.0} %",
        m.normalized_force,
        100.0 * m.stick_fraction
    );
    if eta != 0.0 || phi != 0.0 {
        title.push_str(&format!(", eta = {eta:.3e}, phi = {phi:.3e}/mm"));
    }
    if !m.status.converged() {
        title.push_str(" (NOT converged)");
    }
    let overlays = [Overlay {
        label: "stick (adhesion) area; slip elsewhere",
        values: &m.stick,
        color: (214, 39, 40),
    }];
    kontakt_plot::field_map(
        path,
        &FieldMap {
            nx: m.cells[0],
            ny: m.cells[1],
            x_min: m.origin_mm[0],
            y_min: m.origin_mm[1],
            dx: m.cell_mm[0],
            dy: m.cell_mm[1],
            values: &m.traction_mpa,
            title: &title,
            x_label: "x [mm] (rolling direction, leading edge at +x)",
            y_label: "y [mm]",
            colorbar_label: "|traction| [MPa]",
            outline: true,
            overlays: &overlays,
            ellipse: Some(Ellipse {
                label: "Hertz contact ellipse",
                centre: (0.0, 0.0),
                semi_axes: (m.semi_axes_mm[0], m.semi_axes_mm[1]),
                angle: 0.0,
                color: (80, 80, 80),
            }),
            max_marker: None,
            color_max: None,
            stretch: None,
        },
        (900, 700),
    )
    .with_context(|| format!("drawing {}", path.display()))
}

/// Draw the curves; Kalker's linear theory up to where it reaches saturation.
pub fn write_plot(path: &Path, r: &TractionReport) -> Result<()> {
    kontakt_plot::Format::from_path(path).map_err(|e| InputError(e.to_string()))?;
    let labels: Vec<String> = r
        .curves
        .iter()
        .map(|c| match c.model {
            "carter" => "Carter".to_string(),
            "kalker_linear" => "Kalker linear (to saturation)".to_string(),
            "fastsim" => "FASTSIM".to_string(),
            "kalker_exact" => "Kalker exact".to_string(),
            other => other.to_string(),
        })
        .collect();
    let points: Vec<Vec<(f64, f64)>> = r
        .curves
        .iter()
        .map(|c| {
            if c.model == "kalker_linear" {
                clip_to_saturation(&r.creepage, &c.normalized_force)
            } else if let Some(x) = &c.exact {
                // Unconverged points are not results: leave them out of the plot.
                r.creepage
                    .iter()
                    .copied()
                    .zip(c.normalized_force.iter().copied())
                    .enumerate()
                    .filter(|(i, _)| !x.not_converged.contains(i))
                    .map(|(_, p)| p)
                    .collect()
            } else {
                r.creepage
                    .iter()
                    .copied()
                    .zip(c.normalized_force.iter().copied())
                    .collect()
            }
        })
        .collect();
    let series: Vec<Series> = r
        .curves
        .iter()
        .enumerate()
        .filter(|(i, _)| !points[*i].is_empty())
        .map(|(i, c)| Series {
            label: &labels[i],
            points: &points[i],
            color: PALETTE[i % PALETTE.len()],
            style: if c.model == "kalker_linear" {
                LineStyle::Dashed
            } else {
                LineStyle::Solid
            },
        })
        .collect();
    let title = format!(
        "{}: Fₙ = {} N, μ = {}",
        r.name.as_deref().unwrap_or("traction curves"),
        r.force_n,
        r.mu
    );
    kontakt_plot::line_plot(
        path,
        &LinePlot {
            title: &title,
            x_label: "creepage = slide-to-roll ratio [-]",
            y_label: "Fₜ / (μ Fₙ) [-]",
            series: &series,
            x_log: false,
            y_from_zero: false,
        },
        (900, 600),
    )
    .with_context(|| format!("drawing {}", path.display()))
}

#[cfg(test)]
mod tests {
    use super::clip_to_saturation;

    #[test]
    fn ordinals() {
        let got: Vec<String> = [2, 3, 5, 11, 12, 13, 21, 22, 101]
            .iter()
            .map(|n| super::ordinal(*n))
            .collect();
        assert_eq!(
            got,
            [
                "2nd", "3rd", "5th", "11th", "12th", "13th", "21st", "22nd", "101st"
            ]
        );
    }

    #[test]
    fn linear_curve_is_cut_at_saturation() {
        let xs = [0.0, 1.0, 2.0, 3.0];
        let ys = [0.0, 0.6, 1.2, 1.8];
        let p = clip_to_saturation(&xs, &ys);
        assert_eq!(p.len(), 3);
        assert!((p[2].0 - 5.0 / 3.0).abs() < 1e-12 && p[2].1 == 1.0);
        let p = clip_to_saturation(&[-2.0, 0.0, 2.0], &[-2.0, 0.0, 2.0]);
        assert_eq!(p, vec![(-1.0, -1.0), (0.0, 0.0), (1.0, 1.0)]);
    }
}
