//! Ring speeds and the kinematics of the cage and the rolling elements, after Harris &
//! Kotzalas (2006), *Rolling Bearing Analysis*, "Ball and roller kinematics": rolling
//! without slip at the centre of both contacts; derivation and signs in
//! `docs/bearing-model.md` §16.1.
//!
//! **Frames and signs.** Speeds are angular velocities about +z (the bearing axis), rad/s,
//! positive counter-clockwise seen from +z (the direction of increasing azimuth ψ). In the
//! element's axial plane `(e_r, e_z)` the element's angular velocity relative to the cage is
//! `ω_R a` with the unit axis `a = (−sin β, cos β)`: β = α, the contact angle, when both
//! contacts have the same angle (a roller, or a ball without speed effects); for a ball at
//! speed β follows from the race-control assumption ([`outer_race_control_pitch`]). With
//! the outer ring fixed and the inner ring turning at ω_i > 0 the cage turns at ω_c > 0 and
//! the element at ω_R < 0 about `a`.
//!
//! With `γ = D/d_m` (element diameter D, pitch diameter d_m, mm) and the contact angles
//! α_i, α_o (rad), pure rolling at both contacts gives (`X_o = cos(α_o − β)/(1 + γ cos α_o)`,
//! `X_i = cos(α_i − β)/(1 − γ cos α_i)`)
//!
//! ```text
//! ω_c = (ω_i X_o + ω_o X_i)/(X_o + X_i),     ω_R = (ω_o − ω_i)/(γ (X_o + X_i)),
//! ```
//!
//! which for α_i = α_o = β = α are Harris's closed forms
//! `ω_c = ½[ω_i (1 − γ cos α) + ω_o (1 + γ cos α)]` and
//! `ω_R = (d_m/2D)(1 − γ² cos² α)(ω_o − ω_i)`.

use kontakt::{Error, Result};

/// Largest ring speed accepted, rad/s (about 1.9 million r/min: far beyond any bearing;
/// only a guard against overflow).
pub const MAX_RING_SPEED_RAD_S: f64 = 2.0e5;

/// The speeds of the two rings about the bearing axis +z, rad/s (positive counter-clockwise
/// seen from +z). The default is at rest.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct RingSpeeds {
    /// Inner-ring speed ω_i, rad/s.
    pub inner_rad_s: f64,
    /// Outer-ring speed ω_o, rad/s.
    pub outer_rad_s: f64,
}

impl RingSpeeds {
    /// Both rings at rest.
    pub const ZERO: RingSpeeds = RingSpeeds {
        inner_rad_s: 0.0,
        outer_rad_s: 0.0,
    };

    /// Speeds in rad/s.
    pub fn new(inner_rad_s: f64, outer_rad_s: f64) -> Self {
        RingSpeeds {
            inner_rad_s,
            outer_rad_s,
        }
    }

    /// Speeds given in revolutions per minute (r/min), converted to rad/s (× 2π/60).
    pub fn from_rpm(inner_rpm: f64, outer_rpm: f64) -> Self {
        let k = std::f64::consts::PI / 30.0;
        RingSpeeds::new(inner_rpm * k, outer_rpm * k)
    }

    /// Whether both rings are at rest.
    pub fn is_zero(&self) -> bool {
        self.inner_rad_s == 0.0 && self.outer_rad_s == 0.0
    }

    /// Check both speeds: finite and `|ω| <= MAX_RING_SPEED_RAD_S`.
    ///
    /// # Errors
    /// [`Error::InvalidInput`] naming `speeds.inner_rad_s` or `speeds.outer_rad_s`.
    pub fn validate(&self) -> Result<()> {
        for (name, w) in [
            ("speeds.inner_rad_s", self.inner_rad_s),
            ("speeds.outer_rad_s", self.outer_rad_s),
        ] {
            if !(w.is_finite() && w.abs() <= MAX_RING_SPEED_RAD_S) {
                return Err(Error::invalid(
                    name,
                    w,
                    format!("a finite speed with |speed| <= {MAX_RING_SPEED_RAD_S} rad/s"),
                ));
            }
        }
        Ok(())
    }
}

/// The kinematics of one rolling element: cage speed, the element's speed about its own
/// axis relative to the cage, and the pitch of that axis.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ElementKinematics {
    /// Cage (orbital) speed ω_c about +z, rad/s.
    pub cage_rad_s: f64,
    /// The element's speed ω_R about its own axis `a = (−sin β, cos β)` relative to the
    /// cage, rad/s.
    pub element_rad_s: f64,
    /// The pitch β of the element's axis, rad.
    pub pitch_rad: f64,
}

/// The kinematics for contact angles α_i, α_o and the axis pitch β (rad), element diameter
/// `element_diameter_mm` and pitch diameter `pitch_diameter_mm` (mm), under pure rolling at
/// the centre of both contacts (module docs).
pub fn kinematics(
    speeds: RingSpeeds,
    element_diameter_mm: f64,
    pitch_diameter_mm: f64,
    alpha_i: f64,
    alpha_o: f64,
    beta: f64,
) -> ElementKinematics {
    let g = element_diameter_mm / pitch_diameter_mm;
    let xo = (alpha_o - beta).cos() / (1.0 + g * alpha_o.cos());
    let xi = (alpha_i - beta).cos() / (1.0 - g * alpha_i.cos());
    let (wi, wo) = (speeds.inner_rad_s, speeds.outer_rad_s);
    ElementKinematics {
        cage_rad_s: (wi * xo + wo * xi) / (xo + xi),
        element_rad_s: (wo - wi) / (g * (xo + xi)),
        pitch_rad: beta,
    }
}

/// The kinematics of elements with one contact angle α (rad) on both raceways and their
/// axis pitched by α (rollers; balls without speed effects): the cage speed
/// `ω_c = ½[ω_i (1 − γ cos α) + ω_o (1 + γ cos α)]` and the element's speed about its own
/// axis relative to the cage `ω_R = (d_m/2D)(1 − γ² cos² α)(ω_o − ω_i)`, rad/s, `γ = D/d_m`
/// (Harris & Kotzalas 2006). For a tapered roller use its mean diameter.
pub fn one_angle_kinematics(
    speeds: RingSpeeds,
    element_diameter_mm: f64,
    pitch_diameter_mm: f64,
    alpha: f64,
) -> ElementKinematics {
    let (d, dm) = (element_diameter_mm, pitch_diameter_mm);
    kinematics(speeds, d, dm, alpha, alpha, alpha)
}

/// The cage speed ω_c (rad/s) of [`one_angle_kinematics`].
pub fn cage_speed(speeds: RingSpeeds, d_mm: f64, pitch_mm: f64, alpha: f64) -> f64 {
    one_angle_kinematics(speeds, d_mm, pitch_mm, alpha).cage_rad_s
}

/// The pitch β (rad) of a ball's axis under outer-race control (no spin about the outer
/// contact normal, Jones 1960): `tan β = sin α_o/(cos α_o + γ)`, `γ = D/d_m`.
pub fn outer_race_control_pitch(gamma: f64, alpha_o: f64) -> f64 {
    let (s, c) = alpha_o.sin_cos();
    s.atan2(c + gamma)
}

/// The centrifugal force of an element of mass `mass_n_s2_per_mm` (N·s²/mm: kg × 10⁻³)
/// orbiting at the pitch radius `d_m/2` (mm) with the cage speed ω_c (rad/s):
/// `F_c = ½ m d_m ω_c²`, N (Harris & Kotzalas 2006).
pub fn centrifugal_force(mass_n_s2_per_mm: f64, pitch_diameter_mm: f64, cage_rad_s: f64) -> f64 {
    0.5 * mass_n_s2_per_mm * pitch_diameter_mm * cage_rad_s * cage_rad_s
}

/// A density in kg/m³ as N·s²/mm⁴ (× 10⁻¹²), so that mass × mm/s² is N.
pub fn density_n_s2_per_mm4(kg_per_m3: f64) -> f64 {
    kg_per_m3 * 1e-12
}

#[cfg(test)]
mod tests {
    #![allow(clippy::unwrap_used)]
    use super::*;

    fn rel(a: f64, b: f64) -> f64 {
        (a - b).abs() / b.abs().max(1e-300)
    }

    /// Harris's closed forms for one contact angle, fixed outer ring and fixed inner ring.
    #[test]
    fn cage_and_element_speed_match_the_closed_forms() {
        let (d, dm) = (7.938, 38.5);
        for alpha in [0.0_f64, 0.3, 40f64.to_radians()] {
            let g = d * alpha.cos() / dm;
            let s = RingSpeeds::new(1000.0, 0.0);
            assert!(rel(cage_speed(s, d, dm, alpha), 500.0 * (1.0 - g)) < 1e-14);
            let wr = dm / (2.0 * d) * (1.0 - g * g) * (-1000.0);
            assert!(rel(one_angle_kinematics(s, d, dm, alpha).element_rad_s, wr) < 1e-14);
            let s = RingSpeeds::new(0.0, 1000.0);
            assert!(rel(cage_speed(s, d, dm, alpha), 500.0 * (1.0 + g)) < 1e-14);
            // both rings together: a rigid rotation, the element does not turn in the cage
            let s = RingSpeeds::new(700.0, 700.0);
            assert!(rel(cage_speed(s, d, dm, alpha), 700.0) < 1e-14);
            assert!(one_angle_kinematics(s, d, dm, alpha).element_rad_s.abs() < 1e-12);
        }
    }

    /// The general kinematics roll without slip at both contact centres: the element's
    /// surface velocity (relative to the cage) equals each ring's there, for unequal angles.
    #[test]
    fn general_kinematics_roll_at_both_contacts() {
        let (d, dm) = (22.225, 125.26);
        let s = RingSpeeds::new(1047.0, -100.0);
        let (ai, ao) = (0.75_f64, 0.55_f64);
        let beta = outer_race_control_pitch(d / dm, ao);
        let k = kinematics(s, d, dm, ai, ao, beta);
        let a = [-beta.sin(), beta.cos()];
        // (a × m)_θ = a_z m_r − a_r m_z in the (e_r, e_θ, e_z) frame
        let v = |m: [f64; 2]| k.element_rad_s * (a[1] * m[0] - a[0] * m[1]);
        let out = [0.5 * d * ao.cos(), 0.5 * d * ao.sin()];
        let inn = [-0.5 * d * ai.cos(), -0.5 * d * ai.sin()];
        let ring_o = (s.outer_rad_s - k.cage_rad_s) * (0.5 * dm + out[0]);
        let ring_i = (s.inner_rad_s - k.cage_rad_s) * (0.5 * dm + inn[0]);
        assert!(rel(v(out), ring_o) < 1e-13, "{} {ring_o}", v(out));
        assert!(rel(v(inn), ring_i) < 1e-13, "{} {ring_i}", v(inn));
        // outer-race control: no spin about the outer normal, relative to the outer ring
        let n_o = [ao.cos(), ao.sin()];
        let spin = k.element_rad_s * (a[0] * n_o[0] + a[1] * n_o[1])
            - (s.outer_rad_s - k.cage_rad_s) * n_o[1];
        assert!(spin.abs() < 1e-12 * k.element_rad_s.abs(), "{spin}");
    }

    #[test]
    fn rpm_conversion_and_bad_speeds() {
        let s = RingSpeeds::from_rpm(3000.0, -60.0);
        assert!(rel(s.inner_rad_s, 100.0 * std::f64::consts::PI) < 1e-15);
        assert!(rel(s.outer_rad_s, -2.0 * std::f64::consts::PI) < 1e-15);
        assert!(RingSpeeds::ZERO.is_zero() && !s.is_zero());
        s.validate().unwrap();
        let e = RingSpeeds::new(f64::NAN, 0.0)
            .validate()
            .unwrap_err()
            .to_string();
        assert!(e.starts_with("invalid speeds.inner_rad_s = NaN"), "{e}");
        let e = RingSpeeds::new(0.0, 3e5)
            .validate()
            .unwrap_err()
            .to_string();
        assert!(e.starts_with("invalid speeds.outer_rad_s = 300000"), "{e}");
        // F_c = ½ m d_m ω_c²: a 1 g ball (1e-6 N s²/mm) at 50 mm pitch, 100 rad/s: 0.25 N
        assert!(rel(centrifugal_force(1e-6, 50.0, 100.0), 0.25) < 1e-15);
        assert!(rel(density_n_s2_per_mm4(7850.0), 7.85e-9) < 1e-15);
    }
}
