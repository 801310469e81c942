//! Steady rolling of dissimilar bodies: the normal problem and the steady tangential
//! problem coupled through Kalker's difference parameter `K`, solved by the outer
//! (Panagiotopoulos) loop, under prescribed creepages or a prescribed longitudinal force.
//!
//! # Formula
//! The contact rolls in `+x` on a grid aligned with the rolling direction (the rolling
//! step one cell, as [`super::SteadySolver`]). For bodies of different materials the
//! tangential tractions `τ` \[MPa\] on body 1 displace the surfaces normally and the
//! pressure `p` \[MPa\] displaces them tangentially ([`super::CouplingOperator`]); both
//! fields are stationary in the contact frame, so the pressure's displacement `A_t p`
//! enters the steady slip as `u = A τ` does:
//!
//! ```text
//! gap:   g = h + C p + A_n τ − δ_n >= 0,   p >= 0,   p g = 0                  (normal)
//! slip:  s_i = ω_i dx + e_i + u_i − u_{i+1},   e_i = (A_t p)_i − (A_t p)_{i+1}  [mm]
//!        |τ_i| <= μ p_i,  stick: s_i = 0,  slip: τ_i = −μ p_i s_i/|s_i|      (tangential)
//! ```
//!
//! with `h` the undeformed gap \[mm\], `C` Love's and `A` Cerruti's operators, `A_n` and
//! `A_t = A_nᵀ` the coupling, `ω = (ξ − φ y, η + φ x)` the rigid slip per unit rolling
//! distance for the creepages `ξ`, `η` \[-\] and the spin `φ` \[1/mm\], `u = A τ` \[mm\].
//! In plane strain the pressure's part is local: `∂(A_t p)_x/∂x = −(2K/G) p`
//! (docs/rolling.md §11), so `e_i/dx ≈ (2K/G) p_i`.
//!
//! **Outer loop.** From the last call's tractions: (1) the normal problem for the gap
//! `h + A_n τ` ([`crate::halfspace::HalfSpaceSolver`], warm-started); (2) the steady
//! tangential problem for that pressure with the extra rigid slip `e`
//! ([`super::SteadySolver::solve_with_rigid_slip`], warm-started); repeated until the
//! change of `(p, τ)` over one pass is at most `tolerance` times their norm (Euclidean
//! over the cells, as CONTACT's criterion and [`super::CoupledShiftSolver`]). For
//! `K = 0` (or `coupling: false`) one pass is exact and step (2) is
//! [`super::SteadySolver::solve`] itself.
//!
//! **Force control** ([`SteadyLoad::LongitudinalForce`], CONTACT's "F = 1"): in every
//! pass the longitudinal creepage `ξ` is sought with `F_x(ξ) = F_x*` for the given
//! `η`, `φ`. `F_x` is continuous and non-increasing in `ξ` (a larger creepage drives
//! body 1 harder against the traction): from the last `ξ` a step along the sign of the
//! residual (sized by the last slope `dF_x/dξ`, else by the creepage scale
//! `(μ + 2|K|) p_max/G`), doubled until the residual changes sign, then the Illinois
//! method (safeguarded regula falsi) inside the bracket, to `|F_x − F_x*| <=
//! force_tolerance · μ F_N`. Free rolling is `F_x* = 0`.
//!
//! Units: mm, N, MPa; forces on body 1. The status reports the outer termination
//! (passes, last relative change), or the failing inner solve's.
//!
//! **Another rolling direction.** CONTACT's rolling direction `χ = 180°` (rolling in
//! `−x`) is this problem mirrored in `x`: the creepage `ξ` and the force `F_x` change sign
//! (`x → −x`), `K`, `η`, the pressure and the cell counts do not.
//!
//! # Assumptions
//! Homogeneous, isotropic, linear elastic half-spaces (free boundary), Coulomb friction
//! with one coefficient, steady state (the fields stationary in the contact frame), small
//! creepages (linear kinematics), the leading-edge column of cells (`i = nx − 1`) out of
//! contact.
//!
//! # References
//! - Kalker, *Three-dimensional elastic bodies in rolling contact* (1990), §1.6, §2.2,
//!   ch. 5 (the steady rolling problem and its discretisation).
//! - Bentall & Johnson (1967), *Int. J. Mech. Sci.* 9, 389-404 (slip in the rolling
//!   contact of two dissimilar elastic rollers; the free-rolling creepage in complete
//!   slip).
//! - Bufler (1959), *Ing.-Arch.* 27, 137-152 (rolling of dissimilar cylinders without
//!   slip).
//! - Johnson, *Contact Mechanics* (1985), eq. 2.25a, §5.4, §8.
//! - Vollebregt, CONTACT user guide (the Panagiotopoulos process, the force-controlled
//!   creepage "F = 1", example `bentall`).

use super::outer::{CoupledParts, OuterLimits, OuterLoop, combined_constants, run_outer};
use super::shift::CellState;
use super::steady::{SteadyOptions, SteadySolution, SteadySolver};
use crate::error::{Error, Result};
use crate::geometry::Grid2;
use crate::halfspace::{Control, SolveReport, SolverOptions};
use crate::material::ElasticMaterial;
use crate::solve::{SolveStatus, Termination};
use crate::tangential::{Creepage, KalkerMaterial};
use crate::units::{Millimetre, Newton, NewtonMillimetre};

/// The tangential load of [`CoupledSteadySolver::solve`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum SteadyLoad {
    /// Prescribed creepages `ξ`, `η` \[-\] and spin `φ` \[1/mm\].
    Creepage(Creepage),
    /// Prescribed longitudinal force `force` \[N\] on body 1 (`|F_x| < μ F_N`; 0: free
    /// rolling) with the lateral creepage `lateral` \[-\] and the spin `spin` \[1/mm\];
    /// the longitudinal creepage is sought.
    LongitudinalForce {
        /// `F_x*` \[N\] on body 1.
        force: Newton,
        /// `η` \[-\].
        lateral: f64,
        /// `φ` \[1/mm\].
        spin: f64,
    },
}

/// Options of [`CoupledSteadySolver`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CoupledSteadyOptions {
    /// Outer tolerance: the change of `(p, τ)` over one pass in the Euclidean norm over
    /// all cells, relative to their norm. In (0, 1); default 1e-6.
    pub tolerance: f64,
    /// Most outer passes per solve, >= 1 (default 30).
    pub max_outer: usize,
    /// Passes without a new lowest change before the loop stops as stagnated, >= 1
    /// (default 5).
    pub patience: usize,
    /// Include the coupling (default `true`). `false` treats the bodies as
    /// quasi-identical (`K = 0`): one pass, the problems decoupled.
    pub coupling: bool,
    /// Force control: the tolerance on `|F_x − F_x*|` relative to `μ F_N`. In (0, 1);
    /// default 1e-8.
    pub force_tolerance: f64,
    /// Force control: most steady solves in one pass's creepage search, >= 2 (default
    /// 100).
    pub max_force_iterations: usize,
    /// The steady tangential solver's options (method, tolerance relative to the
    /// largest rigid slip, limits).
    pub steady: SteadyOptions,
    /// The normal solver's options (default: the half-space solver's defaults on one
    /// thread, which the tangential solver also uses).
    pub normal: SolverOptions,
}

impl Default for CoupledSteadyOptions {
    fn default() -> Self {
        CoupledSteadyOptions {
            tolerance: 1e-6,
            max_outer: 30,
            patience: 5,
            coupling: true,
            force_tolerance: 1e-8,
            max_force_iterations: 100,
            steady: SteadyOptions::default(),
            normal: SolverOptions {
                threads: Some(1),
                ..SolverOptions::default()
            },
        }
    }
}

impl CoupledSteadyOptions {
    /// Check every option.
    ///
    /// # Errors
    /// [`Error::InvalidInput`] naming the option, its value and the valid range.
    pub fn validate(&self) -> Result<()> {
        for (name, v) in [
            ("tolerance", self.tolerance),
            ("force_tolerance", self.force_tolerance),
            ("steady.tolerance", self.steady.tolerance),
            ("steady.steady_tolerance", self.steady.steady_tolerance),
        ] {
            if !(v.is_finite() && v > 0.0 && v < 1.0) {
                return Err(Error::invalid(name, v, "0 < tolerance < 1"));
            }
        }
        for (name, v, min) in [
            ("max_outer", self.max_outer, 1),
            ("patience", self.patience, 1),
            ("max_force_iterations", self.max_force_iterations, 2),
            ("steady.max_iterations", self.steady.max_iterations, 1),
            ("steady.max_steps", self.steady.max_steps, 1),
            (
                "steady.max_newton_iterations",
                self.steady.max_newton_iterations,
                1,
            ),
        ] {
            if v < min {
                return Err(Error::invalid(name, v, format!("at least {min}")));
            }
        }
        self.normal.validate()
    }
}

/// The solution of [`CoupledSteadySolver::solve`].
#[derive(Debug, Clone, PartialEq)]
pub struct CoupledSteadySolution {
    /// Pressure \[MPa\], row-major, x fastest.
    pub pressure: Vec<f64>,
    /// Tractions `τ_x` on body 1 \[MPa\].
    pub traction_x: Vec<f64>,
    /// Tractions `τ_y` on body 1 \[MPa\].
    pub traction_y: Vec<f64>,
    /// Slip `S_x = s_x/dx` per unit rolling distance \[-\]; zero in stick and exterior
    /// cells.
    pub slip_x: Vec<f64>,
    /// Slip `S_y` \[-\].
    pub slip_y: Vec<f64>,
    /// State of each cell (exterior: no pressure).
    pub state: Vec<CellState>,
    /// The pressure's tangential displacement difference `A_t p` \[mm\], x component
    /// (zero without coupling).
    pub pressure_displacement_x: Vec<f64>,
    /// The pressure's tangential displacement difference, y component \[mm\].
    pub pressure_displacement_y: Vec<f64>,
    /// The tractions' normal displacement sum `A_n τ` \[mm\] (positive: opens the gap;
    /// zero without coupling).
    pub coupling_gap: Vec<f64>,
    /// The creepages used: prescribed, or with the longitudinal creepage found under
    /// force control (`ξ`, `η` \[-\], `φ` \[1/mm\]).
    pub creepage: Creepage,
    /// Creep force on body 1 `[F_x, F_y]` \[N\].
    pub force: [Newton; 2],
    /// Spin moment on body 1 about the grid origin \[N·mm\].
    pub spin_moment: NewtonMillimetre,
    /// Normal force `Σ p ΔA` \[N\].
    pub normal_force: Newton,
    /// Rigid normal approach \[mm\] (from the zero level of the gap `h + A_n τ`).
    pub approach: Millimetre,
    /// Cells with pressure.
    pub contact_cells: usize,
    /// Cells in stick.
    pub stick_cells: usize,
    /// Cells in slip.
    pub slip_cells: usize,
    /// Kalker's difference parameter used (0 when the coupling is off).
    pub difference_parameter: f64,
    /// Steady solves over all passes (more than the passes under force control).
    pub steady_solves: usize,
    /// FFT applications of the steady solver over all passes.
    pub fft_iterations: usize,
    /// The last steady solve's status (see [`super::SteadySolution::status`]); `None`
    /// when no steady solve ran (the normal solve failed in the first pass).
    pub steady_status: Option<SolveStatus>,
    /// The last normal solve's report.
    pub normal_report: SolveReport,
    /// The outer loop: termination, passes, and the last relative change (0 after the
    /// single pass of uncoupled bodies). When an inner solve failed: its termination
    /// and residual; when the creepage search failed: its termination and
    /// `|F_x − F_x*|/(μ F_N)`.
    pub status: SolveStatus,
}

/// Steady rolling of two (possibly dissimilar) bodies on one grid aligned with the
/// rolling direction (`+x`), the normal problem solved in the same loop (see the module
/// docs). Keeps the last pressure, tractions, creepage and slope as the warm start of
/// the next call; [`CoupledSteadySolver::reset`] forgets them.
///
/// # Example
/// The free-rolling creepage of an aluminium roller on a steel one (CONTACT's example
/// `bentall`: a strip of 216 cells, `a = 0.1` mm, `R = 25` mm) with almost no friction:
/// Bentall & Johnson's `ξ = −(2K/G) p0 cos θ* = −5.263e-4` (docs/rolling.md §11).
///
/// ```
/// use kontakt::geometry::Grid2;
/// use kontakt::halfspace::Control;
/// use kontakt::material::ElasticMaterial;
/// use kontakt::rolling::{CoupledSteadyOptions, CoupledSteadySolver, SteadyLoad};
///
/// let aluminium = ElasticMaterial::new(60_260.0, 0.31)?; // E [MPa], ν (G = 23 000 MPa)
/// let steel = ElasticMaterial::new(209_920.0, 0.28)?; // G = 82 000 MPa
/// let grid = Grid2::new([-0.108, 0.108], [-500.0, 500.0], 216, 1)?;
/// let gap: Vec<f64> = grid.points().map(|(x, _)| x * x / 50.0).collect();
/// let mut solver =
///     CoupledSteadySolver::new(&grid, &aluminium, &steel, CoupledSteadyOptions::default())?;
/// let free = SteadyLoad::LongitudinalForce { force: 0.0, lateral: 0.0, spin: 0.0 };
/// let s = solver.solve(&gap, Control::Force(16_201.9), 1e-4, free)?;
/// assert!(s.status.converged());
/// assert!((s.creepage.longitudinal / -5.263e-4 - 1.0).abs() < 3e-3);
/// # Ok::<(), kontakt::Error>(())
/// ```
#[derive(Debug)]
pub struct CoupledSteadySolver {
    grid: Grid2,
    options: CoupledSteadyOptions,
    material: KalkerMaterial,
    k: f64,
    steady: SteadySolver,
    /// The normal solver, the coupling operator and the outer loop's work arrays.
    outer: OuterLoop,
    /// Work arrays: the extra slip and the last tractions.
    extra: [Vec<f64>; 2],
    tau: [Vec<f64>; 2],
    /// The last longitudinal creepage and slope `dF_x/dξ` \[N\] of the force control.
    last_xi: Option<f64>,
    last_slope: Option<f64>,
}

/// The outcome of one pass's creepage search.
struct Search {
    solution: SteadySolution,
    xi: f64,
    slope: Option<f64>,
    solves: usize,
    fft: usize,
    termination: Termination,
    /// `|F_x − F_x*|/(μ F_N)`.
    residual: f64,
}

impl CoupledParts for CoupledSteadySolver {
    fn parts(&mut self) -> (&mut OuterLoop, [&[f64]; 2]) {
        let [tx, ty] = &self.tau;
        (&mut self.outer, [tx, ty])
    }
}

impl CoupledSteadySolver {
    /// A solver for `grid` \[mm\] (rolling along `+x`), body 1 and body 2 (body 1
    /// carries the tractions `τ`; either may be rigid, not both) and `options`.
    ///
    /// # Errors
    /// [`Error::InvalidInput`] for two rigid bodies, a grid with fewer than 2 cells
    /// along `x`, or options out of range.
    pub fn new(
        grid: &Grid2,
        body1: &ElasticMaterial,
        body2: &ElasticMaterial,
        options: CoupledSteadyOptions,
    ) -> Result<Self> {
        options.validate()?;
        let (material, k) = combined_constants(body1, body2, options.coupling)?;
        Self::from_constants(grid, material, k, options)
    }

    /// A solver from Kalker's combined constants `material` (`G` \[MPa\], `ν`) and
    /// difference parameter `k` (`|K| <= 0.5`) directly.
    ///
    /// # Errors
    /// [`Error::InvalidInput`] for constants or options out of range, or a grid with
    /// fewer than 2 cells along `x`.
    pub fn from_constants(
        grid: &Grid2,
        material: KalkerMaterial,
        k: f64,
        options: CoupledSteadyOptions,
    ) -> Result<Self> {
        options.validate()?;
        let (k, outer) = OuterLoop::new(grid, material, k, options.coupling, options.normal)?;
        let steady = SteadySolver::new(grid, material, options.normal.threads)?;
        let n = grid.len();
        let z2 = || [vec![0.0; n], vec![0.0; n]];
        Ok(CoupledSteadySolver {
            grid: *grid,
            options,
            material,
            k,
            steady,
            outer,
            extra: z2(),
            tau: z2(),
            last_xi: None,
            last_slope: None,
        })
    }

    /// Kalker's difference parameter in use (0 with the coupling off).
    pub fn difference_parameter(&self) -> f64 {
        self.k
    }

    /// Forget the warm start: the next solve starts from zero traction and, under
    /// force control, from `ξ = 0`.
    pub fn reset(&mut self) {
        self.steady.reset();
        for v in self.tau.iter_mut() {
            v.fill(0.0);
        }
        self.outer.forget();
        self.last_xi = None;
        self.last_slope = None;
    }

    /// Solve the steady rolling problem for the undeformed gap `gap` \[mm\] (row-major,
    /// x fastest; `+inf` where the bodies cannot meet), the normal `control` (force
    /// \[N\] or approach \[mm\]), the friction coefficient `mu` (> 0) and the tangential
    /// `load` (creepages, or the longitudinal force with `η`, `φ`), warm-started from
    /// the last call.
    ///
    /// Not converging is not an error: see the solution's `status`.
    ///
    /// # Errors
    /// [`Error::InvalidInput`] for a gap of the wrong length or NaN, a normal load not
    /// finite and > 0, `mu` not finite and > 0, creepages or a force target not finite,
    /// a force target with `|F_x*| >= μ F_N`, a pressure in the leading-edge column
    /// (`i = nx − 1`: extend the grid along `+x`); [`Error::Geometry`] when the bodies
    /// do not touch.
    pub fn solve(
        &mut self,
        gap: &[f64],
        control: Control,
        mu: f64,
        load: SteadyLoad,
    ) -> Result<CoupledSteadySolution> {
        crate::tangential::check_friction(mu)?;
        let control = control.point()?;
        match load {
            SteadyLoad::Creepage(c) => c.validate()?,
            SteadyLoad::LongitudinalForce {
                force,
                lateral,
                spin,
            } => {
                if !force.is_finite() {
                    return Err(Error::invalid(
                        "force_x",
                        force,
                        "a finite longitudinal force in N",
                    ));
                }
                Creepage {
                    longitudinal: 0.0,
                    lateral,
                    spin,
                }
                .validate()?;
                if let Control::Force(f_n) = control {
                    check_force_target(force, mu * f_n)?;
                }
            }
        }
        OuterLoop::check_gap(&self.grid, gap)?;
        let opts = self.options;
        let limits = OuterLimits {
            tolerance: opts.tolerance,
            patience: opts.patience,
            max_outer: opts.max_outer,
        };
        let nx = self.grid.nx();
        let area = self.grid.cell_area();
        let g_mod = self.material.shear_modulus;
        let mut solves = 0;
        let mut fft = 0;
        let mut last: Option<(SteadySolution, f64)> = None;
        let (report, status) = run_outer(self, gap, control, limits, |s| {
            // (2) The pressure's tangential displacement as an extra rigid slip.
            let extra = match s.outer.pressure_displacement()? {
                true => {
                    for (e, u) in s.extra.iter_mut().zip(&s.outer.up) {
                        for (row_e, row_u) in e.chunks_exact_mut(nx).zip(u.chunks_exact(nx)) {
                            for i in 0..nx - 1 {
                                row_e[i] = row_u[i] - row_u[i + 1];
                            }
                            row_e[nx - 1] = 0.0;
                        }
                    }
                    Some([&s.extra[0][..], &s.extra[1][..]])
                }
                false => None,
            };
            let p = s.outer.normal.pressure();
            // (3) The steady tangential problem for this pressure.
            let (solution, xi, inner) = match load {
                SteadyLoad::Creepage(c) => {
                    let sol = steady_solve(&mut s.steady, p, mu, c, extra, &opts.steady)?;
                    s.last_xi = Some(c.longitudinal);
                    solves += 1;
                    fft += sol.fft_iterations;
                    let t = sol.status.termination;
                    let r = sol.status.residual;
                    (sol, c.longitudinal, (t, r))
                }
                SteadyLoad::LongitudinalForce {
                    force,
                    lateral,
                    spin,
                } => {
                    let normal_force = p.iter().sum::<f64>() * area;
                    let limit = mu * normal_force;
                    check_force_target(force, limit)?;
                    let p_max = p.iter().fold(0.0f64, |a, v| a.max(*v));
                    let scale = (mu + 2.0 * s.k.abs()) * p_max / g_mod;
                    let search = find_creepage(
                        &mut s.steady,
                        p,
                        mu,
                        extra,
                        [lateral, spin],
                        force,
                        limit,
                        (s.last_xi.unwrap_or(0.0), s.last_slope, scale),
                        &opts,
                    )?;
                    solves += search.solves;
                    fft += search.fft;
                    s.last_xi = Some(search.xi);
                    if search.slope.is_some() {
                        s.last_slope = search.slope;
                    }
                    let inner = if search.termination == Termination::Converged {
                        let st = search.solution.status;
                        (st.termination, st.residual)
                    } else {
                        (search.termination, search.residual)
                    };
                    (search.solution, search.xi, inner)
                }
            };
            s.tau[0].copy_from_slice(&solution.traction_x);
            s.tau[1].copy_from_slice(&solution.traction_y);
            last = Some((solution, xi));
            Ok((inner.0 != Termination::Converged).then_some(inner))
        })?;
        Ok(self.finish(last, load, solves, fft, report, status))
    }

    /// Collect the solution of the last pass.
    fn finish(
        &mut self,
        last: Option<(SteadySolution, f64)>,
        load: SteadyLoad,
        steady_solves: usize,
        fft_iterations: usize,
        report: SolveReport,
        status: SolveStatus,
    ) -> CoupledSteadySolution {
        let n = self.grid.len();
        let area = self.grid.cell_area();
        let p = self.outer.normal.pressure().to_vec();
        let mut pressure_displacement_x = vec![0.0; n];
        let mut pressure_displacement_y = vec![0.0; n];
        let [tx, ty] = &self.tau;
        let coupling_gap = self.outer.final_fields([tx, ty]);
        if self.outer.cross.is_some() {
            pressure_displacement_x.copy_from_slice(&self.outer.up[0]);
            pressure_displacement_y.copy_from_slice(&self.outer.up[1]);
        }
        let creepage_of = |xi: f64| match load {
            SteadyLoad::Creepage(c) => c,
            SteadyLoad::LongitudinalForce { lateral, spin, .. } => Creepage {
                longitudinal: xi,
                lateral,
                spin,
            },
        };
        let contact_cells = p.iter().filter(|v| **v > 0.0).count();
        let normal_force = p.iter().sum::<f64>() * area;
        match last {
            Some((s, xi)) => CoupledSteadySolution {
                pressure: p,
                traction_x: s.traction_x,
                traction_y: s.traction_y,
                slip_x: s.slip_x,
                slip_y: s.slip_y,
                state: s.state,
                pressure_displacement_x,
                pressure_displacement_y,
                coupling_gap,
                creepage: creepage_of(xi),
                force: s.force,
                spin_moment: s.spin_moment,
                normal_force,
                approach: report.approach,
                contact_cells,
                stick_cells: s.stick_cells,
                slip_cells: s.slip_cells,
                difference_parameter: self.k,
                steady_solves,
                fft_iterations,
                steady_status: Some(s.status),
                normal_report: report,
                status,
            },
            // The normal solve failed in the first pass: the pressure and no tractions.
            None => {
                let state = p
                    .iter()
                    .map(|v| {
                        if *v > 0.0 {
                            CellState::Stick
                        } else {
                            CellState::Exterior
                        }
                    })
                    .collect();
                CoupledSteadySolution {
                    pressure: p,
                    traction_x: self.tau[0].clone(),
                    traction_y: self.tau[1].clone(),
                    slip_x: vec![0.0; n],
                    slip_y: vec![0.0; n],
                    state,
                    pressure_displacement_x,
                    pressure_displacement_y,
                    coupling_gap,
                    creepage: creepage_of(self.last_xi.unwrap_or(0.0)),
                    force: [
                        self.tau[0].iter().sum::<f64>() * area,
                        self.tau[1].iter().sum::<f64>() * area,
                    ],
                    spin_moment: 0.0,
                    normal_force,
                    approach: report.approach,
                    contact_cells,
                    stick_cells: contact_cells,
                    slip_cells: 0,
                    difference_parameter: self.k,
                    steady_solves,
                    fft_iterations,
                    steady_status: None,
                    normal_report: report,
                    status,
                }
            }
        }
    }
}

/// `|F_x*| < μ F_N` (`limit` \[N\]), else the one-line error naming `force_x`.
fn check_force_target(force: f64, limit: f64) -> Result<()> {
    if force.abs() < limit {
        Ok(())
    } else {
        Err(Error::invalid(
            "force_x",
            force,
            format!(
                "-{limit:e} N < F_x < {limit:e} N (|F_x| < mu F_N: at mu F_N the contact \
                 slides and the creepage is undetermined)"
            ),
        ))
    }
}

/// One steady solve, with the extra rigid slip when there is one.
fn steady_solve(
    steady: &mut SteadySolver,
    p: &[f64],
    mu: f64,
    c: Creepage,
    extra: Option<[&[f64]; 2]>,
    options: &SteadyOptions,
) -> Result<SteadySolution> {
    match extra {
        None => steady.solve(p, mu, c, options),
        Some(e) => steady.solve_with_rigid_slip(p, mu, c, e, options),
    }
}

/// The longitudinal creepage with `F_x(ξ) = target` for the pressure `p`: from `start =
/// (ξ₀, last slope dF_x/dξ [N], creepage scale)`, steps along the sign of the residual
/// (`F_x` is non-increasing in `ξ`) doubled until it changes sign, then the Illinois
/// method inside the bracket. The returned solution is that of the returned `ξ` (the
/// last solve).
#[allow(clippy::too_many_arguments)] // the pieces of one pass, named at the call
fn find_creepage(
    steady: &mut SteadySolver,
    p: &[f64],
    mu: f64,
    extra: Option<[&[f64]; 2]>,
    [lateral, spin]: [f64; 2],
    target: f64,
    limit: f64,
    (xi0, slope0, scale): (f64, Option<f64>, f64),
    options: &CoupledSteadyOptions,
) -> Result<Search> {
    let tol = options.force_tolerance * limit;
    let max = options.max_force_iterations;
    // Steady solves and their FFT applications.
    let mut cnt = (0usize, 0usize);
    // g(ξ) = F_x(ξ) − F_x*, with the solve.
    let mut eval = |xi: f64, cnt: &mut (usize, usize)| -> Result<(f64, SteadySolution)> {
        let c = Creepage {
            longitudinal: xi,
            lateral,
            spin,
        };
        let s = steady_solve(steady, p, mu, c, extra, &options.steady)?;
        cnt.0 += 1;
        cnt.1 += s.fft_iterations;
        Ok((s.force[0] - target, s))
    };
    let failed = |s: &SteadySolution| s.status.termination != Termination::Converged;
    // The answer at a solve that met the force or failed: its status, and the force
    // residual (or the failed solve's own); a slope only if it is a usable one.
    let answer =
        |s: SteadySolution, xi: f64, g: f64, slope: Option<f64>, cnt: (usize, usize)| Search {
            termination: s.status.termination,
            residual: if failed(&s) {
                s.status.residual
            } else {
                g.abs() / limit
            },
            solution: s,
            xi,
            slope: slope.filter(|v| *v < 0.0 && v.is_finite()),
            solves: cnt.0,
            fft: cnt.1,
        };
    let (g0, s0) = eval(xi0, &mut cnt)?;
    if g0.abs() <= tol || failed(&s0) {
        return Ok(answer(s0, xi0, g0, None, cnt));
    }
    // F_x falls with ξ: a positive residual asks for a larger ξ.
    let dir = g0.signum();
    let mut step = match slope0 {
        Some(s) if s < 0.0 && s.is_finite() => (1.5 * g0 / -s).abs().min(scale).max(1e-6 * scale),
        _ => scale,
    };
    if !(step > 0.0 && step.is_finite()) {
        // No pressure scale (cannot happen with contact); a creepage of order 1e-3.
        step = 1e-3;
    }
    let mut prev = (xi0, g0);
    let mut cur;
    loop {
        let xi = prev.0 + dir * step;
        let (g, s) = eval(xi, &mut cnt)?;
        if failed(&s) || g.abs() <= tol {
            let slope = (g - prev.1) / (xi - prev.0);
            return Ok(answer(s, xi, g, Some(slope), cnt));
        }
        if g.signum() != dir {
            cur = (xi, g, s);
            break;
        }
        if cnt.0 >= max {
            return Ok(Search {
                termination: Termination::MaxIterations,
                residual: g.abs() / limit,
                solution: s,
                xi,
                slope: None,
                solves: cnt.0,
                fft: cnt.1,
            });
        }
        prev = (xi, g);
        // Doubling, but never to an infinite creepage (a target out of reach, e.g. with
        // lateral creepage or spin, ends at `max_force_iterations`).
        if step < 1e12 * scale {
            step *= 2.0;
        }
    }
    // The bracket: `lo` with g > 0, `hi` with g < 0 (ξ_lo < ξ_hi).
    let (mut lo, mut hi) = if dir > 0.0 {
        (prev, (cur.0, cur.1))
    } else {
        ((cur.0, cur.1), prev)
    };
    let mut side = 0i8;
    loop {
        // A bracket at the resolution of ξ: the residual cannot fall further (the
        // computed F_x is only as smooth as the steady solver's tolerance).
        let collapsed = hi.0 - lo.0 <= 4.0 * f64::EPSILON * (lo.0.abs() + hi.0.abs());
        if cnt.0 >= max || collapsed {
            return Ok(Search {
                termination: if collapsed {
                    Termination::Stagnated
                } else {
                    Termination::MaxIterations
                },
                residual: cur.1.abs() / limit,
                solution: cur.2,
                xi: cur.0,
                slope: None,
                solves: cnt.0,
                fft: cnt.1,
            });
        }
        let x = (lo.0 * hi.1 - hi.0 * lo.1) / (hi.1 - lo.1);
        let xi = if x > lo.0 && x < hi.0 {
            x
        } else {
            0.5 * (lo.0 + hi.0)
        };
        let (g, s) = eval(xi, &mut cnt)?;
        if failed(&s) || g.abs() <= tol {
            let slope = (hi.1 - lo.1) / (hi.0 - lo.0);
            return Ok(answer(s, xi, g, Some(slope), cnt));
        }
        if g > 0.0 {
            lo = (xi, g);
            if side == 1 {
                hi.1 *= 0.5;
            }
            side = 1;
        } else {
            hi = (xi, g);
            if side == -1 {
                lo.1 *= 0.5;
            }
            side = -1;
        }
        cur = (xi, g, s);
    }
}
