//! Catalogue friction models of a whole bearing: the torques a bearing engineer takes
//! from the catalogues, side by side, each in its own file with its published constants.
//!
//! - [`skf2004`]: the SKF model (SKF General Catalogue 6000 EN, 2005, and its successors):
//!   `M = φ_ish φ_rs M_rr + M_sl + M_seal + M_drag`.
//! - [`schaeffler`]: the Schaeffler (INA/FAG) model after Palmgren: `M = M0 + M1`.
//! - [`aihara`]: Aihara (1987) running torque of a tapered roller bearing under axial
//!   load: EHL rolling resistance of the raceways plus rib sliding.
//!
//! - [`raceway`]: the contact-based losses of one raceway slice (line-contact EHL film,
//!   rolling resistance after Zhou & Hoeprich 1991 and Biboulet & Houpert 2010, sliding
//!   traction of the mixed law), the first brick of the contact-by-contact torque.
//! - [`ball`]: the contact-based friction of ball bearings: every ball's inner and outer
//!   contact, spin and Heathcote's differential slip over the Hertz ellipse through the
//!   friction integral, the Hamrock-Dowson film and the rolling resistance by strips.
//!
//! The catalogue models are fits, not contact mechanics: they are the baseline the
//! contact-based friction is compared with. Their equations, constants, sources, ranges and
//! omissions are in `docs/bearing-friction-catalogue.md`.
//!
//! ## Example
//! The SKF torque of a 32008 X (40 × 68 × 19 mm, Y = 1.6) under 12.85 kN axial load at
//! 1000 r/min, oil jet, ν = 70.11 mm²/s:
//! ```
//! use kontakt_bearing::friction::skf2004::{skf2004, SkfBearing, SkfOptions, TaperedSeries};
//! use kontakt_bearing::friction::{Envelope, Lubrication, OperatingPoint, RPM_PER_RAD_S};
//! let bearing = SkfBearing::TaperedRoller { series: TaperedSeries::S320X, y: 1.6 };
//! let envelope = Envelope::new(40.0, 68.0, 19.0)?;
//! let op = OperatingPoint {
//!     speed_rad_s: 1000.0 / RPM_PER_RAD_S,
//!     viscosity_mm2_s: 70.11,
//!     radial_load_n: 0.0,
//!     axial_load_n: 12_850.0,
//!     lubrication: Lubrication::OilJet,
//! };
//! let m = skf2004(&bearing, &envelope, &op, &SkfOptions::default())?;
//! assert!((m.total_nmm - 1077.46).abs() < 0.01); // N·mm: rolling 1046.8 + sliding 30.7
//! assert!(m.warnings.unverified_constants); // the 320 X row has one public source
//! # Ok::<(), kontakt::Error>(())
//! ```
//!
//! ## Units and the operating point
//! Lengths mm, forces N, moments N·mm, kinematic viscosity mm²/s, speed rad/s (the
//! library's unit). The catalogues write the speed in r/min: `n = ω · 60 / (2π)`
//! ([`RPM_PER_RAD_S`]); every model converts internally and reports the speed it used.
//! The speed is the speed of one ring relative to the other (inner ring rotating, outer
//! ring fixed in the catalogues' tests); the catalogue torques are that of the bearing
//! about its axis, the same on both rings (the models do not split it).

pub mod aihara;
pub mod ball;
pub mod crb_rib;
pub mod raceway;
pub mod schaeffler;
pub mod skf2004;
pub mod torque;

use kontakt::error::positive_as;
use kontakt::{Error, Result};

/// Revolutions per minute in one rad/s: `n [r/min] = ω [rad/s] · 60/(2π)`.
pub const RPM_PER_RAD_S: f64 = 60.0 / (2.0 * std::f64::consts::PI);

/// The boundary envelope of a bearing (catalogue dimensions, mm).
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct Envelope {
    /// Bore diameter d \[mm\].
    pub bore_mm: f64,
    /// Outside diameter D \[mm\].
    pub outer_mm: f64,
    /// Width B \[mm\] (for a tapered roller bearing the cup width C or the total width T;
    /// only the SKF drag term uses it).
    pub width_mm: f64,
}

impl Envelope {
    /// An envelope d × D × B \[mm\].
    ///
    /// # Errors
    /// [`Error::InvalidInput`] naming `bore_mm`, `outer_mm` or `width_mm` unless
    /// `0 < bore_mm < outer_mm` and `width_mm > 0`, all finite.
    pub fn new(bore_mm: f64, outer_mm: f64, width_mm: f64) -> Result<Self> {
        let env = Envelope {
            bore_mm,
            outer_mm,
            width_mm,
        };
        env.check()?;
        Ok(env)
    }

    /// Check the fields (the struct has public fields; every model calls this).
    ///
    /// # Errors
    /// As [`Envelope::new`].
    pub fn check(&self) -> Result<()> {
        positive_as("bore_mm", self.bore_mm, "a finite bore diameter > 0 mm")?;
        positive_as(
            "outer_mm",
            self.outer_mm,
            "a finite outside diameter > 0 mm",
        )?;
        positive_as("width_mm", self.width_mm, "a finite width > 0 mm")?;
        if self.outer_mm <= self.bore_mm {
            return Err(Error::invalid(
                "outer_mm",
                self.outer_mm,
                format!("an outside diameter > the bore, {} mm", self.bore_mm),
            ));
        }
        Ok(())
    }

    /// Mean diameter `d_m = (d + D)/2` \[mm\], the catalogues' size parameter.
    pub fn mean_diameter_mm(&self) -> f64 {
        0.5 * (self.bore_mm + self.outer_mm)
    }
}

/// How the bearing is lubricated; the catalogue models differ by it.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "serde", serde(rename_all = "snake_case"))]
pub enum Lubrication {
    /// Oil bath with the static oil level `level_mm` above the lowest point of the outer
    /// ring raceway \[mm\] (SKF's `H`). SKF adds the drag of the rolling elements in the
    /// bath; a level above the bearing centre (`H > D/2`) is outside what the catalogue
    /// models were fitted for (flagged).
    OilBath {
        /// Oil level H \[mm\], 0 ≤ H.
        level_mm: f64,
    },
    /// Oil jet or circulating oil (no bath).
    OilJet,
    /// Grease.
    Grease,
    /// Oil-air (or oil mist).
    OilAir,
}

/// One operating point of a bearing for the catalogue models.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct OperatingPoint {
    /// Speed of the rotating ring relative to the other \[rad/s\], ≥ 0; 0 is the
    /// starting (breakaway) condition.
    pub speed_rad_s: f64,
    /// Kinematic viscosity of the oil (of the base oil of a grease) at the operating
    /// temperature \[mm²/s\], > 0.
    pub viscosity_mm2_s: f64,
    /// Radial load F_r \[N\], ≥ 0.
    pub radial_load_n: f64,
    /// Axial load F_a \[N\], ≥ 0.
    pub axial_load_n: f64,
    /// Lubrication method.
    pub lubrication: Lubrication,
}

impl OperatingPoint {
    /// Speed in r/min, the catalogues' unit.
    pub fn speed_rpm(&self) -> f64 {
        self.speed_rad_s * RPM_PER_RAD_S
    }

    /// Check every field: one error naming the first one out of range.
    ///
    /// # Errors
    /// [`Error::InvalidInput`] naming `speed_rad_s` (finite, ≥ 0), `viscosity_mm2_s`
    /// (finite, > 0), `radial_load_n`, `axial_load_n` (finite, ≥ 0) or
    /// `lubrication.level_mm` (finite, ≥ 0).
    pub fn check(&self) -> Result<()> {
        non_negative_as(
            "speed_rad_s",
            self.speed_rad_s,
            "a finite speed >= 0 rad/s (0 = starting torque)",
        )?;
        positive_as(
            "viscosity_mm2_s",
            self.viscosity_mm2_s,
            "a finite kinematic viscosity > 0 mm²/s",
        )?;
        non_negative_as("radial_load_n", self.radial_load_n, "a finite load >= 0 N")?;
        non_negative_as("axial_load_n", self.axial_load_n, "a finite load >= 0 N")?;
        if let Lubrication::OilBath { level_mm } = self.lubrication {
            non_negative_as(
                "lubrication.level_mm",
                level_mm,
                "a finite oil level >= 0 mm",
            )?;
        }
        Ok(())
    }
}

/// `value` if finite and ≥ 0, else the one-line error naming `field`.
pub(crate) fn non_negative_as(
    field: &'static str,
    value: f64,
    expected: &'static str,
) -> Result<f64> {
    if value.is_finite() && value >= 0.0 {
        Ok(value)
    } else {
        Err(Error::invalid(field, value, expected))
    }
}

/// A result that left the range of `f64` (absurd inputs): the error names the input
/// that drove it.
pub(crate) fn finite_or(field: &'static str, input: f64, value: f64) -> Result<f64> {
    if value.is_finite() {
        Ok(value)
    } else {
        Err(Error::invalid(
            field,
            input,
            "a value small enough for the torque to be a finite number",
        ))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn point() -> OperatingPoint {
        OperatingPoint {
            speed_rad_s: 100.0,
            viscosity_mm2_s: 30.0,
            radial_load_n: 1000.0,
            axial_load_n: 500.0,
            lubrication: Lubrication::OilJet,
        }
    }

    #[test]
    fn rpm_conversion_is_exact() {
        let p = OperatingPoint {
            speed_rad_s: 2.0 * std::f64::consts::PI,
            ..point()
        };
        assert!((p.speed_rpm() - 60.0).abs() < 1e-12);
    }

    #[test]
    fn bad_fields_are_named() {
        let cases: [(OperatingPoint, &str); 5] = [
            (
                OperatingPoint {
                    speed_rad_s: -1.0,
                    ..point()
                },
                "speed_rad_s",
            ),
            (
                OperatingPoint {
                    viscosity_mm2_s: 0.0,
                    ..point()
                },
                "viscosity_mm2_s",
            ),
            (
                OperatingPoint {
                    radial_load_n: f64::NAN,
                    ..point()
                },
                "radial_load_n",
            ),
            (
                OperatingPoint {
                    axial_load_n: -3.0,
                    ..point()
                },
                "axial_load_n",
            ),
            (
                OperatingPoint {
                    lubrication: Lubrication::OilBath { level_mm: -1.0 },
                    ..point()
                },
                "lubrication.level_mm",
            ),
        ];
        for (p, field) in cases {
            let e = p.check().unwrap_err();
            assert_eq!(e.field(), Some(field), "{e}");
            assert!(!e.to_string().contains('\n'));
        }
        assert!(point().check().is_ok());
        let e = Envelope::new(40.0, 40.0, 19.0).unwrap_err();
        assert_eq!(e.field(), Some("outer_mm"));
        let e = Envelope::new(40.0, 68.0, 0.0).unwrap_err();
        assert_eq!(e.field(), Some("width_mm"));
        let env = Envelope::new(40.0, 68.0, 19.0).unwrap();
        assert_eq!(env.mean_diameter_mm(), 54.0);
    }
}
