//! `[speed]` of a bearing case: the ring speeds, and the report of a ball bearing at speed
//! (Jones 1960, Harris & Kotzalas 2006; `docs/bearing-model.md` §16), on
//! [`kontakt_bearing::ball_speed`].
//!
//! ```toml
//! [speed]
//! inner_rpm = 12000.0   # r/min about +z, default 0
//! outer_rpm = 0.0       # default 0
//! ```
//!
//! The library takes rad/s ([`RingSpeeds`]); the case speaks r/min, as the friction
//! case's `[speed]` does. Roller bearings take a speed with `roller_model = "rib_contact"`
//! (`roller_speed.rs`, `docs/bearing-model.md` §15.7); the ISO roller model takes it without
//! centrifugal force and warns; thrust bearings refuse it, naming the key. The friction
//! section (`[operating]`, `crate::bearing_friction`) takes its ring speeds from here.

use super::BallRow;
use kontakt::{Error, Result};
use kontakt_bearing::ball_speed::BallSpeedSolver;
use kontakt_bearing::speed::RingSpeeds;
use serde::{Deserialize, Serialize};

/// The largest ring speed of a case, r/min (as the friction case's).
pub const MAX_RING_RPM: f64 = 100_000.0;

/// `[speed]`: the speeds of the rings about the bearing axis +z, r/min (positive
/// counter-clockwise seen from +z), default at rest.
#[derive(Debug, Clone, Copy, PartialEq, Default, Serialize, Deserialize, schemars::JsonSchema)]
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
}

/// The ball rows of a solve at speed (both contacts) and the largest load on each raceway.
pub(super) fn speed_rows(solver: &BallSpeedSolver) -> (Vec<BallRow>, [f64; 2]) {
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
    (rows, q_max)
}
