//! Bad input of the friction section (issue 29, "Bad input"): what [`super::friction_report`]
//! refuses or warns about beyond the library's own range checks.
//!
//! - an oil bath level above the bearing's centre: refused, naming `operating.oil_level_mm`
//!   with the valid range (the catalogue drag models and the half-roller bath of the tests
//!   are for levels up to the centre; a level above it is a flooded bearing that no model
//!   here describes);
//! - an oil temperature outside the lubricant's viscosity data (ν40 and ν100, or an ISO VG
//!   grade's, at 40 and 100 °C) but inside the Walther line's accepted −20..=150 °C: a
//!   warning naming `lubricant.temperature_c` (the viscosity is extrapolated); outside
//!   −20..=150 °C the library refuses it (`kontakt::lubrication::TEMPERATURE_RANGE_C`);
//! - a raceway film outside the fitted range of the line-contact film formula
//!   (Dowson-Higginson, piezoviscous-elastic: Moes M ≥ 10, Biboulet & Houpert 2010): a
//!   warning naming the contact farthest outside (roller, azimuth, cone or cup), its M, L
//!   and Λ, and the range, beside the count of slices; the result stays finite.
//!
//! Zero speed is not bad input: the starting torque (boundary friction per unit speed,
//! `kontakt_bearing::friction::torque`).
//!
//! Units: mm, N, N/mm, °C, rad/s.

use crate::friction_case::LubricantSpec;
use kontakt::lubrication::{LineFilmContact, line_film_regime};
use kontakt::{Error, Result};
use kontakt_bearing::friction::torque::BearingFrictionModel;
use kontakt_bearing::geometry::RollerBearing;

/// The temperatures of the viscosity data of a `[lubricant]` (ν40, ν100 or ISO VG) \[°C\].
pub const VISCOSITY_DATA_C: (f64, f64) = (40.0, 100.0);

/// The height of the bearing's centre above the lowest point of the outer raceway \[mm\]:
/// the outer raceway's mid radius `d_m/2 + (D_w/2) cos α`.
pub fn centre_height_mm(bearing: &RollerBearing) -> f64 {
    0.5 * bearing.pitch_diameter_mm
        + 0.5 * bearing.roller_diameter_mm * bearing.contact_angle_rad.cos()
}

/// The oil bath level `level_mm` \[mm\] checked: finite, ≥ 0 and not above the centre.
///
/// # Errors
/// [`Error::InvalidInput`] naming `operating.oil_level_mm` with the valid range.
pub fn oil_level(level_mm: f64, bearing: &RollerBearing) -> Result<f64> {
    oil_level_below(level_mm, centre_height_mm(bearing))
}

/// The oil bath level `level_mm` \[mm\] checked against the bearing's centre `centre` \[mm\]
/// above the lowest point of the outer raceway (any bearing; a ball bearing's is
/// `d_m/2 + (D/2) cos α₀`).
///
/// # Errors
/// As [`oil_level`].
pub fn oil_level_below(level_mm: f64, centre: f64) -> Result<f64> {
    if level_mm.is_finite() && (0.0..=centre).contains(&level_mm) {
        Ok(level_mm)
    } else {
        Err(Error::invalid(
            "operating.oil_level_mm",
            level_mm,
            format!(
                "0..={centre:.2} mm: the oil level above the lowest point of the outer raceway, at most the bearing's centre (a level above the centre is outside every drag model here)"
            ),
        ))
    }
}

/// The warning of an oil temperature `lub.temperature_c` outside the viscosity data.
pub fn temperature_warning(lub: &LubricantSpec) -> Option<String> {
    let t = lub.temperature_c;
    let (lo, hi) = VISCOSITY_DATA_C;
    (t < lo || t > hi).then(|| {
        format!(
            "lubricant.temperature_c = {t} °C is outside the oil's viscosity data ({lo}-{hi} °C, the ν40 and ν100 of the Walther line): the viscosity is extrapolated"
        )
    })
}

/// The raceway contact farthest outside the film formula's fit, as a warning with the
/// count `slices` of flagged slices, or `None` when no slice is flagged. Every loaded
/// slice of `cup` and `cone` (N, roller-major, as the model evaluated them) at its load per
/// length, with the reduced radius and the entrainment speed of its line's midpoint
/// (`1/(cos β/r + cos α_i/R_i)` on the cone, `1/(cos β/r − cos α/R_o)` on the cup, `|ω_R| r`,
/// untilted: the kinematics of `kontakt_bearing::friction::torque`, whose radii vary along
/// the line by the roller's taper, so M is approximate); the slice with the smallest Moes M
/// is named (roller, azimuth, raceway, position along the line).
///
/// # Errors
/// Those of [`line_film_regime`] (a finite model's inputs do not raise them).
pub fn film_warning(
    model: &BearingFrictionModel,
    speeds: [f64; 2],
    azimuths_rad: &[f64],
    slice_loads: [&[f64]; 2],
    slices: usize,
) -> Result<Option<String>> {
    if slices == 0 {
        return Ok(None);
    }
    let b = model.bearing();
    let n = b.slices;
    let width = b.effective_length_mm / n as f64;
    let lub = model.losses().lubrication();
    let (ri, ro, r) = model.pitch_radii();
    let (_, spin) = model.speeds(speeds[0], speeds[1]);
    let cos_beta = (0.5 * (b.contact_angle_rad - b.cone_angle_rad)).cos();
    let radii = [
        1.0 / (cos_beta / r + b.cone_angle_rad.cos() / ri),
        1.0 / (cos_beta / r - b.contact_angle_rad.cos() / ro),
    ];
    let modulus = crate::bearing_case::STEEL_CONTACT_MODULUS_MPA;
    // (M, L, roller, raceway, slice)
    let mut worst: Option<(f64, f64, usize, usize, usize)> = None;
    for (side, loads) in slice_loads.iter().enumerate() {
        for (i, &q) in loads.iter().enumerate() {
            if q <= 0.0 {
                continue;
            }
            let regime = line_film_regime(
                &LineFilmContact {
                    radius: radii[side],
                    entrainment_speed: spin * r,
                    load_per_length: q / width,
                    reduced_modulus: modulus,
                },
                lub.viscosity,
                lub.alpha,
            )?;
            if let Some(m) = regime.moes_m
                && worst.is_none_or(|w| m < w.0)
            {
                worst = Some((m, regime.moes_l, i / n, side, i % n));
            }
        }
    }
    let mut text = format!(
        "{slices} loaded raceway slices outside the Dowson-Higginson film fit (its range: Moes M >= 10, piezoviscous-elastic, Biboulet & Houpert 2010; or h_c < h_min): films and Λ extrapolated"
    );
    if let Some((m, l, j, side, k)) = worst {
        let az = azimuths_rad.get(j).copied().unwrap_or(0.0).to_degrees();
        let name = ["cone", "cup"][side];
        let lambda = model.rollers().get(j).map_or(f64::NAN, |r| r.min_lambda);
        text.push_str(&format!(
            "; farthest: roller {j} (azimuth {az:.1}°) {name}, slice {k} at {x:.2} mm from the line's midpoint, M ≈ {m:.3}, L = {l:.2} (the roller's smallest Λ = {lambda:.3})",
            x = model.slice_position(k)
        ));
    }
    Ok(Some(text))
}
