//! The Schaeffler (INA/FAG) frictional torque after Palmgren: `M = M0 + M1` \[N·mm\].
//!
//! - speed-dependent (no-load, hydrodynamic) part, n in r/min, ν in mm²/s, d_m in mm:
//!   `M0 = f0 (ν n)^(2/3) d_m³ · 10⁻⁷` for `ν n ≥ 2000`,
//!   `M0 = 160 · 10⁻⁷ f0 d_m³` for `ν n < 2000`;
//! - load-dependent part: `M1 = f1 P1 d_m`, P1 \[N\] the bearing type's load for the
//!   frictional torque.
//!
//! Sources: the Schaeffler catalogue's "Friction and increases in temperature" chapter
//! as quoted in the KIT lecture notes (`bearing-model.md` §3.1); the same two-term form
//! is Palmgren's, written in kgf·mm with d_m in cm by Aihara (1987, eq. 1) and used by
//! ISO 15312 for the thermal reference speed.
//!
//! **What is not here, and why.** The bearing factors f0 (per series and lubrication
//! method), f1 and the rule for P1 per bearing type, and the axial-load term M2 of
//! cylindrical roller bearings, are in catalogue tables that could not be read in any
//! public source during this work: the caller supplies f0, f1 and P1
//! ([`SchaefflerFactors`]); no value is guessed.
//!
//! **A discontinuity of the published model.** `2000^(2/3) = 158.74`, not 160: the low-speed
//! constant is the high-speed formula at ν n = 2000 rounded up, so M0 jumps by
//! `160/2000^(2/3) − 1 = +0.7937 %` when ν n falls below 2000
//! ([`LOW_SPEED_JUMP`]). We keep the published constant (the catalogue is the reference
//! here) and say so; the result flags the low-speed branch.

use super::{Envelope, OperatingPoint, finite_or, non_negative_as};
use kontakt::Result;

/// The threshold of ν n \[mm²/s · r/min\] below which M0 is constant.
pub const NU_N_THRESHOLD: f64 = 2000.0;

/// The relative jump of M0 at the threshold: `160 / 2000^(2/3) − 1` (≈ +0.794 %).
pub const LOW_SPEED_JUMP: f64 = 0.007_936_839_915_898_775;

/// The catalogue bearing factors, supplied by the caller from the Schaeffler catalogue.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct SchaefflerFactors {
    /// Bearing factor for the speed-dependent torque f0 (series and lubrication method).
    pub f0: f64,
    /// Bearing factor for the load-dependent torque f1.
    pub f1: f64,
    /// Load for the frictional torque P1 \[N\] (per bearing type in the catalogue).
    pub p1_n: f64,
}

/// The Schaeffler torque and its parts \[N·mm\].
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct SchaefflerTorque {
    /// Speed used \[r/min\].
    pub speed_rpm: f64,
    /// ν n \[mm²/s · r/min\].
    pub nu_n: f64,
    /// Speed-dependent torque M0 \[N·mm\].
    pub m0_nmm: f64,
    /// Load-dependent torque M1 \[N·mm\].
    pub m1_nmm: f64,
    /// Total M0 + M1 \[N·mm\].
    pub total_nmm: f64,
    /// ν n < 2000: M0 is the catalogue's low-speed constant (at standstill too: the model
    /// has no zero-speed limit).
    pub low_speed_branch: bool,
}

/// M0 \[N·mm\] for factor `f0`, ν n and mean diameter `dm` \[mm\].
pub fn m0(f0: f64, nu_n: f64, dm: f64) -> f64 {
    if nu_n >= NU_N_THRESHOLD {
        1e-7 * f0 * nu_n.powf(2.0 / 3.0) * dm.powi(3)
    } else {
        160e-7 * f0 * dm.powi(3)
    }
}

/// The Schaeffler torque of a bearing (envelope `env`) at `op` with the catalogue
/// factors `factors`. The loads of `op` are not used (P1 carries them); its speed and
/// viscosity are.
///
/// # Errors
/// [`kontakt::Error::InvalidInput`] naming the field: those of [`OperatingPoint::check`]
/// and [`Envelope::check`], `f0`, `f1`, `p1_n` (finite, ≥ 0); a torque that overflows
/// names `speed_rad_s`.
pub fn schaeffler(
    env: &Envelope,
    op: &OperatingPoint,
    factors: &SchaefflerFactors,
) -> Result<SchaefflerTorque> {
    env.check()?;
    op.check()?;
    let f0 = non_negative_as("f0", factors.f0, "a finite bearing factor f0 >= 0")?;
    let f1 = non_negative_as("f1", factors.f1, "a finite bearing factor f1 >= 0")?;
    let p1 = non_negative_as("p1_n", factors.p1_n, "a finite load P1 >= 0 N")?;
    let n = op.speed_rpm();
    let nu_n = op.viscosity_mm2_s * n;
    let dm = env.mean_diameter_mm();
    let m0_nmm = finite_or("speed_rad_s", op.speed_rad_s, m0(f0, nu_n, dm))?;
    let m1_nmm = finite_or("p1_n", p1, f1 * p1 * dm)?;
    Ok(SchaefflerTorque {
        speed_rpm: n,
        nu_n,
        m0_nmm,
        m1_nmm,
        total_nmm: m0_nmm + m1_nmm,
        low_speed_branch: nu_n < NU_N_THRESHOLD,
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::friction::{Lubrication, RPM_PER_RAD_S};

    fn op(rpm: f64, nu: f64) -> OperatingPoint {
        OperatingPoint {
            speed_rad_s: rpm / RPM_PER_RAD_S,
            viscosity_mm2_s: nu,
            radial_load_n: 0.0,
            axial_load_n: 0.0,
            lubrication: Lubrication::OilJet,
        }
    }

    const F: SchaefflerFactors = SchaefflerFactors {
        f0: 3.0,
        f1: 4e-4,
        p1_n: 5000.0,
    };

    #[test]
    fn m0_scales_as_nu_n_to_the_two_thirds_above_the_threshold() {
        let env = Envelope::new(40.0, 68.0, 19.0).unwrap();
        let a = schaeffler(&env, &op(1000.0, 30.0), &F).unwrap();
        for k in [1.5, 4.0, 27.0] {
            let b = schaeffler(&env, &op(1000.0 * k, 30.0), &F).unwrap();
            assert!((b.m0_nmm / a.m0_nmm / k.powf(2.0 / 3.0) - 1.0).abs() < 1e-12);
            let c = schaeffler(&env, &op(1000.0, 30.0 * k), &F).unwrap();
            assert!((c.m0_nmm / a.m0_nmm / k.powf(2.0 / 3.0) - 1.0).abs() < 1e-12);
        }
        // M0 ∝ d_m³ and M1 = f1 P1 d_m
        assert!((a.m0_nmm - 1e-7 * 3.0 * 30_000f64.powf(2.0 / 3.0) * 54f64.powi(3)).abs() < 1e-12);
        assert!((a.m1_nmm - 4e-4 * 5000.0 * 54.0).abs() < 1e-12);
        assert!(!a.low_speed_branch);
    }

    #[test]
    fn the_threshold_jump_is_the_published_rounding_and_nothing_else() {
        // just above and just below ν n = 2000
        let above = m0(1.0, NU_N_THRESHOLD, 50.0);
        let below = m0(1.0, NU_N_THRESHOLD * (1.0 - 1e-12), 50.0);
        let jump = below / above - 1.0;
        assert!((jump - LOW_SPEED_JUMP).abs() < 1e-12, "{jump}");
        assert!((160.0 / 2000f64.powf(2.0 / 3.0) - 1.0 - LOW_SPEED_JUMP).abs() < 1e-15);
        // constant below the threshold, standstill included
        let env = Envelope::new(40.0, 68.0, 19.0).unwrap();
        let still = schaeffler(&env, &op(0.0, 30.0), &F).unwrap();
        let slow = schaeffler(&env, &op(10.0, 30.0), &F).unwrap();
        assert_eq!(still.m0_nmm, slow.m0_nmm);
        assert!(still.low_speed_branch);
        assert!((still.m0_nmm - 160e-7 * 3.0 * 54f64.powi(3)).abs() < 1e-12);
    }

    #[test]
    fn bad_input_names_the_field() {
        let env = Envelope::new(40.0, 68.0, 19.0).unwrap();
        let e = schaeffler(&env, &op(-1.0, 30.0), &F).unwrap_err();
        assert_eq!(e.field(), Some("speed_rad_s"));
        let e = schaeffler(&env, &op(100.0, 0.0), &F).unwrap_err();
        assert_eq!(e.field(), Some("viscosity_mm2_s"));
        let bad = SchaefflerFactors { f0: f64::NAN, ..F };
        assert_eq!(
            schaeffler(&env, &op(100.0, 30.0), &bad)
                .unwrap_err()
                .field(),
            Some("f0")
        );
        let bad = SchaefflerFactors { p1_n: -1.0, ..F };
        assert_eq!(
            schaeffler(&env, &op(100.0, 30.0), &bad)
                .unwrap_err()
                .field(),
            Some("p1_n")
        );
    }
}
