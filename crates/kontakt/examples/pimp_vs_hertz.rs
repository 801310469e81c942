//! PimP (both modes) against exact Hertz over the Table 1 ranges of Wirsching et al. (2019)
//! (spheres of 10-1000 mm on a plane, spheres of 10-100 mm on a torus of radii 20 and 30 mm, steel,
//! 100-500 N) and for elliptical contacts a/b = 1..10: the tables of docs/VALIDATION.md.
//!
//! Run: `cargo run --release -p kontakt --example pimp_vs_hertz`

use kontakt::geometry::RelativeCurvature;
use kontakt::hertz::{HertzPointContact, PointGeometry, curvature_ratio};
use kontakt::material::ElasticMaterial;
use kontakt::pimp::{Mode, Pimp, PimpOptions, QuadraticGap};

fn main() -> kontakt::Result<()> {
    let steel = ElasticMaterial::STEEL;
    let inf = f64::INFINITY;
    let mut cases: Vec<(String, RelativeCurvature)> = Vec::new();
    for r in [10.0, 31.6, 100.0, 316.0, 1000.0] {
        let k = RelativeCurvature::from_radii([r, r], [inf, inf], 0.0)?;
        cases.push((format!("sphere {r} mm on plane"), k));
    }
    // Torus of tube radius 20 mm and centre-circle radius 30 mm, sphere on its outer
    // equator: principal radii 20 mm (tube) and 50 mm (around the axis).
    for r in [10.0, 31.6, 100.0] {
        let k = RelativeCurvature::from_radii([r, r], [20.0, 50.0], 0.0)?;
        cases.push((format!("sphere {r} mm on torus 20/30"), k));
    }
    for ab in [1.0, 2.0, 4.0, 7.0, 10.0] {
        let ratio = curvature_ratio(1.0 / ab)?;
        let k = RelativeCurvature::from_tensor(0.02, 0.02 * ratio, 0.0)?;
        cases.push((format!("ellipse a/b = {ab}"), k));
    }
    let forces = [100.0, 200.0, 300.0, 400.0, 500.0];
    println!("Deviation from exact Hertz, range over F = 100-500 N, 64 x 64 adaptive grid");
    println!();
    println!("| case | mode | p_max | area | approach | a | b |");
    println!("|---|---|---|---|---|---|---|");
    for (name, k) in &cases {
        let hertz = HertzPointContact::new(PointGeometry::from_curvature(*k), steel, steel)?;
        for mode in [Mode::Corrected, Mode::Published] {
            let pimp = Pimp::new(
                steel,
                steel,
                PimpOptions {
                    mode,
                    ..Default::default()
                },
            )?;
            let mut range = [[f64::INFINITY, f64::NEG_INFINITY]; 5];
            for f in forces {
                let s = pimp.solve_force(&QuadraticGap::new(*k), f)?;
                let h = hertz.solve_force(f)?;
                let dev = [
                    s.max_pressure / h.max_pressure,
                    s.contact_area / h.contact_area,
                    s.approach / h.approach,
                    s.semi_axes[0] / h.semi_axes[0],
                    s.semi_axes[1] / h.semi_axes[1],
                ];
                for (r, d) in range.iter_mut().zip(dev) {
                    let pct = 100.0 * (d - 1.0);
                    r[0] = r[0].min(pct);
                    r[1] = r[1].max(pct);
                }
            }
            let cells: Vec<String> = range
                .iter()
                .map(|[lo, hi]| {
                    if (hi - lo).abs() < 0.005 {
                        format!("{lo:+.2} %")
                    } else {
                        format!("{lo:+.2} … {hi:+.2} %")
                    }
                })
                .collect();
            println!("| {name} | {} | {} |", mode.as_str(), cells.join(" | "));
        }
    }
    Ok(())
}
