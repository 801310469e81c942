//! PimP output: the result table, the pressure CSV and the pressure map; and the demo
//! report of the roller-end/rib study.

use crate::commands::{InputError, cannot_write, progress};
use anyhow::{Context, Result};
use kontakt::bearing::{DemoRow, DemoStudy, STUDY_FORCES, TABLE1, demo_study};
use kontakt::geometry::Grid2;
use kontakt_case::PimpReport;
use kontakt_plot::{FieldMap, LinePlot, LineStyle, PALETTE, Series};
use std::io::Write;
use std::path::Path;

/// Print a PimP result as a table or JSON.
pub fn print_report(out: &mut impl Write, r: &PimpReport, json: bool) -> Result<()> {
    if json {
        return crate::output::print_json(out, r);
    }
    let name = r.name.as_deref().unwrap_or("(unnamed)");
    let method = match r.mode {
        Some(mode) => format!("PimP, {} mode", mode.as_str()),
        None => "coupled half-space (BEM)".to_string(),
    };
    let column = if r.mode.is_some() { "PimP" } else { "BEM" };
    writeln!(out, "{name}: {method}, {}", r.geometry)?;
    let hz = |f: &dyn Fn(&kontakt_case::pimp_case::HertzEcho) -> f64, prec: usize| {
        r.hertz
            .as_ref()
            .map_or(String::from("-"), |h| format!("{:.*}", prec, f(h)))
    };
    writeln!(out, "  {:<26} {:>14} {:>14}", "", column, "Hertz (local)")?;
    let rows: [(&str, String, String); 6] = [
        (
            "force [N]",
            format!("{:.2}", r.force_n),
            format!("{:.2}", r.force_n),
        ),
        (
            "max pressure [MPa]",
            format!("{:.1}", r.max_pressure_mpa),
            hz(&|h| h.max_pressure_mpa, 1),
        ),
        (
            "contact area [mm²]",
            format!("{:.5}", r.contact_area_mm2),
            hz(&|h| h.contact_area_mm2, 5),
        ),
        (
            "approach [mm]",
            format!("{:.6}", r.approach_mm),
            hz(&|h| h.approach_mm, 6),
        ),
        (
            "semi-axis a [mm]",
            format!("{:.4}", r.semi_axes_mm[0]),
            hz(&|h| h.semi_axes_mm[0], 4),
        ),
        (
            "semi-axis b [mm]",
            format!("{:.4}", r.semi_axes_mm[1]),
            hz(&|h| h.semi_axes_mm[1], 4),
        ),
    ];
    for (label, ours, hertz) in rows {
        writeln!(out, "  {label:<26} {ours:>14} {hertz:>14}")?;
    }
    writeln!(out, "  {:<26} {:>14}", "patches", r.patches)?;
    let curvature = r
        .centre_line_curvature_per_mm
        .map_or("-".to_string(), |k| format!("{k:.4}"));
    writeln!(
        out,
        "  {:<26} {:>14}",
        "centre-line curv. [1/mm]", curvature
    )?;
    if let Some(a) = r.rib_angle_deg {
        writeln!(out, "  {:<26} {:>14.3}", "rib angle [deg]", a)?;
    }
    if let Some(s) = r.separation_mm {
        writeln!(out, "  {:<26} {:>14.6}", "pose separation [mm]", s)?;
    }
    // `grid_rounds` counts PimP's grid resizes and the half-space solver's domains.
    let work = match &r.solver {
        Some(s) => format!(
            "{} iterations ({} FFT convolutions), residual {:.1e} (tolerance {:.0e}), {:?} boundary, {} domain(s)",
            r.iterations,
            s.operator_applications,
            s.residual,
            s.tolerance,
            s.boundary,
            r.grid_rounds
        ),
        None => format!(
            "{} force evaluations, {} grid resizes",
            r.iterations, r.grid_rounds
        ),
    };
    writeln!(
        out,
        "  grid {} x {} cells of {:.4} x {:.4} mm, {work}",
        r.grid.cells[0], r.grid.cells[1], r.grid.cell_mm[0], r.grid.cell_mm[1]
    )?;
    for warning in &r.warnings {
        writeln!(out, "  warning: {warning}")?;
    }
    Ok(())
}

/// Write fields as CSV: one row per cell, `x_mm, y_mm` and one column per named field.
pub fn write_csv(path: &Path, grid: &Grid2, fields: &[(&str, &[f64])]) -> Result<()> {
    let mut w = crate::commands::CsvFile::create(path)?;
    let mut header = vec!["x_mm", "y_mm"];
    header.extend(fields.iter().map(|(name, _)| *name));
    w.record(&header)?;
    for (k, (x, y)) in grid.points().enumerate() {
        let mut row = vec![format!("{x:.6e}"), format!("{y:.6e}")];
        row.extend(fields.iter().map(|(_, v)| format!("{:.6e}", v[k])));
        w.record(&row)?;
    }
    w.finish()?;
    Ok(())
}

/// The name of a grid axis by its direction `d` in the bearing frame (a unit vector; `X`
/// radial, `Y` circumferential at the contact point, `Z` the ring axis), with its unit: the
/// rib runs round the ring, so a circumferential axis is "along the rib" and an axis in the
/// axial section plane is "across the rib" (with its lean from radial).
pub fn axis_name(d: [f64; 3]) -> String {
    let circumferential = d[1].abs().min(1.0);
    let off = circumferential.acos().to_degrees();
    if off <= 15.0 {
        "along the rib (circumferential) [mm]".to_string()
    } else if off >= 75.0 {
        let from_radial = d[2].abs().atan2(d[0].abs()).to_degrees();
        if from_radial < 10.0 {
            "across the rib (radial) [mm]".to_string()
        } else {
            format!("across the rib ({from_radial:.0}° from radial) [mm]")
        }
    } else {
        format!("{off:.0}° from circumferential [mm]")
    }
}

/// How a pressure map is annotated: the names of its axes and the Hertz ellipse at the
/// contact point (semi-axes `[a, b]` in mm, `a` along the grid's `x`, centred at the origin).
pub struct MapNotes {
    /// Labels of the x and y axes.
    pub axes: (String, String),
    /// Hertz semi-axes, if the ellipse is to be drawn.
    pub hertz_semi_axes_mm: Option<[f64; 2]>,
}

impl MapNotes {
    /// Axes named by their direction in the bearing (see [`axis_name`]).
    pub fn in_bearing(axes: [[f64; 3]; 2], hertz_semi_axes_mm: Option<[f64; 2]>) -> Self {
        MapNotes {
            axes: (axis_name(axes[0]), axis_name(axes[1])),
            hertz_semi_axes_mm,
        }
    }

    /// Axes of the gap's principal frame (x along the Hertz major axis), for contacts that
    /// are not placed in a bearing; plain x, y for a gap map (no Hertz contact point).
    pub fn principal(hertz_semi_axes_mm: Option<[f64; 2]>) -> Self {
        let axes = if hertz_semi_axes_mm.is_some() {
            (
                "x, along the Hertz major axis [mm]".to_string(),
                "y, along the Hertz minor axis [mm]".to_string(),
            )
        } else {
            ("x [mm]".to_string(), "y [mm]".to_string())
        };
        MapNotes {
            axes,
            hertz_semi_axes_mm,
        }
    }
}

/// The legend entry of the maximum-pressure marker.
pub fn max_label(pressure: &[f64]) -> String {
    let max = pressure.iter().copied().fold(0.0f64, f64::max);
    format!("p_max = {max:.0} MPa")
}

/// Draw a pressure map with the contact outline, optional overlays, the Hertz ellipse at
/// the contact point and the maximum marked, its axes named as `notes` says.
pub fn write_map(
    path: &Path,
    grid: &Grid2,
    pressure: &[f64],
    title: &str,
    overlays: &[kontakt_plot::Overlay<'_>],
    notes: &MapNotes,
) -> Result<()> {
    kontakt_plot::Format::from_path(path).map_err(|e| InputError(e.to_string()))?;
    let g = grid;
    let max = max_label(pressure);
    let map = FieldMap {
        nx: g.nx(),
        ny: g.ny(),
        x_min: g.x(0) - 0.5 * g.dx(),
        y_min: g.y(0) - 0.5 * g.dy(),
        dx: g.dx(),
        dy: g.dy(),
        values: pressure,
        title,
        x_label: &notes.axes.0,
        y_label: &notes.axes.1,
        colorbar_label: "pressure [MPa]",
        outline: true,
        overlays,
        ellipse: notes
            .hertz_semi_axes_mm
            .map(|[a, b]| kontakt_plot::Ellipse {
                label: "Hertz ellipse at the contact point",
                centre: (0.0, 0.0),
                semi_axes: (a, b),
                angle: 0.0,
                color: HERTZ_COLOR,
            }),
        max_marker: Some(&max),
    };
    kontakt_plot::field_map(path, &map, (900, 640))
        .with_context(|| format!("drawing {}", path.display()))
}

/// Colour of the Hertz ellipse on pressure maps (magenta: apart from viridis, the black
/// outline and the overlays' red and orange).
pub const HERTZ_COLOR: (u8, u8, u8) = (220, 0, 220);

/// One curve per pairing (solid and dashed in turn, the palette's colours) on one plot.
pub fn pairing_plot<S: AsRef<str>>(
    path: &Path,
    title: &str,
    x_label: &str,
    y_label: &str,
    curves: &[(S, Vec<(f64, f64)>)],
    x_log: bool,
) -> Result<()> {
    let series: Vec<Series> = curves
        .iter()
        .enumerate()
        .map(|(k, (name, pts))| Series {
            label: name.as_ref(),
            points: pts,
            color: PALETTE[k % PALETTE.len()],
            style: if k % 2 == 0 {
                LineStyle::Solid
            } else {
                LineStyle::Dashed
            },
        })
        .collect();
    kontakt_plot::line_plot(
        path,
        &LinePlot {
            title,
            x_label,
            y_label,
            series: &series,
            x_log,
        },
        (900, 600),
    )
    .with_context(|| format!("drawing {}", path.display()))
}

/// The files the demo writes besides report.md, by kind, in the order written: the summary
/// line counts these lists, so it cannot disagree with what is on disk.
#[derive(Debug, Default)]
pub struct Written {
    /// Pressure maps (PNG).
    pub maps: Vec<String>,
    /// Line plots (PNG).
    pub plots: Vec<String>,
    /// Maps of the friction study (PNG).
    pub friction_maps: Vec<String>,
    /// CSV tables.
    pub tables: Vec<String>,
}

impl Written {
    /// The demo's last line: the report and every file written with it, counted.
    pub fn summary(&self, report: &Path, results: usize) -> String {
        let pictures = self.maps.len() + self.plots.len() + self.friction_maps.len();
        format!(
            "Report written to {} with {pictures} pictures ({} pressure maps, {} plots, {} \
             friction maps) and {} tables ({}; {results} results in results.csv)",
            report.display(),
            self.maps.len(),
            self.plots.len(),
            self.friction_maps.len(),
            self.tables.len(),
            self.tables.join(", "),
        )
    }
}

/// Run the roller-end/rib study (`kontakt::bearing::demo_study`) and write the report
/// folder: the computation is the library's, this renders it.
pub fn demo(out_dir: &Path, out: &mut impl Write, json: bool) -> Result<()> {
    std::fs::create_dir_all(out_dir).map_err(|e| cannot_write("create", out_dir, e))?;
    let spinner = progress(
        None,
        "{spinner} [{elapsed_precise}] the roller-end/rib study: 8 pairings, PimP and Hertz",
        json,
    );
    let study = demo_study(&STUDY_FORCES).context("the roller-end/rib demo study");
    if let Some(s) = &spinner {
        s.finish_and_clear();
    }
    let DemoStudy { rows, maps: fields } = study?;
    let mut maps = Vec::with_capacity(fields.len());
    for m in &fields {
        let file = format!("{}_{:.0}N.png", m.pairing, m.force_n);
        write_map(
            &out_dir.join(&file),
            &m.grid,
            &m.pressure,
            &format!("{}, {:.0} N, PimP corrected", m.pairing, m.force_n),
            &[],
            &MapNotes::in_bearing(m.axes, Some(m.hertz_semi_axes_mm)),
        )?;
        maps.push((m.pairing, file));
    }
    let mut written = Written::default();
    written.maps.extend(maps.iter().map(|(_, f)| f.clone()));
    // CSV of every row.
    let csv_path = out_dir.join("results.csv");
    let mut w = crate::commands::CsvFile::create(&csv_path)?;
    for r in &rows {
        w.serialize(r)?;
    }
    w.finish()?;
    written.tables.push("results.csv".into());
    // Maximum pressure and area against force, corrected mode.
    let series_of = |f: &dyn Fn(&DemoRow) -> f64| -> Vec<(&'static str, Vec<(f64, f64)>)> {
        TABLE1
            .iter()
            .map(|&(name, ..)| {
                let pts = rows
                    .iter()
                    .filter(|r| r.pairing == name && r.mode == "corrected")
                    .map(|r| (r.force_n, f(r)))
                    .collect();
                (name, pts)
            })
            .collect()
    };
    for (file, title, ylabel, f) in [
        (
            "max_pressure.png",
            "Maximum pressure, PimP corrected",
            "max pressure [MPa]",
            (&|r: &DemoRow| r.max_pressure_mpa) as &dyn Fn(&DemoRow) -> f64,
        ),
        (
            "contact_area.png",
            "Contact area, PimP corrected",
            "contact area [mm²]",
            &|r: &DemoRow| r.contact_area_mm2,
        ),
    ] {
        pairing_plot(
            &out_dir.join(file),
            title,
            "normal force [N]",
            ylabel,
            &series_of(f),
            false,
        )?;
        written.plots.push(file.into());
    }
    // Markdown report.
    let md_path = out_dir.join("report.md");
    let mut md = String::new();
    md.push_str("# kontakt demo: roller end face against the rib\n\n");
    md.push_str(
        "The four geometry pairings of Wirsching, Schwarz & Tremmel (2020) Table 1, each with both \
         parameter sets, on the 60 mm bore tapered roller bearing of docs/bearing.md (steel, \
         contact height 2.75 mm), loaded from 100 to 400 N. PimP corrected and published \
         modes; Hertz uses the relative curvature at the contact point.\n\n",
    );
    md.push_str("![maximum pressure](max_pressure.png)\n\n![contact area](contact_area.png)\n\n");
    md.push_str("## At 400 N\n\n| pairing | rib angle [deg] | mode | p_max [MPa] | Hertz p0 [MPa] | area [mm²] | Hertz area [mm²] | a x b [mm] | patches | centre-line curvature [1/mm] |\n|---|---|---|---|---|---|---|---|---|---|\n");
    for r in rows.iter().filter(|r| r.force_n == 400.0) {
        md.push_str(&format!(
            "| {} | {:.2} | {} | {:.0} | {:.0} | {:.4} | {:.4} | {:.3} x {:.3} | {} | {} |\n",
            r.pairing,
            r.rib_angle_deg,
            r.mode,
            r.max_pressure_mpa,
            r.hertz_max_pressure_mpa,
            r.contact_area_mm2,
            r.hertz_contact_area_mm2,
            r.semi_axis_a_mm,
            r.semi_axis_b_mm,
            r.patches,
            r.centre_line_curvature_per_mm
                .map_or("-".into(), |k| format!("{k:.3}")),
        ));
    }
    md.push_str(
        "\n## Pressure maps at 400 N (corrected)\n\nEach map shows the PimP pressure inside \
         the contact outline (black), the Hertz ellipse at the contact point's curvature \
         (magenta, dotted) and the maximum (ringed dot, value in the legend). The axes are \
         directions on the rib: along it (circumferential) and across it (in the axial \
         section, with the lean from radial), in mm. A zone more slender than 2.5:1 is drawn \
         with its short axis stretched by a whole factor, as the note under the title says.\n\n",
    );
    for (name, file) in &maps {
        md.push_str(&format!("### {name}\n\n![{name}]({file})\n\n"));
    }
    md.push_str("All rows (both modes, every load): [results.csv](results.csv).\n");
    // Traction curves of every model on one contact (examples/traction_ball_all_models.toml).
    let traction = kontakt_case::run_traction_case(&kontakt_case::TractionCase::from_toml_str(
        include_str!("../../../../examples/traction_ball_all_models.toml"),
    )?)
    .context("the demo's traction case")?;
    crate::commands::traction::write_plot(&out_dir.join("traction.png"), &traction)?;
    crate::commands::traction::write_csv(&out_dir.join("traction.csv"), &traction)?;
    written.plots.push("traction.png".into());
    written.tables.push("traction.csv".into());
    md.push_str(
        "\n## Traction curves\n\nA 20 mm steel ball rolling on a flat steel disc, 200 N, mu = 0.1: \
         Carter, Kalker's linear theory, FASTSIM and the asperity model of the thesis \
         (`kontakt traction examples/traction_ball_all_models.toml`). Data: \
         [traction.csv](traction.csv).\n\n![traction curves](traction.png)\n",
    );
    let friction = crate::commands::friction::demo_study(out_dir, &mut md, &mut written)?;
    std::fs::write(&md_path, md).map_err(|e| cannot_write("write", &md_path, e))?;

    if json {
        serde_json::to_writer_pretty(&mut *out, &rows)?;
        writeln!(out)?;
    } else {
        writeln!(
            out,
            "Roller end / rib, PimP corrected at 400 N (Hertz at the contact point):"
        )?;
        writeln!(
            out,
            "  {:<16} {:>9} {:>10} {:>10} {:>11} {:>11} {:>8} {:>10}",
            "pairing", "rib [deg]", "p_max", "Hertz p0", "area", "Hertz area", "patches", "curv."
        )?;
        writeln!(
            out,
            "  {:<16} {:>9} {:>10} {:>10} {:>11} {:>11} {:>8} {:>10}",
            "", "", "[MPa]", "[MPa]", "[mm²]", "[mm²]", "", "[1/mm]"
        )?;
        for r in rows
            .iter()
            .filter(|r| r.force_n == 400.0 && r.mode == "corrected")
        {
            writeln!(
                out,
                "  {:<16} {:>9.2} {:>10.0} {:>10.0} {:>11.4} {:>11.4} {:>8} {:>10}",
                r.pairing,
                r.rib_angle_deg,
                r.max_pressure_mpa,
                r.hertz_max_pressure_mpa,
                r.contact_area_mm2,
                r.hertz_contact_area_mm2,
                r.patches,
                r.centre_line_curvature_per_mm
                    .map_or("-".into(), |k| format!("{k:.3}")),
            )?;
        }
        writeln!(
            out,
            "\nRib friction torque of the bearing [N·mm] (examples/rib_friction.toml on each pairing):"
        )?;
        if let Some(first) = friction.first() {
            let cols = [0, first.speeds.len() / 2, first.speeds.len() - 1];
            write!(out, "  {:<16}", "pairing")?;
            for &i in &cols {
                write!(
                    out,
                    " {:>21}",
                    format!("{:.0} r/min: PimP", first.speeds[i])
                )?;
                write!(out, " {:>7}", "/Hertz")?;
            }
            writeln!(out)?;
            for s in &friction {
                write!(out, "  {:<16}", s.pairing)?;
                for &i in &cols {
                    write!(
                        out,
                        " {:>21.1} {:>7.4}",
                        s.torque[1][i],
                        s.torque[1][i] / s.torque[0][i]
                    )?;
                }
                writeln!(out)?;
            }
        }
        writeln!(out, "{}", written.summary(&md_path, rows.len()))?;
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::axis_name;

    #[test]
    fn axes_are_named_by_their_direction_on_the_rib() {
        assert_eq!(
            axis_name([0.0, -1.0, 0.0]),
            "along the rib (circumferential) [mm]"
        );
        assert_eq!(axis_name([1.0, 0.0, 0.0]), "across the rib (radial) [mm]");
        let (s, c) = 21f64.to_radians().sin_cos();
        assert_eq!(
            axis_name([-c, 0.0, s]),
            "across the rib (21° from radial) [mm]"
        );
        let (s, c) = 45f64.to_radians().sin_cos();
        assert_eq!(axis_name([c, s, 0.0]), "45° from circumferential [mm]");
    }
}
