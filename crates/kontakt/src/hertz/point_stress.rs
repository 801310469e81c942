//! Subsurface stress peaks and first yield of a planned Hertz point contact.

use super::point::{HertzPointContact, HertzPointSolution};
use crate::error::{Error, Result};
use crate::hertz::subsurface::{self, StressPeaks, YieldCriterion};
use crate::units::{Megapascal, Newton};

impl HertzPointContact {
    /// Peak subsurface stresses on the load axis for a solution of this contact. The two
    /// bodies differ only through Poisson's ratio; the larger of the two bodies' peaks
    /// (by maximum shear stress) is returned with the body index (1 or 2).
    ///
    /// # Errors
    /// Propagates errors of [`subsurface::axis_stress_peaks`].
    pub fn subsurface_peaks(&self, solution: &HertzPointSolution) -> Result<(StressPeaks, usize)> {
        let [a, b] = solution.semi_axes;
        let p0 = solution.max_pressure;
        let s1 = subsurface::axis_stress_peaks(p0, a, b, self.materials()[0].poisson_ratio())?;
        if self.materials()[1].poisson_ratio() == self.materials()[0].poisson_ratio() {
            return Ok((s1, 1));
        }
        let s2 = subsurface::axis_stress_peaks(p0, a, b, self.materials()[1].poisson_ratio())?;
        Ok(if s2.max_shear > s1.max_shear {
            (s2, 2)
        } else {
            (s1, 1)
        })
    }

    /// The normal force \[N\] at which the material first yields below the surface, for a
    /// yield stress `yield_stress` \[MPa\] (> 0) common to both bodies (give the weaker
    /// body's value), by the chosen criterion. Uses p0 ∝ F^(1/3):
    /// $F_Y = (p_{0Y}/p_{0,1})^3$ with $p_{0,1}$ the maximum pressure at 1 N.
    ///
    /// # Errors
    /// Non-positive or non-finite yield stress.
    ///
    /// # References
    /// Johnson (1982) eqs (21a/b); Johnson, *Contact Mechanics* (1985) §3.9.
    pub fn first_yield(
        &self,
        yield_stress: Megapascal,
        criterion: YieldCriterion,
    ) -> Result<FirstYield> {
        crate::error::positive("yield_stress", yield_stress)?;
        let p0_unit = self.max_pressure_at_unit_force();
        let mut best: Option<FirstYield> = None;
        for (i, m) in self.materials().iter().enumerate() {
            let ratio =
                subsurface::yield_pressure_ratio(self.axis_ratio(), m.poisson_ratio(), criterion)?;
            let p0_yield = ratio * yield_stress;
            let load = (p0_yield / p0_unit).powi(3);
            if best.is_none_or(|b| load < b.load) {
                best = Some(FirstYield {
                    load,
                    max_pressure: p0_yield,
                    body: i + 1,
                });
            }
        }
        best.ok_or_else(|| Error::invalid("materials", "none", "two materials"))
    }
}

/// First yield of a Hertz contact.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct FirstYield {
    /// Normal force at first yield \[N\].
    pub load: Newton,
    /// Maximum contact pressure at first yield \[MPa\].
    pub max_pressure: Megapascal,
    /// The body (1 or 2) that yields first.
    pub body: usize,
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::hertz::PointGeometry;
    use crate::material::{ElasticMaterial, effective_modulus};
    use approx::assert_relative_eq;

    /// Sphere on flat: the planned contact's first-yield load equals the subsurface
    /// module's closed route P_Y = pi^3 R^2 p0Y^3 / (6 E*^2).
    #[test]
    fn first_yield_matches_sphere_formula() {
        let s = ElasticMaterial::STEEL;
        let c = HertzPointContact::new(PointGeometry::sphere_on_flat(12.0).unwrap(), s, s).unwrap();
        for crit in [YieldCriterion::VonMises, YieldCriterion::Tresca] {
            let fy = c.first_yield(1500.0, crit).unwrap();
            let reference = subsurface::first_yield_load_circular(
                12.0,
                effective_modulus(&s, &s),
                1500.0,
                0.3,
                crit,
            )
            .unwrap();
            assert_relative_eq!(fy.load, reference, max_relative = 1e-12);
            // At that load the maximum pressure is the first-yield pressure.
            let sol = c.solve_force(fy.load).unwrap();
            assert_relative_eq!(sol.max_pressure, fy.max_pressure, max_relative = 1e-12);
        }
    }

    /// Dissimilar Poisson's ratios: the body whose ratio yields at the lower load is named.
    #[test]
    fn first_yield_picks_the_weaker_body() {
        let a = ElasticMaterial::new(210_000.0, 0.3).unwrap();
        let b = ElasticMaterial::new(210_000.0, 0.45).unwrap();
        let g = PointGeometry::new([10.0, 20.0], [f64::INFINITY; 2], 0.0).unwrap();
        let c = HertzPointContact::new(g, a, b).unwrap();
        let fy = c.first_yield(1000.0, YieldCriterion::VonMises).unwrap();
        let r = |nu| {
            subsurface::yield_pressure_ratio(c.axis_ratio(), nu, YieldCriterion::VonMises).unwrap()
        };
        let expected_body = if r(0.3) <= r(0.45) { 1 } else { 2 };
        assert_eq!(fy.body, expected_body);
        assert_relative_eq!(
            fy.max_pressure,
            1000.0 * r(0.3).min(r(0.45)),
            max_relative = 1e-14
        );
        assert!(c.first_yield(0.0, YieldCriterion::VonMises).is_err());
    }
}
