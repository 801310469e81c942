//! `[speed]` of a bearing case: the ring speeds, and the report of a ball bearing at speed
//! (Jones 1960, Harris & Kotzalas 2006; `docs/bearing-model.md` §9), on
//! [`kontakt_bearing::ball_speed`].
//!
//! ```toml
//! [speed]
//! inner_rpm = 12000.0   # r/min about +z, default 0
//! outer_rpm = 0.0       # default 0
//! ```
//!
//! The library takes rad/s ([`RingSpeeds`]); the case speaks r/min, as the friction
//! case's `[speed]` does. Roller bearings take no speed yet (an error names the key).

use super::{
    BallPart, BallRow, BallSpec, BearingCase, BearingElements, BearingReport, GrooveKeys,
    ball_contacts, map_load, report, solver_echo, solver_warnings,
};
use kontakt::{Error, Result};
use kontakt_bearing::ball_speed::BallSpeedSolver;
use kontakt_bearing::equilibrium::RingLoad;
use kontakt_bearing::speed::RingSpeeds;
use serde::{Deserialize, Serialize};

/// The largest ring speed of a case, r/min (as the friction case's).
pub const MAX_RING_RPM: f64 = 100_000.0;

/// `[speed]`: the speeds of the rings about the bearing axis +z, r/min (positive
/// counter-clockwise seen from +z), default at rest.
#[derive(Debug, Clone, Copy, PartialEq, Default, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct BearingSpeedSpec {
    /// Inner-ring speed, r/min (default 0), |speed| <= 100 000.
    #[serde(default)]
    pub inner_rpm: f64,
    /// Outer-ring speed, r/min (default 0), |speed| <= 100 000.
    #[serde(default)]
    pub outer_rpm: f64,
}

impl BearingSpeedSpec {
    /// Whether both rings are at rest.
    pub fn at_rest(&self) -> bool {
        self.inner_rpm == 0.0 && self.outer_rpm == 0.0
    }

    /// The speeds in rad/s, `None` at rest.
    ///
    /// # Errors
    /// [`Error::InvalidInput`] naming `speed.inner_rpm` or `speed.outer_rpm` for a speed
    /// that is not finite or beyond ±100 000 r/min.
    pub fn ring_speeds(&self) -> Result<Option<RingSpeeds>> {
        for (key, v) in [
            ("speed.inner_rpm", self.inner_rpm),
            ("speed.outer_rpm", self.outer_rpm),
        ] {
            if !(v.is_finite() && v.abs() <= MAX_RING_RPM) {
                return Err(Error::invalid(
                    key,
                    v,
                    format!(
                        "a finite speed with |speed| <= {MAX_RING_RPM} r/min (negative: clockwise seen from +z)"
                    ),
                ));
            }
        }
        Ok((!self.at_rest()).then(|| RingSpeeds::from_rpm(self.inner_rpm, self.outer_rpm)))
    }

    /// Refuse a speed for a bearing type without speed effects.
    pub(crate) fn require_at_rest(&self, label: &str) -> Result<()> {
        for (key, v) in [
            ("speed.inner_rpm", self.inner_rpm),
            ("speed.outer_rpm", self.outer_rpm),
        ] {
            if v != 0.0 {
                return Err(Error::invalid(
                    key,
                    v,
                    format!(
                        "0 for type = \"{label}\": the speed effects (centrifugal force, gyroscopic moment) are modelled for ball bearings only"
                    ),
                ));
            }
        }
        Ok(())
    }
}

/// The report of a ball bearing's solve at speed.
pub(super) fn ball_speed_report(
    case: &BearingCase,
    label: &'static str,
    solver: &mut BallSpeedSolver,
    s: &BallSpec,
    keys: &GrooveKeys,
    load: &RingLoad,
    start: Option<[f64; 5]>,
) -> Result<BearingReport> {
    let sol = match start {
        Some(u) => solver.solve_from(load, u),
        None => solver.solve(load),
    }
    .map_err(map_load)?;
    let warnings = solver_warnings(&sol.status, sol.note)?;
    let mut q_max = [0.0f64; 2];
    let rows: Vec<BallRow> = solver
        .ball_loads()
        .iter()
        .map(|q| {
            q_max[0] = q_max[0].max(q.inner_load_n);
            q_max[1] = q_max[1].max(q.outer_load_n);
            BallRow {
                azimuth_deg: q.azimuth_rad.to_degrees(),
                load_n: q.inner_load_n,
                contact_angle_deg: q.inner_contact_angle_rad.to_degrees(),
                approach_mm: q.approach_mm[0] + q.approach_mm[1],
                inner_max_pressure_mpa: q.inner_max_pressure_mpa,
                outer_max_pressure_mpa: q.outer_max_pressure_mpa,
                inner_load_n: q.inner_load_n,
                outer_load_n: q.outer_load_n,
                inner_contact_angle_deg: q.inner_contact_angle_rad.to_degrees(),
                outer_contact_angle_deg: q.outer_contact_angle_rad.to_degrees(),
                centrifugal_force_n: q.centrifugal_force_n,
                gyroscopic_moment_nmm: q.gyroscopic_moment_nmm,
            }
        })
        .collect();
    let b = solver.bearing();
    let contacts = ball_contacts(b, s, keys, q_max)?;
    let elements = BearingElements::Balls(BallPart {
        balls: b.balls,
        free_contact_angle_deg: b.free_contact_angle().to_degrees(),
        ball_stiffness_n_per_mm1_5: solver.ball_stiffness(),
        max_ball_load_n: sol.max_ball_load_n,
        max_inner_pressure_mpa: sol.max_pressure_mpa[0],
        max_outer_pressure_mpa: sol.max_pressure_mpa[1],
        ball_loads: rows,
        race_control: Some("outer"),
    });
    let mut report = report(case, label, elements, sol.displacement, sol.load);
    report.solver = solver_echo(&sol.status);
    report.load_zone_epsilon = sol.load_zone;
    report.stiffness_matrix = sol.stiffness;
    report.warnings = warnings;
    report.contacts = contacts;
    report.ring_speeds_rpm = Some([case.speed.inner_rpm, case.speed.outer_rpm]);
    Ok(report)
}
