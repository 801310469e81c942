//! Elastohydrodynamic (EHL) film thickness of a line contact (a roller slice on a raceway):
//! the Dowson-Higginson (1977 form) minimum film and the Dowson-Toyoda (1979) central film,
//! the dimensionless groups per unit length and the Moes regime parameters, and the two
//! corrections that the isothermal, fully flooded formulas leave out: the Zhu-Cheng inlet
//! shear-heating (thermal) reduction factor and a starvation factor.
//!
//! Conventions (Dowson-Higginson, per unit length): E′ = 2E*, R the reduced radius in the
//! rolling direction (1/R = 1/R₁ + 1/R₂), u the mean (entrainment) speed (u₁ + u₂)/2,
//! w the load per unit length,
//!
//! ```text
//! U = η₀ u / (E′ R)     G = α E′     W = w / (E′ R)
//! H_min = h_min / R = 2.65 U^0.70 G^0.54 W^−0.13     (Dowson & Higginson, 1977 form)
//! H_c   = h_c   / R = 3.06 U^0.69 G^0.56 W^−0.10     (Dowson & Toyoda, 1979)
//! ```
//!
//! Units: lengths mm, load per length N/mm, modulus MPa, speed mm/s, viscosity MPa·s,
//! α 1/MPa; every group is a ratio of the same quantities, so no conversion is needed.
//! Sources, the regime map and what is not implemented (Pan & Hamrock 1989, whose constants
//! were found in no readable source here): `docs/film.md` §7.
//!
//! [`line_film_thickness`] allocates nothing; its validity limits are reported as
//! [`LineFilmWarnings`], never hidden.

use crate::error::{Error, Result, positive_as as positive};

/// A lubricated line contact, per unit length.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(
    feature = "serde",
    derive(serde::Serialize, serde::Deserialize, schemars::JsonSchema)
)]
pub struct LineFilmContact {
    /// Reduced radius of curvature in the rolling direction R \[mm\], finite and > 0
    /// (1/R = 1/R₁ + 1/R₂; for a roller of radius r on an inner raceway of radius R_i,
    /// 1/R = 1/r + 1/R_i).
    pub radius: f64,
    /// Mean surface speed u = (u₁ + u₂)/2 relative to the contact \[mm/s\], finite and ≥ 0.
    /// Zero gives h = 0 (boundary lubrication) with a warning.
    pub entrainment_speed: f64,
    /// Load per unit length w \[N/mm\], finite and > 0.
    pub load_per_length: f64,
    /// Contact modulus E* \[MPa\], finite and > 0 (1/E* = (1−ν₁²)/E₁ + (1−ν₂²)/E₂;
    /// Dowson and Higginson's E′ is 2E*).
    pub reduced_modulus: f64,
}

/// The line-contact film formula.
#[non_exhaustive]
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
#[cfg_attr(
    feature = "serde",
    derive(serde::Serialize, serde::Deserialize, schemars::JsonSchema)
)]
pub enum LineFilmFormula {
    /// Isothermal, fully flooded, Newtonian, smooth line contact: minimum film
    /// H_min = 2.65 U^0.70 G^0.54 W^−0.13 (Dowson & Higginson, 1977 form of their 1966
    /// formula), central film H_c = 3.06 U^0.69 G^0.56 W^−0.10 (Dowson & Toyoda, 1979).
    DowsonHigginson,
}

/// The dimensionless groups of a line contact (Dowson-Higginson convention, per unit
/// length) and the Hertz values that go with them.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct LineFilmRegime {
    /// Speed parameter U = η₀u/(E′R), u the mean speed.
    pub u: f64,
    /// Material parameter G = αE′.
    pub g: f64,
    /// Load parameter W = w/(E′R).
    pub w: f64,
    /// Moes load parameter of the line contact M = W (2U)^(−1/2) (Moes' speed parameter is
    /// built on the sum speed, 2U here; Biboulet & Houpert 2010 eq. 14 write it M_l =
    /// W/√U with their U = 2η₀u/(E′R)); `None` at zero speed, where it diverges.
    pub moes_m: Option<f64>,
    /// Moes material parameter L = G (2U)^(1/4); 0 at zero speed.
    pub moes_l: f64,
    /// Hertz semi-width b = √(8wR/(πE′)) = R√(8W/π) \[mm\].
    pub half_width: f64,
    /// Hertz peak pressure p_h = E′√(W/(2π)) = 2w/(πb) \[MPa\].
    pub max_pressure: f64,
}

/// Validity flags of a line-film result: `Copy`, no allocation.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct LineFilmWarnings {
    /// Zero entrainment speed: no hydrodynamic film, h = 0.
    pub zero_entrainment: bool,
    /// M < 10: the contact is away from the piezoviscous-elastic regime on which the
    /// Dowson-Higginson and Dowson-Toyoda fits were made (Biboulet & Houpert 2010 find the
    /// rolling force at its elastic asymptote only above M ≈ 10; below, it tends to the
    /// rigid-isoviscous one). The film is extrapolated.
    pub outside_elastic_regime: bool,
    /// H_c < H_min: the two fits cross (they come from different papers) far outside
    /// their ranges; both numbers are returned as computed.
    pub central_below_minimum: bool,
}

impl LineFilmWarnings {
    /// `true` if no flag is raised.
    pub fn is_empty(&self) -> bool {
        *self == LineFilmWarnings::default()
    }

    /// One human-readable line per raised flag with the numbers of `regime`. Allocates;
    /// for reports.
    pub fn lines(&self, regime: &LineFilmRegime) -> Vec<String> {
        let mut out = Vec::new();
        if self.zero_entrainment {
            out.push(ZERO_ENTRAINMENT.to_string());
        }
        if self.outside_elastic_regime {
            out.push(format!(
                "Moes M = {:.3} < 10: the contact is not piezoviscous-elastic; the \
                 Dowson-Higginson film is extrapolated (L = {:.2})",
                regime.moes_m.unwrap_or(f64::NAN),
                regime.moes_l
            ));
        }
        if self.central_below_minimum {
            out.push(
                "the Dowson-Toyoda central film is below the Dowson-Higginson minimum film: \
                 both fits are far outside their range"
                    .to_string(),
            );
        }
        out
    }
}

/// A line-contact film result (isothermal, fully flooded: multiply by
/// [`zhu_cheng_thermal_factor`] and a starvation factor as needed).
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct LineFilm {
    /// Central film thickness h_c \[mm\].
    pub central: f64,
    /// Minimum film thickness h_min \[mm\].
    pub minimum: f64,
    /// The formula.
    pub formula: LineFilmFormula,
    /// The dimensionless groups.
    pub regime: LineFilmRegime,
    /// Validity flags.
    pub warnings: LineFilmWarnings,
}

/// The warning line of a zero entrainment speed (point and line contacts).
pub(crate) const ZERO_ENTRAINMENT: &str =
    "zero entrainment speed: no hydrodynamic film, boundary lubrication, h = 0";

/// M below which [`LineFilmWarnings::outside_elastic_regime`] is raised.
pub const LINE_ELASTIC_REGIME_M: f64 = 10.0;

/// The check of a mean surface speed `speed` \[mm/s\] (field `entrainment_speed`): finite
/// and ≥ 0. Returns it.
fn check_entrainment(speed: f64) -> Result<f64> {
    if speed.is_finite() && speed >= 0.0 {
        Ok(speed)
    } else {
        Err(Error::invalid(
            "entrainment_speed",
            speed,
            "a finite mean surface speed >= 0 mm/s",
        ))
    }
}

/// The checks that the point- and line-contact films share: `entrainment_speed` finite and
/// ≥ 0 mm/s; `reduced_modulus`, `viscosity`, `alpha` finite and > 0. Returns
/// (E*, η₀, α).
pub(crate) fn check_speed_and_oil(
    speed: f64,
    reduced_modulus: f64,
    viscosity: f64,
    alpha: f64,
) -> Result<(f64, f64, f64)> {
    check_entrainment(speed)?;
    Ok((
        positive(
            "reduced_modulus",
            reduced_modulus,
            "a finite contact modulus E* > 0 MPa",
        )?,
        positive(
            "viscosity",
            viscosity,
            "a finite dynamic viscosity > 0 MPa·s",
        )?,
        positive(
            "alpha",
            alpha,
            "a finite pressure-viscosity coefficient > 0 1/MPa",
        )?,
    ))
}

/// The dimensionless groups of `contact` for an oil of viscosity `viscosity` η₀ \[MPa·s\]
/// and pressure-viscosity coefficient `alpha` α \[1/MPa\], with the field checks of
/// [`line_film_thickness`].
///
/// # Errors
/// As [`line_film_thickness`].
pub fn line_film_regime(
    contact: &LineFilmContact,
    viscosity: f64,
    alpha: f64,
) -> Result<LineFilmRegime> {
    let r = positive("radius", contact.radius, "a finite reduced radius > 0 mm")?;
    let speed = contact.entrainment_speed;
    let load = positive(
        "load_per_length",
        contact.load_per_length,
        "a finite load per unit length > 0 N/mm",
    )?;
    let (e_star, eta, alpha) =
        check_speed_and_oil(speed, contact.reduced_modulus, viscosity, alpha)?;
    let e_prime = 2.0 * e_star;
    let g = alpha * e_prime;
    let w = load / (e_prime * r);
    let regime = speed_groups(
        LineFilmRegime {
            u: 0.0,
            g,
            w,
            moes_m: None,
            moes_l: 0.0,
            half_width: r * (8.0 * w / std::f64::consts::PI).sqrt(),
            max_pressure: e_prime * (w / (2.0 * std::f64::consts::PI)).sqrt(),
        },
        eta,
        speed,
        e_prime,
        r,
    )?;
    if !(g.is_finite() && w.is_finite() && w > 0.0 && regime.half_width.is_finite()) {
        return Err(Error::invalid(
            "load_per_length",
            load,
            "inputs for which G and W are finite, non-zero f64 (inputs too extreme)",
        ));
    }
    Ok(regime)
}

/// `regime` with its speed groups U, M and L at the mean speed `speed` \[mm/s\] (η₀ `eta`
/// \[MPa·s\], E′ `e_prime` \[MPa\], R `r` \[mm\]), checked; the load groups kept.
fn speed_groups(
    regime: LineFilmRegime,
    eta: f64,
    speed: f64,
    e_prime: f64,
    r: f64,
) -> Result<LineFilmRegime> {
    let u = eta * speed / (e_prime * r);
    let (moes_m, moes_l) = if speed == 0.0 {
        (None, 0.0)
    } else {
        let us = 2.0 * u;
        (Some(regime.w / us.sqrt()), regime.g * us.powf(0.25))
    };
    let speed_ok = u.is_finite() && (speed == 0.0 || u > 0.0) && moes_l.is_finite();
    if !(speed_ok && moes_m.is_none_or(f64::is_finite)) {
        return Err(Error::invalid(
            "entrainment_speed",
            speed,
            "a speed for which U, M and L are finite, non-zero f64 (inputs too extreme)",
        ));
    }
    Ok(LineFilmRegime {
        u,
        moes_m,
        moes_l,
        ..regime
    })
}

impl LineFilmRegime {
    /// The groups of the same contact at the mean speed of `contact` (its radius, load and
    /// modulus those this regime was made with, by [`line_film_regime`]): U, M and L
    /// recomputed, G, W and the Hertz values kept. Bit for bit [`line_film_regime`] of
    /// `contact`, without its load-dependent work (a speed sweep of one load distribution).
    ///
    /// # Errors
    /// [`Error::InvalidInput`] naming `entrainment_speed` (finite, ≥ 0, and U, M, L finite)
    /// or `viscosity` (finite, > 0).
    pub fn at_speed(&self, contact: &LineFilmContact, viscosity: f64) -> Result<LineFilmRegime> {
        let speed = check_entrainment(contact.entrainment_speed)?;
        let eta = positive(
            "viscosity",
            viscosity,
            "a finite dynamic viscosity > 0 MPa·s",
        )?;
        speed_groups(
            *self,
            eta,
            speed,
            2.0 * contact.reduced_modulus,
            contact.radius,
        )
    }
}

/// The speed-independent powers of G and W in a line-film formula (Dowson-Higginson:
/// G^0.56, W^−0.10 of the central film, G^0.54, W^−0.13 of the minimum film), from a
/// regime; [`line_film_with`] multiplies them by the speed's power in the formula's order.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LineFilmPowers {
    formula: LineFilmFormula,
    central: (f64, f64),
    minimum: (f64, f64),
}

impl LineFilmPowers {
    /// The powers of `regime`'s G and W in `formula`.
    pub fn of(regime: &LineFilmRegime, formula: LineFilmFormula) -> Self {
        let (g, w) = (regime.g, regime.w);
        match formula {
            LineFilmFormula::DowsonHigginson => LineFilmPowers {
                formula,
                central: (g.powf(0.56), w.powf(-0.10)),
                minimum: (g.powf(0.54), w.powf(-0.13)),
            },
        }
    }
}

/// The film of `contact` from its groups `regime` ([`line_film_regime`] or
/// [`LineFilmRegime::at_speed`]) and the powers `powers` of its G and W
/// ([`LineFilmPowers::of`] of a regime of the same contact at any speed): bit for bit
/// [`line_film_thickness`] by the powers' formula. No heap allocation.
///
/// # Errors
/// As [`line_film_thickness`] where the film leaves `f64`.
pub fn line_film_with(
    contact: &LineFilmContact,
    regime: &LineFilmRegime,
    powers: &LineFilmPowers,
) -> Result<LineFilm> {
    let u = regime.u;
    let zero = contact.entrainment_speed == 0.0;
    let (central, minimum) = if zero {
        (0.0, 0.0)
    } else {
        match powers.formula {
            LineFilmFormula::DowsonHigginson => (
                3.06 * u.powf(0.69) * powers.central.0 * powers.central.1 * contact.radius,
                2.65 * u.powf(0.70) * powers.minimum.0 * powers.minimum.1 * contact.radius,
            ),
        }
    };
    if !(central.is_finite() && minimum.is_finite()) {
        return Err(Error::invalid(
            "load_per_length",
            contact.load_per_length,
            "inputs for which the film is a finite f64 (inputs too extreme)",
        ));
    }
    let warnings = LineFilmWarnings {
        zero_entrainment: zero,
        outside_elastic_regime: regime.moes_m.is_some_and(|m| m < LINE_ELASTIC_REGIME_M),
        central_below_minimum: !zero && central < minimum,
    };
    Ok(LineFilm {
        central,
        minimum,
        formula: powers.formula,
        regime: *regime,
        warnings,
    })
}

/// The isothermal, fully flooded EHL film of the line contact `contact` lubricated by an
/// oil of inlet viscosity `viscosity` η₀ \[MPa·s\] (1 Pa·s = 1e-6 MPa·s) and
/// pressure-viscosity coefficient `alpha` α \[1/MPa\] (1e-8 m²/N = 0.01 1/MPa), by
/// `formula`. h_min = 2.65 U^0.70 G^0.54 W^−0.13 R and h_c = 3.06 U^0.69 G^0.56 W^−0.10 R
/// \[mm\]. Zero entrainment speed returns h = 0 with
/// [`LineFilmWarnings::zero_entrainment`]. No heap allocation.
///
/// # Errors
/// [`Error::InvalidInput`] naming the field: `radius`, `load_per_length`,
/// `reduced_modulus`, `viscosity`, `alpha` not finite or not > 0; `entrainment_speed`
/// negative or not finite; inputs so extreme that a group leaves `f64` name
/// `entrainment_speed` or `load_per_length`.
pub fn line_film_thickness(
    contact: &LineFilmContact,
    viscosity: f64,
    alpha: f64,
    formula: LineFilmFormula,
) -> Result<LineFilm> {
    let regime = line_film_regime(contact, viscosity, alpha)?;
    line_film_with(contact, &regime, &LineFilmPowers::of(&regime, formula))
}

/// The thermal loading parameter of Zhu & Cheng, L_T = (−∂η/∂T) u² / K (dimensionless),
/// from the temperature slope of the inlet viscosity `viscosity_slope` ∂η/∂T \[MPa·s/K\]
/// (negative for an oil), the mean speed `entrainment_speed` u \[mm/s\] and the thermal
/// conductivity of the oil `conductivity` K \[W/(m·K)\] (mineral oils ≈ 0.13-0.14). In
/// these units the ratio needs no conversion: MPa·s/K · mm²/s² = N/(s·K) = W/(m·K).
///
/// # Errors
/// [`Error::InvalidInput`] naming `viscosity_slope` (finite, ≤ 0), `entrainment_speed`
/// (finite, ≥ 0) or `conductivity` (finite, > 0).
pub fn thermal_loading(
    viscosity_slope: f64,
    entrainment_speed: f64,
    conductivity: f64,
) -> Result<f64> {
    if !(viscosity_slope.is_finite() && viscosity_slope <= 0.0) {
        return Err(Error::invalid(
            "viscosity_slope",
            viscosity_slope,
            "a finite temperature slope of the viscosity <= 0 MPa·s/K (oil thins when heated)",
        ));
    }
    check_entrainment(entrainment_speed)?;
    let k = positive(
        "conductivity",
        conductivity,
        "a finite thermal conductivity > 0 W/(m·K)",
    )?;
    let l = -viscosity_slope * entrainment_speed * entrainment_speed / k;
    if l.is_finite() {
        Ok(l)
    } else {
        Err(Error::invalid(
            "entrainment_speed",
            entrainment_speed,
            "a speed for which the thermal loading is a finite f64",
        ))
    }
}

/// The temperature slope ∂η/∂T \[MPa·s/K\] of the dynamic viscosity of `lubricant` at
/// `temperature_c` \[°C\], differentiated exactly from its Walther line
/// (log10 log10(ν + 0.7) = A − B log10 T): ∂ν/∂T = −(ν + 0.7) ln 10 · log10(ν + 0.7) · B / T,
/// ∂η/∂T = ρ ∂ν/∂T (density constant). Negative.
///
/// # Errors
/// As [`crate::lubrication::Lubricant::kinematic_viscosity`].
pub fn viscosity_temperature_slope(
    lubricant: &crate::lubrication::Lubricant,
    temperature_c: f64,
) -> Result<f64> {
    let nu = lubricant.kinematic_viscosity(temperature_c)?;
    let (_, b) = lubricant.walther_constants();
    let t = temperature_c + 273.15;
    let dnu_dt = -(nu + 0.7) * std::f64::consts::LN_10 * (nu + 0.7).log10() * b / t;
    // mm²/s → MPa·s as in `Lubricant::dynamic_viscosity`.
    Ok(dnu_dt * 1e-6 * lubricant.density() * 1e-6)
}

/// Inlet shear-heating (thermal) reduction factor of the film, Zhu & Cheng (as printed by
/// Zhou & Hoeprich 1991, eq. 21, and Wingertszahn et al. 2023, eq. 12):
///
/// ```text
/// φ_T = [1 − 13.2 (p_h/E′) L_T^0.42] / [1 + 0.213 (1 + 2.23 S^0.83) L_T^0.64]
/// ```
///
/// with `max_pressure` p_h \[MPa\], `reduced_modulus` E* \[MPa\] (E′ = 2E*),
/// `thermal_loading` L_T ([`thermal_loading`]) and `slide_roll` S = |v_s|/u (sliding
/// speed over mean speed, ≥ 0). φ_T = 1 at L_T = 0. Zhou & Hoeprich (eq. 22) apply the same
/// factor to the rolling resistance.
///
/// # Errors
/// [`Error::InvalidInput`] naming the field for a non-finite or negative input, a
/// non-positive `reduced_modulus`, or `thermal_loading` so large that the numerator is ≤ 0
/// (far outside the fit).
pub fn zhu_cheng_thermal_factor(
    max_pressure: f64,
    reduced_modulus: f64,
    thermal_loading: f64,
    slide_roll: f64,
) -> Result<f64> {
    for (field, v) in [
        ("max_pressure", max_pressure),
        ("thermal_loading", thermal_loading),
        ("slide_roll", slide_roll),
    ] {
        if !(v.is_finite() && v >= 0.0) {
            return Err(Error::invalid(field, v, "a finite value >= 0"));
        }
    }
    let e_star = positive(
        "reduced_modulus",
        reduced_modulus,
        "a finite contact modulus E* > 0 MPa",
    )?;
    let num = 1.0 - 13.2 * (max_pressure / (2.0 * e_star)) * thermal_loading.powf(0.42);
    if num <= 0.0 {
        return Err(Error::invalid(
            "thermal_loading",
            thermal_loading,
            "a thermal loading for which the Zhu-Cheng numerator 1 - 13.2 (p_h/E') L^0.42 > 0",
        ));
    }
    let den = 1.0 + 0.213 * (1.0 + 2.23 * slide_roll.powf(0.83)) * thermal_loading.powf(0.64);
    Ok(num / den)
}

/// Check a user-given film starvation factor φ_s in (0, 1] (Zhou & Hoeprich 1991, eq. 23:
/// F = φ_s φ_T F_iso, after Hamrock & Dowson 1981; 1 = fully flooded, their value in every
/// comparison). No formula for φ_s of a line contact was found in a readable source here;
/// the factor is the caller's. Returns it.
///
/// # Errors
/// [`Error::InvalidInput`] (`starvation_factor`) outside (0, 1].
pub fn film_starvation_factor(starvation_factor: f64) -> Result<f64> {
    if starvation_factor.is_finite() && starvation_factor > 0.0 && starvation_factor <= 1.0 {
        Ok(starvation_factor)
    } else {
        Err(Error::invalid(
            "starvation_factor",
            starvation_factor,
            "a film starvation factor in (0, 1] (1 = fully flooded)",
        ))
    }
}
