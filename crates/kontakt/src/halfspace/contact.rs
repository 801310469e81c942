//! The half-space solver on any substitute geometry ([`GapSource`]) or gap map, with a
//! domain that adapts to the contact.

use super::gapmap::GapMap;
use super::operator::{Boundary, HalfSpacePlan};
use super::planner::HalfSpacePlanner;
use super::solver::{Control, HalfSpaceSolver, SolveReport, SolverOptions, Start};
use crate::error::{Error, Result, positive_as};
use crate::geometry::Grid2;
use crate::material::{ElasticMaterial, effective_modulus};
use crate::pimp::{ContactZone, GapSource, Mode, Pimp, PimpOptions};
use crate::units::{Megapascal, Millimetre, Newton};
use serde::{Deserialize, Serialize};
use std::sync::{Arc, Mutex, PoisonError};

/// Fewest loaded cells across the contact (each direction) that a solve accepts.
pub const MIN_CELLS_ACROSS: usize = 8;

/// How many domains the adaptive extent may try.
const MAX_ROUNDS: usize = 8;

/// Options of [`Bem`].
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct BemOptions {
    /// Cells `[nx, ny]` of the grid, each in 8..=4096 (default 64 × 64).
    pub cells: [usize; 2],
    /// Fixed half-extents `[x, y]` \[mm\] of the domain along the principal axes of the
    /// gap, centred on the contact point; `None` (default) adapts the domain: it starts
    /// from the PimP estimate of the zone times `margin`, grows when the contact reaches
    /// the border and shrinks when the contact fills less than 60 % of it.
    pub extent: Option<[Millimetre; 2]>,
    /// Domain half-size over the zone's half-extent in the adaptive mode, in \[1.05, 4\]
    /// (default 1.2).
    pub margin: f64,
    /// Relative residual (see [`SolverOptions::tolerance`]), default 1e-8.
    pub tolerance: f64,
    /// Most iterations per solve, >= 1 (default 1000).
    pub max_iterations: usize,
    /// Threads of the FFT passes; unset uses all cores.
    pub threads: Option<usize>,
}

impl Default for BemOptions {
    fn default() -> Self {
        BemOptions {
            cells: [64, 64],
            extent: None,
            margin: 1.2,
            tolerance: 1e-8,
            max_iterations: 1000,
            threads: None,
        }
    }
}

impl BemOptions {
    /// Check every option.
    ///
    /// # Errors
    /// [`Error::InvalidInput`] naming the option, its value and the valid range.
    pub fn validate(&self) -> Result<()> {
        for (field, n) in [("cells[0]", self.cells[0]), ("cells[1]", self.cells[1])] {
            if !(8..=4096).contains(&n) {
                return Err(Error::invalid(field, n, "8 <= cells <= 4096"));
            }
        }
        if let Some([x, y]) = self.extent {
            positive_as("extent[0]", x, "a finite half-extent > 0 mm")?;
            positive_as("extent[1]", y, "a finite half-extent > 0 mm")?;
        }
        if !(1.05..=4.0).contains(&self.margin) {
            return Err(Error::invalid("margin", self.margin, "1.05 <= margin <= 4"));
        }
        self.solver(Boundary::Free).validate()
    }

    fn solver(&self, boundary: Boundary) -> SolverOptions {
        SolverOptions {
            tolerance: self.tolerance,
            max_iterations: self.max_iterations,
            threads: self.threads,
            boundary,
        }
    }
}

/// The solution of one half-space contact.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct BemSolution {
    /// Normal force \[N\] (the sum of pressure times cell area).
    pub force: Newton,
    /// Rigid approach \[mm\] from the gap's zero level (first touch for a touching gap).
    pub approach: Millimetre,
    /// Largest pressure \[MPa\].
    pub max_pressure: Megapascal,
    /// Mean pressure over the contact area \[MPa\].
    pub mean_pressure: Megapascal,
    /// Contact area \[mm²\]: loaded cells times the cell area.
    pub contact_area: f64,
    /// Half-extents of the zone along the grid's x and y \[mm\].
    pub semi_axes: [Millimetre; 2],
    /// Angle \[rad\] from the gap source's `x` axis to the grid's `x` axis.
    pub orientation: f64,
    /// Shape of the zone in the grid frame.
    pub zone: ContactZone,
    /// The solver's outcome: convergence, iterations, residual, complementarity.
    pub report: SolveReport,
    /// Domains tried by the adaptive extent.
    pub grid_rounds: usize,
    /// The grid \[mm\].
    pub grid: Grid2,
    /// Pressure per cell \[MPa\], row-major with x fastest.
    pub pressure: Vec<Megapascal>,
    /// Elastic displacement of the two-body system per cell \[mm\].
    pub displacement: Vec<Millimetre>,
    /// Undeformed gap per cell \[mm\] (`+inf` where the bodies cannot meet).
    pub gap: Vec<Millimetre>,
}

impl BemSolution {
    fn new(
        solver: &HalfSpaceSolver,
        report: SolveReport,
        gap: Vec<f64>,
        orientation: f64,
        grid_rounds: usize,
    ) -> Result<Self> {
        let grid = *solver.grid();
        let pressure = solver.pressure().to_vec();
        let zone = ContactZone::analyse(&grid, &pressure)?;
        Ok(BemSolution {
            force: report.force,
            approach: report.approach,
            max_pressure: report.max_pressure,
            mean_pressure: if report.contact_area > 0.0 {
                report.force / report.contact_area
            } else {
                0.0
            },
            contact_area: report.contact_area,
            semi_axes: zone.half_extents(),
            orientation,
            zone,
            report,
            grid_rounds,
            grid,
            pressure,
            displacement: solver.displacement().to_vec(),
            gap,
        })
    }
}

/// The coupled elastic half-space solver for one pair of materials.
///
/// It plans each grid once: a [`HalfSpacePlanner`] behind an `Arc<Mutex<_>>` keeps the
/// plans of the domains it solved on, so repeated solves (and the same adaptive rounds)
/// reuse them. Clones share the planner; `Bem` is cheap to clone and `Send + Sync`, and
/// the lock is held only while a plan is looked up or built, not during a solve.
#[derive(Debug, Clone)]
pub struct Bem {
    body1: ElasticMaterial,
    body2: ElasticMaterial,
    options: BemOptions,
    planner: Arc<Mutex<HalfSpacePlanner>>,
}

/// Equal materials and options (the planner, a cache, does not count).
impl PartialEq for Bem {
    fn eq(&self, other: &Self) -> bool {
        self.body1 == other.body1 && self.body2 == other.body2 && self.options == other.options
    }
}

impl Bem {
    /// A solver for body 1 against body 2.
    ///
    /// # Errors
    /// [`Error::InvalidInput`] for an invalid option.
    pub fn new(
        body1: ElasticMaterial,
        body2: ElasticMaterial,
        options: BemOptions,
    ) -> Result<Self> {
        Self::with_planner(
            body1,
            body2,
            options,
            Arc::new(Mutex::new(HalfSpacePlanner::new())),
        )
    }

    /// A solver for body 1 against body 2 that takes its plans from `planner` (shared
    /// with other solvers, e.g. of other load cases on the same grids).
    ///
    /// # Errors
    /// [`Error::InvalidInput`] for an invalid option.
    pub fn with_planner(
        body1: ElasticMaterial,
        body2: ElasticMaterial,
        options: BemOptions,
        planner: Arc<Mutex<HalfSpacePlanner>>,
    ) -> Result<Self> {
        options.validate()?;
        Ok(Bem {
            body1,
            body2,
            options,
            planner,
        })
    }

    /// The planner that holds this solver's plans (shared by its clones).
    pub fn planner(&self) -> &Arc<Mutex<HalfSpacePlanner>> {
        &self.planner
    }

    /// The half-space solver on `grid` \[mm\], on the planner's plan for its cells and
    /// spacing.
    fn solver(&self, grid: Grid2, boundary: Boundary) -> Result<HalfSpaceSolver> {
        let options = self.options.solver(boundary);
        let plan: Arc<HalfSpacePlan> = self
            .planner
            .lock()
            // A panic while planning leaves the cache consistent (a plan is inserted
            // whole or not at all): keep using it.
            .unwrap_or_else(PoisonError::into_inner)
            .plan(&grid, self.e_star(), boundary, options.threads)?;
        HalfSpaceSolver::with_plan_on(grid, plan, options)
    }

    /// The options.
    pub fn options(&self) -> &BemOptions {
        &self.options
    }

    /// The contact modulus E* \[MPa\].
    pub fn e_star(&self) -> f64 {
        effective_modulus(&self.body1, &self.body2)
    }

    /// Solve `source` under the normal force `force` \[N\].
    ///
    /// # Errors
    /// - [`Error::InvalidInput`] for a non-positive force.
    /// - [`Error::Geometry`] when the contact reaches the border of a fixed domain,
    ///   spans fewer than [`MIN_CELLS_ACROSS`] cells, or the adaptive domain cannot hold it.
    /// - [`Error::NotConverged`] when the solver does not reach its tolerance.
    pub fn solve_force(&self, source: &dyn GapSource, force: Newton) -> Result<BemSolution> {
        positive_as("force", force, "a finite force > 0 N")?;
        self.run(source, Control::Force(force))
    }

    /// Solve `source` for the rigid approach `approach` \[mm\] from first touch.
    ///
    /// # Errors
    /// As [`Bem::solve_force`], for `approach`.
    pub fn solve_approach(
        &self,
        source: &dyn GapSource,
        approach: Millimetre,
    ) -> Result<BemSolution> {
        positive_as("approach", approach, "a finite approach > 0 mm")?;
        self.run(source, Control::Approach(approach))
    }

    /// Solve a gap map on its own grid (no adaptation).
    ///
    /// # Errors
    /// - As [`HalfSpaceSolver::solve`].
    /// - [`Error::Geometry`] when, on a free boundary, the contact reaches the border of
    ///   the map (the load is too large for the domain) or spans too few cells.
    /// - [`Error::NotConverged`] when the solver does not reach its tolerance.
    pub fn solve_map(
        &self,
        map: &GapMap,
        control: Control,
        boundary: Boundary,
    ) -> Result<BemSolution> {
        let mut solver = self.solver(*map.grid(), boundary)?;
        let report = solver.solve(map.values(), control, Start::Cold)?;
        HalfSpaceSolver::require_converged(report)?;
        let solution = BemSolution::new(&solver, report, map.values().to_vec(), 0.0, 1)?;
        if boundary == Boundary::Free {
            check_border(
                &solution,
                "the gap map",
                "use a larger map or a smaller load",
            )?;
        }
        check_resolution(&solution)?;
        Ok(solution)
    }

    /// The zone's bounding box `[[x0, x1], [y0, y1]]` \[mm\] in the principal frame, from
    /// the (corrected) PimP estimate.
    fn estimate(&self, source: &dyn GapSource, control: Control) -> Result<[[f64; 2]; 2]> {
        let pimp = Pimp::new(
            self.body1,
            self.body2,
            PimpOptions {
                mode: Mode::Corrected,
                cells: [48, 48],
                ..PimpOptions::default()
            },
        )?;
        let s = match control {
            Control::Force(f) => pimp.solve_force(source, f)?,
            Control::Approach(d) => pimp.solve_approach(source, d)?,
        };
        Ok(s.zone.extents)
    }

    fn run(&self, source: &dyn GapSource, control: Control) -> Result<BemSolution> {
        let orientation = source.curvature().orientation;
        let [nx, ny] = self.options.cells;
        let mut bounds = match self.options.extent {
            Some([hx, hy]) => [[-hx, hx], [-hy, hy]],
            None => {
                let e = self.estimate(source, control)?;
                let m = self.options.margin;
                let grow = |r: [f64; 2]| {
                    let (c, h) = (0.5 * (r[0] + r[1]), 0.5 * (r[1] - r[0]));
                    [c - m * h, c + m * h]
                };
                [grow(e[0]), grow(e[1])]
            }
        };
        let mut shrunk = false;
        for round in 1..=MAX_ROUNDS {
            let grid = Grid2::new(bounds[0], bounds[1], nx, ny)?;
            let mut gap = vec![0.0; grid.len()];
            source.sample(&grid, orientation, &mut gap)?;
            let mut solver = self.solver(grid, Boundary::Free)?;
            let report = solver.solve(&gap, control, Start::Cold)?;
            HalfSpaceSolver::require_converged(report)?;
            let solution = BemSolution::new(&solver, report, gap, orientation, round)?;
            if self.options.extent.is_some() {
                check_border(
                    &solution,
                    "the fixed extent",
                    "enlarge `extent` or leave it unset",
                )?;
                check_resolution(&solution)?;
                return Ok(solution);
            }
            let z = &solution.zone;
            let [bx, by] = z.touches_border;
            if bx || by {
                // Grow about the domain centre in the direction(s) that touch.
                for (axis, touch) in [(0, bx), (1, by)] {
                    if touch {
                        let (c, h) = (
                            0.5 * (bounds[axis][0] + bounds[axis][1]),
                            0.5 * (bounds[axis][1] - bounds[axis][0]),
                        );
                        bounds[axis] = [c - 1.6 * h, c + 1.6 * h];
                    }
                }
                continue;
            }
            let fill = [
                (z.extents[0][1] - z.extents[0][0]) / (bounds[0][1] - bounds[0][0]),
                (z.extents[1][1] - z.extents[1][0]) / (bounds[1][1] - bounds[1][0]),
            ];
            if !shrunk && (fill[0] < 0.6 || fill[1] < 0.6) {
                shrunk = true;
                let m = self.options.margin;
                for ((bound, ext), cells) in
                    bounds.iter_mut().zip(z.extents).zip(self.options.cells)
                {
                    let (c, h) = (0.5 * (ext[0] + ext[1]), 0.5 * (ext[1] - ext[0]));
                    // Keep at least two cells of margin beyond the loaded cells.
                    let cell = (bound[1] - bound[0]) / cells as f64;
                    let half = (m * h).max(h + 2.0 * cell);
                    *bound = [c - half, c + half];
                }
                continue;
            }
            check_resolution(&solution)?;
            return Ok(solution);
        }
        Err(Error::Geometry {
            field: "extent".into(),
            reason: format!(
                "the adaptive domain did not settle on the contact after {MAX_ROUNDS} domains; \
                 give a fixed `extent` (mm) that holds the contact"
            ),
        })
    }
}

fn check_border(solution: &BemSolution, what: &str, fix: &str) -> Result<()> {
    let [bx, by] = solution.zone.touches_border;
    if bx || by {
        return Err(Error::Geometry {
            field: "extent".into(),
            reason: format!(
                "the contact reaches the border of {what} ({}): the load is too large for \
                 the domain; {fix}",
                match (bx, by) {
                    (true, true) => "x and y",
                    (true, false) => "x",
                    _ => "y",
                }
            ),
        });
    }
    Ok(())
}

fn check_resolution(solution: &BemSolution) -> Result<()> {
    let g = &solution.grid;
    let z = &solution.zone;
    let across = [
        ((z.extents[0][1] - z.extents[0][0]) / g.dx()).round() as usize,
        ((z.extents[1][1] - z.extents[1][0]) / g.dy()).round() as usize,
    ];
    if across[0] < MIN_CELLS_ACROSS || across[1] < MIN_CELLS_ACROSS {
        return Err(Error::Geometry {
            field: "cells".into(),
            reason: format!(
                "the grid is too coarse for the contact: it spans {} x {} cells, at least \
                 {MIN_CELLS_ACROSS} are needed each way; use more cells or a smaller extent",
                across[0], across[1]
            ),
        });
    }
    Ok(())
}
