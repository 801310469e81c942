//! The internal geometry of ball bearings as validated data: deep-groove and
//! angular-contact ball bearings (single row), their groove osculations, clearance or free
//! contact angle and materials. Lengths in mm, angles in rad, moduli in MPa; the frames and
//! the derivation are in `docs/bearing-model.md` §8.

use kontakt::hertz::{HertzPointContact, PointGeometry};
use kontakt::material::ElasticMaterial;
use kontakt::{Error, Result};
use std::f64::consts::{FRAC_PI_2, PI};

/// The density of bearing steel, kg/m³: the default of [`BallBearing::ball_density_kg_m3`].
pub const STEEL_DENSITY_KG_M3: f64 = 7850.0;

/// Which kind of ball bearing.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "serde", serde(rename_all = "snake_case"))]
pub enum BallBearingKind {
    /// Deep-groove ball bearing (60xx, 62xx, ...): symmetric grooves, given by its diametral
    /// clearance; carries radial load and axial load in both directions (the contact
    /// angle changes sign with the axial load).
    DeepGroove,
    /// Single-row angular-contact ball bearing (72xx B, ...): given by its free contact
    /// angle α0 (the angle at which the balls touch both grooves without load); carries
    /// axial load in +z only (the inner ring pushed into the outer).
    AngularContact,
}

/// A single-row ball bearing's internal geometry. Build one with
/// [`BallBearing::deep_groove`] or [`BallBearing::angular_contact`] and adjust the public
/// fields; [`BallBearing::validate`] (called by the solver) checks them.
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct BallBearing {
    /// The kind of bearing.
    pub kind: BallBearingKind,
    /// Pitch diameter d_m: the diameter of the circle through the ball centres, mm.
    pub pitch_diameter_mm: f64,
    /// Number of balls Z (≥ 3).
    pub balls: usize,
    /// Ball diameter D, mm.
    pub ball_diameter_mm: f64,
    /// Inner groove osculation f_i = r_i/D (r_i the groove's curvature radius), > 0.5.
    pub inner_osculation: f64,
    /// Outer groove osculation f_o = r_o/D, > 0.5.
    pub outer_osculation: f64,
    /// Deep groove only: the diametral clearance P_d, mm (≥ 0; negative: a radial
    /// preload), the free play of the inner ring across the diameter with the rings
    /// centred. Ignored for an angular-contact bearing.
    pub clearance_mm: f64,
    /// Angular contact only: the free contact angle α0, rad (`0 < α0 < π/2`): the balls
    /// touch both grooves at α0 without load. Ignored for a deep-groove bearing (its free
    /// contact angle follows from the clearance, [`BallBearing::free_contact_angle`]).
    pub contact_angle_rad: f64,
    /// Material of the balls (default bearing steel, E = 210 000 MPa, ν = 0.3).
    pub ball_material: ElasticMaterial,
    /// Material of the rings.
    pub ring_material: ElasticMaterial,
    /// Azimuth ψ₀ of ball 0 from the x axis, rad; ball j sits at `ψ₀ + 2π j/Z`.
    pub first_ball_azimuth_rad: f64,
    /// Density of the balls, kg/m³ (default bearing steel, 7850; silicon nitride about
    /// 3200): their centrifugal force and gyroscopic moment at speed
    /// ([`crate::ball_speed`]).
    pub ball_density_kg_m3: f64,
}

impl BallBearing {
    fn base(
        kind: BallBearingKind,
        pitch_diameter_mm: f64,
        balls: usize,
        ball_diameter_mm: f64,
        osculations: [f64; 2],
    ) -> Self {
        BallBearing {
            kind,
            pitch_diameter_mm,
            balls,
            ball_diameter_mm,
            inner_osculation: osculations[0],
            outer_osculation: osculations[1],
            clearance_mm: 0.0,
            contact_angle_rad: 0.0,
            ball_material: ElasticMaterial::STEEL,
            ring_material: ElasticMaterial::STEEL,
            first_ball_azimuth_rad: 0.0,
            ball_density_kg_m3: STEEL_DENSITY_KG_M3,
        }
    }

    /// A deep-groove ball bearing with the osculations `[f_i, f_o]`, zero clearance and
    /// steel balls and rings.
    pub fn deep_groove(
        pitch_diameter_mm: f64,
        balls: usize,
        ball_diameter_mm: f64,
        osculations: [f64; 2],
    ) -> Self {
        Self::base(
            BallBearingKind::DeepGroove,
            pitch_diameter_mm,
            balls,
            ball_diameter_mm,
            osculations,
        )
    }

    /// An angular-contact ball bearing with the osculations `[f_i, f_o]` and the free
    /// contact angle `contact_angle_rad`, steel balls and rings.
    pub fn angular_contact(
        pitch_diameter_mm: f64,
        balls: usize,
        ball_diameter_mm: f64,
        osculations: [f64; 2],
        contact_angle_rad: f64,
    ) -> Self {
        let mut b = Self::base(
            BallBearingKind::AngularContact,
            pitch_diameter_mm,
            balls,
            ball_diameter_mm,
            osculations,
        );
        b.contact_angle_rad = contact_angle_rad;
        b
    }

    /// Set the osculations from the groove curvature radii `r_i`, `r_o` (mm): `f = r/D`.
    #[must_use]
    pub fn with_groove_radii(mut self, inner_mm: f64, outer_mm: f64) -> Self {
        self.inner_osculation = inner_mm / self.ball_diameter_mm;
        self.outer_osculation = outer_mm / self.ball_diameter_mm;
        self
    }

    /// The total curvature `B = f_i + f_o − 1`.
    pub fn total_curvature(&self) -> f64 {
        self.inner_osculation + self.outer_osculation - 1.0
    }

    /// The distance between the groove curvature centres with both grooves touching the
    /// ball, `A0 = B D`, mm.
    pub fn centre_distance_mm(&self) -> f64 {
        self.total_curvature() * self.ball_diameter_mm
    }

    /// The free contact angle α0, rad: the given one of an angular-contact bearing;
    /// `acos(1 − P_d/(2 B D))` for a deep-groove one (0 with no or negative clearance).
    pub fn free_contact_angle(&self) -> f64 {
        match self.kind {
            BallBearingKind::AngularContact => self.contact_angle_rad,
            BallBearingKind::DeepGroove => {
                let c = 1.0 - 0.5 * self.clearance_mm / self.centre_distance_mm();
                c.min(1.0).acos()
            }
        }
    }

    /// The vector from the outer to the inner groove curvature centre in the ball's axial
    /// plane, `(radial, axial)` in mm, with the inner ring at the origin of its
    /// displacement: `A0 (cos α0, sin α0)` for an angular-contact bearing (touching at
    /// α0), `(A0 − P_d/2, 0)` for a deep-groove one (rings centred).
    pub fn unloaded_centre_offset(&self) -> [f64; 2] {
        let a0 = self.centre_distance_mm();
        match self.kind {
            BallBearingKind::AngularContact => {
                let (s, c) = self.contact_angle_rad.sin_cos();
                [a0 * c, a0 * s]
            }
            BallBearingKind::DeepGroove => [a0 - 0.5 * self.clearance_mm, 0.0],
        }
    }

    /// The contact angle at which the Hertz stiffness is evaluated, rad: α0 for an
    /// angular-contact bearing, 0 for a deep-groove one (its nominal angle).
    pub fn stiffness_contact_angle(&self) -> f64 {
        match self.kind {
            BallBearingKind::AngularContact => self.contact_angle_rad,
            BallBearingKind::DeepGroove => 0.0,
        }
    }

    /// The exact Hertz point contacts of a ball with the inner and the outer raceway at
    /// the contact angle `alpha` (rad), from `kontakt::hertz`. Body 1 is the ball (radii
    /// D/2); body 2 the raceway with the principal radii, convex positive: along the
    /// rolling direction `±(d_m/cos α ∓ D)/2` (Meusnier: the raceway's circle of radius
    /// `(d_m ∓ D cos α)/2` seen along the normal; + convex inner, − concave outer), across
    /// it the groove `−f D` (concave).
    ///
    /// # Errors
    /// [`Error::InvalidInput`] naming `inner_osculation` or `outer_osculation` when
    /// kontakt's Hertz refuses the geometry (e.g. conformal).
    pub fn contacts(&self, alpha: f64) -> Result<[HertzPointContact; 2]> {
        let d = self.ball_diameter_mm;
        let dm = self.pitch_diameter_mm;
        let c = alpha.cos();
        let rolling = |sign: f64| {
            if c > 0.0 {
                sign * 0.5 * (dm / c - sign * d)
            } else {
                f64::INFINITY
            }
        };
        let ball = [0.5 * d; 2];
        let make = |name: &'static str, f: f64, r_roll: f64| {
            PointGeometry::new(ball, [r_roll, -f * d], 0.0)
                .and_then(|g| HertzPointContact::new(g, self.ball_material, self.ring_material))
                .map_err(|e| {
                    Error::invalid(
                        name,
                        f,
                        format!("a groove kontakt's Hertz point contact accepts ({e})"),
                    )
                })
        };
        Ok([
            make("inner_osculation", self.inner_osculation, rolling(1.0))?,
            make("outer_osculation", self.outer_osculation, rolling(-1.0))?,
        ])
    }

    /// The load coefficient `K_n` of a ball between both raceways, `Q = K_n δ^1.5` with δ
    /// the total approach of the two contacts (mm, N): the two Hertz contacts in series,
    /// `K_n = (K_i^(−2/3) + K_o^(−2/3))^(−3/2)`, at the contact angle `alpha` (rad).
    ///
    /// # Errors
    /// As [`BallBearing::contacts`].
    pub fn ball_stiffness(&self, alpha: f64) -> Result<f64> {
        let [i, o] = self.contacts(alpha)?;
        let s = i.load_coefficient().powf(-2.0 / 3.0) + o.load_coefficient().powf(-2.0 / 3.0);
        Ok(s.powf(-1.5))
    }

    /// Check every field: one error naming the first field out of range, its value and
    /// the valid range.
    ///
    /// # Errors
    /// [`Error::InvalidInput`] or [`Error::Geometry`] naming the field
    /// (`pitch_diameter_mm`, `balls`, `inner_osculation`, `clearance_mm`, ...).
    pub fn validate(&self) -> Result<()> {
        use kontakt::error::positive_as as pos;
        const LEN: &str = "a finite length > 0 mm";
        let dm = pos("pitch_diameter_mm", self.pitch_diameter_mm, LEN)?;
        let d = pos("ball_diameter_mm", self.ball_diameter_mm, LEN)?;
        if !(3..=10_000).contains(&self.balls) {
            return Err(Error::invalid("balls", self.balls, "3 <= balls <= 10000"));
        }
        for (name, f) in [
            ("inner_osculation", self.inner_osculation),
            ("outer_osculation", self.outer_osculation),
        ] {
            if !(f > 0.5 && f <= 1.0) {
                return Err(Error::invalid(
                    name,
                    f,
                    "an osculation r/D with 0.5 < f <= 1 (the groove radius larger than the ball's; typically 0.515 to 0.54)",
                ));
            }
        }
        if !(d < dm) {
            return Err(Error::Geometry {
                field: "ball_diameter_mm".into(),
                reason: format!(
                    "a ball of diameter {d} mm does not fit between the rings of pitch diameter {dm} mm (needs ball_diameter_mm < pitch_diameter_mm)"
                ),
            });
        }
        // neighbouring ball centres are the chord d_m sin(π/Z) apart
        let chord = dm * (PI / self.balls as f64).sin();
        if d > chord {
            return Err(Error::Geometry {
                field: "balls".into(),
                reason: format!(
                    "{} balls of diameter {d} mm do not fit on the pitch circle of {dm} mm: neighbouring centres are d_m sin(pi/Z) = {chord:.4} mm apart, needs ball_diameter_mm <= that",
                    self.balls
                ),
            });
        }
        let a0 = self.centre_distance_mm();
        match self.kind {
            BallBearingKind::DeepGroove => {
                if !(self.clearance_mm.is_finite() && self.clearance_mm.abs() < a0) {
                    return Err(Error::invalid(
                        "clearance_mm",
                        self.clearance_mm,
                        format!(
                            "a finite diametral clearance with |clearance| < (f_i + f_o - 1) D = {a0:.6} mm (negative: preload)"
                        ),
                    ));
                }
            }
            BallBearingKind::AngularContact => {
                let a = self.contact_angle_rad;
                if !(a > 0.0 && a < FRAC_PI_2) {
                    return Err(Error::invalid(
                        "contact_angle_rad",
                        a,
                        "a free contact angle 0 < alpha0 < pi/2 rad for an angular-contact ball bearing",
                    ));
                }
            }
        }
        if !self.first_ball_azimuth_rad.is_finite() {
            return Err(Error::invalid(
                "first_ball_azimuth_rad",
                self.first_ball_azimuth_rad,
                "a finite angle in rad",
            ));
        }
        if !(self.ball_density_kg_m3.is_finite()
            && self.ball_density_kg_m3 > 0.0
            && self.ball_density_kg_m3 <= 1e5)
        {
            return Err(Error::invalid(
                "ball_density_kg_m3",
                self.ball_density_kg_m3,
                "a density 0 < density <= 100000 kg/m^3 (steel 7850, silicon nitride about 3200)",
            ));
        }
        self.contacts(self.stiffness_contact_angle()).map(|_| ())
    }
}

#[cfg(test)]
mod tests {
    #![allow(clippy::unwrap_used)]
    use super::*;

    /// A 6205-class deep-groove ball bearing (representative internal data, not a
    /// manufacturer's): d_m 38.5 mm, 9 balls of 7.938 mm, f_i 0.52, f_o 0.53.
    pub(crate) fn dgbb_6205() -> BallBearing {
        BallBearing::deep_groove(38.5, 9, 7.938, [0.52, 0.53])
    }

    #[test]
    fn defaults_are_valid_and_derived_quantities_hold() {
        let b = dgbb_6205();
        b.validate().unwrap();
        assert!((b.centre_distance_mm() - 0.05 * 7.938).abs() < 1e-15);
        let mut c = b.clone();
        c.clearance_mm = 0.02;
        // cos α0 = 1 − P_d/(2 B D)
        let want = (1.0_f64 - 0.01 / (0.05 * 7.938)).acos();
        assert!((c.free_contact_angle() - want).abs() < 1e-15);
        let r = b.clone().with_groove_radii(0.52 * 7.938, 0.53 * 7.938);
        assert!((r.inner_osculation - 0.52).abs() < 1e-15);
        let a = BallBearing::angular_contact(38.5, 12, 7.938, [0.52, 0.53], 40f64.to_radians());
        a.validate().unwrap();
        let [x, z] = a.unloaded_centre_offset();
        assert!((x.hypot(z) - a.centre_distance_mm()).abs() < 1e-15);
    }

    /// Series stiffness of the two exact Hertz contacts: δ_i + δ_o at a force equals
    /// (Q/K_n)^(2/3). Each contact's K against the approximation of Hamrock & Brewe (1983)
    /// from Harris's curvature sums (`ρ = 2/D, 2/D, −1/(f D), ±(2/D) γ/(1 ∓ γ)`,
    /// γ = D/d_m): within 2.5 % (measured 1.7 % inner, 0.2 % outer); a convex/concave
    /// slip of the rolling radius moves the inner K by 6 %.
    #[test]
    fn ball_stiffness_is_the_series_of_the_two_hertz_contacts() {
        let b = dgbb_6205();
        let k = b.ball_stiffness(0.0).unwrap();
        let [i, o] = b.contacts(0.0).unwrap();
        let q = 1234.5;
        let d = i.approach_from_force(q).unwrap() + o.approach_from_force(q).unwrap();
        assert!(((q / k).powf(2.0 / 3.0) - d).abs() < 1e-14, "{k}");
        let (dd, g) = (7.938, 7.938 / 38.5);
        let e_prime =
            2.0 * kontakt::material::effective_modulus(&b.ball_material, &b.ring_material);
        let hamrock = |f: f64, s: f64| {
            let along = 0.5 * (2.0 / dd - 1.0 / (f * dd)); // across the groove
            let roll = 0.5 * (2.0 / dd + s * 2.0 / dd * g / (1.0 - s * g));
            let (rx, ry) = (0.5 / roll, 0.5 / along);
            let kk = 1.0339 * (ry / rx).powf(0.636);
            let ee = 1.0003 + 0.5968 * rx / ry;
            let ff = 1.5277 + 0.6023 * (ry / rx).ln();
            let r = 1.0 / (1.0 / rx + 1.0 / ry);
            let d1 = ff * (4.5 / (ee * r) * (1.0 / (PI * kk * e_prime)).powi(2)).cbrt();
            d1.powf(-1.5)
        };
        let rel = |a: f64, b: f64| (a - b).abs() / b;
        let (ki, ko) = (i.load_coefficient(), o.load_coefficient());
        assert!(rel(ki, hamrock(0.52, 1.0)) < 0.025, "{ki}");
        assert!(rel(ko, hamrock(0.53, -1.0)) < 0.025, "{ko}");
    }

    #[test]
    fn bad_geometry_is_named() {
        let msg = |b: BallBearing| b.validate().unwrap_err().to_string();
        let mut b = dgbb_6205();
        b.inner_osculation = 0.5;
        let e = msg(b);
        assert!(
            e.starts_with(
                "invalid inner_osculation = 0.5: expected an osculation r/D with 0.5 < f <= 1"
            ),
            "{e}"
        );
        let e = msg(BallBearing::deep_groove(38.5, 16, 7.938, [0.52, 0.53]));
        assert!(
            e.starts_with("balls: 16 balls of diameter 7.938 mm do not fit"),
            "{e}"
        );
        let e = msg(BallBearing::deep_groove(7.0, 3, 7.938, [0.52, 0.53]));
        assert!(
            e.starts_with("ball_diameter_mm: a ball of diameter 7.938 mm does not fit"),
            "{e}"
        );
        let mut b = dgbb_6205();
        b.clearance_mm = 0.5;
        assert!(
            msg(b).starts_with("invalid clearance_mm = 0.5: expected a finite diametral clearance")
        );
        let b = BallBearing::angular_contact(38.5, 9, 7.938, [0.52, 0.53], 0.0);
        assert!(msg(b).starts_with("invalid contact_angle_rad = 0"));
        let mut b = dgbb_6205();
        b.outer_osculation = f64::NAN;
        assert!(msg(b).starts_with("invalid outer_osculation = NaN"));
        let mut b = dgbb_6205();
        b.pitch_diameter_mm = -1.0;
        assert!(msg(b).starts_with("invalid pitch_diameter_mm = -1"));
    }
}
