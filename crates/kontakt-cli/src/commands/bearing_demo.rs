//! The whole-bearing section of `kontakt demo`: the 32008 X class tapered roller bearing
//! under combined load and the 6205 class deep-groove ball bearing under radial load (the
//! examples of the same names), each with its table and its load distribution in
//! `report.md`, the pictures of `kontakt bearing` beside it and one line each on the console.

use crate::render::Written;
use anyhow::{Context, Result};
use kontakt_case::bearing_case::BearingElements;
use kontakt_case::{BearingCase, BearingReport, run_bearing_case};
use std::io::Write;
use std::path::Path;

/// The demo's bearings: (example file, its text, what the demo says of its load).
const BEARINGS: [(&str, &str, &str); 2] = [
    (
        "examples/bearing_32008x.toml",
        include_str!("../../../../examples/bearing_32008x.toml"),
        "5 kN radial and 3 kN axial load, the shaft holding the tilts",
    ),
    (
        "examples/bearing_6205.toml",
        include_str!("../../../../examples/bearing_6205.toml"),
        "2 kN radial load",
    ),
];

/// Solve the demo's bearings, draw their pictures into `out_dir` (counted in `written`)
/// and append their section to the Markdown report `md`; the reports, for the console.
pub fn demo_section(
    out_dir: &Path,
    md: &mut String,
    written: &mut Written,
) -> Result<Vec<BearingReport>> {
    md.push_str(
        "\n## Whole bearings\n\nThe load distribution of two whole bearings (`kontakt bearing`; \
         the model in docs/bearing-model.md of the repository): every rolling \
         element in equilibrium with the rings, the rollers cut into slices with the \
         ISO/TS 16281 slice law and profile, the balls as exact Hertz point contacts. The \
         polar diagrams draw each element's load as a spoke at its azimuth ψ (from x toward \
         y), from 0 on the inner circle, with the radial load's direction (arrow) and the \
         loaded arc from Sjövall's load-zone parameter ε (shaded).\n",
    );
    let mut reports = Vec::new();
    for (file, text, load) in BEARINGS {
        let case = BearingCase::from_toml_str(text).with_context(|| file.to_string())?;
        let report = run_bearing_case(&case).with_context(|| format!("the demo's {file}"))?;
        let stem = Path::new(file)
            .file_stem()
            .and_then(|s| s.to_str())
            .unwrap_or("bearing");
        let name = report.name.clone().unwrap_or_else(|| stem.to_string());
        let mut table = Vec::new();
        crate::commands::bearing::print_report(&mut table, &report, false)?;
        md.push_str(&format!(
            "\n### {name}\n\n{load} (`kontakt bearing {file}`):\n\n```text\n{}```\n\n",
            String::from_utf8_lossy(&table)
        ));
        let mut pictures: Vec<(String, &str)> = vec![
            (format!("{stem}_loads.png"), "load distribution"),
            (format!("{stem}_elements.png"), "element loads"),
        ];
        if report.rollers().is_some() {
            pictures.push((format!("{stem}_slices.png"), "most loaded roller"));
            pictures.push((format!("{stem}_map.png"), "every slice"));
        }
        for (k, (picture, alt)) in pictures.iter().enumerate() {
            let path = out_dir.join(picture);
            match k {
                0 => crate::commands::bearing_plot::write_load_plot(&path, &report)?,
                1 => crate::commands::bearing_plot::write_element_plot(&path, &report)?,
                2 => crate::commands::bearing_plot::write_slice_plot(&path, &report)?,
                _ => crate::commands::bearing_plot::write_slice_map(&path, &report)?,
            }
            written.plots.push(picture.clone());
            md.push_str(&format!("![{name}: {alt}]({picture})\n\n"));
        }
        reports.push(report);
    }
    Ok(reports)
}

/// One console line per bearing of the demo.
pub fn print_summary(out: &mut impl Write, reports: &[BearingReport]) -> Result<()> {
    writeln!(
        out,
        "\nWhole bearings (kontakt bearing {}, {}):",
        BEARINGS[0].0, BEARINGS[1].0
    )?;
    for r in reports {
        let name = r.name.as_deref().unwrap_or(r.bearing_type);
        match &r.elements {
            BearingElements::Rollers(p) => {
                let rib = p
                    .roller_loads
                    .iter()
                    .map(|w| w.rib_load_n)
                    .fold(0.0, f64::max);
                let eps = r
                    .load_zone_epsilon
                    .map_or_else(String::new, |e| format!(", ε = {e:.3}"));
                writeln!(
                    out,
                    "  {name}: {} rollers{eps}; largest roller load {:.1} N, rib load {rib:.1} N, load per length {:.1} N/mm",
                    p.rollers, p.max_roller_load_n, p.max_load_per_length_n_per_mm
                )?;
            }
            BearingElements::Balls(p) => writeln!(
                out,
                "  {name}: {} balls; largest ball load {:.1} N, Hertz pressure {:.0} MPa inner, {:.0} MPa outer raceway",
                p.balls, p.max_ball_load_n, p.max_inner_pressure_mpa, p.max_outer_pressure_mpa
            )?,
        }
    }
    Ok(())
}
