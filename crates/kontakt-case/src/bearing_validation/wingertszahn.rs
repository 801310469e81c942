//! Wingertszahn et al. (2023)'s TRB 32216 (issue 29 §4): the contact-based torque against
//! the measured radial sweep (6.5 kN axial plus 1-15 kN radial at 2000 r/min, FVA 3 oil bath
//! at half roller height, 50 °C) and the axial speed sweep, and the number of loaded
//! rollers against the paper's (11 of 16 at 16 kN radial, their Fig. 8, a simulation).
//!
//! The case is compiled in: `examples/bearing_32216_friction.toml` (its radial sweep is the
//! one of [`radial_sweep`]). The paper gives the envelope, the pitch diameter, the rollers
//! and the profile but not the raceway angles nor the rib: everything the case assumes is in
//! [`CONTACT_32216_ASSUMPTIONS`] (and `validation/measured/README.md`).
//!
//! Units: r/min, N, °C, N·mm.

use super::{ContactSetup, FILES, parse_points};
use crate::bearing_case::{BearingCase, run_bearing_case};
use kontakt::{Error, Result};

/// The contact-based 32216 case (Wingertszahn et al. 2023 conditions).
pub const CONTACT_32216: ContactSetup = ContactSetup {
    case_toml: include_str!("../../../../examples/bearing_32216_friction.toml"),
    assumptions: CONTACT_32216_ASSUMPTIONS,
};

/// What the contact-based column of the 32216 assumes.
pub const CONTACT_32216_ASSUMPTIONS: &[&str] = &[
    "contact-based model: the case examples/bearing_32216_friction.toml at each point's speed, loads and temperature",
    "geometry from the paper (Table 4): pitch diameter 108.5 mm, 16 rollers of 17 mm, roller length 22.7 mm less the two 1 mm edge radii (20.7 mm effective, the profile's c_p)",
    "not in the paper, assumed: cup angle 16.0° (the catalogue e = 0.43 of a 32216, e = 1.5 tan α), cone angle 11.7° (the roller apex on the bearing axis), zero clearance, the ISO/TS 16281 profile for the paper's logarithmic one, the shaft holding the tilts",
    "ISO slice model (31 slices) without rib contacts and without the rollers' centrifugal force: the rib sliding friction (rib geometry not given) is missing",
    "oil FVA 3 as the Walther line through the paper's Vogel fit at 40 and 100 °C (ν40 96.88, ν100 11.79 mm²/s; within 0.1 % of the Vogel fit at 42 and 50 °C), ρ 866.6 kg/m³ (Vogel's at 50 °C), α = 0.021 1/MPa assumed; the test temperature (outer ring) taken as the oil's",
    "roughness: the paper's raceway σ = 0.16 µm taken as the composite; the mixed friction preset; Biboulet & Houpert (2010) rolling resistance with the Zhu-Cheng inlet-heating factor, fully flooded (the half-roller bath feeds every contact)",
    "no drag term: SKF's drag factor V_M is a diagram reading not available here, and the Schaeffler f0 of the 322 series in an oil bath was not found in a citable source",
];

/// Loaded rollers of the paper's simulation at 6 kN axial plus 16 kN radial (Fig. 8).
pub const PAPER_LOADED_ROLLERS_AT_16KN: usize = 11;

/// One point of the radial sweep.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct RadialPoint {
    /// Radial force \[N\].
    pub radial_load_n: f64,
    /// The contact-based torque \[N·mm\].
    pub contact_nmm: f64,
    /// SKF 2004 (without drag) \[N·mm\].
    pub skf_nmm: Option<f64>,
    /// Rollers that carry load.
    pub loaded_rollers: usize,
    /// The measured torque at this radial load, if there is a point \[N·mm\].
    pub measured_nmm: Option<f64>,
}

/// The example's radial sweep (1-16 kN at 6.5 kN axial, 2000 r/min, 50 °C), one solve per
/// point warm-started from the last, beside the measured points of
/// `wingertszahn2023_radial.csv` at the same radial loads.
///
/// # Errors
/// Those of the case and of the measured file.
pub fn radial_sweep() -> Result<Vec<RadialPoint>> {
    let case = BearingCase::from_toml_str(CONTACT_32216.case_toml)?;
    let report = run_bearing_case(&case)?;
    let friction = report
        .friction
        .ok_or_else(|| Error::invalid("operating", "missing", "the 32216 case's [operating]"))?;
    let (file, text) = FILES
        .iter()
        .find(|(f, _)| *f == "wingertszahn2023_radial.csv")
        .ok_or_else(|| Error::invalid("dataset", "wingertszahn2023_radial", "a file of FILES"))?;
    let measured = parse_points(file, text)?;
    Ok(friction
        .radial_load_sweep
        .iter()
        .map(|r| RadialPoint {
            radial_load_n: r.radial_load_n,
            contact_nmm: r.total_nmm,
            skf_nmm: r.skf_total_nmm,
            loaded_rollers: r.loaded_rollers,
            measured_nmm: measured
                .iter()
                .find(|p| p.radial_load_n == r.radial_load_n)
                .map(|p| p.torque_nmm),
        })
        .collect())
}

#[cfg(test)]
mod tests {
    #![allow(clippy::unwrap_used)] // tests: a panic is a failure with its message
    use super::*;
    use crate::bearing_validation::{compare, datasets, deviation_pct};

    /// The radial sweep: the contact-based torque falls as the radial load rises (the
    /// measurement does above 4 kN; SKF rises), the loaded rollers fall from 16 to the
    /// paper's 11 at 16 kN. The level is recorded, not asserted (docs/VALIDATION.md).
    #[test]
    fn the_torque_falls_with_the_radial_load_as_measured() {
        let rows = radial_sweep().unwrap();
        println!("Fr N | contact N·mm | measured | dev % | SKF (no drag) | dev % | loaded");
        for r in &rows {
            let dev = |m: Option<f64>, x: f64| m.map(|m| deviation_pct(x, m));
            println!(
                "{:.0} | {:.0} | {:?} | {:?} | {:.0} | {:?} | {}",
                r.radial_load_n,
                r.contact_nmm,
                r.measured_nmm,
                dev(r.measured_nmm, r.contact_nmm).map(|d| d.round()),
                r.skf_nmm.unwrap(),
                dev(r.measured_nmm, r.skf_nmm.unwrap()).map(|d| d.round()),
                r.loaded_rollers
            );
        }
        let with_measure: Vec<_> = rows.iter().filter(|r| r.measured_nmm.is_some()).collect();
        assert_eq!(with_measure.len(), 5, "every measured radial load is swept");
        // from 4 kN on the measured torque falls, and so does ours; SKF rises
        let tail: Vec<_> = with_measure.iter().skip(1).collect();
        for w in tail.windows(2) {
            assert!(w[1].contact_nmm < w[0].contact_nmm);
            assert!(w[1].skf_nmm > w[0].skf_nmm);
        }
        let first = with_measure[1];
        let last = with_measure[4];
        let drop = |a: f64, b: f64| 100.0 * (1.0 - b / a);
        let measured_drop = drop(first.measured_nmm.unwrap(), last.measured_nmm.unwrap());
        let model_drop = drop(first.contact_nmm, last.contact_nmm);
        println!("4 → 15 kN: measured −{measured_drop:.0} %, contact-based −{model_drop:.0} %");
        assert!(model_drop > 0.0 && measured_drop > 0.0);
        assert_eq!(rows[0].loaded_rollers, 16);
        let at16 = rows.iter().find(|r| r.radial_load_n == 16_000.0).unwrap();
        assert_eq!(at16.loaded_rollers, PAPER_LOADED_ROLLERS_AT_16KN);
    }

    /// The axial (speed) and combined datasets get the contact-based column: the torque
    /// rises with speed as measured; the deviations are recorded in docs/VALIDATION.md.
    #[test]
    fn the_axial_and_combined_sweeps_have_the_contact_column() {
        for id in ["wingertszahn2023_axial", "wingertszahn2023_combined"] {
            let set = datasets()
                .unwrap()
                .into_iter()
                .find(|d| d.id == id)
                .unwrap();
            let c = compare(&set).unwrap();
            for r in &c.rows {
                println!(
                    "{id}: {} r/min {} °C: measured {:.0}, contact {:.0} ({:+.0} %), SKF {:.0} ({:+.0} %)",
                    r.measured.speed_rpm,
                    r.measured.temperature_c,
                    r.measured.torque_nmm,
                    r.contact_nmm.unwrap(),
                    r.contact_deviation_pct().unwrap(),
                    r.skf.unwrap().total_nmm,
                    r.skf_deviation_pct().unwrap()
                );
            }
            // each row is the example run at the point's speed, loads and temperature,
            // through the case text (an independent path)
            for r in &c.rows {
                let m = &r.measured;
                let text = CONTACT_32216
                    .case_toml
                    .replace(
                        "inner_rpm = 2000.0",
                        &format!("inner_rpm = {:?}", m.speed_rpm),
                    )
                    .replace(
                        "force_n = [1000.0, 0.0, 6500.0]",
                        &format!(
                            "force_n = [{:?}, 0.0, {:?}]",
                            m.radial_load_n,
                            m.axial_load_n.unwrap()
                        ),
                    )
                    .replace(
                        "temperature_c = 50.0",
                        &format!("temperature_c = {:?}", m.temperature_c),
                    )
                    .replace("sweep_radial_n", "# sweep_radial_n");
                let case = BearingCase::from_toml_str(&text).unwrap();
                let f = run_bearing_case(&case).unwrap().friction.unwrap();
                assert!(f.radial_load_sweep.is_empty());
                assert!((f.total_nmm / r.contact_nmm.unwrap() - 1.0).abs() < 1e-9);
            }
            let at50: Vec<_> = c
                .rows
                .iter()
                .filter(|r| r.measured.temperature_c == 50.0)
                .collect();
            for w in at50.windows(2) {
                assert!(w[1].contact_nmm > w[0].contact_nmm);
            }
            println!("{id}: {:?}", c.contact_deviation_stats());
        }
    }
}
