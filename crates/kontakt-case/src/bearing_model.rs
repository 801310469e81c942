//! A whole bearing solved for many loads: [`BearingModel`] holds the solver plan of a
//! bearing case (`method = "bearing"`, [`crate::bearing_case`]: roller and ball bearings)
//! and warm-starts every solve from the last equilibrium (the library's `solve_from`).
//! [`crate::run_bearing_case`] is a cold solve of a model, so a solve gives the same
//! [`BearingReport`] (the same keys and, up to the last digits of the Newton iteration, the
//! same numbers); only `solver.iterations` tells a warm solve from a cold one.
//!
//! The Python class `kontakt.Bearing` is built on this.

use crate::bearing_case::{
    BearingCase, BearingLoadSpec, BearingReport, Planned, plan, solve_planned,
};
use crate::validity::checked;
use kontakt::Result;

/// A bearing of a case, planned once and solved for many loads of its inner ring.
#[derive(Debug, Clone)]
pub struct BearingModel {
    case: BearingCase,
    label: &'static str,
    planned: Planned,
    /// The displacement of the last converged solve, the start of the next one.
    last: Option<[f64; 5]>,
}

impl BearingModel {
    /// Plan the bearing of `case` (its `[load]` is not used: see [`BearingModel::solve`]).
    ///
    /// # Errors
    /// As [`crate::run_bearing_case`] for the `[bearing]` table and `method`: errors name
    /// the case key (`bearing.roller_diameter_mm`, `bearing.inner_osculation`).
    pub fn new(case: &BearingCase) -> Result<Self> {
        let (planned, label) = plan(case)?;
        Ok(BearingModel {
            case: case.clone(),
            label,
            planned,
            last: None,
        })
    }

    /// The bearing type of the case: `"cylindrical"`, `"tapered"`, `"thrust"`,
    /// `"deep_groove_ball"` or `"angular_contact_ball"`.
    pub fn bearing_type(&self) -> &'static str {
        self.label
    }

    /// Forget the last equilibrium: the next solve starts from the closed forms.
    pub fn reset(&mut self) {
        self.last = None;
    }

    /// The displacement the next solve starts from, `(δx, δy, δz, θx, θy)` mm and rad;
    /// `None` before the first converged solve, after [`BearingModel::reset`] and after a
    /// solve with every element lifted off (then the next solve starts from the closed
    /// forms).
    pub fn warm_start(&self) -> Option<[f64; 5]> {
        self.last
    }

    /// Solve the equilibrium under `load` (forces N, moments N·mm, prescribed
    /// displacements mm and rad, as the case's `[load]`), from the last converged
    /// equilibrium when there is one, and report it as [`crate::run_bearing_case`] does.
    ///
    /// # Errors
    /// [`kontakt::Error::InvalidInput`] naming the case key of the load
    /// (`load.force_n[2]`, `load.prescribed.tilt_x_rad`); [`kontakt::Error::NotConverged`]
    /// for an equilibrium that ends at the iteration limit or diverges (the warm start is
    /// kept).
    pub fn solve(&mut self, load: &BearingLoadSpec) -> Result<BearingReport> {
        let report = checked(self.solve_unchecked(load)?)?;
        // with every element lifted off the displacement says nothing about the next load:
        // the closed-form start is the better one
        let loaded = report.rollers().map_or(0.0, |r| r.max_roller_load_n)
            + report.balls().map_or(0.0, |b| b.max_ball_load_n)
            > 0.0;
        self.last = loaded.then_some([
            report.displacement_mm[0],
            report.displacement_mm[1],
            report.displacement_mm[2],
            report.tilt_rad[0],
            report.tilt_rad[1],
        ]);
        Ok(report)
    }

    /// [`BearingModel::solve`] before the validity check, without keeping the solution.
    pub(crate) fn solve_unchecked(&mut self, l: &BearingLoadSpec) -> Result<BearingReport> {
        let start = if unloaded(l) { None } else { self.last };
        solve_planned(&self.case, self.label, &mut self.planned, l, start)
    }
}

/// Whether `l` is no load at all (forces, moments and prescribed displacements zero): then
/// the closed-form start is the exact answer (every element lifted off), and Newton from an
/// old equilibrium would end at the round-off floor instead.
pub(crate) fn unloaded(l: &BearingLoadSpec) -> bool {
    let p = &l.prescribed;
    l.force_n.iter().chain(&l.moment_nmm).all(|f| *f == 0.0)
        && [p.dx_mm, p.dy_mm, p.dz_mm, p.tilt_x_rad, p.tilt_y_rad]
            .iter()
            .all(|u| u.is_none_or(|u| u == 0.0))
}

mod element;
mod friction;
pub use element::{BearingElement, BearingElementOutput, BearingElementStatus, prescribed_load};
pub use friction::{ElementFriction, ElementFrictionStatus};

#[cfg(test)]
mod tests;
