//! Friction of the roller-end/rib contact of a tapered roller bearing under axial load: the
//! rib load per roller, the pressure field (Hertz, PimP or the half-space solver), the
//! sliding field of the bearing's kinematics, the lubricant film, the friction law over
//! the field, and the rib's friction torque and power for the whole bearing.
//!
//! # Rib load (roller equilibrium in its meridian plane)
//!
//! Pure axial load `F_a` shared by `Z` rollers; the cup (outer ring) touches a roller only
//! on its raceway, so its normal force is `Q_e = F_a / (Z sin α_o)` exactly. The roller is
//! in equilibrium under `Q_e` (direction `n_o = (−cos α_o, sin α_o)` in (radial, axial)
//! components), the inner raceway force `Q_i` (`n_i = (cos α_i, −sin α_i)`), the rib force
//! `Q_f` along the rib contact normal `d` (from the rib into the roller) and the centrifugal
//! force `F_c = m ω_c² r_c` (radial):
//!
//! ```text
//! Q_i n_i + Q_f d = −Q_e n_o − F_c e_x        (2 × 2 linear system for Q_i, Q_f)
//! ```
//!
//! With `d = −e_r` (rib normal along the roller axis) this gives `Q_i = Q_e − F_c cos α_m /
//! cos β` and `Q_f = 2 Q_e sin β + F_c sin α_i / cos β`. The moment balance only places the
//! raceway resultants along the contact lines (and takes the gyroscopic moment); it does not
//! change `Q_f`. Raceway friction and roller skew are not in this balance.
//!
//! # Torque and power
//!
//! Each roller's rib contact dissipates `P` (the friction integral of
//! [`crate::friction::integral`]); the bearing's rib power is `Z P` and the rib's share of the
//! bearing's friction torque, by the power balance with the rings turning at `ω_i`, `ω_o`,
//! is `M = Z P / |ω_i − ω_o|`. For constant μ and a point contact at height `e` above the inner
//! raceway contact line (`|v_s| = |ω_rel| e`, `|ω_rel| = |ω_i − ω_o| sin α_o / sin 2β`) with
//! `d = −e_r`, this is exactly
//!
//! ```text
//! M = Z μ Q_f e sin α_o / sin 2β = μ e F_a / cos β,
//! ```
//!
//! which Aihara's (1987) `μ e cos β F_a` matches to first order: the two differ by the factor
//! `cos² β` (relative `sin² β`, 0.27 % at β = 3°). docs/friction.md §5 has the derivation.
//!
//! Under any other load (radial load, moment) every roller has its own cup load from a
//! bearing model; [`RibFrictionModel::evaluate_rollers`] and
//! [`RibFrictionModel::sweep_rollers`] take each roller's loads and sum the rollers'
//! powers (module `rollers`, `docs/bearing-model.md` §10).
//!
//! Units: mm, N, MPa, rad/s (speeds), °C, kg/m³ (roller density); torque N·mm, power W.
//!
//! ```
//! use kontakt::bearing::{PressureModel, RibFrictionModel, RibLubrication, RollerRibSpec, RollerSet};
//! use kontakt::friction::FrictionLaw;
//! use kontakt::lubrication::{FilmFormula, Lubricant};
//!
//! // Spherical face r_R = 57 mm on a toroidal rib (Wirsching et al. 2020, Table 1), 17 rollers,
//! // ISO VG 68 at 70 °C, mixed friction with mu_b = 0.12, centrifugal force included.
//! let oil = RibLubrication {
//!     lubricant: Lubricant::iso_vg(68, 860.0, 0.02)?,
//!     temperature: 70.0,
//!     roughness: [0.2e-3, 0.2e-3],
//!     formula: FilmFormula::Chittenden,
//! };
//! let model = RibFrictionModel::new(
//!     RollerRibSpec::builtin("sphere-torus-57")?,
//!     RollerSet::default(),
//!     FrictionLaw::mixed(0.12)?,
//!     Some(oil),
//!     true,
//! )?;
//! // 15 kN axial load at 100 and 3000 r/min (inner ring; outer ring fixed).
//! let speeds = [100.0, 3000.0].map(|n: f64| n * std::f64::consts::PI / 30.0);
//! let sweep = model.sweep(PressureModel::Pimp, 15_000.0, &speeds)?;
//! for r in &sweep {
//!     println!(
//!         "Q_f = {:.1} N, Lambda = {:.2}, mu = {:.4}, torque {:.0} N·mm, power {:.1} W",
//!         r.loads.rib, r.film.lambda, r.coefficient, r.bearing_torque, r.bearing_power
//!     );
//! }
//! // The film grows with speed and the coefficient falls (the Stribeck branch).
//! assert!(sweep[1].film.lambda > sweep[0].film.lambda);
//! assert!(sweep[1].coefficient < sweep[0].coefficient);
//! # Ok::<(), kontakt::error::Error>(())
//! ```

use crate::bearing::kinematics::TaperedKinematics;
use crate::bearing::roller_rib::{RollerRib, RollerRibSpec};
use crate::error::{Error, Result};
use crate::field::NormalSolution;
use crate::friction::{ContactFriction, FilmState, FrictionLaw, contact_friction};
use crate::gap::{GapSource, SurfacePairGap};
use crate::geometry::ContactFrame;
use crate::halfspace::{Bem, BemOptions};
use crate::hertz::{HertzPointContact, PointGeometry};
use crate::lubrication::{
    FilmContact, FilmFormula, FilmThickness, Lubricant, film_parameter, film_thickness,
};
use crate::material::ElasticMaterial;
use crate::pimp::{Pimp, PimpOptions};
use nalgebra::{Unit, Vector3};

mod rollers;

pub use rollers::{
    BearingRibFriction, RollerCup, RollerRibFriction, RollerRibLoad, roller_loads_on_cup,
};

/// Which model gives the pressure field of the rib contact.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
#[cfg_attr(
    feature = "serde",
    derive(serde::Serialize, serde::Deserialize, schemars::JsonSchema)
)]
#[cfg_attr(feature = "serde", serde(rename_all = "snake_case"))]
pub enum PressureModel {
    /// Hertz's ellipse from the curvatures at the contact point, sampled on a grid.
    Hertz,
    /// PimP (corrected bedding).
    Pimp,
    /// The coupled elastic half-space solver.
    #[cfg_attr(feature = "serde", serde(rename = "halfspace"))]
    HalfSpace,
}

impl PressureModel {
    /// All three, in the order of the reports.
    pub const ALL: [PressureModel; 3] = [
        PressureModel::Hertz,
        PressureModel::Pimp,
        PressureModel::HalfSpace,
    ];

    /// The name used in reports and case files.
    pub fn as_str(&self) -> &'static str {
        match self {
            PressureModel::Hertz => "hertz",
            PressureModel::Pimp => "pimp",
            PressureModel::HalfSpace => "halfspace",
        }
    }
}

/// The rollers of the bearing: number, length and density (for the centrifugal force).
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(
    feature = "serde",
    derive(serde::Serialize, serde::Deserialize, schemars::JsonSchema)
)]
#[cfg_attr(feature = "serde", serde(default, deny_unknown_fields))]
pub struct RollerSet {
    /// Number of rollers Z (≥ 3).
    pub count: usize,
    /// Roller length along its axis \[mm\].
    #[cfg_attr(feature = "serde", serde(rename = "length_mm"))]
    pub length: f64,
    /// Density of the roller material \[kg/m³\] (steel 7850).
    #[cfg_attr(feature = "serde", serde(rename = "density_kg_m3"))]
    pub density: f64,
}

impl Default for RollerSet {
    /// 17 steel rollers 16 mm long: representative values for the default bearing of
    /// 60 mm bore and 110 mm outside diameter (docs/friction.md §5), not a manufacturer's
    /// drawing.
    fn default() -> Self {
        RollerSet {
            count: 17,
            length: 16.0,
            density: 7850.0,
        }
    }
}

/// Mass properties of one roller (a frustum of the roller cone).
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct RollerMass {
    /// Mass \[kg\].
    pub mass: f64,
    /// Distance of the centre of mass from the apex along the roller axis \[mm\].
    pub apex_distance: f64,
    /// Radius of the centre of mass from the ring axis \[mm\].
    pub radius: f64,
}

impl RollerSet {
    /// Check the fields.
    ///
    /// # Errors
    /// [`Error::InvalidInput`] naming the field: `count` ≥ 3, `length` finite and > 0,
    /// `density` finite and > 0 kg/m³.
    pub fn check(&self) -> Result<()> {
        if self.count < 3 {
            return Err(Error::invalid("count", self.count, "at least 3 rollers"));
        }
        if !(self.length.is_finite() && self.length > 0.0) {
            return Err(Error::invalid(
                "length",
                self.length,
                "a finite length > 0 mm",
            ));
        }
        if !(self.density.is_finite() && self.density > 0.0) {
            return Err(Error::invalid(
                "density",
                self.density,
                "a finite density > 0 kg/m³",
            ));
        }
        Ok(())
    }

    /// Mass and centre of mass of a roller of the pair `rr`: the frustum of the roller cone
    /// (apex at the bearing's apex, half-angle β) between the large end (radius `r_L`, at
    /// `s_L = r_L / tan β` from the apex) and `length` towards the apex. Frustum of radii `R`
    /// (large) and `r`, length `l`: `V = π l (R² + R r + r²)/3`, centroid at
    /// `l (R² + 2 R r + 3 r²) / (4 (R² + R r + r²))` from the large end.
    ///
    /// # Errors
    /// Those of [`RollerSet::check`]; field `length` when the roller would reach past the
    /// apex (`length ≥ s_L`).
    pub fn mass(&self, rr: &RollerRib) -> Result<RollerMass> {
        self.check()?;
        let beta = rr.spec.bearing.roller_half_angle_deg.to_radians();
        let big = rr.spec.bearing.roller_large_end_radius;
        let s_large = big / beta.tan();
        if self.length >= s_large {
            return Err(Error::invalid(
                "length",
                self.length,
                format!("less than the apex distance of the large end, {s_large:.3} mm"),
            ));
        }
        let small = big - self.length * beta.tan();
        let (volume, from_large) = frustum(big, small, self.length); // mm³, mm
        let apex_distance = s_large - from_large;
        let alpha_m = (rr.raceway_angle_deg + rr.spec.bearing.roller_half_angle_deg).to_radians();
        Ok(RollerMass {
            mass: self.density * volume * 1e-9,
            apex_distance,
            radius: apex_distance * alpha_m.sin(),
        })
    }
}

/// The volume \[mm³\] of a frustum of radii `large` and `small` \[mm\] and length `length`
/// \[mm\], `V = π l (R² + R r + r²)/3`, and the distance of its centroid from the large
/// end, `l (R² + 2 R r + 3 r²) / (4 (R² + R r + r²))` \[mm\] (a cylinder for `R = r`: `l/2`).
/// The rollers of [`RollerSet::mass`] and of the whole bearing at speed
/// (`kontakt_bearing::roller_speed`).
pub fn frustum(large: f64, small: f64, length: f64) -> (f64, f64) {
    let sum = large * large + large * small + small * small;
    let volume = std::f64::consts::PI * length * sum / 3.0;
    let from_large =
        length * (large * large + 2.0 * large * small + 3.0 * small * small) / (4.0 * sum);
    (volume, from_large)
}

/// The normal forces on one roller \[N\].
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct RollerLoads {
    /// Outer raceway (cup) normal force Q_e \[N\].
    pub outer_raceway: f64,
    /// Inner raceway (cone) normal force Q_i \[N\].
    pub inner_raceway: f64,
    /// Rib normal force Q_f \[N\].
    pub rib: f64,
    /// Centrifugal force on the roller F_c \[N\].
    pub centrifugal: f64,
}

/// The loads on one roller under the axial load `axial_load` \[N\] shared by `count` rollers,
/// with the centrifugal force `centrifugal` \[N\] and the rib's force on the roller along
/// `rib_normal` (world, roller at cage angle 0; its component out of the section plane is
/// ignored). See the module docs.
///
/// # Errors
/// [`Error::InvalidInput`]: `axial_load` finite and > 0; `centrifugal` finite and ≥ 0;
/// `count` ≥ 3; `rib_normal` finite, in the section plane and pointing towards the apex
/// side (so that the rib holds the roller back); `inner_speed` when the centrifugal force
/// would lift the roller off the inner raceway (Q_i < 0).
pub fn roller_loads(
    kinematics: &TaperedKinematics,
    rib_normal: &Vector3<f64>,
    axial_load: f64,
    count: usize,
    centrifugal: f64,
) -> Result<RollerLoads> {
    if !(axial_load.is_finite() && axial_load > 0.0) {
        return Err(Error::invalid(
            "axial_load",
            axial_load,
            "a finite force > 0 N",
        ));
    }
    if !(centrifugal.is_finite() && centrifugal >= 0.0) {
        return Err(Error::invalid(
            "centrifugal",
            centrifugal,
            "a finite force >= 0 N",
        ));
    }
    if count < 3 {
        return Err(Error::invalid("count", count, "at least 3 rollers"));
    }
    let d = rib_direction(kinematics, rib_normal)?;
    let q_e = axial_load / (count as f64 * kinematics.outer_raceway_angle().sin());
    let (q_i, q_f) = raceway_and_rib(kinematics, &d, q_e, centrifugal);
    if !(q_i >= 0.0) {
        return Err(Error::invalid(
            "inner_speed",
            format!("a speed at which the centrifugal force {centrifugal:.4e} N exceeds"),
            "a speed at which the roller stays on the inner raceway (Q_i >= 0)",
        ));
    }
    if !(q_f > 0.0 && q_f.is_finite()) {
        return Err(Error::invalid(
            "rib_normal",
            format!("{:?}", rib_normal),
            "a rib contact normal that takes load (Q_f > 0)",
        ));
    }
    Ok(RollerLoads {
        outer_raceway: q_e,
        inner_raceway: q_i,
        rib: q_f,
        centrifugal,
    })
}

/// The unit rib normal in the section plane (its component out of the plane dropped).
///
/// # Errors
/// [`Error::InvalidInput`] (field `rib_normal`) unless finite, mostly in the section plane
/// and pointing back along the roller axis.
fn rib_direction(
    kinematics: &TaperedKinematics,
    rib_normal: &Vector3<f64>,
) -> Result<Vector3<f64>> {
    let d = Vector3::new(rib_normal.x, 0.0, rib_normal.z);
    let n = d.norm();
    let e_r = kinematics.directions(0.0).roller_axis;
    if !(n.is_finite() && n > 0.5 * rib_normal.norm() && d.dot(&e_r) < 0.0) {
        return Err(Error::invalid(
            "rib_normal",
            format!("{:?}", rib_normal),
            "a finite direction in the section plane pointing back along the roller axis",
        ));
    }
    Ok(d / n)
}

/// The inner raceway and rib loads `(Q_i, Q_f)` \[N\] of a roller with the cup load `q_e`
/// \[N\] and the centrifugal force `centrifugal` \[N\], the rib normal `d` a unit vector in
/// the section plane: the 2 × 2 system of the module docs,
/// `Q_i n_i + Q_f d = −Q_e n_o − F_c e_x`.
fn raceway_and_rib(
    kinematics: &TaperedKinematics,
    d: &Vector3<f64>,
    q_e: f64,
    centrifugal: f64,
) -> (f64, f64) {
    let (ai, ao) = (
        kinematics.inner_raceway_angle,
        kinematics.outer_raceway_angle(),
    );
    // Q_i n_i + Q_f d = r, r = −Q_e n_o − F_c e_x; n_i = (cos α_i, −sin α_i).
    let (ni_x, ni_z) = (ai.cos(), -ai.sin());
    let (r_x, r_z) = (q_e * ao.cos() - centrifugal, -q_e * ao.sin());
    let det = ni_x * d.z - ni_z * d.x;
    let q_i = (r_x * d.z - r_z * d.x) / det;
    let q_f = (ni_x * r_z - ni_z * r_x) / det;
    (q_i, q_f)
}

/// The lubricant at the rib contact: oil, inlet temperature, the two surfaces' roughness and
/// the film formula. The film is evaluated at the contact point for every operating point
/// (entrainment speed, rib load); its central thickness sets the shear rate and
/// `Λ = h_c / √(σ₁² + σ₂²)`.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct RibLubrication {
    /// The oil.
    pub lubricant: Lubricant,
    /// Inlet (bulk oil) temperature \[°C\].
    pub temperature: f64,
    /// RMS roughness of the roller end face and of the rib \[mm\].
    pub roughness: [f64; 2],
    /// Film thickness formula.
    pub formula: FilmFormula,
}

impl RibLubrication {
    fn check(&self) -> Result<()> {
        self.lubricant.dynamic_viscosity(self.temperature)?;
        film_parameter(1.0, self.roughness[0], self.roughness[1]).map_err(|e| match e {
            Error::InvalidInput {
                value, expected, ..
            } => Error::InvalidInput {
                field: "roughness".into(),
                value,
                expected,
            },
            other => other,
        })?;
        Ok(())
    }
}

/// Operating point of the bearing.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct Operating {
    /// Axial load F_a \[N\].
    pub axial_load: f64,
    /// Inner ring speed ω_i \[rad/s\].
    pub inner_speed: f64,
    /// Outer ring speed ω_o \[rad/s\].
    pub outer_speed: f64,
}

/// The friction of the rib contact at one operating point.
#[derive(Debug, Clone, PartialEq)]
pub struct RibFriction {
    /// The operating point.
    pub operating: Operating,
    /// Pressure model of the field.
    pub model: PressureModel,
    /// Cage speed ω_c \[rad/s\].
    pub cage_speed: f64,
    /// |ω_rel|, the roller's angular speed relative to the rib \[rad/s\].
    pub relative_speed: f64,
    /// Loads on one roller \[N\].
    pub loads: RollerLoads,
    /// Largest pressure of the rib contact \[MPa\].
    pub max_pressure: f64,
    /// Height of the contact point above the inner raceway contact line, e \[mm\].
    pub contact_height: f64,
    /// Sliding speed at the contact point \[mm/s\].
    pub sliding_speed: f64,
    /// Entrainment speed at the contact point \[mm/s\] (cage frame).
    pub entrainment_speed: f64,
    /// The film used by the friction law (dry when no lubricant is given).
    pub film: FilmState,
    /// The film thickness, its regime groups and warnings (none when dry).
    pub film_thickness: Option<FilmThickness>,
    /// Friction of one roller's rib contact (force and moments on the roller).
    pub contact: ContactFriction,
    /// Effective friction coefficient |F_t| / Q_f.
    pub coefficient: f64,
    /// Moment of the rib friction on the roller about its own axis \[N·mm\].
    pub roller_axis_moment: f64,
    /// Moment of the rib friction on the inner ring about the ring axis, all rollers
    /// \[N·mm\].
    pub ring_axis_moment: f64,
    /// Power dissipated at one rib contact \[W\].
    pub power: f64,
    /// Power dissipated at all rib contacts \[W\].
    pub bearing_power: f64,
    /// The rib's share of the bearing's friction torque, `Z P / |ω_i − ω_o|` \[N·mm\].
    pub bearing_torque: f64,
}

/// The roller-end/rib contact of a bearing with its rollers and friction law, ready to be
/// evaluated at any operating point.
#[derive(Debug, Clone)]
pub struct RibFrictionModel {
    pair: RollerRib,
    gap: SurfacePairGap,
    frame: ContactFrame,
    rollers: RollerSet,
    mass: RollerMass,
    law: FrictionLaw,
    lubrication: Option<RibLubrication>,
    centrifugal: bool,
    material: ElasticMaterial,
    hertz: HertzPointContact,
    pimp: Pimp,
    bem: Bem,
}

impl RibFrictionModel {
    /// The model of the pairing `spec` (steel on steel) with `rollers`, the friction law
    /// `law` and the lubricant `lubrication` (`None`: dry, every cell in boundary friction);
    /// `centrifugal` adds the rollers' centrifugal force to the rib load.
    ///
    /// # Errors
    /// Those of [`RollerRib::new`], [`RollerSet::mass`], [`FrictionLaw::check`], of the
    /// lubricant at its temperature, field `roughness` (negative, non-finite or both zero),
    /// field `count` (more rollers than fit side by side around the ring,
    /// `Z > π / asin(r_L / R)`), and of the solvers' set-up.
    pub fn new(
        spec: RollerRibSpec,
        rollers: RollerSet,
        law: FrictionLaw,
        lubrication: Option<RibLubrication>,
        centrifugal: bool,
    ) -> Result<Self> {
        law.check()?;
        if let Some(l) = &lubrication {
            l.check()?;
        }
        let pair = RollerRib::new(spec)?;
        let mass = rollers.mass(&pair)?;
        // The rollers must fit side by side around the ring: neighbours' centres a chord
        // 2 R sin(pi/Z) >= 2 r_L apart. (A billion rollers, found by probing, carried
        // nothing each, and the error blamed the speed.)
        let r_l = pair.spec.bearing.roller_large_end_radius;
        let fit = if r_l < mass.radius {
            (std::f64::consts::PI / (r_l / mass.radius).asin()).floor()
        } else {
            0.0
        };
        if rollers.count as f64 > fit {
            return Err(Error::invalid(
                "count",
                rollers.count,
                format!(
                    "at most {fit} rollers: no more of large-end radius {r_l} mm fit side by \
                     side around the ring at {:.4} mm from its axis",
                    mass.radius
                ),
            ));
        }
        let gap = SurfacePairGap::new(pair.face.clone(), pair.rib.clone(), pair.contact)?;
        let frame = ContactFrame::of_gap(&gap);
        let material = ElasticMaterial::STEEL;
        let hertz = HertzPointContact::new(
            PointGeometry::from_curvature(gap.curvature()),
            material,
            material,
        )?;
        let pimp = Pimp::new(material, material, PimpOptions::default())?;
        let bem = Bem::new(material, material, BemOptions::default())?
            .with_estimate(crate::pimp::zone_estimate(material, material)?);
        Ok(RibFrictionModel {
            pair,
            gap,
            frame,
            rollers,
            mass,
            law,
            lubrication,
            centrifugal,
            material,
            hertz,
            pimp,
            bem,
        })
    }

    /// The roller/rib pair.
    pub fn pair(&self) -> &RollerRib {
        &self.pair
    }

    /// The contact's gap (substitute geometry).
    pub fn gap(&self) -> &SurfacePairGap {
        &self.gap
    }

    /// The contact frame of the gap (where every field's grid lies).
    pub fn frame(&self) -> &ContactFrame {
        &self.frame
    }

    /// Mass properties of one roller.
    pub fn roller_mass(&self) -> RollerMass {
        self.mass
    }

    /// The elastic material of roller and ring.
    pub fn material(&self) -> ElasticMaterial {
        self.material
    }

    /// Kinematics and roller loads at `op`.
    ///
    /// # Errors
    /// Those of [`TaperedKinematics::of_roller_rib`] and [`roller_loads`].
    pub fn loads(&self, op: &Operating) -> Result<(TaperedKinematics, RollerLoads)> {
        let k = TaperedKinematics::of_roller_rib(&self.pair, op.inner_speed, op.outer_speed)?;
        let centrifugal = self.centrifugal_force(&k);
        let loads = roller_loads(
            &k,
            &self.pair.contact.normal.into_inner(),
            op.axial_load,
            self.rollers.count,
            centrifugal,
        )?;
        Ok((k, loads))
    }

    /// The centrifugal force on one roller at the cage speed of `k`, `m ω_c² r_c` \[N\]
    /// (0 when the model leaves it out).
    pub fn centrifugal_force(&self, k: &TaperedKinematics) -> f64 {
        if self.centrifugal {
            // m [kg] ω² [1/s²] r [mm] 1e-3 = N
            self.mass.mass * k.cage_speed * k.cage_speed * self.mass.radius * 1e-3
        } else {
            0.0
        }
    }

    /// The pressure field of the rib contact at the rib load `rib_load` \[N\] by `model`.
    /// Hertz is sampled on a 64 × 64 grid over the ellipse (5 % margin) in its principal
    /// frame, where PimP and the half-space solver lay their grids (x along the major axis).
    ///
    /// # Errors
    /// Those of the solvers.
    pub fn solve(&self, model: PressureModel, rib_load: f64) -> Result<NormalSolution<()>> {
        Ok(match model {
            PressureModel::Hertz => {
                // On the gap's principal frame, as PimP and the half-space solver: the
                // maps and the friction integral see the three models' grids alike.
                let h = self.hertz.solve_force(rib_load)?;
                h.on_principal_grid(64, 64, 0.05)?.map_detail(|_| ())
            }
            PressureModel::Pimp => self
                .pimp
                .solve_force(&self.gap, rib_load)?
                .map_detail(|_| ()),
            PressureModel::HalfSpace => self
                .bem
                .solve_force(&self.gap, rib_load)?
                .map_detail(|_| ()),
        })
    }

    /// The friction at `op` on a field already solved at the rib load of `loads` (the fast
    /// path: no solve, no allocation).
    ///
    /// # Errors
    /// Those of [`contact_friction`] and [`FrictionLaw::with_film`].
    pub fn friction_on<D>(
        &self,
        model: PressureModel,
        field: &NormalSolution<D>,
        op: &Operating,
        kinematics: &TaperedKinematics,
        loads: &RollerLoads,
    ) -> Result<RibFriction> {
        self.friction_share(
            model,
            field,
            op,
            kinematics,
            loads,
            self.rollers.count as f64,
        )
    }

    /// [`RibFrictionModel::friction_on`] with the bearing totals (`bearing_power`,
    /// `bearing_torque`, `ring_axis_moment`) of `z` rollers each carrying `loads`: the
    /// roller count for a bearing under pure axial load, 1 for one roller's share (as
    /// [`RibFrictionModel::evaluate_rollers`] gives every roller). Allocates nothing.
    ///
    /// # Errors
    /// Those of [`RibFrictionModel::friction_on`].
    pub fn friction_share<D>(
        &self,
        model: PressureModel,
        field: &NormalSolution<D>,
        op: &Operating,
        kinematics: &TaperedKinematics,
        loads: &RollerLoads,
        z: f64,
    ) -> Result<RibFriction> {
        let pair = kinematics.rib_pair(0.0)?;
        let centre = pair.velocities(&self.frame.origin, &self.frame.normal)?;
        let (film, film_thickness) = self.film(&centre.entrainment, loads.rib)?;
        let law = self.law.with_film(&film)?;
        let contact = contact_friction(field, &self.frame, &pair, &law)?;
        let apex = kinematics.apex;
        let inner_line = kinematics.directions(0.0).inner_line;
        let r = self.frame.origin - apex;
        let contact_height = (r - inner_line * r.dot(&inner_line)).norm();
        let roller = pair.body1.pose.translation.vector;
        let roller_axis = Unit::new_normalize(kinematics.directions(0.0).roller_axis);
        let power = contact.grid.power;
        let bearing_power = z * power;
        let dw = (op.inner_speed - op.outer_speed).abs();
        Ok(RibFriction {
            operating: *op,
            model,
            cage_speed: kinematics.cage_speed,
            relative_speed: kinematics.relative_speed.abs(),
            loads: *loads,
            max_pressure: field.max_pressure,
            contact_height,
            sliding_speed: centre.sliding.norm(),
            entrainment_speed: centre.entrainment.norm(),
            film,
            film_thickness,
            coefficient: contact.force.norm() / loads.rib,
            roller_axis_moment: contact.moment_about(&roller.into(), &roller_axis),
            ring_axis_moment: -z * contact.moment_about(&apex, &Vector3::z_axis()),
            power,
            bearing_power,
            bearing_torque: if dw > 0.0 {
                bearing_power * 1e3 / dw
            } else {
                0.0
            },
            contact,
        })
    }

    /// The film at the contact point for the entrainment velocity `entrainment` \[mm/s\]
    /// (world frame, in the contact plane) and the rib load `load` \[N\]: the Hertzian
    /// radii of the gap's principal curvatures, the entrainment angle from its first
    /// principal direction. Dry without a lubricant.
    ///
    /// # Errors
    /// Those of [`film_thickness`], [`film_parameter`] and [`FilmState::new`].
    pub fn film(
        &self,
        entrainment: &Vector3<f64>,
        load: f64,
    ) -> Result<(FilmState, Option<FilmThickness>)> {
        let Some(lub) = &self.lubrication else {
            return Ok((FilmState::dry(), None));
        };
        let k = self.gap.curvature();
        let (s, c) = k.orientation.sin_cos();
        let (ex, ey) = (self.frame.ex.into_inner(), self.frame.ey.into_inner());
        let px = ex * c + ey * s;
        let py = -ex * s + ey * c;
        let contact = FilmContact {
            rx: 0.5 / k.a_coef,
            ry: 0.5 / k.b_coef,
            entrainment_angle: entrainment.dot(&py).atan2(entrainment.dot(&px)),
            entrainment_speed: entrainment.norm(),
            load,
            reduced_modulus: crate::material::effective_modulus(&self.material, &self.material),
        };
        let eta = lub.lubricant.dynamic_viscosity(lub.temperature)?;
        let alpha = lub.lubricant.alpha();
        let h = film_thickness(&contact, eta, alpha, lub.formula)?;
        let lambda = film_parameter(h.central, lub.roughness[0], lub.roughness[1])?;
        Ok((FilmState::new(h.central, lambda, eta, alpha)?, Some(h)))
    }

    /// The friction law.
    pub fn law(&self) -> &FrictionLaw {
        &self.law
    }

    /// The lubricant, if any.
    pub fn lubrication(&self) -> Option<&RibLubrication> {
        self.lubrication.as_ref()
    }

    /// Solve the field at the rib load of `op` and the friction on it.
    ///
    /// # Errors
    /// Those of [`RibFrictionModel::loads`], [`RibFrictionModel::solve`] and
    /// [`RibFrictionModel::friction_on`].
    pub fn evaluate(&self, model: PressureModel, op: &Operating) -> Result<RibFriction> {
        let (k, loads) = self.loads(op)?;
        let field = self.solve(model, loads.rib)?;
        self.friction_on(model, &field, op, &k, &loads)
    }

    /// The friction at each inner-ring speed of `inner_speeds` \[rad/s\] (outer ring fixed)
    /// under `axial_load` \[N\]. Without the centrifugal force the rib load is the same at
    /// every speed and the field is solved once.
    ///
    /// # Errors
    /// [`Error::InvalidInput`] (field `speeds`) for an empty list; those of
    /// [`RibFrictionModel::evaluate`].
    pub fn sweep(
        &self,
        model: PressureModel,
        axial_load: f64,
        inner_speeds: &[f64],
    ) -> Result<Vec<RibFriction>> {
        if inner_speeds.is_empty() {
            return Err(Error::invalid(
                "speeds",
                "an empty list",
                "at least one speed",
            ));
        }
        let mut out = Vec::with_capacity(inner_speeds.len());
        let mut cached: Option<(f64, NormalSolution<()>)> = None;
        for &w in inner_speeds {
            let op = Operating {
                axial_load,
                inner_speed: w,
                outer_speed: 0.0,
            };
            let (k, loads) = self.loads(&op)?;
            let reuse = cached.as_ref().is_some_and(|(q, _)| *q == loads.rib);
            if !reuse {
                cached = Some((loads.rib, self.solve(model, loads.rib)?));
            }
            let field = cached
                .as_ref()
                .map(|(_, f)| f)
                .ok_or_else(|| Error::invalid("speeds", w, "a solvable speed"))?;
            out.push(self.friction_on(model, field, &op, &k, &loads)?);
        }
        Ok(out)
    }
}
