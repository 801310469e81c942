//! The adaptive domain of the field solvers: one loop, used by PimP and by the coupled
//! half-space solver.
//!
//! A solve on a grid of fixed cell count is only as good as the grid's extent: too large
//! and the contact spans few cells; too small and the contact is cut off at the border.
//! The loop starts from an estimate of the zone, solves, and then
//! 1. grows the domain by [`GROWTH`] about its centre along each axis on which loaded
//!    cells reach the border (an error for a fixed extent);
//! 2. zooms in once when the zone is small in the domain ([`Shrink`]);
//! 3. refuses a zone that spans fewer than [`MIN_CELLS_ACROSS`] cells either way.
//!
//! Units: mm. Bounds are `[[x_min, x_max], [y_min, y_max]]` in the solver's grid frame.

use super::ContactZone;
use crate::error::{Error, Result};
use crate::gap::GapSource;
use crate::geometry::Grid2;
use crate::load::LoadControl;

/// An estimate of the contact zone's bounding box `[[x0, x1], [y0, y1]]` \[mm\] in the
/// principal frame of a gap, for a load: where an adaptive domain starts. The
/// half-space solver takes one as a parameter (`halfspace::Bem::with_estimate`; PimP's
/// is `pimp::zone_estimate`), so the reference solver does not depend on the method
/// it checks.
pub type ZoneEstimate =
    std::sync::Arc<dyn Fn(&dyn GapSource, LoadControl) -> Result<[[f64; 2]; 2]> + Send + Sync>;

/// Fewest loaded cells across the contact zone, in each direction, for a result to be
/// trusted; a coarser zone is an error.
pub const MIN_CELLS_ACROSS: usize = 8;

/// Factor by which the domain grows along an axis on which the contact reaches the border.
pub const GROWTH: f64 = 1.6;

/// How the domain zooms in (once) on a contact that is small in it.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Shrink {
    /// About the origin (the contact point): when the zone's reach `max(|x_min|, |x_max|)`
    /// along either axis is below `trigger` times the half-extent, the half-extents
    /// become `factor` times the reach (never larger than before). PimP's rule.
    AboutOrigin {
        /// Reach over half-extent below which the domain zooms in.
        trigger: f64,
        /// New half-extent over the zone's reach.
        factor: f64,
    },
    /// About the zone's centre: when the zone fills less than `trigger` of the domain's
    /// width along either axis, the domain becomes the zone's half-width times `margin`,
    /// with at least two cells beyond the loaded ones. The half-space solver's rule.
    AboutZone {
        /// Zone width over domain width below which the domain zooms in.
        trigger: f64,
        /// New half-width over the zone's half-width.
        margin: f64,
    },
}

/// The adaptive-domain policy of a solver.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Policy {
    /// Most grids to try before giving up.
    pub max_domains: usize,
    /// How to zoom in.
    pub shrink: Shrink,
}

/// What a solver hands back for one grid: its own result and the zone's shape.
#[derive(Debug, Clone)]
pub struct Trial<T> {
    /// The solver's result on this grid.
    pub result: T,
    /// The shape of its pressure field.
    pub zone: ContactZone,
}

/// The accepted result, the grid it was found on and the number of grids tried (>= 1).
#[derive(Debug, Clone)]
pub struct Adapted<T> {
    /// The solver's result.
    pub result: T,
    /// The zone's shape.
    pub zone: ContactZone,
    /// The grid \[mm\].
    pub grid: Grid2,
    /// Grids tried, >= 1.
    pub domains: usize,
}

/// Run `solve` on grids of `cells` cells, starting from `bounds` \[mm\]; `fixed` keeps the
/// bounds (the contact must then fit in them). `solve` gets the grid and the 0-based
/// index of the attempt.
///
/// # Errors
/// - Errors of `solve`.
/// - [`Error::Geometry`] (field `extent`) when no cell is loaded, when the zone reaches
///   the border of a fixed domain, or when the adaptive domain does not settle in
///   `policy.max_domains` grids; (field `cells`) when the zone spans fewer than
///   [`MIN_CELLS_ACROSS`] cells either way.
pub fn adapt<T>(
    mut bounds: [[f64; 2]; 2],
    fixed: bool,
    cells: [usize; 2],
    policy: Policy,
    mut solve: impl FnMut(&Grid2, usize) -> Result<Trial<T>>,
) -> Result<Adapted<T>> {
    let mut shrunk = false;
    for attempt in 0..policy.max_domains {
        let grid = Grid2::new(bounds[0], bounds[1], cells[0], cells[1])?;
        let Trial { result, zone } = solve(&grid, attempt)?;
        if zone.patches == 0 {
            return Err(Error::Geometry {
                field: "extent".into(),
                reason: format!(
                    "no grid cell is in contact (grid [{:.4e}, {:.4e}] × [{:.4e}, {:.4e}] mm, \
                     {} × {} cells): the contact is smaller than one cell; use a smaller \
                     extent or the adaptive domain",
                    bounds[0][0], bounds[0][1], bounds[1][0], bounds[1][1], cells[0], cells[1]
                ),
            });
        }
        let [bx, by] = zone.touches_border;
        if bx || by {
            if fixed {
                return Err(Error::Geometry {
                    field: "extent".into(),
                    reason: format!(
                        "the contact reaches the border of the fixed extent ({}): the load \
                         is too large for the domain; enlarge `extent` or leave it unset for \
                         the adaptive domain",
                        axes(bx, by)
                    ),
                });
            }
            for (bound, touch) in bounds.iter_mut().zip([bx, by]) {
                if touch {
                    let (c, h) = (0.5 * (bound[0] + bound[1]), 0.5 * (bound[1] - bound[0]));
                    *bound = [c - GROWTH * h, c + GROWTH * h];
                }
            }
            continue;
        }
        if !fixed
            && !shrunk
            && let Some(smaller) = zoom(policy.shrink, bounds, &zone, cells)
        {
            bounds = smaller;
            shrunk = true;
            continue;
        }
        check_resolution(&grid, &zone)?;
        return Ok(Adapted {
            result,
            zone,
            grid,
            domains: attempt + 1,
        });
    }
    Err(Error::Geometry {
        field: "extent".into(),
        reason: format!(
            "the adaptive domain did not settle on the contact in {} grids (last \
             [{:.4e}, {:.4e}] × [{:.4e}, {:.4e}] mm): the contact zone is unbounded or far \
             from the contact point; give a fixed `extent` (mm) that holds the contact",
            policy.max_domains, bounds[0][0], bounds[0][1], bounds[1][0], bounds[1][1]
        ),
    })
}

/// The smaller domain, when the policy zooms in on this zone.
fn zoom(
    shrink: Shrink,
    bounds: [[f64; 2]; 2],
    zone: &ContactZone,
    cells: [usize; 2],
) -> Option<[[f64; 2]; 2]> {
    let e = zone.extents;
    match shrink {
        Shrink::AboutOrigin { trigger, factor } => {
            let reach = [
                e[0][0].abs().max(e[0][1].abs()),
                e[1][0].abs().max(e[1][1].abs()),
            ];
            let half = [bounds[0][1], bounds[1][1]];
            if reach[0] < trigger * half[0] || reach[1] < trigger * half[1] {
                let h = [
                    (factor * reach[0]).min(half[0]),
                    (factor * reach[1]).min(half[1]),
                ];
                Some([[-h[0], h[0]], [-h[1], h[1]]])
            } else {
                None
            }
        }
        Shrink::AboutZone { trigger, margin } => {
            let fill = [
                (e[0][1] - e[0][0]) / (bounds[0][1] - bounds[0][0]),
                (e[1][1] - e[1][0]) / (bounds[1][1] - bounds[1][0]),
            ];
            if fill[0] < trigger || fill[1] < trigger {
                let mut out = bounds;
                for ((bound, ext), n) in out.iter_mut().zip(e).zip(cells) {
                    let (c, h) = (0.5 * (ext[0] + ext[1]), 0.5 * (ext[1] - ext[0]));
                    // Keep at least two cells of margin beyond the loaded cells.
                    let cell = (bound[1] - bound[0]) / n as f64;
                    let half = (margin * h).max(h + 2.0 * cell);
                    *bound = [c - half, c + half];
                }
                Some(out)
            } else {
                None
            }
        }
    }
}

fn axes(x: bool, y: bool) -> &'static str {
    match (x, y) {
        (true, true) => "x and y",
        (true, false) => "x",
        _ => "y",
    }
}

/// Refuse a contact that reaches the border of a domain that cannot grow (a gap map on
/// a free boundary). `what` names the domain, `fix` says what to do.
///
/// # Errors
/// [`Error::Geometry`] (field `extent`) when loaded cells lie on the border.
pub fn check_border(zone: &ContactZone, what: &str, fix: &str) -> Result<()> {
    let [bx, by] = zone.touches_border;
    if bx || by {
        return Err(Error::Geometry {
            field: "extent".into(),
            reason: format!(
                "the contact reaches the border of {what} ({}): the load is too large for \
                 the domain; {fix}",
                axes(bx, by)
            ),
        });
    }
    Ok(())
}

/// Refuse a zone that spans fewer than [`MIN_CELLS_ACROSS`] cells either way.
///
/// # Errors
/// [`Error::Geometry`] (field `cells`).
pub fn check_resolution(grid: &Grid2, zone: &ContactZone) -> Result<()> {
    let e = zone.extents;
    let across = [
        ((e[0][1] - e[0][0]) / grid.dx()).round() as usize,
        ((e[1][1] - e[1][0]) / grid.dy()).round() as usize,
    ];
    if across[0] < MIN_CELLS_ACROSS || across[1] < MIN_CELLS_ACROSS {
        return Err(Error::Geometry {
            field: "cells".into(),
            reason: format!(
                "the grid is too coarse for the contact: the zone spans {} × {} cells, at \
                 least {MIN_CELLS_ACROSS} are needed each way; use more cells or a smaller \
                 extent",
                across[0], across[1]
            ),
        });
    }
    Ok(())
}
