//! The normal-tangential coupling operator of dissimilar bodies by FFT.
//!
//! # Formula
//! With Kalker's difference parameter `K` ([`super::difference_parameter`]) and the
//! coupling coefficients `A_nx`, `A_ny` of [`super::influence::coupling`] \[mm/MPa\]:
//!
//! ```text
//! u_n = A_nx * τ_x + A_ny * τ_y        (normal displacement sum, opens the gap)
//! u_x = -A_nx * p,   u_y = -A_ny * p   (tangential displacement difference)
//! ```
//!
//! for tractions `τ` \[MPa\] on body 1 and pressure `p` \[MPa\], each `*` a discrete
//! convolution over the grid. `A_nx` is odd in `x` and even in `y` (`A_ny` the reverse),
//! so its spectrum is imaginary: the real-spectrum plans of [`crate::halfspace`] (even or
//! odd-odd kernels) do not apply. This operator keeps the full complex spectrum of each
//! kernel on the zero-padded `2nx × 2ny` grid (free boundary) and transforms with
//! complex FFTs along `x` and `y`. It is applied once per outer (normal-tangential)
//! iteration, not inside the inner solvers, so its cost is secondary.
//!
//! # Assumptions
//! Homogeneous, isotropic, linear elastic half-spaces; free boundary.
//!
//! # References
//! Johnson, *Contact Mechanics* (1985) §3.2-3.3; Kalker (1990) §1.6. Derivation:
//! docs/rolling.md §9.

use super::influence::coupling;
use crate::error::{Error, Result};
use crate::geometry::Grid2;
use crate::tangential::KalkerMaterial;
use rustfft::num_complex::Complex;
use rustfft::{Fft, FftPlanner};
use std::sync::Arc;

/// The coupling operator of one grid (see the module docs): planned once, applied
/// without allocating.
pub struct CouplingOperator {
    grid: Grid2,
    /// Padded sizes.
    mx: usize,
    my: usize,
    k: f64,
    row_fwd: Arc<dyn Fft<f64>>,
    row_inv: Arc<dyn Fft<f64>>,
    col_fwd: Arc<dyn Fft<f64>>,
    col_inv: Arc<dyn Fft<f64>>,
    /// Spectra of `A_nx` and `A_ny`, transposed layout `[i * my + j]`, scaled by
    /// `1/(mx my)`.
    spec: [Vec<Complex<f64>>; 2],
    buf: Vec<Complex<f64>>,
    tbuf: Vec<Complex<f64>>,
    acc: Vec<Complex<f64>>,
    scratch: Vec<Complex<f64>>,
}

impl std::fmt::Debug for CouplingOperator {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("CouplingOperator")
            .field("cells", &[self.grid.nx(), self.grid.ny()])
            .field("difference_parameter", &self.k)
            .finish()
    }
}

impl CouplingOperator {
    /// Plan the operator for `grid` \[mm\], the combined constants `material` (its shear
    /// modulus \[MPa\]) and Kalker's difference parameter `k` (`|K| <= 0.5`).
    ///
    /// # Errors
    /// [`Error::InvalidInput`] for constants out of range or `|k| > 0.5` (or not finite).
    pub fn new(grid: &Grid2, material: KalkerMaterial, k: f64) -> Result<Self> {
        super::operator::check_material(&material)?;
        check_difference(k)?;
        let (nx, ny) = (grid.nx(), grid.ny());
        let (mx, my) = (2 * nx, 2 * ny);
        let mut planner = FftPlanner::new();
        let row_fwd = planner.plan_fft_forward(mx);
        let row_inv = planner.plan_fft_inverse(mx);
        let col_fwd = planner.plan_fft_forward(my);
        let col_inv = planner.plan_fft_inverse(my);
        let scratch_len = [&row_fwd, &row_inv, &col_fwd, &col_inv]
            .iter()
            .map(|f| f.get_inplace_scratch_len())
            .max()
            .unwrap_or(0);
        let m = mx * my;
        let zero = Complex::new(0.0, 0.0);
        let mut op = CouplingOperator {
            grid: *grid,
            mx,
            my,
            k,
            row_fwd,
            row_inv,
            col_fwd,
            col_inv,
            spec: [vec![zero; m], vec![zero; m]],
            buf: vec![zero; m],
            tbuf: vec![zero; m],
            acc: vec![zero; m],
            scratch: vec![zero; scratch_len],
        };
        let (dx, dy, g) = (grid.dx(), grid.dy(), material.shear_modulus);
        let scale = 1.0 / m as f64;
        for dir in 0..2 {
            op.buf.fill(zero);
            // Offsets -(n-1)..=(n-1); the offsets ±n stay 0 (never used on the grid).
            for j in -(ny as isize - 1)..=(ny as isize - 1) {
                for i in -(nx as isize - 1)..=(nx as isize - 1) {
                    let (x, y) = (i as f64 * dx, j as f64 * dy);
                    let c = if dir == 0 {
                        coupling(x, y, dx, dy, g, k)
                    } else {
                        coupling(y, x, dy, dx, g, k)
                    };
                    let (ii, jj) = (i.rem_euclid(mx as isize), j.rem_euclid(my as isize));
                    op.buf[jj as usize * mx + ii as usize] = Complex::new(c * scale, 0.0);
                }
            }
            op.forward();
            op.spec[dir].copy_from_slice(&op.tbuf);
        }
        Ok(op)
    }

    /// The grid \[mm\].
    pub fn grid(&self) -> &Grid2 {
        &self.grid
    }

    /// Kalker's difference parameter `K`.
    pub fn difference_parameter(&self) -> f64 {
        self.k
    }

    /// Forward 2-D transform of `buf` (row-major, x fastest) into `tbuf` (transposed).
    fn forward(&mut self) {
        let (mx, my) = (self.mx, self.my);
        self.row_fwd
            .process_with_scratch(&mut self.buf, &mut self.scratch);
        for j in 0..my {
            for i in 0..mx {
                self.tbuf[i * my + j] = self.buf[j * mx + i];
            }
        }
        self.col_fwd
            .process_with_scratch(&mut self.tbuf, &mut self.scratch);
    }

    /// Inverse 2-D transform of `tbuf` (transposed) into `buf` (row-major).
    fn inverse(&mut self) {
        let (mx, my) = (self.mx, self.my);
        self.col_inv
            .process_with_scratch(&mut self.tbuf, &mut self.scratch);
        for i in 0..mx {
            for j in 0..my {
                self.buf[j * mx + i] = self.tbuf[i * my + j];
            }
        }
        self.row_inv
            .process_with_scratch(&mut self.buf, &mut self.scratch);
    }

    /// Load the field `f` (nx·ny, row-major) zero-padded into `buf`.
    fn load(&mut self, f: &[f64]) {
        let (nx, mx) = (self.grid.nx(), self.mx);
        self.buf.fill(Complex::new(0.0, 0.0));
        for (j, row) in f.chunks_exact(nx).enumerate() {
            for (i, v) in row.iter().enumerate() {
                self.buf[j * mx + i] = Complex::new(*v, 0.0);
            }
        }
    }

    /// Copy `factor ×` the real part of `buf`'s grid block into `out`.
    fn store(&self, out: &mut [f64], factor: f64) {
        let (nx, mx) = (self.grid.nx(), self.mx);
        for (j, row) in out.chunks_exact_mut(nx).enumerate() {
            for (i, v) in row.iter_mut().enumerate() {
                *v = factor * self.buf[j * mx + i].re;
            }
        }
    }

    fn check(&self, fields: &[(&'static str, usize)]) -> Result<()> {
        let n = self.grid.len();
        for (name, len) in fields {
            if *len != n {
                return Err(Error::invalid(
                    *name,
                    format!("{len} values"),
                    format!("{n} values ({} x {} grid)", self.grid.nx(), self.grid.ny()),
                ));
            }
        }
        Ok(())
    }

    /// `u_n = A_nx * τ_x + A_ny * τ_y` \[mm\] for the tractions \[MPa\] on body 1: the
    /// normal displacement sum, positive where it opens the gap. Allocates nothing.
    ///
    /// # Errors
    /// [`Error::InvalidInput`] when a length differs from `nx·ny`.
    pub fn normal(&mut self, tx: &[f64], ty: &[f64], un: &mut [f64]) -> Result<()> {
        self.check(&[
            ("traction_x", tx.len()),
            ("traction_y", ty.len()),
            ("u_n", un.len()),
        ])?;
        self.load(tx);
        self.forward();
        for ((a, t), s) in self.acc.iter_mut().zip(&self.tbuf).zip(&self.spec[0]) {
            *a = t * s;
        }
        self.load(ty);
        self.forward();
        for ((t, a), s) in self.tbuf.iter_mut().zip(&self.acc).zip(&self.spec[1]) {
            *t = *t * s + a;
        }
        self.inverse();
        self.store(un, 1.0);
        Ok(())
    }

    /// `u_x = -A_nx * p`, `u_y = -A_ny * p` \[mm\] for the pressure `p` \[MPa\]: the
    /// tangential displacement difference (body 1 minus body 2). Allocates nothing.
    ///
    /// # Errors
    /// [`Error::InvalidInput`] when a length differs from `nx·ny`.
    pub fn tangential(&mut self, p: &[f64], ux: &mut [f64], uy: &mut [f64]) -> Result<()> {
        self.check(&[("pressure", p.len()), ("u_x", ux.len()), ("u_y", uy.len())])?;
        self.load(p);
        self.forward();
        self.acc.copy_from_slice(&self.tbuf);
        for (t, s) in self.tbuf.iter_mut().zip(&self.spec[0]) {
            *t *= s;
        }
        self.inverse();
        self.store(ux, -1.0);
        for ((t, a), s) in self.tbuf.iter_mut().zip(&self.acc).zip(&self.spec[1]) {
            *t = a * s;
        }
        self.inverse();
        self.store(uy, -1.0);
        Ok(())
    }
}

/// Check Kalker's difference parameter: finite, `|K| <= 0.5` (the bound for a rigid
/// body against one with `ν = 0`).
pub(super) fn check_difference(k: f64) -> Result<()> {
    if !(k.is_finite() && k.abs() <= 0.5) {
        return Err(Error::invalid(
            "difference_parameter",
            k,
            "-0.5 <= K <= 0.5 (Kalker's difference parameter)",
        ));
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    fn pseudo_random(n: usize, seed: u64) -> Vec<f64> {
        let mut s = seed;
        (0..n)
            .map(|_| {
                s = s
                    .wrapping_mul(6364136223846793005)
                    .wrapping_add(1442695040888963407);
                (s >> 11) as f64 / (1u64 << 53) as f64 - 0.5
            })
            .collect()
    }

    #[test]
    fn fft_equals_the_dense_sum() {
        for &(nx, ny) in &[(7, 5), (10, 16)] {
            let grid = Grid2::centered(0.7, 0.4, nx, ny).unwrap();
            let m = KalkerMaterial {
                shear_modulus: 8.0e4,
                poisson_ratio: 0.25,
            };
            let k = 0.17;
            let mut op = CouplingOperator::new(&grid, m, k).unwrap();
            let n = nx * ny;
            let (tx, ty, p) = (
                pseudo_random(n, 1),
                pseudo_random(n, 2),
                pseudo_random(n, 3),
            );
            let (mut un, mut ux, mut uy) = (vec![0.0; n], vec![0.0; n], vec![0.0; n]);
            op.normal(&tx, &ty, &mut un).unwrap();
            op.tangential(&p, &mut ux, &mut uy).unwrap();
            let scale = un.iter().fold(0.0f64, |a, v| a.max(v.abs()));
            let (dx, dy) = (grid.dx(), grid.dy());
            for i in 0..n {
                let (ix, iy) = ((i % nx) as f64, (i / nx) as f64);
                let (mut dn, mut dux, mut duy) = (0.0, 0.0, 0.0);
                for j in 0..n {
                    let (x, y) = ((ix - (j % nx) as f64) * dx, (iy - (j / nx) as f64) * dy);
                    let cx = coupling(x, y, dx, dy, 8.0e4, k);
                    let cy = coupling(y, x, dy, dx, 8.0e4, k);
                    dn += cx * tx[j] + cy * ty[j];
                    dux -= cx * p[j];
                    duy -= cy * p[j];
                }
                assert!((un[i] - dn).abs() < 1e-12 * scale, "{nx}x{ny} un {i}");
                assert!((ux[i] - dux).abs() < 1e-12 * scale, "{nx}x{ny} ux {i}");
                assert!((uy[i] - duy).abs() < 1e-12 * scale, "{nx}x{ny} uy {i}");
            }
            // Reciprocity: p·(A_n τ) = τ·(A_t p) with A_t = A_n^T.
            let lhs: f64 = p.iter().zip(&un).map(|(a, b)| a * b).sum();
            let rhs: f64 = tx
                .iter()
                .zip(&ux)
                .chain(ty.iter().zip(&uy))
                .map(|(a, b)| a * b)
                .sum();
            // u_t = -A^T... : with A_xn(x) = -A_nx(x) = A_nx(-x), the transpose.
            assert!(
                (lhs - rhs).abs() < 1e-12 * lhs.abs().max(rhs.abs()),
                "{lhs} {rhs}"
            );
        }
    }

    #[test]
    fn bad_input() {
        let grid = Grid2::centered(1.0, 1.0, 4, 4).unwrap();
        let m = KalkerMaterial {
            shear_modulus: 8.0e4,
            poisson_ratio: 0.3,
        };
        for k in [0.51, -0.6, f64::NAN, f64::INFINITY] {
            assert!(CouplingOperator::new(&grid, m, k).is_err(), "{k}");
        }
        let mut op = CouplingOperator::new(&grid, m, 0.1).unwrap();
        let mut u = vec![0.0; 16];
        assert!(op.normal(&[0.0; 15], &[0.0; 16], &mut u).is_err());
    }
}
