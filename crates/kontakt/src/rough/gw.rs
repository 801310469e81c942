//! Greenwood-Williamson (1966): a nominally flat rough surface against a smooth rigid
//! flat (or two rough surfaces reduced to one), each summit a Hertz contact.
//!
//! # Formulas
//! Summits of density $\eta$ \[1/mm²\], tip radius $\beta$ \[mm\] and heights of standard
//! deviation $\sigma_s$ \[mm\]; the flat at separation $d$ \[mm\] from the summit datum
//! (mean summit plane for Gaussian heights, lowest summit for exponential ones),
//! $h = d/\sigma_s$. A summit of height $z > d$ is compressed by $z - d$ and carries the
//! Hertz load $\tfrac43 E^*\beta^{1/2}(z-d)^{3/2}$ on the area $\pi\beta(z-d)$. Per unit
//! nominal area (GW 1966 eqs 5-8):
//!
//! $$n = \eta\,F_0(h),\qquad \frac{A}{A_0} = \pi\eta\beta\sigma_s\,F_1(h),\qquad
//!   \bar p = \frac{P}{A_0} = \tfrac43\,\eta E^*\beta^{1/2}\sigma_s^{3/2}\,F_{3/2}(h)$$
//!
//! with $F_n$ from [`height_integral`](super::height_integral). For exponential heights
//! and $h \ge 0$ all three are proportional to $e^{-h}$, so the real area and the number
//! of contacts grow exactly in proportion to the load.
//!
//! The **plasticity index** (GW 1966 eq. 16) $\psi = (E^*/H)\sqrt{\sigma_s/\beta}$, with
//! the hardness $H$ \[MPa\]: below about 0.6 the contact is elastic at any practical load,
//! above about 1 most summits yield. GW write $E'$ for our $E^*$ (the contact modulus of
//! the crate conventions).
//!
//! # Assumptions
//! Summits are spherical caps of one radius, far enough apart not to interact
//! (the bulk does not deform: no coupling through the half-space), elastic and
//! frictionless; $d$ measured from the datum of the distribution.
//!
//! # Reference
//! Greenwood and Williamson (1966), "Contact of nominally flat surfaces", Proc. R. Soc.
//! Lond. A 295, 300-319. doi:10.1098/rspa.1966.0242

use super::heights::{SummitHeights, exponential_closed_form, height_integral};
use crate::error::{Error, Result, positive_as};
use crate::units::{Megapascal, Millimetre};

/// Range of standardised separations the inverse solve searches.
const H_RANGE: (f64, f64) = (-30.0, 37.0);

/// A Greenwood-Williamson rough surface against a smooth flat.
///
/// # Example
/// A ground steel surface: σ_s = 0.5 µm, β = 20 µm, η = 2000 summits/mm²:
/// ```
/// use kontakt::rough::{GreenwoodWilliamson, SummitHeights};
/// let gw = GreenwoodWilliamson::new(2000.0, 0.02, 5e-4, 115_000.0, SummitHeights::Gaussian)?;
/// let s = gw.at_standardised_separation(2.0)?;
/// // nominal pressure, real area fraction and contacts per mm² at d = 2 σ_s
/// assert!(s.nominal_pressure > 0.0 && s.area_fraction < 0.01);
/// // the inverse returns the same separation
/// let back = gw.separation_from_pressure(s.nominal_pressure)?;
/// assert!((back.standardised_separation - 2.0).abs() < 1e-10);
/// # Ok::<(), kontakt::Error>(())
/// ```
///
/// Serialized but not deserialized: build it with [`new`](Self::new), which validates.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct GreenwoodWilliamson {
    summit_density: f64,
    summit_radius: Millimetre,
    summit_std: Millimetre,
    e_star: Megapascal,
    heights: SummitHeights,
}

/// The state of a GW contact at one separation (all per unit nominal area).
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(
    feature = "serde",
    derive(serde::Serialize, serde::Deserialize, schemars::JsonSchema)
)]
pub struct GwState {
    /// $d$, separation of the flat from the summit datum \[mm\].
    pub separation: Millimetre,
    /// $h = d/\sigma_s$ \[-\].
    pub standardised_separation: f64,
    /// $\bar p = P/A_0$, load per nominal area \[MPa\].
    pub nominal_pressure: Megapascal,
    /// $A/A_0$, real contact area per nominal area \[-\].
    pub area_fraction: f64,
    /// $n = N/A_0$, number of summit contacts per nominal area \[1/mm²\].
    pub contact_density: f64,
    /// $P/A$, mean pressure on the real contact area \[MPa\] (0 when nothing touches).
    pub mean_real_pressure: Megapascal,
}

impl GreenwoodWilliamson {
    /// A rough surface.
    ///
    /// # Arguments
    /// - `summit_density` — $\eta$ \[1/mm²\], finite, > 0.
    /// - `summit_radius` — $\beta$ \[mm\], finite, > 0.
    /// - `summit_std` — $\sigma_s$, standard deviation of summit heights \[mm\], finite, > 0.
    /// - `e_star` — contact modulus $E^*$ \[MPa\], finite, > 0.
    /// - `heights` — the summit-height distribution.
    ///
    /// # Errors
    /// [`Error::InvalidInput`] naming the first argument out of range.
    pub fn new(
        summit_density: f64,
        summit_radius: Millimetre,
        summit_std: Millimetre,
        e_star: Megapascal,
        heights: SummitHeights,
    ) -> Result<Self> {
        positive_as(
            "summit_density",
            summit_density,
            "a finite density > 0 per mm²",
        )?;
        positive_as("summit_radius", summit_radius, "a finite radius > 0 mm")?;
        positive_as("summit_std", summit_std, "a finite roughness > 0 mm")?;
        positive_as("e_star", e_star, "a finite modulus > 0 MPa")?;
        Ok(GreenwoodWilliamson {
            summit_density,
            summit_radius,
            summit_std,
            e_star,
            heights,
        })
    }

    /// The summit-height distribution.
    pub fn heights(&self) -> SummitHeights {
        self.heights
    }

    /// $\tfrac43\eta E^*\beta^{1/2}\sigma_s^{3/2}$ \[MPa\]: $\bar p / F_{3/2}(h)$.
    pub fn pressure_scale(&self) -> Megapascal {
        4.0 / 3.0
            * self.summit_density
            * self.e_star
            * self.summit_radius.sqrt()
            * self.summit_std.powf(1.5)
    }

    /// The state at separation `separation` \[mm\] from the summit datum.
    ///
    /// # Errors
    /// [`Error::InvalidInput`] (field `separation`) for a non-finite value.
    pub fn at_separation(&self, separation: Millimetre) -> Result<GwState> {
        if !separation.is_finite() {
            return Err(Error::invalid(
                "separation",
                separation,
                "a finite separation in mm",
            ));
        }
        self.at_standardised_separation(separation / self.summit_std)
    }

    /// The state at the standardised separation $h = d/\sigma_s$ \[-\].
    ///
    /// # Errors
    /// [`Error::InvalidInput`] (field `separation`) for a non-finite value.
    pub fn at_standardised_separation(&self, h: f64) -> Result<GwState> {
        let f0 = height_integral(self.heights, 0.0, h)?;
        let f1 = height_integral(self.heights, 1.0, h)?;
        let f32 = height_integral(self.heights, 1.5, h)?;
        Ok(self.state(h, f0, f1, f32))
    }

    fn state(&self, h: f64, f0: f64, f1: f64, f32: f64) -> GwState {
        let eta = self.summit_density;
        let area_fraction = std::f64::consts::PI * eta * self.summit_radius * self.summit_std * f1;
        let nominal_pressure = self.pressure_scale() * f32;
        GwState {
            separation: h * self.summit_std,
            standardised_separation: h,
            nominal_pressure,
            area_fraction,
            contact_density: eta * f0,
            mean_real_pressure: if area_fraction > 0.0 {
                nominal_pressure / area_fraction
            } else {
                0.0
            },
        }
    }

    /// The separation at which the load per nominal area is `nominal_pressure` \[MPa\],
    /// and the state there (the inverse of [`at_standardised_separation`](Self::at_standardised_separation)).
    ///
    /// $\bar p(h)$ decreases strictly, so the root is unique: closed form
    /// $h = \ln(\Gamma(\tfrac52)\,\bar p_s/\bar p)$ for exponential heights when it is
    /// $\ge 0$, otherwise Newton's method on $\ln F_{3/2}(h)$ (slope
    /// $-\tfrac32 F_{1/2}/F_{3/2}$) kept inside a bisection bracket of
    /// $h \in [-30, 37]$; converged when the bracket or step is below 1e-13.
    ///
    /// # Errors
    /// [`Error::InvalidInput`] (field `nominal_pressure`) for a value that is not finite
    /// and > 0, or outside the range the bracket spans (the flat 30 σ_s into the
    /// summits, or so far away that $F_{3/2}$ underflows).
    pub fn separation_from_pressure(&self, nominal_pressure: Megapascal) -> Result<GwState> {
        positive_as(
            "nominal_pressure",
            nominal_pressure,
            "a finite pressure > 0 MPa",
        )?;
        let target = nominal_pressure / self.pressure_scale();
        if self.heights == SummitHeights::Exponential {
            let h = (exponential_closed_form(1.5, 0.0) / target).ln();
            if h >= 0.0 && h.is_finite() {
                return self.at_standardised_separation(h);
            }
        }
        let f = |h: f64| height_integral(self.heights, 1.5, h);
        let (mut lo, mut hi) = H_RANGE;
        let (f_lo, f_hi) = (f(lo)?, f(hi)?);
        if !(target <= f_lo && target >= f_hi) {
            return Err(Error::invalid(
                "nominal_pressure",
                nominal_pressure,
                format!(
                    "between {:e} and {:e} MPa for this surface (separation -30 to 37 σ_s)",
                    f_hi * self.pressure_scale(),
                    f_lo * self.pressure_scale()
                ),
            ));
        }
        let ln_t = target.ln();
        let mut h = 0.0f64.clamp(lo, hi);
        for _ in 0..200 {
            let f32 = f(h)?;
            let f12 = height_integral(self.heights, 0.5, h)?;
            if f32 > target {
                lo = h;
            } else {
                hi = h;
            }
            let r = f32.max(f64::MIN_POSITIVE).ln() - ln_t;
            let slope = -1.5 * f12 / f32;
            let mut next = h - r / slope;
            if !(next > lo && next < hi && next.is_finite()) {
                next = 0.5 * (lo + hi);
            }
            if (next - h).abs() < 1e-13 * (1.0 + h.abs()) || hi - lo < 1e-13 {
                return self.at_standardised_separation(next);
            }
            h = next;
        }
        Err(Error::NotConverged {
            what: "GW separation from pressure".into(),
            iterations: 200,
            residual: hi - lo,
        })
    }
}

/// The plasticity index $\psi = (E^*/H)\sqrt{\sigma_s/\beta}$ \[-\] (GW 1966 eq. 16).
///
/// # Arguments
/// `e_star` $E^*$ \[MPa\], `hardness` $H$ \[MPa\], `summit_std` $\sigma_s$ \[mm\],
/// `summit_radius` $\beta$ \[mm\]; each finite and > 0.
///
/// # Errors
/// [`Error::InvalidInput`] naming the first argument out of range.
///
/// # Example
/// ```
/// // steel: E* = 115 GPa, H = 6 GPa, σ_s = 0.5 µm, β = 20 µm → ψ ≈ 3 (plastic)
/// let psi = kontakt::rough::plasticity_index(115_000.0, 6000.0, 5e-4, 0.02)?;
/// assert!((psi - 3.0305).abs() < 1e-4);
/// # Ok::<(), kontakt::Error>(())
/// ```
pub fn plasticity_index(
    e_star: Megapascal,
    hardness: Megapascal,
    summit_std: Millimetre,
    summit_radius: Millimetre,
) -> Result<f64> {
    positive_as("e_star", e_star, "a finite modulus > 0 MPa")?;
    positive_as("hardness", hardness, "a finite hardness > 0 MPa")?;
    positive_as("summit_std", summit_std, "a finite roughness > 0 mm")?;
    positive_as("summit_radius", summit_radius, "a finite radius > 0 mm")?;
    Ok(e_star / hardness * (summit_std / summit_radius).sqrt())
}

impl GreenwoodWilliamson {
    /// The plasticity index of this surface for hardness `hardness` \[MPa\]; see
    /// [`plasticity_index`].
    ///
    /// # Errors
    /// [`Error::InvalidInput`] (field `hardness`) unless finite and > 0.
    pub fn plasticity_index(&self, hardness: Megapascal) -> Result<f64> {
        plasticity_index(self.e_star, hardness, self.summit_std, self.summit_radius)
    }
}
