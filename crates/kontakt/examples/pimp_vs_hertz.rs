//! PimP (both modes) against exact Hertz over seed 001's Table 1 ranges and for
//! elliptical contacts a/b = 1..10: the table behind docs/VALIDATION.md.
//!
//! Run: `cargo run --release -p kontakt --example pimp_vs_hertz`

use kontakt::geometry::RelativeCurvature;
use kontakt::hertz::{HertzPointContact, PointGeometry};
use kontakt::material::ElasticMaterial;
use kontakt::pimp::{Mode, Pimp, PimpOptions, QuadraticGap};

fn main() -> kontakt::Result<()> {
    let steel = ElasticMaterial::STEEL;
    let inf = f64::INFINITY;
    println!(
        "| case | mode | F [N] | p_max / Hertz - 1 | area / Hertz - 1 | approach / Hertz - 1 |"
    );
    println!("|---|---|---|---|---|---|");
    let mut cases: Vec<(String, RelativeCurvature)> = Vec::new();
    for r in [10.0, 100.0, 1000.0] {
        cases.push((
            format!("sphere R{r} on plane"),
            RelativeCurvature::from_radii([r, r], [inf, inf], 0.0)?,
        ));
    }
    for k in [1.0, 2.0, 5.0, 10.0] {
        let ratio = kontakt::hertz::curvature_ratio(1.0 / k)?;
        cases.push((
            format!("ellipse a/b = {k}"),
            RelativeCurvature::from_tensor(2.0 * 0.01, 2.0 * 0.01 * ratio, 0.0)?,
        ));
    }
    for (name, k) in &cases {
        for mode in [Mode::Published, Mode::Corrected] {
            let pimp = Pimp::new(
                steel,
                steel,
                PimpOptions {
                    mode,
                    ..Default::default()
                },
            )?;
            for f in [100.0, 500.0] {
                let s = pimp.solve_force(&QuadraticGap::new(*k), f)?;
                let h = HertzPointContact::new(PointGeometry::from_curvature(*k), steel, steel)?
                    .solve_force(f)?;
                println!(
                    "| {name} | {} | {f} | {:+.2} % | {:+.2} % | {:+.2} % | it {} rounds {}",
                    mode.as_str(),
                    100.0 * (s.max_pressure / h.max_pressure - 1.0),
                    100.0 * (s.contact_area / h.contact_area - 1.0),
                    100.0 * (s.approach / h.approach - 1.0),
                    s.iterations,
                    s.grid_rounds
                );
            }
        }
    }
    Ok(())
}
