//! Hertz theory's size limit: the contact must be small against the bodies.
//!
//! Hertz theory replaces each surface near the contact point by its quadratic
//! approximation `z = x² / (2R)` and each body by an elastic half-space (Johnson 1985,
//! §4.1: "the significant dimensions of the contact area must be small compared with the
//! dimensions of each body and with the relative radii of curvature of the surfaces"). For
//! a circular profile of radius `R` the true gap at a distance `s` from the contact point is
//! `R − √(R² − s²)`; the quadratic form is smaller by the fraction
//!
//! ```text
//! e(s/R) = 1 − (s/R)² / (2 (1 − √(1 − (s/R)²)))  ≈ (s/R)² / 4,
//! ```
//!
//! 0.25 % at `s/R` = 0.1, 4.2 % at 0.4 and 50 % at 1, where the profile turns vertical and
//! stops being a graph over the tangent plane. The same holds for a concave surface (a
//! groove, a cup), whose radius then bounds the contact as well.
//!
//! [`point_size_check`] and [`line_size_check`] take the largest ratio of the contact's
//! extent to a body's radius of curvature, in any direction of the contact ellipse: the
//! ellipse's radius in a direction times the body's normal curvature in that direction
//! (Euler's formula). Above [`WARN_SIZE_RATIO`] a result carries a warning
//! ([`SizeCheck::warning`]); at [`MAX_SIZE_RATIO`] or more it is refused, because the
//! contact would then be as wide as the body's radius of curvature: a ten-times overload of
//! a ball, or a groove that conforms to the ball to within micrometres.
//!
//! Units: mm; angles in radians from body 1's first principal direction.

use crate::error::{Error, Result};
use crate::hertz::line::LineSolution;
use crate::hertz::point::{HertzPointSolution, PointGeometry};
use crate::units::{Millimetre, Radian};

/// Contact extent / radius of curvature above which a result carries a warning: the
/// quadratic gap is then more than 4.2 % low at the contact's edge.
pub const WARN_SIZE_RATIO: f64 = 0.4;

/// Contact extent / radius of curvature at which a result is refused: the body's profile
/// turns vertical at the contact's edge (the quadratic gap is 50 % low there).
pub const MAX_SIZE_RATIO: f64 = 1.0;

/// Directions sampled over the half-turn of the ellipse (the ratio is π-periodic); the
/// principal axes of the ellipse and of both bodies are evaluated exactly in addition.
const DIRECTIONS: usize = 180;

/// The largest ratio of the contact's extent to a body's radius of curvature.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SizeCheck {
    /// The ratio `extent / |radius|` \[-\]; 0 when both bodies are flat.
    pub ratio: f64,
    /// The body it belongs to: 1 or 2 (1 when both bodies are flat).
    pub body: u8,
    /// The contact's extent in that direction (the ellipse's radius, or the line
    /// contact's half-width) \[mm\].
    pub extent: Millimetre,
    /// The body's radius of curvature in that direction (signed: concave < 0) \[mm\].
    pub radius: Millimetre,
    /// The direction, from body 1's first principal direction \[rad\] (0 for a line
    /// contact, whose extent is across the axis).
    pub direction: Radian,
}

impl SizeCheck {
    /// The warning a result should carry, when the ratio exceeds [`WARN_SIZE_RATIO`]:
    /// one line naming the extent, the body's radius, the ratio and the gap error.
    pub fn warning(&self) -> Option<String> {
        (self.ratio > WARN_SIZE_RATIO).then(|| {
            format!(
                "contact size: the contact reaches {} mm from its centre, {:.2} of body {}'s \
                 radius of curvature {} mm in that direction; Hertz theory assumes a \
                 contact small against the bodies (above {WARN_SIZE_RATIO} the quadratic gap \
                 is more than 4 % low at the contact's edge, here {:.1} %)",
                significant(self.extent),
                self.ratio,
                self.body,
                significant(self.radius),
                100.0 * quadratic_gap_error(self.ratio)
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
            field: if self.body == 1 {
                "body1.radii".into()
            } else {
                "body2.radii".into()
            },
            reason: format!(
                "the contact would reach {} mm from its centre, {} times body {}'s radius of \
                 curvature {} mm in that direction: Hertz theory needs a contact small against \
                 the bodies (ratio < {MAX_SIZE_RATIO}, < {WARN_SIZE_RATIO} for 4 % accuracy of \
                 the gap); reduce the load, or check the radii (a near-conformal groove?)",
                significant(self.extent),
                significant(self.ratio),
                self.body,
                significant(self.radius)
            ),
        })
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

/// The fraction by which the quadratic gap `s²/(2R)` falls short of a circular profile's
/// `R − √(R² − s²)` at `s = ratio · R`, for `0 ≤ ratio ≤ 1`. Written with the conjugate
/// (`1 − √(1 − q) = q / (1 + √(1 − q))`) so that it stays exact for small ratios.
pub fn quadratic_gap_error(ratio: f64) -> f64 {
    let q = (ratio * ratio).min(1.0);
    1.0 - (1.0 + (1.0 - q).sqrt()) / 2.0
}

/// Normal curvature \[1/mm\] of a surface with principal radii `radii` (flat: infinite) in
/// the direction at `theta` from its first principal direction (Euler's formula).
fn normal_curvature(radii: [Millimetre; 2], theta: Radian) -> f64 {
    let (s, c) = theta.sin_cos();
    c * c / radii[0] + s * s / radii[1]
}

/// The largest contact-extent-to-radius ratio of a Hertz point contact over every direction
/// of its ellipse and both bodies.
///
/// # Errors
/// [`Error::Geometry`] (field `body1.radii` or `body2.radii`) when the ratio reaches
/// [`MAX_SIZE_RATIO`].
///
/// ```
/// use kontakt::hertz::{HertzPointContact, PointGeometry};
/// use kontakt::hertz::validity::point_size_check;
/// use kontakt::material::ElasticMaterial;
/// let steel = ElasticMaterial::new(210_000.0, 0.3)?;
/// let g = PointGeometry::sphere_on_flat(5.0)?;
/// let c = HertzPointContact::new(g, steel, steel)?;
/// let sol = c.solve_force(1000.0)?;
/// let check = point_size_check(&g, &sol)?;
/// assert!((check.ratio - sol.semi_axes[0] / 5.0).abs() < 1e-12);
/// assert!(check.warning().is_none());
/// assert!(point_size_check(&g, &c.solve_force(1e7)?).is_err()); // a ≥ R
/// # Ok::<(), kontakt::Error>(())
/// ```
pub fn point_size_check(geometry: &PointGeometry, sol: &HertzPointSolution) -> Result<SizeCheck> {
    point_size(geometry, sol).refuse_too_large()
}

/// The ratio of [`point_size_check`] without the refusal (for callers that apply
/// [`SizeCheck::refuse_too_large`] and [`SizeCheck::warning`] later, naming their own key).
pub fn point_size(geometry: &PointGeometry, sol: &HertzPointSolution) -> SizeCheck {
    let [a, b] = sol.semi_axes;
    let radii = [geometry.body1_radii(), geometry.body2_radii()];
    let offsets = [0.0, geometry.angle()];
    // Directions (relative to the major axis) to evaluate: a uniform sample, plus the
    // ellipse's axes and each body's principal directions, where the maximum usually is.
    let axes = [
        0.0,
        std::f64::consts::FRAC_PI_2,
        -sol.orientation,
        std::f64::consts::FRAC_PI_2 - sol.orientation,
        geometry.angle() - sol.orientation,
        geometry.angle() + std::f64::consts::FRAC_PI_2 - sol.orientation,
    ];
    let sample = (0..DIRECTIONS).map(|k| k as f64 * std::f64::consts::PI / DIRECTIONS as f64);
    let mut best = SizeCheck {
        ratio: 0.0,
        body: 1,
        extent: a,
        radius: f64::INFINITY,
        direction: sol.orientation,
    };
    for phi in axes.into_iter().chain(sample) {
        let (s, c) = phi.sin_cos();
        let extent = 1.0 / ((c / a).powi(2) + (s / b).powi(2)).sqrt();
        let direction = sol.orientation + phi;
        for (body, (r, offset)) in radii.iter().zip(offsets).enumerate() {
            let kappa = normal_curvature(*r, direction - offset);
            let ratio = extent * kappa.abs();
            if ratio > best.ratio {
                best = SizeCheck {
                    ratio,
                    body: body as u8 + 1,
                    extent,
                    radius: 1.0 / kappa,
                    direction: direction.rem_euclid(std::f64::consts::PI),
                };
            }
        }
    }
    best
}

/// The contact-half-width-to-radius ratio of a Hertz line contact between cylinders of
/// radii `radii` \[mm\] (convex > 0, concave < 0, flat infinite).
///
/// # Errors
/// [`Error::Geometry`] (field `body1.radii` or `body2.radii`) when the ratio reaches
/// [`MAX_SIZE_RATIO`].
pub fn line_size_check(radii: [Millimetre; 2], sol: &LineSolution) -> Result<SizeCheck> {
    line_size(radii, sol).refuse_too_large()
}

/// The ratio of [`line_size_check`] without the refusal.
pub fn line_size(radii: [Millimetre; 2], sol: &LineSolution) -> SizeCheck {
    let b = sol.half_width;
    let (body, r) = if radii[0].abs() <= radii[1].abs() {
        (1, radii[0])
    } else {
        (2, radii[1])
    };
    SizeCheck {
        ratio: b / r.abs(),
        body,
        extent: b,
        radius: r,
        direction: 0.0,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::hertz::HertzPointContact;
    use crate::hertz::line::LineContact;
    use crate::material::ElasticMaterial;

    fn steel() -> ElasticMaterial {
        ElasticMaterial::new(210_000.0, 0.3).unwrap()
    }

    /// The gap error of the quadratic profile against the circle, at the ratios the module
    /// quotes: 0.25 % at 0.1, 4.2 % at 0.4, 50 % at 1, and (s/R)²/4 for small ratios.
    #[test]
    fn quadratic_gap_error_matches_the_circle() {
        for (ratio, expected) in [(0.1f64, 0.002_506), (0.4, 0.041_742), (1.0, 0.5)] {
            let exact = 1.0 - (ratio * ratio / 2.0) / (1.0 - (1.0 - ratio * ratio).sqrt());
            assert!(
                (quadratic_gap_error(ratio) - exact).abs() < 1e-12,
                "{ratio}"
            );
            assert!((exact - expected).abs() < 1e-6, "{ratio}: {exact}");
        }
        let small = 1e-4;
        assert!((quadratic_gap_error(small) / (small * small / 4.0) - 1.0).abs() < 1e-6);
    }

    /// A ball in a groove: the ratio is the largest of a/R_ball, a/|R_groove| and
    /// b/R_race over the axes (here a across the groove against the ball), found by the
    /// direction search, and a groove conforming to within 1 µm is refused naming body 1.
    #[test]
    fn ball_in_groove_ratio_and_near_conformal_refusal() {
        let g = PointGeometry::new([3.969, 3.969], [15.281, -4.128], 0.0).unwrap();
        let c = HertzPointContact::new(g, steel(), steel()).unwrap();
        let sol = c.solve_force(1000.0).unwrap();
        let check = point_size_check(&g, &sol).unwrap();
        // a lies across the groove (y); the ball's radius 3.969 is the smaller one there.
        let expected = sol.semi_axes[0] / 3.969;
        assert!((check.ratio - expected).abs() < 1e-12, "{check:?}");
        assert_eq!(check.body, 1);
        assert!(check.warning().is_none(), "0.33 < 0.4");
        // Ten times the load: a grows by 10^(1/3), the ratio passes 0.4 and warns.
        let heavy = c.solve_force(10_000.0).unwrap();
        let w = point_size_check(&g, &heavy).unwrap().warning().unwrap();
        assert!(
            w.contains("0.71 of body 1") && w.contains("3.969 mm"),
            "{w}"
        );
        // A groove conforming to within 1 µm: the contact would be far wider than the ball.
        let g = PointGeometry::new([3.969, 3.969], [15.281, -3.970], 0.0).unwrap();
        let c = HertzPointContact::new(g, steel(), steel()).unwrap();
        let e = point_size_check(&g, &c.solve_force(1000.0).unwrap()).unwrap_err();
        assert!(
            matches!(&e, Error::Geometry { field, .. } if field == "body1.radii"),
            "{e}"
        );
    }

    /// Crossed cylinders at 45°: the maximum lies off the axes, so the direction search
    /// must find a ratio at least as large as at either axis and at most 1 % above the
    /// densely sampled maximum.
    #[test]
    fn oblique_crossed_cylinders_search_every_direction() {
        let angle = 45f64.to_radians();
        let g = PointGeometry::new([5.0, f64::INFINITY], [8.0, f64::INFINITY], angle).unwrap();
        let c = HertzPointContact::new(g, steel(), steel()).unwrap();
        let sol = c.solve_force(2000.0).unwrap();
        let check = point_size_check(&g, &sol).unwrap();
        let [a, b] = sol.semi_axes;
        let mut dense: f64 = 0.0;
        for k in 0..100_000 {
            let phi = k as f64 * std::f64::consts::PI / 100_000.0;
            let extent = 1.0 / ((phi.cos() / a).powi(2) + (phi.sin() / b).powi(2)).sqrt();
            let d = sol.orientation + phi;
            let k1 = normal_curvature(g.body1_radii(), d).abs();
            let k2 = normal_curvature(g.body2_radii(), d - angle).abs();
            dense = dense.max(extent * k1.max(k2));
        }
        assert!(
            check.ratio <= dense * (1.0 + 1e-9),
            "{} > {dense}",
            check.ratio
        );
        assert!(check.ratio >= dense * 0.99, "{} < {dense}", check.ratio);
    }

    /// Line contact: half-width over the smaller radius; flat on flat is refused earlier
    /// by the geometry, a flat body never limits.
    #[test]
    fn line_contact_ratio() {
        let c = LineContact::new(10.0, f64::INFINITY, steel(), steel()).unwrap();
        let sol = c.solve(1000.0).unwrap();
        let check = line_size_check(c.radii(), &sol).unwrap();
        assert!((check.ratio - sol.half_width / 10.0).abs() < 1e-15);
        assert_eq!(check.body, 1);
        let huge = c.solve(1e8).unwrap();
        assert!(sol.half_width < huge.half_width);
        assert!(line_size_check(c.radii(), &huge).is_err());
    }
}
