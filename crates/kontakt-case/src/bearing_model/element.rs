//! A whole bearing as one force element of a multi-body code: the inner ring's
//! displacement and velocity relative to the outer ring in, the bearing's reaction on the
//! inner ring and the 5 × 5 stiffness out (issue 28 §4; the C API's bearing element,
//! `kontakt_bearing_element_evaluate`, is a thin layer over [`BearingElement`]).
//!
//! **Frames, signs, units.** Those of [`BearingModel`] (docs/bearing-model.md): the outer
//! ring is fixed, z is the bearing axis, x and y radial; the inner ring's displacement is
//! `u = (δx, δy, δz, θx, θy)` (mm, mm, mm, rad, rad; small rotations about x and y through
//! the bearing centre), its velocity `v = u̇` (mm/s, mm/s, mm/s, rad/s, rad/s). The
//! element returns the **reaction of the bearing on the inner ring**,
//! `R = −(F(u) + β K(u) v)`: forces in N, moments in N·mm about the bearing centre, where
//! `F(u)` is the load the rolling elements carry at the prescribed displacement (the
//! `force_n`/`moment_nmm` of a [`BearingModel`] solve with all five degrees of freedom
//! prescribed) and `K = ∂F/∂u` its stiffness (N/mm, N/rad, N, N·mm/rad; symmetric, positive
//! semi-definite). So `∂R/∂u = −K` and `∂R/∂v = −β K`; the outer ring gets `−R`.
//!
//! **Velocity.** The rolling-element model is quasi-static; the velocity enters only
//! through an optional viscous damping proportional to the stiffness, `C = β K(u)`, with
//! `β` = [`BearingElement::damping_s`] in s (default 0: the velocity is checked for
//! finiteness and has no effect). Like any stiffness-proportional (Rayleigh) damping it
//! vanishes with the contact (every element lifted off: `K = 0`) and, since it is added
//! as is, a fast separation can make the total reaction pull the rings together while
//! the elements still touch.
//!
//! **Friction.** With a `[lubricant]` in its case the element also returns the bearing's
//! friction torque about z and its power ([`BearingElementOutput::friction`], module
//! [`super::friction`]: the contact-based torque of docs/bearing-friction.md from the
//! loads this call solved, at the ring speeds of [`BearingElement::set_speeds`], rad/s,
//! initially the case's `[speed]`): while the rings turn relative to each other,
//! `moment_nmm[2] = −M sign(ω_i − ω_o)` on the inner ring; at Δω = 0 and without a
//! lubricant `moment_nmm[2]` is 0.
//!
//! **Validity.** The model assumes small displacements against the element diameter:
//! a translation above the roller (ball) diameter, or a tilt that moves the ring by more
//! than that at the pitch radius, is refused naming the argument (`displacement[3]`), as
//! are non-finite displacements, velocities and damping. Every element lifted off is not an
//! error: [`BearingElementStatus::LiftedOff`], zero force and stiffness.
//!
//! **Cost.** Each call is one evaluation of the planned solver (all five degrees of freedom
//! prescribed, warm-started from the previous call like every [`BearingModel`] solve),
//! plus the friction torque when on, and allocates nothing (but the rib contact fields of
//! a lubricated `roller_model = "rib_contact"` bearing's rib friction).

use super::BearingModel;
use super::friction::{ElementFriction, FrictionPlan};
use crate::bearing_case::{BearingCase, BearingLoadSpec, Planned, PrescribedSpec};
use crate::bearing_slices::SliceSolver;
use kontakt::solve::{SolveStatus, Termination};
use kontakt::{Error, Result};
use kontakt_bearing::equilibrium::RingLoad;
use kontakt_bearing::friction::RPM_PER_RAD_S;
use kontakt_bearing::geometry::RollerBearing;

/// The largest ring speed, r/min (`[speed]`'s).
const MAX_RING_RPM: f64 = 100_000.0;

/// What the rolling elements of an evaluated bearing do.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum BearingElementStatus {
    /// The inner ring touches no rolling element: zero force and stiffness (at speed the
    /// elements may still press the outer ring).
    LiftedOff,
    /// At least one rolling element carries load.
    Loaded,
}

/// One evaluation of a [`BearingElement`]: the reaction of the bearing on the inner ring.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct BearingElementOutput {
    /// Lifted off or loaded.
    pub status: BearingElementStatus,
    /// Force on the inner ring `(Fx, Fy, Fz)`, N: elastic and damping parts; the outer ring
    /// gets minus this.
    pub force_n: [f64; 3],
    /// Moment on the inner ring about the bearing centre `(Mx, My, Mz)`, N·mm; `Mz` is the
    /// friction moment `friction.inner_ring_nmm` (`−M sign(ω_i − ω_o)`; 0 at Δω = 0 and
    /// without a lubricant).
    pub moment_nmm: [f64; 3],
    /// The damping part of the reaction, `−β K v`, in the order `(Fx, Fy, Fz, Mx, My)`,
    /// N and N·mm (zero when [`BearingElement::damping_s`] is 0).
    pub damping: [f64; 5],
    /// The stiffness `K = ∂F/∂u` of the carried load F (= −∂reaction/∂u), rows and columns
    /// `(x, y, z, θx, θy)`: N/mm, N/rad (force per tilt), N (moment per mm), N·mm/rad.
    pub stiffness: [[f64; 5]; 5],
    /// The largest rolling-element load (a roller's outer raceway load, a ball's load), N.
    pub max_element_load_n: f64,
    /// Newton iterations of the solve (0 when every degree of freedom is prescribed, as
    /// here: the rolling-element model has no internal unknowns today).
    pub iterations: usize,
    /// Why the status is what it is (`"every roller is lifted off: zero load"`), empty
    /// when loaded.
    pub message: &'static str,
    /// The bearing's friction torque, power and breakdown at the element's ring speeds
    /// (status off and zeros without a `[lubricant]`).
    pub friction: ElementFriction,
}

/// A bearing of a case as one force element: planned once, evaluated at many
/// displacements and velocities (module docs: frames, signs, units).
#[derive(Debug, Clone)]
pub struct BearingElement {
    model: BearingModel,
    damping_s: f64,
    friction: FrictionPlan,
    /// Ring speeds `[ω_i, ω_o]`, rad/s.
    speeds: [f64; 2],
}

/// The `[load]` that holds all five degrees of freedom of the inner ring at `u`
/// (`δx, δy, δz` mm, `θx, θy` rad): a [`BearingModel`] solve under it gives minus the
/// elastic reaction of [`BearingElement::evaluate`] at `u`, and the same stiffness.
pub fn prescribed_load(u: [f64; 5]) -> BearingLoadSpec {
    BearingLoadSpec {
        force_n: [0.0; 3],
        moment_nmm: [0.0; 2],
        prescribed: PrescribedSpec {
            dx_mm: Some(u[0]),
            dy_mm: Some(u[1]),
            dz_mm: Some(u[2]),
            tilt_x_rad: Some(u[3]),
            tilt_y_rad: Some(u[4]),
        },
    }
}

/// The names of the five components, as the element's arguments name them.
const DISPLACEMENT_ARGS: [&str; 5] = [
    "displacement[0]",
    "displacement[1]",
    "displacement[2]",
    "displacement[3]",
    "displacement[4]",
];
const VELOCITY_ARGS: [&str; 5] = [
    "velocity[0]",
    "velocity[1]",
    "velocity[2]",
    "velocity[3]",
    "velocity[4]",
];

impl BearingElement {
    /// The element of a planned bearing (its case's `[load]` is not used), undamped, at
    /// the ring speeds of the case's `[speed]`, with the friction torque when the case has
    /// a `[lubricant]`.
    ///
    /// # Errors
    /// Those of the case's friction tables, naming the case key (`lubricant.temperature_c`,
    /// `operating.drag`, `catalogue.skf_series`).
    pub fn new(model: BearingModel) -> Result<Self> {
        let friction = FrictionPlan::new(&model.case, &model.planned)?;
        let s = &model.case.speed;
        let speeds = [s.inner_rpm / RPM_PER_RAD_S, s.outer_rpm / RPM_PER_RAD_S];
        Ok(BearingElement {
            model,
            damping_s: 0.0,
            friction,
            speeds,
        })
    }

    /// Plan the element of a bearing case (`method = "bearing"`, TOML text; the schema's
    /// `[load]` is required but not used).
    ///
    /// # Errors
    /// [`Error::CaseFile`] for malformed TOML or an unknown key, and the errors of
    /// [`BearingModel::new`] naming the case key.
    pub fn from_toml(text: &str) -> Result<Self> {
        let case = BearingCase::from_toml_str(text)?;
        Self::new(BearingModel::new(&case)?)
    }

    /// The planned bearing.
    pub fn model(&self) -> &BearingModel {
        &self.model
    }

    /// The damping coefficient β, s: the damping matrix is `β K(u)`.
    pub fn damping_s(&self) -> f64 {
        self.damping_s
    }

    /// Set the damping coefficient β, s (0 ≤ β, finite; default 0).
    ///
    /// # Errors
    /// [`Error::InvalidInput`] naming `damping_s` for a negative or non-finite value (the
    /// element keeps its β).
    pub fn set_damping(&mut self, damping_s: f64) -> Result<()> {
        if !(damping_s.is_finite() && damping_s >= 0.0) {
            return Err(Error::invalid(
                "damping_s",
                damping_s,
                "a finite damping coefficient beta >= 0 s (the damping matrix is beta times the stiffness)",
            ));
        }
        self.damping_s = damping_s;
        Ok(())
    }

    /// The ring speeds `[ω_i, ω_o]` of the friction torque, rad/s.
    pub fn speeds(&self) -> [f64; 2] {
        self.speeds
    }

    /// Set the ring speeds of the friction torque: inner ring `inner_rad_s`, outer ring
    /// `outer_rad_s`, rad/s about +z (finite, |ω| ≤ 100 000 r/min as `[speed]`). They
    /// change the friction torque only, not the load distribution (whose centrifugal
    /// forces, if any, stay those of the case's `[speed]`). Equal speeds give the starting
    /// torque.
    ///
    /// # Errors
    /// [`Error::InvalidInput`] naming `inner_rad_s` or `outer_rad_s` (the element keeps its
    /// speeds).
    pub fn set_speeds(&mut self, inner_rad_s: f64, outer_rad_s: f64) -> Result<()> {
        let max = MAX_RING_RPM / RPM_PER_RAD_S;
        for (name, w) in [("inner_rad_s", inner_rad_s), ("outer_rad_s", outer_rad_s)] {
            if !(w.is_finite() && w.abs() <= max) {
                return Err(Error::invalid(
                    name,
                    w,
                    format!(
                        "a finite ring speed with |speed| <= {max:.1} rad/s ({MAX_RING_RPM} r/min)"
                    ),
                ));
            }
        }
        self.speeds = [inner_rad_s, outer_rad_s];
        Ok(())
    }

    /// Forget the last equilibrium (the next call starts from the closed forms).
    pub fn reset(&mut self) {
        self.model.reset();
    }

    /// The largest translation, mm, and the largest tilt times the pitch radius: the
    /// rolling element's diameter; and the pitch radius, mm.
    fn limits(&self) -> (f64, f64, &'static str) {
        match &self.model.planned {
            Planned::Roller(s) => roller_limits(s.bearing()),
            Planned::Coupled(s) => roller_limits(s.bearing()),
            Planned::RibRoller(s) => roller_limits(s.bearing()),
            Planned::Ball { solver, .. } => ball_limits(solver.bearing()),
            Planned::BallAtSpeed { solver, .. } => ball_limits(solver.bearing()),
        }
    }

    /// The bearing's reaction on the inner ring at the displacement `u` (mm, rad) and the
    /// velocity `v` (mm/s, rad/s) of the inner ring relative to the outer ring.
    ///
    /// # Errors
    /// [`Error::InvalidInput`] naming the argument (`displacement[2]`, `velocity[4]`) for a
    /// non-finite value or a displacement beyond the model's validity (above the rolling
    /// element's diameter); [`Error::NotConverged`] if the solver does not converge (not
    /// expected: every degree of freedom is prescribed); with a lubricant, those of the
    /// friction torque (a film or friction integral that fails, naming its field). The warm
    /// start is kept on error.
    pub fn evaluate(&mut self, u: [f64; 5], v: [f64; 5]) -> Result<BearingElementOutput> {
        for i in 0..5 {
            if !u[i].is_finite() {
                return Err(Error::invalid(
                    DISPLACEMENT_ARGS[i],
                    u[i],
                    "a finite number",
                ));
            }
            if !v[i].is_finite() {
                return Err(Error::invalid(VELOCITY_ARGS[i], v[i], "a finite number"));
            }
        }
        let (limit, r, key) = self.limits();
        for i in 0..5 {
            if i < 3 && u[i].abs() > limit {
                return Err(Error::invalid(
                    DISPLACEMENT_ARGS[i],
                    u[i],
                    format!(
                        "|value| <= {limit} mm, the rolling element's diameter {key} (beyond it the model's small-displacement assumption fails)"
                    ),
                ));
            }
            if i >= 3 && (u[i] * r).abs() > limit {
                return Err(Error::invalid(
                    DISPLACEMENT_ARGS[i],
                    u[i],
                    format!(
                        "|value| <= {} rad: a tilt that moves the ring at the pitch radius {r} mm by at most the rolling element's diameter {key} = {limit} mm (beyond it the model's small-rotation assumption fails)",
                        limit / r
                    ),
                ));
            }
        }
        let load = RingLoad::displacements(u);
        let start = self.model.last;
        let (force, stiffness, status, note, max_load) = match &mut self.model.planned {
            Planned::Roller(s) => roller_step(s, &load, start)?,
            Planned::Coupled(s) => roller_step(s.as_mut(), &load, start)?,
            Planned::RibRoller(s) => {
                let sol = match start {
                    Some(w) => s.solve_from(&load, w),
                    None => s.solve(&load),
                }?;
                (
                    sol.load,
                    sol.stiffness,
                    sol.status,
                    sol.note,
                    sol.max_roller_load_n,
                )
            }
            Planned::Ball { solver, .. } => {
                let sol = match start {
                    Some(w) => solver.solve_from(&load, w),
                    None => solver.solve(&load),
                }?;
                ball_step(sol)
            }
            // at speed: the stiffness is not symmetric (the gyroscopic friction)
            Planned::BallAtSpeed { solver, .. } => {
                let sol = match start {
                    Some(w) => solver.solve_from(&load, w),
                    None => solver.solve(&load),
                }?;
                ball_step(sol)
            }
        };
        if !matches!(
            status.termination,
            Termination::Converged | Termination::Stagnated
        ) {
            status.require_converged(note.unwrap_or("bearing element: no equilibrium"))?;
        }
        // the damping part −β K v
        let mut damping = [0.0; 5];
        if self.damping_s > 0.0 {
            for (i, d) in damping.iter_mut().enumerate() {
                let kv: f64 = (0..5).map(|j| stiffness[i][j] * v[j]).sum();
                *d = -self.damping_s * kv;
            }
        }
        let reaction: [f64; 5] = std::array::from_fn(|i| -force[i] + damping[i]);
        if reaction
            .iter()
            .chain(stiffness.iter().flatten())
            .any(|x| !x.is_finite())
        {
            return Err(Error::invalid(
                "velocity",
                format!("{v:?}"),
                format!(
                    "a velocity whose damping force beta K v is finite (beta = damping_s = {} s; the force overflows)",
                    self.damping_s
                ),
            ));
        }
        // lifted off: the inner ring touches no element (at speed the rollers of the
        // rib-contact model still press the outer ring with their centrifugal force, so
        // the largest element load alone does not say it)
        let loaded = max_load > 0.0 && force.iter().any(|f| *f != 0.0);
        let friction = self.friction.evaluate(&self.model.planned, self.speeds)?;
        self.model.last = loaded.then_some(u);
        Ok(BearingElementOutput {
            status: if loaded {
                BearingElementStatus::Loaded
            } else {
                BearingElementStatus::LiftedOff
            },
            force_n: [reaction[0], reaction[1], reaction[2]],
            moment_nmm: [reaction[3], reaction[4], friction.inner_ring_nmm],
            damping,
            stiffness,
            max_element_load_n: max_load,
            iterations: status.iterations,
            message: if loaded {
                ""
            } else {
                note.unwrap_or("every rolling element is lifted off: zero load")
            },
            friction,
        })
    }
}

/// The largest translation (the roller diameter), the pitch radius and the key naming the
/// former, of a roller bearing.
fn roller_limits(b: &RollerBearing) -> (f64, f64, &'static str) {
    (
        b.roller_diameter_mm,
        0.5 * b.pitch_diameter_mm,
        "bearing.roller_diameter_mm",
    )
}

/// The load, stiffness, status, note and largest roller load of a roller bearing's solve
/// under `load`, from `start` when given; either slice model.
#[allow(clippy::type_complexity)]
fn roller_step<S: SliceSolver>(
    s: &mut S,
    load: &RingLoad,
    start: Option<[f64; 5]>,
) -> Result<(
    [f64; 5],
    [[f64; 5]; 5],
    SolveStatus,
    Option<&'static str>,
    f64,
)> {
    let sol = match start {
        Some(w) => s.solve_from(load, w),
        None => s.solve(load),
    }?;
    Ok((
        sol.load,
        sol.stiffness,
        sol.status,
        sol.note,
        sol.max_roller_load_n,
    ))
}

/// The limits of a ball bearing: the ball diameter, the pitch radius and the key.
fn ball_limits(b: &kontakt_bearing::geometry::BallBearing) -> (f64, f64, &'static str) {
    (
        b.ball_diameter_mm,
        0.5 * b.pitch_diameter_mm,
        "bearing.ball_diameter_mm",
    )
}

/// A ball bearing's solution as the element's step.
fn ball_step(
    sol: kontakt_bearing::ball_equilibrium::BallSolution,
) -> (
    [f64; 5],
    [[f64; 5]; 5],
    kontakt::solve::SolveStatus,
    Option<&'static str>,
    f64,
) {
    (
        sol.load,
        sol.stiffness,
        sol.status,
        sol.note,
        sol.max_ball_load_n,
    )
}
