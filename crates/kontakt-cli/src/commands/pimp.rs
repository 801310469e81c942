//! PimP output: the result table, the pressure CSV and the pressure map; and the demo
//! report of the roller-end/rib study.

use crate::commands::{cannot_write, progress};
use crate::render::{MapNotes, Written, map_stretch, pairing_plot, write_map};
use anyhow::{Context, Result};
use kontakt::bearing::{DemoMap, DemoRow, DemoStudy, STUDY_FORCES, TABLE1, demo_study};
use kontakt::geometry::Grid2;
use kontakt_case::PimpReport;
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
    let num = crate::output::Num;
    let hz = |f: &dyn Fn(&kontakt_case::pimp_case::HertzEcho) -> f64, prec: usize| {
        r.hertz
            .as_ref()
            .map_or(String::from("-"), |h| format!("{:.*}", prec, num(f(h))))
    };
    writeln!(out, "  {:<26} {:>14} {:>14}", "", column, "Hertz (local)")?;
    let rows: [(&str, String, String); 6] = [
        (
            "force [N]",
            format!("{:.2}", num(r.force_n)),
            format!("{:.2}", num(r.force_n)),
        ),
        (
            "max pressure [MPa]",
            format!("{:.1}", num(r.max_pressure_mpa)),
            hz(&|h| h.max_pressure_mpa, 1),
        ),
        (
            "contact area [mm²]",
            format!("{:.5}", num(r.contact_area_mm2)),
            hz(&|h| h.contact_area_mm2, 5),
        ),
        (
            "approach [mm]",
            format!("{:.6}", num(r.approach_mm)),
            hz(&|h| h.approach_mm, 6),
        ),
        (
            "semi-axis a [mm]",
            format!("{:.4}", num(r.semi_axes_mm[0])),
            hz(&|h| h.semi_axes_mm[0], 4),
        ),
        (
            "semi-axis b [mm]",
            format!("{:.4}", num(r.semi_axes_mm[1])),
            hz(&|h| h.semi_axes_mm[1], 4),
        ),
    ];
    for (label, ours, hertz) in rows {
        writeln!(out, "  {label:<26} {ours:>14} {hertz:>14}")?;
    }
    writeln!(out, "  {:<26} {:>14}", "patches", r.patches)?;
    let curvature = r
        .centre_line_curvature_per_mm
        .map_or("-".to_string(), |k| format!("{:.4}", num(k)));
    writeln!(
        out,
        "  {:<26} {:>14}",
        "centre-line curv. [1/mm]", curvature
    )?;
    if let Some(a) = r.rib_angle_deg {
        writeln!(out, "  {:<26} {:>14.3}", "rib angle [deg]", num(a))?;
    }
    if let Some(s) = r.separation_mm {
        writeln!(out, "  {:<26} {:>14.6}", "pose separation [mm]", num(s))?;
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

/// The notes of the demo's pressure maps: axes on the rib, the Hertz ellipse, one colour
/// scale for all pairings (a colour is one pressure on each map) and each pairing's
/// stretch as `kontakt validate` draws it (see [`map_stretch`]).
fn demo_map_notes(maps: &[DemoMap]) -> Vec<MapNotes> {
    let color_max = maps
        .iter()
        .flat_map(|m| m.pressure.iter().copied())
        .fold(0.0f64, f64::max);
    maps.iter()
        .map(|m| {
            let hertz = Some(m.hertz_semi_axes_mm);
            MapNotes::in_bearing(m.axes, hertz).shared(
                (color_max > 0.0).then_some(color_max),
                Some(map_stretch(&m.grid, &m.pressure, hertz)),
            )
        })
        .collect()
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
    for (m, notes) in fields.iter().zip(demo_map_notes(&fields)) {
        let file = format!("{}_{:.0}N.png", m.pairing, m.force_n);
        write_map(
            &out_dir.join(&file),
            &m.grid,
            &m.pressure,
            &format!("{}, {:.0} N, PimP corrected", m.pairing, m.force_n),
            &[],
            &notes,
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
         (magenta, dotted) and the maximum (ringed dot, value in the legend), all on one \
         colour scale. The axes are \
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
    let bearings = crate::commands::bearing_demo::demo_section(out_dir, &mut md, &mut written)?;
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
        crate::commands::bearing_demo::print_summary(out, &bearings)?;
        writeln!(out, "{}", written.summary(&md_path, rows.len()))?;
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    #![allow(clippy::unwrap_used)]

    /// Issue 30, item 18: the demo's pressure maps share one colour scale (the largest
    /// pressure of them all) and each has its pairing's stretch.
    #[test]
    fn demo_maps_share_one_colour_scale() {
        let study = kontakt::bearing::demo_study(&[400.0]).unwrap();
        let notes = super::demo_map_notes(&study.maps);
        let top = study
            .maps
            .iter()
            .flat_map(|m| m.pressure.iter().copied())
            .fold(0.0f64, f64::max);
        assert_eq!(notes.len(), 8);
        for (m, n) in study.maps.iter().zip(&notes) {
            assert_eq!(n.color_max, Some(top), "{}", m.pairing);
            let own = m.pressure.iter().copied().fold(0.0f64, f64::max);
            assert!(own <= top);
            let k = n.stretch.unwrap();
            assert!(k >= 1.0 && k.fract() == 0.0, "{}: {k}", m.pairing);
        }
        // the pairings' own maxima differ, so a scale per map would differ
        assert!(
            study
                .maps
                .iter()
                .any(|m| m.pressure.iter().copied().fold(0.0, f64::max) < 0.8 * top)
        );
    }
}
