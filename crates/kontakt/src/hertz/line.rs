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
use crate::material::{ElasticMaterial, effective_modulus};
use crate::units::{Megapascal, Millimetre, Newton, NewtonPerMillimetre};
use serde::Serialize;
use std::f64::consts::PI;

/// Lundberg's constant in the approach of a finite line contact.
pub const LUNDBERG_CONSTANT: f64 = 1.8864;

/// Smallest ratio l/b (half-length over half-width) accepted by [`LineContact::lundberg_approach`].
pub const MIN_LENGTH_TO_WIDTH: f64 = 5.0;

/// A planned line contact of two parallel cylinders.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct LineContact {
    radii: [Millimetre; 2],
    effective_radius: Millimetre,
    e_star: Megapascal,
}

/// The state of a line contact at one line load.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
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

    /// Solution for a line load `line_load` [N/mm] (> 0, finite).
    ///
    /// # Errors
    /// Non-positive or non-finite line load.
    pub fn solve(&self, line_load: NewtonPerMillimetre) -> Result<LineSolution> {
        crate::error::positive("line_load", line_load)?;
        let b = (4.0 * line_load * self.effective_radius / (PI * self.e_star)).sqrt();
        let p0 = 2.0 * line_load / (PI * b);
        Ok(LineSolution {
            line_load,
            half_width: b,
            max_pressure: p0,
            mean_pressure: line_load / (2.0 * b),
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
        if l < MIN_LENGTH_TO_WIDTH * b {
            return Err(Error::invalid(
                "length",
                length,
                format!(
                    ">= {:.4} mm: Lundberg's formula needs l >= {MIN_LENGTH_TO_WIDTH} b (half-width b = {b:.4} mm)",
                    2.0 * MIN_LENGTH_TO_WIDTH * b
                ),
            ));
        }
        Ok(force / (PI * l * self.e_star) * ((l / b).ln() + LUNDBERG_CONSTANT))
    }
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

#[cfg(test)]
mod tests {
    use super::*;
    use approx::assert_relative_eq;

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
