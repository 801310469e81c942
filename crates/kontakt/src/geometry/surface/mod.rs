//! Analytic surfaces of the PimP method, ray casting and closest points.
//!
//! The roller end face and the rib are described by the implicit equations of Wirsching et al.
//! (2020) eq. (1) (also Wirsching et al. (2019) eq. 1), each in its own canonical local frame:
//!
//! | surface | local frame | implicit equation |
//! |---|---|---|
//! | [`Plane`] | the plane `z = 0` | $z = 0$ |
//! | [`Sphere`] | centre at the origin | $x^2+y^2+z^2 = r^2$ |
//! | [`Cone`] | apex at the origin, axis `+z`, nappe `z > 0` | $x^2+y^2 - m z^2 = 0$, $m = \tan^2\alpha$ |
//! | [`Torus`] | centre at the origin, axis `z` | $(x^2+y^2+z^2+R^2-r^2)^2 = 4R^2(x^2+y^2)$ |
//! | [`Revolution`] | axis `z` | $\sqrt{x^2+y^2} = \rho(z)$, $z_{min} \le z \le z_{max}$ |
//!
//! A [`Surface`] is one of these shapes plus the side its body's [`Material`] is on; a
//! [`PlacedSurface`] adds a pose (local → world). The local geometry around a contact point
//! is sampled by casting rays $\mathbf s(t) = \mathbf q + t\,\mathbf n$ (Wirsching et al. (2020)
//! eq. 2).
//!
//! ## Conventions
//! - **Outward normal**: the unit normal pointing *away from the material*. It is the
//!   gradient of [`Surface::signed_distance`] and of [`Surface::implicit`] (up to length).
//! - **Signed distance** and **implicit function**: negative inside the material.
//! - **Curvature**: $k > 0$ where the surface is convex seen from outside (it bends away
//!   from the outward normal, like a ball), $k < 0$ where it is concave (a groove, a cup).
//!   This matches the crate's radius convention ($R = 1/k$, convex positive).
//! - A ray **hit** is a transversal crossing (a sign change of the signed distance).
//!   Tangent touches and misses are `None`.
//!
//! Units: lengths in \[mm\], angles in \[rad\], curvatures in \[1/mm\]. Derivations,
//! the torus root finder and the accuracy guarantees are in `docs/surfaces.md`.

mod cone;
mod placed;
mod plane;
mod revolution;
mod sphere;
mod torus;
mod trace;

pub use cone::Cone;
pub use placed::PlacedSurface;
pub(crate) use placed::check_pose;
pub use plane::Plane;
pub use revolution::{Profile, Revolution};
pub use sphere::Sphere;
pub use torus::Torus;

use crate::error::{Error, Result};
use nalgebra::{Matrix3, Point3, Unit, Vector3};

/// Which side of the surface the body's material is on.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[cfg_attr(
    feature = "serde",
    derive(serde::Serialize, serde::Deserialize, schemars::JsonSchema)
)]
#[cfg_attr(feature = "serde", serde(rename_all = "snake_case"))]
pub enum Material {
    /// The solid is the region enclosed by the surface: a ball for a sphere, the tube of a
    /// torus, the inside of a cone's nappe, `z < 0` for the plane, the roller inside a
    /// surface of revolution.
    Inside,
    /// The complement: a spherical cup, a toroidal groove, the material around a conical
    /// hole, `z > 0` for the plane, a bore.
    Outside,
}

impl Material {
    /// `+1` for [`Material::Inside`], `-1` for [`Material::Outside`]: the factor that turns
    /// the enclosed-solid quantities (signed distance, normal, curvature) into this side's.
    pub fn sign(self) -> f64 {
        match self {
            Material::Inside => 1.0,
            Material::Outside => -1.0,
        }
    }
}

/// A ray $\mathbf s(t) = \mathbf q + t\,\mathbf n$ (Wirsching et al. (2020) eq. 2) with a unit
/// direction.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Ray {
    /// Origin `q` \[mm\].
    pub origin: Point3<f64>,
    /// Unit direction `n`; the ray parameter `t` is therefore a length \[mm\].
    pub dir: Unit<Vector3<f64>>,
}

impl Ray {
    /// A ray from `origin` along `dir` (normalised here).
    ///
    /// # Errors
    /// [`Error::InvalidInput`] for a non-finite origin (`origin`) or a zero or non-finite
    /// direction (`dir`).
    pub fn new(origin: Point3<f64>, dir: Vector3<f64>) -> Result<Ray> {
        if !origin.coords.iter().all(|c| c.is_finite()) {
            return Err(Error::invalid(
                "origin",
                format!("{:?}", origin.coords.as_slice()),
                "finite coordinates in mm",
            ));
        }
        let norm = dir.norm();
        if !(norm.is_finite() && norm > 0.0) {
            return Err(Error::invalid(
                "dir",
                format!("{:?}", dir.as_slice()),
                "a finite, non-zero direction vector",
            ));
        }
        Ok(Ray {
            origin,
            dir: Unit::new_unchecked(dir / norm),
        })
    }

    /// The point at parameter `t` \[mm\].
    pub fn at(&self, t: f64) -> Point3<f64> {
        self.origin + self.dir.into_inner() * t
    }
}

/// The intersection of a ray with a surface.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Hit {
    /// Ray parameter of the hit \[mm\].
    pub t: f64,
    /// The hit point \[mm\], on the surface to rounding.
    pub point: Point3<f64>,
    /// Outward unit normal at the hit point (away from the material).
    pub normal: Unit<Vector3<f64>>,
}

/// Principal curvatures at a surface point.
///
/// Sign: $k > 0$ where the surface is convex seen from outside (it bends away from the
/// outward normal, like a ball), $k < 0$ where concave. `k1 <= k2`; `d1`, `d2` are the
/// corresponding unit tangent principal directions (`d1 × d2` is the outward normal).
/// An infinite value marks a singular point (the cone's apex, a spindle torus' cusp).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Curvature {
    /// Smaller principal curvature \[1/mm\].
    pub k1: f64,
    /// Larger principal curvature \[1/mm\].
    pub k2: f64,
    /// Principal direction of `k1`.
    pub d1: Unit<Vector3<f64>>,
    /// Principal direction of `k2`.
    pub d2: Unit<Vector3<f64>>,
}

impl Curvature {
    /// The principal radii `[1/k1, 1/k2]` \[mm\] in the crate's convention (convex
    /// positive, `inf` for a flat direction).
    pub fn radii(&self) -> [f64; 2] {
        [1.0 / self.k1, 1.0 / self.k2]
    }
}

/// An analytic surface in its canonical local frame, with the side of its material.
///
/// Built by the validating constructors ([`Surface::sphere`], ...). Serialised as a tagged
/// table, e.g. `{ type = "torus", major = 2.0, minor = 14.0, material = "inside" }`;
/// deserialisation validates like the constructors.
///
/// # Example
/// The roller end face of Wirsching et al. (2020) Table 1 with eccentricity e = 2 mm and face
/// radius r_R = 14 mm is a spindle torus; a ray down at x = 10 mm meets it where
/// (10 - 2)² + z² = 14²:
/// ```
/// use kontakt::geometry::{Material, Ray, Surface};
/// use nalgebra::{Point3, Vector3};
/// let face = Surface::torus(2.0, 14.0, Material::Inside)?;
/// let ray = Ray::new(Point3::new(10.0, 0.0, 30.0), -Vector3::z())?;
/// let hit = face.intersect(&ray, 0.0, 100.0).expect("a hit");
/// assert!((hit.point.z - 132f64.sqrt()).abs() < 1e-13);
/// assert!((hit.normal.z - 132f64.sqrt() / 14.0).abs() < 1e-15);
/// // The fast path from a neighbouring root returns the same t.
/// let t = face.intersect_near(&ray, hit.t + 0.01, 0.0, 100.0).expect("a hit");
/// assert!((t - hit.t).abs() < 1e-13);
/// # Ok::<(), kontakt::Error>(())
/// ```
#[derive(Debug, Clone, PartialEq)]
pub enum Surface {
    /// The plane `z = 0`.
    Plane(Plane),
    /// A sphere centred at the origin.
    Sphere(Sphere),
    /// A cone with apex at the origin, axis `+z`.
    Cone(Cone),
    /// A torus centred at the origin, axis `z`.
    Torus(Torus),
    /// A surface of revolution about `z`.
    Revolution(Revolution),
}

/// The per-shape geometry in the local frame, for the *enclosed solid* (Material::Inside);
/// [`Surface`] multiplies by the material sign.
pub(crate) trait Shape {
    /// The (sign-normalised) implicit function of Wirsching et al. (2020) eq. (1), negative inside.
    fn implicit(&self, p: &Point3<f64>) -> f64;
    /// Signed distance, negative inside.
    fn signed_distance(&self, p: &Point3<f64>) -> f64;
    /// Outward unit normal at or near `p`.
    fn normal(&self, p: &Point3<f64>) -> Vector3<f64>;
    /// Closest surface point and the outward unit normal there.
    fn foot(&self, p: &Point3<f64>) -> (Point3<f64>, Vector3<f64>);
    /// `foot` and `signed_distance` at once (the contact search needs both at every step).
    fn foot_distance(&self, p: &Point3<f64>) -> (Point3<f64>, Vector3<f64>, f64) {
        let (q, n) = self.foot(p);
        (q, n, self.signed_distance(p))
    }
    /// Principal curvatures (convex positive) and directions, unsorted.
    fn curvature(&self, p: &Point3<f64>) -> [(f64, Vector3<f64>); 2];
    /// [`Shape::curvature`] and [`Shape::normal`] at once (a shape that finds the foot
    /// for both overrides it to find it once).
    fn curvature_normal(&self, p: &Point3<f64>) -> ([(f64, Vector3<f64>); 2], Vector3<f64>) {
        (self.curvature(p), self.normal(p))
    }
    /// [`Shape::curvature`] at the surface point `q` whose outward normal `n` is known
    /// (a contact search's foot): a shape whose curvature needs only the point and normal
    /// overrides it to skip the foot search.
    fn curvature_on(&self, q: &Point3<f64>, _n: &Vector3<f64>) -> [(f64, Vector3<f64>); 2] {
        self.curvature(q)
    }
    /// Hessian of the signed distance at `p` (on the surface: the shape operator).
    fn sdf_hessian(&self, p: &Point3<f64>) -> Matrix3<f64>;
    /// The Hessian's quadratic form on two directions: `[e1ᵀHe1, e1ᵀHe2, e2ᵀHe2]` (a
    /// shape with a closed-form Hessian overrides it to skip the 3 × 3 matrix).
    fn sdf_hessian_form(&self, p: &Point3<f64>, e1: &Vector3<f64>, e2: &Vector3<f64>) -> [f64; 3] {
        let h = self.sdf_hessian(p);
        [e1.dot(&(h * e1)), e1.dot(&(h * e2)), e2.dot(&(h * e2))]
    }
    /// First crossing in `[t_min, t_max]`: `(t, point)`.
    fn intersect(
        &self,
        o: &Point3<f64>,
        d: &Vector3<f64>,
        t_min: f64,
        t_max: f64,
    ) -> Option<(f64, Point3<f64>)>;
    /// The same root as `intersect`, from a guess.
    fn intersect_near(
        &self,
        o: &Point3<f64>,
        d: &Vector3<f64>,
        t_guess: f64,
        t_min: f64,
        t_max: f64,
    ) -> Option<f64> {
        let _ = t_guess;
        self.intersect(o, d, t_min, t_max).map(|(t, _)| t)
    }
    /// Characteristic size \[mm\] (0 for unbounded shapes without a length scale).
    fn extent(&self) -> f64;
}

macro_rules! dispatch {
    ($self:expr, $s:ident => $e:expr) => {
        match $self {
            Surface::Plane($s) => $e,
            Surface::Sphere($s) => $e,
            Surface::Cone($s) => $e,
            Surface::Torus($s) => $e,
            Surface::Revolution($s) => $e,
        }
    };
}

impl Surface {
    /// The plane `z = 0` of the local frame. With [`Material::Inside`] the material is
    /// `z < 0` (outward normal `+z`); with [`Material::Outside`] it is `z > 0`.
    pub fn plane(material: Material) -> Surface {
        Surface::Plane(Plane::new(material))
    }

    /// A sphere of radius `radius` \[mm\] centred at the local origin.
    ///
    /// # Errors
    /// [`Error::InvalidInput`] (field `radius`) unless `radius` is finite and > 0.
    pub fn sphere(radius: f64, material: Material) -> Result<Surface> {
        Sphere::new(radius, material).map(Surface::Sphere)
    }

    /// A cone with apex at the local origin, axis `+z`, nappe `z > 0`:
    /// $x^2+y^2 = m z^2$, $m = \tan^2\alpha$ (Wirsching et al. (2020) eq. 1), `half_angle` = α
    /// \[rad\].
    ///
    /// # Errors
    /// [`Error::InvalidInput`] (field `half_angle`) unless 0 < α < π/2.
    pub fn cone(half_angle: f64, material: Material) -> Result<Surface> {
        Cone::new(half_angle, material).map(Surface::Cone)
    }

    /// A torus centred at the local origin with axis `z`:
    /// $(x^2+y^2+z^2+R^2-r^2)^2 = 4R^2(x^2+y^2)$ (Wirsching et al. (2020) eq. 1), `major` = R
    /// \[mm\] (radius of the centre circle), `minor` = r \[mm\] (tube radius).
    ///
    /// A spindle torus (R < r) is valid with [`Material::Inside`]: the solid is the union
    /// of the balls of radius r centred on the circle (a roller end face with eccentricity
    /// e = R smaller than the face radius); its surface is the outer ("apple") sheet.
    ///
    /// # Errors
    /// [`Error::InvalidInput`] for `major` not finite or < 0, `minor` not finite or <= 0,
    /// and (field `minor`) for R < r with [`Material::Outside`].
    pub fn torus(major: f64, minor: f64, material: Material) -> Result<Surface> {
        Torus::new(major, minor, material).map(Surface::Torus)
    }

    /// A surface of revolution about local `z` with meridian $\rho = $ `profile`(z).
    ///
    /// # Errors
    /// The profile's validation errors (fields `profile.radius`, `profile.z`, ...).
    pub fn revolution(profile: Profile, material: Material) -> Result<Surface> {
        Revolution::new(profile, material).map(Surface::Revolution)
    }

    /// The side of the surface the material is on.
    pub fn material(&self) -> Material {
        dispatch!(self, s => s.material())
    }

    fn sign(&self) -> f64 {
        self.material().sign()
    }

    /// Characteristic size \[mm\]: radius of a sphere, R + r of a torus, the largest radius
    /// or half-length of a surface of revolution; 0 for the plane and the cone.
    pub fn extent(&self) -> f64 {
        dispatch!(self, s => s.extent())
    }

    /// Signed distance \[mm\] from `p` (local frame) to the surface, negative inside the
    /// material.
    ///
    /// Exact for the plane, sphere, cone (including the region whose nearest point is the
    /// apex) and torus (the distance to the tube, $\sqrt{(\rho-R)^2+z^2}-r$). For a surface
    /// of revolution it is the distance to the meridian patch, computed by a safeguarded
    /// Newton iteration in the meridian plane, signed by the implicit function.
    pub fn signed_distance(&self, p: &Point3<f64>) -> f64 {
        self.sign() * dispatch!(self, s => s.signed_distance(p))
    }

    /// The implicit function of Wirsching et al. (2020) eq. (1) \[mm²\] (\[mm\] for the plane and a
    /// surface of revolution), sign-normalised so that it is negative inside the material.
    ///
    /// - plane: $z$; sphere: $x^2+y^2+z^2-r^2$;
    /// - cone: $x^2+y^2-m\,z|z|$: the paper's $x^2+y^2-mz^2$ on the nappe's side `z >= 0`,
    ///   positive below the apex so that the mirrored nappe `z < 0` is not a zero;
    /// - torus: the quartic in its factored form
    ///   $((\rho-R)^2+z^2-r^2)\,|(\rho+R)^2+z^2-r^2|$, equal to
    ///   $(x^2+y^2+z^2+R^2-r^2)^2-4R^2\rho^2$ wherever the second factor is positive (always for
    ///   R >= r); the absolute value keeps a spindle torus' inner lemon inside the solid;
    /// - revolution: $\rho - \rho(z)$ with `z` clamped to the profile's range.
    ///
    /// For Material::Outside every value is negated.
    pub fn implicit(&self, p: &Point3<f64>) -> f64 {
        self.sign() * dispatch!(self, s => s.implicit(p))
    }

    /// Outward unit normal (away from the material) at or near `p`: the gradient of the
    /// signed distance (for a surface of revolution, of the implicit function).
    pub fn normal(&self, p: &Point3<f64>) -> Unit<Vector3<f64>> {
        Unit::new_unchecked(self.sign() * dispatch!(self, s => s.normal(p)))
    }

    /// Principal curvatures at the surface point nearest to `p` (sign convention of
    /// [`Curvature`]). Plane: 0, 0. Sphere of radius r: 1/r, 1/r for Material::Inside,
    /// −1/r, −1/r for Outside. Torus (Inside): 1/r along the tube's meridian and
    /// cos θ/(R + r cos θ) around the axis (θ = 0 on the outer equator). Cone (Inside): 0
    /// along the generatrix and cos α/ρ around the axis. Surface of revolution (Inside):
    /// $-\rho''/(1+\rho'^2)^{3/2}$ along the meridian, $1/(\rho\sqrt{1+\rho'^2})$ around.
    pub fn curvature(&self, p: &Point3<f64>) -> Curvature {
        let sign = self.sign();
        let (raw, normal) = dispatch!(self, s => s.curvature_normal(p));
        Self::principal(raw, sign, &(sign * normal))
    }

    /// [`Surface::curvature`] at the point `q` on the surface whose outward normal is `n`
    /// (local frame; the foot and normal of a contact search), without searching the foot
    /// again where the shape allows (the torus).
    pub(crate) fn curvature_on(&self, q: &Point3<f64>, n: &Unit<Vector3<f64>>) -> Curvature {
        let sign = self.sign();
        let raw = dispatch!(self, s => s.curvature_on(q, &(sign * n.into_inner())));
        Self::principal(raw, sign, n)
    }

    /// Sorted, signed and right-handed about the outward normal `normal`.
    fn principal(
        [(ka, da), (kb, db)]: [(f64, Vector3<f64>); 2],
        sign: f64,
        normal: &Vector3<f64>,
    ) -> Curvature {
        let (ka, kb) = (sign * ka, sign * kb);
        let ((k1, d1), (k2, d2)) = if ka <= kb || kb.is_nan() {
            ((ka, da), (kb, db))
        } else {
            ((kb, db), (ka, da))
        };
        // Right-handed: d1 × d2 = outward normal.
        let d2 = if d1.cross(&d2).dot(normal) < 0.0 {
            -d2
        } else {
            d2
        };
        Curvature {
            k1,
            k2,
            d1: Unit::new_normalize(d1),
            d2: Unit::new_normalize(d2),
        }
    }

    /// The nearest crossing of `ray` (local frame) with the surface for `t` in
    /// `[t_min, t_max]`, or `None` (miss, tangent touch, empty interval, NaN input).
    ///
    /// Plane: linear. Sphere and cone: the quadratic in a numerically stable form, with the
    /// ray origin first moved to its closest approach to the centre or apex. For the sphere
    /// the quadratic is then $s^2 = r^2 - |\mathbf o_c|^2$ (no cancellation); for the cone
    /// it is solved with $q = -(b + \mathrm{sign}(b)\sqrt{\Delta})/2$, roots $q/a$ and $c/q$,
    /// and polished by one Newton step on the exact signed distance; only the cone's
    /// `z >= 0` nappe counts. Torus and surface of revolution: a certified first-root
    /// search along the ray (sphere tracing with quadratic bounds, then safeguarded Newton;
    /// no quartic in monomial form, see `docs/surfaces.md`). The hit point is on the surface
    /// to a few ulps of the surface's size, also for origins far away.
    pub fn intersect(&self, ray: &Ray, t_min: f64, t_max: f64) -> Option<Hit> {
        if !(t_min <= t_max) {
            return None;
        }
        let (t, point) = dispatch!(self, s => s.intersect(&ray.origin, &ray.dir, t_min, t_max))?;
        Some(Hit {
            t,
            point,
            normal: self.normal(&point),
        })
    }

    /// The same root as [`Surface::intersect`] (the nearest crossing in `[t_min, t_max]`),
    /// found from a guess `t_guess` \[mm\] — the fast path for dense sampling, where the
    /// previous grid cell's `t` is an excellent guess. Returns only `t`.
    ///
    /// **Contract.** The result is always the root `intersect` returns (to rounding), or
    /// `None` exactly when `intersect` returns `None`. For the torus and the surface of
    /// revolution a few Newton steps on the signed distance start from the guess; the root
    /// is accepted only with a *certificate* that no earlier root lies in `[t_min, t)`
    /// (the quadratic bound on the implicit function's second derivative around the root,
    /// completed if needed by the Lipschitz bound `|sdf(t_min)|`). When Newton fails,
    /// leaves `[t_min, t_max]`, the ray grazes (|cos| < 1e-4) or the certificate does not
    /// hold, it falls back to `intersect`. Plane, sphere and cone use their closed form,
    /// which is as fast. No allocation.
    pub fn intersect_near(&self, ray: &Ray, t_guess: f64, t_min: f64, t_max: f64) -> Option<f64> {
        if !(t_min <= t_max) {
            return None;
        }
        dispatch!(self, s => s.intersect_near(&ray.origin, &ray.dir, t_guess, t_min, t_max))
    }

    /// The surface point nearest to `p` (foot point) and the outward normal there.
    /// Where the foot is not unique (the centre of a sphere, the axis of a torus or a
    /// cone's inside) one of the nearest points is returned.
    pub fn closest_point(&self, p: &Point3<f64>) -> (Point3<f64>, Unit<Vector3<f64>>) {
        let (q, n) = dispatch!(self, s => s.foot(p));
        (q, Unit::new_unchecked(self.sign() * n))
    }

    /// [`Surface::closest_point`] and [`Surface::signed_distance`] of `p` at once \[mm\]
    /// (local frame): the foot, the outward normal there, the signed distance.
    pub fn closest_point_distance(
        &self,
        p: &Point3<f64>,
    ) -> (Point3<f64>, Unit<Vector3<f64>>, f64) {
        let sign = self.sign();
        let (q, n, d) = dispatch!(self, s => s.foot_distance(p));
        (q, Unit::new_unchecked(sign * n), sign * d)
    }

    /// The quadratic form of the signed distance's Hessian \[1/mm\] at `p` (local frame) on
    /// the directions `e1`, `e2`: `[e1ᵀHe1, e1ᵀHe2, e2ᵀHe2]`. On the surface the Hessian
    /// is the shape operator $\sum_i k_i\,\mathbf d_i \mathbf d_i^\mathsf T$; off the
    /// surface the curvature of the parallel surface through `p`.
    pub(crate) fn sdf_hessian_form(
        &self,
        p: &Point3<f64>,
        e1: &Vector3<f64>,
        e2: &Vector3<f64>,
    ) -> [f64; 3] {
        let sign = self.sign();
        dispatch!(self, s => s.sdf_hessian_form(p, e1, e2)).map(|h| sign * h)
    }
}

// ---------------------------------------------------------------------------------------
// Serialisation: a tagged table, validated on the way in.

#[cfg(feature = "serde")]
#[derive(serde::Serialize, serde::Deserialize, schemars::JsonSchema)]
#[serde(tag = "type", rename_all = "snake_case", deny_unknown_fields)]
enum SurfaceSpec {
    Plane {
        material: Material,
    },
    Sphere {
        radius: f64,
        material: Material,
    },
    Cone {
        half_angle: f64,
        material: Material,
    },
    Torus {
        major: f64,
        minor: f64,
        material: Material,
    },
    Revolution {
        profile: Profile,
        material: Material,
    },
}

/// The schema of a surface is that of its tagged table.
#[cfg(feature = "serde")]
impl schemars::JsonSchema for Surface {
    fn schema_name() -> std::borrow::Cow<'static, str> {
        "Surface".into()
    }

    fn json_schema(generator: &mut schemars::SchemaGenerator) -> schemars::Schema {
        <SurfaceSpec as schemars::JsonSchema>::json_schema(generator)
    }
}

#[cfg(feature = "serde")]
impl serde::Serialize for Surface {
    fn serialize<S: serde::Serializer>(
        &self,
        serializer: S,
    ) -> std::result::Result<S::Ok, S::Error> {
        let spec = match self {
            Surface::Plane(s) => SurfaceSpec::Plane {
                material: s.material(),
            },
            Surface::Sphere(s) => SurfaceSpec::Sphere {
                radius: s.radius(),
                material: s.material(),
            },
            Surface::Cone(s) => SurfaceSpec::Cone {
                half_angle: s.half_angle(),
                material: s.material(),
            },
            Surface::Torus(s) => SurfaceSpec::Torus {
                major: s.major(),
                minor: s.minor(),
                material: s.material(),
            },
            Surface::Revolution(s) => SurfaceSpec::Revolution {
                profile: s.profile().clone(),
                material: s.material(),
            },
        };
        serde::Serialize::serialize(&spec, serializer)
    }
}

#[cfg(feature = "serde")]
impl<'de> serde::Deserialize<'de> for Surface {
    fn deserialize<D: serde::Deserializer<'de>>(
        deserializer: D,
    ) -> std::result::Result<Self, D::Error> {
        let surface = match <SurfaceSpec as serde::Deserialize>::deserialize(deserializer)? {
            SurfaceSpec::Plane { material } => Ok(Surface::plane(material)),
            SurfaceSpec::Sphere { radius, material } => Surface::sphere(radius, material),
            SurfaceSpec::Cone {
                half_angle,
                material,
            } => Surface::cone(half_angle, material),
            SurfaceSpec::Torus {
                major,
                minor,
                material,
            } => Surface::torus(major, minor, material),
            SurfaceSpec::Revolution { profile, material } => Surface::revolution(profile, material),
        };
        surface.map_err(serde::de::Error::custom)
    }
}

// ---------------------------------------------------------------------------------------
// Small helpers shared by the shapes.

/// A unit vector perpendicular to the unit vector `n` (Duff et al. 2017, "Building an
/// orthonormal basis, revisited", JCGT 6(1)): branch-free apart from the sign, no
/// normalisation needed.
pub(crate) fn tangent_basis(n: &Vector3<f64>) -> (Vector3<f64>, Vector3<f64>) {
    let sign = 1f64.copysign(n.z);
    let a = -1.0 / (sign + n.z);
    let b = n.x * n.y * a;
    let e1 = Vector3::new(1.0 + sign * n.x * n.x * a, sign * b, -sign * n.x);
    let e2 = Vector3::new(b, sign + n.y * n.y * a, -n.y);
    (e1, e2)
}

/// `√(x² + y²)` \[same unit as x, y\]: the square root of the sum of squares (one rounding
/// more than `f64::hypot`, a few times cheaper: the contact search calls it a dozen times per
/// Newton step) wherever the squares neither overflow nor underflow (the sum between 1e-290
/// and 1e290), `f64::hypot` elsewhere.
#[inline]
pub(crate) fn hypot(x: f64, y: f64) -> f64 {
    let s = x * x + y * y;
    if s > 1e-290 && s < 1e290 {
        s.sqrt()
    } else {
        x.hypot(y)
    }
}

/// Unit radial direction of `p` about the z axis and its distance `rho` from the axis; on
/// the axis the radial direction is `+x`.
pub(crate) fn radial(p: &Point3<f64>) -> (Vector3<f64>, f64) {
    let rho = p.x.hypot(p.y);
    if rho > 0.0 {
        (Vector3::new(p.x / rho, p.y / rho, 0.0), rho)
    } else {
        (Vector3::x(), 0.0)
    }
}

/// [`radial`] with the cheaper [`hypot`] (one rounding more in `rho`): the torus' foot,
/// curvature and distance Hessian. Its ray casts take `rho` as the same square root of the
/// sum of squares, so that at approaches near the rounding of the coordinates (1e-14 mm at
/// 40 mm) the contact search and the ray casts round alike (the PimP tracker's round-off
/// touch test). The cone and the surface of revolution keep [`radial`].
pub(crate) fn radial_fast(p: &Point3<f64>) -> (Vector3<f64>, f64) {
    let rho = hypot(p.x, p.y);
    if rho > 0.0 {
        (Vector3::new(p.x / rho, p.y / rho, 0.0), rho)
    } else {
        (Vector3::x(), 0.0)
    }
}

/// The roots of `a t² + b t + c = 0` in the numerically stable form
/// $q = -(b + \mathrm{sign}(b)\sqrt{b^2-4ac})/2$, roots $q/a$ and $c/q$, ascending; NaN
/// for a missing root. `None` when the discriminant is not positive (no crossing).
pub(crate) fn quadratic_roots(a: f64, b: f64, c: f64) -> Option<(f64, f64)> {
    let disc = b * b - 4.0 * a * c;
    if !(disc > 0.0) {
        return None;
    }
    let q = -0.5 * (b + 1f64.copysign(b) * disc.sqrt());
    let (r1, r2) = (q / a, c / q);
    let (r1, r2) = (
        if r1.is_finite() { r1 } else { f64::NAN },
        if r2.is_finite() { r2 } else { f64::NAN },
    );
    Some(if r1 <= r2 || r2.is_nan() {
        (r1, r2)
    } else {
        (r2, r1)
    })
}

/// `v vᵀ`.
pub(crate) fn outer(v: &Vector3<f64>) -> Matrix3<f64> {
    v * v.transpose()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn tangent_basis_is_orthonormal() {
        for n in [
            Vector3::new(0.0, 0.0, 1.0),
            Vector3::new(0.0, 0.0, -1.0),
            Vector3::new(1.0, 2.0, -3.0).normalize(),
            Vector3::new(-0.3, 0.1, 0.2).normalize(),
        ] {
            let (e1, e2) = tangent_basis(&n);
            assert!((e1.norm() - 1.0).abs() < 1e-15);
            assert!((e2.norm() - 1.0).abs() < 1e-15);
            assert!(e1.dot(&n).abs() < 1e-15 && e2.dot(&n).abs() < 1e-15);
            assert!((e1.cross(&e2) - n).norm() < 1e-15);
        }
    }

    #[test]
    fn stable_quadratic() {
        // (t - 1)(t - 1e8) = t² - (1e8 + 1) t + 1e8: the small root exact.
        let (r1, r2) = quadratic_roots(1.0, -(1e8 + 1.0), 1e8).unwrap();
        assert_eq!(r1, 1.0);
        assert_eq!(r2, 1e8);
        // Linear limit a = 0.
        let (r1, r2) = quadratic_roots(0.0, 2.0, -4.0).unwrap();
        assert!(r1.is_nan() || r2.is_nan());
        assert!(r1 == 2.0 || r2 == 2.0);
        assert!(quadratic_roots(1.0, 0.0, 1.0).is_none());
    }

    #[cfg(feature = "serde")]
    #[test]
    fn serde_round_trip_validates() {
        let s = Surface::torus(2.0, 14.0, Material::Inside).unwrap();
        let json = serde_json::to_string(&s).unwrap();
        assert_eq!(
            json,
            r#"{"type":"torus","major":2.0,"minor":14.0,"material":"inside"}"#
        );
        let back: Surface = serde_json::from_str(&json).unwrap();
        assert_eq!(back, s);
        let bad = r#"{"type":"torus","major":2.0,"minor":14.0,"material":"outside"}"#;
        let err = serde_json::from_str::<Surface>(bad)
            .unwrap_err()
            .to_string();
        assert!(err.contains("minor"), "{err}");
    }
}
