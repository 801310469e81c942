//! Bearing level: the roller end face against the rib of a tapered roller bearing, built
//! from the bearing's parameters (Wirsching et al. (2020) §2.1, Figure 2b and Table 1).
//!
//! Units: mm, N, MPa; angles in degrees at this interface (the case-file convention).
//! The construction and the reading of Table 1 are in `docs/bearing.md`; [`kinematics`]: cage
//! and roller speeds, body twists, sliding and entrainment velocities (docs/bearing.md §4);
//! [`rib_friction`]: rib load, friction torque and power of the whole bearing
//! (docs/friction.md).

pub mod demo;
pub mod kinematics;
pub mod rib_friction;
pub mod roller_rib;
pub mod validation;

pub use demo::{DemoMap, DemoRow, DemoStudy, demo_study};
pub use kinematics::{
    Bodies, BodyState, ContactFrame, ContactPair, ContactVelocities, Directions, TaperedKinematics,
};
pub use rib_friction::{
    BearingRibFriction, Operating, PressureModel, RibFriction, RibFrictionModel, RibLubrication,
    RollerCup, RollerLoads, RollerMass, RollerRibFriction, RollerRibLoad, RollerSet, frustum,
    roller_loads, roller_loads_on_cup,
};
pub use roller_rib::{
    CONTACT_HEIGHT, FaceShape, RibShape, RollerRib, RollerRibSpec, STUDY_FORCES, TABLE1,
    TaperedRollerBearing,
};
