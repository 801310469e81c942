//! Hertz line contact of parallel cylinders: half-width, maximum pressure and the pressure
//! profile per unit length, and Lundberg's approach of a finite line contact.
//!
//! # Formulas
//! With $1/R = 1/R_1 + 1/R_2$ (convex > 0, concave < 0) and the line load $P'$ [N/mm]:
//!
//! ```text
//! b = √(4 P' R / (π E*)),   p₀ = 2 P' / (π b) = √(P' E* / (π R)),   p(x) = p₀ √(1 - x²/b²).
//! ```
//!
//! (Johnson 1982 eqs 9-11; thesis eqs 2.3-2.6, which call the half-width `a`.) The approach
//! of a two-dimensional contact is not defined without a datum (eq. 22); for a contact of
//! finite length $L = 2l$ Lundberg's formula (eq. 25) gives the approach at the centre:
//!
//! ```text
//! δ = P / (π l E*) · [ln(l/b) + 1.8864].
//! ```
//!
//! Its derivative gives the stiffness [`LineContact::stiffness`]; the subsurface peaks of
//! the more stressed body ([`LineContact::subsurface_peaks`]) and the first yield
//! ([`LineContact::first_yield`], Johnson 1982 eq. 21b) follow from
//! [`crate::hertz::subsurface`].
//!
//! # Assumptions
//! Plane strain, elastic half-spaces, frictionless; Lundberg: uniform load along a contact
//! much longer than wide (l ≫ b), ends ignored.
//!
//! # References
//! - Johnson (1982) eqs (9)-(11), (22), (25); Johnson, *Contact Mechanics* (1985) §4.2.
//! - Lundberg (1939), "Elastische Berührung zweier Halbräume", Forschung auf dem Gebiete
//!   des Ingenieurwesens 10, 201-211 (constant 1.8864).

use crate::error::{Error, Result};
use crate::geometry::curvature::validate_radius;
use crate::hertz::subsurface::{self, StressPeaks, YieldCriterion};
use crate::material::{ElasticMaterial, effective_modulus};
use crate::units::{Megapascal, Millimetre, Newton, NewtonPerMillimetre};
use std::f64::consts::PI;

/// Lundberg's constant in the approach of a finite line contact.
pub const LUNDBERG_CONSTANT: f64 = 1.8864;

/// Smallest ratio l/b (half-length over half-width) accepted by [`LineContact::lundberg_approach`].
pub const MIN_LENGTH_TO_WIDTH: f64 = 5.0;

/// A planned line contact of two parallel cylinders.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct LineContact {
    radii: [Millimetre; 2],
    effective_radius: Millimetre,
    e_star: Megapascal,
    materials: [ElasticMaterial; 2],
}

/// The state of a line contact at one line load.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct LineSolution {
    /// Line load P' [N/mm].
    pub line_load: NewtonPerMillimetre,
    /// Half-width b of the contact strip \[mm\].
    pub half_width: Millimetre,
    /// Maximum pressure p0 \[MPa\].
    pub max_pressure: Megapascal,
    /// Mean pressure P'/(2b) = pi p0 / 4 \[MPa\].
    pub mean_pressure: Megapascal,
}

impl LineContact {
    /// Two parallel cylinders of radii `body1_radius`, `body2_radius` \[mm\] (convex > 0,
    /// concave < 0, `inf` for a flat).
    ///
    /// # Errors
    /// Zero/NaN radius; relative curvature 1/R1 + 1/R2 not positive (conformal or
    /// separating surfaces).
    ///
    /// # Example
    /// A 10 mm roller (R = 5 mm) on a flat, 500 N/mm, steel:
    /// ```
    /// use kontakt::{hertz::line::LineContact, material::ElasticMaterial};
    /// let s = ElasticMaterial::STEEL;
    /// let c = LineContact::new(5.0, f64::INFINITY, s, s)?;
    /// let sol = c.solve(500.0)?;
    /// // b = sqrt(4 P' R / (pi E*)) = 0.166093 mm, p0 = 2 P' / (pi b) = 1916.46 MPa
    /// assert!((sol.half_width - 0.166_093).abs() < 1e-6);
    /// assert!((sol.max_pressure - 1_916.46).abs() < 0.01);
    /// # Ok::<(), kontakt::Error>(())
    /// ```
    pub fn new(
        body1_radius: Millimetre,
        body2_radius: Millimetre,
        body1: ElasticMaterial,
        body2: ElasticMaterial,
    ) -> Result<Self> {
        validate_radius("body1.radius", body1_radius)?;
        validate_radius("body2.radius", body2_radius)?;
        let curvature = 1.0 / body1_radius + 1.0 / body2_radius;
        if !(curvature > 0.0) {
            return Err(Error::Geometry {
                field: "radii".into(),
                reason: format!(
                    "the relative curvature 1/R1 + 1/R2 = {curvature:.6e} 1/mm must be > 0: the \
                     cylinders are conformal or separate (a concave radius must be larger in \
                     magnitude than the convex one)"
                ),
            });
        }
        Ok(LineContact {
            radii: [body1_radius, body2_radius],
            effective_radius: 1.0 / curvature,
            e_star: effective_modulus(&body1, &body2),
            materials: [body1, body2],
        })
    }

    /// Effective radius R = 1/(1/R1 + 1/R2) \[mm\].
    pub fn effective_radius(&self) -> Millimetre {
        self.effective_radius
    }
    /// Contact modulus E* \[MPa\].
    pub fn e_star(&self) -> Megapascal {
        self.e_star
    }
    /// The two radii \[mm\].
    pub fn radii(&self) -> [Millimetre; 2] {
        self.radii
    }
    /// The materials of body 1 and body 2.
    pub fn materials(&self) -> [ElasticMaterial; 2] {
        self.materials
    }

    /// Solution for a line load `line_load` [N/mm] (> 0, finite).
    ///
    /// # Errors
    /// Non-positive or non-finite line load.
    pub fn solve(&self, line_load: NewtonPerMillimetre) -> Result<LineSolution> {
        crate::error::positive("line_load", line_load)?;
        let b = (4.0 * line_load * self.effective_radius / (PI * self.e_star)).sqrt();
        let p0 = 2.0 * line_load / (PI * b);
        let mean = line_load / (2.0 * b);
        // A line load near f64::MAX overflows the half-width (found by the Python fuzz
        // harness): an error naming the load, never inf in a result.
        for (name, q) in [
            ("half-width", b),
            ("maximum pressure", p0),
            ("mean pressure", mean),
        ] {
            if !(q.is_finite() && q > 0.0) {
                return Err(Error::invalid(
                    "line_load",
                    line_load,
                    format!(
                        "a load whose contact is representable in double precision (its {name} \
                         would be {q}; scale the inputs towards engineering values)"
                    ),
                ));
            }
        }
        Ok(LineSolution {
            line_load,
            half_width: b,
            max_pressure: p0,
            mean_pressure: mean,
        })
    }

    /// Line load [N/mm] that produces a maximum pressure `max_pressure` \[MPa\]:
    /// $P' = \pi R p_0^2 / E^*$.
    ///
    /// # Errors
    /// Non-positive or non-finite pressure.
    pub fn line_load_from_max_pressure(
        &self,
        max_pressure: Megapascal,
    ) -> Result<NewtonPerMillimetre> {
        crate::error::positive("max_pressure", max_pressure)?;
        Ok(PI * self.effective_radius * max_pressure * max_pressure / self.e_star)
    }

    /// Lundberg's approach \[mm\] at the centre of a contact of length `length` \[mm\] under the
    /// total force `force` \[N\] (Johnson 1982 eq. 25, constant [`LUNDBERG_CONSTANT`]).
    ///
    /// # Errors
    /// Non-positive force or length, or a contact shorter than
    /// [`MIN_LENGTH_TO_WIDTH`] half-widths per half-length (the formula assumes l ≫ b).
    pub fn lundberg_approach(&self, force: Newton, length: Millimetre) -> Result<Millimetre> {
        crate::error::positive("force", force)?;
        crate::error::positive("length", length)?;
        let l = 0.5 * length;
        let b = self.solve(force / length)?.half_width;
        lundberg_length(length, b)?;
        let approach = force / (PI * l * self.e_star) * ((l / b).ln() + LUNDBERG_CONSTANT);
        // A length near f64::MAX overflows `π l E*` (found by the Python fuzz harness: NaN).
        if !(approach.is_finite() && approach > 0.0) {
            return Err(Error::invalid(
                "length",
                length,
                format!(
                    "a contact whose approach is representable in double precision (it would be \
                     {approach}; scale the inputs towards engineering values)"
                ),
            ));
        }
        Ok(approach)
    }

    /// Contact stiffness dF/dδ [N/mm] of a contact of length `length` \[mm\] under the
    /// line load `line_load` [N/mm], from Lundberg's approach (Johnson 1982 eq. 25):
    ///
    /// $$k = \frac{dF}{d\delta} = \frac{\pi l E^*}{\ln(l/b) + 1.8864 - 1/2},\qquad l = L/2,$$
    ///
    /// the derivative of $\delta = F/(\pi l E^*)\,[\ln(l/b) + 1.8864]$ with $b \propto F^{1/2}$
    /// (Johnson 1982 eq. 9) at fixed length: $d\ln b/dF = 1/(2F)$ gives the $-1/2$.
    ///
    /// # Errors
    /// Non-positive or non-finite line load or length, or a contact shorter than
    /// [`MIN_LENGTH_TO_WIDTH`] half-widths per half-length (Lundberg's formula assumes
    /// l ≫ b, as [`LineContact::lundberg_approach`]).
    ///
    /// # Assumptions
    /// As [`LineContact::lundberg_approach`]: uniform load along the contact, ends ignored.
    ///
    /// # References
    /// Johnson (1982) eqs (9), (25); Lundberg (1939).
    pub fn stiffness(
        &self,
        line_load: NewtonPerMillimetre,
        length: Millimetre,
    ) -> Result<NewtonPerMillimetre> {
        crate::error::positive("length", length)?;
        let b = self.solve(line_load)?.half_width;
        let half = 0.5 * length;
        lundberg_length(length, b)?;
        Ok(PI * half * self.e_star / ((half / b).ln() + LUNDBERG_CONSTANT - 0.5))
    }

    /// Peak subsurface stresses below the centre line for a solution of this contact
    /// (stresses \[MPa\], depths \[mm\]), with the body (1 or 2) they belong to. The two
    /// bodies carry the same Hertz pressure and differ only through Poisson's ratio; the
    /// more stressed one, by the larger von Mises peak, is returned (body 1 on a tie).
    ///
    /// # Errors
    /// Propagates errors of [`subsurface::line_stress_peaks`].
    ///
    /// # Assumptions
    /// Plane strain, frictionless Hertz pressure (as [`subsurface::line_stress_peaks`]).
    ///
    /// # References
    /// McEwen (1949); Johnson, *Contact Mechanics* (1985) §4.2, eq. (4.49).
    pub fn subsurface_peaks(&self, solution: &LineSolution) -> Result<(StressPeaks, usize)> {
        let (p0, b) = (solution.max_pressure, solution.half_width);
        let p1 = subsurface::line_stress_peaks(p0, b, self.materials[0].poisson_ratio())?;
        let p2 = subsurface::line_stress_peaks(p0, b, self.materials[1].poisson_ratio())?;
        Ok(if p2.max_von_mises > p1.max_von_mises {
            (p2, 2)
        } else {
            (p1, 1)
        })
    }

    /// First yield below the surface for a yield stress `yield_stress` \[MPa\] (> 0)
    /// common to both bodies (give the weaker body's value), by the chosen criterion:
    /// the maximum pressure $p_{0Y} = \min_i (p_{0Y}/Y)(\nu_i)\,Y$ over the two bodies'
    /// Poisson's ratios ([`subsurface::line_yield_pressure_ratio`]) and the line load
    /// $P'_Y = \pi R p_{0Y}^2/E^*$ [N/mm] that produces it.
    ///
    /// # Errors
    /// Non-positive or non-finite yield stress; errors of
    /// [`subsurface::line_yield_pressure_ratio`].
    ///
    /// # Assumptions
    /// Plane strain, elastic-perfectly plastic material, no residual stress.
    ///
    /// # References
    /// Johnson (1982) eq. (21b); Johnson, *Contact Mechanics* (1985) §4.2.
    pub fn first_yield(
        &self,
        yield_stress: Megapascal,
        criterion: YieldCriterion,
    ) -> Result<LineFirstYield> {
        crate::error::positive("yield_stress", yield_stress)?;
        let ratios = self
            .materials
            .iter()
            .map(|m| subsurface::line_yield_pressure_ratio(m.poisson_ratio(), criterion))
            .collect::<Result<Vec<_>>>()?;
        let ratio = ratios.iter().copied().fold(f64::INFINITY, f64::min);
        let body = if ratios[1] < ratios[0] { 2 } else { 1 };
        let p0y = ratio * yield_stress;
        Ok(LineFirstYield {
            line_load: self.line_load_from_max_pressure(p0y)?,
            max_pressure: p0y,
            body,
        })
    }
}

/// First yield of a line contact ([`LineContact::first_yield`]).
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct LineFirstYield {
    /// Line load at first yield [N/mm].
    pub line_load: NewtonPerMillimetre,
    /// Maximum contact pressure at first yield \[MPa\].
    pub max_pressure: Megapascal,
    /// The body (1 or 2) that yields first.
    pub body: usize,
}

impl LineSolution {
    /// Pressure p(x) = p0 sqrt(1 - x²/b²) \[MPa\] at the distance `x` \[mm\] from the centre
    /// line; 0 outside the strip.
    pub fn pressure_at(&self, x: Millimetre) -> Megapascal {
        let r = x / self.half_width;
        if r.abs() < 1.0 {
            self.max_pressure * (1.0 - r * r).sqrt()
        } else {
            0.0
        }
    }
}

/// Lundberg's formula assumes a contact much longer than wide: refuse a half-length
/// `length / 2` \[mm\] below [`MIN_LENGTH_TO_WIDTH`] half-widths `b` \[mm\].
fn lundberg_length(length: Millimetre, b: Millimetre) -> Result<()> {
    if 0.5 * length < MIN_LENGTH_TO_WIDTH * b {
        return Err(Error::invalid(
            "length",
            length,
            format!(
                ">= {:.4} mm: Lundberg's formula needs l >= {MIN_LENGTH_TO_WIDTH} b (half-width b = {b:.4} mm)",
                2.0 * MIN_LENGTH_TO_WIDTH * b
            ),
        ));
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;
    use approx::assert_relative_eq;

    /// Found by the Python fuzz harness: a line load of f64::MAX on R = 1 mm gave an
    /// infinite half-width; now an error naming the load.
    #[test]
    fn overflowing_line_load_is_an_error() {
        let s = ElasticMaterial::STEEL;
        let c = LineContact::new(1.0, 1.0, s, s).unwrap();
        let e = c.solve(f64::MAX).unwrap_err();
        assert!(
            matches!(&e, Error::InvalidInput { field, .. } if field == "line_load"),
            "{e}"
        );
        assert!(e.to_string().contains("double precision"), "{e}");
        assert!(c.solve(1e-300).is_ok());
        // Lundberg's approach over a length near f64::MAX: NaN before, now an error.
        let flat = LineContact::new(f64::INFINITY, 1.0, s, s).unwrap();
        let e = flat.lundberg_approach(f64::MAX, f64::MAX).unwrap_err();
        assert!(e.to_string().contains("double precision"), "{e}");
    }

    #[test]
    fn profile_integrates_to_line_load() {
        let s = ElasticMaterial::STEEL;
        let c = LineContact::new(8.0, -40.0, s, s).unwrap();
        let sol = c.solve(300.0).unwrap();
        // Midpoint rule, 200 000 cells: error O(n^-1.5) from the square-root edges.
        let n = 200_000;
        let h = 2.0 * sol.half_width / n as f64;
        let total: f64 = (0..n)
            .map(|i| sol.pressure_at(-sol.half_width + (i as f64 + 0.5) * h) * h)
            .sum();
        assert_relative_eq!(total, 300.0, max_relative = 1e-6);
        assert_relative_eq!(
            sol.mean_pressure,
            PI / 4.0 * sol.max_pressure,
            max_relative = 1e-14
        );
        assert_relative_eq!(
            c.line_load_from_max_pressure(sol.max_pressure).unwrap(),
            300.0,
            max_relative = 1e-13
        );
    }

    /// The stiffness is the derivative of Lundberg's approach: against a central
    /// difference of [`LineContact::lundberg_approach`] (step 1e-3 F: truncation
    /// ~1e-7 relative, tolerance 1e-6), and exactly (1e-14) the identity
    /// k δ / F = (ln(l/b) + C) / (ln(l/b) + C - 1/2) that follows from the two formulas.
    #[test]
    fn stiffness_is_the_derivative_of_lundbergs_approach() {
        let s = ElasticMaterial::STEEL;
        let c = LineContact::new(8.0, 30.0, s, s).unwrap();
        for (q, length) in [(100.0, 12.0), (800.0, 20.0), (2500.0, 40.0)] {
            let f = q * length;
            let k = c.stiffness(q, length).unwrap();
            let h = 1e-3 * f;
            let fd = 2.0 * h
                / (c.lundberg_approach(f + h, length).unwrap()
                    - c.lundberg_approach(f - h, length).unwrap());
            assert_relative_eq!(k, fd, max_relative = 1e-6);
            let delta = c.lundberg_approach(f, length).unwrap();
            let b = c.solve(q).unwrap().half_width;
            let log = (0.5 * length / b).ln() + LUNDBERG_CONSTANT;
            assert_relative_eq!(k * delta / f, log / (log - 0.5), max_relative = 1e-14);
        }
        // Too short for Lundberg's formula, and bad input.
        assert_eq!(
            c.stiffness(1000.0, 0.5).unwrap_err().field(),
            Some("length")
        );
        assert_eq!(
            c.stiffness(1000.0, 0.0).unwrap_err().field(),
            Some("length")
        );
        assert_eq!(
            c.stiffness(-1.0, 10.0).unwrap_err().field(),
            Some("line_load")
        );
    }

    /// Equal steels: τmax = 0.300 p0 at z = 0.786 b (Johnson 1985 §4.2, tolerance 1e-3);
    /// the peaks scale exactly with p0 and the depths with b (quadrupling the load
    /// doubles both; tolerance 1e-12); body 1 is reported on a tie.
    #[test]
    fn subsurface_peaks_follow_johnson_and_scale_with_the_load() {
        let s = ElasticMaterial::STEEL;
        let c = LineContact::new(6.0, f64::INFINITY, s, s).unwrap();
        let sol = c.solve(400.0).unwrap();
        let (p, body) = c.subsurface_peaks(&sol).unwrap();
        assert_eq!(body, 1);
        assert_relative_eq!(p.max_shear / sol.max_pressure, 0.300, max_relative = 1e-3);
        assert_relative_eq!(
            p.max_shear_depth / sol.half_width,
            0.786,
            max_relative = 1e-3
        );
        let (p4, _) = c.subsurface_peaks(&c.solve(1600.0).unwrap()).unwrap();
        assert_relative_eq!(p4.max_shear, 2.0 * p.max_shear, max_relative = 1e-12);
        assert_relative_eq!(
            p4.max_von_mises,
            2.0 * p.max_von_mises,
            max_relative = 1e-12
        );
        assert_relative_eq!(
            p4.max_shear_depth,
            2.0 * p.max_shear_depth,
            max_relative = 1e-12
        );
        assert_relative_eq!(
            p4.max_von_mises_depth,
            2.0 * p.max_von_mises_depth,
            max_relative = 1e-12
        );
    }

    /// Dissimilar Poisson's ratios: the body with the larger von Mises peak is named and
    /// its peaks are those of `line_stress_peaks` at its ratio (exactly).
    #[test]
    fn subsurface_peaks_pick_the_more_stressed_body() {
        let a = ElasticMaterial::new(210_000.0, 0.45).unwrap();
        let b = ElasticMaterial::new(210_000.0, 0.2).unwrap();
        for (m1, m2) in [(a, b), (b, a)] {
            let c = LineContact::new(10.0, 10.0, m1, m2).unwrap();
            let sol = c.solve(500.0).unwrap();
            let (p, body) = c.subsurface_peaks(&sol).unwrap();
            let at =
                |nu| subsurface::line_stress_peaks(sol.max_pressure, sol.half_width, nu).unwrap();
            let (s1, s2) = (at(m1.poisson_ratio()), at(m2.poisson_ratio()));
            assert_ne!(s1.max_von_mises, s2.max_von_mises);
            let expected = if s2.max_von_mises > s1.max_von_mises {
                (s2, 2)
            } else {
                (s1, 1)
            };
            assert_eq!((p, body), expected);
        }
        // Lower Poisson's ratio, larger von Mises stress: body b (ν = 0.2) is named.
        let c = LineContact::new(10.0, 10.0, a, b).unwrap();
        assert_eq!(c.subsurface_peaks(&c.solve(500.0).unwrap()).unwrap().1, 2);
    }

    /// First yield, equal steels (ν = 0.3): p0Y = 1.6651 Y (Tresca, Johnson: 1.67 Y) and
    /// 1.7937 Y (von Mises, Johnson: 1.79 Y), tolerance 1e-4; the line load is the closed
    /// form P'Y = π R p0Y²/E* and reproduces p0Y when solved (1e-12).
    #[test]
    fn first_yield_matches_johnson_and_the_closed_form() {
        let s = ElasticMaterial::STEEL;
        let c = LineContact::new(7.5, 25.0, s, s).unwrap();
        let y = 1200.0;
        for (crit, ratio) in [
            (YieldCriterion::Tresca, 1.6651),
            (YieldCriterion::VonMises, 1.7937),
        ] {
            let fy = c.first_yield(y, crit).unwrap();
            assert_eq!(fy.body, 1);
            assert_relative_eq!(fy.max_pressure / y, ratio, max_relative = 1e-4);
            let r = c.effective_radius();
            assert_relative_eq!(
                fy.line_load,
                PI * r * fy.max_pressure * fy.max_pressure / c.e_star(),
                max_relative = 1e-12
            );
            assert_relative_eq!(
                c.solve(fy.line_load).unwrap().max_pressure,
                fy.max_pressure,
                max_relative = 1e-12
            );
        }
        assert_eq!(
            c.first_yield(0.0, YieldCriterion::Tresca)
                .unwrap_err()
                .field(),
            Some("yield_stress")
        );
        assert!(c.first_yield(f64::NAN, YieldCriterion::VonMises).is_err());
    }

    /// Dissimilar Poisson's ratios: the body whose ratio gives the lower first-yield
    /// pressure is named, and that pressure is the minimum (exact).
    #[test]
    fn first_yield_picks_the_weaker_body() {
        let a = ElasticMaterial::new(210_000.0, 0.3).unwrap();
        let b = ElasticMaterial::new(210_000.0, 0.45).unwrap();
        let crit = YieldCriterion::VonMises;
        let r = |nu| subsurface::line_yield_pressure_ratio(nu, crit).unwrap();
        assert_ne!(r(0.3), r(0.45));
        let weaker = if r(0.45) < r(0.3) { 2 } else { 1 };
        let c = LineContact::new(10.0, 20.0, a, b).unwrap();
        let fy = c.first_yield(1000.0, crit).unwrap();
        assert_eq!(fy.body, weaker);
        assert_eq!(fy.max_pressure, r(0.3).min(r(0.45)) * 1000.0);
        let swapped = LineContact::new(10.0, 20.0, b, a).unwrap();
        assert_eq!(swapped.first_yield(1000.0, crit).unwrap().body, 3 - weaker);
    }

    #[test]
    fn bad_input() {
        let s = ElasticMaterial::STEEL;
        assert!(LineContact::new(5.0, -5.0, s, s).is_err());
        assert!(LineContact::new(5.0, -4.0, s, s).is_err());
        assert!(LineContact::new(0.0, 5.0, s, s).is_err());
        let c = LineContact::new(5.0, f64::INFINITY, s, s).unwrap();
        assert!(c.solve(0.0).is_err());
        assert!(c.solve(f64::NAN).is_err());
        let e = c.lundberg_approach(1000.0, 0.5).unwrap_err();
        assert_eq!(e.field(), Some("length"));
    }
}
