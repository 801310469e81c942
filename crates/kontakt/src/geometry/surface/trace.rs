//! Certified first-root search along a ray for surfaces without a closed-form
//! intersection (the torus and surfaces of revolution).
//!
//! Along the ray $\mathbf s(t) = \mathbf q + t\,\mathbf n$ (Wirsching et al. (2020) eq. 2) a
//! surface is described by two functions of the ray parameter with the same sign and the same
//! zeros:
//!
//! - `f`, with a Lipschitz bound $L$ on an interval, so that no zero lies within $|f|/L$ of
//!   a sample. For the torus it is the exact signed distance ($L = 1$), for a surface of
//!   revolution $F = \rho - \rho(z)$ with $L = \sqrt{1+\max\rho'^2}$ over the interval.
//! - `g`, smooth, with computable bounds $g''_{lo} \le g'' \le g''_{hi}$ on any interval.
//!   For the torus it is the quartic's first factor $G = (\rho-R)^2+z^2-r^2$, whose second
//!   derivative is bounded in closed form; for a surface of revolution `g = f = F`.
//!
//! The search steps from the start of the interval by the largest step that is *proved*
//! root free: the Lipschitz step $|f|/L$ (sphere tracing) or the step to the first zero of the
//! quadratic lower bound $g + g' \tau + \tfrac12 g''_{lo} \tau^2$, whichever is longer. A
//! crossing is *proved* as soon as the quadratic upper bound reaches zero; that bracket then
//! contains exactly the first root and is polished by safeguarded Newton/bisection.
//! Neither step can pass a root, so the root found is the first one; tangent touches
//! (a zero without a sign change) are stepped over, so grazing rays are misses. See
//! `docs/surfaces.md`.

/// One evaluation of the ray functions at a ray parameter.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Sample {
    /// Signed value with a Lipschitz bound (see [`RayFunction::free_step`]).
    pub f: f64,
    /// df/ds.
    pub f1: f64,
    /// Smooth signed value with bounded second derivative, same sign as `f`.
    pub g: f64,
    /// dg/ds.
    pub g1: f64,
}

/// A surface seen along one ray, parametrised by `s` (the ray parameter minus an offset).
pub(crate) trait RayFunction {
    /// The functions at `s`.
    fn sample(&self, s: f64) -> Sample;
    /// Lower and upper bounds on g'' over `[a, b]`; `-inf`/`+inf` when unknown.
    fn g2_bounds(&self, a: f64, b: f64) -> (f64, f64);
    /// A step from `a` proved root free by a Lipschitz bound valid on `[a, b]` (at most
    /// `b - a`), given the sample at `a`.
    fn free_step(&self, at_a: &Sample, a: f64, b: f64) -> f64;
    /// |f| at or below this is "on the surface" (rounding level, absolute).
    fn tol(&self) -> f64;
    /// Step taken past a tangent touch (a zero of `f` without a proved crossing).
    fn skip(&self) -> f64;
}

/// Steps of the first-root search before giving up (a miss). The accelerated steps need a
/// few dozen even for rays that skim the surface at 1e-12 of its size; see the tests.
pub(crate) const MAX_STEPS: usize = 400;
/// Newton steps allowed in [`root_near`] before falling back to the full search.
const MAX_NEWTON: usize = 6;
/// |f'| below this is treated as grazing by [`root_near`] (falls back to the full search).
const MIN_SLOPE: f64 = 1e-4;

/// The smallest `tau >= 0` at which `a tau² + b tau + c` (with `c > 0`) vanishes, if any.
/// `a = -inf` means "no information": the bound is void from `tau = 0`.
fn first_zero(a: f64, b: f64, c: f64) -> Option<f64> {
    if a.is_nan() || a == f64::NEG_INFINITY {
        return Some(0.0);
    }
    if a == f64::INFINITY {
        return None;
    }
    if a == 0.0 {
        return (b < 0.0).then(|| -c / b);
    }
    let disc = b * b - 4.0 * a * c;
    if disc < 0.0 {
        return None; // a > 0 here (c > 0): the quadratic stays positive
    }
    let q = -0.5 * (b + b.signum() * disc.sqrt());
    let (r1, r2) = (q / a, c / q);
    [r1, r2]
        .into_iter()
        .filter(|r| r.is_finite() && *r >= 0.0)
        .reduce(f64::min)
}

/// |f'| above which a sample with `f == 0` exactly is a crossing (below: a touch).
const ZERO_CROSSING_SLOPE: f64 = 1e-6;

/// The first zero of the ray function in `[lo, hi]` (a sign change of `f`), or `None`.
pub(crate) fn first_root<F: RayFunction>(func: &F, lo: f64, hi: f64) -> Option<f64> {
    if !(lo <= hi) {
        return None;
    }
    let mut s = lo;
    let mut smp = func.sample(s);
    if !smp.f.is_finite() {
        return None;
    }
    if smp.f == 0.0 {
        return Some(s);
    }
    let pos = smp.f > 0.0;
    let sg = if pos { 1.0 } else { -1.0 };
    let crossed = |x: &Sample| {
        if x.f == 0.0 {
            x.f1.abs() > ZERO_CROSSING_SLOPE
        } else {
            (x.f > 0.0) != pos
        }
    };
    // Consecutive samples on the surface (within rounding) without a proved crossing.
    let mut stuck = 0;
    for _ in 0..MAX_STEPS {
        let rem = hi - s;
        let (g, g1) = (sg * smp.g, sg * smp.g1);
        // (1) A proved crossing: the upper bound g + g1 tau + hi2 tau²/2 reaches zero.
        let (lo2_all, hi2_all) = func.g2_bounds(s, hi);
        let upper = if pos { hi2_all } else { -lo2_all };
        if g > 0.0
            && let Some(tc) = first_zero(0.5 * upper, g1, g)
            && tc <= rem
        {
            let b = s + tc;
            let smp_b = func.sample(b);
            if crossed(&smp_b) {
                return Some(polish(func, s, smp, b, smp_b, pos));
            }
        }
        // (2) The longest step proved root free, over shrinking windows (tighter bounds),
        // down to the step already proved.
        let mut step = 0.0f64;
        let mut w = rem;
        for _ in 0..48 {
            let (lo2, hi2) = func.g2_bounds(s, s + w);
            let l = if pos { lo2 } else { -hi2 };
            let tq = if g > 0.0 {
                first_zero(0.5 * l, g1, g).map_or(w, |t| t.min(w))
            } else {
                0.0
            };
            step = step.max(tq).max(func.free_step(&smp, s, s + w).min(w));
            if step >= 0.5 * w {
                break;
            }
            w *= 0.25;
            if w <= step {
                break;
            }
        }
        // (3) At a tangent touch (on the surface within rounding, or steps below the
        // resolution of s, no proved crossing) step over it, doubling the step while the
        // samples stay on the surface; a sign change on the other side is still caught
        // below. A crossing that stays within the rounding tolerance over the skipped length
        // counts as grazing.
        if smp.f.abs() <= func.tol() || s + step <= s {
            step = step.max(func.skip() * f64::from(1u32 << stuck.min(30)));
            stuck += 1;
        } else {
            stuck = 0;
        }
        let s_new = s + step;
        if s_new >= hi || !(step > 0.0) {
            let smp_hi = func.sample(hi);
            return crossed(&smp_hi).then(|| polish(func, s, smp, hi, smp_hi, pos));
        }
        let smp_new = func.sample(s_new);
        if crossed(&smp_new) {
            return Some(polish(func, s, smp, s_new, smp_new, pos));
        }
        s = s_new;
        smp = smp_new;
    }
    None
}

/// Safeguarded Newton/bisection on `f` in a bracket `[a, b]` with `f(a)` of sign `pos` and
/// `f(b)` of the other sign (or zero). Returns once `|f| <= tol` (after one last Newton
/// step, which brings the root to full precision) or the bracket is at the resolution of s.
fn polish<F: RayFunction>(
    func: &F,
    mut a: f64,
    fa: Sample,
    mut b: f64,
    fb: Sample,
    pos: bool,
) -> f64 {
    if fb.f == 0.0 {
        return b;
    }
    let tol = func.tol();
    let (mut x, mut smp) = if fa.f.abs() < fb.f.abs() {
        (a, fa)
    } else {
        (b, fb)
    };
    let mut last_dx = f64::INFINITY;
    for _ in 0..200 {
        let newton = x - smp.f / smp.f1;
        let newton_ok = smp.f1 != 0.0 && newton >= a && newton <= b;
        if smp.f.abs() <= tol {
            return if newton_ok { newton } else { x };
        }
        if b - a <= 4.0 * f64::EPSILON * a.abs().max(b.abs()) {
            return x;
        }
        let dx = (newton - x).abs();
        x = if newton_ok && dx <= 0.5 * last_dx {
            last_dx = dx;
            newton
        } else {
            last_dx = b - a;
            0.5 * (a + b)
        };
        smp = func.sample(x);
        if smp.f == 0.0 {
            return x;
        }
        if (smp.f > 0.0) == pos {
            a = x;
        } else {
            b = x;
        }
    }
    x
}

/// The root near `s = 0` (the guess) by Newton on `f`, *certified* to be the first root in
/// `[lo, hi]`; `None` when Newton does not converge quickly, leaves `[lo, hi]`, the ray is
/// grazing, or the certificate cannot be established cheaply (the caller then runs the full
/// search, so the answer is always the same root as [`first_root`] would give).
pub(crate) fn root_near<F: RayFunction>(func: &F, lo: f64, hi: f64) -> Option<f64> {
    let (s, g1) = newton_near(func, lo, hi)?;
    certify(func, lo, s, g1).then_some(s)
}

/// Newton on `f` from `s = 0` (which must lie in `[lo, hi]`): the converged root and `g'`
/// there, or `None` (not converged in a few steps, left `[lo, hi]`, grazing).
pub(crate) fn newton_near<F: RayFunction>(func: &F, lo: f64, hi: f64) -> Option<(f64, f64)> {
    if !(lo <= 0.0 && hi >= 0.0) {
        return None;
    }
    let tol = func.tol();
    let mut s = 0.0;
    let mut smp = func.sample(s);
    let mut k = 0;
    while !(smp.f.abs() <= tol) {
        if k == MAX_NEWTON || !(smp.f1.abs() >= MIN_SLOPE) {
            return None;
        }
        s -= smp.f / smp.f1;
        if !(s >= lo && s <= hi) {
            return None;
        }
        smp = func.sample(s);
        k += 1;
    }
    if !(smp.f1.abs() >= MIN_SLOPE) {
        return None;
    }
    // One more Newton step for full precision (free: the sample is at hand).
    let s_fin = s - smp.f / smp.f1;
    Some((if s_fin >= lo && s_fin <= hi { s_fin } else { s }, smp.g1))
}

/// True when no root of the ray function lies in `[lo, s_root)`, given `g'` at the
/// (converged) root `s_root`.
///
/// With `g(s*) = 0`, the Taylor bound $g(s^*-\sigma) \ge |g'(s^*)|\sigma +
/// \tfrac12 g''_{lo}\sigma^2$ (for `g` normalised positive before the root) keeps `g` away
/// from zero on `[s* - w, s*)`, `w = 2|g'|/|g''_lo|` (all of it if `g''_lo >= 0`); if that
/// does not reach `lo`, the Lipschitz step from `lo` must cover the rest.
pub(crate) fn certify<F: RayFunction>(func: &F, lo: f64, s_root: f64, g1_root: f64) -> bool {
    let span = s_root - lo;
    if span <= 0.0 {
        return true;
    }
    // Before the root, g has the sign opposite to g'(s*); normalise it to positive.
    let before_pos = g1_root < 0.0;
    let (lo2, hi2) = func.g2_bounds(lo, s_root);
    let l = if before_pos { lo2 } else { -hi2 };
    let w = if l >= 0.0 {
        f64::INFINITY
    } else {
        // Shrunk slightly: g(s*) is zero only to rounding.
        2.0 * g1_root.abs() / (-l) * (1.0 - 1e-9)
    };
    if w >= span {
        return true;
    }
    let a = func.sample(lo);
    (a.f > 0.0) == before_pos && a.f != 0.0 && func.free_step(&a, lo, s_root) >= span - w
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn first_zero_of_quadratics() {
        // tau² - 3 tau + 2 = (tau-1)(tau-2)
        assert_eq!(first_zero(1.0, -3.0, 2.0), Some(1.0));
        assert_eq!(first_zero(1.0, 3.0, 2.0), None);
        assert_eq!(first_zero(0.0, -2.0, 1.0), Some(0.5));
        assert_eq!(first_zero(0.0, 2.0, 1.0), None);
        assert_eq!(first_zero(f64::NEG_INFINITY, 2.0, 1.0), Some(0.0));
        assert_eq!(first_zero(f64::INFINITY, -2.0, 1.0), None);
        // -tau² + 1: zero at 1
        assert_eq!(first_zero(-1.0, 0.0, 1.0), Some(1.0));
    }
}
