//! Whole-bearing cases (`method = "bearing"`, `schema_version = 1`): the load distribution
//! of a roller bearing (cylindrical, tapered, cylindrical roller thrust) under forces and
//! moments or prescribed displacements of its inner ring, on [`kontakt_bearing`]'s
//! five-degree-of-freedom equilibrium with the ISO/TS 16281 (2008) slice law.
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
//! `(Fx, Fy, Fz, Mx, My)` (N, N·mm). A bearing type is a tag (`type`), so the ball
//! bearings of a later step are a variant with their own keys.
//!
//! **Not converged.** The report is one equilibrium: a solve that ends at the iteration
//! limit or diverges (a load the bearing cannot carry) is refused as
//! [`Error::NotConverged`] (exit status 1 in the CLI), like the single solves of the field
//! methods; a solve that stagnates at the round-off floor (residual at most 1e-8 of the
//! load, 1000 times the tolerance) is reported with a warning.

use crate::common::{SCHEMA_VERSION, in_degrees, parse_toml};
use crate::validity::{ContactSize, checked, checked_report};
use kontakt::solve::Termination;
use kontakt::{Error, Result};
use kontakt_bearing::equilibrium::{Dof, RingLoad, RollerBearingSolver};
use kontakt_bearing::geometry::{DEFAULT_SLICES, RollerBearing, RollerBearingKind};
use kontakt_bearing::profile::{Profile, TabulatedProfile};
use serde::{Deserialize, Serialize};

/// The contact modulus of two steel bodies (E = 210 GPa, ν = 0.3), MPa: the default of the
/// design-load profiles.
pub const STEEL_CONTACT_MODULUS_MPA: f64 = 210_000.0 / (2.0 * (1.0 - 0.09));

/// Most slices of a whole bearing, `rollers × slices` (the solver holds two numbers per
/// slice and evaluates every slice per iteration).
pub const MAX_BEARING_SLICES: usize = 1_000_000;

/// A whole-bearing case, as read from TOML.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
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
}

/// `[bearing]`: the type (`type = "cylindrical" | "tapered" | "thrust"`) and its internal
/// geometry.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(tag = "type", rename_all = "snake_case")]
pub enum BearingSpec {
    /// A cylindrical roller bearing (contact angle 0; carries no axial load).
    Cylindrical(RollerSpec),
    /// A single-row tapered roller bearing (`cup_angle_deg`, `cone_angle_deg` required).
    Tapered(RollerSpec),
    /// A cylindrical roller thrust bearing, 81xxx (contact angle 90°; no radial load).
    Thrust(RollerSpec),
}

/// The internal geometry of a roller bearing. Lengths in mm, angles in degrees.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
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
}

fn default_slices() -> usize {
    DEFAULT_SLICES
}

/// A roller or raceway profile (`kind = ...`), drops in mm at the axial position from the
/// roller centre; the formulas are those of `docs/bearing-model.md` §4. `length_mm`
/// defaults to the roller length, `contact_modulus_mpa` to steel on steel (115 385 MPa).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
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
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
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
#[derive(Debug, Clone, Copy, PartialEq, Default, Serialize, Deserialize)]
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

/// The result of a whole-bearing case. Keys carry their units.
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
    /// `"cylindrical"`, `"tapered"` or `"thrust"`.
    pub bearing_type: &'static str,
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
    /// Inner-ring displacement `[δx, δy, δz]`, mm.
    pub displacement_mm: [f64; 3],
    /// Inner-ring tilt `[θx, θy]`, rad.
    pub tilt_rad: [f64; 2],
    /// The force the rollers carry `[Fx, Fy, Fz]`, N: the applied force on force-controlled
    /// components (to the residual), the reaction on prescribed ones.
    pub force_n: [f64; 3],
    /// The moment the rollers carry `[Mx, My]`, N·mm (as `force_n`).
    pub moment_nmm: [f64; 2],
    /// How the equilibrium solve ended.
    pub solver: BearingSolverEcho,
    /// The load-zone parameter ε (Sjövall 1933) from the ring displacement; absent without
    /// a radial displacement and for thrust bearings. Exact for rigid rings without tilt.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub load_zone_epsilon: Option<f64>,
    /// The largest roller (outer raceway) load, N.
    pub max_roller_load_n: f64,
    /// The largest slice load per unit length of any roller, N/mm.
    pub max_load_per_length_n_per_mm: f64,
    /// Per roller, in azimuth order.
    pub roller_loads: Vec<RollerRow>,
    /// The slices of the most loaded roller.
    pub most_loaded_roller: SliceTable,
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
    /// No Hertz or half-space contact is sized in the slice model (the validity check has
    /// only the finiteness of the report to check); not in the JSON.
    #[serde(skip)]
    pub contacts: Vec<ContactSize>,
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
        parse_toml(text)
    }
}

/// The case's bearing as the library's [`RollerBearing`]: errors named by the case key.
fn roller_bearing(spec: &BearingSpec) -> Result<(RollerBearing, &'static str)> {
    let (kind, s, label) = match spec {
        BearingSpec::Cylindrical(s) => (RollerBearingKind::Cylindrical, s, "cylindrical"),
        BearingSpec::Tapered(s) => (RollerBearingKind::Tapered, s, "tapered"),
        BearingSpec::Thrust(s) => (RollerBearingKind::Thrust, s, "thrust"),
    };
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
    Ok((b, label))
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

/// [`run_bearing_case`] before the validity check of [`crate::validity::checked`].
pub(crate) fn run_bearing_case_unchecked(case: &BearingCase) -> Result<BearingReport> {
    if case.method != "bearing" {
        return Err(Error::invalid(
            "method",
            &case.method,
            "\"bearing\" for this schema",
        ));
    }
    let (bearing, label) = roller_bearing(&case.bearing)?;
    let l = &case.load;
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
    let map_load = |e: Error| e.map_field(|f| load_key(f).unwrap_or_else(|| f.to_string()));
    let mut solver = RollerBearingSolver::new(bearing).map_err(map_bearing_field)?;
    let sol = solver.solve(&RingLoad { dofs }).map_err(map_load)?;
    let mut warnings = Vec::new();
    match sol.status.termination {
        Termination::Converged => {}
        Termination::Stagnated => warnings.push(format!(
            "the equilibrium stagnated at the round-off floor after {} iterations (residual {:.1e} of the load, tolerance 1e-11)",
            sol.status.iterations, sol.status.residual
        )),
        _ => {
            let what = format!(
                "bearing equilibrium: {}",
                sol.note.unwrap_or("no equilibrium")
            );
            sol.status.require_converged(what)?;
        }
    }
    if let Some(note) = sol.note
        && sol.status.termination == Termination::Converged
    {
        warnings.push(note.to_string());
    }
    let b = solver.bearing();
    if b.slices < DEFAULT_SLICES {
        warnings.push(format!(
            "{} slices per roller: fewer than the recommended {DEFAULT_SLICES}, the roller loads are coarse (docs/bearing-model.md §6)",
            b.slices
        ));
    }
    let ns = b.slices;
    let width = b.effective_length_mm / ns as f64;
    let loads = solver.slice_loads();
    let approaches = solver.slice_approaches();
    let mut rows = Vec::with_capacity(b.rollers);
    let mut most = 0;
    let mut q_max = f64::NEG_INFINITY;
    for (j, r) in solver.roller_loads().iter().enumerate() {
        let slice_max = loads[j * ns..(j + 1) * ns]
            .iter()
            .copied()
            .fold(0.0, f64::max);
        if r.outer_n > q_max {
            q_max = r.outer_n;
            most = j;
        }
        rows.push(RollerRow {
            azimuth_deg: r.azimuth_rad.to_degrees(),
            inner_load_n: r.inner_n,
            outer_load_n: r.outer_n,
            rib_load_n: r.rib_n,
            max_load_per_length_n_per_mm: slice_max / width,
            approach_mm: r.max_approach_mm,
        });
    }
    let slice_loads = loads[most * ns..(most + 1) * ns].to_vec();
    let most_loaded = SliceTable {
        roller: most,
        position_mm: solver.slice_positions().to_vec(),
        load_per_length_n_per_mm: slice_loads.iter().map(|q| q / width).collect(),
        load_n: slice_loads,
        approach_mm: approaches[most * ns..(most + 1) * ns].to_vec(),
    };
    let u = sol.displacement;
    Ok(BearingReport {
        kontakt_version: kontakt::VERSION,
        schema_version: SCHEMA_VERSION,
        name: case.name.clone(),
        method: "bearing",
        bearing_type: label,
        rollers: b.rollers,
        slices: ns,
        contact_angle_deg: b.contact_angle_rad.to_degrees(),
        cone_angle_deg: b.cone_angle_rad.to_degrees(),
        roller_stiffness_n_per_mm10_9: b.roller_stiffness(),
        displacement_mm: [u[0], u[1], u[2]],
        tilt_rad: [u[3], u[4]],
        force_n: [sol.load[0], sol.load[1], sol.load[2]],
        moment_nmm: [sol.load[3], sol.load[4]],
        solver: BearingSolverEcho {
            converged: sol.status.converged(),
            termination: sol.status.termination.as_str(),
            iterations: sol.status.iterations,
            residual: sol.status.residual,
        },
        load_zone_epsilon: sol.load_zone,
        max_roller_load_n: sol.max_roller_load_n,
        max_load_per_length_n_per_mm: rows
            .iter()
            .map(|r| r.max_load_per_length_n_per_mm)
            .fold(0.0, f64::max),
        roller_loads: rows,
        most_loaded_roller: most_loaded,
        stiffness_dofs: DOFS,
        stiffness_matrix: sol.stiffness,
        stiffness_units: stiffness_units(),
        warnings,
        contacts: Vec::new(),
    })
}
