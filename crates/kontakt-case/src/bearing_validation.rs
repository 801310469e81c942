//! Whole-bearing friction torque against measurements (issue 29 §4): the measured points of
//! `validation/measured/*.csv` (each dataset with its provenance in
//! `validation/measured/README.md`) beside the SKF (2004) model at the same conditions.
//!
//! Data flow: [`datasets`] (the case: the measured points, compiled into the library, and
//! every assumption about the bearing, the oil and the catalogue constants) →
//! [`compare`] (the model: `kontakt_bearing::friction::skf2004` at every point and along
//! curves for the plots) → [`DatasetComparison`] (the result: rows with deviations in %)
//! → the CLI's `kontakt validate --bearing` (the report: table, CSV, plots).
//!
//! Units: speed r/min (the catalogues' unit; the library's rad/s inside), loads N, torque
//! N·mm, viscosity mm²/s, temperature °C.
//!
//! The contact-based whole-bearing torque (issue 29 §1-2), [`ComparisonRow::contact_nmm`],
//! is the friction section of a bearing case at each point ([`contact`]; the dataset's
//! [`Dataset::contact`], with its assumptions): Manjunath et al.'s 40 × 68 × 19 TRB from
//! the internal data of Liu (2022), raceways only (no rib geometry).
//!
//! What is not filled, and why, rather than a number without a source:
//! - the contact-based torque where the internal geometry is not stated (Zhou & Hoeprich
//!   1991's LM12700 without its load and oil); Wingertszahn et al. 2023's 32216 has it with
//!   assumed raceway angles ([`wingertszahn`]);
//! - Aihara (1987) ([`ComparisonRow::aihara_nmm`]) needs the rib contact height, the roller
//!   geometry and the oil's pressure-viscosity coefficient, which none of the datasets
//!   states: `None`, and the dataset's `aihara_note` says which input is missing;
//! - the SKF model where the load or the viscosity is not stated (Zhou & Hoeprich 1991,
//!   Fig. 9: the axial load and the SAE 75 oil's viscosity are not in the paper).

use kontakt::lubrication::Lubricant;
use kontakt::{Error, Result};
use kontakt_bearing::friction::skf2004::{
    SkfBearing, SkfOptions, SkfTorque, TaperedSeries, skf2004,
};
use kontakt_bearing::friction::{Envelope, Lubrication, OperatingPoint, RPM_PER_RAD_S};

pub mod contact;
pub mod rib_study;
pub mod wingertszahn;
pub use contact::{ContactParts, ContactSetup, ContactVariation, contact_at, contact_parts_at};

/// How far a measured value can be trusted.
#[derive(Debug, Clone, Copy, PartialEq, Eq, serde::Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Status {
    /// Transcribed from a table of the source.
    Verified,
    /// Read from a figure by a third party whose reading could not be checked against the
    /// figure: only with a wide band.
    Unverified,
}

impl Status {
    /// The CSV spelling.
    pub fn name(self) -> &'static str {
        match self {
            Status::Verified => "verified",
            Status::Unverified => "unverified",
        }
    }
}

/// What a measured torque is.
#[derive(Debug, Clone, Copy, PartialEq, Eq, serde::Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Quantity {
    /// The whole bearing's friction torque.
    Total,
    /// The raceways' rolling-resistance torque M_rr, as Manjunath et al. (2023) reconstruct
    /// it from their measurement: the measured total minus their computed rib torque. The
    /// models' raceway parts are compared with it (SKF: its rolling term; the
    /// contact-based model: cone + cup).
    RollingResistance,
}

impl Quantity {
    /// The CSV spelling.
    pub fn name(self) -> &'static str {
        match self {
            Quantity::Total => "total",
            Quantity::RollingResistance => "rolling_resistance",
        }
    }
}

/// One measured point (a row of a `validation/measured/*.csv` file).
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct MeasuredPoint {
    /// Speed of the rotating (inner) ring \[r/min\].
    pub speed_rpm: f64,
    /// Axial load \[N\]; `None` where the source does not state it.
    pub axial_load_n: Option<f64>,
    /// Radial load \[N\].
    pub radial_load_n: f64,
    /// Test temperature \[°C\] (the dataset's README says which temperature it is).
    pub temperature_c: f64,
    /// Measured total friction torque of the bearing \[N·mm\].
    pub torque_nmm: f64,
    /// Half width of the error band, in % of the value (± band_pct).
    pub band_pct: f64,
    /// Table value or unverified figure reading.
    pub status: Status,
    /// What was measured (the CSV's `quantity`).
    pub quantity: Quantity,
}

/// The kinematic viscosity of a test oil against temperature, from the source's data.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Oil {
    /// Walther line (ASTM D341) through ν40 and ν100 \[mm²/s\].
    Walther {
        /// ν at 40 °C \[mm²/s\].
        nu40: f64,
        /// ν at 100 °C \[mm²/s\].
        nu100: f64,
    },
    /// Vogel: η = K exp(B/(ϑ + C)) \[mPa·s\], ρ = ρ15 + dρ/dϑ (ϑ − 15) \[kg/m³\].
    Vogel {
        /// K \[mPa·s\].
        k_mpa_s: f64,
        /// B \[°C\].
        b_c: f64,
        /// C \[°C\].
        c_c: f64,
        /// Density at 15 °C \[kg/m³\].
        rho15: f64,
        /// dρ/dϑ \[kg/(m³·K)\].
        drho_dt: f64,
    },
    /// Not stated in the source: no viscosity, no SKF value.
    Unknown,
}

impl Oil {
    /// ν \[mm²/s\] at `temperature_c`; `None` for [`Oil::Unknown`].
    ///
    /// # Errors
    /// Those of [`Lubricant::kinematic_viscosity`] (`temperature_c` out of range).
    pub fn viscosity_mm2_s(&self, temperature_c: f64) -> Result<Option<f64>> {
        Ok(match *self {
            Oil::Walther { nu40, nu100 } => {
                // density and α do not enter the kinematic viscosity
                Some(Lubricant::new(nu40, nu100, 880.0, 0.02)?.kinematic_viscosity(temperature_c)?)
            }
            Oil::Vogel {
                k_mpa_s,
                b_c,
                c_c,
                rho15,
                drho_dt,
            } => {
                let eta = k_mpa_s * (b_c / (temperature_c + c_c)).exp();
                let rho = rho15 + drho_dt * (temperature_c - 15.0);
                Some(1.0e3 * eta / rho)
            }
            Oil::Unknown => None,
        })
    }
}

/// The SKF model's inputs for a dataset.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SkfSetup {
    /// Type, series and Y.
    pub bearing: SkfBearing,
    /// d × D × B \[mm\].
    pub envelope: Envelope,
    /// Lubrication method (oil bath level, oil jet).
    pub lubrication: Lubrication,
}

/// What the plots of a dataset run along.
#[derive(Debug, Clone, Copy, PartialEq, Eq, serde::Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Axis {
    /// Torque against speed.
    Speed,
    /// Torque against radial load at one speed.
    RadialLoad,
}

/// A model curve for the plots: one temperature and load (or speed) over a range of x.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CurveSpec {
    /// Temperature \[°C\].
    pub temperature_c: f64,
    /// Axial load \[N\].
    pub axial_load_n: f64,
    /// Radial load \[N\] (for [`Axis::Speed`]).
    pub radial_load_n: f64,
    /// Speed \[r/min\] (for [`Axis::RadialLoad`]).
    pub speed_rpm: f64,
    /// x from, to (r/min or N).
    pub range: (f64, f64),
}

/// One dataset: the measured points and everything the models need, with the assumptions.
#[derive(Debug, Clone, PartialEq)]
pub struct Dataset {
    /// Short name, the CSV's file stem.
    pub id: &'static str,
    /// The bearing and the conditions, one line.
    pub title: &'static str,
    /// Source: authors, year, journal, figure.
    pub source: &'static str,
    /// Plot axis.
    pub axis: Axis,
    /// Measured points (empty where the source gives figures only and no reading exists).
    pub points: Vec<MeasuredPoint>,
    /// The SKF model's inputs; `None` where the source lacks one (see `skf_note`).
    pub skf: Option<SkfSetup>,
    /// The test oil.
    pub oil: Oil,
    /// Every assumption about the bearing, the oil and the catalogue constants.
    pub assumptions: &'static [&'static str],
    /// Why Aihara (1987) is not evaluated.
    pub aihara_note: &'static str,
    /// The contact-based model's case and assumptions; `None` where the internal geometry
    /// is not stated.
    pub contact: Option<ContactSetup>,
    /// Model curves for the plots (explicit where there are no measured points).
    pub curves: Vec<CurveSpec>,
}

/// Parse a measured-torque CSV (`speed_rpm,axial_load_n,radial_load_n,temperature_c,
/// quantity,torque_nmm,band_pct,status`; an empty axial load = not stated; quantity
/// `total` or `rolling_resistance`, [`Quantity`]).
///
/// # Errors
/// [`Error::InvalidInput`] naming `<file> line <k> column` for a missing, non-numeric,
/// non-finite or negative value, an unknown quantity or status, a band outside 0..=100 %.
pub fn parse_points(file: &str, text: &str) -> Result<Vec<MeasuredPoint>> {
    const HEADER: &str =
        "speed_rpm,axial_load_n,radial_load_n,temperature_c,quantity,torque_nmm,band_pct,status";
    let mut lines = text.lines();
    let header = lines.next().unwrap_or("").trim();
    if header != HEADER {
        return Err(Error::invalid(
            format!("{file} line 1"),
            header,
            format!("the header {HEADER}"),
        ));
    }
    let mut points = Vec::new();
    for (k, line) in lines.enumerate() {
        let line = line.trim();
        if line.is_empty() {
            continue;
        }
        let at = |col: &str| format!("{file} line {} {col}", k + 2);
        let cells: Vec<&str> = line.split(',').map(str::trim).collect();
        if cells.len() != 8 {
            return Err(Error::invalid(at("row"), line, "8 comma-separated cells"));
        }
        let number = |i: usize, col: &str| -> Result<f64> {
            match cells[i].parse::<f64>() {
                Ok(v) if v.is_finite() && v >= 0.0 => Ok(v),
                _ => Err(Error::invalid(at(col), cells[i], "a finite number >= 0")),
            }
        };
        let quantity = match cells[4] {
            "total" => Quantity::Total,
            "rolling_resistance" => Quantity::RollingResistance,
            q => {
                return Err(Error::invalid(
                    at("quantity"),
                    q,
                    "total (the whole bearing's torque) | rolling_resistance (the raceways')",
                ));
            }
        };
        let band_pct = number(6, "band_pct")?;
        if band_pct > 100.0 {
            return Err(Error::invalid(at("band_pct"), band_pct, "0..=100 %"));
        }
        let status = match cells[7] {
            "verified" => Status::Verified,
            "unverified" => Status::Unverified,
            s => return Err(Error::invalid(at("status"), s, "verified | unverified")),
        };
        points.push(MeasuredPoint {
            speed_rpm: number(0, "speed_rpm")?,
            axial_load_n: if cells[1].is_empty() {
                None
            } else {
                Some(number(1, "axial_load_n")?)
            },
            radial_load_n: number(2, "radial_load_n")?,
            temperature_c: number(3, "temperature_c")?,
            torque_nmm: number(5, "torque_nmm")?,
            band_pct,
            status,
            quantity,
        });
    }
    Ok(points)
}

/// The measured-torque files, compiled in (file name, text).
pub const FILES: [(&str, &str); 6] = [
    (
        "manjunath2023_fig13.csv",
        include_str!("../../../validation/measured/manjunath2023_fig13.csv"),
    ),
    (
        "manjunath2023_fig13_alt.csv",
        include_str!("../../../validation/measured/manjunath2023_fig13_alt.csv"),
    ),
    (
        "wingertszahn2023_axial.csv",
        include_str!("../../../validation/measured/wingertszahn2023_axial.csv"),
    ),
    (
        "wingertszahn2023_combined.csv",
        include_str!("../../../validation/measured/wingertszahn2023_combined.csv"),
    ),
    (
        "wingertszahn2023_radial.csv",
        include_str!("../../../validation/measured/wingertszahn2023_radial.csv"),
    ),
    (
        "zhou_hoeprich1991_fig9.csv",
        include_str!("../../../validation/measured/zhou_hoeprich1991_fig9.csv"),
    ),
];

/// Zhou & Hoeprich (1991) Table 1 (isothermal EHL line-contact moments), compiled in.
pub const ZHOU_HOEPRICH_TABLE1: &str =
    include_str!("../../../validation/measured/zhou_hoeprich1991_table1.csv");

/// FVA reference oil No. 3A as Manjunath et al. (2023) give it: ν40 = 90.02, ν100 = 10.41 mm²/s.
pub const FVA3A: Oil = Oil::Walther {
    nu40: 90.02,
    nu100: 10.41,
};

/// FVA reference oil No. 3, Vogel parameters of Wingertszahn et al. (2023) Table A1.
pub const FVA3: Oil = Oil::Vogel {
    k_mpa_s: 0.062,
    b_c: 1021.7,
    c_c: 101.5517,
    rho15: 887.6,
    drho_dt: -0.6,
};

/// The 40 × 68 × 19 TRB of Manjunath et al. (2023) for the SKF model.
const SKF_32008X: SkfSetup = SkfSetup {
    bearing: SkfBearing::TaperedRoller {
        series: TaperedSeries::S320X,
        y: 1.6,
    },
    envelope: Envelope {
        bore_mm: 40.0,
        outer_mm: 68.0,
        width_mm: 19.0,
    },
    lubrication: Lubrication::OilJet,
};

const MANJUNATH_ASSUMPTIONS: &[&str] = &[
    "bearing: 32008 X envelope 40 × 68 × 19 mm (the paper's 40 × 68 × 19 TRB)",
    "SKF series row 320 X (R1 2.38e-6, R2 10.9, S1 0.014, S2 2; a single public transcription of the catalogue table)",
    "Y = 1.6: the axial load factor of 32008 X in the SKF product table (e = 0.37), not stated in the paper",
    "load: 12.85 kN axial, the caption of Fig. 13 (verified in the paper's text)",
    "quantity: Fig. 13 shows, by its caption, the rolling-resistance torque M_rr, which the paper reconstructs as the measured total minus its computed rib torque (its eqs. 15-17, 21); so SKF's rolling term and the contact-based model's raceways (cone + cup) are compared with it (the third party labelled the reading 'total')",
    "circulating oil (0.3 l/min) taken as the SKF 'oil jet' (K_rs = 3e-8, no drag term)",
    "viscosity: Walther line (ASTM D341) through the paper's ν40 = 90.02 and ν100 = 10.41 mm²/s at the stated oil temperature (the bearing runs warmer: the viscosity in the contacts is lower)",
    "mu_bl = 0.12, mu_EHL = 0.002 (SKF catalogue values for tapered roller bearings)",
];

const MANJUNATH_AIHARA: &str = "the rib contact height, the oil's pressure-viscosity coefficient and the roller geometry are not stated (Liu et al. 2022's 32008 is the same size, not proven the same bearing)";

/// The 32216 of Wingertszahn et al. (2023) for the SKF model.
const SKF_32216: SkfSetup = SkfSetup {
    bearing: SkfBearing::TaperedRoller {
        series: TaperedSeries::S322,
        y: 1.4,
    },
    envelope: Envelope {
        bore_mm: 80.0,
        outer_mm: 140.0,
        width_mm: 35.25,
    },
    lubrication: Lubrication::OilBath { level_mm: 8.5 },
};

const WINGERTSZAHN_ASSUMPTIONS: &[&str] = &[
    "bearing: TRB 32216 (d 80, D 140, T 35.25 mm: the ISO 355 envelope of 32216; d, D as the paper's Table 4)",
    "SKF series row 322 (R1 2.27e-6, R2 10.9, S1 0.018, S2 2; a single public transcription of the catalogue table)",
    "Y = 1.4: the axial load factor of 32216 in the SKF product table (e = 0.43), not stated in the paper",
    "oil bath at half roller height: H = d_RB/2 = 8.5 mm above the lowest point of the outer raceway",
    "SKF drag term omitted: the drag factor V_M is a catalogue diagram reading that is not available here (the SKF value is low by the drag loss)",
    "viscosity: Vogel fit of FVA 3 (K 0.062 mPa·s, B 1021.7 °C, C 101.5517 °C; ρ15 887.6 kg/m³, −0.6 kg/(m³·K)), the paper's Table A1, at the test temperature (outer ring)",
    "mu_bl = 0.12, mu_EHL = 0.002 (SKF catalogue values for tapered roller bearings)",
];

/// Every dataset of `validation/measured/`, with its assumptions.
///
/// # Errors
/// Those of [`parse_points`] for a malformed file.
pub fn datasets() -> Result<Vec<Dataset>> {
    let points = |name: &str| -> Result<Vec<MeasuredPoint>> {
        let (file, text) = FILES
            .iter()
            .find(|(f, _)| *f == name)
            .ok_or_else(|| Error::invalid("dataset", name, "a file of FILES"))?;
        parse_points(file, text)
    };
    let manjunath = Dataset {
        id: "manjunath2023_fig13",
        title: "TRB 40×68×19 (32008 X class), rolling-resistance torque M_rr, 12.85 kN axial, FVA 3A, oil jet 0.3 l/min, 55 and 65 °C",
        source: "Manjunath, Fauconnier, Ost & De Baets (2023), Machines 11(8):801, Fig. 13 (caption: 'TRB rolling-resistance torque models and measured results', 55 and 65 °C supply oil, 12.85 kN axial); third-party figure reading, unverified",
        axis: Axis::Speed,
        points: points("manjunath2023_fig13.csv")?,
        skf: Some(SKF_32008X),
        oil: FVA3A,
        assumptions: MANJUNATH_ASSUMPTIONS,
        aihara_note: MANJUNATH_AIHARA,
        contact: Some(contact::MANJUNATH_CONTACT),
        curves: Vec::new(),
    };
    let mut sets = vec![
        Dataset {
            id: "manjunath2023_fig13_alt",
            title: "the same figure, a second third-party reading that disagrees with the first (up to 40 % at 1000 r/min)",
            source: "Manjunath, Fauconnier, Ost & De Baets (2023), Machines 11(8):801, Fig. 13; a second third-party reading (\"image processing\") in the same third party's report, unverified",
            points: points("manjunath2023_fig13_alt.csv")?,
            ..manjunath.clone()
        },
        Dataset {
            id: "wingertszahn2023_axial",
            title: "TRB 32216, 6 kN axial, FVA 3, oil bath at half roller height, 50 and 42 °C",
            source: "Wingertszahn, Koch, Maccioni, Concli & Sauer (2023), Lubricants 11:369, Fig. 5 (Table 1); third-party figure reading, unverified",
            axis: Axis::Speed,
            points: points("wingertszahn2023_axial.csv")?,
            skf: Some(SKF_32216),
            oil: FVA3,
            assumptions: WINGERTSZAHN_ASSUMPTIONS,
            aihara_note: "the raceway angles, the rib geometry and the oil's pressure-viscosity coefficient at the test temperature are not given (the paper's Table 4 lacks the angles)",
            contact: Some(wingertszahn::CONTACT_32216),
            curves: Vec::new(),
        },
        Dataset {
            id: "wingertszahn2023_combined",
            title: "TRB 32216, 6 kN axial + 6.5 kN radial (Table 2), FVA 3, oil bath, 42 and 50 °C",
            source: "Wingertszahn, Koch, Maccioni, Concli & Sauer (2023), Lubricants 11:369, Fig. 6 (Table 2); third-party figure reading, unverified",
            axis: Axis::Speed,
            points: points("wingertszahn2023_combined.csv")?,
            skf: Some(SKF_32216),
            oil: FVA3,
            assumptions: WINGERTSZAHN_ASSUMPTIONS,
            aihara_note: "Aihara (1987) is for axial load only, and its inputs are missing as for the axial test",
            contact: Some(wingertszahn::CONTACT_32216),
            curves: Vec::new(),
        },
        Dataset {
            id: "wingertszahn2023_radial",
            title: "TRB 32216, 6.5 kN axial + 1-15 kN radial, 2000 r/min, FVA 3, oil bath, 50 °C",
            source: "Wingertszahn, Koch, Maccioni, Concli & Sauer (2023), Lubricants 11:369, Fig. 7 (Table 3); third-party figure reading, unverified; at 1 kN radial half the pure-axial torque of Fig. 5 although the axial load is larger: the 6.5 kN 'preload' may not be an external axial load of 6.5 kN",
            axis: Axis::RadialLoad,
            points: points("wingertszahn2023_radial.csv")?,
            skf: Some(SKF_32216),
            oil: FVA3,
            assumptions: WINGERTSZAHN_ASSUMPTIONS,
            aihara_note: "Aihara (1987) is for axial load only",
            contact: Some(wingertszahn::CONTACT_32216),
            curves: vec![CurveSpec {
                temperature_c: 50.0,
                axial_load_n: 6500.0,
                radial_load_n: 0.0,
                speed_rpm: 2000.0,
                range: (1000.0, 15000.0),
            }],
        },
        Dataset {
            id: "zhou_hoeprich1991_fig9",
            title: "TRB LM12700 (cup work point 41.5 mm, 17 rollers), SAE 75, 80 °C, axial load not stated",
            source: "Zhou & Hoeprich (1991), J. Tribol. 113:590, Fig. 9 (total torque); third-party figure reading, unverified",
            axis: Axis::Speed,
            points: points("zhou_hoeprich1991_fig9.csv")?,
            skf: None,
            oil: Oil::Unknown,
            assumptions: &[
                "SKF not evaluated: the paper states neither the load of Fig. 9 nor the viscosity of its SAE 75 oil at 80 °C (a third party back-calculated 3.6 kN axial; unverified, not used)",
            ],
            aihara_note: "the load, the oil data and the rib geometry are not stated",
            contact: None,
            curves: Vec::new(),
        },
    ];
    sets.insert(0, manjunath);
    for set in &mut sets {
        if set.curves.is_empty() {
            set.curves = speed_curves(&set.points);
        }
    }
    Ok(sets)
}

/// One model curve per (temperature, loads) group of measured points, each from half the
/// dataset's lowest measured speed to its highest.
fn speed_curves(points: &[MeasuredPoint]) -> Vec<CurveSpec> {
    let mut curves: Vec<CurveSpec> = Vec::new();
    for p in points {
        let Some(fa) = p.axial_load_n else { continue };
        let same = |c: &CurveSpec| {
            c.temperature_c == p.temperature_c
                && c.axial_load_n == fa
                && c.radial_load_n == p.radial_load_n
        };
        match curves.iter_mut().find(|c| same(c)) {
            Some(c) => c.range = (c.range.0.min(p.speed_rpm), c.range.1.max(p.speed_rpm)),
            None => curves.push(CurveSpec {
                temperature_c: p.temperature_c,
                axial_load_n: fa,
                radial_load_n: p.radial_load_n,
                speed_rpm: 0.0,
                range: (p.speed_rpm, p.speed_rpm),
            }),
        }
    }
    let lo = curves
        .iter()
        .map(|c| c.range.0)
        .fold(f64::INFINITY, f64::min);
    let hi = curves.iter().map(|c| c.range.1).fold(0.0, f64::max);
    for c in &mut curves {
        c.range = (0.5 * lo, hi);
    }
    curves
}

/// The SKF (2004) torque of `setup` at one condition (speed r/min, ν, loads).
///
/// # Errors
/// Those of [`skf2004`].
pub fn skf_at(
    setup: &SkfSetup,
    speed_rpm: f64,
    viscosity_mm2_s: f64,
    axial_load_n: f64,
    radial_load_n: f64,
) -> Result<SkfTorque> {
    skf2004(
        &setup.bearing,
        &setup.envelope,
        &OperatingPoint {
            speed_rad_s: speed_rpm / RPM_PER_RAD_S,
            viscosity_mm2_s,
            radial_load_n,
            axial_load_n,
            lubrication: setup.lubrication,
        },
        &SkfOptions::default(),
    )
}

/// One measured point beside the models.
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
pub struct ComparisonRow {
    /// The measured point.
    pub measured: MeasuredPoint,
    /// Viscosity at the point's temperature \[mm²/s\] (`None`: oil data not stated).
    pub viscosity_mm2_s: Option<f64>,
    /// SKF (2004) total, rolling, sliding, drag \[N·mm\] (`None`: an input not stated).
    pub skf: Option<SkfParts>,
    /// Aihara (1987) \[N·mm\]: `None` (inputs not stated; the dataset's `aihara_note`).
    pub aihara_nmm: Option<f64>,
    /// The contact-based torque (issue 29 §1-2) compared with the measurement \[N·mm\]:
    /// the whole bearing's for a [`Quantity::Total`], the raceways' (cone + cup) for a
    /// [`Quantity::RollingResistance`]; `None` where the dataset has no [`Dataset::contact`]
    /// (internal geometry not stated).
    pub contact_nmm: Option<f64>,
    /// The contact-based torque's breakdown (cone, cup, rib, drag, total) \[N·mm\].
    pub contact_parts: Option<ContactParts>,
}

/// The SKF torque's parts \[N·mm\].
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct SkfParts {
    /// φ_ish φ_rs M_rr + M_sl + M_seal + M_drag.
    pub total_nmm: f64,
    /// φ_ish φ_rs M_rr.
    pub rolling_nmm: f64,
    /// M_sl.
    pub sliding_nmm: f64,
    /// M_drag (0 where omitted).
    pub drag_nmm: f64,
}

impl From<&SkfTorque> for SkfParts {
    fn from(t: &SkfTorque) -> Self {
        SkfParts {
            total_nmm: t.total_nmm,
            rolling_nmm: t.rolling_nmm,
            sliding_nmm: t.sliding_nmm,
            drag_nmm: t.drag_nmm,
        }
    }
}

/// `100 (model / measured − 1)` \[%\].
pub fn deviation_pct(model: f64, measured: f64) -> f64 {
    100.0 * (model / measured - 1.0)
}

impl ComparisonRow {
    /// SKF against the measurement \[%\].
    pub fn skf_deviation_pct(&self) -> Option<f64> {
        self.skf_compared_nmm()
            .map(|s| deviation_pct(s, self.measured.torque_nmm))
    }

    /// The SKF torque compared with the measurement \[N·mm\]: the total for a
    /// [`Quantity::Total`], the rolling term φ_ish φ_rs M_rr for a
    /// [`Quantity::RollingResistance`].
    pub fn skf_compared_nmm(&self) -> Option<f64> {
        self.skf.map(|s| match self.measured.quantity {
            Quantity::Total => s.total_nmm,
            Quantity::RollingResistance => s.rolling_nmm,
        })
    }

    /// Aihara (1987) against the measurement \[%\].
    pub fn aihara_deviation_pct(&self) -> Option<f64> {
        self.aihara_nmm
            .map(|a| deviation_pct(a, self.measured.torque_nmm))
    }

    /// The contact-based model against the measurement \[%\].
    pub fn contact_deviation_pct(&self) -> Option<f64> {
        self.contact_nmm
            .map(|c| deviation_pct(c, self.measured.torque_nmm))
    }
}

/// A model curve for a plot: its label and (x, SKF total \[N·mm\]) points.
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
pub struct ModelCurve {
    /// Condition, e.g. "SKF 2004, 55 °C".
    pub label: String,
    /// The curve's temperature \[°C\] (to pair it with its measured points).
    pub temperature_c: f64,
    /// (x, torque \[N·mm\]) with x in r/min or N.
    pub points: Vec<(f64, f64)>,
}

/// A dataset with its rows and curves.
#[derive(Debug, Clone, PartialEq)]
pub struct DatasetComparison {
    /// The dataset.
    pub dataset: Dataset,
    /// One row per measured point.
    pub rows: Vec<ComparisonRow>,
    /// SKF curves along the dataset's axis (empty without SKF inputs): the total, or its
    /// rolling term for a dataset of rolling-resistance torques.
    pub skf_curves: Vec<ModelCurve>,
    /// The SKF model's warnings, once each (e.g. the omitted drag term).
    pub skf_warnings: Vec<String>,
}

impl DatasetComparison {
    /// (mean |deviation|, smallest, largest) of SKF against the measurement \[%\], `None`
    /// without SKF values.
    pub fn skf_deviation_stats(&self) -> Option<(f64, f64, f64)> {
        deviation_stats(
            self.rows
                .iter()
                .filter_map(ComparisonRow::skf_deviation_pct),
        )
    }

    /// As [`DatasetComparison::skf_deviation_stats`] for the contact-based model.
    pub fn contact_deviation_stats(&self) -> Option<(f64, f64, f64)> {
        deviation_stats(
            self.rows
                .iter()
                .filter_map(ComparisonRow::contact_deviation_pct),
        )
    }
}

/// (mean |d|, smallest, largest) of the deviations `d` \[%\], `None` for none.
fn deviation_stats(d: impl Iterator<Item = f64>) -> Option<(f64, f64, f64)> {
    let d: Vec<f64> = d.collect();
    if d.is_empty() {
        return None;
    }
    let mean = d.iter().map(|x| x.abs()).sum::<f64>() / d.len() as f64;
    let lo = d.iter().copied().fold(f64::INFINITY, f64::min);
    let hi = d.iter().copied().fold(f64::NEG_INFINITY, f64::max);
    Some((mean, lo, hi))
}

/// Points along each model curve.
pub const CURVE_POINTS: usize = 57;

/// Evaluate the models for every point and along the curves of `dataset`.
///
/// # Errors
/// Those of [`Oil::viscosity_mm2_s`], [`skf2004`] and [`contact_parts_at`].
pub fn compare(dataset: &Dataset) -> Result<DatasetComparison> {
    let mut warnings: Vec<String> = Vec::new();
    let mut note = |t: &SkfTorque| {
        for w in t.warnings.lines() {
            if !warnings.contains(&w) {
                warnings.push(w);
            }
        }
    };
    let mut rows = Vec::with_capacity(dataset.points.len());
    for p in &dataset.points {
        let nu = dataset.oil.viscosity_mm2_s(p.temperature_c)?;
        let skf = match (&dataset.skf, nu, p.axial_load_n) {
            (Some(setup), Some(nu), Some(fa)) => {
                let t = skf_at(setup, p.speed_rpm, nu, fa, p.radial_load_n)?;
                note(&t);
                Some(SkfParts::from(&t))
            }
            _ => None,
        };
        let contact_parts = match &dataset.contact {
            Some(setup) => contact_parts_at(setup, &ContactVariation::default(), p)?,
            None => None,
        };
        rows.push(ComparisonRow {
            measured: *p,
            viscosity_mm2_s: nu,
            skf,
            aihara_nmm: None,
            contact_nmm: contact_parts.map(|c| match p.quantity {
                Quantity::Total => c.total_nmm,
                Quantity::RollingResistance => c.raceways_nmm(),
            }),
            contact_parts,
        });
    }
    let mut skf_curves = Vec::new();
    // the SKF term that stands for the measured quantity: its rolling term beside a
    // rolling-resistance torque, its total otherwise
    let rolling_only = rib_study::is_rolling_resistance(dataset);
    if let Some(setup) = &dataset.skf {
        for c in &dataset.curves {
            let Some(nu) = dataset.oil.viscosity_mm2_s(c.temperature_c)? else {
                continue;
            };
            let mut pts = Vec::with_capacity(CURVE_POINTS);
            for k in 0..CURVE_POINTS {
                let x = c.range.0 + (c.range.1 - c.range.0) * k as f64 / (CURVE_POINTS - 1) as f64;
                let t = match dataset.axis {
                    Axis::Speed => skf_at(setup, x, nu, c.axial_load_n, c.radial_load_n)?,
                    Axis::RadialLoad => skf_at(setup, c.speed_rpm, nu, c.axial_load_n, x)?,
                };
                note(&t);
                pts.push((
                    x,
                    if rolling_only {
                        t.rolling_nmm
                    } else {
                        t.total_nmm
                    },
                ));
            }
            skf_curves.push(ModelCurve {
                label: if rolling_only {
                    format!("SKF 2004 rolling term, {} °C", c.temperature_c)
                } else {
                    format!("SKF 2004, {} °C", c.temperature_c)
                },
                temperature_c: c.temperature_c,
                points: pts,
            });
        }
    }
    Ok(DatasetComparison {
        dataset: dataset.clone(),
        rows,
        skf_curves,
        skf_warnings: warnings,
    })
}

/// Every dataset compared ([`datasets`] then [`compare`]).
///
/// # Errors
/// Those of [`datasets`] and [`compare`].
pub fn compare_all() -> Result<Vec<DatasetComparison>> {
    datasets()?.iter().map(compare).collect()
}
