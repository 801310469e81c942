//! Relative curvature of two bodies touching at a point.
//!
//! Near the first point of contact the separation of two smooth surfaces is the quadratic
//! form $h = \tfrac12\,\mathbf x^\mathsf T (\mathbf K_1 + \mathbf K_2)\,\mathbf x$ where
//! $\mathbf K_i$ is the curvature tensor of body *i* in the common tangent plane. Its
//! eigenvalues are $2A \le 2B$ and it can be written $h = A x'^2 + B y'^2$
//! (Johnson 1982, eqs 1 and 50). We compute $A$, $B$ and the principal direction from the
//! tensor sum directly; this is algebraically identical to Johnson's eqs (51a/b) (note
//! that the extracted eq. 51b in Johnson (1982) shows sums of curvatures in the first two squared
//! terms; they must be *differences*, as in Johnson's *Contact Mechanics* eq. 3.3 and in the
//! thesis' eq. 2.12, which in turn prints `cos(phi)` for `cos(2 phi)`; see
//! `docs/hertz.md`).

use crate::error::{Error, Result};
use crate::units::{Millimetre, Radian};

/// Largest ratio B/A accepted as a point contact. Beyond it (contact ellipse with
/// b/a below about 4e-6) the contact is a line contact for every practical purpose and
/// [`crate::hertz::line`] is the right model.
pub const MAX_CURVATURE_RATIO: f64 = 1e10;

/// Validate one principal radius of curvature \[mm\]: non-zero and not NaN; `±inf` is flat.
pub fn validate_radius(field: &'static str, radius: Millimetre) -> Result<Millimetre> {
    if radius.is_nan() || radius == 0.0 {
        Err(Error::invalid(
            field,
            radius,
            "a non-zero radius in mm (convex > 0, concave < 0, inf for flat)",
        ))
    } else {
        Ok(radius)
    }
}

/// The principal relative curvatures $A \le B$ [1/mm] of two touching bodies and the
/// direction of $A$.
///
/// The gap is $h = A x'^2 + B y'^2$ with $A = 1/(2R')$, $B = 1/(2R'')$; `orientation` is
/// the angle \[rad\] in (-pi/2, pi/2] from body 1's first principal direction (`x`) to `x'`,
/// the direction of *least* relative curvature, along which the contact ellipse's major
/// semi-axis lies.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct RelativeCurvature {
    /// A = 1/(2R') [1/mm], the smaller coefficient, > 0.
    pub a_coef: f64,
    /// B = 1/(2R'') [1/mm], the larger coefficient, >= A.
    pub b_coef: f64,
    /// Angle from body 1's first principal direction to the direction of A \[rad\].
    pub orientation: Radian,
}

impl RelativeCurvature {
    /// Relative curvature of two bodies given by their principal radii.
    ///
    /// # Arguments
    /// - `body1_radii`, `body2_radii` — principal radii of curvature \[mm\] of each body,
    ///   first along the body's first principal direction. Convex > 0, concave < 0,
    ///   `inf` for flat; zero and NaN are invalid.
    /// - `angle` — theta \[rad\], the angle from body 1's first principal direction to
    ///   body 2's, finite.
    ///
    /// # Errors
    /// - [`Error::InvalidInput`] for a zero or NaN radius (`body1.radii[0]`, ...) or a
    ///   non-finite angle.
    /// - [`Error::Geometry`] (field `radii`) when the relative curvature is not positive
    ///   in every direction: the surfaces are conformal, separate (a concave radius
    ///   smaller in magnitude than the convex one it holds), touch along a line (then use
    ///   [`crate::hertz::line`]) or are so elongated that B/A exceeds
    ///   [`MAX_CURVATURE_RATIO`].
    ///
    /// # Example
    /// Two equal cylinders (R = 10 mm) crossed at 90°: A = B = 1/20 mm⁻¹, a circle.
    /// ```
    /// use kontakt::geometry::RelativeCurvature;
    /// let inf = f64::INFINITY;
    /// let k = RelativeCurvature::from_radii([10.0, inf], [10.0, inf], std::f64::consts::FRAC_PI_2)?;
    /// assert!((k.a_coef - 0.05).abs() < 1e-15 && (k.b_coef - 0.05).abs() < 1e-15);
    /// # Ok::<(), kontakt::Error>(())
    /// ```
    ///
    /// # References
    /// Johnson (1982) eqs (1), (50), (51); Johnson, *Contact Mechanics* (1985) §3.1.
    pub fn from_radii(
        body1_radii: [Millimetre; 2],
        body2_radii: [Millimetre; 2],
        angle: Radian,
    ) -> Result<Self> {
        const FIELDS: [[&str; 2]; 2] = [
            ["body1.radii[0]", "body1.radii[1]"],
            ["body2.radii[0]", "body2.radii[1]"],
        ];
        for (radii, fields) in [body1_radii, body2_radii].iter().zip(FIELDS) {
            for (r, f) in radii.iter().zip(fields) {
                validate_radius(f, *r)?;
            }
        }
        if !angle.is_finite() {
            return Err(Error::invalid("angle", angle, "a finite angle"));
        }
        let (k11, k12) = (1.0 / body1_radii[0], 1.0 / body1_radii[1]);
        let (k21, k22) = (1.0 / body2_radii[0], 1.0 / body2_radii[1]);
        // Curvature tensor of body 2 rotated into body 1's principal frame.
        let (s, c) = if angle == 0.0 {
            (0.0, 1.0)
        } else {
            angle.sin_cos()
        };
        let kxx = k11 + k21 * c * c + k22 * s * s;
        let kyy = k12 + k21 * s * s + k22 * c * c;
        let kxy = (k21 - k22) * s * c;
        Self::from_tensor(kxx, kyy, kxy)
    }

    /// Relative curvature from the components of the summed curvature tensor
    /// $\mathbf K_1 + \mathbf K_2$ [1/mm] in body 1's frame, so that
    /// $h = \tfrac12(k_{xx}x^2 + 2k_{xy}xy + k_{yy}y^2)$.
    ///
    /// # Errors
    /// As [`RelativeCurvature::from_radii`].
    pub fn from_tensor(kxx: f64, kyy: f64, kxy: f64) -> Result<Self> {
        if !(kxx.is_finite() && kyy.is_finite() && kxy.is_finite()) {
            return Err(Error::invalid(
                "curvature",
                format!("[{kxx}, {kyy}, {kxy}]"),
                "finite curvature components in 1/mm",
            ));
        }
        let mean = 0.5 * (kxx + kyy);
        let half_diff = 0.5 * (kxx - kyy);
        // sqrt of the sum of squares is exact enough and much cheaper than hypot; hypot
        // only where squaring could overflow (radii below 1e-150 mm).
        let dev = if kxy == 0.0 {
            half_diff.abs()
        } else if half_diff.abs().max(kxy.abs()) < 1e150 {
            (half_diff * half_diff + kxy * kxy).sqrt()
        } else {
            half_diff.hypot(kxy)
        };
        let lambda_max = mean + dev;
        // The smaller eigenvalue from the determinant avoids cancellation in mean - dev
        // when the contact is long and thin.
        let lambda_min = if kxy == 0.0 {
            kxx.min(kyy)
        } else if lambda_max > 0.0 {
            ((kxx * kyy - kxy * kxy) / lambda_max).min(lambda_max)
        } else {
            mean - dev
        };
        let lambda_max = if kxy == 0.0 { kxx.max(kyy) } else { lambda_max };
        // Direction of lambda_min: perpendicular to the major eigenvector.
        let phi_max = if kxy == 0.0 {
            if half_diff >= 0.0 {
                0.0
            } else {
                std::f64::consts::FRAC_PI_2
            }
        } else {
            0.5 * kxy.atan2(half_diff)
        };
        let mut orientation = phi_max + std::f64::consts::FRAC_PI_2;
        if orientation > std::f64::consts::FRAC_PI_2 {
            orientation -= std::f64::consts::PI;
        }
        let (a_coef, b_coef) = (0.5 * lambda_min, 0.5 * lambda_max);
        if !(b_coef > 0.0) || a_coef < 0.0 {
            return Err(Error::Geometry {
                field: "radii".into(),
                reason: format!(
                    "the relative curvature must be positive in every direction, got \
                     A = {a_coef:.6e} and B = {b_coef:.6e} 1/mm: the surfaces are conformal or \
                     separate (a concave radius must be larger in magnitude than the convex \
                     radius it holds)"
                ),
            });
        }
        if a_coef == 0.0 || b_coef / a_coef > MAX_CURVATURE_RATIO {
            return Err(Error::Geometry {
                field: "radii".into(),
                reason: format!(
                    "the relative curvature is (nearly) zero in one direction (A = {a_coef:.6e}, \
                     B = {b_coef:.6e} 1/mm, B/A > {MAX_CURVATURE_RATIO:e}): this is a line \
                     contact, use the line-contact model"
                ),
            });
        }
        Ok(RelativeCurvature {
            a_coef,
            b_coef,
            orientation: if dev == 0.0 { 0.0 } else { orientation },
        })
    }

    /// Equivalent radius $R_e = \sqrt{R'R''} = \tfrac12 (AB)^{-1/2}$ \[mm\] (Johnson 1982 eq. 53).
    pub fn equivalent_radius(&self) -> Millimetre {
        0.5 / (self.a_coef * self.b_coef).sqrt()
    }

    /// Effective radius $R = 1/(2(A+B))$ \[mm\]; for a circular contact $R = R_e$, and in
    /// general $1/R = 1/R' + 1/R''$ (Hamrock's curvature sum).
    pub fn effective_radius(&self) -> Millimetre {
        0.5 / (self.a_coef + self.b_coef)
    }

    /// Ratio $B/A = R'/R'' \ge 1$.
    pub fn ratio(&self) -> f64 {
        self.b_coef / self.a_coef
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use approx::assert_relative_eq;
    const INF: f64 = f64::INFINITY;

    /// Johnson (1982) eqs (51a/b) with the misprint corrected (differences in the squares).
    fn johnson_51(r1: [f64; 2], r2: [f64; 2], theta: f64) -> (f64, f64) {
        let sum = 0.5 * (1.0 / r1[0] + 1.0 / r1[1] + 1.0 / r2[0] + 1.0 / r2[1]);
        let d1 = 1.0 / r1[0] - 1.0 / r1[1];
        let d2 = 1.0 / r2[0] - 1.0 / r2[1];
        let diff = 0.5 * (d1 * d1 + d2 * d2 + 2.0 * d1 * d2 * (2.0 * theta).cos()).sqrt();
        (0.5 * (sum - diff), 0.5 * (sum + diff))
    }

    #[test]
    fn agrees_with_johnson_51_over_angles() {
        for (r1, r2) in [
            ([10.0, 25.0], [40.0, -60.0]),
            ([5.0, INF], [8.0, 30.0]),
            ([12.0, 12.0], [20.0, 7.0]),
        ] {
            for k in 0..24 {
                let theta = k as f64 * 0.27 - 1.3;
                let rc = RelativeCurvature::from_radii(r1, r2, theta).unwrap();
                let (a, b) = johnson_51(r1, r2, theta);
                assert_relative_eq!(rc.a_coef, a, max_relative = 1e-12);
                assert_relative_eq!(rc.b_coef, b, max_relative = 1e-12);
            }
        }
    }

    #[test]
    fn orientation_points_along_least_curvature() {
        // Body 1 a cylinder with its axis along x (flat along x): least curvature along x.
        let rc = RelativeCurvature::from_radii([INF, 10.0], [20.0, 20.0], 0.0).unwrap();
        assert_relative_eq!(rc.orientation, 0.0);
        // Same cylinder axis along y.
        let rc = RelativeCurvature::from_radii([10.0, INF], [20.0, 20.0], 0.0).unwrap();
        assert_relative_eq!(rc.orientation.abs(), std::f64::consts::FRAC_PI_2);
        // General: check that h along the orientation equals A.
        let theta = 0.4;
        let (r1, r2) = ([8.0, 30.0], [15.0, -90.0]);
        let rc = RelativeCurvature::from_radii(r1, r2, theta).unwrap();
        let h = |phi: f64| {
            let (s1, c1) = phi.sin_cos();
            let (s2, c2) = (phi - theta).sin_cos();
            0.5 * (c1 * c1 / r1[0] + s1 * s1 / r1[1] + c2 * c2 / r2[0] + s2 * s2 / r2[1])
        };
        assert_relative_eq!(h(rc.orientation), rc.a_coef, max_relative = 1e-12);
        assert_relative_eq!(
            h(rc.orientation + std::f64::consts::FRAC_PI_2),
            rc.b_coef,
            max_relative = 1e-12
        );
    }

    #[test]
    fn rejects_non_touching_conformal_and_line() {
        // Ball of 5 mm in a 4 mm groove: separate (concave radius smaller than ball).
        let e = RelativeCurvature::from_radii([5.0, 5.0], [-4.0, -4.0], 0.0).unwrap_err();
        assert!(matches!(e, Error::Geometry { .. }), "{e}");
        // Perfectly conformal.
        assert!(RelativeCurvature::from_radii([5.0, 5.0], [-5.0, -5.0], 0.0).is_err());
        // Parallel cylinders: line contact.
        let e = RelativeCurvature::from_radii([INF, 5.0], [INF, 7.0], 0.0).unwrap_err();
        assert!(e.to_string().contains("line contact"), "{e}");
        // Flat on flat.
        assert!(RelativeCurvature::from_radii([INF, INF], [INF, INF], 0.0).is_err());
        // Zero / NaN radius, NaN angle.
        let e = RelativeCurvature::from_radii([0.0, 5.0], [INF, INF], 0.0).unwrap_err();
        assert_eq!(e.field(), Some("body1.radii[0]"));
        let e = RelativeCurvature::from_radii([1.0, 5.0], [INF, f64::NAN], 0.0).unwrap_err();
        assert_eq!(e.field(), Some("body2.radii[1]"));
        assert!(RelativeCurvature::from_radii([1.0, 5.0], [INF, INF], f64::NAN).is_err());
    }
}
