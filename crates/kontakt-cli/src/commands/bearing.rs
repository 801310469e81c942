//! `kontakt bearing CASE.toml`: the load distribution of a whole roller or ball bearing (a
//! `method = "bearing"` case): ring displacement and tilt, the load of every roller or
//! ball (with the slices of the most loaded roller, the contact angle and Hertz pressures
//! of every ball) and the 5 × 5 stiffness matrix, as a table, JSON and a per-element CSV,
//! and plots of the load distribution and of the slices (drawn by `bearing_plot`). The
//! physics is `kontakt_case::run_bearing_case`.

use crate::cli::BearingArgs;
pub use crate::commands::bearing_plot::{
    write_element_plot, write_load_plot, write_slice_map, write_slice_plot,
};
use crate::output::Num;
use anyhow::{Context, Result};
use kontakt_case::bearing_case::{BallPart, BearingElements, BearingSpec, RollerPart};
use kontakt_case::bearing_rating::RatingReport;
use kontakt_case::{BearingCase, BearingReport, run_bearing_case};
use std::io::Write;
use std::path::Path;

/// Run the subcommand.
pub fn run(args: &BearingArgs, out: &mut impl Write) -> Result<()> {
    let (label, text) = args.input.read("bearing")?;
    let case = BearingCase::from_toml_str(&text).with_context(|| label.clone())?;
    if let Some(flag) = [(&args.slice_plot, "--slice-plot"), (&args.map, "--map")]
        .iter()
        .find_map(|(p, flag)| p.as_ref().map(|_| *flag))
        && matches!(
            case.bearing,
            BearingSpec::DeepGrooveBall(_) | BearingSpec::AngularContactBall(_)
        )
    {
        return Err(crate::commands::InputError(format!(
            "{flag}: {label} is a ball bearing; it has no slices along a roller to draw (use --plot or --element-plot for the ball loads)"
        ))
        .into());
    }
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
    if let Some(path) = &args.element_plot {
        write_element_plot(path, &report)?;
    }
    if let Some(path) = &args.map {
        write_slice_map(path, &report)?;
    }
    print_report(out, &report, args.input.json)
}

/// The report as text or as pretty JSON.
pub fn print_report(out: &mut impl Write, r: &BearingReport, json: bool) -> Result<()> {
    if json {
        return crate::output::print_json(out, r);
    }
    let name = crate::output::name_suffix(r.name.as_deref());
    match &r.elements {
        BearingElements::Rollers(p) => roller_header(out, r, p, &name)?,
        BearingElements::Balls(p) => ball_header(out, r, p, &name)?,
    }
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
    match &r.elements {
        BearingElements::Rollers(p) => roller_table(out, r, p)?,
        BearingElements::Balls(p) => ball_table(out, r, p)?,
    }
    rating_lines(out, &r.rating)?;
    if let Some(f) = &r.friction {
        writeln!(out)?;
        for line in f.lines() {
            writeln!(out, "  {line}")?;
        }
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

fn roller_header(
    out: &mut impl Write,
    r: &BearingReport,
    p: &RollerPart,
    name: &str,
) -> Result<()> {
    writeln!(
        out,
        "kontakt {} — {} roller bearing{name}",
        r.kontakt_version, r.bearing_type
    )?;
    let angles = if r.bearing_type == "tapered" {
        format!(
            ", cup {:.2} deg, cone {:.2} deg",
            Num(p.contact_angle_deg),
            Num(p.cone_angle_deg)
        )
    } else {
        String::new()
    };
    let model = if p.pressure.is_some() {
        "coupled slices: half-space strips, ISO/TS 16281 mean approach"
    } else if p.roller_model.is_some() {
        "ISO/TS 16281 slice law per raceway, rollers in their own balance"
    } else {
        "ISO/TS 16281 slice law"
    };
    writeln!(
        out,
        "  {} rollers × {} slices{angles} ({model})",
        p.rollers, p.slices
    )?;
    Ok(())
}

fn ball_header(out: &mut impl Write, r: &BearingReport, p: &BallPart, name: &str) -> Result<()> {
    writeln!(
        out,
        "kontakt {} — {} bearing{name}",
        r.kontakt_version,
        r.bearing_type.replace('_', " ")
    )?;
    writeln!(
        out,
        "  {} balls, free contact angle {:.2} deg, K_n = {:.1} N/mm^1.5 (Hertz point contacts)",
        p.balls,
        Num(p.free_contact_angle_deg),
        Num(p.ball_stiffness_n_per_mm1_5)
    )?;
    Ok(())
}

fn roller_table(out: &mut impl Write, r: &BearingReport, p: &RollerPart) -> Result<()> {
    let eps = r
        .load_zone_epsilon
        .map_or_else(|| "-".to_string(), |e| format!("{:.4}", Num(e)));
    writeln!(
        out,
        "  load zone ε = {eps}; largest roller load {:.1} N, largest load per length {:.1} N/mm",
        Num(p.max_roller_load_n),
        Num(p.max_load_per_length_n_per_mm)
    )?;
    if p.roller_model.is_some() {
        return crate::commands::bearing_rib::rib_roller_table(out, p);
    }
    writeln!(out)?;
    writeln!(
        out,
        "  {:>6} {:>10} {:>10} {:>10} {:>10} {:>12} {:>10} {:>10}",
        "ψ deg",
        "Q_in N",
        "Q_out N",
        "Q_rib N",
        "q_max N/mm",
        "approach mm",
        "p_in MPa",
        "p_out MPa"
    )?;
    for row in &p.roller_loads {
        writeln!(
            out,
            "  {:>6.1} {:>10.1} {:>10.1} {:>10.1} {:>10.1} {:>12.6} {:>10.0} {:>10.0}",
            Num(row.azimuth_deg),
            Num(row.inner_load_n),
            Num(row.outer_load_n),
            Num(row.rib_load_n),
            Num(row.max_load_per_length_n_per_mm),
            Num(row.approach_mm),
            Num(row.inner_max_pressure_mpa),
            Num(row.outer_max_pressure_mpa)
        )?;
    }
    if let Some(all) = &p.pressure {
        let (pmax, inner) = (
            all.max_pressure_mpa,
            &p.most_loaded_roller.inner_pressure_mpa,
        );
        let (first, last) = (inner[0], inner[inner.len() - 1]);
        let centre = inner[inner.len() / 2];
        writeln!(out)?;
        writeln!(
            out,
            "  largest slice pressure {:.0} MPa; most loaded roller, inner raceway: {:.0} MPa at the centre, {:.0} / {:.0} MPa at the end slices (every slice in --json: slice_pressure_mpa)",
            Num(pmax),
            Num(centre),
            Num(first),
            Num(last)
        )?;
    }
    Ok(())
}

fn ball_table(out: &mut impl Write, r: &BearingReport, p: &BallPart) -> Result<()> {
    let eps = r
        .load_zone_epsilon
        .map_or_else(|| "-".to_string(), |e| format!("{:.4}", Num(e)));
    writeln!(
        out,
        "  load zone ε = {eps}; largest ball load {:.1} N; largest Hertz pressure {:.0} MPa inner, {:.0} MPa outer raceway",
        Num(p.max_ball_load_n),
        Num(p.max_inner_pressure_mpa),
        Num(p.max_outer_pressure_mpa)
    )?;
    writeln!(out)?;
    if let Some([ni, no]) = r.ring_speeds_rpm {
        return ball_speed_table(out, p, [ni, no]);
    }
    writeln!(
        out,
        "  {:>6} {:>10} {:>8} {:>12} {:>10} {:>10}",
        "ψ deg", "Q N", "α deg", "approach mm", "p_in MPa", "p_out MPa"
    )?;
    for row in &p.ball_loads {
        writeln!(
            out,
            "  {:>6.1} {:>10.1} {:>8.2} {:>12.6} {:>10.0} {:>10.0}",
            Num(row.azimuth_deg),
            Num(row.load_n),
            Num(row.contact_angle_deg),
            Num(row.approach_mm),
            Num(row.inner_max_pressure_mpa),
            Num(row.outer_max_pressure_mpa)
        )?;
    }
    Ok(())
}

/// The balls at speed: both contacts' loads and angles, the centrifugal force and the
/// gyroscopic moment.
fn ball_speed_table(out: &mut impl Write, p: &BallPart, rpm: [f64; 2]) -> Result<()> {
    writeln!(
        out,
        "  speed: inner ring {:.0} r/min, outer ring {:.0} r/min; {}-race control (Jones 1960)",
        Num(rpm[0]),
        Num(rpm[1]),
        p.race_control.unwrap_or("outer")
    )?;
    writeln!(
        out,
        "  {:>6} {:>10} {:>10} {:>8} {:>8} {:>8} {:>10} {:>9} {:>9}",
        "ψ deg",
        "Q_in N",
        "Q_out N",
        "α_in°",
        "α_out°",
        "F_c N",
        "M_g N mm",
        "p_in MPa",
        "p_out MPa"
    )?;
    for row in &p.ball_loads {
        writeln!(
            out,
            "  {:>6.1} {:>10.1} {:>10.1} {:>8.2} {:>8.2} {:>8.1} {:>10.1} {:>9.0} {:>9.0}",
            Num(row.azimuth_deg),
            Num(row.inner_load_n),
            Num(row.outer_load_n),
            Num(row.inner_contact_angle_deg),
            Num(row.outer_contact_angle_deg),
            Num(row.centrifugal_force_n),
            Num(row.gyroscopic_moment_nmm),
            Num(row.inner_max_pressure_mpa),
            Num(row.outer_max_pressure_mpa)
        )?;
    }
    Ok(())
}

/// The static safety and the lives of the report's `rating`.
fn rating_lines(out: &mut impl Write, r: &RatingReport) -> Result<()> {
    writeln!(out)?;
    let s0 = r
        .static_safety_from_pressure
        .map_or_else(|| "-".to_string(), |s| format!("{:.3}", Num(s)));
    let mut line = format!(
        "  static safety: {s0} from the largest pressure {:.0} MPa (ISO 76 limit {:.0} MPa)",
        Num(r.max_pressure_mpa),
        Num(r.pressure_limit_mpa)
    );
    if let (Some(s), Some(p0)) = (r.static_safety, r.equivalent_static_load_n) {
        line += &format!("; C0/P0 = {:.3} (P0 = {:.1} N)", Num(s), Num(p0));
    }
    writeln!(out, "{line}")?;
    let mut lives = Vec::new();
    if let (Some(l), Some(p)) = (r.l10_mrev, r.equivalent_dynamic_load_n) {
        lives.push(format!(
            "L10 = {:.1} Mrev (ISO 281, P = {:.1} N)",
            Num(l),
            Num(p)
        ));
    }
    if let (Some(l), Some(p)) = (r.l10r_mrev, r.reference_load_n) {
        lives.push(format!(
            "L10r = {:.1} Mrev (ISO/TS 16281, P_ref = {:.1} N)",
            Num(l),
            Num(p)
        ));
    }
    if !lives.is_empty() {
        writeln!(out, "  life:          {}", lives.join("; "))?;
    }
    Ok(())
}

/// `x` for the table, with round-off below 1e-9 of the group's largest magnitude `scale`
/// shown as 0 (a 1e-13 N reaction of a symmetric load); the JSON keeps the raw numbers.
fn clean(x: f64, scale: f64) -> Num {
    Num(if x.abs() < 1e-9 * scale { 0.0 } else { x })
}

/// One row per roller or ball: the report's `roller_loads` or `ball_loads` keys; with a
/// friction section, its per-roller (or per-ball) table too, in `<stem>.friction.csv`
/// beside `path`, and a speed, load or temperature sweep's rows in
/// `<stem>.friction_sweep.csv`.
pub fn write_csv(path: &Path, r: &BearingReport) -> Result<()> {
    if let Some(f) = &r.friction {
        let friction_path = path.with_extension("friction.csv");
        let mut w = crate::commands::CsvFile::create(&friction_path)?;
        for row in &f.rollers {
            w.serialize(row)?;
        }
        // A ball bearing's friction rows (its `rollers` are empty).
        for row in &f.balls {
            w.serialize(row)?;
        }
        w.finish()?;
        // a speed, load or temperature sweep: one row per point in <stem>.friction_sweep.csv
        if let Some((_, rows)) = f.sweep_rows() {
            let sweep_path = path.with_extension("friction_sweep.csv");
            let mut w = crate::commands::CsvFile::create(&sweep_path)?;
            for row in rows {
                w.serialize(row)?;
            }
            w.finish()?;
        }
    }
    let mut w = crate::commands::CsvFile::create(path)?;
    match &r.elements {
        BearingElements::Rollers(p) => {
            for row in &p.roller_loads {
                w.serialize(row)?;
            }
        }
        BearingElements::Balls(p) => {
            for row in &p.ball_loads {
                w.serialize(row)?;
            }
        }
    }
    w.finish()
}
