//! The asperity-based traction model of the thesis (§3.1.2.2): periodic
//! spherical asperities on a nominal Hertz contact, Mindlin's partial slip per asperity.
//!
//! # Model
//! A square (or rectangular) lattice of spherical asperities of period `p` along the
//! rolling direction `x` and `p_t` across it covers the nominal contact, with a valley at
//! the contact centre: the tips sit at $x_i = (i+\tfrac12)p$, $y_j = (j+\tfrac12)p_t$.
//! Every tip strictly inside the nominal contact carries a normal force $F_i$, its share
//! of the nominal (Hertz) pressure over its lattice cell ([`LoadSharing`]).
//!
//! The contact rolls with the slide-to-roll ratio $\xi = \Delta V / V_r$ (the sliding
//! speed over the mean surface speed). An asperity pair that met at the leading edge has,
//! after travelling the distance $d_i$ through the contact, a relative tangential
//! displacement ([`SlipReference`])
//!
//! $$\delta_i = \xi_{\mathrm{eff}}\, d_i, \qquad \xi_{\mathrm{eff}} = \xi \;\text{(rolling speed)}
//!   \quad\text{or}\quad \frac{\xi}{1 + \xi/2}\;\text{(faster surface)}.$$
//!
//! Mindlin's partial-slip law for two identical elastic spheres (thesis eqs 2.15-2.18,
//! Johnson 1985 eq. 7.42) turns it into a tangential force:
//!
//! $$B_i = \frac{8\,G\,a_i\,\delta_i}{3(2-\nu)\,\mu F_i} = \frac{\delta_i}{\delta^*_i},\qquad
//!   F_{T,i} = \mu F_i\left[1 - (1 - \min(B_i, 1))^{3/2}\right],$$
//!
//! with the asperity contact radius $a_i$ ([`AsperityContactLaw`]) and the gross-slip
//! displacement $\delta^*_i = 3(2-\nu)\mu F_i / (8 G a_i)$. The traction curve is
//!
//! $$\frac{F_T}{\mu F_N}(\xi) = \frac{\sum_i n_i F_{T,i}}{\mu F_N},$$
//!
//! where $n_i$ is the number of identical asperities an entry stands for (the rows of a
//! line contact). It is zero at $\xi = 0$, non-decreasing, and constant at
//! $\sum_i n_i F_i / F_N$ (exactly 1 with [`LoadSharing::Integral`]) once every asperity
//! slides.
//!
//! # Assumptions
//! Quasi-static: each asperity's load is the nominal pressure at its position and its
//! tangential loading is monotonic (no Mindlin-Deresiewicz unloading as the load falls
//! towards the trailing edge). Identical elastic bodies (one E, nu, G). Asperity pairs
//! meet tip to tip; neighbouring asperities do not interact; the nominal pressure is not
//! changed by roughness or friction.
//!
//! # References
//! - Thesis §3.1.2.2.1-2, eqs 2.15-2.18, 3.9-3.14, Tables 3.1-3.7, Annexes A-B.
//! - Mindlin (1949), "Compliance of elastic bodies in contact", J. Appl. Mech. 16, 259-268.
//! - Johnson (1955), "Surface interaction between elastically loaded bodies under
//!   tangential forces", Proc. R. Soc. A 230, 531-548 (the 1.11 of eq. 2.17).
//! - Johnson, *Contact Mechanics* (1985), §7.2, eqs (7.40)-(7.42).

use super::cells::{arc_area, disk_cell};
use crate::error::{Error, Result, positive_as};
use crate::hertz::line::LineContact;
use crate::hertz::{HertzPointContact, PointGeometry};
use crate::material::ElasticMaterial;
use crate::units::{Megapascal, Millimetre, Newton, Radian};
use std::f64::consts::PI;

/// Most asperities a model may hold (a guard against absurdly fine lattices).
pub const MAX_ASPERITIES: usize = 1_000_000;

/// Relative tolerance of the cross-check of a given maximum pressure against the load.
pub const MAX_PRESSURE_TOLERANCE: f64 = 1e-4;

/// Largest `1 - b/a` of a Hertz point contact still accepted as circular.
pub const CIRCULARITY_TOLERANCE: f64 = 1e-9;

/// The nominal (smooth) contact the asperities sit on, tagged by `kind` in TOML.
///
/// The half-width is either given or computed with [`crate::hertz`] from the bodies'
/// radii and the asperity material; the maximum pressure always follows from the load
/// ($p_0 = 2F_N/(\pi a L)$ for a line, $3F_N/(2\pi a^2)$ for a circle). A given
/// `max_pressure` is only a cross-check: it must agree with the load within
/// [`MAX_PRESSURE_TOLERANCE`].
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(
    feature = "serde",
    derive(serde::Serialize, serde::Deserialize, schemars::JsonSchema)
)]
#[cfg_attr(
    feature = "serde",
    serde(tag = "kind", rename_all = "snake_case", deny_unknown_fields)
)]
pub enum NominalContact {
    /// Rough line contact (rectangular contact shape) of length `length` and given
    /// half-width.
    Line {
        /// Contact (roller) length L \[mm\], > 0.
        #[cfg_attr(feature = "serde", serde(rename = "length_mm"))]
        length: Millimetre,
        /// Half-width a of the contact strip \[mm\], > 0.
        #[cfg_attr(feature = "serde", serde(rename = "half_width_mm"))]
        half_width: Millimetre,
        /// Optional cross-check of the maximum pressure p0 \[MPa\].
        #[cfg_attr(feature = "serde", serde(rename = "max_pressure_mpa", default))]
        max_pressure: Option<Megapascal>,
    },
    /// Line contact of two parallel cylinders of radii `radii` \[mm\] (convex > 0, concave
    /// < 0, `inf` flat) and length `length`, solved by [`LineContact`] with the line load
    /// F_N / L.
    HertzLine {
        /// Contact (roller) length L \[mm\], > 0.
        #[cfg_attr(feature = "serde", serde(rename = "length_mm"))]
        length: Millimetre,
        /// The cylinders' radii \[mm\].
        #[cfg_attr(feature = "serde", serde(rename = "radii_mm"))]
        radii: [Millimetre; 2],
    },
    /// Circular contact of given radius ("half-width").
    Circular {
        /// Radius a of the contact circle \[mm\], > 0.
        #[cfg_attr(feature = "serde", serde(rename = "half_width_mm"))]
        half_width: Millimetre,
        /// Optional cross-check of the maximum pressure p0 \[MPa\].
        #[cfg_attr(feature = "serde", serde(rename = "max_pressure_mpa", default))]
        max_pressure: Option<Megapascal>,
    },
    /// Circular contact solved by [`HertzPointContact`]: two spheres, or crossed
    /// cylinders of equal radii (`[R, inf]`, `[R, inf]`, angle pi/2). The geometry must
    /// give a circle (b/a within [`CIRCULARITY_TOLERANCE`] of 1).
    HertzCircular {
        /// Principal radii of body 1 \[mm\].
        #[cfg_attr(feature = "serde", serde(rename = "body1_radii_mm"))]
        body1_radii: [Millimetre; 2],
        /// Principal radii of body 2 \[mm\].
        #[cfg_attr(feature = "serde", serde(rename = "body2_radii_mm"))]
        body2_radii: [Millimetre; 2],
        /// Angle between the principal planes \[rad\] (crate *Conventions*).
        #[cfg_attr(feature = "serde", serde(rename = "angle_rad", default))]
        angle: Radian,
    },
}

/// Shape of the nominal contact.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[cfg_attr(
    feature = "serde",
    derive(serde::Serialize, serde::Deserialize, schemars::JsonSchema)
)]
#[cfg_attr(feature = "serde", serde(rename_all = "snake_case"))]
pub enum ContactShape {
    /// Rectangular strip of length L and width 2a (thesis §3.1.2.2.1).
    Line,
    /// Circle of radius a (thesis §3.1.2.2.2).
    Circular,
}

/// The contact radius a_i of one asperity pair under its normal force F_i, tagged by
/// `law` in TOML.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(
    feature = "serde",
    derive(serde::Serialize, serde::Deserialize, schemars::JsonSchema)
)]
#[cfg_attr(
    feature = "serde",
    serde(tag = "law", rename_all = "snake_case", deny_unknown_fields)
)]
pub enum AsperityContactLaw {
    /// Hertz, computed by [`HertzPointContact`] for the two asperity spheres:
    /// $a_i = f\,(3 F_i R / (4E^*))^{1/3}$ with $1/R = 1/r_1 + 1/r_2$. The factor `f`
    /// (default 1) is a calibration knob; the thesis' circular sheet corresponds to
    /// `f = 11.1` (see `docs/traction-asperity.md` §6).
    Hertz {
        /// Multiplier f on the Hertz radius \[-\], finite and > 0 (default 1).
        #[cfg_attr(feature = "serde", serde(default = "unit_factor"))]
        factor: f64,
    },
    /// Johnson (1955) as printed in thesis eq. 2.17:
    /// $a_i = c\,(F_i R / E)^{1/3}$ with Young's modulus E. For identical steel bodies
    /// (nu = 0.3) Hertz gives c = (3(1-nu²)/2)^(1/3) = 1.1093; Johnson and the thesis'
    /// line-contact sheet use c = 1.11.
    Johnson {
        /// The coefficient c \[-\], finite and > 0.
        coefficient: f64,
    },
}

#[cfg(feature = "serde")]
fn unit_factor() -> f64 {
    1.0
}

impl Default for AsperityContactLaw {
    fn default() -> Self {
        AsperityContactLaw::Hertz { factor: 1.0 }
    }
}

/// Which surface speed turns the slide-to-roll ratio into slip per distance travelled.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
#[cfg_attr(
    feature = "serde",
    derive(serde::Serialize, serde::Deserialize, schemars::JsonSchema)
)]
#[cfg_attr(feature = "serde", serde(rename_all = "snake_case"))]
pub enum SlipReference {
    /// $\delta = \xi d$: the asperity junction travels at the rolling speed
    /// $V_r = (V_1+V_2)/2$ (Carter/Kalker's creepage; thesis Tables AP 0.3, 3.4 and 3.7).
    #[default]
    RollingSpeed,
    /// $\delta = d\,\Delta V / V_1 = d\,\xi/(1 + \xi/2)$: the junction travels with the
    /// faster surface (thesis Tables 3.3 and 3.5).
    FasterSurface,
}

/// How the nominal load is shared among the asperities.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
#[cfg_attr(
    feature = "serde",
    derive(serde::Serialize, serde::Deserialize, schemars::JsonSchema)
)]
#[cfg_attr(feature = "serde", serde(rename_all = "snake_case"))]
pub enum LoadSharing {
    /// Each asperity carries the integral of the nominal pressure over its lattice cell
    /// (closed form); the loads are then scaled so that they add up to F_N exactly (the
    /// scale, [`AsperityTraction::load_scale`], differs from 1 only by the slivers of
    /// cells whose tip lies outside the contact).
    #[default]
    Integral,
    /// The thesis' rectangle rule: pressure at the tip times the area of its cell inside
    /// the contact. The loads add up to F_N only approximately (thesis Table 3.5
    /// saturates at 0.98868).
    Midpoint,
    /// The thesis' circular rule (Table 3.6): pressure at the tip times p² for every
    /// asperity except the outermost of each lattice strip, which gets the strip's area
    /// under the arc minus the full cells; strips run across `x` in the octant |x| <= |y|
    /// and across `y` in |x| > |y| (the thesis computes one octant and mirrors it). Needs
    /// a square lattice. For a line contact it equals [`LoadSharing::Midpoint`].
    ThesisStrip,
}

/// All inputs of [`AsperityTraction`] \[mm, N, MPa\]. Two identical elastic bodies.
///
/// TOML keys carry units (`load_n`, `period_mm`, ...); the error of a bad value names the
/// Rust field.
///
/// # Example
/// ```toml
/// load_n = 680.0
/// friction_coefficient = 0.3
/// youngs_modulus_mpa = 210000.0
/// poisson_ratio = 0.3
/// shear_modulus_mpa = 73000.0        # optional, default E / (2 (1 + nu))
/// asperity_radii_mm = [0.02, 0.02]
/// period_mm = 0.05
/// # transverse_period_mm = 0.05      # optional, default period
/// # asperity_contact = { law = "johnson", coefficient = 1.11 }
/// # slip_reference = "faster_surface"
/// # load_sharing = "thesis_strip"
/// [nominal]
/// kind = "circular"
/// half_width_mm = 0.4
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(
    feature = "serde",
    derive(serde::Serialize, serde::Deserialize, schemars::JsonSchema)
)]
#[cfg_attr(feature = "serde", serde(deny_unknown_fields))]
pub struct AsperityTractionParams {
    /// The nominal contact and its size.
    pub nominal: NominalContact,
    /// Total normal force F_N \[N\], > 0.
    #[cfg_attr(feature = "serde", serde(rename = "load_n"))]
    pub load: Newton,
    /// Coulomb friction coefficient mu \[-\], > 0.
    pub friction_coefficient: f64,
    /// Young's modulus E of both bodies \[MPa\].
    #[cfg_attr(feature = "serde", serde(rename = "youngs_modulus_mpa"))]
    pub youngs_modulus: Megapascal,
    /// Poisson's ratio nu of both bodies \[-\], -1 < nu <= 0.5.
    pub poisson_ratio: f64,
    /// Shear modulus G ("modulus of rigidity" C in the thesis) \[MPa\], > 0; `None` for
    /// E / (2 (1 + nu)). The thesis gives it separately (79 300 and 73 000 MPa).
    #[cfg_attr(feature = "serde", serde(rename = "shear_modulus_mpa", default))]
    pub shear_modulus: Option<Megapascal>,
    /// Tip radii r1, r2 of the asperities of body 1 and body 2 \[mm\] (> 0; `inf` for a
    /// smooth counter-surface, not both). Their pair radius is 1/(1/r1 + 1/r2).
    #[cfg_attr(feature = "serde", serde(rename = "asperity_radii_mm"))]
    pub asperity_radii: [Millimetre; 2],
    /// Lattice period p along the rolling direction \[mm\], > 0 and small enough to put
    /// an asperity inside the contact.
    #[cfg_attr(feature = "serde", serde(rename = "period_mm"))]
    pub period: Millimetre,
    /// Lattice period p_t across the rolling direction \[mm\] (> 0, at most the length
    /// of a line contact); `None` for `period`.
    #[cfg_attr(feature = "serde", serde(rename = "transverse_period_mm", default))]
    pub transverse_period: Option<Millimetre>,
    /// Contact radius of an asperity pair (default Hertz).
    #[cfg_attr(feature = "serde", serde(default))]
    pub asperity_contact: AsperityContactLaw,
    /// Speed that converts the slide-to-roll ratio into slip (default rolling speed).
    #[cfg_attr(feature = "serde", serde(default))]
    pub slip_reference: SlipReference,
    /// Load sharing among the asperities (default exact cell integral).
    #[cfg_attr(feature = "serde", serde(default))]
    pub load_sharing: LoadSharing,
}

impl AsperityTractionParams {
    /// Parameters with the default options: G = E / (2 (1 + nu)), square lattice,
    /// Hertz asperity contacts, rolling-speed slip and integral load sharing.
    ///
    /// # Arguments
    /// - `nominal` — the nominal contact.
    /// - `load` — F_N \[N\].
    /// - `friction_coefficient` — mu \[-\].
    /// - `material` — both bodies' E \[MPa\] and nu.
    /// - `asperity_radii` — r1, r2 \[mm\].
    /// - `period` — p \[mm\].
    pub fn new(
        nominal: NominalContact,
        load: Newton,
        friction_coefficient: f64,
        material: ElasticMaterial,
        asperity_radii: [Millimetre; 2],
        period: Millimetre,
    ) -> Self {
        AsperityTractionParams {
            nominal,
            load,
            friction_coefficient,
            youngs_modulus: material.youngs_modulus(),
            poisson_ratio: material.poisson_ratio(),
            shear_modulus: None,
            asperity_radii,
            period,
            transverse_period: None,
            asperity_contact: AsperityContactLaw::default(),
            slip_reference: SlipReference::default(),
            load_sharing: LoadSharing::default(),
        }
    }
}

/// One asperity (pair) of the planned model: the per-asperity quantities of the thesis'
/// Annex B that do not depend on the slide-to-roll ratio.
///
/// Frame: `x` along the rolling direction, with material entering the contact at the
/// leading edge `x = +a` (line) or `x = +sqrt(a² - y²)` (circle) and leaving at the
/// trailing edge, as in [`crate`]'s tangential conventions; `y` across. The thesis
/// measures its position the other way round (`x_thesis = -x`).
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct AsperityState {
    /// Tip position along the rolling direction \[mm\].
    pub x: Millimetre,
    /// Tip position across the rolling direction \[mm\] (0 for a line contact, whose
    /// rows are all alike).
    pub y: Millimetre,
    /// Number of identical asperities this entry stands for \[-\]: L / p_t rows for a
    /// line contact (may be fractional), 1 for a circular one.
    pub count: f64,
    /// Area of the asperity's cell used for its load \[mm²\].
    pub cell_area: f64,
    /// Nominal pressure at the tip \[MPa\].
    pub pressure: Megapascal,
    /// Normal force F_i on the asperity \[N\].
    pub normal_force: Newton,
    /// Contact radius a_i of the asperity pair \[mm\].
    pub contact_radius: Millimetre,
    /// Distance d_i from the leading edge to the tip along the rolling direction \[mm\].
    pub entry_distance: Millimetre,
    /// Mindlin's gross-slip displacement delta*_i = 3 (2 - nu) mu F_i / (8 G a_i) \[mm\].
    pub saturation_displacement: Millimetre,
    /// Effective slip ratio delta*_i / d_i at which the asperity fully slides \[-\]
    /// (the slide-to-roll ratio itself with [`SlipReference::RollingSpeed`]).
    pub saturation_slip: f64,
}

/// The tangential state of one asperity at one slide-to-roll ratio (thesis Table 3.3).
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct AsperityForce {
    /// Tangential displacement delta_i = xi_eff d_i between the asperities \[mm\].
    pub displacement: Millimetre,
    /// Slip parameter B_i = delta_i / delta*_i \[-\], not clamped (the thesis' "IF B < 1"
    /// column); the force uses min(B, 1).
    pub slip_parameter: f64,
    /// Y = (1 - min(B, 1))^(3/2) \[-\].
    pub stick_factor: f64,
    /// Tangential force F_T,i = mu F_i (1 - Y) of one asperity \[N\].
    pub tangential_force: Newton,
    /// Whether the asperity slides (B >= 1).
    pub sliding: bool,
}

/// A planned asperity traction model: the per-asperity loads, radii and gross-slip
/// ratios are computed once in [`new`](Self::new); a curve point is then one pass over
/// the asperities (about 5 ns per asperity, see `docs/traction-asperity.md`).
///
/// # Example
/// The thesis' rough line contact (Annex A, Figure AP 0-6): 400 N on a 10 mm roller,
/// half-width 0.2334 mm, asperities r = 0.02 mm every 0.05 mm, G = 79 300 MPa, mu = 0.3,
/// with the thesis' own choices (eq. 2.17, faster-surface slip, rectangle rule):
/// ```
/// use kontakt::traction::{AsperityTraction, AsperityTractionParams, AsperityContactLaw,
///     LoadSharing, NominalContact, SlipReference};
/// use kontakt::material::ElasticMaterial;
/// let nominal = NominalContact::Line { length: 10.0, half_width: 0.233_354_393, max_pressure: None };
/// let mut params = AsperityTractionParams::new(
///     nominal, 400.0, 0.3, ElasticMaterial::STEEL, [0.02, 0.02], 0.05);
/// params.shear_modulus = Some(79_300.0);
/// params.asperity_contact = AsperityContactLaw::Johnson { coefficient: 1.11 };
/// params.slip_reference = SlipReference::FasterSurface;
/// params.load_sharing = LoadSharing::Midpoint;
/// let model = AsperityTraction::new(params)?;
/// // Table 3.5: 0.020002 % -> 0.292820957
/// assert!((model.traction_ratio(0.020002e-2)? - 0.292_820_957).abs() < 1e-8);
/// assert_eq!(model.asperities().len(), 10); // one row of 10, standing for 200 rows
/// # Ok::<(), kontakt::Error>(())
/// ```
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct AsperityTraction {
    params: AsperityTractionParams,
    shape: ContactShape,
    half_width: Millimetre,
    max_pressure: Megapascal,
    length: Option<Millimetre>,
    shear_modulus: Megapascal,
    load_scale: f64,
    asperities: Vec<AsperityState>,
    /// d_i / delta*_i: B_i = xi_eff * slip_gain[i].
    #[cfg_attr(feature = "serde", serde(skip))]
    slip_gain: Vec<f64>,
    /// n_i F_i / F_N: the saturated share of each entry.
    #[cfg_attr(feature = "serde", serde(skip))]
    weight: Vec<f64>,
}

/// The resolved nominal contact.
struct Nominal {
    shape: ContactShape,
    half_width: f64,
    max_pressure: f64,
    length: Option<f64>,
}

impl AsperityTraction {
    /// Validate the parameters, lay out the lattice and precompute every asperity.
    ///
    /// # Errors
    /// [`Error::InvalidInput`] naming the field: `load`, `friction_coefficient`,
    /// `youngs_modulus`, `poisson_ratio`, `shear_modulus`, `asperity_radii`, `period`
    /// (also when no asperity fits inside the contact, or more than [`MAX_ASPERITIES`]
    /// would), `transverse_period` (longer than a line contact, or differing from
    /// `period` with [`LoadSharing::ThesisStrip`] on a circle), `asperity_contact`,
    /// `nominal.length`, `nominal.half_width`, `nominal.max_pressure` (inconsistent with
    /// the load); errors of [`LineContact`] / [`PointGeometry`] prefixed with `nominal.`;
    /// [`Error::Geometry`] for an elliptical Hertz contact.
    pub fn new(params: AsperityTractionParams) -> Result<Self> {
        let p = &params;
        positive_as("load", p.load, "a finite normal force > 0 N")?;
        positive_as(
            "friction_coefficient",
            p.friction_coefficient,
            "a finite friction coefficient mu > 0",
        )?;
        let material = ElasticMaterial::new(p.youngs_modulus, p.poisson_ratio)?;
        let shear_modulus = match p.shear_modulus {
            Some(g) => positive_as("shear_modulus", g, "a finite modulus > 0 MPa")?,
            None => material.shear_modulus(),
        };
        let period = positive_as("period", p.period, "a finite period > 0 mm")?;
        let transverse = match p.transverse_period {
            Some(t) => positive_as("transverse_period", t, "a finite period > 0 mm")?,
            None => period,
        };
        let radius_law = asperity_radius_law(p, material)?;
        let nominal = resolve_nominal(p, material)?;
        let mu = p.friction_coefficient;
        let nu = p.poisson_ratio;

        let cells = match nominal.shape {
            ContactShape::Line => line_cells(&nominal, p, period, transverse)?,
            ContactShape::Circular => circular_cells(&nominal, p, period, transverse)?,
        };
        let captured: f64 = cells.iter().map(|c| c.count * c.force).sum();
        let load_scale = match p.load_sharing {
            LoadSharing::Integral => p.load / captured,
            LoadSharing::Midpoint | LoadSharing::ThesisStrip => 1.0,
        };
        if !(load_scale.is_finite() && load_scale > 0.0) {
            return Err(no_asperity(period));
        }

        let mut asperities = Vec::with_capacity(cells.len());
        for c in cells {
            let normal_force = c.force * load_scale;
            let contact_radius = radius_law.radius(normal_force);
            let saturation_displacement =
                3.0 * (2.0 - nu) * mu * normal_force / (8.0 * shear_modulus * contact_radius);
            let saturation_slip = saturation_displacement / c.entry_distance;
            if !(saturation_slip.is_finite() && saturation_slip > 0.0) {
                return Err(crate::error::overflow("load", p.load));
            }
            asperities.push(AsperityState {
                x: c.x,
                y: c.y,
                count: c.count,
                cell_area: c.area,
                pressure: c.pressure,
                normal_force,
                contact_radius,
                entry_distance: c.entry_distance,
                saturation_displacement,
                saturation_slip,
            });
        }
        let mut model = AsperityTraction {
            params,
            shape: nominal.shape,
            half_width: nominal.half_width,
            max_pressure: nominal.max_pressure,
            length: nominal.length,
            shear_modulus,
            load_scale,
            asperities,
            slip_gain: Vec::new(),
            weight: Vec::new(),
        };
        model.rebuild();
        Ok(model)
    }

    fn rebuild(&mut self) {
        let load = self.params.load;
        self.slip_gain = self
            .asperities
            .iter()
            .map(|a| 1.0 / a.saturation_slip)
            .collect();
        self.weight = self
            .asperities
            .iter()
            .map(|a| a.count * a.normal_force / load)
            .collect();
    }

    /// The parameters the model was planned with.
    pub fn params(&self) -> &AsperityTractionParams {
        &self.params
    }
    /// Line or circular.
    pub fn shape(&self) -> ContactShape {
        self.shape
    }
    /// Half-width (line) or radius (circle) a of the nominal contact \[mm\].
    pub fn half_width(&self) -> Millimetre {
        self.half_width
    }
    /// Maximum nominal pressure p0 \[MPa\], consistent with the load.
    pub fn max_pressure(&self) -> Megapascal {
        self.max_pressure
    }
    /// Contact length L of a line contact \[mm\].
    pub fn length(&self) -> Option<Millimetre> {
        self.length
    }
    /// Shear modulus G used in Mindlin's law \[MPa\].
    pub fn shear_modulus(&self) -> Megapascal {
        self.shear_modulus
    }
    /// The factor applied to the cell integrals so that the loads add up to F_N
    /// ([`LoadSharing::Integral`]); 1 for the thesis rules.
    pub fn load_scale(&self) -> f64 {
        self.load_scale
    }
    /// The asperities, ordered by row (`y` ascending), then from the leading edge
    /// (entry distance ascending).
    pub fn asperities(&self) -> &[AsperityState] {
        &self.asperities
    }
    /// Number of asperities represented, sum of the counts \[-\].
    pub fn asperity_total(&self) -> f64 {
        self.asperities.iter().map(|a| a.count).sum()
    }
    /// Normal force carried by the asperities, sum of count × F_i \[N\]: F_N with
    /// [`LoadSharing::Integral`], close to it with the thesis rules. The traction ratio
    /// saturates at this over F_N.
    pub fn carried_load(&self) -> Newton {
        self.asperities
            .iter()
            .map(|a| a.count * a.normal_force)
            .sum()
    }

    /// Remove the asperities for which `keep` returns false (worn or missing asperities;
    /// the thesis' circular sheet omits two, see `docs/traction-asperity.md`). F_N stays
    /// the normalising load.
    pub fn retain_asperities(&mut self, mut keep: impl FnMut(&AsperityState) -> bool) {
        self.asperities.retain(|a| keep(a));
        self.rebuild();
    }

    /// The effective slip ratio xi_eff \[-\] for a slide-to-roll ratio `slide_to_roll`:
    /// xi itself, or xi / (1 + xi/2) for [`SlipReference::FasterSurface`].
    ///
    /// # Errors
    /// `slide_to_roll` negative or not finite.
    pub fn effective_slip(&self, slide_to_roll: f64) -> Result<f64> {
        check_srr("slide_to_roll", slide_to_roll)?;
        Ok(self.effective_unchecked(slide_to_roll))
    }

    fn effective_unchecked(&self, xi: f64) -> f64 {
        match self.params.slip_reference {
            SlipReference::RollingSpeed => xi,
            SlipReference::FasterSurface => xi / (1.0 + 0.5 * xi),
        }
    }

    fn ratio_unchecked(&self, xi: f64) -> f64 {
        let s = self.effective_unchecked(xi);
        let mut sum = 0.0;
        for (&g, &w) in self.slip_gain.iter().zip(&self.weight) {
            let r = 1.0 - (s * g).min(1.0);
            sum += w * (1.0 - r * r.sqrt());
        }
        sum
    }

    /// The traction ratio F_T / (mu F_N) \[-\] at the slide-to-roll ratio
    /// `slide_to_roll` = ΔV / V_r \[-\] (a fraction, not percent), >= 0.
    ///
    /// # Errors
    /// [`Error::InvalidInput`] naming `slide_to_roll` if it is negative or not finite.
    pub fn traction_ratio(&self, slide_to_roll: f64) -> Result<f64> {
        check_srr("slide_to_roll", slide_to_roll)?;
        Ok(self.ratio_unchecked(slide_to_roll))
    }

    /// The total tangential force F_T = sum of count × F_T,i \[N\] at `slide_to_roll`.
    ///
    /// # Errors
    /// As [`traction_ratio`](Self::traction_ratio).
    pub fn tangential_force(&self, slide_to_roll: f64) -> Result<Newton> {
        Ok(self.traction_ratio(slide_to_roll)?
            * self.params.friction_coefficient
            * self.params.load)
    }

    /// The traction curve F_T / (mu F_N) at every slide-to-roll ratio of `slide_to_roll`.
    ///
    /// # Errors
    /// [`Error::InvalidInput`] naming `slide_to_roll[i]` for the first bad entry.
    pub fn curve(&self, slide_to_roll: &[f64]) -> Result<Vec<f64>> {
        for (i, &xi) in slide_to_roll.iter().enumerate() {
            if !(xi.is_finite() && xi >= 0.0) {
                return Err(Error::invalid(
                    format!("slide_to_roll[{i}]"),
                    xi,
                    "a finite slide-to-roll ratio >= 0",
                ));
            }
        }
        Ok(slide_to_roll
            .iter()
            .map(|&xi| self.ratio_unchecked(xi))
            .collect())
    }

    /// Every asperity's tangential state at `slide_to_roll` (thesis Table 3.3), in the
    /// order of [`asperities`](Self::asperities).
    ///
    /// # Errors
    /// As [`traction_ratio`](Self::traction_ratio).
    pub fn asperity_forces(&self, slide_to_roll: f64) -> Result<Vec<AsperityForce>> {
        let s = self.effective_slip(slide_to_roll)?;
        let mu = self.params.friction_coefficient;
        Ok(self
            .asperities
            .iter()
            .map(|a| {
                let displacement = s * a.entry_distance;
                let slip_parameter = displacement / a.saturation_displacement;
                let r = 1.0 - slip_parameter.min(1.0);
                let stick_factor = r * r.sqrt();
                AsperityForce {
                    displacement,
                    slip_parameter,
                    stick_factor,
                    tangential_force: mu * a.normal_force * (1.0 - stick_factor),
                    sliding: slip_parameter >= 1.0,
                }
            })
            .collect())
    }

    /// Slope of the curve at xi = 0, d(F_T / (mu F_N))/d xi \[-\]:
    /// $\tfrac32 \sum_i n_i F_i d_i / (F_N \delta^*_i) = \sum_i n_i k_i d_i / (\mu F_N)$
    /// with Mindlin's initial tangential stiffness $k_i = 4 G a_i / (2-\nu)$.
    pub fn initial_slope(&self) -> f64 {
        self.slip_gain
            .iter()
            .zip(&self.weight)
            .map(|(g, w)| 1.5 * g * w)
            .sum()
    }

    /// The smallest slide-to-roll ratio at which every asperity slides, beyond which the
    /// curve is flat at [`carried_load`](Self::carried_load) / F_N; `None` if some
    /// asperity never fully slides (possible with [`SlipReference::FasterSurface`],
    /// whose xi_eff stays below 2) or there are no asperities.
    pub fn full_sliding_slide_to_roll(&self) -> Option<f64> {
        let s = self
            .asperities
            .iter()
            .map(|a| a.saturation_slip)
            .fold(None, |m: Option<f64>, v| Some(m.map_or(v, |m| m.max(v))))?;
        match self.params.slip_reference {
            SlipReference::RollingSpeed => Some(s),
            SlipReference::FasterSurface => (s < 2.0).then(|| s / (1.0 - 0.5 * s)),
        }
    }
}

fn check_srr(field: &'static str, xi: f64) -> Result<f64> {
    if xi.is_finite() && xi >= 0.0 {
        Ok(xi)
    } else {
        Err(Error::invalid(
            field,
            xi,
            "a finite slide-to-roll ratio >= 0 (a fraction, not percent)",
        ))
    }
}

fn no_asperity(period: f64) -> Error {
    Error::invalid(
        "period",
        period,
        "a period small enough to put at least one loaded asperity inside the contact \
         (p < 2a for a line, (p/2)² + (p_t/2)² < a² for a circle)",
    )
}

/// a_i = unit * F^(1/3).
struct RadiusLaw {
    unit: f64,
}

impl RadiusLaw {
    fn radius(&self, force: f64) -> f64 {
        self.unit * force.cbrt()
    }
}

fn asperity_radius_law(p: &AsperityTractionParams, material: ElasticMaterial) -> Result<RadiusLaw> {
    let [r1, r2] = p.asperity_radii;
    let geometry = PointGeometry::new([r1, r1], [r2, r2], 0.0)
        .map_err(|e| e.map_field(|_| "asperity_radii".to_string()))?;
    for r in [r1, r2] {
        if !(r > 0.0) {
            return Err(Error::invalid(
                "asperity_radii",
                r,
                "tip radii > 0 mm (inf for a smooth counter-surface, not both)",
            ));
        }
    }
    let unit = match p.asperity_contact {
        AsperityContactLaw::Hertz { factor } => {
            positive_as("asperity_contact.factor", factor, "a finite factor > 0")?;
            let hertz = HertzPointContact::new(geometry, material, material)?;
            factor * hertz.solve_force(1.0)?.semi_axes[0]
        }
        AsperityContactLaw::Johnson { coefficient } => {
            positive_as(
                "asperity_contact.coefficient",
                coefficient,
                "a finite coefficient > 0 (1.11 in the thesis)",
            )?;
            let pair_radius = 1.0 / (1.0 / r1 + 1.0 / r2);
            coefficient * (pair_radius / material.youngs_modulus()).cbrt()
        }
    };
    if !(unit.is_finite() && unit > 0.0) {
        return Err(crate::error::overflow("asperity_radii", r1));
    }
    Ok(RadiusLaw { unit })
}

fn nominal_field(e: Error) -> Error {
    e.map_field(|f| format!("nominal.{f}"))
}

fn check_max_pressure(given: Option<f64>, consistent: f64, formula: &str) -> Result<()> {
    let Some(p0) = given else { return Ok(()) };
    if p0.is_finite() && ((p0 - consistent) / consistent).abs() <= MAX_PRESSURE_TOLERANCE {
        Ok(())
    } else {
        Err(Error::invalid(
            "nominal.max_pressure",
            p0,
            format!(
                "{formula} = {consistent:.6} MPa (consistent with the load, relative tolerance \
                 {MAX_PRESSURE_TOLERANCE:e}), or leave it out"
            ),
        ))
    }
}

fn resolve_nominal(p: &AsperityTractionParams, material: ElasticMaterial) -> Result<Nominal> {
    let load = p.load;
    match p.nominal {
        NominalContact::Line {
            length,
            half_width,
            max_pressure,
        } => {
            positive_as("nominal.length", length, "a finite length > 0 mm")?;
            positive_as(
                "nominal.half_width",
                half_width,
                "a finite half-width > 0 mm",
            )?;
            let p0 = 2.0 * load / (PI * half_width * length);
            check_max_pressure(max_pressure, p0, "2 F_N / (pi a L)")?;
            finite_p0(p0, load)?;
            Ok(Nominal {
                shape: ContactShape::Line,
                half_width,
                max_pressure: p0,
                length: Some(length),
            })
        }
        NominalContact::HertzLine { length, radii } => {
            positive_as("nominal.length", length, "a finite length > 0 mm")?;
            let contact =
                LineContact::new(radii[0], radii[1], material, material).map_err(nominal_field)?;
            let sol = contact.solve(load / length).map_err(nominal_field)?;
            Ok(Nominal {
                shape: ContactShape::Line,
                half_width: sol.half_width,
                max_pressure: sol.max_pressure,
                length: Some(length),
            })
        }
        NominalContact::Circular {
            half_width,
            max_pressure,
        } => {
            positive_as("nominal.half_width", half_width, "a finite radius > 0 mm")?;
            let p0 = 3.0 * load / (2.0 * PI * half_width * half_width);
            check_max_pressure(max_pressure, p0, "3 F_N / (2 pi a²)")?;
            finite_p0(p0, load)?;
            Ok(Nominal {
                shape: ContactShape::Circular,
                half_width,
                max_pressure: p0,
                length: None,
            })
        }
        NominalContact::HertzCircular {
            body1_radii,
            body2_radii,
            angle,
        } => {
            let geometry =
                PointGeometry::new(body1_radii, body2_radii, angle).map_err(nominal_field)?;
            let contact =
                HertzPointContact::new(geometry, material, material).map_err(nominal_field)?;
            if contact.axis_ratio() < 1.0 - CIRCULARITY_TOLERANCE {
                return Err(Error::Geometry {
                    field: "nominal".into(),
                    reason: format!(
                        "the Hertz contact is elliptical (b/a = {:.6}); the asperity model needs \
                         a circle: two spheres, or crossed cylinders of equal radii",
                        contact.axis_ratio()
                    ),
                });
            }
            let sol = contact.solve_force(load).map_err(nominal_field)?;
            let a = (sol.semi_axes[0] * sol.semi_axes[1]).sqrt();
            Ok(Nominal {
                shape: ContactShape::Circular,
                half_width: a,
                max_pressure: 3.0 * load / (2.0 * PI * a * a),
                length: None,
            })
        }
    }
}

fn finite_p0(p0: f64, load: f64) -> Result<()> {
    if p0.is_finite() && p0 > 0.0 {
        Ok(())
    } else {
        Err(crate::error::overflow("load", load))
    }
}

/// One asperity before the radius law: position, cell, load.
struct Cell {
    x: f64,
    y: f64,
    count: f64,
    area: f64,
    pressure: f64,
    force: f64,
    entry_distance: f64,
}

fn too_many(period: f64, n: f64) -> Error {
    Error::invalid(
        "period",
        period,
        format!("a coarser lattice: it would hold {n:.3e} asperities, more than {MAX_ASPERITIES}"),
    )
}

fn line_cells(
    nominal: &Nominal,
    params: &AsperityTractionParams,
    period: f64,
    transverse: f64,
) -> Result<Vec<Cell>> {
    let a = nominal.half_width;
    let p0 = nominal.max_pressure;
    let length = nominal.length.unwrap_or(f64::NAN);
    if !(transverse <= length) {
        let field = if params.transverse_period.is_some() {
            "transverse_period"
        } else {
            "period"
        };
        return Err(Error::invalid(
            field,
            transverse,
            format!("a period <= the contact length {length} mm (at least one row of asperities)"),
        ));
    }
    let half = a / period;
    if half + 1.0 > MAX_ASPERITIES as f64 / 2.0 {
        return Err(too_many(period, 2.0 * half));
    }
    let n = half.ceil() as i64;
    let count = length / transverse;
    let mut cells = Vec::new();
    // Leading edge first: x from +a down to -a.
    for i in (-n..n).rev() {
        let x = (i as f64 + 0.5) * period;
        if !(x.abs() < a) {
            continue;
        }
        let lo = (x - 0.5 * period).max(-a);
        let hi = (x + 0.5 * period).min(a);
        let width = hi - lo;
        let pressure = p0 * (1.0 - (x / a) * (x / a)).max(0.0).sqrt();
        let force = match params.load_sharing {
            LoadSharing::Integral => transverse * p0 / a * (arc_area(a, hi) - arc_area(a, lo)),
            LoadSharing::Midpoint | LoadSharing::ThesisStrip => pressure * width * transverse,
        };
        if force > 0.0 {
            cells.push(Cell {
                x,
                y: 0.0,
                count,
                area: width * transverse,
                pressure,
                force,
                entry_distance: a - x,
            });
        }
    }
    if cells.is_empty() {
        return Err(no_asperity(period));
    }
    Ok(cells)
}

/// Index of a lattice line in the first quadrant: i >= 0 -> i, i < 0 -> -i-1.
fn folded(i: i64) -> i64 {
    if i >= 0 { i } else { -i - 1 }
}

fn circular_cells(
    nominal: &Nominal,
    params: &AsperityTractionParams,
    period: f64,
    transverse: f64,
) -> Result<Vec<Cell>> {
    let a = nominal.half_width;
    let p0 = nominal.max_pressure;
    let thesis = params.load_sharing == LoadSharing::ThesisStrip;
    if thesis && transverse != period {
        return Err(Error::invalid(
            "transverse_period",
            transverse,
            format!("the period {period} mm: the thesis' strip rule needs a square lattice"),
        ));
    }
    let estimate = PI * (a / period + 1.0) * (a / transverse + 1.0);
    if estimate > MAX_ASPERITIES as f64 {
        return Err(too_many(period, estimate));
    }
    let nx = (a / period).ceil() as i64;
    let ny = (a / transverse).ceil() as i64;
    let inside = |i: i64, j: i64| {
        let x = (i as f64 + 0.5) * period;
        let y = (j as f64 + 0.5) * transverse;
        x * x + y * y < a * a
    };
    // Thesis rule: number of tips in the first-quadrant half strip of folded index k.
    let strip_count = |k: i64| (0..nx.max(ny) + 1).filter(|&m| inside(k, m)).count() as i64;
    let strip_area = |k: i64| {
        let lo = k as f64 * period;
        arc_area(a, lo + period) - arc_area(a, lo)
    };
    let mut cells = Vec::new();
    for j in -ny..ny {
        let y = (j as f64 + 0.5) * transverse;
        for i in (-nx..nx).rev() {
            if !inside(i, j) {
                continue;
            }
            let x = (i as f64 + 0.5) * period;
            let (fi, fj) = (folded(i), folded(j));
            let x0 = fi as f64 * period;
            let y0 = fj as f64 * transverse;
            let (exact_area, volume) = disk_cell(a, x0, x0 + period, y0, y0 + transverse);
            let pressure = p0 * (1.0 - (x * x + y * y) / (a * a)).max(0.0).sqrt();
            let (area, force) = match params.load_sharing {
                LoadSharing::Integral => (exact_area, p0 / a * volume),
                LoadSharing::Midpoint => (exact_area, pressure * exact_area),
                LoadSharing::ThesisStrip => {
                    // Strip across the larger folded coordinate's direction: |x| <= |y|
                    // -> the strip at x (index fi) running along y, and vice versa.
                    let (strip, along) = if fi <= fj { (fi, fj) } else { (fj, fi) };
                    let n = strip_count(strip);
                    let area = if along == n - 1 {
                        (strip_area(strip) - (n - 1) as f64 * period * period).max(0.0)
                    } else {
                        period * period
                    };
                    (area, pressure * area)
                }
            };
            if force > 0.0 {
                cells.push(Cell {
                    x,
                    y,
                    count: 1.0,
                    area,
                    pressure,
                    force,
                    entry_distance: (a * a - y * y).max(0.0).sqrt() - x,
                });
            }
        }
    }
    if cells.is_empty() {
        return Err(no_asperity(period));
    }
    Ok(cells)
}
