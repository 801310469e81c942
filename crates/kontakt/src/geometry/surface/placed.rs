//! A surface placed in the world by a rigid transform.

use super::{Curvature, Hit, Material, Ray, Surface};
use crate::error::{Error, Result};
use nalgebra::{Isometry3, Point3, Unit, Vector3};

/// A surface placed in the world: `pose` maps local coordinates to world coordinates
/// (the body's frame in the global frame of a multi-body simulation, Wirsching et al. (2020) step
/// 1).
///
/// All queries take and return world coordinates and have the semantics of the
/// [`Surface`] method of the same name; distances, ray parameters and curvatures are
/// invariant under the rigid motion.
#[derive(Debug, Clone, PartialEq)]
pub struct PlacedSurface {
    /// The surface in its canonical local frame.
    pub surface: Surface,
    /// Local → world rigid transform.
    pub pose: Isometry3<f64>,
}

impl PlacedSurface {
    /// Place `surface` with `pose` (local → world).
    ///
    /// # Errors
    /// [`Error::InvalidInput`] (field `pose`) when the translation or the rotation
    /// quaternion has a non-finite entry, or the quaternion is not of unit length (to 1e-9).
    pub fn new(surface: Surface, pose: Isometry3<f64>) -> Result<Self> {
        check_pose(&pose)?;
        Ok(PlacedSurface { surface, pose })
    }

    /// The side of the surface the material is on.
    pub fn material(&self) -> Material {
        self.surface.material()
    }

    /// `p` (world) in the local frame.
    pub fn to_local(&self, p: &Point3<f64>) -> Point3<f64> {
        self.pose.inverse_transform_point(p)
    }

    /// `v` (local) in the world frame.
    fn vec_to_world(&self, v: &Vector3<f64>) -> Vector3<f64> {
        self.pose.rotation.transform_vector(v)
    }

    fn unit_to_world(&self, v: &Unit<Vector3<f64>>) -> Unit<Vector3<f64>> {
        Unit::new_unchecked(self.vec_to_world(v))
    }

    fn ray_to_local(&self, ray: &Ray) -> Ray {
        Ray {
            origin: self.pose.inverse_transform_point(&ray.origin),
            dir: Unit::new_unchecked(self.pose.inverse_transform_vector(&ray.dir)),
        }
    }

    /// Signed distance \[mm\] from the world point `p`, negative inside the material.
    pub fn signed_distance(&self, p: &Point3<f64>) -> f64 {
        self.surface.signed_distance(&self.to_local(p))
    }

    /// The sign-normalised implicit function at the world point `p` (see
    /// [`Surface::implicit`]).
    pub fn implicit(&self, p: &Point3<f64>) -> f64 {
        self.surface.implicit(&self.to_local(p))
    }

    /// Outward unit normal (world) at or near the world point `p`.
    pub fn normal(&self, p: &Point3<f64>) -> Unit<Vector3<f64>> {
        self.unit_to_world(&self.surface.normal(&self.to_local(p)))
    }

    /// Principal curvatures at the surface point nearest to the world point `p`, with the
    /// principal directions in world coordinates.
    pub fn curvature(&self, p: &Point3<f64>) -> Curvature {
        let c = self.surface.curvature(&self.to_local(p));
        Curvature {
            d1: self.unit_to_world(&c.d1),
            d2: self.unit_to_world(&c.d2),
            ..c
        }
    }

    /// [`PlacedSurface::curvature`] at the world point `q` on the surface whose outward
    /// normal (world) is `n`: a contact search's foot, whose foot is not searched again.
    pub(crate) fn curvature_on(&self, q: &Point3<f64>, n: &Unit<Vector3<f64>>) -> Curvature {
        let local = Unit::new_unchecked(self.pose.inverse_transform_vector(n));
        let c = self.surface.curvature_on(&self.to_local(q), &local);
        Curvature {
            d1: self.unit_to_world(&c.d1),
            d2: self.unit_to_world(&c.d2),
            ..c
        }
    }

    /// The nearest crossing of the world ray with the surface for `t` in `[t_min, t_max]`
    /// (see [`Surface::intersect`]); point and normal in world coordinates.
    pub fn intersect(&self, ray: &Ray, t_min: f64, t_max: f64) -> Option<Hit> {
        let hit = self
            .surface
            .intersect(&self.ray_to_local(ray), t_min, t_max)?;
        Some(Hit {
            t: hit.t,
            point: self.pose.transform_point(&hit.point),
            normal: self.unit_to_world(&hit.normal),
        })
    }

    /// The root of [`PlacedSurface::intersect`] from a guess (see
    /// [`Surface::intersect_near`] for the contract).
    pub fn intersect_near(&self, ray: &Ray, t_guess: f64, t_min: f64, t_max: f64) -> Option<f64> {
        self.surface
            .intersect_near(&self.ray_to_local(ray), t_guess, t_min, t_max)
    }

    /// [`PlacedSurface::intersect_near`] of the ray from the world point `origin` along the
    /// direction whose local image is `dir_local` (`pose⁻¹` applied to the world direction):
    /// the same root, bit for bit, for rays that share a direction with one rotation fewer
    /// each (the gap stencil's rays along the contact normal).
    pub(crate) fn intersect_near_along(
        &self,
        origin: &Point3<f64>,
        dir_local: &Unit<Vector3<f64>>,
        t_guess: f64,
        t_min: f64,
        t_max: f64,
    ) -> Option<f64> {
        let local = Ray {
            origin: self.pose.inverse_transform_point(origin),
            dir: *dir_local,
        };
        self.surface.intersect_near(&local, t_guess, t_min, t_max)
    }

    /// The local image of the world direction `dir` (for
    /// [`PlacedSurface::intersect_near_along`]).
    pub(crate) fn dir_to_local(&self, dir: &Unit<Vector3<f64>>) -> Unit<Vector3<f64>> {
        Unit::new_unchecked(self.pose.inverse_transform_vector(dir))
    }

    /// The surface point nearest to the world point `p` and the outward normal there
    /// (world).
    pub fn closest_point(&self, p: &Point3<f64>) -> (Point3<f64>, Unit<Vector3<f64>>) {
        let (q, n) = self.surface.closest_point(&self.to_local(p));
        (self.pose.transform_point(&q), self.unit_to_world(&n))
    }

    /// [`PlacedSurface::closest_point`] and [`PlacedSurface::signed_distance`] of the world
    /// point `p` at once: the foot \[mm\], the outward normal there (world), the signed
    /// distance \[mm\].
    pub fn closest_point_distance(
        &self,
        p: &Point3<f64>,
    ) -> (Point3<f64>, Unit<Vector3<f64>>, f64) {
        let (q, n, d) = self.surface.closest_point_distance(&self.to_local(p));
        (self.pose.transform_point(&q), self.unit_to_world(&n), d)
    }
}

/// The check of [`PlacedSurface::new`]: a finite translation and a finite unit quaternion
/// (to 1e-9); else [`Error::InvalidInput`] for the field `pose`.
pub(crate) fn check_pose(pose: &Isometry3<f64>) -> Result<()> {
    let t = &pose.translation.vector;
    let q = pose.rotation.quaternion().coords;
    let finite = t.iter().chain(q.iter()).all(|c| c.is_finite());
    // |‖q‖ − 1| ≤ 1e-9 on the squared norm (no square root per call).
    const LO: f64 = (1.0 - 1e-9) * (1.0 - 1e-9);
    const HI: f64 = (1.0 + 1e-9) * (1.0 + 1e-9);
    let n2 = q.norm_squared();
    if !finite || !(LO..=HI).contains(&n2) {
        return Err(Error::invalid(
            "pose",
            format!(
                "translation [{}, {}, {}], rotation quaternion [w {}, i {}, j {}, k {}]",
                t.x, t.y, t.z, q.w, q.x, q.y, q.z
            ),
            "a rigid transform with a finite translation in mm and a finite unit quaternion",
        ));
    }
    Ok(())
}
