//! A cylindrical roller bearing under radial load against an independent implementation:
//! `fcylrolbear` of moritzploss/tribology (`tribology/roller_bearings.py`).
//!
//! `tests/data/crb_fcylrolbear.csv` holds fcylrolbear's roller loads for Z = 14 rollers
//! 11 × 11 mm on d_m = 60 mm, 31 slices, clearance −10 (a preload), 0, 10 and 20 µm,
//! F_r = 1, 5, 10 and 20 kN, straight rollers and the ISO/TS 16281 logarithmic profile
//! (32 cases, 448 roller loads); it was written by
//! `tools/reference/crb_fcylrolbear.py` (its header records the tribology commit, the date
//! and the command). The two codes share the ISO/TS 16281 slice law (35948 L^(8/9) δ^(10/9)
//! for the roller, 1/n of it per slice) but no code: fcylrolbear solves one unknown (the
//! ring displacement along the load) by a secant iteration, kontakt five by Newton with
//! the analytic stiffness; the geometry of the approach (δ_r cos ψ − s/2 − 2 P), the
//! clearance convention, the slice count and the summation are what is cross-checked.
//!
//! **Conventions, translated explicitly** (docs/bearing-model.md, "Cross-check against
//! fcylrolbear"):
//! - fcylrolbear's `rad_clear` enters as `δ_r cos ψ − rad_clear/2`: both sides together,
//!   kontakt's `clearance_mm` (diametral), so the same number goes to both;
//! - its `comb_prof` is subtracted twice (inner and outer contact): with straight raceways it
//!   is kontakt's roller profile drop, `2 P_roller`; the script evaluates the ISO profile at
//!   kontakt's slice centres from its own formula and records the values, and this test
//!   checks that `Profile::iso` gives the same drops;
//! - its roller length in the stiffness is the span of `ax_rol`, which the script makes
//!   exactly L_we (its slice positions enter nothing else when the roller does not tilt).
//!
//! **Tolerance.** fcylrolbear stops when `|F_r − Σ Q_j cos ψ_j| ≤ max_dif F_r` (max_dif =
//! 1e-9 here). Its roller loads are those of its discrete equations at a ring displacement
//! off by dδ_r; each roller changes by `k_j cos ψ_j dδ_r` while the load sum changes by
//! `Σ k_j cos² ψ_j dδ_r`, and the roller at ψ = 0 (present here) is the stiffest (its
//! approach is the largest, also under preload), so every
//! roller load is within `|ΔF| ≤ max_dif F_r` of the exact solution. kontakt converges to
//! 1e-11 F_r. Every roller must agree to `(max_dif + 1e-10) F_r`; the test also checks
//! that halving kontakt's clearance (the radial-vs-diametral mix-up) misses by far more.

#![allow(clippy::unwrap_used, clippy::expect_used)] // test helpers: a panic is a test failure

use kontakt::solve::Termination;
use kontakt_bearing::equilibrium::{RingLoad, RollerBearingSolver};
use kontakt_bearing::geometry::RollerBearing;
use kontakt_bearing::profile::Profile;

const PITCH_MM: f64 = 60.0;
const ROLLERS: usize = 14;
const ROLLER_D_MM: f64 = 11.0;
const ROLLER_L_MM: f64 = 11.0;
const SLICES: usize = 31;
/// fcylrolbear's convergence criterion used by the script (the CSV header states it).
const MAX_DIF: f64 = 1e-9;
/// kontakt's own convergence (1e-11 of the load) with margin.
const KONTAKT_TOL: f64 = 1e-10;

const DATA: &str = include_str!("data/crb_fcylrolbear.csv");
const PROFILE: &str = include_str!("data/crb_fcylrolbear_profile.csv");

/// One roller row of the reference.
struct Row {
    case: String,
    profile: String,
    clearance_mm: f64,
    fr_n: f64,
    roller: usize,
    azimuth_rad: f64,
    q_n: f64,
    delta_f_n: f64,
}

/// The data lines of a CSV with `#` comments and a header row, split at commas.
fn records(text: &str) -> Vec<Vec<&str>> {
    text.lines()
        .filter(|l| !l.starts_with('#') && !l.trim().is_empty())
        .skip(1)
        .map(|l| l.split(',').collect())
        .collect()
}

fn num(s: &str) -> f64 {
    s.parse().unwrap_or_else(|_| panic!("not a number: {s:?}"))
}

fn rows() -> Vec<Row> {
    records(DATA)
        .into_iter()
        .map(|r| Row {
            case: r[0].to_string(),
            profile: r[1].to_string(),
            clearance_mm: num(r[2]),
            fr_n: num(r[3]),
            roller: r[4].parse().unwrap(),
            azimuth_rad: num(r[5]),
            q_n: num(r[6]),
            delta_f_n: num(r[7]),
        })
        .collect()
}

fn bearing(profile: &str, clearance_mm: f64) -> RollerBearing {
    let mut b = RollerBearing::cylindrical(PITCH_MM, ROLLERS, ROLLER_D_MM, ROLLER_L_MM);
    b.slices = SLICES;
    b.clearance_mm = clearance_mm;
    b.first_roller_azimuth_rad = 0.0;
    b.roller_profile = match profile {
        "straight" => Profile::Straight,
        "iso" => Profile::iso(ROLLER_L_MM, ROLLER_D_MM),
        other => panic!("unknown profile {other:?}"),
    };
    b
}

/// kontakt's roller loads (N) under the radial load `fr_n` along ψ = 0, tilts held.
fn kontakt_loads(b: RollerBearing, fr_n: f64) -> Vec<f64> {
    let mut solver = RollerBearingSolver::new(b).unwrap();
    let sol = solver
        .solve(&RingLoad::forces([fr_n, 0.0, 0.0, 0.0, 0.0]).with_tilts_held())
        .unwrap();
    assert_eq!(
        sol.status.termination,
        Termination::Converged,
        "{:?}",
        sol.note
    );
    solver.roller_loads().iter().map(|r| r.outer_n).collect()
}

/// The cases of the file in order, each with its rows.
fn cases() -> Vec<Vec<Row>> {
    let mut out: Vec<Vec<Row>> = Vec::new();
    for r in rows() {
        match out.last_mut() {
            Some(c) if c[0].case == r.case => c.push(r),
            _ => out.push(vec![r]),
        }
    }
    out
}

#[test]
fn the_file_is_what_the_test_assumes() {
    assert!(
        DATA.contains(&format!("# max_dif = {MAX_DIF:e}").replace("e-9", "e-09")),
        "the header must state max_dif = {MAX_DIF}"
    );
    let cases = cases();
    assert_eq!(cases.len(), 32, "2 profiles x 4 clearances x 4 loads");
    for c in &cases {
        assert_eq!(c.len(), ROLLERS, "{}", c[0].case);
        for (j, r) in c.iter().enumerate() {
            assert_eq!(r.roller, j);
            let psi = 2.0 * std::f64::consts::PI * j as f64 / ROLLERS as f64;
            assert!((r.azimuth_rad - psi).abs() < 1e-15, "{} roller {j}", r.case);
        }
        // fcylrolbear's own criterion held, and its loads balance F_r to its residual
        let r0 = &c[0];
        assert!(r0.delta_f_n.abs() <= MAX_DIF * r0.fr_n, "{}", r0.case);
        let carried: f64 = c.iter().map(|r| r.q_n * r.azimuth_rad.cos()).sum();
        let err = (r0.fr_n - r0.delta_f_n - carried).abs();
        assert!(err < 1e-12 * r0.fr_n, "{}: {err} N", r0.case);
    }
}

/// The combined profile handed to fcylrolbear is kontakt's ISO roller drop at its slices.
#[test]
fn the_same_profile_went_to_both() {
    let solver = RollerBearingSolver::new(bearing("iso", 0.0)).unwrap();
    let x = solver.slice_positions();
    let iso = Profile::iso(ROLLER_L_MM, ROLLER_D_MM);
    let rec = records(PROFILE);
    assert_eq!(rec.len(), SLICES);
    for (k, r) in rec.iter().enumerate() {
        let (xk, p) = (num(r[1]), num(r[2]));
        assert!((xk - x[k]).abs() < 1e-14, "slice {k}: x {xk} vs {}", x[k]);
        let ours = iso.drop(x[k]);
        assert!(
            (ours - p).abs() <= 1e-14 * p.max(1e-3),
            "slice {k}: drop {ours} vs {p} mm"
        );
    }
}

#[test]
fn roller_loads_match_fcylrolbear() {
    let mut worst: f64 = 0.0;
    let mut report = Vec::new();
    for c in cases() {
        let r0 = &c[0];
        let tol = (MAX_DIF + KONTAKT_TOL) * r0.fr_n;
        let ours = kontakt_loads(bearing(&r0.profile, r0.clearance_mm), r0.fr_n);
        let mut dmax: f64 = 0.0;
        for (r, q) in c.iter().zip(&ours) {
            let d = (q - r.q_n).abs();
            assert!(
                d <= tol,
                "{} roller {}: kontakt {q} N, fcylrolbear {} N, difference {d:e} N > {tol:e} N",
                r.case,
                r.roller,
                r.q_n
            );
            dmax = dmax.max(d);
        }
        let qmax = c.iter().map(|r| r.q_n).fold(0.0, f64::max);
        worst = worst.max(dmax / r0.fr_n);
        report.push(format!(
            "{:24} Q_max {qmax:12.6} N  max |dQ| {dmax:.2e} N = {:.2e} F_r",
            r0.case,
            dmax / r0.fr_n
        ));
    }
    println!("{}\nworst: {worst:.2e} F_r", report.join("\n"));
}

/// The tolerance sees the clearance convention: with kontakt's clearance halved (as if
/// fcylrolbear's `rad_clear` were one side's play) every case with clearance misses by far.
#[test]
fn a_halved_clearance_is_caught() {
    for c in cases() {
        let r0 = &c[0];
        if r0.clearance_mm == 0.0 {
            continue;
        }
        let tol = (MAX_DIF + KONTAKT_TOL) * r0.fr_n;
        let ours = kontakt_loads(bearing(&r0.profile, 0.5 * r0.clearance_mm), r0.fr_n);
        let dmax = c
            .iter()
            .zip(&ours)
            .map(|(r, q)| (q - r.q_n).abs())
            .fold(0.0, f64::max);
        assert!(
            dmax > 1e3 * tol,
            "{}: halved clearance misses by only {dmax:e} N",
            r0.case
        );
    }
}
