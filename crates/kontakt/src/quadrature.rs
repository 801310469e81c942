//! Gauss-Legendre quadrature: the nodes and weights that the friction integral over the
//! Hertz ellipse (`friction::ellipse`), the load-zone integrals of `kontakt-bearing` and the
//! tests share.
//!
//! The nodes are the roots of the Legendre polynomial `P_n`, found by Newton's method on the
//! three-term recurrence `k P_k = (2k − 1) x P_{k−1} − (k − 1) P_{k−2}` from the classical
//! start `cos(π (i + 3/4)/(n + 1/2))`; the weights are `2 / ((1 − x²) P_n'(x)²)`
//! (Abramowitz & Stegun 1964, 25.4.29). No table to mistype. An `n`-point rule integrates
//! polynomials of degree up to `2n − 1` exactly (tested).

/// The `n` Gauss-Legendre nodes and weights `(x, w)` on [−1, 1], nodes in descending order.
/// `n = 0` gives an empty rule.
pub fn gauss_legendre(n: usize) -> Vec<(f64, f64)> {
    let mut out = Vec::with_capacity(n);
    for i in 0..n {
        let mut x = (std::f64::consts::PI * (i as f64 + 0.75) / (n as f64 + 0.5)).cos();
        let mut dp = 1.0;
        for _ in 0..100 {
            let (mut p0, mut p1) = (1.0, x);
            for k in 2..=n {
                let k = k as f64;
                let p2 = ((2.0 * k - 1.0) * x * p1 - (k - 1.0) * p0) / k;
                p0 = p1;
                p1 = p2;
            }
            dp = n as f64 * (x * p1 - p0) / (x * x - 1.0);
            let step = p1 / dp;
            x -= step;
            if step.abs() < 1e-16 {
                break;
            }
        }
        out.push((x, 2.0 / ((1.0 - x * x) * dp * dp)));
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    /// An n-point rule integrates x^k exactly for k <= 2n − 1 (∫ x^k over [−1, 1] is
    /// 2/(k + 1) for even k, 0 for odd k), and misses x^(2n) by exactly the Gauss remainder
    /// 2^(2n+1) (n!)^4 / ((2n + 1) ((2n)!)^2) (A&S 25.4.29 with f^(2n) = (2n)!).
    #[test]
    fn exact_to_degree_two_n_minus_one() {
        for n in 1..=20 {
            let rule = gauss_legendre(n);
            assert_eq!(rule.len(), n);
            for k in 0..=(2 * n) {
                let q: f64 = rule.iter().map(|(x, w)| w * x.powi(k as i32)).sum();
                let exact = if k % 2 == 0 {
                    2.0 / (k as f64 + 1.0)
                } else {
                    0.0
                };
                if k < 2 * n {
                    assert!((q - exact).abs() < 1e-14, "n {n}, k {k}: {q} vs {exact}");
                } else {
                    let fact = |m: usize| (1..=m).map(|i| i as f64).product::<f64>();
                    let rem = 2f64.powi(2 * n as i32 + 1) * fact(n).powi(4)
                        / ((2 * n + 1) as f64 * fact(2 * n).powi(2));
                    let miss = exact - q;
                    assert!(
                        (miss - rem).abs() < 1e-14 + 1e-9 * rem,
                        "n {n}: x^{k} missed by {miss}, remainder {rem}"
                    );
                }
            }
        }
        assert!(gauss_legendre(0).is_empty());
    }
}
