//! The traction model `kalker_exact` (`kontakt::rolling::KalkerExact`): Kalker's exact
//! theory of steady rolling on a Hertz ellipse, against the published reference outputs
//! of Vollebregt's CONTACT (its examples `tractcurv` and `fastsim`, numbers only), Kalker's
//! linear theory at small creepage, saturation, and bad input.
//!
//! The base tests use 16 cells across the contact, with tolerances set for that grid, each
//! with the value measured when it was set; the `_fine` tests repeat the comparisons on 24² and 32² grids with tighter
//! tolerances. The `#[ignore]`d tests print the grid-convergence and FASTSIM error tables
//! of docs/tangential.md §11
//! (`cargo test --release -p kontakt --test rolling_exact -- --ignored --nocapture`).
//!
//! Reference data (CONTACT, github.com/eve70a/CONTACT, Apache-2.0; numbers from its
//! `examples/*.ref_out`, read 2026-11-24):
//! - `tractcurv`, first series (Kalker's theory, Coulomb friction): the Eurosprinter case
//!   of Polach (2005): Hertz ellipse a = 6.304 mm along rolling, b = 12.61 mm,
//!   F_N = 106.7 kN, μ = 0.33, G = 82 000 MPa, ν = 0.28; 48 × 44 cells over 1.1 times the
//!   ellipse; `FX/FSTAT/FN` at longitudinal creepages 0.4 ‰ ... 3.2 ‰.
//! - `fastsim`, case 1 (Kalker's theory): Hertz ellipse a = 8 mm along rolling, b = 4 mm,
//!   F_N = 82 kN, μ = 0.3, G = 82 000 MPa, ν = 0.28, η = -6.25e-4, φ = 6.25e-4 1/mm;
//!   44 × 44 cells over 1.1 times the ellipse: F_y = -1.494e4 N, M_z = -4.821e4 N·mm.
//!   Case 2 is FASTSIM with the parabolic traction bound: F_y = -1.505e4 N,
//!   M_z = -3.900e4 N·mm.

#![allow(clippy::unwrap_used)] // test helpers: a panic is a test failure with its message

use kontakt::Error;
use kontakt::rolling::{KalkerExact, KalkerExactOptions};
use kontakt::solve::Termination;
use kontakt::tangential::{
    ContactEllipse, Creepage, Fastsim, FastsimOptions, KalkerMaterial, TractionCurve,
    creep_coefficients,
};

const RAIL: KalkerMaterial = KalkerMaterial {
    shear_modulus: 82_000.0,
    poisson_ratio: 0.28,
};

/// CONTACT `tractcurv`, first series: (ξ, F_x/(μ F_N)).
const TRACTCURV: [(f64, f64); 8] = [
    (4.0e-4, -0.2588),
    (8.0e-4, -0.4742),
    (1.2e-3, -0.6482),
    (1.6e-3, -0.7831),
    (2.0e-3, -0.8816),
    (2.4e-3, -0.9467),
    (2.8e-3, -0.9832),
    (3.2e-3, -0.9976),
];

fn model(ellipse: ContactEllipse, mu: f64, cells: [usize; 2]) -> KalkerExact {
    let options = KalkerExactOptions {
        elements: cells,
        ..KalkerExactOptions::default()
    };
    KalkerExact::with_material(ellipse, RAIL, mu, options).unwrap()
}

fn tractcurv_errors(cells: [usize; 2]) -> Vec<f64> {
    let e = ContactEllipse::new(6.304, 12.61, 106_700.0).unwrap();
    let m = model(e, 0.33, cells);
    let creepages: Vec<Creepage> = TRACTCURV
        .iter()
        .map(|&(xi, _)| Creepage::longitudinal(xi))
        .collect();
    let points = m.curve(&creepages).unwrap();
    points
        .iter()
        .zip(TRACTCURV)
        .map(|(p, (xi, reference))| {
            assert!(p.status.converged(), "{xi}: {:?}", p.status);
            let ours = p.force[0] / (0.33 * 106_700.0);
            println!(
                "tractcurv {cells:?} xi {xi:.1e}: ours {ours:.4}, CONTACT {reference:.4}, \
                 stick {:.3}, steps {}",
                p.stick_fraction, p.status.iterations
            );
            ours - reference
        })
        .collect()
}

/// CONTACT's Eurosprinter creep curve (a/b = 0.5, longitudinal creepage) on 16 × 16
/// cells: within 0.03 of μ F_N at every point (measured: max 0.0233 at ξ = 1.6 ‰, our
/// force above CONTACT's, the first-order grid error; CONTACT has about 44 × 40 cells
/// across the contact).
#[test]
fn contact_tractcurv_creep_curve_coarse() {
    let errors = tractcurv_errors([16, 16]);
    let worst = errors.iter().fold(0.0f64, |a, e| a.max(e.abs()));
    assert!(worst < 0.03, "{errors:?}");
    // The error is the grid's: our force is larger in magnitude at every point.
    assert!(errors.iter().all(|e| *e < 0.0), "{errors:?}");
}

/// The same on 32 × 32 cells: within 0.006 of μ F_N (measured 0.0040 max; 24 × 24:
/// 0.0043).
#[test]
fn contact_tractcurv_creep_curve_fine() {
    for cells in [[24, 24], [32, 32]] {
        let errors = tractcurv_errors(cells);
        let worst = errors.iter().fold(0.0f64, |a, e| a.max(e.abs()));
        assert!(worst < 0.006, "{cells:?}: {errors:?}");
    }
}

fn fastsim_case(cells: [usize; 2]) -> ([f64; 2], f64, f64) {
    let e = ContactEllipse::new(8.0, 4.0, 82_000.0).unwrap();
    let m = model(e, 0.3, cells);
    let c = Creepage {
        longitudinal: 0.0,
        lateral: -6.25e-4,
        spin: 6.25e-4,
    };
    let p = m.solve(&c, false).unwrap();
    assert!(p.status.converged(), "{:?}", p.status);
    println!(
        "fastsim case 1 {cells:?}: Fx {:.1} Fy {:.1} Mz {:.1} stick {:.3} steps {}",
        p.force[0], p.force[1], p.spin_moment, p.stick_fraction, p.status.iterations
    );
    (p.force, p.spin_moment, p.stick_fraction)
}

/// CONTACT's lateral creepage with spin on an ellipse a/b = 2 (its `fastsim` example,
/// case 1, Kalker's theory: F_y = -1.494e4 N, M_z = -4.821e4 N·mm with 40 cells across):
/// on 16 × 16 cells F_y within 12 % and M_z within 13 % (measured -9.2 %, +10.0 %: the
/// spin terms converge slowly, first order in `dx`, see the fine version), F_x = 0 by
/// symmetry.
#[test]
fn contact_lateral_spin_case_coarse() {
    let (f, mz, _) = fastsim_case([16, 16]);
    assert!(f[0].abs() < 1e-6 * 82_000.0 * 0.3, "Fx {}", f[0]);
    let (fy_ref, mz_ref) = (-1.494e4, -4.821e4);
    let (efy, emz) = (f[1] / fy_ref - 1.0, mz / mz_ref - 1.0);
    assert!(efy < 0.0 && efy > -0.12, "Fy {} vs {fy_ref}", f[1]);
    assert!(emz > 0.0 && emz < 0.13, "Mz {mz} vs {mz_ref}");
}

/// The same refined: 24 × 24 and 32 × 32 cells; the errors fall (F_y -9.2 %, -5.6 %,
/// -3.0 %; M_z +10.0 %, +4.2 %, +3.0 % at 16, 24, 32 cells) and are within 4 % at 32.
#[test]
fn contact_lateral_spin_case_fine() {
    let mut last = (1.0f64, 1.0f64);
    for n in [24, 32] {
        let (f, mz, _) = fastsim_case([n, n]);
        let e = ((f[1] / -1.494e4 - 1.0).abs(), (mz / -4.821e4 - 1.0).abs());
        assert!(e.0 < last.0 && e.1 < last.1, "{n}: {e:?} after {last:?}");
        last = e;
    }
    assert!(last.0 < 0.04 && last.1 < 0.04, "{last:?}");
}

/// `F_y/(μF_N)` of CONTACT's `fastsim` case 1 on `n × n` cells.
fn lateral_spin_force(n: usize) -> f64 {
    fastsim_case([n, n]).0[1] / (0.3 * 82_000.0)
}

/// Issue 30 item 5b: the grid study behind `KalkerExactOptions::SPIN_ELEMENTS`. CONTACT's
/// lateral-plus-spin case converges at first order (measured order 0.97 from 32, 64, 128
/// cells; limit −0.6262 of μF_N, CONTACT's own extrapolation agrees within 0.15 %), and is
/// the slowest case measured: −5.9 % at the default 32 cells, −3.0 % at 64, −1.5 % at 128
/// (pure creepages: 1-2 % at 32). Tolerances: order 0.8 ... 1.2; error at 32 worse than
/// −5 % (so the default grid warns with spin), at `SPIN_ELEMENTS` within 3.5 %.
#[test]
fn lateral_spin_case_converges_at_first_order() {
    let f = [32, 64, 128].map(lateral_spin_force);
    let order = ((f[1] - f[0]) / (f[2] - f[1])).log2();
    let limit = f[2] + (f[2] - f[1]) / (2f64.powf(order) - 1.0);
    let error = f.map(|v| v / limit - 1.0);
    println!("order {order:.3}, limit {limit:.5}, errors {error:?}");
    assert!((0.8..1.2).contains(&order), "{order}");
    assert!((-0.63..-0.62).contains(&limit), "{limit}");
    assert!(error[0] < -0.05, "{error:?}");
    assert_eq!(KalkerExactOptions::SPIN_ELEMENTS, 64);
    assert!(error[1].abs() < 0.035, "{error:?}");
    // The default grid is coarse for spin, not for pure creepages; 64 cells are not.
    let spin = Creepage {
        spin: 1e-4,
        ..Creepage::default()
    };
    let default = KalkerExactOptions::default();
    assert!(default.coarse_for(&[Creepage::longitudinal(1e-3), spin]));
    assert!(!default.coarse_for(&[Creepage::longitudinal(1e-3)]));
    let fine = KalkerExactOptions {
        elements: [64, 64],
        ..default
    };
    assert!(!fine.coarse_for(&[spin]));
}

/// Prints the grid study of docs/rolling.md §6.1 for CONTACT's `fastsim` case 1
/// (`cargo test -p kontakt --test rolling_exact -- --ignored --nocapture spin_grid`).
#[test]
#[ignore]
fn spin_grid_convergence_table() {
    for n in [16, 24, 32, 40, 48, 64, 96, 128] {
        let t = std::time::Instant::now();
        let f = lateral_spin_force(n);
        println!(
            "{n:>4} cells: F_y/(mu F_N) = {f:.5} ({:+.2} % from -0.62624), {:.2?}",
            100.0 * (f / -0.62624 - 1.0),
            t.elapsed()
        );
    }
}

/// Our FASTSIM on CONTACT's `fastsim` case 2 (parabolic bound): F_y within 2 % of
/// CONTACT's FASTSIM, M_z within 5 %; and FASTSIM's spin moment is 19 % below the exact
/// one in CONTACT's own numbers, the weak spot Kalker (1982) names.
#[test]
fn contact_fastsim_case_with_our_fastsim() {
    let e = ContactEllipse::new(8.0, 4.0, 82_000.0).unwrap();
    let steel =
        kontakt::material::ElasticMaterial::new(2.0 * 82_000.0 * (1.0 + 0.28), 0.28).unwrap();
    let c = Creepage {
        longitudinal: 0.0,
        lateral: -6.25e-4,
        spin: 6.25e-4,
    };
    for n in [50, 200] {
        let options = FastsimOptions {
            elements: [n, n],
            ..FastsimOptions::default()
        };
        let f = Fastsim::new(e, &steel, &steel, 0.3, options).unwrap();
        let s = f.solve(&c).unwrap();
        println!(
            "our FASTSIM {n}: Fy {:.1} Mz {:.1}",
            s.forces[1], s.spin_moment
        );
        if n == 200 {
            assert!(
                (s.forces[1] / -1.564e4 - 1.0).abs() < 0.03,
                "{}",
                s.forces[1]
            );
            assert!(
                (s.spin_moment / -3.798e4 - 1.0).abs() < 0.03,
                "{}",
                s.spin_moment
            );
        }
    }
}

/// Small creepage: the slope is Kalker's linear C11 (a circle, ν = 0.28, C11 = 4.226 by
/// the reference table) within the grid error: +4.8 % measured on 16 × 16 (the grid
/// error at small creepage is not monotone: +0.9 %, +4.8 %, -0.3 %, +1.4 % at 12, 16, 24,
/// 32 cells); tolerance 6 %. Lateral: C22 likewise.
#[test]
fn small_creepage_slope_is_kalker_linear() {
    let e = ContactEllipse::new(1.0, 1.0, 1000.0).unwrap();
    let mu = 0.3;
    let m = model(e, mu, [16, 16]);
    let k = creep_coefficients(1.0, RAIL.poisson_ratio).unwrap();
    let scale = RAIL.shear_modulus * e.mean_semi_axis().powi(2);
    let xi = 1e-3 * mu * e.normal_force() / (scale * k.c11); // u = 1e-3 of saturation
    let p = m.solve(&Creepage::longitudinal(xi), false).unwrap();
    assert!(p.status.converged());
    let c11 = -p.force[0] / (scale * xi);
    println!("C11 {c11:.4} vs {:.4}", k.c11);
    assert!(
        c11 / k.c11 - 1.0 > 0.0 && c11 / k.c11 - 1.0 < 0.06,
        "C11 {c11}"
    );
    assert!(p.stick_fraction > 0.99, "{}", p.stick_fraction);
    let p = m
        .solve(
            &Creepage {
                lateral: xi,
                ..Creepage::default()
            },
            false,
        )
        .unwrap();
    let c22 = -p.force[1] / (scale * xi);
    println!("C22 {c22:.4} vs {:.4}", k.c22);
    assert!((c22 / k.c22 - 1.0).abs() < 0.06, "C22 {c22}");
}

/// Kalker's creep coefficients of one ellipse from our exact solver, independent of any
/// table: `C11 = -F_x/(G c² ξ)`, `C22 = -F_y/(G c² η)`, `C23 = -F_y/(G c³ φ)` at a
/// creepage so small (1e-6, μ = 1000) that every cell sticks. The loaded cells (centre
/// inside the ellipse) cover an area that jitters with the grid (−1 % at 32 cells, +1 %
/// at 24, 0.3 % at 64): in full stick the force scales with the area at fixed shape (as
/// `c²`, `c³` for `C23`), so each value is normalised by `πab / Σ ΔA` (power 1 or 3/2),
/// which leaves a monotone, first-order sequence; first-order Richardson from `n` and `2n`
/// cells gives the limit. Returns the limits `[C11, C22, C23]`.
fn exact_creep_coefficients(a: f64, b: f64, n: usize) -> [f64; 3] {
    let e = ContactEllipse::new(a, b, 82_000.0).unwrap();
    let (g, c) = (RAIL.shear_modulus, (a * b).sqrt());
    let at = |cells: usize| {
        let m = model(e, 1e3, [cells, cells]);
        let loaded = m.pressure().iter().filter(|p| **p > 0.0).count() as f64;
        let r = std::f64::consts::PI * a * b / (loaded * m.grid().cell_area());
        let x = 1e-6;
        let s = |creepage: Creepage| {
            let p = m.solve(&creepage, false).unwrap();
            assert!(p.status.converged() && p.stick_fraction == 1.0, "{p:?}");
            p.force
        };
        let fx = s(Creepage::longitudinal(x))[0];
        let fy = s(Creepage {
            lateral: x,
            ..Creepage::default()
        })[1];
        let fs = s(Creepage {
            spin: x / c,
            ..Creepage::default()
        })[1];
        let k = -1.0 / (g * c * c * x);
        [fx * k * r, fy * k * r, fs * k * r.powf(1.5)]
    };
    let (coarse, fine) = (at(n), at(2 * n));
    std::array::from_fn(|i| 2.0 * fine[i] - coarse[i])
}

/// Issue 30 item 5: CONTACT's FASTSIM on its `fastsim` case (a = 8 mm along rolling,
/// b = 4 mm, ν = 0.28) converges to `F_y/(μF_N)` = −0.6417 where ours gives −0.6476; its
/// printed flexibilities imply `C11`, `C22` 1.3 % and 1.6 % above Kalker's table (ours)
/// and `C23` 0.3 % below (with those, our FASTSIM gives −0.6416 on 1600², so the whole
/// difference is the coefficients). The exact solver, extrapolated from 48² and 96², gives
/// the table's values: measured −0.02 %, +0.15 %, +0.07 % (5.2028, 4.9790, 2.6585 against
/// 5.2037, 4.9715, 2.6566; 64² and 128²: 5.2023, 4.9800, 2.6599); tolerance 0.3 %, which
/// CONTACT's implied values (+1.3 %, +1.6 %, −0.3 % of the table: 1.3 %, 1.4 % and 0.36 %
/// from ours) fail. So FASTSIM and the linear theory keep the table.
#[test]
fn creep_coefficients_of_contacts_fastsim_ellipse_from_the_exact_solver() {
    let table = creep_coefficients(2.0, RAIL.poisson_ratio).unwrap();
    let table = [table.c11, table.c22, table.c23];
    let exact = exact_creep_coefficients(8.0, 4.0, 48);
    let contact = [1.013, 1.016, 0.997];
    for k in 0..3 {
        let error = exact[k] / table[k] - 1.0;
        println!(
            "C{}: exact {:.4}, table {:.4} ({:+.2} %)",
            ["11", "22", "23"][k],
            exact[k],
            table[k],
            100.0 * error
        );
        assert!(error.abs() < 3e-3, "{k}: {exact:?} vs {table:?}");
        assert!(
            (exact[k] / (contact[k] * table[k]) - 1.0).abs() > 3e-3,
            "{k}: CONTACT's implied value would pass"
        );
    }
}

/// Prints the exact solver's creep coefficients against Kalker's table for three ellipses
/// (docs/rolling.md §6.1;
/// `cargo test -p kontakt --test rolling_exact -- --ignored --nocapture coefficient_table`).
#[test]
#[ignore]
fn creep_coefficient_table() {
    for (a, b) in [(8.0, 4.0), (4.0, 4.0), (2.0, 4.0)] {
        for n in [48, 64] {
            let exact = exact_creep_coefficients(a, b, n);
            let t = creep_coefficients(a / b, RAIL.poisson_ratio).unwrap();
            let table = [t.c11, t.c22, t.c23];
            let e: Vec<String> = (0..3)
                .map(|k| {
                    format!(
                        "{:.4} ({:+.2} %)",
                        exact[k],
                        100.0 * (exact[k] / table[k] - 1.0)
                    )
                })
                .collect();
            println!(
                "a/b = {}, {n}/{}: {} vs table {table:.4?}",
                a / b,
                2 * n,
                e.join(", ")
            );
        }
    }
}

/// Large creepage: full sliding, `F_T/(μ F_N) = 1` (1e-4) and no stick cell; the
/// traction-curve trait gives the same number.
#[test]
fn saturation_is_one() {
    let e = ContactEllipse::new(1.0, 0.5, 1000.0).unwrap();
    let m = model(e, 0.2, [16, 16]);
    let p = m.solve(&Creepage::longitudinal(0.05), false).unwrap();
    assert!(p.status.converged());
    assert!(
        (p.normalized_force - 1.0).abs() < 1e-4,
        "{}",
        p.normalized_force
    );
    assert_eq!(p.stick_fraction, 0.0);
    let t = m.normalized_force(0.05).unwrap();
    assert!((t - p.normalized_force).abs() < 1e-9);
    // Odd: the negative creepage gives the negative force.
    let t = m.normalized_force(-0.05).unwrap();
    assert!((t + 1.0).abs() < 1e-4, "{t}");
}

/// Warm starts along a curve give the cold-start values (1e-4 of μ F_N).
#[test]
fn warm_start_gives_the_cold_values() {
    let e = ContactEllipse::new(1.0, 1.0, 1000.0).unwrap();
    let m = model(e, 0.3, [12, 12]);
    let xis = [2e-4, 4e-4, 6e-4];
    let warm = m.traction_curve(&xis).unwrap();
    for (xi, w) in xis.iter().zip(&warm) {
        let cold = m.normalized_force(*xi).unwrap();
        assert!((cold - w).abs() < 1e-4, "{xi}: warm {w} cold {cold}");
    }
    assert!(warm[0] < warm[1] && warm[1] < warm[2]);
}

/// Bad input: non-finite creepages, friction ≤ 0, a grid too coarse to resolve the slip
/// area, and a point that does not converge (reported by its status; an error through
/// the traction-curve trait).
#[test]
fn bad_input_and_unconverged_points() {
    let e = ContactEllipse::new(1.0, 1.0, 1000.0).unwrap();
    let m = model(e, 0.3, [8, 8]);
    for (c, field) in [
        (Creepage::longitudinal(f64::NAN), "creepage.longitudinal"),
        (
            Creepage {
                lateral: f64::INFINITY,
                ..Creepage::default()
            },
            "creepage.lateral",
        ),
        (
            Creepage {
                spin: f64::NEG_INFINITY,
                ..Creepage::default()
            },
            "creepage.spin",
        ),
    ] {
        assert_eq!(m.solve(&c, false).unwrap_err().field(), Some(field));
        let curve = [Creepage::longitudinal(1e-4), c];
        assert_eq!(m.curve(&curve).unwrap_err().field(), Some(field));
    }
    assert_eq!(
        m.normalized_force(f64::NAN).unwrap_err().field(),
        Some("creepage")
    );
    assert_eq!(
        m.traction_curve(&[0.0, f64::INFINITY]).unwrap_err().field(),
        Some("creepage")
    );
    for mu in [0.0, -0.1, f64::NAN, f64::INFINITY] {
        let err = KalkerExact::with_material(e, RAIL, mu, KalkerExactOptions::default());
        assert_eq!(err.unwrap_err().field(), Some("friction_coefficient"));
    }
    for (cells, field) in [
        ([7, 16], "elements[0]"),
        ([16, 4], "elements[1]"),
        ([16, 2000], "elements[1]"),
    ] {
        let options = KalkerExactOptions {
            elements: cells,
            ..KalkerExactOptions::default()
        };
        let err = KalkerExact::with_material(e, RAIL, 0.3, options).unwrap_err();
        assert_eq!(err.field(), Some(field));
        assert!(err.to_string().contains("slip area"), "{err}");
    }
    // One Newton iteration is too few: the status says so, the trait refuses.
    let mut options = KalkerExactOptions {
        elements: [8, 8],
        ..KalkerExactOptions::default()
    };
    options.steady.max_newton_iterations = 1;
    let m = KalkerExact::with_material(e, RAIL, 0.3, options).unwrap();
    let p = m.solve(&Creepage::longitudinal(3e-4), false).unwrap();
    assert_eq!(p.status.termination, Termination::MaxIterations);
    assert!(!p.status.converged());
    assert!(matches!(
        m.normalized_force(3e-4),
        Err(Error::NotConverged { .. })
    ));
    assert!(matches!(
        m.traction_curve(&[1e-4, 3e-4]),
        Err(Error::NotConverged { .. })
    ));
}

/// Grid convergence of the force (docs/tangential.md §11): the circle at u = 0.5 and
/// 1.5 of Kalker's saturation creepage, 12 ... 48 cells.
#[test]
#[ignore = "prints the grid-convergence table; slow"]
fn grid_convergence_table() {
    let e = ContactEllipse::new(1.0, 1.0, 1000.0).unwrap();
    let mu = 0.3;
    let k = creep_coefficients(1.0, RAIL.poisson_ratio).unwrap();
    let scale = RAIL.shear_modulus * e.mean_semi_axis().powi(2) * k.c11 / (mu * e.normal_force());
    for n in [12, 16, 24, 32, 48] {
        let m = model(e, mu, [n, n]);
        let t = std::time::Instant::now();
        let us = [1e-3, 0.5, 1.5, 2.5];
        let pts: Vec<Creepage> = us
            .iter()
            .map(|u| Creepage::longitudinal(u / scale))
            .collect();
        let p = m.curve(&pts).unwrap();
        println!(
            "| {n} | {} | {:.2?} |",
            p.iter()
                .zip(us)
                .map(|(p, u)| format!(
                    "u={u}: {:.5}",
                    p.normalized_force / if u < 0.01 { u } else { 1.0 }
                ))
                .collect::<Vec<_>>()
                .join(" | "),
            t.elapsed()
        );
    }
}

/// FASTSIM's error against the exact curve (docs/tangential.md §11): a circle and an
/// ellipse a/b = 0.5, longitudinal and lateral creepage, at normalised creepages
/// `u = G c² C_ii ξ/(μ F_N)`.
#[test]
#[ignore = "prints the FASTSIM error table; slow"]
fn fastsim_error_table() {
    let mu = 0.3;
    let steel = kontakt::material::ElasticMaterial::new(2.0 * 82_000.0 * 1.28, 0.28).unwrap();
    let cells: usize = std::env::var("CELLS")
        .ok()
        .and_then(|s| s.parse().ok())
        .unwrap_or(32);
    for (label, a, b) in [("circle", 1.0, 1.0), ("ellipse a/b=0.5", 0.5, 1.0)] {
        let e = ContactEllipse::new(a, b, 1000.0).unwrap();
        let m = model(e, mu, [cells, cells]);
        let f = Fastsim::new(e, &steel, &steel, mu, FastsimOptions::default()).unwrap();
        let k = creep_coefficients(a / b, RAIL.poisson_ratio).unwrap();
        for (dir, c) in [("longitudinal", k.c11), ("lateral", k.c22)] {
            let scale = RAIL.shear_modulus * a * b * c / (mu * 1000.0);
            let us = [0.25, 0.5, 1.0, 1.5, 2.0, 2.5, 3.0, 4.0];
            let pts: Vec<Creepage> = us
                .iter()
                .map(|u| {
                    if dir == "longitudinal" {
                        Creepage::longitudinal(u / scale)
                    } else {
                        Creepage {
                            lateral: u / scale,
                            ..Creepage::default()
                        }
                    }
                })
                .collect();
            let exact = m.curve(&pts).unwrap();
            for (p, u) in exact.iter().zip(us) {
                let k = usize::from(dir == "lateral");
                let ex = -p.force[k] / (mu * 1000.0);
                let fs = -f.solve(&p.creepage).unwrap().forces[k] / (mu * 1000.0);
                println!(
                    "| {label} | {dir} | {u} | {:.3e} | {ex:.4} | {fs:.4} | {:+.1} | {} |",
                    if k == 0 {
                        p.creepage.longitudinal
                    } else {
                        p.creepage.lateral
                    },
                    100.0 * (fs / ex - 1.0),
                    if p.status.converged() {
                        "ok"
                    } else {
                        "NOT CONVERGED"
                    }
                );
            }
        }
    }
}

// ---- Dissimilar bodies: `KalkerExactOptions::coupling` ----------------------------------

/// Aluminium (G = 23 000 MPa, ν = 0.31), as in CONTACT's `bentall`.
fn aluminium() -> kontakt::material::ElasticMaterial {
    kontakt::material::ElasticMaterial::new(2.0 * 23_000.0 * 1.31, 0.31).unwrap()
}

/// Steel (G = 82 000 MPa, ν = 0.28).
fn steel() -> kontakt::material::ElasticMaterial {
    kontakt::material::ElasticMaterial::new(2.0 * 82_000.0 * 1.28, 0.28).unwrap()
}

/// Sphere of radius `R` on a plane: the Hertz circle under `force` for the two bodies.
const SPHERE_R: f64 = 10.0;

fn sphere(
    body1: &kontakt::material::ElasticMaterial,
    body2: &kontakt::material::ElasticMaterial,
    force: f64,
) -> ContactEllipse {
    let e_star = kontakt::material::effective_modulus(body1, body2);
    let a = (3.0 * force * SPHERE_R / (4.0 * e_star)).cbrt();
    ContactEllipse::new(a, a, force).unwrap()
}

fn coupled_model(
    body1: &kontakt::material::ElasticMaterial,
    body2: &kontakt::material::ElasticMaterial,
    mu: f64,
    coupling: bool,
) -> KalkerExact {
    let options = KalkerExactOptions {
        elements: [16, 16],
        coupling,
        ..KalkerExactOptions::default()
    };
    KalkerExact::new(sphere(body1, body2, 300.0), body1, body2, mu, options).unwrap()
}

/// Equal materials (`K = 0`): the coupling changes nothing, bit for bit, and the
/// free-rolling creepage is zero exactly.
#[test]
fn coupling_with_equal_materials_is_the_uncoupled_model_exactly() {
    let st = steel();
    let xis = [0.0, 1e-3, 3e-3, 2e-2].map(Creepage::longitudinal);
    let off = coupled_model(&st, &st, 0.3, false);
    let on = coupled_model(&st, &st, 0.3, true);
    assert_eq!(on.difference_parameter(), Some(0.0));
    assert!(!on.is_coupled());
    assert_eq!(on.grid(), off.grid());
    assert_eq!(on.curve(&xis).unwrap(), off.curve(&xis).unwrap());
    let free = on.free_rolling(0.0, 0.0).unwrap();
    assert!(free.status.converged());
    assert_eq!(free.creepage.longitudinal, 0.0);
    assert_eq!(free.force, [0.0, 0.0]);
}

/// Aluminium sphere on a steel plane (`K = 0.100`), 16 cells across: the model's
/// free-rolling creepage and creep curve against `CoupledSteadySolver` on the same grid
/// with the sphere's gap `(x² + y²)/(2R)` (the model derives its gap from the ellipse:
/// the same to rounding). Tolerances: the creepage 1e-9 relative (measured 2e-11:
/// −1.4292795e-3 both), the forces 1e-7 of `μ F_N`, the steady solver's tolerance
/// (measured up to 1e-9: the rounding of the gap moves the iterates).
#[test]
fn coupled_model_is_the_coupled_solver_on_the_hertz_gap() {
    use kontakt::halfspace::Control;
    use kontakt::rolling::{CoupledSteadyOptions, CoupledSteadySolver, SteadyLoad};
    let (al, st) = (aluminium(), steel());
    let mu = 0.3;
    let model = coupled_model(&al, &st, mu, true);
    assert!(model.is_coupled());
    let k = model.difference_parameter().unwrap();
    assert!((k - 0.1002).abs() < 1e-4, "K = {k}");
    let free = model.free_rolling(0.0, 0.0).unwrap();
    assert!(free.status.converged(), "{:?}", free.status);
    let grid = *model.grid();
    let gap: Vec<f64> = grid
        .points()
        .map(|(x, y)| (x * x + y * y) / (2.0 * SPHERE_R))
        .collect();
    let options = CoupledSteadyOptions {
        steady: KalkerExactOptions::default().steady,
        ..CoupledSteadyOptions::default()
    };
    let mut solver = CoupledSteadySolver::new(&grid, &al, &st, options).unwrap();
    let load = SteadyLoad::LongitudinalForce {
        force: 0.0,
        lateral: 0.0,
        spin: 0.0,
    };
    let r = solver.solve(&gap, Control::Force(300.0), mu, load).unwrap();
    assert!(r.status.converged());
    let (xi, xr) = (free.creepage.longitudinal, r.creepage.longitudinal);
    println!("free rolling: model {xi:e}, solver {xr:e}");
    // K > 0 (body 1 the more compliant): body 1 creeps backwards, ξ < 0.
    assert!(xi < 0.0);
    assert!((xi - xr).abs() <= 1e-9 * xr.abs(), "{xi:e} vs {xr:e}");
    // The curve with warm starts against the solver's sequence.
    let xis = [-3e-3, 0.0, 2e-3, 5e-3];
    let points = model.curve(&xis.map(Creepage::longitudinal)).unwrap();
    solver.reset();
    let bound = mu * 300.0;
    for (p, x) in points.iter().zip(xis) {
        let r = solver
            .solve(
                &gap,
                Control::Force(300.0),
                mu,
                SteadyLoad::Creepage(Creepage::longitudinal(x)),
            )
            .unwrap();
        assert!(p.status.converged() && r.status.converged());
        let d = (p.force[0] - r.force[0]).abs() / bound;
        println!(
            "ξ = {x:e}: F_x/(μF_N) {:.6}, difference {d:.1e}",
            p.normalized_force
        );
        assert!(d <= 1e-7, "ξ = {x}: {} vs {}", p.force[0], r.force[0]);
        // The point's pressure is its normal solution's (1e-6 relative; measured 1e-9).
        let p_max = r.pressure.iter().fold(0.0f64, |a, b| a.max(*b));
        println!("  p_max {:.6} MPa", p.max_pressure);
        assert!(
            (p.max_pressure / p_max - 1.0).abs() < 1e-6,
            "{} vs {p_max}",
            p.max_pressure
        );
    }
    // ... which changes with the tractions along the curve.
    assert!(
        points
            .windows(2)
            .all(|w| w[0].max_pressure != w[1].max_pressure)
    );
    // F_x falls with ξ and vanishes at ξ_free < 0: at ξ = 0 it is negative, at
    // ξ = −3e-3 < ξ_free positive.
    assert!(points[1].force[0] < 0.0, "{:?}", points[1].force);
    assert!(
        xis[0] < xi && points[0].force[0] > 0.0,
        "{:?}",
        points[0].force
    );
}

/// Swapping the bodies flips `K` and the free-rolling creepage (same size, 1e-9); the
/// coupled curve saturates at `μ F_N` in full sliding (1e-4).
#[test]
fn free_rolling_creepage_follows_k_and_the_curve_saturates() {
    let (al, st) = (aluminium(), steel());
    let mu = 0.3;
    let m12 = coupled_model(&al, &st, mu, true);
    let m21 = coupled_model(&st, &al, mu, true);
    assert!(m21.difference_parameter().unwrap() < 0.0);
    let x12 = m12.free_rolling(0.0, 0.0).unwrap();
    let x21 = m21.free_rolling(0.0, 0.0).unwrap();
    assert!(x12.status.converged() && x21.status.converged());
    let (a, b) = (x12.creepage.longitudinal, x21.creepage.longitudinal);
    println!("free rolling: K > 0 {a:e}, K < 0 {b:e}");
    assert!(a < 0.0 && b > 0.0, "{a:e} {b:e}");
    // Measured: −1.4292795e-3 and +1.4292795e-3, equal in size to the last bit.
    assert!((a + b).abs() <= 1e-9 * a.abs(), "{a:e} {b:e}");
    // Full sliding (ξ = 0.1, far beyond 2 μ p0/E* + (2K/G) p0 ≈ 0.02).
    let p = m12.solve(&Creepage::longitudinal(0.1), false).unwrap();
    assert!(p.status.converged());
    let total = p.force[0].hypot(p.force[1]) / (mu * 300.0);
    println!(
        "full sliding: F_T/(μF_N) = {:.8}, |F|/(μF_N) = {total:.8}, stick {}",
        p.normalized_force, p.stick_fraction
    );
    assert_eq!(p.stick_fraction, 0.0);
    // Measured: 0.99998295 (the steady solver's tolerance, as without the coupling:
    // `saturation_is_one`). Bound 1e-4.
    assert!((total - 1.0).abs() < 1e-4, "{total}");
    assert!(p.normalized_force > 0.999 && p.normalized_force <= 1.0 + 1e-9);
    // Through the TractionCurve interface: the same, from zero traction.
    let n = m12.normalized_force(0.1).unwrap();
    assert!((n - p.normalized_force).abs() < 1e-9);
}

/// The coupling is refused where the model has no `K` or no gap; a bad outer tolerance
/// is named.
#[test]
fn coupling_refused_without_materials_or_gap() {
    let options = KalkerExactOptions {
        elements: [16, 16],
        coupling: true,
        ..KalkerExactOptions::default()
    };
    let e = ContactEllipse::new(0.3, 0.3, 300.0).unwrap();
    let err = KalkerExact::with_material(e, RAIL, 0.3, options).unwrap_err();
    assert!(matches!(err, Error::InvalidInput { .. }));
    assert!(err.to_string().contains("coupling"), "{err}");
    let grid = kontakt::geometry::Grid2::centered(0.4, 0.4, 16, 16).unwrap();
    let p = vec![100.0; grid.len()];
    let err = KalkerExact::from_pressure(&grid, &p, 0.0, RAIL, 0.3, options).unwrap_err();
    assert!(err.to_string().contains("coupling"), "{err}");
    let bad = KalkerExactOptions {
        outer_tolerance: 0.0,
        ..options
    };
    let st = steel();
    let err = KalkerExact::new(e, &st, &aluminium(), 0.3, bad).unwrap_err();
    assert!(err.to_string().contains("outer_tolerance"), "{err}");
}

/// The tractions' normal displacement shifts the coupled contact along the rolling
/// direction (aluminium on steel, μ = 1, full sliding, 64 cells across: measured 0.047 a
/// beyond the ellipse, 1.5 cells); the coupled grid's margin keeps the leading-edge
/// column empty (two columns only were not enough), in both directions of sliding.
#[test]
fn the_coupled_contact_shifts_within_the_grid() {
    let (al, st) = (aluminium(), steel());
    let options = KalkerExactOptions {
        elements: [64, 64],
        coupling: true,
        ..KalkerExactOptions::default()
    };
    let e = sphere(&al, &st, 300.0);
    let m = KalkerExact::new(e, &al, &st, 1.0, options).unwrap();
    for xi in [0.05, -0.05] {
        let (p, s) = m
            .solve_with_field(&Creepage::longitudinal(xi), false)
            .unwrap();
        assert!(p.status.converged(), "{:?}", p.status);
        let g = m.grid();
        let reach = g
            .points()
            .zip(&s.state)
            .filter(|(_, st)| **st != kontakt::rolling::CellState::Exterior)
            .fold(0.0f64, |r, ((x, _), _)| r.max(x.abs()));
        println!("ξ = {xi}: contact to {:.4} a", reach / e.a());
        assert!(reach > e.a(), "{reach}");
    }
}
