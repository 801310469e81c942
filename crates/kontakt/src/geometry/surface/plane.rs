//! The plane `z = 0` (Wirsching et al. (2020): the rib of a cylindrical roller bearing seen from
//! far, the flat of the sphere-on-plane comparison of Wirsching et al. (2019)).

use super::{Material, Shape};
use nalgebra::{Matrix3, Point3, Vector3};

/// The plane `z = 0` of the local frame; with [`Material::Inside`] the material is `z < 0`
/// and the outward normal `+z`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Plane {
    material: Material,
}

impl Plane {
    /// The plane with its material side.
    pub fn new(material: Material) -> Self {
        Plane { material }
    }

    /// The side of the material.
    pub fn material(&self) -> Material {
        self.material
    }
}

impl Shape for Plane {
    fn implicit(&self, p: &Point3<f64>) -> f64 {
        p.z
    }

    fn signed_distance(&self, p: &Point3<f64>) -> f64 {
        p.z
    }

    fn normal(&self, _p: &Point3<f64>) -> Vector3<f64> {
        Vector3::z()
    }

    fn foot(&self, p: &Point3<f64>) -> (Point3<f64>, Vector3<f64>) {
        (Point3::new(p.x, p.y, 0.0), Vector3::z())
    }

    fn curvature(&self, _p: &Point3<f64>) -> [(f64, Vector3<f64>); 2] {
        [(0.0, Vector3::x()), (0.0, Vector3::y())]
    }

    fn sdf_hessian(&self, _p: &Point3<f64>) -> Matrix3<f64> {
        Matrix3::zeros()
    }

    fn intersect(
        &self,
        o: &Point3<f64>,
        d: &Vector3<f64>,
        t_min: f64,
        t_max: f64,
    ) -> Option<(f64, Point3<f64>)> {
        if d.z == 0.0 {
            return None; // parallel: a miss, or the ray lies in the plane (grazing)
        }
        let t = -o.z / d.z;
        (t >= t_min && t <= t_max).then(|| (t, Point3::new(o.x + t * d.x, o.y + t * d.y, 0.0)))
    }

    fn extent(&self) -> f64 {
        0.0
    }
}
