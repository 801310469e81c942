//! Hydrodynamic rolling resistance of an EHL line contact in pure rolling: the force per
//! unit length that the inlet pressure build-up and the Poiseuille shear of the oil oppose
//! to rolling (Crook's F_r0 = −½∫h ∂p/∂x dx), by the fit of Zhou & Hoeprich (1991) or of
//! Biboulet & Houpert (2010), and the Biboulet-Houpert starvation factor.
//!
//! Groups as in [`crate::lubrication::line_film_regime`] (E′ = 2E*, u the mean speed,
//! U = η₀u/(E′R), W = w/(E′R), G = αE′). With F̃ = f/(E′R) (f the force per unit length):
//!
//! ```text
//! Zhou & Hoeprich (1991, eq. 17):  f = 29.2 (R/α) (G U)^0.648 W^0.246
//!                                  ⇔ F̃ = 29.2 G^−0.352 U^0.648 W^0.246
//! Biboulet & Houpert (2010, eq. 42), in their groups U_B = 2U, M = W/√U_B:
//!   T* = M^−3/2 · 1.4 √M / (1 + ((1.4/1.45) √M)^10)^(1/10),   T* = t/(p_h b²)
//!   F̃ ≈ T̃ = t/(E′R²) = (8/(π√(2π))) W^(3/2) T*
//!      = (8/(π√(2π))) · 1.4 (U_B W)^(1/2) / (1 + ((1.4/1.45) √M)^10)^(1/10)
//! ```
//!
//! Asymptotes of the latter: rigid-isoviscous F̃ = 1.42 (U_B W)^(1/2) (M → 0), elastic
//! F̃ = 1.47 U_B^(3/4), independent of load and G (M → ∞) — Biboulet & Houpert eq. 40-41.
//! The moment on each body about its centre is t ≈ f R (their eq. 30-31); the power
//! dissipated per unit length is 2 f u (their eq. 45: (16/π²) M² ∫Θ dX = T, Newtonian,
//! derived in `docs/raceway-losses.md` §2.3).
//!
//! Units: f N/mm, t N·mm/mm, power W/mm; inputs as the film (mm, N/mm, MPa, mm/s, MPa·s,
//! 1/MPa). Sources and validation: `docs/raceway-losses.md`.

use super::line_film::LineFilmRegime;
use crate::error::{Error, Result, positive_as};

/// The rolling-resistance fit of an EHL line contact.
#[non_exhaustive]
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
#[cfg_attr(
    feature = "serde",
    derive(serde::Serialize, serde::Deserialize, schemars::JsonSchema)
)]
pub enum RollingResistanceModel {
    /// Zhou & Hoeprich (1991), eq. 17: f = 29.2 (R/α)(GU)^0.648 W^0.246, a power-law fit of
    /// their isothermal numerical EHL results (Table 1, G = 3745).
    ZhouHoeprich,
    /// Biboulet & Houpert (2010, Part 1), eq. 42: one fit from the rigid-isoviscous to the
    /// elastic regime (0.2 ≤ M ≤ 200, 4 ≤ L ≤ 16 computed), load- and G-independent in EHL.
    BibouletHoupert,
}

/// Rolling resistance of a line contact, per unit length.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct RollingResistance {
    /// Rolling-resistance force per unit length f \[N/mm\], ≥ 0, opposing the rolling.
    pub force_per_length: f64,
    /// Moment per unit length on each body about its centre t ≈ f R \[N·mm/mm = N\].
    pub moment_per_length: f64,
    /// Dissipated power per unit length 2 f u \[W/mm\].
    pub power_per_length: f64,
    /// The dimensionless force F̃ = f/(E′R).
    pub dimensionless: f64,
    /// The model.
    pub model: RollingResistanceModel,
}

/// 8/(π√(2π)): T̃ = this · W^(3/2) · T* (line Hertz: p_h = E′√(W/2π), b = 4Rp_h/E′).
pub const HERTZ_TO_CLASSICAL: f64 = 1.015_898_174_947_855_7;

/// The Zhou & Hoeprich (1991) dimensionless rolling force F̃ = 29.2 G^−0.352 U^0.648
/// W^0.246 (U on the mean speed). 0 at U = 0.
pub fn zhou_hoeprich_dimensionless(u: f64, g: f64, w: f64) -> f64 {
    if u == 0.0 {
        return 0.0;
    }
    29.2 * g.powf(-0.352) * u.powf(0.648) * w.powf(0.246)
}

/// The Biboulet & Houpert (2010) fully flooded moment T* = t/(p_h b²) as a function of
/// their load parameter `m` M = W/√(2U) (eq. 42).
pub fn biboulet_houpert_moment(m: f64) -> f64 {
    m.powf(-1.5) * 1.4 * m.sqrt() / transition(m)
}

/// The blend (1 + ((1.4/1.45)√M)^10)^(1/10) of eq. 42, written to stay finite for large M.
fn transition(m: f64) -> f64 {
    let x = 1.4 / 1.45 * m.sqrt();
    if x > 1.0 {
        x * (1.0 + x.powi(-10)).powf(0.1)
    } else {
        (1.0 + x.powi(10)).powf(0.1)
    }
}

/// The Biboulet & Houpert (2010) dimensionless rolling force F̃ ≈ T̃ = t/(E′R²) for the
/// groups U (mean speed) and W: (8/(π√(2π))) · 1.4 √(2UW) / (1 + ((1.4/1.45)√M)^10)^(1/10),
/// M = W/√(2U). 0 at U = 0.
pub fn biboulet_houpert_dimensionless(u: f64, w: f64) -> f64 {
    if u == 0.0 {
        return 0.0;
    }
    let ub = 2.0 * u;
    HERTZ_TO_CLASSICAL * 1.4 * (ub * w).sqrt() / transition(w / ub.sqrt())
}

/// The rolling resistance of a line contact of reduced radius `radius` R \[mm\], contact
/// modulus `reduced_modulus` E* \[MPa\] and mean speed `entrainment_speed` u \[mm/s\], from
/// its groups `regime` ([`crate::lubrication::line_film_regime`]), isothermal and fully
/// flooded (multiply by φ_T and [`biboulet_houpert_starvation`] as needed).
///
/// # Errors
/// [`Error::InvalidInput`] naming `radius`, `reduced_modulus` (finite, > 0) or
/// `entrainment_speed` (finite, ≥ 0).
pub fn rolling_resistance(
    regime: &LineFilmRegime,
    radius: f64,
    reduced_modulus: f64,
    entrainment_speed: f64,
    model: RollingResistanceModel,
) -> Result<RollingResistance> {
    positive_as("radius", radius, "a finite reduced radius > 0 mm")?;
    positive_as(
        "reduced_modulus",
        reduced_modulus,
        "a finite contact modulus E* > 0 MPa",
    )?;
    if !(entrainment_speed.is_finite() && entrainment_speed >= 0.0) {
        return Err(Error::invalid(
            "entrainment_speed",
            entrainment_speed,
            "a finite mean surface speed >= 0 mm/s",
        ));
    }
    let dimensionless = match model {
        RollingResistanceModel::ZhouHoeprich => {
            zhou_hoeprich_dimensionless(regime.u, regime.g, regime.w)
        }
        RollingResistanceModel::BibouletHoupert => {
            biboulet_houpert_dimensionless(regime.u, regime.w)
        }
    };
    let force = dimensionless * 2.0 * reduced_modulus * radius;
    let power = 2.0 * force * entrainment_speed * 1e-3;
    if !(force.is_finite() && power.is_finite()) {
        return Err(Error::invalid(
            "entrainment_speed",
            entrainment_speed,
            "inputs for which the rolling force and power are finite f64",
        ));
    }
    Ok(RollingResistance {
        force_per_length: force,
        moment_per_length: force * radius,
        power_per_length: power,
        dimensionless,
        model,
    })
}

/// Smallest degree of starvation S that Biboulet & Houpert (2010) computed (S = 2);
/// below it [`biboulet_houpert_starvation`] extrapolates.
pub const BIBOULET_HOUPERT_MIN_STARVATION: f64 = 2.0;

/// The Biboulet & Houpert (2010, eq. 44) starvation factor of the rolling resistance
/// T/T* = (S² + 162.8 S)/(S² + 193.1 S + 1257), with S = h_a/h*_min the oil film thickness
/// available at the inlet over the fully flooded minimum film (any common length unit).
/// → 1 as S → ∞; 0.200 at S = 2, the most starved case computed. Returns the factor and
/// whether S lies below the computed range.
///
/// # Errors
/// [`Error::InvalidInput`] (`starvation_degree`) for S not finite or < 0.
pub fn biboulet_houpert_starvation(starvation_degree: f64) -> Result<(f64, bool)> {
    let s = starvation_degree;
    if !(s.is_finite() && s >= 0.0) {
        return Err(Error::invalid(
            "starvation_degree",
            s,
            "a finite inlet-to-minimum film ratio S = h_a/h_min >= 0",
        ));
    }
    // Divide through by S² for large S to stay finite.
    let f = if s > 1e8 {
        (1.0 + 162.8 / s) / (1.0 + 193.1 / s + 1257.0 / (s * s))
    } else {
        (s * s + 162.8 * s) / (s * s + 193.1 * s + 1257.0)
    };
    Ok((f, s < BIBOULET_HOUPERT_MIN_STARVATION))
}
