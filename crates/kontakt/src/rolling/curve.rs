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
//! accuracy and speed.
//!
//! # Assumptions
//! Those of [`super::SteadySolver`]: quasi-identical bodies (Kalker's `K = 0`), the Hertz
//! pressure unchanged by the tractions, constant Coulomb friction `μ`, steady rolling
//! along `x` (an axis of the ellipse).
//!
//! # References
//! Kalker, *Three-dimensional elastic bodies in rolling contact* (1990), ch. 5;
//! Vollebregt, CONTACT user guide (reference outputs of its examples, used as test data
//! in `tests/rolling_exact.rs`).

use super::steady::{SteadyOptions, SteadySolution, SteadySolver};
use crate::error::{Error, Result};
use crate::geometry::Grid2;
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
        }
    }
}

impl KalkerExactOptions {
    /// Fewest cells across the contact in each direction: a coarser grid cannot resolve
    /// the slip area (it starts as a strip at the trailing edge).
    pub const MIN_ELEMENTS: usize = 8;
    /// Most cells across the contact in each direction.
    pub const MAX_ELEMENTS: usize = 1024;

    /// Check the options (the steady solver's own options are checked at each solve).
    ///
    /// # Errors
    /// [`Error::InvalidInput`] naming `elements[0]` or `elements[1]` outside
    /// 8..=1024 cells.
    pub fn validate(&self) -> Result<()> {
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
    /// FFT applications of the tangential operator for this point.
    pub fft_iterations: usize,
    /// The steady solver's status: converged, the rolling steps and the last relative
    /// traction change. A point that did not converge must not be used as a result.
    pub status: SolveStatus,
}

/// Kalker's exact theory of steady rolling on a Hertz ellipse, planned once and evaluated
/// at many creepages (see the module docs).
#[derive(Debug)]
pub struct KalkerExact {
    ellipse: ContactEllipse,
    mu: f64,
    material: KalkerMaterial,
    options: KalkerExactOptions,
    grid: Grid2,
    pressure: Vec<f64>,
    solver: Mutex<SteadySolver>,
}

impl KalkerExact {
    /// Plan the model for the `ellipse` (semi-axes \[mm\], normal force \[N\]), two
    /// materials (Kalker's combined `G`, `ν`), friction coefficient `mu` \[-\] and
    /// `options`.
    ///
    /// # Errors
    /// [`Error::InvalidInput`] naming `friction_coefficient` (not finite and > 0),
    /// `materials` (two rigid bodies), `elements[0]`/`elements[1]` (see
    /// [`KalkerExactOptions::validate`]) or `threads`.
    pub fn new(
        ellipse: ContactEllipse,
        body1: &ElasticMaterial,
        body2: &ElasticMaterial,
        mu: f64,
        options: KalkerExactOptions,
    ) -> Result<Self> {
        let material = KalkerMaterial::new(body1, body2)?;
        Self::with_material(ellipse, material, mu, options)
    }

    /// As [`new`](Self::new), from Kalker's combined constants directly.
    ///
    /// # Errors
    /// As [`new`](Self::new); the constants must be a finite `G > 0` \[MPa\] and
    /// `0 <= ν <= 0.5` (checked by the solver's operator).
    pub fn with_material(
        ellipse: ContactEllipse,
        material: KalkerMaterial,
        mu: f64,
        options: KalkerExactOptions,
    ) -> Result<Self> {
        let mu = check_friction(mu)?;
        options.validate()?;
        let [mx, my] = options.elements;
        let (a, b) = (ellipse.a(), ellipse.b());
        let (dx, dy) = (2.0 * a / mx as f64, 2.0 * b / my as f64);
        // One empty column beyond each edge along x: the leading-edge column is unloaded.
        let grid = Grid2::centered(a + dx, b, mx + 2, my)?;
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
        let solver = SteadySolver::new(&grid, material, options.threads)?;
        Ok(KalkerExact {
            ellipse,
            mu,
            material,
            options,
            grid,
            pressure,
            solver: Mutex::new(solver),
        })
    }

    /// The contact ellipse.
    pub fn ellipse(&self) -> &ContactEllipse {
        &self.ellipse
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
    /// The solver's grid \[mm\] (`mx + 2` by `my` cells).
    pub fn grid(&self) -> &Grid2 {
        &self.grid
    }
    /// The cell pressures \[MPa\], row-major with `x` fastest, summing to `F_N/ΔA`.
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
        let mut solver = self
            .solver
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
        let bound = self.mu * self.ellipse.normal_force();
        let loaded = s.stick_cells + s.slip_cells;
        let t = -s.force[0] / bound;
        let point = ExactPoint {
            creepage: *creepage,
            force: s.force,
            spin_moment: s.spin_moment,
            normalized_force: if t == 0.0 { 0.0 } else { t },
            stick_fraction: s.stick_cells as f64 / loaded.max(1) as f64,
            fft_iterations: s.fft_iterations,
            status: s.status,
        };
        Ok((point, s))
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
