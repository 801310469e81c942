//! The contact element driven through a prescribed motion of one roller against the rib
//! (what `kontakt mbs` shows): a load ramp, then tilt and skew of the roller about its
//! reference point at constant rib load (load control by [`ContactElement::press_to_force`]),
//! with the roller spinning against the rib at the bearing's kinematics; for the Hertz, PimP
//! and half-space back-ends. Returns plain samples; rendering is the CLI's.
//!
//! Frames: the bodies' frames are the bearing (world) frame at the reference placement of the
//! pairing ([`crate::bearing::roller_rib`]); tilt turns the roller about the world `Y` axis
//! (circumferential at cage angle 0) through its reference point, skew about `e_r × Y`.
//! Units: mm, N, N·mm, MPa, W, deg, r/min; times in µs (wall clock of this machine).

use super::{Backend, ContactElement, ElementSpec};
use crate::bearing::{BodyState, RollerRib, RollerRibSpec, TaperedKinematics};
use crate::error::{Error, Result};
use crate::friction::FrictionLaw;
use crate::gap::SurfacePairGap;
use crate::geometry::Twist;
use crate::halfspace::BemOptions;
use crate::pimp::PimpOptions;
use nalgebra::{Isometry3, Point3, Translation3, Unit, UnitQuaternion, Vector3};
use std::time::Instant;

/// One sample of the motion.
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct MotionSample {
    /// Back-end: `hertz`, `pimp` or `halfspace`.
    pub backend: &'static str,
    /// Phase: `load`, `tilt` or `skew`.
    pub phase: &'static str,
    /// Tilt or skew angle \[deg\] (0 in the load ramp).
    pub angle_deg: f64,
    /// Rib load \[N\].
    pub force_n: f64,
    /// Approach \[mm\].
    pub approach_mm: f64,
    /// Force on the roller \[N\], world frame.
    pub force_x_n: f64,
    /// y component \[N\].
    pub force_y_n: f64,
    /// z component \[N\].
    pub force_z_n: f64,
    /// Moment on the roller about its reference point \[N·mm\], world frame.
    pub moment_x_nmm: f64,
    /// y component \[N·mm\].
    pub moment_y_nmm: f64,
    /// z component \[N·mm\].
    pub moment_z_nmm: f64,
    /// Contact point relative to the reference contact point, in the roller's frame, along
    /// the reference contact plane's x axis \[mm\].
    pub migration_x_mm: f64,
    /// The same along its y axis \[mm\].
    pub migration_y_mm: f64,
    /// Largest pressure \[MPa\].
    pub max_pressure_mpa: f64,
    /// Friction power \[W\].
    pub friction_power_w: f64,
    /// Wall time of the load-controlled step (several evaluations) \[µs\].
    pub step_time_us: f64,
}

/// The motion study: samples and the time per evaluation of each back-end.
#[derive(Debug, Clone, PartialEq)]
pub struct MotionStudy {
    /// Every sample, back-end by back-end, phase by phase.
    pub samples: Vec<MotionSample>,
    /// Back-end and mean wall time of one evaluation at the reference pose \[µs\].
    pub timing: Vec<(&'static str, f64)>,
}

fn linspace(a: f64, b: f64, n: usize) -> Vec<f64> {
    (0..n)
        .map(|i| a + (b - a) * i as f64 / (n - 1).max(1) as f64)
        .collect()
}

/// The back-ends of the study by name: `hertz`, `pimp`, `halfspace`.
pub const BACKENDS: [&str; 3] = ["hertz", "pimp", "halfspace"];

/// Run the motion for the built-in `pairing` at the rib load `force` \[N\] (the load ramp
/// runs from 0.2 to 1.6 times it), tilt and skew up to ±`angle_deg`, the inner ring at `rpm`
/// (outer ring fixed), `steps` samples per phase, Coulomb friction μ = 0.1, with the
/// back-ends named in `backends` (a subset of [`BACKENDS`], in that order).
///
/// # Errors
/// [`Error::InvalidInput`] naming `force` (> 0), `angle_deg` (0 < a ≤ 2), `rpm`
/// (0..=100 000), `steps` (3..=1000), `backends` (unknown, none or one twice), `pairing`;
/// the element's errors at a load, named `force`.
pub fn roller_rib_motion(
    pairing: &str,
    force: f64,
    angle_deg: f64,
    rpm: f64,
    steps: usize,
    backends: &[&str],
) -> Result<MotionStudy> {
    crate::error::choices("backends", backends, &BACKENDS)?;
    if !(force.is_finite() && force > 0.0) {
        return Err(Error::invalid("force", force, "a finite force > 0 N"));
    }
    if !(angle_deg > 0.0 && angle_deg <= 2.0) {
        return Err(Error::invalid("angle_deg", angle_deg, "0 < angle <= 2 deg"));
    }
    if !((0.0..=1e5).contains(&rpm)) {
        return Err(Error::invalid("rpm", rpm, "0 <= speed <= 100000 r/min"));
    }
    if !(3..=1000).contains(&steps) {
        return Err(Error::invalid(
            "steps",
            steps,
            "3 to 1000 samples per phase",
        ));
    }
    let rr = RollerRib::new(RollerRibSpec::builtin(pairing)?)?;
    let k = TaperedKinematics::of_roller_rib(&rr, rpm * std::f64::consts::PI / 30.0, 0.0)?;
    let pair = k.rib_pair(0.0)?;
    // The bodies' frames are the world frame at the reference placement: twists about the
    // world origin.
    let at_origin = |b: &BodyState| Twist::new(b.velocity_at(&Point3::origin()), b.twist.angular);
    let (t1, t2) = (at_origin(&pair.body1), at_origin(&pair.body2));
    let c = Point3::from(pair.body1.pose.translation.vector);
    let e_r = rr.roller_axis.into_inner();
    let tilt_axis = Unit::new_normalize(Vector3::y());
    let skew_axis = Unit::new_normalize(e_r.cross(&Vector3::y()));
    let n0 = rr.contact.normal;
    let down = Unit::new_unchecked(-n0.into_inner());
    let gap = SurfacePairGap::new(rr.face.clone(), rr.rib.clone(), rr.contact)?;
    let [ex, ey, _] = gap.axes();
    let turned = |axis: &Unit<Vector3<f64>>, deg: f64| {
        let q = UnitQuaternion::from_axis_angle(axis, deg.to_radians());
        Isometry3::from_parts(Translation3::from(c.coords - q * c.coords), q)
    };
    let mut phases: Vec<(&'static str, f64, f64, Isometry3<f64>)> = Vec::new();
    for f in linspace(0.2 * force, 1.6 * force, steps) {
        phases.push(("load", 0.0, f, Isometry3::identity()));
    }
    for (name, axis) in [("tilt", &tilt_axis), ("skew", &skew_axis)] {
        for a in linspace(-angle_deg, angle_deg, steps) {
            phases.push((name, a, force, turned(axis, a)));
        }
    }
    let all = [
        ("hertz", Backend::Hertz),
        ("pimp", Backend::Pimp(PimpOptions::default())),
        ("halfspace", Backend::HalfSpace(BemOptions::default())),
    ];
    let backends = all.into_iter().filter(|(name, _)| backends.contains(name));
    let mut samples = Vec::new();
    let mut timing = Vec::new();
    for (name, backend) in backends {
        let mut spec = ElementSpec::new(rr.face.clone(), rr.rib.clone())?;
        spec.backend = backend;
        spec.friction = FrictionLaw::coulomb(0.1)?;
        let mut element = ContactElement::new(spec)?;
        for (phase, angle, load, pose0) in &phases {
            let start = Instant::now();
            let (pose, r) = element
                .press_to_force(pose0, &Isometry3::identity(), &t1, &t2, &down, *load)
                .map_err(|e| at_load(e, name, phase, *load, force))?;
            let step_time_us = start.elapsed().as_secs_f64() * 1e6;
            let local = pose.inverse_transform_point(&r.point) - rr.contact.point;
            samples.push(MotionSample {
                backend: name,
                phase,
                angle_deg: *angle,
                force_n: r.normal_force,
                approach_mm: r.approach,
                force_x_n: r.force1.x,
                force_y_n: r.force1.y,
                force_z_n: r.force1.z,
                moment_x_nmm: r.moment1.x,
                moment_y_nmm: r.moment1.y,
                moment_z_nmm: r.moment1.z,
                migration_x_mm: local.dot(&ex),
                migration_y_mm: local.dot(&ey),
                max_pressure_mpa: r.max_pressure,
                friction_power_w: r.friction_power,
                step_time_us,
            });
        }
        // Time per evaluation at the last pose, averaged over repeated calls.
        let (pose, _) = element
            .press_to_force(
                &Isometry3::identity(),
                &Isometry3::identity(),
                &t1,
                &t2,
                &down,
                force,
            )
            .map_err(|e| at_load(e, name, "timing", force, force))?;
        let calls = 20;
        let start = Instant::now();
        for _ in 0..calls {
            element.evaluate(&pose, &Isometry3::identity(), &t1, &t2)?;
        }
        timing.push((name, start.elapsed().as_secs_f64() * 1e6 / calls as f64));
    }
    Ok(MotionStudy { samples, timing })
}

/// An element error at the study's `load` named by what the caller gave: the rib load
/// `force` (the element's own fields, `bodies`, `surfaces`, mean nothing to the caller of a
/// study; found by probing `kontakt mbs --force 1e9`). A computation that did not converge
/// stays a failed computation.
fn at_load(e: Error, backend: &str, phase: &str, load: f64, force: f64) -> Error {
    let reason = match &e {
        Error::Geometry { .. } | Error::InvalidInput { .. } => e.to_string(),
        _ => return e,
    };
    Error::invalid(
        "force",
        force,
        format!(
            "a rib load the {backend} back-end can press the roller to (at {load:.4e} N in the \
             {phase} phase: {reason})"
        ),
    )
}
