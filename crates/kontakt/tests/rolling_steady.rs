//! Exploration (temporary).
#![allow(clippy::unwrap_used)]
use kontakt::geometry::Grid2;
use kontakt::rolling::{SteadyMethod, SteadyOptions, SteadySolver};
use kontakt::tangential::{Creepage, KalkerMaterial};

const A: f64 = 0.5;
const P0: f64 = 1500.0;
const MU: f64 = 0.3;
const G: f64 = 80_000.0;

fn hertz_rolling(n: usize) -> (Grid2, Vec<f64>) {
    let h = A * (1.0 + 2.0 / n as f64);
    let grid = Grid2::centered(h, h, n, n).unwrap();
    let p = grid
        .points()
        .map(|(x, y)| {
            let r2 = (x * x + y * y) / (A * A);
            if r2 < 1.0 { P0 * (1.0 - r2).sqrt() } else { 0.0 }
        })
        .collect();
    (grid, p)
}

#[test]
fn explore() {
    let m = KalkerMaterial { shear_modulus: G, poisson_ratio: 0.25 };
    let xs = 3.0 * MU * P0 / (G * 4.12) ; // rough
    for n in [16usize, 35] {
        let (grid, p) = hertz_rolling(n);
        let mut solver = SteadySolver::new(&grid, m, Some(1)).unwrap();
        for c in [Creepage::longitudinal(1e-5), Creepage::longitudinal(0.5*xs), Creepage::longitudinal(1.5*xs), Creepage::longitudinal(0.05),
                  Creepage { longitudinal: 0.3*xs, lateral: 0.2*xs, spin: 0.5*xs/A }] {
            for method in [SteadyMethod::Newton, SteadyMethod::Marching] {
                if n > 20 && method == SteadyMethod::Marching { continue; }
                solver.reset();
                let t = std::time::Instant::now();
                let s = solver.solve(&p, MU, c, &SteadyOptions { method, ..Default::default() }).unwrap();
                println!("{n} {method:?} {c:?}: F {:?} Mz {:.6e} stick {} slip {} {:?} fft {} lin {} {:?}",
                    s.force, s.spin_moment, s.stick_cells, s.slip_cells, s.status, s.fft_iterations, s.linear_iterations, t.elapsed());
            }
        }
    }
}
