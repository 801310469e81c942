//! The slice model of a roller bearing case, `[bearing] slice_model`: the ISO/TS 16281
//! slice law (independent slices, the default) or coupled slices (the slices of a roller
//! interact through the elastic half-space, so that the pressure along a crowned or tilted
//! roller and the edge peak at its ends come out; `docs/bearing-model.md` §12). Both
//! solvers answer the report's questions through `SliceSolver`.

use kontakt::Result;
use kontakt_bearing::equilibrium::coupled::CoupledSliceSolver;
use kontakt_bearing::equilibrium::{RingLoad, RollerBearingSolver, RollerLoad, RollerSolution};
use kontakt_bearing::geometry::RollerBearing;
use serde::{Deserialize, Serialize};

/// `[bearing] slice_model`: how the slices of a roller carry load.
#[derive(
    Debug, Clone, Copy, PartialEq, Eq, Default, Serialize, Deserialize, schemars::JsonSchema,
)]
#[serde(rename_all = "snake_case")]
pub enum SliceModel {
    /// `"iso"`: ISO/TS 16281 (2008), `q = c_s δ^(10/9)` per slice, each slice on its own
    /// (fast; no edge stress).
    #[default]
    Iso,
    /// `"coupled"`: half-space strips with the local Hertz half-width, coupled through
    /// their influence coefficients (de Mul, Kalker & Vree 1998; Teutsch & Sauer 2004),
    /// the mean approach of a uniformly loaded roller fixed by the ISO law; reports the
    /// peak pressure of every slice (MPa). Steel on steel.
    Coupled,
}

/// The pressure along every roller in the report (`slice_model = "coupled"`).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct RollerPressures {
    /// The largest slice pressure of any roller, MPa.
    pub max_pressure_mpa: f64,
    /// The pressure along every roller, slice by slice (the larger of the two raceways),
    /// `[roller][slice]`, MPa.
    pub slice_pressure_mpa: Vec<Vec<f64>>,
}

/// What a roller bearing report needs of a solver.
pub(crate) trait SliceSolver {
    fn solve(&mut self, load: &RingLoad) -> Result<RollerSolution>;
    fn solve_from(&mut self, load: &RingLoad, start: [f64; 5]) -> Result<RollerSolution>;
    fn bearing(&self) -> &RollerBearing;
    fn slice_positions(&self) -> &[f64];
    fn slice_loads(&self) -> &[f64];
    fn slice_approaches(&self) -> &[f64];
    fn roller_loads(&self) -> &[RollerLoad];
    /// The peak pressure of every slice on the inner and the outer raceway (MPa,
    /// roller-major), where the model has one.
    fn slice_pressures(&self) -> Option<(&[f64], &[f64])> {
        None
    }
}

macro_rules! slice_solver {
    ($t:ty) => {
        fn solve(&mut self, load: &RingLoad) -> Result<RollerSolution> {
            <$t>::solve(self, load)
        }
        fn solve_from(&mut self, load: &RingLoad, start: [f64; 5]) -> Result<RollerSolution> {
            <$t>::solve_from(self, load, start)
        }
        fn bearing(&self) -> &RollerBearing {
            <$t>::bearing(self)
        }
        fn slice_positions(&self) -> &[f64] {
            <$t>::slice_positions(self)
        }
        fn slice_loads(&self) -> &[f64] {
            <$t>::slice_loads(self)
        }
        fn slice_approaches(&self) -> &[f64] {
            <$t>::slice_approaches(self)
        }
        fn roller_loads(&self) -> &[RollerLoad] {
            <$t>::roller_loads(self)
        }
    };
}

impl SliceSolver for RollerBearingSolver {
    slice_solver!(RollerBearingSolver);
}

impl SliceSolver for CoupledSliceSolver {
    slice_solver!(CoupledSliceSolver);
    fn slice_pressures(&self) -> Option<(&[f64], &[f64])> {
        Some((self.inner_pressures(), self.outer_pressures()))
    }
}

/// The per-slice peak pressure (the larger of the two raceways, MPa) of every roller,
/// `[roller][slice]`, and per roller its largest; `None` without pressures.
pub(crate) fn pressure_map<S: SliceSolver>(solver: &S) -> Option<(Vec<Vec<f64>>, Vec<f64>)> {
    let (inner, outer) = solver.slice_pressures()?;
    let ns = solver.bearing().slices;
    let map: Vec<Vec<f64>> = inner
        .chunks(ns)
        .zip(outer.chunks(ns))
        .map(|(i, o)| i.iter().zip(o).map(|(a, b)| a.max(*b)).collect())
        .collect();
    let max = map
        .iter()
        .map(|r| r.iter().copied().fold(0.0, f64::max))
        .collect();
    Some((map, max))
}
