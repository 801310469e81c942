//! Fast approximations of the elliptical Hertz contact: Greenwood's equivalent radius
//! (Johnson 1982 eqs 16-20) and Hamrock & Brewe's curve fits (1983).
//!
//! Both return the same [`HertzPointSolution`] as the exact solver, so they can be swapped
//! in. Their error against the exact solution over B/A from 1 to 10⁴ is tabulated in
//! `docs/hertz.md` and bounded by the tests of this module. The exact solver costs well
//! under a microsecond; prefer it unless these formulas are needed for comparison with
//! other software.
//!
//! # References
//! - Johnson (1982), eqs (16)-(20) and Appendix 1 (Greenwood's procedure).
//! - Hamrock & Brewe (1983), "Simplified solution for stresses and deformations",
//!   J. Lubr. Technol. 105(2), 171-177, doi:10.1115/1.3254558; Hamrock, *Fundamentals of
//!   Fluid Film Lubrication* (1994), eqs (3.26)-(3.28) (with E' = 2 E*).

use super::point::HertzPointSolution;
use crate::error::Result;
use crate::geometry::RelativeCurvature;
use crate::units::{Megapascal, Newton};
use std::f64::consts::PI;

/// Which approximation to use.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[cfg_attr(
    feature = "serde",
    derive(serde::Serialize, serde::Deserialize, schemars::JsonSchema)
)]
#[cfg_attr(feature = "serde", serde(rename_all = "snake_case"))]
pub enum Approximation {
    /// Greenwood's equivalent radius with the correction factors set to one and
    /// b/a = (A/B)^(2/3) (Johnson 1982 eqs 16-20).
    Greenwood,
    /// Hamrock & Brewe's curve fits for the ellipticity and the elliptic integrals.
    HamrockBrewe,
}

/// Approximate solution of a point contact of relative curvature `curvature` and contact
/// modulus `e_star` \[MPa\] under the force `force` \[N\] (> 0).
///
/// Greenwood: $c = \sqrt{ab} = (3FR_e/4E^*)^{1/3}$, $b/a = (A/B)^{2/3}$,
/// $\delta = (9F^2/16E^{*2}R_e)^{1/3}$ with $R_e = (R'R'')^{1/2}$.
///
/// Hamrock-Brewe, with $\alpha_r = B/A$ and $1/R = 2(A+B)$: $\bar k = a/b = 1.0339\,\alpha_r^{0.636}$,
/// $\bar E = 1.0003 + 0.5968/\alpha_r$, $\bar F = 1.5277 + 0.6023\ln\alpha_r$,
/// $a = (3\bar k^2 \bar E F R/\pi E^*)^{1/3}$, $b = (3\bar E F R/\pi\bar k E^*)^{1/3}$,
/// $\delta = \bar F\,[\tfrac{9}{2\bar E R}(F/2\pi\bar k E^*)^2]^{1/3}$.
///
/// # Errors
/// Non-positive or non-finite force or modulus.
pub fn approximate_point_contact(
    curvature: &RelativeCurvature,
    e_star: Megapascal,
    force: Newton,
    model: Approximation,
) -> Result<HertzPointSolution> {
    crate::error::positive("force", force)?;
    crate::error::positive("e_star", e_star)?;
    let ratio = curvature.ratio();
    let (a, b, approach) = match model {
        Approximation::Greenwood => {
            let re = curvature.equivalent_radius();
            let c = (0.75 * force * re / e_star).cbrt();
            let shape = ratio.powf(-2.0 / 3.0); // b/a
            let a = c / shape.sqrt();
            let b = c * shape.sqrt();
            let delta = (9.0 * force * force / (16.0 * e_star * e_star * re)).cbrt();
            (a, b, delta)
        }
        Approximation::HamrockBrewe => {
            let r = curvature.effective_radius();
            let k = 1.0339 * ratio.powf(0.636);
            let e_bar = 1.0003 + 0.5968 / ratio;
            let f_bar = 1.5277 + 0.6023 * ratio.ln();
            let a = (3.0 * k * k * e_bar * force * r / (PI * e_star)).cbrt();
            let b = (3.0 * e_bar * force * r / (PI * k * e_star)).cbrt();
            let q = force / (2.0 * PI * k * e_star);
            let delta = f_bar * (9.0 / (2.0 * e_bar * r) * q * q).cbrt();
            (a, b, delta)
        }
    };
    let area = PI * a * b;
    Ok(HertzPointSolution {
        semi_axes: [a, b],
        orientation: curvature.orientation,
        force,
        approach,
        max_pressure: 1.5 * force / area,
        mean_pressure: force / area,
        contact_area: area,
        stiffness: 1.5 * force / approach,
    })
}

/// Largest relative errors of an approximation against the exact solution.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct ApproximationError {
    /// B/A of the case.
    pub curvature_ratio: f64,
    /// Relative error of a.
    pub semi_major: f64,
    /// Relative error of b.
    pub semi_minor: f64,
    /// Relative error of p0.
    pub max_pressure: f64,
    /// Relative error of delta.
    pub approach: f64,
}

/// Relative errors (approximate / exact - 1) of `model` at the curvature ratio
/// `curvature_ratio` = B/A (>= 1). The errors do not depend on load, size or modulus.
///
/// # Errors
/// Ratio below 1 or beyond [`crate::geometry::curvature::MAX_CURVATURE_RATIO`].
pub fn approximation_error(
    curvature_ratio: f64,
    model: Approximation,
) -> Result<ApproximationError> {
    if !(curvature_ratio >= 1.0) {
        return Err(crate::Error::invalid(
            "curvature_ratio",
            curvature_ratio,
            ">= 1",
        ));
    }
    let k = RelativeCurvature::from_tensor(2.0, 2.0 * curvature_ratio, 0.0)?;
    let geometry = super::PointGeometry::from_curvature(k);
    let m = crate::material::ElasticMaterial::STEEL;
    let exact = super::HertzPointContact::new(geometry, m, m)?.solve_force(100.0)?;
    let approx =
        approximate_point_contact(&k, crate::material::effective_modulus(&m, &m), 100.0, model)?;
    let rel = |x: f64, y: f64| x / y - 1.0;
    Ok(ApproximationError {
        curvature_ratio,
        semi_major: rel(approx.semi_axes[0], exact.semi_axes[0]),
        semi_minor: rel(approx.semi_axes[1], exact.semi_axes[1]),
        max_pressure: rel(approx.max_pressure, exact.max_pressure),
        approach: rel(approx.approach, exact.approach),
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    fn worst(model: Approximation, max_ratio: f64) -> [f64; 4] {
        let mut w = [0.0f64; 4];
        for i in 0..=80 {
            let r = max_ratio.powf(i as f64 / 80.0);
            let e = approximation_error(r, model).unwrap();
            for (wi, v) in
                w.iter_mut()
                    .zip([e.semi_major, e.semi_minor, e.max_pressure, e.approach])
            {
                *wi = wi.max(v.abs());
            }
        }
        w
    }

    /// Bounds documented in docs/hertz.md (rounded up from the printed table).
    #[test]
    fn documented_error_bounds_hold() {
        // Circle: Greenwood is exact.
        let e = approximation_error(1.0, Approximation::Greenwood).unwrap();
        assert!(e.semi_major.abs() < 1e-14 && e.approach.abs() < 1e-14);
        // Hamrock-Brewe over B/A = 1..100 (its fitted range). The individual fits are
        // good to about 3 %; combined, delta is off by up to about 5.4 % (at B/A = 1).
        let w = worst(Approximation::HamrockBrewe, 100.0);
        let bounds = [0.045, 0.025, 0.025, 0.056];
        assert!(w.iter().zip(bounds).all(|(&x, b)| x < b), "{w:?}");
        // Greenwood with F0 = F1 = F2 = 1 over B/A = 1..10: p0 up to about 12 % low
        // (the correction factor F1^(-2/3) of Johnson's Fig. 3 is 0.88 at B/A = 10).
        let w = worst(Approximation::Greenwood, 10.0);
        let bounds = [0.085, 0.052, 0.123, 0.072];
        assert!(w.iter().zip(bounds).all(|(&x, b)| x < b), "{w:?}");
        // And they do fail for thin ellipses: the errors must be visible at B/A = 1e4.
        let e = approximation_error(1e4, Approximation::Greenwood).unwrap();
        assert!(e.semi_minor.abs() > 0.05, "{e:?}");
    }
}
