//! The contact-based torque column of `kontakt validate --bearing` (issue 29 §4): the
//! friction section of a bearing case (`crate::bearing_friction`, derivations in
//! `docs/bearing-friction.md`) at each measured point's speed, loads and oil temperature.
//!
//! The case is compiled in: `examples/bearing_32008x_friction.toml` for Manjunath et al.'s
//! (2023) 40 × 68 × 19 TRB (the internal data of Liu 2022, as `examples/bearing_32008x.toml`).
//! Everything it assumes is in [`MANJUNATH_CONTACT_ASSUMPTIONS`], which the report lists.
//!
//! Units: r/min, N, °C, N·mm.

use super::MeasuredPoint;
use crate::bearing_case::{BearingCase, run_bearing_case};
use kontakt::{Error, Result};

/// A bearing case whose friction section gives the contact-based torque of a dataset.
#[derive(Debug, Clone, PartialEq)]
pub struct ContactSetup {
    /// The case (TOML) with `[operating]`, `[lubricant]`: its speed, load and oil
    /// temperature are replaced by each point's; its speed sweep is dropped.
    pub case_toml: &'static str,
    /// Every assumption of the case that the source does not state.
    pub assumptions: &'static [&'static str],
}

/// The 32008 X friction case (Manjunath et al. 2023 conditions).
pub const MANJUNATH_CONTACT: ContactSetup = ContactSetup {
    case_toml: include_str!("../../../../examples/bearing_32008x_friction.toml"),
    assumptions: MANJUNATH_CONTACT_ASSUMPTIONS,
};

/// What the contact-based column of the 40 × 68 × 19 TRB assumes.
pub const MANJUNATH_CONTACT_ASSUMPTIONS: &[&str] = &[
    "contact-based model: the case examples/bearing_32008x_friction.toml at each point's speed, axial load and oil temperature",
    "internal geometry: Liu (2022)'s 32008 (23 rollers, D_we 6.4885 mm, L_we 13.66 mm, d_m 54 mm, cup 14.17°, cone 11.17°, zero clearance, ISO 16281 profile; the same size as Manjunath et al.'s bearing, not proven the same bearing)",
    "ISO slice model (31 slices): the load distribution without the rollers' centrifugal force and without rib contacts; the rib's sliding friction (the rib geometry is not stated) is missing, so the column is the raceways' rolling resistance and sliding alone, a lower bound",
    "oil: FVA 3A (ν40 90.02, ν100 10.41 mm²/s, ρ 884.1 kg/m³; Walther line) at the stated oil temperature; α = 0.021 1/MPa (FVA 3's, Wingertszahn et al. 2023) assumed",
    "roughness 0.14 µm Rq on roller and raceways (composite 0.198 µm) assumed; the mixed friction preset (boundary μ 0.1, limiting shear); Biboulet & Houpert (2010) rolling resistance with the Zhu-Cheng inlet-heating factor, fully flooded; no drag (circulating oil)",
];

/// The contact-based total torque (N·mm) of `setup` at the point `p`; `None` where the
/// point does not state its axial load.
///
/// # Errors
/// Those of the case (parse, [`run_bearing_case`]); a case without `[operating]` or
/// `[lubricant]` is an error naming the table.
pub fn contact_at(setup: &ContactSetup, p: &MeasuredPoint) -> Result<Option<f64>> {
    let Some(fa) = p.axial_load_n else {
        return Ok(None);
    };
    let mut case = BearingCase::from_toml_str(setup.case_toml)?;
    case.speed.inner_rpm = p.speed_rpm;
    case.speed.outer_rpm = 0.0;
    case.load.force_n = [p.radial_load_n, 0.0, fa];
    let missing = |table: &'static str| {
        Error::invalid(
            table,
            "missing",
            "the contact setup's case with [operating] and [lubricant]",
        )
    };
    case.operating
        .as_mut()
        .ok_or_else(|| missing("operating"))?
        .sweep_inner_rpm = None;
    if let Some(op) = case.operating.as_mut() {
        // and the load and temperature sweeps (crate::bearing_friction::sweeps)
        op.sweep_axial_n = None;
        op.sweep_radial_n = None;
        op.sweep_temperature_c = None;
    }
    case.lubricant
        .as_mut()
        .ok_or_else(|| missing("lubricant"))?
        .temperature_c = p.temperature_c;
    let report = run_bearing_case(&case)?;
    let friction = report.friction.ok_or_else(|| missing("operating"))?;
    Ok(Some(friction.total_nmm))
}
