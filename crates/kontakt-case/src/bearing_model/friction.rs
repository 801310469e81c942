//! The friction torque of a bearing element (issue 29 §5): the torque about the bearing
//! axis and the power of the bearing's friction, computed on every
//! [`super::BearingElement::evaluate`] from the load distribution that call has just solved,
//! so that a multi-body simulation gets the forces, the stiffness and the friction in one
//! call.
//!
//! **When.** The friction is on when the element's case has a `[lubricant]` table (with
//! `[friction]` and `[operating]` as in the case's friction section; `[operating]` may be
//! absent: its defaults). Without a lubricant it is off: [`ElementFrictionStatus::Off`] and
//! every field 0. Roller bearings (tapered, cylindrical) and ball bearings (deep groove,
//! angular contact) have it; thrust roller bearings do not yet:
//! [`ElementFrictionStatus::NotBuilt`], every field 0 (the one match to extend is
//! [`FrictionPlan::new`]).
//!
//! **What.** The contact-based torque of `kontakt_bearing::friction::torque`
//! (docs/bearing-friction.md), exactly as the case's report computes it (the same functions of
//! `crate::bearing_friction`): the raceway rolling resistance and sliding of every slice,
//! the rib friction of the roller ends (`roller_model = "rib_contact"`: a tapered bearing's
//! cone rib, a cylindrical bearing's ribs of NJ/NUP/NU/N), the drag term of `operating.drag`. Breakdown: cone (inner raceway), cup (outer
//! raceway), rib, drag; M = cone + cup + rib + drag ≥ 0. A ball bearing's is
//! `kontakt_bearing::friction::ball` (spin and differential slip over every contact
//! ellipse, rolling resistance; outer-race control) as the case's report computes it: its
//! inner race is the breakdown's cone, its outer race the cup, no rib.
//!
//! **Speeds.** The ring speeds ω_i, ω_o \[rad/s\] start as the case's `[speed]`
//! (`speed.inner_rpm`, `speed.outer_rpm` converted from r/min) and are set by
//! [`super::BearingElement::set_speeds`] (a multi-body code sets the shaft speed of each
//! step). They change the friction only: the load distribution keeps the centrifugal
//! forces planned at the case's `[speed]` (the rib-contact and ball models at speed).
//!
//! **Sign.** While the rings turn relative to each other (Δω = ω_i − ω_o ≠ 0) the friction
//! moment of the bearing on the inner ring about +z is `Mz = −M sign(Δω)` (it opposes the
//! relative rotation; the outer ring gets −Mz), and it is the element's `moment_nmm[2]`.
//! The power is `P = M |Δω|` (W, with M in N·mm: `P = 10⁻³ M |Δω|`), ≥ 0. At Δω = 0 the
//! torque is the starting (break-away) torque — the boundary friction of the sliding
//! contacts, no film — reported as `torque_nmm` with [`ElementFrictionStatus::Starting`],
//! but not applied: `Mz = 0` and `P = 0` (its direction is the one of the drive, which the
//! element does not know; a multi-body code models the stick phase itself).
//!
//! **Cost.** One raceway friction evaluation (every slice of every roller); with a tapered
//! bearing's rib contact also one rib contact field per loaded roller, which allocates (the
//! raceway part, the ISO slice models and a cylindrical bearing's ribs, integrated over
//! their Hertz ellipses, allocate nothing; so does a ball bearing's friction).
//!
//! Units: rad/s, N·mm, W.

use crate::bearing_case::{BearingCase, Planned};
use crate::bearing_friction::{
    DragSpec, OperatingSpec, RacewayOil, RacewayPlan, crb_rib_model, crb_rib_values, oil_supply,
    plan_raceways, raceway_oil, rib_model, rib_powers, skf_bearing,
};
use kontakt::bearing::{PressureModel, RibFrictionModel, RollerRibLoad};
use kontakt::{Error, Result};
use kontakt_bearing::friction::ball::{
    BallAttitude, BallContacts, BallFrictionModel, BallFrictionOperating,
};
use kontakt_bearing::friction::crb_rib::CylindricalRibFriction;
use kontakt_bearing::friction::schaeffler::m0;
use kontakt_bearing::friction::skf2004::{SkfBearing, SkfOptions, skf2004};
use kontakt_bearing::friction::torque::{
    BearingFrictionModel, DragModel, FrictionOperating, iso_slice_loads,
};
use kontakt_bearing::friction::{Envelope, Lubrication, OperatingPoint};
use kontakt_bearing::geometry::{BallBearing, RollerBearing, RollerBearingKind};

/// Whether the element computed the friction torque, and which.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ElementFrictionStatus {
    /// The case has no `[lubricant]`: no friction, every field 0.
    Off,
    /// The rings turn relative to each other: the running torque, applied as
    /// `moment_nmm[2]`.
    Running,
    /// Δω = 0: `torque_nmm` is the starting torque; not applied (`moment_nmm[2]` = 0, power 0).
    Starting,
    /// The case has a lubricant but the element has no friction model for its bearing yet
    /// (ball bearings, thrust roller bearings): every field 0.
    NotBuilt,
}

/// The friction of one evaluation (module docs: when, sign, units).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ElementFriction {
    /// Off, running, starting or not built.
    pub status: ElementFrictionStatus,
    /// Inner ring speed ω_i used \[rad/s\].
    pub inner_speed_rad_s: f64,
    /// Outer ring speed ω_o used \[rad/s\].
    pub outer_speed_rad_s: f64,
    /// The bearing's friction torque M ≥ 0 \[N·mm\]: running, or the starting torque at
    /// Δω = 0.
    pub torque_nmm: f64,
    /// The friction moment on the inner ring about +z, `−M sign(ω_i − ω_o)` \[N·mm\] (0 at
    /// Δω = 0): the element's `moment_nmm[2]`.
    pub inner_ring_nmm: f64,
    /// Friction power `10⁻³ M |ω_i − ω_o|` \[W\] (0 at Δω = 0).
    pub power_w: f64,
    /// Cone (inner raceway) share of M, rolling resistance and sliding \[N·mm\].
    pub cone_nmm: f64,
    /// Cup (outer raceway) share of M \[N·mm\].
    pub cup_nmm: f64,
    /// Rib (roller end) share of M \[N·mm\].
    pub rib_nmm: f64,
    /// Drag share of M \[N·mm\].
    pub drag_nmm: f64,
}

/// A friction evaluation's torques \[N·mm\] and power \[W\] as the library reports them:
/// `inner_ring` is the drive's torque on the inner ring (`M sign(Δω)`).
struct Shares {
    total: f64,
    inner_ring: f64,
    power: f64,
    cone: f64,
    cup: f64,
    rib: f64,
    drag: f64,
}

impl ElementFriction {
    /// The element's friction at the ring speeds `[ω_i, ω_o]` \[rad/s\] from the library's
    /// result: running, or at Δω = 0 the starting torque, reported and not applied.
    fn of([wi, wo]: [f64; 2], f: Shares) -> Self {
        let starting = wi == wo;
        ElementFriction {
            status: if starting {
                ElementFrictionStatus::Starting
            } else {
                ElementFrictionStatus::Running
            },
            inner_speed_rad_s: wi,
            outer_speed_rad_s: wo,
            torque_nmm: f.total,
            // the drive's torque on the inner ring is M sign(Δω); the bearing's is minus it
            inner_ring_nmm: if starting { 0.0 } else { -f.inner_ring },
            power_w: f.power,
            cone_nmm: f.cone,
            cup_nmm: f.cup,
            rib_nmm: f.rib,
            drag_nmm: f.drag,
        }
    }

    /// No friction (`status` off or not built) at the speeds `[ω_i, ω_o]` \[rad/s\].
    pub fn none(status: ElementFrictionStatus, speeds: [f64; 2]) -> Self {
        ElementFriction {
            status,
            inner_speed_rad_s: speeds[0],
            outer_speed_rad_s: speeds[1],
            torque_nmm: 0.0,
            inner_ring_nmm: 0.0,
            power_w: 0.0,
            cone_nmm: 0.0,
            cup_nmm: 0.0,
            rib_nmm: 0.0,
            drag_nmm: 0.0,
        }
    }
}

/// The drag term of `operating.drag`, planned: evaluated at each relative speed.
#[derive(Debug, Clone)]
enum DragPlan {
    /// `"none"`.
    None,
    /// `"skf"`: the SKF 2004 drag term of the catalogue bearing.
    Skf {
        bearing: SkfBearing,
        envelope: Envelope,
        supply: Lubrication,
        options: SkfOptions,
    },
    /// `"schaeffler_m0"`: Schaeffler's M0 with f0 and the mean diameter \[mm\].
    M0 { f0: f64, mean_diameter_mm: f64 },
}

impl DragPlan {
    /// The drag model at the relative speed `dw` = |ω_i − ω_o| \[rad/s\] with the oil's
    /// kinematic viscosity `nu` \[mm²/s\], as the case's report computes it.
    fn at(&self, dw: f64, nu: f64) -> Result<DragModel> {
        let point = |lubrication| OperatingPoint {
            speed_rad_s: dw,
            viscosity_mm2_s: nu,
            // the drag term does not depend on the load
            radial_load_n: 0.0,
            axial_load_n: 0.0,
            lubrication,
        };
        Ok(match self {
            DragPlan::None => DragModel::None,
            DragPlan::Skf {
                bearing,
                envelope,
                supply,
                options,
            } => DragModel::Torque {
                nmm: skf2004(bearing, envelope, &point(*supply), options)
                    .map_err(|e| e.map_field(|f| format!("catalogue.{f}")))?
                    .drag_nmm,
            },
            DragPlan::M0 {
                f0,
                mean_diameter_mm,
            } => DragModel::Torque {
                nmm: m0(
                    *f0,
                    nu * point(Lubrication::OilJet).speed_rpm(),
                    *mean_diameter_mm,
                ),
            },
        })
    }
}

/// The planned friction of a roller bearing element: the raceway model, the slice and rib
/// buffers (allocated once), the rib model of a rib-contact solver, the drag.
#[derive(Debug, Clone)]
pub(crate) struct RollerFrictionPlan {
    model: BearingFrictionModel,
    cup: Vec<f64>,
    cone: Vec<f64>,
    tilts: Vec<f64>,
    rib: Option<RibPlan>,
    drag: DragPlan,
    nu: f64,
}

/// The rib friction of a rib-contact solver: its model and buffers.
#[derive(Debug, Clone)]
struct RibPlan {
    model: RibModel,
    values: Vec<f64>,
}

/// The rib friction model of a tapered or a cylindrical bearing.
#[derive(Debug, Clone)]
enum RibModel {
    /// A tapered roller's large end on the cone's rib (the rib study's pair).
    Tapered {
        model: Box<RibFrictionModel>,
        pressure: PressureModel,
        loads: Vec<RollerRibLoad>,
    },
    /// A cylindrical roller's ends on the ribs of its arrangement.
    Cylindrical(Box<CylindricalRibFriction>),
}

/// The element's friction, planned from its case.
#[derive(Debug, Clone)]
pub(crate) enum FrictionPlan {
    /// No `[lubricant]`.
    Off,
    /// A lubricant, but no friction model for this bearing yet.
    NotBuilt,
    /// A roller bearing's friction.
    Roller(Box<RollerFrictionPlan>),
    /// A ball bearing's friction.
    Ball(Box<BallFrictionPlan>),
}

/// The planned friction of a ball bearing element: the ball friction model, the balls'
/// contacts (a buffer, allocated once), the drag.
#[derive(Debug, Clone)]
pub(crate) struct BallFrictionPlan {
    model: BallFrictionModel,
    balls: Vec<BallContacts>,
    drag: DragPlan,
    nu: f64,
}

impl FrictionPlan {
    /// Plan the friction of `case`, whose solver is `planned`.
    ///
    /// # Errors
    /// Those of the case's friction section naming the case key (`lubricant.*`,
    /// `friction.*`, `operating.*`, `catalogue.*`).
    pub(crate) fn new(case: &BearingCase, planned: &Planned) -> Result<Self> {
        let Some(lub) = &case.lubricant else {
            return Ok(FrictionPlan::Off);
        };
        let default = OperatingSpec::default();
        let op = case.operating.as_ref().unwrap_or(&default);
        // The one dispatch on the bearing.
        let (bearing, rib_solver) = match planned {
            Planned::Roller(s) => (s.bearing(), None),
            Planned::Coupled(s) => (s.bearing(), None),
            Planned::RibRoller(s) => (s.bearing(), Some(s.as_ref())),
            Planned::Ball { solver, .. } => {
                return Self::ball(case, op, lub, solver.bearing(), solver.ball_loads().len());
            }
            Planned::BallAtSpeed { solver, .. } => {
                return Self::ball(case, op, lub, solver.bearing(), solver.ball_loads().len());
            }
        };
        if bearing.kind == RollerBearingKind::Thrust {
            return Ok(FrictionPlan::NotBuilt);
        }
        let RacewayPlan {
            model,
            rib_lub,
            law,
            nu,
        } = plan_raceways(op, lub, case.friction.as_ref(), bearing)?;
        let rib = match rib_solver.map(|s| (s.rib_pair(), s.arrangement())) {
            Some((Some(pair), _)) => Some(RibModel::Tapered {
                model: Box::new(rib_model(pair, bearing, law, rib_lub)?),
                pressure: op.rib_pressure,
                loads: Vec::with_capacity(bearing.rollers),
            }),
            Some((None, Some(_))) => {
                crate::bearing_friction::crb_rib_pressure(op)?;
                Some(RibModel::Cylindrical(Box::new(crb_rib_model(
                    bearing, law, rib_lub,
                )?)))
            }
            _ => None,
        }
        .map(|model| RibPlan {
            model,
            values: vec![0.0; bearing.rollers],
        });
        let n = bearing.rollers * bearing.slices;
        Ok(FrictionPlan::Roller(Box::new(RollerFrictionPlan {
            drag: drag_plan(case, op, DragOf::Roller(bearing))?,
            model,
            cup: vec![0.0; n],
            cone: vec![0.0; n],
            tilts: vec![0.0; bearing.rollers],
            rib,
            nu,
        })))
    }

    /// The friction plan of a ball bearing with `balls` balls: the case's friction section's
    /// model (outer-race control, as the speed model assumes).
    fn ball(
        case: &BearingCase,
        op: &OperatingSpec,
        lub: &crate::friction_case::LubricantSpec,
        bearing: &BallBearing,
        balls: usize,
    ) -> Result<Self> {
        let RacewayOil { losses, nu, .. } = raceway_oil(op, lub, case.friction.as_ref())?;
        Ok(FrictionPlan::Ball(Box::new(BallFrictionPlan {
            model: BallFrictionModel::new(bearing.clone(), losses, BallAttitude::OuterRaceControl)?,
            balls: vec![BallContacts::default(); balls],
            drag: drag_plan(case, op, DragOf::Ball(bearing))?,
            nu,
        })))
    }

    /// The friction of `planned`'s last solve at the ring speeds `[ω_i, ω_o]` \[rad/s\]
    /// (finite: the element checks them).
    ///
    /// # Errors
    /// Those of the raceway and rib friction models (a film or rib field that fails).
    pub(crate) fn evaluate(
        &mut self,
        planned: &Planned,
        speeds: [f64; 2],
    ) -> Result<ElementFriction> {
        let p = match self {
            FrictionPlan::Off => {
                return Ok(ElementFriction::none(ElementFrictionStatus::Off, speeds));
            }
            FrictionPlan::NotBuilt => {
                return Ok(ElementFriction::none(
                    ElementFrictionStatus::NotBuilt,
                    speeds,
                ));
            }
            FrictionPlan::Roller(p) => p.as_mut(),
            FrictionPlan::Ball(p) => return p.evaluate(planned, speeds),
        };
        let mut rib = None;
        match planned {
            Planned::Roller(s) => {
                iso_slice_loads(s.slice_loads(), s.roller_loads(), &mut p.cup, &mut p.cone)?;
            }
            Planned::Coupled(s) => {
                iso_slice_loads(s.slice_loads(), s.roller_loads(), &mut p.cup, &mut p.cone)?;
            }
            Planned::RibRoller(s) => {
                p.cup.copy_from_slice(s.cup_slice_loads());
                p.cone.copy_from_slice(s.cone_slice_loads());
                for (t, r) in p.tilts.iter_mut().zip(s.roller_loads()) {
                    *t = r.tilt_rad;
                }
                if let Some(r) = &mut p.rib {
                    match &mut r.model {
                        RibModel::Tapered {
                            model,
                            pressure,
                            loads,
                        } => {
                            rib_powers(model, *pressure, s, speeds, loads, &mut r.values)?;
                        }
                        RibModel::Cylindrical(model) => {
                            crb_rib_values(model, s, speeds, &mut r.values)?;
                        }
                    }
                    rib = Some(r.values.as_slice());
                }
            }
            Planned::Ball { .. } | Planned::BallAtSpeed { .. } => {
                return Ok(ElementFriction::none(
                    ElementFrictionStatus::NotBuilt,
                    speeds,
                ));
            }
        }
        let [wi, wo] = speeds;
        let dw = wi - wo;
        let f = p.model.evaluate(&FrictionOperating {
            inner_speed: wi,
            outer_speed: wo,
            cup_slices: &p.cup,
            cone_slices: &p.cone,
            tilts: Some(&p.tilts),
            rib,
            drag: p.drag.at(dw.abs(), p.nu)?,
            coefficient_basis: None,
        })?;
        Ok(ElementFriction::of(
            speeds,
            Shares {
                total: f.total_nmm,
                inner_ring: f.inner_ring_nmm,
                power: f.power.total_w,
                cone: f.cone.total_nmm(),
                cup: f.cup.total_nmm(),
                rib: f.rib_nmm,
                drag: f.drag_nmm,
            },
        ))
    }
}

/// The bearing a drag plan is for: its oil-level check and its SKF 2004 bearing.
#[derive(Clone, Copy)]
enum DragOf<'a> {
    Roller(&'a RollerBearing),
    Ball(&'a BallBearing),
}

/// The drag of `operating.drag`, with the errors of the case's friction section.
fn drag_plan(case: &BearingCase, op: &OperatingSpec, of: DragOf<'_>) -> Result<DragPlan> {
    let supply = oil_supply(op)?;
    // an oil bath above the bearing's centre: refused as by the case's friction section
    if let kontakt_bearing::friction::Lubrication::OilBath { level_mm } = supply {
        match of {
            DragOf::Roller(b) => crate::bearing_friction::oil_level(level_mm, b)?,
            DragOf::Ball(b) => crate::bearing_friction::oil_level_below(
                level_mm,
                crate::bearing_friction::ball::centre_height_mm(b),
            )?,
        };
    }
    let catalogue = case.catalogue.as_ref();
    let envelope = match catalogue {
        Some(c) => Some(
            Envelope::new(c.bore_mm, c.outer_mm, c.width_mm)
                .map_err(|e| e.map_field(|f| format!("catalogue.{f}")))?,
        ),
        None => None,
    };
    Ok(match op.drag {
        DragSpec::None => DragPlan::None,
        DragSpec::Skf => match (
            catalogue,
            envelope,
            catalogue.and_then(|c| c.skf_series.as_ref()),
        ) {
            (Some(c), Some(envelope), Some(series)) => DragPlan::Skf {
                bearing: match of {
                    DragOf::Roller(b) => skf_bearing(c, series, b)?,
                    DragOf::Ball(b) => {
                        crate::bearing_friction::ball::skf_ball_bearing(c, series, b)?
                    }
                },
                envelope,
                supply,
                options: crate::bearing_friction::skf_options(op, Some(c))?,
            },
            _ => {
                return Err(Error::invalid(
                    "operating.drag",
                    "skf",
                    "\"none\" or \"schaeffler_m0\" unless [catalogue] has skf_series (the SKF drag term needs its series)",
                ));
            }
        },
        DragSpec::SchaefflerM0 => match (catalogue.and_then(|c| c.schaeffler_f0), envelope) {
            (Some(f0), Some(env)) => DragPlan::M0 {
                f0,
                mean_diameter_mm: env.mean_diameter_mm(),
            },
            _ => {
                return Err(Error::invalid(
                    "operating.drag",
                    "schaeffler_m0",
                    "\"none\" or \"skf\" unless [catalogue] has schaeffler_f0",
                ));
            }
        },
    })
}

impl BallFrictionPlan {
    /// The friction of a ball bearing's last solve at the ring speeds `[ω_i, ω_o]`
    /// \[rad/s\]: the inner race is the breakdown's "cone", the outer race its "cup".
    fn evaluate(&mut self, planned: &Planned, speeds: [f64; 2]) -> Result<ElementFriction> {
        match planned {
            Planned::Ball { solver, .. } => {
                for (b, l) in self.balls.iter_mut().zip(solver.ball_loads()) {
                    *b = l.into();
                }
            }
            Planned::BallAtSpeed { solver, .. } => {
                for (b, l) in self.balls.iter_mut().zip(solver.ball_loads()) {
                    *b = l.into();
                }
            }
            _ => {
                return Err(Error::invalid(
                    "bearing",
                    "a roller bearing",
                    "the ball bearing the friction was planned for",
                ));
            }
        }
        let [wi, wo] = speeds;
        let dw = wi - wo;
        let f = self.model.evaluate(&BallFrictionOperating {
            inner_speed: wi,
            outer_speed: wo,
            balls: &self.balls,
            drag: self.drag.at(dw.abs(), self.nu)?,
            coefficient_basis: None,
        })?;
        Ok(ElementFriction::of(
            speeds,
            Shares {
                total: f.total_nmm,
                inner_ring: f.inner_ring_nmm,
                power: f.power.total_w,
                cone: f.inner_race.rolling_nmm + f.inner_race.sliding_nmm,
                cup: f.outer_race.rolling_nmm + f.outer_race.sliding_nmm,
                rib: 0.0,
                drag: f.drag_nmm,
            },
        ))
    }
}
