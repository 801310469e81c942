//! The exact Hertz solution for elliptical (and, as a special case, circular) point
//! contact, with complete elliptic integrals.
//!
//! # Formulas
//! With $k' = b/a \le 1$, $y = k'^2$ and Carlson's $R_F = R_F(0,y,1) = K(e)$,
//! $R_D = R_D(0,y,1)$, Johnson's (1982) eqs (56a-c), (57) become
//!
//! ```text
//! B/A = (3 R_F - R_D) / (y R_D),   a³ = F R_D / (2π E* A),   b = k' a,
//! p₀ = 3F / (2π a b),   δ = 3 F R_F / (2π a E*).
//! ```
//!
//! The shape $k'$ depends only on the geometry, so [`HertzPointContact::new`] solves it once
//! and every later call is a cube root: plan once, solve many. The derivation is written
//! out in `docs/hertz.md`.
//!
//! # Assumptions
//! Linear elastic, isotropic, homogeneous half-spaces (contact size ≪ radii), frictionless,
//! quadratic gap (Johnson 1982 §1). Dissimilar materials are treated through $E^*$ only;
//! the Dundurs coupling (beta ≠ 0) is neglected, as in Hertz' theory.
//!
//! # References
//! - Hertz (1882), J. reine angew. Math. 92, 156-171.
//! - Johnson (1982), "One hundred years of Hertz contact", Proc. IMechE 196, 363-378,
//!   Appendix 1, eqs (50)-(61). doi:10.1243/PIME_PROC_1982_196_039_02
//! - Johnson, *Contact Mechanics* (1985), §3.5, eqs (3.63)-(3.72).
//! - Carlson (1995), Numer. Algorithms 10, 13-26; DLMF §19.25.

use super::elliptic;
use crate::error::{Error, Result};
use crate::field::{ContactZone, NormalSolution};
use crate::geometry::{Grid2, RelativeCurvature};
use crate::material::{ElasticMaterial, effective_modulus};
use crate::solve::{SolveStatus, Termination};
use crate::units::{Megapascal, Millimetre, Newton, Radian};
use std::f64::consts::PI;

/// The Hertz shape function: the curvature ratio $B/A = R'/R''$ that produces a contact
/// ellipse of axis ratio `axis_ratio` $= b/a \in (0, 1]$ (Johnson 1982 eq. 57, in the
/// cancellation-free Carlson form of `docs/hertz.md`). [`HertzPointContact::new`] inverts it.
///
/// # Errors
/// `axis_ratio` outside (0, 1].
pub fn curvature_ratio(axis_ratio: f64) -> Result<f64> {
    if !(axis_ratio > 0.0 && axis_ratio <= 1.0) {
        return Err(Error::invalid("axis_ratio", axis_ratio, "0 < b/a <= 1"));
    }
    elliptic::shape_ratio(axis_ratio * axis_ratio)
}

/// The undeformed geometry of a point contact: both bodies' principal radii and the angle
/// between their principal planes (see the crate *Conventions*).
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct PointGeometry {
    body1_radii: [Millimetre; 2],
    body2_radii: [Millimetre; 2],
    angle: Radian,
    curvature: RelativeCurvature,
}

impl PointGeometry {
    /// Two bodies by their principal radii of curvature \[mm\] (convex > 0, concave < 0,
    /// `f64::INFINITY` for flat) and the angle `angle` \[rad\] from body 1's first principal
    /// direction to body 2's.
    ///
    /// # Errors
    /// See [`RelativeCurvature::from_radii`]: zero/NaN radii, a non-finite angle, and
    /// geometries that are conformal, separate or line contacts.
    pub fn new(
        body1_radii: [Millimetre; 2],
        body2_radii: [Millimetre; 2],
        angle: Radian,
    ) -> Result<Self> {
        let curvature = RelativeCurvature::from_radii(body1_radii, body2_radii, angle)?;
        Ok(PointGeometry {
            body1_radii,
            body2_radii,
            angle,
            curvature,
        })
    }

    /// A sphere of radius `radius` \[mm\] (> 0) on a flat.
    ///
    /// # Errors
    /// A non-positive or non-finite radius.
    pub fn sphere_on_flat(radius: Millimetre) -> Result<Self> {
        crate::error::positive("radius", radius)?;
        Self::new([radius; 2], [f64::INFINITY; 2], 0.0)
    }

    /// A geometry given directly by its relative curvature (for example the local
    /// curvature of a substitute geometry). The body radii are then reported as
    /// body 1 = (1/(2A), 1/(2B)) rotated by the orientation, body 2 flat.
    pub fn from_curvature(curvature: RelativeCurvature) -> Self {
        PointGeometry {
            body1_radii: [0.5 / curvature.a_coef, 0.5 / curvature.b_coef],
            body2_radii: [f64::INFINITY; 2],
            angle: 0.0,
            curvature,
        }
    }

    /// Principal radii of body 1 \[mm\].
    pub fn body1_radii(&self) -> [Millimetre; 2] {
        self.body1_radii
    }
    /// Principal radii of body 2 \[mm\].
    pub fn body2_radii(&self) -> [Millimetre; 2] {
        self.body2_radii
    }
    /// Angle between the principal planes \[rad\].
    pub fn angle(&self) -> Radian {
        self.angle
    }
    /// The relative curvature A <= B and its orientation.
    pub fn curvature(&self) -> RelativeCurvature {
        self.curvature
    }
}

/// A planned Hertz point contact: geometry, materials and the solved ellipse shape.
///
/// Constructing it inverts the shape equation once (about 0.3 µs); afterwards
/// [`solve_force`](Self::solve_force) and [`solve_approach`](Self::solve_approach) cost a
/// cube root each, which is what a multi-body simulation needs.
///
/// # Example
/// A ball (R = 6 mm) in a groove of conformity 0.52 (groove radius -6.24 mm) of a ring
/// whose raceway radius is 20 mm, 1000 N, steel:
/// ```
/// use kontakt::{hertz::{HertzPointContact, PointGeometry}, material::ElasticMaterial};
/// let g = PointGeometry::new([6.0, 6.0], [20.0, -6.24], 0.0)?;
/// let c = HertzPointContact::new(g, ElasticMaterial::STEEL, ElasticMaterial::STEEL)?;
/// let s = c.solve_force(1000.0)?;
/// assert!(s.semi_axes[0] > 3.0 * s.semi_axes[1]);   // long ellipse across the groove
/// let f = c.force_from_approach(s.approach)?;        // inverse pair round-trips
/// assert!((f - 1000.0).abs() < 1e-9);
/// # Ok::<(), kontakt::Error>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct HertzPointContact {
    geometry: PointGeometry,
    materials: [ElasticMaterial; 2],
    e_star: Megapascal,
    /// b/a.
    axis_ratio: f64,
    /// Semi-major axis at F = 1 N \[mm\].
    a_unit: Millimetre,
    /// Approach at F = 1 N \[mm\].
    delta_unit: Millimetre,
    /// Evaluations the shape inversion took.
    shape_evaluations: usize,
    /// $d(B/A)/dy$ at the root, $y = (b/a)^2$ (for the next warm inversion's predictor;
    /// within 1e-8 relative of it after a warm inversion, which takes it at its predicted
    /// point; NaN for a circle).
    #[cfg_attr(feature = "serde", serde(skip))]
    shape_slope: f64,
    /// $R_F$, $R_D$ about the last exact evaluation, for the next warm inversion.
    #[cfg_attr(feature = "serde", serde(skip))]
    series: Option<elliptic::ShapeSeries>,
}

/// `∛v` from a nearby cube root `x0`: with `ε = v/x0³ − 1`, `|ε| ≤ 1e-4`, the binomial
/// series $x_0(1 + ε/3 − ε^2/9 + 5ε^3/81)$, whose next term ($10ε^4/243 < 5\cdot10^{-18}$)
/// lies below the rounding (a contact element's next call: one division instead of a cube
/// root); `f64::cbrt` otherwise. Within a few ulps of `f64::cbrt` (tested).
fn cbrt_near(v: f64, x0: f64) -> f64 {
    let e = v / (x0 * x0 * x0) - 1.0;
    if e.abs() <= 1e-4 {
        x0 * (1.0 + e * (1.0 / 3.0 - e * (1.0 / 9.0 - e * (5.0 / 81.0))))
    } else {
        v.cbrt()
    }
}

/// The state of a Hertz point contact at one load.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct HertzPointSolution {
    /// Semi-axes [a, b] of the contact ellipse \[mm\], a >= b.
    pub semi_axes: [Millimetre; 2],
    /// Angle from body 1's first principal direction to the major semi-axis a \[rad\].
    pub orientation: Radian,
    /// Normal force F \[N\].
    pub force: Newton,
    /// Approach delta of distant points \[mm\].
    pub approach: Millimetre,
    /// Maximum (central) pressure p0 = 3F / (2 pi a b) \[MPa\].
    pub max_pressure: Megapascal,
    /// Mean pressure F / (pi a b) = 2 p0 / 3 \[MPa\].
    pub mean_pressure: Megapascal,
    /// Contact area pi a b \[mm²\].
    pub contact_area: f64,
    /// Contact stiffness dF/d(delta) = 3F / (2 delta) [N/mm].
    pub stiffness: f64,
}

impl HertzPointContact {
    /// Plan a contact: validate, compute E* and solve the ellipse shape (eq. 57).
    ///
    /// # Errors
    /// Only the shape inversion can fail (never observed for B/A in its valid range);
    /// the geometry and materials are validated by their own constructors.
    pub fn new(
        geometry: PointGeometry,
        body1: ElasticMaterial,
        body2: ElasticMaterial,
    ) -> Result<Self> {
        Self::new_near(geometry, body1, body2, None)
    }

    /// [`HertzPointContact::new`] with the shape inversion warm-started from `previous`, a
    /// contact of nearby curvature (for example the last call of a contact element along a
    /// trajectory): one evaluation of the elliptic integrals when the ratio B/A moved by
    /// less than about 1e-4 (a Newton step on the exact slope kept from `previous`, for
    /// b/a below 0.9995), else the safeguarded secant from `previous` (3 evaluations on
    /// average for changes up to 1 %, against 4.3 cold); the same ellipse to a few ulps
    /// (tested).
    ///
    /// # Errors
    /// As [`HertzPointContact::new`].
    pub fn new_near(
        geometry: PointGeometry,
        body1: ElasticMaterial,
        body2: ElasticMaterial,
        previous: Option<&HertzPointContact>,
    ) -> Result<Self> {
        let k = geometry.curvature;
        let e_star = effective_modulus(&body1, &body2);
        let ratio = k.ratio();
        // One evaluation when the last root is near (Newton on the exact slope), else the
        // safeguarded secant.
        let newton = previous.and_then(|h| {
            let y = h.axis_ratio * h.axis_ratio;
            elliptic::invert_shape_ratio_newton(
                ratio,
                (h.geometry.curvature.ratio(), y, h.shape_slope),
                h.series.as_ref(),
            )
        });
        let inversion = match newton {
            Some(i) => i,
            None => {
                let start = previous.map(|h| (h.geometry.curvature.ratio(), h.axis_ratio));
                elliptic::invert_shape_ratio_near(ratio, start)?
            }
        };
        let (axis_ratio, shape_evaluations) = (inversion.axis_ratio, inversion.evaluations);
        let (rf, rd) = inversion.rf_rd;
        let shape_slope = inversion
            .slope
            .unwrap_or_else(|| elliptic::shape_slope(axis_ratio * axis_ratio, rf, rd));
        // The next warm inversion's series: kept, or about this root.
        let series = inversion
            .series
            .or_else(|| elliptic::ShapeSeries::new(axis_ratio * axis_ratio, rf, rd));
        let cube = rd / (2.0 * PI * e_star * k.a_coef);
        let a_unit = match previous {
            Some(h) => cbrt_near(cube, h.a_unit),
            None => cube.cbrt(),
        };
        let delta_unit = 3.0 * rf / (2.0 * PI * a_unit * e_star);
        Ok(HertzPointContact {
            geometry,
            materials: [body1, body2],
            e_star,
            axis_ratio,
            a_unit,
            delta_unit,
            shape_evaluations,
            shape_slope,
            series,
        })
    }

    /// The geometry this contact was planned for.
    pub fn geometry(&self) -> &PointGeometry {
        &self.geometry
    }
    /// The two materials.
    pub fn materials(&self) -> [ElasticMaterial; 2] {
        self.materials
    }
    /// Contact modulus E* \[MPa\].
    pub fn e_star(&self) -> Megapascal {
        self.e_star
    }
    /// Axis ratio b/a of the contact ellipse (load independent).
    pub fn axis_ratio(&self) -> f64 {
        self.axis_ratio
    }
    /// Eccentricity e = sqrt(1 - (b/a)²).
    pub fn eccentricity(&self) -> f64 {
        ((1.0 - self.axis_ratio) * (1.0 + self.axis_ratio)).sqrt()
    }
    /// Number of shape-function evaluations the eccentricity inversion used.
    pub fn shape_evaluations(&self) -> usize {
        self.shape_evaluations
    }
    /// Load coefficient k of the force law F = k delta^(3/2) [N/mm^1.5].
    pub fn load_coefficient(&self) -> f64 {
        self.delta_unit.powf(-1.5)
    }

    /// Approach \[mm\] for a normal force `force` \[N\] (> 0, finite).
    ///
    /// # Errors
    /// Non-positive or non-finite force.
    pub fn approach_from_force(&self, force: Newton) -> Result<Millimetre> {
        crate::error::positive("force", force)?;
        Ok(self.delta_unit * force.cbrt().powi(2))
    }

    /// Normal force \[N\] for an approach `approach` \[mm\] (> 0, finite):
    /// $F = (\delta/\delta_1)^{3/2}$ with $\delta_1$ the approach at 1 N.
    ///
    /// # Errors
    /// Non-positive or non-finite approach.
    pub fn force_from_approach(&self, approach: Millimetre) -> Result<Newton> {
        crate::error::positive("approach", approach)?;
        let r = approach / self.delta_unit;
        Ok(r * r.sqrt())
    }

    /// Full solution for a normal force `force` \[N\] (> 0, finite).
    ///
    /// # Errors
    /// Non-positive or non-finite force; a result that over- or underflows f64 (for
    /// example radii of 1e-300 mm), named by the input `force`.
    pub fn solve_force(&self, force: Newton) -> Result<HertzPointSolution> {
        crate::error::positive("force", force)?;
        self.solution(force).representable("force", force)
    }

    /// Full solution for an approach `approach` \[mm\] (> 0, finite).
    ///
    /// # Errors
    /// Non-positive or non-finite approach; a result that over- or underflows f64.
    pub fn solve_approach(&self, approach: Millimetre) -> Result<HertzPointSolution> {
        crate::error::positive("approach", approach)?;
        // F^(1/3) = (δ/δ₁)^(1/2): the square root of the force law's ratio, no cube root.
        let r = approach / self.delta_unit;
        let c = r.sqrt();
        let mut s = self.solution_at(r * c, c);
        s.approach = approach;
        s.representable("approach", approach)
    }

    /// Maximum pressure at a force of 1 N \[MPa\]; p0 scales as F^(1/3).
    pub fn max_pressure_at_unit_force(&self) -> Megapascal {
        self.solution(1.0).max_pressure
    }

    fn solution(&self, force: Newton) -> HertzPointSolution {
        self.solution_at(force, force.cbrt())
    }

    /// The solution at `force` whose cube root is `c`.
    fn solution_at(&self, force: Newton, c: f64) -> HertzPointSolution {
        let a = self.a_unit * c;
        let b = self.axis_ratio * a;
        let area = PI * a * b;
        let mean_pressure = force / area;
        let approach = self.delta_unit * c * c;
        HertzPointSolution {
            semi_axes: [a, b],
            orientation: self.geometry.curvature.orientation,
            force,
            approach,
            max_pressure: 1.5 * mean_pressure,
            mean_pressure,
            contact_area: area,
            stiffness: 1.5 * force / approach,
        }
    }
}

impl HertzPointSolution {
    /// `Ok(self)` when every quantity is finite and positive; otherwise an error naming the
    /// input `field` = `value` that led to a result beyond f64 (an overflow to inf, or an
    /// underflow to 0 and then NaN).
    fn representable(self, field: &'static str, value: f64) -> Result<Self> {
        let quantities = [
            ("semi-axis a", self.semi_axes[0]),
            ("semi-axis b", self.semi_axes[1]),
            ("force", self.force),
            ("approach", self.approach),
            ("maximum pressure", self.max_pressure),
            ("contact area", self.contact_area),
            ("stiffness", self.stiffness),
        ];
        match quantities
            .into_iter()
            .find(|(_, q)| !(q.is_finite() && *q > 0.0))
        {
            None => Ok(self),
            Some((name, q)) => Err(Error::invalid(
                field,
                value,
                format!(
                    "a load whose contact is representable in double precision (its {name} \
                     would be {q}; scale the inputs towards engineering values)"
                ),
            )),
        }
    }

    /// Hertz pressure \[MPa\] at the point (x, y) \[mm\] of the contact frame (x along body 1's
    /// first principal direction):
    /// $p = p_0\sqrt{1 - (x'/a)^2 - (y'/b)^2}$ inside the ellipse, 0 outside
    /// (Johnson 1982 eq. 54).
    pub fn pressure_at(&self, x: Millimetre, y: Millimetre) -> Megapascal {
        let (s, c) = self.orientation.sin_cos();
        let xp = c * x + s * y;
        let yp = -s * x + c * y;
        let [a, b] = self.semi_axes;
        let r2 = (xp / a).powi(2) + (yp / b).powi(2);
        if r2 < 1.0 {
            self.max_pressure * (1.0 - r2).sqrt()
        } else {
            0.0
        }
    }

    /// Pressure \[MPa\] sampled at every point of `grid`, row-major with x fastest: the
    /// values of [`pressure_at`](Self::pressure_at), bit for bit, with its rotation computed
    /// once (one `sin_cos` per grid, not per cell).
    pub fn sample_pressure(&self, grid: &Grid2) -> Vec<Megapascal> {
        let mut out = vec![0.0; grid.len()];
        self.fill_pressure(grid, &mut out);
        out
    }

    /// The Hertz pressure sampled on `grid` \[mm\] (the contact frame: x along body 1's
    /// first principal direction), as the field solvers report theirs: the one result
    /// type [`NormalSolution`] of PimP and the half-space solver, so Hertz sits beside them
    /// in every comparison, report and integral over the contact (friction power).
    ///
    /// The force and approach are the closed-form values; the maximum pressure, area,
    /// extents and zone shape are read off the sampled cells, as for the field solvers
    /// (the area counts whole cells: first order in the cell size). `detail` is the
    /// closed-form solution; the status is converged with no iteration.
    ///
    /// # Errors
    /// [`Error::Geometry`] (field `grid`) when no cell centre lies inside the ellipse.
    pub fn on_grid(&self, grid: Grid2) -> Result<NormalSolution<HertzPointSolution>> {
        let pressure = self.sample_pressure(&grid);
        let zone = ContactZone::analyse(&grid, &pressure)?;
        if zone.patches == 0 {
            return Err(Error::Geometry {
                field: "grid".into(),
                reason: format!(
                    "no cell centre of the grid lies inside the contact ellipse (semi-axes \
                     {:.4e} x {:.4e} mm): use finer cells or a grid over the contact",
                    self.semi_axes[0], self.semi_axes[1]
                ),
            });
        }
        Ok(NormalSolution {
            force: self.force,
            approach: self.approach,
            max_pressure: zone.max_pressure,
            mean_pressure: self.force / zone.area,
            contact_area: zone.area,
            semi_axes: zone.half_extents(),
            orientation: 0.0,
            zone,
            status: SolveStatus::new(Termination::Converged, 0, 0.0),
            domains: 1,
            grid,
            pressure,
            detail: *self,
        })
    }

    /// The Hertz pressure on a grid of `nx × ny` cells in the ellipse's own principal frame
    /// (`x` along the major semi-axis `a`), covering it with a margin of `margin` (e.g. 0.05
    /// for 5 %) on each side; the solution's `orientation` is the ellipse's, so its grid
    /// lies as PimP's and the half-space solver's grids lie for the same gap (their `x`
    /// along the direction of least relative curvature), and a map or a friction integral
    /// treats all three alike. [`on_grid`](Self::on_grid) instead samples the turned
    /// ellipse on a grid of the contact frame (orientation 0).
    ///
    /// # Errors
    /// Those of [`Grid2::centered`] and [`on_grid`](Self::on_grid).
    pub fn on_principal_grid(
        &self,
        nx: usize,
        ny: usize,
        margin: f64,
    ) -> Result<NormalSolution<HertzPointSolution>> {
        let unturned = HertzPointSolution {
            orientation: 0.0,
            ..*self
        };
        let mut solution = unturned.on_grid(unturned.covering_grid(nx, ny, margin)?)?;
        solution.orientation = self.orientation;
        solution.detail = *self;
        Ok(solution)
    }

    /// A grid of `nx × ny` cells in the contact frame that covers the ellipse (turned by
    /// its orientation) with a margin of `margin` (e.g. 0.05 for 5 %) on each side: the
    /// half-extents of its bounding box, `√(a² cos²θ + b² sin²θ)` and
    /// `√(a² sin²θ + b² cos²θ)`, times `1 + margin`.
    ///
    /// # Errors
    /// Those of [`Grid2::centered`] (cell counts, a non-finite or negative margin).
    pub fn covering_grid(&self, nx: usize, ny: usize, margin: f64) -> Result<Grid2> {
        let [a, b] = self.semi_axes;
        let (s, c) = self.orientation.sin_cos();
        let k = 1.0 + margin;
        Grid2::centered(
            (a * a * c * c + b * b * s * s).sqrt() * k,
            (a * a * s * s + b * b * c * c).sqrt() * k,
            nx,
            ny,
        )
    }

    /// Pressure sampled into a caller-provided buffer (no allocation).
    ///
    /// # Errors
    /// `out.len()` differs from `grid.len()`.
    pub fn sample_pressure_into(&self, grid: &Grid2, out: &mut [Megapascal]) -> Result<()> {
        if out.len() != grid.len() {
            return Err(Error::invalid(
                "out.len()",
                out.len(),
                format!("{} (the grid size)", grid.len()),
            ));
        }
        self.fill_pressure(grid, out);
        Ok(())
    }

    /// [`sample_pressure_into`](Self::sample_pressure_into) on a buffer of the grid's size.
    fn fill_pressure(&self, grid: &Grid2, out: &mut [Megapascal]) {
        // `pressure_at` with the rotation hoisted out of the loop and the rows outside the
        // ellipse's bounding box skipped (the same arithmetic per cell, so the same bits).
        let (s, c) = self.orientation.sin_cos();
        let [a, b] = self.semi_axes;
        // Half-height of the rotated ellipse's bounding box.
        let reach = (a * s).hypot(b * c);
        let nx = grid.nx();
        for (j, row) in out.chunks_exact_mut(nx).enumerate() {
            let y = grid.y(j);
            if y.abs() > reach * (1.0 + 1e-12) {
                row.fill(0.0);
                continue;
            }
            if s == 0.0 && c == 1.0 {
                // Unturned (the principal grid): `xp = x + 0·y` and `yp = −0·x + y` are
                // `±x` and `±y`, so the row's `(yp/b)²` is one number (computed once).
                let ry = (y / b).powi(2);
                for (i, o) in row.iter_mut().enumerate() {
                    let r2 = (grid.x(i) / a).powi(2) + ry;
                    *o = if r2 < 1.0 {
                        self.max_pressure * (1.0 - r2).sqrt()
                    } else {
                        0.0
                    };
                }
                continue;
            }
            for (i, o) in row.iter_mut().enumerate() {
                let x = grid.x(i);
                let xp = c * x + s * y;
                let yp = -s * x + c * y;
                let r2 = (xp / a).powi(2) + (yp / b).powi(2);
                *o = if r2 < 1.0 {
                    self.max_pressure * (1.0 - r2).sqrt()
                } else {
                    0.0
                };
            }
        }
    }
}

#[cfg(test)]
mod tests {
    #![allow(clippy::unwrap_used)]
    use super::*;
    use crate::geometry::RelativeCurvature;
    use crate::material::ElasticMaterial;

    /// A uniform number in [0, 1) from a 64-bit LCG (Knuth's MMIX constants).
    fn uniform(state: &mut u64) -> f64 {
        *state = state
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        (*state >> 11) as f64 / (1u64 << 53) as f64
    }

    /// The sampled field is `pressure_at` at every cell centre, bit for bit (the rotation
    /// computed once per grid), for a turned ellipse on a grid wider than it (rows skipped
    /// outside its bounding box) and on one cutting it.
    #[test]
    fn sampled_pressure_is_pressure_at_every_cell() {
        let steel = ElasticMaterial::STEEL;
        let g = PointGeometry::from_curvature(
            RelativeCurvature::from_tensor(0.004, 0.05, 0.003).unwrap(),
        );
        let h = HertzPointContact::new(g, steel, steel)
            .unwrap()
            .solve_force(250.0)
            .unwrap();
        assert!(h.orientation != 0.0);
        let [a, _] = h.semi_axes;
        // Turned, and unturned as `on_principal_grid` samples it (the row's `(y/b)²` once).
        let unturned = HertzPointSolution {
            orientation: 0.0,
            ..h
        };
        for h in [h, unturned] {
            for half in [1.6 * a, 0.5 * a] {
                for (nx, ny) in [(37, 29), (64, 64)] {
                    let grid = Grid2::centered(half, 0.9 * half, nx, ny).unwrap();
                    let sampled = h.sample_pressure(&grid);
                    let mut inside = 0;
                    for ((x, y), p) in grid.points().zip(&sampled) {
                        assert_eq!(p.to_bits(), h.pressure_at(x, y).to_bits(), "({x}, {y})");
                        inside += usize::from(*p > 0.0);
                    }
                    assert!(inside > 0 && inside < grid.len(), "{inside}");
                }
            }
        }
    }

    /// The series cube root agrees with `f64::cbrt` to 2 ulps inside its range
    /// (|ε| ≤ 1e-4) and falls back to it outside, over roots from 1e-6 to 1e6.
    #[test]
    fn cbrt_near_is_the_cube_root_to_rounding() {
        let mut state = 7;
        for _ in 0..20_000 {
            let x0 = 10f64.powf(12.0 * uniform(&mut state) - 6.0);
            // ε from -3e-4 to 3e-4: a third of the draws fall back.
            let e = 6e-4 * (uniform(&mut state) - 0.5);
            let v = x0 * x0 * x0 * (1.0 + e);
            let (got, want) = (cbrt_near(v, x0), v.cbrt());
            assert!(
                (got - want).abs() <= 2.0 * f64::EPSILON * want,
                "x0 {x0:e} e {e:e}: {got:e} vs {want:e}"
            );
        }
        assert!(cbrt_near(8.0, f64::NAN) == 2.0 && cbrt_near(8.0, 0.0) == 2.0);
    }

    /// Planned near the last contact (the element's warm path: one evaluation of the
    /// elliptic integrals and the series cube root) the contact is the cold one to a few
    /// ulps: along a random drift of the curvature over 400 steps, axis ratio, semi-axes and
    /// approach at 250 N within 1e-14 relative.
    #[test]
    fn a_warm_plan_is_the_cold_plan() {
        let steel = ElasticMaterial::STEEL;
        let mut state = 11;
        let (mut a, mut b) = (0.004, 0.05);
        let mut last: Option<HertzPointContact> = None;
        let mut newton = 0;
        for i in 0..400 {
            // Mostly small steps (the Newton inversion and the series cube root), every 10th
            // a larger one (the secant and `cbrt`), every 50th a jump.
            let size = match i % 50 {
                49 => 0.2,
                k if k % 10 == 9 => 1e-3,
                _ => 2e-5,
            };
            a *= 1.0 + size * (uniform(&mut state) - 0.5);
            b *= 1.0 + size * (uniform(&mut state) - 0.5);
            let g =
                PointGeometry::from_curvature(RelativeCurvature::from_tensor(a, b, 0.0).unwrap());
            let warm = HertzPointContact::new_near(g, steel, steel, last.as_ref()).unwrap();
            let cold = HertzPointContact::new(g, steel, steel).unwrap();
            let (w, c) = (
                warm.solve_force(250.0).unwrap(),
                cold.solve_force(250.0).unwrap(),
            );
            let close = |x: f64, y: f64| (x - y).abs() <= 1e-14 * y.abs();
            assert!(
                close(warm.axis_ratio, cold.axis_ratio)
                    && close(w.semi_axes[0], c.semi_axes[0])
                    && close(w.semi_axes[1], c.semi_axes[1])
                    && close(w.approach, c.approach),
                "step {i}: {w:?} vs {c:?}"
            );
            newton += usize::from(warm.shape_evaluations() == 1);
            last = Some(warm);
        }
        assert!(
            newton >= 300,
            "{newton} of 400 plans took the one-evaluation path"
        );
    }
}
