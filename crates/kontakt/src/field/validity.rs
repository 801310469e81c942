//! The field solvers' size limit: the contact zone must be small against the bodies and
//! lie on their faces.
//!
//! PimP and the half-space solver both treat each body as an elastic half-space whose
//! surface is the contact plane: the pressure acts along the common normal, and the
//! displacement is that of a flat, unbounded body (Johnson 1985, §4.1: the contact must be
//! small against the radii of curvature and the dimensions of each body). Two things break
//! that assumption as the zone grows:
//!
//! - **The body's curvature.** At a distance `s` from the contact point a surface of
//!   radius `R` is inclined by `asin(s/R)` to the contact plane, and its height departs
//!   from the quadratic gap by the fraction `e(s/R)` of [`crate::hertz::validity`]
//!   (4.2 % at `s/R` = 0.4). PimP and the half-space solver sample the *true* gap of two
//!   placed surfaces, so the gap itself is right; but pressure along the common normal and
//!   the half-space's flat surface are not: at `s/R` = 0.4 the surface is inclined by
//!   23.6° at the zone's edge, and the normal component of a pressure along the local
//!   normal is 8 % smaller than the model's. At `s/R` = 1 the profile turns vertical: the
//!   zone would be as wide as the body's radius of curvature. The limits are those of
//!   Hertz theory ([`WARN_SIZE_RATIO`] 0.4 warns, [`MAX_SIZE_RATIO`] 1 is refused), so
//!   that one case gets the same verdict whichever method solves it.
//! - **The face's edge.** A roller's end face ends at the roller's large end, a crowned
//!   roller at its ends ([`crate::gap::FaceEdge`]). A half-space has no edge: near a free
//!   edge the body is softer and the pressure rises (a quarter-space, Hetényi 1970). The
//!   ratio is the zone's reach towards the edge over the contact point's distance from it;
//!   above [`WARN_EDGE_RATIO`] (0.5: the land left between the zone and the edge is less
//!   than the zone's own reach) the result warns, at [`MAX_EDGE_RATIO`] (1: the zone runs
//!   over the edge, the contact is larger than the face) it is refused.
//!
//! [`zone_size_check`] evaluates both on a solution, with the bodies of its gap source
//! ([`crate::gap::GapSource::bodies`]); a source that does not know its bodies (a gap map,
//! an [`crate::gap::FnGap`]) is not checked. The zone's extent in a direction is the radius
//! of the ellipse through the zone's furthest reach along the grid's axes (its bounding
//! box about the contact point); towards an edge, the bounding box's support. Both are at
//! least the zone's true extent, so the check errs on the safe side. Units: mm.

use crate::error::{Error, Result};
use crate::field::NormalSolution;
use crate::gap::{BodyAtContact, FaceEdge, GapSource};
use crate::units::Millimetre;

/// Zone extent / radius of curvature above which a result carries a warning: the surface
/// is inclined by more than 23.6° to the contact plane at the zone's edge. The same value
/// as Hertz theory's `hertz::validity::WARN_SIZE_RATIO`.
pub const WARN_SIZE_RATIO: f64 = 0.4;

/// Zone extent / radius of curvature at which a result is refused: the body's profile
/// turns vertical at the zone's edge. The same value as `hertz::validity::MAX_SIZE_RATIO`.
pub const MAX_SIZE_RATIO: f64 = 1.0;

/// Zone's reach towards a face edge / the contact point's distance from it, above which a
/// result carries a warning: the land between the zone and the edge is narrower than the
/// zone's reach.
pub const WARN_EDGE_RATIO: f64 = 0.5;

/// Zone's reach towards a face edge / the contact point's distance from it at which a
/// result is refused: the zone would run over the edge of the face.
pub const MAX_EDGE_RATIO: f64 = 1.0;

/// Directions sampled over the half-turn; the grid's axes and the bodies' principal
/// directions are evaluated exactly in addition.
const DIRECTIONS: usize = 180;

/// The largest ratio of the zone's extent to a body's radius of curvature.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CurvatureRatio {
    /// `extent / |radius|` \[-\]; 0 when both bodies are flat.
    pub ratio: f64,
    /// The body: 1 or 2.
    pub body: u8,
    /// The zone's extent from the contact point in that direction \[mm\].
    pub extent: Millimetre,
    /// The body's radius of curvature in that direction (signed: concave < 0) \[mm\].
    pub radius: Millimetre,
}

impl CurvatureRatio {
    /// The warning a result should carry when the ratio exceeds [`WARN_SIZE_RATIO`]: one
    /// line naming the extent, the body's radius, the ratio and the surface's inclination.
    pub fn warning(&self) -> Option<String> {
        (self.ratio > WARN_SIZE_RATIO).then(|| {
            format!(
                "contact size: the contact zone reaches {} mm from the contact point, {:.2} of \
                 body {}'s radius of curvature {} mm in that direction; the half-space model \
                 assumes a zone small against the bodies (above {WARN_SIZE_RATIO} the surface is \
                 inclined by more than 24 degrees at the zone's edge, here {:.0})",
                significant(self.extent),
                self.ratio,
                self.body,
                significant(self.radius),
                self.ratio.min(1.0).asin().to_degrees()
            )
        })
    }

    /// `Ok(self)` below [`MAX_SIZE_RATIO`]; otherwise [`Error::Geometry`] with field
    /// `body1.radii` or `body2.radii` (a case layer renames it to its own key).
    ///
    /// # Errors
    /// As above.
    pub fn refuse_too_large(self) -> Result<Self> {
        if self.ratio < MAX_SIZE_RATIO {
            return Ok(self);
        }
        Err(Error::Geometry {
            field: format!("body{}.radii", self.body).into(),
            reason: format!(
                "the contact zone would reach {} mm from the contact point, {} times body {}'s \
                 radius of curvature {} mm in that direction: the half-space model needs a zone \
                 small against the bodies (ratio < {MAX_SIZE_RATIO}, < {WARN_SIZE_RATIO} for \
                 the surface to stay within 24 degrees of the contact plane); reduce the load, \
                 or check the radii (a near-conformal groove?)",
                significant(self.extent),
                significant(self.ratio),
                self.body,
                significant(self.radius)
            ),
        })
    }
}

/// The largest ratio of the zone's reach towards a face edge to the edge's distance.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct EdgeRatio {
    /// `reach / distance` \[-\].
    pub ratio: f64,
    /// The body: 1 or 2.
    pub body: u8,
    /// The zone's reach from the contact point towards the edge \[mm\].
    pub reach: Millimetre,
    /// The edge.
    pub edge: FaceEdge,
}

/// The outcome of [`zone_size_check`] on a result that is not refused.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct ZoneCheck {
    /// Against the bodies' curvature (`None`: the source does not know its bodies).
    pub curvature: Option<CurvatureRatio>,
    /// Against the nearest face edge (`None`: no body has an edge, or no bodies known).
    pub edge: Option<EdgeRatio>,
}

impl ZoneCheck {
    /// The warnings a result should carry: one line each for a curvature ratio above
    /// [`WARN_SIZE_RATIO`] and an edge ratio above [`WARN_EDGE_RATIO`].
    pub fn warnings(&self) -> Vec<String> {
        let mut w = Vec::new();
        w.extend(self.curvature.and_then(|c| c.warning()));
        if let Some(e) = self.edge.filter(|e| e.ratio > WARN_EDGE_RATIO) {
            w.push(format!(
                "face edge: the contact zone reaches {} mm towards {} of body {}, which is {} \
                 mm from the contact point ({:.2} of the way, set by {}); the half-space model \
                 assumes the face continues well beyond the zone (above {WARN_EDGE_RATIO} the \
                 land left is narrower than the zone's reach, and the pressure near the edge \
                 is underestimated)",
                significant(e.reach),
                e.edge.what,
                e.body,
                significant(e.edge.distance),
                e.ratio,
                e.edge.quantity
            ));
        }
        w
    }
}

/// `x` with four significant digits, in exponent notation outside 0.001-100 000.
fn significant(x: f64) -> String {
    let a = x.abs();
    if (1e-3..1e5).contains(&a) {
        let decimals = (3 - a.log10().floor() as i32).max(0) as usize;
        format!("{x:.decimals$}")
    } else {
        format!("{x:.3e}")
    }
}

/// Check a field solution against the bodies of the source it was solved on: the zone's
/// extent against each body's radius of curvature in every direction, and its reach
/// towards each face edge (module documentation; docs/pimp.md and docs/halfspace.md).
///
/// # Errors
/// [`Error::Geometry`] when the zone reaches [`MAX_SIZE_RATIO`] of a body's radius of
/// curvature (field `body1.radii` or `body2.radii`) or [`MAX_EDGE_RATIO`] of an edge's
/// distance (field: the edge's [`FaceEdge::quantity`]).
///
/// ```
/// use kontakt::field::validity::zone_size_check;
/// use kontakt::gap::QuadraticGap;
/// use kontakt::material::ElasticMaterial;
/// use kontakt::pimp::{Pimp, PimpOptions};
/// let steel = ElasticMaterial::new(210_000.0, 0.3)?;
/// let pimp = Pimp::new(steel, steel, PimpOptions { cells: [32, 32], ..Default::default() })?;
/// let inf = f64::INFINITY;
/// let ball = QuadraticGap::of_bodies([5.0, 5.0], [inf, inf], 0.0)?;
/// let check = zone_size_check(&ball, &pimp.solve_force(&ball, 1000.0)?)?;
/// assert!(check.warnings().is_empty());
/// assert!(check.curvature.unwrap().ratio < 0.4);
/// # Ok::<(), kontakt::Error>(())
/// ```
pub fn zone_size_check<D>(
    source: &dyn GapSource,
    solution: &NormalSolution<D>,
) -> Result<ZoneCheck> {
    check(
        source,
        solution.zone.extents,
        solution.orientation,
        [solution.grid.dx(), solution.grid.dy()],
    )
}

/// The same check on a predicted zone, the ellipse of semi-axes `semi_axes` \[mm\] (the
/// first at `orientation` \[rad\] from the source's `x` axis) centred on the contact
/// point: run before a solve on the Hertz ellipse of the local curvature, it refuses a
/// contact that would be far larger than the bodies (a groove conforming to within
/// micrometres) with the quantity named, where the solver would fail on its grid or take
/// long to find an answer that is refused anyway.
///
/// # Errors
/// As [`zone_size_check`].
pub fn ellipse_size_check(
    source: &dyn GapSource,
    semi_axes: [Millimetre; 2],
    orientation: f64,
) -> Result<ZoneCheck> {
    let [a, b] = semi_axes;
    check(source, [[-a, a], [-b, b]], orientation, [0.0, 0.0])
}

/// The check of a zone with the bounding box `extents` (grid frame, turned by `rotation`
/// from the source's `x`) on a grid of cells `cell` \[mm\].
fn check(
    source: &dyn GapSource,
    extents: [[f64; 2]; 2],
    rotation: f64,
    cell: [f64; 2],
) -> Result<ZoneCheck> {
    let Some(bodies) = source.bodies() else {
        return Ok(ZoneCheck::default());
    };
    let [[x0, x1], [y0, y1]] = extents;
    let half = [x0.abs().max(x1.abs()), y0.abs().max(y1.abs())];
    let curvature = curvature_ratio(&bodies, half, rotation);
    let curvature = curvature.refuse_too_large()?;
    let box_ = extents;
    let edge = bodies
        .iter()
        .enumerate()
        .flat_map(|(b, body)| body.edges.iter().flatten().map(move |e| (b, e)))
        .map(|(b, e)| {
            // The edge's direction in the grid frame; the zone's bounding box's support.
            let t = e.direction[1].atan2(e.direction[0]) - rotation;
            let (s, c) = t.sin_cos();
            let reach = (box_[0][0] * c).max(box_[0][1] * c) + (box_[1][0] * s).max(box_[1][1] * s);
            let reach = reach.max(0.0);
            // Where the face ends the gap does (a ray misses the surface): a zone on the
            // true gap stops there, so one that reaches the edge to within a cell is cut.
            let cut = reach + (cell[0] * c).abs() + (cell[1] * s).abs() >= e.distance;
            let ratio = if e.distance > 0.0 {
                reach / e.distance
            } else {
                f64::INFINITY
            };
            EdgeRatio {
                ratio: if cut {
                    ratio.max(MAX_EDGE_RATIO)
                } else {
                    ratio
                },
                body: b as u8 + 1,
                reach,
                edge: *e,
            }
        })
        .fold(None, |best: Option<EdgeRatio>, e| match best {
            Some(b) if !(e.ratio > b.ratio) => Some(b),
            _ => Some(e),
        });
    if let Some(e) = edge.filter(|e| !(e.ratio < MAX_EDGE_RATIO)) {
        return Err(Error::Geometry {
            field: e.edge.quantity.into(),
            reason: format!(
                "the contact zone reaches {} mm towards {} of body {}, which is {} mm from the \
                 contact point: the contact is larger than the face (it reaches the edge to \
                 within a grid cell, or beyond); reduce the load, or check the dimensions",
                significant(e.reach),
                e.edge.what,
                e.body,
                significant(e.edge.distance),
            ),
        });
    }
    Ok(ZoneCheck {
        curvature: Some(curvature),
        edge,
    })
}

/// The largest extent-to-radius ratio over every direction of the ellipse with half-axes
/// `half` along the grid's axes, the grid turned by `rotation` from the source's `x`.
fn curvature_ratio(bodies: &[BodyAtContact; 2], half: [f64; 2], rotation: f64) -> CurvatureRatio {
    let [a, b] = half;
    let mut best = CurvatureRatio {
        ratio: 0.0,
        body: 1,
        extent: a,
        radius: f64::INFINITY,
    };
    // Directions relative to the grid's x axis: the axes, each body's principal
    // directions, and a uniform sample.
    let mut special = vec![0.0, std::f64::consts::FRAC_PI_2];
    for body in bodies {
        special.extend(body.principal_directions().map(|d| d - rotation));
    }
    let sample = (0..DIRECTIONS).map(|k| k as f64 * std::f64::consts::PI / DIRECTIONS as f64);
    for phi in special.into_iter().chain(sample) {
        let (s, c) = phi.sin_cos();
        let extent = if a > 0.0 && b > 0.0 {
            1.0 / ((c / a).powi(2) + (s / b).powi(2)).sqrt()
        } else {
            0.0
        };
        for (n, body) in bodies.iter().enumerate() {
            let kappa = body.normal_curvature(rotation + phi);
            let ratio = extent * kappa.abs();
            // NaN (a singular point's infinite curvature times a zero extent) is refused.
            if ratio > best.ratio || ratio.is_nan() {
                best = CurvatureRatio {
                    ratio: if ratio.is_nan() { f64::INFINITY } else { ratio },
                    body: n as u8 + 1,
                    extent,
                    radius: 1.0 / kappa,
                };
            }
        }
    }
    best
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A circle of radius 1 against a ball of radius 2 and a flat: ratio 0.5 in every
    /// direction, body 1; a saddle of +-1 against a 1 x 0.5 ellipse: the larger ratio 1
    /// along x.
    #[test]
    fn curvature_ratio_over_directions() {
        let inf = f64::INFINITY;
        let ball = BodyAtContact::from_radii([2.0, 2.0], 0.0);
        let flat = BodyAtContact::from_radii([inf, inf], 0.0);
        let r = curvature_ratio(&[ball, flat], [1.0, 1.0], 0.3);
        assert!((r.ratio - 0.5).abs() < 1e-12, "{r:?}");
        assert_eq!(r.body, 1);
        let saddle = BodyAtContact::from_radii([1.0, -1.0], 0.0);
        let r = curvature_ratio(&[flat, saddle], [1.0, 0.5], 0.0);
        assert!((r.ratio - 1.0).abs() < 1e-12, "{r:?}");
        assert_eq!(r.body, 2);
        // Turned by 90°: the ellipse's long axis now lies along the saddle's y.
        let r = curvature_ratio(&[flat, saddle], [1.0, 0.5], std::f64::consts::FRAC_PI_2);
        assert!((r.ratio - 1.0).abs() < 1e-12 && r.radius < 0.0, "{r:?}");
    }
}
