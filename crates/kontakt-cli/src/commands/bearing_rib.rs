//! The roller table of `kontakt bearing` for `roller_model = "rib_contact"`
//! (docs/bearing-model.md §15): per roller the cone, cup and rib loads, the roller's tilt and
//! the Hertz pressure on the rib; a cylindrical bearing's outer ring ribs in a column of
//! their own.

use crate::output::Num;
use anyhow::Result;
use kontakt_case::bearing_case::RollerPart;
use std::io::Write;

/// The per-roller table of the rib-contact model (after the load-zone line).
pub fn rib_roller_table(out: &mut impl Write, p: &RollerPart) -> Result<()> {
    let normal = p
        .rib_normal_deg
        .map_or_else(String::new, |d| format!(" (rib normal {:.3} deg)", Num(d)));
    writeln!(
        out,
        "  rollers in their own balance, Hertz rib contact{normal}; largest rib pressure {:.0} MPa; skew moments 0 (no friction)",
        Num(p.max_rib_pressure_mpa.unwrap_or(f64::NAN))
    )?;
    if let Some(fc) = p.roller_loads.first().and_then(|r| r.centrifugal_force_n) {
        writeln!(
            out,
            "  at speed: centrifugal force F_c = m ω_c² r_c = {:.4} N on every roller (on the cup)",
            Num(fc)
        )?;
    }
    let outer = p.roller_loads.iter().any(|r| r.outer_rib_load_n.is_some());
    let (rib, extra) = if outer {
        ("Q_irib N", format!(" {:>10}", "Q_orib N"))
    } else {
        ("Q_rib N", String::new())
    };
    writeln!(out)?;
    writeln!(
        out,
        "  {:>6} {:>10} {:>10} {:>10}{extra} {:>10} {:>12} {:>11} {:>10}",
        "ψ deg", "Q_in N", "Q_out N", rib, "q_max N/mm", "approach mm", "tilt rad", "p_rib MPa"
    )?;
    for row in &p.roller_loads {
        let extra = row
            .outer_rib_load_n
            .map_or_else(String::new, |q| format!(" {:>10.1}", Num(q)));
        writeln!(
            out,
            "  {:>6.1} {:>10.1} {:>10.1} {:>10.1}{extra} {:>10.1} {:>12.6} {:>11.3e} {:>10.0}",
            Num(row.azimuth_deg),
            Num(row.inner_load_n),
            Num(row.outer_load_n),
            Num(row.rib_load_n),
            Num(row.max_load_per_length_n_per_mm),
            Num(row.approach_mm),
            row.roller_tilt_rad.unwrap_or(0.0),
            Num(row.rib_max_pressure_mpa.unwrap_or(f64::NAN))
        )?;
    }
    Ok(())
}
