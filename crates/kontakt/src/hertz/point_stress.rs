//! Subsurface stress peaks and first yield of a planned Hertz point contact.

use super::point::{HertzPointContact, HertzPointSolution};
use crate::error::{Error, Result};
use crate::hertz::subsurface::{self, StressPeaks, YieldCriterion};
use crate::units::{Megapascal, Newton};
use serde::Serialize;

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
        let mut best: Option<FirstYield> = None;
        for (i, m) in self.materials().iter().enumerate() {
            let ratio =
                subsurface::yield_pressure_ratio(self.axis_ratio(), m.poisson_ratio(), criterion)?;
            let p0_yield = ratio * yield_stress;
            let p0_unit = self.max_pressure_at_unit_force();
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
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct FirstYield {
    /// Normal force at first yield \[N\].
    pub load: Newton,
    /// Maximum contact pressure at first yield \[MPa\].
    pub max_pressure: Megapascal,
    /// The body (1 or 2) that yields first.
    pub body: usize,
}
