//! The internal geometry of roller bearings as validated data.
//!
//! A [`RollerBearing`] holds what the load distribution needs: pitch diameter, roller
//! count, roller diameter and effective length, the contact angles of the outer
//! (cup) and inner (cone) raceways, the clearance, the three profiles and the slice
//! count. Cylindrical roller bearings (contact angle 0), single-row tapered roller
//! bearings (cup angle α, cone angle α_i < α) and cylindrical roller thrust bearings
//! (81xxx, contact angle 90°) share one description; the frames and signs are those of
//! `docs/bearing-model.md`. Lengths in mm, angles in rad.
//!
//! Ball bearings (deep-groove and angular-contact) are [`BallBearing`]s.
//!
//! Not yet here (later steps of issue 28): the rib geometry and roller end face (today in
//! `kontakt::bearing::roller_rib`), the NU/NJ/NUP/N rib arrangement of cylindrical roller
//! bearings, paired and double-row bearings, materials other than steel. A
//! representative internal design from the boundary dimensions: [`design`].

mod ball;
pub mod design;
mod rib_study;

pub use ball::{BallBearing, BallBearingKind, STEEL_DENSITY_KG_M3};

use crate::profile::Profile;
use kontakt::{Error, Result};
use std::f64::consts::{FRAC_PI_2, PI};

/// Which kind of roller bearing; decides the valid contact angles.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "serde", serde(rename_all = "snake_case"))]
pub enum RollerBearingKind {
    /// Cylindrical roller bearing: both contact angles 0; carries no axial load (the rib
    /// arrangement NJ/NUP that would is a later step).
    Cylindrical,
    /// Single-row tapered roller bearing: cup angle `0 < α < 90°`, cone angle
    /// `0 < α_i < α`; the cone's large rib takes the difference of the raceway forces.
    Tapered,
    /// Cylindrical roller thrust bearing (81xxx): contact angle 90°, rollers radial; carries
    /// axial load and tilting moments, no radial load.
    Thrust,
}

/// The ISO/TS 16281 line-contact stiffness constant of steel rollers, N/mm^(10/9) per
/// mm^(8/9): a roller of effective length `L` (mm) between both raceways carries
/// `Q = 35948 L^(8/9) δ^(10/9)` (N) at the total approach δ (mm) of the two contacts.
pub const ISO_ROLLER_STIFFNESS: f64 = 35_948.0;

/// A roller bearing's internal geometry. Build one with [`RollerBearing::cylindrical`],
/// [`RollerBearing::tapered`] or [`RollerBearing::thrust`] and adjust the public fields;
/// [`RollerBearing::validate`] (called by the solver) checks them.
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct RollerBearing {
    /// The kind of bearing.
    pub kind: RollerBearingKind,
    /// Pitch diameter d_m: the diameter of the circle through the roller centres, mm
    /// (for a thrust bearing the mean diameter of the roller path).
    pub pitch_diameter_mm: f64,
    /// Number of rollers Z (≥ 3).
    pub rollers: usize,
    /// Roller diameter D_we, mm (the mean diameter of a tapered roller).
    pub roller_diameter_mm: f64,
    /// Effective roller length L_we (the length of the contact line), mm.
    pub effective_length_mm: f64,
    /// Contact angle α of the outer raceway (cup) normal to the radial plane, rad: 0 for
    /// cylindrical, `0 < α < π/2` tapered, `π/2` thrust. The load of a roller acts along
    /// this normal.
    pub contact_angle_rad: f64,
    /// Contact angle α_i of the inner raceway (cone), rad: equal to `contact_angle_rad`
    /// for cylindrical and thrust bearings, `0 < α_i < α` for tapered ones.
    pub cone_angle_rad: f64,
    /// Tapered only: direction of the rib's force on the roller in the roller's axial
    /// plane, measured like the contact angles, rad; `None`: along the roller axis toward
    /// the small end, `(α + α_i)/2 + π/2` (a rib face perpendicular to the roller axis).
    pub rib_angle_rad: Option<f64>,
    /// Operating clearance along the contact normal, both sides together (diametral for a
    /// radial bearing, axial for a thrust bearing), mm; negative: preload.
    pub clearance_mm: f64,
    /// Roller profile (acts on both contacts of a roller).
    pub roller_profile: Profile,
    /// Inner raceway (cone, shaft washer) profile.
    pub inner_profile: Profile,
    /// Outer raceway (cup, housing washer) profile.
    pub outer_profile: Profile,
    /// Number of slices along a roller: odd, 1..=10001 (31 by default; ≥ 31 recommended).
    pub slices: usize,
    /// Azimuth ψ₀ of roller 0 from the x axis, rad; roller j sits at `ψ₀ + 2π j/Z`.
    pub first_roller_azimuth_rad: f64,
}

/// The default slice count.
pub const DEFAULT_SLICES: usize = 31;

impl RollerBearing {
    fn base(
        kind: RollerBearingKind,
        pitch_diameter_mm: f64,
        rollers: usize,
        roller_diameter_mm: f64,
        effective_length_mm: f64,
        contact_angle_rad: f64,
        cone_angle_rad: f64,
    ) -> Self {
        RollerBearing {
            kind,
            pitch_diameter_mm,
            rollers,
            roller_diameter_mm,
            effective_length_mm,
            contact_angle_rad,
            cone_angle_rad,
            rib_angle_rad: None,
            clearance_mm: 0.0,
            roller_profile: Profile::iso(effective_length_mm, roller_diameter_mm),
            inner_profile: Profile::Straight,
            outer_profile: Profile::Straight,
            slices: DEFAULT_SLICES,
            first_roller_azimuth_rad: 0.0,
        }
    }

    /// A cylindrical roller bearing with the ISO/TS 16281 roller profile, straight
    /// raceways, zero clearance and 31 slices.
    pub fn cylindrical(
        pitch_diameter_mm: f64,
        rollers: usize,
        roller_diameter_mm: f64,
        effective_length_mm: f64,
    ) -> Self {
        Self::base(
            RollerBearingKind::Cylindrical,
            pitch_diameter_mm,
            rollers,
            roller_diameter_mm,
            effective_length_mm,
            0.0,
            0.0,
        )
    }

    /// A single-row tapered roller bearing with cup angle `cup_angle_rad` and cone angle
    /// `cone_angle_rad`, otherwise as [`RollerBearing::cylindrical`].
    pub fn tapered(
        pitch_diameter_mm: f64,
        rollers: usize,
        roller_diameter_mm: f64,
        effective_length_mm: f64,
        cup_angle_rad: f64,
        cone_angle_rad: f64,
    ) -> Self {
        Self::base(
            RollerBearingKind::Tapered,
            pitch_diameter_mm,
            rollers,
            roller_diameter_mm,
            effective_length_mm,
            cup_angle_rad,
            cone_angle_rad,
        )
    }

    /// A cylindrical roller thrust bearing (81xxx), otherwise as
    /// [`RollerBearing::cylindrical`].
    pub fn thrust(
        pitch_diameter_mm: f64,
        rollers: usize,
        roller_diameter_mm: f64,
        effective_length_mm: f64,
    ) -> Self {
        Self::base(
            RollerBearingKind::Thrust,
            pitch_diameter_mm,
            rollers,
            roller_diameter_mm,
            effective_length_mm,
            FRAC_PI_2,
            FRAC_PI_2,
        )
    }

    /// The ISO/TS 16281 stiffness of one roller between both raceways,
    /// `c_l = 35948 L_we^(8/9)`, N/mm^(10/9).
    pub fn roller_stiffness(&self) -> f64 {
        ISO_ROLLER_STIFFNESS * self.effective_length_mm.powf(8.0 / 9.0)
    }

    /// The axial positions of the slice centres from the roller centre, mm:
    /// `x_k = −L/2 + (k + ½) L/n`.
    pub fn slice_positions(&self) -> impl Iterator<Item = f64> + '_ {
        let w = self.effective_length_mm / self.slices as f64;
        (0..self.slices).map(move |k| -0.5 * self.effective_length_mm + (k as f64 + 0.5) * w)
    }

    /// The direction of the rib force on a tapered roller (see
    /// [`RollerBearing::rib_angle_rad`]), rad.
    pub fn rib_angle(&self) -> f64 {
        self.rib_angle_rad
            .unwrap_or(0.5 * (self.contact_angle_rad + self.cone_angle_rad) + FRAC_PI_2)
    }

    /// Check every field: one error naming the first field out of range, its value and
    /// the valid range.
    ///
    /// # Errors
    /// [`Error::InvalidInput`] or [`Error::Geometry`] naming the field (`pitch_diameter_mm`,
    /// `rollers`, `contact_angle_rad`, `roller_profile.length_mm`, ...).
    pub fn validate(&self) -> Result<()> {
        use kontakt::error::positive_as as pos;
        const LEN: &str = "a finite length > 0 mm";
        pos("pitch_diameter_mm", self.pitch_diameter_mm, LEN)?;
        pos("roller_diameter_mm", self.roller_diameter_mm, LEN)?;
        pos("effective_length_mm", self.effective_length_mm, LEN)?;
        if !(3..=10_000).contains(&self.rollers) {
            return Err(Error::invalid(
                "rollers",
                self.rollers,
                "3 <= rollers <= 10000",
            ));
        }
        if self.slices.is_multiple_of(2) || !(1..=10_001).contains(&self.slices) {
            return Err(Error::invalid(
                "slices",
                self.slices,
                "an odd count 1..=10001 (31 or more recommended)",
            ));
        }
        let (a, ai) = (self.contact_angle_rad, self.cone_angle_rad);
        match self.kind {
            RollerBearingKind::Cylindrical => {
                if a != 0.0 {
                    return Err(Error::invalid(
                        "contact_angle_rad",
                        a,
                        "0 for a cylindrical roller bearing",
                    ));
                }
                if ai != 0.0 {
                    return Err(Error::invalid(
                        "cone_angle_rad",
                        ai,
                        "0 for a cylindrical roller bearing",
                    ));
                }
            }
            RollerBearingKind::Thrust => {
                if a != FRAC_PI_2 || ai != FRAC_PI_2 {
                    let (f, v) = if a != FRAC_PI_2 {
                        ("contact_angle_rad", a)
                    } else {
                        ("cone_angle_rad", ai)
                    };
                    return Err(Error::invalid(f, v, "pi/2 for a thrust bearing"));
                }
            }
            RollerBearingKind::Tapered => {
                if !(a > 0.0 && a < FRAC_PI_2) {
                    return Err(Error::invalid(
                        "contact_angle_rad",
                        a,
                        "0 < cup angle < pi/2 rad for a tapered roller bearing",
                    ));
                }
                if !(ai > 0.0 && ai < a) {
                    return Err(Error::invalid(
                        "cone_angle_rad",
                        ai,
                        format!(
                            "0 < cone angle < cup angle contact_angle_rad = {a} rad for a tapered roller bearing"
                        ),
                    ));
                }
                let b = self.rib_angle();
                if !(b.is_finite() && (b - ai).sin() > 0.1 && (b - a).sin() >= 0.0) {
                    return Err(Error::invalid(
                        "rib_angle_rad",
                        b,
                        "a rib force direction beta with sin(beta - cone angle) > 0.1 and sin(beta - cup angle) >= 0 (about the roller axis)",
                    ));
                }
            }
        }
        let d = self.roller_diameter_mm;
        let dm = self.pitch_diameter_mm;
        match self.kind {
            RollerBearingKind::Thrust => {
                if !(self.effective_length_mm < dm) {
                    return Err(Error::Geometry {
                        field: "effective_length_mm".into(),
                        reason: format!(
                            "a thrust roller of length {} mm does not fit inside the pitch diameter {dm} mm (needs length < pitch_diameter_mm)",
                            self.effective_length_mm
                        ),
                    });
                }
                // rollers side by side on the inner end of the path
                let inner = 0.5 * (dm - self.effective_length_mm);
                if self.rollers as f64 * d > 2.0 * PI * inner {
                    return Err(Error::Geometry {
                        field: "rollers".into(),
                        reason: format!(
                            "{} rollers of diameter {d} mm do not fit around the inner end of the roller path (radius {inner} mm): needs rollers · D_we <= 2 pi · (pitch_diameter_mm - effective_length_mm)/2",
                            self.rollers
                        ),
                    });
                }
            }
            _ => {
                if !(d < dm) {
                    return Err(Error::Geometry {
                        field: "roller_diameter_mm".into(),
                        reason: format!(
                            "a roller of diameter {d} mm does not fit between the rings of pitch diameter {dm} mm (needs roller_diameter_mm < pitch_diameter_mm)"
                        ),
                    });
                }
                if self.rollers as f64 * d > PI * dm {
                    return Err(Error::Geometry {
                        field: "rollers".into(),
                        reason: format!(
                            "{} rollers of diameter {d} mm do not fit on the pitch circle of {dm} mm: needs rollers · D_we <= pi · d_m = {:.3} mm",
                            self.rollers,
                            PI * dm
                        ),
                    });
                }
            }
        }
        if !(self.clearance_mm.is_finite() && self.clearance_mm.abs() < d) {
            return Err(Error::invalid(
                "clearance_mm",
                self.clearance_mm,
                format!(
                    "a finite clearance, |clearance| < roller_diameter_mm = {d} mm (negative: preload)"
                ),
            ));
        }
        if !self.first_roller_azimuth_rad.is_finite() {
            return Err(Error::invalid(
                "first_roller_azimuth_rad",
                self.first_roller_azimuth_rad,
                "a finite angle in rad",
            ));
        }
        for (name, p) in [
            ("roller_profile", &self.roller_profile),
            ("inner_profile", &self.inner_profile),
            ("outer_profile", &self.outer_profile),
        ] {
            p.validate()
                .map_err(|e| e.map_field(|f| format!("{name}.{f}")))?;
            let half = 0.5 * self.effective_length_mm;
            // issue 28, bad input: a roller longer than its raceway (or than its own
            // crowned length) is refused by the length the profile gives
            if let Some((field, value, reach)) = profile_reach(p)
                && reach < half * (1.0 - 1e-12)
            {
                let what = if name == "roller_profile" {
                    "the roller's crowned length is shorter than the roller"
                } else {
                    "a roller longer than its raceway"
                };
                return Err(Error::invalid(
                    format!("{name}.{field}"),
                    value,
                    format!(
                        "a profile that covers the roller's effective length L_we = {} mm ({field} >= {}; {what})",
                        self.effective_length_mm,
                        if field == "length_mm" {
                            self.effective_length_mm
                        } else {
                            half
                        }
                    ),
                ));
            }
            let w = self.effective_length_mm / self.slices as f64;
            // the outermost slice centre must see material
            let x = half - 0.5 * w;
            let drop = p.drop(x);
            if !(drop.is_finite() && drop < d) {
                return Err(Error::Geometry {
                    field: name.into(),
                    reason: format!(
                        "the profile's drop at the outermost slice centre x = {x} mm is {drop} mm: the profile is shorter than the effective length {} mm",
                        self.effective_length_mm
                    ),
                });
            }
        }
        Ok(())
    }
}

/// The field that bounds a profile's length, its value and the half-length it covers
/// (mm): `length_mm` of the profiles that have one, the last `x_mm` of a table (beyond it
/// the table extends its last drop); `None` for the profiles without an end. The name is
/// borrowed but for a table's, so that a validation (done by the life per solve, as in a
/// sweep's case) allocates nothing.
fn profile_reach(p: &Profile) -> Option<(std::borrow::Cow<'static, str>, f64, f64)> {
    match p {
        Profile::IsoLogarithmic { length_mm, .. }
        | Profile::Logarithmic { length_mm, .. }
        | Profile::Lundberg { length_mm, .. }
        | Profile::JohnsGohar { length_mm, .. }
        | Profile::Fujiwara { length_mm, .. }
        | Profile::EdgeRadii { length_mm, .. } => {
            Some(("length_mm".into(), *length_mm, 0.5 * length_mm))
        }
        Profile::Tabulated(t) => {
            let n = t.x_mm().len();
            let last = *t.x_mm().last()?;
            Some((format!("x_mm[{}]", n - 1).into(), last, last))
        }
        Profile::Straight | Profile::Circular { .. } => None,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn defaults_are_valid() {
        RollerBearing::cylindrical(50.0, 14, 8.0, 10.0)
            .validate()
            .unwrap();
        RollerBearing::tapered(
            54.0,
            23,
            6.5,
            13.66,
            14.17_f64.to_radians(),
            11.17_f64.to_radians(),
        )
        .validate()
        .unwrap();
        RollerBearing::thrust(50.0, 15, 5.0, 5.0)
            .validate()
            .unwrap();
    }

    #[test]
    fn bad_geometry_is_named() {
        let msg = |b: RollerBearing| b.validate().unwrap_err().to_string();
        let e = msg(RollerBearing::tapered(54.0, 23, 6.5, 13.66, 0.25, 0.0));
        assert!(
            e.starts_with("invalid cone_angle_rad = 0: expected 0 < cone angle"),
            "{e}"
        );
        let e = msg(RollerBearing::cylindrical(50.0, 30, 8.0, 10.0));
        assert!(
            e.starts_with("rollers: 30 rollers of diameter 8 mm do not fit"),
            "{e}"
        );
        let e = msg(RollerBearing::cylindrical(8.0, 3, 8.0, 10.0));
        assert!(
            e.starts_with("roller_diameter_mm: a roller of diameter 8 mm does not fit"),
            "{e}"
        );
        let mut b = RollerBearing::cylindrical(50.0, 14, 8.0, 10.0);
        b.slices = 30;
        assert!(msg(b).starts_with("invalid slices = 30"));
        let mut b = RollerBearing::cylindrical(50.0, 14, 8.0, 10.0);
        b.roller_profile = Profile::iso(8.0, 8.0); // shorter than the roller
        let e = msg(b);
        assert!(
            e.starts_with("invalid roller_profile.length_mm = 8: expected a profile that covers"),
            "{e}"
        );
        // issue 28, bad input: a raceway shorter than the roller, even by a little (the
        // outermost slice centre still inside: accepted silently before)
        let mut b = RollerBearing::cylindrical(50.0, 14, 8.0, 10.0);
        b.inner_profile = Profile::Logarithmic {
            drop_scale_mm: 0.001,
            length_mm: 9.9,
            flat_length_mm: 0.0,
        };
        let e = msg(b);
        assert!(
            e.starts_with("invalid inner_profile.length_mm = 9.9: expected a profile that covers the roller's effective length L_we = 10 mm (length_mm >= 10; a roller longer than its raceway)"),
            "{e}"
        );
        let mut b = RollerBearing::cylindrical(50.0, 14, 8.0, 10.0);
        b.outer_profile = Profile::Tabulated(
            crate::profile::TabulatedProfile::new(vec![0.0, 2.0, 4.0], vec![0.0, 0.0, 0.001])
                .unwrap(),
        );
        let e = msg(b);
        assert!(
            e.starts_with("invalid outer_profile.x_mm[2] = 4: expected a profile that covers"),
            "{e}"
        );
        let mut b = RollerBearing::cylindrical(50.0, 14, 8.0, 10.0);
        b.roller_profile = Profile::iso(f64::NAN, 8.0);
        let e = msg(b);
        assert!(
            e.starts_with("invalid roller_profile.length_mm = NaN"),
            "{e}"
        );
        let mut b = RollerBearing::cylindrical(50.0, 14, 8.0, 10.0);
        b.clearance_mm = f64::INFINITY;
        assert!(msg(b).starts_with("invalid clearance_mm = inf"));
    }
}
