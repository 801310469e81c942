//! The torus $(x^2+y^2+z^2+R^2-r^2)^2 = 4R^2(x^2+y^2)$ (Wirsching et al. (2020) eq. 1): toroidal
//! roller end faces (R = eccentricity e, r = face radius r_R) and toroidal ribs.
//!
//! The quartic factors as
//! $$ (|\mathbf p|^2+R^2-r^2)^2-4R^2\rho^2 =
//! \big((\rho-R)^2+z^2-r^2\big)\big((\rho+R)^2+z^2-r^2\big), \quad \rho = \sqrt{x^2+y^2}, $$ and
//! the surface is the zero set of the tube distance $d = \sqrt{(\rho-R)^2+z^2} - r$, the exact
//! signed distance of the solid tube (1-Lipschitz). Ray casting never forms the quartic in monomial
//! form (catastrophic cancellation for R ≫ r or far origins); it runs the certified first-root
//! search of [`super::trace`] on `d` and on the first factor $G = (\rho-R)^2+z^2-r^2$, whose second
//! derivative along a unit ray is bounded in closed form: $G'' = 2 - 2R\,h^2/\rho^3 \in [2 - 2R
//! h^2/\rho_{min}^3,\ 2]$ with $h$ the constant $|(\mathbf p \times \mathbf n)_z|$ of the ray.
//!
//! For a spindle torus (R < r) the zero set of `d` is exactly the outer (apple) sheet,
//! the boundary of the union of the balls of radius r centred on the circle.

use super::trace::{self, RayFunction, Sample};
use super::{Material, Shape, hypot, outer, radial_fast};
use crate::error::{Error, Result};
use nalgebra::{Matrix3, Point3, Vector3};

/// A torus centred at the local origin with axis `z`: major radius R (centre circle),
/// minor radius r (tube).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Torus {
    major: f64,
    minor: f64,
    material: Material,
}

impl Torus {
    /// A torus with major radius `major` = R >= 0 \[mm\] and minor radius `minor` = r > 0
    /// \[mm\]. R < r (spindle torus) is valid only with [`Material::Inside`].
    ///
    /// # Errors
    /// [`Error::InvalidInput`] for a non-finite or negative `major`, a non-finite or
    /// non-positive `minor`, or `minor > major` with [`Material::Outside`].
    pub fn new(major: f64, minor: f64, material: Material) -> Result<Self> {
        if !(major.is_finite() && major >= 0.0) {
            return Err(Error::invalid(
                "major",
                major,
                "a finite major radius >= 0 mm (radius of the tube's centre circle)",
            ));
        }
        if !(minor.is_finite() && minor > 0.0) {
            return Err(Error::invalid(
                "minor",
                minor,
                "a finite minor (tube) radius > 0 mm",
            ));
        }
        if material == Material::Outside && minor > major {
            return Err(Error::invalid(
                "minor",
                minor,
                format!(
                    "a minor radius <= major = {major} mm for Material::Outside: the complement \
                     of a spindle torus is not a groove; use Material::Inside or a larger major"
                ),
            ));
        }
        Ok(Torus {
            major,
            minor,
            material,
        })
    }

    /// Major radius R \[mm\].
    pub fn major(&self) -> f64 {
        self.major
    }

    /// Minor (tube) radius r \[mm\].
    pub fn minor(&self) -> f64 {
        self.minor
    }

    /// The side of the material.
    pub fn material(&self) -> Material {
        self.material
    }

    /// For a spindle torus, the cusp (on the axis) nearest to `p` when the tube's foot
    /// point of `p` would lie across the axis, i.e. when the outer sheet's nearest point is
    /// the cusp.
    fn cusp(&self, rho: f64, z: f64) -> Option<Point3<f64>> {
        let (big_r, r) = (self.major, self.minor);
        if big_r >= r {
            return None;
        }
        let a = rho - big_r;
        let dd = hypot(a, z);
        // Foot at rho_f = R + r (rho - R)/D < 0.
        (big_r * dd + r * a < 0.0).then(|| {
            let zc = ((r - big_r) * (r + big_r)).sqrt();
            Point3::new(0.0, 0.0, if z >= 0.0 { zc } else { -zc })
        })
    }

    /// Unit normal of the tube at the direction of (rho - R, z) from the centre circle.
    fn tube_normal(er: &Vector3<f64>, a: f64, z: f64, dd: f64) -> Vector3<f64> {
        if dd > 0.0 {
            er * (a / dd) + Vector3::z() * (z / dd)
        } else {
            *er
        }
    }

    fn ray(&self, o: Point3<f64>, d: Vector3<f64>) -> TorusRay {
        let h = o.x * d.y - o.y * d.x;
        TorusRay {
            o,
            d,
            big_r: self.major,
            r: self.minor,
            tol: 8.0 * f64::EPSILON * (self.major + self.minor),
            v2: d.x * d.x + d.y * d.y,
            h2: h * h,
        }
    }

    /// `[lo, hi]` of ray parameters `t` in `[t_min, t_max]` inside the bounding sphere and
    /// slab of the torus, with the parameter of the closest approach to the centre.
    fn clip(&self, o: &Point3<f64>, d: &Vector3<f64>, t_min: f64, t_max: f64) -> Option<Clip> {
        let margin = 1.0 + 1e-9;
        let rb = (self.major + self.minor) * margin;
        let tc = -o.coords.dot(d);
        let oc = o + d * tc;
        let b2 = oc.coords.norm_squared();
        if !(b2 < rb * rb) {
            return None;
        }
        let half = ((rb - b2.sqrt()) * (rb + b2.sqrt())).sqrt();
        let (mut lo, mut hi) = ((tc - half).max(t_min), (tc + half).min(t_max));
        let zr = self.minor * margin;
        if d.z != 0.0 {
            let (s1, s2) = ((-zr - oc.z) / d.z, (zr - oc.z) / d.z);
            lo = lo.max(tc + s1.min(s2));
            hi = hi.min(tc + s1.max(s2));
        } else if oc.z.abs() > zr {
            return None;
        }
        (lo <= hi).then_some(Clip { tc, oc, lo, hi })
    }
}

struct Clip {
    tc: f64,
    oc: Point3<f64>,
    lo: f64,
    hi: f64,
}

/// A root found by [`TorusRay::newton`]: `s` and a lower bound on |G'| there with the sign
/// of G', as the fraction `slope_num / slope_den` (divided only if the certificate needs it).
struct NewtonRoot {
    s: f64,
    slope_num: f64,
    slope_den: f64,
}

impl NewtonRoot {
    fn slope(&self) -> f64 {
        self.slope_num / self.slope_den
    }
}

/// The torus along a ray `o + s d` (|d| = 1): `f` = tube distance, `g` = first factor of
/// the quartic.
struct TorusRay {
    o: Point3<f64>,
    d: Vector3<f64>,
    big_r: f64,
    r: f64,
    tol: f64,
    /// dx² + dy².
    v2: f64,
    /// h² = (ox dy - oy dx)², constant along the ray.
    h2: f64,
}

impl TorusRay {
    /// The hot path of `intersect_near`: a third-order Newton (Chebyshev) iteration on G
    /// from `s = 0` (in `[lo, hi]`), accepted as soon as a rigorous Taylor bound on |G| at
    /// the next iterate is below the tolerance, so that a guess within about 1e-4 of the
    /// size needs one evaluation of G (one square root, one division).
    ///
    /// With $\delta = -G/G'$ the step is $\Delta = \delta - \frac{G''}{2G'}\delta^2$ and
    /// $|G(s+\Delta)| \le u_2(|\delta\epsilon| + \epsilon^2/2) + u_3|\Delta|^3/6$,
    /// $\epsilon = \Delta - \delta$, where on $[s, s+\Delta]$
    /// $|G''| \le u_2 = \max(2, 2Rh^2/\rho_m^3 - 2)$ and
    /// $|G'''| = |6Rh^2\rho'/\rho^4| \le u_3 = 6Rh^2/\rho_m^4$, $\rho_m = \rho - |\Delta|$.
    #[inline]
    fn newton(&self, lo: f64, hi: f64) -> Option<NewtonRoot> {
        if !(lo <= 0.0 && hi >= 0.0) {
            return None;
        }
        let (o, d) = (&self.o, &self.d);
        let tol_g = 2.0 * self.r * self.tol;
        let min_half_slope = self.r * 1e-4;
        let rh = self.big_r * self.h2; // R h²
        // The accepted root, with |G'| there >= |G'(s)| - u2 |step|
        // = (2|q| rm³ - u2m rho |step|)/(rho rm³).
        let root = |s_root: f64, step: f64, rm3: f64, u2m: f64, (q, rho): (f64, f64)| {
            let slope_num = 2.0 * q.abs() * rm3 - u2m * rho * step.abs();
            (slope_num > 0.0 && s_root >= lo && s_root <= hi).then(|| NewtonRoot {
                s: s_root,
                slope_num: slope_num.copysign(q),
                slope_den: rho * rm3,
            })
        };
        let mut s = 0.0;
        for _ in 0..6 {
            let (px, py, pz) = (o.x + s * d.x, o.y + s * d.y, o.z + s * d.z);
            let rho2 = px * px + py * py;
            let rho = rho2.sqrt();
            let a = rho - self.big_r;
            let g = a * a + pz * pz - self.r * self.r;
            // q = G' rho / 2 = a (p_xy . d_xy) + z dz rho.
            let q = a * (px * d.x + py * d.y) + pz * d.z * rho;
            if !(q.abs() >= min_half_slope * rho && rho > 0.0) {
                return None; // grazing (or on the axis): the full search decides
            }
            let inv = 1.0 / (q * rho2);
            let delta = -0.5 * g * rho * rho2 * inv;
            // Accept the Newton step if |G(s + delta)| <= u2 delta²/2 <= tol (times rm³, no
            // division): u2 rm³ = max(2 rm³, 2 R h² - 2 rm³), rm = rho - |delta|.
            let rm = rho - delta.abs();
            let rm3 = rm * rm * rm;
            let u2m = (2.0 * rm3).max(2.0 * rh - 2.0 * rm3);
            if rm > 0.0 && 0.5 * u2m * delta * delta <= tol_g * rm3 {
                return root(s + delta, delta, rm3, u2m, (q, rho));
            }
            // Close to the root: the Chebyshev step, error O(delta³).
            let mut step = delta;
            if delta.abs() <= 1e-2 * self.r {
                // G''/(2G') delta² = (rho³ - R h²)/(2 q rho²) delta².
                let eps = -0.5 * (rho * rho2 - rh) * delta * delta * inv;
                let cheb = delta + eps;
                let rm = rho - cheb.abs();
                if eps.abs() <= 0.5 * delta.abs() && rm > 0.0 {
                    // The bound times rm⁴; u3 rm⁴ / 6 = R h².
                    let rm3 = rm * rm * rm;
                    let u2m = (2.0 * rm3).max(2.0 * rh - 2.0 * rm3);
                    let cubed = cheb.abs() * cheb * cheb;
                    let bound = u2m * rm * ((delta * eps).abs() + 0.5 * eps * eps) + rh * cubed;
                    if bound <= tol_g * rm3 * rm {
                        return root(s + cheb, cheb, rm3, u2m, (q, rho));
                    }
                    step = cheb;
                }
            }
            s += step;
            if !(s >= lo && s <= hi) {
                return None;
            }
        }
        None
    }

    /// Whether G'' >= 0 on `[a, b]`: then G, zero with G' < 0 at `b`, is positive on
    /// `[a, b)` (no earlier root). With $G'' = 2 - 2R h^2/\rho^3$ that is
    /// $\rho_{min}^3 \ge R h^2$, tested in squares without division or root.
    #[inline]
    fn convex_on(&self, a: f64, b: f64) -> bool {
        if self.v2 == 0.0 {
            return true; // rho constant, h = 0: G'' = 2
        }
        let (o, d) = (&self.o, &self.d);
        // The projected line's closest approach to the axis at sc = -(o.v)/v2.
        let ov = -(o.x * d.x + o.y * d.y);
        let rh = self.big_r * self.h2 * (1.0 + 1e-9);
        if ov >= a * self.v2 && ov <= b * self.v2 {
            // rho_min² = h²/v2 there: (h²/v2)³ >= R² h⁴ <=> h² >= R² v2³ (false if h = 0:
            // the ray meets the axis, a kink).
            return self.h2 > 0.0
                && self.h2 * (1.0 - 1e-9) >= self.big_r * self.big_r * self.v2 * self.v2 * self.v2;
        }
        let e = if ov < a * self.v2 { a } else { b };
        let (wx, wy) = (o.x + e * d.x, o.y + e * d.y);
        let rmin2 = wx * wx + wy * wy;
        rmin2 * rmin2 * rmin2 >= rh * rh
    }
}

impl RayFunction for TorusRay {
    #[inline]
    fn sample(&self, s: f64) -> Sample {
        let (o, d) = (&self.o, &self.d);
        let (px, py, pz) = (o.x + s * d.x, o.y + s * d.y, o.z + s * d.z);
        let rho = (px * px + py * py).sqrt();
        let rho1 = if rho > 0.0 {
            (px * d.x + py * d.y) / rho
        } else {
            self.v2.sqrt()
        };
        let a = rho - self.big_r;
        let dd = (a * a + pz * pz).sqrt();
        let f = dd - self.r;
        let num = a * rho1 + pz * d.z; // D D'
        Sample {
            f,
            f1: if dd > 0.0 { num / dd } else { 0.0 },
            g: f * (dd + self.r),
            g1: 2.0 * num,
        }
    }

    fn g2_bounds(&self, a: f64, b: f64) -> (f64, f64) {
        // G'' = 2 - 2R h²/rho³ (exact along a unit ray): its bounds over [a, b] follow from
        // the extreme values of rho, which is convex along the ray: the minimum at the
        // projected line's closest approach to the axis (clamped), the maximum at an end.
        if self.v2 == 0.0 || self.h2 == 0.0 {
            let two = (2.0 * (1.0 - 1e-12), 2.0 * (1.0 + 1e-12));
            if self.v2 == 0.0 {
                return two; // rho constant along the ray
            }
            // The ray meets the axis: rho'' = 0 except at the crossing (a kink).
            let (o, d) = (&self.o, &self.d);
            let sc = -(o.x * d.x + o.y * d.y) / self.v2;
            return if sc >= a && sc <= b {
                (f64::NEG_INFINITY, two.1)
            } else {
                two
            };
        }
        let (o, d) = (&self.o, &self.d);
        let rho2_at = |s: f64| {
            let (wx, wy) = (o.x + s * d.x, o.y + s * d.y);
            wx * wx + wy * wy
        };
        let sc = (-(o.x * d.x + o.y * d.y) / self.v2).clamp(a, b);
        let rmin2 = rho2_at(sc);
        let rmax2 = rho2_at(a).max(rho2_at(b));
        let term = |r2: f64| 2.0 * self.big_r * self.h2 / (r2 * r2.sqrt());
        let (lo, hi) = (2.0 - term(rmin2), 2.0 - term(rmax2));
        (lo - 1e-9 * lo.abs() - 1e-12, hi + 1e-9 * hi.abs() + 1e-12)
    }

    fn free_step(&self, at_a: &Sample, _a: f64, _b: f64) -> f64 {
        at_a.f.abs() // the tube distance is 1-Lipschitz
    }

    fn tol(&self) -> f64 {
        self.tol
    }

    fn skip(&self) -> f64 {
        4.0 * (self.tol * self.r).sqrt()
    }
}

impl Shape for Torus {
    fn implicit(&self, p: &Point3<f64>) -> f64 {
        let (big_r, r) = (self.major, self.minor);
        let rho = p.x.hypot(p.y);
        let d_near = hypot(rho - big_r, p.z);
        let d_far = hypot(rho + big_r, p.z);
        (d_near - r) * (d_near + r) * ((d_far - r) * (d_far + r)).abs()
    }

    fn signed_distance(&self, p: &Point3<f64>) -> f64 {
        let rho = p.x.hypot(p.y);
        match self.cusp(rho, p.z) {
            Some(c) => -(p - c).norm(),
            None => hypot(rho - self.major, p.z) - self.minor,
        }
    }

    fn normal(&self, p: &Point3<f64>) -> Vector3<f64> {
        self.foot(p).1
    }

    fn foot(&self, p: &Point3<f64>) -> (Point3<f64>, Vector3<f64>) {
        let (c, n, _) = self.foot_distance(p);
        (c, n)
    }

    fn foot_distance(&self, p: &Point3<f64>) -> (Point3<f64>, Vector3<f64>, f64) {
        let (er, rho) = radial_fast(p);
        if let Some(c) = self.cusp(rho, p.z) {
            let v = c - p;
            let len = v.norm();
            let n = if len > 0.0 {
                v / len
            } else {
                Vector3::z() * c.z.signum()
            };
            return (c, n, -len);
        }
        let a = rho - self.major;
        let dd = hypot(a, p.z);
        let n = Self::tube_normal(&er, a, p.z, dd);
        (
            Point3::from(er * self.major + n * self.minor),
            n,
            dd - self.minor,
        )
    }

    fn curvature(&self, p: &Point3<f64>) -> [(f64, Vector3<f64>); 2] {
        self.curvature_normal(p).0
    }

    fn curvature_normal(&self, p: &Point3<f64>) -> ([(f64, Vector3<f64>); 2], Vector3<f64>) {
        let (q, n) = self.foot(p);
        (self.curvature_on(&q, &n), n)
    }

    fn curvature_on(&self, q: &Point3<f64>, n: &Vector3<f64>) -> [(f64, Vector3<f64>); 2] {
        let n = *n;
        let (er, rho_f) = radial_fast(q);
        let around = Vector3::new(-er.y, er.x, 0.0);
        let cos_theta = n.dot(&er);
        let meridian = around.cross(&n);
        // Around the axis: cos(theta)/(R + r cos(theta)); along the tube: 1/r.
        let k_around = if rho_f > 0.0 {
            cos_theta / rho_f
        } else if self.major == 0.0 {
            1.0 / self.minor // R = 0 is a sphere of radius r; its poles are regular
        } else {
            f64::NEG_INFINITY // a spindle torus' cusp
        };
        [(1.0 / self.minor, meridian), (k_around, around)]
    }

    fn sdf_hessian(&self, p: &Point3<f64>) -> Matrix3<f64> {
        let tiny = f64::MIN_POSITIVE.sqrt();
        let (er, rho) = radial_fast(p);
        if let Some(c) = self.cusp(rho, p.z) {
            // sdf = -|p - c|.
            let v = p - c;
            let len = v.norm().max(tiny);
            let n = v / len;
            return -(Matrix3::identity() - outer(&n)) / len;
        }
        let a = rho - self.major;
        let dd = hypot(a, p.z).max(tiny);
        let n = Self::tube_normal(&er, a, p.z, dd);
        let around = Vector3::new(-er.y, er.x, 0.0);
        let meridian = around.cross(&n);
        outer(&meridian) / dd + outer(&around) * ((a / dd) / rho.max(tiny))
    }

    fn sdf_hessian_form(&self, p: &Point3<f64>, e1: &Vector3<f64>, e2: &Vector3<f64>) -> [f64; 3] {
        let tiny = f64::MIN_POSITIVE.sqrt();
        let rho = hypot(p.x, p.y);
        if self.cusp(rho, p.z).is_some() || !(rho > 0.0) {
            let h = self.sdf_hessian(p);
            return [e1.dot(&(h * e1)), e1.dot(&(h * e2)), e2.dot(&(h * e2))];
        }
        // H = m mᵀ / D + t tᵀ (a/D)/ρ (see sdf_hessian): the form from the projections,
        // with two divisions (1/ρ, 1/D) instead of six.
        let inv_rho = 1.0 / rho;
        let er = Vector3::new(p.x * inv_rho, p.y * inv_rho, 0.0);
        let a = rho - self.major;
        let inv_dd = 1.0 / hypot(a, p.z).max(tiny);
        let n = er * (a * inv_dd) + Vector3::z() * (p.z * inv_dd);
        let around = Vector3::new(-er.y, er.x, 0.0);
        let meridian = around.cross(&n);
        let (km, kt) = (inv_dd, a * inv_dd * inv_rho);
        let (m1, m2, t1, t2) = (
            meridian.dot(e1),
            meridian.dot(e2),
            around.dot(e1),
            around.dot(e2),
        );
        [
            km * m1 * m1 + kt * t1 * t1,
            km * m1 * m2 + kt * t1 * t2,
            km * m2 * m2 + kt * t2 * t2,
        ]
    }

    fn intersect(
        &self,
        o: &Point3<f64>,
        d: &Vector3<f64>,
        t_min: f64,
        t_max: f64,
    ) -> Option<(f64, Point3<f64>)> {
        let clip = self.clip(o, d, t_min, t_max)?;
        let ray = self.ray(clip.oc, *d);
        let s = trace::first_root(&ray, clip.lo - clip.tc, clip.hi - clip.tc)?;
        Some((clip.tc + s, clip.oc + d * s))
    }

    fn intersect_near(
        &self,
        o: &Point3<f64>,
        d: &Vector3<f64>,
        t_guess: f64,
        t_min: f64,
        t_max: f64,
    ) -> Option<f64> {
        if t_guess >= t_min && t_guess <= t_max {
            // Rebased at the guess; the clip to the bounding region only if the certificate
            // needs a closer start than t_min.
            let og = o + d * t_guess;
            let ray = self.ray(og, *d);
            let (lo, hi) = (t_min - t_guess, t_max - t_guess);
            if let Some(root) = ray.newton(lo, hi) {
                let s = root.s;
                if root.slope_num < 0.0 && ray.convex_on(lo, s) {
                    return Some(t_guess + s);
                }
                let g1 = root.slope();
                if trace::certify(&ray, lo, s, g1) {
                    return Some(t_guess + s);
                }
                if let Some(clip) = self.clip(&og, d, lo, hi)
                    && clip.lo > lo
                    && trace::certify(&ray, clip.lo, s, g1)
                {
                    return Some(t_guess + s);
                }
            }
        }
        self.intersect(o, d, t_min, t_max).map(|(t, _)| t)
    }

    fn extent(&self) -> f64 {
        self.major + self.minor
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The curvature at a known foot and normal equals the curvature found from a point
    /// off the surface, bit for bit (the same foot), for ring, spindle and R = 0 tori.
    #[test]
    fn curvature_on_the_foot_equals_the_curvature() {
        let mut x = 0.61f64;
        let mut rnd = || {
            x = (x * 7919.0 + 0.4321).fract();
            2.0 * x - 1.0
        };
        for (big_r, r) in [(40.0, 12.0), (5.0, 8.0), (0.0, 3.0)] {
            let torus = Torus::new(big_r, r, Material::Inside).unwrap();
            for _ in 0..200 {
                let p = Point3::new(rnd(), rnd(), rnd()) * (big_r + 1.5 * r);
                let (q, n) = torus.foot(&p);
                let [(ka, da), (kb, db)] = torus.curvature(&p);
                let [(la, ea), (lb, eb)] = torus.curvature_on(&q, &n);
                assert!(ka == la && kb == lb || (kb.is_infinite() && lb.is_infinite()));
                assert_eq!((da, db), (ea, eb));
            }
        }
    }

    /// The torus' closed-form quadratic form of the distance Hessian equals the form of
    /// its 3 × 3 matrix (the trait's default) to 1e-13 of the curvature scale, on and off
    /// the surface, for ring and spindle tori, including points whose foot is the cusp.
    #[test]
    fn hessian_form_matches_the_matrix() {
        let mut x = 0.37f64;
        let mut rnd = || {
            x = (x * 7919.0 + 0.1234).fract();
            2.0 * x - 1.0
        };
        for (big_r, r) in [(40.0, 12.0), (5.0, 8.0), (0.0, 3.0)] {
            let torus = Torus::new(big_r, r, Material::Inside).unwrap();
            let scale = 1.0 / r;
            for _ in 0..400 {
                let p = Point3::new(rnd(), rnd(), rnd()) * (big_r + 1.5 * r);
                let e1 = Vector3::new(rnd(), rnd(), rnd());
                let e2 = Vector3::new(rnd(), rnd(), rnd());
                let h = torus.sdf_hessian(&p);
                let want = [e1.dot(&(h * e1)), e1.dot(&(h * e2)), e2.dot(&(h * e2))];
                let got = torus.sdf_hessian_form(&p, &e1, &e2);
                for k in 0..3 {
                    let tol = 1e-13 * scale.max(want[k].abs()) * e1.norm().max(e2.norm()).powi(2);
                    assert!(
                        (got[k] - want[k]).abs() <= tol,
                        "R {big_r} r {r} p {p:?}: {got:?} vs {want:?}"
                    );
                }
            }
        }
    }
}
