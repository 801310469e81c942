//! The friction section of a ball bearing case (deep groove, angular contact; issue 29
//! §1-2): the contact-based torque of `kontakt_bearing::friction::ball` on the solved
//! load distribution (at rest or at speed), beside the SKF 2004 deep groove or angular
//! contact ball bearing torque and the Schaeffler M0. The same tables as the roller
//! bearings (`[operating]`, `[lubricant]`, `[friction]`, `[catalogue]` with `c0_n` for the
//! SKF deep groove model); the report's `cone_*` fields are the inner race, `cup_*` the
//! outer race, and `balls` lists every ball.
//!
//! Units: r/min in the case (rad/s in the library), mm, N, N·mm, W, °C.

use super::{
    CatalogueSpec, CatalogueTorques, FrictionReport, OperatingSpec, RacewayOil, Tables, check_rpm,
    drag_model, envelope, key, lubricant_of, oil_level_below, oil_supply, raceway_oil, skf_options,
    with_sweeps,
};
use crate::friction_case::LubricantSpec;
use kontakt::{Error, Result};
use kontakt_bearing::friction::ball::{
    BallAttitude, BallContacts, BallFrictionModel, BallFrictionOperating,
};
use kontakt_bearing::friction::skf2004::{
    AngularContactSeries, DeepGrooveSeries, SkfBearing, SkfOptions, skf2004,
};
use kontakt_bearing::friction::{Envelope, Lubrication, OperatingPoint, RPM_PER_RAD_S};
use kontakt_bearing::geometry::{BallBearing, BallBearingKind};
use serde::Serialize;

/// One ball of the friction table (torques N·mm, power W).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct FrictionBallRow {
    /// Ball index.
    pub ball: usize,
    /// Azimuth \[deg\].
    pub azimuth_deg: f64,
    /// Inner raceway load \[N\].
    pub inner_load_n: f64,
    /// Outer raceway load \[N\].
    pub outer_load_n: f64,
    /// Spin at the inner contact ω_s \[rad/s\] (per rad/s of Δω at standstill).
    pub inner_spin_rad_s: f64,
    /// Spin at the outer contact \[rad/s\].
    pub outer_spin_rad_s: f64,
    /// Rolling-resistance power at the inner race \[W\].
    pub inner_rolling_w: f64,
    /// Sliding power (spin and differential slip) at the inner race \[W\].
    pub inner_sliding_w: f64,
    /// Rolling-resistance power at the outer race \[W\].
    pub outer_rolling_w: f64,
    /// Sliding power at the outer race \[W\].
    pub outer_sliding_w: f64,
    /// The ball's share of the bearing torque \[N·mm\].
    pub torque_nmm: f64,
    /// Smallest Λ of its loaded contacts (absent without load or at standstill).
    pub min_lambda: Option<f64>,
}

/// The friction section of the ball bearing `bearing` with the solved `balls` under the
/// force `force` \[N\] at the case's tables `case` (its `[speed]` in r/min), with the
/// sweeps of `operating.sweep_inner_rpm` and `sweep_temperature_c` on the same load
/// distribution (the load sweeps re-solve the case and come here per point).
///
/// # Errors
/// [`Error::InvalidInput`] naming the case key (`speed.inner_rpm`, `lubricant.*`,
/// `friction.*`, `catalogue.*`, `operating.*`).
pub(crate) fn friction_report(
    case: &Tables<'_>,
    op: &OperatingSpec,
    bearing: &BallBearing,
    balls: &[BallContacts],
    force: [f64; 3],
) -> Result<FrictionReport> {
    let envelope = envelope(case.catalogue)?;
    let on = Solved {
        bearing,
        balls,
        force,
        envelope: envelope.as_ref(),
    };
    with_sweeps(op, case.rpm, case.lubricant, force, |rpm, lub| {
        point(case, op, rpm, lub, &on)
    })
}

/// The solved bearing a friction point reads.
struct Solved<'a> {
    bearing: &'a BallBearing,
    balls: &'a [BallContacts],
    force: [f64; 3],
    envelope: Option<&'a Envelope>,
}

/// [`friction_report`] at the ring speeds `rpm` (r/min) with the lubricant `lubricant`.
fn point(
    case: &Tables<'_>,
    op: &OperatingSpec,
    rpm: [f64; 2],
    lubricant: Option<&LubricantSpec>,
    on: &Solved<'_>,
) -> Result<FrictionReport> {
    let Solved {
        bearing,
        balls,
        force,
        envelope,
    } = *on;
    check_rpm(rpm)?;
    let lub = lubricant_of(lubricant)?;
    let RacewayOil { losses, nu, .. } = raceway_oil(op, lub, case.friction)?;
    let mut model =
        BallFrictionModel::new(bearing.clone(), losses, BallAttitude::OuterRaceControl)?;
    let mut warnings = Vec::new();
    let lubrication = oil_supply(op)?;
    if let Lubrication::OilBath { level_mm } = lubrication {
        oil_level_below(level_mm, centre_height_mm(bearing))?;
    }
    warnings.extend(super::checks::temperature_warning(lub));
    let (wi, wo) = (rpm[0] / RPM_PER_RAD_S, rpm[1] / RPM_PER_RAD_S);
    let starting = wi == wo;
    let point = OperatingPoint {
        speed_rad_s: (wi - wo).abs(),
        viscosity_mm2_s: nu,
        radial_load_n: force[0].hypot(force[1]),
        axial_load_n: force[2].abs(),
        lubrication,
    };
    let options = skf_options(op, case.catalogue)?;
    let cat = catalogue_torques(
        case.catalogue,
        envelope,
        bearing,
        &point,
        &options,
        &mut warnings,
    )?;
    let drag = drag_model(op, &cat, nu * point.speed_rpm(), &mut warnings)?;
    let p = force.iter().map(|f| f * f).sum::<f64>().sqrt();
    let d = envelope.map_or(bearing.pitch_diameter_mm, |e| e.bore_mm);
    let f = model.evaluate(&BallFrictionOperating {
        inner_speed: wi,
        outer_speed: wo,
        balls,
        drag,
        coefficient_basis: Some((p, d)),
    })?;
    warnings.extend(f.warnings.lines());
    let finite = |v: f64| v.is_finite().then_some(v);
    let rows: Vec<FrictionBallRow> = model
        .balls()
        .iter()
        .map(|b| FrictionBallRow {
            ball: b.ball,
            azimuth_deg: b.azimuth_rad.to_degrees(),
            inner_load_n: b.inner.load_n,
            outer_load_n: b.outer.load_n,
            inner_spin_rad_s: b.inner.spin_rad_s,
            outer_spin_rad_s: b.outer.spin_rad_s,
            inner_rolling_w: b.inner.rolling_w,
            inner_sliding_w: b.inner.sliding_w,
            outer_rolling_w: b.outer.rolling_w,
            outer_sliding_w: b.outer.sliding_w,
            torque_nmm: b.torque_nmm,
            min_lambda: [&b.inner, &b.outer]
                .iter()
                .filter(|c| c.load_n > 0.0 && !starting)
                .map(|c| c.lambda)
                .reduce(f64::min),
        })
        .collect();
    let cage = if starting {
        0.0
    } else {
        model
            .balls()
            .iter()
            .map(|b| b.cage_speed_rad_s)
            .sum::<f64>()
            / model.balls().len().max(1) as f64
    };
    Ok(FrictionReport {
        inner_rpm: rpm[0],
        outer_rpm: rpm[1],
        cage_rpm: cage * RPM_PER_RAD_S,
        temperature_c: lub.temperature_c,
        viscosity_mm2_s: nu,
        starting,
        total_nmm: f.total_nmm,
        inner_ring_nmm: f.inner_ring_nmm,
        outer_ring_nmm: f.outer_ring_nmm,
        cone_rolling_nmm: f.inner_race.rolling_nmm,
        cone_sliding_nmm: f.inner_race.sliding_nmm,
        cup_rolling_nmm: f.outer_race.rolling_nmm,
        cup_sliding_nmm: f.outer_race.sliding_nmm,
        rib_nmm: 0.0,
        drag_nmm: f.drag_nmm,
        rolling_power_w: f.power.rolling_w,
        sliding_power_w: f.power.sliding_w,
        rib_power_w: 0.0,
        drag_power_w: f.power.drag_w,
        power_w: f.power.total_w,
        coefficient: f.coefficient,
        coefficient_diameter_mm: d,
        min_lambda: finite(f.min_lambda),
        catalogue: cat,
        rollers: Vec::new(),
        warnings,
        speed_sweep: Vec::new(),
        axial_load_sweep: Vec::new(),
        radial_load_sweep: Vec::new(),
        temperature_sweep: Vec::new(),
        balls: rows,
    })
}

/// The SKF 2004 ball bearing torque and the Schaeffler M0 of `catalogue`.
fn catalogue_torques(
    catalogue: Option<&CatalogueSpec>,
    envelope: Option<&Envelope>,
    bearing: &BallBearing,
    point: &OperatingPoint,
    options: &SkfOptions,
    warnings: &mut Vec<String>,
) -> Result<CatalogueTorques> {
    let mut cat = CatalogueTorques::default();
    let (Some(c), Some(env)) = (catalogue, envelope) else {
        warnings.push(
            "catalogue torques not computed: give [catalogue] (bore_mm, outer_mm, width_mm, skf_series, c0_n)"
                .to_string(),
        );
        return Ok(cat);
    };
    if let Some(series) = &c.skf_series {
        let skf = skf_ball_bearing(c, series, bearing)?;
        let t = skf2004(&skf, env, point, options).map_err(|e| e.map_field(key("catalogue")))?;
        cat.add_skf(&t, warnings);
    } else {
        warnings.push(
            "SKF catalogue torque not computed: give catalogue.skf_series (and c0_n for deep groove ball bearings)"
                .to_string(),
        );
    }
    cat.add_schaeffler(c, point.viscosity_mm2_s * point.speed_rpm(), env);
    Ok(cat)
}

/// The SKF 2004 bearing of `[catalogue]` with the series `series` for the ball bearing
/// `bearing` (deep groove: with `catalogue.c0_n`).
///
/// # Errors
/// [`Error::InvalidInput`] naming `catalogue.skf_series` or `catalogue.c0_n`.
pub(crate) fn skf_ball_bearing(
    c: &CatalogueSpec,
    series: &str,
    bearing: &BallBearing,
) -> Result<SkfBearing> {
    let named = |e: Error| e.map_field(|_| "catalogue.skf_series".to_string());
    Ok(match bearing.kind {
        BallBearingKind::DeepGroove => SkfBearing::DeepGrooveBall {
            series: DeepGrooveSeries::from_name(series).map_err(named)?,
            c0_n: c.c0_n.ok_or_else(|| {
                Error::invalid(
                    "catalogue.c0_n",
                    "missing",
                    "the basic static load rating C0 [N] of the product table with skf_series",
                )
            })?,
        },
        BallBearingKind::AngularContact => SkfBearing::AngularContactBall {
            series: AngularContactSeries::from_name(series).map_err(named)?,
        },
    })
}

/// The height of a ball bearing's centre above the lowest point of its outer raceway
/// \[mm\]: the highest static oil level of an oil bath.
pub(crate) fn centre_height_mm(bearing: &BallBearing) -> f64 {
    0.5 * (bearing.pitch_diameter_mm
        + bearing.ball_diameter_mm * bearing.free_contact_angle().cos())
}
