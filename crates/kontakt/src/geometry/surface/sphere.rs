//! The sphere $x^2+y^2+z^2 = r^2$ (Wirsching et al. (2020) eq. 1): roller end faces with zero
//! eccentricity, balls.

use super::{Material, Shape, outer, tangent_basis};
use crate::error::{Result, positive_as};
use nalgebra::{Matrix3, Point3, Vector3};

/// A sphere of radius `r` centred at the local origin.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Sphere {
    radius: f64,
    material: Material,
}

impl Sphere {
    /// A sphere of radius `radius` \[mm\].
    ///
    /// # Errors
    /// [`crate::Error::InvalidInput`] (field `radius`) unless finite and > 0.
    pub fn new(radius: f64, material: Material) -> Result<Self> {
        positive_as("radius", radius, "a finite radius > 0 mm")?;
        Ok(Sphere { radius, material })
    }

    /// Radius r \[mm\].
    pub fn radius(&self) -> f64 {
        self.radius
    }

    /// The side of the material.
    pub fn material(&self) -> Material {
        self.material
    }
}

/// Unit vector along `p` (`+z` at the origin) and `|p|`.
fn direction(p: &Point3<f64>) -> (Vector3<f64>, f64) {
    let len = p.coords.norm();
    if len > 0.0 {
        (p.coords / len, len)
    } else {
        (Vector3::z(), 0.0)
    }
}

impl Shape for Sphere {
    fn implicit(&self, p: &Point3<f64>) -> f64 {
        p.coords.norm_squared() - self.radius * self.radius
    }

    fn signed_distance(&self, p: &Point3<f64>) -> f64 {
        p.coords.norm() - self.radius
    }

    fn normal(&self, p: &Point3<f64>) -> Vector3<f64> {
        direction(p).0
    }

    fn foot(&self, p: &Point3<f64>) -> (Point3<f64>, Vector3<f64>) {
        let n = direction(p).0;
        (Point3::from(n * self.radius), n)
    }

    fn curvature(&self, p: &Point3<f64>) -> [(f64, Vector3<f64>); 2] {
        let (e1, e2) = tangent_basis(&direction(p).0);
        let k = 1.0 / self.radius;
        [(k, e1), (k, e2)]
    }

    fn sdf_hessian(&self, p: &Point3<f64>) -> Matrix3<f64> {
        // sdf = |p| - r: Hessian (I - n nᵀ)/|p|.
        let (n, len) = direction(p);
        (Matrix3::identity() - outer(&n)) / len.max(f64::MIN_POSITIVE.sqrt())
    }

    fn intersect(
        &self,
        o: &Point3<f64>,
        d: &Vector3<f64>,
        t_min: f64,
        t_max: f64,
    ) -> Option<(f64, Point3<f64>)> {
        let r = self.radius;
        // Move the origin to the closest approach to the centre: the quadratic becomes
        // s² = r² - |oc|² with no cancellation for far origins (Haines et al., Ray Tracing
        // Gems, 2019, ch. 7), the same roots as the stable q-formula.
        let tc = -o.coords.dot(d);
        let oc = o + d * tc;
        let b = oc.coords.norm();
        if !(b < r) {
            return None; // miss or tangent (grazing)
        }
        let half = ((r - b) * (r + b)).sqrt();
        // Rebased, the hit point oc + s d is on the sphere to a few ulps of r (no polish
        // needed; the tests check 1e-12 r with origins up to 5 r away).
        [-half, half]
            .into_iter()
            .map(|s| (tc + s, s))
            .find(|(t, _)| *t >= t_min && *t <= t_max)
            .map(|(t, s)| (t, oc + d * s))
    }

    fn extent(&self) -> f64 {
        self.radius
    }
}
