//! Geometry: principal curvatures of contacting bodies and their relative curvature,
//! sampling grids, the analytic surfaces of the PimP method with ray casting, and the
//! contact point between two placed surfaces.
//!
//! - [`curvature`]: relative curvature of two bodies from their principal radii.
//! - [`grid`]: uniform sampling grids in the contact plane.
//! - [`surface`]: plane, sphere, cone, torus (Wirsching et al. (2020) eq. 1) and surfaces of
//!   revolution
//!   in canonical local frames; signed distance, normals, principal curvatures, closest
//!   points and robust ray casting along $\mathbf s(t) = \mathbf q + t\,\mathbf n$
//!   (Wirsching et al. (2020) eq. 2); [`PlacedSurface`] puts a surface in the world with a pose.
//! - [`contact_point`]: the points of two placed surfaces with anti-parallel normals
//!   (closest points, or the deepest point of an interpenetration), step 1 of PimP.
//! - [`twist`]: rigid-body velocity ([`Twist`]: velocity of the reference point and angular
//!   velocity, world frame) and the velocity of a body point.
//! - [`motion`]: two bodies in contact: contact frame, sliding and entrainment velocities at
//!   a point, on a grid, or as the exact affine field of rigid motion.

pub mod contact_point;
pub mod curvature;
pub mod grid;
pub mod motion;
pub mod surface;
pub mod twist;

pub use contact_point::{ContactPoint, find_contact};
pub use curvature::RelativeCurvature;
pub use grid::Grid2;
pub use motion::{BodyState, ContactFrame, ContactPair, ContactVelocities, VelocityField};
pub use surface::{Curvature, Hit, Material, PlacedSurface, Profile, Ray, Surface};
pub use twist::Twist;

/// `(sin θ, cos θ)` of an angle \[rad\], exactly `(0, 1)` at θ = 0 without the library call:
/// the grid frames of the Hertz path are not turned (θ = 0), and a per-call `sin_cos` there
/// costs as much as a dozen multiplications. Bit for bit `f64::sin_cos` everywhere.
#[inline]
pub(crate) fn sin_cos(angle: f64) -> (f64, f64) {
    if angle == 0.0 {
        (0.0, 1.0)
    } else {
        angle.sin_cos()
    }
}
