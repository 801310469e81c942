//! A contact element for multi-body codes: two analytic surfaces fixed to two bodies,
//! planned once; [`ContactElement::evaluate`] takes the bodies' poses and twists and returns
//! the contact force and the moments about each body's reference point, the approach, the
//! contact point and normal, the friction force and power, and the contact status.
//!
//! # Coupling (docs/mbs.md)
//!
//! - Frames: every pose, twist, point, force and moment is in the world frame. A body's
//!   pose maps body coordinates to world coordinates; its reference point is the pose's
//!   origin. Each surface is placed in its body's frame by [`ElementSpec::surface1`] /
//!   [`ElementSpec::surface2`]; at evaluation it sits at `pose ∘ placement`.
//! - Signs: the normal `n` points from body 2 into body 1 (the direction of the normal force
//!   on body 1). The approach `δ = −separation ≥ 0` in contact. The force on body 2 is minus
//!   the force on body 1.
//! - Units: mm, N, MPa, mm/s, rad/s; moments N·mm; power W.
//!
//! # Model
//!
//! 1. The contact point (closest points, or the deepest point of an overlap) by
//!    [`find_contact`], started from the last call's point.
//! 2. Separated (`separation > 0`): zero force, status [`ContactStatus::Separated`].
//! 3. The normal problem at the approach `δ` by the back-end: Hertz at the contact point's
//!    relative curvature, PimP, or the coupled half-space solver, on the gap of the two
//!    placed surfaces.
//! 4. Friction: the law over the pressure with the sliding field of the two twists, scaled
//!    to the back-end's normal force: [`crate::friction::grid_friction`] over the field
//!    solvers' grids (PimP's tracked grid and the half-space back-end's warm grid:
//!    [`crate::friction::grid_friction_binned`], blocks of 4 to 16 cells per evaluation of
//!    the law where the sliding varies little); for Hertz,
//!    [`crate::friction::HertzFrictionRules`], a polar quadrature of the semi-ellipsoid
//!    (16 to 512 nodes by the law and the sliding field's smoothness; no sampled field;
//!    accuracy in docs/VALIDATION.md).
//! 5. Damping (optional): `F_d = c(δ) δ̇`, `δ̇ = −n · (v_1 − v_2)` at the contact point,
//!    `c(δ) = c_max s(δ / δ_c)`, `s(t) = 3t² − 2t³` on `[0, 1]`, 1 beyond: zero with zero slope
//!    at first touch, so the force has no jump. The total normal force `F_n + F_d` is not
//!    allowed to pull (clamped at 0).
//! 6. Validity: the approach is compared with `max_approach_ratio · R_min`, `R_min` the
//!    smallest relative radius of curvature at the contact point (Hertz's small-strain
//!    assumption; default 1 %). Beyond it the status is [`ContactStatus::OutOfValidity`] with
//!    the force still computed (continuous for the integrator) and the reason in
//!    [`ElementResult::message`]: never a silent huge force.

mod halfspace_warm;
mod pimp_path;
pub mod study;

use crate::error::{Error, Result};
use crate::field::NormalSolution;
use crate::friction::{
    CellLaw, FilmState, FrictionLaw, GridFriction, HertzFrictionRules, grid_friction,
    grid_friction_binned,
};
use crate::gap::{GapSource, SurfacePairGap};
use crate::geometry::surface::check_pose;
use crate::geometry::{
    BodyState, ContactFrame, ContactPair, Grid2, PlacedSurface, Twist, find_contact,
};
use crate::halfspace::{Bem, BemOptions, HalfSpacePlanner};
use crate::hertz::{HertzPointContact, PointGeometry};
use crate::material::ElasticMaterial;
use crate::pimp::{GapSampling, Pimp, PimpOptions, PimpTracker};
use nalgebra::{Isometry3, Matrix6, Point3, Unit, UnitQuaternion, Vector3};
use std::sync::{Arc, Mutex};

/// Which model solves the normal problem.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Backend {
    /// Hertz at the relative curvature of the contact point (closed form; the friction
    /// integral runs over the ellipse by a polar quadrature, no sampled field).
    Hertz,
    /// PimP with these options.
    Pimp(PimpOptions),
    /// The coupled elastic half-space solver with these options.
    HalfSpace(BemOptions),
}

/// Normal damping that switches on smoothly with the approach.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Damping {
    /// Full damping coefficient c_max \[N·s/mm\], ≥ 0.
    pub coefficient: f64,
    /// Approach δ_c \[mm\] over which the coefficient rises from 0 to c_max, > 0.
    pub ramp: f64,
}

/// What an element is made of.
#[derive(Debug, Clone, PartialEq)]
pub struct ElementSpec {
    /// Surface of body 1, placed in body 1's frame.
    pub surface1: PlacedSurface,
    /// Surface of body 2, placed in body 2's frame.
    pub surface2: PlacedSurface,
    /// Material of body 1.
    pub material1: ElasticMaterial,
    /// Material of body 2.
    pub material2: ElasticMaterial,
    /// Normal-contact back-end.
    pub backend: Backend,
    /// Friction law.
    pub friction: FrictionLaw,
    /// The lubricant film the friction law sees ([`FilmState::dry`] for dry friction).
    pub film: FilmState,
    /// Optional normal damping.
    pub damping: Option<Damping>,
    /// Validity limit of the approach as a fraction of the smallest relative radius of
    /// curvature at the contact point (default 0.01).
    pub max_approach_ratio: f64,
    /// Relative residual at which the half-space back-end's warm calls stop, in
    /// \[0, 1e-2\] (default [`WARM_TOLERANCE`], 1e-6). A warm call stops at the looser of
    /// this and `BemOptions::tolerance`; the solves that lay a grid keep
    /// `BemOptions::tolerance`. 0 keeps `BemOptions::tolerance` for every call
    /// (docs/mbs.md: the force error of a multi-body step's tolerance).
    pub warm_tolerance: f64,
}

/// The default [`ElementSpec::warm_tolerance`]: on the roller-end/rib pairing's warm steps
/// it moves the force by at most a few 1e-7 of itself against 1e-8 (docs/mbs.md) and needs
/// about half the iterations.
pub const WARM_TOLERANCE: f64 = 1e-6;

impl ElementSpec {
    /// An element of two placed surfaces with steel bodies, the Hertz back-end, Coulomb
    /// friction μ = 0.1, no damping and the default validity limit.
    ///
    /// # Errors
    /// None today; kept fallible for the checks of [`ContactElement::new`].
    pub fn new(surface1: PlacedSurface, surface2: PlacedSurface) -> Result<Self> {
        Ok(ElementSpec {
            surface1,
            surface2,
            material1: ElasticMaterial::STEEL,
            material2: ElasticMaterial::STEEL,
            backend: Backend::Hertz,
            friction: FrictionLaw::coulomb(0.1)?,
            film: FilmState::dry(),
            damping: None,
            max_approach_ratio: 0.01,
            warm_tolerance: WARM_TOLERANCE,
        })
    }
}

/// The state of the contact after an evaluation.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ContactStatus {
    /// The bodies do not touch: zero force.
    Separated,
    /// In contact within the model's validity.
    Contact,
    /// In contact beyond the model's validity (the force is computed and flagged; see
    /// [`ElementResult::message`]).
    OutOfValidity,
}

/// What an evaluation returns (world frame; mm, N, N·mm, W).
#[derive(Debug, Clone, PartialEq)]
pub struct ElementResult {
    /// Contact status.
    pub status: ContactStatus,
    /// Signed separation \[mm\]: > 0 apart, < 0 overlapping (`−approach`).
    pub separation: f64,
    /// Approach δ = max(−separation, 0) \[mm\].
    pub approach: f64,
    /// Contact point (midpoint of the two surface points) \[mm\].
    pub point: Point3<f64>,
    /// Contact normal, from body 2 into body 1.
    pub normal: Unit<Vector3<f64>>,
    /// Elastic normal force \[N\].
    pub normal_force: f64,
    /// Damping force along the normal \[N\] (after the no-pull clamp of the total).
    pub damping_force: f64,
    /// Friction force on body 1 \[N\].
    pub friction_force: Vector3<f64>,
    /// Moment of the friction stresses on body 1 about the contact point \[N·mm\], along
    /// the normal: the spin (drilling) friction torque of the contact. With the friction
    /// force acting at the contact point it makes up the friction's share of `moment1`;
    /// body 2 gets minus both.
    pub friction_moment: Vector3<f64>,
    /// Friction power \[W\], ≥ 0.
    pub friction_power: f64,
    /// Total force on body 1 \[N\] (normal, damping, friction); body 2 gets minus this.
    pub force1: Vector3<f64>,
    /// Moment on body 1 about its reference point \[N·mm\].
    pub moment1: Vector3<f64>,
    /// Moment on body 2 about its reference point \[N·mm\].
    pub moment2: Vector3<f64>,
    /// Largest pressure \[MPa\].
    pub max_pressure: f64,
    /// Contact area \[mm²\].
    pub contact_area: f64,
    /// Iterations of the back-end's solver (0 for Hertz).
    pub iterations: usize,
    /// Why the status is [`ContactStatus::OutOfValidity`] (empty otherwise).
    pub message: String,
}

/// A planned contact element (see the module docs). `Send`: one element per roller can be
/// evaluated on its own thread.
#[derive(Debug, Clone)]
pub struct ContactElement {
    spec: ElementSpec,
    law: CellLaw,
    pimp: Option<Pimp>,
    bem: Option<Bem>,
    /// The last contact point in body 1's frame: the next search starts there.
    last_point: Option<Point3<f64>>,
    /// The contact point before it (body 1's frame), for the secant start.
    prev_point: Option<Point3<f64>>,
    /// Area of the last contact \[mm²\] (0 when separated): the secant start is taken when
    /// the last step of the contact point was below a tenth of its size `√area`.
    last_area: f64,
    /// The Hertz back-end's last contact: the next shape inversion starts from it.
    last_hertz: Option<HertzPointContact>,
    /// The Hertz back-end's quadrature rules over the contact ellipse (built once).
    hertz_rules: HertzFrictionRules,
    /// The half-space back-end's grid and last field, for the warm start.
    warm: halfspace_warm::WarmHalfSpace,
    /// The PimP back-end's grid and buffers, kept between calls (`pimp::PimpTracker`).
    tracker: Option<PimpTracker>,
    /// The two surfaces at the last call's poses (the contact search's bodies), and their
    /// gap at the last contact: both moved in place each call, the surfaces never copied.
    placed: [PlacedSurface; 2],
    gap: Option<SurfacePairGap>,
}

/// Most steps of [`ContactElement::press_to_force`].
pub const PRESS_STEPS: usize = 100;

/// Where the friction integral takes its pressure from.
enum Samples<'a> {
    /// A field on a grid (PimP, the half-space solver).
    Grid(Grid2, &'a [f64]),
    /// PimP's tracked field or the half-space back-end's kept grid: the friction by
    /// [`grid_friction_binned`].
    Binned(Grid2, &'a [f64]),
    /// Hertz's semi-ellipsoid, integrated by the element's [`HertzFrictionRules`].
    Ellipse {
        semi_axes: [f64; 2],
        orientation: f64,
        max_pressure: f64,
    },
}

/// The normal solution as the rest of an evaluation needs it, whichever back-end gave it.
struct FieldView<'a> {
    samples: Samples<'a>,
    /// Angle of the grid's x axis from the gap frame's x axis \[rad\].
    orientation: f64,
    /// Centre of pressure in the grid frame \[mm\].
    centroid: [f64; 2],
    force: f64,
    max_pressure: f64,
    contact_area: f64,
    iterations: usize,
}

fn check_twist(name: &'static str, t: &Twist) -> Result<()> {
    if t.is_finite() {
        Ok(())
    } else {
        Err(Error::invalid(
            name,
            format!("{t:?}"),
            "finite velocities in mm/s and rad/s",
        ))
    }
}

/// The cubic smooth step 3t² − 2t³ on [0, 1], 0 below, 1 above.
fn smooth_step(t: f64) -> f64 {
    let t = t.clamp(0.0, 1.0);
    t * t * (3.0 - 2.0 * t)
}

impl ContactElement {
    /// Plan an element.
    ///
    /// # Errors
    /// [`Error::InvalidInput`] naming the field: `surface1.pose` / `surface2.pose` (the
    /// placements: finite, unit quaternion), the friction law and film
    /// ([`FrictionLaw::with_film`]), `damping.coefficient` (finite, ≥ 0), `damping.ramp`
    /// (finite, > 0), `max_approach_ratio` (finite, > 0), and the back-end's options.
    pub fn new(spec: ElementSpec) -> Result<Self> {
        Self::with_planner(spec, Arc::new(Mutex::new(HalfSpacePlanner::new())))
    }

    /// Plan an element whose half-space back-end takes its plans (the FFT of the influence
    /// coefficients on a grid) from `planner`, shared with other elements: elements of
    /// similar contacts (for example the rollers of one bearing) lay their grids on the
    /// same ladder of spacings and then hold one plan, not a copy each. Other back-ends
    /// do not use it.
    ///
    /// # Errors
    /// As [`ContactElement::new`].
    pub fn with_planner(spec: ElementSpec, planner: Arc<Mutex<HalfSpacePlanner>>) -> Result<Self> {
        let law = spec.friction.with_film(&spec.film)?;
        // A placement built as a struct literal bypasses PlacedSurface::new's check.
        for (name, s) in [
            ("surface1.pose", &spec.surface1),
            ("surface2.pose", &spec.surface2),
        ] {
            check_pose(&s.pose).map_err(|e| e.map_field(|_| name.to_string()))?;
        }
        if let Some(d) = spec.damping {
            if !(d.coefficient.is_finite() && d.coefficient >= 0.0) {
                return Err(Error::invalid(
                    "damping.coefficient",
                    d.coefficient,
                    "a finite coefficient >= 0 N·s/mm",
                ));
            }
            if !(d.ramp.is_finite() && d.ramp > 0.0) {
                return Err(Error::invalid(
                    "damping.ramp",
                    d.ramp,
                    "a finite approach > 0 mm",
                ));
            }
        }
        let r = spec.max_approach_ratio;
        if !(r.is_finite() && r > 0.0) {
            return Err(Error::invalid(
                "max_approach_ratio",
                r,
                "a finite fraction > 0 of the smallest radius",
            ));
        }
        let t = spec.warm_tolerance;
        if !(0.0..=1e-2).contains(&t) {
            return Err(Error::invalid(
                "warm_tolerance",
                t,
                "0 <= warm_tolerance <= 1e-2",
            ));
        }
        let (m1, m2) = (spec.material1, spec.material2);
        let (pimp, bem) = match spec.backend {
            Backend::Hertz => (None, None),
            Backend::Pimp(o) => (Some(Pimp::new(m1, m2, o)?), None),
            Backend::HalfSpace(o) => (
                None,
                Some(
                    Bem::with_planner(m1, m2, o, planner)?
                        .with_estimate(crate::pimp::zone_estimate(m1, m2)?),
                ),
            ),
        };
        let tracker = match pimp {
            // A fixed extent keeps the full solve on every call.
            Some(p) if p.options().extent.is_none() => {
                Some(PimpTracker::new(p, GapSampling::default())?)
            }
            _ => None,
        };
        Ok(ContactElement {
            placed: [spec.surface1.clone(), spec.surface2.clone()],
            gap: None,
            spec,
            law,
            pimp,
            bem,
            last_point: None,
            prev_point: None,
            last_area: 0.0,
            last_hertz: None,
            hertz_rules: HertzFrictionRules::new()?,
            warm: Default::default(),
            tracker,
        })
    }

    /// Grids the half-space back-end has laid since the element was planned or reset: one
    /// at the first contact, one more each time the zone outgrows its grid or shrinks below
    /// 45 % of it (0 for the other back-ends).
    pub fn grids_laid(&self) -> usize {
        self.warm.grids_laid
    }

    /// The element's specification.
    pub fn spec(&self) -> &ElementSpec {
        &self.spec
    }

    /// The stiffness of the contact with respect to body 1's pose: the 6 × 6 matrix
    /// `∂(F₁, M₁)/∂(x₁, θ₁)` (rows: force \[N\] and moment about body 1's reference point
    /// \[N·mm\], world axes; columns: translations of body 1 \[mm\] along the world axes and
    /// small rotations \[rad\] about world axes through its reference point), by central
    /// differences with the steps `step_translation` \[mm\] and `step_rotation` \[rad\]:
    /// column j = (r(q + h e_j) − r(q − h e_j)) / 2h, error O(h²). Body 2 held at `pose2`,
    /// both twists fixed (damping enters through the approach). By the action-reaction of
    /// the pair, body 2's block is the same with the signs and the moment point changed.
    /// Steps of 1e-3 of the approach (translation) and of the approach over the contact width
    /// (rotation) are a good start.
    ///
    /// Every difference is evaluated from the element's state at the call (warm starts, the
    /// PimP grid and a fade between grids under way), and the element is left in that state:
    /// a Jacobian taken between two time steps does not move the trajectory's warm starts,
    /// and two calls give the same matrix bit for bit. (This copies the element's buffers
    /// once per difference.)
    ///
    /// # Errors
    /// [`Error::InvalidInput`] (fields `step_translation`, `step_rotation`) for non-finite or
    /// non-positive steps; those of [`ContactElement::evaluate`].
    pub fn stiffness(
        &mut self,
        pose1: &Isometry3<f64>,
        pose2: &Isometry3<f64>,
        twist1: &Twist,
        twist2: &Twist,
        step_translation: f64,
        step_rotation: f64,
    ) -> Result<Matrix6<f64>> {
        for (name, h) in [
            ("step_translation", step_translation),
            ("step_rotation", step_rotation),
        ] {
            if !(h.is_finite() && h > 0.0) {
                return Err(Error::invalid(name, h, "a finite step > 0"));
            }
        }
        let start = self.clone();
        let k = self.differences(
            &start,
            pose1,
            pose2,
            twist1,
            twist2,
            [step_translation, step_rotation],
        );
        *self = start;
        k
    }

    /// The central differences of [`ContactElement::stiffness`], each evaluated from the
    /// state `start`.
    fn differences(
        &mut self,
        start: &ContactElement,
        pose1: &Isometry3<f64>,
        pose2: &Isometry3<f64>,
        twist1: &Twist,
        twist2: &Twist,
        [step_translation, step_rotation]: [f64; 2],
    ) -> Result<Matrix6<f64>> {
        let mut k = Matrix6::zeros();
        for j in 0..6 {
            let mut column = [[0.0; 6]; 2];
            for (side, sign) in [(0, 1.0), (1, -1.0)] {
                let mut p = *pose1;
                if j < 3 {
                    p.translation.vector[j] += sign * step_translation;
                } else {
                    let mut axis = Vector3::zeros();
                    axis[j - 3] = sign * step_rotation;
                    p.rotation = UnitQuaternion::from_scaled_axis(axis) * p.rotation;
                }
                self.clone_from(start);
                let r = self.evaluate(&p, pose2, twist1, twist2)?;
                for i in 0..3 {
                    column[side][i] = r.force1[i];
                    column[side][i + 3] = r.moment1[i];
                }
            }
            let h = if j < 3 {
                step_translation
            } else {
                step_rotation
            };
            for i in 0..6 {
                k[(i, j)] = (column[0][i] - column[1][i]) / (2.0 * h);
            }
        }
        Ok(k)
    }

    /// Load control on top of the element: move body 1 from `pose1` along `direction` (a unit
    /// vector, world frame: the way body 1 approaches body 2) until the elastic normal force
    /// is `force` \[N\] to 1e-9 relative; returns the pose and the result there. Each step
    /// moves to the approach `δ (F_target/F)^(2/3)` of the point-contact power law (exact for
    /// Hertz, fast for the field back-ends), starting from contact if the bodies are apart,
    /// at most [`PRESS_STEPS`] steps. (After a grid resize the PimP back-end fades between
    /// its two grids as the contact moves, `pimp::FADE_TRAVEL`; the force is then a blend of
    /// the two, which differ by about 1e-5, and the steps converge on the blend.)
    ///
    /// # Errors
    /// [`Error::InvalidInput`] (field `force`) for a non-finite or non-positive force, (field
    /// `direction`) for a direction along which the bodies do not approach;
    /// [`Error::NotConverged`] after [`PRESS_STEPS`] steps; those of
    /// [`ContactElement::evaluate`].
    pub fn press_to_force(
        &mut self,
        pose1: &Isometry3<f64>,
        pose2: &Isometry3<f64>,
        twist1: &Twist,
        twist2: &Twist,
        direction: &Unit<Vector3<f64>>,
        force: f64,
    ) -> Result<(Isometry3<f64>, ElementResult)> {
        if !(force.is_finite() && force > 0.0) {
            return Err(Error::invalid("force", force, "a finite force > 0 N"));
        }
        let d = direction.into_inner();
        let moved = |offset: f64| {
            let mut p = *pose1;
            p.translation.vector += d * offset;
            p
        };
        let mut offset = 0.0;
        let mut residual = f64::INFINITY;
        for _ in 0..PRESS_STEPS {
            let pose = moved(offset);
            let r = self.evaluate(&pose, pose2, twist1, twist2)?;
            // How much the approach grows per unit offset along `direction`.
            let gain = -r.normal.dot(&d);
            if !(gain > 1e-3) {
                return Err(Error::invalid(
                    "direction",
                    format!("{d:?}"),
                    "a direction along which body 1 approaches body 2 (against the normal)",
                ));
            }
            if r.status == ContactStatus::Separated {
                // Close the gap, then aim at a small approach.
                offset += (r.separation + 1e-6) / gain;
                continue;
            }
            residual = (r.normal_force - force) / force;
            if residual.abs() < 1e-9 {
                return Ok((pose, r));
            }
            // The power law F ∝ δ^(3/2) of a point contact gives the next approach
            // δ (F_target / F)^(2/3): exact for Hertz, a Newton-like step for the field
            // back-ends, and safe from a round-off touch (δ ≈ 1e-14 mm, F ≈ 1e-15 N). The
            // growth per step is capped at 1000×.
            let next = if r.normal_force > 0.0 && r.approach > 0.0 {
                r.approach * (force / r.normal_force).powf(2.0 / 3.0).min(1e3)
            } else {
                r.approach.max(1e-9) * 2.0
            };
            offset += (next - r.approach) / gain;
        }
        Err(Error::NotConverged {
            what: "press_to_force".into(),
            iterations: PRESS_STEPS,
            residual,
        })
    }

    /// Forget the last contact point (the next search starts from scratch).
    pub fn reset(&mut self) {
        self.last_point = None;
        self.prev_point = None;
        self.last_area = 0.0;
        self.last_hertz = None;
        self.warm.reset();
        if let Some(t) = &mut self.tracker {
            t.reset();
        }
    }

    /// Evaluate the contact at the poses `pose1`, `pose2` and twists `twist1`, `twist2` of
    /// the two bodies (world frame; a twist is the velocity of the body's reference point,
    /// its pose's origin, and the angular velocity).
    ///
    /// # Errors
    /// [`Error::InvalidInput`]: field `pose1` / `pose2` (non-finite or a non-unit rotation),
    /// `twist1` / `twist2` (non-finite); the contact search's and the back-end's errors
    /// (for example a half-space solve that does not converge, [`Error::NotConverged`]).
    pub fn evaluate(
        &mut self,
        pose1: &Isometry3<f64>,
        pose2: &Isometry3<f64>,
        twist1: &Twist,
        twist2: &Twist,
    ) -> Result<ElementResult> {
        let r = self.evaluate_unchecked(pose1, pose2, twist1, twist2)?;
        // Finite inputs can still overflow (a twist of 1e150 rad/s times a damping of
        // 1e300 N·s/mm, found by fuzzing the C API): an error, never inf or NaN.
        let v = |x: &Vector3<f64>| [x.x, x.y, x.z];
        let named = [
            ("separation", r.separation),
            ("damping_force", r.damping_force),
            ("friction_power", r.friction_power),
            ("normal_force", r.normal_force),
            ("max_pressure", r.max_pressure),
            ("contact_area", r.contact_area),
        ];
        let vectors = [
            ("point", v(&r.point.coords)),
            ("normal", v(&r.normal)),
            ("friction_force", v(&r.friction_force)),
            ("friction_moment", v(&r.friction_moment)),
            ("force1", v(&r.force1)),
            ("moment1", v(&r.moment1)),
            ("moment2", v(&r.moment2)),
        ];
        let first = named
            .iter()
            .find(|(_, x)| !x.is_finite())
            .map(|(n, _)| *n)
            .or_else(|| {
                vectors
                    .iter()
                    .find(|(_, x)| x.iter().any(|c| !c.is_finite()))
                    .map(|(n, _)| *n)
            });
        match first {
            None => Ok(r),
            Some(name) => Err(Error::Geometry {
                field: "result".into(),
                reason: format!(
                    "{name} overflows f64 at this state: the velocities, damping or friction are too large"
                ),
            }),
        }
    }

    fn evaluate_unchecked(
        &mut self,
        pose1: &Isometry3<f64>,
        pose2: &Isometry3<f64>,
        twist1: &Twist,
        twist2: &Twist,
    ) -> Result<ElementResult> {
        check_twist("twist1", twist1)?;
        check_twist("twist2", twist2)?;
        // The poses are checked as given; a checked pose composed with a placement (itself
        // checked when it was made) is a rigid transform.
        check_pose(pose1).map_err(|e| e.map_field(|_| "pose1".to_string()))?;
        check_pose(pose2).map_err(|e| e.map_field(|_| "pose2".to_string()))?;
        self.placed[0].pose = pose1 * self.spec.surface1.pose;
        self.placed[1].pose = pose2 * self.spec.surface2.pose;
        let [p1, p2] = &self.placed;
        // The search starts from the last contact point, extrapolated along its last step
        // (the secant) when that step was small against the contact: along a smooth motion
        // the start is then second-order close and the Newton search saves an iteration.
        let guess = match (self.last_point, self.prev_point) {
            // |p − q| ≤ 0.1 √area, on the squares.
            (Some(p), Some(q)) if (p - q).norm_squared() <= 0.01 * self.last_area => {
                Some(pose1 * (p + (p - q)))
            }
            (p, _) => p.map(|p| pose1 * p),
        };
        let contact = find_contact(p1, p2, guess)?;
        let here = pose1.inverse_transform_point(&contact.point);
        // The contact point's step over the last contact's size (0 after a separation): the
        // motion that moves a PimP fade between grids on.
        let travel = match self.last_point {
            Some(p) if self.last_area > 0.0 => (here - p).norm() / self.last_area.sqrt(),
            _ => 0.0,
        };
        self.prev_point = self.last_point;
        self.last_point = Some(here);
        self.last_area = 0.0;
        let zero = Vector3::zeros();
        let separated = ElementResult {
            status: ContactStatus::Separated,
            separation: contact.separation,
            approach: 0.0,
            point: contact.point,
            normal: contact.normal,
            normal_force: 0.0,
            damping_force: 0.0,
            friction_force: zero,
            friction_moment: zero,
            friction_power: 0.0,
            force1: zero,
            moment1: zero,
            moment2: zero,
            max_pressure: 0.0,
            contact_area: 0.0,
            iterations: 0,
            message: String::new(),
        };
        if !(contact.separation < 0.0) {
            return Ok(separated);
        }
        let approach = -contact.separation;
        let gap = match &mut self.gap {
            Some(g) => {
                g.move_to(&p1.pose, &p2.pose, contact)?;
                g
            }
            gap @ None => gap.insert(SurfacePairGap::new(p1.clone(), p2.clone(), contact)?),
        };
        let gap = &*gap;
        let frame = ContactFrame::of_gap(gap);
        let curvature = gap.curvature();
        // The field solvers' results live here while the view borrows them.
        let solved: NormalSolution<()>;
        let field = match self.spec.backend {
            Backend::Hertz => {
                // Closed form; the friction integral runs over the ellipse (turned in the gap
                // frame) by a quadrature of the semi-ellipsoid, no sampled field.
                // The ellipse's shape warm-started from the last call's.
                let planned = HertzPointContact::new_near(
                    PointGeometry::from_curvature(curvature),
                    self.spec.material1,
                    self.spec.material2,
                    self.last_hertz.as_ref(),
                )?;
                self.last_hertz = Some(planned);
                let h = planned.solve_approach(approach)?;
                FieldView {
                    samples: Samples::Ellipse {
                        semi_axes: h.semi_axes,
                        orientation: h.orientation,
                        max_pressure: h.max_pressure,
                    },
                    orientation: 0.0,
                    centroid: [0.0, 0.0],
                    force: h.force,
                    max_pressure: h.max_pressure,
                    contact_area: h.contact_area,
                    iterations: 0,
                }
            }
            Backend::HalfSpace(_) if self.bem.is_some() => {
                let bem = self.bem.as_ref().ok_or_else(|| {
                    Error::invalid("backend", "no planned solver", "a planned element")
                })?;
                let w = self
                    .warm
                    .solve(bem, gap, approach, self.spec.warm_tolerance)?;
                FieldView {
                    samples: Samples::Binned(w.grid, w.pressure),
                    orientation: w.rotation,
                    centroid: w.zone.centroid,
                    force: w.force,
                    max_pressure: w.zone.max_pressure,
                    contact_area: w.zone.area,
                    iterations: w.iterations,
                }
            }
            Backend::Pimp(_) if self.tracker.is_some() => {
                // The grid and buffers kept between calls, the gap interpolated from a
                // stencil of exact rays (docs/mbs.md).
                let t = self
                    .tracker
                    .as_mut()
                    .ok_or_else(|| Error::invalid("backend", "pimp", "a planned element"))?
                    .evaluate_moved(gap, approach, travel)?;
                FieldView {
                    samples: Samples::Binned(t.grid, t.pressure),
                    orientation: t.orientation,
                    centroid: t.centroid,
                    force: t.force,
                    max_pressure: t.max_pressure,
                    contact_area: t.contact_area,
                    iterations: 0,
                }
            }
            Backend::Pimp(_) | Backend::HalfSpace(_) => {
                solved = match (&self.pimp, &self.bem) {
                    (Some(pimp), _) => pimp.solve_approach(gap, approach)?.map_detail(|_| ()),
                    (None, Some(bem)) => bem.solve_approach(gap, approach)?.map_detail(|_| ()),
                    (None, None) => {
                        return Err(Error::invalid(
                            "backend",
                            "a field back-end without a planned solver",
                            "an element planned by ContactElement::new",
                        ));
                    }
                };
                FieldView {
                    samples: Samples::Grid(solved.grid, &solved.pressure),
                    orientation: solved.orientation,
                    centroid: solved.zone.centroid,
                    force: solved.force,
                    max_pressure: solved.max_pressure,
                    contact_area: solved.contact_area,
                    iterations: solved.status.iterations,
                }
            }
        };
        self.last_area = field.contact_area;
        // The normal force of the back-end (Hertz: the closed form).
        let normal_force = field.force;
        let iterations = field.iterations;
        let n = contact.normal.into_inner();
        let state1 = BodyState {
            pose: *pose1,
            twist: *twist1,
        };
        let state2 = BodyState {
            pose: *pose2,
            twist: *twist2,
        };
        let pair = ContactPair {
            body1: state1,
            body2: state2,
            observer: BodyState::at_rest(),
        };
        // Damping along the normal.
        let v_rel = state1.velocity_at(&contact.point) - state2.velocity_at(&contact.point);
        let approach_rate = -n.dot(&v_rel);
        let mut damping_force = match self.spec.damping {
            Some(d) => d.coefficient * smooth_step(approach / d.ramp) * approach_rate,
            None => 0.0,
        };
        if normal_force + damping_force < 0.0 {
            damping_force = -normal_force;
        }
        // The friction integral over the sampled field, in the grid frame.
        let (s, c) = crate::geometry::sin_cos(field.orientation);
        let (ex, ey) = (frame.ex.into_inner(), frame.ey.into_inner());
        let gx = ex * c + ey * s;
        let gy = -ex * s + ey * c;
        let sliding = pair.velocity_field(&frame, field.orientation)?;
        let mut sums: GridFriction = match field.samples {
            Samples::Grid(grid, pressure) => grid_friction(&grid, pressure, &sliding, &self.law)?,
            Samples::Binned(grid, pressure) => {
                grid_friction_binned(&grid, pressure, &sliding, &self.law)?
            }
            Samples::Ellipse {
                semi_axes,
                orientation,
                max_pressure,
            } => self.hertz_rules.friction(
                semi_axes,
                orientation,
                max_pressure,
                &sliding,
                &self.law,
            )?,
        };
        // Scale the sums to the back-end's normal force (a factor 1 to round-off: the
        // ellipse rule integrates the semi-ellipsoid exactly, the field solvers' fields carry
        // their own force).
        if sums.normal_force > 0.0 {
            let k = normal_force / sums.normal_force;
            sums.force = sums.force.map(|f| f * k);
            sums.moment *= k;
            sums.power *= k;
        }
        let friction_force = gx * sums.force[0] + gy * sums.force[1];
        // Moment of the friction about the grid origin (the contact point), along n.
        let friction_moment = n * sums.moment;
        // Normal force at the centre of pressure.
        let [cx, cy] = field.centroid;
        let centre = frame.origin + gx * cx + gy * cy;
        let fn_vec = n * (normal_force + damping_force);
        let force1 = fn_vec + friction_force;
        let o1 = Point3::from(pose1.translation.vector);
        let o2 = Point3::from(pose2.translation.vector);
        let moment1 = (centre - o1).cross(&fn_vec)
            + friction_moment
            + (frame.origin - o1).cross(&friction_force);
        let moment2 = -(moment1 + (o1 - o2).cross(&force1));
        let r_min = 0.5 / curvature.b_coef;
        let limit = self.spec.max_approach_ratio * r_min;
        let (status, message) = if approach > limit {
            (
                ContactStatus::OutOfValidity,
                format!(
                    "approach {approach:.4e} mm exceeds {:.3} × the smallest relative radius \
                     {r_min:.4e} mm (= {limit:.4e} mm): the contact is no longer small \
                     against the bodies",
                    self.spec.max_approach_ratio
                ),
            )
        } else {
            (ContactStatus::Contact, String::new())
        };
        Ok(ElementResult {
            status,
            separation: contact.separation,
            approach,
            point: contact.point,
            normal: contact.normal,
            normal_force,
            damping_force,
            friction_force,
            friction_moment,
            friction_power: sums.power,
            force1,
            moment1,
            moment2,
            max_pressure: field.max_pressure,
            contact_area: field.contact_area,
            iterations,
            message,
        })
    }
}
