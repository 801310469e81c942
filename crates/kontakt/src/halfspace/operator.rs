//! The elastic operator `u = K p` by FFT: plan once, apply many times without
//! allocating, share the plan.
//!
//! The design follows RustFFT's planner → immutable plan → execute with the caller's
//! scratch: a [`HalfSpacePlan`] holds everything that depends on the grid only (FFT plans,
//! kernel spectrum, thread pool) and is immutable, `Send + Sync` and shared behind an
//! [`Arc`]; an [`OperatorScratch`] holds the work arrays of one caller, so that any number
//! of solvers (on any threads) apply one plan at once
//! ([`HalfSpacePlan::apply_with_scratch`]). [`ElasticOperator`] bundles a plan with a
//! scratch of its own. [`super::HalfSpacePlanner`] caches plans by grid.
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
//! All buffers are allocated with the [`OperatorScratch`].

use crate::error::{Error, Result};
use crate::geometry::Grid2;
use rayon::prelude::*;
use realfft::{ComplexToReal, RealFftPlanner, RealToComplex};
use rustfft::num_complex::Complex;
use rustfft::{Fft, FftPlanner};
use std::sync::Arc;

use super::influence::quadrant_table;

/// How the grid's edges behave.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default)]
#[cfg_attr(
    feature = "serde",
    derive(serde::Serialize, serde::Deserialize, schemars::JsonSchema)
)]
#[cfg_attr(feature = "serde", serde(rename_all = "snake_case"))]
pub enum Boundary {
    /// An isolated contact on an unbounded half-space (zero padding to `2n`).
    #[default]
    Free,
    /// The grid is one period of a doubly periodic surface.
    Periodic,
}

/// How a free-boundary kernel given on one quadrant of offsets extends to the others.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Parity {
    /// `k(-x, y) = k(x, -y) = k(x, y)` (Love's and Cerruti's direct coefficients).
    Even,
    /// `k(-x, y) = k(x, -y) = -k(x, y)` (Cerruti's cross coefficients).
    OddOdd,
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

/// Threading of a plan: serial, or a pool of its own.
///
/// The pool lives in the plan, not in the solver: the plan decides how the passes are
/// split into tasks (`rows_per_task`, `cols_per_task`, the number of workspaces), which
/// must match the pool's size, and solvers that share a plan then share one pool instead
/// of starting `threads` OS threads each (four solvers of a multi-body model on a 2-core
/// machine would otherwise run 4 pools of 2 threads). A solver runs its whole iteration
/// inside this pool ([`HalfSpacePlan::pool`]), so the serial passes between two FFTs do
/// not compete with the pool's workers for the cores. `rayon::ThreadPool` is
/// `Send + Sync`, and concurrent `install`s from several threads are queued by rayon.
#[derive(Clone)]
enum Threads {
    Serial,
    Pool(Arc<rayon::ThreadPool>),
}

/// The sizes of the work arrays a plan needs; a scratch fits a plan when they are equal.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
struct Layout {
    /// Row spectra (and column results): `ny · kx`.
    spectra: usize,
    /// Workspaces: one per task.
    tasks: usize,
    /// Length of a workspace's real row (`mx`).
    row: usize,
    /// Length of a workspace's block (`BLOCK · max(my, kx)`).
    block: usize,
    /// Length of a workspace's FFT scratch.
    fft_scratch: usize,
}

/// The immutable plan of the elastic operator of one grid: `u = K p` \[mm\] for `p`
/// \[MPa\], for the cells and spacing \[mm\] of a grid, one boundary mode and one
/// contact modulus E* \[MPa\].
///
/// It holds the FFT plans, the kernel spectrum and the thread pool, and no work array:
/// it is `Send + Sync`, shared behind an [`Arc`] by any number of solvers, each applying
/// it with its own [`OperatorScratch`] ([`HalfSpacePlan::apply_with_scratch`]). Plan it
/// with [`HalfSpacePlan::new`], or through a [`super::HalfSpacePlanner`] that returns the
/// same plan for equal grids.
///
/// The kernel is built for the plan's E*, exactly as a solver of its own would build it,
/// so a shared plan gives bit-identical results. (The kernel is proportional to 1/E*: a
/// plan at unit E* scaled per body would serve every material pair, but it would change
/// the last bits of the results, so it is not done.)
pub struct HalfSpacePlan {
    grid: Grid2,
    e_star: f64,
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
    rows_per_task: usize,
    cols_per_task: usize,
    layout: Layout,
    /// The thread count asked for (`None` resolved to rayon's), before the small-grid
    /// rule: part of the planner's key.
    threads_requested: usize,
    threads: Threads,
    /// The FFT preconditioner of this operator, planned on first use and shared by the
    /// solvers on this plan.
    preconditioner: std::sync::OnceLock<Arc<HalfSpacePlan>>,
    /// Whether the kernel is Love's influence coefficients on a free boundary (planned by
    /// [`HalfSpacePlan::new`]), whose table [`HalfSpacePlan::influence_rows`] gives.
    love: bool,
    /// Love's coefficients, rows mirrored, made on first use.
    quadrant: std::sync::OnceLock<Vec<f64>>,
}

impl std::fmt::Debug for HalfSpacePlan {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("HalfSpacePlan")
            .field("nx", &self.nx)
            .field("ny", &self.ny)
            .field("padded", &[self.mx, self.my])
            .field("spacing", &[self.grid.dx(), self.grid.dy()])
            .field("boundary", &self.boundary)
            .field("e_star", &self.e_star)
            .field("threads", &self.threads())
            .field("tasks", &self.layout.tasks)
            .finish()
    }
}

/// The work arrays of one caller of a [`HalfSpacePlan`]: row spectra, column results
/// and one workspace per task. Make it with [`HalfSpacePlan::scratch`]; it fits every
/// plan of the same cells, boundary and threads.
pub struct OperatorScratch {
    layout: Layout,
    /// Row spectra of the data rows, `[j * kx + k]`.
    rows: Vec<Complex<f64>>,
    /// Column results for the data rows, `[k * ny + j]`.
    cols: Vec<Complex<f64>>,
    work: Vec<Workspace>,
}

impl std::fmt::Debug for OperatorScratch {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("OperatorScratch")
            .field("layout", &self.layout)
            .finish()
    }
}

impl OperatorScratch {
    /// Bytes held by the work arrays.
    pub fn memory_bytes(&self) -> usize {
        let c = std::mem::size_of::<Complex<f64>>();
        (self.rows.len() + self.cols.len()) * c
            + self
                .work
                .iter()
                .map(|w| w.row.len() * 8 + (w.block.len() + w.scratch.len()) * c)
                .sum::<usize>()
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

/// The thread count a request resolves to: `Some(n)` is `n`, `None` rayon's current
/// count (all cores, or the size of the pool the caller runs in).
///
/// # Errors
/// [`Error::InvalidInput`] for `Some(0)` or more than [`crate::MAX_THREADS`].
pub(super) fn resolve_threads(threads: Option<usize>) -> Result<usize> {
    match threads {
        Some(n) if !(1..=crate::MAX_THREADS).contains(&n) => Err(Error::invalid(
            "threads",
            n,
            "1 <= threads <= 256 (kontakt::MAX_THREADS), or unset for all cores",
        )),
        Some(n) => Ok(n),
        None => Ok(rayon::current_num_threads()),
    }
}

impl HalfSpacePlan {
    /// Plan the operator for `grid` \[mm\], contact modulus `e_star` \[MPa\] and
    /// `boundary`. `threads`: `Some(1)` runs serially, `Some(n)` builds a pool of `n`
    /// threads, `None` a pool of as many threads as rayon's global pool (all cores).
    /// Grids below 96 × 96 cells always run serially.
    ///
    /// # Errors
    /// [`Error::InvalidInput`] for a non-positive modulus or `threads` outside 1..=[`crate::MAX_THREADS`].
    pub fn new(
        grid: &Grid2,
        e_star: f64,
        boundary: Boundary,
        threads: Option<usize>,
    ) -> Result<Arc<Self>> {
        crate::error::positive_as("e_star", e_star, "a finite contact modulus > 0 MPa")?;
        let wanted = resolve_threads(threads)?;
        Self::build(grid, e_star, boundary, wanted).map(Arc::new)
    }

    /// Plan for a resolved thread count `wanted >= 1` and a checked modulus.
    pub(super) fn build(
        grid: &Grid2,
        e_star: f64,
        boundary: Boundary,
        wanted: usize,
    ) -> Result<Self> {
        let (nx, ny) = (grid.nx(), grid.ny());
        let (mx, my) = match boundary {
            Boundary::Free => (2 * nx, 2 * ny),
            Boundary::Periodic => (nx, ny),
        };
        let threads = Self::threads_for(nx, ny, wanted)?;
        let mut plan = Self::layout_on(grid, e_star, mx, my, boundary, wanted, threads);
        plan.plan_kernel(grid.dx(), grid.dy(), e_star);
        plan.love = boundary == Boundary::Free;
        Ok(plan)
    }

    /// The threading of a plan of `nx × ny` cells for a resolved count `wanted >= 1`.
    fn threads_for(nx: usize, ny: usize, wanted: usize) -> Result<Threads> {
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
        Ok(threads)
    }

    /// A free-boundary plan whose kernel is given by the caller: `quadrant[j * (nx + 1)
    /// + i]` is the displacement \[mm\] at the offset `(i dx, j dy)`, `i = 0..=nx`,
    /// `j = 0..=ny`, per unit traction \[MPa\] on a cell, extended to negative offsets
    /// by `parity`. `modulus` \[MPa\] is recorded as the plan's modulus (it does not
    /// enter the kernel). Used by the tangential (Cerruti) operator of
    /// [`crate::rolling`]; such a plan has no preconditioner of its own.
    ///
    /// # Errors
    /// [`Error::InvalidInput`] for `threads` outside 1..=[`crate::MAX_THREADS`] or a
    /// quadrant of the wrong length.
    pub(crate) fn from_quadrant(
        grid: &Grid2,
        modulus: f64,
        quadrant: &[f64],
        parity: Parity,
        threads: Option<usize>,
    ) -> Result<Arc<Self>> {
        let wanted = resolve_threads(threads)?;
        let (nx, ny) = (grid.nx(), grid.ny());
        if quadrant.len() != (nx + 1) * (ny + 1) {
            return Err(Error::invalid(
                "quadrant",
                format!("{} values", quadrant.len()),
                format!("{} values ((nx + 1) (ny + 1))", (nx + 1) * (ny + 1)),
            ));
        }
        let threads = Self::threads_for(nx, ny, wanted)?;
        let mut plan = Self::layout_on(
            grid,
            modulus,
            2 * nx,
            2 * ny,
            Boundary::Free,
            wanted,
            threads,
        );
        plan.fill_free_kernel(quadrant, parity);
        Ok(Arc::new(plan))
    }

    /// The eigenvalues \[mm/MPa\] of the circulant operator the plan applies on its
    /// padded grid (the kernel spectrum, one per wave vector of the half spectrum). The
    /// operator on the `nx × ny` cells is a principal block of that circulant, so their
    /// range bounds its eigenvalues.
    pub(crate) fn spectrum(&self) -> impl Iterator<Item = f64> + '_ {
        let scale = (self.mx * self.my) as f64;
        self.kernel.iter().map(move |k| k * scale)
    }

    /// The bytes a plan of `nx × ny` cells (`boundary`) and one [`OperatorScratch`] of it
    /// will hold, on `threads` resolved threads, counted from the layout
    /// [`HalfSpacePlan::layout_on`] makes before anything is allocated: the kernel spectrum
    /// (`kx·my` f64), the row spectra and column results (`2·ny·kx` complex) and one
    /// workspace per task (a real row of `mx`, a block of `BLOCK·max(my, kx)` complex and
    /// an FFT scratch, bounded here by `4·max(mx, my)` complex). Returns `(plan, scratch)`.
    pub(crate) fn estimate_bytes(
        nx: usize,
        ny: usize,
        boundary: Boundary,
        threads: usize,
    ) -> (u64, u64) {
        // In f64, whose cast to u64 saturates: an absurd grid gives u64::MAX, not an
        // overflow (exact below 2^53 bytes).
        let (nx, ny) = (nx as f64, ny as f64);
        let (mx, my) = match boundary {
            Boundary::Free => (2.0 * nx, 2.0 * ny),
            Boundary::Periodic => (nx, ny),
        };
        let serial = threads <= 1 || nx * ny < PARALLEL_MIN_CELLS as f64;
        let kx = (mx / 2.0).floor() + 1.0;
        let c = std::mem::size_of::<Complex<f64>>() as f64;
        let tasks = if serial { 1.0 } else { 4.0 * threads as f64 };
        let workspace = 8.0 * mx + c * (BLOCK as f64 * my.max(kx) + 4.0 * mx.max(my));
        (
            (8.0 * kx * my) as u64,
            (2.0 * c * ny * kx + tasks * workspace) as u64,
        )
    }

    /// The FFT plans, task split and an empty kernel for a `mx × my` transform of the
    /// grid's data on `threads`.
    fn layout_on(
        grid: &Grid2,
        e_star: f64,
        mx: usize,
        my: usize,
        boundary: Boundary,
        wanted: usize,
        threads: Threads,
    ) -> Self {
        let (nx, ny) = (grid.nx(), grid.ny());
        let kx = mx / 2 + 1;
        let n_threads = match &threads {
            Threads::Serial => 1,
            Threads::Pool(p) => p.current_num_threads(),
        };
        let PaddedFfts {
            r2c,
            c2r,
            col_fwd,
            col_inv,
            scratch_len,
        } = PaddedFfts::plan(mx, my);
        // A few tasks per thread balance the load; one task when serial.
        let tasks = if n_threads == 1 { 1 } else { 4 * n_threads };
        let rows_per_task = ny.div_ceil(tasks).max(1);
        let cols_per_task = kx.div_ceil(tasks).div_ceil(BLOCK).max(1) * BLOCK;
        let n_work = tasks
            .max(ny.div_ceil(rows_per_task))
            .max(kx.div_ceil(cols_per_task));
        let layout = Layout {
            spectra: ny * kx,
            tasks: n_work,
            row: mx,
            block: BLOCK * my.max(kx),
            fft_scratch: scratch_len,
        };
        HalfSpacePlan {
            grid: *grid,
            e_star,
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
            rows_per_task,
            cols_per_task,
            layout,
            threads_requested: wanted,
            threads,
            preconditioner: std::sync::OnceLock::new(),
            love: false,
            quadrant: std::sync::OnceLock::new(),
        }
    }

    /// The influence coefficients \[mm/MPa\] of a free-boundary plan of Love's kernel,
    /// the table the kernel spectrum was made from, with each row mirrored: row `j`
    /// (`2 nx − 1` values) holds the offsets `(i dx, j dy)` for `i = −(nx − 1)..nx`, so
    /// that one cell's displacement along a grid row is one contiguous slice. Made on
    /// first use and shared; `None` for other plans. For displacement updates from a few
    /// cells.
    pub(super) fn influence_rows(&self) -> Option<&[f64]> {
        self.love.then(|| {
            self.quadrant
                .get_or_init(|| {
                    let (nx, ny) = (self.nx, self.ny);
                    let q = quadrant_table(nx, ny, self.grid.dx(), self.grid.dy(), self.e_star);
                    let w = 2 * nx - 1;
                    let mut rows = vec![0.0; w * ny];
                    for (row, qj) in rows.chunks_exact_mut(w).zip(q.chunks_exact(nx + 1)) {
                        for (k, v) in row.iter_mut().enumerate() {
                            *v = qj[k.abs_diff(nx - 1)];
                        }
                    }
                    rows
                })
                .as_slice()
        })
    }

    /// The FFT preconditioner of the constrained conjugate gradients (Vollebregt 2014;
    /// docs/halfspace.md §9): a circulant operator on the unpadded `nx × ny` grid, on this
    /// plan's threads, whose symbol is the inverse of this operator's.
    ///
    /// - Periodic: the inverse of the spectral compliance, `E*|q|/2`, exact on the grid.
    /// - Free: the inverse of Strang's circulant of the influence coefficients (the
    ///   coefficients of the offsets `-n/2..n/2` wrapped on the `nx × ny` circle), which
    ///   is positive: the sum of a decaying `1/r` kernel over a window.
    ///
    /// The mean (`q = 0`) term is zero: the solver deflates the mean itself.
    /// Planned once per plan (on first use) and shared.
    pub(super) fn preconditioner(&self) -> Arc<Self> {
        Arc::clone(
            self.preconditioner
                .get_or_init(|| Arc::new(self.plan_preconditioner())),
        )
    }

    fn plan_preconditioner(&self) -> Self {
        let grid = &self.grid;
        let (nx, ny) = (self.nx, self.ny);
        let mut plan = Self::layout_on(
            grid,
            self.e_star,
            nx,
            ny,
            Boundary::Periodic,
            self.threads_requested,
            self.threads.clone(),
        );
        let kx = plan.kx;
        let norm = 1.0 / (nx * ny) as f64;
        match self.boundary {
            Boundary::Periodic => {
                // The same wave vectors as this plan's kernel: invert it.
                for (m, &c) in plan.kernel.iter_mut().zip(&self.kernel) {
                    *m = if c > 0.0 { norm * norm / c } else { 0.0 };
                }
            }
            Boundary::Free => {
                let quadrant = quadrant_table(nx, ny, grid.dx(), grid.dy(), self.e_star);
                let mut spec = vec![Complex::default(); ny * kx];
                let mut row = vec![0.0; nx];
                let mut scratch = vec![Complex::default(); plan.r2c.get_scratch_len()];
                for j in 0..ny {
                    let jj = signed(j, ny).abs() as usize;
                    let q = &quadrant[jj * (nx + 1)..(jj + 1) * (nx + 1)];
                    for (i, r) in row.iter_mut().enumerate() {
                        *r = q[signed(i, nx).abs() as usize];
                    }
                    plan.r2c
                        .process_with_scratch(
                            &mut row,
                            &mut spec[j * kx..(j + 1) * kx],
                            &mut scratch,
                        )
                        .expect("invariant: lengths match the plan");
                }
                let mut col = vec![Complex::default(); ny];
                let mut cs = vec![Complex::default(); plan.col_fwd.get_inplace_scratch_len()];
                for (k, m) in plan.kernel.chunks_mut(ny).enumerate() {
                    for (j, c) in col.iter_mut().enumerate() {
                        *c = spec[j * kx + k];
                    }
                    plan.col_fwd.process_with_scratch(&mut col, &mut cs);
                    for (mv, c) in m.iter_mut().zip(&col) {
                        *mv = if c.re > 0.0 { norm / c.re } else { 0.0 };
                    }
                }
                plan.kernel[0] = 0.0;
            }
        }
        plan
    }

    /// Fill the kernel spectrum.
    fn plan_kernel(&mut self, dx: f64, dy: f64, e_star: f64) {
        let (mx, my, kx) = (self.mx, self.my, self.kx);
        let norm = 1.0 / (mx * my) as f64;
        match self.boundary {
            Boundary::Free => {
                let quadrant = quadrant_table(self.nx, self.ny, dx, dy, e_star);
                self.fill_free_kernel(&quadrant, Parity::Even);
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

    /// Fill the kernel spectrum of a free-boundary plan from the coefficients of one
    /// quadrant of offsets, `quadrant[j * (nx + 1) + i]` for the offsets `i = 0..=nx`,
    /// `j = 0..=ny` cells, extended to negative offsets by `parity`.
    fn fill_free_kernel(&mut self, quadrant: &[f64], parity: Parity) {
        let (mx, my, kx) = (self.mx, self.my, self.kx);
        let norm = 1.0 / (mx * my) as f64;
        // Real-space kernel on the padded circle, transformed once.
        let (nx, ny) = (self.nx, self.ny);
        let mut spec = vec![Complex::default(); my * kx];
        let mut row = vec![0.0; mx];
        let mut scratch = vec![Complex::default(); self.r2c.get_scratch_len()];
        for j in 0..my {
            let jj = signed(j, my).abs() as usize;
            let q = &quadrant[jj * (nx + 1)..(jj + 1) * (nx + 1)];
            match parity {
                Parity::Even => {
                    for (i, r) in row.iter_mut().enumerate() {
                        *r = q[signed(i, mx).abs() as usize];
                    }
                }
                Parity::OddOdd => {
                    // The offsets ±nx, ±ny (unused by the first nx × ny
                    // outputs) are zero, so that the kernel is exactly odd.
                    let sy = signed(j, my);
                    for (i, r) in row.iter_mut().enumerate() {
                        let sx = signed(i, mx);
                        *r = if jj == ny || sx.abs() as usize == nx || sx == 0.0 || sy == 0.0 {
                            0.0
                        } else {
                            (sx.signum() * sy.signum()) * q[sx.abs() as usize]
                        };
                    }
                }
            }
            self.r2c
                .process_with_scratch(&mut row, &mut spec[j * kx..(j + 1) * kx], &mut scratch)
                .expect("invariant: lengths match the plan");
        }
        let mut col = vec![Complex::default(); my];
        let mut cs = vec![Complex::default(); self.col_fwd.get_inplace_scratch_len()];
        for (k, kernel) in self.kernel.chunks_mut(my).enumerate() {
            for (j, c) in col.iter_mut().enumerate() {
                *c = spec[j * kx + k];
            }
            self.col_fwd.process_with_scratch(&mut col, &mut cs);
            for (kv, c) in kernel.iter_mut().zip(&col) {
                // The kernel is even in x and y, or odd in both: either way
                // its spectrum is real.
                *kv = c.re * norm;
            }
        }
    }

    /// New work arrays for applying this plan (and every plan of the same cells,
    /// boundary and threads).
    pub fn scratch(&self) -> OperatorScratch {
        let l = self.layout;
        OperatorScratch {
            layout: l,
            rows: vec![Complex::default(); l.spectra],
            cols: vec![Complex::default(); l.spectra],
            work: self.workspaces(),
        }
    }

    /// [`HalfSpacePlan::scratch`] with its grid-sized arrays allocated fallibly.
    ///
    /// # Errors
    /// [`Error::InvalidInput`] naming `grid` when the memory is refused.
    pub(crate) fn try_scratch(&self) -> Result<OperatorScratch> {
        let l = self.layout;
        Ok(OperatorScratch {
            layout: l,
            rows: crate::error::try_filled("grid", l.spectra, Complex::default())?,
            cols: crate::error::try_filled("grid", l.spectra, Complex::default())?,
            work: self.workspaces(),
        })
    }

    /// One workspace per task (a row, a block and an FFT scratch each).
    fn workspaces(&self) -> Vec<Workspace> {
        let l = self.layout;
        (0..l.tasks)
            .map(|_| Workspace {
                row: vec![0.0; l.row],
                block: vec![Complex::default(); l.block],
                scratch: vec![Complex::default(); l.fft_scratch],
            })
            .collect()
    }

    /// Whether `scratch` fits this plan.
    pub fn fits(&self, scratch: &OperatorScratch) -> bool {
        scratch.layout == self.layout
    }

    /// The plan's thread pool, if it has one: run a whole solve inside it
    /// (`pool.install`) so that the serial work between FFTs runs on a pool thread.
    pub fn pool(&self) -> Option<Arc<rayon::ThreadPool>> {
        match &self.threads {
            Threads::Serial => None,
            Threads::Pool(p) => Some(Arc::clone(p)),
        }
    }

    /// Threads the passes run on (1 when serial).
    pub fn threads(&self) -> usize {
        match &self.threads {
            Threads::Serial => 1,
            Threads::Pool(p) => p.current_num_threads(),
        }
    }

    /// The thread count the plan was asked for (`None` resolved to all cores), before
    /// small grids fall back to one thread.
    pub fn threads_requested(&self) -> usize {
        self.threads_requested
    }

    /// The grid \[mm\] the plan was made for. The operator depends on its cells and
    /// spacing only, so the plan serves every grid of the same cells and spacing
    /// ([`HalfSpacePlan::serves`]).
    pub fn grid(&self) -> &Grid2 {
        &self.grid
    }

    /// Whether the plan is the operator of `grid` \[mm\]: equal cells and bit-equal
    /// spacing (the origin does not enter the operator).
    pub fn serves(&self, grid: &Grid2) -> bool {
        grid.nx() == self.nx
            && grid.ny() == self.ny
            && grid.dx().to_bits() == self.grid.dx().to_bits()
            && grid.dy().to_bits() == self.grid.dy().to_bits()
    }

    /// The contact modulus E* \[MPa\] the kernel was built for.
    pub fn e_star(&self) -> f64 {
        self.e_star
    }

    /// Cells `[nx, ny]` of the grid.
    pub fn cells(&self) -> [usize; 2] {
        [self.nx, self.ny]
    }

    /// The boundary mode.
    pub fn boundary(&self) -> Boundary {
        self.boundary
    }

    /// Bytes held by the plan (the kernel spectrum, and the influence table once a
    /// solver's incremental updates made it; the FFT plans' twiddles are not counted).
    /// The work arrays are in [`OperatorScratch::memory_bytes`].
    pub fn memory_bytes(&self) -> usize {
        self.kernel.len() * 8 + self.quadrant.get().map_or(0, |q| q.len() * 8)
    }

    /// `u = K p` with newly allocated work arrays: the displacement \[mm\] of the
    /// two-body system for the cell pressures `p` \[MPa\] (both row-major, x fastest,
    /// length `nx·ny`). For repeated applications keep an [`OperatorScratch`] and call
    /// [`HalfSpacePlan::apply_with_scratch`], which allocates nothing.
    ///
    /// # Errors
    /// [`Error::InvalidInput`] when a length differs from `nx·ny`.
    pub fn apply(&self, p: &[f64], u: &mut [f64]) -> Result<()> {
        let mut scratch = self.scratch();
        self.apply_with_scratch(p, u, &mut scratch)
    }

    /// `u = K p`: the displacement \[mm\] of the two-body system for the cell pressures
    /// `p` \[MPa\] (both row-major, x fastest, length `nx·ny`), using the caller's work
    /// arrays. Allocates nothing; several threads may apply one plan at once, each with
    /// its own scratch.
    ///
    /// # Errors
    /// [`Error::InvalidInput`] when a length differs from `nx·ny` or `scratch` was made
    /// for a plan of other cells, boundary or threads.
    pub fn apply_with_scratch(
        &self,
        p: &[f64],
        u: &mut [f64],
        scratch: &mut OperatorScratch,
    ) -> Result<()> {
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
        if !self.fits(scratch) {
            return Err(Error::invalid(
                "scratch",
                format!("work arrays for {:?}", scratch.layout),
                format!(
                    "the work arrays of this plan ({} x {} cells, {:?}, {} threads): \
                     HalfSpacePlan::scratch",
                    self.nx,
                    self.ny,
                    self.boundary,
                    self.threads()
                ),
            ));
        }
        let HalfSpacePlan {
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
            rows_per_task,
            cols_per_task,
            threads,
            ..
        } = self;
        let OperatorScratch {
            rows, cols, work, ..
        } = scratch;
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
                r2c.process_with_scratch(&mut w.row, s, &mut w.scratch)
                    .expect("invariant: lengths match the plan");
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
                    c2r.process_with_scratch(spec, &mut w.row, &mut w.scratch)
                        .expect("invariant: lengths match the plan");
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

/// A [`HalfSpacePlan`] with work arrays of its own: `u = K p` \[mm\] for `p` \[MPa\]
/// through `&mut self`, the shape of the operator before plans could be shared.
#[derive(Debug)]
pub struct ElasticOperator {
    plan: Arc<HalfSpacePlan>,
    scratch: OperatorScratch,
}

impl ElasticOperator {
    /// Plan the operator for `grid` \[mm\], contact modulus `e_star` \[MPa\] and
    /// `boundary` (see [`HalfSpacePlan::new`] for `threads`).
    ///
    /// # Errors
    /// [`Error::InvalidInput`] for a non-positive modulus or `threads` outside 1..=[`crate::MAX_THREADS`].
    pub fn new(
        grid: &Grid2,
        e_star: f64,
        boundary: Boundary,
        threads: Option<usize>,
    ) -> Result<Self> {
        HalfSpacePlan::new(grid, e_star, boundary, threads).map(Self::from_plan)
    }

    /// The operator of a (shared) plan, with new work arrays.
    pub fn from_plan(plan: Arc<HalfSpacePlan>) -> Self {
        let scratch = plan.scratch();
        ElasticOperator { plan, scratch }
    }

    /// The shared plan.
    pub fn plan(&self) -> &Arc<HalfSpacePlan> {
        &self.plan
    }

    /// The plan's thread pool, if it has one (see [`HalfSpacePlan::pool`]).
    pub fn pool(&self) -> Option<Arc<rayon::ThreadPool>> {
        self.plan.pool()
    }

    /// Cells `[nx, ny]` of the grid.
    pub fn cells(&self) -> [usize; 2] {
        self.plan.cells()
    }

    /// The boundary mode.
    pub fn boundary(&self) -> Boundary {
        self.plan.boundary()
    }

    /// Bytes held by the plan and the work arrays (kernel spectrum, transposition
    /// buffers, workspaces).
    pub fn memory_bytes(&self) -> usize {
        self.plan.memory_bytes() + self.scratch.memory_bytes()
    }

    /// `u = K p`: the displacement \[mm\] of the two-body system for the cell pressures
    /// `p` \[MPa\] (both row-major, x fastest, length `nx·ny`). Allocates nothing.
    ///
    /// # Errors
    /// [`Error::InvalidInput`] when a length differs from `nx·ny`.
    pub fn apply(&mut self, p: &[f64], u: &mut [f64]) -> Result<()> {
        self.plan.apply_with_scratch(p, u, &mut self.scratch)
    }
}

/// The FFT plans of a 2-D transform on a padded `mx × my` array, real along `x` and
/// complex along `y` (the layout of [`HalfSpacePlan`] and of the steady rolling operator),
/// with the longest scratch any of them needs.
pub(crate) struct PaddedFfts {
    /// Real-to-complex transform of a row (length `mx`).
    pub r2c: Arc<dyn RealToComplex<f64>>,
    /// Its inverse.
    pub c2r: Arc<dyn ComplexToReal<f64>>,
    /// Complex transform of a column (length `my`).
    pub col_fwd: Arc<dyn Fft<f64>>,
    /// Its inverse.
    pub col_inv: Arc<dyn Fft<f64>>,
    /// The longest scratch of the four (complex values).
    pub scratch_len: usize,
}

impl PaddedFfts {
    /// Plan the four transforms for `mx × my`.
    pub(crate) fn plan(mx: usize, my: usize) -> Self {
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
        PaddedFfts {
            r2c,
            c2r,
            col_fwd,
            col_inv,
            scratch_len,
        }
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
