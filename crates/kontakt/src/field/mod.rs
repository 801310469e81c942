//! The shared vocabulary of the field solvers: a pressure field on a grid and what is
//! read off it.
//!
//! - [`NormalSolution`]: the one result type of every normal-contact field solver
//!   (PimP, the coupled half-space solver, and the ones to come): headline numbers,
//!   the zone's shape, why the solve stopped, and the pressure per cell. Its `detail`
//!   carries what only one method has (PimP's bedding law; the half-space solver's
//!   displacement, gap and iteration record).
//! - [`ContactZone`]: the shape of a pressure field (area, extents, centre of pressure,
//!   patches, centre-line curvature).
//! - [`validity`]: the size check of a solution against its bodies (the zone small against
//!   their radii of curvature, clear of their faces' edges).
//! - [`domain`]: the one adaptive-domain loop that both field solvers run: a grid that
//!   grows until it holds the contact and zooms in once when the contact is small in it.
//!
//! Units: mm, N, MPa. Frames: a solution's grid lies in the principal frame of the gap,
//! turned by `orientation` \[rad\] from the gap source's `x` axis about the contact
//! normal (see [`crate::gap::GapSource`]).

pub mod domain;
pub mod validity;
mod zone;

pub use zone::{ContactZone, ZoneScratch};

use crate::geometry::Grid2;
use crate::solve::SolveStatus;
use crate::units::{Megapascal, Millimetre, Newton};

/// The solution of a normal contact on a grid: the same fields whichever method solved
/// it, plus the method's own `detail`.
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct NormalSolution<D> {
    /// Normal force \[N\].
    pub force: Newton,
    /// Rigid approach \[mm\] of distant points, from first touch (or a gap map's zero
    /// level).
    pub approach: Millimetre,
    /// Largest pressure \[MPa\].
    pub max_pressure: Megapascal,
    /// Mean pressure over the contact area \[MPa\].
    pub mean_pressure: Megapascal,
    /// Contact area \[mm²\]: loaded cells times the cell area.
    pub contact_area: f64,
    /// Half-extents of the zone along the grid's x and y \[mm\] (the semi-axes for an
    /// elliptical zone).
    pub semi_axes: [Millimetre; 2],
    /// Angle \[rad\] from the gap source's `x` axis to the grid's `x` axis (the direction
    /// of least relative curvature).
    pub orientation: f64,
    /// Shape of the zone in the grid frame.
    pub zone: ContactZone,
    /// Why the solver's iteration stopped, its iterations and final residual.
    pub status: SolveStatus,
    /// Grids tried by the adaptive domain (1 when the first grid held the contact).
    pub domains: usize,
    /// The grid \[mm\] (principal frame of the gap).
    pub grid: Grid2,
    /// Pressure per cell \[MPa\], row-major with x fastest.
    pub pressure: Vec<Megapascal>,
    /// What only this solver's method gives.
    pub detail: D,
}

impl<D> NormalSolution<D> {
    /// The resultant force \[N\] and its point of action `[x, y]` \[mm\] in the grid frame
    /// (the centre of pressure).
    pub fn resultant(&self) -> (Newton, [Millimetre; 2]) {
        (self.zone.force, self.zone.centroid)
    }

    /// The same solution with its method's `detail` replaced by `f(detail)` (for example
    /// `|_| ()` to keep fields of different solvers in one collection).
    pub fn map_detail<E>(self, f: impl FnOnce(D) -> E) -> NormalSolution<E> {
        NormalSolution {
            force: self.force,
            approach: self.approach,
            max_pressure: self.max_pressure,
            mean_pressure: self.mean_pressure,
            contact_area: self.contact_area,
            semi_axes: self.semi_axes,
            orientation: self.orientation,
            zone: self.zone,
            status: self.status,
            domains: self.domains,
            grid: self.grid,
            pressure: self.pressure,
            detail: f(self.detail),
        }
    }
}
