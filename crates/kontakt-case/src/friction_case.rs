//! Friction cases (`method = "friction"`, `schema_version = 1`): the roller-end/rib contact of
//! a tapered roller bearing under axial load over a sweep of inner-ring speeds, with the
//! pressure from Hertz, PimP and/or the half-space solver, and its report: rib load, film,
//! friction coefficient, friction moments, power and the rib's share of the bearing torque.
//!
//! ```toml
//! name = "rib friction, sphere/torus r_R = 57 mm"
//! method = "friction"
//! models = ["hertz", "pimp", "halfspace"]   # pressure models; default ["pimp"]
//!
//! [geometry]                 # as for method = "pimp": a built-in pairing or face + rib
//! kind = "roller_rib"
//! pairing = "sphere-torus-57"
//!
//! [rollers]                  # optional; default 17 rollers, 16 mm, 7850 kg/m³
//! count = 17
//! length_mm = 16.0
//! density_kg_m3 = 7850.0
//!
//! [load]
//! axial_n = 15000.0
//! centrifugal = true         # default true: the rollers' centrifugal force adds to the rib load
//!
//! [speed]                    # inner ring, outer ring fixed: a list ...
//! rpm = [100.0, 1000.0, 3000.0]
//! # ... or a range: min_rpm = 50.0, max_rpm = 6000.0, points = 12, spacing = "log" (or "linear")
//!
//! [lubricant]                # optional; absent = dry (boundary friction everywhere)
//! iso_vg = 68                # or nu40_mm2_s and nu100_mm2_s
//! density_kg_m3 = 860.0
//! alpha_per_mpa = 0.02
//! temperature_c = 70.0
//! roughness_mm = [0.0002, 0.0002]   # rms of the roller end face and the rib
//! formula = "chittenden"   # default; or "hamrock_dowson"
//!
//! [friction]                 # optional
//! preset = "mixed"           # "coulomb" (default when dry), "aihara", "mixed" (default when lubricated)
//! mu = 0.12                  # boundary friction coefficient (overrides the preset's)
//! # sharing = "exponential"; b = 1.9; c = 0.99      load sharing phi = exp(-b Lambda^c), or "boundary"
//! # fluid = "limiting_shear"; tau_l0_mpa = 2.0; tau_l_slope = 0.07   or "none", "newtonian", "eyring" (tau0_mpa)
//! # regularisation_speed_mm_s = 1.0
//! ```
//!
//! The schema is documented in `docs/case-schema.md`; [`run_friction_case`] turns a case
//! into a [`FrictionOutcome`] (the [`FrictionReport`] and the fields for the maps).

use crate::common::SCHEMA_VERSION;
use crate::pimp_case::{GeometrySpec, roller_rib_from_spec};
use crate::validity::{ContactSize, Size, checked, checked_report};
use kontakt::bearing::{
    BearingRibFriction, Operating, PressureModel, RibFriction, RibFrictionModel, RibLubrication,
    RollerCup, RollerRib, RollerSet,
};
use kontakt::field::NormalSolution;
use kontakt::friction::{
    FluidShear, FrictionLaw, LoadSharing, power_density as power_density_into,
};
use kontakt::geometry::VelocityField;
use kontakt::hertz::{HertzPointContact, PointGeometry};
use kontakt::lubrication::{FilmFormula, Lubricant};
use kontakt::{Error, Result};
use kontakt_bearing::equilibrium::{Dof, RingLoad, RollerBearingSolver};
use kontakt_bearing::geometry::RollerBearing;
use serde::{Deserialize, Serialize};
use std::collections::BTreeSet;

/// rad/s per r/min.
const RAD_S_PER_RPM: f64 = std::f64::consts::PI / 30.0;

/// A friction case, as read from TOML.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize, schemars::JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct FrictionCase {
    /// Optional label echoed in the report.
    #[serde(default)]
    pub name: Option<String>,
    /// Must be `"friction"`.
    pub method: String,
    /// Pressure models, in this order (default: pimp).
    #[serde(default = "default_models")]
    pub models: Vec<PressureModel>,
    /// The roller/rib geometry (`kind = "roller_rib"`).
    pub geometry: GeometrySpec,
    /// The rollers (default [`RollerSet::default`]).
    #[serde(default)]
    pub rollers: RollerSet,
    /// The bearing load.
    pub load: FrictionLoad,
    /// Inner-ring speeds.
    pub speed: SpeedSpec,
    /// The lubricant; absent: dry.
    #[serde(default)]
    pub lubricant: Option<LubricantSpec>,
    /// The friction law.
    #[serde(default)]
    pub friction: FrictionSpec,
}

fn default_models() -> Vec<PressureModel> {
    vec![PressureModel::Pimp]
}

/// `[load]`: the bearing's load on its inner ring (outer ring fixed). Every roller's cup
/// load comes from the whole bearing's equilibrium (`kontakt_bearing`, the rib study's
/// bearing built by `RollerBearing::of_roller_rib`), its rib load from its own balance
/// with its centrifugal force (`docs/bearing-model.md`, "The rib friction of every
/// roller").
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize, schemars::JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct FrictionLoad {
    /// Axial load of the bearing F_a \[N\], > 0 (a single-row tapered roller bearing
    /// needs it).
    pub axial_n: f64,
    /// Add the rollers' centrifugal force to the rib load (default true).
    #[serde(default = "yes")]
    pub centrifugal: bool,
    /// Radial load F_r along the bearing's x axis \[N\], ≥ 0 (default 0). Roller 0 sits at
    /// azimuth 0, on the x axis, in the middle of the load zone.
    #[serde(default)]
    pub radial_n: f64,
    /// Tilting moment M_y about the bearing's y axis \[N·mm\] (the plane of the radial
    /// load). Given: the inner ring's tilt about y is free under this moment (a single row
    /// may not carry it). Absent (the default): both tilts are held at zero by the shaft
    /// and the moments they take are reported (`reaction_moment_nmm`). The tilt about x
    /// is always held (zero moment there by symmetry).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub moment_nmm: Option<f64>,
}

fn yes() -> bool {
    true
}

/// `[speed]`: inner-ring speeds \[r/min\] (outer ring fixed), a list or a range.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize, schemars::JsonSchema, Default)]
#[serde(deny_unknown_fields)]
pub struct SpeedSpec {
    /// The speeds \[r/min\]: a list, or one number (`rpm = 1500.0`, as a sweep's
    /// parameter on `speed.rpm` sets it).
    #[serde(default, deserialize_with = "one_or_many")]
    #[schemars(with = "Option<OneOrMany>")]
    pub rpm: Option<Vec<f64>>,
    /// Lowest speed of a range \[r/min\].
    #[serde(default)]
    pub min_rpm: Option<f64>,
    /// Highest speed of a range \[r/min\].
    #[serde(default)]
    pub max_rpm: Option<f64>,
    /// Points of a range (2..=1000, default 12).
    #[serde(default)]
    pub points: Option<usize>,
    /// Spacing of a range (default log).
    #[serde(default)]
    pub spacing: Spacing,
}

/// `rpm = 1500.0` or `rpm = [500.0, 1500.0]`.
fn one_or_many<'de, D: serde::Deserializer<'de>>(
    d: D,
) -> std::result::Result<Option<Vec<f64>>, D::Error> {
    Ok(Some(match OneOrMany::deserialize(d)? {
        OneOrMany::One(v) => vec![v],
        OneOrMany::Many(v) => v,
    }))
}

/// A speed \[r/min\] or a list of them.
#[derive(Deserialize, schemars::JsonSchema)]
#[serde(untagged, expecting = "a speed in r/min or a list of them")]
enum OneOrMany {
    One(f64),
    Many(Vec<f64>),
}

/// Spacing of a speed range.
#[derive(
    Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize, schemars::JsonSchema, Default,
)]
#[serde(rename_all = "snake_case")]
pub enum Spacing {
    /// Evenly in log(speed).
    #[default]
    Log,
    /// Evenly in speed.
    Linear,
}

impl SpeedSpec {
    /// The speeds \[r/min\].
    ///
    /// # Errors
    /// Keys `speed.rpm`, `speed.min_rpm`, `speed.max_rpm`, `speed.points`: either a list or a
    /// range; speeds finite and > 0 r/min (≤ 100 000); min < max; 2..=1000 points.
    pub fn speeds(&self) -> Result<Vec<f64>> {
        const MAX: f64 = 1e5;
        let check = |key: &'static str, v: f64| {
            if v.is_finite() && v > 0.0 && v <= MAX {
                Ok(v)
            } else {
                Err(Error::invalid(key, v, "a speed > 0 and <= 100000 r/min"))
            }
        };
        match (&self.rpm, self.min_rpm, self.max_rpm) {
            (Some(list), None, None) if self.points.is_none() => {
                if list.is_empty() {
                    return Err(Error::invalid(
                        "speed.rpm",
                        "an empty list",
                        "at least one speed",
                    ));
                }
                list.iter().map(|&v| check("speed.rpm", v)).collect()
            }
            (None, Some(lo), Some(hi)) => {
                let (lo, hi) = (check("speed.min_rpm", lo)?, check("speed.max_rpm", hi)?);
                if lo >= hi {
                    return Err(Error::invalid(
                        "speed.max_rpm",
                        hi,
                        format!("a speed above min_rpm = {lo}"),
                    ));
                }
                let n = self.points.unwrap_or(12);
                if !(2..=1000).contains(&n) {
                    return Err(Error::invalid("speed.points", n, "2 to 1000 points"));
                }
                // The ends exactly as given; a linear step as (hi - lo) * i / (n - 1), so
                // 500..2500 in 5 points is 500, 1000, 1500, 2000, 2500 to the last bit.
                Ok((0..n)
                    .map(|i| {
                        if i == 0 {
                            return lo;
                        }
                        if i == n - 1 {
                            return hi;
                        }
                        match self.spacing {
                            Spacing::Log => lo * (hi / lo).powf(i as f64 / (n - 1) as f64),
                            Spacing::Linear => lo + (hi - lo) * i as f64 / (n - 1) as f64,
                        }
                    })
                    .collect())
            }
            (rpm, lo, hi) => {
                // Say what was given: a list and (part of) a range (a sweep parameter on
                // `speed.rpm` of a case with a range, issue 30 item 13), a list with
                // `points`, half a range, or nothing.
                let mut given: Vec<&str> = Vec::new();
                if rpm.is_some() {
                    given.push("rpm");
                }
                if lo.is_some() {
                    given.push("min_rpm");
                }
                if hi.is_some() {
                    given.push("max_rpm");
                }
                if self.points.is_some() {
                    given.push("points");
                }
                let value = if given.is_empty() {
                    "no speeds".to_string()
                } else {
                    given.join(", ")
                };
                Err(Error::invalid(
                    "speed",
                    value,
                    "either a list rpm = [...] or a range min_rpm, max_rpm (with optional \
                     points, spacing), not both (a sweep over speed.rpm needs a base case \
                     with rpm; over a range, sweep speed.min_rpm or speed.max_rpm)",
                ))
            }
        }
    }
}

/// `[lubricant]`.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize, schemars::JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct LubricantSpec {
    /// ISO VG grade (32, 46, 68, 100, 150, 220); or give both viscosities.
    #[serde(default)]
    pub iso_vg: Option<u32>,
    /// Kinematic viscosity at 40 °C \[mm²/s\].
    #[serde(default)]
    pub nu40_mm2_s: Option<f64>,
    /// Kinematic viscosity at 100 °C \[mm²/s\].
    #[serde(default)]
    pub nu100_mm2_s: Option<f64>,
    /// Density \[kg/m³\].
    pub density_kg_m3: f64,
    /// Pressure-viscosity coefficient \[1/MPa\].
    pub alpha_per_mpa: f64,
    /// Oil (inlet) temperature \[°C\].
    pub temperature_c: f64,
    /// RMS roughness of the roller end face and of the rib \[mm\].
    pub roughness_mm: [f64; 2],
    /// Film formula (default Chittenden et al. 1985).
    #[serde(default)]
    pub formula: FormulaSpec,
}

/// Film formula names of the case file.
#[derive(
    Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize, schemars::JsonSchema, Default,
)]
#[serde(rename_all = "snake_case")]
pub enum FormulaSpec {
    /// Chittenden et al. (1985) central film, entrainment at any angle (the default: the
    /// rib's entrainment runs along the major axis of its contact ellipse).
    #[default]
    Chittenden,
    /// Hamrock & Dowson (1977), fitted for entrainment along the minor axis.
    HamrockDowson,
}

/// `[friction]`: a preset and overrides.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize, schemars::JsonSchema, Default)]
#[serde(deny_unknown_fields)]
pub struct FrictionSpec {
    /// The starting law (default: coulomb when dry, mixed when lubricated).
    #[serde(default)]
    pub preset: Option<Preset>,
    /// Boundary friction coefficient μ_b.
    #[serde(default)]
    pub mu: Option<f64>,
    /// Load sharing.
    #[serde(default)]
    pub sharing: Option<SharingSpec>,
    /// `b` of exp(−b Λ^c).
    #[serde(default)]
    pub b: Option<f64>,
    /// `c` of exp(−b Λ^c).
    #[serde(default)]
    pub c: Option<f64>,
    /// Fluid shear law.
    #[serde(default)]
    pub fluid: Option<FluidSpec>,
    /// Eyring stress \[MPa\].
    #[serde(default)]
    pub tau0_mpa: Option<f64>,
    /// Limiting shear stress at zero pressure \[MPa\].
    #[serde(default)]
    pub tau_l0_mpa: Option<f64>,
    /// Pressure slope of the limiting shear stress.
    #[serde(default)]
    pub tau_l_slope: Option<f64>,
    /// Regularisation speed \[mm/s\].
    #[serde(default)]
    pub regularisation_speed_mm_s: Option<f64>,
}

/// Friction presets.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize, schemars::JsonSchema)]
#[serde(rename_all = "snake_case")]
pub enum Preset {
    /// Plain Coulomb, μ = 0.1.
    Coulomb,
    /// Aihara (1987): 0.2 exp(−1.8 Λ^1.2), no fluid shear.
    Aihara,
    /// exp(−1.90 Λ^0.99) sharing (Wingertszahn et al. 2023), μ_b = 0.1, limiting shear.
    Mixed,
}

/// Load-sharing names.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize, schemars::JsonSchema)]
#[serde(rename_all = "snake_case")]
pub enum SharingSpec {
    /// φ = 1.
    Boundary,
    /// φ = exp(−b Λ^c).
    Exponential,
}

/// Fluid-law names.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize, schemars::JsonSchema)]
#[serde(rename_all = "snake_case")]
pub enum FluidSpec {
    /// No fluid shear.
    None,
    /// Newtonian.
    Newtonian,
    /// Eyring.
    Eyring,
    /// Limiting shear.
    LimitingShear,
}

impl FrictionSpec {
    /// The law: the preset, then each given key.
    ///
    /// # Errors
    /// Keys `friction.*` out of range (see [`FrictionLaw::check`]).
    pub fn law(&self, lubricated: bool) -> Result<FrictionLaw> {
        let preset = self.preset.unwrap_or(if lubricated {
            Preset::Mixed
        } else {
            Preset::Coulomb
        });
        let mut law = match preset {
            Preset::Coulomb => FrictionLaw::coulomb(0.1)?,
            Preset::Aihara => FrictionLaw::aihara(),
            Preset::Mixed => FrictionLaw::mixed(0.1)?,
        };
        if let Some(mu) = self.mu {
            law.boundary_coefficient = mu;
        }
        let (b0, c0) = match law.sharing {
            LoadSharing::Exponential { b, c } => (b, c),
            LoadSharing::Boundary => (1.9, 0.99),
        };
        match self.sharing {
            Some(SharingSpec::Boundary) => law.sharing = LoadSharing::Boundary,
            Some(SharingSpec::Exponential) => {
                law.sharing = LoadSharing::Exponential { b: b0, c: c0 }
            }
            None => {}
        }
        if self.b.is_some() || self.c.is_some() {
            match &mut law.sharing {
                LoadSharing::Exponential { b, c } => {
                    *b = self.b.unwrap_or(*b);
                    *c = self.c.unwrap_or(*c);
                }
                LoadSharing::Boundary => {
                    return Err(Error::invalid(
                        "friction.b",
                        "given with sharing = \"boundary\"",
                        "b and c only with sharing = \"exponential\"",
                    ));
                }
            }
        }
        if let Some(fluid) = self.fluid {
            law.fluid = match fluid {
                FluidSpec::None => FluidShear::None,
                FluidSpec::Newtonian => FluidShear::Newtonian,
                FluidSpec::Eyring => FluidShear::Eyring {
                    tau0: self.tau0_mpa.unwrap_or(5.0),
                },
                FluidSpec::LimitingShear => FluidShear::LimitingShear {
                    tau_l0: self.tau_l0_mpa.unwrap_or(2.0),
                    slope: self.tau_l_slope.unwrap_or(0.07),
                },
            };
        } else if let FluidShear::LimitingShear { tau_l0, slope } = law.fluid {
            law.fluid = FluidShear::LimitingShear {
                tau_l0: self.tau_l0_mpa.unwrap_or(tau_l0),
                slope: self.tau_l_slope.unwrap_or(slope),
            };
        }
        if let Some(v) = self.regularisation_speed_mm_s {
            law.regularisation_speed = v;
        }
        law.check().map_err(|e| {
            e.map_field(|f| {
                let key = match f {
                    "boundary_coefficient" => "mu",
                    "sharing.b" => "b",
                    "sharing.c" => "c",
                    "fluid.tau0" => "tau0_mpa",
                    "fluid.tau_l0" => "tau_l0_mpa",
                    "fluid.slope" => "tau_l_slope",
                    "regularisation_speed" => "regularisation_speed_mm_s",
                    other => other,
                };
                format!("friction.{key}")
            })
        })?;
        Ok(law)
    }
}

impl LubricantSpec {
    /// The lubrication of the rib.
    ///
    /// # Errors
    /// Keys `lubricant.*` out of range.
    pub fn lubrication(&self) -> Result<RibLubrication> {
        let key = |f: &str| {
            let k = match f {
                "nu40" => "nu40_mm2_s",
                "nu100" => "nu100_mm2_s",
                "density" => "density_kg_m3",
                "alpha" => "alpha_per_mpa",
                "grade" => "iso_vg",
                "temperature_c" | "temperature" => "temperature_c",
                "roughness" | "sigma1" | "sigma2" => "roughness_mm",
                other => other,
            };
            format!("lubricant.{k}")
        };
        let lubricant = match (self.iso_vg, self.nu40_mm2_s, self.nu100_mm2_s) {
            (Some(g), None, None) => Lubricant::iso_vg(g, self.density_kg_m3, self.alpha_per_mpa),
            (None, Some(a), Some(b)) => {
                Lubricant::new(a, b, self.density_kg_m3, self.alpha_per_mpa)
            }
            _ => {
                return Err(Error::invalid(
                    "lubricant.iso_vg",
                    "neither a grade nor both viscosities",
                    "either iso_vg or both nu40_mm2_s and nu100_mm2_s",
                ));
            }
        }
        .map_err(|e| e.map_field(key))?;
        let lub = RibLubrication {
            lubricant,
            temperature: self.temperature_c,
            roughness: self.roughness_mm,
            formula: match self.formula {
                FormulaSpec::Chittenden => FilmFormula::Chittenden,
                FormulaSpec::HamrockDowson => FilmFormula::HamrockDowson,
            },
        };
        Ok(lub)
    }
}

/// One row of the report: one pressure model at one speed.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct FrictionRow {
    /// The pairing (`custom` for explicit shapes).
    pub pairing: String,
    /// Pressure model.
    pub model: &'static str,
    /// Inner-ring speed \[r/min\].
    pub speed_rpm: f64,
    /// Cage speed \[r/min\].
    pub cage_speed_rpm: f64,
    /// Roller speed relative to the rib |ω_rel| \[rad/s\].
    pub relative_speed_rad_s: f64,
    /// Rib load of the most loaded roller \[N\] (every roller's under pure axial load);
    /// the per-contact columns below (pressure, film, coefficient, `power_w`, moments
    /// about the roller axis) are that roller's.
    pub rib_load_n: f64,
    /// Centrifugal force per roller \[N\].
    pub centrifugal_n: f64,
    /// Largest rib pressure \[MPa\].
    pub max_pressure_mpa: f64,
    /// Height of the contact above the inner raceway contact line \[mm\].
    pub contact_height_mm: f64,
    /// Sliding speed at the contact point \[mm/s\].
    pub sliding_speed_mm_s: f64,
    /// Entrainment speed at the contact point \[mm/s\].
    pub entrainment_speed_mm_s: f64,
    /// Central film thickness \[mm\] (absent when dry).
    pub film_central_mm: Option<f64>,
    /// Minimum film thickness \[mm\] (absent when dry).
    pub film_minimum_mm: Option<f64>,
    /// Film parameter Λ (0 when dry).
    pub lambda: f64,
    /// Ellipticity k of the film formula (absent when dry).
    pub film_k: Option<f64>,
    /// Moes' M (absent when dry or at zero entrainment).
    pub moes_m: Option<f64>,
    /// Moes' L (absent when dry).
    pub moes_l: Option<f64>,
    /// Asperity share φ(Λ).
    pub asperity_share: f64,
    /// Effective friction coefficient |F_t| / Q_f.
    pub coefficient: f64,
    /// Friction power of one rib contact \[W\].
    pub power_w: f64,
    /// Friction power of all rib contacts, summed over the rollers \[W\].
    pub bearing_power_w: f64,
    /// The rib friction's share of the bearing's drag torque \[N·mm\]: the torque the shaft
    /// must supply to it, from the power balance `Σ_j P_j / |ω_i − ω_o|` over the rollers
    /// (docs/friction.md §5.2; `Z P` under pure axial load).
    /// This is the rib's friction torque of the bearing (the plots' "rib torque").
    pub bearing_drag_torque_nmm: f64,
    /// Moment of the rib friction on one roller about the roller's axis \[N·mm\].
    pub roller_axis_moment_nmm: f64,
    /// Moment of the rib friction forces on the inner ring alone about the ring axis, all
    /// rollers \[N·mm\]. Not the drag torque: the same forces turn the rollers back about
    /// their axes, and that moment returns to the rings through the raceway contacts; the
    /// net that the shaft feels is `bearing_drag_torque_nmm`.
    pub inner_ring_rib_moment_nmm: f64,
    /// Sum of the rollers' rib loads \[N\].
    pub rib_load_sum_n: f64,
    /// Rollers with a rib load (in contact with the rib).
    pub rib_contacts: usize,
}

/// One roller of the report's per-roller table: one pressure model at one speed. (Its
/// keys differ from the rows' so that a sweep's table leaves it out.)
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct FrictionRollerRow {
    /// Pressure model.
    pub pressure_model: &'static str,
    /// Inner-ring speed \[r/min\].
    pub inner_speed_rpm: f64,
    /// Roller index (0: on the x axis, where the radial load points).
    pub roller: usize,
    /// Azimuth of the roller from the x axis toward y \[deg\].
    pub azimuth_deg: f64,
    /// Cup (outer raceway) load \[N\].
    pub cup_load_n: f64,
    /// Cone (inner raceway) load \[N\] (0: the roller is off the cone).
    pub cone_load_n: f64,
    /// Rib load \[N\].
    pub roller_rib_load_n: f64,
    /// Magnitude of the rib friction force on the roller \[N\].
    pub friction_force_n: f64,
    /// Friction power of the roller's rib contact \[W\].
    pub roller_power_w: f64,
    /// Largest rib pressure of the roller \[MPa\] (0 without rib load).
    pub roller_max_pressure_mpa: f64,
}

impl FrictionRow {
    /// The row of `r`, computed at the case's speed `rpm` (reported as given, not
    /// converted back from rad/s: 1500, not 1500.0000000000002).
    fn of(pairing: &str, rpm: f64, b: &BearingRibFriction) -> Result<Self> {
        let r = b
            .most_loaded()
            .and_then(|r| r.friction.as_ref())
            .ok_or_else(|| {
                Error::invalid(
                    "load",
                    "no roller with a rib load",
                    "a load that presses the rollers against the rib",
                )
            })?;
        let film = r.film_thickness;
        Ok(FrictionRow {
            pairing: pairing.to_string(),
            model: r.model.as_str(),
            speed_rpm: rpm,
            cage_speed_rpm: r.cage_speed / RAD_S_PER_RPM,
            relative_speed_rad_s: r.relative_speed,
            rib_load_n: r.loads.rib,
            centrifugal_n: r.loads.centrifugal,
            max_pressure_mpa: r.max_pressure,
            contact_height_mm: r.contact_height,
            sliding_speed_mm_s: r.sliding_speed,
            entrainment_speed_mm_s: r.entrainment_speed,
            film_central_mm: film.map(|f| f.central),
            film_minimum_mm: film.map(|f| f.minimum),
            lambda: r.film.lambda,
            film_k: film.map(|f| f.regime.k),
            moes_m: film.and_then(|f| f.regime.moes_m),
            moes_l: film.map(|f| f.regime.moes_l),
            asperity_share: r.contact.asperity_share,
            coefficient: r.coefficient,
            power_w: r.power,
            bearing_power_w: b.power,
            bearing_drag_torque_nmm: b.torque,
            roller_axis_moment_nmm: r.roller_axis_moment,
            inner_ring_rib_moment_nmm: b.ring_axis_moment,
            rib_load_sum_n: b.rib_load,
            rib_contacts: b.rollers.iter().filter(|r| r.friction.is_some()).count(),
        })
    }
}

/// How much the pressure model changes the rib torque at one speed: each model's torque
/// divided by Hertz's.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct ModelDifference {
    /// Inner-ring speed \[r/min\].
    pub speed_rpm: f64,
    /// Model name.
    pub model: &'static str,
    /// Rib torque of the model over the Hertz torque at the same speed.
    pub torque_vs_hertz: f64,
}

/// The report of a friction case.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct FrictionReport {
    /// Schema version of the report.
    pub schema_version: u32,
    /// `"friction"`.
    pub method: &'static str,
    /// Version of kontakt that wrote the report.
    pub kontakt_version: &'static str,
    /// The case's name.
    pub name: Option<String>,
    /// The pairing (`custom` for explicit shapes).
    pub pairing: String,
    /// Number of rollers.
    pub rollers: usize,
    /// Mass of one roller \[kg\].
    pub roller_mass_kg: f64,
    /// Axial load \[N\].
    pub axial_load_n: f64,
    /// Radial load along x \[N\].
    pub radial_load_n: f64,
    /// The applied tilting moment about y \[N·mm\]; absent: the tilts are held.
    pub moment_nmm: Option<f64>,
    /// Whether the centrifugal force was added to the rib load.
    pub centrifugal: bool,
    /// Viscosity of the oil at the inlet temperature \[MPa·s\] (absent when dry).
    pub viscosity_mpa_s: Option<f64>,
    /// The friction law.
    pub law: FrictionLaw,
    /// One row per model and speed, models in the case's order.
    pub rows: Vec<FrictionRow>,
    /// Torque of each model relative to Hertz (when Hertz is among the models).
    pub model_difference: Vec<ModelDifference>,
    /// Every distinct warning of the film formula and the models, and of the rib
    /// contact's size against the roller end and the rib.
    pub warnings: Vec<String>,
    /// The bearing's equilibrium under the load: the inner ring's displacement.
    pub bearing: FrictionBearing,
    /// Every roller at every model and speed.
    pub roller_table: Vec<FrictionRollerRow>,
    /// The rib contact's size against the bodies at the largest rib load, for the
    /// validity check ([`crate::validity`]); not in the JSON.
    #[serde(skip)]
    pub contacts: Vec<ContactSize>,
}

checked_report!(FrictionReport);

/// The whole bearing's equilibrium that gives the rollers' cup loads
/// (`RollerBearing::of_roller_rib`, ISO/TS 16281 slices, rigid rings, static).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct FrictionBearing {
    /// Pitch diameter \[mm\].
    pub pitch_diameter_mm: f64,
    /// Mean roller diameter \[mm\].
    pub roller_diameter_mm: f64,
    /// Cup angle \[deg\].
    pub cup_angle_deg: f64,
    /// Pure axial load: every roller's cup load is `F_a / (Z sin α)`, the cups' axial
    /// balance by symmetry (the equilibrium's solution, to 1e-10; no solve, so the rib
    /// loads do not depend on the rollers' stiffness law). The fields below are then
    /// absent.
    pub closed_form: bool,
    /// Inner-ring displacement `(δx, δy, δz)` \[mm\].
    pub displacement_mm: Option<[f64; 3]>,
    /// Inner-ring tilt `(θx, θy)` \[rad\] (0 where held).
    pub tilt_rad: Option<[f64; 2]>,
    /// The moments `(Mx, My)` the rollers carry \[N·mm\]: the applied one where the tilt
    /// is free, the shaft's reaction where it is held.
    pub moment_nmm: Option<[f64; 2]>,
    /// The load-zone parameter ε (absent without radial displacement).
    pub load_zone: Option<f64>,
    /// Newton iterations of the equilibrium (0 in closed form).
    pub iterations: usize,
}

/// The rib study's bearing under `[load]`: every roller's cup load (static) and the
/// equilibrium's summary.
fn bearing_loads(
    case: &FrictionCase,
    pair: &RollerRib,
) -> Result<(Vec<RollerCup>, FrictionBearing, Vec<String>)> {
    let l = &case.load;
    if !(l.radial_n.is_finite() && l.radial_n >= 0.0) {
        return Err(Error::invalid(
            "load.radial_n",
            l.radial_n,
            "a finite force >= 0 N",
        ));
    }
    if let Some(m) = l.moment_nmm
        && !m.is_finite()
    {
        return Err(Error::invalid(
            "load.moment_nmm",
            m,
            "a finite moment in N·mm",
        ));
    }
    let bearing = RollerBearing::of_roller_rib(pair, &case.rollers).map_err(|e| {
        e.map_field(|f| match f {
            "rollers" | "count" => "rollers.count".to_string(),
            "length" | "effective_length_mm" => "rollers.length_mm".to_string(),
            other => format!("rollers ({other})"),
        })
    })?;
    let summary = (
        bearing.pitch_diameter_mm,
        bearing.roller_diameter_mm,
        bearing.contact_angle_rad.to_degrees(),
    );
    bearing.validate().map_err(|e| {
        e.map_field(|f| match f {
            "rollers" => "rollers.count".to_string(),
            other => format!("rollers ({other})"),
        })
    })?;
    let z = bearing.rollers;
    if l.radial_n == 0.0 && l.moment_nmm.is_none() {
        let q = l.axial_n / (z as f64 * bearing.contact_angle_rad.sin());
        let cups = (0..z)
            .map(|j| RollerCup {
                azimuth: bearing.first_roller_azimuth_rad
                    + 2.0 * std::f64::consts::PI * j as f64 / z as f64,
                outer_raceway: q,
            })
            .collect();
        let b = FrictionBearing {
            pitch_diameter_mm: summary.0,
            roller_diameter_mm: summary.1,
            cup_angle_deg: summary.2,
            closed_form: true,
            displacement_mm: None,
            tilt_rad: None,
            moment_nmm: None,
            load_zone: None,
            iterations: 0,
        };
        return Ok((cups, b, Vec::new()));
    }
    let mut solver = RollerBearingSolver::new(bearing).map_err(|e| {
        e.map_field(|f| match f {
            "rollers" => "rollers.count".to_string(),
            other => format!("rollers ({other})"),
        })
    })?;
    let load = RingLoad {
        dofs: [
            Dof::Force(l.radial_n),
            Dof::Force(0.0),
            Dof::Force(l.axial_n),
            Dof::Displacement(0.0),
            l.moment_nmm.map_or(Dof::Displacement(0.0), Dof::Force),
        ],
    };
    let sol = solver.solve(&load).map_err(|e| {
        e.map_field(|f| match f {
            "load.fx_n" => "load.radial_n".to_string(),
            "load.fz_n" => "load.axial_n".to_string(),
            "load.my_nmm" => "load.moment_nmm".to_string(),
            other => other.to_string(),
        })
    })?;
    let mut warnings = Vec::new();
    match sol.status.termination {
        kontakt::solve::Termination::Converged => {}
        kontakt::solve::Termination::Stagnated => warnings.push(format!(
            "the bearing equilibrium stagnated at the round-off floor (residual {:.1e} of the load)",
            sol.status.residual
        )),
        _ => {
            sol.status.require_converged(format!(
                "bearing equilibrium under [load]: {}",
                sol.note.unwrap_or("no equilibrium")
            ))?;
        }
    }
    let cups = solver
        .roller_loads()
        .iter()
        .map(|r| RollerCup {
            azimuth: r.azimuth_rad,
            outer_raceway: r.outer_n,
        })
        .collect();
    let u = sol.displacement;
    Ok((
        cups,
        FrictionBearing {
            pitch_diameter_mm: summary.0,
            roller_diameter_mm: summary.1,
            cup_angle_deg: summary.2,
            closed_form: false,
            displacement_mm: Some([u[0], u[1], u[2]]),
            tilt_rad: Some([u[3], u[4]]),
            moment_nmm: Some([sol.load[3], sol.load[4]]),
            load_zone: sol.load_zone,
            iterations: sol.status.iterations,
        },
        warnings,
    ))
}
checked_report!(FrictionOutcome, report);

/// A friction case's report and the fields of its maps.
#[derive(Debug, Clone, PartialEq)]
pub struct FrictionOutcome {
    /// The report.
    pub report: FrictionReport,
    /// The fields at the middle speed of the first model.
    pub map: FrictionMap,
}

/// The fields of one rib contact at one speed: pressure, sliding velocity and the
/// dissipated power density, on the field's grid.
#[derive(Debug, Clone, PartialEq)]
pub struct FrictionMap {
    /// The pressure model.
    pub model: PressureModel,
    /// Inner-ring speed \[r/min\].
    pub speed_rpm: f64,
    /// The friction at this speed.
    pub result: RibFriction,
    /// The pressure field (grid in the gap's principal frame).
    pub field: NormalSolution<()>,
    /// Sliding velocity of the roller on the rib over the grid \[mm/s\].
    pub sliding: VelocityField,
    /// Power density τ · v_s per cell \[W/mm²\].
    pub power_density: Vec<f64>,
    /// The grid's `x` and `y` axes as unit vectors in the bearing frame (`X` radial, `Y`
    /// circumferential at the contact point, `Z` the ring axis).
    pub axes: [[f64; 3]; 2],
}

impl FrictionMap {
    /// The most loaded roller's rib contact at `rpm` under the cup loads `cups`; its
    /// `result` is that roller's share (Z = 1).
    fn new(
        model: &RibFrictionModel,
        m: PressureModel,
        axial_n: f64,
        cups: &[RollerCup],
        rpm: f64,
    ) -> Result<Self> {
        let op = operating(axial_n, rpm);
        let k = model.kinematics(op.inner_speed, op.outer_speed)?;
        let loads = model
            .roller_loads_on_cups(&k, cups)?
            .into_iter()
            .map(|r| r.loads)
            .reduce(|a, b| if b.rib > a.rib { b } else { a })
            .ok_or_else(|| Error::invalid("rollers.count", 0, "at least 3 rollers"))?;
        let field = model.solve(m, loads.rib)?;
        let result = model.friction_share(m, &field, &op, &k, &loads, 1.0)?;
        let sliding = k
            .rib_pair(0.0)?
            .velocity_field(model.frame(), field.orientation)?;
        let law = model.law().with_film(&result.film)?;
        let mut power_density = vec![0.0; field.grid.len()];
        power_density_into(
            &field.grid,
            &field.pressure,
            &sliding,
            &law,
            &mut power_density,
        )?;
        Ok(FrictionMap {
            model: m,
            speed_rpm: rpm,
            result,
            field,
            sliding,
            power_density,
            axes: model.gap().principal_axes(),
        })
    }
}

/// Run a friction case.
///
/// # Errors
/// Invalid input named by its case-file key, and the solvers' failures.
pub fn run_friction_case(case: &FrictionCase) -> Result<FrictionOutcome> {
    checked(run_friction_case_unchecked(case)?)
}

/// The rib contact's size against the roller end face and the rib at the largest rib
/// load of the speeds `speeds` \[r/min\]: the Hertz ellipse of the contact point's
/// curvature, as PimP and the half-space solver check before a solve
/// (`kontakt::field::validity::ellipse_size_check`). Refused here, before any solve, when
/// the contact would be as large as a body's radius of curvature or run over the face's
/// edge; otherwise the contact for the validity check and the warnings about the edge.
fn rib_contact_size(
    case: &FrictionCase,
    model: &RibFrictionModel,
    gap: &kontakt::gap::SurfacePairGap,
    cups: &[RollerCup],
    speeds: &[f64],
) -> Result<(Vec<ContactSize>, Vec<String>)> {
    // A speed the loads cannot be computed at is reported by the sweep, with its key.
    let Some(rib_load) = speeds
        .iter()
        .filter_map(|&rpm| {
            let k = model.kinematics(rpm * RAD_S_PER_RPM, 0.0).ok()?;
            model.roller_loads_on_cups(&k, cups).ok()
        })
        .flat_map(|rollers| rollers.into_iter().map(|r| r.loads.rib))
        .reduce(f64::max)
    else {
        return Ok((Vec::new(), Vec::new()));
    };
    let material = model.material();
    let sol = HertzPointContact::new(
        PointGeometry::from_curvature(kontakt::gap::GapSource::curvature(gap)),
        material,
        material,
    )
    .and_then(|h| h.solve_force(rib_load))?;
    let at = format!("rib contact at the largest rib load, {rib_load:.6} N");
    let key = |f: &str| crate::pimp_case::size_field(&case.geometry, f);
    let check = kontakt::field::validity::ellipse_size_check(gap, sol.semi_axes, sol.orientation)
        .map_err(|e| match e {
        Error::Geometry { field, reason } => Error::Geometry {
            field: key(&field).into(),
            reason: format!("{at}: {reason}"),
        },
        other => other,
    })?;
    let edge = kontakt::field::validity::ZoneCheck {
        curvature: None,
        ..check
    };
    let contacts = check
        .curvature
        .map(|c| ContactSize {
            at: Some(at.clone()),
            // The message of the first model's theory.
            size: if case.models.first() == Some(&PressureModel::Hertz) {
                Size::Hertz(kontakt::hertz::validity::SizeCheck {
                    ratio: c.ratio,
                    body: c.body,
                    extent: c.extent,
                    radius: c.radius,
                    direction: 0.0,
                })
            } else {
                Size::HalfSpace(c)
            },
            keys: [key("body1.radii"), key("body2.radii")],
        })
        .into_iter()
        .collect();
    let edge = edge.warnings().into_iter().map(|w| format!("{at}: {w}"));
    Ok((contacts, edge.collect()))
}

/// [`run_friction_case`] before the validity check of [`crate::validity::checked`].
pub(crate) fn run_friction_case_unchecked(case: &FrictionCase) -> Result<FrictionOutcome> {
    if case.method != "friction" {
        return Err(Error::invalid(
            "method",
            &case.method,
            "\"friction\" for this schema",
        ));
    }
    let names: Vec<&str> = case.models.iter().map(PressureModel::as_str).collect();
    let valid = PressureModel::ALL.map(|m| m.as_str());
    kontakt::error::choices("models", &names, &valid)?;
    let (pairing, pair) = roller_rib_from_spec(&case.geometry)?.ok_or_else(|| {
        Error::invalid(
            "geometry.kind",
            "not roller_rib",
            "\"roller_rib\" (friction cases are roller-end/rib contacts)",
        )
    })?;
    let speeds = case.speed.speeds()?;
    if !(case.load.axial_n.is_finite() && case.load.axial_n > 0.0) {
        return Err(Error::invalid(
            "load.axial_n",
            case.load.axial_n,
            "a finite force > 0 N",
        ));
    }
    let lubrication = case
        .lubricant
        .as_ref()
        .map(|l| l.lubrication())
        .transpose()?;
    let law = case.friction.law(lubrication.is_some())?;
    // The gap with the face's edge, for the size check (the model's own has no edges).
    let gap = pair.gap()?;
    let model = RibFrictionModel::new(
        pair.spec,
        case.rollers,
        law,
        lubrication,
        case.load.centrifugal,
    )
    .map_err(|e| {
        e.map_field(|f| match f {
            "count" | "length" | "density" => format!(
                "rollers.{}",
                match f {
                    "length" => "length_mm",
                    "density" => "density_kg_m3",
                    other => other,
                }
            ),
            "roughness" => "lubricant.roughness_mm".to_string(),
            "temperature_c" | "temperature" => "lubricant.temperature_c".to_string(),
            other => other.to_string(),
        })
    })?;
    let (cups, bearing, bearing_warnings) = bearing_loads(case, model.pair())?;
    let (contacts, edge_warnings) = rib_contact_size(case, &model, &gap, &cups, &speeds)?;
    let mut rows = Vec::new();
    let mut roller_table = Vec::new();
    let mut warnings: BTreeSet<String> = bearing_warnings.into_iter().collect();
    let middle = speeds[speeds.len() / 2];
    for &m in &case.models {
        let sweep = model
            .sweep_rollers(
                m,
                &cups,
                &speeds.iter().map(|s| s * RAD_S_PER_RPM).collect::<Vec<_>>(),
            )
            .map_err(|e| {
                e.map_field(|f| match f {
                    "axial_load" => "load.axial_n".to_string(),
                    "inner_speed" | "speeds" => "speed".to_string(),
                    other => other.to_string(),
                })
            })?;
        for (b, &rpm) in sweep.iter().zip(&speeds) {
            for (j, r) in b.rollers.iter().enumerate() {
                if let Some(h) = r.friction.as_ref().and_then(|f| f.film_thickness.as_ref()) {
                    warnings.extend(h.warning_lines());
                }
                roller_table.push(FrictionRollerRow {
                    pressure_model: m.as_str(),
                    inner_speed_rpm: rpm,
                    roller: j,
                    azimuth_deg: r.azimuth.to_degrees(),
                    cup_load_n: r.loads.outer_raceway,
                    cone_load_n: r.loads.inner_raceway,
                    roller_rib_load_n: r.loads.rib,
                    friction_force_n: r.friction_force(),
                    roller_power_w: r.power(),
                    roller_max_pressure_mpa: r.friction.as_ref().map_or(0.0, |f| f.max_pressure),
                });
            }
            rows.push(FrictionRow::of(&pairing, rpm, b)?);
        }
    }
    let mut model_difference = Vec::new();
    for i in 0..speeds.len() {
        let n = speeds.len();
        let at = |k: usize| &rows[k * n + i];
        if let Some(h) = case.models.iter().position(|m| *m == PressureModel::Hertz) {
            let base = at(h).bearing_drag_torque_nmm;
            for (k, m) in case.models.iter().enumerate() {
                if *m != PressureModel::Hertz && base > 0.0 {
                    model_difference.push(ModelDifference {
                        speed_rpm: at(k).speed_rpm,
                        model: m.as_str(),
                        torque_vs_hertz: at(k).bearing_drag_torque_nmm / base,
                    });
                }
            }
        }
    }
    let viscosity = match model.lubrication() {
        Some(l) => Some(l.lubricant.dynamic_viscosity(l.temperature)?),
        None => None,
    };
    let report = FrictionReport {
        schema_version: SCHEMA_VERSION,
        method: "friction",
        kontakt_version: kontakt::VERSION,
        name: case.name.clone(),
        pairing,
        rollers: case.rollers.count,
        roller_mass_kg: model.roller_mass().mass,
        axial_load_n: case.load.axial_n,
        radial_load_n: case.load.radial_n,
        moment_nmm: case.load.moment_nmm,
        centrifugal: case.load.centrifugal,
        viscosity_mpa_s: viscosity,
        law,
        rows,
        model_difference,
        warnings: edge_warnings.into_iter().chain(warnings).collect(),
        bearing,
        roller_table,
        contacts,
    };
    let map = FrictionMap::new(&model, case.models[0], case.load.axial_n, &cups, middle)?;
    Ok(FrictionOutcome { report, map })
}

/// Operating point helper for front ends: `rpm` inner-ring speed, outer ring fixed.
pub fn operating(axial_n: f64, rpm: f64) -> Operating {
    Operating {
        axial_load: axial_n,
        inner_speed: rpm * RAD_S_PER_RPM,
        outer_speed: 0.0,
    }
}
