//! The half-space solver on any substitute geometry ([`GapSource`]) or gap map, with a
//! domain that adapts to the contact.

use super::operator::{Boundary, HalfSpacePlan};
use super::planner::HalfSpacePlanner;
use super::solver::{Control, HalfSpaceSolver, SolveReport, SolverOptions, Start};
use crate::error::{Error, Result, positive_as};
use crate::field::domain::{self, Policy, Shrink, Trial};
use crate::field::{ContactZone, NormalSolution};
use crate::gap::{GapMap, GapSource};
use crate::geometry::Grid2;
use crate::material::{ElasticMaterial, effective_modulus};
use crate::units::{Millimetre, Newton};
use std::sync::{Arc, Mutex, PoisonError};

pub use crate::field::domain::ZoneEstimate;

/// Options of [`Bem`].
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(
    feature = "serde",
    derive(serde::Serialize, serde::Deserialize, schemars::JsonSchema)
)]
#[cfg_attr(feature = "serde", serde(deny_unknown_fields, default))]
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
            ..SolverOptions::default()
        }
    }
}

/// What only the half-space solver gives in a [`NormalSolution`].
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct HalfSpaceDetail {
    /// The solver's record: operator applications, complementarity, force, approach.
    pub report: SolveReport,
    /// Elastic displacement of the two-body system per cell \[mm\].
    pub displacement: Vec<Millimetre>,
    /// Undeformed gap per cell \[mm\] (`+inf` where the bodies cannot meet).
    pub gap: Vec<Millimetre>,
}

/// The solution of one half-space contact: `status` is the conjugate-gradient
/// iteration's, `domains` the number of domains tried by the adaptive extent.
pub type BemSolution = NormalSolution<HalfSpaceDetail>;

/// The fields of a finished solve on `solver`'s grid.
fn solution(
    solver: &HalfSpaceSolver,
    report: SolveReport,
    gap: Vec<f64>,
    orientation: f64,
    zone: ContactZone,
    domains: usize,
) -> BemSolution {
    NormalSolution {
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
        status: report.status,
        domains,
        grid: *solver.grid(),
        pressure: solver.pressure().to_vec(),
        detail: HalfSpaceDetail {
            report,
            displacement: solver.displacement().to_vec(),
            gap,
        },
    }
}

/// The coupled elastic half-space solver for one pair of materials.
///
/// It plans each grid once: a [`HalfSpacePlanner`] behind an `Arc<Mutex<_>>` keeps the
/// plans of the domains it solved on, so repeated solves (and the same adaptive rounds)
/// reuse them. Clones share the planner; `Bem` is cheap to clone and `Send + Sync`, and
/// the lock is held only while a plan is looked up or built, not during a solve.
#[derive(Clone)]
pub struct Bem {
    body1: ElasticMaterial,
    body2: ElasticMaterial,
    options: BemOptions,
    estimate: Option<ZoneEstimate>,
    planner: Arc<Mutex<HalfSpacePlanner>>,
}

impl std::fmt::Debug for Bem {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("Bem")
            .field("body1", &self.body1)
            .field("body2", &self.body2)
            .field("options", &self.options)
            .field("estimate", &self.estimate.as_ref().map(|_| "zone estimate"))
            .field("planner", &self.planner)
            .finish()
    }
}

/// Equal materials and options (the zone estimate and the planner, a cache, do not count).
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
            estimate: None,
            planner,
        })
    }

    /// Start the adaptive domain from `estimate` (the zone's bounding box for a gap and
    /// a load, in the gap's principal frame \[mm\]) times `margin`. Without one, an
    /// adaptive solve starts from the gap's quadratic form (a Hertz ellipse); a fixed
    /// `extent` needs none.
    #[must_use]
    pub fn with_estimate(mut self, estimate: ZoneEstimate) -> Self {
        self.estimate = Some(estimate);
        self
    }

    /// The planner that holds this solver's plans (shared by its clones).
    pub fn planner(&self) -> &Arc<Mutex<HalfSpacePlanner>> {
        &self.planner
    }

    /// A free-boundary half-space solver on `grid` \[mm\] with this solver's options, on
    /// the planner's shared plan for the grid's cells and spacing (built on first use).
    /// The solver keeps its own fields, so a caller can hold it between solves and warm
    /// start ([`Start::Warm`]), as the multi-body contact element does.
    ///
    /// # Errors
    /// [`Error::InvalidInput`] for a grid the planner cannot plan.
    pub fn solver_on(&self, grid: Grid2) -> Result<HalfSpaceSolver> {
        self.solver(grid, Boundary::Free)
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
    ///   spans fewer than [`domain::MIN_CELLS_ACROSS`] cells, or the adaptive domain
    ///   cannot hold it.
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
        let report = report.require_converged()?;
        let zone = ContactZone::analyse(map.grid(), solver.pressure())?;
        if boundary == Boundary::Free {
            domain::check_border(&zone, "the gap map", "use a larger map or a smaller load")?;
        }
        domain::check_resolution(map.grid(), &zone)?;
        Ok(solution(
            &solver,
            report,
            map.values().to_vec(),
            0.0,
            zone,
            1,
        ))
    }

    /// The zone's bounding box `[[x0, x1], [y0, y1]]` \[mm\] in the principal frame:
    /// the given estimate, else the Hertz ellipse of the gap's quadratic form.
    fn estimate(&self, source: &dyn GapSource, control: Control) -> Result<[[f64; 2]; 2]> {
        if let Some(estimate) = &self.estimate {
            return estimate(source, control);
        }
        let hertz = crate::hertz::HertzPointContact::new(
            crate::hertz::PointGeometry::from_curvature(source.curvature()),
            self.body1,
            self.body2,
        )?;
        let s = match control {
            Control::Force(f) => hertz.solve_force(f)?,
            // (a line load was refused by `solve_force`/`solve_approach`)
            Control::Approach(d) | Control::LineLoad(d) => hertz.solve_approach(d)?,
        };
        let [a, b] = s.semi_axes;
        Ok([[-a, a], [-b, b]])
    }

    fn run(&self, source: &dyn GapSource, control: Control) -> Result<BemSolution> {
        let orientation = source.curvature().orientation;
        let m = self.options.margin;
        let bounds = match self.options.extent {
            Some([hx, hy]) => [[-hx, hx], [-hy, hy]],
            None => {
                let e = self.estimate(source, control)?;
                let grow = |r: [f64; 2]| {
                    let (c, h) = (0.5 * (r[0] + r[1]), 0.5 * (r[1] - r[0]));
                    [c - m * h, c + m * h]
                };
                [grow(e[0]), grow(e[1])]
            }
        };
        let policy = Policy {
            max_domains: 8,
            shrink: Shrink::AboutZone {
                trigger: 0.6,
                margin: m,
            },
        };
        let adapted = domain::adapt(
            bounds,
            self.options.extent.is_some(),
            self.options.cells,
            policy,
            |grid, _| {
                let mut gap = vec![0.0; grid.len()];
                source.sample(grid, orientation, &mut gap)?;
                let mut solver = self.solver(*grid, Boundary::Free)?;
                let report = solver.solve(&gap, control, Start::Cold)?;
                let report = report.require_converged()?;
                let zone = ContactZone::analyse(grid, solver.pressure())?;
                Ok(Trial {
                    result: (solver, report, gap),
                    zone,
                })
            },
        )?;
        let (solver, report, gap) = adapted.result;
        Ok(solution(
            &solver,
            report,
            gap,
            orientation,
            adapted.zone,
            adapted.domains,
        ))
    }
}
