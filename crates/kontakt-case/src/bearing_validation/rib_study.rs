//! The rib of the contact-based model against the measurements (issue 29 §4): the torque
//! breakdown (cone, cup, rib, drag) along the speed beside the SKF model, and the
//! sensitivity of the comparison to the uncertain inputs of the rib and the oil.
//!
//! Data flow: a dataset with a [`super::Dataset::contact`] (the case) → [`breakdown`] /
//! [`sensitivity`] (the model: the contact setup's bearing case, changed by one
//! [`ContactVariation`] at a time, at every measured point) → [`BreakdownCurve`] /
//! [`SensitivityRow`] (the result) → the CLI's plot, table and report.
//!
//! Every variation is one physical input moved over its plausible range, never fitted to
//! the measurement; [`VARIATIONS`] says why each range.
//!
//! Units: r/min, N, °C, mm, N·mm; deviations in % of the measured value.

use super::contact::{
    ContactParts, ContactSetup, ContactVariation, MANJUNATH_CONTACT_RACEWAYS, contact_parts,
};
use super::{Axis, Dataset, Quantity, SkfParts, deviation_pct, skf_at};
use kontakt::{Error, Result};

/// The contact-based breakdown and the SKF model along the speed at one temperature and load.
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
pub struct BreakdownCurve {
    /// Oil temperature \[°C\].
    pub temperature_c: f64,
    /// Axial load \[N\].
    pub axial_load_n: f64,
    /// Radial load \[N\].
    pub radial_load_n: f64,
    /// One point per speed.
    pub points: Vec<BreakdownPoint>,
}

/// One speed of a [`BreakdownCurve`].
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct BreakdownPoint {
    /// Inner ring speed \[r/min\].
    pub speed_rpm: f64,
    /// The contact-based torque and its parts \[N·mm\].
    pub contact: ContactParts,
    /// The SKF (2004) torque and its parts \[N·mm\] (`None`: no SKF inputs).
    pub skf: Option<SkfParts>,
}

/// Speeds of a breakdown curve.
pub const BREAKDOWN_POINTS: usize = 23;

/// The contact-based breakdown along the speed for each (temperature, load) curve of a
/// dataset with a contact setup, from its curves' lowest speed (at least 50 r/min) to the
/// highest, [`BREAKDOWN_POINTS`] speeds; empty for a dataset without a contact setup or
/// along the radial load.
///
/// # Errors
/// Those of [`contact_parts`] and [`skf_at`].
pub fn breakdown(dataset: &Dataset) -> Result<Vec<BreakdownCurve>> {
    let Some(setup) = &dataset.contact else {
        return Ok(Vec::new());
    };
    if dataset.axis != Axis::Speed {
        return Ok(Vec::new());
    }
    let mut out = Vec::with_capacity(dataset.curves.len());
    for c in &dataset.curves {
        let (lo, hi) = (c.range.0.max(50.0), c.range.1);
        let nu = dataset.oil.viscosity_mm2_s(c.temperature_c)?;
        let mut points = Vec::with_capacity(BREAKDOWN_POINTS);
        for k in 0..BREAKDOWN_POINTS {
            let n = lo + (hi - lo) * k as f64 / (BREAKDOWN_POINTS - 1) as f64;
            let contact = contact_parts(
                setup,
                &ContactVariation::default(),
                n,
                c.axial_load_n,
                c.radial_load_n,
                c.temperature_c,
            )?;
            let skf = match (&dataset.skf, nu) {
                (Some(s), Some(nu)) => Some(SkfParts::from(&skf_at(
                    s,
                    n,
                    nu,
                    c.axial_load_n,
                    c.radial_load_n,
                )?)),
                _ => None,
            };
            points.push(BreakdownPoint {
                speed_rpm: n,
                contact,
                skf,
            });
        }
        out.push(BreakdownCurve {
            temperature_c: c.temperature_c,
            axial_load_n: c.axial_load_n,
            radial_load_n: c.radial_load_n,
            points,
        });
    }
    Ok(out)
}

/// One uncertain input of the study and the values it is moved to.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Variation {
    /// The input, e.g. "rib roughness (composite)".
    pub parameter: &'static str,
    /// Its value, as printed.
    pub value: &'static str,
    /// Why this value is physical.
    pub why: &'static str,
    /// The change to the case.
    pub change: ContactVariation,
    /// Run the bearing without its rib (the ISO slice model) instead.
    pub without_rib: bool,
}

/// The contact point's distance from the rollers' common apex (Liu 2022's 32008, contact
/// 1 mm above the inner raceway line) \[mm\]: the face radius ratios refer to it.
pub const APEX_DISTANCE_MM: f64 = 130.6;

/// The large-end radius of Liu (2022)'s 32008 roller, D_we/2 + (L_we/2) tan β \[mm\]: the
/// contact heights h = ρ_L − e.
pub const LARGE_END_RADIUS_MM: f64 = 3.4231;

const fn vary(
    parameter: &'static str,
    value: &'static str,
    why: &'static str,
    change: ContactVariation,
) -> Variation {
    Variation {
        parameter,
        value,
        why,
        change,
        without_rib: false,
    }
}

const NONE: ContactVariation = ContactVariation {
    face_radius_mm: None,
    contact_height_mm: None,
    rib_roughness_mm: None,
    temperature_rise_k: 0.0,
    alpha_per_mpa: None,
    boundary_mu: None,
};

/// The variations of the study, one input at a time from the case of
/// `examples/bearing_32008x_rib_friction.toml` (face radius 0.9 × 130.6 mm, contact 1 mm
/// above the raceway line, 0.198 µm composite roughness, the stated oil temperature,
/// α = 0.021 1/MPa, boundary μ 0.1).
pub const VARIATIONS: [Variation; 15] = [
    Variation {
        parameter: "case",
        value: "as assumed",
        why: "examples/bearing_32008x_rib_friction.toml",
        change: NONE,
        without_rib: false,
    },
    Variation {
        parameter: "rib",
        value: "none (raceways only)",
        why: "the column of the previous study: the ISO slice model without the rib contact",
        change: NONE,
        without_rib: true,
    },
    vary(
        "face radius / apex distance",
        "0.75",
        "Liu X. et al. (2023)'s optimum for a spherical rib",
        ContactVariation {
            face_radius_mm: Some(0.75 * APEX_DISTANCE_MM),
            ..NONE
        },
    ),
    vary(
        "face radius / apex distance",
        "0.85",
        "lower end of the ratios a recent rib study varies (Machines 13:910, 2025)",
        ContactVariation {
            face_radius_mm: Some(0.85 * APEX_DISTANCE_MM),
            ..NONE
        },
    ),
    vary(
        "face radius / apex distance",
        "0.95",
        "upper end of the same range",
        ContactVariation {
            face_radius_mm: Some(0.95 * APEX_DISTANCE_MM),
            ..NONE
        },
    ),
    vary(
        "contact height e above the raceway line",
        "0.5 mm",
        "rib slide-to-roll ratio 0.18 (reference notes §1.3): below Zhou & Hoeprich's 0.25-0.4",
        ContactVariation {
            contact_height_mm: Some(LARGE_END_RADIUS_MM - 0.5),
            ..NONE
        },
    ),
    vary(
        "contact height e above the raceway line",
        "1.5 mm",
        "slide-to-roll ratio 0.61: above Zhou & Hoeprich's range",
        ContactVariation {
            contact_height_mm: Some(LARGE_END_RADIUS_MM - 1.5),
            ..NONE
        },
    ),
    vary(
        "rib roughness (composite, rib only)",
        "0.10 µm",
        "a finely ground or run-in rib",
        ContactVariation {
            rib_roughness_mm: Some([0.0000707, 0.0000707]),
            ..NONE
        },
    ),
    vary(
        "rib roughness (composite, rib only)",
        "0.24 µm",
        "the 32216 rib of Wingertszahn et al. (2023), the one published TRB rib roughness",
        ContactVariation {
            rib_roughness_mm: Some([0.0001697, 0.0001697]),
            ..NONE
        },
    ),
    vary(
        "rib roughness (composite, rib only)",
        "0.35 µm",
        "a coarsely ground rib",
        ContactVariation {
            rib_roughness_mm: Some([0.0002475, 0.0002475]),
            ..NONE
        },
    ),
    vary(
        "bearing above the oil temperature",
        "+5 K",
        "the outer ring runs warmer than the supply oil (Manjunath et al. evaluate the viscosity at the outer ring's temperature)",
        ContactVariation {
            temperature_rise_k: 5.0,
            ..NONE
        },
    ),
    vary(
        "bearing above the oil temperature",
        "+10 K",
        "as +5 K",
        ContactVariation {
            temperature_rise_k: 10.0,
            ..NONE
        },
    ),
    vary(
        "pressure-viscosity coefficient α",
        "0.0185 1/MPa",
        "FVA 3A at 55 °C, interpolated in Manjunath et al.'s Table 3 (2.16e-3 1/bar at 25 °C, 1.58e-3 at 80 °C)",
        ContactVariation {
            alpha_per_mpa: Some(0.0185),
            ..NONE
        },
    ),
    vary(
        "boundary friction coefficient μ_b",
        "0.12",
        "the SKF model's μ_bl for a running bearing",
        ContactVariation {
            boundary_mu: Some(0.12),
            ..NONE
        },
    ),
    vary(
        "boundary friction coefficient μ_b",
        "0.15",
        "the SKF model's μ_bl at start (Manjunath et al.'s nomenclature)",
        ContactVariation {
            boundary_mu: Some(0.15),
            ..NONE
        },
    ),
];

/// The comparison of a dataset's points with the contact-based model under one variation.
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
pub struct SensitivityRow {
    /// The dataset.
    pub dataset: &'static str,
    /// The input varied.
    pub parameter: &'static str,
    /// Its value.
    pub value: &'static str,
    /// Why the value is physical.
    pub why: &'static str,
    /// Mean |deviation| of the model's raceways (cone + cup) from the measured values \[%\]
    /// (the comparison for the rolling-resistance torque M_rr).
    pub raceways_mean_abs_pct: f64,
    /// Mean |deviation| of the model's total torque from the measured values \[%\] (the
    /// comparison if the values were the total torque).
    pub total_mean_abs_pct: f64,
    /// The raceways' deviation at the lowest measured speed, per temperature \[%\].
    pub raceways_start_pct: Vec<(f64, f64)>,
    /// The total's deviation at the lowest measured speed, per temperature \[%\].
    pub total_start_pct: Vec<(f64, f64)>,
    /// The rib torque at the lowest measured speed, per temperature \[N·mm\].
    pub rib_start_nmm: Vec<(f64, f64)>,
}

/// The dataset's points against the contact-based model under each of [`VARIATIONS`].
///
/// # Errors
/// A dataset without a contact setup or without measured axial loads; those of
/// [`contact_parts`].
pub fn sensitivity(dataset: &Dataset) -> Result<Vec<SensitivityRow>> {
    let setup = dataset.contact.as_ref().ok_or_else(|| {
        Error::invalid(
            "dataset",
            dataset.id,
            "a dataset with a contact-based setup",
        )
    })?;
    let start = dataset
        .points
        .iter()
        .map(|p| p.speed_rpm)
        .fold(f64::INFINITY, f64::min);
    VARIATIONS
        .iter()
        .map(|v| {
            let s: &ContactSetup = if v.without_rib {
                &MANJUNATH_CONTACT_RACEWAYS
            } else {
                setup
            };
            let (mut race, mut total) = (Vec::new(), Vec::new());
            let mut row = SensitivityRow {
                dataset: dataset.id,
                parameter: v.parameter,
                value: v.value,
                why: v.why,
                raceways_mean_abs_pct: 0.0,
                total_mean_abs_pct: 0.0,
                raceways_start_pct: Vec::new(),
                total_start_pct: Vec::new(),
                rib_start_nmm: Vec::new(),
            };
            for p in &dataset.points {
                let fa = p.axial_load_n.ok_or_else(|| {
                    Error::invalid("axial_load_n", "not stated", "a stated axial load")
                })?;
                let c = contact_parts(
                    s,
                    &v.change,
                    p.speed_rpm,
                    fa,
                    p.radial_load_n,
                    p.temperature_c,
                )?;
                let (dr, dt) = (
                    deviation_pct(c.raceways_nmm(), p.torque_nmm),
                    deviation_pct(c.total_nmm, p.torque_nmm),
                );
                race.push(dr.abs());
                total.push(dt.abs());
                if p.speed_rpm == start {
                    row.raceways_start_pct.push((p.temperature_c, dr));
                    row.total_start_pct.push((p.temperature_c, dt));
                    row.rib_start_nmm.push((p.temperature_c, c.rib_nmm));
                }
            }
            let mean = |d: &[f64]| d.iter().sum::<f64>() / d.len().max(1) as f64;
            row.raceways_mean_abs_pct = mean(&race);
            row.total_mean_abs_pct = mean(&total);
            Ok(row)
        })
        .collect()
}

/// Whether a dataset's measured values are the raceways' torque (all its points
/// [`Quantity::RollingResistance`]).
pub fn is_rolling_resistance(dataset: &Dataset) -> bool {
    !dataset.points.is_empty()
        && dataset
            .points
            .iter()
            .all(|p| p.quantity == Quantity::RollingResistance)
}

/// The axial loads of the LM12700 study \[N\]: the third party's back-calculated 3.6 kN
/// (not in the paper) and a bracket around it.
pub const LM12700_LOADS_N: [f64; 3] = [3600.0, 2000.0, 6000.0];

/// The speeds of the LM12700 study \[r/min\]: Zhou & Hoeprich's Fig. 9 range, 100 to
/// 4800 r/min.
pub const LM12700_SPEEDS: (f64, f64) = (100.0, 4800.0);

/// The contact-based breakdown of the LM12700 (`super::contact::LM12700_CONTACT`, every
/// assumption there) along the speed at its 80 °C, one curve per axial load of `loads_n`,
/// [`BREAKDOWN_POINTS`] speeds over [`LM12700_SPEEDS`]; no SKF (the envelope's series
/// constants are not known for this inch bearing).
///
/// # Errors
/// Those of [`contact_parts`].
pub fn lm12700_breakdown(loads_n: &[f64]) -> Result<Vec<BreakdownCurve>> {
    let setup = &super::contact::LM12700_CONTACT;
    let (lo, hi) = LM12700_SPEEDS;
    loads_n
        .iter()
        .map(|&fa| {
            let points = (0..BREAKDOWN_POINTS)
                .map(|k| {
                    let n = lo + (hi - lo) * k as f64 / (BREAKDOWN_POINTS - 1) as f64;
                    Ok(BreakdownPoint {
                        speed_rpm: n,
                        contact: contact_parts(
                            setup,
                            &ContactVariation::default(),
                            n,
                            fa,
                            0.0,
                            80.0,
                        )?,
                        skf: None,
                    })
                })
                .collect::<Result<Vec<_>>>()?;
            Ok(BreakdownCurve {
                temperature_c: 80.0,
                axial_load_n: fa,
                radial_load_n: 0.0,
                points,
            })
        })
        .collect()
}

/// The speed \[r/min\] above which the raceways' torque (cone + cup) exceeds the rib's, by
/// linear interpolation between the curve's speeds; `None` if it does not change sign.
pub fn crossover_rpm(curve: &BreakdownCurve) -> Option<f64> {
    let diff = |p: &BreakdownPoint| p.contact.raceways_nmm() - p.contact.rib_nmm;
    curve.points.windows(2).find_map(|w| {
        let (a, b) = (diff(&w[0]), diff(&w[1]));
        (a < 0.0 && b >= 0.0)
            .then(|| w[0].speed_rpm + (w[1].speed_rpm - w[0].speed_rpm) * (-a) / (b - a))
    })
}
