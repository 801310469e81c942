//! The elastic operator `u = K p` by FFT: plan once, apply many times without
//! allocating.
//!
//! **Free boundary** (an isolated contact): the pressure on the `nx × ny` grid is
//! zero-padded to `2nx × 2ny` and circularly convolved with Love's coefficients laid out
//! for the offsets `-nx..nx`, `-ny..ny`; the first `nx × ny` outputs are then exactly the
//! linear (non-periodic) convolution, the dense sum `u_i = Σ_j C_ij p_j`.
//!
//! **Periodic** (a rough surface repeated in both directions): no padding; the kernel is
//! the half-space's spectral compliance `2 / (E* |q|)` and the mean displacement is
//! zero (the `q = 0` term is dropped), as in the periodic solvers of the field.
//!
//! One application: a real FFT along `x` of the `ny` data rows only (the padded rows are
//! zero), then for each block of 8 spectral columns one cache-resident pass that gathers
//! the columns, transforms them along `y`, multiplies by the (real, symmetric) kernel
//! spectrum, transforms back and keeps the `ny` data rows, then an inverse real FFT along
//! `x` of the `ny` data rows. Rows and column blocks are shared among threads (rayon).
//! All buffers are allocated in [`ElasticOperator::new`].

use crate::error::{Error, Result};
use crate::geometry::Grid2;
use rayon::prelude::*;
use realfft::{ComplexToReal, RealFftPlanner, RealToComplex};
use rustfft::num_complex::Complex;
use rustfft::{Fft, FftPlanner};
use serde::{Deserialize, Serialize};
use std::sync::Arc;

use super::influence::quadrant_table;

/// How the grid's edges behave.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Boundary {
    /// An isolated contact on an unbounded half-space (zero padding to `2n`).
    #[default]
    Free,
    /// The grid is one period of a doubly periodic surface.
    Periodic,
}

/// Columns (or rows) handled together in the transposing passes: two cache lines of
/// `Complex<f64>`.
const BLOCK: usize = 8;

/// Per-task buffers, so that no pass allocates.
struct Workspace {
    /// One real row of the padded length.
    row: Vec<f64>,
    /// `BLOCK` spectral columns of the padded length (column pass) or `BLOCK` spectral
    /// rows (inverse row pass).
    block: Vec<Complex<f64>>,
    scratch: Vec<Complex<f64>>,
}

/// Threading of the operator: serial, or a pool of its own. The solver runs its whole
/// iteration inside the pool (see [`ElasticOperator::pool`]), so the serial passes between
/// two FFTs do not compete with the pool's workers for the cores.
enum Threads {
    Serial,
    Pool(Arc<rayon::ThreadPool>),
}

/// The planned elastic operator of one grid: `u = K p` \[mm\] for `p` \[MPa\].
pub struct ElasticOperator {
    nx: usize,
    ny: usize,
    mx: usize,
    my: usize,
    kx: usize,
    boundary: Boundary,
    r2c: Arc<dyn RealToComplex<f64>>,
    c2r: Arc<dyn ComplexToReal<f64>>,
    col_fwd: Arc<dyn Fft<f64>>,
    col_inv: Arc<dyn Fft<f64>>,
    /// Kernel spectrum, real, column-major `[k * my + j]`, including `1/(mx·my)`.
    kernel: Vec<f64>,
    /// Row spectra of the data rows, `[j * kx + k]`.
    rows: Vec<Complex<f64>>,
    /// Column results for the data rows, `[k * ny + j]`.
    cols: Vec<Complex<f64>>,
    work: Vec<Workspace>,
    rows_per_task: usize,
    cols_per_task: usize,
    threads: Threads,
}

impl std::fmt::Debug for ElasticOperator {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("ElasticOperator")
            .field("nx", &self.nx)
            .field("ny", &self.ny)
            .field("padded", &[self.mx, self.my])
            .field("boundary", &self.boundary)
            .field("tasks", &self.work.len())
            .finish()
    }
}

/// Offset of index `i` on a circle of length `m`: `0..=m/2` forward, the rest backward.
fn signed(i: usize, m: usize) -> f64 {
    if i <= m / 2 {
        i as f64
    } else {
        i as f64 - m as f64
    }
}

/// Grids below this many cells run on one thread even when threads are allowed: the
/// hand-over costs more than it saves (measured in benches/halfspace.rs).
const PARALLEL_MIN_CELLS: usize = 96 * 96;

impl ElasticOperator {
    /// Plan the operator for `grid`, contact modulus `e_star` \[MPa\] and `boundary`.
    /// `threads`: `Some(1)` runs serially, `Some(n)` builds a pool of `n` threads, `None`
    /// a pool of as many threads as rayon's global pool (all cores). Grids below 96 × 96
    /// cells always run serially.
    ///
    /// # Errors
    /// [`Error::InvalidInput`] for a non-positive modulus or `threads == Some(0)`.
    pub fn new(
        grid: &Grid2,
        e_star: f64,
        boundary: Boundary,
        threads: Option<usize>,
    ) -> Result<Self> {
        crate::error::positive_as("e_star", e_star, "a finite contact modulus > 0 MPa")?;
        let (nx, ny) = (grid.nx(), grid.ny());
        let (mx, my) = match boundary {
            Boundary::Free => (2 * nx, 2 * ny),
            Boundary::Periodic => (nx, ny),
        };
        let kx = mx / 2 + 1;
        let wanted = match threads {
            Some(0) => return Err(Error::invalid("threads", 0, ">= 1 thread, or unset")),
            Some(n) => n,
            None => rayon::current_num_threads(),
        };
        let threads = if wanted <= 1 || nx * ny < PARALLEL_MIN_CELLS {
            Threads::Serial
        } else {
            match rayon::ThreadPoolBuilder::new().num_threads(wanted).build() {
                Ok(pool) => Threads::Pool(Arc::new(pool)),
                Err(e) => {
                    return Err(Error::invalid(
                        "threads",
                        wanted,
                        format!("a usable count ({e})"),
                    ));
                }
            }
        };
        let n_threads = match &threads {
            Threads::Serial => 1,
            Threads::Pool(p) => p.current_num_threads(),
        };
        let mut real = RealFftPlanner::<f64>::new();
        let r2c = real.plan_fft_forward(mx);
        let c2r = real.plan_fft_inverse(mx);
        let mut planner = FftPlanner::<f64>::new();
        let col_fwd = planner.plan_fft_forward(my);
        let col_inv = planner.plan_fft_inverse(my);
        let scratch_len = r2c
            .get_scratch_len()
            .max(c2r.get_scratch_len())
            .max(col_fwd.get_inplace_scratch_len())
            .max(col_inv.get_inplace_scratch_len());
        // A few tasks per thread balance the load; one task when serial.
        let tasks = if n_threads == 1 { 1 } else { 4 * n_threads };
        let rows_per_task = ny.div_ceil(tasks).max(1);
        let cols_per_task = kx.div_ceil(tasks).div_ceil(BLOCK).max(1) * BLOCK;
        let n_work = tasks
            .max(ny.div_ceil(rows_per_task))
            .max(kx.div_ceil(cols_per_task));
        let work = (0..n_work)
            .map(|_| Workspace {
                row: vec![0.0; mx],
                block: vec![Complex::default(); BLOCK * my.max(kx)],
                scratch: vec![Complex::default(); scratch_len],
            })
            .collect();
        let mut op = ElasticOperator {
            nx,
            ny,
            mx,
            my,
            kx,
            boundary,
            r2c,
            c2r,
            col_fwd,
            col_inv,
            kernel: vec![0.0; kx * my],
            rows: vec![Complex::default(); ny * kx],
            cols: vec![Complex::default(); kx * ny],
            work,
            rows_per_task,
            cols_per_task,
            threads,
        };
        op.plan_kernel(grid.dx(), grid.dy(), e_star);
        Ok(op)
    }

    /// Fill the kernel spectrum.
    fn plan_kernel(&mut self, dx: f64, dy: f64, e_star: f64) {
        let (mx, my, kx) = (self.mx, self.my, self.kx);
        let norm = 1.0 / (mx * my) as f64;
        match self.boundary {
            Boundary::Free => {
                // Real-space kernel on the padded circle, transformed once.
                let (nx, ny) = (self.nx, self.ny);
                let quadrant = quadrant_table(nx, ny, dx, dy, e_star);
                let mut spec = vec![Complex::default(); my * kx];
                let mut row = vec![0.0; mx];
                let mut scratch = vec![Complex::default(); self.r2c.get_scratch_len()];
                for j in 0..my {
                    let jj = signed(j, my).abs() as usize;
                    let q = &quadrant[jj * (nx + 1)..(jj + 1) * (nx + 1)];
                    for (i, r) in row.iter_mut().enumerate() {
                        *r = q[signed(i, mx).abs() as usize];
                    }
                    // Lengths match the plan, so the transform cannot fail.
                    let _ = self.r2c.process_with_scratch(
                        &mut row,
                        &mut spec[j * kx..(j + 1) * kx],
                        &mut scratch,
                    );
                }
                let mut col = vec![Complex::default(); my];
                let mut cs = vec![Complex::default(); self.col_fwd.get_inplace_scratch_len()];
                for (k, kernel) in self.kernel.chunks_mut(my).enumerate() {
                    for (j, c) in col.iter_mut().enumerate() {
                        *c = spec[j * kx + k];
                    }
                    self.col_fwd.process_with_scratch(&mut col, &mut cs);
                    for (kv, c) in kernel.iter_mut().zip(&col) {
                        // The kernel is even in x and y: its spectrum is real.
                        *kv = c.re * norm;
                    }
                }
            }
            Boundary::Periodic => {
                let (lx, ly) = (self.nx as f64 * dx, self.ny as f64 * dy);
                let two_pi = 2.0 * std::f64::consts::PI;
                for k in 0..kx {
                    let qx = two_pi * k as f64 / lx;
                    for j in 0..my {
                        let qy = two_pi * signed(j, my) / ly;
                        let q = qx.hypot(qy);
                        self.kernel[k * my + j] = if q > 0.0 {
                            2.0 / (e_star * q) * norm
                        } else {
                            0.0
                        };
                    }
                }
            }
        }
    }

    /// The operator's thread pool, if it has one: run a whole solve inside it
    /// (`pool.install`) so that the serial work between FFTs runs on a pool thread.
    pub fn pool(&self) -> Option<Arc<rayon::ThreadPool>> {
        match &self.threads {
            Threads::Serial => None,
            Threads::Pool(p) => Some(Arc::clone(p)),
        }
    }

    /// Cells `[nx, ny]` of the grid.
    pub fn cells(&self) -> [usize; 2] {
        [self.nx, self.ny]
    }

    /// The boundary mode.
    pub fn boundary(&self) -> Boundary {
        self.boundary
    }

    /// Bytes held by the plan (kernel spectrum, transposition buffers, workspaces).
    pub fn memory_bytes(&self) -> usize {
        let c = std::mem::size_of::<Complex<f64>>();
        self.kernel.len() * 8
            + (self.rows.len() + self.cols.len()) * c
            + self
                .work
                .iter()
                .map(|w| w.row.len() * 8 + (w.block.len() + w.scratch.len()) * c)
                .sum::<usize>()
    }

    /// `u = K p`: the displacement \[mm\] of the two-body system for the cell pressures
    /// `p` \[MPa\] (both row-major, x fastest, length `nx·ny`). Allocates nothing.
    ///
    /// # Errors
    /// [`Error::InvalidInput`] when a length differs from `nx·ny`.
    pub fn apply(&mut self, p: &[f64], u: &mut [f64]) -> Result<()> {
        let n = self.nx * self.ny;
        for (field, len) in [("pressure", p.len()), ("displacement", u.len())] {
            if len != n {
                return Err(Error::invalid(
                    field,
                    format!("{len} values"),
                    format!("{n} values ({} x {} grid)", self.nx, self.ny),
                ));
            }
        }
        let ElasticOperator {
            nx,
            ny,
            mx,
            my,
            kx,
            r2c,
            c2r,
            col_fwd,
            col_inv,
            kernel,
            rows,
            cols,
            work,
            rows_per_task,
            cols_per_task,
            threads,
            ..
        } = self;
        let (nx, ny, mx, my, kx) = (*nx, *ny, *mx, *my, *kx);
        let (rpt, cpt) = (*rows_per_task, *cols_per_task);
        let forward = |((spec, input), w): ((&mut [Complex<f64>], &[f64]), &mut Workspace)| {
            for (s, x) in spec.chunks_mut(kx).zip(input.chunks(nx)) {
                if x.iter().all(|v| *v == 0.0) {
                    // Rows outside the loaded set are common (the search direction is
                    // zero off the contact): their spectrum is zero.
                    s.fill(Complex::default());
                    continue;
                }
                w.row[..nx].copy_from_slice(x);
                w.row[nx..].fill(0.0);
                let _ = r2c.process_with_scratch(&mut w.row, s, &mut w.scratch);
            }
        };
        match threads {
            Threads::Serial => rows
                .chunks_mut(rpt * kx)
                .zip(p.chunks(rpt * nx))
                .zip(work.iter_mut())
                .for_each(forward),
            Threads::Pool(pool) => pool.install(|| {
                rows.par_chunks_mut(rpt * kx)
                    .zip(p.par_chunks(rpt * nx))
                    .zip(work.par_iter_mut())
                    .for_each(forward)
            }),
        }
        let rows: &[Complex<f64>] = rows;
        let kernel: &[f64] = kernel;
        let column = |((t, out), w): ((usize, &mut [Complex<f64>]), &mut Workspace)| {
            let k_first = t * cpt;
            let n_cols = out.len() / ny;
            for b0 in (0..n_cols).step_by(BLOCK) {
                let nb = BLOCK.min(n_cols - b0);
                let k0 = k_first + b0;
                let block = &mut w.block[..nb * my];
                for j in 0..ny {
                    let src = &rows[j * kx + k0..j * kx + k0 + nb];
                    for (b, v) in src.iter().enumerate() {
                        block[b * my + j] = *v;
                    }
                }
                for b in 0..nb {
                    let col = &mut block[b * my..(b + 1) * my];
                    col[ny..].fill(Complex::default());
                    col_fwd.process_with_scratch(col, &mut w.scratch);
                    let ker = &kernel[(k0 + b) * my..(k0 + b + 1) * my];
                    for (c, k) in col.iter_mut().zip(ker) {
                        *c *= *k;
                    }
                    col_inv.process_with_scratch(col, &mut w.scratch);
                    out[(b0 + b) * ny..(b0 + b + 1) * ny].copy_from_slice(&col[..ny]);
                }
            }
        };
        match threads {
            Threads::Serial => cols
                .chunks_mut(cpt * ny)
                .enumerate()
                .zip(work.iter_mut())
                .for_each(column),
            Threads::Pool(pool) => pool.install(|| {
                cols.par_chunks_mut(cpt * ny)
                    .enumerate()
                    .zip(work.par_iter_mut())
                    .for_each(column)
            }),
        }
        let cols: &[Complex<f64>] = cols;
        let even = mx % 2 == 0;
        let inverse = |((t, out), w): ((usize, &mut [f64]), &mut Workspace)| {
            let j_first = t * rpt;
            let n_rows = out.len() / nx;
            for b0 in (0..n_rows).step_by(BLOCK) {
                let nb = BLOCK.min(n_rows - b0);
                let j0 = j_first + b0;
                let block = &mut w.block[..nb * kx];
                for k in 0..kx {
                    let src = &cols[k * ny + j0..k * ny + j0 + nb];
                    for (b, v) in src.iter().enumerate() {
                        block[b * kx + k] = *v;
                    }
                }
                for b in 0..nb {
                    let spec = &mut block[b * kx..(b + 1) * kx];
                    // Exactly real in exact arithmetic; drop the round-off.
                    spec[0].im = 0.0;
                    if even {
                        spec[kx - 1].im = 0.0;
                    }
                    let _ = c2r.process_with_scratch(spec, &mut w.row, &mut w.scratch);
                    out[(b0 + b) * nx..(b0 + b + 1) * nx].copy_from_slice(&w.row[..nx]);
                }
            }
        };
        match threads {
            Threads::Serial => u
                .chunks_mut(rpt * nx)
                .enumerate()
                .zip(work.iter_mut())
                .for_each(inverse),
            Threads::Pool(pool) => pool.install(|| {
                u.par_chunks_mut(rpt * nx)
                    .enumerate()
                    .zip(work.par_iter_mut())
                    .for_each(inverse)
            }),
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::halfspace::influence::dense_matrix;

    fn pseudo_random(n: usize) -> Vec<f64> {
        let mut s = 12345u64;
        (0..n)
            .map(|_| {
                s = s
                    .wrapping_mul(6364136223846793005)
                    .wrapping_add(1442695040888963407);
                (s >> 11) as f64 / (1u64 << 53) as f64
            })
            .collect()
    }

    #[test]
    fn fft_equals_the_dense_sum() {
        for &(nx, ny, threads) in &[(7, 5, Some(1)), (12, 9, None), (16, 16, Some(2))] {
            let grid = Grid2::centered(0.7, 0.4, nx, ny).unwrap();
            let e = 115_384.6;
            let mut op = ElasticOperator::new(&grid, e, Boundary::Free, threads).unwrap();
            let p = pseudo_random(nx * ny);
            let mut u = vec![0.0; nx * ny];
            op.apply(&p, &mut u).unwrap();
            let m = dense_matrix(nx, ny, grid.dx(), grid.dy(), e);
            let n = nx * ny;
            let scale = u.iter().fold(0.0f64, |a, v| a.max(v.abs()));
            for i in 0..n {
                let direct: f64 = (0..n).map(|j| m[i * n + j] * p[j]).sum();
                assert!(
                    (u[i] - direct).abs() < 1e-12 * scale,
                    "{nx}x{ny} cell {i}: {} vs {direct}",
                    u[i]
                );
            }
        }
    }

    #[test]
    fn threaded_equals_serial() {
        let grid = Grid2::centered(1.0, 1.0, 128, 100).unwrap();
        let p = pseudo_random(grid.len());
        let mut a = vec![0.0; grid.len()];
        let mut b = vec![0.0; grid.len()];
        ElasticOperator::new(&grid, 1e5, Boundary::Free, Some(1))
            .unwrap()
            .apply(&p, &mut a)
            .unwrap();
        ElasticOperator::new(&grid, 1e5, Boundary::Free, Some(2))
            .unwrap()
            .apply(&p, &mut b)
            .unwrap();
        for (x, y) in a.iter().zip(&b) {
            assert!((x - y).abs() < 1e-13 * x.abs().max(1e-12));
        }
    }

    #[test]
    fn periodic_mode_has_zero_mean_and_the_spectral_compliance() {
        // A single cosine pressure p = cos(q x) displaces the surface by 2 cos(q x)/(E* q).
        let (nx, ny) = (64, 8);
        let grid = Grid2::centered(2.0, 0.25, nx, ny).unwrap();
        let q = 2.0 * std::f64::consts::PI * 3.0 / 4.0; // three waves over 4 mm
        let p: Vec<f64> = grid.points().map(|(x, _)| (q * x).cos()).collect();
        let mut u = vec![0.0; grid.len()];
        let e = 2e5;
        ElasticOperator::new(&grid, e, Boundary::Periodic, Some(1))
            .unwrap()
            .apply(&p, &mut u)
            .unwrap();
        for (pi, ui) in p.iter().zip(&u) {
            assert!((ui - 2.0 * pi / (e * q)).abs() < 1e-12 / (e * q));
        }
    }

    #[test]
    fn wrong_lengths_are_errors() {
        let grid = Grid2::centered(1.0, 1.0, 8, 8).unwrap();
        let mut op = ElasticOperator::new(&grid, 1e5, Boundary::Free, None).unwrap();
        let mut u = vec![0.0; 64];
        let err = op.apply(&[0.0; 63], &mut u).unwrap_err();
        assert_eq!(err.field(), Some("pressure"));
        assert!(ElasticOperator::new(&grid, -1.0, Boundary::Free, None).is_err());
        assert!(ElasticOperator::new(&grid, 1.0, Boundary::Free, Some(0)).is_err());
    }
}
