//! Cerruti's influence coefficients: the tangential surface displacements of an elastic
//! half-space under a uniform tangential traction on one rectangular cell.
//!
//! # Formula
//! A point force `Q` \[N\] in `x` on the surface of a half-space displaces the surface
//! point `(X, Y)`, `ρ = sqrt(X² + Y²)`, by (Cerruti; Johnson 1985 eq. 3.86a)
//!
//! ```text
//! u_x = Q/(2πG) [(1-ν)/ρ + ν X²/ρ³],   u_y = Q/(2πG) ν X Y/ρ³.
//! ```
//!
//! For two bodies with opposite tractions, the displacement *difference* (body 1 minus
//! body 2) is the same expression with `1/(πG)` and Kalker's combined constants
//! (Kalker 1990 §1.6)
//!
//! ```text
//! 1/G = (1/G1 + 1/G2)/2,   ν/G = (ν1/G1 + ν2/G2)/2        [G in MPa].
//! ```
//!
//! A uniform traction `τ` \[MPa\] in `x` on the cell `|ξ| <= a`, `|η| <= b` then gives,
//! with the four-corner sum `S[F] = F(x+a, y+b) - F(x+a, y-b) - F(x-a, y+b) + F(x-a, y-b)`
//! (as for Love's normal coefficients in [`crate::halfspace::influence`]),
//!
//! ```text
//! u_x = τ/(πG) · S[(1-ν) X asinh(Y/|X|) + Y asinh(X/|Y|)]   (A_xx)
//! u_y = τ/(πG) · S[-ν ρ]                                    (A_yx)
//! ```
//!
//! and a traction in `y` gives `A_yy` (the roles of `X` and `Y` exchanged) and
//! `A_xy = A_yx`. The antiderivatives follow from
//! `∂²/∂X∂Y [Y asinh(X/|Y|)] = X²/ρ³`, `∂²/∂X∂Y [X asinh(Y/|X|)] = Y²/ρ³` and
//! `∂²/∂X∂Y [-ρ] = X Y/ρ³` (derivation in docs/rolling.md §2). `A_xx`, `A_yy` are even in
//! `x` and in `y`; `A_xy` is odd in each.
//!
//! # Assumptions
//! Linear elastic, homogeneous, isotropic half-spaces; quasi-identical bodies (Kalker's
//! difference parameter `K = (G/4)[(1-2ν1)/G1 - (1-2ν2)/G2] = 0`), so that tangential
//! tractions cause no normal displacement difference and pressure none tangential: the
//! normal and tangential problems decouple. For dissimilar bodies this neglects the
//! coupling ([`super::difference_parameter`] reports its size).
//!
//! # Coupling of dissimilar bodies
//! [`coupling`] gives the normal-tangential coupling coefficient `A_nx = K/(πG) S[X
//! atan(Y/X) + Y ln ρ]` \[mm/MPa\] (the cell integral of `K X/(πG ρ²)`), used by
//! [`super::CouplingOperator`] and [`super::CoupledShiftSolver`].
//!
//! # References
//! - Johnson, *Contact Mechanics* (1985), §3.3, eq. (3.86a).
//! - Kalker, *Three-dimensional elastic bodies in rolling contact* (1990), §1.6 and
//!   ch. 5 (influence numbers for piecewise-constant tractions).
//! - Love (1929) for the normal analogue.

use std::f64::consts::PI;

/// The three antiderivatives at one corner `(X, Y)` \[mm\]: `X asinh(Y/|X|)`,
/// `Y asinh(X/|Y|)` (each 0 where its factor vanishes) and `ρ`.
fn corner(x: f64, y: f64) -> [f64; 3] {
    let fx = if x != 0.0 {
        x * (y / x.abs()).asinh()
    } else {
        0.0
    };
    let fy = if y != 0.0 {
        y * (x / y.abs()).asinh()
    } else {
        0.0
    };
    [fx, fy, x.hypot(y)]
}

/// The tangential influence coefficients \[mm/MPa\] of one cell at one offset.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CerrutiCoefficients {
    /// `u_x` per unit traction in `x`.
    pub xx: f64,
    /// `u_y` per unit traction in `y`.
    pub yy: f64,
    /// `u_x` per unit traction in `y`, equal to `u_y` per unit traction in `x`.
    pub xy: f64,
}

/// The coefficients \[mm/MPa\] at the point `(x, y)` \[mm\] for a uniform traction on the
/// cell `dx × dy` \[mm\] centred on the origin, combined shear modulus `g` \[MPa\] and
/// Poisson's ratio `nu` (Kalker's combined constants, see the module docs).
#[must_use]
pub fn cerruti(x: f64, y: f64, dx: f64, dy: f64, g: f64, nu: f64) -> CerrutiCoefficients {
    let (a, b) = (0.5 * dx, 0.5 * dy);
    let c = [
        (corner(x + a, y + b), 1.0),
        (corner(x + a, y - b), -1.0),
        (corner(x - a, y + b), -1.0),
        (corner(x - a, y - b), 1.0),
    ];
    let mut s = [0.0; 3];
    for (f, sign) in c {
        for k in 0..3 {
            s[k] += sign * f[k];
        }
    }
    coefficients(s, g, nu)
}

/// The coefficients from the four-corner sums `[S[X asinh(Y/|X|)], S[Y asinh(X/|Y|)], S[ρ]]`.
fn coefficients(s: [f64; 3], g: f64, nu: f64) -> CerrutiCoefficients {
    let scale = 1.0 / (PI * g);
    CerrutiCoefficients {
        xx: scale * ((1.0 - nu) * s[0] + s[1]),
        yy: scale * (s[0] + (1.0 - nu) * s[1]),
        xy: -scale * nu * s[2],
    }
}

/// The coefficient tables \[mm/MPa\] `[xx, yy, xy]` for the offsets `i = 0..=nx`,
/// `j = 0..=ny` cells, each stored `[j * (nx + 1) + i]`: one quadrant, the others follow
/// by parity (`xx`, `yy` even, `xy` odd in each direction). Each antiderivative is
/// evaluated once per cell corner and shared by the four cells meeting there.
#[must_use]
pub fn quadrant_tables(nx: usize, ny: usize, dx: f64, dy: f64, g: f64, nu: f64) -> [Vec<f64>; 3] {
    let (cx, cy) = (nx + 2, ny + 2);
    // Corner k sits at (k - 1/2) dx.
    let mut corners = vec![[0.0; 3]; cx * cy];
    for l in 0..cy {
        let y = (l as f64 - 0.5) * dy;
        for k in 0..cx {
            corners[l * cx + k] = corner((k as f64 - 0.5) * dx, y);
        }
    }
    let n = (nx + 1) * (ny + 1);
    let mut tables = [vec![0.0; n], vec![0.0; n], vec![0.0; n]];
    for j in 0..=ny {
        for i in 0..=nx {
            let c = |k: usize, l: usize| corners[l * cx + k];
            let (pp, pm, mp, mm) = (c(i + 1, j + 1), c(i + 1, j), c(i, j + 1), c(i, j));
            let mut s = [0.0; 3];
            for (k, sk) in s.iter_mut().enumerate() {
                *sk = pp[k] - pm[k] - mp[k] + mm[k];
            }
            let co = coefficients(s, g, nu);
            let idx = j * (nx + 1) + i;
            tables[0][idx] = co.xx;
            tables[1][idx] = co.yy;
            // Exactly zero on the axes, where the cross coefficient is odd.
            tables[2][idx] = if i == 0 || j == 0 { 0.0 } else { co.xy };
        }
    }
    tables
}

/// The antiderivative `F = X atan(Y/X) + Y ln ρ` of `X/ρ²` (`∂²F/∂X∂Y = X/ρ²`) at one
/// corner `(X, Y)` \[mm\]; each term 0 where its factor vanishes (its limit). The unit
/// of the logarithm's argument only adds a function of `Y` alone, which cancels in the
/// four-corner sum.
fn coupling_corner(x: f64, y: f64) -> f64 {
    let fx = if x != 0.0 { x * (y / x).atan() } else { 0.0 };
    let fy = if y != 0.0 { y * x.hypot(y).ln() } else { 0.0 };
    fx + fy
}

/// The normal-tangential coupling coefficient \[mm/MPa\] of dissimilar bodies at the
/// point `(x, y)` \[mm\] for a uniform traction on the cell `dx × dy` \[mm\] centred on the
/// origin, combined shear modulus `g` \[MPa\] and Kalker's difference parameter `k`
/// (see [`super::difference_parameter`]):
///
/// ```text
/// A_nx = K/(πG) ∫∫_cell X/ρ² = K/(πG) S[X atan(Y/X) + Y ln ρ],
/// ```
///
/// the normal displacement sum `u_z1 + u_z2` (positive into the bodies: it opens the
/// gap) per unit traction `τ_x` on body 1. The same number with the opposite sign is the
/// tangential displacement difference `u_x = u_x1 - u_x2` per unit pressure:
/// `A_xn(x, y) = -A_nx(x, y)` (Betti's reciprocity with the field point and the source
/// exchanged, `A_nx` being odd in `x`). The coefficients for `τ_y` follow with `x` and `y`
/// exchanged: `A_ny(x, y) = coupling(y, x, dy, dx, g, k)`. `A_nx` is odd in `x`, even in
/// `y`, and 0 on the axis `x = 0`. Derivation: docs/rolling.md §9.
#[must_use]
pub fn coupling(x: f64, y: f64, dx: f64, dy: f64, g: f64, k: f64) -> f64 {
    let (a, b) = (0.5 * dx, 0.5 * dy);
    if x == 0.0 {
        // Odd in x: exactly zero on the axis.
        return 0.0;
    }
    let s = coupling_corner(x + a, y + b)
        - coupling_corner(x + a, y - b)
        - coupling_corner(x - a, y + b)
        + coupling_corner(x - a, y - b);
    k / (PI * g) * s
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Midpoint-rule quadrature of Cerruti's point-force solution (two bodies, combined
    /// constants) over the cell, for points outside it: `[u_x, u_y]` per unit `τ_x`.
    fn quadrature(x: f64, y: f64, dx: f64, dy: f64, g: f64, nu: f64) -> [f64; 2] {
        let n = 400;
        let (hx, hy) = (dx / n as f64, dy / n as f64);
        let mut s = [0.0; 2];
        for i in 0..n {
            for j in 0..n {
                let xx = x - (-0.5 * dx + (i as f64 + 0.5) * hx);
                let yy = y - (-0.5 * dy + (j as f64 + 0.5) * hy);
                let r = xx.hypot(yy);
                s[0] += (1.0 - nu) / r + nu * xx * xx / r.powi(3);
                s[1] += nu * xx * yy / r.powi(3);
            }
        }
        let k = hx * hy / (PI * g);
        [s[0] * k, s[1] * k]
    }

    #[test]
    fn closed_form_matches_quadrature_in_every_quadrant() {
        let (g, nu) = (8.0e4, 0.28);
        for &(x, y) in &[
            (2.0, 0.3),
            (-1.7, 0.9),
            (0.4, -2.2),
            (-3.0, -3.0),
            (0.0, 1.6),
            (1.3, 0.0),
        ] {
            let c = cerruti(x, y, 1.0, 0.6, g, nu);
            let [ux, uy] = quadrature(x, y, 1.0, 0.6, g, nu);
            assert!(
                ((c.xx - ux) / ux).abs() < 1e-5,
                "xx ({x}, {y}): {} vs {ux}",
                c.xx
            );
            // u_y is odd: compare to the size of u_x where it vanishes.
            assert!(
                (c.xy - uy).abs() < 1e-5 * ux.abs(),
                "xy ({x}, {y}): {} vs {uy}",
                c.xy
            );
            // A traction in y: exchange the roles of x and y.
            let t = cerruti(y, x, 0.6, 1.0, g, nu);
            assert!(((t.yy - ux) / ux).abs() < 1e-5, "yy ({y}, {x})");
            assert!((t.xy - uy).abs() < 1e-5 * ux.abs(), "yx ({y}, {x})");
        }
    }

    #[test]
    fn signs_of_the_cross_coefficient() {
        // A traction in +x pulls the surface towards +y in the first and third quadrants.
        let (g, nu) = (8.0e4, 0.3);
        assert!(cerruti(1.0, 1.0, 0.2, 0.2, g, nu).xy > 0.0);
        assert!(cerruti(-1.0, -1.0, 0.2, 0.2, g, nu).xy > 0.0);
        assert!(cerruti(-1.0, 1.0, 0.2, 0.2, g, nu).xy < 0.0);
        assert_eq!(cerruti(0.0, 0.7, 0.2, 0.2, g, nu).xy, 0.0);
        assert_eq!(cerruti(0.0, 0.0, 0.2, 0.2, g, 0.0).xy, 0.0);
    }

    #[test]
    fn centre_of_a_square_cell() {
        // u_x = (4 - 2ν) ln(1 + √2) s τ/(πG) at the centre of a square of side s.
        let (s, g, nu) = (0.37, 7.9e4, 0.3);
        let expected = (4.0 - 2.0 * nu) * (1.0 + 2f64.sqrt()).ln() * s / (PI * g);
        let c = cerruti(0.0, 0.0, s, s, g, nu);
        assert!((c.xx - expected).abs() < 1e-12 * expected);
        assert!((c.xx - c.yy).abs() < 1e-12 * expected);
    }

    #[test]
    fn quadrant_tables_equal_the_direct_coefficients() {
        let (nx, ny, dx, dy, g, nu) = (9, 6, 0.13, 0.07, 8.1e4, 0.29);
        let [txx, tyy, txy] = quadrant_tables(nx, ny, dx, dy, g, nu);
        for j in 0..=ny {
            for i in 0..=nx {
                let d = cerruti(i as f64 * dx, j as f64 * dy, dx, dy, g, nu);
                let k = j * (nx + 1) + i;
                let scale = d.xx.abs();
                assert!((txx[k] - d.xx).abs() <= 1e-13 * scale, "xx ({i}, {j})");
                assert!((tyy[k] - d.yy).abs() <= 1e-13 * scale, "yy ({i}, {j})");
                assert!((txy[k] - d.xy).abs() <= 1e-13 * scale, "xy ({i}, {j})");
            }
        }
    }

    #[test]
    fn far_field_is_a_point_force() {
        // Far away the cell acts as the point force τ dx dy.
        let (dx, dy, g, nu) = (0.1, 0.2, 8.0e4, 0.3);
        let (x, y): (f64, f64) = (30.0, -40.0);
        let r = x.hypot(y);
        let c = cerruti(x, y, dx, dy, g, nu);
        let k = dx * dy / (PI * g);
        let ux = k * ((1.0 - nu) / r + nu * x * x / r.powi(3));
        let uy = k * nu * x * y / r.powi(3);
        let vx = k * ((1.0 - nu) / r + nu * y * y / r.powi(3));
        assert!(((c.xx - ux) / ux).abs() < 1e-5);
        assert!(((c.xy - uy) / uy).abs() < 1e-5);
        assert!(((c.yy - vx) / vx).abs() < 1e-5);
    }
    /// Midpoint quadrature of `K/(πG) X/ρ²` over the cell (the coupling's point-force
    /// kernel), for points outside the cell.
    fn coupling_quadrature(x: f64, y: f64, dx: f64, dy: f64, g: f64, k: f64) -> f64 {
        let n = 400;
        let (hx, hy) = (dx / n as f64, dy / n as f64);
        let mut s = 0.0;
        for i in 0..n {
            for j in 0..n {
                let xx = x - (-0.5 * dx + (i as f64 + 0.5) * hx);
                let yy = y - (-0.5 * dy + (j as f64 + 0.5) * hy);
                s += xx / (xx * xx + yy * yy);
            }
        }
        s * hx * hy * k / (PI * g)
    }

    #[test]
    fn coupling_matches_quadrature_and_parity() {
        let (g, k, dx, dy) = (8.0e4, 0.2, 1.0, 0.6);
        for &(x, y) in &[
            (2.0, 0.3),
            (-1.7, 0.9),
            (0.4, -2.2),
            (-3.0, -3.0),
            (1.3, 0.0),
        ] {
            let c = coupling(x, y, dx, dy, g, k);
            let q = coupling_quadrature(x, y, dx, dy, g, k);
            assert!(((c - q) / q).abs() < 1e-5, "({x}, {y}): {c} vs {q}");
            // Odd in x, even in y.
            assert!((coupling(-x, y, dx, dy, g, k) + c).abs() <= 1e-14 * c.abs());
            assert!((coupling(x, -y, dx, dy, g, k) - c).abs() <= 1e-14 * c.abs());
        }
        // Inside the cell the integrand is singular but integrable: the neighbouring
        // cell's coefficient equals quadrature, and the own cell's is 0 by symmetry.
        assert_eq!(coupling(0.0, 0.0, dx, dy, g, k), 0.0);
        assert_eq!(coupling(0.0, 1.2, dx, dy, g, k), 0.0);
        // Sign: ahead of a traction in +x (x > 0) the gap opens for K > 0.
        assert!(coupling(1.0, 0.0, dx, dy, g, k) > 0.0);
        // Linear in K, inverse in G.
        let c = coupling(1.5, 0.5, dx, dy, g, k);
        assert!((coupling(1.5, 0.5, dx, dy, 2.0 * g, -k) + 0.5 * c).abs() < 1e-15 * c.abs());
    }

    #[test]
    fn coupling_far_field_and_adjacent_cell() {
        // Far away the cell acts as the point force τ dx dy: K/(πG) X/ρ² dx dy.
        let (dx, dy, g, k) = (0.1, 0.2, 8.0e4, 0.3);
        let (x, y): (f64, f64) = (30.0, -40.0);
        let c = coupling(x, y, dx, dy, g, k);
        let point = k / (PI * g) * x / (x * x + y * y) * dx * dy;
        assert!(((c - point) / point).abs() < 1e-5, "{c} vs {point}");
        // The adjacent cell along x: closed form of the strip integral
        // ∫_{a}^{3a} ∫_{-b}^{b} X/ρ² dY dX = [2X atan(b/X) + b ln(X² + b²)]_{a}^{3a},
        // with a = dx/2, b = dy/2.
        let (a, b) = (0.5 * dx, 0.5 * dy);
        let f = |xx: f64| 2.0 * xx * (b / xx).atan() + b * (xx * xx + b * b).ln();
        let exact = k / (PI * g) * (f(3.0 * a) - f(a));
        let c = coupling(dx, 0.0, dx, dy, g, k);
        assert!(((c - exact) / exact).abs() < 1e-13, "{c} vs {exact}");
    }
}
