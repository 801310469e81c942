//! Complete elliptic integrals in Carlson's symmetric form, as used by the exact Hertz
//! solution.
//!
//! With the complementary modulus $k' = b/a$ and $y = k'^2$, Legendre's integrals are
//! $K = R_F(0, y, 1)$ and $E = R_F(0,y,1) - \tfrac{m}{3}R_D(0,y,1)$ with $m = 1 - y$
//! (DLMF 19.25.1). Hertz' equations (Johnson 1982 eq. 56) only need
//!
//! - $K - E = \tfrac{m}{3} R_D$,
//! - $(a/b)^2 E - K = \tfrac{m}{y}\,(R_F - R_D/3)$,
//!
//! so the factor $m = e^2$ cancels and the shape equation (57) becomes
//! $B/A = (3R_F - R_D)/(y\,R_D)$: free of cancellation from the circle ($y = 1$) to
//! extremely thin ellipses. The integrals themselves come from `ellip` (about 1 ulp).

use crate::error::{Error, Result};
use std::f64::consts::PI;

/// $R_F(0, y, 1)$ and $R_D(0, y, 1)$ for $y = (b/a)^2 \in (0, 1]$.
///
/// At $y = 1$ the exact values $\pi/2$ and $3\pi/4$ are returned, so that the circular
/// contact falls out of the general solution exactly.
pub(crate) fn rf_rd(y: f64) -> Result<(f64, f64)> {
    if y == 1.0 {
        return Ok((0.5 * PI, 0.75 * PI));
    }
    let map = |what: &'static str| {
        move |msg: &'static str| Error::invalid(what, format!("y = {y} ({msg})"), "0 < y <= 1")
    };
    let rf = ellip::elliprf(0.0, y, 1.0).map_err(map("elliprf"))?;
    let rd = ellip::elliprd(0.0, y, 1.0).map_err(map("elliprd"))?;
    Ok((rf, rd))
}

/// The Hertz shape function $B/A = (3R_F - R_D)/(y R_D)$ of $y = (b/a)^2$ (Johnson 1982
/// eq. 57 in Carlson form). Strictly decreasing from $+\infty$ at $y \to 0$ to 1 at $y = 1$.
pub(crate) fn shape_ratio(y: f64) -> Result<f64> {
    let (rf, rd) = rf_rd(y)?;
    Ok((3.0 * rf - rd) / (y * rd))
}

/// The cold start of [`invert_shape_ratio_near`] (the tests' reference).
#[cfg(test)]
pub(crate) fn invert_shape_ratio(ratio: f64) -> Result<Inversion> {
    invert_shape_ratio_near(ratio, None)
}

/// Solve the shape equation $B/A = $ `ratio` for $k' = b/a \in (0, 1]$.
///
/// Safeguarded secant iteration on $u = \ln k'$, where $\ln(B/A)$ is nearly linear
/// (slope between -1 and about -2), started from Hamrock and Brewe's fit
/// $a/b \approx 1.0339\,(B/A)^{0.636}$. Converges to machine precision in 4-6 evaluations.
///
/// Warm start: `previous = (ratio, k')`, the root of a nearby ratio, whose residual for
/// this ratio is `ln(previous ratio / ratio)` without an evaluation, so the secant starts
/// from two points after one evaluation (3 evaluations on average for changes up to 1 %,
/// against 4.3 cold). The same root to 1e-14 (tested).
///
/// Returns the root, the number of function evaluations and $(R_F, R_D)$ at the root.
pub(crate) fn invert_shape_ratio_near(
    ratio: f64,
    previous: Option<(f64, f64)>,
) -> Result<Inversion> {
    if !(ratio.is_finite() && ratio >= 1.0) {
        return Err(Error::invalid("B/A", ratio, "a finite ratio >= 1"));
    }
    if ratio <= 1.0 + 4.0 * f64::EPSILON {
        return Ok(Inversion {
            axis_ratio: 1.0,
            evaluations: 0,
            rf_rd: rf_rd(1.0)?,
            slope: None,
            series: None,
        });
    }
    let target = ratio.ln();
    // The last (R_F, R_D) evaluated, so that the caller does not evaluate them again.
    let mut last = (0.0, 0.0, 0.0);
    let mut g = |u: f64| -> Result<f64> {
        let y = (2.0 * u).exp();
        let (rf, rd) = rf_rd(y)?;
        last = (u, rf, rd);
        Ok(((3.0 * rf - rd) / (y * rd)).ln() - target)
    };
    // Bracket: g(0) = -ln(ratio) < 0; g decreases in u. The lower end must have g > 0.
    let mut hi = 0.0_f64;
    let mut g_hi = -target;
    // Initial guess: Hamrock & Brewe's fit for moderate ratios; for thin ellipses the
    // asymptote B/A ≈ 1/(y (ln(4/k') - 1)) (from K → ln(4/k'), E → 1), iterated as a
    // fixed point. Clamped into the admissible range.
    let mut u0 = if ratio < 100.0 {
        -(1.0339_f64.ln() + 0.636 * target)
    } else {
        let mut kp = ratio.sqrt().recip();
        for _ in 0..3 {
            kp = (ratio * ((4.0 / kp).ln() - 1.0)).sqrt().recip();
        }
        kp.ln()
    };
    u0 = u0.min(-1e-9);
    // The warm start: the previous root, whose residual for this ratio is known.
    let warm = previous.and_then(|(r, kp)| {
        let u = kp.ln();
        (r.is_finite() && r > 1.0 + 4.0 * f64::EPSILON && u < 0.0 && u.is_finite() && r != ratio)
            .then(|| (u, r.ln() - target))
            .filter(|&(_, g)| g != 0.0)
    });
    let (mut g0, mut evals) = match warm {
        Some((u, g_known)) => {
            u0 = u;
            (g_known, 0)
        }
        None => (g(u0)?, 1),
    };
    let mut lo = f64::NEG_INFINITY;
    let mut g_lo = f64::NAN;
    if g0 > 0.0 {
        lo = u0;
        g_lo = g0;
    } else {
        hi = u0;
        g_hi = g0;
    }
    // Second point: a step along the local slope estimate of -2 (thin) .. -1 (round).
    let mut u1 = u0 + g0 / 1.6;
    if u1 >= 0.0 {
        u1 = 0.5 * u0;
    }
    let mut g1 = g(u1)?;
    evals += 1;
    for _ in 0..100 {
        if g1 > 0.0 {
            if u1 > lo {
                lo = u1;
                g_lo = g1;
            }
        } else if u1 < hi {
            hi = u1;
            g_hi = g1;
        }
        if g1 == 0.0 {
            return finish(u1, evals, last);
        }
        let slope = (g1 - g0) / (u1 - u0);
        let mut u2 = u1 - g1 / slope;
        // Safeguard: stay inside the bracket; bisect (or expand) otherwise.
        if !(u2.is_finite() && u2 < hi && (lo == f64::NEG_INFINITY || u2 > lo)) {
            u2 = if lo.is_finite() {
                // Regula falsi step inside the bracket.
                lo - g_lo * (hi - lo) / (g_hi - g_lo)
            } else {
                hi - 2.0 * (hi - u1).abs().max(1.0)
            };
        }
        if (u2 - u1).abs() <= 4.0 * f64::EPSILON * u1.abs().max(1e-300) {
            return finish(u2, evals, last);
        }
        u0 = u1;
        g0 = g1;
        u1 = u2;
        g1 = g(u1)?;
        evals += 1;
        if g1.abs() <= 2.0 * f64::EPSILON * target.abs().max(1.0) {
            return finish(u1, evals, last);
        }
    }
    Err(Error::NotConverged {
        what: "Hertz eccentricity inversion (Johnson 1982 eq. 57)".into(),
        iterations: evals,
        residual: g1.abs(),
    })
}

/// The slopes $dR_F/dy$ and $dR_D/dy$ of $R_F(0, y, 1)$ and $R_D(0, y, 1)$ from their
/// values, through Legendre's $K = R_F$, $E = R_F - \tfrac{m}{3}R_D$, $m = 1 - y$ and
/// DLMF 19.4.1: $dK/dm = (E - yK)/(2my)$, $dE/dm = (E - K)/(2m) = -R_D/6$, and from
/// $R_D = 3(K - E)/m$: $dR_D/dm = (3\,dK/dm - R_D/2)/m$. Both lose about
/// $\epsilon/m^2$ relative to cancellation near the circle; [`invert_shape_ratio_newton`]
/// uses them only for $m \ge 10^{-3}$ and only to move a root by $10^{-8}$ of itself.
pub(crate) fn rf_rd_slopes(y: f64, rf: f64, rd: f64) -> (f64, f64) {
    let m = 1.0 - y;
    let e = rf - m * rd / 3.0;
    let dk_dm = (e - y * rf) / (2.0 * m * y);
    let drd_dm = (3.0 * dk_dm - 0.5 * rd) / m;
    (-dk_dm, -drd_dm)
}

/// $d(B/A)/dy$ of the shape function $S(y) = (3R_F - R_D)/(y R_D) = 3R_F/(yR_D) - 1/y$
/// at $y$ with $(R_F, R_D)$ there (NaN at the circle, where it is not needed).
pub(crate) fn shape_slope(y: f64, rf: f64, rd: f64) -> f64 {
    let (drf, drd) = rf_rd_slopes(y, rf, rd);
    let q = y * rd;
    3.0 * (drf * q - rf * (rd + y * drd)) / (q * q) + 1.0 / (y * y)
}

/// Taylor coefficients kept of [`ShapeSeries`] (orders 0 to 5).
const SERIES_TERMS: usize = 6;

/// $R_F(0, y, 1)$ and $R_D(0, y, 1)$ as Taylor series about a point $y_a$ where they were
/// evaluated exactly, for the warm shape inversion of a contact element: a call then
/// evaluates two polynomials instead of Carlson's iterations.
///
/// In $m = 1 - y$ the pair $K = R_F$, $D = R_D$ solves the linear system (from
/// [`rf_rd_slopes`]) $2(1-m)K' = K - D/3$ and $2m(1-m)D' = 3K - (2-m)D$. With
/// $m = m_a + h$, $K = \sum k_n h^n$, $D = \sum d_n h^n$, matching powers of $h$ gives
/// the coefficients from the values $k_0 = R_F$, $d_0 = R_D$ alone:
/// $$k_{n+1} = \frac{(2n+1)k_n - d_n/3}{2(1-m_a)(n+1)}, \qquad
///   d_{n+1} = \frac{3k_n - [2 - m_a + 2n(1-2m_a)]\,d_n + (2n-1)\,d_{n-1}}
///                  {2m_a(1-m_a)(n+1)}.$$
/// Both functions are analytic in $|h| < 1 - m_a = y_a$ (the logarithmic singularity at
/// $y = 0$; at the circle $m = 0$ they are regular, but the recursion divides by $m_a$).
/// The series is used for $|h| \le 10^{-3}\min(y_a, m_a)$: the first term dropped is
/// then about $10^{-18}$ relative, and the rounding of the coefficients, amplified by
/// $1/m_a$ per order, is scaled back by $h^n$. Within 4 ulps of `ellip`'s values (tested
/// over 5000 random anchors).
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct ShapeSeries {
    /// $y_a$.
    y: f64,
    /// Largest $|y - y_a|$ served.
    reach: f64,
    k: [f64; SERIES_TERMS],
    d: [f64; SERIES_TERMS],
}

impl ShapeSeries {
    /// The series about `y` from $(R_F, R_D)$ there; `None` outside $0 < y < 1$.
    pub(crate) fn new(y: f64, rf: f64, rd: f64) -> Option<Self> {
        let m = 1.0 - y;
        if !(y > 0.0 && m > 0.0 && rf.is_finite() && rd.is_finite()) {
            return None;
        }
        let (inv_k, inv_d) = (1.0 / (2.0 * y), 1.0 / (2.0 * m * y));
        let (mut k, mut d) = ([rf; SERIES_TERMS], [rd; SERIES_TERMS]);
        let mut d_before = 0.0;
        for n in 0..SERIES_TERMS - 1 {
            let nf = n as f64;
            let scale = 1.0 / (nf + 1.0);
            k[n + 1] = ((2.0 * nf + 1.0) * k[n] - d[n] / 3.0) * inv_k * scale;
            d[n + 1] = (3.0 * k[n] - (2.0 - m + 2.0 * nf * (1.0 - 2.0 * m)) * d[n]
                + (2.0 * nf - 1.0) * d_before)
                * inv_d
                * scale;
            d_before = d[n];
        }
        Some(ShapeSeries {
            y,
            reach: 1e-3 * y.min(m),
            k,
            d,
        })
    }

    /// $(R_F, R_D)$ and their slopes $(dR_F/dy, dR_D/dy)$ at `y`, or `None` beyond reach.
    pub(crate) fn at(&self, y: f64) -> Option<((f64, f64), (f64, f64))> {
        let h = self.y - y;
        if !(h.abs() <= self.reach) {
            return None;
        }
        let horner = |c: &[f64; SERIES_TERMS]| {
            let (mut v, mut dv) = (c[SERIES_TERMS - 1], 0.0);
            for &cn in c[..SERIES_TERMS - 1].iter().rev() {
                dv = dv * h + v;
                v = v * h + cn;
            }
            (v, -dv) // d/dy = -d/dh
        };
        let ((rf, drf), (rd, drd)) = (horner(&self.k), horner(&self.d));
        Some(((rf, rd), (drf, drd)))
    }
}

/// Largest $y = (b/a)^2$ of [`invert_shape_ratio_newton`]: nearer the circle the slopes
/// of [`rf_rd_slopes`] cancel.
const NEWTON_Y_MAX: f64 = 0.999;

/// The root of the shape equation for `ratio` by one evaluation of the elliptic integrals,
/// from the root `previous = (ratio, y, slope)` of a nearby ratio (a contact element's
/// last call): the tangent predicts $y_1$, one evaluation there gives $S(y_1)$ and the
/// exact slope, a Newton step moves to $y_2$, and $(R_F, R_D)$ follow to $y_2$ along their
/// slopes. Accepted only where that is exact to rounding: the Newton step at most
/// $10^{-8} y_1$ (the neglected terms are then of order $10^{-16}$ relative) and
/// $y \le 0.999$; otherwise `None`, and the caller takes the safeguarded
/// [`invert_shape_ratio_near`].
pub(crate) fn invert_shape_ratio_newton(
    ratio: f64,
    previous: (f64, f64, f64),
    series: Option<&ShapeSeries>,
) -> Option<Inversion> {
    let (r0, y0, slope0) = previous;
    if !(ratio.is_finite() && ratio > 1.0 && y0 > 0.0 && y0 <= NEWTON_Y_MAX) {
        return None;
    }
    let y1 = y0 + (ratio - r0) / slope0;
    if !(y1 > 0.0 && y1 <= NEWTON_Y_MAX) {
        return None;
    }
    // The integrals at y1 from the last exact evaluation's series when in reach, else
    // evaluated (and the series moves there).
    let (series, ((rf, rd), (drf, drd))) = match series.and_then(|s| Some((*s, s.at(y1)?))) {
        Some(hit) => hit,
        None => {
            let (rf, rd) = rf_rd(y1).ok()?;
            (
                ShapeSeries::new(y1, rf, rd)?,
                ((rf, rd), rf_rd_slopes(y1, rf, rd)),
            )
        }
    };
    let s1 = (3.0 * rf - rd) / (y1 * rd);
    let q = y1 * rd;
    let slope = 3.0 * (drf * q - rf * (rd + y1 * drd)) / (q * q) + 1.0 / (y1 * y1);
    let dy = -(s1 - ratio) / slope;
    if !(dy.abs() <= 1e-8 * y1) {
        return None;
    }
    let y = y1 + dy;
    Some(Inversion {
        axis_ratio: y.sqrt(),
        evaluations: 1,
        rf_rd: (rf + drf * dy, rd + drd * dy),
        // At y1, within 1e-8 of the slope at y: a predictor's slope for the next call.
        slope: Some(slope),
        series: Some(series),
    })
}

/// Result of [`invert_shape_ratio_near`].
pub(crate) struct Inversion {
    /// b/a.
    pub axis_ratio: f64,
    /// Shape-function evaluations used.
    pub evaluations: usize,
    /// $(R_F, R_D)$ at $y = (b/a)^2$.
    pub rf_rd: (f64, f64),
    /// $d(B/A)/dy$ near the root (relative 1e-8) when the inversion took it, for the next
    /// inversion's predictor ([`invert_shape_ratio_newton`]); else `None`.
    pub slope: Option<f64>,
    /// The series of the integrals about the last exact evaluation, when the inversion
    /// kept one ([`invert_shape_ratio_newton`]); else `None`.
    pub series: Option<ShapeSeries>,
}

/// Package the root; reuse the last evaluation when it was taken at the root itself
/// (the secant step that converged moved u by at most a few ulps, which changes R_F and
/// R_D by far less than their own rounding; otherwise evaluate once more).
fn finish(u: f64, evaluations: usize, last: (f64, f64, f64)) -> Result<Inversion> {
    let rf_rd = if last.0 == u {
        (last.1, last.2)
    } else {
        rf_rd((2.0 * u).exp())?
    };
    Ok(Inversion {
        axis_ratio: u.exp(),
        evaluations,
        rf_rd,
        slope: None,
        series: None,
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use approx::assert_relative_eq;

    #[test]
    fn legendre_identities() {
        // K and E from Carlson agree with ellip's Legendre forms. Legendre's form takes
        // m = 1 - k'^2, which rounds away the information in a small k': at k' = 1e-3 the
        // Legendre value itself is only good to ~1e-11 (the reason we use Carlson's form).
        for &(kp, tol) in &[(0.9, 1e-14), (0.5, 1e-14), (0.1, 1e-14), (1e-3, 1e-10)] {
            let y: f64 = kp * kp;
            let m = 1.0 - y;
            let (rf, rd) = rf_rd(y).unwrap();
            assert_relative_eq!(rf, ellip::ellipk(m).unwrap(), max_relative = tol);
            assert_relative_eq!(
                rf - m / 3.0 * rd,
                ellip::ellipe(m).unwrap(),
                max_relative = tol
            );
        }
        assert_relative_eq!(shape_ratio(1.0).unwrap(), 1.0, max_relative = 1e-15);
        // Continuity of the exact y = 1 branch.
        assert_relative_eq!(shape_ratio(1.0 - 1e-12).unwrap(), 1.0, max_relative = 1e-11);
    }

    #[test]
    fn inversion_round_trips_over_the_range() {
        let mut max_evals = 0;
        for i in 0..=400 {
            let kp = 10f64.powf(-(i as f64) * 4.5 / 400.0);
            let r = shape_ratio(kp * kp).unwrap();
            let inv = invert_shape_ratio(r).unwrap();
            max_evals = max_evals.max(inv.evaluations);
            assert_relative_eq!(inv.axis_ratio, kp, max_relative = 2e-13);
            let (rf, rd) = rf_rd(inv.axis_ratio * inv.axis_ratio).unwrap();
            assert_relative_eq!(inv.rf_rd.0, rf, max_relative = 1e-14);
            assert_relative_eq!(inv.rf_rd.1, rd, max_relative = 1e-14);
        }
        assert!(max_evals <= 8, "max evaluations {max_evals}");
    }

    /// Warm starts from the root of a ratio 1e-8 to 30 % away, over k' from 1 to 3e-5: the
    /// same root as the cold start to 1e-14 relative (R_F, R_D too), in fewer evaluations
    /// on average for steps up to 1 % (measured: 3.0 against 4.3).
    #[test]
    fn warm_start_finds_the_same_root_in_fewer_evaluations() {
        let (mut warm_sum, mut cold_sum) = (0, 0);
        for i in 0..=90 {
            let kp = 10f64.powf(-(i as f64) * 4.5 / 90.0);
            let r0 = shape_ratio(kp * kp).unwrap();
            let prev = invert_shape_ratio(r0).unwrap();
            for step in [1e-8, 1e-6, 1e-4, 1e-2, -1e-2, 0.3] {
                let r = (r0 * (1.0 + step)).max(1.0 + 1e-6);
                let cold = invert_shape_ratio(r).unwrap();
                let warm = invert_shape_ratio_near(r, Some((r0, prev.axis_ratio))).unwrap();
                assert_relative_eq!(warm.axis_ratio, cold.axis_ratio, max_relative = 1e-14);
                assert_relative_eq!(warm.rf_rd.0, cold.rf_rd.0, max_relative = 1e-14);
                assert_relative_eq!(warm.rf_rd.1, cold.rf_rd.1, max_relative = 1e-14);
                if step.abs() <= 1e-2 && r0 > 1.0 + 1e-6 {
                    warm_sum += warm.evaluations;
                    cold_sum += cold.evaluations;
                }
            }
        }
        println!("evaluations in all: warm {warm_sum}, cold {cold_sum}");
        assert!(
            10 * warm_sum < 8 * cold_sum,
            "warm {warm_sum}, cold {cold_sum}"
        );
    }

    /// The slopes of R_F and R_D against central differences (h = 1e-6 y), and the shape
    /// function's slope likewise, over k' from 0.03 to 0.99: to 1e-8 relative.
    #[test]
    fn slopes_match_central_differences() {
        for i in 0..=40 {
            let kp: f64 = 0.03 + 0.96 * i as f64 / 40.0;
            let y = kp * kp;
            let h = 1e-6 * y;
            let (rf, rd) = rf_rd(y).unwrap();
            let (p, m) = (rf_rd(y + h).unwrap(), rf_rd(y - h).unwrap());
            let (drf, drd) = rf_rd_slopes(y, rf, rd);
            assert_relative_eq!(drf, (p.0 - m.0) / (2.0 * h), max_relative = 1e-8);
            assert_relative_eq!(drd, (p.1 - m.1) / (2.0 * h), max_relative = 1e-8);
            let ds = (shape_ratio(y + h).unwrap() - shape_ratio(y - h).unwrap()) / (2.0 * h);
            assert_relative_eq!(shape_slope(y, rf, rd), ds, max_relative = 1e-7);
        }
    }

    /// The one-evaluation Newton inversion against the cold inversion, from the root of a
    /// ratio 1e-9 to 1e-5 away (a contact element's step), over k' from 3e-4 to 0.99: the
    /// same b/a, R_F and R_D as the cold start to 1e-14 (the warm-start test's tolerance), a
    /// residual of the shape equation no larger than the cold root's (or within S's own
    /// rounding), and R_F, R_D those of the root to 1e-15, in one evaluation. Steps it
    /// cannot take exactly (1e-2, or the near-circle y > 0.999) return None.
    #[test]
    fn newton_inversion_is_exact_in_one_evaluation_or_declines() {
        let mut taken = 0;
        for i in 0..=80 {
            let kp = 10f64.powf(-3.5 + 3.5 * i as f64 / 80.0).min(0.99);
            let r0 = shape_ratio(kp * kp).unwrap();
            let prev = invert_shape_ratio(r0).unwrap();
            let y0 = prev.axis_ratio * prev.axis_ratio;
            let slope0 = shape_slope(y0, prev.rf_rd.0, prev.rf_rd.1);
            let series = ShapeSeries::new(y0, prev.rf_rd.0, prev.rf_rd.1).unwrap();
            for (step, series) in [1e-9, -1e-7, 1e-5, -1e-5]
                .into_iter()
                .flat_map(|step| [(step, None), (step, Some(&series))])
            {
                let r = r0 * (1.0 + step);
                let cold = invert_shape_ratio(r).unwrap();
                let Some(warm) = invert_shape_ratio_newton(r, (r0, y0, slope0), series) else {
                    panic!("k' {kp}, step {step}: declined");
                };
                taken += 1;
                assert_eq!(warm.evaluations, 1);
                assert_relative_eq!(warm.axis_ratio, cold.axis_ratio, max_relative = 1e-14);
                assert_relative_eq!(warm.rf_rd.0, cold.rf_rd.0, max_relative = 1e-14);
                assert_relative_eq!(warm.rf_rd.1, cold.rf_rd.1, max_relative = 1e-14);
                // As good a root as the cold one (whose secant stops at 4 ulps of ln k'), or
                // within the rounding of S itself (a few ulps; up to 14 at k' = 4e-4).
                let residual = |kp: f64| (shape_ratio(kp * kp).unwrap() / r - 1.0).abs();
                let (rw, rc) = (residual(warm.axis_ratio), residual(cold.axis_ratio));
                assert!(
                    rw <= rc.max(32.0 * f64::EPSILON),
                    "k' {kp}: {rw:e} vs {rc:e}"
                );
                // R_F and R_D carried along their slopes: those of the root to rounding.
                let (rf, rd) = rf_rd(warm.axis_ratio * warm.axis_ratio).unwrap();
                assert_relative_eq!(warm.rf_rd.0, rf, max_relative = 1e-15);
                assert_relative_eq!(warm.rf_rd.1, rd, max_relative = 1e-15);
            }
            assert!(invert_shape_ratio_newton(r0 * 1.01, (r0, y0, slope0), None).is_none());
        }
        assert!(taken > 600);
        // Near the circle the slopes cancel: declined.
        let r0 = shape_ratio(0.9995).unwrap();
        let prev = invert_shape_ratio(r0).unwrap();
        let y0 = prev.axis_ratio * prev.axis_ratio;
        let slope0 = shape_slope(y0, prev.rf_rd.0, prev.rf_rd.1);
        assert!(invert_shape_ratio_newton(r0 * (1.0 + 1e-9), (r0, y0, slope0), None).is_none());
    }

    /// The series of R_F and R_D about y_a against `ellip`'s values anywhere in its reach,
    /// for y_a from 1e-4 to 0.9999: values within 8 ulps (3.8 measured), slopes within 1e-13 of the
    /// closed form's (itself good to about ε/m², added to the tolerance); beyond its reach
    /// or at the circle there is no series.
    #[test]
    fn series_of_the_integrals_is_exact_in_its_reach() {
        let mut state = 3u64;
        let mut uniform = || {
            state = state
                .wrapping_mul(6364136223846793005)
                .wrapping_add(1442695040888963407);
            (state >> 11) as f64 / (1u64 << 53) as f64
        };
        let mut worst: f64 = 0.0;
        for _ in 0..5000 {
            let u = uniform();
            // Both ends: thin ellipses and near-circles.
            let ya = if u < 0.5 {
                10f64.powf(-4.0 + 8.0 * u)
            } else {
                1.0 - 10f64.powf(-4.0 + 8.0 * (u - 0.5))
            };
            let (rf, rd) = rf_rd(ya).unwrap();
            let s = ShapeSeries::new(ya, rf, rd).unwrap();
            let y = ya + s.reach * (2.0 * uniform() - 1.0);
            let ((sf, sd), (dsf, dsd)) = s.at(y).unwrap();
            let (ef, ed) = rf_rd(y).unwrap();
            let err = ((sf - ef) / ef).abs().max(((sd - ed) / ed).abs());
            worst = worst.max(err);
            // Both ends carry `ellip`'s own rounding (about 1-2 ulps each).
            assert!(err <= 8.0 * f64::EPSILON, "y_a {ya:e}, y {y:e}: {err:e}");
            let (cf, cd) = rf_rd_slopes(y, ef, ed);
            let m = 1.0 - y;
            let tol = 1e-13 + 4.0 * f64::EPSILON / (m * m);
            assert_relative_eq!(dsf, cf, max_relative = tol);
            assert_relative_eq!(dsd, cd, max_relative = tol);
            assert!(s.at(ya + 1.01 * s.reach).is_none() && s.at(ya - 1.01 * s.reach).is_none());
        }
        assert!(worst > 0.0, "the comparison ran");
        assert!(ShapeSeries::new(1.0, 0.5 * PI, 0.75 * PI).is_none());
        assert!(ShapeSeries::new(0.0, f64::INFINITY, f64::INFINITY).is_none());
    }

    #[test]
    fn rejects_bad_ratio() {
        assert!(invert_shape_ratio(0.5).is_err());
        assert!(invert_shape_ratio(f64::NAN).is_err());
        assert!(invert_shape_ratio(f64::INFINITY).is_err());
    }
}
