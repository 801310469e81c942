//! Surfaces of revolution about `z` with a meridian $\rho = \rho(z)$, $z_{min} \le z \le
//! z_{max}$: crowned and logarithmic roller profiles, or a tabulated meridian.
//!
//! The implicit function is $F = \rho - \rho(z)$ (negative inside the solid), with
//! $|\nabla F| = \sqrt{1+\rho'^2}$, so $F/\sqrt{1+\max\rho'^2}$ is 1-Lipschitz along any ray
//! and the certified ray search of [`super::trace`] applies with the bounds
//! $-\max|\rho''|\,n_z^2 \le F'' \le h^2/\rho_{min}^3 + \max|\rho''|\,n_z^2$ along a unit ray.
//! The surface is the lateral patch only: its ends are open (a ray through an end cap
//! hits the patch from inside or not at all).

use super::trace::{self, RayFunction, Sample};
use super::{Material, Shape, outer, quadratic_roots, radial};
use crate::error::{Error, Result};
use nalgebra::{Matrix3, Point3, Vector3};

/// Meridian profile of a [`Revolution`] surface: $\rho(z) > 0$ with continuous first and
/// second derivatives, about the local `z` axis. Lengths in \[mm\].
///
/// Serialised as a table tagged by `kind`, e.g.
/// `{ kind = "crowned", radius = 10.0, crown_radius = 500.0, half_length = 8.0 }`.
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(
    feature = "serde",
    derive(serde::Serialize, serde::Deserialize, schemars::JsonSchema)
)]
#[cfg_attr(
    feature = "serde",
    serde(tag = "kind", rename_all = "snake_case", deny_unknown_fields)
)]
pub enum Profile {
    /// A cylinder of radius `radius` with a circular crown of radius `crown_radius`
    /// centred at `z = 0`:
    /// $\rho = R - (R_c - \sqrt{R_c^2 - z^2})$ for $|z| \le$ `half_length`.
    /// `crown_radius = inf` gives a straight cylinder.
    Crowned {
        /// Radius R at `z = 0` \[mm\], > 0.
        radius: f64,
        /// Crown radius R_c \[mm\], > `half_length` (may be `inf`).
        crown_radius: f64,
        /// Half-length L \[mm\] of the profile, > 0.
        half_length: f64,
    },
    /// The logarithmic roller profile of Johns & Gohar (1981) in the form of Fujiwara &
    /// Kawase (2007) with the crowning over the whole length ($K_2 = 1$):
    /// $$ \rho = R - A \ln\frac{1}{1 - \big(1 - e^{-z_m/A}\big)(z/L)^2}, \quad |z| \le L. $$
    /// The drop is 0 at the centre and exactly $z_m$ at the ends; $A$ (Fujiwara & Kawase's
    /// $A = 2K_1 Q/(\pi L_{we} E')$, a length) sets the shape: large `scale` tends to a
    /// parabola $z_m (z/L)^2$, small `scale` concentrates the drop at the ends.
    Logarithmic {
        /// Radius R at `z = 0` \[mm\], > 0.
        radius: f64,
        /// Half-length L \[mm\] of the profile, > 0.
        half_length: f64,
        /// Drop $z_m$ at the ends \[mm\], 0 <= z_m < R.
        end_drop: f64,
        /// Shape length A \[mm\], > 0.
        scale: f64,
    },
    /// A tabulated meridian (`z` strictly ascending, `rho > 0`, at least 4 points),
    /// interpolated by a natural cubic spline (C², zero curvature at the ends).
    Table {
        /// Axial positions \[mm\], strictly ascending.
        z: Vec<f64>,
        /// Radii \[mm\] at `z`, > 0.
        rho: Vec<f64>,
    },
}

/// A surface of revolution about local `z` (see [`Profile`]).
#[derive(Debug, Clone, PartialEq)]
pub struct Revolution {
    profile: Profile,
    material: Material,
    z_min: f64,
    z_max: f64,
    /// Natural-spline second derivatives at the knots (`Table` only).
    spline_m: Vec<f64>,
    rho_max: f64,
    /// Per spline interval: largest |rho'| and |rho''| (`Table` only).
    interval_bounds: Vec<(f64, f64)>,
}

fn finite_positive(field: &'static str, v: f64, expected: &'static str) -> Result<f64> {
    if v.is_finite() && v > 0.0 {
        Ok(v)
    } else {
        Err(Error::invalid(field, v, expected))
    }
}

impl Revolution {
    /// Validate the profile and precompute the spline and the derivative bounds.
    ///
    /// # Errors
    /// [`Error::InvalidInput`] naming the profile field (`profile.radius`,
    /// `profile.crown_radius`, `profile.half_length`, `profile.end_drop`, `profile.scale`,
    /// `profile.z`, `profile.rho`) with its valid range.
    pub fn new(profile: Profile, material: Material) -> Result<Self> {
        let mut rev = Revolution {
            profile,
            material,
            z_min: 0.0,
            z_max: 0.0,
            spline_m: Vec::new(),
            rho_max: 0.0,
            interval_bounds: Vec::new(),
        };
        match &rev.profile {
            &Profile::Crowned {
                radius,
                crown_radius,
                half_length,
            } => {
                finite_positive("profile.radius", radius, "a finite radius > 0 mm")?;
                if !(crown_radius > 0.0) {
                    return Err(Error::invalid(
                        "profile.crown_radius",
                        crown_radius,
                        "a crown radius > 0 mm (inf for a straight cylinder)",
                    ));
                }
                finite_positive(
                    "profile.half_length",
                    half_length,
                    "a finite half-length > 0 mm",
                )?;
                if !(half_length < crown_radius) {
                    return Err(Error::invalid(
                        "profile.half_length",
                        half_length,
                        format!("a half-length < crown_radius = {crown_radius} mm"),
                    ));
                }
                rev.z_min = -half_length;
                rev.z_max = half_length;
            }
            &Profile::Logarithmic {
                radius,
                half_length,
                end_drop,
                scale,
            } => {
                finite_positive("profile.radius", radius, "a finite radius > 0 mm")?;
                finite_positive(
                    "profile.half_length",
                    half_length,
                    "a finite half-length > 0 mm",
                )?;
                if !(end_drop >= 0.0 && end_drop < radius) {
                    return Err(Error::invalid(
                        "profile.end_drop",
                        end_drop,
                        format!("an end drop in [0, radius = {radius}) mm"),
                    ));
                }
                finite_positive("profile.scale", scale, "a finite shape length A > 0 mm")?;
                rev.z_min = -half_length;
                rev.z_max = half_length;
            }
            Profile::Table { z, rho } => {
                if z.len() < 4 {
                    return Err(Error::invalid(
                        "profile.z",
                        format!("{} points", z.len()),
                        "at least 4 points",
                    ));
                }
                if rho.len() != z.len() {
                    return Err(Error::invalid(
                        "profile.rho",
                        format!("{} values", rho.len()),
                        format!("as many values as profile.z ({})", z.len()),
                    ));
                }
                if let Some(i) =
                    (0..z.len()).find(|&i| !z[i].is_finite() || (i > 0 && !(z[i] > z[i - 1])))
                {
                    return Err(Error::invalid(
                        format!("profile.z[{i}]"),
                        z[i],
                        "finite values in mm, strictly ascending",
                    ));
                }
                if let Some(i) = (0..rho.len()).find(|&i| !(rho[i].is_finite() && rho[i] > 0.0)) {
                    return Err(Error::invalid(
                        format!("profile.rho[{i}]"),
                        rho[i],
                        "a finite radius > 0 mm",
                    ));
                }
                rev.z_min = z[0];
                rev.z_max = z[z.len() - 1];
                rev.spline_m = natural_spline(z, rho);
            }
        }
        rev.bounds()?;
        Ok(rev)
    }

    /// The profile.
    pub fn profile(&self) -> &Profile {
        &self.profile
    }

    /// The side of the material.
    pub fn material(&self) -> Material {
        self.material
    }

    /// The axial range `[z_min, z_max]` \[mm\] of the patch.
    pub fn z_range(&self) -> [f64; 2] {
        [self.z_min, self.z_max]
    }

    /// `rho(z)`, `rho'(z)`, `rho''(z)` with `z` clamped to the profile's range.
    pub fn meridian(&self, z: f64) -> (f64, f64, f64) {
        let z = z.clamp(self.z_min, self.z_max);
        match &self.profile {
            &Profile::Crowned {
                radius,
                crown_radius: rc,
                ..
            } => {
                if rc.is_infinite() {
                    return (radius, 0.0, 0.0);
                }
                let w = ((rc - z) * (rc + z)).sqrt();
                // rc - w without cancellation.
                (radius - z * z / (rc + w), -z / w, -rc * rc / (w * w * w))
            }
            &Profile::Logarithmic {
                radius,
                half_length: l,
                end_drop,
                scale: a,
            } => {
                let c = -(-end_drop / a).exp_m1();
                let u = c * (z / l) * (z / l);
                let drop = -a * (-u).ln_1p();
                let d1 = a * 2.0 * c * z / (l * l * (1.0 - u));
                let d2 = a * 2.0 * c * (1.0 + u) / (l * l * (1.0 - u) * (1.0 - u));
                (radius - drop, -d1, -d2)
            }
            Profile::Table { z: zs, rho } => {
                let i = zs.partition_point(|&k| k <= z).clamp(1, zs.len() - 1) - 1;
                spline_eval(zs, rho, &self.spline_m, i, z)
            }
        }
    }

    /// Bounds: largest radius, slope and |rho''| over the range (and per spline interval);
    /// rejects a profile that is not positive everywhere.
    fn bounds(&mut self) -> Result<()> {
        #[derive(Clone, Copy)]
        struct Acc {
            rho_min: f64,
            rho_max: f64,
            slope: f64,
            curv: f64,
        }
        impl Acc {
            const EMPTY: Acc = Acc {
                rho_min: f64::INFINITY,
                rho_max: 0.0,
                slope: 0.0,
                curv: 0.0,
            };
            fn visit(&mut self, r: (f64, f64, f64)) {
                self.rho_min = self.rho_min.min(r.0);
                self.rho_max = self.rho_max.max(r.0);
                self.slope = self.slope.max(r.1.abs());
                self.curv = self.curv.max(r.2.abs());
            }
            fn merge(&mut self, o: Acc) {
                self.rho_min = self.rho_min.min(o.rho_min);
                self.rho_max = self.rho_max.max(o.rho_max);
                self.slope = self.slope.max(o.slope);
                self.curv = self.curv.max(o.curv);
            }
        }
        let mut all = Acc::EMPTY;
        match &self.profile {
            // Monotone in |z|: the extremes are at the centre and the ends.
            Profile::Crowned { .. } | Profile::Logarithmic { .. } => {
                all.visit(self.meridian(0.0));
                all.visit(self.meridian(self.z_max));
            }
            Profile::Table { z, rho } => {
                let m = &self.spline_m;
                for i in 0..z.len() - 1 {
                    let h = z[i + 1] - z[i];
                    let at = |b: f64| spline_eval(z, rho, m, i, z[i] + b * h);
                    let mut acc = Acc::EMPTY;
                    acc.visit(at(0.0));
                    acc.visit(at(1.0));
                    // rho' is quadratic in B = (z - z_i)/h; its roots are rho's extrema.
                    let (qa, qb, qc) = (
                        0.5 * h * (m[i + 1] - m[i]),
                        h * m[i],
                        (rho[i + 1] - rho[i]) / h - h * (2.0 * m[i] + m[i + 1]) / 6.0,
                    );
                    let mut cands = [f64::NAN; 3];
                    if qa == 0.0 {
                        cands[0] = -qc / qb;
                    } else if let Some((r1, r2)) = quadratic_roots(qa, qb, qc) {
                        cands[0] = r1;
                        cands[1] = r2;
                    }
                    // rho'' is linear in B: the slope's extremum.
                    if m[i] != m[i + 1] {
                        cands[2] = m[i] / (m[i] - m[i + 1]);
                    }
                    for b in cands {
                        if (0.0..=1.0).contains(&b) {
                            acc.visit(at(b));
                        }
                    }
                    self.interval_bounds.push((acc.slope, acc.curv));
                    all.merge(acc);
                }
                if !(all.rho_min > 0.0) {
                    return Err(Error::invalid(
                        "profile.rho",
                        format!("min {:e}", all.rho_min),
                        "a table whose spline stays > 0 mm between the points",
                    ));
                }
            }
        }
        if !(all.rho_min > 0.0) {
            return Err(Error::invalid(
                "profile.radius",
                all.rho_min,
                "a radius larger than the crown drop at the ends (rho > 0 mm everywhere)",
            ));
        }
        self.rho_max = all.rho_max;
        Ok(())
    }

    /// Largest |rho'| and |rho''| for `z` between `z0` and `z1` (clamped to the range).
    fn local_bounds(&self, z0: f64, z1: f64) -> (f64, f64) {
        let (lo, hi) = (
            z0.min(z1).clamp(self.z_min, self.z_max),
            z0.max(z1).clamp(self.z_min, self.z_max),
        );
        match &self.profile {
            Profile::Crowned { .. } | Profile::Logarithmic { .. } => {
                // |rho'| and |rho''| grow with |z|.
                let (_, r1, r2) = self.meridian(if lo.abs() > hi.abs() { lo } else { hi });
                (r1.abs(), r2.abs())
            }
            Profile::Table { z, .. } => {
                let first = z.partition_point(|&k| k <= lo).clamp(1, z.len() - 1) - 1;
                let last = z.partition_point(|&k| k < hi).clamp(1, z.len() - 1) - 1;
                self.interval_bounds[first..=last.max(first)]
                    .iter()
                    .fold((0.0f64, 0.0f64), |acc, b| (acc.0.max(b.0), acc.1.max(b.1)))
            }
        }
    }

    fn scale(&self) -> f64 {
        self.rho_max.max(self.z_min.abs()).max(self.z_max.abs())
    }

    /// Closest meridian point to `(rho_p, z_p)`: the axial position `z*` on the patch.
    fn closest_z(&self, rho_p: f64, z_p: f64) -> f64 {
        let phi = |z: f64| {
            let (r, _, _) = self.meridian(z);
            (r - rho_p) * (r - rho_p) + (z - z_p) * (z - z_p)
        };
        // q(z) = phi'(z)/2 and q'(z).
        let q = |z: f64| {
            let (r, r1, r2) = self.meridian(z);
            (
                (r - rho_p) * r1 + (z - z_p),
                1.0 + r1 * r1 + (r - rho_p) * r2,
            )
        };
        const N: usize = 24;
        let dz = (self.z_max - self.z_min) / N as f64;
        let mut best = (z_p.clamp(self.z_min, self.z_max), 0.0);
        best.1 = phi(best.0);
        for k in 0..=N {
            let z = self.z_min + k as f64 * dz;
            let v = phi(z);
            if v < best.1 {
                best = (z, v);
            }
        }
        let (mut a, mut b) = ((best.0 - dz).max(self.z_min), (best.0 + dz).min(self.z_max));
        let (qa, qb) = (q(a).0, q(b).0);
        if !(qa < 0.0 && qb > 0.0) {
            // No interior minimum in the bracket: the better end or the grid point.
            return [a, b, best.0]
                .into_iter()
                .min_by(|x, y| phi(*x).total_cmp(&phi(*y)))
                .unwrap_or(best.0);
        }
        let mut z = best.0.clamp(a, b);
        for _ in 0..100 {
            let (qz, q1) = q(z);
            if qz == 0.0 {
                break;
            }
            if qz < 0.0 {
                a = z;
            } else {
                b = z;
            }
            let newton = z - qz / q1;
            let next = if q1 > 0.0 && newton > a && newton < b {
                newton
            } else {
                0.5 * (a + b)
            };
            if (next - z).abs() <= 4.0 * f64::EPSILON * self.scale() {
                z = next;
                break;
            }
            z = next;
        }
        z
    }

    fn ray(&self, o: Point3<f64>, d: Vector3<f64>) -> RevolutionRay<'_> {
        let tol = 8.0 * f64::EPSILON * self.scale();
        let h = o.x * d.y - o.y * d.x;
        RevolutionRay {
            rev: self,
            o,
            d,
            tol,
            skip: 4.0 * (tol * self.scale()).sqrt(),
            v2: d.x * d.x + d.y * d.y,
            h2: h * h,
        }
    }

    /// Ray parameters in `[t_min, t_max]` inside the slab `z_min..z_max` and the cylinder
    /// `rho <= rho_max`, relative to a rebased origin.
    fn clip(&self, o: &Point3<f64>, d: &Vector3<f64>, t_min: f64, t_max: f64) -> Option<Clip> {
        let centre = Vector3::new(0.0, 0.0, 0.5 * (self.z_min + self.z_max));
        let tc = -(o.coords - centre).dot(d);
        let oc = o + d * tc;
        let (mut lo, mut hi) = (t_min - tc, t_max - tc);
        let margin = 1e-9 * self.scale();
        if d.z != 0.0 {
            let s1 = (self.z_min - margin - oc.z) / d.z;
            let s2 = (self.z_max + margin - oc.z) / d.z;
            lo = lo.max(s1.min(s2));
            hi = hi.min(s1.max(s2));
        } else if oc.z < self.z_min - margin || oc.z > self.z_max + margin {
            return None;
        }
        let rm = self.rho_max * (1.0 + 1e-9);
        let v2 = d.x * d.x + d.y * d.y;
        let c = oc.x * oc.x + oc.y * oc.y - rm * rm;
        if v2 > 0.0 {
            let b = 2.0 * (oc.x * d.x + oc.y * d.y);
            let (r1, r2) = quadratic_roots(v2, b, c)?;
            lo = lo.max(r1);
            hi = hi.min(r2);
        } else if c > 0.0 {
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

/// Natural cubic spline: second derivatives at the knots (tridiagonal, Thomas algorithm).
fn natural_spline(z: &[f64], y: &[f64]) -> Vec<f64> {
    let n = z.len();
    let mut m = vec![0.0; n];
    let mut c_prime = vec![0.0; n];
    let mut d_prime = vec![0.0; n];
    for i in 1..n - 1 {
        let (h0, h1) = (z[i] - z[i - 1], z[i + 1] - z[i]);
        let (a, b, c) = (h0 / 6.0, (h0 + h1) / 3.0, h1 / 6.0);
        let d = (y[i + 1] - y[i]) / h1 - (y[i] - y[i - 1]) / h0;
        let denom = b - a * c_prime[i - 1];
        c_prime[i] = c / denom;
        d_prime[i] = (d - a * d_prime[i - 1]) / denom;
    }
    for i in (1..n - 1).rev() {
        m[i] = d_prime[i] - c_prime[i] * m[i + 1];
    }
    m
}

/// Spline value and derivatives on interval `i` at `z`.
fn spline_eval(zs: &[f64], y: &[f64], m: &[f64], i: usize, z: f64) -> (f64, f64, f64) {
    let h = zs[i + 1] - zs[i];
    let b = (z - zs[i]) / h;
    let a = 1.0 - b;
    let rho = a * y[i]
        + b * y[i + 1]
        + ((a * a * a - a) * m[i] + (b * b * b - b) * m[i + 1]) * h * h / 6.0;
    let rho1 = (y[i + 1] - y[i]) / h - (3.0 * a * a - 1.0) / 6.0 * h * m[i]
        + (3.0 * b * b - 1.0) / 6.0 * h * m[i + 1];
    let rho2 = a * m[i] + b * m[i + 1];
    (rho, rho1, rho2)
}

/// The surface of revolution along a ray: `f = g = F = rho - rho(z)`.
struct RevolutionRay<'a> {
    rev: &'a Revolution,
    o: Point3<f64>,
    d: Vector3<f64>,
    tol: f64,
    skip: f64,
    v2: f64,
    h2: f64,
}

impl RayFunction for RevolutionRay<'_> {
    fn sample(&self, s: f64) -> Sample {
        let (o, d) = (&self.o, &self.d);
        let (px, py, pz) = (o.x + s * d.x, o.y + s * d.y, o.z + s * d.z);
        let rho = (px * px + py * py).sqrt();
        let rho1 = if rho > 0.0 {
            (px * d.x + py * d.y) / rho
        } else {
            self.v2.sqrt()
        };
        let (r, r1, _) = self.rev.meridian(pz);
        let g = rho - r;
        let g1 = rho1 - r1 * d.z;
        Sample {
            f: g,
            f1: g1,
            g,
            g1,
        }
    }

    fn free_step(&self, at_a: &Sample, a: f64, b: f64) -> f64 {
        // |F'| <= sqrt(1 + rho'²) along a unit ray.
        let (za, zb) = (self.o.z + a * self.d.z, self.o.z + b * self.d.z);
        let (slope, _) = self.rev.local_bounds(za, zb);
        at_a.f.abs() / ((1.0 + slope * slope).sqrt() * (1.0 + 1e-12))
    }

    fn g2_bounds(&self, a: f64, b: f64) -> (f64, f64) {
        let (za, zb) = (self.o.z + a * self.d.z, self.o.z + b * self.d.z);
        let (_, curv) = self.rev.local_bounds(za, zb);
        let bend = curv * self.d.z * self.d.z * (1.0 + 1e-9) + 1e-300;
        let lo = -bend;
        if self.v2 == 0.0 {
            return (lo, bend);
        }
        // rho'' = h²/rho³ >= 0, between its values at the extremes of rho (rho is convex
        // along the ray: the minimum at the closest approach to the axis, the maximum at an
        // end).
        let (o, d) = (&self.o, &self.d);
        let rho2_at = |s: f64| {
            let (wx, wy) = (o.x + s * d.x, o.y + s * d.y);
            wx * wx + wy * wy
        };
        let rmin2 = rho2_at((-(o.x * d.x + o.y * d.y) / self.v2).clamp(a, b));
        let rmax2 = rho2_at(a).max(rho2_at(b));
        if self.h2 == 0.0 {
            return (lo, if rmin2 > 0.0 { bend } else { f64::INFINITY });
        }
        let rho_lo = self.h2 / (rmax2 * rmax2.sqrt()) * (1.0 - 1e-9);
        let rho_hi = self.h2 / (rmin2 * rmin2.sqrt()) * (1.0 + 1e-9);
        (rho_lo + lo, rho_hi + bend)
    }

    fn tol(&self) -> f64 {
        self.tol
    }

    fn skip(&self) -> f64 {
        self.skip
    }
}

impl Shape for Revolution {
    fn implicit(&self, p: &Point3<f64>) -> f64 {
        p.x.hypot(p.y) - self.meridian(p.z).0
    }

    fn signed_distance(&self, p: &Point3<f64>) -> f64 {
        let (q, _) = self.foot(p);
        let dist = (p - q).norm();
        let f = self.implicit(p);
        if f < 0.0 { -dist } else { dist }
    }

    fn normal(&self, p: &Point3<f64>) -> Vector3<f64> {
        let (er, _) = radial(p);
        let (_, r1, _) = self.meridian(p.z);
        (er - Vector3::z() * r1) / (1.0 + r1 * r1).sqrt()
    }

    fn foot(&self, p: &Point3<f64>) -> (Point3<f64>, Vector3<f64>) {
        let (er, rho) = radial(p);
        let z = self.closest_z(rho, p.z);
        let (r, r1, _) = self.meridian(z);
        let q = er * r + Vector3::z() * z;
        (
            Point3::from(q),
            (er - Vector3::z() * r1) / (1.0 + r1 * r1).sqrt(),
        )
    }

    fn curvature(&self, p: &Point3<f64>) -> [(f64, Vector3<f64>); 2] {
        let (er, rho) = radial(p);
        let z = self.closest_z(rho, p.z);
        let (r, r1, r2) = self.meridian(z);
        let w = (1.0 + r1 * r1).sqrt();
        let meridian = (er * r1 + Vector3::z()) / w;
        let around = Vector3::new(-er.y, er.x, 0.0);
        [(-r2 / (w * w * w), meridian), (1.0 / (r * w), around)]
    }

    fn sdf_hessian(&self, p: &Point3<f64>) -> Matrix3<f64> {
        // Parallel-surface curvature k/(1 + k d) in the principal directions of the foot.
        let d = self.signed_distance(p);
        let mut h = Matrix3::zeros();
        for (k, dir) in self.curvature(p) {
            let denom = (1.0 + k * d).max(1e-12);
            h += outer(&dir) * (k / denom);
        }
        h
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
        let s = trace::first_root(&ray, clip.lo, clip.hi)?;
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
            let clip = self.clip(o, d, t_min, t_max)?;
            // Rebase at the guess.
            let shift = t_guess - clip.tc;
            let og = clip.oc + d * shift;
            let ray = self.ray(og, *d);
            if let Some(s) = trace::root_near(&ray, clip.lo - shift, clip.hi - shift) {
                return Some(t_guess + s);
            }
        }
        self.intersect(o, d, t_min, t_max).map(|(t, _)| t)
    }

    fn extent(&self) -> f64 {
        self.scale()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn spline_reproduces_a_cubic_interior_and_knots() {
        let z: Vec<f64> = (0..8).map(|i| i as f64).collect();
        let rho: Vec<f64> = z.iter().map(|z| 10.0 + 0.1 * z).collect();
        let rev = Revolution::new(Profile::Table { z, rho }, Material::Inside).unwrap();
        let (r, r1, r2) = rev.meridian(3.3);
        assert!((r - 10.33).abs() < 1e-13 && (r1 - 0.1).abs() < 1e-13 && r2.abs() < 1e-13);
    }

    #[test]
    fn crowned_and_logarithmic_derivatives_match_finite_differences() {
        let profiles = [
            Profile::Crowned {
                radius: 10.0,
                crown_radius: 50.0,
                half_length: 8.0,
            },
            Profile::Logarithmic {
                radius: 10.0,
                half_length: 8.0,
                end_drop: 0.05,
                scale: 0.01,
            },
        ];
        for p in profiles {
            let rev = Revolution::new(p, Material::Inside).unwrap();
            for z in [-7.5, -3.0, 0.0, 1.0, 6.0] {
                let h = 1e-5;
                let (r, r1, r2) = rev.meridian(z);
                let (rp, r1p, _) = rev.meridian(z + h);
                let (rm, r1m, _) = rev.meridian(z - h);
                assert!((r1 - (rp - rm) / (2.0 * h)).abs() < 1e-7 * (1.0 + r1.abs()));
                assert!((r2 - (r1p - r1m) / (2.0 * h)).abs() < 1e-5 * (1.0 + r2.abs()));
                assert!(r > 0.0);
            }
        }
    }
}
