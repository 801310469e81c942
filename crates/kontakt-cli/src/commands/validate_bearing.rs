//! `kontakt validate --bearing`: the measured friction torque of whole bearings
//! (`validation/measured/`, provenance in its README) beside the SKF (2004) model and,
//! where the internal geometry is known, the contact-based model at the same conditions: a
//! table on stdout, `bearing_torque.csv` (one row per measured point),
//! `bearing_skf_curves.csv` (the model curves of the plots), `bearing_breakdown.csv` and
//! `bearing_rib_sensitivity.csv` (the rib study), `bearing_report.md`, one plot per dataset
//! (`bearing_<dataset>.png`) and one breakdown plot per contact-based curve
//! (`bearing_<dataset>_breakdown_<T>C.png`: cone, cup, rib, drag stacked beside SKF and the
//! measurement). The study is `kontakt_case::bearing_validation` and its `rib_study`; this
//! file only writes it out. Torque in N·mm.

use crate::commands::{CsvFile, cannot_write};
use anyhow::{Context, Result};
use kontakt_case::bearing_validation::rib_study::{
    BreakdownCurve, LM12700_LOADS_N, SensitivityRow, VARIATIONS, breakdown, crossover_rpm,
    lm12700_breakdown, sensitivity,
};
use kontakt_case::bearing_validation::{
    Axis, ComparisonRow, ContactParts, DatasetComparison, Quantity, compare_all,
};
use kontakt_plot::{LinePlot, LineStyle, PALETTE, Series};
use std::io::Write;
use std::path::Path;

/// The columns of `bearing_torque.csv`.
pub const TORQUE_COLUMNS: [&str; 24] = [
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
    "quantity",
    "contact_total_nmm",
    "contact_cone_nmm",
    "contact_cup_nmm",
    "contact_rib_nmm",
    "contact_drag_nmm",
];

/// The columns of `bearing_breakdown.csv`.
pub const BREAKDOWN_COLUMNS: [&str; 12] = [
    "dataset",
    "temperature_c",
    "axial_load_n",
    "speed_rpm",
    "total_nmm",
    "cone_nmm",
    "cup_nmm",
    "rib_nmm",
    "drag_nmm",
    "skf_nmm",
    "skf_rolling_nmm",
    "skf_sliding_nmm",
];

/// Image size of the plots (pixels).
pub const PLOT_SIZE: (u32, u32) = (900, 600);

/// Image size of the breakdown plots (pixels): wider, for their longer legend.
pub const BREAKDOWN_SIZE: (u32, u32) = (1200, 600);

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
    // the contact-based model's breakdown and the rib study, where a dataset has one
    let mut rib = Vec::new();
    for s in &studies {
        let curves = breakdown(&s.dataset).context("the contact-based breakdown")?;
        if curves.is_empty() {
            continue;
        }
        for c in &curves {
            let path = out_dir.join(breakdown_file(s.dataset.id, c.temperature_c));
            breakdown_plot(&path, s, c)?;
            plots += 1;
        }
        let sens = sensitivity(&s.dataset).context("the rib sensitivity study")?;
        rib.push((s.dataset.id, curves, sens));
    }
    // the LM12700 of Zhou & Hoeprich (1991): its rib and raceways against speed with an
    // assumed geometry, load and oil, beside their Fig. 9 totals (the load not stated)
    if let Some(s) = studies
        .iter()
        .find(|s| s.dataset.id == "zhou_hoeprich1991_fig9")
    {
        let curves = lm12700_breakdown(&LM12700_LOADS_N).context("the LM12700 breakdown")?;
        let path = out_dir.join(breakdown_file(s.dataset.id, curves[0].temperature_c));
        breakdown_plot(&path, s, &curves[0])?;
        plots += 1;
        rib.push((s.dataset.id, curves, Vec::new()));
    }
    write_breakdown_csv(&out_dir.join("bearing_breakdown.csv"), &rib)?;
    write_sensitivity_csv(&out_dir.join("bearing_rib_sensitivity.csv"), &rib)?;
    std::fs::write(
        out_dir.join("bearing_report.md"),
        report(&studies) + &rib_report(&rib),
    )
    .map_err(|e| cannot_write("write", &out_dir.join("bearing_report.md"), e))?;
    if json {
        let mut v = summary_json(&studies);
        v["rib_study"] = serde_json::json!(
            rib.iter()
                .map(|(id, curves, sens)| serde_json::json!({
                    "dataset": id,
                    "breakdown": curves,
                    "sensitivity": sens,
                }))
                .collect::<Vec<_>>()
        );
        serde_json::to_writer_pretty(&mut *out, &v)?;
        writeln!(out)?;
    } else {
        write!(out, "{}", table(&studies))?;
        write!(out, "{}", rib_table(&rib))?;
        writeln!(
            out,
            "report written to {}: bearing_report.md, bearing_torque.csv, bearing_skf_curves.csv, bearing_breakdown.csv, bearing_rib_sensitivity.csv and {plots} plots",
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
            let cells = [
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
                m.quantity.name().to_string(),
            ];
            w.record(
                cells
                    .into_iter()
                    .chain(parts_cells(r.contact_parts.as_ref())),
            )?;
        }
    }
    w.finish()?;
    Ok(())
}

/// The cells of a contact-based breakdown, total, cone, cup, rib, drag \[N·mm\] (empty
/// without one).
fn parts_cells(c: Option<&ContactParts>) -> [String; 5] {
    let f = |g: fn(&ContactParts) -> f64| opt(c.map(g), 3);
    [
        f(|c| c.total_nmm),
        f(|c| c.cone_nmm),
        f(|c| c.cup_nmm),
        f(|c| c.rib_nmm),
        f(|c| c.drag_nmm),
    ]
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
                    "measured{}, {t} °C ({}, ±{} %)",
                    match first.measured.quantity {
                        Quantity::Total => "",
                        Quantity::RollingResistance => " M_rr",
                    },
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
                format!(
                    "contact-based (kontakt), {}, {t} °C",
                    if rows
                        .iter()
                        .all(|r| r.measured.quantity == Quantity::RollingResistance)
                    {
                        "raceways (cone + cup)"
                    } else {
                        "total"
                    }
                ),
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
    let title = if s.rows.is_empty() {
        format!("{}: SKF model only (no measured numbers)", s.dataset.id)
    } else if has_contact {
        format!("{}: measured, SKF (2004) and contact-based", s.dataset.id)
    } else {
        format!("{}: measured and SKF (2004)", s.dataset.id)
    };
    let x_label = match s.dataset.axis {
        Axis::Speed => "inner-ring speed [r/min]",
        Axis::RadialLoad => "radial load [N]",
    };
    draw(path, &title, x_label, &data, PLOT_SIZE)?;
    Ok(true)
}

/// Draw `data` as a torque plot (y from 0) of `size` pixels.
fn draw(path: &Path, title: &str, x_label: &str, data: &[Curve], size: (u32, u32)) -> Result<()> {
    let series: Vec<Series> = data
        .iter()
        .map(|(label, points, color, style)| Series {
            label,
            points,
            color: *color,
            style: *style,
        })
        .collect();
    kontakt_plot::line_plot(
        path,
        &LinePlot {
            title,
            x_label,
            y_label: "friction torque [N·mm]",
            series: &series,
            x_log: false,
            y_from_zero: true,
        },
        size,
    )
    .with_context(|| format!("drawing {}", path.display()))
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
            "  {:>6} {:>7} {:>7} {:>5} {:>7} {:>16} {:>7} {:>7} {:>8} {:>8} {:>7} {:>6}\n",
            "n",
            "F_a",
            "F_r",
            "T",
            "nu",
            "measured",
            "SKF",
            "SKF %",
            "contact",
            "cont. %",
            "c.total",
            "c.rib"
        ));
        for r in &s.rows {
            let m = &r.measured;
            t.push_str(&format!(
                "  {:>6} {:>7} {:>7} {:>5} {:>7} {:>16} {:>7} {:>7} {:>8} {:>8} {:>7} {:>6}\n",
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
                nmm(r.skf_compared_nmm()),
                pct(r.skf_deviation_pct()),
                nmm(r.contact_nmm),
                pct(r.contact_deviation_pct()),
                nmm(r.contact_parts.map(|c| c.total_nmm)),
                nmm(r.contact_parts.map(|c| c.rib_nmm)),
            ));
        }
        if s.rows
            .iter()
            .any(|r| r.measured.quantity == Quantity::RollingResistance)
        {
            t.push_str("  measured: the rolling-resistance torque M_rr (the raceways'); SKF: its rolling term; contact: cone + cup (c.total, c.rib: the whole bearing's, the rib's)\n");
        }
        match s.skf_deviation_stats() {
            Some((mean, lo, hi)) => t.push_str(&format!(
                "  SKF against measured: mean |dev| {mean:.1} %, from {lo:+.1} to {hi:+.1} %\n"
            )),
            None => t.push_str("  SKF not evaluated: an input is not stated in the source\n"),
        }
        if let Some((mean, lo, hi)) = s.contact_deviation_stats() {
            t.push_str(&format!(
                "  contact-based against measured: mean |dev| {mean:.1} %, from {lo:+.1} to {hi:+.1} % (assumptions in bearing_report.md)\n"
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
            md.push_str("\n| n [r/min] | F_a [N] | F_r [N] | T [°C] | ν [mm²/s] | measured [N·mm] | SKF [N·mm] | SKF dev. | contact-based | dev. | contact total (rib) |\n|---|---|---|---|---|---|---|---|---|---|---|\n");
            for r in &s.rows {
                let m = &r.measured;
                md.push_str(&format!(
                    "| {} | {} | {} | {} | {} | {} ± {} % ({}, {}) | {} | {} % | {} | {} | {} ({}) |\n",
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
                    m.quantity.name(),
                    nmm(r.skf_compared_nmm()),
                    pct(r.skf_deviation_pct()),
                    nmm(r.contact_nmm),
                    pct(r.contact_deviation_pct()),
                    nmm(r.contact_parts.map(|c| c.total_nmm)),
                    nmm(r.contact_parts.map(|c| c.rib_nmm)),
                ));
            }
            if let Some((mean, lo, hi)) = s.skf_deviation_stats() {
                md.push_str(&format!(
                    "\nSKF against the measurement: mean |deviation| {mean:.1} %, from {lo:+.1} to {hi:+.1} %.\n"
                ));
            }
            if let Some((mean, lo, hi)) = s.contact_deviation_stats() {
                md.push_str(&format!(
                    "\nContact-based against the measurement: mean |deviation| {mean:.1} %, from {lo:+.1} to {hi:+.1} %.\n"
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

/// The file of a breakdown plot: `bearing_<dataset>_breakdown_<T>C.png`.
pub fn breakdown_file(id: &str, temperature_c: f64) -> String {
    format!("bearing_{id}_breakdown_{temperature_c}C.png")
}

/// Colours of the breakdown plot: cone, + cup, + rib, + drag, SKF total, SKF rolling term,
/// measured (black).
pub const BREAKDOWN_COLOURS: [(u8, u8, u8); 7] = [
    PALETTE[0],
    PALETTE[1],
    PALETTE[2],
    PALETTE[3],
    PALETTE[4],
    PALETTE[5],
    (0, 0, 0),
];

/// The breakdown of the contact-based torque along the speed at one temperature, stacked as
/// lines (cone; cone + cup; + rib; + drag = total), beside the SKF total and its rolling term
/// (dashed) and the dataset's measured points of that temperature with their error bars.
fn breakdown_plot(path: &Path, s: &DatasetComparison, c: &BreakdownCurve) -> Result<()> {
    let [c_cone, c_cup, c_rib, c_drag, c_skf, c_skf_rr, c_meas] = BREAKDOWN_COLOURS;
    let line = |f: &dyn Fn(&ContactParts) -> f64| {
        c.points
            .iter()
            .map(|p| (p.speed_rpm, f(&p.contact)))
            .collect::<Vec<_>>()
    };
    let no_drag = c.points.iter().all(|p| p.contact.drag_nmm == 0.0);
    let mut data: Vec<Curve> = Vec::new();
    let rows: Vec<&ComparisonRow> = s
        .rows
        .iter()
        .filter(|r| r.measured.temperature_c == c.temperature_c)
        .collect();
    for r in &rows {
        data.push((
            String::new(),
            error_bar(
                r.measured.speed_rpm,
                r.measured.torque_nmm,
                r.measured.band_pct,
            )
            .to_vec(),
            c_meas,
            LineStyle::Solid,
        ));
    }
    let skf: Vec<(f64, f64, f64)> = c
        .points
        .iter()
        .filter_map(|p| p.skf.map(|k| (p.speed_rpm, k.total_nmm, k.rolling_nmm)))
        .collect();
    if !skf.is_empty() {
        data.push((
            "SKF 2004 total".into(),
            skf.iter().map(|&(n, t, _)| (n, t)).collect(),
            c_skf,
            LineStyle::Dashed,
        ));
        data.push((
            "SKF 2004 rolling term".into(),
            skf.iter().map(|&(n, _, r)| (n, r)).collect(),
            c_skf_rr,
            LineStyle::Dashed,
        ));
    }
    data.push((
        "cone".into(),
        line(&|p| p.cone_nmm),
        c_cone,
        LineStyle::Solid,
    ));
    data.push((
        "cone + cup (raceways)".into(),
        line(&|p| p.cone_nmm + p.cup_nmm),
        c_cup,
        LineStyle::Solid,
    ));
    data.push((
        if no_drag {
            "+ rib = total (drag 0: circulating oil)".into()
        } else {
            "+ rib".into()
        },
        line(&|p| p.cone_nmm + p.cup_nmm + p.rib_nmm),
        c_rib,
        LineStyle::Solid,
    ));
    if !no_drag {
        data.push((
            "+ drag = total".into(),
            line(&|p| p.total_nmm),
            c_drag,
            LineStyle::Solid,
        ));
    }
    if let Some(first) = rows.first() {
        data.push((
            format!(
                "measured {} ({}, ±{} %)",
                match first.measured.quantity {
                    Quantity::Total => "total",
                    Quantity::RollingResistance => "M_rr (raceways)",
                },
                first.measured.status.name(),
                first.measured.band_pct
            ),
            rows.iter()
                .map(|r| (r.measured.speed_rpm, r.measured.torque_nmm))
                .collect(),
            c_meas,
            LineStyle::Markers,
        ));
    }
    let title = format!(
        "{}: contact-based breakdown, {} °C, {} kN axial",
        s.dataset.id,
        c.temperature_c,
        c.axial_load_n / 1000.0
    );
    draw(
        path,
        &title,
        "inner-ring speed [r/min]",
        &data,
        BREAKDOWN_SIZE,
    )
}

/// The rib study of each dataset with a contact setup: its id, breakdown and sensitivity.
type RibStudy = (&'static str, Vec<BreakdownCurve>, Vec<SensitivityRow>);

fn write_breakdown_csv(path: &Path, rib: &[RibStudy]) -> Result<()> {
    let mut w = CsvFile::create(path)?;
    w.record(BREAKDOWN_COLUMNS)?;
    for (id, curves, _) in rib {
        for c in curves {
            for p in &c.points {
                let head = [
                    (*id).to_string(),
                    format!("{}", c.temperature_c),
                    format!("{}", c.axial_load_n),
                    format!("{}", p.speed_rpm),
                ];
                let skf = [
                    opt(p.skf.map(|x| x.total_nmm), 3),
                    opt(p.skf.map(|x| x.rolling_nmm), 3),
                    opt(p.skf.map(|x| x.sliding_nmm), 3),
                ];
                w.record(
                    head.into_iter()
                        .chain(parts_cells(Some(&p.contact)))
                        .chain(skf),
                )?;
            }
        }
    }
    w.finish()?;
    Ok(())
}

/// `(temperature, value)` pairs as "value unit (T °C)", joined; a deviation (unit `" %"`)
/// with its sign.
fn start_list(v: &[(f64, f64)], unit: &str) -> String {
    v.iter()
        .map(|(t, d)| {
            if unit == " %" {
                format!("{d:+.0}{unit} ({t} °C)")
            } else {
                format!("{d:.0}{unit} ({t} °C)")
            }
        })
        .collect::<Vec<_>>()
        .join(", ")
}

/// A sensitivity row as text: input, value, raceways' and total's mean |deviation|, both at
/// the lowest speed.
fn sensitivity_cells(r: &SensitivityRow) -> [String; 6] {
    [
        r.parameter.to_string(),
        r.value.to_string(),
        format!("{:.1} %", r.raceways_mean_abs_pct),
        format!("{:.1} %", r.total_mean_abs_pct),
        start_list(&r.raceways_start_pct, " %"),
        start_list(&r.total_start_pct, " %"),
    ]
}

fn write_sensitivity_csv(path: &Path, rib: &[RibStudy]) -> Result<()> {
    let mut w = CsvFile::create(path)?;
    w.record([
        "dataset",
        "parameter",
        "value",
        "raceways_mean_abs_pct",
        "total_mean_abs_pct",
        "temperature_c",
        "raceways_start_pct",
        "total_start_pct",
        "rib_start_nmm",
    ])?;
    for (_, _, sens) in rib {
        for r in sens {
            for (k, &(t, dr)) in r.raceways_start_pct.iter().enumerate() {
                w.record([
                    r.dataset.to_string(),
                    r.parameter.to_string(),
                    r.value.to_string(),
                    format!("{:.2}", r.raceways_mean_abs_pct),
                    format!("{:.2}", r.total_mean_abs_pct),
                    format!("{t}"),
                    format!("{dr:.2}"),
                    format!("{:.2}", r.total_start_pct[k].1),
                    format!("{:.3}", r.rib_start_nmm[k].1),
                ])?;
            }
        }
    }
    w.finish()?;
    Ok(())
}

/// The stdout lines of the rib study: per dataset the mean |deviation| under each
/// variation (raceways against M_rr, total against the values as if they were totals).
fn rib_table(rib: &[RibStudy]) -> String {
    let mut t = String::new();
    for (id, curves, sens) in rib {
        for c in curves {
            if let Some(x) = crossover_rpm(c) {
                t.push_str(&format!(
                    "\n{id}: contact-based, {} N axial, {} °C: the raceways' torque exceeds the rib's above {x:.0} r/min",
                    c.axial_load_n, c.temperature_c
                ));
            }
        }
        if !curves.is_empty() {
            t.push('\n');
        }
        if sens.is_empty() {
            continue;
        }
        t.push_str(&format!(
            "\n{id}: rib and oil sensitivity of the contact-based model (mean |dev| %: raceways | total; at the lowest speed: raceways | total)\n"
        ));
        for r in sens {
            let [p, v, rm, tm, rs, ts] = sensitivity_cells(r);
            t.push_str(&format!(
                "  {p:<42} {v:<20} {rm:>7} | {tm:>7}   {rs} | {ts}\n"
            ));
        }
    }
    t
}

/// The report's section of the rib study: the breakdown plots and the sensitivity table with
/// the reason for every value.
fn rib_report(rib: &[RibStudy]) -> String {
    let mut md = String::new();
    if rib.is_empty() {
        return md;
    }
    md.push_str("# The contact-based breakdown and the rib study\n\n");
    md.push_str("Every variation moves one uncertain input of the contact-based case over a physical range (the reason in the last column), the others as assumed; none is fitted to the measurement. Mean |deviation| of the raceways (cone + cup, the comparison for a rolling-resistance torque M_rr) and of the total (the comparison if the measured values were the total torque), and both at the lowest measured speed.\n\n");
    for (id, curves, sens) in rib {
        md.push_str(&format!("## {id}\n\n"));
        let mut drawn: Vec<f64> = Vec::new();
        for c in curves {
            if let Some(x) = crossover_rpm(c) {
                md.push_str(&format!(
                    "- {} N axial, {} °C: the raceways' torque exceeds the rib's above {x:.0} r/min\n",
                    c.axial_load_n, c.temperature_c
                ));
            }
        }
        md.push('\n');
        for c in curves {
            if drawn.contains(&c.temperature_c) {
                continue;
            }
            drawn.push(c.temperature_c);
            md.push_str(&format!(
                "![{id} breakdown at {} °C]({})\n\n",
                c.temperature_c,
                breakdown_file(id, c.temperature_c)
            ));
        }
        if sens.is_empty() {
            md.push_str("The LM12700's geometry beyond the caption of Fig. 9, its load and its oil are assumed (`examples/bearing_lm12700_rib_friction.toml`); the curves at 2 and 6 kN are in `bearing_breakdown.csv`.\n\n");
            continue;
        }
        md.push_str("| input | value | raceways mean \\|dev\\| | total mean \\|dev\\| | raceways at start | total at start | rib at start [N·mm] | why this value |\n|---|---|---|---|---|---|---|---|\n");
        for r in sens {
            md.push_str(&format!(
                "| {} | {} | {} |\n",
                sensitivity_cells(r).join(" | "),
                start_list(&r.rib_start_nmm, ""),
                r.why
            ));
        }
        md.push('\n');
    }
    debug_assert_eq!(VARIATIONS.len(), rib[0].2.len());
    md
}
