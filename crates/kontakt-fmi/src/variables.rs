//! The FMUs' variables, one table per element: the model description (description.rs)
//! and the binary (model.rs) read the same rows, so that a new output is one row here.
//!
//! Every variable is a Real (FMI 2.0 `fmi2Real`). Value references are the position in
//! [`crate::model::Model::variables`]: the parameters first, then the inputs, then the
//! outputs. The status is a Real output too (0, 1, 2): an Integer would be a discrete
//! variable, which a model-exchange FMU may change only in event mode, while a contact
//! opens and closes in continuous time.

use kontakt::element::{ContactStatus, ElementResult};
use kontakt_case::bearing_model::{BearingElementOutput, BearingElementStatus};

/// How `fmi2GetDirectionalDerivative` obtains an output's partial derivatives.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Derivative {
    /// Row `i` (`Fx, Fy, Fz, Mx, My`) of the bearing's reaction `R = −(F(u) + β K(u) v)`:
    /// `∂R_i/∂u = −K_i`, `∂R_i/∂v = −β K_i` from the element's stiffness K (exact when
    /// `β (∂K/∂u) v` vanishes, i.e. β = 0 or v = 0; otherwise central differences are used).
    Reaction(usize),
    /// Piecewise constant (a status): zero.
    Zero,
    /// Central differences of the evaluation along the seed direction (two evaluations
    /// from the element's state at the call; the state is left unchanged).
    Differences,
}

/// An input: a Real with a start value.
#[derive(Debug, Clone, Copy)]
pub struct Input {
    /// FMI name.
    pub name: &'static str,
    /// Unit (a name of the model description's `UnitDefinitions`), `None` for a number.
    pub unit: Option<&'static str>,
    /// What it is, with frame and sign.
    pub description: &'static str,
    /// Start value.
    pub start: f64,
}

/// An output: a Real computed from an evaluation of type `T`.
#[derive(Debug, Clone, Copy)]
pub struct Output<T> {
    /// FMI name.
    pub name: &'static str,
    /// Unit (a name of `UnitDefinitions`), `None` for a number.
    pub unit: Option<&'static str>,
    /// What it is, with frame and sign.
    pub description: &'static str,
    /// Its value in an evaluation.
    pub value: fn(&T) -> f64,
    /// How its partial derivatives are computed.
    pub derivative: Derivative,
}

/// A parameter: a tunable Real whose start value comes from the case.
#[derive(Debug, Clone, Copy)]
pub struct Parameter {
    /// FMI name.
    pub name: &'static str,
    /// Unit, `None` for a number.
    pub unit: Option<&'static str>,
    /// What it is and the case key it overrides.
    pub description: &'static str,
}

/// The units of every table, as `UnitDefinitions` rows: name, then the SI base-unit
/// exponents `kg, m, s, rad` and the factor to SI.
pub const UNITS: &[(&str, [i32; 4], f64)] = &[
    ("mm", [0, 1, 0, 0], 1e-3),
    ("rad", [0, 0, 0, 1], 1.0),
    ("mm/s", [0, 1, -1, 0], 1e-3),
    ("rad/s", [0, 0, -1, 1], 1.0),
    ("N", [1, 1, -2, 0], 1.0),
    ("N.mm", [1, 2, -2, 0], 1e-3),
    ("W", [1, 2, -3, 0], 1.0),
    ("s", [0, 0, 1, 0], 1.0),
    ("N.s/mm", [1, 0, -1, 0], 1e3),
    ("MPa", [1, -1, -2, 0], 1e6),
    ("mm2", [0, 2, 0, 0], 1e-6),
];

// ---------------------------------------------------------------- the bearing element

/// The bearing element's parameters (start values from the case and the element's
/// defaults).
#[rustfmt::skip]
pub const BEARING_PARAMETERS: &[Parameter] = &[Parameter {
    name: "damping_s",
    unit: Some("s"),
    description: "stiffness-proportional damping beta: the damping matrix is beta times the stiffness (>= 0; 0: no damping)",
}];

/// The bearing element's inputs: the inner ring's displacement and velocity relative to
/// the outer ring, in the outer ring's frame (z the bearing axis).
#[rustfmt::skip]
pub const BEARING_INPUTS: &[Input] = &[
    Input { name: "dx", unit: Some("mm"), description: "displacement of the inner ring relative to the outer ring along x (radial), outer ring's frame", start: 0.0 },
    Input { name: "dy", unit: Some("mm"), description: "displacement of the inner ring along y (radial)", start: 0.0 },
    Input { name: "dz", unit: Some("mm"), description: "displacement of the inner ring along z (the bearing axis)", start: 0.0 },
    Input { name: "theta_x", unit: Some("rad"), description: "small rotation of the inner ring about x through the bearing centre", start: 0.0 },
    Input { name: "theta_y", unit: Some("rad"), description: "small rotation of the inner ring about y through the bearing centre", start: 0.0 },
    Input { name: "vx", unit: Some("mm/s"), description: "velocity of the inner ring relative to the outer ring along x", start: 0.0 },
    Input { name: "vy", unit: Some("mm/s"), description: "velocity of the inner ring along y", start: 0.0 },
    Input { name: "vz", unit: Some("mm/s"), description: "velocity of the inner ring along z", start: 0.0 },
    Input { name: "omega_x", unit: Some("rad/s"), description: "tilt rate of the inner ring about x", start: 0.0 },
    Input { name: "omega_y", unit: Some("rad/s"), description: "tilt rate of the inner ring about y", start: 0.0 },
    Input { name: "omega_inner", unit: Some("rad/s"), description: "inner ring speed about +z for the friction torque (start: the case's [speed])", start: 0.0 },
    Input { name: "omega_outer", unit: Some("rad/s"), description: "outer ring speed about +z for the friction torque (start: the case's [speed])", start: 0.0 },
];

/// The bearing element's outputs: the bearing's reaction on the inner ring (the outer ring
/// gets minus it). A new output of [`BearingElementOutput`] is one row here.
#[rustfmt::skip]
pub const BEARING_OUTPUTS: &[Output<BearingElementOutput>] = &[
    Output { name: "Fx", unit: Some("N"), description: "force of the bearing on the inner ring along x (elastic and damping; the outer ring gets minus it)", value: |o| o.force_n[0], derivative: Derivative::Reaction(0) },
    Output { name: "Fy", unit: Some("N"), description: "force of the bearing on the inner ring along y", value: |o| o.force_n[1], derivative: Derivative::Reaction(1) },
    Output { name: "Fz", unit: Some("N"), description: "force of the bearing on the inner ring along z (the bearing axis)", value: |o| o.force_n[2], derivative: Derivative::Reaction(2) },
    Output { name: "Mx", unit: Some("N.mm"), description: "moment of the bearing on the inner ring about x through the bearing centre", value: |o| o.moment_nmm[0], derivative: Derivative::Reaction(3) },
    Output { name: "My", unit: Some("N.mm"), description: "moment of the bearing on the inner ring about y through the bearing centre", value: |o| o.moment_nmm[1], derivative: Derivative::Reaction(4) },
    Output { name: "Mz", unit: Some("N.mm"), description: "friction moment of the bearing on the inner ring about z, -friction_torque sign(omega_inner - omega_outer) (0 without a [lubricant])", value: |o| o.moment_nmm[2], derivative: Derivative::Differences },
    Output { name: "friction_torque", unit: Some("N.mm"), description: "the bearing's friction torque M >= 0 (the starting torque at equal ring speeds; 0 without a [lubricant])", value: |o| o.friction.torque_nmm, derivative: Derivative::Differences },
    Output { name: "friction_power", unit: Some("W"), description: "friction power 1e-3 M |omega_inner - omega_outer|", value: |o| o.friction.power_w, derivative: Derivative::Differences },
    Output { name: "max_element_load", unit: Some("N"), description: "largest rolling-element load", value: |o| o.max_element_load_n, derivative: Derivative::Differences },
    Output { name: "status", unit: None, description: "0: every rolling element lifted off (zero force), 1: loaded", value: |o| match o.status { BearingElementStatus::LiftedOff => 0.0, BearingElementStatus::Loaded => 1.0 }, derivative: Derivative::Zero },
];

/// The names the bearing element's errors give its arguments, and the FMI variables they
/// are: `displacement[i]` is input i, `velocity[i]` input 5 + i, the ring speeds of
/// `set_speeds` inputs 10 and 11.
pub const BEARING_ARGUMENTS: [&str; 12] = [
    "displacement[0]",
    "displacement[1]",
    "displacement[2]",
    "displacement[3]",
    "displacement[4]",
    "velocity[0]",
    "velocity[1]",
    "velocity[2]",
    "velocity[3]",
    "velocity[4]",
    "inner_rad_s",
    "outer_rad_s",
];

// ---------------------------------------------------------------- the contact element

/// The contact element's parameters (start values from the case).
#[rustfmt::skip]
pub const CONTACT_PARAMETERS: &[Parameter] = &[
    Parameter { name: "damping_coefficient", unit: Some("N.s/mm"), description: "full normal damping coefficient (case key damping.coefficient_n_s_per_mm; 0: no damping)" },
    Parameter { name: "damping_ramp", unit: Some("mm"), description: "approach over which the damping switches on (case key damping.ramp_mm; default 0.001 mm when the case has no damping)" },
    Parameter { name: "mu", unit: None, description: "boundary friction coefficient (case key friction.mu)" },
];

const fn body(
    name: &'static str,
    unit: &'static str,
    description: &'static str,
    start: f64,
) -> Input {
    Input {
        name,
        unit: Some(unit),
        description,
        start,
    }
}

/// The contact element's inputs: the two bodies' poses (position of the reference point,
/// rotation body to world as a unit quaternion) and twists, world frame.
#[rustfmt::skip]
pub const CONTACT_INPUTS: &[Input] = &[
    body("pose1.x", "mm", "body 1: position of its reference point, world frame", 0.0),
    body("pose1.y", "mm", "body 1: position of its reference point", 0.0),
    body("pose1.z", "mm", "body 1: position of its reference point", 0.0),
    Input { name: "pose1.qw", unit: None, description: "body 1: rotation body to world, unit quaternion (w, x, y, z; normalised by the FMU)", start: 1.0 },
    Input { name: "pose1.qx", unit: None, description: "body 1: rotation quaternion, x", start: 0.0 },
    Input { name: "pose1.qy", unit: None, description: "body 1: rotation quaternion, y", start: 0.0 },
    Input { name: "pose1.qz", unit: None, description: "body 1: rotation quaternion, z", start: 0.0 },
    body("pose2.x", "mm", "body 2: position of its reference point, world frame", 0.0),
    body("pose2.y", "mm", "body 2: position of its reference point", 0.0),
    body("pose2.z", "mm", "body 2: position of its reference point", 0.0),
    Input { name: "pose2.qw", unit: None, description: "body 2: rotation body to world, unit quaternion (w, x, y, z; normalised by the FMU)", start: 1.0 },
    Input { name: "pose2.qx", unit: None, description: "body 2: rotation quaternion, x", start: 0.0 },
    Input { name: "pose2.qy", unit: None, description: "body 2: rotation quaternion, y", start: 0.0 },
    Input { name: "pose2.qz", unit: None, description: "body 2: rotation quaternion, z", start: 0.0 },
    body("twist1.vx", "mm/s", "body 1: velocity of its reference point, world frame", 0.0),
    body("twist1.vy", "mm/s", "body 1: velocity of its reference point", 0.0),
    body("twist1.vz", "mm/s", "body 1: velocity of its reference point", 0.0),
    body("twist1.wx", "rad/s", "body 1: angular velocity, world frame", 0.0),
    body("twist1.wy", "rad/s", "body 1: angular velocity", 0.0),
    body("twist1.wz", "rad/s", "body 1: angular velocity", 0.0),
    body("twist2.vx", "mm/s", "body 2: velocity of its reference point, world frame", 0.0),
    body("twist2.vy", "mm/s", "body 2: velocity of its reference point", 0.0),
    body("twist2.vz", "mm/s", "body 2: velocity of its reference point", 0.0),
    body("twist2.wx", "rad/s", "body 2: angular velocity, world frame", 0.0),
    body("twist2.wy", "rad/s", "body 2: angular velocity", 0.0),
    body("twist2.wz", "rad/s", "body 2: angular velocity", 0.0),
];

/// The FMI inputs behind each argument name of the contact element's errors.
pub const CONTACT_ARGUMENTS: [(&str, &str); 4] = [
    ("pose1", "pose1 (inputs pose1.x to pose1.qz)"),
    ("pose2", "pose2 (inputs pose2.x to pose2.qz)"),
    ("twist1", "twist1 (inputs twist1.vx to twist1.wz)"),
    ("twist2", "twist2 (inputs twist2.vx to twist2.wz)"),
];

const fn vector(
    name: &'static str,
    unit: Option<&'static str>,
    description: &'static str,
    value: fn(&ElementResult) -> f64,
) -> Output<ElementResult> {
    Output {
        name,
        unit,
        description,
        value,
        derivative: Derivative::Differences,
    }
}

/// The contact element's outputs (world frame; the normal points from body 2 into body 1;
/// body 2 gets minus the force on body 1).
#[rustfmt::skip]
pub const CONTACT_OUTPUTS: &[Output<ElementResult>] = &[
    vector("force1.x", Some("N"), "total force on body 1 (normal, damping, friction); body 2 gets minus it", |r| r.force1.x),
    vector("force1.y", Some("N"), "total force on body 1", |r| r.force1.y),
    vector("force1.z", Some("N"), "total force on body 1", |r| r.force1.z),
    vector("moment1.x", Some("N.mm"), "moment on body 1 about its reference point", |r| r.moment1.x),
    vector("moment1.y", Some("N.mm"), "moment on body 1 about its reference point", |r| r.moment1.y),
    vector("moment1.z", Some("N.mm"), "moment on body 1 about its reference point", |r| r.moment1.z),
    vector("moment2.x", Some("N.mm"), "moment on body 2 about its reference point", |r| r.moment2.x),
    vector("moment2.y", Some("N.mm"), "moment on body 2 about its reference point", |r| r.moment2.y),
    vector("moment2.z", Some("N.mm"), "moment on body 2 about its reference point", |r| r.moment2.z),
    vector("friction_force.x", Some("N"), "friction force on body 1", |r| r.friction_force.x),
    vector("friction_force.y", Some("N"), "friction force on body 1", |r| r.friction_force.y),
    vector("friction_force.z", Some("N"), "friction force on body 1", |r| r.friction_force.z),
    vector("friction_moment.x", Some("N.mm"), "spin friction moment on body 1 about the contact point", |r| r.friction_moment.x),
    vector("friction_moment.y", Some("N.mm"), "spin friction moment on body 1 about the contact point", |r| r.friction_moment.y),
    vector("friction_moment.z", Some("N.mm"), "spin friction moment on body 1 about the contact point", |r| r.friction_moment.z),
    vector("friction_power", Some("W"), "friction power (>= 0)", |r| r.friction_power),
    vector("point.x", Some("mm"), "contact point (midpoint of the two surface points)", |r| r.point.x),
    vector("point.y", Some("mm"), "contact point", |r| r.point.y),
    vector("point.z", Some("mm"), "contact point", |r| r.point.z),
    vector("normal.x", None, "unit contact normal, from body 2 into body 1", |r| r.normal.x),
    vector("normal.y", None, "unit contact normal", |r| r.normal.y),
    vector("normal.z", None, "unit contact normal", |r| r.normal.z),
    vector("separation", Some("mm"), "signed separation: > 0 apart, < 0 overlapping", |r| r.separation),
    vector("approach", Some("mm"), "approach max(-separation, 0)", |r| r.approach),
    vector("normal_force", Some("N"), "elastic normal force", |r| r.normal_force),
    vector("damping_force", Some("N"), "damping force along the normal", |r| r.damping_force),
    vector("max_pressure", Some("MPa"), "largest contact pressure", |r| r.max_pressure),
    vector("contact_area", Some("mm2"), "contact area", |r| r.contact_area),
    Output { name: "status", unit: None, description: "0: separated, 1: contact, 2: contact beyond the model's validity (the call returns fmi2Discard)", value: |r| match r.status { ContactStatus::Separated => 0.0, ContactStatus::Contact => 1.0, ContactStatus::OutOfValidity => 2.0 }, derivative: Derivative::Zero },
];
