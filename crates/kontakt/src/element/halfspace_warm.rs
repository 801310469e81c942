//! The half-space back-end's state between evaluations: a solver on a fixed grid in the
//! contact frame, warm-started from the last pressure field.
//!
//! A multi-body step moves the bodies a little, so the contact zone changes a little. The
//! element keeps one [`HalfSpaceSolver`] on a grid that holds the zone with a margin, and
//! each evaluation re-samples the gap on that grid (interpolated from exact rays at
//! Chebyshev-Lobatto nodes, as the PimP tracker does) and restarts the constrained conjugate
//! gradients from the previous pressure (Polonsky & Keer 1999; [`Start::Warm`]). The grid
//! is re-chosen only when the zone reaches its border or fills less than
//! [`MIN_FILL`] of it (or the warm solve does not converge); then one adaptive solve ([`Bem::solve_approach`]) finds the zone
//! and the new grid is laid on a ladder of spacings `2^(k/8)` mm, so that elements of
//! similar contacts land on the same spacing and share one plan through the planner
//! ([`ContactElement::with_planner`](super::ContactElement::with_planner)).
//!
//! The grid is turned by a fixed rotation in the gap frame (the gap's principal
//! direction when the grid was laid), so the warm field stays aligned while the
//! principal directions drift; any rotation holds the zone, the solve does not depend on
//! it beyond the discretisation.

use crate::error::{Error, Result};
use crate::field::ContactZone;
use crate::gap::GapSource;
use crate::geometry::Grid2;
use crate::halfspace::{Bem, Control, HalfSpaceSolver, Start};

/// The zone must fill at least this fraction of the grid's width along each axis, or
/// the grid is re-chosen (smaller). The adaptive solver shrinks below 0.6; the lower
/// bound here gives hysteresis, so a zone near a threshold does not toggle the grid.
pub const MIN_FILL: f64 = 0.45;

/// Steps per octave of the grid-spacing ladder.
const LADDER_STEPS: f64 = 8.0;

/// The back-end's state. `Clone` gives a cold state (the solver's fields are not copied).
#[derive(Debug, Default)]
pub(crate) struct WarmHalfSpace {
    state: Option<State>,
    /// Grids laid since the element was planned or reset.
    pub(crate) grids_laid: usize,
}

impl Clone for WarmHalfSpace {
    fn clone(&self) -> Self {
        WarmHalfSpace::default()
    }
}

#[derive(Debug)]
struct State {
    solver: HalfSpaceSolver,
    /// Rotation of the grid in the gap frame \[rad\].
    rotation: f64,
    /// The gap sampled on the grid \[mm\].
    gap: Vec<f64>,
    /// Zeros of the grid's size: the field when the approach reaches no cell centre.
    zeros: Vec<f64>,
    /// The zone of the solver's last pressure field (on warm calls its one-pass
    /// summary, [`ContactZone::summarise`]: the element needs no patch count or shape).
    zone: ContactZone,
    /// The interpolated gap of the warm calls (`None`: ray-cast every cell).
    stencil: Option<Stencil>,
}

/// Chebyshev-Lobatto nodes per axis of the warm calls' interpolated gap.
const NODES: usize = 9;

/// The gap of a warm call interpolated from exact rays at `NODES × NODES`
/// Chebyshev-Lobatto points spanning the grid's cell centres (the PimP tracker's
/// approach, docs/mbs.md), instead of a ray at every cell: 81 rays instead of 4096 at
/// 64², and a tensor-product Lagrange interpolation with weights planned with the grid.
#[derive(Debug)]
struct Stencil {
    xs: [f64; NODES],
    ys: [f64; NODES],
    /// Lagrange weights of the nodes at each cell centre: `wx[i]` along x, `wy[j]` along y,
    /// and `wx` node-major, `wx_t[k * nx + i] = wx[i][k]`.
    wx: Vec<[f64; NODES]>,
    wy: Vec<[f64; NODES]>,
    wx_t: Vec<f64>,
    /// Exact gaps at the nodes, `values[l * NODES + k]` at `(xs[k], ys[l])`.
    values: [f64; NODES * NODES],
    /// The rays' warm-start data (`GapSource::sample_points`).
    warm: Vec<[f64; 2]>,
}

impl Stencil {
    fn new(grid: &Grid2) -> Option<Self> {
        let (nx, ny) = (grid.nx(), grid.ny());
        if nx < NODES || ny < NODES {
            return None;
        }
        let nodes = |lo: f64, hi: f64| -> [f64; NODES] {
            std::array::from_fn(|k| {
                let t = (std::f64::consts::PI * k as f64 / (NODES - 1) as f64).cos();
                0.5 * (lo + hi) + 0.5 * (hi - lo) * t
            })
        };
        let xs = nodes(grid.x(0), grid.x(nx - 1));
        let ys = nodes(grid.y(0), grid.y(ny - 1));
        let wx: Vec<[f64; NODES]> = (0..nx).map(|i| lagrange(grid.x(i), &xs)).collect();
        let wx_t = (0..NODES)
            .flat_map(|k| wx.iter().map(move |w| w[k]))
            .collect();
        Some(Stencil {
            xs,
            ys,
            wx,
            wx_t,
            wy: (0..ny).map(|j| lagrange(grid.y(j), &ys)).collect(),
            values: [0.0; NODES * NODES],
            warm: vec![[f64::INFINITY; 2]; NODES * NODES],
        })
    }

    /// The interpolated gap into `out`; `false` (and `out` untouched) when a node's ray
    /// misses a surface, for the caller to ray-cast every cell.
    fn sample(&mut self, source: &dyn GapSource, rotation: f64, out: &mut [f64]) -> Result<bool> {
        source.sample_points(
            &self.xs,
            &self.ys,
            rotation,
            &mut self.values,
            &mut self.warm,
        )?;
        if self.values.iter().any(|v| !v.is_finite()) {
            return Ok(false);
        }
        let nx = self.wx.len();
        for (row, wy) in out.chunks_exact_mut(nx).zip(&self.wy) {
            // Interpolate along y first: the row's values at the x nodes.
            let mut a = [0.0; NODES];
            for (l, w) in wy.iter().enumerate() {
                let f = &self.values[l * NODES..(l + 1) * NODES];
                for (ak, fk) in a.iter_mut().zip(f) {
                    *ak += w * fk;
                }
            }
            // Then along x, node by node over the row (vectorisable across the cells;
            // each cell's sum from -0.0 in node order, as `Iterator::sum`: same bits).
            row.fill(-0.0);
            for (wk, &ak) in self.wx_t.chunks_exact(nx).zip(&a) {
                for (o, &w) in row.iter_mut().zip(wk) {
                    *o += w * ak;
                }
            }
        }
        Ok(true)
    }
}

/// The Lagrange weights of Chebyshev-Lobatto `nodes` at `x` (barycentric form, node
/// weights `(-1)^k`, halved at the two ends).
fn lagrange(x: f64, nodes: &[f64; NODES]) -> [f64; NODES] {
    let mut w = [0.0; NODES];
    if let Some(k) = nodes.iter().position(|&n| n == x) {
        w[k] = 1.0;
        return w;
    }
    let mut sum = 0.0;
    for (k, (wk, &n)) in w.iter_mut().zip(nodes).enumerate() {
        let b = if k == 0 || k == NODES - 1 { 0.5 } else { 1.0 };
        let sign = if k % 2 == 0 { 1.0 } else { -1.0 };
        *wk = sign * b / (x - n);
        sum += *wk;
    }
    w.iter_mut().for_each(|v| *v /= sum);
    w
}

/// The one-cell unloaded field of an approach that reaches no cell centre of the
/// adaptive solver's grids (a touch in round-off, for example surfaces placed exactly
/// tangent).
const UNLOADED: [f64; 1] = [0.0];

/// What one evaluation gives: borrowed from the state.
pub(crate) struct WarmField<'a> {
    pub grid: Grid2,
    pub pressure: &'a [f64],
    pub rotation: f64,
    pub zone: ContactZone,
    pub force: f64,
    pub iterations: usize,
}

impl WarmHalfSpace {
    /// Forget the grid and the last field.
    pub(crate) fn reset(&mut self) {
        self.state = None;
        self.grids_laid = 0;
    }

    /// Solve `source` at the rigid approach `approach` \[mm\], warm when the kept grid
    /// still holds the zone (stopping at the looser of `warm_tolerance` and the
    /// back-end's tolerance), else on a newly laid grid (at the back-end's tolerance).
    pub(crate) fn solve(
        &mut self,
        bem: &Bem,
        source: &dyn GapSource,
        approach: f64,
        warm_tolerance: f64,
    ) -> Result<WarmField<'_>> {
        let control = Control::Approach(approach);
        let mut iterations = 0;
        let warm_ok = match self.state.as_mut() {
            Some(st) => {
                let grid = *st.solver.grid();
                let interpolated = match st.stencil.as_mut() {
                    Some(s) => s.sample(source, st.rotation, &mut st.gap)?,
                    None => false,
                };
                if !interpolated {
                    source.sample(&grid, st.rotation, &mut st.gap)?;
                }
                let h_min = crate::halfspace::smallest(&st.gap);
                if approach <= h_min {
                    // The bodies overlap by less than the gap at any cell centre: no
                    // cell is loaded; the grid is kept for the next call.
                    let st = self.state.as_ref().ok_or_else(no_state)?;
                    return Ok(unloaded(grid, &st.zeros, st.rotation));
                }
                st.solver
                    .set_tolerance(bem.options().tolerance.max(warm_tolerance))?;
                let report = st.solver.solve(&st.gap, control, Start::Secant)?;
                iterations += report.status.iterations;
                // A warm solve that does not converge is not the answer: lay a grid and
                // solve from cold (whose non-convergence is then an error).
                report.status.converged() && {
                    st.zone = ContactZone::summarise(&grid, st.solver.pressure())?;
                    fits(&grid, &st.zone)
                }
            }
            None => false,
        };
        if !warm_ok {
            match self.lay_grid(bem, source, approach) {
                Ok(n) => iterations += n,
                Err(Error::Geometry { field, .. }) if field == "approach" => {
                    let grid = Grid2::new([-1e-6, 1e-6], [-1e-6, 1e-6], 1, 1)?;
                    return Ok(unloaded(grid, &UNLOADED, 0.0));
                }
                Err(e) => return Err(e),
            }
        }
        let st = self.state.as_ref().ok_or_else(no_state)?;
        Ok(WarmField {
            grid: *st.solver.grid(),
            pressure: st.solver.pressure(),
            rotation: st.rotation,
            zone: st.zone,
            force: st.zone.force,
            iterations,
        })
    }

    /// Find the zone with the adaptive solver, lay a ladder grid over it and solve there
    /// from cold. Returns the iterations spent.
    fn lay_grid(&mut self, bem: &Bem, source: &dyn GapSource, approach: f64) -> Result<usize> {
        let found = bem.solve_approach(source, approach)?;
        let mut iterations = found.status.iterations;
        let rotation = found.orientation;
        let cells = [found.grid.nx(), found.grid.ny()];
        let margin = bem.options().margin;
        let mut half = [0.0; 2];
        let mut centre = [0.0; 2];
        for k in 0..2 {
            let [lo, hi] = found.zone.extents[k];
            centre[k] = 0.5 * (lo + hi);
            half[k] = 0.5 * (hi - lo) * margin;
        }
        // Grow by one ladder step at most a few times if the laid grid cuts the zone.
        for _ in 0..4 {
            let grid = ladder_grid(centre, half, cells)?;
            let mut solver = bem.solver_on(grid)?;
            let mut gap = vec![0.0; grid.len()];
            source.sample(&grid, rotation, &mut gap)?;
            let report = solver
                .solve(&gap, Control::Approach(approach), Start::Cold)?
                .require_converged()?;
            iterations += report.status.iterations;
            let zone = ContactZone::analyse(&grid, solver.pressure())?;
            self.grids_laid += 1;
            let [bx, by] = zone.touches_border;
            if bx || by {
                half = half.map(|h| h * 2f64.powf(1.0 / LADDER_STEPS) * 1.2);
                continue;
            }
            crate::field::domain::check_resolution(&grid, &zone)?;
            solver.set_incremental_updates(true);
            solver.set_secant_only(true);
            self.state = Some(State {
                solver,
                rotation,
                zeros: vec![0.0; gap.len()],
                gap,
                zone,
                stencil: Stencil::new(&grid),
            });
            return Ok(iterations);
        }
        Err(Error::Geometry {
            field: "extent".into(),
            reason: "the half-space grid of the contact element did not settle on the \
                     contact zone in 4 grids: the zone is unbounded or far from the contact \
                     point"
                .into(),
        })
    }
}

fn no_state() -> Error {
    Error::invalid(
        "backend",
        "a half-space state without a grid",
        "a grid laid by the first evaluation",
    )
}

/// The field of no loaded cell on `grid`.
fn unloaded(grid: Grid2, zeros: &[f64], rotation: f64) -> WarmField<'_> {
    WarmField {
        grid,
        pressure: zeros,
        rotation,
        zone: ContactZone::EMPTY,
        force: 0.0,
        iterations: 0,
    }
}

/// Whether the kept grid still holds the zone: not on the border, and filling at least
/// [`MIN_FILL`] of the width each way.
fn fits(grid: &Grid2, zone: &ContactZone) -> bool {
    let [bx, by] = zone.touches_border;
    if bx || by || zone.patches == 0 {
        return false;
    }
    let e = zone.extents;
    let fill = [
        (e[0][1] - e[0][0]) / (grid.nx() as f64 * grid.dx()),
        (e[1][1] - e[1][0]) / (grid.ny() as f64 * grid.dy()),
    ];
    fill[0] >= MIN_FILL && fill[1] >= MIN_FILL
}

/// The grid of `cells` centred on `centre` \[mm\] whose spacing is the next rung at or
/// above `2·half/n` on the ladder `2^(k/8)` mm.
fn ladder_grid(centre: [f64; 2], half: [f64; 2], cells: [usize; 2]) -> Result<Grid2> {
    let mut bounds = [[0.0; 2]; 2];
    for k in 0..2 {
        let want = 2.0 * half[k] / cells[k] as f64;
        let rung = (want.log2() * LADDER_STEPS).ceil() / LADDER_STEPS;
        let d = 2f64.powf(rung);
        let h = 0.5 * d * cells[k] as f64;
        bounds[k] = [centre[k] - h, centre[k] + h];
    }
    Grid2::new(bounds[0], bounds[1], cells[0], cells[1])
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The half-space solver for steel on steel, one thread.
    fn steel_bem() -> Bem {
        Bem::new(
            crate::material::ElasticMaterial::STEEL,
            crate::material::ElasticMaterial::STEEL,
            crate::halfspace::BemOptions {
                threads: Some(1),
                ..crate::halfspace::BemOptions::default()
            },
        )
        .unwrap()
    }

    /// The interpolated gap against the ray cast of every cell on the warm grid of the
    /// torus/torus roller-end/rib pairing at 4.2 µm, and the force of a warm solve on each
    /// (docs/PERFORMANCE.md, issue 12).
    #[test]
    fn interpolated_gap_matches_the_ray_cast() {
        use crate::bearing::{RollerRib, RollerRibSpec};
        use crate::gap::SurfacePairGap;
        let rr = RollerRib::new(RollerRibSpec::builtin("torus-torus-14").unwrap()).unwrap();
        let source = SurfacePairGap::new(rr.face.clone(), rr.rib.clone(), rr.contact).unwrap();
        let bem = steel_bem();
        let approach = 0.0042;
        let mut warm = WarmHalfSpace::default();
        warm.solve(&bem, &source, approach, 0.0).unwrap();
        let st = warm.state.as_mut().unwrap();
        let grid = *st.solver.grid();
        let mut exact = vec![0.0; grid.len()];
        source.sample(&grid, st.rotation, &mut exact).unwrap();
        let mut interp = vec![0.0; grid.len()];
        let stencil = st.stencil.as_mut().unwrap();
        assert!(stencil.sample(&source, st.rotation, &mut interp).unwrap());
        let (mut worst, mut worst_loaded) = (0.0f64, 0.0f64);
        for ((e, i), p) in exact.iter().zip(&interp).zip(st.solver.pressure()) {
            worst = worst.max((e - i).abs());
            if *p > 0.0 {
                worst_loaded = worst_loaded.max((e - i).abs());
            }
        }
        let fx = st
            .solver
            .solve(&exact, Control::Approach(approach), Start::Warm)
            .unwrap()
            .force;
        let fi = st
            .solver
            .solve(&interp, Control::Approach(approach), Start::Warm)
            .unwrap()
            .force;
        eprintln!(
            "interpolated gap on {}x{}: worst error {worst:.2e} mm ({:.1e} of the approach), \
             {worst_loaded:.2e} mm on loaded cells; force {fx:.9} N exact, {fi:.9} N \
             interpolated ({:.1e})",
            grid.nx(),
            grid.ny(),
            worst / approach,
            fi / fx - 1.0
        );
        assert!(worst < 1e-6 * approach, "{worst:e} mm");
        assert!((fi / fx - 1.0).abs() < 1e-6);
    }

    /// The element's friction on the warm grid ([`crate::friction::grid_friction_binned`],
    /// the Coulomb law once per block of cells) against the cell-by-cell sums of
    /// [`crate::friction::grid_friction`] on the same field: the roller-end/rib pairing at
    /// 4.2 µm, the roller spinning at 10 rad/s about the world z axis (the bench's twist),
    /// after a few warm pose steps. Errors relative to `T = Σ |τ| ΔA` for the force, to
    /// `T` times the zone's half-length for the moment and to `T v_max` for the power:
    /// below 2e-6 (the blocks' bound is 1e-6 of each cell's stress), with blocks of more
    /// than one cell in effect.
    #[test]
    fn binned_friction_on_the_warm_grid_matches_the_cell_sums() {
        use crate::bearing::{RollerRib, RollerRibSpec};
        use crate::friction::grid_friction_binned;
        use crate::friction::{FilmState, FrictionLaw, binning_blocks, grid_friction};
        use crate::gap::SurfacePairGap;
        use crate::geometry::{BodyState, ContactFrame, ContactPair, Twist};
        use nalgebra::{Isometry3, Translation3, UnitQuaternion, Vector3};
        let rr = RollerRib::new(RollerRibSpec::builtin("torus-torus-14").unwrap()).unwrap();
        let bem = steel_bem();
        let law = FrictionLaw::coulomb(0.1)
            .unwrap()
            .with_film(&FilmState::dry())
            .unwrap();
        let n = rr.contact.normal.into_inner();
        let across = n.cross(&Vector3::z()).normalize();
        let mut warm = WarmHalfSpace::default();
        for k in 0..4 {
            let shift = Isometry3::from_parts(
                Translation3::from(across * (1.4e-3 * k as f64)),
                UnitQuaternion::identity(),
            );
            let face =
                crate::geometry::PlacedSurface::new(rr.face.surface.clone(), shift * rr.face.pose)
                    .unwrap();
            let contact = crate::geometry::find_contact(&face, &rr.rib, None).unwrap();
            let approach = -contact.separation;
            let source = SurfacePairGap::new(face, rr.rib.clone(), contact).unwrap();
            let w = warm.solve(&bem, &source, approach, 1e-6).unwrap();
            let pair = ContactPair {
                body1: BodyState {
                    pose: shift,
                    twist: Twist::new(Vector3::zeros(), Vector3::new(0.0, 0.0, 10.0)),
                },
                body2: BodyState::at_rest(),
                observer: BodyState::at_rest(),
            };
            let sliding = pair
                .velocity_field(&ContactFrame::of_gap(&source), w.rotation)
                .unwrap();
            let blocks = binning_blocks(&w.grid, &sliding).unwrap();
            let cells = grid_friction(&w.grid, w.pressure, &sliding, &law).unwrap();
            let binned = grid_friction_binned(&w.grid, w.pressure, &sliding, &law).unwrap();
            let t = 0.1 * cells.normal_force;
            let half = 0.5
                * (w.zone.extents[0][1] - w.zone.extents[0][0])
                    .max(w.zone.extents[1][1] - w.zone.extents[1][0]);
            let v_max = w
                .grid
                .points()
                .map(|(x, y)| {
                    let [vx, vy] = sliding.sliding_at(x, y);
                    vx.hypot(vy)
                })
                .fold(0.0, f64::max);
            let e = [
                (binned.force[0] - cells.force[0]).hypot(binned.force[1] - cells.force[1]) / t,
                (binned.moment - cells.moment).abs() / (t * half),
                (binned.power - cells.power).abs() / (t * v_max * 1e-3),
            ];
            eprintln!(
                "step {k}: blocks {blocks:?}, errors force {:.1e}, moment {:.1e}, power {:.1e}",
                e[0], e[1], e[2]
            );
            assert!(blocks[0] * blocks[1] > 1, "{blocks:?}");
            assert!(e.iter().all(|&x| x < 2e-6), "{e:?}");
        }
    }

    #[test]
    fn ladder_spacing_is_a_rung_at_or_above_the_request() {
        for want in [1e-4, 3.3e-3, 0.0217, 0.5, 1.0] {
            let g = ladder_grid([0.1, -0.2], [want * 32.0, want * 16.0], [64, 32]).unwrap();
            for d in [g.dx(), g.dy()] {
                let k = d.log2() * LADDER_STEPS;
                assert!((k - k.round()).abs() < 1e-9, "{d} is not a rung");
                assert!(
                    d >= want * (1.0 - 1e-12) && d < want * 2f64.powf(1.0 / 8.0),
                    "{d}"
                );
            }
            assert!((0.5 * (g.x(0) + g.x(63)) - 0.1).abs() < 1e-12);
        }
    }
}
