//! Traction-curve cases (`method = "traction"`, `schema_version = 1`) and their report:
//! the normalized tangential force `F_T/(mu F_N)` against the longitudinal creepage (the
//! slide-to-roll ratio) for several models of [`kontakt::tangential`].
//!
//! ```toml
//! name = "twin-disc, crowned disc on cylindrical disc"
//! method = "traction"
//! models = ["carter", "kalker_linear", "fastsim"]   # default: these three; also
//!                                                   # "kalker_exact", "asperity"
//!
//! [geometry]
//! kind = "hertz"             # principal radii -> Hertz ellipse; rolling along body 1's
//! radii1_mm = [20.0, 50.0]   # first principal direction (the first radius)
//! radii2_mm = [20.0, inf]
//! angle_deg = 0.0
//! # kind = "ellipse": semi_axes_mm = [a, b], a along the rolling direction
//! # kind = "line": radii_mm = [R1, R2] or half_width_mm = a, and length_mm = L
//! #   (parallel cylinders, or a strip of given half-width under the Hertz pressure;
//! #   carter and asperity only)
//!
//! [body1]
//! e_mpa = 210000.0
//! nu = 0.3
//! [body2]
//! e_mpa = 210000.0
//! nu = 0.3
//!
//! [load]
//! force_n = 1000.0           # or, for kind = "line", line_load_n_per_mm [N/mm]
//!
//! [friction]
//! mu = 0.1
//!
//! [creepage]                 # slide-to-roll ratios, evenly spaced
//! max = 0.006
//! points = 121               # optional, default 101
//! # min = 0.0                # optional, default 0
//! # lateral = 0.0            # optional: a constant lateral creepage [-] at every point
//! # spin_per_mm = 0.0        # optional: a constant spin creepage [1/mm] at every point
//! #                          # (both: kalker_linear, fastsim, kalker_exact)
//!
//! [fastsim]                  # optional
//! elements = [50, 50]
//! pressure = "parabolic"     # or "elliptic"
//!
//! [kalker_exact]             # optional: Kalker's exact theory on the half-space grid
//! elements = [32, 32]        # cells across the ellipse (along rolling, across), 8..=1024
//! max_iterations = 100       # Newton iterations per point before it counts as not converged
//! coupling = false           # true: dissimilar bodies, normal and tangential problems coupled
//!                            # through Kalker's K (and the free-rolling creepage)
//!
//! # [asperity]               # for models = [..., "asperity"]: circular or line contacts
//! # asperity_radii_mm = [0.02, 0.02]     # of identical bodies (kontakt::traction)
//! # period_mm = 0.05
//! ```
//!
//! The schema is documented in `docs/case-schema.md`; [`run_traction_case`] turns a case
//! into a [`TractionReport`]. Kalker's linear curve is reported *unclipped* (it is the
//! linear theory; it exceeds 1 beyond its saturation creepage); `kontakt traction --plot`
//! draws it up to where it reaches 1.
//!
//! `kalker_exact` ([`kontakt::rolling::KalkerExact`]) solves Kalker's exact steady-rolling
//! problem at every point of the curve (warm-started along it) and reports each point's
//! solver status, the stick fraction and the grid in the curve's `exact` record; a point
//! that did not converge is named in the report's `warnings`. It costs a steady solve per
//! point (about 1-10 ms at the default 32 × 32 cells, growing steeply with `elements`), where the
//! other models cost microseconds.
//!
//! Every model assumes quasi-identical bodies (Kalker's difference parameter `K = 0`)
//! except `kalker_exact` with `[kalker_exact] coupling = true`, which couples the normal
//! problem of the Hertz gap with steady rolling through `K` at every point and reports the
//! free-rolling creepage. The report gives `K` (`difference_parameter`) and warns, naming
//! its value and the models, when the materials differ and `K` is neglected.

use crate::common::{MaterialSpec, SCHEMA_VERSION, material, parse_toml};
use crate::validity::{ContactSize, Size, checked, checked_report};
use kontakt::hertz::line::LineContact;
use kontakt::hertz::validity::{line_size, point_size};
use kontakt::hertz::{HertzPointContact, PointGeometry};
use kontakt::material::effective_modulus;
use kontakt::rolling::{KalkerExact, KalkerExactOptions, difference_parameter};
use kontakt::solve::SolveStatus;
use kontakt::tangential::{
    Carter, ContactEllipse, CreepCoefficients, Fastsim, FastsimOptions, KalkerLinear,
    KalkerMaterial, PressureShape, TractionCurve,
};
use kontakt::traction::{
    AsperityContactLaw, AsperityCurve, AsperityTraction, AsperityTractionParams, LoadSharing,
    NominalContact, SlipReference, nominal_of_ellipse, rolling_axis,
};
use kontakt::{Error, Result};
use serde::{Deserialize, Serialize};

/// A traction-curve case, as read from TOML.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize, schemars::JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct TractionCase {
    /// Optional label echoed in the report.
    #[serde(default)]
    pub name: Option<String>,
    /// Must be `"traction"`.
    pub method: String,
    /// Models to evaluate, in this order (default: carter, kalker_linear, fastsim).
    #[serde(default = "default_models")]
    pub models: Vec<TractionModel>,
    /// The contact geometry.
    pub geometry: TractionGeometry,
    /// Body 1 material.
    pub body1: MaterialSpec,
    /// Body 2 material.
    pub body2: MaterialSpec,
    /// The normal load.
    pub load: TractionLoad,
    /// Friction.
    pub friction: FrictionSpec,
    /// The creepage range.
    pub creepage: CreepageRange,
    /// FASTSIM options.
    #[serde(default)]
    pub fastsim: FastsimSpec,
    /// Options of the `kalker_exact` model.
    #[serde(default)]
    pub kalker_exact: KalkerExactSpec,
    /// The asperity lattice, needed by the `asperity` model.
    #[serde(default)]
    pub asperity: Option<AsperitySpec>,
}

/// `[asperity]`: the rough-surface model of [`kontakt::traction`] on the case's nominal
/// contact (circular or line), with the case's load, friction and (identical) materials.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize, schemars::JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct AsperitySpec {
    /// Tip radii of the asperities of body 1 and body 2 \[mm\].
    pub asperity_radii_mm: [f64; 2],
    /// Lattice period along the rolling direction \[mm\].
    pub period_mm: f64,
    /// Lattice period across it \[mm\]; default `period_mm`.
    #[serde(default)]
    pub transverse_period_mm: Option<f64>,
    /// Shear modulus \[MPa\]; default E / (2 (1 + nu)).
    #[serde(default)]
    pub shear_modulus_mpa: Option<f64>,
    /// Contact radius law of an asperity pair (default Hertz).
    #[serde(default)]
    pub asperity_contact: AsperityContactLaw,
    /// Speed that turns the slide-to-roll ratio into slip (default rolling speed).
    #[serde(default)]
    pub slip_reference: SlipReference,
    /// Load sharing among the asperities (default exact cell integral).
    #[serde(default)]
    pub load_sharing: LoadSharing,
}

fn default_models() -> Vec<TractionModel> {
    vec![
        TractionModel::Carter,
        TractionModel::KalkerLinear,
        TractionModel::Fastsim,
    ]
}

/// A model of a traction curve.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize, schemars::JsonSchema)]
#[serde(rename_all = "snake_case")]
pub enum TractionModel {
    /// Carter's 2D curve ([`Carter`]); for a point contact, of the central strip.
    Carter,
    /// Kalker's linear theory ([`KalkerLinear`]), unclipped.
    KalkerLinear,
    /// Kalker's FASTSIM ([`Fastsim`]).
    Fastsim,
    /// The asperity micro-slip model ([`AsperityTraction`]) of a rough circular or line
    /// contact; needs `[asperity]`.
    Asperity,
    /// Kalker's exact theory of steady rolling on the half-space grid
    /// ([`KalkerExact`]), with a solver status per point.
    KalkerExact,
}

impl TractionModel {
    /// Every model, in the order the documentation lists them (the help of
    /// `kontakt traction` is built from it).
    pub const ALL: [TractionModel; 5] = [
        TractionModel::Carter,
        TractionModel::KalkerLinear,
        TractionModel::Fastsim,
        TractionModel::KalkerExact,
        TractionModel::Asperity,
    ];

    /// The model's name as in the case file and the report.
    pub fn as_str(self) -> &'static str {
        match self {
            TractionModel::Carter => "carter",
            TractionModel::KalkerLinear => "kalker_linear",
            TractionModel::Fastsim => "fastsim",
            TractionModel::Asperity => "asperity",
            TractionModel::KalkerExact => "kalker_exact",
        }
    }
}

/// `[geometry]`.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize, schemars::JsonSchema)]
#[serde(tag = "kind", rename_all = "snake_case", deny_unknown_fields)]
pub enum TractionGeometry {
    /// Two bodies by their principal radii: the Hertz ellipse of [`kontakt::hertz`]. The
    /// rolling direction is body 1's first principal direction; it must lie along an axis
    /// of the contact ellipse.
    Hertz {
        /// Body 1 principal radii \[mm\] (convex > 0, concave < 0, inf flat).
        radii1_mm: [f64; 2],
        /// Body 2 principal radii \[mm\].
        radii2_mm: [f64; 2],
        /// Angle between the principal planes \[deg\].
        #[serde(default)]
        angle_deg: f64,
    },
    /// A given contact ellipse with the Hertz pressure of the normal force.
    Ellipse {
        /// Semi-axes `[a, b]` \[mm\]: `a` along the rolling direction, `b` across.
        semi_axes_mm: [f64; 2],
    },
    /// Two parallel cylinders rolling about their axes (Carter's case), given by their
    /// radii or by the half-width of their contact strip (exactly one).
    Line {
        /// Radii `[R1, R2]` \[mm\] (convex > 0, concave < 0, inf flat).
        #[serde(default)]
        radii_mm: Option<[f64; 2]>,
        /// Half-width `a` \[mm\] of the strip, carrying the Hertz pressure
        /// `p0 = 2 P'/(pi a)` of the line load `P'`.
        #[serde(default)]
        half_width_mm: Option<f64>,
        /// Contact length \[mm\]: the line load is `force_n / length_mm`.
        length_mm: f64,
    },
}

/// `[load]`.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize, schemars::JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct TractionLoad {
    /// Normal force \[N\], > 0 (exactly one of `force_n` and `line_load_n_per_mm`).
    #[serde(default)]
    pub force_n: Option<f64>,
    /// Line load \[N/mm\], > 0, for `kind = "line"`: the force is this times `length_mm`.
    #[serde(default)]
    pub line_load_n_per_mm: Option<f64>,
}

impl TractionLoad {
    /// The normal force \[N\] and the key that gave it, for a contact of length `length`
    /// \[mm\] (line contacts).
    ///
    /// # Errors
    /// [`Error::InvalidInput`] naming `load` (none or both given),
    /// `load.line_load_n_per_mm` (a point contact, or not a finite value > 0) or
    /// `load.force_n` (not a finite value > 0).
    pub fn force(&self, length: Option<f64>) -> Result<(f64, &'static str)> {
        match (self.force_n, self.line_load_n_per_mm, length) {
            (Some(f), None, _) => Ok((
                kontakt::error::positive_as("load.force_n", f, "a finite force > 0 N")?,
                "load.force_n",
            )),
            (None, Some(q), Some(l)) => {
                let q = kontakt::error::positive_as(
                    "load.line_load_n_per_mm",
                    q,
                    "a finite line load > 0 N/mm",
                )?;
                Ok((q * l, "load.line_load_n_per_mm"))
            }
            (None, Some(q), None) => Err(Error::invalid(
                "load.line_load_n_per_mm",
                q,
                "force_n for a point contact (a line load needs kind = \"line\")",
            )),
            (f, q, _) => Err(Error::invalid(
                "load",
                if f.is_some() && q.is_some() {
                    "both force_n and line_load_n_per_mm"
                } else {
                    "neither force_n nor line_load_n_per_mm"
                },
                "exactly one of force_n [N] or line_load_n_per_mm [N/mm] (kind = \"line\")",
            )),
        }
    }
}

/// `[friction]`.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize, schemars::JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct FrictionSpec {
    /// Coefficient of friction \[-\], > 0.
    pub mu: f64,
}

/// `[creepage]`: evenly spaced longitudinal creepages (slide-to-roll ratios) \[-\].
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize, schemars::JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct CreepageRange {
    /// First creepage \[-\], default 0.
    #[serde(default)]
    pub min: f64,
    /// Last creepage \[-\], > min.
    pub max: f64,
    /// Number of points, 2..=100000, default 101.
    #[serde(default = "default_points")]
    pub points: usize,
    /// Lateral creepage \[-\], the same at every point, default 0 (Kalker's linear
    /// theory and FASTSIM only).
    #[serde(default)]
    pub lateral: f64,
    /// Spin creepage \[1/mm\], the same at every point, default 0 (Kalker's linear theory
    /// and FASTSIM only).
    #[serde(default)]
    pub spin_per_mm: f64,
}

fn default_points() -> usize {
    101
}

impl CreepageRange {
    /// The creepages `min + (max - min) i/(points - 1)`.
    ///
    /// # Errors
    /// [`Error::InvalidInput`] naming `creepage.min`, `creepage.max` or
    /// `creepage.points`.
    pub fn values(&self) -> Result<Vec<f64>> {
        if !self.min.is_finite() {
            return Err(Error::invalid(
                "creepage.min",
                self.min,
                "a finite creepage [-]",
            ));
        }
        if !(self.max.is_finite() && self.max > self.min) {
            return Err(Error::invalid(
                "creepage.max",
                self.max,
                format!("a finite creepage > creepage.min = {}", self.min),
            ));
        }
        if !(2..=100_000).contains(&self.points) {
            return Err(Error::invalid(
                "creepage.points",
                self.points,
                "2..=100000 points",
            ));
        }
        for (field, v, unit) in [
            (
                "creepage.lateral",
                self.lateral,
                "a finite lateral creepage [-]",
            ),
            (
                "creepage.spin_per_mm",
                self.spin_per_mm,
                "a finite spin creepage [1/mm]",
            ),
        ] {
            if !v.is_finite() {
                return Err(Error::invalid(field, v, unit));
            }
        }
        let n = self.points - 1;
        // Where (max - min) i overflows (min = -1e308, max = 1e308 made inf * 0, a NaN
        // creepage nobody typed; found by probing), min (1 - t) + max t instead.
        let span = self.max - self.min;
        let span = if (span * n as f64).is_finite() {
            span
        } else {
            f64::INFINITY
        };
        Ok((0..=n)
            .map(|i| {
                if span.is_finite() {
                    self.min + span * i as f64 / n as f64
                } else {
                    let t = i as f64 / n as f64;
                    self.min * (1.0 - t) + self.max * t
                }
            })
            .collect())
    }
}

/// A library error about one point of the creepage range (`creepage = 1e306`, a value the
/// case does not give), said as the bound of `[creepage]` on its side (`creepage.max` or
/// `creepage.min`), with the point in the message.
fn range_point(e: Error, range: &CreepageRange) -> Error {
    match e {
        Error::InvalidInput {
            field,
            value,
            expected,
        } if field == "creepage" || field == "creepage.longitudinal" => {
            // The bound on the point's side: max for a point of max's sign within it (the
            // larger bound in magnitude when the point does not parse).
            let max_side = value
                .parse::<f64>()
                .map_or(range.max.abs() >= range.min.abs(), |x| {
                    x.signum() == range.max.signum() && x.abs() <= range.max.abs()
                });
            let (key, bound) = if max_side {
                ("creepage.max", range.max)
            } else {
                ("creepage.min", range.min)
            };
            Error::invalid(
                key,
                bound,
                format!("{expected} (the range reaches the creepage {value})"),
            )
        }
        other => other,
    }
}

/// `[fastsim]`: FASTSIM options.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize, schemars::JsonSchema)]
#[serde(deny_unknown_fields, default)]
pub struct FastsimSpec {
    /// Elements `[nx, ny]` (along rolling, strips), each 1..=4096.
    pub elements: [usize; 2],
    /// Pressure for the traction bound: `parabolic` (Kalker) or `elliptic` (Hertz).
    pub pressure: PressureSpec,
}

/// Pressure shape of FASTSIM's traction bound, as written in a case.
#[derive(
    Debug, Clone, Copy, PartialEq, Eq, Default, Serialize, Deserialize, schemars::JsonSchema,
)]
#[serde(rename_all = "snake_case")]
pub enum PressureSpec {
    /// Kalker's parabolic pressure.
    #[default]
    Parabolic,
    /// The Hertz pressure.
    Elliptic,
}

impl Default for FastsimSpec {
    fn default() -> Self {
        FastsimSpec {
            elements: FastsimOptions::default().elements,
            pressure: PressureSpec::Parabolic,
        }
    }
}

/// `[kalker_exact]`: options of Kalker's exact theory.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize, schemars::JsonSchema)]
#[serde(deny_unknown_fields, default)]
pub struct KalkerExactSpec {
    /// Cells across the contact ellipse `[mx, my]` (along the rolling direction, across),
    /// each 8..=1024; default `[32, 32]`. Below 16 the report warns: the creep force may
    /// then be off by 5 % or more (grid convergence in docs/tangential.md §11); with spin
    /// below 64 (`KalkerExactOptions::SPIN_ELEMENTS`; docs/rolling.md §6.1).
    pub elements: [usize; 2],
    /// Most Newton iterations of the steady solver per point, >= 1 (default 100); a
    /// point that needs more is reported as not converged.
    pub max_iterations: usize,
    /// Couple the normal and the tangential problem through Kalker's difference
    /// parameter `K` (dissimilar bodies: the pressure changes with the tractions, and
    /// the report gives the free-rolling creepage); default `false` (quasi-identical
    /// bodies, `K` neglected; the report warns when `K ≠ 0`).
    pub coupling: bool,
}

impl Default for KalkerExactSpec {
    fn default() -> Self {
        KalkerExactSpec {
            elements: KalkerExactOptions::default().elements,
            max_iterations: KalkerExactOptions::default().steady.max_newton_iterations,
            coupling: false,
        }
    }
}

/// Most creepage points of a `kalker_exact` curve (each is a steady-rolling solve).
pub const KALKER_EXACT_MAX_POINTS: usize = 1001;

/// Fewer cells across the contact than this gives a warning for `kalker_exact`.
pub const KALKER_EXACT_WARN_ELEMENTS: usize = 16;

impl TractionCase {
    /// Parse a traction case from TOML text.
    ///
    /// # Errors
    /// [`Error::CaseFile`] (line, key path, what the schema takes) for malformed TOML,
    /// unknown keys or wrong types.
    pub fn from_toml_str(text: &str) -> Result<Self> {
        parse_toml(text)
    }
}

/// One model's curve in a [`TractionReport`].
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct CurveReport {
    /// Model name (`carter`, `kalker_linear`, `fastsim`).
    pub model: &'static str,
    /// `F_T/(mu F_N)` \[-\] at each creepage of the report (Kalker linear: unclipped),
    /// with `F_T = -Fx` the longitudinal creep force opposing the longitudinal creepage.
    pub normalized_force: Vec<f64>,
    /// The creep forces in both directions and the spin moment at each point (Kalker's
    /// linear theory and FASTSIM, which take lateral and spin creepage): present when the
    /// case gives `creepage.lateral` or `creepage.spin_per_mm`.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub forces: Option<CreepForces>,
    /// Kalker's exact theory only: the grid and the solver's record at each point.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub exact: Option<ExactCurveReport>,
}

/// The solver's record of a `kalker_exact` curve.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct ExactCurveReport {
    /// Cells across the contact `[mx, my]`.
    pub elements: [usize; 2],
    /// Cell size `[dx, dy]` \[mm\].
    pub cell_mm: [f64; 2],
    /// Whether every point converged.
    pub converged: bool,
    /// Indices of the points that did not converge (their values are not results).
    pub not_converged: Vec<usize>,
    /// Whether the normal and tangential problems were coupled through Kalker's
    /// difference parameter (`[kalker_exact] coupling = true` and `K ≠ 0`); only when so.
    #[serde(skip_serializing_if = "std::ops::Not::not")]
    pub coupling: bool,
    /// With the coupling: the free-rolling creepage \[-\] (the longitudinal creepage at
    /// which `Fx = 0`, with the case's lateral and spin creepage).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub free_rolling_creepage: Option<f64>,
    /// Stick cells over loaded cells at each point \[-\].
    pub stick_fraction: Vec<f64>,
    /// FFT applications of the tangential operator over the whole curve.
    pub fft_iterations: usize,
    /// The steady solver's status at each point: termination, Newton iterations and the
    /// residual (the largest stick-cell slip or slip-law defect relative to the largest
    /// rigid slip `max |ω| dx`).
    pub status: Vec<SolveStatus>,
}

/// Creep forces and spin moment on body 1 along a curve (Kalker's sign convention: the
/// forces oppose the creepages).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct CreepForces {
    /// Longitudinal force `Fx` \[N\] at each point.
    pub longitudinal_force_n: Vec<f64>,
    /// Lateral force `Fy` \[N\] at each point.
    pub lateral_force_n: Vec<f64>,
    /// Spin moment `Mz` about the contact centre \[N·mm\] at each point (FASTSIM; the
    /// linear theory's `C33` is not in kontakt's coefficient table, so none for it).
    pub spin_moment_nmm: Option<Vec<f64>>,
}

/// The result of a traction case. Keys carry their units; dimensionless quantities have
/// none.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct TractionReport {
    /// Version of kontakt that produced the record.
    pub kontakt_version: &'static str,
    /// Version of this schema.
    pub schema_version: u32,
    /// The case's name, if any.
    pub name: Option<String>,
    /// `"traction"`.
    pub method: &'static str,
    /// `"hertz"`, `"ellipse"` or `"line"`.
    pub geometry: &'static str,
    /// Normal force \[N\].
    pub force_n: f64,
    /// Line load [N/mm] (line contacts).
    pub line_load_n_per_mm: Option<f64>,
    /// Friction coefficient \[-\].
    pub mu: f64,
    /// Contact modulus E* \[MPa\].
    pub e_star_mpa: f64,
    /// Kalker's combined shear modulus G \[MPa\].
    pub shear_modulus_mpa: f64,
    /// Kalker's combined Poisson's ratio \[-\].
    pub poisson_ratio: f64,
    /// Kalker's difference parameter `K` \[-\] of the two materials (0 for equal ones);
    /// neglected unless `kalker_exact` runs with `coupling = true`.
    pub difference_parameter: f64,
    /// `[a, b]` \[mm\]: semi-axis along the rolling direction and across it (line: half-width
    /// and half-length).
    pub semi_axes_mm: [f64; 2],
    /// Maximum Hertz pressure p0 \[MPa\].
    pub max_pressure_mpa: f64,
    /// Kalker's creepage coefficients (point contacts).
    pub creep_coefficients: Option<CreepCoefficients>,
    /// Creepage at which Kalker's linear force reaches mu F_N \[-\] (point contacts).
    pub kalker_saturation_creepage: Option<f64>,
    /// Carter's full-slip creepage `2 mu p0/E*` \[-\].
    pub carter_saturation_creepage: f64,
    /// FASTSIM elements `[nx, ny]`, if FASTSIM ran.
    pub fastsim_elements: Option<[usize; 2]>,
    /// Number of asperities of the asperity model, if it ran.
    pub asperities: Option<usize>,
    /// The longitudinal creepages (slide-to-roll ratios) \[-\].
    pub creepage: Vec<f64>,
    /// The constant lateral creepage \[-\] of every point, when the case gives lateral or
    /// spin creepage.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub lateral_creepage: Option<f64>,
    /// The constant spin creepage \[1/mm\] of every point, when the case gives lateral or
    /// spin creepage.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub spin_creepage_per_mm: Option<f64>,
    /// One curve per model, in the order of the case.
    pub curves: Vec<CurveReport>,
    /// Results to treat with care: a contact large against the bodies, unconverged points
    /// of `kalker_exact`, a coarse grid.
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub warnings: Vec<String>,
    /// The contact's size against the bodies (`kind = "hertz"`, and `"line"` with radii),
    /// for the validity check ([`crate::validity`]); not in the JSON.
    #[serde(skip)]
    pub contacts: Vec<ContactSize>,
}

checked_report!(TractionReport);

/// Run a traction case: build the contact, plan each model once and evaluate its curve.
///
/// # Errors
/// [`Error::InvalidInput`] or [`Error::Geometry`] naming the case key at fault
/// (`friction.mu`, `load.force_n`, `geometry.radii1_mm[0]`, `creepage.max`, `models`,
/// `fastsim.elements[0]`, ...).
///
/// # Example
/// ```
/// use kontakt_case::traction_case::{TractionCase, run_traction_case};
/// let case = TractionCase::from_toml_str(r#"
///     method = "traction"
///     [geometry]
///     kind = "ellipse"
///     semi_axes_mm = [0.3, 0.9]
///     [body1]
///     e_mpa = 210000.0
///     nu = 0.3
///     [body2]
///     e_mpa = 210000.0
///     nu = 0.3
///     [load]
///     force_n = 1000.0
///     [friction]
///     mu = 0.1
///     [creepage]
///     max = 0.01
/// "#)?;
/// let r = run_traction_case(&case)?;
/// assert_eq!(r.curves.len(), 3);
/// assert!((r.curves[2].normalized_force[100] - 1.0).abs() < 1e-9); // FASTSIM saturated
/// # Ok::<(), kontakt::Error>(())
/// ```
pub fn run_traction_case(case: &TractionCase) -> Result<TractionReport> {
    run_traction_case_with_map(case, None).map(|(r, _)| r)
}

/// Where `kontakt traction --map` draws the stick/slip map of `kalker_exact`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum MapPoint {
    /// The first point of the curve where `F_T/(mu F_N)` reaches 0.5 (partial slip).
    Auto,
    /// This longitudinal creepage \[-\] (with the case's lateral and spin creepage).
    Creepage(f64),
}

/// The tractions and the stick/slip state of one `kalker_exact` point on its grid.
#[derive(Debug, Clone, PartialEq)]
pub struct ExactMap {
    /// Longitudinal, lateral creepage \[-\] and spin \[1/mm\] of the point.
    pub creepage: [f64; 3],
    /// `F_T/(mu F_N)` \[-\] of the point.
    pub normalized_force: f64,
    /// Stick cells over loaded cells \[-\].
    pub stick_fraction: f64,
    /// The solver's status at the point.
    pub status: SolveStatus,
    /// Cells `[nx, ny]` of the grid (with the unloaded columns).
    pub cells: [usize; 2],
    /// Lower-left corner of the grid `[x_min, y_min]` \[mm\].
    pub origin_mm: [f64; 2],
    /// Cell size `[dx, dy]` \[mm\].
    pub cell_mm: [f64; 2],
    /// Semi-axes `[a, b]` of the contact ellipse \[mm\].
    pub semi_axes_mm: [f64; 2],
    /// Traction magnitude `|tau|` \[MPa\] per cell, row-major with x fastest.
    pub traction_mpa: Vec<f64>,
    /// 1 in stick cells, 0 elsewhere.
    pub stick: Vec<f64>,
    /// 1 in slip cells, 0 elsewhere.
    pub slip: Vec<f64>,
}

/// [`run_traction_case`], and with `map` the stick/slip map of `kalker_exact` at that
/// point (solved from zero traction on the model's grid).
///
/// # Errors
/// As [`run_traction_case`]; [`Error::InvalidInput`] naming `models` when a map is asked
/// for without `kalker_exact`, or `--map-creepage` when it is not finite.
pub fn run_traction_case_with_map(
    case: &TractionCase,
    map: Option<MapPoint>,
) -> Result<(TractionReport, Option<ExactMap>)> {
    let (report, map) = run_traction_case_with_map_unchecked(case, map)?;
    Ok((checked(report)?, map))
}

/// [`run_traction_case_with_map`] before the validity check of
/// [`crate::validity::checked`].
pub(crate) fn run_traction_case_with_map_unchecked(
    case: &TractionCase,
    map: Option<MapPoint>,
) -> Result<(TractionReport, Option<ExactMap>)> {
    if map.is_some() && !case.models.contains(&TractionModel::KalkerExact) {
        return Err(Error::invalid(
            "models",
            format!(
                "{:?}",
                case.models.iter().map(|m| m.as_str()).collect::<Vec<_>>()
            ),
            "a list with \"kalker_exact\" for --map (the stick/slip map of Kalker's exact theory)",
        ));
    }
    if let Some(MapPoint::Creepage(xi)) = map
        && !xi.is_finite()
    {
        return Err(Error::invalid(
            "--map-creepage",
            xi,
            "a finite creepage [-]",
        ));
    }
    let mut exact_map = None;
    let mut exact_slot = None;
    if case.method != "traction" {
        return Err(Error::invalid(
            "method",
            &case.method,
            "\"traction\" for this schema",
        ));
    }
    let names: Vec<&str> = case.models.iter().map(|m| m.as_str()).collect();
    kontakt::error::choices(
        "models",
        &names,
        &TractionModel::ALL.map(TractionModel::as_str),
    )?;
    let m1 = material(&case.body1, "body1")?;
    let m2 = material(&case.body2, "body2")?;
    let mu = case.friction.mu;
    let length = match &case.geometry {
        TractionGeometry::Line { length_mm, .. } => {
            if !(length_mm.is_finite() && *length_mm > 0.0) {
                return Err(Error::invalid(
                    "geometry.length_mm",
                    length_mm,
                    "a finite length > 0 mm",
                ));
            }
            Some(*length_mm)
        }
        _ => None,
    };
    let (force, load_key) = case.load.force(length)?;
    let map_common = |e: Error| {
        range_point(e, &case.creepage).map_field(|f| match f {
            "friction_coefficient" => "friction.mu".into(),
            "normal_force" | "force" | "line_load" => load_key.into(),
            "poisson_ratio" => "body1.nu, body2.nu".into(),
            "elements[0]" => "fastsim.elements[0]".into(),
            "elements[1]" => "fastsim.elements[1]".into(),
            "creepage.spin" => "creepage.spin_per_mm".into(),
            "semi_axes[0]" => "geometry.semi_axes_mm[0]".into(),
            "semi_axes[1]" => "geometry.semi_axes_mm[1]".into(),
            other => other.into(),
        })
    };
    kontakt::tangential::check_friction(mu).map_err(map_common)?;
    let creepage = case.creepage.values()?;
    let kalker_material = KalkerMaterial::new(&m1, &m2).map_err(map_common)?;
    let e_star = effective_modulus(&m1, &m2);
    let k_difference = difference_parameter(&m1, &m2).map_err(map_common)?;

    // (label, ellipse, Carter, line load, [a, b] or [half-width, half-length], p0)
    let mut contacts = Vec::new();
    let (label, ellipse, carter, line_load, semi_axes_mm, max_pressure_mpa) = match &case.geometry {
        TractionGeometry::Hertz {
            radii1_mm,
            radii2_mm,
            angle_deg,
        } => {
            let (sol, size) = hertz_of_geometry(*radii1_mm, *radii2_mm, *angle_deg, m1, m2, force)
                .map_err(map_common)?;
            contacts.push(size);
            let Some(axis) = rolling_axis(&sol) else {
                return Err(Error::Geometry {
                    field: "geometry.angle_deg".into(),
                    reason: format!(
                        "the rolling direction (body 1's first principal direction) is at {:.3} \
                         deg to the major axis of the contact ellipse; the creep models need it \
                         along an axis (use angle_deg = 0 or 90, or kind = \"ellipse\")",
                        sol.orientation.to_degrees()
                    ),
                });
            };
            let e = ContactEllipse::from_hertz(&sol, axis)?;
            let carter = Carter::from_ellipse(&e, &m1, &m2, mu).map_err(map_common)?;
            let axes = [e.a(), e.b()];
            ("hertz", Some(e), carter, None, axes, e.max_pressure())
        }
        TractionGeometry::Ellipse { semi_axes_mm } => {
            let e =
                ContactEllipse::new(semi_axes_mm[0], semi_axes_mm[1], force).map_err(map_common)?;
            let carter = Carter::from_ellipse(&e, &m1, &m2, mu).map_err(map_common)?;
            let axes = [e.a(), e.b()];
            ("ellipse", Some(e), carter, None, axes, e.max_pressure())
        }
        TractionGeometry::Line {
            radii_mm,
            half_width_mm,
            length_mm,
        } => {
            let line_load = force / length_mm;
            let carter = match (radii_mm, half_width_mm) {
                (Some(radii_mm), None) => {
                    let contact =
                        LineContact::new(radii_mm[0], radii_mm[1], m1, m2).map_err(|e| {
                            e.map_field(|f| match f {
                                "body1.radius" => "geometry.radii_mm[0]".into(),
                                "body2.radius" => "geometry.radii_mm[1]".into(),
                                _ => "geometry.radii_mm".into(),
                            })
                        })?;
                    let sol = contact.solve(line_load).map_err(map_common)?;
                    let size = ContactSize::new(
                        Size::Hertz(line_size(contact.radii(), &sol)),
                        ["geometry.radii_mm[0]", "geometry.radii_mm[1]"],
                    );
                    size.verdict()?;
                    contacts.push(size);
                    Carter::from_line_contact(&contact, line_load, mu).map_err(map_common)?
                }
                (None, Some(a)) => {
                    let a = kontakt::error::positive_as(
                        "geometry.half_width_mm",
                        *a,
                        "a finite half-width > 0 mm",
                    )?;
                    // Hertz strip: P' = (pi/2) p0 a.
                    let p0 = 2.0 * line_load / (std::f64::consts::PI * a);
                    Carter::new(a, p0, e_star, mu).map_err(map_common)?
                }
                (r, _) => {
                    return Err(Error::invalid(
                        "geometry",
                        if r.is_some() {
                            "both radii_mm and half_width_mm"
                        } else {
                            "neither radii_mm nor half_width_mm"
                        },
                        "exactly one of radii_mm [R1, R2] or half_width_mm for kind = \"line\"",
                    ));
                }
            };
            let axes = [carter.semi_width(), 0.5 * length_mm];
            (
                "line",
                None,
                carter,
                Some(line_load),
                axes,
                carter.max_pressure(),
            )
        }
    };

    let mut kalker = None;
    let mut fastsim = None;
    let mut asperity = None;
    let mut curves = Vec::with_capacity(case.models.len());
    let mut warnings = Vec::new();
    let combined = case.creepage.lateral != 0.0 || case.creepage.spin_per_mm != 0.0;
    for &model in &case.models {
        if combined && matches!(model, TractionModel::Carter | TractionModel::Asperity) {
            let (field, value) = if case.creepage.lateral != 0.0 {
                ("creepage.lateral", case.creepage.lateral)
            } else {
                ("creepage.spin_per_mm", case.creepage.spin_per_mm)
            };
            return Err(Error::invalid(
                field,
                value,
                format!(
                    "0 with model {} (a theory of longitudinal creepage only); lateral and \
                     spin creepage need models = [\"kalker_linear\", \"fastsim\", \
                     \"kalker_exact\"]",
                    model.as_str()
                ),
            ));
        }
        let curve: &dyn TractionCurve = match model {
            TractionModel::KalkerExact => {
                let Some(e) = ellipse else {
                    return Err(Error::invalid(
                        "models",
                        model.as_str(),
                        "carter or asperity for kind = \"line\" (Kalker's theories need a \
                         contact ellipse: use kind = \"hertz\" or \"ellipse\")",
                    ));
                };
                // Solved after the other models (below), so that their input errors come
                // first and cheaply; the slot keeps the case's order.
                exact_slot = Some((curves.len(), e));
                curves.push(CurveReport {
                    model: model.as_str(),
                    normalized_force: Vec::new(),
                    forces: None,
                    exact: None,
                });
                continue;
            }
            TractionModel::Carter => &carter,
            TractionModel::Asperity => {
                asperity = Some(asperity_model(case, force, &carter, ellipse, m1, m2)?);
                asperity.as_ref().expect("invariant: just set")
            }
            TractionModel::KalkerLinear | TractionModel::Fastsim => {
                let Some(e) = ellipse else {
                    return Err(Error::invalid(
                        "models",
                        model.as_str(),
                        "carter or asperity for kind = \"line\" (Kalker's theories need a \
                         contact ellipse: use kind = \"hertz\" or \"ellipse\")",
                    ));
                };
                if model == TractionModel::KalkerLinear {
                    kalker = Some(KalkerLinear::new(e, &m1, &m2, mu).map_err(map_common)?);
                    kalker.as_ref().expect("invariant: just set")
                } else {
                    let options = FastsimOptions {
                        elements: case.fastsim.elements,
                        pressure: match case.fastsim.pressure {
                            PressureSpec::Parabolic => PressureShape::Parabolic,
                            PressureSpec::Elliptic => PressureShape::Elliptic,
                        },
                    };
                    fastsim = Some(Fastsim::new(e, &m1, &m2, mu, options).map_err(map_common)?);
                    fastsim.as_ref().expect("invariant: just set")
                }
            }
        };
        let (normalized_force, forces) = if combined {
            let (n, f) = combined_curve(&case.creepage, &creepage, kalker, fastsim.as_ref(), model)
                .map_err(map_common)?;
            (n, Some(f))
        } else {
            let n = curve.traction_curve(&creepage).map_err(map_common)?;
            (n, None)
        };
        curves.push(CurveReport {
            model: model.as_str(),
            normalized_force,
            forces,
            exact: None,
        });
    }
    if let Some((slot, e)) = exact_slot {
        let (report, notes, field) =
            exact_curve(case, e, &m1, &m2, &creepage, combined, map).map_err(map_common)?;
        exact_map = field;
        warnings.extend(notes);
        curves[slot] = report;
    }
    if k_difference != 0.0 {
        let coupled = exact_slot.is_some() && case.kalker_exact.coupling;
        let neglecting: Vec<&str> = case
            .models
            .iter()
            .filter(|m| !(coupled && **m == TractionModel::KalkerExact))
            .map(|m| m.as_str())
            .collect();
        if !neglecting.is_empty() {
            warnings.push(format!(
                "Kalker's difference parameter K = {k_difference:.4e} (dissimilar materials) is \
                 neglected by {}: quasi-identical bodies assumed, the normal and tangential \
                 problems uncoupled (no free-rolling creepage); model kalker_exact with \
                 [kalker_exact] coupling = true includes it",
                neglecting.join(", ")
            ));
        }
    }
    // Linear-theory data for every point contact, also when the model was not asked for.
    let linear = match (&kalker, ellipse) {
        (Some(k), _) => Some(*k),
        (None, Some(e)) => Some(KalkerLinear::new(e, &m1, &m2, mu).map_err(map_common)?),
        (None, None) => None,
    };
    let report = TractionReport {
        kontakt_version: kontakt::VERSION,
        schema_version: SCHEMA_VERSION,
        name: case.name.clone(),
        method: "traction",
        geometry: label,
        force_n: force,
        line_load_n_per_mm: line_load,
        mu,
        e_star_mpa: e_star,
        shear_modulus_mpa: kalker_material.shear_modulus,
        poisson_ratio: kalker_material.poisson_ratio,
        difference_parameter: k_difference,
        semi_axes_mm,
        max_pressure_mpa,
        creep_coefficients: linear.map(|k| k.coefficients()),
        kalker_saturation_creepage: linear.map(|k| k.saturation_creepage()),
        carter_saturation_creepage: carter.saturation_creepage(),
        fastsim_elements: fastsim.map(|f| f.options().elements),
        asperities: asperity.map(|a| a.model().asperities().len()),
        creepage,
        lateral_creepage: combined.then_some(case.creepage.lateral),
        spin_creepage_per_mm: combined.then_some(case.creepage.spin_per_mm),
        curves,
        warnings,
        contacts,
    };
    Ok((report, exact_map))
}

/// Kalker's exact theory along the case's creepages (longitudinal `xis` \[-\], with the
/// constant lateral and spin creepage when `combined`): the curve, its solver record and
/// the warnings (a coarse grid, unconverged points).
fn exact_curve(
    case: &TractionCase,
    ellipse: ContactEllipse,
    m1: &kontakt::material::ElasticMaterial,
    m2: &kontakt::material::ElasticMaterial,
    xis: &[f64],
    combined: bool,
    map: Option<MapPoint>,
) -> Result<(CurveReport, Vec<String>, Option<ExactMap>)> {
    if xis.len() > KALKER_EXACT_MAX_POINTS {
        return Err(Error::invalid(
            "creepage.points",
            xis.len(),
            format!(
                "at most {KALKER_EXACT_MAX_POINTS} points with model kalker_exact (a steady \
                 rolling solve each)"
            ),
        ));
    }
    if case.kalker_exact.max_iterations == 0 {
        return Err(Error::invalid(
            "kalker_exact.max_iterations",
            0,
            "at least 1 Newton iteration",
        ));
    }
    let mut options = KalkerExactOptions {
        elements: case.kalker_exact.elements,
        coupling: case.kalker_exact.coupling,
        ..KalkerExactOptions::default()
    };
    options.steady.max_newton_iterations = case.kalker_exact.max_iterations;
    let model = KalkerExact::new(ellipse, m1, m2, case.friction.mu, options).map_err(|e| {
        e.map_field(|f| match f {
            "elements[0]" => "kalker_exact.elements[0]".into(),
            "elements[1]" => "kalker_exact.elements[1]".into(),
            other => other.into(),
        })
    })?;
    let creepages: Vec<kontakt::tangential::Creepage> = xis
        .iter()
        .map(|&xi| kontakt::tangential::Creepage {
            longitudinal: xi,
            lateral: case.creepage.lateral,
            spin: case.creepage.spin_per_mm,
        })
        .collect();
    let points = model.curve(&creepages)?;
    let coupled = model.is_coupled();
    let free = if coupled {
        Some(model.free_rolling(case.creepage.lateral, case.creepage.spin_per_mm)?)
    } else {
        None
    };
    let mut warnings = Vec::new();
    let [mx, my] = case.kalker_exact.elements;
    if mx.min(my) < KALKER_EXACT_WARN_ELEMENTS {
        warnings.push(format!(
            "kalker_exact: {mx} x {my} cells across the contact; below \
             {KALKER_EXACT_WARN_ELEMENTS} the creep force may be off by 5 % or more (grid \
             convergence: docs/tangential.md section 11); use kalker_exact.elements >= [32, 32] \
             for results"
        ));
    }
    if mx.min(my) >= KALKER_EXACT_WARN_ELEMENTS && options.coarse_for(&creepages) {
        warnings.push(format!(
            "kalker_exact: {mx} x {my} cells across the contact with spin; the creep force \
             converges slowly there (first order; CONTACT's lateral-plus-spin case: 5.9 % low \
             at 32 cells, 3.0 % at 64, 1.5 % at 128; docs/rolling.md section 6.1): use \
             kalker_exact.elements >= [{n}, {n}] for results",
            n = KalkerExactOptions::SPIN_ELEMENTS
        ));
    }
    let not_converged: Vec<usize> = points
        .iter()
        .enumerate()
        .filter(|(_, p)| !p.status.converged())
        .map(|(i, _)| i)
        .collect();
    if !not_converged.is_empty() {
        let first = &points[not_converged[0]];
        warnings.push(format!(
            "kalker_exact: {} of {} points did not converge (first at creepage {:e}: {} after \
             {} {}, residual {:.1e}); their values are not results",
            not_converged.len(),
            points.len(),
            first.creepage.longitudinal,
            first.status.termination.as_str(),
            first.status.iterations,
            if coupled {
                "outer passes"
            } else {
                "Newton iterations"
            },
            first.status.residual
        ));
    }
    if let Some(f) = free.filter(|f| !f.status.converged()) {
        warnings.push(format!(
            "kalker_exact: the free-rolling creepage did not converge ({} after {} outer \
             passes, residual {:.1e}); its value {:e} is not a result",
            f.status.termination.as_str(),
            f.status.iterations,
            f.status.residual,
            f.creepage.longitudinal
        ));
    }
    let grid = model.grid();
    let field = match map {
        None => None,
        Some(at) => {
            let xi = match at {
                MapPoint::Creepage(xi) => xi,
                MapPoint::Auto => points
                    .iter()
                    .find(|p| p.normalized_force >= 0.5)
                    .or(points.last())
                    .map_or(0.0, |p| p.creepage.longitudinal),
            };
            let c = kontakt::tangential::Creepage {
                longitudinal: xi,
                lateral: case.creepage.lateral,
                spin: case.creepage.spin_per_mm,
            };
            let (p, s) = model.solve_with_field(&c, false)?;
            let flag = |want: kontakt::rolling::CellState| -> Vec<f64> {
                s.state
                    .iter()
                    .map(|st| if *st == want { 1.0 } else { 0.0 })
                    .collect()
            };
            Some(ExactMap {
                creepage: [xi, c.lateral, c.spin],
                normalized_force: p.normalized_force,
                stick_fraction: p.stick_fraction,
                status: p.status,
                cells: [grid.nx(), grid.ny()],
                origin_mm: [grid.x(0) - 0.5 * grid.dx(), grid.y(0) - 0.5 * grid.dy()],
                cell_mm: [grid.dx(), grid.dy()],
                semi_axes_mm: [ellipse.a(), ellipse.b()],
                traction_mpa: s
                    .traction_x
                    .iter()
                    .zip(&s.traction_y)
                    .map(|(x, y)| x.hypot(*y))
                    .collect(),
                stick: flag(kontakt::rolling::CellState::Stick),
                slip: flag(kontakt::rolling::CellState::Slip),
            })
        }
    };
    let exact = ExactCurveReport {
        elements: [mx, my],
        cell_mm: [grid.dx(), grid.dy()],
        converged: not_converged.is_empty(),
        not_converged,
        coupling: coupled,
        free_rolling_creepage: free.map(|f| f.creepage.longitudinal),
        stick_fraction: points.iter().map(|p| p.stick_fraction).collect(),
        fft_iterations: points.iter().map(|p| p.fft_iterations).sum(),
        status: points.iter().map(|p| p.status).collect(),
    };
    let forces = combined.then(|| CreepForces {
        longitudinal_force_n: points.iter().map(|p| p.force[0]).collect(),
        lateral_force_n: points.iter().map(|p| p.force[1]).collect(),
        spin_moment_nmm: Some(points.iter().map(|p| p.spin_moment).collect()),
    });
    Ok((
        CurveReport {
            model: TractionModel::KalkerExact.as_str(),
            normalized_force: points.iter().map(|p| p.normalized_force).collect(),
            forces,
            exact: Some(exact),
        },
        warnings,
        field,
    ))
}

/// Kalker's linear theory or FASTSIM along the longitudinal creepages `xis` \[-\] with the
/// case's constant lateral and spin creepage: `F_T/(mu F_N) = -Fx/(mu F_N)` (FASTSIM:
/// within [-1, 1], as its pure-creepage curve) and the forces and moment.
fn combined_curve(
    range: &CreepageRange,
    xis: &[f64],
    kalker: Option<KalkerLinear>,
    fastsim: Option<&Fastsim>,
    model: TractionModel,
) -> Result<(Vec<f64>, CreepForces)> {
    let n = xis.len();
    let mut normalized = Vec::with_capacity(n);
    let mut fx = Vec::with_capacity(n);
    let mut fy = Vec::with_capacity(n);
    let mut mz = Vec::with_capacity(n);
    for &xi in xis {
        let c = kontakt::tangential::Creepage {
            longitudinal: xi,
            lateral: range.lateral,
            spin: range.spin_per_mm,
        };
        let (forces, moment, bound, clip) = match (model, kalker, fastsim) {
            (TractionModel::KalkerLinear, Some(k), _) => (
                k.forces(&c)?,
                None,
                k.friction_coefficient() * k.ellipse().normal_force(),
                false,
            ),
            (TractionModel::Fastsim, _, Some(f)) => {
                let s = f.solve(&c)?;
                (
                    s.forces,
                    Some(s.spin_moment),
                    f.friction_coefficient() * f.ellipse().normal_force(),
                    true,
                )
            }
            _ => {
                return Err(Error::invalid(
                    "models",
                    model.as_str(),
                    "kalker_linear or fastsim with lateral or spin creepage",
                ));
            }
        };
        let t = -forces[0] / bound;
        let t = if clip { t.clamp(-1.0, 1.0) } else { t };
        normalized.push(if t == 0.0 { 0.0 } else { t });
        fx.push(forces[0]);
        fy.push(forces[1]);
        mz.extend(moment);
    }
    Ok((
        normalized,
        CreepForces {
            longitudinal_force_n: fx,
            lateral_force_n: fy,
            spin_moment_nmm: (mz.len() == n).then_some(mz),
        },
    ))
}

/// The Hertz solution of a `kind = "hertz"` geometry (principal radii \[mm\], the angle
/// between the principal planes \[deg\]) under the normal force `force` \[N\]; errors name
/// the case keys (`geometry.angle_deg`, `geometry.radii1_mm`, ...), and its size against
/// the bodies (keys `geometry.radii1_mm`, `geometry.radii2_mm`; refused here already when
/// as large as a body's radius of curvature). Shared with the Cattaneo-Mindlin cases.
pub(crate) fn hertz_of_geometry(
    radii1_mm: [f64; 2],
    radii2_mm: [f64; 2],
    angle_deg: f64,
    m1: kontakt::material::ElasticMaterial,
    m2: kontakt::material::ElasticMaterial,
    force: f64,
) -> Result<(kontakt::hertz::HertzPointSolution, ContactSize)> {
    if !angle_deg.is_finite() {
        return Err(Error::invalid(
            "geometry.angle_deg",
            angle_deg,
            "a finite angle [deg]",
        ));
    }
    let g = PointGeometry::new(radii1_mm, radii2_mm, angle_deg.to_radians()).map_err(|e| {
        e.map_field(|f| match f {
            "radii" => "geometry.radii1_mm, geometry.radii2_mm".into(),
            f => f
                .replace("body1.radii", "geometry.radii1_mm")
                .replace("body2.radii", "geometry.radii2_mm"),
        })
    })?;
    let sol = HertzPointContact::new(g, m1, m2)?.solve_force(force)?;
    let size = ContactSize::new(
        Size::Hertz(point_size(&g, &sol)),
        ["geometry.radii1_mm", "geometry.radii2_mm"],
    );
    size.verdict()?;
    Ok((sol, size))
}

/// Plan the asperity model on the case's nominal contact.
fn asperity_model(
    case: &TractionCase,
    force: f64,
    carter: &Carter,
    ellipse: Option<ContactEllipse>,
    m1: kontakt::material::ElasticMaterial,
    m2: kontakt::material::ElasticMaterial,
) -> Result<AsperityCurve> {
    let spec = case.asperity.ok_or_else(|| {
        Error::invalid(
            "asperity",
            "missing",
            "an [asperity] table (asperity_radii_mm, period_mm) for the asperity model",
        )
    })?;
    if m1 != m2 {
        return Err(Error::invalid(
            "body2",
            format!(
                "E = {} MPa, nu = {}",
                m2.youngs_modulus(),
                m2.poisson_ratio()
            ),
            "the material of body1 (the asperity model assumes identical bodies)",
        ));
    }
    let nominal = match (
        &case.geometry,
        ellipse.as_ref().and_then(nominal_of_ellipse),
    ) {
        (
            TractionGeometry::Line {
                radii_mm: Some(radii_mm),
                length_mm,
                ..
            },
            _,
        ) => NominalContact::HertzLine {
            length: *length_mm,
            radii: *radii_mm,
        },
        (TractionGeometry::Line { .. }, _) => {
            return Err(Error::invalid(
                "geometry.half_width_mm",
                carter.semi_width(),
                "radii_mm instead, for the asperity model (its Hertz line contact needs the radii)",
            ));
        }
        (_, Some(circle)) => circle,
        _ => {
            return Err(Error::invalid(
                "models",
                format!(
                    "asperity on an ellipse a = {:.6} mm, b = {:.6} mm",
                    ellipse.map_or(carter.semi_width(), |e| e.a()),
                    ellipse.map_or(0.0, |e| e.b())
                ),
                "a circular (a = b) or line contact for the asperity model",
            ));
        }
    };
    let params = AsperityTractionParams {
        nominal,
        load: force,
        friction_coefficient: case.friction.mu,
        youngs_modulus: m1.youngs_modulus(),
        poisson_ratio: m1.poisson_ratio(),
        shear_modulus: spec.shear_modulus_mpa,
        asperity_radii: spec.asperity_radii_mm,
        period: spec.period_mm,
        transverse_period: spec.transverse_period_mm,
        asperity_contact: spec.asperity_contact,
        slip_reference: spec.slip_reference,
        load_sharing: spec.load_sharing,
    };
    let model = AsperityTraction::new(params).map_err(|e| {
        e.map_field(|f| match f {
            "load" => "load.force_n".into(),
            "friction_coefficient" => "friction.mu".into(),
            "youngs_modulus" => "body1.e_mpa".into(),
            "poisson_ratio" => "body1.nu".into(),
            "shear_modulus" => "asperity.shear_modulus_mpa".into(),
            "asperity_radii" => "asperity.asperity_radii_mm".into(),
            "period" => "asperity.period_mm".into(),
            "transverse_period" => "asperity.transverse_period_mm".into(),
            "asperity_contact" => "asperity.asperity_contact".into(),
            other if other.starts_with("nominal") => format!("geometry ({other})"),
            other => format!("asperity.{other}"),
        })
    })?;
    Ok(AsperityCurve::new(model))
}
