//! Lubricant properties, the film parameter and the EHL film thickness: the lubricant film
//! model.
//!
//! * [`Lubricant`]: kinematic viscosity at 40 °C and 100 °C, density and pressure-viscosity
//!   coefficient, validated field by field; viscosity at any temperature in
//!   [`TEMPERATURE_RANGE_C`] by the Ubbelohde-Walther relation of ASTM D341;
//!   [`Lubricant::iso_vg`] builds typical ISO VG grades.
//! * [`film_parameter`]: Λ = h / √(σ₁² + σ₂²).
//! * [`film_thickness`] (submodule `film`, re-exported here): the Hamrock-Dowson (1977)
//!   central and minimum film of an elliptical contact and the Chittenden et al. (1985)
//!   central film for entrainment at any angle ([`FilmFormula`]), entrainment at any angle
//!   through the radius in the entrainment direction, the dimensionless groups (U, G, W, k,
//!   Moes M and L, g_V and g_E) and validity warnings ([`FilmWarnings`]).
//! * [`line_film_thickness`] (submodule `line_film`): the line contact (a roller slice) —
//!   Dowson-Higginson minimum and Dowson-Toyoda central film, the groups per unit length,
//!   Moes M and L, the Zhu-Cheng thermal factor and a starvation factor.
//! * [`rolling_resistance()`] (submodule `rolling_resistance`): the hydrodynamic rolling
//!   resistance of the line contact, Zhou & Hoeprich (1991) or Biboulet & Houpert (2010),
//!   and the Biboulet-Houpert starvation factor.
//!
//! Not here: the Chittenden et al. minimum film and the regime-spanning
//! Nijenbanning-Venner-Moes (1994) formula, whose constants could not be found in two
//! independent sources; thermal, starvation and roughness corrections of the point contact
//! (the line contact has the first two). See `docs/film.md`.
//!
//! Units: kinematic viscosity mm²/s (= cSt), density kg/m³, dynamic viscosity MPa·s
//! (1 MPa·s = 10⁶ Pa·s; 1 mPa·s = 1e-9 MPa·s), pressure-viscosity coefficient 1/MPa,
//! temperatures in °C at the interface (converted to K internally, T = t + 273.15),
//! lengths (film thickness, roughness) in mm.

mod film;
mod line_film;
mod rolling_resistance;

pub use film::{
    CHITTENDEN_CENTRAL, FilmContact, FilmFormula, FilmRegime, FilmThickness, FilmWarnings,
    HAMROCK_DOWSON_K_RANGE, film_thickness,
};
pub use line_film::{
    LINE_ELASTIC_REGIME_M, LineFilm, LineFilmContact, LineFilmFormula, LineFilmPowers,
    LineFilmRegime, LineFilmWarnings, film_starvation_factor, line_film_regime,
    line_film_thickness, line_film_with, thermal_loading, viscosity_temperature_slope,
    zhu_cheng_thermal_factor,
};
pub use rolling_resistance::{
    BIBOULET_HOUPERT_MIN_STARVATION, HERTZ_TO_CLASSICAL, RollingResistance, RollingResistanceModel,
    biboulet_houpert_dimensionless, biboulet_houpert_moment, biboulet_houpert_starvation,
    rolling_resistance, zhou_hoeprich_dimensionless,
};

use crate::error::{Error, Result, positive_as};

/// Temperatures [°C] at which [`Lubricant::kinematic_viscosity`] answers. Below about
/// −20 °C mineral oils approach their pour point, where the Walther line no longer holds
/// (wax, non-Newtonian behaviour); above 150 °C oxidation and the 0.7 form of the relation
/// at viscosities under 2 mm²/s make it unreliable. Outside the range the call is refused.
pub const TEMPERATURE_RANGE_C: (f64, f64) = (-20.0, 150.0);

/// Smallest kinematic viscosity [mm²/s] accepted at 100 °C: ASTM D341's simple form
/// log log(ν + 0.7) holds for ν ≥ 2 mm²/s (below, the standard adds a correction term that
/// is not implemented).
pub const MIN_VISCOSITY_MM2_S: f64 = 2.0;

const KELVIN: f64 = 273.15;

/// A lubricating oil: the two viscosities that define its Walther line, its density and
/// its pressure-viscosity coefficient.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct Lubricant {
    nu40: f64,
    nu100: f64,
    density: f64,
    alpha: f64,
    walther_a: f64,
    walther_b: f64,
}

/// log10(log10(ν + 0.7)), the ordinate of the ASTM D341 chart.
fn walther_z(nu: f64) -> f64 {
    (nu + 0.7).log10().log10()
}

impl Lubricant {
    /// A lubricant from its kinematic viscosities at 40 °C and 100 °C [mm²/s], density
    /// [kg/m³] (taken constant: give the value at the operating temperature) and
    /// pressure-viscosity coefficient α [1/MPa] (mineral oils ≈ 0.01-0.03 1/MPa).
    ///
    /// # Errors
    /// [`Error::InvalidInput`] naming the field if a value is not finite or out of range:
    /// `nu40` > `nu100` ≥ 2 mm²/s, 500 ≤ `density` ≤ 2500 kg/m³, 0 < `alpha` ≤ 0.1 1/MPa.
    pub fn new(nu40: f64, nu100: f64, density: f64, alpha: f64) -> Result<Self> {
        let nu100 = positive_as("nu100", nu100, "a finite viscosity >= 2 mm²/s")?;
        if nu100 < MIN_VISCOSITY_MM2_S {
            return Err(Error::invalid(
                "nu100",
                nu100,
                "a finite viscosity >= 2 mm²/s (ASTM D341 simple form)",
            ));
        }
        let nu40 = positive_as("nu40", nu40, "a finite viscosity > nu100 in mm²/s")?;
        if nu40 <= nu100 {
            return Err(Error::invalid(
                "nu40",
                nu40,
                format!("a finite viscosity > nu100 = {nu100} mm²/s (oil thins when heated)"),
            ));
        }
        if !(density.is_finite() && (500.0..=2500.0).contains(&density)) {
            return Err(Error::invalid(
                "density",
                density,
                "a finite density in 500..=2500 kg/m³",
            ));
        }
        if !(alpha.is_finite() && alpha > 0.0 && alpha <= 0.1) {
            return Err(Error::invalid(
                "alpha",
                alpha,
                "a finite pressure-viscosity coefficient in (0, 0.1] 1/MPa",
            ));
        }
        let (t1, t2) = ((40.0 + KELVIN).log10(), (100.0 + KELVIN).log10());
        let walther_b = (walther_z(nu100) - walther_z(nu40)) / (t1 - t2);
        let walther_a = walther_z(nu100) + walther_b * t2;
        Ok(Lubricant {
            nu40,
            nu100,
            density,
            alpha,
            walther_a,
            walther_b,
        })
    }

    /// A typical mineral oil of ISO VG grade `grade` (32, 46, 68, 100, 150 or 220): ν40 =
    /// the grade (ISO 3448 mid-point), ν100 from the "typ. 100 °C" column of the lubesolut
    /// ISO VG reference table (<https://lubesolut.com/en/herramientas/tabla-viscosidades>):
    /// 5.5, 6.5, 8.5, 11.4, 14.5, 19.0 mm²/s. Real oils differ (viscosity index): use
    /// [`Lubricant::new`] with the data sheet values to override. Density and α are not part
    /// of the grade and are passed in.
    ///
    /// # Errors
    /// [`Error::InvalidInput`] for another `grade`, or a bad `density` or `alpha`.
    pub fn iso_vg(grade: u32, density: f64, alpha: f64) -> Result<Self> {
        let nu100 = match grade {
            32 => 5.5,
            46 => 6.5,
            68 => 8.5,
            100 => 11.4,
            150 => 14.5,
            220 => 19.0,
            _ => {
                return Err(Error::invalid(
                    "grade",
                    grade,
                    "one of the built-in ISO VG grades 32, 46, 68, 100, 150, 220",
                ));
            }
        };
        Lubricant::new(f64::from(grade), nu100, density, alpha)
    }

    /// Kinematic viscosity at 40 °C [mm²/s].
    pub fn nu40(&self) -> f64 {
        self.nu40
    }

    /// Kinematic viscosity at 100 °C [mm²/s].
    pub fn nu100(&self) -> f64 {
        self.nu100
    }

    /// Density [kg/m³].
    pub fn density(&self) -> f64 {
        self.density
    }

    /// Pressure-viscosity coefficient α [1/MPa].
    pub fn alpha(&self) -> f64 {
        self.alpha
    }

    /// The Walther constants (A, B) of log10 log10(ν + 0.7) = A − B log10 T, T in K
    /// (t + 273.15), ν in mm²/s, fitted through the 40 °C and 100 °C viscosities.
    pub fn walther_constants(&self) -> (f64, f64) {
        (self.walther_a, self.walther_b)
    }

    /// Kinematic viscosity [mm²/s] at `temperature_c` [°C] by ASTM D341 (Ubbelohde-Walther):
    /// ν = 10^(10^(A − B log10 T)) − 0.7.
    ///
    /// # Errors
    /// [`Error::InvalidInput`] (`temperature_c`) outside [`TEMPERATURE_RANGE_C`] or NaN.
    pub fn kinematic_viscosity(&self, temperature_c: f64) -> Result<f64> {
        let (lo, hi) = TEMPERATURE_RANGE_C;
        if !(temperature_c.is_finite() && (lo..=hi).contains(&temperature_c)) {
            return Err(Error::invalid(
                "temperature_c",
                temperature_c,
                "a temperature in -20..=150 °C (Walther line; pour point and above 150 °C not modelled)",
            ));
        }
        let z = self.walther_a - self.walther_b * (temperature_c + KELVIN).log10();
        Ok(10f64.powf(10f64.powf(z)) - 0.7)
    }

    /// Dynamic viscosity η = ρ ν [MPa·s] at `temperature_c` [°C] (density taken constant).
    ///
    /// # Errors
    /// As [`Lubricant::kinematic_viscosity`].
    pub fn dynamic_viscosity(&self, temperature_c: f64) -> Result<f64> {
        // ν [mm²/s] = 1e-6 m²/s; ρ ν [Pa·s] = 1e-6 MPa·s.
        Ok(self.kinematic_viscosity(temperature_c)? * 1e-6 * self.density * 1e-6)
    }
}

/// The film parameter (specific film thickness) Λ = h / √(σ₁² + σ₂²): film thickness `h`
/// over the composite rms roughness of the two surfaces (same length unit, e.g. mm).
///
/// # Errors
/// [`Error::InvalidInput`] naming `h`, `sigma1` or `sigma2` if not finite or negative, or if
/// both roughnesses are zero (`sigma1`, Λ undefined).
pub fn film_parameter(h: f64, sigma1: f64, sigma2: f64) -> Result<f64> {
    for (field, v) in [("h", h), ("sigma1", sigma1), ("sigma2", sigma2)] {
        if !(v.is_finite() && v >= 0.0) {
            return Err(Error::invalid(field, v, "a finite length >= 0 mm"));
        }
    }
    let sigma = sigma1.hypot(sigma2);
    if sigma <= 0.0 {
        return Err(Error::invalid(
            "sigma1",
            sigma1,
            "a composite roughness sqrt(sigma1² + sigma2²) > 0 mm",
        ));
    }
    let lambda = h / sigma;
    if lambda.is_finite() {
        Ok(lambda)
    } else {
        Err(crate::error::overflow("h", h))
    }
}
