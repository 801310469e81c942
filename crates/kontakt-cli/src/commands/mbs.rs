//! `kontakt mbs`: the contact element driven through a prescribed motion of one roller
//! against the rib (`kontakt::element::study`): load ramp, tilt and skew at constant rib
//! load, with the Hertz, PimP and half-space back-ends; writes the time series (CSV), plots,
//! and the measured time per evaluation. The computation is the library's; this renders it.

use crate::cli::MbsArgs;
use crate::commands::cannot_write;
use anyhow::Result;
use kontakt::element::study::{MotionSample, roller_rib_motion};
use std::io::Write;

/// Run the subcommand.
pub fn run(args: &MbsArgs, out: &mut impl Write) -> Result<()> {
    std::fs::create_dir_all(&args.out).map_err(|e| cannot_write("create", &args.out, e))?;
    let backends: Vec<&str> = args.backends.iter().map(String::as_str).collect();
    let study = roller_rib_motion(
        &args.pairing,
        args.force,
        args.angle_deg,
        args.rpm,
        args.steps,
        &backends,
    )
    .map_err(|e| {
        e.map_field(|f| {
            match f {
                "force" => "--force",
                "angle_deg" => "--angle-deg",
                "rpm" => "--rpm",
                "steps" => "--steps",
                "pairing" => "--pairing",
                "backends" => "--backends",
                other => other,
            }
            .to_string()
        })
    })?;
    let (samples, timing) = (&study.samples, &study.timing);
    let backends: Vec<&str> = timing.iter().map(|(name, _)| *name).collect();
    // CSV.
    let csv_path = args.out.join("mbs.csv");
    let mut w = crate::commands::CsvFile::create(&csv_path)?;
    for s in samples {
        w.serialize(s)?;
    }
    w.finish()?;
    // Plots: one curve per back-end and phase.
    let curves =
        |phase: &str, f: &dyn Fn(&MotionSample) -> (f64, f64)| -> Vec<(String, Vec<(f64, f64)>)> {
            backends
                .iter()
                .map(|name| {
                    (
                        name.to_string(),
                        samples
                            .iter()
                            .filter(|s| s.backend == *name && s.phase == phase)
                            .map(f)
                            .collect(),
                    )
                })
                .collect()
        };
    let plot =
        |path: &std::path::Path,
         title: &str,
         x: &str,
         y: &str,
         c: &[(String, Vec<(f64, f64)>)],
         log: bool| { crate::render::pairing_plot(path, title, x, y, c, log, false) };
    let dir = &args.out;
    plot(
        &dir.join("mbs_load.png"),
        &format!("{}: approach against rib load", args.pairing),
        "rib load [N]",
        "approach [mm]",
        &curves("load", &|s| (s.force_n, s.approach_mm)),
        false,
    )?;
    for (phase, what) in [("tilt", "tilt"), ("skew", "skew")] {
        plot(
            &dir.join(format!("mbs_{phase}_migration.png")),
            &format!(
                "{}: contact point migration under {what} at {} N",
                args.pairing, args.force
            ),
            &format!("{what} angle [deg]"),
            "contact point migration on the roller face [mm] (signed with the angle)",
            &curves(phase, &|s| {
                (
                    s.angle_deg,
                    s.migration_x_mm.hypot(s.migration_y_mm) * s.angle_deg.signum(),
                )
            }),
            false,
        )?;
        plot(
            &dir.join(format!("mbs_{phase}_pressure.png")),
            &format!(
                "{}: maximum pressure under {what} at {} N",
                args.pairing, args.force
            ),
            &format!("{what} angle [deg]"),
            "max pressure [MPa]",
            &curves(phase, &|s| (s.angle_deg, s.max_pressure_mpa)),
            false,
        )?;
    }
    if args.json {
        serde_json::to_writer_pretty(&mut *out, samples)?;
        writeln!(out)?;
        return Ok(());
    }
    writeln!(
        out,
        "Roller {} against the rib: {} N, tilt and skew ±{}°, {} r/min, Coulomb mu = 0.1",
        args.pairing, args.force, args.angle_deg, args.rpm
    )?;
    writeln!(
        out,
        "  {:<10} {:>12} {:>14} {:>14} {:>14} {:>14} {:>12}",
        "back-end",
        "eval [µs]",
        "p at 0° [MPa]",
        "tilt migr.",
        "skew migr.",
        "p skew [MPa]",
        "P [W]"
    )?;
    writeln!(
        out,
        "  {:<10} {:>12} {:>14} {:>14} {:>14} {:>14} {:>12}",
        "", "", "", "[mm]", "[mm]", "at +angle", "at 0°"
    )?;
    for (name, t) in timing {
        let of = |phase: &str| -> Vec<&MotionSample> {
            samples
                .iter()
                .filter(|s| s.backend == *name && s.phase == phase)
                .collect()
        };
        let (tilt, skew) = (of("tilt"), of("skew"));
        let mid = &tilt[tilt.len() / 2];
        // Distance between the contact points at −angle and +angle, on the roller face.
        let span = |v: &[&MotionSample]| {
            let (a, b) = (v[0], v[v.len() - 1]);
            (b.migration_x_mm - a.migration_x_mm).hypot(b.migration_y_mm - a.migration_y_mm)
        };
        writeln!(
            out,
            "  {:<10} {:>12.1} {:>14.1} {:>14.5} {:>14.5} {:>14.1} {:>12.4}",
            name,
            t,
            mid.max_pressure_mpa,
            span(&tilt),
            span(&skew),
            skew[skew.len() - 1].max_pressure_mpa,
            mid.friction_power_w
        )?;
    }
    writeln!(
        out,
        "Written to {} (mbs.csv: {} samples; mbs_load.png, mbs_tilt_*.png, mbs_skew_*.png)",
        args.out.display(),
        samples.len()
    )?;
    Ok(())
}
