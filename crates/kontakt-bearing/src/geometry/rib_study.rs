//! The tapered roller bearing of a roller/rib pair (kontakt's rib study,
//! `kontakt::bearing::RollerRib` with its `RollerSet`) as a whole bearing: the one mapping
//! used by the rib friction of every roller and by `examples/bearing_rib_study_60mm.toml`.
//!
//! From the pair's construction (common apex, docs/bearing.md §1): the cone angle is the
//! inner raceway half-angle α_i, the cup angle α_i + 2β, the rib angle the direction of
//! the rib contact's normal (rib into roller) in the section plane, measured like the
//! contact angles, `atan2(−n_z, n_x)`. The roller runs `length` from its large end (apex
//! distance `s_L = r_L / tan β`) toward the apex; its middle, at `s_m = s_L − length/2`,
//! gives the mean roller diameter `2 s_m tan β` and the pitch diameter
//! `2 s_m sin(α_i + β)`; the effective length is the whole roller length. Not from the
//! pair (it has none): the ISO/TS 16281 roller profile, straight raceways, zero clearance,
//! 31 slices (the defaults of [`RollerBearing::tapered`]).

use super::RollerBearing;
use kontakt::bearing::{RollerRib, RollerSet, TaperedKinematics};
use kontakt::{Error, Result};

impl RollerBearing {
    /// The single-row tapered roller bearing of the roller/rib pair `pair` with the
    /// rollers `rollers` (count and length; module docs). Lengths in mm, angles in rad.
    ///
    /// # Errors
    /// Those of [`RollerSet::check`] and [`TaperedKinematics::of_roller_rib`]; field
    /// `length` when the roller would reach past the apex.
    pub fn of_roller_rib(pair: &RollerRib, rollers: &RollerSet) -> Result<Self> {
        rollers.check()?;
        let k = TaperedKinematics::of_roller_rib(pair, 0.0, 0.0)?;
        let beta = k.roller_half_angle;
        let s_large = pair.spec.bearing.roller_large_end_radius / beta.tan();
        let s_mid = s_large - 0.5 * rollers.length;
        if !(s_mid > 0.5 * rollers.length) {
            return Err(Error::invalid(
                "length",
                rollers.length,
                format!("less than the apex distance of the large end, {s_large:.3} mm"),
            ));
        }
        let n = pair.contact.normal.into_inner();
        let mut b = RollerBearing::tapered(
            2.0 * s_mid * k.roller_axis_angle().sin(),
            rollers.count,
            2.0 * s_mid * beta.tan(),
            rollers.length,
            k.outer_raceway_angle(),
            k.inner_raceway_angle,
        );
        b.rib_angle_rad = Some((-n.z).atan2(n.x));
        Ok(b)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use kontakt::bearing::RollerRibSpec;

    /// The rib study's bearing: the numbers `examples/bearing_rib_study_60mm.toml` states
    /// (its comment derives them by hand), to their rounding.
    #[test]
    fn the_rib_study_bearing_has_the_example_numbers() {
        let pair = RollerRib::new(RollerRibSpec::builtin("sphere-torus-57").unwrap()).unwrap();
        let b = RollerBearing::of_roller_rib(&pair, &RollerSet::default()).unwrap();
        assert!((b.pitch_diameter_mm - 74.141904).abs() < 5e-7);
        assert!((b.roller_diameter_mm - 10.161476).abs() < 5e-7);
        assert!((b.contact_angle_rad.to_degrees() - 25.481595648).abs() < 5e-10);
        assert!((b.cone_angle_rad.to_degrees() - 19.481595648).abs() < 5e-10);
        let rib = b.rib_angle_rad.unwrap().to_degrees();
        assert!((rib - 109.716252089).abs() < 5e-10, "{rib}");
        assert_eq!((b.rollers, b.effective_length_mm), (17, 16.0));
        b.validate().unwrap();
        let long = RollerSet {
            length: 200.0,
            ..RollerSet::default()
        };
        let e = RollerBearing::of_roller_rib(&pair, &long).unwrap_err();
        assert!(e.to_string().contains("length"), "{e}");
    }
}
