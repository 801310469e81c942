//! The contact-based torque column of `kontakt validate --bearing` (issue 29 §4): the
//! friction section of a bearing case (`crate::bearing_friction`, derivations in
//! `docs/bearing-friction.md`) at each measured point's speed, loads and oil temperature,
//! with its breakdown (cone, cup, rib, drag).
//!
//! The cases are compiled in: `examples/bearing_32008x_rib_friction.toml` for Manjunath et
//! al.'s (2023) 40 × 68 × 19 TRB (the internal data of Liu 2022 and an assumed rib,
//! `roller_model = "rib_contact"`), and `examples/bearing_32008x_friction.toml`, the same
//! bearing without its rib (the ISO slice model: raceways only), for the comparison.
//! Everything they assume is in [`MANJUNATH_CONTACT_ASSUMPTIONS`], which the report lists.
//!
//! [`ContactVariation`] changes the uncertain inputs of a case (the rib's face radius,
//! contact height and roughness, the oil's temperature rise and pressure-viscosity
//! coefficient, the boundary friction coefficient) for the sensitivity study of
//! `super::rib_study`.
//!
//! Units: r/min, N, °C, mm, N·mm.

use super::MeasuredPoint;
use crate::bearing_case::{BearingCase, BearingSpec, run_bearing_case};
use crate::bearing_friction::FrictionReport;
use kontakt::bearing::FaceShape;
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

/// The 32008 X friction case with its rib (Manjunath et al. 2023 conditions).
pub const MANJUNATH_CONTACT: ContactSetup = ContactSetup {
    case_toml: include_str!("../../../../examples/bearing_32008x_rib_friction.toml"),
    assumptions: MANJUNATH_CONTACT_ASSUMPTIONS,
};

/// The same bearing without its rib (ISO slice model, raceways only): the column of the
/// previous study, kept for the comparison (`super::rib_study`).
pub const MANJUNATH_CONTACT_RACEWAYS: ContactSetup = ContactSetup {
    case_toml: include_str!("../../../../examples/bearing_32008x_friction.toml"),
    assumptions: &[
        "raceways only: examples/bearing_32008x_friction.toml (ISO slice model, no rib contact)",
    ],
};

/// What the contact-based column of the 40 × 68 × 19 TRB assumes.
pub const MANJUNATH_CONTACT_ASSUMPTIONS: &[&str] = &[
    "contact-based model: the case examples/bearing_32008x_rib_friction.toml at each point's speed, axial load and oil temperature",
    "internal geometry: Liu (2022)'s 32008 (23 rollers, D_we 6.4885 mm, L_we 13.66 mm, d_m 54 mm, cup 14.17°, cone 11.17°, zero clearance, ISO 16281 profile; the same size as Manjunath et al.'s bearing, not proven the same bearing)",
    "rib (stated by no source for this bearing, assumed): spherical roller end of radius 117.6 mm (0.9 × the contact point's apex distance 130.6 mm), conical rib, contact 1.0 mm above the inner raceway line (2.423 mm from the roller axis; rib slide-to-roll ratio 0.38, inside Zhou & Hoeprich 1991's 0.25-0.4)",
    "every roller in its own force and moment balance with its centrifugal force (roller_model = \"rib_contact\", Hertz rib contact); the rib friction is kontakt's rib friction model (Hertz pressure, Chittenden et al. 1985 film) with the rib loads of that balance",
    "oil: FVA 3A (ν40 90.02, ν100 10.41 mm²/s, ρ 884.1 kg/m³; Walther line) at the stated oil temperature; α = 0.021 1/MPa (FVA 3's, Wingertszahn et al. 2023) assumed",
    "roughness 0.14 µm Rq on roller, raceways and rib (composite 0.198 µm) assumed; the mixed friction preset (boundary μ 0.1, limiting shear); Biboulet & Houpert (2010) rolling resistance with the Zhu-Cheng inlet-heating factor, fully flooded; no drag (circulating oil)",
];

/// The contact-based torque and its breakdown \[N·mm\] (the moment on the inner ring).
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct ContactParts {
    /// cone + cup + rib + drag.
    pub total_nmm: f64,
    /// The cone's (inner raceway's) share: rolling resistance and sliding.
    pub cone_nmm: f64,
    /// The cup's (outer raceway's) share.
    pub cup_nmm: f64,
    /// The rib contacts' share.
    pub rib_nmm: f64,
    /// Drag.
    pub drag_nmm: f64,
}

impl ContactParts {
    /// The raceways' share, cone + cup \[N·mm\]: what the rolling-resistance torque M_rr of
    /// Manjunath et al. (2023) stands for.
    pub fn raceways_nmm(&self) -> f64 {
        self.cone_nmm + self.cup_nmm
    }

    fn of(f: &FrictionReport) -> Self {
        ContactParts {
            total_nmm: f.total_nmm,
            cone_nmm: f.cone_rolling_nmm + f.cone_sliding_nmm,
            cup_nmm: f.cup_rolling_nmm + f.cup_sliding_nmm,
            rib_nmm: f.rib_nmm,
            drag_nmm: f.drag_nmm,
        }
    }
}

/// Changes to a contact setup's uncertain inputs (the sensitivity study). `None` / 0 keeps
/// the case's value.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct ContactVariation {
    /// The roller end's sphere radius \[mm\] (a case with a spherical face).
    pub face_radius_mm: Option<f64>,
    /// The rib contact's distance from the roller axis \[mm\].
    pub contact_height_mm: Option<f64>,
    /// RMS roughness of roller end and rib \[mm\], the rib contact only: the raceways keep the
    /// case's roughness (the case is run twice, its rib share taken from the second run).
    pub rib_roughness_mm: Option<[f64; 2]>,
    /// The bearing's temperature above the stated oil temperature \[K\] (every contact).
    pub temperature_rise_k: f64,
    /// The oil's pressure-viscosity coefficient \[1/MPa\].
    pub alpha_per_mpa: Option<f64>,
    /// The boundary friction coefficient of the mixed law (raceways and rib).
    pub boundary_mu: Option<f64>,
}

/// The contact-based total torque (N·mm) of `setup` at the point `p`; `None` where the
/// point does not state its axial load.
///
/// # Errors
/// Those of [`contact_parts_at`].
pub fn contact_at(setup: &ContactSetup, p: &MeasuredPoint) -> Result<Option<f64>> {
    Ok(contact_parts_at(setup, &ContactVariation::default(), p)?.map(|c| c.total_nmm))
}

/// The contact-based torque of `setup`, changed by `variation`, at the point `p`, with its
/// breakdown; `None` where the point does not state its axial load.
///
/// # Errors
/// Those of the case (parse, [`run_bearing_case`]); a case without `[operating]` or
/// `[lubricant]` is an error naming the table, a face radius for a case without a
/// spherical rib face or a contact height without `[bearing.rib_contact]` one naming the key.
pub fn contact_parts_at(
    setup: &ContactSetup,
    variation: &ContactVariation,
    p: &MeasuredPoint,
) -> Result<Option<ContactParts>> {
    let Some(fa) = p.axial_load_n else {
        return Ok(None);
    };
    contact_parts(
        setup,
        variation,
        p.speed_rpm,
        fa,
        p.radial_load_n,
        p.temperature_c,
    )
    .map(Some)
}

/// As [`contact_parts_at`] at a speed \[r/min\], loads \[N\] and oil temperature \[°C\].
///
/// # Errors
/// Those of [`contact_parts_at`].
pub fn contact_parts(
    setup: &ContactSetup,
    variation: &ContactVariation,
    speed_rpm: f64,
    axial_load_n: f64,
    radial_load_n: f64,
    temperature_c: f64,
) -> Result<ContactParts> {
    let mut case = BearingCase::from_toml_str(setup.case_toml)?;
    case.speed.inner_rpm = speed_rpm;
    case.speed.outer_rpm = 0.0;
    case.load.force_n = [radial_load_n, 0.0, axial_load_n];
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
    let lubricant = case
        .lubricant
        .as_mut()
        .ok_or_else(|| missing("lubricant"))?;
    lubricant.temperature_c = temperature_c + variation.temperature_rise_k;
    if let Some(a) = variation.alpha_per_mpa {
        lubricant.alpha_per_mpa = a;
    }
    if let Some(mu) = variation.boundary_mu {
        case.friction.get_or_insert_with(Default::default).mu = Some(mu);
    }
    if variation.face_radius_mm.is_some() || variation.contact_height_mm.is_some() {
        let rib = match &mut case.bearing {
            BearingSpec::Tapered(r) => r.rib_contact.as_mut(),
            _ => None,
        }
        .ok_or_else(|| {
            Error::invalid(
                "bearing.rib_contact",
                "missing",
                "a tapered bearing case with [bearing.rib_contact] for a rib variation",
            )
        })?;
        if let Some(h) = variation.contact_height_mm {
            rib.contact_height_mm = Some(h);
        }
        if let Some(r) = variation.face_radius_mm {
            match &mut rib.face {
                Some(FaceShape::Sphere { radius }) => *radius = r,
                _ => {
                    return Err(Error::invalid(
                        "bearing.rib_contact.face",
                        "not a sphere",
                        "a spherical roller end face for a face radius variation",
                    ));
                }
            }
        }
    }
    let run = |case: &BearingCase| -> Result<ContactParts> {
        let report = run_bearing_case(case)?;
        let friction = report.friction.ok_or_else(|| missing("operating"))?;
        Ok(ContactParts::of(&friction))
    };
    let mut parts = run(&case)?;
    if let Some(sigma) = variation.rib_roughness_mm {
        let mut rough = case.clone();
        rough
            .lubricant
            .as_mut()
            .ok_or_else(|| missing("lubricant"))?
            .roughness_mm = sigma;
        let rib = run(&rough)?.rib_nmm;
        parts.total_nmm += rib - parts.rib_nmm;
        parts.rib_nmm = rib;
    }
    Ok(parts)
}

/// The LM12700 of Zhou & Hoeprich (1991), Fig. 9, with an assumed internal geometry, rib,
/// load and oil (`examples/bearing_lm12700_rib_friction.toml`): its rib and raceway torque
/// against speed beside their Fig. 9 totals (`super::rib_study::lm12700_breakdown`).
pub const LM12700_CONTACT: ContactSetup = ContactSetup {
    case_toml: include_str!("../../../../examples/bearing_lm12700_rib_friction.toml"),
    assumptions: LM12700_CONTACT_ASSUMPTIONS,
};

/// What the contact-based LM12700 case assumes beyond the caption of Zhou & Hoeprich's Fig. 9.
pub const LM12700_CONTACT_ASSUMPTIONS: &[&str] = &[
    "stated by the paper (Fig. 9 caption): cup work-point diameter 41.5 mm, cup angle 11°32', roller length 10.8 mm, 17 rollers, SAE 75 oil at 80 °C",
    "roller mean diameter 5.6493 mm (rollers filling 85 % of the pitch circle), pitch diameter 35.965 mm = 41.5 − D_we cos α_o, cone angle 8.4162° from the common apex (roller half-angle 1.5585°)",
    "rib as the 32008 X case's, scaled: spherical roller end of radius 98.4 mm (0.9 × apex distance 109.3 mm), conical rib, contact 0.868 mm above the inner raceway line (2.1035 mm from the roller axis)",
    "axial load 3.6 kN (a third party's back-calculation, not in the paper), also 2 and 6 kN; oil ISO VG 32 for SAE 75 (viscosity not stated), ρ 870 kg/m³, α 0.018 1/MPa; roughness 0.14 µm on every surface; mixed friction preset; no drag",
];
