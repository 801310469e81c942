//! Rigid bodies in contact: a body's pose and twist ([`BodyState`]), a contact frame, and
//! the sliding and entrainment velocities of two bodies at a contact point
//! ([`ContactPair::velocities`]), on every cell of a contact grid
//! ([`ContactPair::fill_field`]) or as the affine field that rigid motion gives
//! ([`ContactPair::velocity_field`], the allocation-free form for hot loops).
//!
//! Units: mm, mm/s, rad/s. Frame: every point and vector is in the world frame.
//!
//! Sliding `v_s = P_t(v_1(P) − v_2(P))` and entrainment
//! `u = P_t((v_1(P) + v_2(P))/2 − v_obs(P))` at a world point `P`, `P_t = I − n nᵀ` the
//! projection onto the contact plane (normal `n`) and `v_obs` the velocity of the frame in
//! which the contact is steady (the cage for a roller/rib contact; a body at rest gives
//! the plain mean surface velocity). Sliding does not depend on the observer.
//!
//! Each body point moves at `v(P) = v_ref + ω × (P − O)`, affine in `P`; so both fields are
//! affine over the contact plane. In a grid frame with axes `g_x`, `g_y` (cell `(x, y)` at
//! `origin + x g_x + y g_y`) the in-plane components are
//! `v(x, y) = v(origin) + x (Δω × g_x) + y (Δω × g_y)` projected on `g_x`, `g_y`, exact to
//! round-off: [`VelocityField`] stores the six numbers per field.

use crate::error::{Error, Result};
use crate::geometry::{Grid2, Twist};
use nalgebra::{Isometry3, Point3, Unit, Vector3};

/// A rigid body's pose and velocity at one instant (world frame).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct BodyState {
    /// Pose: the body frame's origin is the body's reference point \[mm\].
    pub pose: Isometry3<f64>,
    /// Velocity of the reference point \[mm/s\] and angular velocity \[rad/s\].
    pub twist: Twist,
}

impl BodyState {
    /// A body at rest at the identity pose (the world frame as an observer).
    pub fn at_rest() -> Self {
        BodyState {
            pose: Isometry3::identity(),
            twist: Twist::zero(),
        }
    }

    /// Velocity \[mm/s\] of the body point at the world point `point` \[mm\].
    pub fn velocity_at(&self, point: &Point3<f64>) -> Vector3<f64> {
        self.twist.velocity_at(&self.pose, point)
    }

    /// Whether the pose and the twist are finite.
    pub fn is_finite(&self) -> bool {
        self.twist.is_finite()
            && self.pose.translation.vector.iter().all(|c| c.is_finite())
            && self.pose.rotation.coords.iter().all(|c| c.is_finite())
    }
}

/// Sliding and entrainment velocity at a contact point, in the contact plane \[mm/s\]
/// (world frame).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ContactVelocities {
    /// Sliding velocity `v_s = P_t(v_1 − v_2)` \[mm/s\].
    pub sliding: Vector3<f64>,
    /// Entrainment (mean surface) velocity `u = P_t((v_1 + v_2)/2 − v_obs)` \[mm/s\].
    pub entrainment: Vector3<f64>,
}

impl ContactVelocities {
    /// Slide-to-roll ratio `|v_s| / |u|`; `None` when `|u| = 0` (or so small that the
    /// ratio overflows): the ratio is undefined there, never NaN or inf.
    pub fn slide_to_roll(&self) -> Option<f64> {
        let u = self.entrainment.norm();
        if u > 0.0 {
            let r = self.sliding.norm() / u;
            r.is_finite().then_some(r)
        } else {
            None
        }
    }
}

/// An orthonormal contact frame: origin and axes in the world frame (as the frame of a
/// [`crate::gap::SurfacePairGap`]: `ex`, `ey` span the contact plane, `normal = ex × ey`).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ContactFrame {
    /// Contact point \[mm\].
    pub origin: Point3<f64>,
    /// First in-plane axis.
    pub ex: Unit<Vector3<f64>>,
    /// Second in-plane axis.
    pub ey: Unit<Vector3<f64>>,
    /// Contact normal.
    pub normal: Unit<Vector3<f64>>,
}

impl ContactFrame {
    /// A frame from its origin and axes.
    ///
    /// # Errors
    /// [`Error::InvalidInput`] (field `frame.origin` / `frame.axes`) for a non-finite origin
    /// or axes that are not a right-handed orthonormal triad to 1e-9.
    pub fn new(
        origin: Point3<f64>,
        ex: Unit<Vector3<f64>>,
        ey: Unit<Vector3<f64>>,
        normal: Unit<Vector3<f64>>,
    ) -> Result<Self> {
        if !origin.iter().all(|c| c.is_finite()) {
            return Err(Error::invalid(
                "frame.origin",
                origin,
                "a finite point in mm",
            ));
        }
        let err = (ex.cross(&ey) - normal.into_inner()).norm() + ex.dot(&ey).abs();
        if !(err < 1e-9) {
            return Err(Error::invalid(
                "frame.axes",
                format!("ex {ex:?}, ey {ey:?}, n {normal:?}"),
                "orthonormal unit vectors with ex × ey = normal",
            ));
        }
        Ok(ContactFrame {
            origin,
            ex,
            ey,
            normal,
        })
    }
}

/// Two bodies in contact and the observer in whose frame the contact is steady.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ContactPair {
    /// Body 1 (the roller for the rib contact).
    pub body1: BodyState,
    /// Body 2 (the inner ring, which carries the rib).
    pub body2: BodyState,
    /// The frame the entrainment velocity is measured in (the cage for the rib contact;
    /// [`BodyState::at_rest`] for the world frame).
    pub observer: BodyState,
}

impl ContactPair {
    /// Sliding `P_t(v_1(P) − v_2(P))` and entrainment `P_t((v_1(P) + v_2(P))/2 − v_obs(P))`
    /// at the world point `point` \[mm\] with contact normal `normal`, `P_t = I − n nᵀ`
    /// (world frame, mm/s).
    ///
    /// # Errors
    /// [`Error::InvalidInput`] (field `point`, `normal`, `body1`, `body2` or `observer`)
    /// for a non-finite input.
    pub fn velocities(
        &self,
        point: &Point3<f64>,
        normal: &Unit<Vector3<f64>>,
    ) -> Result<ContactVelocities> {
        self.check()?;
        if !point.iter().all(|c| c.is_finite()) {
            return Err(Error::invalid("point", point, "a finite point in mm"));
        }
        if !normal.iter().all(|c| c.is_finite()) {
            return Err(Error::invalid(
                "normal",
                normal.into_inner(),
                "a finite unit vector",
            ));
        }
        let v1 = self.body1.velocity_at(point);
        let v2 = self.body2.velocity_at(point);
        let vo = self.observer.velocity_at(point);
        let n = normal.into_inner();
        let tangential = |v: Vector3<f64>| v - n * n.dot(&v);
        Ok(ContactVelocities {
            sliding: tangential(v1 - v2),
            entrainment: tangential(0.5 * (v1 + v2) - vo),
        })
    }

    /// Fill `sliding` and `entrainment` with the velocities \[mm/s\] at every cell of
    /// `grid`, as 2-D vectors `[x, y]` in the grid frame, row-major with x fastest (the
    /// layout of [`crate::field::NormalSolution::pressure`]). The grid lies in the contact
    /// plane of `frame`, turned by `orientation` \[rad\] from `frame.ex` about the normal
    /// (as a `NormalSolution`'s grid from its gap source's x axis): the cell `(x, y)` is the
    /// world point `origin + x g_x + y g_y` with `g_x = cos θ ex + sin θ ey`,
    /// `g_y = −sin θ ex + cos θ ey`. Does not allocate.
    ///
    /// # Errors
    /// [`Error::InvalidInput`] (field `sliding` / `entrainment`) when a buffer's length is
    /// not the grid's cell count, (field `orientation`) for a non-finite angle, and those
    /// of [`ContactPair::velocities`] for non-finite bodies.
    pub fn fill_field(
        &self,
        frame: &ContactFrame,
        grid: &Grid2,
        orientation: f64,
        sliding: &mut [[f64; 2]],
        entrainment: &mut [[f64; 2]],
    ) -> Result<()> {
        self.check()?;
        for (name, len) in [
            ("sliding", sliding.len()),
            ("entrainment", entrainment.len()),
        ] {
            if len != grid.len() {
                return Err(Error::invalid(
                    name,
                    format!("a buffer of {len} cells"),
                    format!("{} cells ({} × {})", grid.len(), grid.nx(), grid.ny()),
                ));
            }
        }
        let (gx, gy) = grid_axes(frame, orientation)?;
        for j in 0..grid.ny() {
            let y = grid.y(j);
            for i in 0..grid.nx() {
                let x = grid.x(i);
                let p = frame.origin + gx * x + gy * y;
                let v1 = self.body1.velocity_at(&p);
                let v2 = self.body2.velocity_at(&p);
                let vo = self.observer.velocity_at(&p);
                let vs = v1 - v2;
                let u = 0.5 * (v1 + v2) - vo;
                let k = j * grid.nx() + i;
                sliding[k] = [vs.dot(&gx), vs.dot(&gy)];
                entrainment[k] = [u.dot(&gx), u.dot(&gy)];
            }
        }
        Ok(())
    }

    /// The sliding and entrainment fields over the contact plane of `frame`, in the grid
    /// frame turned by `orientation` \[rad\] from `frame.ex` about the normal (the layout of
    /// [`ContactPair::fill_field`]), as exact affine functions of the in-plane coordinates.
    /// Does not allocate.
    ///
    /// # Errors
    /// [`Error::InvalidInput`] (field `orientation`) for a non-finite angle, and those of
    /// [`ContactPair::velocities`] for non-finite bodies.
    pub fn velocity_field(&self, frame: &ContactFrame, orientation: f64) -> Result<VelocityField> {
        self.check()?;
        let (gx, gy) = grid_axes(frame, orientation)?;
        let o = frame.origin;
        let (v1, v2, vo) = (
            self.body1.velocity_at(&o),
            self.body2.velocity_at(&o),
            self.observer.velocity_at(&o),
        );
        let (w1, w2, wo) = (
            self.body1.twist.angular,
            self.body2.twist.angular,
            self.observer.twist.angular,
        );
        let project = |v: Vector3<f64>| [v.dot(&gx), v.dot(&gy)];
        let affine = |at: Vector3<f64>, w: Vector3<f64>| {
            [project(at), project(w.cross(&gx)), project(w.cross(&gy))]
        };
        Ok(VelocityField {
            sliding: affine(v1 - v2, w1 - w2),
            entrainment: affine(0.5 * (v1 + v2) - vo, 0.5 * (w1 + w2) - wo),
        })
    }

    fn check(&self) -> Result<()> {
        for (name, b) in [
            ("body1", &self.body1),
            ("body2", &self.body2),
            ("observer", &self.observer),
        ] {
            if !b.is_finite() {
                return Err(Error::invalid(
                    name,
                    format!("{:?}", b.twist),
                    "a finite pose and twist",
                ));
            }
        }
        Ok(())
    }
}

/// The grid axes `g_x = cos θ ex + sin θ ey`, `g_y = −sin θ ex + cos θ ey` of a grid turned
/// by `θ = orientation` from the frame's `ex` about its normal.
fn grid_axes(frame: &ContactFrame, orientation: f64) -> Result<(Vector3<f64>, Vector3<f64>)> {
    if !orientation.is_finite() {
        return Err(Error::invalid(
            "orientation",
            orientation,
            "a finite angle in rad",
        ));
    }
    let (s, c) = super::sin_cos(orientation);
    let (ex, ey) = (frame.ex.into_inner(), frame.ey.into_inner());
    Ok((ex * c + ey * s, -ex * s + ey * c))
}

/// The sliding and entrainment velocities over a contact plane as affine functions of the
/// in-plane coordinates `(x, y)` \[mm\] of a grid frame (see the module docs), in mm/s.
/// Exact for rigid bodies; evaluating a cell costs four multiply-adds per field.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct VelocityField {
    /// Sliding at the origin `[x, y]` and its derivatives along x and y \[mm/s, 1/s\]:
    /// `v_s(x, y) = sliding[0] + x sliding[1] + y sliding[2]`.
    pub sliding: [[f64; 2]; 3],
    /// Entrainment, the same layout \[mm/s, 1/s\].
    pub entrainment: [[f64; 2]; 3],
}

impl VelocityField {
    /// Sliding velocity `[x, y]` \[mm/s\] at the in-plane point `(x, y)` \[mm\].
    #[inline]
    pub fn sliding_at(&self, x: f64, y: f64) -> [f64; 2] {
        let [o, dx, dy] = self.sliding;
        [o[0] + x * dx[0] + y * dy[0], o[1] + x * dx[1] + y * dy[1]]
    }

    /// Entrainment velocity `[x, y]` \[mm/s\] at the in-plane point `(x, y)` \[mm\].
    #[inline]
    pub fn entrainment_at(&self, x: f64, y: f64) -> [f64; 2] {
        let [o, dx, dy] = self.entrainment;
        [o[0] + x * dx[0] + y * dy[0], o[1] + x * dx[1] + y * dy[1]]
    }
}
