//! The substitute geometry: the gap between the two undeformed bodies, measured along the
//! common normal from the contact plane.
//!
//! Sign convention (Wirsching et al. 2020, Step 2; Wirsching et al. 2019, "Generating local geometry"): the contact
//! plane touches both bodies at the contact point, its normal `z` points into body 1.
//! `g1(x, y)` is the height of body 1's surface above the plane along `+z` (>= 0 for a
//! convex body 1), `g2(x, y)` the height of body 2's surface (<= 0 for a convex body 2).
//! The substitute geometry is `g = g1 - g2 >= 0`, zero at the contact point, and a rigid
//! approach `delta` leaves the overlap `u = delta - g` where it is positive.
//!
//! A [`GapSource`] provides `g` in a frame whose `x, y` axes lie in the contact plane.
//! Sources: [`QuadraticGap`] (the Hertz gap, for validation), [`FnGap`] (any function,
//! for example a two-zone geometry) and [`SurfacePairGap`] (two placed analytic surfaces,
//! ray-cast). A [`GapMap`] is a gap (or height) map on its own grid, solved as it is by
//! the half-space solver.
//!
//! This module is shared vocabulary: every field solver (PimP, the half-space solver,
//! the ones to come) takes its geometry from here, and none of them owns it.

mod bodies;
mod map;
mod surface_pair;

pub use bodies::{BodyAtContact, FaceEdge};
pub use map::{GapMap, MapKind};
pub use surface_pair::SurfacePairGap;

use crate::error::{Error, Result, positive_as};
use crate::geometry::{Grid2, RelativeCurvature};
use crate::units::Millimetre;

/// A substitute geometry that can be sampled on a grid.
///
/// `Send + Sync`: a source is plain geometry, shared read-only between the threads of a
/// multi-body simulation or a sweep.
pub trait GapSource: Send + Sync {
    /// The gap's quadratic form at the contact point: `g ≈ A x'² + B y'²` with `A <= B`
    /// \[1/mm\] and `x'` at angle `orientation` \[rad\] from the source's `x` axis.
    fn curvature(&self) -> RelativeCurvature;

    /// The two bodies at the contact point (each one's curvature and the edges of its
    /// face), for the size check of a solution ([`crate::field::validity`]); `None` when
    /// the source knows only the gap (the default: an [`FnGap`], a [`QuadraticGap`] built
    /// from a relative curvature). [`SurfacePairGap`] and [`QuadraticGap::of_bodies`] know
    /// them.
    fn bodies(&self) -> Option<[BodyAtContact; 2]> {
        None
    }

    /// Sample the touching gap `g >= 0` \[mm\] at the cell centres of `grid` into `out`
    /// (`out.len() == grid.len()`). The grid lives in a frame turned by `rotation` \[rad\]
    /// about `z`: grid point `(x', y')` is the source point
    /// `(x' cos r - y' sin r, x' sin r + y' cos r)`. Points where the bodies cannot meet
    /// (a ray misses a surface) get `f64::INFINITY`.
    ///
    /// # Errors
    /// A source may fail on geometry it cannot evaluate; it never returns NaN.
    fn sample(&self, grid: &Grid2, rotation: f64, out: &mut [f64]) -> Result<()>;

    /// Sample the gap \[mm\] at the tensor points `(xs[k], ys[l])` \[mm\] of a frame turned
    /// by `rotation` \[rad\] (as in [`GapSource::sample`]) into `out[l * xs.len() + k]`
    /// (`out.len() == xs.len() * ys.len()`): a stencil on non-uniform nodes. `warm` (one
    /// entry per point, or empty) carries a source's warm-start data from one call to the
    /// next, `f64::INFINITY` for none; the caller only keeps it. The default samples each
    /// point as a grid of one cell and ignores `warm`; [`SurfacePairGap`] starts each ray
    /// from the last call's hit at the same point (kept in `warm` as heights over the plane
    /// \[mm\]) or else from the neighbour's.
    ///
    /// # Errors
    /// [`Error::InvalidInput`] (field `out.len()`) for a wrong length; the source's errors.
    fn sample_points(
        &self,
        xs: &[f64],
        ys: &[f64],
        rotation: f64,
        out: &mut [f64],
        warm: &mut [[f64; 2]],
    ) -> Result<()> {
        let _ = warm;
        if out.len() != xs.len() * ys.len() {
            return Err(Error::invalid(
                "out.len()",
                out.len(),
                "xs.len() * ys.len() points",
            ));
        }
        let scale = xs.iter().chain(ys).fold(0.0f64, |m, v| m.max(v.abs()));
        let e = 1e-9 * scale.max(1e-6);
        for (l, &y) in ys.iter().enumerate() {
            for (k, &x) in xs.iter().enumerate() {
                let point = Grid2::new([x - e, x + e], [y - e, y + e], 1, 1)?;
                let mut g = [0.0];
                self.sample(&point, rotation, &mut g)?;
                out[l * xs.len() + k] = g[0];
            }
        }
        Ok(())
    }
}

/// The Hertz gap `g = A x'² + B y'²` (Johnson 1982 eq. 1): the reference geometry of
/// every PimP validation.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct QuadraticGap {
    curvature: RelativeCurvature,
    bodies: Option<[BodyAtContact; 2]>,
}

impl QuadraticGap {
    /// The gap of a relative curvature (the bodies' own radii unknown: a solution on it is
    /// not size-checked against them).
    pub fn new(curvature: RelativeCurvature) -> Self {
        QuadraticGap {
            curvature,
            bodies: None,
        }
    }

    /// The gap of two bodies given by their principal radii \[mm\] (convex > 0, concave
    /// < 0, `inf` flat), body 2's first principal direction at `angle` \[rad\] from body
    /// 1's, as [`RelativeCurvature::from_radii`]; the source's `x` axis is body 1's first
    /// principal direction. The bodies are known to [`GapSource::bodies`].
    ///
    /// # Errors
    /// Those of [`RelativeCurvature::from_radii`].
    pub fn of_bodies(
        body1_radii: [Millimetre; 2],
        body2_radii: [Millimetre; 2],
        angle: f64,
    ) -> Result<Self> {
        let curvature = RelativeCurvature::from_radii(body1_radii, body2_radii, angle)?;
        Ok(QuadraticGap {
            curvature,
            bodies: Some([
                BodyAtContact::from_radii(body1_radii, 0.0),
                BodyAtContact::from_radii(body2_radii, angle),
            ]),
        })
    }
}

impl GapSource for QuadraticGap {
    fn curvature(&self) -> RelativeCurvature {
        self.curvature
    }

    fn bodies(&self) -> Option<[BodyAtContact; 2]> {
        self.bodies
    }

    fn sample(&self, grid: &Grid2, rotation: f64, out: &mut [f64]) -> Result<()> {
        check_len(grid, out)?;
        let k = self.curvature;
        // Angle from the A axis to the grid's x axis.
        let (s, c) = (rotation - k.orientation).sin_cos();
        for (o, (x, y)) in out.iter_mut().zip(grid.points()) {
            let xp = c * x - s * y;
            let yp = s * x + c * y;
            *o = k.a_coef * xp * xp + k.b_coef * yp * yp;
        }
        Ok(())
    }
}

/// A gap given by any function `g(x, y)` \[mm\] of the contact-plane coordinates \[mm\],
/// with `g(0, 0) = 0` at the contact point and `g >= 0` around it.
///
/// Its quadratic form at the origin is found by central differences with step `scale`.
pub struct FnGap<F> {
    f: F,
    curvature: RelativeCurvature,
}

impl<F: Fn(Millimetre, Millimetre) -> Millimetre> FnGap<F> {
    /// Wrap `f`; `scale` \[mm\] is the finite-difference step for the curvature at the
    /// origin (a small fraction of the expected contact size).
    ///
    /// # Errors
    /// - [`Error::InvalidInput`] for a non-positive `scale` or a non-finite `f(0, 0)`.
    /// - [`Error::Geometry`] when the gap is not positively curved at the origin (then
    ///   the origin is not a point of first contact).
    pub fn new(f: F, scale: Millimetre) -> Result<Self> {
        positive_as("scale", scale, "a finite step > 0 mm")?;
        let h = scale;
        let g0 = f(0.0, 0.0);
        if !g0.is_finite() {
            return Err(Error::invalid("gap(0, 0)", g0, "a finite gap in mm"));
        }
        let kxx = (f(h, 0.0) - 2.0 * g0 + f(-h, 0.0)) / (h * h);
        let kyy = (f(0.0, h) - 2.0 * g0 + f(0.0, -h)) / (h * h);
        let kxy = (f(h, h) - f(h, -h) - f(-h, h) + f(-h, -h)) / (4.0 * h * h);
        let curvature = RelativeCurvature::from_tensor(kxx, kyy, kxy)?;
        Ok(FnGap { f, curvature })
    }
}

impl<F: Fn(Millimetre, Millimetre) -> Millimetre + Send + Sync> GapSource for FnGap<F> {
    fn curvature(&self) -> RelativeCurvature {
        self.curvature
    }

    fn sample(&self, grid: &Grid2, rotation: f64, out: &mut [f64]) -> Result<()> {
        check_len(grid, out)?;
        let (s, c) = rotation.sin_cos();
        for (k, (o, (x, y))) in out.iter_mut().zip(grid.points()).enumerate() {
            let g = (self.f)(c * x - s * y, s * x + c * y);
            if g.is_nan() {
                return Err(Error::invalid(
                    format!("gap[{k}]"),
                    g,
                    "a gap in mm (inf where the bodies cannot meet)",
                ));
            }
            *o = g;
        }
        Ok(())
    }
}

pub(crate) fn check_len(grid: &Grid2, out: &[f64]) -> Result<()> {
    if out.len() != grid.len() {
        return Err(Error::invalid(
            "out.len()",
            out.len(),
            "the number of grid points nx * ny",
        ));
    }
    Ok(())
}
