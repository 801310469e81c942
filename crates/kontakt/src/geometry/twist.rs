//! Rigid-body velocity: the twist of a body (the velocity of its reference point and its
//! angular velocity) and the velocity of any point of it.
//!
//! Units: mm/s for linear velocities, rad/s for angular velocities, mm for positions.
//! Frame: every vector and point is in the world frame; the body's reference point is the
//! origin of its pose ([`Isometry3`]), which is also in the world frame.

use nalgebra::{Isometry3, Point3, Vector3};

/// The velocity state of a rigid body at one instant, in the world frame.
///
/// `linear` is the velocity \[mm/s\] of the body's reference point, the origin of its pose;
/// `angular` its angular velocity \[rad/s\] (right-hand rule about the vector).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Twist {
    /// Velocity of the body's reference point (its pose's origin) \[mm/s\], world frame.
    pub linear: Vector3<f64>,
    /// Angular velocity \[rad/s\], world frame.
    pub angular: Vector3<f64>,
}

impl Twist {
    /// A twist from the velocity of the reference point \[mm/s\] and the angular velocity
    /// \[rad/s\], both in the world frame.
    pub fn new(linear: Vector3<f64>, angular: Vector3<f64>) -> Self {
        Twist { linear, angular }
    }

    /// A body at rest.
    pub fn zero() -> Self {
        Twist {
            linear: Vector3::zeros(),
            angular: Vector3::zeros(),
        }
    }

    /// A pure rotation at `angular` \[rad/s\] about an axis through the world point
    /// `centre`, for a body whose pose has its origin at `origin`: the reference point moves
    /// at `angular × (origin − centre)` \[mm/s\].
    pub fn rotation_about(
        angular: Vector3<f64>,
        centre: &Point3<f64>,
        origin: &Point3<f64>,
    ) -> Self {
        Twist {
            linear: angular.cross(&(origin - centre)),
            angular,
        }
    }

    /// Velocity \[mm/s\] of the body point at the world point `point` \[mm\]:
    /// `v_P = v_O + ω × (P − O)`, with `O` the origin of `pose` (the body's reference
    /// point, whose velocity is `self.linear`). World frame throughout; only the pose's
    /// translation enters (the rotation does not change a velocity field).
    pub fn velocity_at(&self, pose: &Isometry3<f64>, point: &Point3<f64>) -> Vector3<f64> {
        let origin = Point3::from(pose.translation.vector);
        self.linear + self.angular.cross(&(point - origin))
    }

    /// `true` when every component is finite.
    pub fn is_finite(&self) -> bool {
        self.linear
            .iter()
            .chain(self.angular.iter())
            .all(|c| c.is_finite())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn velocity_of_a_point_of_a_turning_body() {
        // Body turning at 2 rad/s about z, reference point at (1, 0, 0) moving at (0, 2, 0):
        // the point (0, 1, 0) moves at (-2, 0, 0) (rotation about the world z axis).
        let pose = Isometry3::translation(1.0, 0.0, 0.0);
        let t = Twist::rotation_about(
            Vector3::new(0.0, 0.0, 2.0),
            &Point3::origin(),
            &Point3::new(1.0, 0.0, 0.0),
        );
        assert_eq!(t.linear, Vector3::new(0.0, 2.0, 0.0));
        let v = t.velocity_at(&pose, &Point3::new(0.0, 1.0, 0.0));
        assert!((v - Vector3::new(-2.0, 0.0, 0.0)).norm() < 1e-15, "{v}");
        // The axis point does not move.
        assert!(t.velocity_at(&pose, &Point3::new(0.0, 0.0, 5.0)).norm() < 1e-15);
    }
}
