//! The contact point of two placed surfaces (PimP step 1, Wirsching et al. (2020) §2.2): the pair
//! of surface points with anti-parallel outward normals whose connecting vector lies along the
//! common normal — the closest points of two separate bodies, or the deepest point of an
//! interpenetration.
//!
//! **Method.** One surface (`a`, the one with the more compact parametrisation: sphere or
//! torus, then surface of revolution, cone, plane) is searched for the minimum of the other
//! body's signed distance $\phi(\mathbf p) = d_b(\mathbf p)$, $\mathbf p \in S_a$. At a
//! critical point the gradient $\nabla d_b = \mathbf n_b(\text{foot})$ is normal to $S_a$,
//! and the foot of $\mathbf p$ on $S_b$ lies along that normal: exactly the contact
//! conditions. The minimisation is a Riemannian Newton iteration on $S_a$: in the tangent
//! plane $(\mathbf e_1, \mathbf e_2)$ of $S_a$ the gradient is $g_i = \mathbf n_b\cdot\mathbf
//! e_i$ and the Hessian
//! $$ \mathbf A = \mathbf E^\mathsf T\big(\nabla^2 d_b - (\mathbf n_b\cdot\mathbf n_a)\,\mathbf
//! K_a\big)\mathbf E, $$ with $\mathbf K_a$ the shape operator of $S_a$; at the solution ($\mathbf
//! n_b = -\mathbf n_a$) it is the sum of the two curvature tensors, i.e. the relative curvature,
//! positive definite for a Hertzian contact. Steps are Levenberg–Marquardt damped inside a trust
//! region and pulled back onto $S_a$ by its closest-point map; they must not increase
//! $\phi$. Starts: the guess (if given and it converges, it wins), otherwise the local
//! minima of $\phi$ on a coarse grid of $S_a$'s parameters; the lowest converged minimum
//! is returned (with two contact zones, the deeper/closer one).

use super::surface::{PlacedSurface, Surface, hypot, tangent_basis};
use crate::error::{Error, Result};
use nalgebra::{Matrix3, Point3, Unit, Vector3};
use std::f64::consts::{PI, TAU};

/// The contact point of two placed surfaces, in world coordinates.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ContactPoint {
    /// The contact point on surface 1 \[mm\].
    pub point1: Point3<f64>,
    /// The contact point on surface 2 \[mm\].
    pub point2: Point3<f64>,
    /// The midpoint of `point1` and `point2`, origin of the contact plane \[mm\].
    pub point: Point3<f64>,
    /// Common unit normal, pointing from body 2 *into* body 1: the outward normal of body 2
    /// at `point2`, equal to minus the outward normal of body 1 at `point1` (the `z` axis of
    /// the crate's contact frame).
    pub normal: Unit<Vector3<f64>>,
    /// Signed separation \[mm\]: > 0 the bodies are apart by this smallest distance; < 0
    /// they interpenetrate and this is minus the depth of the deepest point; 0 touching.
    /// `point1 - point2 = separation * normal`.
    pub separation: f64,
}

/// Largest |n_a + n_b| accepted as anti-parallel.
const ANTIPARALLEL_TOL: f64 = 1e-9;
/// Tangential gradient |P n_b| (sine of the normals' misalignment) counted as converged.
const GRAD_TOL: f64 = 1e-11;
/// Tangential gradient at which the polishing stops (rounding floor).
const GRAD_TARGET: f64 = 1e-15;
/// Newton iterations per start.
const MAX_ITER: usize = 100;
/// Local minima of the start grid refined.
const MAX_STARTS: usize = 6;

/// Find the contact point of `body1` and `body2`.
///
/// `guess` is a world point near the expected contact (for a multi-body simulation, the
/// previous step's [`ContactPoint::point`]); when it converges to a valid contact point
/// that point is returned even if another contact zone is deeper. Without a guess (or
/// when it fails) a multi-start search returns the deepest (most negative separation) /
/// closest contact.
///
/// Exact closed forms (sphere/plane, sphere/sphere, sphere/torus) are reproduced to about
/// 1e-12 relative. Supported pairs: any two of sphere, torus, cone, surface of revolution
/// and plane, except plane/plane.
///
/// # Errors
/// - [`Error::InvalidInput`] (field `guess`) for a non-finite guess.
/// - [`Error::Geometry`] when no point with anti-parallel normals exists: two planes
///   (parallel planes are equidistant everywhere, non-parallel ones interpenetrate without
///   bound), or one body engulfing the other's surface so that the extremal normals are
///   parallel.
/// - [`Error::NotConverged`] when no start converges (e.g. the extremum is at a cone's
///   apex or the edge of a surface of revolution: not a smooth contact).
///
/// # Example
/// A ball of radius 10 mm 0.5 mm above a flat:
/// ```
/// use kontakt::geometry::{find_contact, Material, PlacedSurface, Surface};
/// use nalgebra::{Isometry3, Vector3};
/// let ball = PlacedSurface::new(
///     Surface::sphere(10.0, Material::Inside)?,
///     Isometry3::translation(0.0, 0.0, 10.5),
/// )?;
/// let flat = PlacedSurface::new(Surface::plane(Material::Inside), Isometry3::identity())?;
/// let c = find_contact(&ball, &flat, None)?;
/// assert!((c.separation - 0.5).abs() < 1e-12);
/// assert!((c.normal.z - 1.0).abs() < 1e-12); // from the flat into the ball
/// # Ok::<(), kontakt::Error>(())
/// ```
pub fn find_contact(
    body1: &PlacedSurface,
    body2: &PlacedSurface,
    guess: Option<Point3<f64>>,
) -> Result<ContactPoint> {
    if let (Surface::Plane(_), Surface::Plane(_)) = (&body1.surface, &body2.surface) {
        return Err(Error::Geometry {
            field: "body2.surface".into(),
            reason: "two planes have no unique contact point: parallel planes are equidistant \
                     everywhere and non-parallel ones interpenetrate without bound; give one \
                     body a curved surface"
                .into(),
        });
    }
    if let Some(g) = guess
        && !g.coords.iter().all(|c| c.is_finite())
    {
        return Err(Error::invalid(
            "guess",
            format!("[{}, {}, {}]", g.x, g.y, g.z),
            "a finite point in mm (or None)",
        ));
    }
    // Search the surface with the more compact parametrisation.
    let swap = rank(&body2.surface) < rank(&body1.surface);
    let (a, b) = if swap { (body2, body1) } else { (body1, body2) };
    let scale = {
        let e = a.surface.extent().max(b.surface.extent());
        if e > 0.0 {
            e
        } else {
            (a.pose.translation.vector - b.pose.translation.vector).norm() + 1.0
        }
    };
    let mut iterations = 0;
    if let Some(g) = guess {
        let sol = refine(a, b, g, scale);
        iterations += sol.iterations;
        if sol.converged && sol.antiparallel() {
            return Ok(sol.contact(swap));
        }
    }
    let mut parallel = false;
    let mut residual = f64::INFINITY;
    // Search `a`; if it has only parallel-normal extrema (e.g. a deep interpenetration where
    // the deepest point of `a` lies beyond `b`'s centre), search `b` instead.
    for (a, b, swap) in [(a, b, swap), (b, a, !swap)] {
        let mut best: Option<Solution> = None;
        for start in starts(a, b) {
            let sol = refine(a, b, start, scale);
            iterations += sol.iterations;
            residual = residual.min((sol.na + sol.nb).norm());
            if !sol.converged {
                continue;
            }
            if !sol.antiparallel() {
                parallel |= sol.na.dot(&sol.nb) > 0.0;
                continue;
            }
            if best.as_ref().is_none_or(|b| sol.sd < b.sd) {
                best = Some(sol);
            }
        }
        if let Some(sol) = best {
            return Ok(sol.contact(swap));
        }
    }
    if parallel {
        Err(Error::Geometry {
            field: "bodies".into(),
            reason: "the extremal points of the two surfaces have parallel, not anti-parallel, \
                     normals: one body engulfs the other's surface, so there is no contact \
                     normal; check the poses and the material sides"
                .into(),
        })
    } else {
        Err(Error::NotConverged {
            what: "contact point (anti-parallel normals)".into(),
            iterations,
            residual,
        })
    }
}

/// Preference for the searched surface: compact two-parameter surfaces first.
fn rank(s: &Surface) -> u8 {
    match s {
        Surface::Sphere(_) | Surface::Torus(_) => 0,
        Surface::Revolution(_) => 1,
        Surface::Cone(_) => 2,
        Surface::Plane(_) => 3,
    }
}

/// The state of one Newton run on surface `a`.
struct Solution {
    /// Point on `a`.
    pa: Point3<f64>,
    /// Its foot on `b`.
    pb: Point3<f64>,
    /// Outward normal of `a` at `pa`.
    na: Vector3<f64>,
    /// Outward normal of `b` at `pb`.
    nb: Vector3<f64>,
    /// Signed distance of `pa` from `b`.
    sd: f64,
    converged: bool,
    iterations: usize,
}

impl Solution {
    fn antiparallel(&self) -> bool {
        (self.na + self.nb).norm() <= ANTIPARALLEL_TOL
    }

    /// The contact point with body 1 = `a` (or `b` when `swap`).
    fn contact(&self, swap: bool) -> ContactPoint {
        // From body 2 into body 1: n_b if a is body 1, n_a if a is body 2; the bisector
        // of the two (equal to ~1e-13) is used.
        let (point1, point2, n2, n1) = if swap {
            (self.pb, self.pa, self.na, self.nb)
        } else {
            (self.pa, self.pb, self.nb, self.na)
        };
        let normal = Unit::new_normalize(n2 - n1);
        ContactPoint {
            point1,
            point2,
            point: nalgebra::center(&point1, &point2),
            normal,
            separation: (point1 - point2).dot(&normal),
        }
    }
}

/// A placed surface with its rotation as a matrix (one conversion per search instead of a
/// quaternion rotation for every point and direction: a Newton step turns about a dozen).
struct Placed<'a> {
    surface: &'a Surface,
    /// Local → world rotation.
    r: Matrix3<f64>,
    /// Its transpose, world → local.
    rt: Matrix3<f64>,
    /// Local origin in the world \[mm\].
    t: Vector3<f64>,
}

impl<'a> Placed<'a> {
    fn new(s: &'a PlacedSurface) -> Self {
        let r = *s.pose.rotation.to_rotation_matrix().matrix();
        Placed {
            surface: &s.surface,
            r,
            rt: r.transpose(),
            t: s.pose.translation.vector,
        }
    }

    fn to_local(&self, p: &Point3<f64>) -> Point3<f64> {
        Point3::from(self.rt * (p.coords - self.t))
    }

    fn to_world(&self, q: &Point3<f64>) -> Point3<f64> {
        Point3::from(self.r * q.coords + self.t)
    }

    /// [`PlacedSurface::closest_point`].
    fn closest_point(&self, p: &Point3<f64>) -> (Point3<f64>, Vector3<f64>) {
        let (q, n) = self.surface.closest_point(&self.to_local(p));
        (self.to_world(&q), self.r * n.into_inner())
    }

    /// [`PlacedSurface::closest_point_distance`].
    fn closest_point_distance(&self, p: &Point3<f64>) -> (Point3<f64>, Vector3<f64>, f64) {
        let (q, n, d) = self.surface.closest_point_distance(&self.to_local(p));
        (self.to_world(&q), self.r * n.into_inner(), d)
    }

    /// The quadratic form of the distance Hessian on two world directions
    /// (`Surface::sdf_hessian_form` on the directions turned into the local frame).
    fn sdf_hessian_form(&self, p: &Point3<f64>, e1: &Vector3<f64>, e2: &Vector3<f64>) -> [f64; 3] {
        self.surface
            .sdf_hessian_form(&self.to_local(p), &(self.rt * e1), &(self.rt * e2))
    }
}

/// Newton / Levenberg–Marquardt minimisation of `b`'s signed distance over surface `a`.
/// Iterates until the tangential gradient reaches [`GRAD_TARGET`] or stops decreasing
/// after reaching [`GRAD_TOL`]; returns the best iterate.
fn refine(a: &PlacedSurface, b: &PlacedSurface, start: Point3<f64>, scale: f64) -> Solution {
    let (a, b) = (Placed::new(a), Placed::new(b));
    let eval = |p: Point3<f64>| {
        let (pb, nb, sd) = b.closest_point_distance(&p);
        (sd, pb, nb)
    };
    let grad = |na: &Vector3<f64>, nb: &Vector3<f64>| {
        let (e1, e2) = tangent_basis(na);
        (e1, e2, nb.dot(&e1), nb.dot(&e2))
    };
    // The foot's normal is the normal at the foot (the same direction): no second foot.
    let (mut p, mut na) = a.closest_point(&start);
    let (mut sd, mut pb, mut nb) = eval(p);
    let mut best = Solution {
        pa: p,
        pb,
        na,
        nb,
        sd,
        converged: false,
        iterations: 0,
    };
    let mut best_g = f64::INFINITY;
    let mut lambda = 0.0;
    let mut radius = 0.25 * scale;
    let mut polish = 0;
    for it in 1..=MAX_ITER {
        let (e1, e2, g1, g2) = grad(&na, &nb);
        let gn = hypot(g1, g2);
        if gn < best_g {
            best_g = gn;
            best = Solution {
                pa: p,
                pb,
                na,
                nb,
                sd,
                converged: false,
                iterations: it,
            };
        }
        if gn <= GRAD_TARGET {
            break;
        }
        if gn <= GRAD_TOL {
            // Quadratic convergence: a few more steps reach the rounding floor.
            polish += 1;
            if polish > 3 {
                break;
            }
        }
        // Eᵀ(∇²d_b − (n_b·n_a) K_a)E from each surface's quadratic form.
        let (hb, ha, c) = (
            b.sdf_hessian_form(&p, &e1, &e2),
            a.sdf_hessian_form(&p, &e1, &e2),
            nb.dot(&na),
        );
        let (a11, a12, a22) = (hb[0] - ha[0] * c, hb[1] - ha[1] * c, hb[2] - ha[2] * c);
        if !(a11.is_finite() && a12.is_finite() && a22.is_finite()) {
            break;
        }
        let floor = 1e-9 * (a11.abs() + a22.abs() + a12.abs()) + 1e-12 / scale;
        let min_eig = 0.5 * (a11 + a22) - (0.25 * (a11 - a22) * (a11 - a22) + a12 * a12).sqrt();
        let mut accepted = false;
        let mut step_len = 0.0;
        for _ in 0..60 {
            if min_eig + lambda <= 0.0 {
                lambda = -min_eig + floor.max(1e-3 * min_eig.abs());
            }
            let (b11, b22) = (a11 + lambda, a22 + lambda);
            let det = b11 * b22 - a12 * a12;
            let mut u1 = -(b22 * g1 - a12 * g2) / det;
            let mut u2 = -(b11 * g2 - a12 * g1) / det;
            let len = hypot(u1, u2);
            if !len.is_finite() {
                lambda = (4.0 * lambda).max(floor);
                continue;
            }
            if len > radius {
                u1 *= radius / len;
                u2 *= radius / len;
            }
            let (p_try, na_try) = a.closest_point(&(p + e1 * u1 + e2 * u2));
            let (sd_try, pb_try, nb_try) = eval(p_try);
            if sd_try <= sd + 8.0 * f64::EPSILON * (sd.abs() + scale) {
                p = p_try;
                sd = sd_try;
                pb = pb_try;
                nb = nb_try;
                na = na_try;
                lambda *= 0.25;
                if lambda < floor {
                    lambda = 0.0;
                }
                radius = (2.0 * radius).min(scale);
                accepted = true;
                step_len = hypot(u1, u2);
                break;
            }
            lambda = (4.0 * lambda).max(floor);
            radius *= 0.25;
        }
        if !accepted || step_len <= 4.0 * f64::EPSILON * scale {
            // No descent left, or a step below the resolution of the coordinates.
            let (_, _, g1, g2) = grad(&na, &nb);
            if hypot(g1, g2) < best_g {
                best_g = hypot(g1, g2);
                best = Solution {
                    pa: p,
                    pb,
                    na,
                    nb,
                    sd,
                    converged: false,
                    iterations: it,
                };
            }
            break;
        }
    }
    best.converged = best_g <= GRAD_TOL;
    best
}

/// Starting points on `a` (world): the local minima of `b`'s signed distance over a coarse
/// grid of `a`'s two surface parameters, best first, at most [`MAX_STARTS`].
fn starts(a: &PlacedSurface, b: &PlacedSurface) -> Vec<Point3<f64>> {
    let (grid, nu, nv, wrap_u) = grid(a, b);
    let values: Vec<f64> = grid.iter().map(|p| b.signed_distance(p)).collect();
    let at = |i: usize, j: usize| values[i * nv + j];
    let mut minima: Vec<(f64, usize)> = Vec::new();
    for i in 0..nu {
        for j in 0..nv {
            let v = at(i, j);
            if !v.is_finite() {
                continue;
            }
            let mut is_min = true;
            for di in [-1i64, 0, 1] {
                for dj in [-1i64, 0, 1] {
                    if di == 0 && dj == 0 {
                        continue;
                    }
                    let ii = i as i64 + di;
                    let ii = if wrap_u {
                        ii.rem_euclid(nu as i64)
                    } else if ii < 0 || ii >= nu as i64 {
                        continue;
                    } else {
                        ii
                    };
                    let jj = (j as i64 + dj).rem_euclid(nv as i64);
                    if at(ii as usize, jj as usize) < v {
                        is_min = false;
                    }
                }
            }
            if is_min {
                minima.push((v, i * nv + j));
            }
        }
    }
    minima.sort_by(|x, y| x.0.total_cmp(&y.0));
    // Grid points at a pole share one location: keep distinct points only.
    let mut out: Vec<Point3<f64>> = Vec::new();
    for (_, k) in minima {
        let p = grid[k];
        if out
            .iter()
            .all(|q| (q - p).norm() > 1e-12 * (1.0 + p.coords.norm()))
        {
            out.push(p);
        }
        if out.len() == MAX_STARTS {
            break;
        }
    }
    out
}

/// A `nu × nv` grid of world points on `a` (`v` periodic, row-major), and whether `u` is
/// periodic.
fn grid(a: &PlacedSurface, b: &PlacedSurface) -> (Vec<Point3<f64>>, usize, usize, bool) {
    const NV: usize = 32;
    let phi = |j: usize| TAU * j as f64 / NV as f64;
    let mut local = Vec::with_capacity(24 * NV);
    let mut push = |nu: usize, point: &dyn Fn(usize, usize) -> Point3<f64>| {
        for i in 0..nu {
            for j in 0..NV {
                local.push(point(i, j));
            }
        }
        nu
    };
    let (nu, wrap_u) = match &a.surface {
        Surface::Sphere(s) => {
            let (r, nu) = (s.radius(), 17);
            let nu = push(nu, &|i, j| {
                let (st, ct) = (PI * i as f64 / (nu - 1) as f64).sin_cos();
                let (sp, cp) = phi(j).sin_cos();
                Point3::new(r * st * cp, r * st * sp, r * ct)
            });
            (nu, false)
        }
        Surface::Torus(t) => {
            let (big_r, r) = (t.major(), t.minor());
            // The outer sheet only: R + r cos(theta) >= 0.
            let wrap = big_r >= r;
            let th_max = if wrap { PI } else { (-big_r / r).acos() };
            let nu = 24;
            let nu = push(nu, &|i, j| {
                let th = if wrap {
                    TAU * i as f64 / nu as f64
                } else {
                    -th_max + 2.0 * th_max * i as f64 / (nu - 1) as f64
                };
                let rho = big_r + r * th.cos();
                let (sp, cp) = phi(j).sin_cos();
                Point3::new(rho * cp, rho * sp, r * th.sin())
            });
            (nu, wrap)
        }
        Surface::Revolution(rev) => {
            let [z0, z1] = rev.z_range();
            let nu = 17;
            let nu = push(nu, &|i, j| {
                let z = z0 + (z1 - z0) * i as f64 / (nu - 1) as f64;
                let rho = rev.meridian(z).0;
                let (sp, cp) = phi(j).sin_cos();
                Point3::new(rho * cp, rho * sp, z)
            });
            (nu, false)
        }
        Surface::Cone(c) => {
            // Slant range from the apex: far enough to pass the other body.
            let other = a.to_local(&Point3::from(b.pose.translation.vector));
            let reach = 2.0 * (other.coords.norm() + b.surface.extent()) + 1e-3;
            let (sin, cos) = c.half_angle().sin_cos();
            let nu = 17;
            let nu = push(nu, &|i, j| {
                let s = reach * (i as f64 + 0.5) / nu as f64;
                let (sp, cp) = phi(j).sin_cos();
                Point3::new(s * sin * cp, s * sin * sp, s * cos)
            });
            (nu, false)
        }
        Surface::Plane(_) => {
            // A square around the other body's origin (reached only when the other surface
            // is searched first and failed).
            let other = a.to_local(&Point3::from(b.pose.translation.vector));
            let half = b.surface.extent().max(1.0) * 2.0;
            let nu = 17;
            let nu = push(nu, &|i, j| {
                let x = other.x - half + 2.0 * half * i as f64 / (nu - 1) as f64;
                let y = other.y - half + 2.0 * half * j as f64 / NV as f64;
                Point3::new(x, y, 0.0)
            });
            (nu, false)
        }
    };
    let pts = local.iter().map(|p| a.pose.transform_point(p)).collect();
    (pts, nu, NV, wrap_u)
}
