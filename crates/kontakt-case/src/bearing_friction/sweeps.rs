//! Friction sweeps against load and temperature (issue 29 §2: a Stribeck-like curve), beside
//! the speed sweep `operating.sweep_inner_rpm` of [`super::friction_report`]:
//!
//! - `operating.sweep_axial_n`: the axial force `load.force_n[2]` \[N\] at each point,
//!   the rest of `[load]` as given; `friction.axial_load_sweep`;
//! - `operating.sweep_radial_n`: the radial force magnitude \[N\] at each point, along the
//!   direction of the case's radial force (`load.force_n[0..2]`; +x when it is zero);
//!   `friction.radial_load_sweep`;
//! - `operating.sweep_temperature_c`: the oil temperature `lubricant.temperature_c` \[°C\]
//!   at each point, the viscosity from the lubricant's own data (ν40/ν100 or ISO VG, the
//!   Walther line) there; `friction.temperature_sweep`.
//!
//! A load sweep re-solves the load distribution at every point with the case's own bearing
//! model (the planned solver of [`crate::BearingModel`], each point warm-started from the
//! last equilibrium); a temperature sweep keeps the load distribution of `[load]` (the
//! load distribution does not depend on the oil). Every point goes through the one
//! validity check ([`crate::validity::checked`]) as the main report does; its warnings
//! that the main point does not already carry join `friction.warnings`, prefixed with the
//! sweep key and value. One sweep at a time: two of the four sweep keys together are an
//! error naming both.
//!
//! Units: N, °C, r/min, N·mm, W.

use super::{FrictionReport, FrictionSweepRow, OperatingSpec};
use crate::bearing_case::{BearingCase, BearingLoadSpec, BearingReport, Planned, solve_planned};
use kontakt::{Error, Result};

/// Most points of a sweep (as `operating.sweep_inner_rpm`).
pub const MAX_SWEEP_POINTS: usize = 10_000;

impl FrictionReport {
    /// The rollers that carry load on a raceway (cone or cup load > 0), or a ball bearing's
    /// balls in the load zone (inner load > 0: at speed every ball presses on the outer
    /// race by its centrifugal force).
    pub fn loaded_rollers(&self) -> usize {
        let balls = self.balls.iter().filter(|b| b.inner_load_n > 0.0).count();
        self.rollers
            .iter()
            .filter(|r| r.cup_load_n > 0.0 || r.cone_load_n > 0.0)
            .count()
            + balls
    }

    /// This point as a sweep row at the loads `force` \[N\].
    pub(crate) fn state_row(&self, force: [f64; 3]) -> FrictionSweepRow {
        let c = &self.catalogue;
        FrictionSweepRow {
            axial_load_n: force[2],
            radial_load_n: force[0].hypot(force[1]),
            inner_rpm: self.inner_rpm,
            temperature_c: self.temperature_c,
            viscosity_mm2_s: self.viscosity_mm2_s,
            total_nmm: self.total_nmm,
            cone_nmm: self.cone_rolling_nmm + self.cone_sliding_nmm,
            cup_nmm: self.cup_rolling_nmm + self.cup_sliding_nmm,
            rib_nmm: self.rib_nmm,
            drag_nmm: self.drag_nmm,
            power_w: self.power_w,
            coefficient: self.coefficient,
            min_lambda: self.min_lambda,
            loaded_rollers: self.loaded_rollers(),
            skf_total_nmm: c.skf_total_nmm,
            aihara_nmm: c.aihara_total_nmm.or(c.aihara_rolling_nmm),
            schaeffler_nmm: c.schaeffler_total_nmm.or(c.schaeffler_m0_nmm),
        }
    }

    /// The rows of the case's one sweep (speed, load or temperature) and its case key, if
    /// any.
    pub fn sweep_rows(&self) -> Option<(&'static str, &[FrictionSweepRow])> {
        if self.speed_sweep.is_empty() {
            self.state_sweep()
        } else {
            Some((SweepKind::Speed.key(), self.speed_sweep.as_slice()))
        }
    }

    /// The load or temperature sweep's rows and its case key, if any.
    pub fn state_sweep(&self) -> Option<(&'static str, &[FrictionSweepRow])> {
        [
            ("operating.sweep_axial_n", &self.axial_load_sweep),
            ("operating.sweep_radial_n", &self.radial_load_sweep),
            ("operating.sweep_temperature_c", &self.temperature_sweep),
        ]
        .into_iter()
        .find(|(_, rows)| !rows.is_empty())
        .map(|(k, rows)| (k, rows.as_slice()))
    }
}

/// What a sweep runs over.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum SweepKind {
    /// `sweep_inner_rpm`.
    Speed,
    /// `sweep_axial_n`.
    Axial,
    /// `sweep_radial_n`.
    Radial,
    /// `sweep_temperature_c`.
    Temperature,
}

impl SweepKind {
    /// The case key.
    pub(crate) fn key(self) -> &'static str {
        match self {
            SweepKind::Speed => "operating.sweep_inner_rpm",
            SweepKind::Axial => "operating.sweep_axial_n",
            SweepKind::Radial => "operating.sweep_radial_n",
            SweepKind::Temperature => "operating.sweep_temperature_c",
        }
    }
}

/// The one sweep of `op` with its values, checked: 1 to [`MAX_SWEEP_POINTS`] finite
/// values (radial forces ≥ 0), one sweep key at most.
///
/// # Errors
/// [`Error::InvalidInput`] naming the sweep key (`operating.sweep_radial_n`), or
/// `operating` naming both keys of two sweeps.
pub(crate) fn sweep_of(op: &OperatingSpec) -> Result<Option<(SweepKind, &[f64])>> {
    let given: Vec<(SweepKind, &[f64])> = [
        (SweepKind::Speed, op.sweep_inner_rpm.as_deref()),
        (SweepKind::Axial, op.sweep_axial_n.as_deref()),
        (SweepKind::Radial, op.sweep_radial_n.as_deref()),
        (SweepKind::Temperature, op.sweep_temperature_c.as_deref()),
    ]
    .into_iter()
    .filter_map(|(k, v)| v.map(|v| (k, v)))
    .collect();
    if given.len() > 1 {
        return Err(Error::invalid(
            "operating",
            format!("{} and {}", given[0].0.key(), given[1].0.key()),
            "one sweep at a time (sweep_inner_rpm, sweep_axial_n, sweep_radial_n or sweep_temperature_c)",
        ));
    }
    let Some(&(kind, values)) = given.first() else {
        return Ok(None);
    };
    if values.is_empty() || values.len() > MAX_SWEEP_POINTS {
        let unit = match kind {
            SweepKind::Speed => "speeds in r/min",
            SweepKind::Axial | SweepKind::Radial => "forces in N",
            SweepKind::Temperature => "temperatures in °C",
        };
        return Err(Error::invalid(
            kind.key(),
            format!("{} values", values.len()),
            format!("1 to {MAX_SWEEP_POINTS} {unit}"),
        ));
    }
    for &v in values {
        let ok = v.is_finite() && (kind != SweepKind::Radial || v >= 0.0);
        if !ok && kind != SweepKind::Speed {
            let range = match kind {
                SweepKind::Radial => "finite radial forces >= 0 N",
                SweepKind::Axial => "finite axial forces in N (Fz, the sign of load.force_n[2])",
                _ => "finite temperatures in °C",
            };
            return Err(Error::invalid(kind.key(), v, range));
        }
    }
    Ok(Some((kind, values)))
}

/// The temperature sweep of [`super::friction_report`]: `at(t)` is the friction at the oil
/// temperature `t` \[°C\] on the solved load distribution; an error of the lubricant at `t`
/// names `operating.sweep_temperature_c`.
///
/// # Errors
/// Those of `at`, renamed.
pub(super) fn temperature_sweep(
    report: &mut FrictionReport,
    temperatures: &[f64],
    force: [f64; 3],
    mut at: impl FnMut(f64) -> Result<FrictionReport>,
) -> Result<()> {
    let key = SweepKind::Temperature.key();
    for &t in temperatures {
        let p = at(t).map_err(|e| {
            e.map_field(|f| match f {
                "lubricant.temperature_c" => key.to_string(),
                other => other.to_string(),
            })
        })?;
        merge_warnings(&mut report.warnings, &[], &p.warnings, key, t, "°C");
        report.temperature_sweep.push(p.state_row(force));
    }
    Ok(())
}

/// The load sweeps of a solved bearing case: with `operating.sweep_axial_n` or
/// `sweep_radial_n`, re-solve `planned` (the solver that has just solved `load`) at every
/// point, warm-started from the last equilibrium, and write the rows into
/// `report.friction`. Without a load sweep: nothing.
///
/// A point whose solve fails (a load the bearing cannot carry, no convergence, a refusal
/// of the validity check) is left out with a warning naming its value and the error.
///
/// # Errors
/// [`Error::InvalidInput`] naming the sweep key for a swept force on a degree of freedom
/// the case's own `[load]` holds at a displacement.
pub(crate) fn load_sweep(
    case: &BearingCase,
    label: &'static str,
    planned: &mut Planned,
    load: &BearingLoadSpec,
    report: &mut BearingReport,
) -> Result<()> {
    let Some(op) = &case.operating else {
        return Ok(());
    };
    let Some((kind, values)) = sweep_of(op)? else {
        return Ok(());
    };
    if !matches!(kind, SweepKind::Axial | SweepKind::Radial) {
        return Ok(());
    }
    let key = kind.key();
    // a swept force on a displacement-controlled degree of freedom: the case's own [load]
    // is a conflict in the file (an error); a solve's load that prescribes it (a
    // BearingModel solve, the element's way of driving the bearing) skips the sweep
    let axial = kind == SweepKind::Axial;
    let held = |l: &BearingLoadSpec| {
        let p = &l.prescribed;
        if axial {
            p.dz_mm.is_some()
        } else {
            p.dx_mm.is_some() || p.dy_mm.is_some()
        }
    };
    let names = if axial {
        "load.prescribed.dz_mm"
    } else {
        "load.prescribed.dx_mm or dy_mm"
    };
    if held(&case.load) {
        return Err(Error::invalid(
            key,
            format!("given with {names}"),
            format!("a force-controlled direction: remove {names} or the sweep"),
        ));
    }
    if held(load) {
        if let Some(f) = report.friction.as_mut() {
            f.warnings.push(format!(
                "{key} not run: this solve's load holds the displacement ({names})"
            ));
        }
        return Ok(());
    }
    // the case of every point: the same, without the sweep (no recursion)
    let mut point_case = case.clone();
    if let Some(o) = point_case.operating.as_mut() {
        o.sweep_axial_n = None;
        o.sweep_radial_n = None;
    }
    let [fx, fy, _] = load.force_n;
    let m = fx.hypot(fy);
    let dir = if m > 0.0 {
        [fx / m, fy / m]
    } else {
        [1.0, 0.0]
    };
    let mut start = warm_start(report);
    let base_warnings: Vec<String> = report
        .warnings
        .iter()
        .chain(report.friction.iter().flat_map(|f| f.warnings.iter()))
        .cloned()
        .collect();
    let unit = "N";
    let mut rows = Vec::with_capacity(values.len());
    let mut new_warnings = Vec::new();
    for &v in values {
        let mut l = *load;
        match kind {
            SweepKind::Axial => l.force_n[2] = v,
            _ => {
                l.force_n[0] = v * dir[0];
                l.force_n[1] = v * dir[1];
            }
        }
        let rename = |e: Error| {
            e.map_field(|f| {
                if f.starts_with("load.force_n") {
                    key.to_string()
                } else {
                    f.to_string()
                }
            })
        };
        // a load the bearing cannot carry (a TRB's radial load beyond F_a / tan α, a solve
        // that does not converge, a contact the validity check refuses) is a limit of the
        // bearing, not bad input: the point is left out, a warning names it and why
        let solved = solve_planned(&point_case, label, planned, &l, start)
            .and_then(crate::validity::checked)
            .map_err(rename);
        let r = match solved {
            Ok(r) => r,
            Err(e) => {
                new_warnings.push(format!("{key} = {v} {unit}: not solved, left out: {e}"));
                continue;
            }
        };
        start = warm_start(&r);
        let f = r
            .friction
            .as_ref()
            .ok_or_else(|| Error::invalid(key, v, "a sweep of a bearing case with [operating]"))?;
        let mut point_warnings = r.warnings.clone();
        point_warnings.extend(f.warnings.iter().cloned());
        merge_warnings(
            &mut new_warnings,
            &base_warnings,
            &point_warnings,
            key,
            v,
            unit,
        );
        // the carried force, the swept components as given (exact, not to the residual)
        let mut shown = r.force_n;
        match kind {
            SweepKind::Axial => shown[2] = l.force_n[2],
            _ => shown[..2].copy_from_slice(&l.force_n[..2]),
        }
        rows.push(f.state_row(shown));
    }
    if let Some(f) = report.friction.as_mut() {
        f.warnings.extend(new_warnings);
        match kind {
            SweepKind::Axial => f.axial_load_sweep = rows,
            _ => f.radial_load_sweep = rows,
        }
    }
    Ok(())
}

/// The displacement of a solved report as the start of the next solve (`None` with every
/// element lifted off, as [`crate::BearingModel::solve`]).
fn warm_start(r: &BearingReport) -> Option<[f64; 5]> {
    let loaded = r.rollers().is_some_and(|p| p.max_roller_load_n > 0.0);
    loaded.then_some([
        r.displacement_mm[0],
        r.displacement_mm[1],
        r.displacement_mm[2],
        r.tilt_rad[0],
        r.tilt_rad[1],
    ])
}

/// Add each of `point`'s warnings whose kind neither `base` nor `into` holds yet to
/// `into`, prefixed `<key> = <value> <unit>: ` (the first point that raises it). Two
/// warnings are of one kind when they differ only in their numbers ("736 loaded raceway
/// slices ..." and "724 loaded raceway slices ..."): a sweep of 50 points adds each kind
/// once, not 50 times.
fn merge_warnings(
    into: &mut Vec<String>,
    base: &[String],
    point: &[String],
    key: &str,
    value: f64,
    unit: &str,
) {
    let kind = |w: &str| -> String {
        w.chars()
            .filter(|c| !(c.is_ascii_digit() || *c == '.' || *c == '-'))
            .collect()
    };
    let prefix = format!("{key} = ");
    for w in point {
        let k = kind(w);
        let seen = base.iter().chain(into.iter()).any(|x| {
            let x = match x.strip_prefix(&prefix) {
                Some(rest) => rest.split_once(": ").map_or(rest, |(_, w)| w),
                None => x,
            };
            kind(x) == k
        });
        if !seen {
            into.push(format!("{key} = {value} {unit}: {w}"));
        }
    }
}

/// The text lines of a load or temperature sweep for `kontakt bearing` (none without one).
pub(super) fn state_sweep_lines(f: &FrictionReport) -> Vec<String> {
    let Some((key, rows)) = f.state_sweep() else {
        return Vec::new();
    };
    let opt = |v: Option<f64>, d: usize| v.map_or("-".to_string(), |x| format!("{x:.d$}"));
    let mut out = vec![format!(
        "  {} sweep (N·mm): Fa N | Fr N | T °C | ν mm²/s | total | cone | cup | rib | drag | μ | loaded rollers | SKF | Aihara | min Λ",
        key.trim_start_matches("operating.sweep_")
    )];
    for r in rows {
        out.push(format!(
            "    {:8.1} | {:8.1} | {:6.1} | {:7.2} | {:9.2} | {:8.2} | {:8.2} | {:8.2} | {:7.2} | {:>8} | {:3} | {:>9} | {:>9} | {:>6}",
            r.axial_load_n,
            r.radial_load_n,
            r.temperature_c,
            r.viscosity_mm2_s,
            r.total_nmm,
            r.cone_nmm,
            r.cup_nmm,
            r.rib_nmm,
            r.drag_nmm,
            opt(r.coefficient, 5),
            r.loaded_rollers,
            opt(r.skf_total_nmm, 2),
            opt(r.aihara_nmm, 2),
            opt(r.min_lambda, 3)
        ));
    }
    out
}
