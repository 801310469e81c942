//! Validation of the coupled slices (docs/VALIDATION.md, coupled-slice rows; run with
//! `-- --nocapture` to print the figures).

use super::*;
use crate::profile::Profile;
use kontakt::geometry::Grid2;
use kontakt::halfspace::{Control, HalfSpaceSolver, SolverOptions, Start};

const E_STAR: f64 = STEEL_CONTACT_MODULUS_MPA;

/// `∫_a^b f` by `panels` panels of 10-point Gauss-Legendre.
fn integrate(f: impl Fn(f64) -> f64, a: f64, b: f64, panels: usize) -> f64 {
    let rule = kontakt::quadrature::gauss_legendre(10);
    let h = (b - a) / panels as f64;
    (0..panels)
        .map(|p| {
            let m = a + (p as f64 + 0.5) * h;
            rule.iter()
                .map(|&(x, w)| w * f(m + 0.5 * h * x))
                .sum::<f64>()
                * 0.5
                * h
        })
        .sum()
}

/// `∫₀^{π/2} f(θ) dθ` on panels graded geometrically toward θ = 0 (log singularities).
fn graded(f: impl Fn(f64) -> f64) -> f64 {
    let mut hi = 0.5 * PI;
    let mut s = 0.0;
    for _ in 0..60 {
        let lo = 0.5 * hi;
        s += integrate(&f, lo, hi, 4);
        hi = lo;
    }
    s
}

#[test]
fn strip_slope_is_the_elliptic_closed_form() {
    // Φ'(t) = ∫ cos²θ /√(t² + sin²θ) dθ by quadrature against √(1+t²)(K − E)
    for t in [1e-4, 0.01, 0.3, 1.0, 2.5, 17.0, 400.0, 1e5] {
        let direct = graded(|th: f64| th.cos().powi(2) / (t * t + th.sin().powi(2)).sqrt());
        let closed = strip_slope(t);
        assert!(
            (closed / direct - 1.0).abs() < 1e-12,
            "t = {t}: {closed} vs {direct}"
        );
    }
    // limits: ln(4/t) − 1 for small t, π/(4t) for large t
    assert!((strip_slope(1e-7) - ((4e7f64).ln() - 1.0)).abs() < 1e-9);
    assert!((strip_slope(1e7) * 1e7 / (0.25 * PI) - 1.0).abs() < 1e-13);
}

#[test]
fn strip_function_matches_its_integral_and_asymptotes() {
    let mut worst: f64 = 0.0;
    for t in [1e-5, 3e-3, 0.07, 0.5, 1.0, 1.37, 4.0, 33.0, 900.0, 2e4, 7e5] {
        let direct = graded(|th: f64| th.cos().powi(2) * (t / th.sin()).asinh());
        let ours = strip_function(t);
        worst = worst.max((ours / direct - 1.0).abs());
        assert!(
            (ours / direct - 1.0).abs() < 2e-9,
            "t = {t}: {ours} vs {direct}"
        );
        assert_eq!(strip_function(-t), -ours);
    }
    println!("strip function Φ(t): table against quadrature, worst {worst:.1e}");
    // the exact asymptotes outside the table and their continuity at its ends
    let big = |t: f64| 0.25 * PI * ((4.0 * t).ln() + 0.5) + PI / (64.0 * t * t);
    for t in [
        1e3,
        1e5,
        U_MAX.exp() * 0.999_999,
        U_MAX.exp() * 1.000_001,
        1e9,
    ] {
        assert!((strip_function(t) / big(t) - 1.0).abs() < 1e-10, "t = {t}");
    }
    let small = |t: f64| t * (4.0 / t).ln();
    for t in [U_MIN.exp() * 0.999_999, U_MIN.exp() * 1.000_001] {
        assert!((strip_function(t) / small(t) - 1.0).abs() < 1e-9, "t = {t}");
    }
    // the table's derivative is the closed-form slope
    for t in [0.01, 0.8, 3.0, 120.0] {
        let (_, d) = strip_at(table(), f64::ln(t));
        assert!((d / (t * strip_slope(t)) - 1.0).abs() < 1e-7, "t = {t}");
    }
}

#[test]
fn far_strips_act_as_line_load_segments() {
    // a uniform line load P on x ∈ [x1, x2] displaces (x = 0, y = 0) by
    // P/(π E*) ln(x2/x1) (Boussinesq integrated along the segment)
    let (w, x1, b) = (0.4, 1.0, 1e-3);
    let x2 = x1 + w;
    let kw = 4.0 / (PI * PI * E_STAR * w);
    let ours = kw * (strip_function(x2 / b) - strip_function(x1 / b));
    let line = (x2 / x1).ln() / (PI * E_STAR * w);
    assert!((ours / line - 1.0).abs() < 1e-6, "{ours} vs {line}");
}

#[test]
fn lu_solves_plain_and_transposed() {
    let m = 4;
    let a0 = [
        0.0, 2.0, 1.0, 3.0, 4.0, 1.0, 0.5, 2.0, 1.0, 1.0, 5.0, 1.0, 2.0, 0.0, 1.0, 6.0,
    ];
    let mut lu = a0;
    let mut perm = [0usize; 4];
    assert!(lu_factor(&mut lu, m, &mut perm));
    let x = [1.0, -2.0, 0.5, 3.0];
    for transposed in [false, true] {
        let mut b = [0.0; 4];
        for i in 0..m {
            for j in 0..m {
                let aij = if transposed {
                    a0[j * m + i]
                } else {
                    a0[i * m + j]
                };
                b[i] += aij * x[j];
            }
        }
        lu_solve(&lu, m, &perm, &mut b, transposed);
        for i in 0..m {
            assert!((b[i] - x[i]).abs() < 1e-13, "{transposed}: {b:?}");
        }
    }
}

/// The rigid interference of a roller on a flat at the approach `a0`: `a0 − drop(x)`.
fn interference(c: &SliceContact, profile: &Profile, a0: f64, tilt: f64) -> Vec<f64> {
    c.positions()
        .iter()
        .map(|&x| a0 + tilt * x - profile.drop(x))
        .collect()
}

/// Solve one roller contact for the roller load `load` (N) by a scalar Newton on the
/// approach; the slice loads.
fn solve_for_load(
    c: &mut SliceContact,
    profile: &Profile,
    load: f64,
    tilt: f64,
) -> (f64, Vec<f64>) {
    let n = c.positions().len();
    let mut q = vec![0.0; n];
    let c_s = 35_948.0 * 10f64.powf(8.0 / 9.0) / n as f64;
    let mut a0 = (load / (c_s * n as f64)).powf(0.9);
    for _ in 0..100 {
        let d = interference(c, profile, a0, tilt);
        let r = c.solve(&d, &mut q, c_s).expect("slice solve");
        let err = r.load_n - load;
        if err.abs() <= 1e-12 * load {
            return (a0, q);
        }
        a0 -= err / r.stiffness[0][0];
    }
    panic!("no load balance");
}

/// kontakt's FFT half-space solver on the same roller on a flat (R = D/2 across, the
/// profile along, no material beyond the ends) under the load `load`: per slice of `c`,
/// the line load (N/mm, the pressure integrated over the slice) and the largest pressure
/// (MPa).
fn fft_roller(
    c: &SliceContact,
    (radius, profile, tilt): (f64, &Profile, f64),
    load: f64,
    cells_per_slice: usize,
    cells_across: usize,
) -> (Vec<f64>, Vec<f64>, f64) {
    let n = c.positions().len();
    let w = c.width();
    let length = w * n as f64;
    // the widest half-width: the largest line load at most 2.5 times the mean
    let b = c.half_width(if tilt == 0.0 { 2.5 } else { 6.0 } * load / n as f64, 0);
    let nx = n * cells_per_slice + 8;
    let half_x = 0.5 * nx as f64 * w / cells_per_slice as f64;
    let grid = Grid2::centered(half_x, 1.2 * b, nx, cells_across).unwrap();
    let gap: Vec<f64> = grid
        .points()
        .map(|(x, y)| {
            if x.abs() > 0.5 * length {
                f64::INFINITY
            } else {
                y * y / (2.0 * radius) + profile.drop(x).min(1.0) + tilt * (0.5 * length - x)
            }
        })
        .collect();
    let options = SolverOptions {
        tolerance: 1e-9,
        threads: Some(1),
        ..SolverOptions::default()
    };
    let mut solver = HalfSpaceSolver::new(grid, E_STAR, options).unwrap();
    let report = solver
        .solve(&gap, Control::Force(load), Start::Cold)
        .unwrap();
    assert!(report.status.converged(), "{report:?}");
    let p = solver.pressure();
    let mut line = vec![0.0; n];
    let mut peak = vec![0.0f64; n];
    for j in 0..grid.ny() {
        for i in 0..grid.nx() {
            let x = grid.x(i);
            if x.abs() > 0.5 * length {
                continue;
            }
            let k = (((x + 0.5 * length) / w) as usize).min(n - 1);
            let pij = p[j * grid.nx() + i];
            line[k] += pij * grid.cell_area() / w;
            peak[k] = peak[k].max(pij);
        }
    }
    (line, peak, report.max_pressure)
}

/// The crowned roller of the half-space comparison: D = 10 mm on a flat (R = 5 mm),
/// L = 10 mm, the ISO/TS 16281 logarithmic profile, 31 slices.
fn crowned(slices: usize) -> (SliceContact, Profile) {
    (roller_on_flat(slices), Profile::iso(10.0, 10.0))
}

/// A roller D 10 × L 10 mm on a flat (one contact, R = 5 mm), steel.
fn roller_on_flat(slices: usize) -> SliceContact {
    SliceContact::new(
        10.0,
        slices,
        &[5.0],
        E_STAR,
        35_948.0 * 10f64.powf(8.0 / 9.0),
    )
    .unwrap()
}

/// Our slice pressures against the FFT half-space for one roller: (ours, FFT p0 of the
/// slice's line load, FFT cell maximum per slice, FFT maximum).
fn compare(
    c: &mut SliceContact,
    profile: &Profile,
    load: f64,
    tilt: f64,
) -> (Vec<f64>, Vec<f64>, Vec<f64>, f64) {
    let (_, q) = solve_for_load(c, profile, load, tilt);
    let ours: Vec<f64> = q.iter().map(|&qi| c.pressure(qi, 0)).collect();
    let (line, peak, pmax) = fft_roller(c, (5.0, profile, tilt), load, 8, 48);
    let fft: Vec<f64> = line
        .iter()
        .map(|&p| (p * E_STAR / (PI * 5.0)).sqrt())
        .collect();
    (ours, fft, peak, pmax)
}

#[test]
fn crowned_roller_pressure_against_the_fft_half_space() {
    // (slices, roller load N, whether the contact ends inside the roller)
    for (slices, load, inside) in [
        (31, 2_000.0, true),
        (31, 3_000.0, true),
        (61, 3_000.0, true),
        (31, 5_000.0, false),
        (31, 8_000.0, false),
    ] {
        let (mut c, profile) = crowned(slices);
        let n = c.positions().len();
        let (ours, fft, peak, pmax) = compare(&mut c, &profile, load, 0.0);
        let our_peak = ours.iter().copied().fold(0.0, f64::max);
        // the edge: the outermost slice entirely inside the FFT's contact (its outer
        // neighbour loaded too)
        let e = (0..n - 1).rev().find(|&k| fft[k + 1] > 0.0).unwrap();
        let (our_edge, fft_edge) = (ours[e], fft[e]);
        println!(
            "ISO crowned roller D 10 x L 10 mm on a flat, {n} slices, Q = {load} N: peak ours {our_peak:.2} MPa, FFT {pmax:.2} MPa ({:+.2} %); edge slice {e}: ours {our_edge:.2} MPa, FFT {fft_edge:.2} MPa ({:+.2} %); end slice: ours {:.2}, FFT {:.2} (cell max {:.2}) MPa",
            100.0 * (our_peak / pmax - 1.0),
            100.0 * (our_edge / fft_edge - 1.0),
            ours[n - 1],
            fft[n - 1],
            peak[n - 1],
        );
        assert!((our_peak / pmax - 1.0).abs() < 0.02);
        if inside {
            assert!((our_edge / fft_edge - 1.0).abs() < 0.02);
            // every slice but the partly loaded outermost ones within 2 %
            for k in 0..n {
                if k >= n - e - 1 && k <= e {
                    assert!((ours[k] / fft[k] - 1.0).abs() < 0.02, "slice {k}");
                }
            }
        }
    }
}

#[test]
fn straight_roller_shows_the_edge_peak_and_the_2d_hertz_pressure_inside() {
    // a straight roller with sharp ends, D 10 x L 10 mm on a flat, 5 kN
    let profile = Profile::Straight;
    let mut seen = Vec::new();
    for slices in [31, 61, 121] {
        let mut c = roller_on_flat(slices);
        let (_, q) = solve_for_load(&mut c, &profile, 5_000.0, 0.0);
        let n = slices;
        let p: Vec<f64> = q.iter().map(|&qi| c.pressure(qi, 0)).collect();
        let (centre, end) = (p[n / 2], p[n - 1]);
        let inner_min = p[1..n - 1].iter().copied().fold(f64::INFINITY, f64::min);
        println!(
            "straight roller, {n} slices: centre {centre:.1} MPa, end slice {end:.1} MPa ({:.3} x centre)",
            end / centre
        );
        // the edge peak: the end slice well above the centre, growing as the slices
        // resolve the singular edge
        assert!(end > 1.2 * centre && end > inner_min);
        seen.push(end);
        if slices == 31 {
            let (ours, fft, peak, _) = compare(&mut c, &profile, 5_000.0, 0.0);
            println!(
                "  against the FFT half-space: end slice ours {:.1}, FFT {:.1} MPa ({:+.2} %), centre ours {:.1}, FFT cell max {:.1} MPa ({:+.2} %)",
                ours[n - 1],
                fft[n - 1],
                100.0 * (ours[n - 1] / fft[n - 1] - 1.0),
                ours[n / 2],
                peak[n / 2],
                100.0 * (ours[n / 2] / peak[n / 2] - 1.0)
            );
            // far from the ends the FFT's pressure is the 2-D Hertz pressure of its own
            // line load, and ours
            assert!((fft[n / 2] / peak[n / 2] - 1.0).abs() < 0.005);
            assert!((ours[n / 2] / peak[n / 2] - 1.0).abs() < 0.01);
            assert!((ours[n - 1] / fft[n - 1] - 1.0).abs() < 0.05);
        }
    }
    assert!(seen[0] < seen[1] && seen[1] < seen[2]);
}

#[test]
fn uniform_load_on_a_straight_roller_has_the_iso_mean_approach() {
    // G for uniform slice loads, averaged over the slices, is the ISO law's approach
    let (l, n) = (12.0_f64, 31);
    let c_l = 35_948.0 * l.powf(8.0 / 9.0);
    let mut c = SliceContact::new(l, n, &[4.2, 5.9], E_STAR, c_l).unwrap();
    let tab = table();
    for q_total in [500.0, 5_000.0, 50_000.0] {
        let qk = q_total / n as f64;
        c.g.iter_mut().for_each(|v| *v = 0.0);
        for j in 0..n {
            c.column(tab, j, qk, 0.0);
        }
        let (dref, _) = c.reference(tab, q_total);
        let mean = c.g.iter().map(|g| g + dref).sum::<f64>() / n as f64;
        let iso = (q_total / c_l).powf(0.9);
        assert!((mean / iso - 1.0).abs() < 1e-12, "{mean} vs {iso}");
        // a straight roller pressed uniformly (rigid, no tilt) at that approach: the edge
        // slices take more, so it carries more than the ISO law says
        let mut q = vec![0.0; n];
        let r = c.solve(&vec![iso; n], &mut q, c_l / n as f64).unwrap();
        println!(
            "straight roller L {l} mm at the ISO approach of {q_total} N: coupled load {:.1} N ({:+.2} %), end/centre slice load {:.3}",
            r.load_n,
            100.0 * (r.load_n / q_total - 1.0),
            q[n - 1] / q[n / 2]
        );
        assert!(r.load_n > q_total && r.load_n < 1.1 * q_total);
    }
}

#[test]
fn tilted_crowned_roller_against_the_fft_half_space() {
    // the ISO-crowned roller tilted by 0.5 and 1 mrad at 3 kN: the load moves to one end
    for (slices, tilt) in [(31, 5e-4), (61, 5e-4), (31, 1e-3), (61, 1e-3)] {
        let (mut c, profile) = crowned(slices);
        let n = c.positions().len();
        let (ours, fft, _, pmax) = compare(&mut c, &profile, 3_000.0, tilt);
        let our_peak = ours.iter().copied().fold(0.0, f64::max);
        let k_peak = (0..n).max_by(|&a, &b| ours[a].total_cmp(&ours[b])).unwrap();
        // slices entirely inside the FFT's contact (both neighbours loaded); the outermost
        // of them at each end, next to where the contact ends, apart
        let inside: Vec<usize> = (1..n - 1)
            .filter(|&k| fft[k - 1] > 0.0 && fft[k + 1] > 0.0)
            .collect();
        let (first, last) = (inside[0], inside[inside.len() - 1]);
        let dev = |k: usize| (ours[k] / fft[k] - 1.0).abs();
        let interior = inside
            .iter()
            .filter(|&&k| k != first && k != last)
            .map(|&k| dev(k))
            .fold(0.0, f64::max);
        let edge = dev(first).max(dev(last));
        println!(
            "ISO crowned roller, {n} slices, tilted {:.1} mrad, 3 kN: peak ours {our_peak:.1} MPa at slice {k_peak}, FFT {pmax:.1} MPa ({:+.2} %); slices inside the contact within {:.2} %, the outermost ones (slices {first}, {last}) within {:.2} %",
            tilt * 1e3,
            100.0 * (our_peak / pmax - 1.0),
            100.0 * interior,
            100.0 * edge
        );
        assert!(k_peak > n / 2, "the load moves toward +x");
        assert!((our_peak / pmax - 1.0).abs() < 0.02);
        assert!(interior < 0.02);
        assert!(edge < 0.04);
    }
}
