//! `kalker_exact`: creep curves of a Hertz contact from Kalker's exact theory of steady
//! rolling ([`super::SteadySolver`]), as a traction model beside Carter, Kalker's linear
//! theory and FASTSIM ([`crate::tangential`]).
//!
//! # Model
//! [`KalkerExact::new`] plans a [`super::SteadySolver`] on a grid over the contact
//! ellipse (`a` along the rolling direction `x`, `b` across, both \[mm\]) with the Hertz
//! pressure `p0 sqrt(1 - x²/a² - y²/b²)` \[MPa\] at the cell centres. The grid has
//! `elements = [mx, my]` cells across the ellipse (`dx = 2a/mx`, `dy = 2b/my`) plus one
//! unloaded column beyond each edge along `x`, so the leading-edge column the steady
//! solver needs is empty. The sampled pressure is scaled so that `Σ p ΔA = F_N` exactly:
//! full sliding then gives `|F| = μ F_N` to the solver's tolerance, and the curve is
//! normalised by the true normal force.
//!
//! **Any pressure field.** [`KalkerExact::from_pressure`] and
//! [`KalkerExact::from_solution`] plan the same solver on the pressure of a normal-contact
//! solver instead (the half-space solver, PimP: non-Hertzian zones). The field, uniform
//! per cell on its own grid, is resampled onto a grid aligned with the rolling
//! direction: `elements = [mx, my]` cells across the loaded cells' extent along and
//! across it, plus one unloaded column beyond each edge along `x`; each new cell takes
//! the bilinear interpolation of the field's cell centres where it lies in a loaded
//! cell of the field, and zero elsewhere (so the support is the field's own loaded
//! cells, and the leading-edge column stays empty); the result is scaled to the
//! field's normal force `Σ p ΔA`. The new grid's origin is the field's origin (the
//! contact point of the gap), so the spin pole and the spin moment refer to it.
//!
//! Each creepage point (longitudinal `ξ` \[-\], lateral `η` \[-\], spin `φ` \[1/mm\]) is one
//! steady solve; along a curve the solver starts from the previous point's tractions (a
//! warm start). Every point carries the solver's [`SolveStatus`]: a point that did not
//! converge is reported as such ([`ExactPoint::status`]), and the [`TractionCurve`]
//! implementation turns it into [`Error::NotConverged`] instead of a number.
//!
//! Forces `F_x`, `F_y` \[N\] and the spin moment `M_z` \[N·mm\] (about the contact centre)
//! act on body 1 and oppose the creepages (conventions of [`crate::tangential`]); the
//! traction curve is `F_T/(μ F_N)` with `F_T = -F_x`.
//!
//! # Grid and accuracy
//! The creep force converges as the grid is refined, but not monotonically at small
//! creepage, where the discrete contact boundary (which cells carry pressure) sets the
//! error: on a circle the small-creepage slope against Kalker's tabulated `C11` is
//! +0.9 %, +4.8 %, -0.3 %, +1.4 %, -0.3 % at 12, 16, 24, 32, 48 cells across; in the knee
//! of the curve (`u = 1.5` of the linear saturation creepage) the force falls steadily,
//! 0.927, 0.923, 0.911, 0.910, 0.904 of `μ F_N`, and lies about 1 % above its
//! extrapolated limit at 32 cells (docs/tangential.md §11). At full slip the grid error
//! vanishes. Grids with fewer than [`KalkerExactOptions::MIN_ELEMENTS`] cells across the
//! contact in either direction are refused (they cannot resolve the slip area, which
//! starts as a strip at the trailing edge); the default `[32, 32]` is a compromise of
//! accuracy and speed for pure creepages (1-2 % in the knee). With spin the force converges
//! more slowly (CONTACT's lateral-plus-spin case on `a/b = 2`: 5.9 % low at 32 cells, 3.0 %
//! at 64, 1.5 % at 128, first order; docs/rolling.md §6.1), and
//! [`KalkerExactOptions::coarse_for`] flags such grids below
//! [`KalkerExactOptions::SPIN_ELEMENTS`] cells.
//!
//! # Dissimilar bodies (the coupling)
//! With [`KalkerExactOptions::coupling`] and bodies of different materials (Kalker's
//! difference parameter `K ≠ 0`, known to [`KalkerExact::new`] from both materials), each
//! point is solved by [`super::CoupledSteadySolver`]: the normal problem (half-space
//! solver, force control `F_N`) and the steady tangential problem coupled through `K`
//! by its outer loop, so the pressure changes with the tractions. The normal problem's
//! undeformed gap is the quadratic gap of the ellipse's Hertz contact,
//! `h = A x² + B y²` \[mm\], whose frictionless solution under `F_N` with
//! `E* = G/(1 − ν)` \[MPa\] (Kalker's constants: Love's compliance of both bodies) is
//! the ellipse (`A`, `B` \[1/mm\] from `a`, `b`, `F_N`, `E*` by Hertz's displacement
//! of the elliptic pressure, Johnson 1985 eq. 3.63). Its grid has the same cell size,
//! with `2 + ⌈max(0.1, |K| μ) mx/2⌉` empty columns beyond each edge along `x` (the
//! tractions' normal displacement shifts the contact along `x`: by 0.03 `a` at `K = 0.1`,
//! `μ = 0.5`, 0.05 `a` at `μ = 1` in full sliding, and the leading-edge column must stay
//! empty) and one empty
//! row beyond each edge along `y`.
//! Points are warm-started along a curve (pressure, tractions); each carries the outer
//! loop's status (its passes and last relative change, or the failing inner solve's).
//! [`KalkerExact::free_rolling`] gives the creepage of free rolling (`F_x = 0`), by the
//! coupled solver's force control; zero for `K = 0`. With `K = 0` (equal materials) or
//! the option off, the model is the uncoupled one, bit for bit. The models on a pressure
//! field ([`KalkerExact::from_pressure`], [`KalkerExact::from_solution`]) and from the
//! combined constants alone ([`KalkerExact::with_material`]) refuse the coupling: the
//! first have no gap, the second no `K`.
//!
//! # Assumptions
//! Those of [`super::SteadySolver`]: quasi-identical bodies (Kalker's `K = 0`) unless the
//! coupling is on, the Hertz pressure (or the given field) unchanged by the tractions
//! (with the coupling: the normal solution of the Hertz gap, coupled), constant Coulomb
//! friction `μ`, steady rolling along `x` (an axis of the ellipse, or the given
//! direction), a plane contact (a field's curved zone is taken in its tangent plane).
//!
//! # References
//! Kalker, *Three-dimensional elastic bodies in rolling contact* (1990), ch. 5 (and
//! §1.6 for `K`); Vollebregt, CONTACT user guide (reference outputs of its examples,
//! used as test data in `tests/rolling_exact.rs`, and its example `bentall`);
//! Bentall & Johnson (1967), the free-rolling creepage of dissimilar rollers; Johnson,
//! *Contact Mechanics* (1985), eq. 3.63.

use super::coupled_steady::{
    CoupledSteadyOptions, CoupledSteadySolution, CoupledSteadySolver, SteadyLoad,
};
use super::operator::difference_parameter;
use super::steady::{SteadyOptions, SteadySolution, SteadySolver};
use crate::error::{Error, Result};
use crate::field::NormalSolution;
use crate::geometry::Grid2;
use crate::halfspace::{Control, SolverOptions};
use crate::hertz::ellipse_gap_curvatures;
use crate::material::ElasticMaterial;
use crate::solve::SolveStatus;
use crate::tangential::{
    ContactEllipse, Creepage, KalkerMaterial, TractionCurve, check_creepage, check_friction,
};
use crate::units::{Newton, NewtonMillimetre};
use std::sync::Mutex;

/// Options of [`KalkerExact`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct KalkerExactOptions {
    /// Cells across the contact ellipse `[mx, my]`: `mx` along the rolling direction
    /// (over `2a`), `my` across (over `2b`); each
    /// [`MIN_ELEMENTS`](Self::MIN_ELEMENTS)..=[`MAX_ELEMENTS`](Self::MAX_ELEMENTS).
    /// Default `[32, 32]`.
    pub elements: [usize; 2],
    /// The steady solver's tolerances and limits. Default: `steady_tolerance = 1e-6`,
    /// `tolerance = 1e-7` (forces to about 1e-5 of `μ F_N`), the rest as
    /// [`SteadyOptions::default`].
    pub steady: SteadyOptions,
    /// Threads of the FFT operator, as for [`crate::halfspace::HalfSpacePlan::new`]
    /// (grids below 96 × 96 run serially anyway). Default `None`.
    pub threads: Option<usize>,
    /// Couple the normal and the tangential problem through Kalker's difference
    /// parameter `K` (dissimilar bodies, [`super::CoupledSteadySolver`]; see the module
    /// docs). Default `false`: quasi-identical bodies (`K` neglected). Only for a model
    /// planned on a Hertz ellipse from both materials ([`KalkerExact::new`]); with
    /// `K = 0` the coupled model is the uncoupled one exactly.
    pub coupling: bool,
    /// With the coupling: the outer loop's tolerance on the change of pressure and
    /// tractions over one pass, relative to their norm. In (0, 1); default 1e-6.
    pub outer_tolerance: f64,
}

impl Default for KalkerExactOptions {
    fn default() -> Self {
        KalkerExactOptions {
            elements: [32, 32],
            steady: SteadyOptions {
                tolerance: 1e-7,
                steady_tolerance: 1e-6,
                ..Default::default()
            },
            threads: None,
            coupling: false,
            outer_tolerance: 1e-6,
        }
    }
}

impl KalkerExactOptions {
    /// Fewest cells across the contact in each direction: a coarser grid cannot resolve
    /// the slip area (it starts as a strip at the trailing edge).
    pub const MIN_ELEMENTS: usize = 8;
    /// Most cells across the contact in each direction.
    pub const MAX_ELEMENTS: usize = 1024;
    /// Fewest cells across the contact for creepages with spin before the grid counts
    /// as coarse ([`coarse_for`](Self::coarse_for)): the creep force converges at first
    /// order in the cell size, and with spin its error is largest (CONTACT's
    /// lateral-plus-spin case, `a/b = 2`: −5.9 %, −3.0 %, −1.5 % of the force at 32, 64,
    /// 128 cells; without spin 1-2 % at 32 cells; docs/rolling.md §6.1).
    pub const SPIN_ELEMENTS: usize = 64;

    /// Whether the grid is coarse for the creepages `creepages`: some point has a spin
    /// `φ ≠ 0` and fewer than [`SPIN_ELEMENTS`](Self::SPIN_ELEMENTS) cells lie across
    /// the contact in either direction. The solution is then no less valid, but its
    /// grid error can reach several per cent (docs/rolling.md §6.1).
    pub fn coarse_for(&self, creepages: &[Creepage]) -> bool {
        creepages.iter().any(|c| c.spin != 0.0)
            && self.elements.iter().any(|n| *n < Self::SPIN_ELEMENTS)
    }

    /// Check the options (the steady solver's own options are checked at each solve).
    ///
    /// # Errors
    /// [`Error::InvalidInput`] naming `elements[0]` or `elements[1]` outside
    /// 8..=1024 cells, or `outer_tolerance` outside (0, 1).
    pub fn validate(&self) -> Result<()> {
        let t = self.outer_tolerance;
        if !(t.is_finite() && t > 0.0 && t < 1.0) {
            return Err(Error::invalid(
                "outer_tolerance",
                t,
                "0 < outer_tolerance < 1",
            ));
        }
        for (k, n) in self.elements.into_iter().enumerate() {
            if !(Self::MIN_ELEMENTS..=Self::MAX_ELEMENTS).contains(&n) {
                return Err(Error::invalid(
                    if k == 0 { "elements[0]" } else { "elements[1]" },
                    n,
                    "8..=1024 cells across the contact (fewer cannot resolve the slip area)",
                ));
            }
        }
        Ok(())
    }
}

/// One creepage point of [`KalkerExact`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ExactPoint {
    /// The creepages of the point.
    pub creepage: Creepage,
    /// Forces `[F_x, F_y]` on body 1 \[N\].
    pub force: [Newton; 2],
    /// Spin moment `M_z` on body 1 about the contact centre \[N·mm\].
    pub spin_moment: NewtonMillimetre,
    /// `F_T/(μ F_N) = -F_x/(μ F_N)` \[-\].
    pub normalized_force: f64,
    /// Stick cells over loaded cells \[-\] (1 in full adhesion, 0 in full sliding).
    pub stick_fraction: f64,
    /// Largest cell pressure \[MPa\]: the sampled pressure's without the coupling; with
    /// it, that of the point's normal solution (which changes with the tractions).
    pub max_pressure: f64,
    /// FFT applications of the tangential operator for this point.
    pub fft_iterations: usize,
    /// The steady solver's status: converged, the rolling steps and the last relative
    /// traction change; with the coupling, the outer loop's (its passes and last
    /// relative change of pressure and tractions, or the failing inner solve's). A point
    /// that did not converge must not be used as a result.
    pub status: SolveStatus,
}

/// Kalker's exact theory of steady rolling on a Hertz ellipse, planned once and evaluated
/// at many creepages (see the module docs).
#[derive(Debug)]
pub struct KalkerExact {
    /// The Hertz ellipse, when the model was planned on one.
    ellipse: Option<ContactEllipse>,
    /// Normal force `Σ p ΔA` \[N\].
    normal_force: f64,
    mu: f64,
    material: KalkerMaterial,
    options: KalkerExactOptions,
    grid: Grid2,
    pressure: Vec<f64>,
    /// The steady solver on the fixed pressure (`None` with the coupling, whose solver
    /// has its own).
    solver: Option<Mutex<SteadySolver>>,
    /// Kalker's difference parameter of the two materials, when known ([`Self::new`]).
    difference: Option<f64>,
    /// The coupled solver and the undeformed gap \[mm\] of the Hertz contact, with the
    /// coupling on and `K ≠ 0`.
    coupled: Option<Mutex<Coupled>>,
}

/// The coupled problem of [`KalkerExact`]: its solver and the undeformed gap.
#[derive(Debug)]
struct Coupled {
    solver: CoupledSteadySolver,
    gap: Vec<f64>,
}

impl KalkerExact {
    /// Plan the model for the `ellipse` (semi-axes \[mm\], normal force \[N\]), two
    /// materials (Kalker's combined `G`, `ν`, and the difference parameter `K`), friction
    /// coefficient `mu` \[-\] and `options`. With `options.coupling` and `K ≠ 0` the
    /// points are solved by the coupled solver on the Hertz contact's undeformed gap
    /// (module docs).
    ///
    /// # Errors
    /// [`Error::InvalidInput`] naming `friction_coefficient` (not finite and > 0),
    /// `materials` (two rigid bodies), `elements[0]`/`elements[1]`, `outer_tolerance`
    /// (see [`KalkerExactOptions::validate`]) or `threads`.
    pub fn new(
        ellipse: ContactEllipse,
        body1: &ElasticMaterial,
        body2: &ElasticMaterial,
        mu: f64,
        options: KalkerExactOptions,
    ) -> Result<Self> {
        let material = KalkerMaterial::new(body1, body2)?;
        let k = difference_parameter(body1, body2)?;
        Self::plan(ellipse, material, Some(k), mu, options)
    }

    /// As [`new`](Self::new), from Kalker's combined constants directly (quasi-identical
    /// bodies: `K` is not known from `G`, `ν`).
    ///
    /// # Errors
    /// As [`new`](Self::new); the constants must be a finite `G > 0` \[MPa\] and
    /// `0 <= ν <= 0.5` (checked by the solver's operator); `coupling` when
    /// `options.coupling` is set (the coupling needs both materials: use
    /// [`new`](Self::new)).
    pub fn with_material(
        ellipse: ContactEllipse,
        material: KalkerMaterial,
        mu: f64,
        options: KalkerExactOptions,
    ) -> Result<Self> {
        if options.coupling {
            return Err(Error::invalid(
                "coupling",
                true,
                "false for Kalker's combined constants alone (K needs both materials: \
                 KalkerExact::new)",
            ));
        }
        Self::plan(ellipse, material, None, mu, options)
    }

    /// The planning on an ellipse, with the difference parameter `k` when known.
    fn plan(
        ellipse: ContactEllipse,
        material: KalkerMaterial,
        k: Option<f64>,
        mu: f64,
        options: KalkerExactOptions,
    ) -> Result<Self> {
        let mu = check_friction(mu)?;
        options.validate()?;
        let [mx, my] = options.elements;
        let (a, b) = (ellipse.a(), ellipse.b());
        let (dx, dy) = (2.0 * a / mx as f64, 2.0 * b / my as f64);
        let coupled_k = k.filter(|k| options.coupling && *k != 0.0);
        // One empty column beyond each edge along x: the leading-edge column is unloaded.
        // With the coupling, whose normal solution may reach a little past the ellipse,
        // two columns beyond each edge along x and one row beyond each edge along y.
        let grid = match coupled_k {
            None => Grid2::centered(a + dx, b, mx + 2, my)?,
            Some(k) => {
                let ex = coupled_margin(mx, k, mu);
                Grid2::centered(a + ex as f64 * dx, b + dy, mx + 2 * ex, my + 2)?
            }
        };
        debug_assert!((grid.dx() - dx).abs() <= 1e-12 * dx && (grid.dy() - dy).abs() <= 1e-12 * dy);
        let mut pressure: Vec<f64> = grid
            .points()
            .map(|(x, y)| ellipse.pressure_at(x, y))
            .collect();
        let sum = pressure.iter().sum::<f64>() * grid.cell_area();
        if !(sum > 0.0) {
            return Err(Error::invalid(
                "elements",
                format!("{mx} x {my}"),
                "a grid with loaded cells (more cells across the contact)",
            ));
        }
        let scale = ellipse.normal_force() / sum;
        for p in &mut pressure {
            *p *= scale;
        }
        let solver = match coupled_k {
            None => Some(Mutex::new(SteadySolver::new(
                &grid,
                material,
                options.threads,
            )?)),
            Some(_) => None,
        };
        let coupled = match coupled_k {
            None => None,
            Some(k) => {
                // The quadratic gap whose frictionless contact is the ellipse, for the
                // bodies' E* = G/(1 − ν) (Kalker's constants give Love's compliance).
                let e_star = material.shear_modulus / (1.0 - material.poisson_ratio);
                let [ca, cb] = ellipse_gap_curvatures(a, b, ellipse.normal_force(), e_star)?;
                let gap = grid
                    .points()
                    .map(|(x, y)| ca * x * x + cb * y * y)
                    .collect();
                let defaults = CoupledSteadyOptions::default();
                let coupled_options = CoupledSteadyOptions {
                    tolerance: options.outer_tolerance,
                    steady: options.steady,
                    normal: SolverOptions {
                        threads: options.threads.or(defaults.normal.threads),
                        ..defaults.normal
                    },
                    ..defaults
                };
                let solver =
                    CoupledSteadySolver::from_constants(&grid, material, k, coupled_options)?;
                Some(Mutex::new(Coupled { solver, gap }))
            }
        };
        Ok(KalkerExact {
            ellipse: Some(ellipse),
            normal_force: ellipse.normal_force(),
            mu,
            material,
            options,
            grid,
            pressure,
            solver,
            difference: k,
            coupled,
        })
    }

    /// Plan the model on a pressure field: `pressure` \[MPa\] per cell of `grid` \[mm\]
    /// (row-major, x fastest; uniform per cell, as the half-space solver and PimP give
    /// it), rolling in the direction at `rolling_angle` \[rad\] from the grid's `x` axis
    /// (counter-clockwise about the contact normal), Kalker's combined constants, the
    /// friction coefficient `mu` \[-\] and `options` (`elements` now counts the cells
    /// across the loaded cells' extent). See the module docs for the resampling.
    ///
    /// # Errors
    /// [`Error::InvalidInput`] naming `pressure` (wrong length, a value not finite or
    /// negative, no loaded cell), `rolling_angle` (not finite), `friction_coefficient`,
    /// `elements[0]`/`elements[1]` or `threads`, as [`with_material`](Self::with_material);
    /// `coupling` when `options.coupling` is set (a given pressure field stays as it is:
    /// for dissimilar bodies solve the coupled problem on the gap with
    /// [`super::CoupledSteadySolver`]).
    pub fn from_pressure(
        grid: &Grid2,
        pressure: &[f64],
        rolling_angle: f64,
        material: KalkerMaterial,
        mu: f64,
        options: KalkerExactOptions,
    ) -> Result<Self> {
        if options.coupling {
            return Err(Error::invalid(
                "coupling",
                true,
                "false for a given pressure field (quasi-identical bodies; the coupled \
                 problem needs the undeformed gap: CoupledSteadySolver)",
            ));
        }
        let mu = check_friction(mu)?;
        options.validate()?;
        if pressure.len() != grid.len() {
            return Err(Error::invalid(
                "pressure",
                format!("{} values", pressure.len()),
                format!("{} values ({} x {} grid)", grid.len(), grid.nx(), grid.ny()),
            ));
        }
        if let Some(p) = pressure.iter().find(|p| !(p.is_finite() && **p >= 0.0)) {
            return Err(Error::invalid(
                "pressure",
                p,
                "finite cell pressures >= 0 MPa",
            ));
        }
        if !rolling_angle.is_finite() {
            return Err(Error::invalid(
                "rolling_angle",
                rolling_angle,
                "a finite angle in rad",
            ));
        }
        let (dx, dy) = (grid.dx(), grid.dy());
        let normal_force = pressure.iter().sum::<f64>() * grid.cell_area();
        if !(normal_force > 0.0) {
            return Err(Error::invalid(
                "pressure",
                "no cell with p > 0",
                "a pressure field with contact (some cell p > 0 MPa)",
            ));
        }
        // The loaded cells' extent in the rolling frame: x' = c x + s y, y' = −s x + c y.
        let (c, s) = (rolling_angle.cos(), rolling_angle.sin());
        let hx = 0.5 * (dx * c.abs() + dy * s.abs());
        let hy = 0.5 * (dx * s.abs() + dy * c.abs());
        let (mut x_range, mut y_range) = (
            [f64::INFINITY, f64::NEG_INFINITY],
            [f64::INFINITY, f64::NEG_INFINITY],
        );
        for ((x, y), p) in grid.points().zip(pressure) {
            if *p > 0.0 {
                let (xr, yr) = (c * x + s * y, -s * x + c * y);
                x_range = [x_range[0].min(xr - hx), x_range[1].max(xr + hx)];
                y_range = [y_range[0].min(yr - hy), y_range[1].max(yr + hy)];
            }
        }
        let [mx, my] = options.elements;
        let ddx = (x_range[1] - x_range[0]) / mx as f64;
        // One empty column beyond each edge along x: the leading-edge column is unloaded.
        let rolled = Grid2::new([x_range[0] - ddx, x_range[1] + ddx], y_range, mx + 2, my)?;
        // The field at a point: bilinear between its cell centres inside a loaded cell,
        // zero outside the loaded cells.
        let (x0, y0) = (grid.x(0), grid.y(0));
        let (nx, ny) = (grid.nx() as isize, grid.ny() as isize);
        let at = |i: isize, j: isize| {
            if (0..nx).contains(&i) && (0..ny).contains(&j) {
                pressure[(j * nx + i) as usize]
            } else {
                0.0
            }
        };
        let field = |x: f64, y: f64| {
            let (u, v) = ((x - x0) / dx, (y - y0) / dy);
            if at(u.round() as isize, v.round() as isize) <= 0.0 {
                return 0.0;
            }
            let (i, j) = (u.floor(), v.floor());
            let (fu, fv) = (u - i, v - j);
            let (i, j) = (i as isize, j as isize);
            (1.0 - fv) * ((1.0 - fu) * at(i, j) + fu * at(i + 1, j))
                + fv * ((1.0 - fu) * at(i, j + 1) + fu * at(i + 1, j + 1))
        };
        let mut resampled: Vec<f64> = rolled
            .points()
            .map(|(xr, yr)| field(c * xr - s * yr, s * xr + c * yr))
            .collect();
        let sum = resampled.iter().sum::<f64>() * rolled.cell_area();
        if !(sum > 0.0) {
            return Err(Error::invalid(
                "pressure",
                "a field too narrow for the resampling",
                "a pressure field whose loaded cells the rolling grid's cell centres reach",
            ));
        }
        let scale = normal_force / sum;
        for p in &mut resampled {
            *p *= scale;
        }
        let solver = SteadySolver::new(&rolled, material, options.threads)?;
        Ok(KalkerExact {
            ellipse: None,
            normal_force,
            mu,
            material,
            options,
            grid: rolled,
            pressure: resampled,
            solver: Some(Mutex::new(solver)),
            difference: None,
            coupled: None,
        })
    }

    /// Plan the model on the pressure of a normal-contact solution (the half-space
    /// solver's or PimP's [`NormalSolution`]), rolling in the direction at
    /// `rolling_direction` \[rad\] from the gap source's `x` axis (the solution's grid is
    /// turned by its `orientation` from that axis). As [`from_pressure`](Self::from_pressure)
    /// with `rolling_angle = rolling_direction − orientation`.
    ///
    /// # Errors
    /// As [`from_pressure`](Self::from_pressure); `rolling_direction` not finite is
    /// named as such.
    pub fn from_solution<D>(
        solution: &NormalSolution<D>,
        rolling_direction: f64,
        material: KalkerMaterial,
        mu: f64,
        options: KalkerExactOptions,
    ) -> Result<Self> {
        if !rolling_direction.is_finite() {
            return Err(Error::invalid(
                "rolling_direction",
                rolling_direction,
                "a finite angle in rad",
            ));
        }
        Self::from_pressure(
            &solution.grid,
            &solution.pressure,
            rolling_direction - solution.orientation,
            material,
            mu,
            options,
        )
    }

    /// The contact ellipse, when the model was planned on one ([`new`](Self::new),
    /// [`with_material`](Self::with_material)); `None` for a pressure field.
    pub fn ellipse(&self) -> Option<&ContactEllipse> {
        self.ellipse.as_ref()
    }
    /// Normal force \[N\].
    pub fn normal_force(&self) -> Newton {
        self.normal_force
    }
    /// Friction coefficient `μ` \[-\].
    pub fn friction_coefficient(&self) -> f64 {
        self.mu
    }
    /// Kalker's combined constants.
    pub fn material(&self) -> KalkerMaterial {
        self.material
    }
    /// The options.
    pub fn options(&self) -> &KalkerExactOptions {
        &self.options
    }
    /// The solver's grid \[mm\] (`mx + 2` by `my` cells; with the coupling wider along
    /// `x` and `my + 2` rows, see the module docs; `x` the rolling direction).
    pub fn grid(&self) -> &Grid2 {
        &self.grid
    }
    /// The cell pressures \[MPa\], row-major with `x` fastest, summing to `F_N/ΔA` (with
    /// the coupling, the frictionless Hertz pressure sampled on the coupled grid; each
    /// point's own pressure comes from the normal solve).
    pub fn pressure(&self) -> &[f64] {
        &self.pressure
    }

    /// Solve one creepage point, warm-started from the last point solved (if
    /// `warm_start`) or from zero traction.
    ///
    /// # Errors
    /// [`Error::InvalidInput`] naming `creepage.longitudinal`, `creepage.lateral` or
    /// `creepage.spin` for a non-finite creepage, or the steady solver's options.
    pub fn solve(&self, creepage: &Creepage, warm_start: bool) -> Result<ExactPoint> {
        self.solve_with_field(creepage, warm_start).map(|(p, _)| p)
    }

    /// As [`solve`](Self::solve), with the solver's full solution: the traction, slip and
    /// stick/slip state of every cell of [`grid`](Self::grid) (for a stick/slip map).
    ///
    /// # Errors
    /// As [`solve`](Self::solve).
    pub fn solve_with_field(
        &self,
        creepage: &Creepage,
        warm_start: bool,
    ) -> Result<(ExactPoint, SteadySolution)> {
        creepage.validate()?;
        if let Some(coupled) = &self.coupled {
            let s = self.solve_coupled(coupled, SteadyLoad::Creepage(*creepage), warm_start)?;
            return Ok(self.coupled_point(s));
        }
        let mut solver = self
            .solver
            .as_ref()
            .expect("invariant: planned without the coupling")
            .lock()
            .unwrap_or_else(std::sync::PoisonError::into_inner);
        if !warm_start {
            solver.reset();
        }
        let s = solver.solve(&self.pressure, self.mu, *creepage, &self.options.steady)?;
        if !s.status.converged() {
            // Do not warm-start the next point from an unconverged field.
            solver.reset();
        }
        let bound = self.mu * self.normal_force;
        let loaded = s.stick_cells + s.slip_cells;
        let t = -s.force[0] / bound;
        let point = ExactPoint {
            creepage: *creepage,
            force: s.force,
            spin_moment: s.spin_moment,
            normalized_force: if t == 0.0 { 0.0 } else { t },
            stick_fraction: s.stick_cells as f64 / loaded.max(1) as f64,
            max_pressure: self.pressure.iter().fold(0.0, |m, p| p.max(m)),
            fft_iterations: s.fft_iterations,
            status: s.status,
        };
        Ok((point, s))
    }

    /// One coupled solve under force control `F_N`, warm-started from the last (if
    /// `warm_start`); an unconverged solve is not kept as the next warm start.
    fn solve_coupled(
        &self,
        coupled: &Mutex<Coupled>,
        load: SteadyLoad,
        warm_start: bool,
    ) -> Result<CoupledSteadySolution> {
        let mut guard = coupled
            .lock()
            .unwrap_or_else(std::sync::PoisonError::into_inner);
        let Coupled { solver, gap } = &mut *guard;
        if !warm_start {
            solver.reset();
        }
        let s = solver.solve(gap, Control::Force(self.normal_force), self.mu, load)?;
        if !s.status.converged() {
            solver.reset();
        }
        Ok(s)
    }

    /// The point and the field of a coupled solution.
    fn coupled_point(&self, s: CoupledSteadySolution) -> (ExactPoint, SteadySolution) {
        let bound = self.mu * self.normal_force;
        let loaded = s.stick_cells + s.slip_cells;
        let t = -s.force[0] / bound;
        let point = ExactPoint {
            creepage: s.creepage,
            force: s.force,
            spin_moment: s.spin_moment,
            normalized_force: if t == 0.0 { 0.0 } else { t },
            stick_fraction: s.stick_cells as f64 / loaded.max(1) as f64,
            max_pressure: s.pressure.iter().fold(0.0, |m, p| p.max(m)),
            fft_iterations: s.fft_iterations,
            status: s.status,
        };
        let field = SteadySolution {
            traction_x: s.traction_x,
            traction_y: s.traction_y,
            slip_x: s.slip_x,
            slip_y: s.slip_y,
            state: s.state,
            force: s.force,
            spin_moment: s.spin_moment,
            normal_force: s.normal_force,
            stick_cells: s.stick_cells,
            slip_cells: s.slip_cells,
            fft_iterations: s.fft_iterations,
            linear_iterations: 0,
            status: s.status,
        };
        (point, field)
    }

    /// Kalker's difference parameter `K` \[-\] of the two materials, when the model was
    /// planned from them ([`new`](Self::new)); `None` from the combined constants or a
    /// pressure field.
    pub fn difference_parameter(&self) -> Option<f64> {
        self.difference
    }

    /// Whether the points are solved with the coupling (the option set and `K ≠ 0`).
    pub fn is_coupled(&self) -> bool {
        self.coupled.is_some()
    }

    /// The free-rolling point: the longitudinal creepage `ξ` \[-\] at which `F_x = 0`
    /// for the lateral creepage `lateral` \[-\] and the spin `spin` \[1/mm\], solved from
    /// zero traction. With the coupling (`K ≠ 0`) the pressure's tangential
    /// displacement makes the bodies creep in free rolling (CONTACT's "F = 1" with
    /// `F_x = 0`; Bentall & Johnson 1967): `ξ` is sought by the coupled solver's force
    /// control, its sign that of `−K` (docs/rolling.md §11). Without
    /// (`K = 0` or the option off) `F_x` is odd in `ξ` for any `η`, `φ` (the contact is
    /// symmetric about the rolling axis), so `ξ = 0` exactly: the point is the solve at
    /// `ξ = 0`.
    ///
    /// # Errors
    /// [`Error::InvalidInput`] naming `creepage.lateral` or `creepage.spin` if not
    /// finite; the solver's errors.
    pub fn free_rolling(&self, lateral: f64, spin: f64) -> Result<ExactPoint> {
        let c = Creepage {
            longitudinal: 0.0,
            lateral,
            spin,
        };
        c.validate()?;
        match &self.coupled {
            None => self.solve(&c, false),
            Some(coupled) => {
                let load = SteadyLoad::LongitudinalForce {
                    force: 0.0,
                    lateral,
                    spin,
                };
                let s = self.solve_coupled(coupled, load, false)?;
                Ok(self.coupled_point(s).0)
            }
        }
    }

    /// A creep curve: every point of `creepages` in order, the first from zero traction,
    /// each further one warm-started from the previous.
    ///
    /// # Errors
    /// As [`solve`](Self::solve), for the first bad creepage (checked before any solve).
    pub fn curve(&self, creepages: &[Creepage]) -> Result<Vec<ExactPoint>> {
        for c in creepages {
            c.validate()?;
        }
        creepages
            .iter()
            .enumerate()
            .map(|(i, c)| self.solve(c, i > 0))
            .collect()
    }
}

/// Empty columns beyond each edge of the ellipse along `x` on the coupled grid of `mx`
/// cells across the ellipse: two, plus `max(0.1, |K| μ)` of the semi-axis. The
/// tractions' normal displacement shifts the contact along `x` (measured on a sphere,
/// `K = 0.1`, up to 32² and 64² cells: 0.03 `a` at `μ = 0.5`, 0.05 `a` at `μ = 1` in full
/// sliding), and the leading-edge column must stay out of contact.
fn coupled_margin(mx: usize, k: f64, mu: f64) -> usize {
    let fraction = (k.abs() * mu).max(0.1);
    2 + (fraction * 0.5 * mx as f64).ceil() as usize
}

impl TractionCurve for KalkerExact {
    fn name(&self) -> &'static str {
        "kalker_exact"
    }

    /// `F_T/(μ F_N)` at the longitudinal creepage `creepage` \[-\], from zero traction.
    ///
    /// # Errors
    /// [`Error::InvalidInput`] naming `creepage` if not finite; [`Error::NotConverged`]
    /// if the steady solver did not converge.
    fn normalized_force(&self, creepage: f64) -> Result<f64> {
        let xi = check_creepage(creepage)?;
        let p = self.solve(&Creepage::longitudinal(xi), false)?;
        p.status.require_converged("kalker_exact steady rolling")?;
        Ok(p.normalized_force)
    }

    /// The curve with warm starts along `creepages`.
    ///
    /// # Errors
    /// As [`normalized_force`](Self::normalized_force), for the first bad or
    /// unconverged point.
    fn traction_curve(&self, creepages: &[f64]) -> Result<Vec<f64>> {
        for &xi in creepages {
            check_creepage(xi)?;
        }
        let points: Vec<Creepage> = creepages
            .iter()
            .map(|&x| Creepage::longitudinal(x))
            .collect();
        self.curve(&points)?
            .into_iter()
            .map(|p| {
                p.status.require_converged("kalker_exact steady rolling")?;
                Ok(p.normalized_force)
            })
            .collect()
    }
}
