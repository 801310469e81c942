//! Human tables and JSON output.

use anyhow::Result;
use kontakt_case::ContactReport;
use kontakt_case::case::ContactKind;
use std::io::Write;

/// A number in the text tables: `{:.N}` gives `N` decimals for `10^-N <= |x| < 1e7` (and
/// 0), and exponent form with `max(N, 3)` decimals of the mantissa outside that range, so
/// that a value of 1e300 prints as `1.000e300` and not as 301 digits that break the
/// table's columns, and 1e-9 MPa not as `0.0` (`{}` without a precision: Rust's shortest
/// form for `1e-5 <= |x| < 1e7`, `{:e}` outside). Width and alignment are honoured (numbers right-aligned by default).
/// Every command's tables format their numbers through it.
#[derive(Debug, Clone, Copy)]
pub struct Num(pub f64);

impl std::fmt::Display for Num {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        let x = self.0;
        // Fixed point while the number has a significant digit among the decimals asked
        // for (at least 1e-5 without a precision) and is below 1e7.
        let smallest = f
            .precision()
            .map_or(1e-5, |p| 10f64.powi(-(p.min(300) as i32)));
        let plain = x == 0.0 || !x.is_finite() || (smallest..1e7).contains(&x.abs());
        let s = match (plain, f.precision()) {
            (true, Some(p)) => format!("{x:.p$}"),
            (true, None) => format!("{x}"),
            (false, Some(p)) => format!("{x:.*e}", p.max(3)),
            (false, None) => format!("{x:e}"),
        };
        let pad = f.width().unwrap_or(0).saturating_sub(s.chars().count());
        let (left, right) = match f.align() {
            Some(std::fmt::Alignment::Left) => (0, pad),
            Some(std::fmt::Alignment::Center) => (pad / 2, pad - pad / 2),
            _ => (pad, 0),
        };
        write!(f, "{:left$}{s}{:right$}", "", "")
    }
}

fn opt(v: Option<f64>, prec: usize) -> String {
    v.map_or_else(|| "-".to_string(), |x| fmt_num(x, prec))
}

/// Significant-digit formatting that stays readable for mm-scale and MPa-scale values.
fn fmt_num(x: f64, sig: usize) -> String {
    if x == 0.0 || !x.is_finite() {
        return format!("{x}");
    }
    let mag = x.abs().log10().floor() as i32;
    if !(-4..7).contains(&mag) {
        return format!("{x:.*e}", sig.saturating_sub(1));
    }
    let decimals = (sig as i32 - 1 - mag).max(0) as usize;
    format!("{x:.decimals$}")
}

fn radii(r: &[f64]) -> String {
    r.iter()
        .map(|x| fmt_num(*x, 6))
        .collect::<Vec<_>>()
        .join(", ")
}

/// One report as a two-column table, or as pretty JSON.
/// Print `report` as pretty JSON with a final newline (every command's `--json`).
pub fn print_json(out: &mut impl Write, report: &impl serde::Serialize) -> Result<()> {
    serde_json::to_writer_pretty(&mut *out, report)?;
    writeln!(out)?;
    Ok(())
}

/// `": NAME"` for a case's optional name, empty without one (the suffix of report titles).
pub fn name_suffix(name: Option<&str>) -> String {
    name.map(|n| format!(": {n}")).unwrap_or_default()
}

pub fn print_report(out: &mut impl Write, r: &ContactReport, json: bool) -> Result<()> {
    if json {
        return crate::output::print_json(out, r);
    }
    let title = match r.kind {
        ContactKind::Point => "Hertz point contact (exact elliptical solution)",
        ContactKind::Line => "Hertz line contact",
    };
    let name = crate::output::name_suffix(r.name.as_deref());
    writeln!(out, "kontakt {} — {title}{name}", r.kontakt_version)?;
    let i = &r.inputs;
    let mut rows: Vec<(&str, String, &str)> = vec![
        ("body 1 radii", radii(&i.body1_radii_mm), "mm"),
        ("body 2 radii", radii(&i.body2_radii_mm), "mm"),
        (
            "E1, nu1",
            format!("{}, {}", Num(i.e1_mpa), Num(i.nu1)),
            "MPa, -",
        ),
        (
            "E2, nu2",
            format!("{}, {}", Num(i.e2_mpa), Num(i.nu2)),
            "MPa, -",
        ),
        ("contact modulus E*", fmt_num(r.e_star_mpa, 7), "MPa"),
    ];
    match r.kind {
        ContactKind::Point => {
            rows.push((
                "angle between principal planes",
                format!("{}", Num(i.angle_deg)),
                "deg",
            ));
            rows.push((
                "relative curvature A, B",
                format!(
                    "{}, {}",
                    fmt_num(r.relative_curvature_per_mm[0], 6),
                    fmt_num(r.relative_curvature_per_mm[1], 6)
                ),
                "1/mm",
            ));
            rows.push(("normal force F", opt(r.force_n, 6), "N"));
            rows.push((
                "semi-axes a, b",
                format!(
                    "{}, {}",
                    fmt_num(r.semi_axes_mm[0], 6),
                    fmt_num(r.semi_axes_mm[1], 6)
                ),
                "mm",
            ));
            rows.push(("axis ratio b/a", fmt_num(r.axis_ratio, 6), "-"));
            rows.push(("orientation of a", fmt_num(r.orientation_deg, 6), "deg"));
        }
        ContactKind::Line => {
            rows.push(("length", opt(i.length_mm, 6), "mm"));
            rows.push(("normal force F", opt(r.force_n, 6), "N"));
            rows.push(("line load", opt(r.line_load_n_per_mm, 6), "N/mm"));
            rows.push(("half-width b", fmt_num(r.semi_axes_mm[1], 6), "mm"));
        }
    }
    rows.extend([
        ("max pressure p0", fmt_num(r.max_pressure_mpa, 6), "MPa"),
        ("mean pressure", fmt_num(r.mean_pressure_mpa, 6), "MPa"),
        ("contact area", opt(r.contact_area_mm2, 6), "mm²"),
        ("approach delta", opt(r.approach_mm, 6), "mm"),
        (
            "stiffness dF/d(delta)",
            opt(r.stiffness_n_per_mm, 6),
            "N/mm",
        ),
        (
            "max shear stress",
            fmt_num(r.max_shear_stress_mpa, 6),
            "MPa",
        ),
        ("  at depth", fmt_num(r.max_shear_depth_mm, 6), "mm"),
        (
            "max von Mises stress",
            fmt_num(r.max_von_mises_stress_mpa, 6),
            "MPa",
        ),
        ("  at depth", fmt_num(r.max_von_mises_depth_mm, 6), "mm"),
    ]);
    if let Some(y) = i.yield_stress_mpa {
        rows.push(("yield stress", fmt_num(y, 6), "MPa"));
        match r.kind {
            ContactKind::Point => {
                rows.push(("first-yield load", opt(r.first_yield_load_n, 6), "N"))
            }
            ContactKind::Line => {
                rows.push((
                    "first-yield line load",
                    opt(r.first_yield_line_load_n_per_mm, 6),
                    "N/mm",
                ));
                rows.push(("first-yield load", opt(r.first_yield_load_n, 6), "N"));
            }
        }
        rows.push((
            "first-yield max pressure",
            opt(r.first_yield_max_pressure_mpa, 6),
            "MPa",
        ));
        rows.push((
            "yield margin p0,Y / p0",
            opt(r.yield_pressure_margin, 4),
            "-",
        ));
    }
    let w = rows
        .iter()
        .map(|(k, _, _)| k.chars().count())
        .max()
        .unwrap_or(0);
    let v = rows
        .iter()
        .map(|(_, val, _)| val.chars().count())
        .max()
        .unwrap_or(0);
    for (k, val, unit) in rows {
        writeln!(out, "  {k:<w$}  {val:>v$}  {unit}")?;
    }
    print_warnings(out, &r.warnings)
}

/// A report's warnings, one `  warning: ...` line each.
pub fn print_warnings(out: &mut impl Write, warnings: &[String]) -> Result<()> {
    for warning in warnings {
        writeln!(out, "  warning: {warning}")?;
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::Num;

    /// Issue 30 item 12: the tables' one number format: fixed point in range, exponent
    /// form outside (1e300 was printed with 301 digits), width and alignment kept.
    #[test]
    fn numbers_switch_to_exponent_form_outside_the_range() {
        assert_eq!(format!("{:.4}", Num(0.123456)), "0.1235");
        assert_eq!(format!("{:>12.6}", Num(0.0004)), "    0.000400");
        assert_eq!(format!("{:.1}", Num(0.0004)), "4.000e-4");
        assert_eq!(format!("{:.1}", Num(1e300)), "1.000e300");
        assert_eq!(format!("{:>10.2}", Num(1e300)), " 1.000e300");
        assert_eq!(format!("{:<8.1}|", Num(2.5)), "2.5     |");
        assert_eq!(format!("{}", Num(1e150)), "1e150");
        assert_eq!(format!("{}", Num(0.3)), "0.3");
        assert_eq!(format!("{}", Num(1e-300)), "1e-300");
        assert_eq!(format!("{:.3}", Num(0.0)), "0.000");
    }
}
