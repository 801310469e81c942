//! Friction over a pressure field: force, moment and dissipated power of the shear
//! stresses of a [`CellLaw`] over every loaded cell.
//!
//! For cells `k` of area `ΔA` at the in-plane points `(x_k, y_k)` of the grid frame, with
//! pressure `p_k` and sliding velocity `v_k` of body 1 relative to body 2:
//!
//! ```text
//! τ_k = −k(p_k, |v_k|) v_k                       shear stress on body 1 [MPa]
//! F   = Σ τ_k ΔA                                 friction force on body 1 [N]
//! M_O = Σ (x_k τ_y,k − y_k τ_x,k) ΔA · n         moment about the grid origin [N·mm]
//! P   = −Σ τ_k · v_k ΔA = Σ k |v_k|² ΔA ≥ 0      dissipated power [N·mm/s = 1e-3 W]
//! ```
//!
//! The moment of in-plane stresses about a point of the plane is along its normal `n`.
//! The moment about any axis through a point `Q` with direction `a` is
//! `a · (M_O + (O − Q) × F)` ([`ContactFriction::moment_about`]). The power does not depend
//! on the frame: `P` is the rate of work of the friction stresses on the relative motion.
//!
//! Works on any [`NormalSolution`]: Hertz sampled on a grid, PimP or the half-space
//! solver. Cells with `p ≤ 0` carry no stress. Units: mm, N, MPa, mm/s; power in W.

use super::law::CellLaw;
use crate::error::{Error, Result};
use crate::field::NormalSolution;
use crate::geometry::{ContactFrame, ContactPair, Grid2, VelocityField};
use nalgebra::{Point3, Unit, Vector3};

/// Sums of the friction integral in the grid frame.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct GridFriction {
    /// Friction force on body 1 `[x, y]` in the grid frame \[N\].
    pub force: [f64; 2],
    /// Moment of the friction stresses on body 1 about the grid origin, component along
    /// the normal \[N·mm\].
    pub moment: f64,
    /// Dissipated power \[W\], ≥ 0.
    pub power: f64,
    /// Normal force `Σ p ΔA` \[N\] (cells with p > 0).
    pub normal_force: f64,
}

impl GridFriction {
    /// Effective friction coefficient `|F| / N` (0 for an unloaded field).
    pub fn coefficient(&self) -> f64 {
        if self.normal_force > 0.0 {
            self.force[0].hypot(self.force[1]) / self.normal_force
        } else {
            0.0
        }
    }
}

/// N·mm/s per W.
const MW_PER_W: f64 = 1e3;

/// `Σ p |v| ΔA` \[W\] over the cells with `p > 0`: the power that a unit friction coefficient
/// would dissipate, so that constant-μ Coulomb friction (`v_ε = 0`) gives
/// `power = μ · pressure_sliding`; divided by the normal force it is the pressure-weighted
/// mean sliding speed (×1000, in mm/s). Kept out of [`grid_friction`], whose time goes into
/// square roots.
///
/// # Errors
/// Those of [`grid_friction`] for the inputs.
pub fn pressure_sliding(grid: &Grid2, pressure: &[f64], field: &VelocityField) -> Result<f64> {
    check_field(grid, pressure, field)?;
    let mut sum = 0.0;
    for (k, (x, y)) in grid.points().enumerate() {
        let p = pressure[k];
        if p > 0.0 {
            let [vx, vy] = field.sliding_at(x, y);
            sum += p * vx.hypot(vy);
        }
    }
    let sum = sum * grid.cell_area() / MW_PER_W;
    if sum.is_finite() {
        Ok(sum)
    } else {
        Err(Error::invalid(
            "pressure",
            "a non-finite value",
            "finite pressures in MPa",
        ))
    }
}

fn check_field(grid: &Grid2, pressure: &[f64], field: &VelocityField) -> Result<()> {
    if pressure.len() != grid.len() {
        return Err(Error::invalid(
            "pressure",
            format!("{} cells", pressure.len()),
            format!("{} cells ({} × {})", grid.len(), grid.nx(), grid.ny()),
        ));
    }
    let finite = |a: &[[f64; 2]; 3]| a.iter().flatten().all(|v| v.is_finite());
    if !finite(&field.sliding) {
        return Err(Error::invalid(
            "sliding",
            format!("{:?}", field.sliding),
            "finite velocities in mm/s",
        ));
    }
    Ok(())
}

/// Cells per block of the boundary kernel: independent accumulators, one per lane, so that
/// no sum is a loop-carried dependency and the compiler can use vector instructions (4 was
/// the fastest of 2, 4 and 8 on the benchmark machine).
const LANES: usize = 4;

/// The boundary (Coulomb) part `k = φ μ_b p / √(|v|² + v_ε²)` over every cell: force,
/// moment about the grid origin, power, load, the raw pressure sum (NaN-propagating) and the
/// `[fx, fy, m, power, load, raw]`. Cells with `p ≤ 0` add no
/// stress. `REG`: v_ε > 0 (else `√(|v|² + v_ε²) = |v|`). One square root and one division
/// per cell; blocks of [`LANES`] cells with no load are skipped. The moment is summed per
/// row as `Σ x τ_y − y Σ τ_x`.
fn boundary_sums<const REG: bool>(
    grid: &Grid2,
    pressure: &[f64],
    field: &VelocityField,
    law: &CellLaw,
) -> [f64; 6] {
    let [o, dx, dy] = field.sliding;
    let kernel = Kernel {
        b: law.boundary_coefficient(),
        eps2: law.regularisation_squared(),
        dvx: dx[0],
        dvy: dx[1],
        offsets: std::array::from_fn(|l| l as f64 * grid.dx()),
    };
    let (nx, h, x0) = (grid.nx(), grid.dx(), grid.x(0));
    let mut total = [0.0; 6];
    for j in 0..grid.ny() {
        let y = grid.y(j);
        let row = &pressure[j * nx..(j + 1) * nx];
        let (ox, oy) = (o[0] + y * dy[0], o[1] + y * dy[1]);
        let mut acc = [[0.0; LANES]; 6];
        let chunks = row.chunks_exact(LANES);
        let tail = chunks.remainder();
        for (c, chunk) in chunks.enumerate() {
            // An all-zero block adds nothing, not even to the raw sum (a NaN is not zero).
            if chunk.iter().all(|&v| v == 0.0) {
                continue;
            }
            let mut p = [0.0; LANES];
            p.copy_from_slice(chunk);
            kernel.block::<REG>(&p, x0 + (c * LANES) as f64 * h, ox, oy, &mut acc);
        }
        if !tail.is_empty() {
            let mut p = [0.0; LANES];
            p[..tail.len()].copy_from_slice(tail);
            kernel.block::<REG>(&p, x0 + (nx - tail.len()) as f64 * h, ox, oy, &mut acc);
        }
        let [rfx, rfy, rmx, rpw, rq, rraw] = acc.map(|a| a.iter().sum::<f64>());
        total[0] += rfx;
        total[1] += rfy;
        total[2] += rmx - y * rfx;
        total[3] += rpw;
        total[4] += rq;
        total[5] += rraw;
    }
    total
}

/// Slots of [`BarusCache`] (a power of two: 2^[`BARUS_BITS`]).
const BARUS_BITS: u32 = 10;

/// The Barus factors `exp(α p)` of the pressures met so far, by the pressure's bits
/// (direct-mapped, the last one per slot): a field symmetric about its axes, as a Hertz
/// ellipse sampled on a centred grid, holds most of its pressures two or four times, bit
/// for bit, and each takes its exponential once. A hit returns the exponential of the same
/// number, so the sums are those computed without the cache, bit for bit.
struct BarusCache {
    keys: [u64; 1 << BARUS_BITS],
    values: [f64; 1 << BARUS_BITS],
    lookups: usize,
    misses: usize,
}

impl BarusCache {
    fn new() -> Self {
        // No pressure the cache is asked about (p > 0) has the bits of this NaN.
        BarusCache {
            keys: [u64::MAX; 1 << BARUS_BITS],
            values: [0.0; 1 << BARUS_BITS],
            lookups: 0,
            misses: 0,
        }
    }

    #[inline(always)]
    fn get(&mut self, law: &CellLaw, p: f64) -> f64 {
        let bits = p.to_bits();
        // Fibonacci hashing: the top bits of the product mix all of the pressure's.
        let slot = (bits.wrapping_mul(0x9E37_79B9_7F4A_7C15) >> (64 - BARUS_BITS)) as usize;
        if self.keys[slot] != bits {
            self.keys[slot] = bits;
            self.values[slot] = law.barus(p);
            self.misses += 1;
        }
        self.lookups += 1;
        self.values[slot]
    }

    /// Whether the field repeats its pressures (a Hertz field on a centred grid, mirrored
    /// in x within each row): after the first rows' [`BARUS_TRIAL`] lookups, at least one in
    /// four a hit. A field that does not (PimP's, the half-space solver's) computes its
    /// factors directly from then on: the cache's lookups would only cost. Either way the
    /// same bits.
    fn worth_it(&self) -> bool {
        self.lookups < BARUS_TRIAL || 4 * (self.lookups - self.misses) >= self.lookups
    }
}

/// Lookups after which [`BarusCache::worth_it`] judges the field.
const BARUS_TRIAL: usize = 64;

/// The fluid part `k = (1 − φ) τ_f(p, |v|) / |v|` over the loaded cells:
/// `[fx, fy, m, power]` (a transcendental function or two per cell, so only where p > 0;
/// the Barus factor from a [`BarusCache`]).
fn fluid_sums(grid: &Grid2, pressure: &[f64], field: &VelocityField, law: &CellLaw) -> [f64; 4] {
    let [o, dx, dy] = field.sliding;
    let (nx, h, x0) = (grid.nx(), grid.dx(), grid.x(0));
    let mut barus = BarusCache::new();
    let mut cached = true;
    let mut total = [0.0; 4];
    for j in 0..grid.ny() {
        let y = grid.y(j);
        let row = &pressure[j * nx..(j + 1) * nx];
        cached = cached && barus.worth_it();
        let (ox, oy) = (o[0] + y * dy[0], o[1] + y * dy[1]);
        let mut acc = [[0.0; LANES]; 4];
        for (i, &p) in row.iter().enumerate() {
            if !(p > 0.0) {
                continue;
            }
            let x = x0 + i as f64 * h;
            let (vx, vy) = (ox + x * dx[0], oy + x * dx[1]);
            let s2 = vx * vx + vy * vy;
            if s2 > 0.0 {
                let factor = if cached {
                    barus.get(law, p)
                } else {
                    law.barus(p)
                };
                let k = law.fluid_part_with_barus(p, s2.sqrt(), factor);
                let l = i % LANES;
                acc[0][l] -= k * vx;
                acc[1][l] -= k * vy;
                acc[2][l] -= x * k * vy;
                acc[3][l] += k * s2;
            }
        }
        let [rfx, rfy, rmx, rpw] = acc.map(|a| a.iter().sum::<f64>());
        total[0] += rfx;
        total[1] += rfy;
        total[2] += rmx - y * rfx;
        total[3] += rpw;
    }
    total
}

/// The per-block work of [`boundary_sums`].
struct Kernel {
    b: f64,
    eps2: f64,
    dvx: f64,
    dvy: f64,
    offsets: [f64; LANES],
}

impl Kernel {
    /// Add one block of cells (pressures `p`, first cell at `xb`, row velocity at x = 0
    /// `(ox, oy)`) to the row's lanes `[τ_x, τ_y, x τ_y, k|v|², q, p]`.
    #[inline(always)]
    fn block<const REG: bool>(
        &self,
        p: &[f64; LANES],
        xb: f64,
        ox: f64,
        oy: f64,
        acc: &mut [[f64; LANES]; 6],
    ) {
        for l in 0..LANES {
            let q = if p[l] > 0.0 { p[l] } else { 0.0 };
            let x = xb + self.offsets[l];
            let vx = ox + x * self.dvx;
            let vy = oy + x * self.dvy;
            let s2 = vx * vx + vy * vy;
            let d = if REG { s2 + self.eps2 } else { s2 }.sqrt();
            // d = 0 only where v = 0: no stress there.
            let k = if d > 0.0 { self.b * q / d } else { 0.0 };
            let (tx, ty) = (-k * vx, -k * vy);
            acc[0][l] += tx;
            acc[1][l] += ty;
            acc[2][l] += x * ty;
            acc[3][l] += k * s2;
            acc[4][l] += q;
            acc[5][l] += p[l];
        }
    }
}

/// The friction integral over `pressure` \[MPa\] on `grid` \[mm\] with the sliding field
/// `field` (grid frame) and the law `law`. Does not allocate.
///
/// # Errors
/// [`Error::InvalidInput`]: field `pressure` (length not the grid's, or a value not finite),
/// `sliding` (not finite), `fluid` (the Newtonian law overflowed: `exp(α p)` too large for
/// `f64`; use a bounded law).
pub fn grid_friction(
    grid: &Grid2,
    pressure: &[f64],
    field: &VelocityField,
    law: &CellLaw,
) -> Result<GridFriction> {
    check_field(grid, pressure, field)?;
    let [mut fx, mut fy, mut m, mut power, load, raw] = if law.regularisation_squared() > 0.0 {
        boundary_sums::<true>(grid, pressure, field, law)
    } else {
        boundary_sums::<false>(grid, pressure, field, law)
    };
    if law.has_fluid() {
        let [f_x, f_y, f_m, f_power] = fluid_sums(grid, pressure, field, law);
        fx += f_x;
        fy += f_y;
        m += f_m;
        power += f_power;
    }
    finish_sums(grid, [fx, fy, m, power, load, raw])
}

/// The sums `[fx, fy, m, power, load, raw]` over the cells (stress × cell, before the cell
/// area) as a [`GridFriction`], or the error of a non-finite pressure or an overflow.
fn finish_sums(grid: &Grid2, [fx, fy, m, power, load, raw]: [f64; 6]) -> Result<GridFriction> {
    let load = if raw.is_finite() { load } else { raw };
    let area = grid.cell_area();
    let sums = GridFriction {
        force: [fx * area, fy * area],
        moment: m * area,
        power: power * area / MW_PER_W,
        normal_force: load * area,
    };
    let all = [
        sums.force[0],
        sums.force[1],
        sums.moment,
        sums.power,
        sums.normal_force,
    ];
    if all.iter().all(|v| v.is_finite()) {
        Ok(sums)
    } else if !load.is_finite() {
        Err(Error::invalid(
            "pressure",
            "a non-finite value",
            "finite pressures in MPa",
        ))
    } else {
        Err(Error::invalid(
            "fluid",
            "a shear stress that overflows (Newtonian law with exp(alpha p) beyond f64)",
            "a bounded fluid law (Eyring or limiting shear) at these pressures",
        ))
    }
}

/// Largest estimated error of [`grid_friction_binned`] relative to `Σ |τ| ΔA` (its Taylor
/// bound, see there) for which it bins the cells; beyond it, the cell-by-cell sums.
pub const BINNED_TOLERANCE: f64 = 1e-6;

/// The friction integral of [`grid_friction`] with the boundary (Coulomb) law evaluated
/// once per block of cells instead of once per cell, where the sliding field allows: the
/// contact element's PimP back-end (docs/mbs.md). Same arguments, outputs and errors as
/// [`grid_friction`]; does not allocate.
///
/// With `q` the pressure (≥ 0) and `g(x) = v/√(|v|² + v_ε²)` the stress direction of the
/// boundary part, a block of centre `c` contributes
/// `Σ q g(x_k) ≈ P g(c) + ∇g(c) · Σ q_k (x_k − c)`, `P = Σ q_k` (one square root and one
/// division per block; the moment `x × g` with the block's exact second moments of `q`, and
/// the power density `|v|² / d`, likewise). The remainder is the second-order Taylor term:
/// along a line, `|∂²g| ≤ 4 L² / |v|²` (`L` the spectral norm of the sliding field's
/// gradient: `|∇v d| ≤ L |d|`), so each cell's error is at most `2 (ρ L / v_min)²` of its `q`, with `ρ` the
/// largest distance from a block's centre to its cells' centres (half the diagonal between
/// its corner cells' centres) and `v_min` a lower bound of the sliding speed over the blocks.
/// The blocks are [`BLOCK_SHAPES`]: of those whose bound is at most [`BINNED_TOLERANCE`],
/// the one with the most cells (of equal ones, the smallest bound), laid from the grid's
/// first cell, the last blocks padded with empty cells ([`binning_blocks`]; the bound is
/// [`binning_error`]). Sliding that varies little over a block (the roller-end/rib contact
/// spinning about a far axis) takes 2 × 4 or larger blocks; otherwise, and for a law with a
/// fluid part (not linear in the pressure), the cell-by-cell sums of [`grid_friction`].
/// Error against them in docs/VALIDATION.md. Where the blocks' sums do not stay finite (a
/// sliding speed whose square overflows), the cell-by-cell sums are taken as well.
///
/// # Errors
/// Those of [`grid_friction`].
pub fn grid_friction_binned(
    grid: &Grid2,
    pressure: &[f64],
    field: &VelocityField,
    law: &CellLaw,
) -> Result<GridFriction> {
    check_field(grid, pressure, field)?;
    let shape = if law.has_fluid() {
        None
    } else {
        binning_blocks(grid, field)
    };
    let sums = match shape {
        Some([2, 2]) => block_sums::<2, 2>(grid, pressure, field, law),
        Some([2, 4]) => block_sums::<2, 4>(grid, pressure, field, law),
        Some([4, 2]) => block_sums::<4, 2>(grid, pressure, field, law),
        Some([4, 4]) => block_sums::<4, 4>(grid, pressure, field, law),
        Some([2, 8]) => block_sums::<2, 8>(grid, pressure, field, law),
        Some([8, 2]) => block_sums::<8, 2>(grid, pressure, field, law),
        _ => return grid_friction(grid, pressure, field, law),
    };
    if sums.iter().all(|v| v.is_finite()) {
        finish_sums(grid, sums)
    } else {
        // The blocks square the sliding speed, which overflows beyond about 1e154 mm/s;
        // the cell-by-cell sums do not: the same answer (or error) as `grid_friction`.
        grid_friction(grid, pressure, field, law)
    }
}

/// The block shapes `[cells along x, cells along y]` of [`grid_friction_binned`], by cells
/// per block (most first).
pub const BLOCK_SHAPES: [[usize; 2]; 6] = [[4, 4], [2, 8], [8, 2], [2, 4], [4, 2], [2, 2]];

/// The block shape [`grid_friction_binned`] uses on `grid` with the sliding `field` (for a
/// law without a fluid part): of [`BLOCK_SHAPES`] with a bound [`block_error`] at most
/// [`BINNED_TOLERANCE`], the one with the most cells, of equal ones the smallest bound;
/// `None` when no shape qualifies (the cell-by-cell sums).
pub fn binning_blocks(grid: &Grid2, field: &VelocityField) -> Option<[usize; 2]> {
    let mut best: Option<([usize; 2], f64)> = None;
    for shape in BLOCK_SHAPES {
        let e = block_error(grid, field, shape);
        if e > BINNED_TOLERANCE {
            continue;
        }
        best = match best {
            Some((b, be)) if b[0] * b[1] > shape[0] * shape[1] || be <= e => Some((b, be)),
            _ => Some((shape, e)),
        };
    }
    best.map(|(b, _)| b)
}

/// The bound of the error of [`grid_friction_binned`] relative to `Σ |τ| ΔA` on `grid`
/// with `field`: [`block_error`] of the blocks it uses ([`binning_blocks`]), or of 2 × 2
/// blocks when it uses none (then above [`BINNED_TOLERANCE`], or infinite when the sliding
/// may vanish on the grid).
pub fn binning_error(grid: &Grid2, field: &VelocityField) -> f64 {
    block_error(grid, field, binning_blocks(grid, field).unwrap_or([2, 2]))
}

/// The Taylor bound `2 (ρ L / v_min)²` of blocks of `shape` (cells along x and y, each ≥ 1)
/// laid from the first cell of `grid` (the last ones padded): `ρ` the largest distance from
/// a block's centre to its cells' centres, `L` the spectral norm of the sliding gradient,
/// `v_min` the least sliding speed over the padded blocks (`|v|` at their centre less `L`
/// times their half-diagonal). Infinite when the sliding may vanish there.
pub fn block_error(grid: &Grid2, field: &VelocityField, shape: [usize; 2]) -> f64 {
    let [_, dx, dy] = field.sliding;
    let [bx, by] = shape.map(|b| b.max(1));
    let (h, k) = (grid.dx(), grid.dy());
    // The padded blocks' extent and centre.
    let (wx, wy) = (
        grid.nx().div_ceil(bx) as f64 * bx as f64 * h,
        grid.ny().div_ceil(by) as f64 * by as f64 * k,
    );
    let xc = grid.x(0) - 0.5 * h + 0.5 * wx;
    let yc = grid.y(0) - 0.5 * k + 0.5 * wy;
    let [vx, vy] = field.sliding_at(xc, yc);
    // The spectral norm of the gradient [[∂v_x/∂x, ∂v_x/∂y], [∂v_y/∂x, ∂v_y/∂y]]:
    // σ² = (F² + √(F⁴ − 4 det²))/2 with F the Frobenius norm (for a spin, F/√2).
    let f2 = dx[0] * dx[0] + dx[1] * dx[1] + dy[0] * dy[0] + dy[1] * dy[1];
    let det = dx[0] * dy[1] - dx[1] * dy[0];
    let l = (0.5 * (f2 + (f2 * f2 - 4.0 * det * det).max(0.0).sqrt())).sqrt();
    // |v| over the blocks >= |v(c)| − L × the half-diagonal. (Square roots of sums of
    // squares, not `hypot`: this runs for every shape on every call; a speed whose square
    // overflows gives an infinite `v_min`, blocks whose sums overflow, and so the cell sums.)
    let v_min = (vx * vx + vy * vy).sqrt() - l * 0.5 * (wx * wx + wy * wy).sqrt();
    let (rx, ry) = ((bx - 1) as f64 * h, (by - 1) as f64 * k);
    let rho = 0.5 * (rx * rx + ry * ry).sqrt();
    if v_min > 0.0 && l.is_finite() {
        2.0 * (rho * l / v_min).powi(2)
    } else {
        f64::INFINITY
    }
}

/// Columns per chunk of a strip in [`block_sums`] (a multiple of every block width).
const CHUNK: usize = 64;
/// Blocks per lane group of [`block_sums`].
const BLOCK_LANES: usize = 4;
/// Lane groups of blocks per chunk (blocks at least 2 cells wide).
const CHUNK_GROUPS: usize = CHUNK / 2 / BLOCK_LANES;

/// The sums of [`grid_friction_binned`] on blocks of `BX × BY` cells laid from the grid's
/// first cell (the last ones padded with empty cells): `[fx, fy, m, power, load, raw]` as
/// [`boundary_sums`], each block by the Taylor expansion about its centre with the block's
/// exact moments of the pressure up to the second. Strips of `BY` rows, in chunks of
/// [`CHUNK`] columns: the columns' sums over the strip's rows, the blocks' moments from
/// them, then the blocks in lane groups (each pass a plain loop over arrays: vector code).
fn block_sums<const BX: usize, const BY: usize>(
    grid: &Grid2,
    pressure: &[f64],
    field: &VelocityField,
    law: &CellLaw,
) -> [f64; 6] {
    let [o, dx, dy] = field.sliding;
    let (b, eps2) = (law.boundary_coefficient(), law.regularisation_squared());
    let (nx, ny) = (grid.nx(), grid.ny());
    let (h, k) = (grid.dx(), grid.dy());
    // Cell offsets from the block's centre, in cells.
    let di: [f64; BX] = std::array::from_fn(|i| i as f64 - 0.5 * (BX - 1) as f64);
    let dj: [f64; BY] = std::array::from_fn(|j| j as f64 - 0.5 * (BY - 1) as f64);
    let (hk, hh, kk) = (h * k, h * h, k * k);
    // The first block's centre and the blocks' pitch along x.
    let (x0, pitch) = (grid.x(0) + 0.5 * (BX - 1) as f64 * h, BX as f64 * h);
    let lane_offsets: [f64; BLOCK_LANES] = std::array::from_fn(|l| l as f64 * pitch);
    // Per column of a chunk over a strip's rows: Σ p, Σ q, Σ q dj, Σ q dj² (q = p where
    // p > 0, else 0; dj in cells).
    let mut col = [[0.0f64; CHUNK]; 4];
    // Per block of a chunk (lane groups): Σ q, and in cell units Σ q di, Σ q di², Σ q dj,
    // Σ q di dj, Σ q dj².
    let mut mom = [[[0.0f64; BLOCK_LANES]; CHUNK_GROUPS]; 6];
    // [Σ g_x q, Σ g_y q, Σ (x g_y − y g_x) q, Σ q |v|²/d, Σ q, Σ p]; the coefficient b at
    // the end.
    let mut t = [0.0; 6];
    for j0 in (0..ny).step_by(BY) {
        let rows = BY.min(ny - j0);
        let yc = grid.y(j0) + 0.5 * (BY - 1) as f64 * k;
        // The strip's velocity at x = 0.
        let (ox, oy) = (o[0] + yc * dy[0], o[1] + yc * dy[1]);
        // Lanes: Σ g_x q, Σ g_y q, Σ x g_y q − (y − y_c) g_x q, the power density, Σ q.
        let mut lanes = [[0.0f64; BLOCK_LANES]; 5];
        for c0 in (0..nx).step_by(CHUNK) {
            let width = CHUNK.min(nx - c0);
            let blocks = width.div_ceil(BX);
            let groups = blocks.div_ceil(BLOCK_LANES);
            // Zero past the grid (padding): the columns of whole lane groups.
            let used = (groups * BLOCK_LANES * BX).min(CHUNK);
            let [raw, s0, s1, s2] = &mut col;
            for c in [&mut *raw, &mut *s0, &mut *s1, &mut *s2] {
                c[width..used].fill(0.0);
            }
            let row = |r: usize| {
                let start = (j0 + r) * nx + c0;
                &pressure[start..start + width]
            };
            if rows == BY {
                // All the strip's rows at once: one store per column.
                let strip: [&[f64]; BY] = std::array::from_fn(row);
                for i in 0..width {
                    let (mut w, mut a, mut b1, mut b2) = (0.0, 0.0, 0.0, 0.0);
                    for (cells, &d) in strip.iter().zip(&dj) {
                        let p = cells[i];
                        let q = if p > 0.0 { p } else { 0.0 };
                        w += p;
                        a += q;
                        b1 += q * d;
                        b2 += q * (d * d);
                    }
                    raw[i] = w;
                    s0[i] = a;
                    s1[i] = b1;
                    s2[i] = b2;
                }
            } else {
                for c in [&mut *raw, &mut *s0, &mut *s1, &mut *s2] {
                    c[..width].fill(0.0);
                }
                for (r, &d) in dj.iter().enumerate().take(rows) {
                    for ((((&p, w), a), b1), b2) in row(r)
                        .iter()
                        .zip(raw.iter_mut())
                        .zip(s0.iter_mut())
                        .zip(s1.iter_mut())
                        .zip(s2.iter_mut())
                    {
                        let q = if p > 0.0 { p } else { 0.0 };
                        *w += p;
                        *a += q;
                        *b1 += q * d;
                        *b2 += q * (d * d);
                    }
                }
            }
            t[5] += raw[..width].iter().sum::<f64>();
            if !s0[..width].iter().any(|&q| q > 0.0) {
                continue;
            }
            // The groups' columns all lie below `used` (CHUNK is a multiple of a group).
            let group = BLOCK_LANES * BX;
            for g in 0..groups.min(CHUNK_GROUPS) {
                let cols = g * group..(g + 1) * group;
                for (l, ((c_0, c_1), c_2)) in s0[cols.clone()]
                    .chunks_exact(BX)
                    .zip(s1[cols.clone()].chunks_exact(BX))
                    .zip(s2[cols].chunks_exact(BX))
                    .enumerate()
                {
                    let mut m = [0.0f64; 6];
                    for (((&a, &b1), &b2), &d) in c_0.iter().zip(c_1).zip(c_2).zip(&di) {
                        m[0] += a;
                        m[1] += a * d;
                        m[2] += a * (d * d);
                        m[3] += b1;
                        m[4] += b1 * d;
                        m[5] += b2;
                    }
                    for (dst, v) in mom.iter_mut().zip(m) {
                        dst[g][l] = v;
                    }
                }
            }
            let xb = x0 + c0 as f64 * h;
            // A lane past the last block carries nothing; its centre is kept on the last
            // block (where the sliding does not vanish).
            let last = xb + (blocks - 1) as f64 * pitch;
            for g in 0..groups.min(CHUNK_GROUPS) {
                let xg = xb + (g * BLOCK_LANES) as f64 * pitch;
                let [pp4, mx4, sxx4, my4, sxy4, syy4] = &mom;
                let (pp4, mx4, sxx4) = (&pp4[g], &mx4[g], &sxx4[g]);
                let (my4, sxy4, syy4) = (&my4[g], &sxy4[g], &syy4[g]);
                for l in 0..BLOCK_LANES {
                    let pp = pp4[l];
                    let xc = (xg + lane_offsets[l]).min(last);
                    // First and second moments about the block's centre.
                    let (mx, my) = (h * mx4[l], k * my4[l]);
                    let (sxx, sxy, syy) = (hh * sxx4[l], hk * sxy4[l], kk * syy4[l]);
                    let (vx, vy) = (ox + xc * dx[0], oy + xc * dx[1]);
                    let s2 = vx * vx + vy * vy;
                    let r = 1.0 / (s2 + eps2).sqrt();
                    let r3 = r * r * r;
                    let (ax, ay) = (vx * dx[0] + vy * dx[1], vx * dy[0] + vy * dy[1]);
                    let (gx, gy) = (vx * r, vy * r);
                    // ∂g/∂x and ∂g/∂y.
                    let (vxr3, vyr3) = (vx * r3, vy * r3);
                    let (gxx, gyx) = (dx[0] * r - vxr3 * ax, dx[1] * r - vyr3 * ax);
                    let (gxy, gyy) = (dy[0] * r - vxr3 * ay, dy[1] * r - vyr3 * ay);
                    let sx = pp * gx + mx * gxx + my * gxy;
                    let sy = pp * gy + mx * gyx + my * gyy;
                    lanes[0][l] += sx;
                    lanes[1][l] += sy;
                    // Σ q (x g_y − y g_x) with g to first order and the exact moments of q:
                    // Σ q x g_y ≈ x_c Σ q g_y + g_y m_x + ∇g_y · Σ q δx δ (δ = x − c),
                    // likewise y; the y_c Σ q g_x part is added per strip.
                    lanes[2][l] +=
                        xc * sy + (mx * gy - my * gx) + (sxx * gyx - syy * gxy) + sxy * (gyy - gxx);
                    // |v|²/d: its gradient (v·∂v) (2 − |v|²/d²)/d.
                    lanes[3][l] += r * (pp * s2 + (mx * ax + my * ay) * (2.0 - s2 * r * r));
                    lanes[4][l] += pp;
                }
            }
        }
        let [sx, sy, m, w, load] = lanes.map(|a| (a[0] + a[1]) + (a[2] + a[3]));
        t[0] += sx;
        t[1] += sy;
        t[2] += m - yc * sx;
        t[3] += w;
        t[4] += load;
    }
    [-b * t[0], -b * t[1], -b * t[2], b * t[3], t[4], t[5]]
}

/// The dissipated power density `τ · v` per cell \[W/mm²\] (0 where `p ≤ 0`), the layout of
/// `pressure`. Does not allocate.
///
/// # Errors
/// Those of [`grid_friction`] for the inputs; field `density` when `out` does not have the
/// grid's cell count.
pub fn power_density(
    grid: &Grid2,
    pressure: &[f64],
    field: &VelocityField,
    law: &CellLaw,
    out: &mut [f64],
) -> Result<()> {
    check_field(grid, pressure, field)?;
    if out.len() != grid.len() {
        return Err(Error::invalid(
            "density",
            format!("a buffer of {} cells", out.len()),
            format!("{} cells", grid.len()),
        ));
    }
    for j in 0..grid.ny() {
        for i in 0..grid.nx() {
            let k = j * grid.nx() + i;
            let p = pressure[k];
            out[k] = if p > 0.0 {
                let [vx, vy] = field.sliding_at(grid.x(i), grid.y(j));
                let s2 = vx * vx + vy * vy;
                let d = if s2 > 0.0 {
                    law.drag(p, s2.sqrt()) * s2
                } else {
                    0.0
                };
                d / MW_PER_W
            } else {
                0.0
            };
        }
    }
    if out.iter().all(|v| v.is_finite()) {
        Ok(())
    } else {
        Err(Error::invalid(
            "fluid",
            "a shear stress that overflows",
            "a bounded fluid law (Eyring or limiting shear) at these pressures",
        ))
    }
}

/// Friction of a contact in the world: the grid-frame sums placed by the contact frame.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ContactFriction {
    /// The grid-frame sums.
    pub grid: GridFriction,
    /// The grid origin (the contact frame's origin) \[mm\], world frame.
    pub origin: Point3<f64>,
    /// Friction force on body 1 \[N\], world frame.
    pub force: Vector3<f64>,
    /// Moment of the friction stresses on body 1 about `origin` \[N·mm\], world frame.
    pub moment: Vector3<f64>,
    /// The asperity share φ(Λ) of the law.
    pub asperity_share: f64,
}

impl ContactFriction {
    /// Moment \[N·mm\] of the friction on body 1 about the axis through `point` \[mm\] with
    /// direction `axis` (world frame), `a · (M_O + (O − Q) × F)`. On body 2 it is the
    /// negative.
    pub fn moment_about(&self, point: &Point3<f64>, axis: &Unit<Vector3<f64>>) -> f64 {
        axis.dot(&(self.moment + (self.origin - point).cross(&self.force)))
    }
}

/// The friction of the contact `solution` between the bodies of `pair` (body 1 is the body
/// of the solution's gap source's body 1), whose gap source lies in `frame`: the sliding
/// field is evaluated on the solution's grid (turned by `solution.orientation`). Does not
/// allocate.
///
/// # Errors
/// Those of [`ContactPair::velocity_field`] and [`grid_friction`].
pub fn contact_friction<D>(
    solution: &NormalSolution<D>,
    frame: &ContactFrame,
    pair: &ContactPair,
    law: &CellLaw,
) -> Result<ContactFriction> {
    let field = pair.velocity_field(frame, solution.orientation)?;
    let sums = grid_friction(&solution.grid, &solution.pressure, &field, law)?;
    let (s, c) = solution.orientation.sin_cos();
    let (ex, ey) = (frame.ex.into_inner(), frame.ey.into_inner());
    let gx = ex * c + ey * s;
    let gy = -ex * s + ey * c;
    Ok(ContactFriction {
        grid: sums,
        origin: frame.origin,
        force: gx * sums.force[0] + gy * sums.force[1],
        moment: frame.normal.into_inner() * sums.moment,
        asperity_share: law.asperity_share(),
    })
}

#[cfg(test)]
mod tests {
    #![allow(clippy::unwrap_used)]
    use super::*;
    use crate::friction::law::{FilmState, FluidShear, FrictionLaw};

    /// [`fluid_sums`] as it was before the Barus cache: the exponential in every cell.
    fn fluid_sums_uncached(
        grid: &Grid2,
        pressure: &[f64],
        field: &VelocityField,
        law: &CellLaw,
    ) -> [f64; 4] {
        let [o, dx, dy] = field.sliding;
        let (nx, h, x0) = (grid.nx(), grid.dx(), grid.x(0));
        let mut total = [0.0; 4];
        for j in 0..grid.ny() {
            let y = grid.y(j);
            let row = &pressure[j * nx..(j + 1) * nx];
            let (ox, oy) = (o[0] + y * dy[0], o[1] + y * dy[1]);
            let mut acc = [[0.0; LANES]; 4];
            for (i, &p) in row.iter().enumerate() {
                if !(p > 0.0) {
                    continue;
                }
                let x = x0 + i as f64 * h;
                let (vx, vy) = (ox + x * dx[0], oy + x * dx[1]);
                let s2 = vx * vx + vy * vy;
                if s2 > 0.0 {
                    let k = law.fluid_part(p, s2.sqrt());
                    let l = i % LANES;
                    acc[0][l] -= k * vx;
                    acc[1][l] -= k * vy;
                    acc[2][l] -= x * k * vy;
                    acc[3][l] += k * s2;
                }
            }
            let [rfx, rfy, rmx, rpw] = acc.map(|a| a.iter().sum::<f64>());
            total[0] += rfx;
            total[1] += rfy;
            total[2] += rmx - y * rfx;
            total[3] += rpw;
        }
        total
    }

    /// With the Barus cache the fluid sums are the uncached ones bit for bit: on a Hertz
    /// field sampled on a centred grid (most pressures repeat by symmetry: the cache's
    /// hits) and on a field of random pressures, many drawn from a short list (repeats in
    /// any order) and many distinct (every slot overwritten), for the three fluid laws.
    #[test]
    fn barus_cache_leaves_the_sums_unchanged() {
        let grid = Grid2::centered(1.1, 0.4, 64, 48).unwrap();
        let hertz: Vec<f64> = grid
            .points()
            .map(|(x, y)| {
                1.4e3
                    * (1.0 - (x / 1.0).powi(2) - (y / 0.36).powi(2))
                        .max(0.0)
                        .sqrt()
            })
            .collect();
        let mut state = 7u64;
        let mut uniform = || {
            state = state
                .wrapping_mul(6364136223846793005)
                .wrapping_add(1442695040888963407);
            (state >> 11) as f64 / (1u64 << 53) as f64
        };
        let list: Vec<f64> = (0..40).map(|_| 2e3 * uniform()).collect();
        let random: Vec<f64> = (0..grid.len())
            .map(|k| match k % 3 {
                0 => list[(40.0 * uniform()) as usize],
                1 => 2e3 * uniform() - 200.0,
                _ => 0.0,
            })
            .collect();
        let field = VelocityField {
            sliding: [[350.0, -40.0], [25.0, 80.0], [-60.0, 15.0]],
            entrainment: [[0.0; 2]; 3],
        };
        let film = FilmState::new(4e-4, 0.6, 4e-8, 0.02).unwrap();
        let fluids = [
            FluidShear::Newtonian,
            FluidShear::Eyring { tau0: 5.0 },
            FluidShear::LimitingShear {
                tau_l0: 2.0,
                slope: 0.07,
            },
        ];
        for fluid in fluids {
            let law = FrictionLaw {
                fluid,
                ..FrictionLaw::mixed(0.1).unwrap()
            }
            .with_film(&film)
            .unwrap();
            assert!(law.has_fluid());
            for p in [&hertz, &random] {
                let new = fluid_sums(&grid, p, &field, &law).map(f64::to_bits);
                let old = fluid_sums_uncached(&grid, p, &field, &law).map(f64::to_bits);
                assert_eq!(new, old, "{fluid:?}");
                assert!(old.iter().all(|&b| b != 0));
            }
        }
    }
}
