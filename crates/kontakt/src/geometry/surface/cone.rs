//! The cone $x^2+y^2 - m z^2 = 0$, $m = \tan^2\alpha$ (Wirsching et al. (2020) eq. 1): the rib of a
//! tapered roller bearing.
//!
//! Only the nappe `z > 0` is the surface. In a meridian half-plane (ρ = √(x²+y²) >= 0, z)
//! the surface is the half-line from the apex along $\mathbf u = (\sin\alpha, \cos\alpha)$,
//! and the exact signed distance of the enclosed solid is
//! $$ d = \begin{cases} \rho\cos\alpha - z\sin\alpha & \text{if } \rho\sin\alpha + z\cos\alpha \ge
//! 0,\\ \sqrt{\rho^2+z^2} & \text{otherwise (the apex is nearest).} \end{cases} $$

use super::{Material, Shape, outer, quadratic_roots, radial};
use crate::error::{Error, Result};
use nalgebra::{Matrix3, Point3, Vector3};
use std::f64::consts::FRAC_PI_2;

/// A cone with apex at the local origin, axis `+z`, half-angle α (nappe `z > 0`).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Cone {
    half_angle: f64,
    sin: f64,
    cos: f64,
    m: f64,
    material: Material,
}

impl Cone {
    /// A cone of half-angle `half_angle` \[rad\], 0 < α < π/2.
    ///
    /// # Errors
    /// [`Error::InvalidInput`] (field `half_angle`) outside (0, π/2) or NaN.
    pub fn new(half_angle: f64, material: Material) -> Result<Self> {
        if !(half_angle > 0.0 && half_angle < FRAC_PI_2) {
            return Err(Error::invalid(
                "half_angle",
                half_angle,
                "a half-angle in (0, pi/2) rad, both ends excluded (0 is a line, pi/2 a plane)",
            ));
        }
        let (sin, cos) = half_angle.sin_cos();
        let tan = sin / cos;
        Ok(Cone {
            half_angle,
            sin,
            cos,
            m: tan * tan,
            material,
        })
    }

    /// Half-angle α \[rad\].
    pub fn half_angle(&self) -> f64 {
        self.half_angle
    }

    /// $m = \tan^2\alpha$ of Wirsching et al. (2020) eq. (1).
    pub fn m(&self) -> f64 {
        self.m
    }

    /// The side of the material.
    pub fn material(&self) -> Material {
        self.material
    }

    /// Projection of `p` on the generatrix in its meridian half-plane, ρ sin α + z cos α.
    fn along(&self, rho: f64, z: f64) -> f64 {
        rho * self.sin + z * self.cos
    }

    /// Signed distance along the ray `oc + s d` and its derivative (the `along >= 0`
    /// branch), for the Newton polish.
    fn ray_sdf(&self, p: &Point3<f64>, d: &Vector3<f64>) -> (f64, f64) {
        let (er, rho) = radial(p);
        let f = rho * self.cos - p.z * self.sin;
        let f1 = (er.x * d.x + er.y * d.y) * self.cos - d.z * self.sin;
        (f, f1)
    }

    /// Whether the unit direction `u` from the apex points into the solid.
    fn inside_direction(&self, u: &Vector3<f64>) -> bool {
        u.z > 0.0 && u.x.hypot(u.y) * self.cos < u.z * self.sin
    }
}

impl Shape for Cone {
    fn implicit(&self, p: &Point3<f64>) -> f64 {
        p.x * p.x + p.y * p.y - self.m * p.z * p.z.abs()
    }

    fn signed_distance(&self, p: &Point3<f64>) -> f64 {
        let rho = p.x.hypot(p.y);
        if self.along(rho, p.z) >= 0.0 {
            rho * self.cos - p.z * self.sin
        } else {
            p.coords.norm()
        }
    }

    fn normal(&self, p: &Point3<f64>) -> Vector3<f64> {
        self.foot(p).1
    }

    fn foot(&self, p: &Point3<f64>) -> (Point3<f64>, Vector3<f64>) {
        let (er, rho) = radial(p);
        let s = self.along(rho, p.z);
        if s > 0.0 {
            let q = er * (s * self.sin) + Vector3::z() * (s * self.cos);
            (Point3::from(q), er * self.cos - Vector3::z() * self.sin)
        } else {
            let len = p.coords.norm();
            let n = if len > 0.0 {
                p.coords / len
            } else {
                -Vector3::z()
            };
            (Point3::origin(), n)
        }
    }

    fn curvature(&self, p: &Point3<f64>) -> [(f64, Vector3<f64>); 2] {
        let (er, rho) = radial(p);
        let s = self.along(rho, p.z).max(0.0);
        let generatrix = er * self.sin + Vector3::z() * self.cos;
        let around = Vector3::new(-er.y, er.x, 0.0);
        // Parallel circle of radius rho_f = s sin(alpha): normal curvature cos(alpha)/rho_f.
        let k_around = self.cos / (s * self.sin);
        [(0.0, generatrix), (k_around, around)]
    }

    fn sdf_hessian(&self, p: &Point3<f64>) -> Matrix3<f64> {
        let (er, rho) = radial(p);
        let tiny = f64::MIN_POSITIVE.sqrt();
        if self.along(rho, p.z) >= 0.0 {
            // d = rho cos(a) - z sin(a); Hess(rho) = e_phi e_phiᵀ / rho.
            let around = Vector3::new(-er.y, er.x, 0.0);
            outer(&around) * (self.cos / rho.max(tiny))
        } else {
            let len = p.coords.norm();
            let n = p.coords / len.max(tiny);
            (Matrix3::identity() - outer(&n)) / len.max(tiny)
        }
    }

    fn intersect(
        &self,
        o: &Point3<f64>,
        d: &Vector3<f64>,
        t_min: f64,
        t_max: f64,
    ) -> Option<(f64, Point3<f64>)> {
        // Rebase at the closest approach to the apex to keep the constant term small.
        let tc = -o.coords.dot(d);
        let oc = o + d * tc;
        let m = self.m;
        let a = d.x * d.x + d.y * d.y - m * d.z * d.z;
        let b = 2.0 * (oc.x * d.x + oc.y * d.y - m * oc.z * d.z);
        let c = oc.x * oc.x + oc.y * oc.y - m * oc.z * oc.z;
        let Some((r1, r2)) = quadratic_roots(a, b, c) else {
            // No transversal crossing of the double cone, except through the apex itself:
            // the ray crosses there when exactly one of its two halves points into the solid.
            let apex_on_ray = oc.coords.norm() <= 4.0 * f64::EPSILON * o.coords.norm();
            let crosses = self.inside_direction(d) != self.inside_direction(&-d);
            return (apex_on_ray && crosses && tc >= t_min && tc <= t_max)
                .then(|| (tc, Point3::origin()));
        };
        for s in [r1, r2] {
            let t = tc + s;
            if !(t >= t_min && t <= t_max) {
                continue;
            }
            let p = oc + d * s;
            if p.z < 0.0 {
                continue; // the mirrored nappe is not part of the surface
            }
            // One Newton step on the exact signed distance.
            let (f, f1) = self.ray_sdf(&p, d);
            if f1.abs() > 1e-4 {
                let ds = -f / f1;
                let t_new = t + ds;
                if t_new >= t_min && t_new <= t_max {
                    return Some((t_new, oc + d * (s + ds)));
                }
            }
            return Some((t, p));
        }
        None
    }

    fn extent(&self) -> f64 {
        0.0
    }
}
