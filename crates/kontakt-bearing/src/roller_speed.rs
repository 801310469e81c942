//! The centrifugal force of the rollers of a radial roller bearing (cylindrical, tapered)
//! at speed (issue 28 §2, "centrifugal force at speed"), for the rib-contact roller model
//! ([`crate::roller_equilibrium::RibContactSolver::set_centrifugal_n`]). Derivation, frames
//! and units: `docs/bearing-model.md` §15.7.
//!
//! **Mass and centre.** A roller is the solid of revolution of its effective length L_we
//! (mm): a cylinder of diameter D_we, or for a tapered roller the frustum of half-angle
//! `β_r = (α − α_i)/2` whose mean diameter D_we lies at the roller centre O (the pitch
//! circle), end radii `R, r = D_we/2 ± (L_we/2) tan β_r`. Volume and centroid are those of
//! the rib study's roller (`kontakt::bearing::frustum`, the same function): the centroid
//! lies `e = L_we/2 − c` from O toward the large end (c its distance from the large end),
//! along the roller axis, pitched by `α_m = (α + α_i)/2` from the bearing axis, so its
//! radius is `r_c = d_m/2 + e sin α_m` (mm; `e = 0` for a cylinder). The mass is
//! `m = ρ V` with ρ in N·s²/mm⁴ (kg/m³ × 10⁻¹², [`crate::speed::density_n_s2_per_mm4`]) and
//! V in mm³, so that m is in N·s²/mm (kg × 10⁻³) and `m ω² r` in N.
//!
//! **Speed.** The cage turns at ω_c of [`crate::speed::cage_speed`] for one contact angle
//! α_m and the mean diameter (rolling without slip at both raceways of the mean section;
//! for a tapered roller with its apex on the bearing axis this is the exact cone kinematics,
//! `ω_c = (ω_i sin α_i + ω_o sin α) / (sin α_i + sin α)`, docs §15.7). The centrifugal force
//! is `F_c = m ω_c² r_c` (N), along `+e_r` of the roller's azimuth.
//!
//! **Not modelled.** Chamfers and the end faces' crowns (the body is the effective length);
//! the moment of F_c about O from the centroid's offset (the solver applies F_c at O); the
//! gyroscopic moment; the cage's own load.

use crate::geometry::{RollerBearing, RollerBearingKind};
use crate::speed::{RingSpeeds, cage_speed, centrifugal_force, density_n_s2_per_mm4};
use kontakt::{Error, Result};

/// Steel's density, kg/m³: the default of `bearing.roller_density_kg_m3`.
pub const STEEL_DENSITY_KG_M3: f64 = 7850.0;

/// One roller's inertia for its centrifugal force.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct RollerInertia {
    /// The roller's mass m, N·s²/mm (kg × 10⁻³).
    pub mass_n_s2_per_mm: f64,
    /// The radius r_c of its centre of mass from the bearing axis, mm.
    pub centre_radius_mm: f64,
    /// The pitch α_m of the roller axis (from the bearing axis, as the contact angles),
    /// rad: `(α + α_i)/2`.
    pub axis_pitch_rad: f64,
}

/// The centrifugal force of every roller at one pair of ring speeds.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct RollerCentrifugal {
    /// The roller's mass and centre.
    pub inertia: RollerInertia,
    /// The cage speed ω_c, rad/s.
    pub cage_rad_s: f64,
    /// `F_c = m ω_c² r_c`, N per roller.
    pub force_n: f64,
}

/// The mass and the centre of mass of a roller of `bearing` (cylindrical or tapered) of
/// density `density_kg_m3` (kg/m³), module docs.
///
/// # Errors
/// [`Error::InvalidInput`] naming `roller_density_kg_m3` unless finite and > 0 (and at most
/// 100 000 kg/m³), `kind` for a thrust bearing, `roller_length_mm` when the tapered roller's
/// small end would reach its apex.
pub fn roller_inertia(bearing: &RollerBearing, density_kg_m3: f64) -> Result<RollerInertia> {
    if !(density_kg_m3.is_finite() && density_kg_m3 > 0.0 && density_kg_m3 <= 1e5) {
        return Err(Error::invalid(
            "roller_density_kg_m3",
            density_kg_m3,
            "a finite density > 0 and <= 100000 kg/m³ (steel 7850)",
        ));
    }
    if bearing.kind == RollerBearingKind::Thrust {
        return Err(Error::invalid(
            "kind",
            "thrust",
            "a cylindrical or tapered roller bearing (the rollers' centrifugal force of a thrust bearing is not modelled)",
        ));
    }
    let (alpha, alpha_i) = (bearing.contact_angle_rad, bearing.cone_angle_rad);
    let (d, l) = (bearing.roller_diameter_mm, bearing.effective_length_mm);
    let half = 0.5 * (alpha - alpha_i);
    let pitch = 0.5 * (alpha + alpha_i);
    let step = 0.5 * l * half.tan();
    let (large, small) = (0.5 * d + step, 0.5 * d - step);
    if !(small > 0.0) {
        return Err(Error::invalid(
            "roller_length_mm",
            l,
            format!(
                "less than D_we / tan((α − α_i)/2) = {:.6} mm (the roller's small end reaches its apex)",
                d / half.tan()
            ),
        ));
    }
    let (volume, from_large) = kontakt::bearing::frustum(large, small, l);
    Ok(RollerInertia {
        mass_n_s2_per_mm: density_n_s2_per_mm4(density_kg_m3) * volume,
        centre_radius_mm: 0.5 * bearing.pitch_diameter_mm + (0.5 * l - from_large) * pitch.sin(),
        axis_pitch_rad: pitch,
    })
}

/// The rollers' centrifugal force at the ring speeds `speeds` (rad/s): the cage speed of
/// [`cage_speed`] at the axis pitch α_m and the mean diameter, `F_c = m ω_c² r_c` (N).
///
/// # Errors
/// Those of [`roller_inertia`] and of [`RingSpeeds::validate`].
pub fn roller_centrifugal(
    bearing: &RollerBearing,
    speeds: RingSpeeds,
    density_kg_m3: f64,
) -> Result<RollerCentrifugal> {
    speeds.validate()?;
    let inertia = roller_inertia(bearing, density_kg_m3)?;
    let w = cage_speed(
        speeds,
        bearing.roller_diameter_mm,
        bearing.pitch_diameter_mm,
        inertia.axis_pitch_rad,
    );
    Ok(RollerCentrifugal {
        inertia,
        cage_rad_s: w,
        force_n: centrifugal_force(inertia.mass_n_s2_per_mm, 2.0 * inertia.centre_radius_mm, w),
    })
}

#[cfg(test)]
mod tests {
    #![allow(clippy::unwrap_used)]
    use super::*;
    use crate::geometry::RollerBearing;
    use crate::profile::Profile;

    fn bearing(kind: RollerBearingKind, alpha_deg: f64, alpha_i_deg: f64) -> RollerBearing {
        RollerBearing {
            kind,
            pitch_diameter_mm: 74.141904,
            rollers: 17,
            roller_diameter_mm: 10.161476,
            effective_length_mm: 16.0,
            contact_angle_rad: alpha_deg.to_radians(),
            cone_angle_rad: alpha_i_deg.to_radians(),
            rib_angle_rad: None,
            clearance_mm: 0.0,
            roller_profile: Profile::Straight,
            inner_profile: Profile::Straight,
            outer_profile: Profile::Straight,
            slices: 31,
            first_roller_azimuth_rad: 0.0,
        }
    }

    fn rel(a: f64, b: f64) -> f64 {
        (a - b).abs() / b.abs()
    }

    /// A cylinder: m = ρ π D² L/4, r_c = d_m/2, ω_c = ½ ω_i (1 − D/d_m) with the outer ring
    /// at rest (Harris & Kotzalas 2006), F_c = m ω_c² d_m/2: all in closed form.
    #[test]
    fn cylindrical_roller_in_closed_form() {
        let b = bearing(RollerBearingKind::Cylindrical, 0.0, 0.0);
        let wi = 300.0;
        let c = roller_centrifugal(&b, RingSpeeds::new(wi, 0.0), 7850.0).unwrap();
        let (d, l, dm) = (10.161476, 16.0, 74.141904);
        let m = 7850e-12 * std::f64::consts::PI * d * d * l / 4.0;
        assert!(rel(c.inertia.mass_n_s2_per_mm, m) < 1e-14);
        assert!(rel(c.inertia.centre_radius_mm, dm / 2.0) < 1e-15);
        let wc = 0.5 * wi * (1.0 - d / dm);
        assert!(rel(c.cage_rad_s, wc) < 1e-14);
        assert!(rel(c.force_n, m * wc * wc * dm / 2.0) < 1e-14);
    }

    /// A tapered roller: its centre of mass lies toward the large end, outside the pitch
    /// circle; the cage speed is the cone kinematics' (ω_i sin α_i + ω_o sin α) /
    /// (sin α_i + sin α) (`kontakt::bearing::TaperedKinematics`).
    #[test]
    fn tapered_roller_centre_and_cage_speed() {
        let b = bearing(RollerBearingKind::Tapered, 25.481595648, 19.481595648);
        let s = RingSpeeds::new(314.0, -20.0);
        let c = roller_centrifugal(&b, s, 7850.0).unwrap();
        assert!(c.inertia.centre_radius_mm > 0.5 * b.pitch_diameter_mm + 0.01);
        let (si, so) = (b.cone_angle_rad.sin(), b.contact_angle_rad.sin());
        let want = (314.0 * si - 20.0 * so) / (si + so);
        // the case's diameters are rounded to 1e-6 mm: the apex is on the axis to ~1e-7
        eprintln!("cage speed {} rad/s, cone kinematics {want}", c.cage_rad_s);
        assert!(rel(c.cage_rad_s, want) < 1e-7, "{} {want}", c.cage_rad_s);
    }

    /// F_c ∝ ω² and ∝ ρ exactly (bit for bit up to one rounding), zero at rest.
    #[test]
    fn force_scales_with_speed_squared_and_density() {
        for kind in [RollerBearingKind::Cylindrical, RollerBearingKind::Tapered] {
            let b = match kind {
                RollerBearingKind::Tapered => bearing(kind, 25.0, 19.0),
                _ => bearing(kind, 0.0, 0.0),
            };
            let f = |w: f64, rho: f64| roller_centrifugal(&b, RingSpeeds::new(w, 0.0), rho);
            let base = f(100.0, 7850.0).unwrap().force_n;
            assert!(base > 0.0);
            assert!(rel(f(300.0, 7850.0).unwrap().force_n, 9.0 * base) < 1e-14);
            assert!(rel(f(-100.0, 7850.0).unwrap().force_n, base) < 1e-15);
            assert!(rel(f(100.0, 3925.0).unwrap().force_n, 0.5 * base) < 1e-14);
            assert_eq!(f(0.0, 7850.0).unwrap().force_n, 0.0);
        }
    }

    #[test]
    fn bad_input_is_named() {
        let b = bearing(RollerBearingKind::Cylindrical, 0.0, 0.0);
        for rho in [0.0, -1.0, f64::NAN, f64::INFINITY] {
            let e = roller_inertia(&b, rho).unwrap_err().to_string();
            assert!(e.starts_with("invalid roller_density_kg_m3"), "{e}");
        }
        let t = bearing(RollerBearingKind::Thrust, 90.0, 90.0);
        let e = roller_inertia(&t, 7850.0).unwrap_err().to_string();
        assert!(e.starts_with("invalid kind = thrust"), "{e}");
        let e = roller_centrifugal(&b, RingSpeeds::new(f64::NAN, 0.0), 7850.0)
            .unwrap_err()
            .to_string();
        assert!(e.starts_with("invalid speeds.inner_rad_s"), "{e}");
    }
}
