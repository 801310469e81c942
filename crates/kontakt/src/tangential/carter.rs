//! Carter's creep curve: steady rolling of two elastic cylinders (plane strain) with a
//! longitudinal creepage, in closed form.
//!
//! # Formulas
//! Hertz strip of half-width `a`, maximum pressure `p0`, line load `P' = pi a p0/2`. The
//! adhesion zone is a strip of width `2c` at the *leading* edge, the slip zone is at the
//! rear (Johnson (1982) Fig. 8d). With `d = a - c` the traction on body 1 is
//!
//! ```text
//! q(x) = -sgn(ξ) μ p₀ [√(1 - x²/a²) - (c/a) √(1 - (x - d)²/c²)]
//! ```
//!
//! (the second term only in the adhesion zone `a - 2c <= x <= a`). The adhesion condition
//! (equal tangential strains of the two surfaces) gives `|xi| = 2 mu p0 d/(a E*)`, so with
//! the saturation creepage
//!
//! ```text
//! ξ_s = 2 μ p₀ / E*     (= μ a / R for cylinders, since p₀ = a E* / (2R))
//! ```
//!
//! the stick width is `c/a = 1 - |xi|/xi_s` and the force is
//!
//! ```text
//! F_T / (μ P') = 1 - (1 - |ξ|/ξ_s)²   (|ξ| < ξ_s),   1 beyond
//! ```
//!
//! (the thesis' eq. 3.8 with its normalized creepage `xi/xi_s`; Johnson 1985 §8.3
//! in the form `xi = (mu a/R)(1 - sqrt(1 - Q/(mu P)))`). The initial slope is
//! `dF_T/dxi = 2 mu P'/xi_s = pi a E*/2` per unit length. The derivation is in
//! `docs/tangential.md`.
//!
//! # Assumptions
//! Plane strain, elastic half-spaces, Coulomb friction with one coefficient, steady
//! rolling, pressure unaffected by the traction (beta = 0: identical or quasi-identical
//! materials). Applied to a point contact ([`Carter::from_ellipse`]) it is the 2D curve
//! of the central strip `y = 0`, an approximation (see the constructor).
//!
//! # References
//! - Carter (1926), "On the action of a locomotive driving wheel", Proc. R. Soc. A 112,
//!   151-157. doi:10.1098/rspa.1926.0100
//! - Johnson (1982), §6(c) and Fig. 10.
//! - Thesis "Study of the traction curves", eq. (3.8).
//! - Johnson, *Contact Mechanics* (1985), §8.3.

use super::{ContactEllipse, TractionCurve, check_creepage, check_friction};
use crate::error::{Error, Result, positive_as};
use crate::hertz::line::LineContact;
use crate::material::{ElasticMaterial, effective_modulus};
use crate::units::{Megapascal, Millimetre, NewtonPerMillimetre};
use std::f64::consts::PI;

/// Carter's rolling contact of a Hertz strip: see the module docs for the formulas.
///
/// # Example
/// Two steel discs of radius 20 mm (R = 10 mm), 800 N/mm, mu = 0.1: the saturation
/// creepage is `mu a/R`, and at half of it the force is `0.75 mu P'`.
/// ```
/// use kontakt::{hertz::line::LineContact, material::ElasticMaterial};
/// use kontakt::tangential::{Carter, TractionCurve};
/// let s = ElasticMaterial::STEEL;
/// let carter = Carter::from_line_contact(&LineContact::new(20.0, 20.0, s, s)?, 800.0, 0.1)?;
/// let a = carter.semi_width();
/// assert!((carter.saturation_creepage() - 0.1 * a / 10.0).abs() < 1e-15);
/// let half = 0.5 * carter.saturation_creepage();
/// assert!((carter.normalized_force(half)? - 0.75).abs() < 1e-12);
/// # Ok::<(), kontakt::Error>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct Carter {
    semi_width: Millimetre,
    max_pressure: Megapascal,
    e_star: Megapascal,
    friction: f64,
}

impl Carter {
    /// Carter's contact from the Hertz strip: half-width `semi_width` `a` \[mm\], maximum
    /// pressure `max_pressure` `p0` \[MPa\], contact modulus `e_star` `E*` \[MPa\] and the
    /// friction coefficient `mu` \[-\]; all finite and > 0.
    ///
    /// # Errors
    /// [`Error::InvalidInput`] naming `semi_width`, `max_pressure`, `e_star` or
    /// `friction_coefficient`.
    pub fn new(
        semi_width: Millimetre,
        max_pressure: Megapascal,
        e_star: Megapascal,
        mu: f64,
    ) -> Result<Self> {
        positive_as("semi_width", semi_width, "a finite half-width > 0 mm")?;
        positive_as("max_pressure", max_pressure, "a finite pressure > 0 MPa")?;
        positive_as("e_star", e_star, "a finite modulus > 0 MPa")?;
        let friction = check_friction(mu)?;
        Ok(Carter {
            semi_width,
            max_pressure,
            e_star,
            friction,
        })
    }

    /// Carter's contact of two cylinders (a planned [`LineContact`]) under the line load
    /// `line_load` `P'` [N/mm] (> 0) with friction `mu` \[-\] (> 0).
    ///
    /// # Errors
    /// [`Error::InvalidInput`] naming `line_load` or `friction_coefficient`.
    pub fn from_line_contact(
        contact: &LineContact,
        line_load: NewtonPerMillimetre,
        mu: f64,
    ) -> Result<Self> {
        let sol = contact.solve(line_load)?;
        Self::new(sol.half_width, sol.max_pressure, contact.e_star(), mu)
    }

    /// Carter's curve applied to the central strip `y = 0` of an elliptical contact: the
    /// strip of half-width `a` (the rolling-direction semi-axis) under the Hertz `p0`, so
    /// that `xi_s = 2 mu p0/E*`. This is the "strip" approximation: it ignores the
    /// three-dimensional elastic coupling between strips, which Kalker's theory
    /// ([`super::KalkerLinear`], [`super::Fastsim`]) includes. The initial slopes of the
    /// normalized curves differ by the factor `2 pi E*/(3 G C11)` (0.70 for a circular
    /// steel contact, nu = 0.3; `docs/tangential.md`).
    ///
    /// # Errors
    /// [`Error::InvalidInput`] naming `friction_coefficient` or `materials`.
    pub fn from_ellipse(
        ellipse: &ContactEllipse,
        body1: &ElasticMaterial,
        body2: &ElasticMaterial,
        mu: f64,
    ) -> Result<Self> {
        let [m1, m2] = super::check_materials(body1, body2)?;
        Self::new(
            ellipse.a(),
            ellipse.max_pressure(),
            effective_modulus(&m1, &m2),
            mu,
        )
    }

    /// Half-width `a` of the strip \[mm\].
    pub fn semi_width(&self) -> Millimetre {
        self.semi_width
    }
    /// Maximum pressure `p0` \[MPa\].
    pub fn max_pressure(&self) -> Megapascal {
        self.max_pressure
    }
    /// Friction coefficient `mu` \[-\].
    pub fn friction_coefficient(&self) -> f64 {
        self.friction
    }
    /// Line load `P' = pi a p0/2` [N/mm].
    pub fn line_load(&self) -> NewtonPerMillimetre {
        0.5 * PI * self.semi_width * self.max_pressure
    }

    /// Saturation creepage `xi_s = 2 mu p0/E*` \[-\]: from here on the whole strip slides.
    pub fn saturation_creepage(&self) -> f64 {
        2.0 * self.friction * self.max_pressure / self.e_star
    }

    /// Creep coefficient `dF_T/dxi` at zero creepage, per unit length: `pi a E*/2` [N/mm].
    pub fn creep_coefficient(&self) -> NewtonPerMillimetre {
        0.5 * PI * self.semi_width * self.e_star
    }

    /// Tangential force per unit length on body 1, `-sgn(xi) mu P' [1 - (1 - |xi|/xi_s)²]`
    /// [N/mm], at the creepage `creepage` \[-\] (finite).
    ///
    /// # Errors
    /// [`Error::InvalidInput`] naming `creepage`.
    pub fn force_per_length(&self, creepage: f64) -> Result<NewtonPerMillimetre> {
        Ok(-self.friction * self.line_load() * self.normalized_force(creepage)?)
    }

    /// The creepage \[-\] that transmits the normalized force `normalized` `= F_T/(mu P')`
    /// \[-\], `-1 < normalized < 1`: `xi = xi_s (1 - sqrt(1 - |f|)) sgn(f)`.
    ///
    /// # Errors
    /// [`Error::InvalidInput`] naming `normalized_force` outside (-1, 1) (at ±1 the
    /// creepage is any value beyond `xi_s`).
    pub fn creepage_from_force(&self, normalized: f64) -> Result<f64> {
        if !(normalized.abs() < 1.0) {
            return Err(Error::invalid(
                "normalized_force",
                normalized,
                "-1 < F_T/(mu P') < 1",
            ));
        }
        Ok(self.saturation_creepage()
            * (1.0 - (1.0 - normalized.abs()).sqrt())
            * normalized.signum())
    }

    /// Half-width `c` of the adhesion zone \[mm\]: `c = a (1 - |xi|/xi_s)`, zero beyond
    /// saturation. The zone is `a - 2c <= x <= a`, at the leading edge.
    ///
    /// # Errors
    /// [`Error::InvalidInput`] naming `creepage`.
    pub fn stick_half_width(&self, creepage: f64) -> Result<Millimetre> {
        check_creepage(creepage)?;
        Ok(self.semi_width * (1.0 - creepage.abs() / self.saturation_creepage()).max(0.0))
    }

    /// Tangential traction on body 1 \[MPa\] at `x` \[mm\] (rolling direction `+x`, leading
    /// edge `x = +a`) for the creepage `creepage` \[-\]; zero outside `|x| < a`.
    ///
    /// # Errors
    /// [`Error::InvalidInput`] naming `creepage`.
    pub fn traction_at(&self, creepage: f64, x: Millimetre) -> Result<Megapascal> {
        let c = self.stick_half_width(creepage)?;
        let a = self.semi_width;
        if !(x.abs() < a) || creepage == 0.0 {
            return Ok(0.0);
        }
        let mut q = (1.0 - (x / a).powi(2)).sqrt();
        let d = a - c;
        if c > 0.0 && (x - d).abs() < c {
            q -= c / a * (1.0 - ((x - d) / c).powi(2)).sqrt();
        }
        Ok(-creepage.signum() * self.friction * self.max_pressure * q)
    }
}

impl TractionCurve for Carter {
    fn name(&self) -> &'static str {
        "carter"
    }

    /// `sgn(xi) [1 - (1 - |xi|/xi_s)²]` for `|xi| < xi_s`, `sgn(xi)` beyond.
    fn normalized_force(&self, creepage: f64) -> Result<f64> {
        check_creepage(creepage)?;
        let s = (creepage.abs() / self.saturation_creepage()).min(1.0);
        Ok(creepage.signum() * (1.0 - (1.0 - s) * (1.0 - s)) * f64::from(creepage != 0.0))
    }
}
