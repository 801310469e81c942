//! Closed-form areas and pressure integrals of lattice cells clipped by the nominal
//! contact: the geometry behind the load sharing of [`super::asperity`].
//!
//! All functions work in the first quadrant of a contact centred at the origin (the
//! asperity lattice has its valleys on the axes, so no cell straddles an axis and every
//! cell maps to the first quadrant by symmetry).
//!
//! # Formulas
//! Circle of radius `a`, `h(x) = sqrt(a² - x²)`:
//!
//! - area under the arc: $C(x) = \int_0^x h\,dt = \tfrac12\left(x\,h(x) + a^2 \arcsin(x/a)\right)$;
//! - "cap volume" over the rectangle `[0,x] × [0,y]` inside the disk
//!   ($x^2 + y^2 \le a^2$), with $s = \sqrt{a^2 - x^2 - y^2}$:
//!
//! $$V(x,y) = \int_0^x\!\!\int_0^y \sqrt{a^2 - u^2 - v^2}\,dv\,du
//!   = \frac{xys}{3} + \frac{x(3a^2 - x^2)}{6}\arctan\frac{y}{s}
//!   + \frac{y(3a^2 - y^2)}{6}\arctan\frac{x}{s} - \frac{a^3}{3}\arctan\frac{xy}{as}.$$
//!
//! The Hertz pressure is $p = (p_0/a)\sqrt{a^2 - r^2}$, so the load on a cell is
//! $(p_0/a)$ times the volume under $\sqrt{a^2-r^2}$ over the cell ∩ disk. A cell
//! `[x0,x1] × [y0,y1]` is split at `x_full = h(y1)` (left of it the whole cell height lies
//! in the disk) and `x_zero = h(y0)` (right of it nothing does); between the two the
//! integrand is cut by the arc, whose column integral is $\pi h(x)^2/4$ minus the part
//! below `y0`. `docs/traction-asperity.md` §4 has the derivation.

use std::f64::consts::PI;

/// `C(x) = ∫_0^x sqrt(a² - t²) dt` for `|x| <= a` (clamped outside), the area under a
/// circular arc of radius `a`; also the integral of the line-contact pressure profile
/// `sqrt(a² - x²)`.
pub(crate) fn arc_area(a: f64, x: f64) -> f64 {
    let x = x.clamp(-a, a);
    let h = (a * a - x * x).max(0.0).sqrt();
    0.5 * (x * h + a * a * (x / a).clamp(-1.0, 1.0).asin())
}

/// `V(x, y)` of the module docs, for `x, y >= 0` and `x² + y² <= a²` (the radicand is
/// clamped at zero for points rounded just outside the circle).
pub(crate) fn cap_volume(a: f64, x: f64, y: f64) -> f64 {
    let s = (a * a - x * x - y * y).max(0.0).sqrt();
    x * y * s / 3.0
        + x * (3.0 * a * a - x * x) / 6.0 * y.atan2(s)
        + y * (3.0 * a * a - y * y) / 6.0 * x.atan2(s)
        - a * a * a / 3.0 * (x * y).atan2(a * s)
}

/// Area of the rectangle `[x0,x1] × [y0,y1]` (first quadrant, `0 <= x0 < x1`,
/// `0 <= y0 < y1`) inside the disk of radius `a`, and the integral of
/// `sqrt(a² - x² - y²)` over that part.
pub(crate) fn disk_cell(a: f64, x0: f64, x1: f64, y0: f64, y1: f64) -> (f64, f64) {
    if x0 >= a || y0 >= a {
        return (0.0, 0.0);
    }
    let x_zero = (a * a - y0 * y0).max(0.0).sqrt();
    let x_full = if y1 < a {
        (a * a - y1 * y1).max(0.0).sqrt()
    } else {
        0.0
    };
    let mut area = 0.0;
    let mut volume = 0.0;
    // Zone A: the whole cell height is inside the disk.
    let (la, ua) = (x0, x1.min(x_full));
    if ua > la {
        area += (y1 - y0) * (ua - la);
        volume += cap_volume(a, ua, y1) - cap_volume(a, la, y1) - cap_volume(a, ua, y0)
            + cap_volume(a, la, y0);
    }
    // Zone B: the arc cuts the cell.
    let (lb, ub) = (x0.max(x_full), x1.min(x_zero));
    if ub > lb {
        area += arc_area(a, ub) - arc_area(a, lb) - y0 * (ub - lb);
        volume += 0.25 * PI * (a * a * (ub - lb) - (ub * ub * ub - lb * lb * lb) / 3.0)
            - (cap_volume(a, ub, y0) - cap_volume(a, lb, y0));
    }
    (area.max(0.0), volume.max(0.0))
}

#[cfg(test)]
mod tests {
    use super::*;
    use approx::assert_relative_eq;

    /// The cap volume against a brute-force midpoint sum of the analytic column
    /// integral.
    #[test]
    fn cap_volume_matches_quadrature() {
        let a = 0.4;
        for (x, y) in [
            (0.1, 0.2),
            (0.3, 0.2),
            (0.05, 0.39),
            (0.28, 0.28),
            (0.24, 0.32),
        ] {
            let n = 20_000;
            let h = x / n as f64;
            let num: f64 = (0..n)
                .map(|i| {
                    let u = (i as f64 + 0.5) * h;
                    let c = (a * a - u * u).sqrt();
                    let v = f64::min(y, c);
                    0.5 * (v * (c * c - v * v).max(0.0).sqrt() + c * c * (v / c).asin()) * h
                })
                .sum();
            assert_relative_eq!(cap_volume(a, x, y), num, max_relative = 1e-8);
        }
        assert_eq!(cap_volume(a, 0.0, 0.3), 0.0);
    }

    /// Tiling a quarter disk with cells reproduces the quarter area pi a²/4 and the
    /// quarter hemisphere volume pi a³/6 exactly, whatever the lattice.
    #[test]
    fn cells_tile_the_quarter_disk() {
        for (a, p, q) in [(0.4, 0.05, 0.05), (1.0, 0.07, 0.03), (0.3, 0.2, 0.11)] {
            let (mut area, mut volume) = (0.0, 0.0);
            let nx = (a / p) as usize + 1;
            let ny = (a / q) as usize + 1;
            for i in 0..nx {
                for j in 0..ny {
                    let (ar, vo) = disk_cell(
                        a,
                        i as f64 * p,
                        (i + 1) as f64 * p,
                        j as f64 * q,
                        (j + 1) as f64 * q,
                    );
                    area += ar;
                    volume += vo;
                }
            }
            assert_relative_eq!(area, PI * a * a / 4.0, max_relative = 1e-13);
            assert_relative_eq!(volume, PI * a * a * a / 6.0, max_relative = 1e-13);
        }
    }

    #[test]
    fn arc_area_limits() {
        assert_relative_eq!(arc_area(2.0, 2.0), PI, max_relative = 1e-15);
        assert_relative_eq!(arc_area(2.0, 5.0), PI, max_relative = 1e-15);
        assert_relative_eq!(arc_area(2.0, -2.0), -PI, max_relative = 1e-15);
        assert_eq!(arc_area(2.0, 0.0), 0.0);
    }
}
