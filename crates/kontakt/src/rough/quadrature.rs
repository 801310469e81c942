//! Adaptive Gauss-Kronrod (7-15) quadrature on a finite interval, for the smooth
//! integrands of the rough-surface models (the summit-height integrals $F_n(h)$).
//!
//! # Method
//! The 15-point Kronrod rule and its embedded 7-point Gauss rule (nodes and weights of
//! QUADPACK's `qk15`, Piessens et al. 1983) give an estimate and an error bound
//! $|K_{15} - G_7|$ on each sub-interval; the interval with the largest error is bisected
//! until the summed error is below `abs_tol` or `rel_tol` times the integral. The Kronrod
//! rule integrates polynomials of degree 22 exactly (unit tested), so the smooth integrands
//! used here converge in a handful of bisections.
//!
//! # Reference
//! Piessens, de Doncker-Kapenga, Überhuber and Kahaner (1983), *QUADPACK*, Springer.

/// Kronrod abscissae on [0, 1] (the rule is symmetric); odd indices are the Gauss nodes.
// The digits as QUADPACK prints them, so that they can be checked by eye.
#[allow(clippy::excessive_precision)]
const XGK: [f64; 8] = [
    0.991_455_371_120_812_639_206_854_697_526_329,
    0.949_107_912_342_758_524_526_189_684_047_851,
    0.864_864_423_359_769_072_789_712_788_640_926,
    0.741_531_185_599_394_439_863_864_773_280_788,
    0.586_087_235_467_691_130_294_144_845_693_013,
    0.405_845_151_377_397_166_906_606_412_076_961,
    0.207_784_955_007_898_467_600_689_403_773_245,
    0.0,
];

/// Kronrod weights, matching [`XGK`].
// The digits as QUADPACK prints them, so that they can be checked by eye.
#[allow(clippy::excessive_precision)]
const WGK: [f64; 8] = [
    0.022_935_322_010_529_224_963_732_008_058_970,
    0.063_092_092_629_978_553_290_700_663_189_204,
    0.104_790_010_322_250_183_839_876_322_541_518,
    0.140_653_259_715_525_918_745_189_590_510_238,
    0.169_004_726_639_267_902_826_583_426_598_550,
    0.190_350_578_064_785_409_913_256_402_421_014,
    0.204_432_940_075_298_892_414_161_999_234_649,
    0.209_482_141_084_727_828_012_999_174_891_714,
];

/// Gauss weights of the nodes `XGK[1], XGK[3], XGK[5], XGK[7]`.
// The digits as QUADPACK prints them, so that they can be checked by eye.
#[allow(clippy::excessive_precision)]
const WG: [f64; 4] = [
    0.129_484_966_168_869_693_270_611_432_679_082,
    0.279_705_391_489_276_667_901_467_771_423_780,
    0.381_830_050_505_118_944_950_369_775_488_975,
    0.417_959_183_673_469_387_755_102_040_816_327,
];

/// Most sub-intervals the adaptive rule creates before it returns its best estimate.
const MAX_INTERVALS: usize = 200;

/// The 15-point Kronrod rule on [-1, 1] as (node, weight) pairs: a fixed rule exact for
/// polynomials of degree 22, for smooth integrands on short intervals.
pub(crate) fn kronrod15_rule() -> [(f64, f64); 15] {
    let mut out = [(0.0, 0.0); 15];
    for i in 0..7 {
        out[2 * i] = (-XGK[i], WGK[i]);
        out[2 * i + 1] = (XGK[i], WGK[i]);
    }
    out[14] = (0.0, WGK[7]);
    out
}

/// One 15-point Kronrod estimate on `[a, b]` and its error bound `|K15 - G7|`.
fn kronrod15(f: &impl Fn(f64) -> f64, a: f64, b: f64) -> (f64, f64) {
    let c = 0.5 * (a + b);
    let h = 0.5 * (b - a);
    let fc = f(c);
    let mut k = WGK[7] * fc;
    let mut g = WG[3] * fc;
    for i in 0..7 {
        let dx = h * XGK[i];
        let s = f(c - dx) + f(c + dx);
        k += WGK[i] * s;
        if i % 2 == 1 {
            g += WG[i / 2] * s;
        }
    }
    (k * h, ((k - g) * h).abs())
}

/// $\int_a^b f(x)\,dx$ by adaptive Gauss-Kronrod; returns `(integral, error estimate)`.
///
/// Stops when the summed error estimate is below `max(abs_tol, rel_tol·|integral|)` or
/// after [`MAX_INTERVALS`] sub-intervals (the estimate is then returned as is; callers
/// that care compare the error estimate with their tolerance).
pub(crate) fn integrate(
    f: impl Fn(f64) -> f64,
    a: f64,
    b: f64,
    abs_tol: f64,
    rel_tol: f64,
) -> (f64, f64) {
    if a == b {
        return (0.0, 0.0);
    }
    let (v, e) = kronrod15(&f, a, b);
    // (a, b, value, error)
    let mut parts: Vec<(f64, f64, f64, f64)> = vec![(a, b, v, e)];
    loop {
        let total: f64 = parts.iter().map(|p| p.2).sum();
        let err: f64 = parts.iter().map(|p| p.3).sum();
        if err <= abs_tol.max(rel_tol * total.abs()) || parts.len() >= MAX_INTERVALS {
            return (total, err);
        }
        let (worst, _) =
            parts.iter().enumerate().fold(
                (0, -1.0),
                |acc, (i, p)| if p.3 > acc.1 { (i, p.3) } else { acc },
            );
        let (a0, b0, _, _) = parts.swap_remove(worst);
        let m = 0.5 * (a0 + b0);
        if !(m > a0 && m < b0) {
            // The interval cannot be split further in f64: accept what we have.
            return (total, err);
        }
        let (v1, e1) = kronrod15(&f, a0, m);
        let (v2, e2) = kronrod15(&f, m, b0);
        parts.push((a0, m, v1, e1));
        parts.push((m, b0, v2, e2));
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The Kronrod weights sum to 1 on [0, 1] (2 on [-1, 1]), the Gauss ones too, and one
    /// panel integrates x^k exactly up to k = 22 (the rule's degree).
    #[test]
    fn rule_is_exact_for_polynomials_to_degree_22() {
        let sk: f64 = 2.0 * WGK[..7].iter().sum::<f64>() + WGK[7];
        let sg: f64 = 2.0 * WG[..3].iter().sum::<f64>() + WG[3];
        assert!((sk - 2.0).abs() < 1e-15, "{sk}");
        assert!((sg - 2.0).abs() < 1e-15, "{sg}");
        for k in 0..=22 {
            let (v, _) = kronrod15(&|x: f64| x.powi(k), -1.0, 1.0);
            let exact = if k % 2 == 0 {
                2.0 / (k as f64 + 1.0)
            } else {
                0.0
            };
            assert!((v - exact).abs() < 1e-14, "k = {k}: {v} vs {exact}");
        }
        // Degree 24 is not exact: the test can tell a wrong node from a right one.
        let (v, _) = kronrod15(&|x: f64| x.powi(24), -1.0, 1.0);
        assert!((v - 2.0 / 25.0).abs() > 1e-12);
    }

    #[test]
    fn adaptive_rule_reaches_tolerance_on_peaked_integrand() {
        // ∫_0^10 exp(-x) dx and ∫_{-5}^{5} 1/(1+100x²) dx = (2/10) atan(50)
        let (v, _) = integrate(|x| (-x).exp(), 0.0, 10.0, 0.0, 1e-14);
        assert!((v - (1.0 - (-10.0f64).exp())).abs() < 1e-14);
        let (v, _) = integrate(|x| 1.0 / (1.0 + 100.0 * x * x), -5.0, 5.0, 0.0, 1e-13);
        assert!((v - 0.2 * 50f64.atan()).abs() < 1e-13, "{v}");
    }
}
