//! Elastohydrodynamic (EHL) film thickness of an elliptical contact: the Hamrock-Dowson
//! (1977) central and minimum film, the Chittenden-Dowson-Dunn-Taylor (1985) central film
//! for entrainment at any angle to the ellipse axes, entrainment at any angle through the
//! radius in the entrainment direction, and the dimensionless groups that place the contact
//! on the regime map (Hamrock-Dowson U, G, W and k; Moes M and L; the viscosity and
//! elasticity parameters g_V and g_E).
//!
//! Units: lengths mm, force N, modulus MPa, speed mm/s, viscosity MPa·s, pressure-viscosity
//! coefficient 1/MPa. Every group is a ratio of the same quantities in consistent units
//! (U = η₀u/(E′R): MPa·s · mm/s / (MPa · mm); W = Q/(E′R²): N / (N/mm² · mm²); G = αE′), so
//! they are computed directly in these units without conversion.
//!
//! [`film_thickness`] is a pure function of `Copy` data: it allocates nothing and can be
//! called once per contact in a hot loop. Its validity limits are reported as
//! [`FilmWarnings`], never hidden; see `docs/film.md` for the formulas, their sources, what
//! was not implemented (the Chittenden et al. minimum film, Nijenbanning-Venner-Moes 1994)
//! and why.

use crate::error::{Error, Result};

/// Geometry and kinematics of an elliptical EHL contact.
///
/// `rx` and `ry` are the reduced (relative) principal radii of curvature of the gap,
/// 1/R = 1/R₁ + 1/R₂ along each principal direction (Hamrock's R_x, R_y). Both must be
/// finite and positive: one infinite radius is a line contact and both infinite a flat
/// gap, neither of which the point-contact formulas describe.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(
    feature = "serde",
    derive(serde::Serialize, serde::Deserialize, schemars::JsonSchema)
)]
pub struct FilmContact {
    /// Reduced radius of curvature along the contact's x axis \[mm\], finite and > 0.
    pub rx: f64,
    /// Reduced radius of curvature along the contact's y axis \[mm\], finite and > 0.
    pub ry: f64,
    /// Angle of the entrainment (mean surface) velocity from the x axis \[rad\], any finite
    /// value; θ and θ + π give the same film.
    pub entrainment_angle: f64,
    /// |u|, the mean surface speed (u₁ + u₂)/2 relative to the contact \[mm/s\], finite and
    /// ≥ 0. Zero gives the boundary-lubrication result h = 0 with a warning.
    pub entrainment_speed: f64,
    /// Normal force \[N\], finite and > 0.
    pub load: f64,
    /// Contact modulus E* \[MPa\] (Johnson 1985, 1/E* = (1−ν₁²)/E₁ + (1−ν₂²)/E₂), finite and
    /// > 0. Hamrock and Dowson's E′ is 2E*.
    pub reduced_modulus: f64,
}

/// The film-thickness formula.
///
/// The regime-spanning central-film formula of Nijenbanning, Venner & Moes (1994) is not
/// implemented: its constants were found only in one third-party code, not in the paper nor
/// in a second independent transcription (see `docs/film.md` §4). The enum is
/// non-exhaustive so that it can be added without breaking callers.
#[non_exhaustive]
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
#[cfg_attr(
    feature = "serde",
    derive(serde::Serialize, serde::Deserialize, schemars::JsonSchema)
)]
pub enum FilmFormula {
    /// Hamrock & Dowson (1977), isothermal, fully flooded, Newtonian point contact:
    /// H_c = 2.69 U^0.67 G^0.53 W^−0.067 (1 − 0.61 e^(−0.73k)),
    /// H_min = 3.63 U^0.68 G^0.49 W^−0.073 (1 − e^(−0.68k)), k = 1.03 (R_s/R_e)^0.64, all
    /// referred to the radius R_e in the entrainment direction. Fitted for entrainment
    /// along x (θ = 0) and 1 ≤ k ≤ 8.
    HamrockDowson,
    /// Chittenden, Dowson, Dunn & Taylor (1985), isothermal central film for entrainment
    /// at any angle to the axes of the contact ellipse:
    /// H_c = h_c/R_e = 4.30 U^0.68 G^0.49 W^−0.073 (1 − e^(−1.30 (R_s/R_e)^(2/3))), with
    /// U and W referred to R_e (constants as printed by the tribonet.org EHL point-contact
    /// calculator; Zhou & Hoeprich 1991 eq. 31 print 1.28 for the 1.30, a difference of at
    /// most 1.6 % in h_c — see `docs/film.md` §3). No Chittenden minimum film could be
    /// read in a source: `minimum` is the Hamrock-Dowson minimum at the same R_e and R_s,
    /// flagged by [`FilmWarnings::minimum_from_hamrock_dowson`]. The formula that the
    /// roller-end/rib contact (entrainment along the major axis, R_s < R_e) should use for
    /// its central film; see `docs/film.md` §5.
    Chittenden,
}

/// The dimensionless groups of the contact, all referred to the radius in the
/// entrainment direction R_e (Hamrock-Dowson convention, E′ = 2E*, u = mean speed).
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct FilmRegime {
    /// R_e, reduced radius in the entrainment direction \[mm\]:
    /// 1/R_e = cos²θ/R_x + sin²θ/R_y.
    pub radius_entrainment: f64,
    /// R_s, reduced radius across the entrainment (side-leakage direction) \[mm\]:
    /// 1/R_s = sin²θ/R_x + cos²θ/R_y.
    pub radius_side: f64,
    /// Speed parameter U = η₀u/(E′R_e).
    pub u: f64,
    /// Material parameter G = αE′.
    pub g: f64,
    /// Load parameter W = Q/(E′R_e²).
    pub w: f64,
    /// Ellipticity k = 1.03 (R_s/R_e)^0.64 (Hamrock & Dowson 1977); k < 1 when the
    /// entrainment runs along the major axis of the contact ellipse.
    pub k: f64,
    /// Moes load parameter M = W (2U)^(−3/4) (sum-velocity speed parameter 2U); `None`
    /// at zero entrainment speed, where it diverges.
    pub moes_m: Option<f64>,
    /// Moes material parameter L = G (2U)^(1/4); 0 at zero entrainment speed.
    pub moes_l: f64,
    /// Viscosity parameter g_V = G W³/U² (Hamrock & Dowson's point-contact form of
    /// Johnson's 1970 parameter); `None` at zero entrainment speed.
    pub g_v: Option<f64>,
    /// Elasticity parameter g_E = W^(8/3)/U²; `None` at zero entrainment speed.
    pub g_e: Option<f64>,
}

/// Validity flags of a film-thickness result: `Copy`, no allocation. A raised flag means
/// the number was computed but lies where the formula was not fitted or does not apply;
/// [`FilmWarnings::lines`] turns them into one sentence each.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct FilmWarnings {
    /// Zero entrainment speed: no hydrodynamic film, boundary lubrication, h = 0.
    pub zero_entrainment: bool,
    /// The entrainment is not along a principal axis (sin 2θ ≠ 0 and R_x ≠ R_y):
    /// Hamrock-Dowson was fitted for θ = 0 only; here it is applied with R_e and R_s.
    pub oblique_entrainment: bool,
    /// k < 1: entrainment along the major axis of the ellipse (side leakage dominates),
    /// below the fitted 1 ≤ k ≤ 8. Typical of the roller-end/rib contact.
    pub ellipticity_below_fit: bool,
    /// k > 8: above the fitted 1 ≤ k ≤ 8 (towards a line contact).
    pub ellipticity_above_fit: bool,
    /// The formula gives a central film only ([`FilmFormula::Chittenden`]): `minimum` is
    /// the Hamrock-Dowson minimum film at the same R_e and R_s (an extrapolation outside
    /// θ = 0 and 1 ≤ k ≤ 8, which the other flags report).
    pub minimum_from_hamrock_dowson: bool,
}

impl FilmWarnings {
    /// `true` if no flag is raised.
    pub fn is_empty(&self) -> bool {
        *self == FilmWarnings::default()
    }

    /// Number of raised flags.
    pub fn count(&self) -> usize {
        [
            self.zero_entrainment,
            self.oblique_entrainment,
            self.ellipticity_below_fit,
            self.ellipticity_above_fit,
            self.minimum_from_hamrock_dowson,
        ]
        .iter()
        .filter(|&&f| f)
        .count()
    }

    /// One human-readable line per raised flag, with the numbers of `regime` (the regime of
    /// the same result). Allocates; meant for reports, not for the hot loop.
    pub fn lines(&self, regime: &FilmRegime) -> Vec<String> {
        let mut out = Vec::with_capacity(self.count());
        if self.zero_entrainment {
            out.push(super::line_film::ZERO_ENTRAINMENT.to_string());
        }
        if self.oblique_entrainment {
            out.push(format!(
                "entrainment not along a principal axis: Hamrock-Dowson was fitted for \
                 entrainment along x only; applied with R_e = {:.4} mm, R_s = {:.4} mm",
                regime.radius_entrainment, regime.radius_side
            ));
        }
        if self.ellipticity_below_fit {
            out.push(format!(
                "k = {:.3} is outside the Hamrock-Dowson fit 1 <= k <= 8 (entrainment along \
                 the major axis of the ellipse): extrapolated",
                regime.k
            ));
        }
        if self.ellipticity_above_fit {
            out.push(format!(
                "k = {:.3} is outside the Hamrock-Dowson fit 1 <= k <= 8: extrapolated",
                regime.k
            ));
        }
        if self.minimum_from_hamrock_dowson {
            out.push(
                "the formula gives the central film only: the minimum film is the \
                 Hamrock-Dowson minimum at the same R_e and R_s"
                    .to_string(),
            );
        }
        out
    }
}

/// A film-thickness result.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct FilmThickness {
    /// Central film thickness h_c \[mm\].
    pub central: f64,
    /// Minimum film thickness h_min \[mm\].
    pub minimum: f64,
    /// The formula that produced the numbers.
    pub formula: FilmFormula,
    /// The dimensionless groups of the contact.
    pub regime: FilmRegime,
    /// Validity flags.
    pub warnings: FilmWarnings,
}

impl FilmThickness {
    /// One human-readable line per raised warning (see [`FilmWarnings::lines`]).
    pub fn warning_lines(&self) -> Vec<String> {
        self.warnings.lines(&self.regime)
    }
}

/// Lower and upper end of the ellipticity range 1 ≤ k ≤ 8 of the Hamrock-Dowson fit
/// (Hamrock & Dowson 1977, abstract: "The ellipticity parameter was varied from one ... to
/// eight").
pub const HAMROCK_DOWSON_K_RANGE: (f64, f64) = (1.0, 8.0);

/// The constants (C, c) of the Chittenden et al. (1985) central film
/// H_c = C U^0.68 G^0.49 W^−0.073 (1 − e^(−c (R_s/R_e)^(2/3))), as printed by the tribonet.org
/// EHL point-contact calculator (eq. 3, θ = 0 form with R_Y/R_X). Zhou & Hoeprich (1991)
/// eq. 31 print C = 4.30 and c = 1.28 (see `docs/film.md` §3).
pub const CHITTENDEN_CENTRAL: (f64, f64) = (4.30, 1.30);

/// |sin 2θ| above which the entrainment counts as oblique (not along x or y).
const OBLIQUE_TOLERANCE: f64 = 1e-9;

fn positive_field(field: &'static str, value: f64, expected: &'static str) -> Result<f64> {
    if value.is_finite() && value > 0.0 {
        Ok(value)
    } else {
        Err(Error::invalid(field, value, expected))
    }
}

/// The EHL film thickness of `contact` lubricated by an oil of inlet viscosity `viscosity`
/// η₀ \[MPa·s\] (at the inlet temperature; 1 Pa·s = 1e-6 MPa·s) and pressure-viscosity
/// coefficient `alpha` α \[1/MPa\] (1e-8 m²/N = 0.01 1/MPa), by `formula`.
///
/// Entrainment at an angle θ to x is handled by referring the groups to the radius in the
/// entrainment direction R_e and the ellipticity to R_s/R_e (1/R_e = cos²θ/R_x +
/// sin²θ/R_y, 1/R_s = sin²θ/R_x + cos²θ/R_y); at θ = 0 this is exactly Hamrock-Dowson, at
/// other angles it is an extrapolation and [`FilmWarnings::oblique_entrainment`] is raised.
/// [`FilmFormula::Chittenden`] is a fit for any entrainment angle: it raises no oblique
/// warning, and takes its minimum film from Hamrock-Dowson (flagged).
/// Zero entrainment speed returns h = 0 (boundary lubrication) with
/// [`FilmWarnings::zero_entrainment`], not an error. No heap allocation.
///
/// # Errors
/// [`Error::InvalidInput`] naming the field: `rx`, `ry`, `load`, `reduced_modulus`,
/// `viscosity`, `alpha` not finite or not > 0; `entrainment_speed` negative or not finite;
/// `entrainment_angle` not finite. If the inputs are so extreme that a group leaves the
/// range of `f64`, the error names `entrainment_speed` (U underflows or M overflows) or
/// `load`.
pub fn film_thickness(
    contact: &FilmContact,
    viscosity: f64,
    alpha: f64,
    formula: FilmFormula,
) -> Result<FilmThickness> {
    let rx = positive_field("rx", contact.rx, "a finite reduced radius > 0 mm")?;
    let ry = positive_field("ry", contact.ry, "a finite reduced radius > 0 mm")?;
    let theta = contact.entrainment_angle;
    if !theta.is_finite() {
        return Err(Error::invalid(
            "entrainment_angle",
            theta,
            "a finite angle in rad",
        ));
    }
    let speed = contact.entrainment_speed;
    let load = positive_field("load", contact.load, "a finite normal force > 0 N")?;
    let (e_star, eta, alpha) =
        super::line_film::check_speed_and_oil(speed, contact.reduced_modulus, viscosity, alpha)?;

    let (sin, cos) = theta.sin_cos();
    let (s2, c2) = (sin * sin, cos * cos);
    let radius_entrainment = 1.0 / (c2 / rx + s2 / ry);
    let radius_side = 1.0 / (s2 / rx + c2 / ry);
    let e_prime = 2.0 * e_star;

    let u = eta * speed / (e_prime * radius_entrainment);
    let g = alpha * e_prime;
    let w = load / (e_prime * radius_entrainment * radius_entrainment);
    let k = 1.03 * (radius_side / radius_entrainment).powf(0.64);

    let zero = speed == 0.0;
    let (moes_m, moes_l, g_v, g_e) = if zero {
        (None, 0.0, None, None)
    } else {
        let us = 2.0 * u;
        (
            Some(w * us.powf(-0.75)),
            g * us.powf(0.25),
            Some(g * w.powi(3) / (u * u)),
            Some(w.powf(8.0 / 3.0) / (u * u)),
        )
    };
    let regime = FilmRegime {
        radius_entrainment,
        radius_side,
        u,
        g,
        w,
        k,
        moes_m,
        moes_l,
        g_v,
        g_e,
    };

    // Hamrock-Dowson minimum film, also the minimum of the central-only formulas.
    let hd_minimum = || {
        3.63 * u.powf(0.68)
            * g.powf(0.49)
            * w.powf(-0.073)
            * (1.0 - (-0.68 * k).exp())
            * radius_entrainment
    };
    let (central, minimum) = if zero {
        (0.0, 0.0)
    } else {
        match formula {
            FilmFormula::HamrockDowson => {
                let hc = 2.69
                    * u.powf(0.67)
                    * g.powf(0.53)
                    * w.powf(-0.067)
                    * (1.0 - 0.61 * (-0.73 * k).exp());
                (hc * radius_entrainment, hd_minimum())
            }
            FilmFormula::Chittenden => {
                let (c0, c1) = CHITTENDEN_CENTRAL;
                let ratio = (radius_side / radius_entrainment).powf(2.0 / 3.0);
                let hc =
                    c0 * u.powf(0.68) * g.powf(0.49) * w.powf(-0.073) * (1.0 - (-c1 * ratio).exp());
                (hc * radius_entrainment, hd_minimum())
            }
        }
    };

    // Never return NaN or infinity: inputs at the edge of f64 are refused instead.
    let speed_groups_finite = u.is_finite()
        && (zero || u > 0.0)
        && moes_l.is_finite()
        && [moes_m, g_v, g_e]
            .iter()
            .all(|v| v.is_none_or(|x| x.is_finite()));
    if !speed_groups_finite {
        return Err(Error::invalid(
            "entrainment_speed",
            speed,
            "a speed for which U, M, g_V and g_E are finite, non-zero f64 (inputs too extreme)",
        ));
    }
    let all_finite = [radius_entrainment, radius_side, g, w, k, central, minimum]
        .iter()
        .all(|v| v.is_finite());
    if !all_finite {
        return Err(Error::invalid(
            "load",
            load,
            "inputs for which the groups G, W, k and the film are finite f64 (inputs too extreme)",
        ));
    }

    let (k_lo, k_hi) = HAMROCK_DOWSON_K_RANGE;
    let warnings = FilmWarnings {
        zero_entrainment: zero,
        // For R_x = R_y every direction is principal: no warning. Chittenden et al. fitted
        // every entrainment angle.
        oblique_entrainment: formula == FilmFormula::HamrockDowson
            && (2.0 * theta).sin().abs() > OBLIQUE_TOLERANCE
            && (rx / ry - 1.0).abs() > OBLIQUE_TOLERANCE,
        ellipticity_below_fit: k < k_lo,
        ellipticity_above_fit: k > k_hi,
        minimum_from_hamrock_dowson: formula == FilmFormula::Chittenden && !zero,
    };

    Ok(FilmThickness {
        central,
        minimum,
        formula,
        regime,
        warnings,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    fn contact() -> FilmContact {
        FilmContact {
            rx: 5.0,
            ry: 50.0,
            entrainment_angle: 0.0,
            entrainment_speed: 5_000.0,
            load: 1_000.0,
            reduced_modulus: 115_000.0,
        }
    }

    #[test]
    fn groups_follow_their_definitions() {
        let f = film_thickness(&contact(), 0.04e-6, 0.02, FilmFormula::HamrockDowson).unwrap();
        let r = f.regime;
        let ep = 230_000.0;
        assert!((r.u / (0.04e-6 * 5_000.0 / (ep * 5.0)) - 1.0).abs() < 1e-14);
        assert!((r.g / (0.02 * ep) - 1.0).abs() < 1e-14);
        assert!((r.w / (1_000.0 / (ep * 25.0)) - 1.0).abs() < 1e-14);
        assert!((r.k / (1.03 * 10f64.powf(0.64)) - 1.0).abs() < 1e-14);
        assert!(f.warnings.is_empty(), "{:?}", f.warning_lines());
    }
}
