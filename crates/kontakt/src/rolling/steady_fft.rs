//! The steady rolling operator `B = (I − S) A` by FFT, both traction components at once.
//!
//! # Formula
//! With `A` the tangential operator ([`super::TangentialOperator`]) and `S` the shift by
//! one cell in `+x`, `(B τ)_i = u_i − u_{i+1}` \[mm\] is itself a convolution, with the
//! kernel
//!
//! ```text
//! b_ab(m, l) = A_ab(m, l) − A_ab(m + 1, l),   a, b ∈ {x, y},
//! ```
//!
//! (`b_yx = b_xy` since `A_yx = A_xy`) over the offsets `|m| < nx`, `|l| < ny`. It is
//! applied by a circular convolution of period `mx × my` with `mx >= 2nx − 1`,
//! `my >= 2ny − 1` rounded up to a product of 2, 3 and 5 (exact on the grid: no
//! wrap-around reaches a grid cell), real FFT along `x`, complex along `y`. Both
//! components are transformed once and combined in the spectral domain
//! (`S_x = B_xx T_x + B_xy T_y`, `S_y = B_xy T_x + B_yy T_y`): two forward and two
//! inverse transforms per application, where applying `A` and differencing takes eight.
//! The kernel is not even in `x`, so its spectra are complex.
//!
//! # References
//! Kalker (1990) ch. 5 (influence numbers); the FFT convolution as in docs/halfspace.md.

use super::influence::quadrant_tables;
use crate::halfspace::PaddedFfts;
use realfft::{ComplexToReal, RealToComplex};
use rustfft::Fft;
use rustfft::num_complex::Complex;
use std::sync::Arc;

/// The smallest `n >= m` with no prime factor above 5.
fn smooth_at_least(m: usize) -> usize {
    let mut n = m.max(1);
    loop {
        let mut k = n;
        for p in [2, 3, 5] {
            while k.is_multiple_of(p) {
                k /= p;
            }
        }
        if k == 1 {
            return n;
        }
        n += 1;
    }
}

/// `s = B τ` on one grid (see the module docs); allocates nothing per application.
pub(super) struct SteadyFft {
    nx: usize,
    ny: usize,
    mx: usize,
    my: usize,
    kx: usize,
    r2c: Arc<dyn RealToComplex<f64>>,
    c2r: Arc<dyn ComplexToReal<f64>>,
    col_fwd: Arc<dyn Fft<f64>>,
    col_inv: Arc<dyn Fft<f64>>,
    /// Spectra of `b_xx`, `b_yy`, `b_xy`, scaled by `1/(mx my)`, stored `[k * my + l]`.
    kernel: [Vec<Complex<f64>>; 3],
    row: Vec<f64>,
    spec: Vec<Complex<f64>>,
    cols: [Vec<Complex<f64>>; 2],
    scratch: Vec<Complex<f64>>,
}

impl std::fmt::Debug for SteadyFft {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("SteadyFft")
            .field("cells", &[self.nx, self.ny])
            .field("period", &[self.mx, self.my])
            .finish()
    }
}

impl SteadyFft {
    /// Plan for `nx × ny` cells of `dx × dy` \[mm\] and Kalker's combined `g` \[MPa\], `nu`.
    pub(super) fn new(nx: usize, ny: usize, dx: f64, dy: f64, g: f64, nu: f64) -> Self {
        let mx = smooth_at_least(2 * nx - 1).max(2);
        let my = smooth_at_least(2 * ny.max(1) - 1).max(2);
        let kx = mx / 2 + 1;
        let PaddedFfts {
            r2c,
            c2r,
            col_fwd,
            col_inv,
            scratch_len,
        } = PaddedFfts::plan(mx, my);
        let [qxx, qyy, qxy] = quadrant_tables(nx, ny, dx, dy, g, nu);
        let q = |t: &[f64], m: isize, l: isize, odd: bool| {
            let (am, al) = (m.unsigned_abs(), l.unsigned_abs());
            if am > nx || al > ny {
                return 0.0;
            }
            let v = t[al * (nx + 1) + am];
            if odd {
                v * (m.signum() * l.signum()) as f64
            } else {
                v
            }
        };
        let mut fft = SteadyFft {
            nx,
            ny,
            mx,
            my,
            kx,
            r2c,
            c2r,
            col_fwd,
            col_inv,
            kernel: [
                vec![Complex::default(); kx * my],
                vec![Complex::default(); kx * my],
                vec![Complex::default(); kx * my],
            ],
            row: vec![0.0; mx],
            spec: vec![Complex::default(); kx * my],
            cols: [
                vec![Complex::default(); kx * my],
                vec![Complex::default(); kx * my],
            ],
            scratch: vec![Complex::default(); scratch_len],
        };
        let scale = 1.0 / (mx * my) as f64;
        let (nxi, nyi) = (nx as isize, ny as isize);
        let mut full = vec![0.0; mx * my];
        for (which, (table, odd)) in [(&qxx, false), (&qyy, false), (&qxy, true)]
            .into_iter()
            .enumerate()
        {
            full.fill(0.0);
            for l in -(nyi - 1)..nyi {
                for m in -(nxi - 1)..nxi {
                    let b = q(table, m, l, odd) - q(table, m + 1, l, odd);
                    let (cm, cl) = (m.rem_euclid(mx as isize), l.rem_euclid(my as isize));
                    full[cl as usize * mx + cm as usize] = b * scale;
                }
            }
            // Rows (all my of them), then columns.
            for l in 0..my {
                fft.row.copy_from_slice(&full[l * mx..(l + 1) * mx]);
                fft.r2c
                    .process_with_scratch(
                        &mut fft.row,
                        &mut fft.spec[l * kx..(l + 1) * kx],
                        &mut fft.scratch,
                    )
                    .expect("invariant: lengths match the plan");
            }
            let ker = &mut fft.kernel[which];
            for l in 0..my {
                for k in 0..kx {
                    ker[k * my + l] = fft.spec[l * kx + k];
                }
            }
            fft.col_fwd.process_with_scratch(ker, &mut fft.scratch);
        }
        fft
    }

    /// `[s_x, s_y] = B [τ_x, τ_y]` \[mm\] for grid fields (row-major, x fastest).
    pub(super) fn apply(&mut self, tau: [&[f64]; 2], out: [&mut [f64]; 2]) {
        let (nx, ny, my, kx) = (self.nx, self.ny, self.my, self.kx);
        for (c, t) in tau.iter().enumerate() {
            let cols = &mut self.cols[c];
            for j in 0..ny {
                let x = &t[j * nx..(j + 1) * nx];
                let s = &mut self.spec[j * kx..(j + 1) * kx];
                if x.iter().all(|v| *v == 0.0) {
                    s.fill(Complex::default());
                } else {
                    self.row[..nx].copy_from_slice(x);
                    self.row[nx..].fill(0.0);
                    self.r2c
                        .process_with_scratch(&mut self.row, s, &mut self.scratch)
                        .expect("invariant: lengths match the plan");
                }
            }
            for k in 0..kx {
                let col = &mut cols[k * my..(k + 1) * my];
                for (j, c) in col[..ny].iter_mut().enumerate() {
                    *c = self.spec[j * kx + k];
                }
                col[ny..].fill(Complex::default());
            }
            self.col_fwd.process_with_scratch(cols, &mut self.scratch);
        }
        {
            let [cx, cy] = &mut self.cols;
            let [kxx, kyy, kxy] = &self.kernel;
            for i in 0..kx * my {
                let (a, b) = (cx[i], cy[i]);
                cx[i] = kxx[i] * a + kxy[i] * b;
                cy[i] = kxy[i] * a + kyy[i] * b;
            }
        }
        let even = self.mx.is_multiple_of(2);
        for (c, o) in out.into_iter().enumerate() {
            let cols = &mut self.cols[c];
            self.col_inv.process_with_scratch(cols, &mut self.scratch);
            for j in 0..ny {
                let s = &mut self.spec[..kx];
                for (k, v) in s.iter_mut().enumerate() {
                    *v = cols[k * my + j];
                }
                // Exactly real in exact arithmetic; drop the round-off.
                s[0].im = 0.0;
                if even {
                    s[kx - 1].im = 0.0;
                }
                self.c2r
                    .process_with_scratch(s, &mut self.row, &mut self.scratch)
                    .expect("invariant: lengths match the plan");
                o[j * nx..(j + 1) * nx].copy_from_slice(&self.row[..nx]);
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geometry::Grid2;
    use crate::rolling::{KalkerMaterial, TangentialOperator};

    #[test]
    fn smooth_sizes() {
        assert_eq!(smooth_at_least(69), 72);
        assert_eq!(smooth_at_least(127), 128);
        assert_eq!(smooth_at_least(21), 24);
        assert_eq!(smooth_at_least(1), 1);
    }

    /// `B τ` equals `A τ` differenced upwind, on grids with odd and even periods.
    #[test]
    fn equals_the_differenced_operator() {
        for &(nx, ny, nu) in &[(7, 5, 0.3), (12, 9, 0.0), (11, 16, 0.25)] {
            let grid = Grid2::centered(0.7, 0.4, nx, ny).unwrap();
            let m = KalkerMaterial {
                shear_modulus: 8.0e4,
                poisson_ratio: nu,
            };
            let mut op = TangentialOperator::new(&grid, m, Some(1)).unwrap();
            let mut fft = SteadyFft::new(nx, ny, grid.dx(), grid.dy(), 8.0e4, nu);
            let n = nx * ny;
            // Tractions zero in the leading-edge column (as in steady rolling).
            let t = |seed: f64| -> Vec<f64> {
                (0..n)
                    .map(|c| {
                        if c % nx == nx - 1 {
                            0.0
                        } else {
                            ((c as f64 + seed) * 1.7).sin()
                        }
                    })
                    .collect()
            };
            let (tx, ty) = (t(0.3), t(2.1));
            let (mut ux, mut uy) = (vec![0.0; n], vec![0.0; n]);
            op.apply(&tx, &ty, &mut ux, &mut uy).unwrap();
            let (mut sx, mut sy) = (vec![0.0; n], vec![0.0; n]);
            fft.apply([&tx, &ty], [&mut sx, &mut sy]);
            let scale = ux.iter().chain(&uy).fold(0.0f64, |a, v| a.max(v.abs()));
            for c in 0..n {
                if c % nx == nx - 1 {
                    continue;
                }
                let (ex, ey) = (ux[c] - ux[c + 1], uy[c] - uy[c + 1]);
                assert!((sx[c] - ex).abs() < 1e-12 * scale, "{nx}x{ny} x {c}");
                assert!((sy[c] - ey).abs() < 1e-12 * scale, "{nx}x{ny} y {c}");
            }
        }
    }
}
