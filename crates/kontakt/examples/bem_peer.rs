//! The kontakt side of the peer comparison (bench/peers): a Hertz sphere on a flat solved
//! by the half-space solver, timed as cold solves with the plan built outside the timing.
//!
//! ```text
//! cargo run --release -p kontakt --example bem_peer -- --n 256 --tol 1e-8 --threads 1 --repeat 5
//! ```
//! Options: `--n` cells a side, `--tol` relative residual, `--threads`, `--repeat`,
//! `--radius` \[mm\], `--force` \[N\], `--domain` (side of the square domain over the Hertz
//! contact radius). Prints one JSON object on stdout.

use kontakt::geometry::Grid2;
use kontakt::halfspace::{Control, HalfSpaceSolver, SolverOptions, Start};
use kontakt::material::{ElasticMaterial, effective_modulus};
use std::time::Instant;

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let mut n = 256usize;
    let (mut tol, mut threads, mut repeat) = (1e-8, 1usize, 5usize);
    let (mut radius, mut force, mut domain) = (10.0, 300.0, 8.0);
    let args: Vec<String> = std::env::args().skip(1).collect();
    for pair in args.chunks(2) {
        let [flag, value] = pair else {
            return Err(format!("missing value after {}", pair[0]).into());
        };
        match flag.as_str() {
            "--n" => n = value.parse()?,
            "--tol" => tol = value.parse()?,
            "--threads" => threads = value.parse()?,
            "--repeat" => repeat = value.parse()?,
            "--radius" => radius = value.parse()?,
            "--force" => force = value.parse()?,
            "--domain" => domain = value.parse()?,
            other => return Err(format!("unknown option {other}").into()),
        }
    }
    let steel = ElasticMaterial::STEEL;
    let e_star = effective_modulus(&steel, &steel);
    let a = (3.0 * force * radius / (4.0 * e_star)).cbrt();
    let half = 0.5 * domain * a;
    let grid = Grid2::centered(half, half, n, n)?;
    let gap: Vec<f64> = grid
        .points()
        .map(|(x, y)| (x * x + y * y) / (2.0 * radius))
        .collect();
    let t0 = Instant::now();
    let mut solver = HalfSpaceSolver::new(
        grid,
        e_star,
        SolverOptions {
            tolerance: tol,
            threads: Some(threads),
            max_iterations: 10_000,
            ..SolverOptions::default()
        },
    )?;
    let plan_seconds = t0.elapsed().as_secs_f64();
    let mut best = f64::INFINITY;
    let mut report = None;
    for _ in 0..repeat.max(1) {
        let t = Instant::now();
        let r = solver.solve(&gap, Control::Force(force), Start::Cold)?;
        best = best.min(t.elapsed().as_secs_f64());
        report = Some(r);
    }
    let r = report.ok_or("no solve")?;
    println!(
        "{{\"code\":\"kontakt\",\"n\":{n},\"threads\":{threads},\"iterations\":{},\
         \"applications\":{},\"seconds\":{best:.6e},\"plan_seconds\":{plan_seconds:.6e},\
         \"p_max\":{:.10e},\"approach\":{:.10e},\"area\":{:.10e},\"residual\":{:.3e},\
         \"converged\":{},\"memory_bytes\":{}}}",
        r.status.iterations,
        r.applications,
        r.max_pressure,
        r.approach,
        r.contact_area,
        r.status.residual,
        r.status.converged(),
        solver.memory_bytes()
    );
    Ok(())
}
