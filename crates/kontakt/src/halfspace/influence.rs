//! Love's influence coefficients: the normal surface displacement of an elastic
//! half-space under uniform pressure on one rectangular cell.
//!
//! Boussinesq's point-force solution integrated over a rectangle (Love 1929; Johnson
//! 1985 §3.3; Johnson 1982 eq. 27). A pressure `p` \[MPa\] on the cell `|ξ| <= a`, `|η| <= b`
//! displaces the surface point `(x, y)` of the two-body system by
//!
//! ```text
//! w(x, y) = p / (π E*) · ∫∫ dξ dη / sqrt((x-ξ)² + (y-η)²)
//!         = p / (π E*) · [F(x+a, y+b) - F(x+a, y-b) - F(x-a, y+b) + F(x-a, y-b)],
//! F(X, Y) = X asinh(Y/|X|) + Y asinh(X/|Y|),      F(0, 0) = 0,
//! ```
//!
//! because `∂²F/∂X∂Y = 1/sqrt(X² + Y²)` (the derivation is in docs/halfspace.md §1).
//! The combined compliance of both bodies enters through `1/E* = (1-ν1²)/E1 + (1-ν2²)/E2`.

/// `F(X, Y) = X asinh(Y/|X|) + Y asinh(X/|Y|)`, each term taken as its limit 0 where its
/// factor vanishes. It differs from `X ln(Y + r) + Y ln(X + r)` by functions of `X` or `Y`
/// alone, which cancel in the four-corner sum, and it stays finite on the axes.
fn antiderivative(x: f64, y: f64) -> f64 {
    let mut f = 0.0;
    if x != 0.0 {
        f += x * (y / x.abs()).asinh();
    }
    if y != 0.0 {
        f += y * (x / y.abs()).asinh();
    }
    f
}

/// The integral `∫∫ dξ dη / r` \[mm\] over a cell of size `dx × dy` \[mm\] centred on the
/// origin, seen from the point `(x, y)` \[mm\]. Multiply by `p / (π E*)` for the
/// displacement \[mm\].
#[must_use]
pub fn cell_integral(x: f64, y: f64, dx: f64, dy: f64) -> f64 {
    let (a, b) = (0.5 * dx, 0.5 * dy);
    antiderivative(x + a, y + b) - antiderivative(x + a, y - b) - antiderivative(x - a, y + b)
        + antiderivative(x - a, y - b)
}

/// The displacement \[mm\] at `(x, y)` \[mm\] per unit pressure \[MPa\] on the cell
/// `dx × dy` \[mm\] at the origin, for the contact modulus `e_star` \[MPa\].
#[must_use]
pub fn influence(x: f64, y: f64, dx: f64, dy: f64, e_star: f64) -> f64 {
    cell_integral(x, y, dx, dy) / (std::f64::consts::PI * e_star)
}

/// The influence coefficients \[mm/MPa\] for the offsets `i = 0..=nx`, `j = 0..=ny`
/// cells, stored `[j * (nx + 1) + i]`: one quadrant, the others follow by symmetry. The
/// antiderivative is evaluated once per cell corner and shared by the four cells that meet
/// there, so the table costs `(nx + 2)(ny + 2)` evaluations.
#[must_use]
pub fn quadrant_table(nx: usize, ny: usize, dx: f64, dy: f64, e_star: f64) -> Vec<f64> {
    let (cx, cy) = (nx + 2, ny + 2);
    // Corner k sits at (k - 1/2) dx.
    let mut corners = vec![0.0; cx * cy];
    for l in 0..cy {
        let y = (l as f64 - 0.5) * dy;
        for k in 0..cx {
            corners[l * cx + k] = antiderivative((k as f64 - 0.5) * dx, y);
        }
    }
    let scale = 1.0 / (std::f64::consts::PI * e_star);
    let mut table = vec![0.0; (nx + 1) * (ny + 1)];
    for j in 0..=ny {
        for i in 0..=nx {
            let c = |k: usize, l: usize| corners[l * cx + k];
            table[j * (nx + 1) + i] =
                (c(i + 1, j + 1) - c(i + 1, j) - c(i, j + 1) + c(i, j)) * scale;
        }
    }
    table
}

/// The dense `n × n` influence matrix of an `nx × ny` grid (row-major fields, x fastest):
/// entry `[i * n + j]` is the displacement at cell `i` per unit pressure on cell `j`.
/// Quadratic in memory and cubic to use: for tests and for checking the FFT operator on
/// small grids only.
#[must_use]
pub fn dense_matrix(nx: usize, ny: usize, dx: f64, dy: f64, e_star: f64) -> Vec<f64> {
    let n = nx * ny;
    let mut m = vec![0.0; n * n];
    for i in 0..n {
        let (ix, iy) = ((i % nx) as f64, (i / nx) as f64);
        for j in 0..n {
            let (jx, jy) = ((j % nx) as f64, (j / nx) as f64);
            m[i * n + j] = influence((ix - jx) * dx, (iy - jy) * dy, dx, dy, e_star);
        }
    }
    m
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Midpoint-rule quadrature of ∫∫ 1/r over the cell, for points outside it.
    fn quadrature(x: f64, y: f64, dx: f64, dy: f64) -> f64 {
        let n = 400;
        let (hx, hy) = (dx / n as f64, dy / n as f64);
        let mut s = 0.0;
        for i in 0..n {
            for j in 0..n {
                let xi = -0.5 * dx + (i as f64 + 0.5) * hx;
                let eta = -0.5 * dy + (j as f64 + 0.5) * hy;
                s += 1.0 / ((x - xi).powi(2) + (y - eta).powi(2)).sqrt();
            }
        }
        s * hx * hy
    }

    #[test]
    fn closed_form_matches_quadrature_in_every_quadrant() {
        for &(x, y) in &[
            (2.0, 0.3),
            (-1.7, 0.9),
            (0.4, -2.2),
            (-3.0, -3.0),
            (0.0, 1.6),
        ] {
            let exact = cell_integral(x, y, 1.0, 0.6);
            let num = quadrature(x, y, 1.0, 0.6);
            assert!(
                ((exact - num) / num).abs() < 1e-5,
                "({x}, {y}): {exact} vs {num}"
            );
        }
    }

    #[test]
    fn centre_of_a_square_cell() {
        // w = 4 ln(1 + sqrt 2) s p / (π E*) at the centre of a square of side s.
        let s = 0.37;
        let expected = 4.0 * (1.0 + 2f64.sqrt()).ln() * s;
        assert!((cell_integral(0.0, 0.0, s, s) - expected).abs() < 1e-14);
    }

    #[test]
    fn quadrant_table_equals_the_direct_coefficients() {
        let (nx, ny, dx, dy, e) = (9, 6, 0.13, 0.07, 1.1e5);
        let t = quadrant_table(nx, ny, dx, dy, e);
        for j in 0..=ny {
            for i in 0..=nx {
                let direct = influence(i as f64 * dx, j as f64 * dy, dx, dy, e);
                let v = t[j * (nx + 1) + i];
                assert!(
                    (v - direct).abs() <= 1e-13 * direct.abs(),
                    "({i}, {j}): {v} vs {direct}"
                );
            }
        }
    }

    #[test]
    fn far_field_is_a_point_force() {
        // Far away the cell acts as a point force p·dx·dy: ∫∫ 1/r -> dx dy / r.
        let (dx, dy) = (0.1, 0.2);
        let r: f64 = 50.0;
        let v = cell_integral(r / 2f64.sqrt(), r / 2f64.sqrt(), dx, dy);
        assert!(((v - dx * dy / r) / v).abs() < 1e-5);
    }
}
