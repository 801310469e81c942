//! Kinematics of a tapered roller bearing with a common apex: cage speed,
//! roller spin, the roller's angular velocity relative to the inner ring (which carries the
//! rib), the bodies' poses and twists, and the sliding and entrainment velocities at a
//! contact point or on every cell of a contact field.
//!
//! Units: mm, mm/s, rad, rad/s. Frame: the bearing (world) frame of
//! [`crate::bearing::roller_rib`]: ring axis along world `Z` through the common apex `A`, the
//! roller at cage angle 0 in the section plane `X`–`Z` (`X` radial). Speeds about the ring
//! axis are signed by the right-hand rule about `+Z`.
//!
//! # Derivation (rolling without slip on both raceway contact lines)
//!
//! Assumptions: rigid bodies; rings turning about the fixed ring axis; the roller's apex on
//! the ring axis at the apex `A` of both raceway cones (common apex, the condition of
//! true rolling); the roller rolls without slip along both raceway contact lines; steady
//! state (the cage carries the roller's axis round at the cage speed).
//!
//! In the meridian plane of the roller (cage angle `θ`), with `e_z` the ring axis, the
//! directions from `A` are
//!
//! - inner raceway contact line `e_in = (sin α_i, cos α_i)`,
//! - roller axis `e_r = (sin α_m, cos α_m)`, `α_m = α_i + β`,
//! - outer raceway contact line `e_out = (sin α_o, cos α_o)`, `α_o = α_i + 2β`,
//!
//! (components radial, axial), `β` the roller half-angle. Every body turns about a line
//! through `A` (the roller's axis passes through the fixed point `A`), so a body point `P`
//! moves at `ω × (P − A)`. The relative velocity of roller and inner ring vanishes on every
//! point of the line `A + s e_in` iff `ω_roller − ω_i e_z ∥ e_in`; the same for the outer
//! ring. With `ω_roller − ω_i e_z = λ e_in` and `ω_roller − ω_o e_z = μ e_out`:
//!
//! ```text
//! radial:  λ sin α_i = μ sin α_o
//! axial:   (ω_i − ω_o) + λ cos α_i − μ cos α_o = 0
//! ⇒ λ = −(ω_i − ω_o) sin α_o / sin 2β,   μ = −(ω_i − ω_o) sin α_i / sin 2β.
//! ```
//!
//! Splitting `ω_roller = ω_i e_z + λ e_in` into `ω_c e_z + ω_R e_r` (with
//! `e_in = (sin β e_z + sin α_i e_r) / sin α_m`) and using `2 cos β sin α_m = sin α_i + sin α_o`:
//!
//! ```text
//! cage speed            ω_c   = (ω_i sin α_i + ω_o sin α_o) / (sin α_i + sin α_o)
//! roller spin (vs cage) ω_R   = λ sin α_i / sin α_m = −(ω_i − ω_c) sin α_i / sin β
//! roller vs inner ring  ω_rel = ω_roller − ω_i e_z = λ e_in,  |ω_rel| = |ω_i − ω_o| sin α_o / sin 2β
//! ```
//!
//! `ω_R < 0` for `ω_i > ω_o`: the roller turns against the inner ring. Because `ω_rel` is a
//! rotation about the inner raceway contact line, the sliding velocity of the roller on the
//! rib (fixed to the inner ring) at a point `P` is `v_s = ω_rel × (P − A)` with
//! `|v_s| = |ω_rel| · e`, `e` the distance of `P` from the inner raceway contact line: the rib
//! contact (at `e > 0`) always slides. With the contact radii `R_i`, `R_o` of the inner and
//! outer raceway at the roller's mid-section (`R = l cos β sin α` for both, `l` the apex
//! distance of the roller's mid-point), `ω_c = (ω_i R_i + ω_o R_o) / (R_i + R_o)`: for
//! zero cone angles this is the textbook epicyclic relation of a cylindrical roller bearing,
//! `ω_c = ω_i D_i / (D_i + D_o)` with the outer ring fixed. The same relations are in
//! Liu X. et al. (2023) eqs. 1–2 (after Jiang et al. 1994); the derivation is in
//! docs/bearing.md §4 "Kinematics". Wirsching et al. (2020) §1 name the sliding speed over the contact area,
//! with the pressure, as what the rib's friction depends on: hence the per-cell field.
//!
//! # The general (twist) form
//!
//! [`TaperedKinematics::bodies`] gives each body's pose and [`Twist`] (world frame); the
//! roller's reference point is a point `C` on its axis carried by the cage, so its twist is
//! `(ω_c e_z × (C − A), ω_c e_z + ω_R e_r)`. [`ContactPair`] evaluates the sliding velocity
//! `v_s = P_t(v_1(P) − v_2(P))` and the entrainment velocity
//! `u = P_t((v_1(P) + v_2(P))/2 − v_obs(P))` at a world point `P`, `P_t` the projection onto
//! the contact plane (normal `n`), and `v_obs` the velocity of the frame in which the contact
//! is steady (the cage for the rib contact; a body at rest gives the plain mean surface
//! velocity `(v_1 + v_2)/2`). Sliding does not depend on the observer.

use crate::bearing::roller_rib::RollerRib;
use crate::error::{Error, Result};
use crate::geometry::Twist;
pub use crate::geometry::motion::{
    BodyState, ContactFrame, ContactPair, ContactVelocities, VelocityField,
};
use nalgebra::{Isometry3, Point3, Translation3, Unit, UnitQuaternion, Vector3};

/// The four bodies of the bearing at one instant.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Bodies {
    /// Inner ring (carries the rib); reference point: the apex.
    pub inner: BodyState,
    /// Outer ring; reference point: the apex.
    pub outer: BodyState,
    /// Cage; reference point: the apex.
    pub cage: BodyState,
    /// Roller; reference point: the point of its axis at `roller_reference` from the apex,
    /// local `z` along the roller axis.
    pub roller: BodyState,
}

/// The kinematics of a common-apex tapered roller bearing (see the module docs for the
/// derivation): ring speeds in, cage speed, roller spin and the roller's angular velocity
/// relative to the inner ring out.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct TaperedKinematics {
    /// Half-angle of the inner raceway cone α_i \[rad\].
    pub inner_raceway_angle: f64,
    /// Roller half-angle β \[rad\].
    pub roller_half_angle: f64,
    /// The common apex on the ring axis (world `Z` through it) \[mm\].
    pub apex: Point3<f64>,
    /// Distance of the roller's reference point from the apex along its axis \[mm\].
    pub roller_reference: f64,
    /// Inner ring speed ω_i about `+Z` \[rad/s\].
    pub inner_speed: f64,
    /// Outer ring speed ω_o about `+Z` \[rad/s\].
    pub outer_speed: f64,
    /// Cage speed ω_c = (ω_i sin α_i + ω_o sin α_o) / (sin α_i + sin α_o) \[rad/s\].
    pub cage_speed: f64,
    /// Roller spin about its own axis `e_r` (away from the apex) relative to the cage,
    /// ω_R = −(ω_i − ω_c) sin α_i / sin β \[rad/s\].
    pub roller_spin: f64,
    /// λ with ω_roller − ω_i e_z = λ e_in: the signed speed of the roller relative to the
    /// inner ring about the inner raceway contact line, λ = −(ω_i − ω_o) sin α_o / sin 2β
    /// \[rad/s\].
    pub relative_speed: f64,
}

/// Unit directions from the apex at one cage angle (world frame).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Directions {
    /// Ring axis `e_z`.
    pub axis: Vector3<f64>,
    /// Inner raceway contact line `e_in`.
    pub inner_line: Vector3<f64>,
    /// Outer raceway contact line `e_out`.
    pub outer_line: Vector3<f64>,
    /// Roller axis `e_r`.
    pub roller_axis: Vector3<f64>,
}

impl TaperedKinematics {
    /// Kinematics from the cone angles, the apex, the roller's reference distance and the
    /// ring speeds.
    ///
    /// # Errors
    /// [`Error::InvalidInput`] naming the field: `inner_speed` / `outer_speed` not finite,
    /// `inner_raceway_angle` / `roller_half_angle` not in (0, π/2) with α_i + 2β < π/2,
    /// `apex` not finite, `roller_reference` not finite and > 0.
    pub fn new(
        inner_raceway_angle: f64,
        roller_half_angle: f64,
        apex: Point3<f64>,
        roller_reference: f64,
        inner_speed: f64,
        outer_speed: f64,
    ) -> Result<Self> {
        for (name, w) in [("inner_speed", inner_speed), ("outer_speed", outer_speed)] {
            if !w.is_finite() {
                return Err(Error::invalid(name, w, "a finite speed in rad/s"));
            }
        }
        let half = std::f64::consts::FRAC_PI_2;
        if !(inner_raceway_angle > 0.0 && inner_raceway_angle < half) {
            return Err(Error::invalid(
                "inner_raceway_angle",
                inner_raceway_angle,
                "0 < alpha_i < pi/2 rad",
            ));
        }
        if !(roller_half_angle > 0.0 && inner_raceway_angle + 2.0 * roller_half_angle < half) {
            return Err(Error::invalid(
                "roller_half_angle",
                roller_half_angle,
                "0 < beta with alpha_i + 2 beta < pi/2 rad",
            ));
        }
        if !apex.iter().all(|c| c.is_finite()) {
            return Err(Error::invalid("apex", apex, "a finite point in mm"));
        }
        if !(roller_reference.is_finite() && roller_reference > 0.0) {
            return Err(Error::invalid(
                "roller_reference",
                roller_reference,
                "a finite distance > 0 mm",
            ));
        }
        let (ai, b) = (inner_raceway_angle, roller_half_angle);
        let (si, so, sm) = (ai.sin(), (ai + 2.0 * b).sin(), (ai + b).sin());
        let cage_speed = (inner_speed * si + outer_speed * so) / (si + so);
        let relative_speed = -(inner_speed - outer_speed) * so / (2.0 * b).sin();
        let roller_spin = relative_speed * si / sm;
        let k = TaperedKinematics {
            inner_raceway_angle,
            roller_half_angle,
            apex,
            roller_reference,
            inner_speed,
            outer_speed,
            cage_speed,
            roller_spin,
            relative_speed,
        };
        if [cage_speed, relative_speed, roller_spin]
            .iter()
            .all(|v| v.is_finite())
        {
            Ok(k)
        } else {
            Err(Error::invalid(
                "inner_speed",
                inner_speed,
                "a speed small enough that the roller speeds stay finite",
            ))
        }
    }

    /// Kinematics of the bearing of a roller/rib pair: α_i, β and the apex from `rr`, the
    /// roller's reference point at the foot of the rib contact point on the roller axis.
    ///
    /// # Errors
    /// Those of [`TaperedKinematics::new`].
    pub fn of_roller_rib(rr: &RollerRib, inner_speed: f64, outer_speed: f64) -> Result<Self> {
        let reference = (rr.contact.point - rr.apex).dot(&rr.roller_axis);
        Self::new(
            rr.raceway_angle_deg.to_radians(),
            rr.spec.bearing.roller_half_angle_deg.to_radians(),
            rr.apex,
            reference,
            inner_speed,
            outer_speed,
        )
    }

    /// Half-angle of the outer raceway cone α_o = α_i + 2β \[rad\].
    pub fn outer_raceway_angle(&self) -> f64 {
        self.inner_raceway_angle + 2.0 * self.roller_half_angle
    }

    /// Angle of the roller axis to the ring axis α_m = α_i + β \[rad\].
    pub fn roller_axis_angle(&self) -> f64 {
        self.inner_raceway_angle + self.roller_half_angle
    }

    /// The directions from the apex with the roller at cage angle `cage_angle` \[rad\]
    /// (0: the section plane `X`–`Z`).
    pub fn directions(&self, cage_angle: f64) -> Directions {
        let (s, c) = cage_angle.sin_cos();
        let meridian = |a: f64| Vector3::new(a.sin() * c, a.sin() * s, a.cos());
        Directions {
            axis: Vector3::z(),
            inner_line: meridian(self.inner_raceway_angle),
            outer_line: meridian(self.outer_raceway_angle()),
            roller_axis: meridian(self.roller_axis_angle()),
        }
    }

    /// Absolute angular velocity of the roller, ω_c e_z + ω_R e_r \[rad/s\].
    pub fn roller_angular_velocity(&self, cage_angle: f64) -> Vector3<f64> {
        let d = self.directions(cage_angle);
        d.axis * self.cage_speed + d.roller_axis * self.roller_spin
    }

    /// Angular velocity of the roller relative to the inner ring (the rib),
    /// ω_rel = λ e_in \[rad/s\]: a rotation about the inner raceway contact line.
    pub fn relative_angular_velocity(&self, cage_angle: f64) -> Vector3<f64> {
        self.directions(cage_angle).inner_line * self.relative_speed
    }

    /// The bodies' poses and twists `time` \[s\] after the instant at which the cage is at
    /// `cage_angle` \[rad\] and the rings and the roller are at their reference turn: the
    /// cage then stands at `cage_angle + ω_c t`, the rings at `ω_i t`, `ω_o t`, the roller
    /// turned by `ω_R t` about its axis. Rings and cage have their reference point at the
    /// apex (velocity 0); the roller's reference point `C` lies on its axis at
    /// `roller_reference` from the apex and moves with the cage, `ω_c e_z × (C − A)`.
    ///
    /// # Errors
    /// [`Error::InvalidInput`] (field `cage_angle` / `time`) for a non-finite value.
    pub fn bodies(&self, cage_angle: f64, time: f64) -> Result<Bodies> {
        if !cage_angle.is_finite() {
            return Err(Error::invalid(
                "cage_angle",
                cage_angle,
                "a finite angle in rad",
            ));
        }
        if !time.is_finite() {
            return Err(Error::invalid("time", time, "a finite time in s"));
        }
        let theta = cage_angle + self.cage_speed * time;
        let turn = |angle: f64| UnitQuaternion::from_axis_angle(&Vector3::z_axis(), angle);
        let ring = |speed: f64, angle: f64| BodyState {
            pose: Isometry3::from_parts(Translation3::from(self.apex.coords), turn(angle)),
            twist: Twist::new(Vector3::zeros(), Vector3::z() * speed),
        };
        let d = self.directions(theta);
        let e_r0 = Unit::new_normalize(self.directions(0.0).roller_axis);
        // Local z along the roller axis at cage angle 0, then the spin, then the cage turn.
        let base = UnitQuaternion::rotation_between(&Vector3::z(), &e_r0)
            .unwrap_or_else(UnitQuaternion::identity);
        let rotation =
            turn(theta) * UnitQuaternion::from_axis_angle(&e_r0, self.roller_spin * time) * base;
        let centre = self.apex + d.roller_axis * self.roller_reference;
        let omega_c = Vector3::z() * self.cage_speed;
        let roller = BodyState {
            pose: Isometry3::from_parts(Translation3::from(centre.coords), rotation),
            twist: Twist::new(
                omega_c.cross(&(centre - self.apex)),
                omega_c + d.roller_axis * self.roller_spin,
            ),
        };
        Ok(Bodies {
            inner: ring(self.inner_speed, self.inner_speed * time),
            outer: ring(self.outer_speed, self.outer_speed * time),
            cage: ring(self.cage_speed, theta),
            roller,
        })
    }

    /// The roller (body 1) on the rib of the inner ring (body 2), observed from the cage,
    /// with the cage at `cage_angle` \[rad\].
    ///
    /// # Errors
    /// Those of [`TaperedKinematics::bodies`].
    pub fn rib_pair(&self, cage_angle: f64) -> Result<ContactPair> {
        let b = self.bodies(cage_angle, 0.0)?;
        Ok(ContactPair {
            body1: b.roller,
            body2: b.inner,
            observer: b.cage,
        })
    }

    /// Sliding velocity of the roller on the inner ring at the world point `point` by the
    /// common-apex form, `ω_rel × (P − A)` \[mm/s\] (not projected).
    pub fn relative_velocity_at(&self, cage_angle: f64, point: &Point3<f64>) -> Vector3<f64> {
        self.relative_angular_velocity(cage_angle)
            .cross(&(point - self.apex))
    }
}

#[cfg(test)]
#[allow(clippy::unwrap_used)]
mod tests {
    use super::*;

    #[test]
    fn slide_to_roll_is_none_when_it_would_overflow() {
        let v = ContactVelocities {
            sliding: Vector3::new(1.0, 0.0, 0.0),
            entrainment: Vector3::new(1e-320, 0.0, 0.0),
        };
        assert_eq!(v.slide_to_roll(), None);
        let v = ContactVelocities {
            sliding: Vector3::new(3.0, 0.0, 0.0),
            entrainment: Vector3::new(0.0, 4.0, 0.0),
        };
        assert_eq!(v.slide_to_roll(), Some(0.75));
    }

    #[test]
    fn cage_speed_closed_form_and_relative_rotation_axis() {
        // α_i = 20°, β = 3°: outer fixed ω_c = ω_i sin α_i / (sin α_i + sin α_o).
        let (ai, b) = (20f64.to_radians(), 3f64.to_radians());
        let k = TaperedKinematics::new(ai, b, Point3::origin(), 80.0, 100.0, 0.0).unwrap();
        let expected = 100.0 * ai.sin() / (ai.sin() + (ai + 2.0 * b).sin());
        assert!((k.cage_speed - expected).abs() < 1e-12 * 100.0);
        // ω_roller − ω_i e_z is parallel to the inner contact line.
        let rel = k.roller_angular_velocity(0.4) - Vector3::z() * k.inner_speed;
        let along = k.directions(0.4).inner_line;
        assert!(rel.cross(&along).norm() < 1e-12 * rel.norm());
        assert!((rel - k.relative_angular_velocity(0.4)).norm() < 1e-12 * rel.norm());
    }
}
