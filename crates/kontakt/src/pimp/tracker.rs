//! PimP along a trajectory of poses: the multi-body path of the contact element (issue 12).
//!
//! [`Pimp::solve_approach`] plans a new adaptive grid and ray-casts every cell of it on
//! every call. Along a trajectory the contact changes little from one call to the next, so a
//! [`PimpTracker`] keeps, between calls,
//!
//! - the grid's extent as a multiple `λ` (per axis) of the bedding law's footprint of the
//!   quadratic part of the gap at the current approach and curvature (for an elliptical
//!   Hertz contact exactly its semi-axes): the grid follows a growing or shrinking contact
//!   continuously, and `λ` itself changes only when the zone reaches more than 90 % or
//!   less than 50 % of the grid (a non-Hertzian zone);
//! - the buffers of the gap and the pressure (no allocation per call);
//! - while `λ` changes, both grids: the outputs fade from the old to the new grid with the
//!   cubic smooth step as the contact moves (over [`FADE_TRAVEL`] of motion: the relative
//!   change of the footprint plus the caller's travel, [`PimpTracker::evaluate_moved`]), so
//!   a resize does not jump the force, and a call repeated at the same pose gives the same
//!   result (a fade counted in calls would move on).
//!
//! The gap is not ray-cast on every cell: [`GapSampling::Interpolated`] casts a stencil of
//! `NODES_X × NODES_Y` Chebyshev-Lobatto points spanning the grid (exact rays through the source) and
//! evaluates the tensor-product interpolating polynomial (degree `NODES_X − 1` along the zone's long axis, `NODES_Y − 1` across) row by row
//! (Horner). Its error against the exact ray cast is measured in `tests/pimp_tracker.rs` for
//! all eight built-in roller/rib pairings and recorded in docs/VALIDATION.md;
//! [`GapSampling::Exact`] casts every cell, for comparison.
//!
//! Units: mm, N, MPa.

use super::bedding::{Bedding, Mode};
use super::{Pimp, SampledGap};
use crate::error::{Error, Result, positive_as};
use crate::gap::GapSource;
use crate::geometry::Grid2;
use crate::hertz::{HertzPointContact, PointGeometry};
use crate::units::Millimetre;
use nalgebra::SMatrix;

/// Stencil points along the grid's x axis (the zone's long axis) of the interpolated gap:
/// Chebyshev-Lobatto nodes, polynomial degree `NODES_X − 1`.
pub const NODES_X: usize = 11;
/// Even and odd coefficients of the polynomial along x.
const EVEN: usize = NODES_X.div_ceil(2);
const ODD: usize = NODES_X / 2;

/// Stencil points along the grid's y axis (polynomial degree `NODES_Y − 1`).
pub const NODES_Y: usize = 5;

/// Motion over which the outputs fade from the old grid to the new one after a resize: the
/// sum over calls of the largest relative change of the footprint's two half-widths and the
/// caller's travel relative to the contact's size ([`PimpTracker::evaluate_moved`]). 0.03
/// is about 12 calls of the element's benchmark (the contact moving 0.1 % of its width per
/// call) and 300 of a load ramp in steps of 2e-4 of the approach.
pub const FADE_TRAVEL: f64 = 0.03;

/// The grid's half-extent over the footprint of the quadratic gap at the start (PimP's
/// first grid, [`Pimp::solve`]).
const LAMBDA_START: f64 = 1.25;
/// Reach of the zone over the grid's half-extent above which the grid grows.
const GROW_AT: f64 = 0.9;
/// Reach below which the grid shrinks.
const SHRINK_AT: f64 = 0.5;
/// Reach a resized grid aims at.
const TARGET_REACH: f64 = 0.75;
/// Growth of an axis whose zone reaches the border (the zone was cut off: immediate).
const GROWTH: f64 = 1.6;
/// Most immediate resizes in one call.
const MAX_RESIZES: usize = 12;

/// How the tracker samples the gap on its grid.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum GapSampling {
    /// Exact rays at a stencil of [`NODES_X`] × [`NODES_Y`] points, the interpolating polynomial on the
    /// cells (default; error in docs/VALIDATION.md).
    #[default]
    Interpolated,
    /// Exact rays at every cell (the reference; about 60 ns per cell for two tori).
    Exact,
}

/// The field of one evaluation, as the contact element needs it; borrows the tracker's
/// buffers.
#[derive(Debug, Clone, Copy)]
pub struct TrackedField<'a> {
    /// The bounding box of the loaded cells of the grid \[mm\] (the dominant grid during a
    /// fade), in the principal frame of the gap: the cells of the tracked grid that carry
    /// pressure, and no others.
    pub grid: Grid2,
    /// Pressure per cell \[MPa\] on `grid`.
    pub pressure: &'a [f64],
    /// Angle \[rad\] from the gap source's `x` axis to the grid's `x` axis.
    pub orientation: f64,
    /// Centre of pressure in the grid frame \[mm\].
    pub centroid: [f64; 2],
    /// Normal force \[N\].
    pub force: f64,
    /// Largest pressure \[MPa\].
    pub max_pressure: f64,
    /// Contact area \[mm²\] (loaded cells).
    pub contact_area: f64,
    /// Weight of the new grid in a fade (1 outside a fade).
    pub fade_weight: f64,
}

/// Scalar results of one grid.
#[derive(Debug, Clone, Copy, Default)]
struct Stats {
    force: f64,
    max_pressure: f64,
    area: f64,
    centroid: [f64; 2],
    /// Reach of the zone over the half-extent, per axis.
    reach: [f64; 2],
    touches: [bool; 2],
}

/// One grid's buffers.
#[derive(Debug, Clone)]
struct Slot {
    sampled: SampledGap,
    pressure: Vec<f64>,
    stats: Stats,
    /// The bounding box of the loaded cells and their pressure (row-major).
    crop: Grid2,
    cropped: Vec<f64>,
    /// Polynomial coefficients of the interpolated gap (corrected mode: with the bedding's
    /// correction), `u^i v^j`.
    coef: SMatrix<f64, NODES_X, NODES_Y>,
    /// Per row: the loaded columns `[first, last + 1)` of the last evaluation (`(0, 0)`:
    /// none), and this call's.
    rows: Vec<Row>,
    /// The stencil rays' warm-start data (`GapSource::sample_points`).
    warm: [[f64; 2]; NODES_X * NODES_Y],
    /// Scratch rows (half a row each, outward from the centre): the gap and the pressure of
    /// the left half.
    gap_left: Vec<f64>,
    press_left: Vec<f64>,
    /// Calls since every row was evaluated in full.
    since_full: usize,
    /// The grid factor of the last evaluation.
    lambda: [f64; 2],
    /// Whether the cells outside the rows' windows hold the gap (`effective`) of this
    /// call (false when only windows were evaluated).
    complete: bool,
}

/// One row's evaluation.
#[derive(Debug, Clone, Copy, Default)]
struct Row {
    /// First evaluated column (the window is `[lo, nx − lo)`); `usize::MAX`: not evaluated.
    lo: usize,
    /// Loaded columns `[first, last + 1)`, `(0, 0)` when none.
    first: usize,
    end: usize,
    /// Σp, Σp u, loaded cells, max p.
    sum: f64,
    sum_u: f64,
    cells: f64,
    max: f64,
}

/// Rows beyond the last zone and cells beyond its row extents evaluated (margin).
const MARGIN: usize = 2;
/// Every this many calls, every cell is evaluated (a patch appearing away from the zone is
/// found then).
const FULL_EVERY: usize = 16;

/// PimP on a grid kept between calls (see the module docs). Plan once per contact element;
/// `evaluate` allocates nothing once its buffers exist.
#[derive(Debug, Clone)]
pub struct PimpTracker {
    pimp: Pimp,
    sampling: GapSampling,
    /// Grid extent over the footprint, per axis; `None` before the first call.
    lambda: Option<[f64; 2]>,
    /// The old grid's `λ` and the fade's progress (motion so far over [`FADE_TRAVEL`]).
    fade: Option<([f64; 2], f64)>,
    /// The last call's footprint \[mm\], for the motion that drives a fade.
    last_footprint: Option<[f64; 2]>,
    slots: [Slot; 2],
    /// Inverses of the stencil's Vandermonde matrices, `V[k][i] = u_k^i`, along x and y.
    vinv_x: SMatrix<f64, NODES_X, NODES_X>,
    vinv_y: SMatrix<f64, NODES_Y, NODES_Y>,
    /// Normalised cell centres `x / half-extent` along x and y.
    u: Vec<f64>,
    v: Vec<f64>,
    stencil: SMatrix<f64, NODES_X, NODES_Y>,
    resizes: usize,
    /// The last call's Hertz contact: the next shape inversion starts from it
    /// ([`HertzPointContact::new_near`]: one evaluation of the elliptic integrals).
    hertz: Option<HertzPointContact>,
}

impl PimpTracker {
    /// A tracker for the solver `pimp` (its mode and cell count; its `extent` must be
    /// `None`: the tracker adapts the grid).
    ///
    /// # Errors
    /// [`Error::InvalidInput`] (field `extent`) for a fixed extent.
    pub fn new(pimp: Pimp, sampling: GapSampling) -> Result<Self> {
        if pimp.options.extent.is_some() {
            return Err(Error::invalid(
                "extent",
                format!("{:?}", pimp.options.extent),
                "None (the tracker adapts the grid to the contact)",
            ));
        }
        let [nx, ny] = pimp.options.cells;
        let grid = Grid2::centered(1.0, 1.0, nx, ny)?;
        let slot = Slot {
            sampled: SampledGap {
                grid,
                rotation: 0.0,
                effective: vec![0.0; nx * ny],
                bedding: Bedding::Published { e_star: 1.0 },
                start_unit: 0.0,
            },
            pressure: vec![0.0; nx * ny],
            stats: Stats::default(),
            crop: grid,
            cropped: Vec::with_capacity(nx * ny),
            coef: SMatrix::zeros(),
            rows: vec![Row::default(); ny],
            warm: [[f64::INFINITY; 2]; NODES_X * NODES_Y],
            gap_left: vec![0.0; nx / 2],
            press_left: vec![0.0; nx / 2],
            since_full: usize::MAX,
            lambda: [0.0; 2],
            complete: true,
        };
        let singular = || Error::Geometry {
            field: "stencil".into(),
            reason: "the stencil's Vandermonde matrix is singular".into(),
        };
        let vinv_x =
            SMatrix::<f64, NODES_X, NODES_X>::from_fn(|k, i| node(k, NODES_X).powi(i as i32))
                .try_inverse()
                .ok_or_else(singular)?;
        let vinv_y =
            SMatrix::<f64, NODES_Y, NODES_Y>::from_fn(|k, i| node(k, NODES_Y).powi(i as i32))
                .try_inverse()
                .ok_or_else(singular)?;
        Ok(PimpTracker {
            pimp,
            sampling,
            lambda: None,
            fade: None,
            last_footprint: None,
            slots: [slot.clone(), slot],
            vinv_x,
            vinv_y,
            u: (0..nx).map(|i| grid.x(i)).collect(),
            v: (0..ny).map(|j| grid.y(j)).collect(),
            stencil: SMatrix::zeros(),
            resizes: 0,
            hertz: None,
        })
    }

    /// How the gap is sampled.
    pub fn sampling(&self) -> GapSampling {
        self.sampling
    }

    /// Grid resizes so far (immediate ones and fades).
    pub fn resizes(&self) -> usize {
        self.resizes
    }

    /// Whether a fade between two grids is under way.
    pub fn fading(&self) -> bool {
        self.fade.is_some()
    }

    /// The grid of the last evaluation \[mm\].
    pub fn grid(&self) -> &Grid2 {
        &self.slots[0].sampled.grid
    }

    /// The gap (corrected mode: including the bedding's correction `(A' − A) x'²`) of the
    /// last evaluation per cell \[mm\], on [`PimpTracker::grid`].
    pub fn effective_gap(&self) -> &[f64] {
        &self.slots[0].sampled.effective
    }

    /// The grid's half-extents over the footprint of the quadratic gap, per axis (`None`
    /// before the first call or after [`PimpTracker::reset`]).
    pub fn grid_factor(&self) -> Option<[f64; 2]> {
        self.lambda
    }

    /// Pin the grid's half-extents to `factor` times the footprint of the quadratic gap
    /// (per axis) for the next call, which then neither settles nor fades (the tracker
    /// still adapts from there on); for comparisons on one grid.
    ///
    /// # Errors
    /// [`Error::InvalidInput`] (field `factor`) unless both entries are finite and > 0.
    pub fn set_grid_factor(&mut self, factor: [f64; 2]) -> Result<()> {
        positive_as("factor", factor[0], "a finite factor > 0")?;
        positive_as("factor", factor[1], "a finite factor > 0")?;
        self.lambda = Some(factor);
        self.fade = None;
        Ok(())
    }

    /// Forget the grid (the next call plans a new one, as after a jump of the poses).
    pub fn reset(&mut self) {
        self.lambda = None;
        self.fade = None;
        self.last_footprint = None;
        self.hertz = None;
        for slot in &mut self.slots {
            slot.since_full = usize::MAX;
        }
    }

    /// The PimP field of `source` at the rigid approach `approach` \[mm\] (> 0) on the
    /// tracked grid.
    ///
    /// # Errors
    /// [`Error::InvalidInput`] for a non-positive approach; [`Error::Geometry`] when no cell
    /// is loaded or the grid cannot be made to hold the zone; the source's errors.
    pub fn evaluate(
        &mut self,
        source: &dyn GapSource,
        approach: Millimetre,
    ) -> Result<TrackedField<'_>> {
        self.evaluate_moved(source, approach, 0.0)
    }

    /// [`PimpTracker::evaluate`] after the contact has travelled `travel` (≥ 0,
    /// dimensionless: for example the contact point's step over the contact's size `√area`)
    /// since the last call, beyond what the footprint's change shows: a fade between grids
    /// moves on by both ([`FADE_TRAVEL`]). The contact element passes its contact point's
    /// step.
    ///
    /// # Errors
    /// As [`PimpTracker::evaluate`]; [`Error::InvalidInput`] (field `travel`) for a negative
    /// or non-finite travel.
    pub fn evaluate_moved(
        &mut self,
        source: &dyn GapSource,
        approach: Millimetre,
        travel: f64,
    ) -> Result<TrackedField<'_>> {
        positive_as("approach", approach, "a finite approach > 0 mm")?;
        if !(travel.is_finite() && travel >= 0.0) {
            return Err(Error::invalid("travel", travel, "a finite travel >= 0"));
        }
        let curvature = source.curvature();
        let hertz = HertzPointContact::new_near(
            PointGeometry::from_curvature(curvature),
            self.pimp.body1,
            self.pimp.body2,
            self.hertz.as_ref(),
        )?;
        self.hertz = Some(hertz);
        let bedding = Bedding::from_hertz(self.pimp.options.mode, curvature, &hertz)?;
        let start_unit = hertz.approach_from_force(1.0)?
            * match bedding.mode() {
                Mode::Corrected => 1.0,
                Mode::Published => 0.6,
            };
        // The footprint of the quadratic part of the gap at this approach.
        let cut = bedding.cut(approach);
        let a_eff = match bedding {
            Bedding::Corrected { d_a, .. } => curvature.a_coef + d_a,
            Bedding::Published { .. } => curvature.a_coef,
        };
        let footprint = [(cut / a_eff).sqrt(), (cut / curvature.b_coef).sqrt()];
        // How far the contact moved since the last call: the footprint's relative change
        // and the caller's travel.
        let motion = travel
            + self.last_footprint.map_or(0.0, |last| {
                (footprint[0] / last[0] - 1.0)
                    .abs()
                    .max((footprint[1] / last[1] - 1.0).abs())
            });
        self.last_footprint = Some(footprint);
        let fresh = self.lambda.is_none();
        let mut lambda = self.lambda.unwrap_or([LAMBDA_START; 2]);
        let mut immediate = 0;
        loop {
            self.fill(
                0,
                source,
                bedding,
                start_unit,
                curvature.orientation,
                lambda,
                footprint,
            )?;
            self.press(0, approach)?;
            let s = self.slots[0].stats;
            let mut again = false;
            for ((l, &touch), &reach) in lambda.iter_mut().zip(&s.touches).zip(&s.reach) {
                // Cut off by the border: grow now (the field is wrong on this grid).
                if touch {
                    *l *= GROWTH;
                    again = true;
                } else if fresh && !(SHRINK_AT..=GROW_AT).contains(&reach) {
                    // A new grid settles at once, as PimP's adaptive domain does.
                    *l *= reach / TARGET_REACH;
                    again = true;
                }
            }
            if !again {
                break;
            }
            immediate += 1;
            self.fade = None;
            if immediate > MAX_RESIZES {
                return Err(Error::Geometry {
                    field: "extent".into(),
                    reason: format!(
                        "the grid does not settle on the contact zone after {MAX_RESIZES} \
                         resizes (grid factor {lambda:?} of the footprint {footprint:?} mm)"
                    ),
                });
            }
        }
        self.resizes += usize::from(!fresh) * immediate;
        // The old grid during a fade.
        let mut weight = 1.0;
        if let Some((old, progress)) = self.fade {
            self.fill(
                1,
                source,
                bedding,
                start_unit,
                curvature.orientation,
                old,
                footprint,
            )?;
            self.press(1, approach)?;
            let t = progress + motion / FADE_TRAVEL;
            if self.slots[1].stats.touches.iter().any(|&t| t) || !(t < 1.0) {
                self.fade = None;
            } else {
                self.fade = Some((old, t));
                weight = t * t * (3.0 - 2.0 * t);
            }
        }
        // Resize smoothly when the zone nears the border or fills little of the grid.
        if self.fade.is_none() && !fresh {
            let s = self.slots[0].stats;
            let mut target = lambda;
            for (t, &reach) in target.iter_mut().zip(&s.reach) {
                if !(SHRINK_AT..=GROW_AT).contains(&reach) {
                    *t *= reach / TARGET_REACH;
                }
            }
            if target != lambda {
                self.fade = Some((lambda, 0.0));
                lambda = target;
                self.resizes += 1;
            }
        }
        self.lambda = Some(lambda);
        let new = self.slots[0].stats;
        let view = if weight >= 0.5 { 0 } else { 1 };
        let blend = |f: fn(&Stats) -> f64| {
            if weight < 1.0 {
                weight * f(&new) + (1.0 - weight) * f(&self.slots[1].stats)
            } else {
                f(&new)
            }
        };
        let slot = &self.slots[view];
        Ok(TrackedField {
            grid: slot.crop,
            pressure: &slot.cropped,
            orientation: curvature.orientation,
            centroid: [blend(|s| s.centroid[0]), blend(|s| s.centroid[1])],
            force: blend(|s| s.force),
            max_pressure: blend(|s| s.max_pressure),
            contact_area: blend(|s| s.area),
            fade_weight: weight,
        })
    }

    /// Sample the gap of `source` into slot `k` on the grid `λ ⊙ footprint`.
    #[allow(clippy::too_many_arguments)]
    fn fill(
        &mut self,
        k: usize,
        source: &dyn GapSource,
        bedding: Bedding,
        start_unit: f64,
        rotation: f64,
        lambda: [f64; 2],
        footprint: [f64; 2],
    ) -> Result<()> {
        let half = [lambda[0] * footprint[0], lambda[1] * footprint[1]];
        let [nx, ny] = self.pimp.options.cells;
        let grid = Grid2::centered(half[0], half[1], nx, ny)?;
        let d_a = match bedding {
            Bedding::Corrected { d_a, .. } => d_a,
            Bedding::Published { .. } => 0.0,
        };
        let slot = &mut self.slots[k];
        slot.sampled.grid = grid;
        slot.sampled.rotation = rotation;
        slot.sampled.bedding = bedding;
        slot.sampled.start_unit = start_unit;
        slot.complete = true;
        if slot.lambda != lambda {
            // Other cells: the last zone's rows do not apply.
            slot.since_full = usize::MAX;
            slot.lambda = lambda;
        }
        let out = &mut slot.sampled.effective;
        match self.sampling {
            GapSampling::Exact => {
                source.sample(&grid, rotation, out)?;
                for row in out.chunks_exact_mut(nx) {
                    for (o, &u) in row.iter_mut().zip(&self.u) {
                        let x = u * half[0];
                        *o += d_a * x * x;
                    }
                }
            }
            GapSampling::Interpolated => {
                // Exact rays at the Chebyshev-Lobatto nodes of the grid's extent.
                let xs: [f64; NODES_X] = std::array::from_fn(|k| half[0] * node(k, NODES_X));
                let ys: [f64; NODES_Y] = std::array::from_fn(|l| half[1] * node(l, NODES_Y));
                // Column-major storage of F[k][l] is out[l * NODES_X + k].
                source.sample_points(
                    &xs,
                    &ys,
                    rotation,
                    self.stencil.as_mut_slice(),
                    &mut slot.warm,
                )?;
                if let Some(bad) = self.stencil.iter().position(|g| !g.is_finite()) {
                    return Err(Error::Geometry {
                        field: "surfaces".into(),
                        reason: format!(
                            "a ray of the gap stencil misses a surface at ({:.4e}, {:.4e}) mm \
                             in the contact plane: the contact reaches beyond the surfaces \
                             (GapSampling::Exact samples every cell instead)",
                            xs[bad % NODES_X],
                            ys[bad / NODES_X]
                        ),
                    });
                }
                // Monomial coefficients c[i][j] of u^i v^j: C = V_x⁻¹ F V_y⁻ᵀ.
                let mut c = self.vinv_x * self.stencil * self.vinv_y.transpose();
                // The corrected law's d_a x² = d_a h_x² u².
                c[(2, 0)] += d_a * half[0] * half[0];
                slot.coef = c;
                if matches!(bedding, Bedding::Corrected { .. }) {
                    // Evaluated row by row where the zone can be (`press`).
                    slot.complete = false;
                    return Ok(());
                }
                for (row, &v) in out.chunks_exact_mut(nx).zip(&self.v) {
                    // Row coefficients a_i = Σ_j c[i][j] v^j.
                    let mut a = [0.0; NODES_X];
                    for (i, ai) in a.iter_mut().enumerate() {
                        let mut s = c[(i, NODES_Y - 1)];
                        for j in (0..NODES_Y - 1).rev() {
                            s = s * v + c[(i, j)];
                        }
                        *ai = s;
                    }
                    // The cells lie symmetrically about u = 0: a(±u) = E(u²) ± u O(u²)
                    // gives two cells for one evaluation of the even and odd parts.
                    let even: [f64; EVEN] = std::array::from_fn(|m| a[2 * m]);
                    let odd: [f64; ODD] = std::array::from_fn(|m| a[2 * m + 1]);
                    let pairs = nx / 2;
                    let (left, rest) = row.split_at_mut(pairs);
                    let (middle, right) = rest.split_at_mut(nx - 2 * pairs);
                    if let Some(m) = middle.first_mut() {
                        *m = a[0];
                    }
                    let positive = &self.u[nx - pairs..];
                    for ((l, r), &u) in left.iter_mut().rev().zip(right.iter_mut()).zip(positive) {
                        let w = u * u;
                        let mut e = even[EVEN - 1];
                        for &c in even[..EVEN - 1].iter().rev() {
                            e = e * w + c;
                        }
                        let mut o = odd[ODD - 1];
                        for &c in odd[..ODD - 1].iter().rev() {
                            o = o * w + c;
                        }
                        *r = e + u * o;
                        *l = e - u * o;
                    }
                }
            }
        }
        Ok(())
    }

    /// The pressure of slot `k` at `approach` and its statistics.
    fn press(&mut self, k: usize, approach: Millimetre) -> Result<()> {
        if !self.slots[k].complete {
            return self.press_rows(k, approach);
        }
        let slot = &mut self.slots[k];
        slot.since_full = usize::MAX;
        let sampled = &slot.sampled;
        let grid = sampled.grid;
        match sampled.bedding {
            Bedding::Corrected {
                stiffness, kappa, ..
            } => {
                // Branch-free so it vectorises.
                let cut = kappa * approach;
                for (p, &g) in slot.pressure.iter_mut().zip(&sampled.effective) {
                    *p = stiffness * (cut - g).max(0.0).sqrt();
                }
            }
            Bedding::Published { .. } => sampled.pressure_into(approach, &mut slot.pressure),
        }
        let nx = grid.nx();
        let (mut total, mut cells, mut pmax) = (0.0, 0usize, 0.0f64);
        let (mut mu, mut my) = (0.0, 0.0);
        let (mut i0, mut i1, mut j0, mut j1) = (usize::MAX, 0, usize::MAX, 0);
        for (j, row) in slot.pressure.chunks_exact(nx).enumerate() {
            // Four independent lanes so the sums vectorise: Σp, Σp u, loaded cells, max p.
            let (mut s4, mut u4, mut n4, mut m4) =
                ([0.0f64; 4], [0.0f64; 4], [0.0f64; 4], [0.0f64; 4]);
            let chunks = row.chunks_exact(4);
            let rest = chunks.remainder();
            for (c, uc) in chunks.zip(self.u.chunks_exact(4)) {
                for l in 0..4 {
                    let p = c[l];
                    s4[l] += p;
                    u4[l] += p * uc[l];
                    n4[l] += if p > 0.0 { 1.0 } else { 0.0 };
                    m4[l] = if p > m4[l] { p } else { m4[l] };
                }
            }
            for (&p, &uc) in rest.iter().zip(&self.u[nx - rest.len()..]) {
                s4[0] += p;
                u4[0] += p * uc;
                n4[0] += if p > 0.0 { 1.0 } else { 0.0 };
                m4[0] = if p > m4[0] { p } else { m4[0] };
            }
            let rn = (n4[0] + n4[1]) + (n4[2] + n4[3]);
            if rn > 0.0 {
                let rs = (s4[0] + s4[1]) + (s4[2] + s4[3]);
                total += rs;
                mu += (u4[0] + u4[1]) + (u4[2] + u4[3]);
                my += rs * grid.y(j);
                cells += rn as usize;
                pmax = pmax.max(m4[0].max(m4[1]).max(m4[2].max(m4[3])));
                j0 = j0.min(j);
                j1 = j1.max(j);
                if let Some(first) = row.iter().position(|&p| p > 0.0) {
                    i0 = i0.min(first);
                }
                if let Some(last) = row.iter().rposition(|&p| p > 0.0) {
                    i1 = i1.max(last);
                }
            }
        }
        finish(slot, approach, total, cells, pmax, mu, my, [i0, i1, j0, j1])
    }
}

impl PimpTracker {
    /// Corrected mode on the interpolated gap: the gap and the pressure row by row, only in
    /// windows about the last call's zone (its rows' loaded columns and [`MARGIN`] cells
    /// and rows beyond), widened to the full row wherever the zone reaches a window's edge
    /// or a row next to an unevaluated one; every [`FULL_EVERY`] calls (and after a resize or
    /// a reset) all cells. Gives the full evaluation's field whenever the zone's rows each
    /// hold one run of loaded cells that overlaps the last call's (a zone moving by less
    /// than [`MARGIN`] cells per call); a new patch away from the zone is found within
    /// [`FULL_EVERY`] calls.
    fn press_rows(&mut self, k: usize, approach: Millimetre) -> Result<()> {
        let slot = &mut self.slots[k];
        let grid = slot.sampled.grid;
        let (nx, ny) = (grid.nx(), grid.ny());
        let Bedding::Corrected {
            stiffness, kappa, ..
        } = slot.sampled.bedding
        else {
            return Err(Error::invalid(
                "mode",
                "published",
                "the corrected law (row windows)",
            ));
        };
        let cut = kappa * approach;
        let full = slot.since_full >= FULL_EVERY;
        slot.since_full = if full { 0 } else { slot.since_full + 1 };
        // No clearing of the pressure: a full pass writes every cell, and a windowed pass
        // every cell that the last call loaded (each row's window holds its last loaded
        // run; a row with no run in the last call, nor in the two rows either side, held
        // none then and is zero). Cells outside this call's windows so stay zero.
        // This call's windows from the last call's loaded runs.
        let pairs = nx / 2;
        for j in 0..ny {
            let lo = if full {
                0
            } else {
                let mut lo = usize::MAX;
                for r in &slot.rows[j.saturating_sub(MARGIN)..(j + MARGIN + 1).min(ny)] {
                    if r.end > r.first {
                        lo = lo.min(r.first.min(nx - r.end));
                    }
                }
                if lo == usize::MAX {
                    usize::MAX
                } else {
                    lo.saturating_sub(MARGIN)
                }
            };
            slot.rows[j].lo = lo;
        }
        for j in 0..ny {
            let lo = slot.rows[j].lo;
            if lo != usize::MAX {
                slot.rows[j] = row_pass(slot, &self.u, &self.v, j, lo, cut, stiffness, pairs);
            }
        }
        // Widen where the zone reaches a window's edge or an unevaluated row.
        loop {
            let mut changed = false;
            for j in 0..ny {
                let r = slot.rows[j];
                if r.lo == usize::MAX || r.end <= r.first {
                    continue;
                }
                if r.lo > 0 && (r.first <= r.lo || r.end >= nx - r.lo) {
                    slot.rows[j] = row_pass(slot, &self.u, &self.v, j, 0, cut, stiffness, pairs);
                    changed = true;
                }
                for n in [j.wrapping_sub(1), j + 1] {
                    if n < ny && slot.rows[n].lo == usize::MAX {
                        slot.rows[n] =
                            row_pass(slot, &self.u, &self.v, n, 0, cut, stiffness, pairs);
                        changed = true;
                    }
                }
            }
            if !changed {
                break;
            }
        }
        // Rows not evaluated carry no load.
        for r in slot.rows.iter_mut().filter(|r| r.lo == usize::MAX) {
            r.first = 0;
            r.end = 0;
        }
        let (mut total, mut cells, mut pmax, mut mu, mut my) = (0.0, 0.0, 0.0f64, 0.0, 0.0);
        let (mut i0, mut i1, mut j0, mut j1) = (usize::MAX, 0, usize::MAX, 0);
        for (j, r) in slot.rows.iter().enumerate() {
            if r.end > r.first {
                total += r.sum;
                mu += r.sum_u;
                my += r.sum * grid.y(j);
                cells += r.cells;
                pmax = pmax.max(r.max);
                i0 = i0.min(r.first);
                i1 = i1.max(r.end - 1);
                j0 = j0.min(j);
                j1 = j1.max(j);
            }
        }
        finish(
            slot,
            approach,
            total,
            cells as usize,
            pmax,
            mu,
            my,
            [i0, i1, j0, j1],
        )
    }
}

/// The zone statistics and the cropped field of `slot` from the sums over its loaded cells:
/// Σp `total`, loaded `cells`, max p, Σp u `mu`, Σp y `my`, bounding box `[i0, i1, j0, j1]`.
///
/// # Errors
/// [`Error::Geometry`] when no cell is loaded.
#[allow(clippy::too_many_arguments)]
fn finish(
    slot: &mut Slot,
    approach: Millimetre,
    total: f64,
    cells: usize,
    pmax: f64,
    mu: f64,
    my: f64,
    [i0, i1, j0, j1]: [usize; 4],
) -> Result<()> {
    let grid = slot.sampled.grid;
    let (nx, ny) = (grid.nx(), grid.ny());
    if cells == 0 {
        return Err(Error::Geometry {
            field: "extent".into(),
            reason: format!(
                "no grid cell is in contact at the approach {approach:.4e} mm ({nx} × {ny} \
                 cells of {:.3e} × {:.3e} mm): the contact is smaller than one cell",
                grid.dx(),
                grid.dy()
            ),
        });
    }
    let da = grid.cell_area();
    let (hx, hy) = (0.5 * nx as f64 * grid.dx(), 0.5 * ny as f64 * grid.dy());
    let reach_x = (-(grid.x(i0) - 0.5 * grid.dx())).max(grid.x(i1) + 0.5 * grid.dx()) / hx;
    let reach_y = (-(grid.y(j0) - 0.5 * grid.dy())).max(grid.y(j1) + 0.5 * grid.dy()) / hy;
    slot.stats = Stats {
        force: total * da,
        max_pressure: pmax,
        area: cells as f64 * da,
        centroid: [mu * hx / total, my / total],
        reach: [reach_x, reach_y],
        touches: [i0 == 0 || i1 + 1 == nx, j0 == 0 || j1 + 1 == ny],
    };
    // The loaded cells' bounding box, for the friction integral (same cell centres).
    let (dx, dy) = (grid.dx(), grid.dy());
    slot.crop = Grid2::new(
        [grid.x(i0) - 0.5 * dx, grid.x(i1) + 0.5 * dx],
        [grid.y(j0) - 0.5 * dy, grid.y(j1) + 0.5 * dy],
        i1 - i0 + 1,
        j1 - j0 + 1,
    )?;
    slot.cropped.clear();
    for row in slot.pressure.chunks_exact(nx).skip(j0).take(j1 - j0 + 1) {
        slot.cropped.extend_from_slice(&row[i0..=i1]);
    }
    Ok(())
}

/// The gap and pressure of row `j` over the columns `[lo, nx − lo)` of `slot`, from the
/// slot's polynomial; `u`, `v` the normalised cell centres. Cells outside the window keep
/// zero pressure.
#[allow(clippy::too_many_arguments)]
fn row_pass(
    slot: &mut Slot,
    u: &[f64],
    v: &[f64],
    j: usize,
    lo: usize,
    cut: f64,
    stiffness: f64,
    pairs: usize,
) -> Row {
    let nx = u.len();
    let lo = lo.min(pairs);
    let c = &slot.coef;
    let vj = v[j];
    let mut a = [0.0; NODES_X];
    for (i, ai) in a.iter_mut().enumerate() {
        let mut s = c[(i, NODES_Y - 1)];
        for jj in (0..NODES_Y - 1).rev() {
            s = s * vj + c[(i, jj)];
        }
        *ai = s;
    }
    let even: [f64; EVEN] = std::array::from_fn(|m| a[2 * m]);
    let odd: [f64; ODD] = std::array::from_fn(|m| a[2 * m + 1]);
    // Pairs k = 0 .. n outward from the centre: E(u²) ± u O(u²) into the scratch rows of
    // the gap (forward loops, so they vectorise) and the pressure of both cells in the same
    // loop (the square roots overlap the polynomial), then the row's two halves.
    let n = pairs - lo;
    let positive = &u[nx - pairs..nx - pairs + n];
    // The right half straight into the row, the left half (outward = backwards) into the
    // scratch rows first.
    let (g_left, g_rest) = slot.sampled.effective[j * nx..(j + 1) * nx].split_at_mut(pairs);
    let (g_middle, g_right) = g_rest.split_at_mut(nx - 2 * pairs);
    let (p_left, p_rest) = slot.pressure[j * nx..(j + 1) * nx].split_at_mut(pairs);
    let (p_middle, p_right) = p_rest.split_at_mut(nx - 2 * pairs);
    let (ls, lp) = (&mut slot.gap_left[..n], &mut slot.press_left[..n]);
    for ((((g_r, g_l), p_r), p_l), &uk) in g_right[..n]
        .iter_mut()
        .zip(ls.iter_mut())
        .zip(p_right[..n].iter_mut())
        .zip(lp.iter_mut())
        .zip(positive)
    {
        let w = uk * uk;
        let mut e = even[EVEN - 1];
        for &cc in even[..EVEN - 1].iter().rev() {
            e = e * w + cc;
        }
        let mut o = odd[ODD - 1];
        for &cc in odd[..ODD - 1].iter().rev() {
            o = o * w + cc;
        }
        let uo = uk * o;
        let (gr, gl) = (e + uo, e - uo);
        *g_r = gr;
        *g_l = gl;
        *p_r = stiffness * (cut - gr).max(0.0).sqrt();
        *p_l = stiffness * (cut - gl).max(0.0).sqrt();
    }
    for (l, &g) in g_left[lo..].iter_mut().zip(ls.iter().rev()) {
        *l = g;
    }
    for (l, &pv) in p_left[lo..].iter_mut().zip(lp.iter().rev()) {
        *l = pv;
    }
    if let (Some(m), Some(pm)) = (g_middle.first_mut(), p_middle.first_mut()) {
        *m = a[0];
        *pm = stiffness * (cut - a[0]).max(0.0).sqrt();
    }
    let p = &slot.pressure[j * nx + lo..(j + 1) * nx - lo];
    let (Some(f), Some(e)) = (
        p.iter().position(|&x| x > 0.0),
        p.iter().rposition(|&x| x > 0.0),
    ) else {
        return Row {
            lo,
            ..Row::default()
        };
    };
    let (first, end) = (lo + f, lo + e + 1);
    let loaded = &p[f..=e];
    let ul = &u[first..end];
    // Four independent lanes so the sums and the maximum vectorise (p ≥ 0, no NaN: the
    // square root of a non-negative number).
    let (mut s4, mut u4, mut n4, mut m4) = ([0.0f64; 4], [0.0f64; 4], [0.0f64; 4], [0.0f64; 4]);
    let chunks = loaded.chunks_exact(4);
    let rest_p = chunks.remainder();
    for (pc, uc) in chunks.zip(ul.chunks_exact(4)) {
        for l in 0..4 {
            s4[l] += pc[l];
            u4[l] += pc[l] * uc[l];
            n4[l] += f64::from(u8::from(pc[l] > 0.0));
            m4[l] = if pc[l] > m4[l] { pc[l] } else { m4[l] };
        }
    }
    for (&pv, &uv) in rest_p.iter().zip(&ul[ul.len() - rest_p.len()..]) {
        s4[0] += pv;
        u4[0] += pv * uv;
        n4[0] += f64::from(u8::from(pv > 0.0));
        m4[0] = if pv > m4[0] { pv } else { m4[0] };
    }
    let cells = (n4[0] + n4[1]) + (n4[2] + n4[3]);
    let max = m4[0].max(m4[1]).max(m4[2].max(m4[3]));
    Row {
        lo,
        first,
        end,
        sum: (s4[0] + s4[1]) + (s4[2] + s4[3]),
        sum_u: (u4[0] + u4[1]) + (u4[2] + u4[3]),
        cells,
        max,
    }
}

/// Chebyshev-Lobatto node `k` of `n` in [−1, 1], ascending.
fn node(k: usize, n: usize) -> f64 {
    -(std::f64::consts::PI * k as f64 / (n - 1) as f64).cos()
}
