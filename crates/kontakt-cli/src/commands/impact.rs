//! `kontakt impact CASE.toml`: a sphere striking a flat (a `method = "impact"` case): the
//! Hertz normal impact and, with friction, the oblique rebound of the rigid-body theory and
//! of the elastic analysis (Maw, Barber and Fawcett 1976), as text or JSON. The physics is
//! `kontakt_case::run_impact_case`.

use crate::cli::ImpactArgs;
use anyhow::{Context, Result};
use kontakt_case::{ImpactCase, ImpactReport, run_impact_case};
use std::io::Write;

/// Run the subcommand.
pub fn run(args: &ImpactArgs, out: &mut impl Write) -> Result<()> {
    let (label, text) = args.input.read("impact")?;
    let case = ImpactCase::from_toml_str(&text).with_context(|| label.clone())?;
    let report = run_impact_case(&case).with_context(|| label.clone())?;
    print_report(out, &report, args.input.json)
}

/// The report as text or as pretty JSON.
pub fn print_report(out: &mut impl Write, r: &ImpactReport, json: bool) -> Result<()> {
    if json {
        return crate::output::print_json(out, r);
    }
    let name = crate::output::name_suffix(r.name.as_deref());
    writeln!(
        out,
        "kontakt {} — impact of a sphere on a flat{name}",
        r.kontakt_version
    )?;
    let n = &r.normal;
    let num = crate::output::Num;
    writeln!(
        out,
        "  mass {:.5e} t, E* = {:.1} MPa; normal speed V = {:.6} mm/s, tangential u1 = {:.6} mm/s, peripheral w1 = {:.6} mm/s",
        r.mass_t,
        num(r.e_star_mpa),
        num(n.normal_speed_mm_per_s),
        num(r.tangential_velocity_mm_per_s),
        num(r.peripheral_velocity_mm_per_s)
    )?;
    writeln!(
        out,
        "  normal (Hertz): contact {:.4} µs, peak force {:.4} N, approach {:.5e} mm{}{}",
        num(1e6 * n.contact_duration_s),
        num(n.max_force_n),
        n.max_approach_mm,
        n.max_contact_radius_mm
            .map(|a| format!(", contact radius {:.5} mm", num(a)))
            .unwrap_or_default(),
        n.max_pressure_mpa
            .map(|p| format!(", p0 {:.1} MPa", num(p)))
            .unwrap_or_default()
    )?;
    if let (Some(rg), Some(el), Some(kappa), Some(chi)) = (&r.rigid, &r.elastic, r.kappa, r.chi) {
        writeln!(
            out,
            "  kappa = 4G*/E* = {:.5}, chi = {:.5}",
            num(kappa),
            num(chi)
        )?;
        writeln!(
            out,
            "  rigid ({}): u2 = {:.6} mm/s, omega2 = {:.6} rad/s, w2 = {:.6} mm/s, energy lost {:.5e} N mm",
            rg.regime.replace('_', " "),
            num(rg.tangential_velocity_mm_per_s),
            num(rg.angular_velocity_rad_per_s),
            num(rg.peripheral_velocity_mm_per_s),
            rg.energy_loss_nmm
        )?;
        writeln!(
            out,
            "  elastic ({}): psi1 = {:.5}, psi2 = {:.5}; u2 = {:.6} mm/s, omega2 = {:.6} rad/s, w2 = {:.6} mm/s, energy lost {:.5e} N mm",
            if el.slid_throughout {
                "sliding throughout"
            } else {
                "partial slip"
            },
            num(el.psi1),
            num(el.psi2),
            num(el.tangential_velocity_mm_per_s),
            num(el.angular_velocity_rad_per_s),
            num(el.peripheral_velocity_mm_per_s),
            el.energy_loss_nmm
        )?;
    }
    crate::output::print_warnings(out, &r.warnings)
}
