//! `kontakt friction CASE.toml`: friction of the roller-end/rib contact of a tapered roller
//! bearing over a speed sweep (a `method = "friction"` case), as a table, JSON, CSV, plots
//! of the rib torque and the friction coefficient against speed, and maps of the sliding
//! velocity and the friction-power density. The physics is `kontakt_case::run_friction_case`.

use crate::cli::FrictionArgs;
use crate::commands::InputError;
use anyhow::{Context, Result};
use kontakt_case::friction_case::{FrictionMap, FrictionReport};
use kontakt_case::{Case, Outcome};
use kontakt_plot::{FieldMap, LinePlot, LineStyle, PALETTE, Series};
use std::io::Write;
use std::path::Path;

/// Run the subcommand.
pub fn run(args: &FrictionArgs, out: &mut impl Write) -> Result<()> {
    let (label, text) = args.input.read("friction")?;
    let case = Case::from_toml_str(&text).with_context(|| label.clone())?;
    let Outcome::Friction(outcome) = case.run(Path::new(".")).with_context(|| label.clone())?
    else {
        return Err(InputError(format!("{label}: not a friction case")).into());
    };
    let r = &outcome.report;
    if let Some(path) = &args.csv {
        write_csv(path, r)?;
    }
    if let Some(path) = &args.plot {
        write_curves(path, r, Curve::Torque)?;
    }
    if let Some(path) = &args.stribeck {
        write_curves(path, r, Curve::Coefficient)?;
    }
    if let Some(path) = &args.map {
        write_sliding_map(path, &outcome.map, r)?;
    }
    if let Some(path) = &args.density {
        write_density_map(path, &outcome.map, r)?;
    }
    print_report(out, r, args.input.json)
}

/// The report as a table per model, or as pretty JSON.
pub fn print_report(out: &mut impl Write, r: &FrictionReport, json: bool) -> Result<()> {
    if json {
        return crate::output::print_json(out, r);
    }
    let name = crate::output::name_suffix(r.name.as_deref());
    let num = crate::output::Num;
    writeln!(
        out,
        "kontakt {} — roller-end/rib friction{name}",
        r.kontakt_version
    )?;
    writeln!(
        out,
        "  pairing {}, {} rollers of {:.1} g, F_a = {} N{}{}",
        r.pairing,
        r.rollers,
        num(r.roller_mass_kg * 1e3),
        num(r.axial_load_n),
        if r.radial_load_n > 0.0 {
            format!(", F_r = {} N", num(r.radial_load_n))
        } else {
            String::new()
        },
        if r.centrifugal {
            ", centrifugal force included"
        } else {
            ""
        }
    )?;
    match r.viscosity_mpa_s {
        Some(eta) => writeln!(
            out,
            "  lubricated: eta = {:.2} mPa·s at the inlet; mu_b = {}",
            num(eta * 1e9),
            num(r.law.boundary_coefficient)
        )?,
        None => writeln!(
            out,
            "  dry: Coulomb friction, mu = {}",
            num(r.law.boundary_coefficient)
        )?,
    }
    let mut model = "";
    for row in &r.rows {
        if row.model != model {
            model = row.model;
            writeln!(out, "\n  pressure model: {model}")?;
            writeln!(
                out,
                "  {:>8} {:>9} {:>8} {:>9} {:>9} {:>7} {:>8} {:>9} {:>10} {:>10}",
                "n [rpm]",
                "Q_f [N]",
                "p [MPa]",
                "v_s[mm/s]",
                "h_c [µm]",
                "Lambda",
                "mu",
                "P_1 [W]",
                "P_all [W]",
                "M [N·mm]"
            )?;
        }
        let h = row
            .film_central_mm
            .map_or_else(|| "-".to_string(), |h| format!("{:.4}", num(h * 1e3)));
        writeln!(
            out,
            "  {:>8.0} {:>9.3} {:>8.1} {:>9.1} {:>9} {:>7.3} {:>8.5} {:>9.4} {:>10.3} {:>10.2}",
            num(row.speed_rpm),
            num(row.rib_load_n),
            num(row.max_pressure_mpa),
            num(row.sliding_speed_mm_s),
            h,
            num(row.lambda),
            num(row.coefficient),
            num(row.power_w),
            num(row.bearing_power_w),
            num(row.bearing_drag_torque_nmm)
        )?;
    }
    if r.bearing.closed_form {
        writeln!(
            out,
            "\n  M: the rib friction's share of the bearing's drag torque, Z·P_1/|ω_i − ω_o| \
             (bearing_drag_torque_nmm; docs/friction.md §5.2)"
        )?;
    } else {
        writeln!(
            out,
            "\n  M: the rib friction's share of the bearing's drag torque, Σ_j P_j/|ω_i − ω_o| \
             over the rollers (bearing_drag_torque_nmm; docs/friction.md §5.2); Q_f, p, mu, \
             P_1: the most loaded roller"
        )?;
    }
    print_rollers(out, r)?;
    if !r.model_difference.is_empty() {
        writeln!(out, "\n  rib torque relative to Hertz:")?;
        let models: Vec<&str> = {
            let mut m: Vec<&str> = r.model_difference.iter().map(|d| d.model).collect();
            m.dedup();
            m.sort_unstable();
            m.dedup();
            m
        };
        write!(out, "  {:>8}", "n [rpm]")?;
        for m in &models {
            write!(out, " {:>11}", format!("{m}/hertz"))?;
        }
        writeln!(out)?;
        let mut speeds: Vec<f64> = r.model_difference.iter().map(|d| d.speed_rpm).collect();
        speeds.dedup();
        for s in speeds {
            write!(out, "  {:>8.0}", num(s))?;
            for m in &models {
                let d = r
                    .model_difference
                    .iter()
                    .find(|d| d.speed_rpm == s && d.model == *m);
                match d {
                    Some(d) => write!(out, " {:>11.4}", num(d.torque_vs_hertz))?,
                    None => write!(out, " {:>11}", "-")?,
                }
            }
            writeln!(out)?;
        }
    }
    for w in &r.warnings {
        writeln!(out, "  warning: {w}")?;
    }
    Ok(())
}

/// Under a combined load (radial load or moment): the bearing's equilibrium and every
/// roller's rib load, friction force and power for the first model at the middle speed
/// (all of them in `--json`, `roller_table`).
fn print_rollers(out: &mut impl Write, r: &FrictionReport) -> Result<()> {
    let b = &r.bearing;
    if b.closed_form {
        return Ok(());
    }
    let num = crate::output::Num;
    let (Some(u), Some(t), Some(m)) = (b.displacement_mm, b.tilt_rad, b.moment_nmm) else {
        return Ok(());
    };
    writeln!(
        out,
        "\n  bearing: F_r = {} N, F_a = {} N, M_y = {:.1} N·mm ({}); inner ring \
         ({:.4}, {:.4}, {:.4}) µm, tilt ({:.3e}, {:.3e}) rad, load zone eps = {}",
        num(r.radial_load_n),
        num(r.axial_load_n),
        num(m[1]),
        if r.moment_nmm.is_some() {
            "applied, tilt free"
        } else {
            "the shaft's reaction, tilts held"
        },
        num(u[0] * 1e3),
        num(u[1] * 1e3),
        num(u[2] * 1e3),
        t[0],
        t[1],
        b.load_zone
            .map_or_else(|| "-".to_string(), |e| format!("{:.3}", num(e)))
    )?;
    let Some(first) = r.rows.first() else {
        return Ok(());
    };
    let speeds: Vec<f64> = r
        .rows
        .iter()
        .filter(|x| x.model == first.model)
        .map(|x| x.speed_rpm)
        .collect();
    let middle = speeds[speeds.len() / 2];
    writeln!(
        out,
        "  every roller, {} at {:.0} rpm:\n  {:>6} {:>9} {:>10} {:>10} {:>9} {:>9} {:>9}",
        first.model,
        num(middle),
        "roller",
        "psi [deg]",
        "Q_cup [N]",
        "Q_cone [N]",
        "Q_f [N]",
        "F_t [N]",
        "P [W]"
    )?;
    for t in r
        .roller_table
        .iter()
        .filter(|t| t.pressure_model == first.model && t.inner_speed_rpm == middle)
    {
        writeln!(
            out,
            "  {:>6} {:>9.2} {:>10.3} {:>10.3} {:>9.3} {:>9.4} {:>9.4}",
            t.roller,
            num(t.azimuth_deg),
            num(t.cup_load_n),
            num(t.cone_load_n),
            num(t.roller_rib_load_n),
            num(t.friction_force_n),
            num(t.roller_power_w)
        )?;
    }
    Ok(())
}

/// Every row, one line per model and speed, with unit-suffixed columns.
pub fn write_csv(path: &Path, r: &FrictionReport) -> Result<()> {
    let mut w = crate::commands::CsvFile::create(path)?;
    for row in &r.rows {
        w.serialize(row)?;
    }
    w.finish()?;
    Ok(())
}

#[derive(Clone, Copy)]
enum Curve {
    Torque,
    Coefficient,
}

fn write_curves(path: &Path, r: &FrictionReport, curve: Curve) -> Result<()> {
    kontakt_plot::Format::from_path(path).map_err(|e| InputError(e.to_string()))?;
    let mut models: Vec<&str> = r.rows.iter().map(|row| row.model).collect();
    models.dedup();
    let points: Vec<Vec<(f64, f64)>> = models
        .iter()
        .map(|m| {
            r.rows
                .iter()
                .filter(|row| row.model == *m)
                .map(|row| {
                    let y = match curve {
                        Curve::Torque => row.bearing_drag_torque_nmm,
                        Curve::Coefficient => row.coefficient,
                    };
                    (row.speed_rpm, y)
                })
                .collect()
        })
        .collect();
    let series: Vec<Series> = models
        .iter()
        .enumerate()
        .map(|(i, m)| {
            let (color, style) = model_style(m);
            Series {
                label: m,
                points: &points[i],
                color,
                style,
            }
        })
        .collect();
    let (what, y_label) = match curve {
        Curve::Torque => (
            "rib friction torque",
            "rib drag torque of the bearing [N·mm]",
        ),
        Curve::Coefficient => ("friction coefficient", COEFFICIENT_LABEL),
    };
    let title = format!(
        "{}: {what}, Fₐ = {} N",
        r.name.as_deref().unwrap_or(&r.pairing),
        r.axial_load_n
    );
    kontakt_plot::line_plot(
        path,
        &LinePlot {
            title: &title,
            x_label: "inner ring speed [r/min] (log scale)",
            y_label,
            series: &series,
            x_log: true,
            y_from_zero: true,
        },
        (900, 600),
    )
    .with_context(|| format!("drawing {}", path.display()))
}

/// The y label of the friction coefficient (plain words: no `Q_f` with a literal
/// underscore).
const COEFFICIENT_LABEL: &str = "μ = friction force / rib load [-]";

/// Colour and line style of a pressure model's curve, the same on every plot; the styles
/// differ so that curves that lie on each other (the models agree to 0.03 % on a Hertzian
/// pairing) stay visible: a solid line, dashes over it and dots at the speeds.
fn model_style(model: &str) -> ((u8, u8, u8), LineStyle) {
    match model {
        "hertz" => (PALETTE[0], LineStyle::Solid),
        "pimp" => (PALETTE[1], LineStyle::Dashed),
        _ => (PALETTE[2], LineStyle::Markers),
    }
}

fn field_map<'a>(
    m: &'a FrictionMap,
    values: &'a [f64],
    title: &'a str,
    colorbar_label: &'a str,
    (axes, max_marker): (&'a (String, String), &'a str),
) -> FieldMap<'a> {
    FieldMap {
        max_marker: Some(max_marker),
        ..crate::render::grid_map(&m.field.grid, values, title, axes, colorbar_label)
    }
}

/// The map axes' names by their direction in the bearing.
fn axis_names(m: &FrictionMap) -> (String, String) {
    use crate::render::axis_name;
    (axis_name(m.axes[0]), axis_name(m.axes[1]))
}

/// The friction-power density τ · v_s per cell over the contact.
fn write_density_map(path: &Path, m: &FrictionMap, r: &FrictionReport) -> Result<()> {
    kontakt_plot::Format::from_path(path).map_err(|e| InputError(e.to_string()))?;
    let title = format!(
        "{}: friction power density, {} at {:.0} r/min (P = {:.3} W per roller)",
        r.pairing,
        m.model.as_str(),
        m.speed_rpm,
        m.result.power
    );
    let max = m.power_density.iter().copied().fold(0.0f64, f64::max);
    let (factor, unit) = crate::render::power_density_unit(max);
    let values: Vec<f64> = m.power_density.iter().map(|d| d * factor).collect();
    let max = format!("maximum {} {unit}", three_digits(max * factor));
    let label = format!("shear stress × sliding speed [{unit}]");
    let axes = axis_names(m);
    kontakt_plot::field_map(
        path,
        &field_map(m, &values, &title, &label, (&axes, &max)),
        (900, 640),
    )
    .with_context(|| format!("drawing {}", path.display()))
}

/// `x` with three significant digits (34.5, 345, 3.45).
fn three_digits(x: f64) -> String {
    let decimals = if x >= 100.0 {
        0
    } else if x >= 10.0 {
        1
    } else {
        2
    };
    format!("{x:.decimals$}")
}

/// The sliding velocity as arrows over the pressure map.
fn write_sliding_map(path: &Path, m: &FrictionMap, r: &FrictionReport) -> Result<()> {
    kontakt_plot::Format::from_path(path).map_err(|e| InputError(e.to_string()))?;
    let title = format!(
        "{}: pressure and sliding velocity, {} at {:.0} r/min",
        r.pairing,
        m.model.as_str(),
        m.speed_rpm
    );
    let (arrows, label) = sliding_arrows(m);
    let max = crate::render::max_label(&m.field.pressure);
    let axes = axis_names(m);
    kontakt_plot::field_map_with_arrows(
        path,
        &field_map(
            m,
            &m.field.pressure,
            &title,
            "pressure [MPa]",
            (&axes, &max),
        ),
        &arrows,
        &label,
        (900, 640),
    )
    .with_context(|| format!("drawing {}", path.display()))
}

/// Arrows of the sliding velocity on a coarse lattice over the loaded cells, scaled so the
/// longest is 1.5 lattice spacings; the label states the scale.
fn sliding_arrows(m: &FrictionMap) -> (Vec<kontakt_plot::Arrow>, String) {
    let g = &m.field.grid;
    let every = (g.nx().max(g.ny()) / 12).max(1);
    let mut raw = Vec::new();
    for j in (every / 2..g.ny()).step_by(every) {
        for i in (every / 2..g.nx()).step_by(every) {
            if m.field.pressure[j * g.nx() + i] > 0.0 {
                let (x, y) = (g.x(i), g.y(j));
                let [vx, vy] = m.sliding.sliding_at(x, y);
                raw.push((x, y, vx, vy));
            }
        }
    }
    let vmax = raw
        .iter()
        .map(|(_, _, vx, vy)| vx.hypot(*vy))
        .fold(0.0f64, f64::max);
    let spacing = every as f64 * g.dx().min(g.dy());
    let scale = if vmax > 0.0 {
        1.5 * spacing / vmax
    } else {
        0.0
    };
    let arrows = raw
        .into_iter()
        .map(|(x, y, vx, vy)| kontakt_plot::Arrow {
            x: x - 0.5 * vx * scale,
            y: y - 0.5 * vy * scale,
            dx: vx * scale,
            dy: vy * scale,
        })
        .collect();
    let label = if scale > 0.0 {
        format!(
            "sliding velocity of the roller on the rib: 1 mm = {:.0} mm/s (max {:.0} mm/s)",
            1.0 / scale,
            vmax
        )
    } else {
        "no sliding".to_string()
    };
    (arrows, label)
}

/// One pairing's line of the demo's friction summary.
pub struct DemoSummary {
    /// Pairing name.
    pub pairing: String,
    /// Speeds \[r/min\] of the columns.
    pub speeds: Vec<f64>,
    /// Rib torque \[N·mm\] per model (hertz, pimp, halfspace) at those speeds.
    pub torque: [Vec<f64>; 3],
}

/// The demo's friction study: the case of `examples/rib_friction.toml` on each pairing of
/// Wirsching et al. (2020) Table 1, with the three pressure models; writes
/// `friction.csv`, the torque and Stribeck plots of PimP, the model-ratio plot and the
/// sliding-velocity and power-density maps of one curved zone, and returns the summary.
pub fn demo_study(
    out_dir: &Path,
    md: &mut String,
    written: &mut crate::render::Written,
) -> Result<Vec<DemoSummary>> {
    use kontakt_case::friction_case::{FrictionCase, run_friction_case};
    let base: FrictionCase =
        match Case::from_toml_str(include_str!("../../../../examples/rib_friction.toml"))? {
            Case::Friction(c) => *c,
            _ => {
                return Err(
                    InputError("examples/rib_friction.toml: not a friction case".into()).into(),
                );
            }
        };
    let csv_path = out_dir.join("friction.csv");
    let mut w = crate::commands::CsvFile::create(&csv_path)?;
    let mut summary = Vec::new();
    let mut torque_curves: Vec<(String, Vec<(f64, f64)>)> = Vec::new();
    let mut mu_curves: Vec<(String, Vec<(f64, f64)>)> = Vec::new();
    let mut ratio_curves: Vec<(String, Vec<(f64, f64)>)> = Vec::new();
    let map_pairing = "torus-cone-28";
    let mut last = None;
    for &(name, ..) in kontakt::bearing::TABLE1.iter() {
        let mut case = base.clone();
        case.name = Some(name.to_string());
        case.models = vec![
            kontakt::bearing::PressureModel::Pimp,
            kontakt::bearing::PressureModel::Hertz,
            kontakt::bearing::PressureModel::HalfSpace,
        ];
        if let kontakt_case::pimp_case::GeometrySpec::RollerRib { pairing, .. } = &mut case.geometry
        {
            *pairing = Some(name.to_string());
        }
        let outcome =
            run_friction_case(&case).with_context(|| format!("friction study, {name}"))?;
        let r = &outcome.report;
        for row in &r.rows {
            w.serialize(row)?;
        }
        let of = |m: &str, f: &dyn Fn(&kontakt_case::friction_case::FrictionRow) -> f64| {
            r.rows
                .iter()
                .filter(|x| x.model == m)
                .map(|x| (x.speed_rpm, f(x)))
                .collect::<Vec<_>>()
        };
        torque_curves.push((name.to_string(), of("pimp", &|x| x.bearing_drag_torque_nmm)));
        mu_curves.push((name.to_string(), of("pimp", &|x| x.coefficient)));
        ratio_curves.push((
            name.to_string(),
            r.model_difference
                .iter()
                .filter(|d| d.model == "pimp")
                .map(|d| (d.speed_rpm, d.torque_vs_hertz))
                .collect(),
        ));
        let speeds: Vec<f64> = r
            .rows
            .iter()
            .filter(|x| x.model == "hertz")
            .map(|x| x.speed_rpm)
            .collect();
        let torque = ["hertz", "pimp", "halfspace"].map(|m| {
            r.rows
                .iter()
                .filter(|x| x.model == m)
                .map(|x| x.bearing_drag_torque_nmm)
                .collect()
        });
        summary.push(DemoSummary {
            pairing: name.to_string(),
            speeds,
            torque,
        });
        if name == map_pairing {
            write_sliding_map(&out_dir.join("friction_sliding.png"), &outcome.map, r)?;
            write_density_map(&out_dir.join("friction_density.png"), &outcome.map, r)?;
            written.friction_maps.push("friction_sliding.png".into());
            written.friction_maps.push("friction_density.png".into());
        }
        last = Some(outcome.report);
    }
    w.finish()?;
    written.tables.push("friction.csv".into());
    let mut plot = |file: &str,
                    title: &str,
                    y_label: &str,
                    curves: &[(String, Vec<(f64, f64)>)],
                    from_zero: bool| {
        crate::render::pairing_plot(
            &out_dir.join(file),
            title,
            "inner ring speed [r/min] (log scale)",
            y_label,
            curves,
            true,
            from_zero,
        )?;
        written.plots.push(file.to_string());
        Ok::<(), anyhow::Error>(())
    };
    let fa = base.load.axial_n;
    plot(
        "friction_torque.png",
        &format!("Rib friction torque of the bearing, PimP, Fₐ = {fa} N"),
        "rib drag torque [N·mm]",
        &torque_curves,
        true,
    )?;
    plot(
        "friction_coefficient.png",
        &format!("Rib friction coefficient (Stribeck), PimP, Fₐ = {fa} N"),
        COEFFICIENT_LABEL,
        &mu_curves,
        true,
    )?;
    plot(
        "friction_model_ratio.png",
        "Rib torque, PimP over Hertz",
        "torque ratio PimP / Hertz [-]",
        &ratio_curves,
        false,
    )?;
    let law = last.map(|r| r.law);
    md.push_str(&format!(
        "\n## Rib friction against speed\n\nThe case of `examples/rib_friction.toml` (F_a = {fa} N \
         axial, 17 rollers, ISO VG 68 at 70 °C, sigma = 0.2 µm on both surfaces, mixed friction \
         with mu_b = {}, centrifugal force included) on every pairing, with the pressure from \
         Hertz, PimP and the half-space solver (`kontakt friction examples/rib_friction.toml`). \
         Every row: [friction.csv](friction.csv).\n\n\
         ![rib torque](friction_torque.png)\n\n![Stribeck curve](friction_coefficient.png)\n\n\
         ![PimP over Hertz](friction_model_ratio.png)\n\n",
        law.map_or(0.0, |l| l.boundary_coefficient)
    ));
    md.push_str("| pairing | n [r/min] | M Hertz [N·mm] | M PimP [N·mm] | M half-space [N·mm] | PimP / Hertz | half-space / Hertz |\n|---|---|---|---|---|---|---|\n");
    for s in &summary {
        for i in [0, s.speeds.len() / 2, s.speeds.len() - 1] {
            let [h, p, b] = [&s.torque[0], &s.torque[1], &s.torque[2]].map(|t| t[i]);
            md.push_str(&format!(
                "| {} | {:.0} | {h:.1} | {p:.1} | {b:.1} | {:.4} | {:.4} |\n",
                s.pairing,
                s.speeds[i],
                p / h,
                b / h
            ));
        }
    }
    md.push_str(&format!(
        "\nSliding velocity of the roller on the rib over the PimP pressure of {map_pairing} \
         (a curved zone) and the friction-power density (shear stress times sliding speed):\n\n\
         ![sliding velocity](friction_sliding.png)\n\n![power density](friction_density.png)\n"
    ));
    Ok(summary)
}
