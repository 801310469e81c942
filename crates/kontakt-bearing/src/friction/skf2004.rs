//! The SKF model of the frictional moment of a whole bearing (SKF General Catalogue
//! 6000 EN, 2005, chapter "Friction", and its successors 10000 EN 2013 and 17000 EN 2018;
//! "SKF 2004" after the year the model was introduced).
//!
//! `M = φ_ish φ_rs M_rr + M_sl + M_seal + M_drag` \[N·mm\], with (n in r/min, ν in mm²/s,
//! d_m = (d + D)/2 in mm, loads in N):
//!
//! - rolling: `M_rr = G_rr (ν n)^0.6`, `G_rr` from the type's formula and the series
//!   constants R1..R3 ([`GeometryConstants`]);
//! - inlet shear heating: `φ_ish = 1 / (1 + 1.84·10⁻⁹ (n d_m)^1.28 ν^0.64)`;
//! - kinematic replenishment/starvation: `φ_rs = 1 / exp(K_rs ν n (d + D) √(K_Z / (2(D − d))))`,
//!   `K_rs = 3·10⁻⁸` for a low oil bath and oil jet, `6·10⁻⁸` for grease and oil-air,
//!   `K_Z` per bearing type;
//! - sliding: `M_sl = G_sl μ_sl`, `μ_sl = φ_bl μ_bl + (1 − φ_bl) μ_EHL`,
//!   `φ_bl = 1 / exp(2.6·10⁻⁸ (n ν)^1.4 d_m)`;
//! - seals: `M_seal` = 0 here (open bearings only; the seal constants were not sourced);
//! - drag in an oil bath (roller bearings): `M_drag = 4 V_M K_roll C_w B d_m⁴ n² +
//!   1.093·10⁻⁷ n² d_m³ (n d_m² f_t / ν)^−1.379 R_s`; ball bearings
//!   `0.4 V_M K_ball d_m⁵ n² + (the same second term)`, with the drag factor `V_M` read by
//!   the user from SKF's diagram at `H/d_m` ([`SkfOptions::drag_factor_vm`]).
//!
//! Every constant carries its source in `docs/bearing-friction-catalogue.md`, and its
//! [`Provenance`]: the series tables were found only as public transcriptions of the
//! catalogue tables; where two independent transcriptions agree the row is
//! [`Provenance::CrossChecked`], otherwise [`Provenance::SingleTranscription`] and the
//! result raises [`SkfWarnings::unverified_constants`].
//!
//! Stated range (catalogue): constant loads in magnitude and direction, at least the
//! minimum load, constant speed below the speed ratings, normal clearance, no
//! misalignment beyond the bearing's limit; grease results are steady-state values. The
//! model is a running-torque model: at zero speed it gives the sliding term with the
//! starting boundary coefficient only (flagged), which Manjunath et al. (2023) found about
//! 15 % below a measured TRB starting torque.

use super::{Envelope, Lubrication, OperatingPoint, finite_or, non_negative_as};
use kontakt::error::positive_as;
use kontakt::{Error, Result};

/// Where a table row comes from.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "serde", serde(rename_all = "snake_case"))]
pub enum Provenance {
    /// Two independent public transcriptions of the catalogue table agree on the row.
    CrossChecked,
    /// One public transcription only (not checked against the catalogue page).
    SingleTranscription,
}

/// The geometric constants of one bearing series (SKF catalogue "Table 2b"/"Table 1b",
/// geometric constants for rolling and sliding frictional moments). Unused ones are 0.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct GeometryConstants {
    /// R1 (rolling).
    pub r1: f64,
    /// R2 (rolling; axial-load weight).
    pub r2: f64,
    /// R3 (rolling; centrifugal term of angular contact ball bearings).
    pub r3: f64,
    /// S1 (sliding).
    pub s1: f64,
    /// S2 (sliding).
    pub s2: f64,
    /// S3 (sliding; centrifugal term of angular contact ball bearings).
    pub s3: f64,
    /// Where the row comes from.
    pub provenance: Provenance,
}

const fn row(r1: f64, r2: f64, s1: f64, s2: f64, provenance: Provenance) -> GeometryConstants {
    GeometryConstants {
        r1,
        r2,
        r3: 0.0,
        s1,
        s2,
        s3: 0.0,
        provenance,
    }
}

use Provenance::{CrossChecked as X2, SingleTranscription as X1};

macro_rules! series {
    ($(#[$doc:meta])* $name:ident { $($(#[$vdoc:meta])* $variant:ident = $label:literal => $consts:expr,)+ }) => {
        $(#[$doc])*
        #[derive(Debug, Clone, Copy, PartialEq, Eq)]
        #[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
        pub enum $name {
            $($(#[$vdoc])* $variant,)+
        }

        impl $name {
            /// Every series of the table, in catalogue order.
            pub const ALL: &'static [$name] = &[$($name::$variant,)+];

            /// The catalogue's name of the series (`"320 X"`, `"all other"`).
            pub fn name(self) -> &'static str {
                match self {
                    $($name::$variant => $label,)+
                }
            }

            /// The series' constants.
            pub fn constants(self) -> GeometryConstants {
                match self {
                    $($name::$variant => $consts,)+
                }
            }

            /// The series by its catalogue name (case and blanks ignored: `"320x"`).
            ///
            /// # Errors
            /// [`Error::InvalidInput`] naming `series`, listing the valid names.
            pub fn from_name(name: &str) -> Result<Self> {
                let key = |s: &str| s.to_ascii_lowercase().replace(' ', "");
                let wanted = key(name);
                $name::ALL
                    .iter()
                    .copied()
                    .find(|s| key(s.name()) == wanted)
                    .ok_or_else(|| {
                        let list: Vec<&str> = $name::ALL.iter().map(|s| s.name()).collect();
                        Error::invalid("series", name, format!("one of {}", list.join(", ")))
                    })
            }
        }
    };
}

// Tapered roller bearings. Source: SKF catalogue table of geometric constants (tapered
// roller bearings), transcribed in JRaposo-m/SKF-Bearing-Selection-Tool,
// friction_RS_constants.csv; the "all other" row's R1, R2, S2 agree with the independent
// MATLAB transcription (BearingFriction.m, "taperedRoller"), whose S1 = 0.15 disagrees
// (0.15 is μ_bl's value: taken as a slip there), so even that row is single-source in S1.
series! {
    /// Series of single row tapered roller bearings with SKF constants
    /// (G_rr = R1 d_m^2.38 (F_r + R2 Y F_a)^0.31, G_sl = S1 d_m^0.82 (F_r + S2 Y F_a)).
    TaperedSeries {
        /// 302.
        S302 = "302" => row(1.76e-6, 10.9, 0.017, 2.0, X1),
        /// 303.
        S303 = "303" => row(1.69e-6, 10.9, 0.017, 2.0, X1),
        /// 313 (X).
        S313X = "313 X" => row(1.84e-6, 10.9, 0.048, 2.0, X1),
        /// 320 X (the 32008 X of Manjunath et al. 2023).
        S320X = "320 X" => row(2.38e-6, 10.9, 0.014, 2.0, X1),
        /// 322.
        S322 = "322" => row(2.27e-6, 10.9, 0.018, 2.0, X1),
        /// 322 B.
        S322B = "322 B" => row(2.38e-6, 10.9, 0.026, 2.0, X1),
        /// 323.
        S323 = "323" => row(2.38e-6, 10.9, 0.019, 2.0, X1),
        /// 323 B.
        S323B = "323 B" => row(2.79e-6, 10.9, 0.030, 2.0, X1),
        /// 329.
        S329 = "329" => row(2.31e-6, 10.9, 0.009, 2.0, X1),
        /// 330.
        S330 = "330" => row(2.71e-6, 11.3, 0.010, 2.0, X1),
        /// 331.
        S331 = "331" => row(2.71e-6, 10.9, 0.015, 2.0, X1),
        /// 332.
        S332 = "332" => row(2.71e-6, 10.9, 0.018, 2.0, X1),
        /// Inch series LL.
        LL = "LL" => row(1.72e-6, 10.9, 0.0057, 2.0, X1),
        /// Inch series L.
        L = "L" => row(2.19e-6, 10.9, 0.0093, 2.0, X1),
        /// Inch series LM.
        LM = "LM" => row(2.25e-6, 10.9, 0.011, 2.0, X1),
        /// Inch series M.
        M = "M" => row(2.48e-6, 10.9, 0.015, 2.0, X1),
        /// Inch series HM.
        HM = "HM" => row(2.60e-6, 10.9, 0.020, 2.0, X1),
        /// Inch series H.
        H = "H" => row(2.66e-6, 10.9, 0.025, 2.0, X1),
        /// Inch series HH.
        HH = "HH" => row(2.51e-6, 10.9, 0.027, 2.0, X1),
        /// All other tapered roller bearings.
        AllOther = "all other" => row(2.31e-6, 10.9, 0.019, 2.0, X1),
    }
}

// Cylindrical roller bearings with a cage. Same transcription; series 22 agrees with the
// MATLAB transcription (R1 = 1.4e-6, S1 = 0.16, S2 = 0.0015).
series! {
    /// Series of cylindrical roller bearings with a cage
    /// (G_rr = R1 d_m^2.41 F_r^0.31, G_sl = S1 d_m^0.9 F_a + S2 d_m F_r).
    CylindricalSeries {
        /// Series 2.
        S2 = "2" => row(1.09e-6, 0.0, 0.16, 0.0015, X1),
        /// Series 3.
        S3 = "3" => row(1.09e-6, 0.0, 0.16, 0.0015, X1),
        /// Series 4.
        S4 = "4" => row(1.00e-6, 0.0, 0.16, 0.0015, X1),
        /// Series 10.
        S10 = "10" => row(1.12e-6, 0.0, 0.17, 0.0015, X1),
        /// Series 12.
        S12 = "12" => row(1.23e-6, 0.0, 0.16, 0.0015, X1),
        /// Series 20.
        S20 = "20" => row(1.23e-6, 0.0, 0.16, 0.0015, X1),
        /// Series 22.
        S22 = "22" => row(1.40e-6, 0.0, 0.16, 0.0015, X2),
        /// Series 23.
        S23 = "23" => row(1.48e-6, 0.0, 0.16, 0.0015, X1),
    }
}

// Deep groove ball bearings. Same transcription; the MATLAB transcription's "deepBall"
// has R1, R2, S1 of series 60 (agree) with S2 of series 62, so no row is fully
// cross-checked.
series! {
    /// Series of deep groove ball bearings (G_rr = R1 d_m^1.96 (F_r + R2/sin α_F F_a)^0.54,
    /// G_sl = S1 d_m^−0.145 (F_r⁵ + S2 d_m^1.5/sin α_F F_a⁴)^(1/3); at F_a = 0
    /// G_rr = R1 d_m^1.96 F_r^0.54, G_sl = S1 d_m^−0.26 F_r^(5/3)).
    DeepGrooveSeries {
        /// 60 (and 630).
        S60 = "60" => row(4.1e-7, 1.7, 3.73e-3, 14.6, X1),
        /// 62 (and 622).
        S62 = "62" => row(3.9e-7, 1.7, 3.23e-3, 36.5, X1),
        /// 63 (and 623).
        S63 = "63" => row(3.7e-7, 1.7, 2.84e-3, 92.8, X1),
        /// 64.
        S64 = "64" => row(3.6e-7, 1.7, 2.43e-3, 198.0, X1),
        /// 160, 161.
        S160 = "160" => row(4.3e-7, 1.7, 4.63e-3, 4.25, X1),
        /// 617, 618, 628, 637, 638.
        S618 = "618" => row(4.7e-7, 1.7, 6.50e-3, 0.78, X1),
        /// 619, 639.
        S619 = "619" => row(4.3e-7, 1.7, 4.75e-3, 3.6, X1),
    }
}

const fn acbb(r1: f64, r2: f64, r3: f64, s1: f64, s2: f64, p: Provenance) -> GeometryConstants {
    GeometryConstants {
        r1,
        r2,
        r3,
        s1,
        s2,
        s3: r3,
        provenance: p,
    }
}

// Single row angular contact ball bearings. Same transcription; 73 BECBP agrees with the
// MATLAB transcription in all five constants. In both, S3 = R3.
series! {
    /// Series of single row angular contact ball bearings
    /// (G_rr = R1 d_m^1.97 (F_r + F_g + R2 F_a)^0.54, F_g = R3 d_m⁴ n²;
    /// G_sl = S1 d_m^0.26 ((F_r + F_g)^(4/3) + S2 F_a^(4/3)), F_g = S3 d_m⁴ n²).
    AngularContactSeries {
        /// 72 BECBP (40°).
        S72Becbp = "72 BECBP" => acbb(4.33e-7, 2.02, 2.44e-12, 1.82e-2, 0.71, X1),
        /// 73 BECBP (40°).
        S73Becbp = "73 BECBP" => acbb(4.54e-7, 2.02, 1.84e-12, 1.64e-2, 0.71, X2),
        /// 72 ACCBM (25°).
        S72Accbm = "72 ACCBM" => acbb(3.58e-7, 3.64, 3.55e-12, 1.14e-2, 1.55, X1),
        /// 73 ACCBM (25°).
        S73Accbm = "73 ACCBM" => acbb(3.48e-7, 3.64, 1.66e-12, 9.85e-3, 1.55, X1),
    }
}

/// The bearing for the SKF model: type, series and the type's extra catalogue datum.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "serde", serde(rename_all = "snake_case"))]
pub enum SkfBearing {
    /// Single row tapered roller bearing; `y` is the axial load factor Y of the product
    /// table (e.g. 1.6 for 32008 X).
    TaperedRoller {
        /// Series.
        series: TaperedSeries,
        /// Axial load factor Y (product table), > 0.
        y: f64,
    },
    /// Cylindrical roller bearing with a cage.
    CylindricalRoller {
        /// Series.
        series: CylindricalSeries,
    },
    /// Deep groove ball bearing; `c0_n` is the basic static load rating \[N\], used by
    /// α_F = 24.6 (F_a/C_0)^0.24 \[°\] when F_a > 0.
    DeepGrooveBall {
        /// Series.
        series: DeepGrooveSeries,
        /// Basic static load rating C_0 \[N\], > 0.
        c0_n: f64,
    },
    /// Single row angular contact ball bearing.
    AngularContactBall {
        /// Series.
        series: AngularContactSeries,
    },
}

impl SkfBearing {
    /// The series' geometric constants.
    pub fn constants(&self) -> GeometryConstants {
        match self {
            SkfBearing::TaperedRoller { series, .. } => series.constants(),
            SkfBearing::CylindricalRoller { series } => series.constants(),
            SkfBearing::DeepGrooveBall { series, .. } => series.constants(),
            SkfBearing::AngularContactBall { series } => series.constants(),
        }
    }

    /// `(K_Z, K_L)`: the bearing-type constants of the starvation and drag terms (SKF
    /// catalogue table "geometric constants K_Z and K_L"). K_Z agrees in both
    /// transcriptions for all four types; K_L (roller bearings only) is single-source.
    pub fn kz_kl(&self) -> (f64, f64) {
        match self {
            SkfBearing::TaperedRoller { .. } => (6.0, 0.7),
            SkfBearing::CylindricalRoller { .. } => (5.1, 0.65),
            SkfBearing::DeepGrooveBall { .. } => (3.1, 0.0),
            SkfBearing::AngularContactBall { .. } => (4.4, 0.0),
        }
    }

    /// μ_EHL, the full-film sliding coefficient (catalogue: 0.002 for tapered, 0.02 for
    /// cylindrical roller bearings; for the others it depends on the oil, `oil`).
    pub fn mu_ehl(&self, oil: BaseOil) -> f64 {
        match self {
            SkfBearing::TaperedRoller { .. } => 0.002,
            SkfBearing::CylindricalRoller { .. } => 0.02,
            _ => match oil {
                BaseOil::Mineral => 0.05,
                BaseOil::Synthetic => 0.04,
                BaseOil::TransmissionFluid => 0.1,
            },
        }
    }

    fn is_roller(&self) -> bool {
        matches!(
            self,
            SkfBearing::TaperedRoller { .. } | SkfBearing::CylindricalRoller { .. }
        )
    }
}

/// The base oil, for μ_EHL of the ball bearings.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "serde", serde(rename_all = "snake_case"))]
pub enum BaseOil {
    /// Mineral oil (μ_EHL = 0.05).
    #[default]
    Mineral,
    /// Synthetic oil (0.04).
    Synthetic,
    /// Transmission fluid (0.1).
    TransmissionFluid,
}

/// The model's free coefficients, with the catalogue's values as defaults.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct SkfOptions {
    /// Boundary sliding coefficient μ_bl while running (0.12, SKF as quoted by Manjunath
    /// et al. 2023; the 2005 catalogue writes "generally ≈ 0.15").
    pub mu_bl: f64,
    /// Boundary sliding coefficient at standstill, n = 0 (0.15).
    pub mu_bl_start: f64,
    /// μ_EHL instead of the catalogue's value for the type; `None` = catalogue.
    pub mu_ehl: Option<f64>,
    /// Base oil (μ_EHL of ball bearings).
    pub base_oil: BaseOil,
    /// Drag loss factor V_M read from the SKF diagram at H/d_m (oil bath); `None` = the
    /// drag term is not computed (flagged in an oil bath).
    pub drag_factor_vm: Option<f64>,
    /// Number of ball rows i_rw (ball-bearing drag), ≥ 1.
    pub ball_rows: u32,
}

impl Default for SkfOptions {
    fn default() -> Self {
        SkfOptions {
            mu_bl: 0.12,
            mu_bl_start: 0.15,
            mu_ehl: None,
            base_oil: BaseOil::Mineral,
            drag_factor_vm: None,
            ball_rows: 1,
        }
    }
}

/// Validity flags of an SKF result (`Copy`; [`SkfWarnings::lines`] gives sentences).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct SkfWarnings {
    /// n = 0: the running-torque model evaluated at standstill (μ_sl = μ_bl_start,
    /// M_rr = 0): a starting-torque estimate, not a fitted one.
    pub starting: bool,
    /// F_r = F_a = 0: below the minimum load the model assumes.
    pub no_load: bool,
    /// The series constants come from one public transcription of the catalogue table.
    pub unverified_constants: bool,
    /// Oil bath with the level above the bearing centre (H > D/2).
    pub oil_level_above_centre: bool,
    /// Oil bath without a drag factor V_M: M_drag is 0 in the total.
    pub drag_omitted: bool,
}

impl SkfWarnings {
    /// One sentence per raised flag.
    pub fn lines(&self) -> Vec<String> {
        let mut out = Vec::new();
        if self.starting {
            out.push("zero speed: the SKF running-torque model gives only its sliding term with the starting boundary coefficient here (Manjunath et al. 2023 found it about 15 % below a measured TRB starting torque)".to_string());
        }
        if self.no_load {
            out.push("no load: below the minimum load the SKF model assumes".to_string());
        }
        if self.unverified_constants {
            out.push("the series constants come from one public transcription of the SKF table, not checked against the catalogue page".to_string());
        }
        if self.oil_level_above_centre {
            out.push("oil level above the bearing centre: outside the conditions of the catalogue drag model".to_string());
        }
        if self.drag_omitted {
            out.push(
                "oil bath without a drag factor V_M: the drag loss is not included".to_string(),
            );
        }
        out
    }
}

/// The SKF frictional moment and its parts \[N·mm\], with the factors that produced it.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct SkfTorque {
    /// Speed used \[r/min\].
    pub speed_rpm: f64,
    /// Inlet shear heating reduction factor φ_ish.
    pub phi_ish: f64,
    /// Kinematic replenishment/starvation reduction factor φ_rs.
    pub phi_rs: f64,
    /// Weighting factor of the boundary sliding coefficient φ_bl.
    pub phi_bl: f64,
    /// Sliding coefficient μ_sl.
    pub mu_sl: f64,
    /// Rolling variable G_rr.
    pub g_rr: f64,
    /// Sliding variable G_sl.
    pub g_sl: f64,
    /// Rolling moment φ_ish φ_rs M_rr \[N·mm\].
    pub rolling_nmm: f64,
    /// Sliding moment M_sl \[N·mm\].
    pub sliding_nmm: f64,
    /// Seal moment M_seal \[N·mm\] (0: open bearings).
    pub seal_nmm: f64,
    /// Drag moment M_drag \[N·mm\].
    pub drag_nmm: f64,
    /// Total M \[N·mm\].
    pub total_nmm: f64,
    /// Validity flags.
    pub warnings: SkfWarnings,
}

/// `(G_rr, G_sl)` of `bearing` at mean diameter `dm` \[mm\], speed `n` \[r/min\] and loads.
///
/// # Errors
/// [`Error::InvalidInput`] naming `y` or `c0_n` if not finite and > 0.
pub fn geometry_variables(
    bearing: &SkfBearing,
    dm: f64,
    n: f64,
    fr: f64,
    fa: f64,
) -> Result<(f64, f64)> {
    let c = bearing.constants();
    Ok(match *bearing {
        SkfBearing::TaperedRoller { y, .. } => {
            let y = positive_as("y", y, "a finite axial load factor Y > 0 (product table)")?;
            (
                c.r1 * dm.powf(2.38) * (fr + c.r2 * y * fa).powf(0.31),
                c.s1 * dm.powf(0.82) * (fr + c.s2 * y * fa),
            )
        }
        SkfBearing::CylindricalRoller { .. } => (
            c.r1 * dm.powf(2.41) * fr.powf(0.31),
            c.s1 * dm.powf(0.9) * fa + c.s2 * dm * fr,
        ),
        SkfBearing::DeepGrooveBall { c0_n, .. } => {
            let c0 = positive_as("c0_n", c0_n, "a finite basic static load rating C0 > 0 N")?;
            if fa == 0.0 {
                (
                    c.r1 * dm.powf(1.96) * fr.powf(0.54),
                    c.s1 * dm.powf(-0.26) * fr.powf(5.0 / 3.0),
                )
            } else {
                let sin_af = (24.6 * (fa / c0).powf(0.24)).to_radians().sin();
                (
                    c.r1 * dm.powf(1.96) * (fr + c.r2 / sin_af * fa).powf(0.54),
                    c.s1 * dm.powf(-0.145)
                        * (fr.powi(5) + c.s2 * dm.powf(1.5) / sin_af * fa.powi(4)).cbrt(),
                )
            }
        }
        SkfBearing::AngularContactBall { .. } => {
            let fg_rr = c.r3 * dm.powi(4) * n * n;
            let fg_sl = c.s3 * dm.powi(4) * n * n;
            (
                c.r1 * dm.powf(1.97) * (fr + fg_rr + c.r2 * fa).powf(0.54),
                c.s1 * dm.powf(0.26) * ((fr + fg_sl).powf(4.0 / 3.0) + c.s2 * fa.powf(4.0 / 3.0)),
            )
        }
    })
}

/// Inlet shear heating reduction factor φ_ish = 1/(1 + 1.84·10⁻⁹ (n d_m)^1.28 ν^0.64)
/// (n r/min, d_m mm, ν mm²/s).
pub fn phi_ish(n: f64, dm: f64, nu: f64) -> f64 {
    1.0 / (1.0 + 1.84e-9 * (n * dm).powf(1.28) * nu.powf(0.64))
}

/// Kinematic replenishment/starvation reduction factor
/// φ_rs = exp(−K_rs ν n (d + D) √(K_Z/(2(D − d)))).
pub fn phi_rs(k_rs: f64, k_z: f64, n: f64, nu: f64, d: f64, big_d: f64) -> f64 {
    (-k_rs * nu * n * (d + big_d) * (k_z / (2.0 * (big_d - d))).sqrt()).exp()
}

/// Weighting factor of the boundary sliding coefficient φ_bl = exp(−2.6·10⁻⁸ (n ν)^1.4 d_m).
pub fn phi_bl(n: f64, nu: f64, dm: f64) -> f64 {
    (-2.6e-8 * (n * nu).powf(1.4) * dm).exp()
}

/// K_rs of the lubrication method: 3·10⁻⁸ for a low oil bath and oil jet, 6·10⁻⁸ for
/// grease and oil-air (SKF catalogue, kinematic replenishment/starvation).
pub fn k_rs(lubrication: &Lubrication) -> f64 {
    match lubrication {
        Lubrication::OilBath { .. } | Lubrication::OilJet => 3e-8,
        Lubrication::Grease | Lubrication::OilAir => 6e-8,
    }
}

/// Drag moment in an oil bath \[N·mm\] (see the module documentation): oil level `h` \[mm\],
/// drag factor `vm`, type constants K_Z, K_L, `rows` ball rows.
fn drag(bearing: &SkfBearing, env: &Envelope, n: f64, nu: f64, h: f64, vm: f64, rows: u32) -> f64 {
    if n == 0.0 {
        return 0.0;
    }
    let (d, big_d, b) = (env.bore_mm, env.outer_mm, env.width_mm);
    let dm = env.mean_diameter_mm();
    let (kz, kl) = bearing.kz_kl();
    let ring = (d + big_d) / (big_d - d);
    // wetted angle of the bath: t = 2 acos((0.6 d_m − H)/(0.6 d_m)), H capped at 1.2 d_m
    let h = h.min(1.2 * dm);
    let t = 2.0 * ((0.6 * dm - h) / (0.6 * dm)).clamp(-1.0, 1.0).acos();
    let f_t = if t <= std::f64::consts::PI {
        (0.5 * t).sin()
    } else {
        1.0
    };
    let f_a = 0.05 * kz * ring;
    let r_s = 0.36 * dm * dm * (t - t.sin()) * f_a;
    let second = if r_s > 0.0 && f_t > 0.0 {
        1.093e-7 * n * n * dm.powi(3) * (n * dm * dm * f_t / nu).powf(-1.379) * r_s
    } else {
        0.0
    };
    let first = if bearing.is_roller() {
        let k_roll = kl * kz * ring * 1e-12;
        let l_d = 5.0 * kl * b / dm;
        let c_w = 2.789e-10 * l_d.powi(3) - 2.786e-4 * l_d * l_d + 0.0195 * l_d + 0.6439;
        4.0 * vm * k_roll * c_w * b * dm.powi(4) * n * n
    } else {
        let k_ball = f64::from(rows) * kz * ring * 1e-12;
        0.4 * vm * k_ball * dm.powi(5) * n * n
    };
    first + second
}

/// The SKF frictional moment of `bearing` (envelope `env`) at `op`.
///
/// # Errors
/// [`Error::InvalidInput`] naming the field: those of [`OperatingPoint::check`] and
/// [`Envelope::check`], `y` / `c0_n` of the bearing, `mu_bl`, `mu_bl_start`, `mu_ehl`
/// (finite, 0 ≤ μ ≤ 1), `drag_factor_vm` (finite, ≥ 0), `ball_rows` (≥ 1); an input so
/// large that the torque is not a finite number is named too.
pub fn skf2004(
    bearing: &SkfBearing,
    env: &Envelope,
    op: &OperatingPoint,
    options: &SkfOptions,
) -> Result<SkfTorque> {
    env.check()?;
    op.check()?;
    let coefficient = |field: &'static str, mu: f64| -> Result<f64> {
        if mu.is_finite() && (0.0..=1.0).contains(&mu) {
            Ok(mu)
        } else {
            Err(Error::invalid(
                field,
                mu,
                "a finite friction coefficient in [0, 1]",
            ))
        }
    };
    let mu_bl = coefficient("mu_bl", options.mu_bl)?;
    let mu_bl_start = coefficient("mu_bl_start", options.mu_bl_start)?;
    let mu_ehl = match options.mu_ehl {
        Some(m) => coefficient("mu_ehl", m)?,
        None => bearing.mu_ehl(options.base_oil),
    };
    if let Some(vm) = options.drag_factor_vm {
        non_negative_as("drag_factor_vm", vm, "a finite drag loss factor V_M >= 0")?;
    }
    if options.ball_rows == 0 {
        return Err(Error::invalid("ball_rows", 0, "a number of ball rows >= 1"));
    }

    let n = op.speed_rpm();
    let nu = op.viscosity_mm2_s;
    let dm = env.mean_diameter_mm();
    let (fr, fa) = (op.radial_load_n, op.axial_load_n);
    let (g_rr, g_sl) = geometry_variables(bearing, dm, n, fr, fa)?;
    // an overflowing load variable is the loads' fault; an overflowing moment below, the speed's
    let load_field = if fa >= fr {
        ("axial_load_n", fa)
    } else {
        ("radial_load_n", fr)
    };
    finite_or(load_field.0, load_field.1, g_rr + g_sl)?;
    let (kz, _) = bearing.kz_kl();

    let ish = phi_ish(n, dm, nu);
    let rs = phi_rs(k_rs(&op.lubrication), kz, n, nu, env.bore_mm, env.outer_mm);
    let rolling = ish * rs * g_rr * (nu * n).powf(0.6);
    let (bl, mu_sl) = if n == 0.0 {
        (1.0, mu_bl_start)
    } else {
        let bl = phi_bl(n, nu, dm);
        (bl, bl * mu_bl + (1.0 - bl) * mu_ehl)
    };
    let sliding = g_sl * mu_sl;

    let mut warnings = SkfWarnings {
        starting: n == 0.0,
        no_load: fr == 0.0 && fa == 0.0,
        unverified_constants: bearing.constants().provenance == Provenance::SingleTranscription,
        ..SkfWarnings::default()
    };
    let drag_nmm = match op.lubrication {
        Lubrication::OilBath { level_mm } => {
            warnings.oil_level_above_centre = level_mm > 0.5 * env.outer_mm;
            match options.drag_factor_vm {
                Some(vm) => drag(bearing, env, n, nu, level_mm, vm, options.ball_rows),
                None => {
                    warnings.drag_omitted = true;
                    0.0
                }
            }
        }
        _ => 0.0,
    };
    let total = rolling + sliding + drag_nmm;
    let rolling = finite_or("speed_rad_s", op.speed_rad_s, rolling)?;
    let total = finite_or(load_field.0, load_field.1, total)?;
    Ok(SkfTorque {
        speed_rpm: n,
        phi_ish: ish,
        phi_rs: rs,
        phi_bl: bl,
        mu_sl,
        g_rr,
        g_sl,
        rolling_nmm: rolling,
        sliding_nmm: sliding,
        seal_nmm: 0.0,
        drag_nmm,
        total_nmm: total,
        warnings,
    })
}

#[cfg(test)]
mod tests;
