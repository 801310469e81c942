//! Whole-bearing cases (`method = "bearing"`, `schema_version = 1`): the load distribution
//! of a roller bearing (cylindrical, tapered, cylindrical roller thrust) or a ball bearing
//! (deep groove, angular contact) under forces and moments or prescribed displacements of
//! its inner ring, on [`kontakt_bearing`]'s five-degree-of-freedom equilibrium: the
//! ISO/TS 16281 (2008) slice law for rollers, two Hertz point contacts in series with a
//! load-dependent contact angle for balls (Jones 1960, Harris & Kotzalas 2006).
//!
//! ```toml
//! method = "bearing"
//! [bearing]
//! type = "cylindrical"        # "cylindrical" | "tapered" | "thrust"
//! pitch_diameter_mm = 60.0
//! rollers = 14
//! roller_diameter_mm = 10.0
//! roller_length_mm = 12.0     # effective length L_we
//! clearance_mm = 0.01         # diametral (axial for thrust); negative: preload
//! [bearing.roller_profile]
//! kind = "iso"                # the default
//! [load]
//! force_n = [10000.0, 0.0, 0.0]
//! [load.prescribed]           # degrees of freedom held at a displacement
//! tilt_x_rad = 0.0
//! tilt_y_rad = 0.0
//! ```
//!
//! Frames and signs are those of `docs/bearing-model.md`: the outer ring is fixed, z is
//! the bearing axis, the inner ring moves by `(δx, δy, δz, θx, θy)` (mm, rad) under
//! `(Fx, Fy, Fz, Mx, My)` (N, N·mm). A bearing type is a tag (`type`); the ball bearings
//! are variants with their own keys:
//!
//! ```toml
//! [bearing]
//! type = "deep_groove_ball"   # or "angular_contact_ball" with contact_angle_deg = 40.0
//! pitch_diameter_mm = 38.5
//! balls = 9
//! ball_diameter_mm = 7.938
//! inner_osculation = 0.52     # or inner_groove_radius_mm (exactly one per groove)
//! outer_osculation = 0.53
//! clearance_mm = 0.015        # deep groove: diametral; negative: preload
//! [bearing.ball_material]     # optional, default steel; also [bearing.ring_material]
//! e_mpa = 210000.0
//! nu = 0.3
//! ```
//!
//! Materials: the library's `BallBearing` takes kontakt's `ElasticMaterial`; the case gives
//! it as the `e_mpa`/`nu` table every other schema uses for its bodies
//! (`MaterialSpec`), errors named `bearing.ball_material.nu`.
//!
//! **Not converged.** The report is one equilibrium: a solve that ends at the iteration
//! limit or diverges (a load the bearing cannot carry) is refused as
//! [`Error::NotConverged`] (exit status 1 in the CLI), like the single solves of the field
//! methods; a solve that stagnates at the round-off floor (residual at most 1e-8 of the
//! load, 1000 times the tolerance) is reported with a warning.

use crate::bearing_post::{BallPost, Post, RollerPost, applied_moment};
use crate::bearing_rating::{RatingReport, RatingSpec};
use crate::bearing_slices::{RollerPressures, SliceModel, SliceSolver, pressure_map};
use crate::common::{MaterialSpec, SCHEMA_VERSION, in_degrees, material};
use crate::validity::{ContactSize, checked, checked_report};
use kontakt::solve::{SolveStatus, Termination};
use kontakt::{Error, Result};
use kontakt_bearing::ball_equilibrium::{BallBearingSolver, BallSolution};
use kontakt_bearing::ball_speed::{BallSpeedSolver, RaceControl};
use kontakt_bearing::equilibrium::coupled::CoupledSliceSolver;
use kontakt_bearing::equilibrium::{Dof, RingLoad, RollerBearingSolver, RollerSolution};
use kontakt_bearing::geometry::{
    BallBearing, BallBearingKind, DEFAULT_SLICES, RollerBearing, RollerBearingKind,
};
use kontakt_bearing::profile::{Profile, TabulatedProfile};
use kontakt_bearing::speed::RingSpeeds;
use serde::{Deserialize, Serialize};

mod roller_speed;
mod speed;
pub(crate) use roller_speed::iso_speed_warning;
pub use speed::BearingSpeedSpec;

/// The contact modulus of two steel bodies (E = 210 GPa, ν = 0.3), MPa: the default of the
/// design-load profiles.
pub const STEEL_CONTACT_MODULUS_MPA: f64 = 210_000.0 / (2.0 * (1.0 - 0.09));

/// Most slices of a whole bearing, `rollers × slices` (the solver holds two numbers per
/// slice and evaluates every slice per iteration).
pub const MAX_BEARING_SLICES: usize = 1_000_000;

/// A whole-bearing case, as read from TOML.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize, schemars::JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct BearingCase {
    /// Optional label echoed in the report.
    #[serde(default)]
    pub name: Option<String>,
    /// Must be `"bearing"`.
    pub method: String,
    /// The bearing's internal geometry.
    pub bearing: BearingSpec,
    /// The load of the inner ring.
    pub load: BearingLoadSpec,
    /// `[operating]`: ring speeds and oil supply of the friction torque (issue 29;
    /// `crate::bearing_friction`). Absent: no friction section.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub operating: Option<crate::bearing_friction::OperatingSpec>,
    /// `[lubricant]` of the friction torque (the friction case's schema).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub lubricant: Option<crate::friction_case::LubricantSpec>,
    /// `[friction]`: the friction law of the raceways and ribs (the friction case's schema).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub friction: Option<crate::friction_case::FrictionSpec>,
    /// `[catalogue]`: envelope and series for the catalogue torques.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub catalogue: Option<crate::bearing_friction::CatalogueSpec>,
    /// `[speed]`: the ring speeds in r/min (default at rest), [`BearingSpeedSpec`].
    #[serde(default)]
    pub speed: BearingSpeedSpec,
}

/// `[bearing]`: the type (`type = "cylindrical" | "tapered" | "thrust"`) and its internal
/// geometry.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize, schemars::JsonSchema)]
#[serde(tag = "type", rename_all = "snake_case")]
#[schemars(transform = crate::bearing_design::tapered_boundary_schema)]
pub enum BearingSpec {
    /// A cylindrical roller bearing (contact angle 0; carries no axial load).
    Cylindrical(RollerSpec),
    /// A single-row tapered roller bearing (`cup_angle_deg`, `cone_angle_deg` required).
    Tapered(RollerSpec),
    /// A cylindrical roller thrust bearing, 81xxx (contact angle 90°; no radial load).
    Thrust(RollerSpec),
    /// A single-row deep-groove ball bearing (60xx, 62xx, ...), given by its diametral
    /// clearance.
    DeepGrooveBall(BallSpec),
    /// A single-row angular-contact ball bearing (72xx B, ...), given by its free contact
    /// angle (`contact_angle_deg` required); carries axial load in +z only.
    AngularContactBall(BallSpec),
}

/// The internal geometry of a ball bearing (`docs/bearing-model.md` §8). Lengths in mm,
/// angles in degrees. Each groove is given by its osculation `f = r/D` or by its curvature
/// radius r, one of the two.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize, schemars::JsonSchema)]
#[serde(deny_unknown_fields)]
#[schemars(transform = crate::bearing_design::boundary_schema)]
pub struct BallSpec {
    /// Pitch diameter d_m through the ball centres, mm.
    pub pitch_diameter_mm: f64,
    /// Number of balls Z, 3..=10000.
    pub balls: usize,
    /// Ball diameter D, mm.
    pub ball_diameter_mm: f64,
    /// Inner groove osculation f_i = r_i/D, 0.5 < f_i <= 1 (or `inner_groove_radius_mm`).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub inner_osculation: Option<f64>,
    /// Outer groove osculation f_o = r_o/D, 0.5 < f_o <= 1 (or `outer_groove_radius_mm`).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub outer_osculation: Option<f64>,
    /// Inner groove curvature radius r_i, mm (or `inner_osculation`).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub inner_groove_radius_mm: Option<f64>,
    /// Outer groove curvature radius r_o, mm (or `outer_osculation`).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub outer_groove_radius_mm: Option<f64>,
    /// Deep groove only: the diametral clearance P_d, mm (default 0; negative: preload),
    /// |P_d| < (f_i + f_o − 1) D.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub clearance_mm: Option<f64>,
    /// Angular contact only (required there): the free contact angle α0, degrees,
    /// 0 < α0 < 90.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub contact_angle_deg: Option<f64>,
    /// Azimuth of ball 0 from the x axis toward y, degrees, default 0.
    #[serde(default)]
    pub first_ball_azimuth_deg: f64,
    /// The balls' material (`e_mpa`, `nu`), default steel (210 000 MPa, 0.3).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub ball_material: Option<MaterialSpec>,
    /// The rings' material (`e_mpa`, `nu`), default steel (210 000 MPa, 0.3).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub ring_material: Option<MaterialSpec>,
    /// The boundary dimensions the missing keys above were generated from
    /// ([`crate::bearing_design`]); absent: every key given.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub boundary: Option<crate::bearing_design::BoundarySpec>,
    /// `[bearing.rating]`: the catalogue's C and C0 for the ISO 281 life and ISO 76 static
    /// safety (`docs/bearing-model.md`, "Life and static safety").
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub rating: Option<RatingSpec>,
    /// The balls' density, kg/m³ (default steel 7850; silicon nitride about 3200, with its
    /// `ball_material`): their centrifugal force and gyroscopic moment at speed.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub ball_density_kg_m3: Option<f64>,
}

/// The internal geometry of a roller bearing. Lengths in mm, angles in degrees.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize, schemars::JsonSchema)]
#[serde(deny_unknown_fields)]
#[schemars(transform = crate::bearing_design::boundary_schema)]
pub struct RollerSpec {
    /// Pitch diameter d_m through the roller centres (thrust: the mean diameter of the
    /// roller path), mm.
    pub pitch_diameter_mm: f64,
    /// Number of rollers Z, 3..=10000.
    pub rollers: usize,
    /// Roller diameter D_we (tapered: the mean diameter), mm.
    pub roller_diameter_mm: f64,
    /// Effective roller length L_we (the contact line), mm.
    pub roller_length_mm: f64,
    /// Tapered only: the cup (outer raceway) angle α to the radial plane, degrees, 0 < α < 90.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub cup_angle_deg: Option<f64>,
    /// Tapered only: the cone (inner raceway) angle α_i, degrees, 0 < α_i < α.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub cone_angle_deg: Option<f64>,
    /// Tapered only: the direction of the rib force on the roller, degrees (default
    /// `(α + α_i)/2 + 90`, along the roller axis).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub rib_angle_deg: Option<f64>,
    /// Operating clearance along the contact normal, both sides together (diametral for a
    /// radial bearing, axial for a thrust bearing), mm; negative: preload. Default 0.
    #[serde(default)]
    pub clearance_mm: f64,
    /// Slices along a roller: odd, 1..=10001, default 31.
    #[serde(default = "default_slices")]
    pub slices: usize,
    /// Azimuth of roller 0 from the x axis toward y, degrees, default 0.
    #[serde(default)]
    pub first_roller_azimuth_deg: f64,
    /// The roller's profile (both of its contacts); default the ISO/TS 16281 profile.
    #[serde(default = "ProfileSpec::default_roller")]
    pub roller_profile: ProfileSpec,
    /// The inner raceway's profile; default straight.
    #[serde(default = "ProfileSpec::straight")]
    pub inner_profile: ProfileSpec,
    /// The outer raceway's profile; default straight.
    #[serde(default = "ProfileSpec::straight")]
    pub outer_profile: ProfileSpec,
    /// The boundary dimensions the missing keys above were generated from
    /// ([`crate::bearing_design`]); absent: every key given.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub boundary: Option<crate::bearing_design::BoundarySpec>,
    /// How the slices carry load: `"iso"` (ISO/TS 16281, default) or `"coupled"`
    /// (half-space strips; reports the pressure of every slice).
    #[serde(default)]
    pub slice_model: SliceModel,
    /// `[bearing.rating]`: the catalogue's C and C0 for the ISO 281 life, the ISO/TS 16281
    /// lamina life and the ISO 76 static safety (`docs/bearing-model.md`, "Life and static safety").
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub rating: Option<RatingSpec>,
    /// Tapered only: `"iso"` (the default: the ISO/TS 16281 slice law of both contacts in
    /// series, the rib load from the roller's force balance) or `"rib_contact"` (every
    /// roller in its own force and moment balance, the rib a Hertz contact;
    /// `docs/bearing-model.md` §15; needs `[bearing.rib_contact]`).
    // Serialized even at its default: the unknown-key check compares the file's keys with
    // what was read, so a skipped default would refuse `roller_model = "iso"` written out.
    #[serde(default)]
    pub roller_model: crate::bearing_rib::RollerModel,
    /// With `roller_model = "rib_contact"`: the roller end/rib pair.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub rib_contact: Option<crate::bearing_rib::RibContactSpec>,
    /// The rollers' density, kg/m³ (default steel 7850): their centrifugal force at speed
    /// (`roller_model = "rib_contact"`, `docs/bearing-model.md` §15.7).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub roller_density_kg_m3: Option<f64>,
}

fn default_slices() -> usize {
    DEFAULT_SLICES
}

/// A roller or raceway profile (`kind = ...`), drops in mm at the axial position from the
/// roller centre; the formulas are those of `docs/bearing-model.md` §4. `length_mm`
/// defaults to the roller length, `contact_modulus_mpa` to steel on steel (115 385 MPa).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize, schemars::JsonSchema)]
#[serde(tag = "kind", rename_all = "snake_case", deny_unknown_fields)]
pub enum ProfileSpec {
    /// No profile.
    Straight,
    /// The ISO/TS 16281 logarithmic profile of the roller (its length and diameter).
    Iso,
    /// Logarithmic with a straight centre: `A ln[1/(1 − u²)]`.
    LogarithmicFlat {
        /// Scale A, mm.
        drop_scale_mm: f64,
        /// Crowned length, mm (default the roller length).
        #[serde(default, skip_serializing_if = "Option::is_none")]
        length_mm: Option<f64>,
        /// Straight centre, mm (default 0).
        #[serde(default)]
        flat_length_mm: f64,
    },
    /// Lundberg (1939) for the design load `load_n`.
    Lundberg {
        /// Design load Q, N.
        load_n: f64,
        /// Effective length, mm (default the roller length).
        #[serde(default, skip_serializing_if = "Option::is_none")]
        length_mm: Option<f64>,
        /// Contact modulus E*, MPa (default steel).
        #[serde(default, skip_serializing_if = "Option::is_none")]
        contact_modulus_mpa: Option<f64>,
    },
    /// Johns & Gohar (1981): Lundberg's profile, finite at the ends.
    JohnsGohar {
        /// Design load Q, N.
        load_n: f64,
        /// Effective length, mm (default the roller length).
        #[serde(default, skip_serializing_if = "Option::is_none")]
        length_mm: Option<f64>,
        /// Contact modulus E*, MPa (default steel).
        #[serde(default, skip_serializing_if = "Option::is_none")]
        contact_modulus_mpa: Option<f64>,
        /// Reduced radius of the contact, mm.
        reduced_radius_mm: f64,
    },
    /// Modified logarithmic after Fujiwara & Kawase (2007) (reconstructed from the abstract).
    Fujiwara {
        /// Design load Q, N.
        load_n: f64,
        /// Effective length, mm (default the roller length).
        #[serde(default, skip_serializing_if = "Option::is_none")]
        length_mm: Option<f64>,
        /// Contact modulus E*, MPa (default steel).
        #[serde(default, skip_serializing_if = "Option::is_none")]
        contact_modulus_mpa: Option<f64>,
        /// Load coefficient K1.
        k1: f64,
        /// Crowned fraction of the length K2, 0 < K2 ≤ 1.
        k2: f64,
        /// Drop at the end z_m, mm (absent: no cap).
        #[serde(default, skip_serializing_if = "Option::is_none")]
        edge_drop_mm: Option<f64>,
    },
    /// Circular crowning tangent to a straight centre.
    Circular {
        /// Crown radius, mm.
        radius_mm: f64,
        /// Straight centre, mm (default 0).
        #[serde(default)]
        flat_length_mm: f64,
    },
    /// A straight roller with rounded edges.
    EdgeRadii {
        /// Effective length, mm (default the roller length).
        #[serde(default, skip_serializing_if = "Option::is_none")]
        length_mm: Option<f64>,
        /// Edge radius r, mm.
        edge_radius_mm: f64,
        /// Axial length c of each rounded edge, mm.
        edge_length_mm: f64,
    },
    /// A table of drops at positions from the roller centre (monotone cubic, Fritsch &
    /// Carlson 1980).
    Tabulated {
        /// Positions |x| from the roller centre, mm, from 0, increasing.
        x_mm: Vec<f64>,
        /// Drops there, mm (0 at x = 0).
        drop_mm: Vec<f64>,
    },
}

impl ProfileSpec {
    fn default_roller() -> Self {
        ProfileSpec::Iso
    }

    fn straight() -> Self {
        ProfileSpec::Straight
    }

    /// The library profile for a roller of length `l` and diameter `d` (mm); errors named
    /// by the library's field (`x_mm[2]`), prefixed by the caller.
    fn profile(&self, l: f64, d: f64) -> Result<Profile> {
        let e = |m: Option<f64>| m.unwrap_or(STEEL_CONTACT_MODULUS_MPA);
        Ok(match self {
            ProfileSpec::Straight => Profile::Straight,
            ProfileSpec::Iso => Profile::iso(l, d),
            ProfileSpec::LogarithmicFlat {
                drop_scale_mm,
                length_mm,
                flat_length_mm,
            } => Profile::Logarithmic {
                drop_scale_mm: *drop_scale_mm,
                length_mm: length_mm.unwrap_or(l),
                flat_length_mm: *flat_length_mm,
            },
            ProfileSpec::Lundberg {
                load_n,
                length_mm,
                contact_modulus_mpa,
            } => Profile::Lundberg {
                load_n: *load_n,
                length_mm: length_mm.unwrap_or(l),
                contact_modulus_mpa: e(*contact_modulus_mpa),
            },
            ProfileSpec::JohnsGohar {
                load_n,
                length_mm,
                contact_modulus_mpa,
                reduced_radius_mm,
            } => Profile::JohnsGohar {
                load_n: *load_n,
                length_mm: length_mm.unwrap_or(l),
                contact_modulus_mpa: e(*contact_modulus_mpa),
                reduced_radius_mm: *reduced_radius_mm,
            },
            ProfileSpec::Fujiwara {
                load_n,
                length_mm,
                contact_modulus_mpa,
                k1,
                k2,
                edge_drop_mm,
            } => Profile::Fujiwara {
                load_n: *load_n,
                length_mm: length_mm.unwrap_or(l),
                contact_modulus_mpa: e(*contact_modulus_mpa),
                k1: *k1,
                k2: *k2,
                edge_drop_mm: *edge_drop_mm,
            },
            ProfileSpec::Circular {
                radius_mm,
                flat_length_mm,
            } => Profile::Circular {
                radius_mm: *radius_mm,
                flat_length_mm: *flat_length_mm,
            },
            ProfileSpec::EdgeRadii {
                length_mm,
                edge_radius_mm,
                edge_length_mm,
            } => Profile::EdgeRadii {
                length_mm: length_mm.unwrap_or(l),
                edge_radius_mm: *edge_radius_mm,
                edge_length_mm: *edge_length_mm,
            },
            ProfileSpec::Tabulated { x_mm, drop_mm } => {
                Profile::Tabulated(TabulatedProfile::new(x_mm.clone(), drop_mm.clone())?)
            }
        })
    }
}

/// `[load]`: forces and moments on the inner ring, and the degrees of freedom held at a
/// prescribed displacement instead.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize, schemars::JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct BearingLoadSpec {
    /// `[Fx, Fy, Fz]`, N (default zero); z is the bearing axis.
    #[serde(default)]
    pub force_n: [f64; 3],
    /// `[Mx, My]`, N·mm (default zero).
    #[serde(default)]
    pub moment_nmm: [f64; 2],
    /// Degrees of freedom held at a displacement (their force entry must then be 0; the
    /// report gives the reaction).
    #[serde(default)]
    pub prescribed: PrescribedSpec,
}

/// `[load.prescribed]`: a displacement (mm) or tilt (rad) per degree of freedom; absent
/// ones are force-controlled.
#[derive(Debug, Clone, Copy, PartialEq, Default, Serialize, Deserialize, schemars::JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct PrescribedSpec {
    /// δx, mm.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub dx_mm: Option<f64>,
    /// δy, mm.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub dy_mm: Option<f64>,
    /// δz, mm.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub dz_mm: Option<f64>,
    /// θx, rad (0: the shaft holds the tilt).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub tilt_x_rad: Option<f64>,
    /// θy, rad.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub tilt_y_rad: Option<f64>,
}

impl PrescribedSpec {
    fn dofs(&self) -> [Option<f64>; 5] {
        [
            self.dx_mm,
            self.dy_mm,
            self.dz_mm,
            self.tilt_x_rad,
            self.tilt_y_rad,
        ]
    }
}

/// The case-file key of a load component `i` (0..5): `load.force_n[2]`, `load.moment_nmm[0]`.
fn force_key(i: usize) -> String {
    if i < 3 {
        format!("load.force_n[{i}]")
    } else {
        format!("load.moment_nmm[{}]", i - 3)
    }
}

/// The library's load field (`load.fz_n`, `load.tilt_x_rad`) as the case file's key.
fn load_key(field: &str) -> Option<String> {
    use kontakt_bearing::equilibrium::{DISPLACEMENT_NAMES, FORCE_NAMES};
    let name = field.strip_prefix("load.")?;
    if let Some(i) = FORCE_NAMES.iter().position(|n| *n == name) {
        return Some(force_key(i));
    }
    DISPLACEMENT_NAMES
        .iter()
        .position(|n| *n == name)
        .map(|i| format!("load.prescribed.{}", DISPLACEMENT_NAMES[i]))
}

/// One roller of the report.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct RollerRow {
    /// Azimuth ψ from x toward y, degrees.
    pub azimuth_deg: f64,
    /// Inner raceway (cone) load Q_i, N.
    pub inner_load_n: f64,
    /// Outer raceway (cup) load Q_o, N.
    pub outer_load_n: f64,
    /// Rib load Q_f, N (tapered rollers; 0 otherwise).
    pub rib_load_n: f64,
    /// The largest slice load per unit length, N/mm.
    pub max_load_per_length_n_per_mm: f64,
    /// The largest slice approach, mm (negative: lifted off by that much).
    pub approach_mm: f64,
    /// The largest Hertz pressure of the roller's slices on the inner raceway, MPa.
    pub inner_max_pressure_mpa: f64,
    /// The largest Hertz pressure of the roller's slices on the outer raceway, MPa.
    pub outer_max_pressure_mpa: f64,
    /// `roller_model = "rib_contact"` only: the roller's tilt in its axial plane, rad
    /// (positive: the small end toward the bearing axis).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub roller_tilt_rad: Option<f64>,
    /// `roller_model = "rib_contact"` only: the maximum Hertz pressure on the rib, MPa.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub rib_max_pressure_mpa: Option<f64>,
    /// `roller_model = "rib_contact"` only: the skew moment about the cup normal, N·mm
    /// (0: the model has no friction).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub skew_moment_nmm: Option<f64>,
    /// `roller_model = "rib_contact"`, cylindrical only: the load on the outer ring's ribs,
    /// N (`rib_load_n` is then the inner ring's).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub outer_rib_load_n: Option<f64>,
    /// `roller_model = "rib_contact"` at speed only: the roller's centrifugal force
    /// `F_c = m ω_c² r_c`, N (`docs/bearing-model.md` §15.7).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub centrifugal_force_n: Option<f64>,
}

/// The slices of the most loaded roller.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct SliceTable {
    /// Index of the roller in `rollers` (0-based).
    pub roller: usize,
    /// Slice centres from the roller centre along its axis (toward the small end of a
    /// tapered roller), mm.
    pub position_mm: Vec<f64>,
    /// Slice loads, N.
    pub load_n: Vec<f64>,
    /// Slice loads per unit length, N/mm.
    pub load_per_length_n_per_mm: Vec<f64>,
    /// Slice approaches, mm.
    pub approach_mm: Vec<f64>,
    /// Maximum Hertz pressure of each slice on the inner raceway, MPa.
    pub inner_pressure_mpa: Vec<f64>,
    /// Maximum Hertz pressure of each slice on the outer raceway, MPa.
    pub outer_pressure_mpa: Vec<f64>,
    /// `roller_model = "rib_contact"` only: the cone (inner raceway) slice loads, N;
    /// `load_n` is then the cup's and `approach_mm` the sum of both contacts' approaches.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub inner_load_n: Option<Vec<f64>>,
}

/// The solver's status.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct BearingSolverEcho {
    /// Whether the equilibrium reached the tolerance.
    pub converged: bool,
    /// `converged`, `stagnated` (reported with a warning); the others are refused.
    pub termination: &'static str,
    /// Newton iterations.
    pub iterations: usize,
    /// Largest residual of a force-controlled component over the load scale (forces to
    /// F_ref, moments to F_ref d_m/2), dimensionless.
    pub residual: f64,
}

/// The result of a whole-bearing case. Keys carry their units; the keys of the rolling
/// elements are those of [`RollerPart`] (roller bearings) or [`BallPart`] (ball bearings),
/// at the top level of the JSON.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct BearingReport {
    /// Version of kontakt that produced the record.
    pub kontakt_version: &'static str,
    /// Version of this schema.
    pub schema_version: u32,
    /// The case's name, if any.
    pub name: Option<String>,
    /// `"bearing"`.
    pub method: &'static str,
    /// `"cylindrical"`, `"tapered"`, `"thrust"`, `"deep_groove_ball"` or
    /// `"angular_contact_ball"`.
    pub bearing_type: &'static str,
    /// The rolling elements: rollers or balls.
    #[serde(flatten)]
    pub elements: BearingElements,
    /// Inner-ring displacement `[δx, δy, δz]`, mm.
    pub displacement_mm: [f64; 3],
    /// Inner-ring tilt `[θx, θy]`, rad.
    pub tilt_rad: [f64; 2],
    /// The force the rolling elements carry `[Fx, Fy, Fz]`, N: the applied force on
    /// force-controlled components (to the residual), the reaction on prescribed ones.
    pub force_n: [f64; 3],
    /// The moment the rolling elements carry `[Mx, My]`, N·mm (as `force_n`).
    pub moment_nmm: [f64; 2],
    /// How the equilibrium solve ended.
    pub solver: BearingSolverEcho,
    /// The load-zone parameter ε (Sjövall 1933) from the ring displacement; absent without
    /// a radial displacement and for thrust bearings. Exact for rigid rings without tilt.
    /// Ball bearings: from the balls' approach around the ring (at speed the inner
    /// contact's), `docs/bearing-model.md` §16.5.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub load_zone_epsilon: Option<f64>,
    /// The names of the degrees of freedom, the order of the stiffness matrix's rows and
    /// columns.
    pub stiffness_dofs: [&'static str; 5],
    /// The 5 × 5 stiffness matrix `∂(carried load)/∂(displacement)`, row i the load
    /// component, column j the displacement; units in `stiffness_units`.
    pub stiffness_matrix: [[f64; 5]; 5],
    /// The unit of every entry of `stiffness_matrix`.
    pub stiffness_units: [[&'static str; 5]; 5],
    /// Results to treat with care. Absent when none applies.
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub warnings: Vec<String>,
    /// The ring speeds `[inner, outer]`, r/min, when not at rest (`[speed]`).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub ring_speeds_rpm: Option<[f64; 2]>,
    /// The Hertz contacts of the most loaded ball, inner and outer raceway, or of the most
    /// loaded roller's most loaded slice on each raceway, sized for the validity check. Not
    /// in the JSON.
    #[serde(skip)]
    pub contacts: Vec<ContactSize>,
    /// Static safety and rating lives (`docs/bearing-model.md`, "Life and static safety").
    pub rating: RatingReport,
    /// The friction torque, contact by contact, beside the catalogue torques (with
    /// `[operating]`; `docs/bearing-friction.md`).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub friction: Option<crate::bearing_friction::FrictionReport>,
}

/// The rolling elements of a [`BearingReport`], their keys flattened into the report.
#[derive(Debug, Clone, PartialEq, Serialize)]
#[serde(untagged)]
// a report, built once per solve: the roller part's size does not matter
#[allow(clippy::large_enum_variant)]
pub enum BearingElements {
    /// A roller bearing (cylindrical, tapered, thrust).
    Rollers(RollerPart),
    /// A ball bearing (deep groove, angular contact).
    Balls(BallPart),
}

impl BearingReport {
    /// The rollers of a roller bearing (`None` for a ball bearing).
    pub fn rollers(&self) -> Option<&RollerPart> {
        match &self.elements {
            BearingElements::Rollers(r) => Some(r),
            BearingElements::Balls(_) => None,
        }
    }

    /// The balls of a ball bearing (`None` for a roller bearing).
    pub fn balls(&self) -> Option<&BallPart> {
        match &self.elements {
            BearingElements::Balls(b) => Some(b),
            BearingElements::Rollers(_) => None,
        }
    }
}

/// The report keys of a roller bearing.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct RollerPart {
    /// Number of rollers Z.
    pub rollers: usize,
    /// Slices per roller.
    pub slices: usize,
    /// The contact angle (cup angle) α, degrees.
    pub contact_angle_deg: f64,
    /// The cone angle α_i, degrees.
    pub cone_angle_deg: f64,
    /// The ISO/TS 16281 stiffness of one roller, `35948 L_we^(8/9)`, N/mm^(10/9).
    pub roller_stiffness_n_per_mm10_9: f64,
    /// The largest roller (outer raceway) load, N.
    pub max_roller_load_n: f64,
    /// The largest slice load per unit length of any roller, N/mm.
    pub max_load_per_length_n_per_mm: f64,
    /// Per roller, in azimuth order.
    pub roller_loads: Vec<RollerRow>,
    /// The slices of the most loaded roller.
    pub most_loaded_roller: SliceTable,
    /// Every roller's slice loads per unit length, N/mm: one row per roller (in the order
    /// of `roller_loads`), one value per slice (at `most_loaded_roller.position_mm`); 0
    /// where a slice is lifted off. The map of `kontakt bearing --map`.
    pub slice_load_per_length_n_per_mm: Vec<Vec<f64>>,
    /// `slice_model = "coupled"`: the pressure along every roller (keys
    /// `max_pressure_mpa`, `slice_pressure_mpa`).
    #[serde(flatten)]
    pub pressure: Option<Box<RollerPressures>>,
    /// The largest Hertz pressure of any slice on the inner raceway, MPa.
    pub max_inner_pressure_mpa: f64,
    /// The largest Hertz pressure of any slice on the outer raceway, MPa.
    pub max_outer_pressure_mpa: f64,
    /// `"rib_contact"` when the rollers are in their own balance with a Hertz rib contact
    /// (absent for the default ISO model).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub roller_model: Option<&'static str>,
    /// `roller_model = "rib_contact"` only: the largest Hertz pressure on the rib, MPa.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub max_rib_pressure_mpa: Option<f64>,
    /// `roller_model = "rib_contact"` only: the rib normal's direction (rib into roller)
    /// of the roller end/rib pair, measured like the contact angles, degrees.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub rib_normal_deg: Option<f64>,
    /// `roller_model = "rib_contact"` only: the rib contact's force law in the balance,
    /// `"hertz"` or `"pimp"` (`bearing.rib_contact.model`); `max_rib_pressure_mpa` and the
    /// rollers' `rib_max_pressure_mpa` are that model's.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub rib_model: Option<&'static str>,
}

/// The report keys of a ball bearing.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct BallPart {
    /// Number of balls Z.
    pub balls: usize,
    /// The free contact angle α0, degrees: the given one of an angular-contact bearing,
    /// `acos(1 − P_d/(2 B D))` of a deep-groove one (0 with no clearance or a preload).
    pub free_contact_angle_deg: f64,
    /// The ball's load coefficient K_n of both Hertz contacts in series, `Q = K_n δ^1.5`,
    /// N/mm^1.5.
    pub ball_stiffness_n_per_mm1_5: f64,
    /// The largest ball load, N.
    pub max_ball_load_n: f64,
    /// The largest Hertz pressure on the inner raceway, MPa.
    pub max_inner_pressure_mpa: f64,
    /// The largest Hertz pressure on the outer raceway, MPa.
    pub max_outer_pressure_mpa: f64,
    /// Per ball, in azimuth order.
    pub ball_loads: Vec<BallRow>,
    /// At speed: the race-control assumption of the balls' kinematics and gyroscopic
    /// moment, `"outer"` (Jones 1960; `docs/bearing-model.md` §16).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub race_control: Option<&'static str>,
}

/// One ball of the report.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct BallRow {
    /// Azimuth ψ from x toward y, degrees.
    pub azimuth_deg: f64,
    /// The ball's load Q, N: the same on both raceways at rest; at speed the inner
    /// raceway's (`inner_load_n`), the load the ring feels.
    pub load_n: f64,
    /// The loaded contact angle α, degrees, the same at both raceways at rest (negative: a
    /// deep groove's other shoulder); at speed the inner one (`inner_contact_angle_deg`). The balls carry the applied force as
    /// `Σ Q (cos α cos ψ, cos α sin ψ, sin α)`.
    pub contact_angle_deg: f64,
    /// The total approach of both contacts, mm (negative: lifted off by that much).
    pub approach_mm: f64,
    /// Maximum Hertz pressure on the inner raceway, MPa.
    pub inner_max_pressure_mpa: f64,
    /// Maximum Hertz pressure on the outer raceway, MPa.
    pub outer_max_pressure_mpa: f64,
    /// Inner raceway load Q_i, N (at rest: `load_n`).
    pub inner_load_n: f64,
    /// Outer raceway load Q_o, N (at rest: `load_n`; at speed it carries the centrifugal
    /// force too).
    pub outer_load_n: f64,
    /// Inner contact angle α_i, degrees (at rest: `contact_angle_deg`).
    pub inner_contact_angle_deg: f64,
    /// Outer contact angle α_o, degrees (at rest: `contact_angle_deg`; it falls with speed).
    pub outer_contact_angle_deg: f64,
    /// Centrifugal force of the ball `F_c = ½ m d_m ω_c²`, N (0 at rest).
    pub centrifugal_force_n: f64,
    /// Gyroscopic moment of the ball `M_g = J ω_R ω_c sin β`, N·mm (0 at rest), held by
    /// the outer contact (outer-race control).
    pub gyroscopic_moment_nmm: f64,
}

checked_report!(BearingReport);

const DOFS: [&str; 5] = ["x_mm", "y_mm", "z_mm", "tilt_x_rad", "tilt_y_rad"];

fn stiffness_units() -> [[&'static str; 5]; 5] {
    std::array::from_fn(|i| {
        std::array::from_fn(|j| match (i < 3, j < 3) {
            (true, true) => "N/mm",
            (true, false) => "N/rad",
            (false, true) => "N",
            (false, false) => "N*mm/rad",
        })
    })
}

impl BearingCase {
    /// Parse a whole-bearing case from TOML text.
    ///
    /// # Errors
    /// [`Error::CaseFile`] (line, key path, what the schema takes) for malformed TOML,
    /// unknown keys or wrong types.
    pub fn from_toml_str(text: &str) -> Result<Self> {
        crate::bearing_design::parse_bearing_case(text)
    }
}

/// The case's bearing as the library's [`RollerBearing`]: errors named by the case key.
fn roller_bearing(
    kind: RollerBearingKind,
    s: &RollerSpec,
    label: &'static str,
) -> Result<RollerBearing> {
    let (l, d) = (s.roller_length_mm, s.roller_diameter_mm);
    let mut b = match kind {
        RollerBearingKind::Cylindrical => {
            RollerBearing::cylindrical(s.pitch_diameter_mm, s.rollers, d, l)
        }
        RollerBearingKind::Thrust => RollerBearing::thrust(s.pitch_diameter_mm, s.rollers, d, l),
        RollerBearingKind::Tapered => {
            let need = |v: Option<f64>, key: &str| {
                v.ok_or_else(|| Error::CaseFile {
                    line: None,
                    key: format!("bearing.{key}").into(),
                    message: format!(
                        "missing key `bearing.{key}`: a tapered roller bearing needs its cup and cone angles [deg]"
                    ),
                })
            };
            let cup = need(s.cup_angle_deg, "cup_angle_deg")?;
            let cone = need(s.cone_angle_deg, "cone_angle_deg")?;
            let mut b = RollerBearing::tapered(
                s.pitch_diameter_mm,
                s.rollers,
                d,
                l,
                cup.to_radians(),
                cone.to_radians(),
            );
            b.rib_angle_rad = s.rib_angle_deg.map(f64::to_radians);
            b
        }
    };
    if kind != RollerBearingKind::Tapered {
        for (key, v) in [
            ("cup_angle_deg", s.cup_angle_deg),
            ("cone_angle_deg", s.cone_angle_deg),
            ("rib_angle_deg", s.rib_angle_deg),
        ] {
            if let Some(v) = v {
                return Err(Error::invalid(
                    format!("bearing.{key}"),
                    v,
                    format!(
                        "no {key} for type = \"{label}\" (its contact angle is fixed; the angles are for type = \"tapered\")"
                    ),
                ));
            }
        }
    }
    b.clearance_mm = s.clearance_mm;
    b.slices = s.slices;
    b.first_roller_azimuth_rad = s.first_roller_azimuth_deg.to_radians();
    // the profiles take the roller's length and diameter; `validate` checks those first
    for (name, p, slot) in [
        ("roller_profile", &s.roller_profile, 0),
        ("inner_profile", &s.inner_profile, 1),
        ("outer_profile", &s.outer_profile, 2),
    ] {
        let profile = p
            .profile(l, d)
            .map_err(|e| e.map_field(|f| format!("bearing.{name}.{f}")))?;
        match slot {
            0 => b.roller_profile = profile,
            1 => b.inner_profile = profile,
            _ => b.outer_profile = profile,
        }
    }
    if s.rollers.saturating_mul(s.slices) > MAX_BEARING_SLICES {
        return Err(Error::invalid(
            "bearing.slices",
            s.slices,
            format!(
                "rollers × slices <= {MAX_BEARING_SLICES} (here {} rollers)",
                s.rollers
            ),
        ));
    }
    b.validate().map_err(|e| {
        let e = map_bearing_field(e);
        // the angles are typed in degrees
        let e = in_degrees(
            e,
            "bearing.cup_angle_deg",
            "bearing.cup_angle_deg",
            s.cup_angle_deg.unwrap_or(0.0),
        );
        // the library's range names the cup angle in rad: say it in the file's degrees
        let e = match e {
            Error::InvalidInput { field, .. } if field == "bearing.cone_angle_deg" => {
                Error::invalid(
                    "bearing.cone_angle_deg",
                    s.cone_angle_deg.unwrap_or(0.0),
                    format!(
                        "0 < cone angle < cup_angle_deg = {} deg for a tapered roller bearing",
                        s.cup_angle_deg.unwrap_or(0.0)
                    ),
                )
            }
            other => other,
        };
        let rib = b.rib_angle().to_degrees();
        let e = in_degrees(e, "bearing.rib_angle_deg", "bearing.rib_angle_deg", rib);
        in_degrees(
            e,
            "bearing.first_roller_azimuth_deg",
            "bearing.first_roller_azimuth_deg",
            s.first_roller_azimuth_deg,
        )
    })?;
    Ok(b)
}

/// The library's field names of [`RollerBearing`] as the case file's keys.
fn map_bearing_field(e: Error) -> Error {
    e.map_field(|f| {
        let key = match f {
            "effective_length_mm" => "roller_length_mm",
            "contact_angle_rad" => "cup_angle_deg",
            "cone_angle_rad" => "cone_angle_deg",
            "rib_angle_rad" => "rib_angle_deg",
            "first_roller_azimuth_rad" => "first_roller_azimuth_deg",
            other => other,
        };
        format!("bearing.{key}")
    })
}

/// Run a whole-bearing case.
///
/// # Errors
/// [`Error::InvalidInput`], [`Error::Geometry`] or [`Error::CaseFile`] naming the case key
/// (`bearing.roller_diameter_mm`, `bearing.roller_profile.load_n`, `load.force_n[2]`, ...),
/// [`Error::NotConverged`] for an equilibrium that ends at the iteration limit or diverges.
pub fn run_bearing_case(case: &BearingCase) -> Result<BearingReport> {
    checked(run_bearing_case_unchecked(case)?)
}

/// [`run_bearing_case`] before the validity check of [`crate::validity::checked`]: a cold
/// solve, the first solve of a [`crate::BearingModel`].
pub(crate) fn run_bearing_case_unchecked(case: &BearingCase) -> Result<BearingReport> {
    let (mut planned, label) = plan(case)?;
    solve_planned(case, label, &mut planned, &case.load, None)
}

/// The friction section (`crate::bearing_friction`) of a case whose `planned` solver has
/// just solved.
fn friction_of_planned(
    case: &BearingCase,
    op: &crate::bearing_friction::OperatingSpec,
    planned: &Planned,
    force: [f64; 3],
) -> Result<crate::bearing_friction::FrictionReport> {
    use crate::bearing_friction::Solved;
    use crate::bearing_friction::ball::friction_report as ball_friction;
    let tables = crate::bearing_friction::Tables {
        rpm: [case.speed.inner_rpm, case.speed.outer_rpm],
        lubricant: case.lubricant.as_ref(),
        friction: case.friction.as_ref(),
        catalogue: case.catalogue.as_ref(),
    };
    let (bearing, solved) = match planned {
        Planned::Roller(s) => (
            s.bearing(),
            Solved::Iso {
                slice_loads: s.slice_loads(),
                rollers: s.roller_loads(),
            },
        ),
        Planned::Coupled(s) => (
            s.bearing(),
            Solved::Iso {
                slice_loads: s.slice_loads(),
                rollers: s.roller_loads(),
            },
        ),
        Planned::RibRoller(s) => (s.bearing(), Solved::Rib(s)),
        Planned::Ball { solver, .. } => {
            let balls: Vec<_> = solver.ball_loads().iter().map(Into::into).collect();
            return ball_friction(&tables, op, solver.bearing(), &balls, force);
        }
        Planned::BallAtSpeed { solver, .. } => {
            let balls: Vec<_> = solver.ball_loads().iter().map(Into::into).collect();
            return ball_friction(&tables, op, solver.bearing(), &balls, force);
        }
    };
    crate::bearing_friction::friction_report(
        op,
        [case.speed.inner_rpm, case.speed.outer_rpm],
        case.lubricant.as_ref(),
        case.friction.as_ref(),
        case.catalogue.as_ref(),
        bearing,
        solved,
        force,
    )
}

/// The solver of a bearing case, planned once (the state of a [`crate::BearingModel`]).
#[derive(Debug, Clone)]
pub(crate) enum Planned {
    /// A roller bearing.
    Roller(RollerBearingSolver),
    /// A roller bearing with coupled slices.
    Coupled(Box<CoupledSliceSolver>),
    /// A tapered roller bearing with `roller_model = "rib_contact"`.
    RibRoller(Box<kontakt_bearing::roller_equilibrium::RibContactSolver>),
    /// A ball bearing, with its case keys for the errors of a solve.
    Ball {
        solver: BallBearingSolver,
        spec: Box<BallSpec>,
        keys: GrooveKeys,
    },
    /// A ball bearing at speed (`[speed]` not at rest).
    BallAtSpeed {
        solver: Box<BallSpeedSolver>,
        spec: Box<BallSpec>,
        keys: GrooveKeys,
    },
}

/// Plan the solver of `case`'s bearing: errors named by the case key.
pub(crate) fn plan(case: &BearingCase) -> Result<(Planned, &'static str)> {
    if case.method != "bearing" {
        return Err(Error::invalid(
            "method",
            &case.method,
            "\"bearing\" for this schema",
        ));
    }
    let (kind, s, label) = match &case.bearing {
        BearingSpec::Cylindrical(s) => (RollerBearingKind::Cylindrical, s, "cylindrical"),
        BearingSpec::Tapered(s) => (RollerBearingKind::Tapered, s, "tapered"),
        BearingSpec::Thrust(s) => (RollerBearingKind::Thrust, s, "thrust"),
        BearingSpec::DeepGrooveBall(s) => {
            let speeds = case.speed.ring_speeds()?;
            return plan_ball(BallBearingKind::DeepGroove, s, "deep_groove_ball", speeds);
        }
        BearingSpec::AngularContactBall(s) => {
            let speeds = case.speed.ring_speeds()?;
            return plan_ball(
                BallBearingKind::AngularContact,
                s,
                "angular_contact_ball",
                speeds,
            );
        }
    };
    let speeds = roller_speed::ring_speeds(&case.speed, s, label)?;
    let bearing = roller_bearing(kind, s, label)?;
    if s.slice_model == SliceModel::Coupled {
        if !s.roller_model.is_iso() {
            return Err(Error::invalid(
                "bearing.slice_model",
                "coupled",
                "\"iso\" with roller_model = \"rib_contact\" (the rib-contact roller model has independent slices; coupled slices with rollers in their own balance are not built yet)",
            ));
        }
        let solver = CoupledSliceSolver::new(bearing).map_err(map_bearing_field)?;
        return Ok((Planned::Coupled(Box::new(solver)), label));
    }
    let rib = s.rib_contact.as_ref();
    if let Some(mut solver) =
        crate::bearing_rib::plan_rib(s.roller_model, rib, s.rib_angle_deg, label, &bearing)?
    {
        roller_speed::set_centrifugal(&mut solver, s, speeds)?;
        return Ok((Planned::RibRoller(Box::new(solver)), label));
    }
    let solver = RollerBearingSolver::new(bearing).map_err(map_bearing_field)?;
    Ok((Planned::Roller(solver), label))
}

/// Solve a planned bearing under `load` from `start` (the closed forms when `None`) and
/// report it.
pub(crate) fn solve_planned(
    case: &BearingCase,
    label: &'static str,
    planned: &mut Planned,
    load: &BearingLoadSpec,
    start: Option<[f64; 5]>,
) -> Result<BearingReport> {
    let load_spec = load;
    let load = ring_load(load)?;
    let mut report = match planned {
        Planned::Roller(solver) => roller_report(case, label, solver, &load, start),
        Planned::Coupled(solver) => roller_report(case, label, solver.as_mut(), &load, start),
        Planned::RibRoller(solver) => rib_roller_report(case, label, solver, &load, start),
        Planned::Ball { solver, spec, keys } => {
            let solver = BallSolver::AtRest(solver);
            ball_report(case, label, solver, spec, keys, &load, start)
        }
        Planned::BallAtSpeed { solver, spec, keys } => {
            let solver = BallSolver::AtSpeed(solver);
            ball_report(case, label, solver, spec, keys, &load, start)
        }
    }?;
    if let Some(op) = &case.operating {
        report.friction = Some(friction_of_planned(case, op, planned, report.force_n)?);
        // operating.sweep_axial_n / sweep_radial_n: re-solve at each point
        crate::bearing_friction::load_sweep(case, label, planned, load_spec, &mut report)?;
    }
    Ok(report)
}

/// The report of a roller bearing's solve.
fn roller_report<S: SliceSolver>(
    case: &BearingCase,
    label: &'static str,
    solver: &mut S,
    load: &RingLoad,
    start: Option<[f64; 5]>,
) -> Result<BearingReport> {
    let sol = match start {
        Some(u) => solver.solve_from(load, u),
        None => solver.solve(load),
    }
    .map_err(map_load)?;
    let b = solver.bearing();
    let ns = b.slices;
    let width = b.effective_length_mm / ns as f64;
    let loads = solver.slice_loads();
    let approaches = solver.slice_approaches();
    let moment = applied_moment(load);
    let (post, warnings, mut pressures) = roller_post(case, b, &sol, |p, w, each| {
        p.run(&*solver, &sol, moment, w, each)
    })?;
    let most = pressures.most;
    let mut rows = Vec::with_capacity(b.rollers);
    for (j, r) in solver.roller_loads().iter().enumerate() {
        let slice_max = loads[j * ns..(j + 1) * ns]
            .iter()
            .copied()
            .fold(0.0, f64::max);
        rows.push(RollerRow {
            azimuth_deg: r.azimuth_rad.to_degrees(),
            inner_load_n: r.inner_n,
            outer_load_n: r.outer_n,
            rib_load_n: r.rib_n,
            max_load_per_length_n_per_mm: slice_max / width,
            approach_mm: r.max_approach_mm,
            inner_max_pressure_mpa: pressures.per_roller[j][0],
            outer_max_pressure_mpa: pressures.per_roller[j][1],
            roller_tilt_rad: None,
            rib_max_pressure_mpa: None,
            skew_moment_nmm: None,
            outer_rib_load_n: None,
            centrifugal_force_n: None,
        });
    }
    let slice_loads = loads[most * ns..(most + 1) * ns].to_vec();
    let most_loaded = SliceTable {
        roller: most,
        position_mm: solver.slice_positions().to_vec(),
        load_per_length_n_per_mm: slice_loads.iter().map(|q| q / width).collect(),
        load_n: slice_loads,
        approach_mm: approaches[most * ns..(most + 1) * ns].to_vec(),
        inner_pressure_mpa: std::mem::take(&mut pressures.most_inner),
        outer_pressure_mpa: std::mem::take(&mut pressures.most_outer),
        inner_load_n: None,
    };
    let map = pressure_map(solver).map(|(map, m)| {
        Box::new(RollerPressures {
            max_pressure_mpa: m.iter().copied().fold(0.0, f64::max),
            slice_pressure_mpa: map,
        })
    });
    let parts = RollerParts {
        rows,
        most_loaded,
        slice_loads: loads,
        pressure_map: map,
    };
    let mut report = roller_part_report(case, label, b, &sol, parts, post, warnings);
    roller_speed::report_iso_speed(&case.speed, &mut report);
    Ok(report)
}

/// The rating spec of a roller bearing case (`[bearing.rating]`).
pub(crate) fn roller_rating(case: &BearingCase) -> Option<&crate::bearing_rating::RatingSpec> {
    match &case.bearing {
        BearingSpec::Cylindrical(s) | BearingSpec::Tapered(s) | BearingSpec::Thrust(s) => {
            s.rating.as_ref()
        }
        _ => None,
    }
}

/// The pressures, rating and most loaded contacts of a roller model's solve `sol`: the
/// solver's warnings, then `run` ([`RollerPost::run`] or [`RollerPost::run_rib`]), the one
/// post-solve path of the report and the sweep's rows ([`crate::bearing_post`]), with the
/// pressures collected for the report.
fn roller_post(
    case: &BearingCase,
    b: &RollerBearing,
    sol: &RollerSolution,
    run: impl FnOnce(
        &mut RollerPost,
        &mut Vec<String>,
        &mut dyn FnMut(usize, [f64; 2], &[f64], &[f64], bool),
    ) -> Result<Post>,
) -> Result<(Post, Vec<String>, Pressures)> {
    let mut warnings = solver_warnings(&sol.status, sol.note)?;
    let mut pressures = Pressures::default();
    let mut post = RollerPost::new(b, roller_rating(case))?;
    let post = run(
        &mut post,
        &mut warnings,
        &mut |j, peaks, inner, outer, most| pressures.add(j, peaks, inner, outer, most),
    )?;
    Ok((post, warnings, pressures))
}

/// The slice pressures the post gives a report: per roller `[inner, outer]` maxima and
/// the slices of the most loaded roller, MPa.
#[derive(Default)]
struct Pressures {
    per_roller: Vec<[f64; 2]>,
    most: usize,
    most_inner: Vec<f64>,
    most_outer: Vec<f64>,
}

impl Pressures {
    fn add(&mut self, j: usize, peaks: [f64; 2], inner: &[f64], outer: &[f64], most: bool) {
        self.per_roller.push(peaks);
        if most {
            self.most = j;
            self.most_inner = inner.to_vec();
            self.most_outer = outer.to_vec();
        }
    }
}

/// What a roller model's solve gives the shared part of its report.
struct RollerParts<'a> {
    rows: Vec<RollerRow>,
    most_loaded: SliceTable,
    /// The outer raceway's slice loads, roller-major, N.
    slice_loads: &'a [f64],
    pressure_map: Option<Box<RollerPressures>>,
}

/// The report of a roller bearing from its solution, its rows and the slices of its most
/// loaded roller, for every roller model: the solver's warnings, the static safety and the
/// lives (`bearing_rating`), the contact sizes; the rib-contact keys unset.
fn roller_part_report(
    case: &BearingCase,
    label: &'static str,
    b: &RollerBearing,
    sol: &RollerSolution,
    parts: RollerParts<'_>,
    post: Post,
    warnings: Vec<String>,
) -> BearingReport {
    let p_max = post.max_pressure_mpa;
    let ns = b.slices;
    let width = b.effective_length_mm / ns as f64;
    let elements = BearingElements::Rollers(RollerPart {
        rollers: b.rollers,
        slices: b.slices,
        contact_angle_deg: b.contact_angle_rad.to_degrees(),
        cone_angle_deg: b.cone_angle_rad.to_degrees(),
        roller_stiffness_n_per_mm10_9: b.roller_stiffness(),
        max_roller_load_n: sol.max_roller_load_n,
        max_load_per_length_n_per_mm: parts
            .rows
            .iter()
            .map(|r| r.max_load_per_length_n_per_mm)
            .fold(0.0, f64::max),
        roller_loads: parts.rows,
        most_loaded_roller: parts.most_loaded,
        slice_load_per_length_n_per_mm: parts
            .slice_loads
            .chunks_exact(ns)
            .take(b.rollers)
            .map(|c| c.iter().map(|q| q / width).collect())
            .collect(),
        pressure: parts.pressure_map,
        max_inner_pressure_mpa: p_max[0],
        max_outer_pressure_mpa: p_max[1],
        roller_model: None,
        max_rib_pressure_mpa: None,
        rib_normal_deg: None,
        rib_model: None,
    });
    let mut report = report(case, label, elements, sol.displacement, sol.load);
    report.solver = solver_echo(&sol.status);
    report.load_zone_epsilon = sol.load_zone;
    report.stiffness_matrix = sol.stiffness;
    report.warnings = warnings;
    report.contacts = post.contact_sizes();
    report.rating = post.rating;
    report
}

/// The report of a rib-contact solve: the ISO report's keys (cup load as `outer_load_n`,
/// cone load as `inner_load_n`) with the roller's tilt, the rib pressure and the skew
/// moment per roller, the cone slices of the most loaded roller. The raceway pressures
/// are the Hertz line contacts of the cup slices, the cone's scaled by the roller's
/// cone-to-cup load ratio (as the ISO model's); the cone's own slice distribution under
/// the roller's tilt is not yet used for them.
fn rib_roller_report(
    case: &BearingCase,
    label: &'static str,
    solver: &mut kontakt_bearing::roller_equilibrium::RibContactSolver,
    load: &RingLoad,
    start: Option<[f64; 5]>,
) -> Result<BearingReport> {
    let sol = match start {
        Some(u) => solver.solve_from(load, u),
        None => solver.solve(load),
    }
    .map_err(map_load)?;
    let b = solver.bearing();
    let ns = b.slices;
    let width = b.effective_length_mm / ns as f64;
    let (cup, cone) = (solver.cup_slice_loads(), solver.cone_slice_loads());
    // the rib contact's size check included
    let moment = applied_moment(load);
    let (post, warnings, mut pressures) = roller_post(case, b, &sol, |p, w, each| {
        p.run_rib(solver, &sol, moment, w, each)
    })?;
    let most = pressures.most;
    let mut rows = Vec::with_capacity(b.rollers);
    for (j, r) in solver.roller_loads().iter().enumerate() {
        let slice_max = cup[j * ns..(j + 1) * ns]
            .iter()
            .chain(&cone[j * ns..(j + 1) * ns])
            .fold(0.0, |m: f64, q| m.max(*q));
        rows.push(RollerRow {
            azimuth_deg: r.azimuth_rad.to_degrees(),
            inner_load_n: r.inner_n,
            outer_load_n: r.outer_n,
            rib_load_n: r.rib_n,
            max_load_per_length_n_per_mm: slice_max / width,
            approach_mm: r.max_approach_mm,
            inner_max_pressure_mpa: pressures.per_roller[j][0],
            outer_max_pressure_mpa: pressures.per_roller[j][1],
            roller_tilt_rad: Some(r.tilt_rad),
            rib_max_pressure_mpa: Some(r.rib_max_pressure_mpa),
            skew_moment_nmm: Some(r.skew_moment_nmm),
            outer_rib_load_n: solver.arrangement().map(|_| r.outer_rib_n),
            centrifugal_force_n: None,
        });
    }
    let range = most * ns..(most + 1) * ns;
    let cup_slices = cup[range.clone()].to_vec();
    let most_loaded = SliceTable {
        roller: most,
        position_mm: solver.slice_positions().to_vec(),
        load_per_length_n_per_mm: cup_slices.iter().map(|q| q / width).collect(),
        load_n: cup_slices,
        approach_mm: solver.slice_approaches()[range.clone()].to_vec(),
        inner_pressure_mpa: std::mem::take(&mut pressures.most_inner),
        outer_pressure_mpa: std::mem::take(&mut pressures.most_outer),
        inner_load_n: Some(cone[range].to_vec()),
    };
    let parts = RollerParts {
        rows,
        most_loaded,
        slice_loads: cup,
        pressure_map: None,
    };
    let mut report = roller_part_report(case, label, b, &sol, parts, post, warnings);
    roller_speed::report_speed(&case.speed, solver, &mut report);
    if let BearingElements::Rollers(p) = &mut report.elements {
        p.roller_model = Some("rib_contact");
        p.max_rib_pressure_mpa = Some(solver.max_rib_pressure_mpa());
        p.rib_normal_deg = solver
            .rib_pair()
            .map(|_| solver.rib_normal_angle().to_degrees());
        p.rib_model = Some(solver.rib_model().as_str());
    }
    Ok(report)
}

/// The library's load-field errors (`load.fz_n`) as the case file's keys.
pub(crate) fn map_load(e: Error) -> Error {
    e.map_field(|f| load_key(f).unwrap_or_else(|| f.to_string()))
}

/// `[load]` as the library's [`RingLoad`]: a prescribed degree of freedom must have no
/// force entry.
pub(crate) fn ring_load(l: &BearingLoadSpec) -> Result<RingLoad> {
    let applied = [
        l.force_n[0],
        l.force_n[1],
        l.force_n[2],
        l.moment_nmm[0],
        l.moment_nmm[1],
    ];
    let prescribed = l.prescribed.dofs();
    let mut dofs = [Dof::Force(0.0); 5];
    for i in 0..5 {
        dofs[i] = match prescribed[i] {
            Some(u) => {
                if applied[i] != 0.0 {
                    return Err(Error::invalid(
                        force_key(i),
                        applied[i],
                        format!(
                            "0 where load.prescribed.{} holds the displacement (a degree of freedom is force- or displacement-controlled)",
                            kontakt_bearing::equilibrium::DISPLACEMENT_NAMES[i]
                        ),
                    ));
                }
                Dof::Displacement(u)
            }
            None => Dof::Force(applied[i]),
        };
    }
    Ok(RingLoad { dofs })
}

/// The warnings of a solve's status (stagnated, the library's note), or the refusal of a
/// solve that did not converge.
pub(crate) fn solver_warnings(
    status: &SolveStatus,
    note: Option<&'static str>,
) -> Result<Vec<String>> {
    let mut warnings = Vec::new();
    match status.termination {
        Termination::Converged => {}
        Termination::Stagnated => warnings.push(format!(
            "the equilibrium stagnated at the round-off floor after {} iterations (residual {:.1e} of the load, tolerance 1e-11)",
            status.iterations, status.residual
        )),
        _ => {
            let what = format!("bearing equilibrium: {}", note.unwrap_or("no equilibrium"));
            status.require_converged(what)?;
        }
    }
    if let Some(note) = note
        && status.termination == Termination::Converged
    {
        warnings.push(note.to_string());
    }
    Ok(warnings)
}

fn solver_echo(status: &SolveStatus) -> BearingSolverEcho {
    BearingSolverEcho {
        converged: status.converged(),
        termination: status.termination.as_str(),
        iterations: status.iterations,
        residual: status.residual,
    }
}

/// The report's common keys; the caller sets the solver, ε, stiffness and warnings.
fn report(
    case: &BearingCase,
    label: &'static str,
    elements: BearingElements,
    u: [f64; 5],
    load: [f64; 5],
) -> BearingReport {
    BearingReport {
        kontakt_version: kontakt::VERSION,
        schema_version: SCHEMA_VERSION,
        name: case.name.clone(),
        method: "bearing",
        bearing_type: label,
        elements,
        displacement_mm: [u[0], u[1], u[2]],
        tilt_rad: [u[3], u[4]],
        force_n: [load[0], load[1], load[2]],
        moment_nmm: [load[3], load[4]],
        solver: BearingSolverEcho {
            converged: false,
            termination: "",
            iterations: 0,
            residual: 0.0,
        },
        load_zone_epsilon: None,
        ring_speeds_rpm: None,
        stiffness_dofs: DOFS,
        stiffness_matrix: [[0.0; 5]; 5],
        stiffness_units: stiffness_units(),
        warnings: Vec::new(),
        contacts: Vec::new(),
        rating: RatingReport::default(),
        friction: None,
    }
}

/// The case keys of a ball bearing's grooves, as the file gives them: the osculation key
/// or the groove-radius key of the inner and the outer ring.
#[derive(Debug, Clone, Copy)]
pub(crate) struct GrooveKeys {
    pub(crate) inner: &'static str,
    pub(crate) outer: &'static str,
}

/// A groove's osculation f = r/D from exactly one of its two keys.
fn osculation(f: Option<f64>, r: Option<f64>, ring: &str, d: f64) -> Result<(f64, &'static str)> {
    let (f_key, r_key): (&'static str, &'static str) = if ring == "inner" {
        ("inner_osculation", "inner_groove_radius_mm")
    } else {
        ("outer_osculation", "outer_groove_radius_mm")
    };
    match (f, r) {
        (Some(f), None) => Ok((f, f_key)),
        (None, Some(r)) => Ok((r / d, r_key)),
        (Some(_), Some(_)) => Err(Error::CaseFile {
            line: None,
            key: format!("bearing.{f_key}, bearing.{r_key}").into(),
            message: format!(
                "both `bearing.{f_key}` and `bearing.{r_key}` given: the {ring} groove takes exactly one of them (the osculation f = r/D or the groove radius r [mm])"
            ),
        }),
        (None, None) => Err(Error::CaseFile {
            line: None,
            key: format!("bearing.{f_key}").into(),
            message: format!(
                "missing key `bearing.{f_key}` (or `bearing.{r_key}`): a ball bearing's {ring} groove needs its osculation f = r/D or its groove radius r [mm], exactly one"
            ),
        }),
    }
}

/// The case's ball bearing as the library's [`BallBearing`]: errors named by the case key.
fn ball_bearing(
    kind: BallBearingKind,
    s: &BallSpec,
    label: &'static str,
) -> Result<(BallBearing, GrooveKeys)> {
    let d = s.ball_diameter_mm;
    let (f_i, inner) = osculation(s.inner_osculation, s.inner_groove_radius_mm, "inner", d)?;
    let (f_o, outer) = osculation(s.outer_osculation, s.outer_groove_radius_mm, "outer", d)?;
    let keys = GrooveKeys { inner, outer };
    let wrong_key = |key: &str, v: f64, why: &str| {
        Error::invalid(
            format!("bearing.{key}"),
            v,
            format!("no {key} for type = \"{label}\" ({why})"),
        )
    };
    let mut b = match kind {
        BallBearingKind::DeepGroove => {
            if let Some(a) = s.contact_angle_deg {
                return Err(wrong_key(
                    "contact_angle_deg",
                    a,
                    "its free contact angle follows from clearance_mm; the angle is for type = \"angular_contact_ball\"",
                ));
            }
            let mut b = BallBearing::deep_groove(s.pitch_diameter_mm, s.balls, d, [f_i, f_o]);
            b.clearance_mm = s.clearance_mm.unwrap_or(0.0);
            b
        }
        BallBearingKind::AngularContact => {
            if let Some(c) = s.clearance_mm {
                return Err(wrong_key(
                    "clearance_mm",
                    c,
                    "its free contact angle contact_angle_deg sets the play; clearance_mm is for type = \"deep_groove_ball\"",
                ));
            }
            let a = s.contact_angle_deg.ok_or_else(|| Error::CaseFile {
                line: None,
                key: "bearing.contact_angle_deg".into(),
                message: "missing key `bearing.contact_angle_deg`: an angular-contact ball bearing needs its free contact angle [deg], 0 < angle < 90".into(),
            })?;
            BallBearing::angular_contact(
                s.pitch_diameter_mm,
                s.balls,
                d,
                [f_i, f_o],
                a.to_radians(),
            )
        }
    };
    b.first_ball_azimuth_rad = s.first_ball_azimuth_deg.to_radians();
    if let Some(m) = &s.ball_material {
        b.ball_material = material(m, "bearing.ball_material")?;
    }
    if let Some(m) = &s.ring_material {
        b.ring_material = material(m, "bearing.ring_material")?;
    }
    if let Some(rho) = s.ball_density_kg_m3 {
        b.ball_density_kg_m3 = rho;
    }
    b.validate()
        .map_err(|e| map_ball_field(e, s, &keys, [f_i, f_o]))?;
    Ok((b, keys))
}

/// The library's field names of [`BallBearing`] as the case file's keys, in the units the
/// file gives them (degrees, a groove radius in mm).
pub(crate) fn map_ball_field(e: Error, s: &BallSpec, keys: &GrooveKeys, f: [f64; 2]) -> Error {
    let d = s.ball_diameter_mm;
    // a groove typed as a radius: its value and range in mm
    let e = match e {
        Error::InvalidInput { field, .. }
            if (field == "inner_osculation" && keys.inner.ends_with("_mm"))
                || (field == "outer_osculation" && keys.outer.ends_with("_mm")) =>
        {
            let (key, r, f) = if field == "inner_osculation" {
                (keys.inner, s.inner_groove_radius_mm, f[0])
            } else {
                (keys.outer, s.outer_groove_radius_mm, f[1])
            };
            Error::invalid(
                format!("bearing.{key}"),
                r.unwrap_or(f64::NAN),
                format!(
                    "a groove radius 0.5 D < r <= D with D = ball_diameter_mm = {d} mm (here r/D = {f}; typically 0.515 D to 0.54 D)"
                ),
            )
        }
        other => other,
    };
    let e = e.map_field(|f| {
        let key = match f {
            "inner_osculation" => keys.inner,
            "outer_osculation" => keys.outer,
            "contact_angle_rad" => "contact_angle_deg",
            "first_ball_azimuth_rad" => "first_ball_azimuth_deg",
            other if other.starts_with("bearing.") => return other.to_string(),
            other => other,
        };
        format!("bearing.{key}")
    });
    let e = in_degrees(
        e,
        "bearing.contact_angle_deg",
        "bearing.contact_angle_deg",
        s.contact_angle_deg.unwrap_or(0.0),
    );
    in_degrees(
        e,
        "bearing.first_ball_azimuth_deg",
        "bearing.first_ball_azimuth_deg",
        s.first_ball_azimuth_deg,
    )
}

/// Plan a ball bearing's solver: errors named by the case key.
fn plan_ball(
    kind: BallBearingKind,
    s: &BallSpec,
    label: &'static str,
    speeds: Option<RingSpeeds>,
) -> Result<(Planned, &'static str)> {
    let (bearing, keys) = ball_bearing(kind, s, label)?;
    let f = [bearing.inner_osculation, bearing.outer_osculation];
    let spec = Box::new(s.clone());
    if let Some(speeds) = speeds {
        let solver = BallSpeedSolver::new(bearing, speeds, RaceControl::Outer)
            .map_err(|e| map_ball_field(e, s, &keys, f))?;
        let solver = Box::new(solver);
        return Ok((Planned::BallAtSpeed { solver, spec, keys }, label));
    }
    let solver = BallBearingSolver::new(bearing).map_err(|e| map_ball_field(e, s, &keys, f))?;
    Ok((Planned::Ball { solver, spec, keys }, label))
}

/// A ball bearing's solver: at rest, or at speed.
pub(crate) enum BallSolver<'a> {
    /// The quasi-static equilibrium (§8).
    AtRest(&'a mut BallBearingSolver),
    /// The high-speed model (§16).
    AtSpeed(&'a mut BallSpeedSolver),
}

/// The report of a ball bearing's solve: the library's equilibrium (Jones 1960, Harris &
/// Kotzalas 2006; at rest or at speed) and the Hertz contacts of the most loaded ball on
/// each raceway for the validity check.
fn ball_report(
    case: &BearingCase,
    label: &'static str,
    mut solver: BallSolver<'_>,
    s: &BallSpec,
    keys: &GrooveKeys,
    load: &RingLoad,
    start: Option<[f64; 5]>,
) -> Result<BearingReport> {
    let sol = match (&mut solver, start) {
        (BallSolver::AtRest(s), Some(u)) => s.solve_from(load, u),
        (BallSolver::AtRest(s), None) => s.solve(load),
        (BallSolver::AtSpeed(s), Some(u)) => s.solve_from(load, u),
        (BallSolver::AtSpeed(s), None) => s.solve(load),
    }
    .map_err(map_load)?;
    let (rows, q_max) = match &solver {
        BallSolver::AtRest(solver) => rest_rows(solver, &sol),
        BallSolver::AtSpeed(solver) => speed::speed_rows(solver),
    };
    let (b, k_n, race_control) = match &solver {
        BallSolver::AtRest(solver) => (solver.bearing(), solver.ball_stiffness(), None),
        BallSolver::AtSpeed(solver) => (solver.bearing(), solver.ball_stiffness(), Some("outer")),
    };
    let mut warnings = solver_warnings(&sol.status, sol.note)?;
    // rating and the most loaded ball's contacts: the one post-solve path of the report
    // and the sweep's rows (crate::bearing_post); the balls' loads on the inner ring (at
    // speed the inner contact's; the outer contact's centrifugal share is not in the life
    // yet), the contacts sized with each raceway's largest load
    let f = [b.inner_osculation, b.outer_osculation];
    let post = BallPost::new(b, s.rating.as_ref(), [keys.inner, keys.outer])?.run(
        b,
        &sol,
        rows.iter().map(|r| r.load_n),
        q_max,
        applied_moment(load),
        &mut warnings,
        |e| map_ball_field(e, s, keys, f),
    )?;
    let elements = BearingElements::Balls(BallPart {
        balls: b.balls,
        free_contact_angle_deg: b.free_contact_angle().to_degrees(),
        ball_stiffness_n_per_mm1_5: k_n,
        max_ball_load_n: sol.max_ball_load_n,
        max_inner_pressure_mpa: sol.max_pressure_mpa[0],
        max_outer_pressure_mpa: sol.max_pressure_mpa[1],
        ball_loads: rows,
        race_control,
    });
    let mut report = report(case, label, elements, sol.displacement, sol.load);
    report.solver = solver_echo(&sol.status);
    report.load_zone_epsilon = sol.load_zone;
    report.stiffness_matrix = sol.stiffness;
    report.warnings = warnings;
    report.contacts = post.contact_sizes();
    report.rating = post.rating;
    if race_control.is_some() {
        report.ring_speeds_rpm = Some([case.speed.inner_rpm, case.speed.outer_rpm]);
    }
    Ok(report)
}

/// The ball rows of a quasi-static solve and the largest ball load on each raceway.
fn rest_rows(solver: &BallBearingSolver, sol: &BallSolution) -> (Vec<BallRow>, [f64; 2]) {
    let rows: Vec<BallRow> = solver
        .ball_loads()
        .iter()
        .map(|q| BallRow {
            azimuth_deg: q.azimuth_rad.to_degrees(),
            load_n: q.load_n,
            contact_angle_deg: q.contact_angle_rad.to_degrees(),
            approach_mm: q.approach_mm,
            inner_max_pressure_mpa: q.inner_max_pressure_mpa,
            outer_max_pressure_mpa: q.outer_max_pressure_mpa,
            inner_load_n: q.load_n,
            outer_load_n: q.load_n,
            inner_contact_angle_deg: q.contact_angle_rad.to_degrees(),
            outer_contact_angle_deg: q.contact_angle_rad.to_degrees(),
            centrifugal_force_n: 0.0,
            gyroscopic_moment_nmm: 0.0,
        })
        .collect();
    let q = sol.max_ball_load_n;
    (rows, [q, q])
}
