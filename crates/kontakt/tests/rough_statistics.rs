//! Statistical rough-surface contact (`kontakt::rough`): Greenwood-Williamson height
//! integrals against independent closed forms, the GW model and its inverse, and the
//! Greenwood-Tripp rough sphere against its smooth (Hertz) and rigid limits, force
//! balance, the centre's gap equation and the picture of Johnson's (1982) Fig. 12.
//! Units: mm, N, MPa. The figures are recorded in docs/VALIDATION.md.
//!
//! Tolerances (relative): closed forms and independent quadrature of F_n 1e-11 .. 1e-13
//! (rounding and the cancellation in the closed forms); GW inverse 1e-9 in h; GT force
//! balance 1e-6; GT centre gap equation 1e-6 (table interpolation 1e-9, Newton 1e-10);
//! GT limits: Hertz 3 % at α = 0.01 (the physics: roughness still acts), rigid layer
//! 0.5 % at α = 500 (the bulk deflection, 0.1 %); Fig. 12 bands as stated in the test.
#![allow(clippy::unwrap_used)] // a panic is a test failure with its message

use kontakt::Error;
use kontakt::rough::{
    GreenwoodTripp, GreenwoodTrippOptions, GreenwoodTrippParams, GreenwoodTrippSolution,
    GreenwoodWilliamson, SummitHeights, height_integral, height_integral_quadrature,
    plasticity_index, roughness_parameter,
};
use std::f64::consts::PI;

// ---------------------------------------------------------------- independent oracles

/// erfc(x) for the test, independent of the library: Maclaurin series of erf for
/// |x| < 1.5, Laplace's continued fraction (evaluated backwards, 4000 terms) beyond.
fn erfc(x: f64) -> f64 {
    if x.abs() < 1.5 {
        let mut term = x;
        let mut sum = x;
        for n in 1..200 {
            term *= -x * x / n as f64;
            sum += term / (2 * n + 1) as f64;
        }
        1.0 - 2.0 / PI.sqrt() * sum
    } else if x > 0.0 {
        // erfc x = e^{-x²}/√π · 1/(x + (1/2)/(x + 1/(x + (3/2)/(x + ...))))
        let mut f = x;
        for k in (1..4000).rev() {
            f = x + 0.5 * k as f64 / f;
        }
        (-x * x).exp() / PI.sqrt() / f
    } else {
        2.0 - erfc(-x)
    }
}

fn phi(h: f64) -> f64 {
    (-0.5 * h * h).exp() / (2.0 * PI).sqrt()
}

/// Gaussian F_n(h) for n = 0, 1, 2 in closed form (erfc).
fn gaussian_closed(n: u32, h: f64) -> f64 {
    let f0 = 0.5 * erfc(h / 2f64.sqrt());
    match n {
        0 => f0,
        1 => phi(h) - h * f0,
        2 => (1.0 + h * h) * f0 - h * phi(h),
        _ => unreachable!(),
    }
}

/// Gaussian F_n(h), any n > -1, by composite Simpson after s = h + t² (smooth integrand
/// 2 t^{2n+1} φ(h + t²)), 200 000 panels on [0, sqrt(40 - h)].
fn gaussian_simpson(n: f64, h: f64) -> f64 {
    let t_max = (40.0 - h).sqrt();
    let m = 200_000;
    let dt = t_max / m as f64;
    let f = |t: f64| 2.0 * t.powf(2.0 * n + 1.0) * phi(h + t * t);
    let mut s = f(0.0) + f(t_max);
    for i in 1..m {
        s += f(i as f64 * dt) * if i % 2 == 1 { 4.0 } else { 2.0 };
    }
    s * dt / 3.0
}

fn rel(a: f64, b: f64) -> f64 {
    ((a - b) / b).abs()
}

// ---------------------------------------------------------------- GW height integrals

/// Exponential heights: the closed form Γ(n+1) e^{-h} against the quadrature path.
#[test]
fn exponential_closed_forms_match_quadrature() {
    let mut worst: f64 = 0.0;
    for n in [0.0, 0.5, 1.0, 1.5, 2.0, 2.5] {
        for h in [0.0, 0.3, 1.0, 2.5, 5.0, 10.0, 30.0] {
            let closed = height_integral(SummitHeights::Exponential, n, h).unwrap();
            let quad = height_integral_quadrature(SummitHeights::Exponential, n, h).unwrap();
            worst = worst.max(rel(closed, quad));
        }
    }
    assert!(worst < 1e-12, "worst relative difference {worst:e}");
    println!("exponential closed form vs quadrature: {worst:e}");
    // below the lowest summit every summit touches: F_0 = 1, F_1 = 1 - h
    for h in [-0.5, -2.0, -7.0] {
        let f0 = height_integral(SummitHeights::Exponential, 0.0, h).unwrap();
        let f1 = height_integral(SummitHeights::Exponential, 1.0, h).unwrap();
        assert!(
            (f0 - 1.0).abs() < 1e-12 && rel(f1, 1.0 - h) < 1e-12,
            "{h}: {f0} {f1}"
        );
    }
}

/// Gaussian F_0, F_1, F_2 against their erfc closed forms; F_{1/2}, F_{3/2} against the
/// exact values at h = 0 and against an independent Simpson rule elsewhere.
#[test]
fn gaussian_integrals_match_independent_values() {
    let mut worst: f64 = 0.0;
    for h in [-3.0, -1.0, 0.0, 0.5, 1.0, 2.0, 3.0, 4.0, 6.0] {
        for n in 0..=2 {
            let ours = height_integral(SummitHeights::Gaussian, n as f64, h).unwrap();
            worst = worst.max(rel(ours, gaussian_closed(n, h)));
        }
    }
    // 1e-11: the closed forms of F_1, F_2 cancel (φ - hF_0) at h = 6, losing 2 digits.
    assert!(worst < 1e-11, "F_0..F_2 worst relative error {worst:e}");
    println!("F_0..F_2 worst relative error {worst:e}");
    // F_n(0) = 2^{(n-1)/2} Γ((n+1)/2) / √(2π); Γ(5/4), Γ(3/4) to 17 digits
    #[allow(clippy::excessive_precision)]
    let f32_0 = 2f64.powf(0.25) * 0.906_402_477_055_477_1 / (2.0 * PI).sqrt();
    let f12_0 = 2f64.powf(-0.25) * 1.225_416_702_465_177_6 / (2.0 * PI).sqrt();
    let g = |n: f64, h: f64| height_integral(SummitHeights::Gaussian, n, h).unwrap();
    assert!(
        rel(g(1.5, 0.0), f32_0) < 1e-13,
        "{} vs {f32_0}",
        g(1.5, 0.0)
    );
    assert!(
        rel(g(0.5, 0.0), f12_0) < 1e-13,
        "{} vs {f12_0}",
        g(0.5, 0.0)
    );
    let mut worst: f64 = 0.0;
    for h in [-2.0, 0.5, 1.0, 2.0, 3.0, 4.0] {
        for n in [0.5, 1.5, 2.5] {
            worst = worst.max(rel(g(n, h), gaussian_simpson(n, h)));
        }
    }
    assert!(
        worst < 1e-10,
        "F_1/2, F_3/2, F_5/2 worst relative error {worst:e}"
    );
    println!("F_1/2, F_3/2, F_5/2 worst relative error {worst:e}");
}

// ---------------------------------------------------------------- GW model

/// Nominal pressure, area and count follow GW's eqs 5-8; for exponential heights their
/// ratios are constant (area and contact count proportional to the load).
#[test]
fn gw_model_and_its_inverse() {
    let (eta, beta, sigma, e) = (2000.0, 0.02, 5e-4, 115_000.0);
    let gw = GreenwoodWilliamson::new(eta, beta, sigma, e, SummitHeights::Gaussian).unwrap();
    let s = gw.at_separation(1.5 * sigma).unwrap();
    let h = 1.5;
    assert!(rel(s.standardised_separation, h) < 1e-15);
    let f = |n: u32| gaussian_closed(n, h);
    assert!(rel(s.contact_density, eta * f(0)) < 1e-12);
    assert!(rel(s.area_fraction, PI * eta * beta * sigma * f(1)) < 1e-12);
    let p = 4.0 / 3.0 * eta * e * beta.sqrt() * sigma.powf(1.5) * gaussian_simpson(1.5, h);
    assert!(rel(s.nominal_pressure, p) < 1e-10);
    // inverse, Gaussian and exponential, across touching and far separations
    for heights in [SummitHeights::Gaussian, SummitHeights::Exponential] {
        let gw = GreenwoodWilliamson::new(eta, beta, sigma, e, heights).unwrap();
        for h in [-4.0, -0.5, 0.0, 0.7, 2.0, 4.5, 8.0] {
            let p = gw.at_standardised_separation(h).unwrap().nominal_pressure;
            let back = gw.separation_from_pressure(p).unwrap();
            assert!(
                (back.standardised_separation - h).abs() < 1e-9,
                "{heights:?} h {h}: {}",
                back.standardised_separation
            );
        }
    }
    let ex = GreenwoodWilliamson::new(eta, beta, sigma, e, SummitHeights::Exponential).unwrap();
    let a = ex.at_standardised_separation(0.5).unwrap();
    let b = ex.at_standardised_separation(3.0).unwrap();
    assert!(
        rel(
            a.area_fraction / a.nominal_pressure,
            b.area_fraction / b.nominal_pressure
        ) < 1e-12
    );
    assert!(
        rel(
            a.contact_density / a.nominal_pressure,
            b.contact_density / b.nominal_pressure
        ) < 1e-12
    );
    // mean real pressure is load over real area
    assert!(rel(b.mean_real_pressure, b.nominal_pressure / b.area_fraction) < 1e-15);
}

#[test]
fn plasticity_index_value() {
    // ψ = (E*/H) sqrt(σ/β) = (115000/6000) sqrt(0.5/20)
    let psi = plasticity_index(115_000.0, 6000.0, 5e-4, 0.02).unwrap();
    assert!(rel(psi, 115.0 / 6.0 * 0.025f64.sqrt()) < 1e-15);
    let gw = GreenwoodWilliamson::new(1.0, 0.02, 5e-4, 115_000.0, SummitHeights::Gaussian).unwrap();
    assert_eq!(gw.plasticity_index(6000.0).unwrap(), psi);
}

// ---------------------------------------------------------------- Greenwood-Tripp

/// A steel sphere R 10 mm under 100 N with roughness chosen for the given α and μ
/// (summit radius 20 µm).
fn gt_params(alpha: f64, mu: f64) -> GreenwoodTrippParams {
    let (p, r, e, beta): (f64, f64, f64, f64) = (100.0, 10.0, 115_000.0, 0.02);
    let d0 = (9.0 * p * p / (16.0 * r * e * e)).cbrt();
    let sigma = alpha * d0;
    let eta = mu / (8.0 / 3.0 * sigma * (2.0 * r * beta).sqrt());
    GreenwoodTrippParams::new(p, r, e, sigma, eta, beta).unwrap()
}

fn gt(alpha: f64, mu: f64) -> GreenwoodTrippSolution {
    let solver = GreenwoodTripp::new(GreenwoodTrippOptions::default()).unwrap();
    let s = solver.solve(&gt_params(alpha, mu)).unwrap();
    assert!(s.status.converged(), "α {alpha} μ {mu}: {:?}", s.status);
    assert!(rel(s.alpha, alpha) < 1e-12 && rel(s.mu, mu) < 1e-12);
    s
}

/// α = 0.01: the smooth Hertz solution within a few per cent.
#[test]
fn gt_hertz_limit() {
    for mu in [4.0, 17.0] {
        let s = gt(0.01, mu);
        let p = s.centre_pressure / s.hertz_pressure;
        let a = s.effective_radius / s.hertz_radius;
        let d = s.approach / s.hertz_approach;
        println!("α 0.01 μ {mu}: p(0)/p0 {p:.4}, a*/a0 {a:.4}, d/δ0 {d:.4}");
        assert!((p - 1.0).abs() < 0.03, "p(0)/p0 = {p}");
        assert!((a - 1.0).abs() < 0.03, "a*/a0 = {a}");
        assert!((d - 1.0).abs() < 0.03, "d/δ0 = {d}");
        // the 95 % radius of Hertz' distribution is a0 sqrt(1 - 0.05^(2/3)) = 0.9297 a0
        let r95 = s.radius_95 / s.hertz_radius;
        assert!(
            (r95 / (1.0 - 0.05f64.powf(2.0 / 3.0)).sqrt() - 1.0).abs() < 0.03,
            "{r95}"
        );
    }
    // and closer still at α = 0.001
    let s = gt(0.001, 17.0);
    assert!((s.centre_pressure / s.hertz_pressure - 1.0).abs() < 0.003);
    assert!((s.effective_radius / s.hertz_radius - 1.0).abs() < 0.003);
}

/// The returned pressure integrates (exactly, piecewise linear) to the load.
#[test]
fn gt_force_balance() {
    for (alpha, mu) in [(0.01, 17.0), (0.3, 4.0), (1.85, 17.0), (20.0, 4.0)] {
        let s = gt(alpha, mu);
        let mut load = 0.0;
        for k in 0..s.radii.len() - 1 {
            let (r0, r1) = (s.radii[k], s.radii[k + 1]);
            let (p0, p1) = (s.pressure[k], s.pressure[k + 1]);
            // ∫ r p dr over a segment with linear p
            let h = r1 - r0;
            load += h * (p0 * (r0 / 2.0 + h / 6.0) + p1 * (r0 / 2.0 + h / 3.0));
        }
        load *= 2.0 * PI;
        assert!(rel(load, 100.0) < 1e-6, "α {alpha}: {load}");
        assert!(rel(s.load, 100.0) < 1e-6);
        println!("α {alpha}: load error {:e}", rel(load, 100.0));
        // negligible pressure at the outer radius
        assert!(*s.pressure.last().unwrap() < 1e-9 * s.centre_pressure);
    }
}

/// At the centre the gap equation holds with an independently computed displacement:
/// w(0) = (2/E*) ∫ p dr, and p(0) is GW's nominal pressure at the gap -d + w(0).
#[test]
fn gt_centre_satisfies_gap_equation() {
    for (alpha, mu) in [(0.05, 17.0), (1.85, 4.0)] {
        let params = gt_params(alpha, mu);
        let s = gt(alpha, mu);
        let mut int_p = 0.0;
        for k in 0..s.radii.len() - 1 {
            int_p += 0.5 * (s.pressure[k] + s.pressure[k + 1]) * (s.radii[k + 1] - s.radii[k]);
        }
        let w0 = 2.0 / 115_000.0 * int_p;
        let sigma = alpha * params.hertz_approach();
        let beta: f64 = 0.02;
        let eta = mu / (8.0 / 3.0 * sigma * (2.0 * 10.0 * beta).sqrt());
        let gw =
            GreenwoodWilliamson::new(eta, beta, sigma, 115_000.0, SummitHeights::Gaussian).unwrap();
        let p = gw.at_separation(-s.approach + w0).unwrap().nominal_pressure;
        println!(
            "α {alpha}: centre gap equation error {:e}",
            rel(p, s.centre_pressure)
        );
        assert!(
            rel(p, s.centre_pressure) < 1e-6,
            "α {alpha}: {p} vs {}",
            s.centre_pressure
        );
    }
}

/// Off the centre the gap equation holds too, with the displacement integrated in the
/// test by another method: w(r) = (4/(πE*)) ∫ p(s) s/(s+r) K(k) ds with K from the
/// arithmetic-geometric mean and a midpoint rule after s = r ± u² on each side of the logarithmic singularity
/// (the solver uses Carlson's R_F, Kronrod and tanh-sinh on a unit kernel).
#[test]
fn gt_gap_equation_off_centre() {
    let (alpha, mu, e, r_sphere, beta) = (0.3, 4.0, 115_000.0, 10.0, 0.02);
    let params = gt_params(alpha, mu);
    let s = gt(alpha, mu);
    let sigma = alpha * params.hertz_approach();
    let eta = mu / (8.0 / 3.0 * sigma * (2.0f64 * r_sphere * beta).sqrt());
    let gw = GreenwoodWilliamson::new(eta, beta, sigma, e, SummitHeights::Gaussian).unwrap();
    let r_max = *s.radii.last().unwrap();
    let dr = s.radii[1];
    let p_at = |x: f64| {
        if x >= r_max {
            return 0.0;
        }
        let k = ((x / dr) as usize).min(s.radii.len() - 2);
        let t = (x - s.radii[k]) / dr;
        s.pressure[k] * (1.0 - t) + s.pressure[k + 1] * t
    };
    // K(k) = π / (2 AGM(1, k')), k' = |x - r|/(x + r) (Gauss's arithmetic-geometric mean)
    let k_of = |kp: f64| {
        let (mut a, mut b) = (1.0f64, kp);
        for _ in 0..40 {
            let (an, bn) = (0.5 * (a + b), (a * b).sqrt());
            a = an;
            b = bn;
        }
        PI / (2.0 * a)
    };
    let integrand = |x: f64, r: f64| p_at(x) * x / (x + r) * k_of((x - r).abs() / (x + r));
    let mut worst: f64 = 0.0;
    for k in [8usize, 16, 24, 32, 40] {
        let r = s.radii[k];
        // ∫_0^r: s = r - u², u ∈ (0, √r); ∫_r^rmax: s = r + u², u ∈ (0, √(rmax - r))
        let m = 40_000;
        let mut w = 0.0;
        for (u_max, sign) in [(r.sqrt(), -1.0), ((r_max - r).sqrt(), 1.0)] {
            let du = u_max / m as f64;
            for i in 0..m {
                let u = (i as f64 + 0.5) * du;
                w += integrand(r + sign * u * u, r) * 2.0 * u * du;
            }
        }
        w *= 4.0 / (PI * e);
        let gap = -s.approach + r * r / (2.0 * r_sphere) + w;
        let p = gw.at_separation(gap).unwrap().nominal_pressure;
        worst = worst.max(((p - s.pressure[k]) / s.centre_pressure).abs());
    }
    println!("off-centre gap equation: worst error {worst:e} of p(0)");
    assert!(worst < 1e-6, "{worst:e}");
}

/// Very rough (α = 500): the bulk hardly deforms, so the pressure tends to the rigid
/// sphere on a GW layer, p̂(0) = c F_3/2(h0) with (2/5) c α F_5/2(h0) = 1/3,
/// c = π μ √α /(4√2), solved here by bisection on the public F_n.
#[test]
fn gt_rigid_limit() {
    let (alpha, mu): (f64, f64) = (500.0, 17.0);
    let c = PI * mu * alpha.sqrt() / (4.0 * 2f64.sqrt());
    let target = 5.0 / (6.0 * c * alpha);
    let (mut lo, mut hi) = (-20.0, 20.0);
    for _ in 0..200 {
        let mid = 0.5 * (lo + hi);
        if height_integral(SummitHeights::Gaussian, 2.5, mid).unwrap() > target {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    let h0 = 0.5 * (lo + hi);
    let p_rigid = c * height_integral(SummitHeights::Gaussian, 1.5, h0).unwrap();
    let s = gt(alpha, mu);
    let p = s.centre_pressure / s.hertz_pressure;
    println!(
        "α {alpha}: p(0)/p0 {p:.6e}, rigid layer {p_rigid:.6e}, d/δ0 {:.3} vs {:.3}",
        s.approach / s.hertz_approach,
        -h0 * alpha
    );
    assert!(rel(p, p_rigid) < 0.005, "{p} vs {p_rigid}");
    assert!(p < p_rigid, "elastic deflection can only spread the load");
}

/// Johnson (1982) Fig. 12 / §8: at α = 1.85 the centre pressure falls far below p0 and
/// the contact spreads well beyond the Hertz radius; at α ≈ 0.05 both stay within about
/// 10 % (Greenwood, Johnson and Matsubara 1984: "not likely to exceed about 7 %").
#[test]
fn gt_johnson_figure_12_picture() {
    for mu in [4.0, 17.0] {
        let s = gt(1.85, mu);
        let p = s.centre_pressure / s.hertz_pressure;
        let a = s.effective_radius / s.hertz_radius;
        let r95 = s.radius_95 / s.hertz_radius;
        println!("α 1.85 μ {mu}: p(0)/p0 {p:.4}, a*/a0 {a:.4}, r95/a0 {r95:.4}");
        assert!(p < 0.45 && p > 0.25, "p(0)/p0 = {p}");
        assert!(a > 1.8, "a*/a0 = {a}");
        assert!(r95 > 1.9, "r95/a0 = {r95}");
        for alpha in [0.047, 0.05] {
            let s = gt(alpha, mu);
            let p = s.centre_pressure / s.hertz_pressure;
            let a = s.effective_radius / s.hertz_radius;
            println!("α {alpha} μ {mu}: p(0)/p0 {p:.4}, a*/a0 {a:.4}");
            assert!((p - 1.0).abs() < 0.08 && (a - 1.0).abs() < 0.08, "{p} {a}");
        }
    }
}

/// Rougher means lower and wider: p(0) falls and a* grows with α.
#[test]
fn gt_trends_in_alpha() {
    let mut last = (f64::INFINITY, 0.0);
    for alpha in [0.003, 0.03, 0.1, 0.3, 1.0, 3.0, 10.0, 30.0] {
        let s = gt(alpha, 17.0);
        let p = s.centre_pressure / s.hertz_pressure;
        let a = s.effective_radius / s.hertz_radius;
        assert!(
            p < last.0 && a > last.1,
            "α {alpha}: {p} {a} after {last:?}"
        );
        last = (p, a);
    }
}

/// The solver converges, balances the load and leaves no pressure at its outer radius
/// over α = 1e-5 … 1e4 and μ = 0.1 … 1000 (the range the docs state).
#[test]
fn gt_converges_over_wide_range() {
    let solver = GreenwoodTripp::new(GreenwoodTrippOptions::default()).unwrap();
    for mu in [0.1, 1.0, 17.0, 1000.0] {
        for alpha in [1e-5, 1e-3, 0.1, 10.0, 1e4] {
            let s = solver.solve(&gt_params(alpha, mu)).unwrap();
            assert!(s.status.converged(), "α {alpha} μ {mu}: {:?}", s.status);
            assert!(s.status.iterations <= 8, "α {alpha} μ {mu}: {:?}", s.status);
            println!("α {alpha} μ {mu}: {} Newton steps", s.status.iterations);
            assert!(rel(s.load, 100.0) < 1e-9, "α {alpha} μ {mu}: {}", s.load);
            assert!(*s.pressure.last().unwrap() < 1e-9 * s.centre_pressure);
            assert!(s.pressure.iter().all(|p| p.is_finite() && *p >= 0.0));
        }
    }
}

/// Grid convergence: 64 intervals (default) and 256 agree to 1e-3.
#[test]
fn gt_grid_convergence() {
    let fine = GreenwoodTripp::new(GreenwoodTrippOptions {
        nodes: 256,
        ..Default::default()
    })
    .unwrap();
    for alpha in [0.01, 1.85] {
        let c = gt(alpha, 17.0);
        let f = fine.solve(&gt_params(alpha, 17.0)).unwrap();
        assert!(rel(c.centre_pressure, f.centre_pressure) < 1e-3);
        assert!(rel(c.effective_radius, f.effective_radius) < 1e-3);
        assert!(rel(c.radius_95, f.radius_95) < 1e-3);
    }
}

// ---------------------------------------------------------------- bad input

fn field_of<T: std::fmt::Debug>(r: kontakt::Result<T>) -> (String, String) {
    match r {
        Err(e @ Error::InvalidInput { .. }) => (e.field().unwrap().to_string(), e.to_string()),
        other => panic!("expected InvalidInput, got {other:?}"),
    }
}

#[test]
fn bad_input_is_a_clear_error() {
    let g = SummitHeights::Gaussian;
    let (f, m) = field_of(GreenwoodWilliamson::new(2000.0, 0.02, -5e-4, 1e5, g));
    assert_eq!(f, "summit_std");
    assert!(m.contains("-0.0005") && m.contains("> 0 mm"), "{m}");
    let (f, m) = field_of(GreenwoodWilliamson::new(f64::NAN, 0.02, 5e-4, 1e5, g));
    assert_eq!(f, "summit_density");
    assert!(m.contains("NaN"), "{m}");
    assert_eq!(
        field_of(GreenwoodWilliamson::new(0.0, 0.02, 5e-4, 1e5, g)).0,
        "summit_density"
    );
    assert_eq!(
        field_of(GreenwoodWilliamson::new(1.0, 0.0, 5e-4, 1e5, g)).0,
        "summit_radius"
    );
    assert_eq!(
        field_of(GreenwoodWilliamson::new(1.0, 0.02, 5e-4, f64::INFINITY, g)).0,
        "e_star"
    );
    let gw = GreenwoodWilliamson::new(2000.0, 0.02, 5e-4, 1e5, g).unwrap();
    assert_eq!(field_of(gw.at_separation(f64::NAN)).0, "separation");
    assert_eq!(
        field_of(gw.separation_from_pressure(-1.0)).0,
        "nominal_pressure"
    );
    assert_eq!(
        field_of(gw.separation_from_pressure(1e300)).0,
        "nominal_pressure"
    );
    assert_eq!(field_of(gw.plasticity_index(0.0)).0, "hardness");
    let (f, m) = field_of(height_integral(g, 0.7, 0.0));
    assert_eq!(f, "order");
    assert!(m.contains("0.7"), "{m}");
    assert_eq!(
        field_of(height_integral(g, 1.5, f64::INFINITY)).0,
        "separation"
    );
    let (f, m) = field_of(GreenwoodTrippParams::new(
        100.0, 10.0, 1e5, -1e-4, 1e3, 0.02,
    ));
    assert_eq!(f, "roughness");
    assert!(m.contains("-0.0001"), "{m}");
    assert_eq!(
        field_of(GreenwoodTrippParams::new(
            f64::NAN,
            10.0,
            1e5,
            1e-4,
            1e3,
            0.02
        ))
        .0,
        "load"
    );
    assert_eq!(
        field_of(GreenwoodTrippParams::new(100.0, 10.0, 1e5, 1e-4, 0.0, 0.02)).0,
        "summit_density"
    );
    assert_eq!(
        field_of(roughness_parameter(100.0, -10.0, 1e5, 1e-4)).0,
        "radius"
    );
    let (f, _) = field_of(GreenwoodTripp::new(GreenwoodTrippOptions {
        nodes: 3,
        ..Default::default()
    }));
    assert_eq!(f, "nodes");
    let (f, _) = field_of(GreenwoodTripp::new(GreenwoodTrippOptions {
        tolerance: f64::NAN,
        ..Default::default()
    }));
    assert_eq!(f, "tolerance");
}
