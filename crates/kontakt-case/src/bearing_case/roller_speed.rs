//! `[speed]` of a roller bearing case: with `roller_model = "rib_contact"` (cylindrical or
//! tapered) every roller carries its centrifugal force `F_c = m ω_c² r_c` (N) of
//! [`kontakt_bearing::roller_speed`] (`docs/bearing-model.md` §15.7), the roller's density
//! `bearing.roller_density_kg_m3` (kg/m³, default steel 7850); the report gains each
//! roller's `centrifugal_force_n` and the bearing's `ring_speeds_rpm`. The ISO model (both
//! raceway contacts in series, no roller in its own balance) takes a speed for the friction
//! torque (`crate::bearing_friction`) but solves its load distribution without centrifugal
//! force, with a warning saying so ([`iso_speed_warning`]); thrust bearings refuse a speed,
//! naming the key.

use super::{BearingElements, BearingReport, BearingSpeedSpec, RollerSpec};
use kontakt::{Error, Result};
use kontakt_bearing::roller_equilibrium::RibContactSolver;
use kontakt_bearing::roller_speed::{STEEL_DENSITY_KG_M3, roller_centrifugal};
use kontakt_bearing::speed::RingSpeeds;

/// The ring speeds of a roller bearing case (`None` at rest), after checking
/// `bearing.roller_density_kg_m3` and that the bearing takes a speed (the ISO roller model
/// takes it without centrifugal force: [`iso_speed_warning`]).
///
/// # Errors
/// [`Error::InvalidInput`] naming `speed.inner_rpm` or `speed.outer_rpm` for a speed out
/// of range or for a thrust bearing;
/// `bearing.roller_density_kg_m3` unless finite, > 0 and <= 100 000 kg/m³.
pub(super) fn ring_speeds(
    speed: &BearingSpeedSpec,
    s: &RollerSpec,
    label: &str,
) -> Result<Option<RingSpeeds>> {
    if let Some(rho) = s.roller_density_kg_m3
        && !(rho.is_finite() && rho > 0.0 && rho <= 1e5)
    {
        return Err(Error::invalid(
            "bearing.roller_density_kg_m3",
            rho,
            "a finite density > 0 and <= 100000 kg/m³ (steel 7850)",
        ));
    }
    let Some(speeds) = speed.ring_speeds()? else {
        return Ok(None);
    };
    let (key, v) = if speed.inner_rpm != 0.0 {
        ("speed.inner_rpm", speed.inner_rpm)
    } else {
        ("speed.outer_rpm", speed.outer_rpm)
    };
    if label == "thrust" {
        return Err(Error::invalid(
            key,
            v,
            "0 for type = \"thrust\": the speed effects are modelled for ball bearings and for cylindrical and tapered roller bearings with roller_model = \"rib_contact\"",
        ));
    }
    Ok(Some(speeds))
}

/// The warning of the ISO roller model at speed (`None` at rest): its load distribution has
/// no centrifugal force (both raceway contacts in series, no roller in its own balance to
/// carry one); the speed enters the friction section only.
pub(crate) fn iso_speed_warning(speed: &BearingSpeedSpec) -> Option<String> {
    (!speed.at_rest()).then(|| {
        format!(
            "speed.inner_rpm = {}, speed.outer_rpm = {} r/min with roller_model = \"iso\": the load distribution is computed without the rollers' centrifugal force (the speed enters only the friction section); for the centrifugal force use roller_model = \"rib_contact\"",
            speed.inner_rpm, speed.outer_rpm
        )
    })
}

/// The ISO roller model at speed: the ring speeds (r/min) in the report and
/// [`iso_speed_warning`] first among its warnings (the sweep's rows put it there too); at
/// rest the report is left as it is.
pub(super) fn report_iso_speed(speed: &BearingSpeedSpec, report: &mut BearingReport) {
    if let Some(w) = iso_speed_warning(speed) {
        report.ring_speeds_rpm = Some([speed.inner_rpm, speed.outer_rpm]);
        report.warnings.insert(0, w);
    }
}

/// Load every roller of `solver` with its centrifugal force at `speeds` (nothing at rest).
///
/// # Errors
/// Those of [`roller_centrifugal`], named by their case keys.
pub(super) fn set_centrifugal(
    solver: &mut RibContactSolver,
    s: &RollerSpec,
    speeds: Option<RingSpeeds>,
) -> Result<()> {
    let Some(speeds) = speeds else {
        return Ok(());
    };
    let rho = s.roller_density_kg_m3.unwrap_or(STEEL_DENSITY_KG_M3);
    let c = roller_centrifugal(solver.bearing(), speeds, rho)
        .map_err(|e| e.map_field(|f| format!("bearing.{f}")))?;
    solver
        .set_centrifugal_n(c.force_n)
        .map_err(|e| e.map_field(|f| format!("bearing.{f}")))
}

/// At speed: the ring speeds (r/min) and every roller's centrifugal force (N) in the
/// report; at rest the report is left as it is.
pub(super) fn report_speed(
    speed: &BearingSpeedSpec,
    solver: &RibContactSolver,
    report: &mut BearingReport,
) {
    if speed.at_rest() {
        return;
    }
    report.ring_speeds_rpm = Some([speed.inner_rpm, speed.outer_rpm]);
    if let BearingElements::Rollers(p) = &mut report.elements {
        for row in &mut p.roller_loads {
            row.centrifugal_force_n = Some(solver.centrifugal_n());
        }
    }
}
