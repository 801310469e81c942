//! Summit-height distributions and their integrals $F_n(h)$ (Greenwood and Williamson
//! 1966), shared by the Greenwood-Williamson and Greenwood-Tripp models.
//!
//! # Formulas
//! With the summit heights $z$ measured in units of their standard deviation $\sigma_s$
//! and the probability density $\phi^*(s)$ of $s = z/\sigma_s$,
//!
//! $$F_n(h) = \int_h^\infty (s-h)^n\,\phi^*(s)\,ds .$$
//!
//! - **Gaussian**, $\phi^*(s) = e^{-s^2/2}/\sqrt{2\pi}$: no closed form for
//!   half-integer $n$; evaluated by adaptive Gauss-Kronrod quadrature after the
//!   substitution $s = h + t^2$, which makes the integrand $2t^{2n+1}\phi^*(h+t^2)$ smooth
//!   for every $n \ge -\tfrac12$. (Closed forms for integer $n$, e.g.
//!   $F_0 = \tfrac12\operatorname{erfc}(h/\sqrt2)$, are the tests' independent check.)
//! - **Exponential**, $\phi^*(s) = e^{-s}$ for $s \ge 0$ (mean and standard deviation 1,
//!   heights measured from the lowest summit): $F_n(h) = \Gamma(n+1)\,e^{-h}$ for
//!   $h \ge 0$ (closed form), and $F_n(h) = \int_0^\infty (u-h)^n e^{-u}\,du$ by
//!   quadrature for $h < 0$, where every summit touches.
//!
//! Both satisfy $dF_n/dh = -n F_{n-1}$.
//!
//! # Reference
//! Greenwood and Williamson (1966), "Contact of nominally flat surfaces", Proc. R. Soc.
//! Lond. A 295, 300-319, eqs (3)-(8). doi:10.1098/rspa.1966.0242

use super::quadrature::integrate;
use crate::error::{Error, Result};
use std::f64::consts::PI;
use std::sync::OnceLock;

/// The distribution of summit heights about their mean plane (Gaussian) or above the
/// lowest summit (exponential), in units of the summit-height standard deviation.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
#[cfg_attr(
    feature = "serde",
    derive(serde::Serialize, serde::Deserialize, schemars::JsonSchema)
)]
#[cfg_attr(feature = "serde", serde(rename_all = "snake_case"))]
pub enum SummitHeights {
    /// $\phi^*(s) = e^{-s^2/2}/\sqrt{2\pi}$; separation measured from the mean summit
    /// plane.
    Gaussian,
    /// $\phi^*(s) = e^{-s}$, $s \ge 0$; separation measured from the lowest summit. GW
    /// (1966) use it as a model of the upper tail, where it gives closed forms.
    Exponential,
}

/// Largest standardised separation at which a Gaussian $F_n$ is evaluated; beyond it
/// $F_n < 10^{-300}$ and 0 is returned.
const GAUSS_H_MAX: f64 = 38.0;

/// Relative tolerance of the quadratures.
const REL_TOL: f64 = 1e-13;

/// $\Gamma(n+1)$ for $n = k/2$, $k \ge -1$, by the recurrence from $\Gamma(1) = 1$ and
/// $\Gamma(\tfrac12) = \sqrt\pi$.
fn gamma_half_integer(n: f64) -> f64 {
    let mut x = n + 1.0; // Γ(x)
    let mut g = 1.0;
    while x > 1.25 {
        x -= 1.0;
        g *= x;
    }
    if (x - 0.5).abs() < 0.25 {
        g * PI.sqrt()
    } else {
        g
    }
}

/// Check the order `n`: a multiple of 1/2 in [0, 4].
fn check_order(n: f64) -> Result<f64> {
    if n.is_finite() && (0.0..=4.0).contains(&n) && (2.0 * n).fract() == 0.0 {
        Ok(n)
    } else {
        Err(Error::invalid(
            "order",
            n,
            "a multiple of 1/2 in [0, 4] (GW use 0, 1 and 3/2)",
        ))
    }
}

/// $F_n(h)$ for the given distribution: the integral of $(s-h)^n$ over the summits
/// above the standardised separation $h = d/\sigma_s$ \[dimensionless\].
///
/// $F_0$ is the fraction of summits in contact, $F_1$ and $F_{3/2}$ give the real area
/// and the load (see [`GreenwoodWilliamson`](super::GreenwoodWilliamson)).
///
/// # Errors
/// [`Error::InvalidInput`] for `order` not a multiple of 1/2 in \[0, 4\] (field `order`)
/// or a non-finite `h` (field `separation`).
///
/// # Example
/// ```
/// use kontakt::rough::{SummitHeights, height_integral};
/// // Gaussian F_0(0) = 1/2: half the summits stand above their mean plane.
/// let f0 = height_integral(SummitHeights::Gaussian, 0.0, 0.0)?;
/// assert!((f0 - 0.5).abs() < 1e-14);
/// // exponential, closed form F_n(h) = Γ(n+1) e^{-h}
/// let f = height_integral(SummitHeights::Exponential, 1.5, 2.0)?;
/// assert!((f - 0.75 * std::f64::consts::PI.sqrt() * (-2.0f64).exp()).abs() < 1e-15);
/// # Ok::<(), kontakt::Error>(())
/// ```
pub fn height_integral(heights: SummitHeights, order: f64, h: f64) -> Result<f64> {
    let n = check_order(order)?;
    if !h.is_finite() {
        return Err(Error::invalid(
            "separation",
            h,
            "a finite standardised separation d/σ_s",
        ));
    }
    Ok(match heights {
        SummitHeights::Gaussian => gaussian_quadrature(n, h),
        SummitHeights::Exponential => {
            if h >= 0.0 {
                exponential_closed_form(n, h)
            } else {
                exponential_quadrature(n, h)
            }
        }
    })
}

/// $F_n(h)$ by quadrature for either distribution and any $h$: the reference path the
/// tests compare the exponential closed form with (slower than [`height_integral`], which
/// it otherwise equals).
///
/// # Errors
/// As [`height_integral`].
pub fn height_integral_quadrature(heights: SummitHeights, order: f64, h: f64) -> Result<f64> {
    let n = check_order(order)?;
    if !h.is_finite() {
        return Err(Error::invalid(
            "separation",
            h,
            "a finite standardised separation d/σ_s",
        ));
    }
    Ok(match heights {
        SummitHeights::Gaussian => gaussian_quadrature(n, h),
        SummitHeights::Exponential => exponential_quadrature(n, h),
    })
}

/// Exponential heights, $h \ge 0$: $\Gamma(n+1)\,e^{-h}$.
pub(crate) fn exponential_closed_form(n: f64, h: f64) -> f64 {
    gamma_half_integer(n) * (-h).exp()
}

/// Exponential heights by quadrature, any $h$: $\int_{\max(0,h)}^\infty (u-h)^n e^{-u}du$
/// (the tests compare it with the closed form for $h \ge 0$).
pub(crate) fn exponential_quadrature(n: f64, h: f64) -> f64 {
    let lo = h.max(0.0);
    // e^{-u} below 1e-35 of its value at lo beyond lo + 80 (the polynomial factor grows
    // far slower); the integral is split at lo + 20 to help the adaptive rule.
    let f = |u: f64| (u - h).max(0.0).powf(n) * (-(u - lo)).exp();
    let (a, _) = integrate(f, lo, lo + 20.0, 0.0, REL_TOL);
    let (b, _) = integrate(f, lo + 20.0, lo + 100.0, 0.0, REL_TOL);
    (a + b) * (-lo).exp()
}

/// Gaussian heights by quadrature, $n \ge -\tfrac12$: $\int_0^T 2t^{2n+1}\phi^*(h+t^2)dt$
/// with $h + T^2 = 38$ (where $\phi^*$ has fallen below $10^{-300}$).
pub(crate) fn gaussian_quadrature(n: f64, h: f64) -> f64 {
    if h >= GAUSS_H_MAX {
        return 0.0;
    }
    let c = 2.0 / (2.0 * PI).sqrt();
    let f = |t: f64| {
        let s = h + t * t;
        c * t.powf(2.0 * n + 1.0) * (-0.5 * s * s).exp()
    };
    let t_max = (GAUSS_H_MAX - h).sqrt();
    // Split where the integrand lives: near t = sqrt(-h) for h < 0, within ~ 1/sqrt(h)
    // of 0 for h > 0.
    let knee = if h < 0.0 {
        (-h).sqrt() + 2.0
    } else {
        (4.0 / (h + 1.0)).sqrt()
    }
    .min(t_max);
    let (a, _) = integrate(f, 0.0, knee, 1e-300, REL_TOL);
    let (b, _) = integrate(f, knee, t_max, 1e-300, REL_TOL);
    a + b
}

/// Gaussian $F_n(h)$ for $h \le -10$ (the flat far below the mean summit plane):
/// $F_n(h) = E[(s-h)^n] = |h|^n\sum_k \binom{n}{2k}(2k-1)!!\,h^{-2k}$ up to $k = 5$
/// (the part of the distribution below $h$, $\sim e^{-50}$, is neglected; the series is
/// asymptotic, its first omitted term below 1e-11 relative at $|h| = 10$). Unit tested
/// against the quadrature.
pub(crate) fn gaussian_far_below(n: f64, h: f64) -> f64 {
    let x = 1.0 / (h * h);
    let mut binom = 1.0; // C(n, 2k)
    let mut dfact = 1.0; // (2k-1)!!
    let mut xk = 1.0;
    let mut sum = 1.0;
    for k in 1..=5 {
        let j = 2.0 * k as f64;
        binom *= (n - j + 2.0) * (n - j + 1.0) / ((j - 1.0) * j);
        dfact *= j - 1.0;
        xk *= x;
        sum += binom * dfact * xk;
    }
    (-h).powf(n) * sum
}

/// Tabulated Gaussian $\ln F_{3/2}$, $\ln F_{1/2}$ for the Greenwood-Tripp iteration,
/// which needs thousands of evaluations per solve: cubic Hermite interpolation of
/// $\ln F_n$ with the exact slopes $-nF_{n-1}/F_n$, on a step of 1/64 (interpolation
/// error below 1e-9 relative, unit tested against the quadrature).
pub(crate) struct GaussTable {
    /// $\ln F_{3/2}$, $\ln F_{1/2}$ at the nodes.
    ln_f: [Vec<f64>; 2],
    /// Their slopes times the step, $-nF_{n-1}/F_n\cdot\Delta h$, at the nodes.
    slope: [Vec<f64>; 2],
}

/// Range and step of [`GaussTable`].
const TABLE_H_MIN: f64 = -10.0;
const TABLE_STEP: f64 = 1.0 / 64.0;
const TABLE_NODES: usize = ((GAUSS_H_MAX - TABLE_H_MIN) * 64.0) as usize + 1;

impl GaussTable {
    /// The table, built on first use (about 10 ms) and shared.
    pub(crate) fn get() -> &'static GaussTable {
        static TABLE: OnceLock<GaussTable> = OnceLock::new();
        TABLE.get_or_init(|| {
            let mut ln_f = [
                Vec::with_capacity(TABLE_NODES),
                Vec::with_capacity(TABLE_NODES),
                Vec::with_capacity(TABLE_NODES),
            ];
            for i in 0..TABLE_NODES {
                let h = TABLE_H_MIN + i as f64 * TABLE_STEP;
                for (k, n) in [1.5, 0.5, -0.5].into_iter().enumerate() {
                    // Beyond ~37.5 F underflows; clamp the logarithm to stay finite.
                    let f = gaussian_quadrature(n, h.min(GAUSS_H_MAX - 1.0)).max(1e-300);
                    ln_f[k].push(f.ln());
                }
            }
            let slope = [
                (0..TABLE_NODES)
                    .map(|j| -1.5 * (ln_f[1][j] - ln_f[0][j]).exp() * TABLE_STEP)
                    .collect(),
                (0..TABLE_NODES)
                    .map(|j| -0.5 * (ln_f[2][j] - ln_f[1][j]).exp() * TABLE_STEP)
                    .collect(),
            ];
            let [l32, l12, _] = ln_f;
            GaussTable {
                ln_f: [l32, l12],
                slope,
            }
        })
    }

    /// Node index and fraction of `h` (inside the table).
    fn locate(h: f64) -> (usize, f64) {
        let x = (h - TABLE_H_MIN) / TABLE_STEP;
        let i = (x.floor() as usize).min(TABLE_NODES - 2);
        (i, x - i as f64)
    }

    /// Cubic Hermite interpolation of table `k` at node `i`, fraction `t`.
    fn hermite(&self, k: usize, i: usize, t: f64) -> f64 {
        let (y, m) = (&self.ln_f[k], &self.slope[k]);
        let t2 = t * t;
        let t3 = t2 * t;
        ((2.0 * t3 - 3.0 * t2 + 1.0) * y[i]
            + (t3 - 2.0 * t2 + t) * m[i]
            + (-2.0 * t3 + 3.0 * t2) * y[i + 1]
            + (t3 - t2) * m[i + 1])
            .exp()
    }

    /// $F_{3/2}(h)$, Gaussian heights.
    pub(crate) fn f32(&self, h: f64) -> f64 {
        if h >= GAUSS_H_MAX - 1.0 {
            return 0.0;
        }
        if h < TABLE_H_MIN {
            return gaussian_far_below(1.5, h);
        }
        let (i, t) = Self::locate(h);
        self.hermite(0, i, t)
    }

    /// $(F_{3/2}(h), F_{1/2}(h))$, Gaussian heights.
    pub(crate) fn f32_f12(&self, h: f64) -> (f64, f64) {
        if h >= GAUSS_H_MAX - 1.0 {
            return (0.0, 0.0);
        }
        if h < TABLE_H_MIN {
            return (gaussian_far_below(1.5, h), gaussian_far_below(0.5, h));
        }
        let (i, t) = Self::locate(h);
        (self.hermite(0, i, t), self.hermite(1, i, t))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn gamma_of_half_integers() {
        assert_eq!(gamma_half_integer(0.0), 1.0);
        assert_eq!(gamma_half_integer(1.0), 1.0);
        assert_eq!(gamma_half_integer(2.0), 2.0);
        assert!((gamma_half_integer(0.5) - 0.5 * PI.sqrt()).abs() < 1e-15);
        assert!((gamma_half_integer(1.5) - 0.75 * PI.sqrt()).abs() < 1e-15);
        assert!((gamma_half_integer(-0.5) - PI.sqrt()).abs() < 1e-15);
    }

    #[test]
    fn table_matches_quadrature() {
        let t = GaussTable::get();
        let mut worst: f64 = 0.0;
        for k in 0..2000 {
            let h = -9.99 + k as f64 * 0.0231;
            let (a, b) = t.f32_f12(h);
            let qa = gaussian_quadrature(1.5, h);
            let qb = gaussian_quadrature(0.5, h);
            worst = worst.max(((a - qa) / qa).abs()).max(((b - qb) / qb).abs());
        }
        assert!(worst < 1e-9, "worst relative error {worst:e}");
    }

    #[test]
    fn far_below_series_matches_quadrature() {
        for h in [-10.0, -12.5, -20.0, -100.0] {
            for n in [0.5, 1.0, 1.5, 2.0] {
                let a = gaussian_far_below(n, h);
                let q = gaussian_quadrature(n, h);
                assert!(((a - q) / q).abs() < 1e-10, "n {n} h {h}: {a} vs {q}");
            }
        }
        // and it joins the table at its lower end
        let (t, _) = GaussTable::get().f32_f12(-10.0 + 1e-12);
        assert!(((t - gaussian_far_below(1.5, -10.0)) / t).abs() < 1e-9);
    }

    #[test]
    fn derivative_identity_holds() {
        // dF_n/dh = -n F_{n-1}, central difference
        for h in [-3.0, -0.5, 0.0, 0.7, 2.5, 5.0] {
            for n in [1.0, 1.5, 2.0] {
                let e = 1e-4;
                let d = (gaussian_quadrature(n, h + e) - gaussian_quadrature(n, h - e)) / (2.0 * e);
                let r = -n * gaussian_quadrature(n - 1.0, h);
                assert!(((d - r) / r).abs() < 1e-7, "n {n} h {h}: {d} vs {r}");
            }
        }
    }
}
