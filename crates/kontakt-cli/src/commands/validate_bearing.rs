//! `kontakt validate --bearing`: the measured friction torque of whole bearings
//! (`validation/measured/`, provenance in its README) beside the SKF (2004) model and,
//! where the internal geometry is known, the contact-based model at the same conditions: a table on stdout, `bearing_torque.csv` (one row per measured point),
//! `bearing_skf_curves.csv` (the model curves of the plots), `bearing_report.md` and one
//! plot per dataset (`bearing_<dataset>.png`). The study is
//! `kontakt_case::bearing_validation`; this file only writes it out. Torque in N·mm.

use crate::commands::{CsvFile, cannot_write};
use anyhow::{Context, Result};
use kontakt_case::bearing_validation::{Axis, ComparisonRow, DatasetComparison, compare_all};
use kontakt_plot::{LinePlot, LineStyle, PALETTE, Series};
use std::io::Write;
use std::path::Path;

/// The columns of `bearing_torque.csv`.
pub const TORQUE_COLUMNS: [&str; 18] = [
    "dataset",
    "status",
    "speed_rpm",
    "axial_load_n",
    "radial_load_n",
    "temperature_c",
    "viscosity_mm2_s",
    "measured_nmm",
    "band_pct",
    "skf_nmm",
    "skf_rolling_nmm",
    "skf_sliding_nmm",
    "skf_drag_nmm",
    "skf_deviation_pct",
    "aihara_nmm",
    "aihara_deviation_pct",
    "contact_nmm",
    "contact_deviation_pct",
];

/// Image size of the plots (pixels).
pub const PLOT_SIZE: (u32, u32) = (900, 600);

/// Run the comparison and write the report folder.
pub fn validate_bearing(out_dir: &Path, out: &mut impl Write, json: bool) -> Result<()> {
    std::fs::create_dir_all(out_dir).map_err(|e| cannot_write("create", out_dir, e))?;
    let studies = compare_all().context("comparing the bearing torque datasets")?;
    write_torque_csv(&out_dir.join("bearing_torque.csv"), &studies)?;
    write_curves_csv(&out_dir.join("bearing_skf_curves.csv"), &studies)?;
    let mut plots = 0usize;
    for s in &studies {
        if plot(&out_dir.join(format!("bearing_{}.png", s.dataset.id)), s)? {
            plots += 1;
        }
    }
    std::fs::write(out_dir.join("bearing_report.md"), report(&studies))
        .map_err(|e| cannot_write("write", &out_dir.join("bearing_report.md"), e))?;
    if json {
        serde_json::to_writer_pretty(&mut *out, &summary_json(&studies))?;
        writeln!(out)?;
    } else {
        write!(out, "{}", table(&studies))?;
        writeln!(
            out,
            "report written to {}: bearing_report.md, bearing_torque.csv, bearing_skf_curves.csv and {plots} plots",
            out_dir.display()
        )?;
    }
    Ok(())
}

fn opt(x: Option<f64>, digits: usize) -> String {
    x.map_or_else(String::new, |v| format!("{v:.digits$}"))
}

fn write_torque_csv(path: &Path, studies: &[DatasetComparison]) -> Result<()> {
    let mut w = CsvFile::create(path)?;
    w.record(TORQUE_COLUMNS)?;
    for s in studies {
        for r in &s.rows {
            let m = &r.measured;
            w.record([
                s.dataset.id.to_string(),
                m.status.name().to_string(),
                format!("{}", m.speed_rpm),
                opt(m.axial_load_n, 0),
                format!("{}", m.radial_load_n),
                format!("{}", m.temperature_c),
                opt(r.viscosity_mm2_s, 3),
                format!("{}", m.torque_nmm),
                format!("{}", m.band_pct),
                opt(r.skf.map(|k| k.total_nmm), 3),
                opt(r.skf.map(|k| k.rolling_nmm), 3),
                opt(r.skf.map(|k| k.sliding_nmm), 3),
                opt(r.skf.map(|k| k.drag_nmm), 3),
                opt(r.skf_deviation_pct(), 2),
                opt(r.aihara_nmm, 3),
                opt(r.aihara_deviation_pct(), 2),
                opt(r.contact_nmm, 3),
                opt(r.contact_deviation_pct(), 2),
            ])?;
        }
    }
    w.finish()?;
    Ok(())
}

fn write_curves_csv(path: &Path, studies: &[DatasetComparison]) -> Result<()> {
    let mut w = CsvFile::create(path)?;
    w.record(["dataset", "temperature_c", "x_name", "x", "skf_nmm"])?;
    for s in studies {
        let x_name = match s.dataset.axis {
            Axis::Speed => "speed_rpm",
            Axis::RadialLoad => "radial_load_n",
        };
        for c in &s.skf_curves {
            for &(x, y) in &c.points {
                w.record([
                    s.dataset.id.to_string(),
                    format!("{}", c.temperature_c),
                    x_name.to_string(),
                    format!("{x}"),
                    format!("{y:.3}"),
                ])?;
            }
        }
    }
    w.finish()?;
    Ok(())
}

/// The temperatures of a dataset's points and curves, in order of appearance: one colour each.
fn temperatures(s: &DatasetComparison) -> Vec<f64> {
    let mut t: Vec<f64> = Vec::new();
    let all = s
        .rows
        .iter()
        .map(|r| r.measured.temperature_c)
        .chain(s.skf_curves.iter().map(|c| c.temperature_c));
    for x in all {
        if !t.contains(&x) {
            t.push(x);
        }
    }
    t
}

/// The error bar of a measured point: (x, y·(1 − band)) to (x, y·(1 + band)).
pub fn error_bar(x: f64, torque_nmm: f64, band_pct: f64) -> [(f64, f64); 2] {
    let d = torque_nmm * band_pct / 100.0;
    [(x, torque_nmm - d), (x, torque_nmm + d)]
}

/// A plotted series: label, points, colour, style.
type Curve = (String, Vec<(f64, f64)>, (u8, u8, u8), LineStyle);

/// Draw the dataset's plot: measured points with their error bars in the colour of their
/// temperature, the SKF curve of that temperature dashed, and, where the study has it, the
/// contact-based torque at the measured points as markers of a colour of its own per
/// temperature. Returns false (nothing drawn)
/// for a dataset with neither points nor curves.
fn plot(path: &Path, s: &DatasetComparison) -> Result<bool> {
    let temps = temperatures(s);
    let x_of = |r: &ComparisonRow| match s.dataset.axis {
        Axis::Speed => r.measured.speed_rpm,
        Axis::RadialLoad => r.measured.radial_load_n,
    };
    // (label, points, colour, style)
    // Drawn in order: every error bar, then the model curves, then the contact-based
    // markers, then the measured markers on top, so that nothing of another series hides
    // a measured point.
    let mut bars: Vec<Curve> = Vec::new();
    let mut lines: Vec<Curve> = Vec::new();
    let mut markers: Vec<Curve> = Vec::new();
    let mut contact_markers: Vec<Curve> = Vec::new();
    for (k, &t) in temps.iter().enumerate() {
        let color = PALETTE[k % PALETTE.len()];
        let rows: Vec<&ComparisonRow> = s
            .rows
            .iter()
            .filter(|r| r.measured.temperature_c == t)
            .collect();
        if let Some(first) = rows.first() {
            markers.push((
                format!(
                    "measured, {t} °C ({}, ±{} %)",
                    first.measured.status.name(),
                    first.measured.band_pct
                ),
                rows.iter()
                    .map(|r| (x_of(r), r.measured.torque_nmm))
                    .collect(),
                color,
                LineStyle::Markers,
            ));
            for r in &rows {
                bars.push((
                    String::new(),
                    error_bar(x_of(r), r.measured.torque_nmm, r.measured.band_pct).to_vec(),
                    color,
                    LineStyle::Solid,
                ));
            }
        }
        for c in s.skf_curves.iter().filter(|c| c.temperature_c == t) {
            lines.push((c.label.clone(), c.points.clone(), color, LineStyle::Dashed));
        }
        // the contact-based model at the measured points (where the internal geometry is
        // known): markers in a colour of its own, after the temperatures' colours, joined by
        // a thin unlabelled line in speed order
        let mut contact: Vec<(f64, f64)> = rows
            .iter()
            .filter_map(|r| r.contact_nmm.map(|c| (x_of(r), c)))
            .collect();
        if !contact.is_empty() {
            let color = PALETTE[(temps.len() + k) % PALETTE.len()];
            contact.sort_by(|a, b| a.0.total_cmp(&b.0));
            lines.push((String::new(), contact.clone(), color, LineStyle::Solid));
            contact_markers.push((
                format!("contact-based (kontakt), raceways only, {t} °C"),
                contact,
                color,
                LineStyle::Markers,
            ));
        }
    }
    let has_contact = !contact_markers.is_empty();
    let data: Vec<Curve> = bars
        .into_iter()
        .chain(lines)
        .chain(contact_markers)
        .chain(markers)
        .collect();
    if data.is_empty() {
        return Ok(false);
    }
    let series: Vec<Series> = data
        .iter()
        .map(|(label, points, color, style)| Series {
            label,
            points,
            color: *color,
            style: *style,
        })
        .collect();
    let title = if s.rows.is_empty() {
        format!("{}: SKF model only (no measured numbers)", s.dataset.id)
    } else if has_contact {
        format!("{}: measured, SKF (2004) and contact-based", s.dataset.id)
    } else {
        format!("{}: measured and SKF (2004)", s.dataset.id)
    };
    kontakt_plot::line_plot(
        path,
        &LinePlot {
            title: &title,
            x_label: match s.dataset.axis {
                Axis::Speed => "inner-ring speed [r/min]",
                Axis::RadialLoad => "radial load [N]",
            },
            y_label: "friction torque [N·mm]",
            series: &series,
            x_log: false,
            y_from_zero: true,
        },
        PLOT_SIZE,
    )
    .with_context(|| format!("drawing {}", path.display()))?;
    Ok(true)
}

fn pct(x: Option<f64>) -> String {
    x.map_or_else(|| "—".to_string(), |v| format!("{v:+.1}"))
}

fn nmm(x: Option<f64>) -> String {
    x.map_or_else(|| "—".to_string(), |v| format!("{v:.0}"))
}

/// The stdout table: one block per dataset.
fn table(studies: &[DatasetComparison]) -> String {
    let mut t = String::from(
        "Whole-bearing friction torque: measured (validation/measured/) against SKF (2004) [N·mm]\n",
    );
    for s in studies {
        t.push_str(&format!("\n{}: {}\n", s.dataset.id, s.dataset.title));
        if s.rows.is_empty() {
            t.push_str("  no measured numbers (figure only, no reading): SKF curve in the plot\n");
            continue;
        }
        t.push_str(&format!(
            "  {:>6} {:>7} {:>7} {:>5} {:>7} {:>16} {:>7} {:>7} {:>8} {:>8}\n",
            "n", "F_a", "F_r", "T", "nu", "measured", "SKF", "SKF %", "contact", "cont. %"
        ));
        for r in &s.rows {
            let m = &r.measured;
            t.push_str(&format!(
                "  {:>6} {:>7} {:>7} {:>5} {:>7} {:>16} {:>7} {:>7} {:>8} {:>8}\n",
                m.speed_rpm,
                m.axial_load_n
                    .map_or_else(|| "?".to_string(), |v| format!("{v}")),
                m.radial_load_n,
                m.temperature_c,
                r.viscosity_mm2_s
                    .map_or_else(|| "?".to_string(), |v| format!("{v:.1}")),
                format!(
                    "{} ±{}% {}",
                    m.torque_nmm,
                    m.band_pct,
                    short(m.status.name())
                ),
                nmm(r.skf.map(|k| k.total_nmm)),
                pct(r.skf_deviation_pct()),
                nmm(r.contact_nmm),
                pct(r.contact_deviation_pct()),
            ));
        }
        match s.skf_deviation_stats() {
            Some((mean, lo, hi)) => t.push_str(&format!(
                "  SKF against measured: mean |dev| {mean:.1} %, from {lo:+.1} to {hi:+.1} %\n"
            )),
            None => t.push_str("  SKF not evaluated: an input is not stated in the source\n"),
        }
        if let Some((mean, lo, hi)) = s.contact_deviation_stats() {
            t.push_str(&format!(
                "  contact-based against measured: mean |dev| {mean:.1} %, from {lo:+.1} to {hi:+.1} % (raceways only: see the assumptions in bearing_report.md)\n"
            ));
        }
    }
    t.push_str(
        "\n(n r/min, F N, T °C, nu mm²/s; u = unverified figure reading; contact: the \
         contact-based model, where the internal geometry is known)\n",
    );
    t
}

fn short(status: &str) -> &'static str {
    if status == "verified" { "v" } else { "u" }
}

fn report(studies: &[DatasetComparison]) -> String {
    let mut md = String::from(
        "# kontakt validate --bearing: whole-bearing friction torque against measurements\n\n\
         Measured points from `validation/measured/` (provenance, reading and error band in its \
         README) beside the SKF (2004) model at the same conditions (speed, loads, the oil's \
         viscosity at the test temperature) and, where the internal geometry is known, the \
         contact-based model (the friction section of a bearing case, its assumptions listed). \
         Deviation = `model / measured − 1` in %. The Aihara (1987) column, and the \
         contact-based one without the internal geometry, stay empty: no value is put in their \
         place.\n\n",
    );
    for s in studies {
        let d = &s.dataset;
        md.push_str(&format!(
            "## {}\n\n{}\n\nSource: {}.\n\n",
            d.id, d.title, d.source
        ));
        md.push_str("Assumptions:\n\n");
        for a in d.assumptions {
            md.push_str(&format!("- {a}\n"));
        }
        md.push_str(&format!(
            "- Aihara (1987) not evaluated: {}\n",
            d.aihara_note
        ));
        for w in &s.skf_warnings {
            md.push_str(&format!("- SKF model: {w}\n"));
        }
        match &d.contact {
            Some(c) => {
                for a in c.assumptions {
                    md.push_str(&format!("- {a}\n"));
                }
            }
            None => md.push_str(
                "- contact-based model not evaluated: the internal geometry is not stated\n",
            ),
        }
        if s.rows.is_empty() {
            md.push_str("\nNo measured numbers: the source has this curve in a figure only, and no reading of it exists. The plot shows the SKF model alone.\n\n");
        } else {
            md.push_str("\n| n [r/min] | F_a [N] | F_r [N] | T [°C] | ν [mm²/s] | measured [N·mm] | SKF [N·mm] | SKF dev. | contact-based | dev. |\n|---|---|---|---|---|---|---|---|---|---|\n");
            for r in &s.rows {
                let m = &r.measured;
                md.push_str(&format!(
                    "| {} | {} | {} | {} | {} | {} ± {} % ({}) | {} | {} % | {} | {} |\n",
                    m.speed_rpm,
                    m.axial_load_n
                        .map_or_else(|| "not stated".to_string(), |v| format!("{v}")),
                    m.radial_load_n,
                    m.temperature_c,
                    r.viscosity_mm2_s
                        .map_or_else(|| "not stated".to_string(), |v| format!("{v:.2}")),
                    m.torque_nmm,
                    m.band_pct,
                    m.status.name(),
                    nmm(r.skf.map(|k| k.total_nmm)),
                    pct(r.skf_deviation_pct()),
                    nmm(r.contact_nmm),
                    pct(r.contact_deviation_pct()),
                ));
            }
            if let Some((mean, lo, hi)) = s.skf_deviation_stats() {
                md.push_str(&format!(
                    "\nSKF against the measurement: mean |deviation| {mean:.1} %, from {lo:+.1} to {hi:+.1} %.\n"
                ));
            }
            if let Some((mean, lo, hi)) = s.contact_deviation_stats() {
                md.push_str(&format!(
                    "\nContact-based (raceways only) against the measurement: mean |deviation| {mean:.1} %, from {lo:+.1} to {hi:+.1} %.\n"
                ));
            }
            md.push('\n');
        }
        md.push_str(&format!("![{}](bearing_{}.png)\n\n", d.id, d.id));
    }
    md
}

fn summary_json(studies: &[DatasetComparison]) -> serde_json::Value {
    serde_json::json!({
        "kontakt_version": kontakt::VERSION,
        "unit_torque": "N·mm",
        "datasets": studies.iter().map(|s| serde_json::json!({
            "dataset": s.dataset.id,
            "title": s.dataset.title,
            "source": s.dataset.source,
            "assumptions": s.dataset.assumptions,
            "aihara_note": s.dataset.aihara_note,
            "contact_assumptions": s.dataset.contact.as_ref().map(|c| c.assumptions),
            "contact_deviation_mean_abs_pct": s.contact_deviation_stats().map(|d| d.0),
            "skf_warnings": s.skf_warnings,
            "skf_deviation_mean_abs_pct": s.skf_deviation_stats().map(|d| d.0),
            "rows": s.rows,
            "skf_curves": s.skf_curves,
        })).collect::<Vec<_>>(),
    })
}
