//! The roller table of `kontakt bearing` for `roller_model = "rib_contact"`
//! (docs/bearing-model.md §9): per roller the cone, cup and rib loads, the roller's tilt and
//! the Hertz pressure on the rib.

use crate::output::Num;
use anyhow::Result;
use kontakt_case::bearing_case::RollerPart;
use std::io::Write;

/// The per-roller table of the rib-contact model (after the load-zone line).
pub fn rib_roller_table(out: &mut impl Write, p: &RollerPart) -> Result<()> {
    writeln!(
        out,
        "  rollers in their own balance, Hertz rib contact (rib normal {:.3} deg); largest rib pressure {:.0} MPa; skew moments 0 (no friction)",
        Num(p.rib_normal_deg.unwrap_or(f64::NAN)),
        Num(p.max_rib_pressure_mpa.unwrap_or(f64::NAN))
    )?;
    writeln!(out)?;
    writeln!(
        out,
        "  {:>6} {:>10} {:>10} {:>10} {:>10} {:>12} {:>11} {:>10}",
        "ψ deg",
        "Q_in N",
        "Q_out N",
        "Q_rib N",
        "q_max N/mm",
        "approach mm",
        "tilt rad",
        "p_rib MPa"
    )?;
    for row in &p.roller_loads {
        writeln!(
            out,
            "  {:>6.1} {:>10.1} {:>10.1} {:>10.1} {:>10.1} {:>12.6} {:>11.3e} {:>10.0}",
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
