//! The coupled slices of a whole bearing (docs/VALIDATION.md, coupled-slice rows): the
//! benchmark TRB of benches/bearing.rs (tests/support/cases.rs) with coupled slices, its
//! equilibrium residual, its stiffness against central differences, the warm start, zero
//! load, bad loads and the slice convergence. `-- --nocapture` prints the figures.

#![allow(clippy::unwrap_used, clippy::expect_used)] // tests: a panic is a failure with its message

// only the TRB of the shared cases is used here
#[allow(dead_code)]
#[path = "support/cases.rs"]
mod cases;

use cases::{trb, trb_load};
use kontakt_bearing::equilibrium::coupled::CoupledSliceSolver;
use kontakt_bearing::equilibrium::{Dof, RingLoad, RollerBearingSolver};
use kontakt_bearing::geometry::RollerBearing;

/// The benchmark TRB with `slices` slices.
fn trb_with(slices: usize) -> RollerBearing {
    let mut b = trb();
    b.slices = slices;
    b
}

#[test]
fn trb_combined_load_converges_with_the_residual_and_stiffness_checked() {
    let mut s = CoupledSliceSolver::new(trb_with(31)).unwrap();
    let load = trb_load(1.0);
    let sol = s.solve(&load).unwrap();
    assert!(sol.status.converged(), "{:?} {:?}", sol.status, sol.note);
    let mut iso = RollerBearingSolver::new(trb_with(31)).unwrap();
    let iso_sol = iso.solve(&load).unwrap();
    println!(
        "TRB 20 x 31 coupled: {} ring iterations, residual {:.1e}, slice iterations {}, Q_max {:.1} N (ISO {:.1} N), dx {:.6} (ISO {:.6}) mm",
        sol.status.iterations,
        sol.status.residual,
        s.slice_iterations(),
        sol.max_roller_load_n,
        iso_sol.max_roller_load_n,
        sol.displacement[0],
        iso_sol.displacement[0]
    );
    // the equilibrium residual at the solution, evaluated afresh
    let (f, _) = s.load_at(sol.displacement).unwrap();
    let target = [20_000.0, 0.0, 10_000.0];
    for i in 0..3 {
        assert!(
            (f[i] - target[i]).abs() <= 1e-9 * 20_000.0,
            "{i}: {} vs {}",
            f[i],
            target[i]
        );
    }
    // the roller loads near the ISO model's (same law for the mean approach)
    assert!((sol.max_roller_load_n / iso_sol.max_roller_load_n - 1.0).abs() < 0.05);
    // per-slice pressures: the most loaded roller's peak and its end slices
    let ns = 31;
    let j = (0..20)
        .max_by(|&a, &b| {
            s.roller_loads()[a]
                .outer_n
                .total_cmp(&s.roller_loads()[b].outer_n)
        })
        .unwrap();
    let p = &s.inner_pressures()[j * ns..(j + 1) * ns];
    println!(
        "  most loaded roller {j}: inner pressure centre {:.0}, max {:.0}, end slices {:.0} / {:.0} MPa",
        p[ns / 2],
        p.iter().copied().fold(0.0, f64::max),
        p[0],
        p[ns - 1]
    );
    // the stiffness against central differences of the carried load, at the solution and
    // tilted (asymmetric slice loads)
    let u = sol.displacement;
    let asym = stiffness_against_central_differences(&mut s, u);
    println!("  stiffness: central differences within 1e-6, asymmetry {asym:.1e}");
    let tilted = [u[0], u[1], u[2], 2e-4, -1e-4];
    let asym = stiffness_against_central_differences(&mut s, tilted);
    println!(
        "  tilted by (2e-4, -1e-4) rad: central differences within 1e-6, asymmetry {asym:.1e}"
    );
    assert!(asym < 1e-2);
}

/// The Jacobian of the coupled solver against central differences of its load (h = 1e-7
/// mm, 1e-9 rad) to 1e-6 of `√(K_ii K_jj)`; returns the largest asymmetry on that scale.
fn stiffness_against_central_differences(s: &mut CoupledSliceSolver, u: [f64; 5]) -> f64 {
    let (_, k) = s.load_at(u).unwrap();
    let h = [1e-7, 1e-7, 1e-7, 1e-9, 1e-9];
    let mut asym: f64 = 0.0;
    for jj in 0..5 {
        let (mut up, mut um) = (u, u);
        up[jj] += h[jj];
        um[jj] -= h[jj];
        let (fp, _) = s.load_at(up).unwrap();
        let (fm, _) = s.load_at(um).unwrap();
        for i in 0..5 {
            let fd = (fp[i] - fm[i]) / (2.0 * h[jj]);
            let scale = (k[i][i].abs() * k[jj][jj].abs()).sqrt();
            assert!(
                (fd - k[i][jj]).abs() < 1e-6 * scale,
                "K[{i}][{jj}] = {} vs {fd}",
                k[i][jj]
            );
            asym = asym.max((k[i][jj] - k[jj][i]).abs() / scale);
        }
    }
    asym
}

#[test]
fn warm_start_and_zero_load() {
    let mut s = CoupledSliceSolver::new(trb_with(31)).unwrap();
    let sol = s.solve(&trb_load(1.0)).unwrap();
    let scaled = RingLoad::forces([20_200.0, 0.0, 10_100.0, 0.0, 0.0]).with_tilts_held();
    let warm = s.solve_from(&scaled, sol.displacement).unwrap();
    assert!(warm.status.converged());
    println!(
        "warm after +1 %: {} ring iterations, slice iterations {}",
        warm.status.iterations,
        s.slice_iterations()
    );
    let cold = CoupledSliceSolver::new(trb_with(31))
        .unwrap()
        .solve(&scaled)
        .unwrap();
    for i in 0..3 {
        assert!((warm.displacement[i] - cold.displacement[i]).abs() < 1e-10);
    }
    let zero = s
        .solve(&RingLoad::forces([0.0; 5]).with_tilts_held())
        .unwrap();
    assert!(zero.status.converged());
    assert_eq!(zero.max_roller_load_n, 0.0);
    // bad input is the ISO solver's named error
    let e = s
        .solve(&RingLoad::forces([1e4, 0.0, -1.0, 0.0, 0.0]).with_tilts_held())
        .unwrap_err();
    assert!(e.to_string().contains("load.fz_n"), "{e}");
    let e = s
        .solve(&RingLoad {
            dofs: [Dof::Force(f64::NAN); 5],
        })
        .unwrap_err();
    assert!(e.to_string().contains("load.fx_n"), "{e}");
}

#[test]
fn slice_convergence_of_the_coupled_bearing() {
    let mut seen = Vec::new();
    for slices in [31, 61, 121] {
        let mut s = CoupledSliceSolver::new(trb_with(slices)).unwrap();
        let sol = s.solve(&trb_load(1.0)).unwrap();
        assert!(sol.status.converged());
        let pmax = s.inner_pressures().iter().copied().fold(0.0, f64::max);
        println!(
            "TRB coupled, {slices} slices: Q_max {:.2} N, largest inner pressure {pmax:.1} MPa, {} ring iterations",
            sol.max_roller_load_n, sol.status.iterations
        );
        seen.push((sol.max_roller_load_n, pmax));
    }
    let d1 = (seen[1].0 - seen[0].0).abs();
    let d2 = (seen[2].0 - seen[1].0).abs();
    assert!(d2 < d1 && d2 < 2e-3 * seen[2].0, "{seen:?}");
    let p1 = (seen[1].1 - seen[0].1).abs();
    let p2 = (seen[2].1 - seen[1].1).abs();
    assert!(p2 < p1 && p2 < 1e-2 * seen[2].1, "{seen:?}");
}

/// The coupled slices converge where the ISO model does: radial loads over three decades,
/// moments with free tilts, a thrust bearing, preload at zero load; every solution's
/// residual checked by an independent evaluation of the carried load.
#[test]
fn converges_over_loads_moments_and_bearing_kinds() {
    let mut crb = RollerBearing::cylindrical(60.0, 14, 10.0, 12.0);
    crb.clearance_mm = 0.01;
    let mut preloaded = crb.clone();
    preloaded.clearance_mm = -0.004;
    let thrust = RollerBearing::thrust(60.0, 16, 6.0, 8.0);
    let mut cases: Vec<(&str, RollerBearing, RingLoad)> = Vec::new();
    for fr in [100.0, 10_000.0, 100_000.0] {
        cases.push((
            "CRB radial",
            crb.clone(),
            RingLoad::forces([fr, 0.0, 0.0, 0.0, 0.0]).with_tilts_held(),
        ));
    }
    cases.push((
        "CRB radial + moment, free tilts",
        crb.clone(),
        RingLoad::forces([10_000.0, 0.0, 0.0, 0.0, 50_000.0]),
    ));
    cases.push((
        "TRB combined + moment, free tilts",
        trb(),
        RingLoad::forces([20_000.0, 0.0, 30_000.0, 200_000.0, 0.0]),
    ));
    cases.push((
        "thrust axial + moment",
        thrust,
        RingLoad::forces([0.0, 0.0, 8_000.0, 0.0, 50_000.0]),
    ));
    cases.push((
        "CRB preloaded, zero load",
        preloaded,
        RingLoad::forces([0.0; 5]).with_tilts_held(),
    ));
    for (name, bearing, load) in cases {
        let mut s = CoupledSliceSolver::new(bearing).unwrap();
        let sol = s.solve(&load).unwrap();
        assert!(
            sol.status.converged(),
            "{name}: {:?} {:?}",
            sol.status,
            sol.note
        );
        let (f, _) = s.load_at(sol.displacement).unwrap();
        let scale = load
            .dofs
            .iter()
            .take(3)
            .map(|d| match d {
                Dof::Force(v) => v.abs(),
                Dof::Displacement(_) => 0.0,
            })
            .fold(sol.max_roller_load_n, f64::max);
        for (i, d) in load.dofs.iter().enumerate() {
            if let Dof::Force(v) = d {
                let s_i = if i < 3 { scale } else { scale * 30.0 };
                assert!(
                    (f[i] - v).abs() <= 1e-9 * s_i,
                    "{name}: component {i}: {} vs {v}",
                    f[i]
                );
            }
        }
        println!(
            "{name}: {} ring iterations, slice iterations {}, Q_max {:.1} N",
            sol.status.iterations,
            s.slice_iterations(),
            sol.max_roller_load_n
        );
    }
}
