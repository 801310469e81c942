//! Bearing sweeps: a sweep whose base case is a whole bearing (`method = "bearing"`) runs
//! its cases through a planned solver instead of reading and reporting each case.
//!
//! - **Load parameters** (every key one of `load.force_n[i]` N, `load.moment_nmm[i]` N·mm,
//!   `load.prescribed.dx_mm|dy_mm|dz_mm` mm, `load.prescribed.tilt_x_rad|tilt_y_rad` rad,
//!   numbers only) are set on the load directly: no TOML is edited or read per case.
//! - **Other parameters** (geometry, clearance, profile, `bearing.type`, ...): when one of
//!   them changes from one case to the next, the case is read from the edited base table
//!   as any sweep case is; the bearing is planned again only when its `[bearing]` or
//!   `[speed]` table differs from the planned one.
//! - **Warm starts**: the cases run in blocks of [`BLOCK`] consecutive cases (aligned to
//!   case indices, so the blocks and hence the numbers do not depend on the thread count);
//!   a block plans its bearing once and solves every case from the last converged
//!   equilibrium, as [`crate::BearingModel`] does (the first case of a block, a case after
//!   every element lifted off and an unloaded case start from the closed forms). A warm
//!   solve reaches the same equilibrium as the cold `kontakt bearing` of that case to the
//!   solver's tolerance (relative residual 1e-11); only `solver.iterations` differs.
//! - **Rows**: one per case, a fixed set of numeric columns ([`COLUMNS`]), the same for
//!   every row (null where a value does not apply). A case whose elements all lift off is
//!   status `lifted_off` with zero force and its message in `warnings`, not an error.
//!
//! - **After the solve** a row goes through the report's own post-solve path
//!   (`crate::bearing_post`, planned once per block): raceway pressures, rating
//!   (`[bearing.rating]`) with its warnings, and the validity check of the most loaded
//!   contacts, so that the row's warnings and refusals are the report's.
//!
//! A case allocates nothing on the way (the solver and the post own their buffers; a row is
//! `Copy` data but for its warnings and error texts, which exist only when there are any).

use super::table::Status;
use super::{Sweep, ValueKind};
use crate::bearing_case::{
    BallSpec, BearingCase, BearingLoadSpec, BearingSpec, GrooveKeys, Planned, map_ball_field,
    map_load, plan, ring_load, solver_warnings,
};
use crate::bearing_post::{BallPost, Post, RollerPost, applied_moment};
use crate::bearing_slices::SliceSolver;
use crate::case::Case;
use arrow_array::{ArrayRef, BooleanArray, Float64Array, Int64Array, StringArray};
use kontakt::solve::SolveStatus;
use kontakt_bearing::ball_equilibrium::{BallBearingSolver, BallSolution};
use kontakt_bearing::ball_speed::BallSpeedSolver;
use kontakt_bearing::equilibrium::{RingLoad, RollerSolution};
use kontakt_bearing::geometry::BallBearing;
use kontakt_bearing::roller_equilibrium::RibContactSolver;
use std::ops::Range;
use std::sync::Arc;

/// Cases per warm-start block: each block plans its bearing and starts cold once.
pub const BLOCK: u64 = 256;

/// A load component a parameter sets directly.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Slot {
    /// `load.force_n[i]`, N.
    Force(usize),
    /// `load.moment_nmm[i]`, N·mm.
    Moment(usize),
    /// `load.prescribed.<DISPLACEMENT_NAMES[i]>`, mm or rad.
    Prescribed(usize),
}

impl Slot {
    fn parse(key: &str) -> Option<Slot> {
        let index = |rest: &str, n: usize| {
            let i: usize = rest.strip_prefix('[')?.strip_suffix(']')?.parse().ok()?;
            (i < n).then_some(i)
        };
        if let Some(rest) = key.strip_prefix("load.force_n") {
            return index(rest, 3).map(Slot::Force);
        }
        if let Some(rest) = key.strip_prefix("load.moment_nmm") {
            return index(rest, 2).map(Slot::Moment);
        }
        let name = key.strip_prefix("load.prescribed.")?;
        kontakt_bearing::equilibrium::DISPLACEMENT_NAMES
            .iter()
            .position(|n| *n == name)
            .map(Slot::Prescribed)
    }

    fn set(self, load: &mut BearingLoadSpec, v: f64) {
        match self {
            Slot::Force(i) => load.force_n[i] = v,
            Slot::Moment(i) => load.moment_nmm[i] = v,
            Slot::Prescribed(i) => {
                let p = &mut load.prescribed;
                *[
                    &mut p.dx_mm,
                    &mut p.dy_mm,
                    &mut p.dz_mm,
                    &mut p.tilt_x_rad,
                    &mut p.tilt_y_rad,
                ][i] = Some(v);
            }
        }
    }
}

/// How a bearing sweep's parameters reach the solver.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct BearingPlan {
    /// Per parameter: the load slots it sets, or `None` for a parameter read through the
    /// case reader.
    direct: Vec<Option<Vec<Slot>>>,
    /// The parameters read through the case reader.
    read: Vec<usize>,
}

impl BearingPlan {
    /// The plan of `sweep`'s parameters (its base case is a bearing case).
    pub(crate) fn new(sweep: &Sweep) -> Self {
        let mut direct = Vec::with_capacity(sweep.parameters.len());
        let mut read = Vec::new();
        for (p, param) in sweep.parameters.iter().enumerate() {
            let numeric = matches!(param.kind, ValueKind::Float | ValueKind::Integer);
            let slots: Option<Vec<Slot>> =
                param.keys.iter().map(|k| Slot::parse(&k.text)).collect();
            match slots.filter(|_| numeric) {
                Some(s) => direct.push(Some(s)),
                None => {
                    direct.push(None);
                    read.push(p);
                }
            }
        }
        BearingPlan { direct, read }
    }
}

/// What a solved bearing case gives: the row's numbers.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct BearingOut {
    bearing_type: &'static str,
    elements: usize,
    /// `(δx, δy, δz, θx, θy)`, mm and rad.
    displacement: [f64; 5],
    /// The carried load `(Fx, Fy, Fz, Mx, My)`, N and N·mm.
    load: [f64; 5],
    max_element_load_n: f64,
    loaded_elements: usize,
    max_rib_load_n: Option<f64>,
    max_load_per_length_n_per_mm: Option<f64>,
    max_pressure_mpa: Option<[f64; 2]>,
    load_zone_epsilon: Option<f64>,
    /// The diagonal of the stiffness matrix: N/mm (x, y, z), N·mm/rad (tilts).
    stiffness: [f64; 5],
    /// The rating (`[bearing.rating]`, the report's `rating`): ISO 76's static safety from
    /// the pressure and C0/P0, ISO 281's L10 and ISO/TS 16281's L10r (Mrev).
    static_safety_from_pressure: Option<f64>,
    static_safety: Option<f64>,
    l10_mrev: Option<f64>,
    l10r_mrev: Option<f64>,
    converged: bool,
    termination: &'static str,
    iterations: usize,
    residual: f64,
}

/// One case of a bearing sweep.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct BearingRow {
    pub(crate) status: Status,
    pub(crate) error: Option<String>,
    out: Option<BearingOut>,
    warnings: Vec<String>,
}

impl BearingRow {
    fn failed(status: Status, error: String) -> Self {
        BearingRow {
            status,
            error: Some(error),
            out: None,
            warnings: Vec::new(),
        }
    }
}

/// The output columns of a bearing sweep, after `case`, the parameters, `status` and
/// `error`, with their units.
pub const COLUMNS: [(&str, &str); 34] = [
    (
        "bearing_type",
        "cylindrical, tapered, thrust, deep_groove_ball, angular_contact_ball",
    ),
    ("elements", "number of rollers or balls"),
    ("displacement_mm[0]", "inner-ring displacement δx, mm"),
    ("displacement_mm[1]", "δy, mm"),
    ("displacement_mm[2]", "δz (axial), mm"),
    ("tilt_rad[0]", "inner-ring tilt θx, rad"),
    ("tilt_rad[1]", "θy, rad"),
    (
        "force_n[0]",
        "carried force Fx (reaction where prescribed), N",
    ),
    ("force_n[1]", "Fy, N"),
    ("force_n[2]", "Fz, N"),
    ("moment_nmm[0]", "carried moment Mx, N·mm"),
    ("moment_nmm[1]", "My, N·mm"),
    (
        "max_element_load_n",
        "largest roller (outer raceway) or ball load, N",
    ),
    ("loaded_elements", "elements with a load > 0"),
    ("max_rib_load_n", "largest rib load, N (roller bearings)"),
    (
        "max_load_per_length_n_per_mm",
        "largest slice load per length, N/mm (rollers)",
    ),
    (
        "max_inner_pressure_mpa",
        "largest raceway pressure, inner raceway, MPa",
    ),
    (
        "max_outer_pressure_mpa",
        "largest raceway pressure, outer raceway, MPa",
    ),
    (
        "load_zone_epsilon",
        "load-zone parameter ε (radial roller bearings)",
    ),
    ("stiffness_x_n_per_mm", "stiffness matrix diagonal, x, N/mm"),
    ("stiffness_y_n_per_mm", "y, N/mm"),
    ("stiffness_z_n_per_mm", "z, N/mm"),
    ("stiffness_tilt_x_nmm_per_rad", "tilt about x, N·mm/rad"),
    ("stiffness_tilt_y_nmm_per_rad", "tilt about y, N·mm/rad"),
    (
        "solver.converged",
        "whether the equilibrium reached the tolerance",
    ),
    ("solver.termination", "converged or stagnated"),
    ("solver.iterations", "Newton iterations"),
    ("solver.residual", "largest relative residual"),
    (
        "warnings",
        "the report's warnings joined by \"; \" (null: none)",
    ),
    ("lifted_off", "every element lifted off (zero force)"),
    (
        "static_safety_from_pressure",
        "ISO 76 static safety from the largest raceway pressure (null without load)",
    ),
    (
        "static_safety",
        "ISO 76 static safety C0/P0 (null without bearing.rating.static_n or load)",
    ),
    (
        "l10_mrev",
        "ISO 281 basic rating life L10, 1e6 rev (null without bearing.rating.dynamic_n or load)",
    ),
    (
        "l10r_mrev",
        "ISO/TS 16281 reference rating life L10r, 1e6 rev (null without bearing.rating.dynamic_n or load)",
    ),
];

/// A bearing planned for a block of cases: the solver, the warm start and what the rows
/// need of the case.
struct BlockModel {
    case: BearingCase,
    label: &'static str,
    planned: Planned,
    last: Option<[f64; 5]>,
    /// What follows the equilibrium (pressures, rating, contact sizes), planned once, the
    /// report's own ([`crate::bearing_post`]); its error is the row's after the solve, as
    /// in the report.
    post: Result<PostPlan, kontakt::Error>,
}

/// The post-solve plan of a block's bearing.
enum PostPlan {
    Roller(RollerPost),
    Ball(Box<BallPost>),
}

/// A row's failure: its status and error text.
type Failure = (Status, String);

impl BlockModel {
    fn new(case: BearingCase) -> kontakt::Result<Self> {
        let (planned, label) = plan(&case)?;
        let roller = |b: &kontakt_bearing::geometry::RollerBearing| {
            let spec = match &case.bearing {
                BearingSpec::Cylindrical(s) | BearingSpec::Tapered(s) | BearingSpec::Thrust(s) => {
                    s.rating.as_ref()
                }
                _ => None,
            };
            RollerPost::new(b, spec).map(PostPlan::Roller)
        };
        let ball = |b: &BallBearing, spec: &BallSpec, keys: &GrooveKeys| {
            BallPost::new(b, spec.rating.as_ref(), [keys.inner, keys.outer])
                .map(|p| PostPlan::Ball(Box::new(p)))
        };
        let post = match &planned {
            Planned::Roller(s) => roller(s.bearing()),
            Planned::Coupled(s) => roller(s.bearing()),
            Planned::RibRoller(s) => roller(s.bearing()),
            Planned::Ball { solver, spec, keys } => ball(solver.bearing(), spec, keys),
            Planned::BallAtSpeed { solver, spec, keys } => ball(solver.bearing(), spec, keys),
        };
        Ok(BlockModel {
            case,
            label,
            planned,
            last: None,
            post,
        })
    }

    /// Solve `load` from the last equilibrium (the closed forms for an unloaded case, as
    /// [`crate::BearingModel`]) and make its row.
    fn solve(&mut self, l: &BearingLoadSpec) -> BearingRow {
        let ring = match ring_load(l) {
            Ok(r) => r,
            Err(e) => return BearingRow::failed(Status::Invalid, e.to_string()),
        };
        let start = if crate::bearing_model::unloaded(l) {
            None
        } else {
            self.last
        };
        let label = self.label;
        let post = &mut self.post;
        let same = |e| e;
        let solved = match &mut self.planned {
            Planned::Roller(solver) => element_row(solver, label, &ring, start, post, &same),
            Planned::Coupled(solver) => {
                element_row(solver.as_mut(), label, &ring, start, post, &same)
            }
            Planned::RibRoller(solver) => {
                element_row(solver.as_mut(), label, &ring, start, post, &same)
            }
            Planned::Ball { solver, spec, keys } => {
                let f = {
                    let b = solver.bearing();
                    [b.inner_osculation, b.outer_osculation]
                };
                let field = |e| map_ball_field(e, spec, keys, f);
                element_row(solver, label, &ring, start, post, &field)
            }
            Planned::BallAtSpeed { solver, spec, keys } => {
                let f = {
                    let b = solver.bearing();
                    [b.inner_osculation, b.outer_osculation]
                };
                let field = |e| map_ball_field(e, spec, keys, f);
                element_row(solver.as_mut(), label, &ring, start, post, &field)
            }
        };
        let (out, mut warnings) = match solved {
            Ok(s) => s,
            Err((status, e)) => return BearingRow::failed(status, e),
        };
        // the ISO roller model at speed: first among the warnings, as in the report
        if matches!(self.planned, Planned::Roller(_) | Planned::Coupled(_))
            && let Some(w) = crate::bearing_case::iso_speed_warning(&self.case.speed)
        {
            warnings.insert(0, w);
        }
        if let Some(name) = non_finite(&out) {
            return BearingRow::failed(
                Status::Invalid,
                format!(
                    "{name}: the result is not finite: the inputs are beyond what f64 arithmetic holds for this model"
                ),
            );
        }
        let lifted = out.max_element_load_n == 0.0;
        self.last = (!lifted).then_some(out.displacement);
        BearingRow {
            status: if lifted {
                Status::LiftedOff
            } else if warnings.is_empty() {
                Status::Ok
            } else {
                Status::Warning
            },
            error: None,
            out: Some(out),
            warnings,
        }
    }
}

/// `Element::solve_at` and `Element::status` of a solver with `solve` and `solve_from`
/// whose solution has `status` and `note`.
macro_rules! warm_solve {
    () => {
        fn solve_at(
            &mut self,
            ring: &RingLoad,
            start: Option<[f64; 5]>,
        ) -> kontakt::Result<Self::Solution> {
            match start {
                Some(u) => self.solve_from(ring, u),
                None => self.solve(ring),
            }
        }

        fn status(sol: &Self::Solution) -> (&SolveStatus, Option<&'static str>) {
            (&sol.status, sol.note)
        }
    };
}

/// A planned solver of a sweep's block: a roller bearing (either slice model) or a ball
/// bearing.
trait Element {
    type Solution;
    /// Solve from `start` (the closed forms when `None`).
    fn solve_at(
        &mut self,
        ring: &RingLoad,
        start: Option<[f64; 5]>,
    ) -> kontakt::Result<Self::Solution>;
    /// The solver's status and note.
    fn status(sol: &Self::Solution) -> (&SolveStatus, Option<&'static str>);
    /// The post-solve path of the report ([`crate::bearing_post`]).
    fn post(&self, sol: &Self::Solution, a: PostArgs<'_>) -> kontakt::Result<Post>;
    /// The row's numbers but for the post's.
    fn out(&self, label: &'static str, sol: &Self::Solution) -> BearingOut;
}

/// The row of a case: the solve from `start`, the solver's warnings (a failure to
/// converge is the row's `failed`), then the one post-solve path of the report with the
/// validity check of its contacts as [`crate::validity::checked`] makes it.
fn element_row<E: Element>(
    solver: &mut E,
    label: &'static str,
    ring: &RingLoad,
    start: Option<[f64; 5]>,
    post: &mut Result<PostPlan, kontakt::Error>,
    field: &dyn Fn(kontakt::Error) -> kontakt::Error,
) -> Result<(BearingOut, Vec<String>), Failure> {
    let invalid = |e: kontakt::Error| (Status::Invalid, e.to_string());
    let sol = solver
        .solve_at(ring, start)
        .map_err(|e| invalid(map_load(e)))?;
    let (status, note) = E::status(&sol);
    let mut warnings =
        solver_warnings(status, note).map_err(|e| (Status::Failed, e.to_string()))?;
    let plan = post.as_mut().map_err(|e| invalid(e.clone()))?;
    let args = PostArgs {
        plan,
        moment: applied_moment(ring),
        warnings: &mut warnings,
        field,
    };
    let post = solver.post(&sol, args).map_err(invalid)?;
    post.check_sizes(&mut warnings).map_err(invalid)?;
    let r = &post.rating;
    let out = BearingOut {
        max_pressure_mpa: Some(post.max_pressure_mpa),
        static_safety_from_pressure: r.static_safety_from_pressure,
        static_safety: r.static_safety,
        l10_mrev: r.l10_mrev,
        l10r_mrev: r.l10r_mrev,
        ..solver.out(label, &sol)
    };
    Ok((out, warnings))
}

/// What a row's post takes besides the solution: the plan, the applied moment (N·mm), the
/// row's warnings and the case key of a geometry error (`field`).
struct PostArgs<'a> {
    plan: &'a mut PostPlan,
    moment: f64,
    warnings: &'a mut Vec<String>,
    field: &'a dyn Fn(kontakt::Error) -> kontakt::Error,
}

impl PostPlan {
    /// The roller post, or an error for a post planned for a ball bearing (a defect: the
    /// plan makes the solver and its post together).
    fn roller(&mut self) -> kontakt::Result<&mut RollerPost> {
        match self {
            PostPlan::Roller(p) => Ok(p),
            PostPlan::Ball(_) => Err(wrong_post("roller")),
        }
    }

    /// The ball post (as [`PostPlan::roller`]).
    fn ball(&mut self) -> kontakt::Result<&mut BallPost> {
        match self {
            PostPlan::Ball(p) => Ok(p),
            PostPlan::Roller(_) => Err(wrong_post("ball")),
        }
    }
}

/// A post planned for another bearing type.
fn wrong_post(label: &str) -> kontakt::Error {
    kontakt::Error::invalid(
        "bearing.type",
        label,
        "the bearing type the sweep's block was planned for",
    )
}

impl<S: SliceSolver> Element for S {
    type Solution = RollerSolution;

    warm_solve!();

    fn post(&self, sol: &RollerSolution, a: PostArgs<'_>) -> kontakt::Result<Post> {
        a.plan
            .roller()?
            .run(self, sol, a.moment, a.warnings, |_, _, _, _, _| {})
    }

    fn out(&self, label: &'static str, sol: &RollerSolution) -> BearingOut {
        let ns = self.bearing().slices;
        let width = self.bearing().effective_length_mm / ns as f64;
        let per_length = self.slice_loads().iter().copied().fold(0.0, f64::max) / width;
        let rollers = self.roller_loads();
        let rib = rollers.iter().map(|r| r.rib_n).fold(0.0, f64::max);
        let loaded = rollers.iter().filter(|r| r.outer_n > 0.0).count();
        roller_row_out(label, sol, [rollers.len(), loaded], rib, per_length)
    }
}

/// A roller model's row numbers from its solution `sol`: `[elements, loaded elements]`,
/// the largest rib load (N) and slice load per length (N/mm).
fn roller_row_out(
    label: &'static str,
    sol: &RollerSolution,
    elements: [usize; 2],
    rib: f64,
    per_length: f64,
) -> BearingOut {
    BearingOut {
        bearing_type: label,
        elements: elements[0],
        displacement: sol.displacement,
        load: sol.load,
        max_element_load_n: sol.max_roller_load_n,
        loaded_elements: elements[1],
        max_rib_load_n: Some(rib),
        max_load_per_length_n_per_mm: Some(per_length),
        load_zone_epsilon: sol.load_zone,
        stiffness: std::array::from_fn(|i| sol.stiffness[i][i]),
        ..status_out(&sol.status)
    }
}

/// The rib-contact roller model (`roller_model = "rib_contact"`): the cup and cone slices
/// each with their own loads, the rib a Hertz contact.
impl Element for RibContactSolver {
    type Solution = RollerSolution;

    warm_solve!();

    fn post(&self, sol: &RollerSolution, a: PostArgs<'_>) -> kontakt::Result<Post> {
        a.plan
            .roller()?
            .run_rib(self, sol, a.moment, a.warnings, |_, _, _, _, _| {})
    }

    fn out(&self, label: &'static str, sol: &RollerSolution) -> BearingOut {
        let b = self.bearing();
        let width = b.effective_length_mm / b.slices as f64;
        let per_length = self
            .cup_slice_loads()
            .iter()
            .chain(self.cone_slice_loads())
            .copied()
            .fold(0.0, f64::max)
            / width;
        let rollers = self.roller_loads();
        let loaded = rollers.iter().filter(|r| r.outer_n > 0.0).count();
        let rib = self.max_rib_load_n();
        roller_row_out(label, sol, [rollers.len(), loaded], rib, per_length)
    }
}

impl Element for BallBearingSolver {
    type Solution = BallSolution;

    warm_solve!();

    fn post(&self, sol: &BallSolution, a: PostArgs<'_>) -> kontakt::Result<Post> {
        let loads = self.ball_loads().iter().map(|q| q.load_n);
        let q = sol.max_ball_load_n;
        let b = self.bearing();
        a.plan
            .ball()?
            .run(b, sol, loads, [q, q], a.moment, a.warnings, a.field)
    }

    fn out(&self, label: &'static str, sol: &BallSolution) -> BearingOut {
        ball_out(label, sol, self.ball_loads().iter().map(|b| b.load_n))
    }
}

/// A ball bearing at speed (`[speed]`, the outer raceway controlling): the balls' inner
/// contact loads in the life, each raceway's contact sized with its own largest load, as
/// the report.
impl Element for BallSpeedSolver {
    type Solution = BallSolution;

    warm_solve!();

    fn post(&self, sol: &BallSolution, a: PostArgs<'_>) -> kontakt::Result<Post> {
        let balls = self.ball_loads();
        let q_max = balls.iter().fold([0.0_f64; 2], |m, q| {
            [m[0].max(q.inner_load_n), m[1].max(q.outer_load_n)]
        });
        let loads = balls.iter().map(|q| q.inner_load_n);
        let b = self.bearing();
        a.plan
            .ball()?
            .run(b, sol, loads, q_max, a.moment, a.warnings, a.field)
    }

    fn out(&self, label: &'static str, sol: &BallSolution) -> BearingOut {
        ball_out(label, sol, self.ball_loads().iter().map(|b| b.inner_load_n))
    }
}

/// The solver status part of a row (the rest filled by the caller).
fn status_out(s: &SolveStatus) -> BearingOut {
    BearingOut {
        bearing_type: "",
        elements: 0,
        displacement: [0.0; 5],
        load: [0.0; 5],
        max_element_load_n: 0.0,
        loaded_elements: 0,
        max_rib_load_n: None,
        max_load_per_length_n_per_mm: None,
        max_pressure_mpa: None,
        load_zone_epsilon: None,
        stiffness: [0.0; 5],
        static_safety_from_pressure: None,
        static_safety: None,
        l10_mrev: None,
        l10r_mrev: None,
        converged: s.converged(),
        termination: s.termination.as_str(),
        iterations: s.iterations,
        residual: s.residual,
    }
}

/// The column of the first number of `o` that is not finite.
fn non_finite(o: &BearingOut) -> Option<&'static str> {
    let opt = |v: Option<f64>| v.unwrap_or(0.0);
    let p = o.max_pressure_mpa.unwrap_or([0.0; 2]);
    let values = [
        o.displacement[0],
        o.displacement[1],
        o.displacement[2],
        o.displacement[3],
        o.displacement[4],
        o.load[0],
        o.load[1],
        o.load[2],
        o.load[3],
        o.load[4],
        o.max_element_load_n,
        opt(o.max_rib_load_n),
        opt(o.max_load_per_length_n_per_mm),
        p[0],
        p[1],
        opt(o.load_zone_epsilon),
        o.stiffness[0],
        o.stiffness[1],
        o.stiffness[2],
        o.stiffness[3],
        o.stiffness[4],
        o.residual,
        opt(o.static_safety_from_pressure),
        opt(o.static_safety),
        opt(o.l10_mrev),
        opt(o.l10r_mrev),
    ];
    // the numeric columns in COLUMNS order, skipping bearing_type, elements (integers),
    // loaded_elements, the solver's flags, the warnings and lifted_off
    const NAMES: [usize; 26] = [
        2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 14, 15, 16, 17, 18, 19, 20, 21, 22, 23, 27, 30, 31, 32,
        33,
    ];
    values
        .iter()
        .zip(NAMES)
        .find(|(v, _)| !v.is_finite())
        .map(|(_, c)| COLUMNS[c].0)
}

/// What one worker keeps from case to case within a block.
struct Worker {
    /// The value indices of the parameters read through the case reader, for the case
    /// the model was made for.
    read_at: Vec<u64>,
    /// The model, or the error of reading or planning the case.
    model: Result<BlockModel, String>,
}

impl Sweep {
    /// The rows of cases `range` of a bearing sweep, computed in parallel blocks of
    /// [`BLOCK`] cases on the current rayon pool, in case order; `on_case` after each.
    pub(crate) fn bearing_rows(
        &self,
        plan: &BearingPlan,
        range: Range<u64>,
        on_case: &(dyn Fn() + Sync),
    ) -> Vec<BearingRow> {
        use rayon::prelude::*;
        let mut blocks = Vec::new();
        let mut start = range.start;
        while start < range.end {
            let end = ((start / BLOCK + 1) * BLOCK).min(range.end);
            blocks.push(start..end);
            start = end;
        }
        let per_block: Vec<Vec<BearingRow>> = blocks
            .into_par_iter()
            .map(|b| self.bearing_block(plan, b, on_case))
            .collect();
        per_block.into_iter().flatten().collect()
    }

    /// The rows of one block, one case after the other with warm starts.
    fn bearing_block(
        &self,
        plan: &BearingPlan,
        block: Range<u64>,
        on_case: &(dyn Fn() + Sync),
    ) -> Vec<BearingRow> {
        let mut rows = Vec::with_capacity((block.end - block.start) as usize);
        let mut worker: Option<Worker> = None;
        for i in block {
            rows.push(self.bearing_case(plan, &mut worker, i));
            on_case();
        }
        rows
    }

    /// Case `i` of a bearing sweep (never panics: a panic of the solver becomes status
    /// `panic`, and the model is planned again for the next case).
    fn bearing_case(&self, plan: &BearingPlan, worker: &mut Option<Worker>, i: u64) -> BearingRow {
        let current = worker.as_ref().is_some_and(|w| {
            plan.read
                .iter()
                .zip(&w.read_at)
                .all(|(&p, &j)| self.value_index(p, i) == j)
        });
        if !current {
            let read_at = plan.read.iter().map(|&p| self.value_index(p, i)).collect();
            let previous = worker.take().and_then(|w| w.model.ok());
            *worker = Some(Worker {
                read_at,
                model: self.bearing_model(i, previous),
            });
        }
        let Some(Worker {
            model: Ok(model), ..
        }) = worker
        else {
            let error = match worker {
                Some(Worker { model: Err(e), .. }) => e.clone(),
                _ => "no model".to_string(),
            };
            return BearingRow::failed(Status::Invalid, error);
        };
        let mut load = model.case.load;
        for (p, slots) in plan.direct.iter().enumerate() {
            if let Some(slots) = slots {
                let v = self.parameters[p].values.get(self.value_index(p, i));
                let v = v
                    .as_float()
                    .or_else(|| v.as_integer().map(|n| n as f64))
                    .unwrap_or(f64::NAN);
                for s in slots {
                    s.set(&mut load, v);
                }
            }
        }
        let run = std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| model.solve(&load)));
        run.unwrap_or_else(|payload| {
            *worker = None;
            let msg = payload
                .downcast_ref::<&str>()
                .map(|s| (*s).to_string())
                .or_else(|| payload.downcast_ref::<String>().cloned())
                .unwrap_or_else(|| "unknown panic".into());
            BearingRow::failed(Status::Panic, format!("panic: {msg}"))
        })
    }

    /// The model of case `i`, read from the edited base table; `previous` is kept (with
    /// its warm start) when its `[bearing]` table is the same.
    fn bearing_model(&self, i: u64, previous: Option<BlockModel>) -> Result<BlockModel, String> {
        let case = match self.case_table(i).map(Case::from_toml_table) {
            Ok(Ok(Case::Bearing(c))) => *c,
            Ok(Ok(other)) => {
                return Err(format!(
                    "invalid method = \"{}\": expected \"bearing\" in every case of a bearing sweep",
                    other.method()
                ));
            }
            Ok(Err(e)) => return Err(e.to_string()),
            Err(e) => return Err(e.to_string()),
        };
        match previous {
            // the ring speeds are part of the plan (a ball bearing at speed has its own
            // solver): a new `[speed]` plans again, as a new `[bearing]` does
            Some(mut m) if m.case.bearing == case.bearing && m.case.speed == case.speed => {
                m.case = case;
                Ok(m)
            }
            _ => BlockModel::new(case).map_err(|e| e.to_string()),
        }
    }
}

/// The output columns of `rows` ([`COLUMNS`], in order), named and typed.
pub(crate) fn bearing_columns(rows: &[BearingRow]) -> Vec<(&'static str, ArrayRef)> {
    let f = |g: &dyn Fn(&BearingOut) -> Option<f64>| -> ArrayRef {
        Arc::new(Float64Array::from(
            rows.iter()
                .map(|r| r.out.as_ref().and_then(g))
                .collect::<Vec<_>>(),
        ))
    };
    let n = |g: &dyn Fn(&BearingOut) -> usize| -> ArrayRef {
        Arc::new(Int64Array::from(
            rows.iter()
                .map(|r| r.out.as_ref().map(|o| g(o) as i64))
                .collect::<Vec<_>>(),
        ))
    };
    let mut arrays: Vec<ArrayRef> = Vec::with_capacity(COLUMNS.len());
    arrays.push(Arc::new(StringArray::from(
        rows.iter()
            .map(|r| r.out.as_ref().map(|o| o.bearing_type))
            .collect::<Vec<_>>(),
    )));
    arrays.push(n(&|o| o.elements));
    for i in 0..5 {
        arrays.push(f(&|o| Some(o.displacement[i])));
    }
    for i in 0..5 {
        arrays.push(f(&|o| Some(o.load[i])));
    }
    arrays.push(f(&|o| Some(o.max_element_load_n)));
    arrays.push(n(&|o| o.loaded_elements));
    arrays.push(f(&|o| o.max_rib_load_n));
    arrays.push(f(&|o| o.max_load_per_length_n_per_mm));
    arrays.push(f(&|o| o.max_pressure_mpa.map(|p| p[0])));
    arrays.push(f(&|o| o.max_pressure_mpa.map(|p| p[1])));
    arrays.push(f(&|o| o.load_zone_epsilon));
    for i in 0..5 {
        arrays.push(f(&|o| Some(o.stiffness[i])));
    }
    arrays.push(Arc::new(BooleanArray::from(
        rows.iter()
            .map(|r| r.out.as_ref().map(|o| o.converged))
            .collect::<Vec<_>>(),
    )));
    arrays.push(Arc::new(StringArray::from(
        rows.iter()
            .map(|r| r.out.as_ref().map(|o| o.termination))
            .collect::<Vec<_>>(),
    )));
    arrays.push(n(&|o| o.iterations));
    arrays.push(f(&|o| Some(o.residual)));
    arrays.push(Arc::new(StringArray::from(
        rows.iter()
            .map(|r| (!r.warnings.is_empty()).then(|| r.warnings.join("; ")))
            .collect::<Vec<_>>(),
    )));
    arrays.push(Arc::new(BooleanArray::from(
        rows.iter()
            .map(|r| r.out.as_ref().map(|o| o.max_element_load_n == 0.0))
            .collect::<Vec<_>>(),
    )));
    arrays.push(f(&|o| o.static_safety_from_pressure));
    arrays.push(f(&|o| o.static_safety));
    arrays.push(f(&|o| o.l10_mrev));
    arrays.push(f(&|o| o.l10r_mrev));
    COLUMNS.iter().map(|(name, _)| *name).zip(arrays).collect()
}

/// The row numbers of a ball bearing's solution but for the post's; `loads` are the balls'
/// loads on the inner ring.
fn ball_out(
    label: &'static str,
    sol: &BallSolution,
    loads: impl Iterator<Item = f64>,
) -> BearingOut {
    let (mut elements, mut loaded) = (0, 0);
    for q in loads {
        elements += 1;
        loaded += usize::from(q > 0.0);
    }
    BearingOut {
        bearing_type: label,
        elements,
        displacement: sol.displacement,
        load: sol.load,
        max_element_load_n: sol.max_ball_load_n,
        loaded_elements: loaded,
        load_zone_epsilon: sol.load_zone,
        stiffness: std::array::from_fn(|i| sol.stiffness[i][i]),
        ..status_out(&sol.status)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The load keys set directly, and the keys read through the case reader (`None`).
    #[test]
    fn load_keys_map_to_their_slots() {
        assert_eq!(Slot::parse("load.force_n[2]"), Some(Slot::Force(2)));
        assert_eq!(Slot::parse("load.moment_nmm[1]"), Some(Slot::Moment(1)));
        assert_eq!(
            Slot::parse("load.prescribed.tilt_y_rad"),
            Some(Slot::Prescribed(4))
        );
        assert_eq!(
            Slot::parse("load.prescribed.dx_mm"),
            Some(Slot::Prescribed(0))
        );
        for read in [
            "load.force_n",
            "load.force_n[3]",
            "load.moment_nmm[2]",
            "load.force_n[0][0]",
            "load.prescribed.dw_mm",
            "bearing.clearance_mm",
            "name",
        ] {
            assert_eq!(Slot::parse(read), None, "{read}");
        }
        let mut l = BearingLoadSpec {
            force_n: [0.0; 3],
            moment_nmm: [0.0; 2],
            prescribed: Default::default(),
        };
        Slot::Prescribed(2).set(&mut l, 0.01);
        Slot::Moment(0).set(&mut l, 5.0);
        assert_eq!(l.prescribed.dz_mm, Some(0.01));
        assert_eq!(l.moment_nmm, [5.0, 0.0]);
    }
}
