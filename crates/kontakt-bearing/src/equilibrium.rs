//! The quasi-static equilibrium of a roller bearing's inner ring relative to its outer
//! ring in five degrees of freedom, after Jones (1960), Harris & Kotzalas (2006) and the
//! slice ("lamina") model of ISO/TS 16281 (2008).
//!
//! **Frames and signs.** The outer ring is fixed; z is the bearing axis, x and y radial.
//! The inner ring's displacement is `u = (δx, δy, δz, θx, θy)` (mm, mm, mm, rad, rad),
//! small rotations about the x and y axes through the bearing centre. Roller j sits at
//! the azimuth ψ_j (from x toward y) on the pitch radius `R = d_m/2`; its load acts along
//! the outer raceway normal `n_j = (cos α cos ψ_j, cos α sin ψ_j, sin α)` (α the contact
//! angle; +z loads a tapered bearing, pushing the cone into the cup). The load applied to
//! the inner ring, `F = (Fx, Fy, Fz, Mx, My)` (N, N·mm), is carried by the rollers:
//! `F = Σ_jk q_jk g_jk` with `g_jk = (n_j, (p_jk × n_j)_x, (p_jk × n_j)_y)` and
//! `p_jk = R e_r + x_k t_j` the slice centre on the roller axis (`t_j` the roller axis
//! direction, toward the small end of a tapered roller).
//!
//! **Slices.** Slice k of roller j (width `w = L_we/n`, centre `x_k`) has the approach
//! `δ_jk = g_jk · u − s/2 − 2 P_roller(x_k) − P_inner(x_k) − P_outer(x_k)` (s the
//! clearance) and carries `q_jk = c_s max(δ_jk, 0)^(10/9)` with `c_s = c_l/n` and
//! `c_l = 35948 L_we^(8/9)` N/mm^(10/9) (ISO/TS 16281; steel, both contacts in series).
//!
//! **Rollers.** The roller's load Q_o = Σ_k q_jk is the outer raceway load; for a tapered
//! roller the roller's force balance in its axial plane (rigid roller, no centrifugal
//! force) gives the inner raceway load and the rib load from the three force directions,
//! `Q_i = Q_o sin(β − α)/sin(β − α_i)`, `Q_f = Q_o sin(α − α_i)/sin(β − α_i)` (β the rib
//! force direction, [`RollerBearing::rib_angle`]). What this first step does not model:
//! the roller's own tilt and moment balance (the rib contact as a contact of kontakt's
//! machinery, through `kontakt::bearing::roller_rib`'s geometry, is a later step), the
//! compliance of the rib, different slice loads on the cone and the cup, centrifugal
//! force, ring deformation, fits, thermal growth, coupled slices (half-space).
//!
//! **Solver.** The carried load is the gradient of the convex potential
//! `Φ(u) = Σ c_s (9/19) δ₊^(19/9)`; Newton's method on `F(u) = F` with the analytic
//! Jacobian (the stiffness matrix `K = Σ k_jk g_jk g_jkᵀ`, `k = (10/9) c_s δ^(1/9)`) and an
//! Armijo backtracking line search on `Φ(u) − F·u` converges from any start where the
//! load can be carried; it starts from the closed forms of [`crate::load_zone`]. Every
//! degree of freedom is force- or displacement-controlled ([`Dof`]); a single bearing
//! under a radial load is usually solved with the tilts held (`θ = 0`, the shaft's
//! support), since a single row cannot balance the moment of its own axial forces. The
//! buffers for the slice approaches and loads are allocated once in
//! [`RollerBearingSolver::new`]; a solve allocates nothing.

use crate::geometry::{RollerBearing, RollerBearingKind};
use crate::newton::{ConvexRing, Outcome, newton, to_rows};
use kontakt::solve::{SolveStatus, Termination};
use kontakt::{Error, Result};
use nalgebra::{Matrix5, Vector5};
use std::f64::consts::PI;

/// Names of the force components of [`RingLoad`], as an error names them
/// (`load.fz_n`): forces in N, moments in N·mm.
pub const FORCE_NAMES: [&str; 5] = ["fx_n", "fy_n", "fz_n", "mx_nmm", "my_nmm"];
/// Names of the displacement components: mm and rad.
pub const DISPLACEMENT_NAMES: [&str; 5] = ["dx_mm", "dy_mm", "dz_mm", "tilt_x_rad", "tilt_y_rad"];

/// One degree of freedom of the inner ring: a given force (N) or moment (N·mm), or a
/// given displacement (mm) or tilt (rad).
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "serde", serde(rename_all = "snake_case"))]
pub enum Dof {
    /// The applied force or moment; the displacement is solved for.
    Force(f64),
    /// The prescribed displacement or tilt; the force is the result.
    Displacement(f64),
}

/// The load case of the inner ring: `(x, y, z, tilt about x, tilt about y)`.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct RingLoad {
    /// The five degrees of freedom in the order x, y, z, θx, θy.
    pub dofs: [Dof; 5],
}

impl RingLoad {
    /// Forces `(Fx, Fy, Fz)` in N and moments `(Mx, My)` in N·mm on all five.
    pub fn forces(f: [f64; 5]) -> Self {
        RingLoad {
            dofs: f.map(Dof::Force),
        }
    }

    /// Prescribed displacements (mm) and tilts (rad) on all five.
    pub fn displacements(u: [f64; 5]) -> Self {
        RingLoad {
            dofs: u.map(Dof::Displacement),
        }
    }

    /// The same load with both tilts held at zero (the moments are the result).
    #[must_use]
    pub fn with_tilts_held(mut self) -> Self {
        self.dofs[3] = Dof::Displacement(0.0);
        self.dofs[4] = Dof::Displacement(0.0);
        self
    }
}

/// The loads of one roller at the solution.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct RollerLoad {
    /// Azimuth ψ_j, rad.
    pub azimuth_rad: f64,
    /// Outer raceway (cup) load Q_o = Σ slice loads, N.
    pub outer_n: f64,
    /// Inner raceway (cone) load Q_i, N (equal to Q_o but for a tapered roller).
    pub inner_n: f64,
    /// Rib load Q_f, N (tapered rollers; 0 otherwise).
    pub rib_n: f64,
    /// The largest slice approach, mm (negative: the roller is lifted off by that much).
    pub max_approach_mm: f64,
}

/// The result of a solve.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct RollerSolution {
    /// Inner-ring displacement `(δx, δy, δz, θx, θy)`, mm and rad.
    pub displacement: [f64; 5],
    /// The load the rollers carry at that displacement, `(Fx, Fy, Fz, Mx, My)`, N and
    /// N·mm: the applied load on force-controlled components (to the residual), the
    /// reaction on displacement-controlled ones.
    pub load: [f64; 5],
    /// The 5 × 5 stiffness matrix `∂load/∂displacement` (N/mm, N, N·mm/rad), symmetric;
    /// rows and columns of directions the bearing has no stiffness in are zero.
    pub stiffness: [[f64; 5]; 5],
    /// How the solve ended; `residual` is the largest residual of a force-controlled
    /// component relative to the load scale (forces to `F_ref`, moments to `F_ref · d_m/2`).
    pub status: SolveStatus,
    /// A message when the status is not plain convergence or when every roller lifted off.
    pub note: Option<&'static str>,
    /// The load-zone parameter ε from the ring displacement (`(δ_a sin α + δ_r cos α −
    /// s/2) / (2 δ_r cos α)`, δ_r the radial displacement); `None` without a radial
    /// displacement or for a thrust bearing. Exact for rigid rings and no tilt.
    pub load_zone: Option<f64>,
    /// The largest roller load Q_o, N.
    pub max_roller_load_n: f64,
}

/// Per roller: `g(x) = g0 + x g1`.
#[derive(Debug, Clone, Copy)]
struct RollerFrame {
    g0: Vector5<f64>,
    g1: Vector5<f64>,
}

/// The solver of one roller bearing: the validated bearing, the per-roller frames and
/// per-slice buffers, evaluated for many load cases.
#[derive(Debug, Clone)]
pub struct RollerBearingSolver {
    bearing: RollerBearing,
    frames: Vec<RollerFrame>,
    x: Vec<f64>,
    /// `s/2 + 2 P_roller + P_inner + P_outer` per slice, mm.
    offset: Vec<f64>,
    c_s: f64,
    approach: Vec<f64>,
    load: Vec<f64>,
    rollers: Vec<RollerLoad>,
    /// Directions the bearing has stiffness in.
    stiff: [bool; 5],
    /// `Σ g gᵀ` over every slice: the shape of the stiffness with all slices in contact.
    probe: Matrix5<f64>,
    inner_ratio: f64,
    rib_ratio: f64,
    /// Largest relative residual accepted as converged (default 1e-11).
    pub tolerance: f64,
    /// Iteration limit (default 100).
    pub max_iterations: usize,
}

const EXP: f64 = 10.0 / 9.0;

impl RollerBearingSolver {
    /// Validate the bearing and set up the frames and buffers.
    ///
    /// # Errors
    /// As [`RollerBearing::validate`].
    pub fn new(bearing: RollerBearing) -> Result<Self> {
        bearing.validate()?;
        let z = bearing.rollers;
        let r = 0.5 * bearing.pitch_diameter_mm;
        let (sa, ca) = bearing.contact_angle_rad.sin_cos();
        let frames: Vec<RollerFrame> = (0..z)
            .map(|j| {
                let psi = bearing.first_roller_azimuth_rad + 2.0 * PI * j as f64 / z as f64;
                let (s, c) = psi.sin_cos();
                RollerFrame {
                    g0: Vector5::new(ca * c, ca * s, sa, r * sa * s, -r * sa * c),
                    g1: Vector5::new(0.0, 0.0, 0.0, -s, c),
                }
            })
            .collect();
        let x: Vec<f64> = bearing.slice_positions().collect();
        let offset = x
            .iter()
            .map(|&xk| {
                0.5 * bearing.clearance_mm
                    + 2.0 * bearing.roller_profile.drop(xk)
                    + bearing.inner_profile.drop(xk)
                    + bearing.outer_profile.drop(xk)
            })
            .collect();
        let c_s = bearing.roller_stiffness() / bearing.slices as f64;
        let mut probe = Matrix5::zeros();
        for f in &frames {
            for &xk in &x {
                let g = f.g0 + f.g1 * xk;
                probe += g * g.transpose();
            }
        }
        // a direction is stiff when its diagonal is not round-off of the others
        let fmax = (0..3).map(|i| probe[(i, i)]).fold(0.0, f64::max);
        let mmax = (3..5).map(|i| probe[(i, i)]).fold(0.0, f64::max);
        let mut stiff = [false; 5];
        for (i, s) in stiff.iter_mut().enumerate() {
            let scale = if i < 3 { fmax } else { mmax };
            *s = probe[(i, i)] > 1e-12 * scale;
        }
        let (inner_ratio, rib_ratio) = if bearing.kind == RollerBearingKind::Tapered {
            let (a, ai, b) = (
                bearing.contact_angle_rad,
                bearing.cone_angle_rad,
                bearing.rib_angle(),
            );
            (
                (b - a).sin() / (b - ai).sin(),
                (a - ai).sin() / (b - ai).sin(),
            )
        } else {
            (1.0, 0.0)
        };
        let n = z * bearing.slices;
        Ok(RollerBearingSolver {
            frames,
            offset,
            c_s,
            approach: vec![0.0; n],
            load: vec![0.0; n],
            rollers: vec![RollerLoad::default(); z],
            stiff,
            probe,
            inner_ratio,
            rib_ratio,
            x,
            bearing,
            tolerance: 1e-11,
            max_iterations: 100,
        })
    }

    /// The bearing.
    pub fn bearing(&self) -> &RollerBearing {
        &self.bearing
    }

    /// The directions the bearing has stiffness in.
    pub(crate) fn stiff(&self) -> &[bool; 5] {
        &self.stiff
    }

    /// Slice centres from the roller centre, mm.
    pub fn slice_positions(&self) -> &[f64] {
        &self.x
    }

    /// Slice loads of the last evaluation, N, roller-major (`[j * slices + k]`).
    pub fn slice_loads(&self) -> &[f64] {
        &self.load
    }

    /// Slice approaches of the last evaluation, mm, roller-major.
    pub fn slice_approaches(&self) -> &[f64] {
        &self.approach
    }

    /// Per-roller loads of the last solve.
    pub fn roller_loads(&self) -> &[RollerLoad] {
        &self.rollers
    }

    /// Evaluate the slices at `u`: fill the approach and load buffers, return the carried
    /// load, the stiffness and the potential `Σ c_s (9/19) δ₊^(19/9)`.
    fn evaluate(&mut self, u: &Vector5<f64>) -> (Vector5<f64>, Matrix5<f64>, f64) {
        let ns = self.x.len();
        let mut f = Vector5::zeros();
        let mut k = Matrix5::zeros();
        let mut phi = 0.0;
        for (j, fr) in self.frames.iter().enumerate() {
            let a0 = fr.g0.dot(u);
            let a1 = fr.g1.dot(u);
            // per roller: Σ q, Σ q x, and Σ k, Σ k x, Σ k x² (g is affine in x)
            let (mut q0, mut q1, mut k0, mut k1, mut k2) = (0.0, 0.0, 0.0, 0.0, 0.0);
            for kk in 0..ns {
                let xk = self.x[kk];
                let d = a0 + a1 * xk - self.offset[kk];
                self.approach[j * ns + kk] = d;
                if d > 0.0 {
                    let d19 = d.powf(1.0 / 9.0);
                    let q = self.c_s * d * d19;
                    let kd = EXP * self.c_s * d19;
                    self.load[j * ns + kk] = q;
                    phi += q * d * (9.0 / 19.0);
                    q0 += q;
                    q1 += q * xk;
                    k0 += kd;
                    k1 += kd * xk;
                    k2 += kd * xk * xk;
                } else {
                    self.load[j * ns + kk] = 0.0;
                }
            }
            f += fr.g0 * q0 + fr.g1 * q1;
            let g0g0 = fr.g0 * fr.g0.transpose();
            let g0g1 = fr.g0 * fr.g1.transpose();
            k += g0g0 * k0 + (g0g1 + g0g1.transpose()) * k1 + fr.g1 * fr.g1.transpose() * k2;
        }
        (f, k, phi)
    }

    /// The load `(Fx, Fy, Fz, Mx, My)` (N, N·mm) the rollers carry at the inner-ring
    /// displacement `u` (mm, rad), and the stiffness matrix there.
    pub fn load_at(&mut self, u: [f64; 5]) -> ([f64; 5], [[f64; 5]; 5]) {
        let (f, k, _) = self.evaluate(&Vector5::from(u));
        (f.into(), to_rows(&k))
    }

    /// Check the load against what the bearing can carry.
    pub(crate) fn check_load(&self, load: &RingLoad) -> Result<()> {
        check_finite(load)?;
        for (i, d) in load.dofs.iter().enumerate() {
            let name = FORCE_NAMES[i];
            if let Dof::Force(v) = *d
                && !self.stiff[i]
                && v != 0.0
            {
                let why = match (self.bearing.kind, i) {
                    (RollerBearingKind::Cylindrical, 2) => {
                        "0: a cylindrical roller bearing carries no axial load in this model (the NJ/NUP rib contacts are not modelled yet)"
                    }
                    (RollerBearingKind::Thrust, _) => {
                        "0: a cylindrical roller thrust bearing carries no radial load"
                    }
                    _ => {
                        "0: the bearing has no stiffness in this direction (too few slices to carry a moment)"
                    }
                };
                return Err(Error::invalid(format!("load.{name}"), v, why));
            }
        }
        let f = |i: usize| match load.dofs[i] {
            Dof::Force(v) => Some(v),
            Dof::Displacement(_) => None,
        };
        let kind = self.bearing.kind;
        // with the axial displacement free, a preload does not help: the ring moves out
        if matches!(kind, RollerBearingKind::Tapered | RollerBearingKind::Thrust)
            && let Some(fz) = f(2)
        {
            if fz < 0.0 {
                return Err(Error::invalid(
                    "load.fz_n",
                    fz,
                    "a load >= 0 N: a single-row bearing carries axial load in +z only (pushing the inner ring into the outer)",
                ));
            }
            if kind == RollerBearingKind::Tapered
                && let (Some(fx), Some(fy)) = (f(0), f(1))
            {
                let fr = fx.hypot(fy);
                let need = fr * self.bearing.contact_angle_rad.tan();
                if fr > 0.0 && !(fz > need) {
                    return Err(Error::invalid(
                        "load.fz_n",
                        fz,
                        format!(
                            "an axial load > F_r tan(alpha) = {need:.6} N: a single-row tapered roller bearing under the radial load F_r = {fr} N needs at least that axial load to hold it (or prescribe dz_mm)"
                        ),
                    ));
                }
            }
            // issue 28, bad input: every roller pushes in +z, so the moment it carries is
            // at most its axial force times the arm R sin(alpha) + L_we/2 of its farthest
            // slice: |M| < F_z (R + L_we/(2 sin alpha)), 0 without an axial load
            let m = [f(3).unwrap_or(0.0), f(4).unwrap_or(0.0)];
            let arm = 0.5 * self.bearing.pitch_diameter_mm
                + 0.5 * self.bearing.effective_length_mm / self.bearing.contact_angle_rad.sin();
            if m[0].hypot(m[1]) > 0.0 && !(m[0].hypot(m[1]) < fz * arm) {
                let i = if m[0].abs() >= m[1].abs() { 3 } else { 4 };
                let label = if kind == RollerBearingKind::Thrust {
                    "cylindrical roller thrust"
                } else {
                    "tapered roller"
                };
                return Err(Error::invalid(
                    format!("load.{}", FORCE_NAMES[i]),
                    m[i - 3],
                    format!(
                        "|M| < F_z (d_m/2 + L_we/(2 sin alpha)) = {:.6} N mm: a single-row {label} bearing carries a moment only through its axial load, here F_z = {fz} N (add axial load, or hold the tilts: prescribe tilt_x_rad and tilt_y_rad)",
                        fz * arm
                    ),
                ));
            }
        }
        Ok(())
    }

    /// Solve the inner ring's equilibrium under `load`, starting from the closed forms.
    ///
    /// # Errors
    /// [`Error::InvalidInput`] naming the load component (`load.fz_n`, ...) for a
    /// non-finite value, a force in a direction the bearing cannot carry (an axial force on
    /// a cylindrical, a radial one on a thrust bearing), a negative axial force on a single
    /// row (also when preloaded: with the axial displacement free the ring moves out), or a radial force on a tapered bearing with too little axial force. Loads that
    /// cannot be carried for other reasons end with [`Termination::Diverged`] and a note.
    pub fn solve(&mut self, load: &RingLoad) -> Result<RollerSolution> {
        self.check_load(load)?;
        let start = self.start(load);
        Ok(self.iterate(load, start))
    }

    /// Solve from the displacement `start` (mm, rad; e.g. the previous solution of a
    /// nearby load case) instead of the closed-form start.
    ///
    /// # Errors
    /// As [`RollerBearingSolver::solve`], and `start` must be finite.
    pub fn solve_from(&mut self, load: &RingLoad, start: [f64; 5]) -> Result<RollerSolution> {
        self.check_load(load)?;
        let u = warm_start(load, start, &self.stiff)?;
        Ok(self.iterate(load, u))
    }

    /// A start from the closed forms: the radial displacement for Q_max = 4.08 F_r/(Z cos α),
    /// the axial one for Q = F_a/(Z sin α), the tilts for the moment carried by the axial
    /// components (or by the slices of a cylindrical roller).
    pub(crate) fn start(&self, load: &RingLoad) -> Vector5<f64> {
        let b = &self.bearing;
        let z = b.rollers as f64;
        let cl = b.roller_stiffness();
        let (sa, ca) = b.contact_angle_rad.sin_cos();
        let play = 0.5 * b.clearance_mm;
        let approach = |q: f64| (q.max(0.0) / cl).powf(0.9);
        let mut u = Vector5::zeros();
        let force = |i: usize| match load.dofs[i] {
            Dof::Force(v) => v,
            Dof::Displacement(_) => 0.0,
        };
        let (fx, fy, fz) = (force(0), force(1), force(2));
        let fr = fx.hypot(fy);
        if self.stiff[0] && fr > 0.0 {
            let d = approach(4.08 * fr / (z * ca)) + play.max(0.0);
            u[0] = d / ca * fx / fr;
            u[1] = d / ca * fy / fr;
        }
        if self.stiff[2] && fz > 0.0 {
            u[2] = (approach(fz / (z * sa)) + play) / sa;
        }
        let r = 0.5 * b.pitch_diameter_mm;
        for i in 3..5 {
            let m = force(i);
            if self.stiff[i] && m != 0.0 {
                let theta = if sa > 1e-3 {
                    approach(2.0 * m.abs() / (z * r * sa)) / (r * sa)
                } else {
                    // a cylindrical roller: the moment of the slices, x_max ~ L/2
                    let l = b.effective_length_mm;
                    approach(8.0 * m.abs() / (z * l)) / (0.5 * l)
                };
                // plus the tilt that closes the play at the farthest slice
                let arm = if sa > 1e-3 {
                    r * sa
                } else {
                    0.5 * b.effective_length_mm
                };
                u[i] = (theta + play.max(0.0) / arm) * m.signum();
            }
        }
        for (i, d) in load.dofs.iter().enumerate() {
            if let Dof::Displacement(v) = *d {
                u[i] = v;
            }
        }
        u
    }

    fn iterate(&mut self, load: &RingLoad, u: Vector5<f64>) -> RollerSolution {
        let b = Scalars {
            rollers: self.bearing.rollers as f64,
            roller_stiffness: self.bearing.roller_stiffness(),
            clearance_mm: self.bearing.clearance_mm,
            contact_angle_rad: self.bearing.contact_angle_rad,
            thrust: self.bearing.kind == RollerBearingKind::Thrust,
        };
        let r = 0.5 * self.bearing.pitch_diameter_mm;
        let (free, target) = free_and_target(load, &self.stiff);
        // the load scale: the applied forces, the moments over the pitch radius, the preload
        let mut f_ref = load_scale(&target, r);
        if b.clearance_mm < 0.0 {
            f_ref = f_ref.max(b.rollers * b.roller_stiffness * (-0.5 * b.clearance_mm).powf(EXP));
        }
        let (tolerance, max_iterations) = (self.tolerance, self.max_iterations);
        let Outcome {
            u,
            termination,
            iterations,
            residual: res,
            note,
            f,
            k,
            buffers_at_u,
        } = newton(self, free, target, u, f_ref, r, tolerance, max_iterations);
        // the per-element buffers hold the last evaluation: at u unless a line search
        // failed (Newton's last trial was elsewhere), the only case evaluated again
        if !buffers_at_u {
            self.evaluate(&u);
        }
        let ns = self.x.len();
        let mut qmax: f64 = 0.0;
        for (j, fr) in self.frames.iter().enumerate() {
            let q: f64 = self.load[j * ns..(j + 1) * ns].iter().sum();
            let dmax = self.approach[j * ns..(j + 1) * ns]
                .iter()
                .copied()
                .fold(f64::NEG_INFINITY, f64::max);
            let psi = (-fr.g1[3]).atan2(fr.g1[4]);
            self.rollers[j] = RollerLoad {
                azimuth_rad: psi,
                outer_n: q,
                inner_n: q * self.inner_ratio,
                rib_n: q * self.rib_ratio,
                max_approach_mm: dmax,
            };
            qmax = qmax.max(q);
        }
        let load_zone = load_zone(&u, b.contact_angle_rad, b.clearance_mm, b.thrust);
        let status = SolveStatus::new(termination, iterations, res);
        roller_solution(u, f, &k, status, note, qmax, load_zone)
    }
}

/// The record of a roller bearing solve at the displacement `u` carrying `f` with the
/// stiffness `k`; a converged solve with no roller loaded gets the lifted-off note.
pub(crate) fn roller_solution(
    u: Vector5<f64>,
    f: Vector5<f64>,
    k: &Matrix5<f64>,
    status: SolveStatus,
    mut note: Option<&'static str>,
    max_roller_load_n: f64,
    load_zone: Option<f64>,
) -> RollerSolution {
    if status.termination == Termination::Converged && max_roller_load_n == 0.0 {
        note = Some("every roller is lifted off: zero load");
    }
    RollerSolution {
        displacement: u.into(),
        load: f.into(),
        stiffness: to_rows(k),
        status,
        note,
        load_zone,
        max_roller_load_n,
    }
}

/// [`ConvexRing::touch`] of slices: the smallest step fraction at which a slice of a roller
/// with `g = g0 + x g1` (`frames`, one per roller), at its last approach (`approach`,
/// roller-major), reaches `d_ref` along `step`; `∞` when none approaches.
pub(crate) fn slice_touch<'a>(
    frames: impl Iterator<Item = (&'a Vector5<f64>, &'a Vector5<f64>)>,
    x: &[f64],
    approach: &[f64],
    step: &Vector5<f64>,
    d_ref: f64,
) -> f64 {
    let mut t_touch = f64::INFINITY;
    for (j, (g0, g1)) in frames.enumerate() {
        let (s0, s1) = (g0.dot(step), g1.dot(step));
        for (kk, &xk) in x.iter().enumerate() {
            let gd = s0 + s1 * xk;
            if gd > 0.0 {
                let need = d_ref - approach[j * x.len() + kk];
                t_touch = t_touch.min(need / gd);
            }
        }
    }
    t_touch
}

/// The bearing's numbers the iteration needs (copied out, so the buffers can be borrowed).
struct Scalars {
    rollers: f64,
    roller_stiffness: f64,
    clearance_mm: f64,
    contact_angle_rad: f64,
    thrust: bool,
}

/// The load-zone parameter ε of the ring displacement `u` (§3 of docs/bearing-model.md);
/// `None` for a thrust bearing or without a radial displacement.
pub(crate) fn load_zone(
    u: &Vector5<f64>,
    contact_angle_rad: f64,
    clearance_mm: f64,
    thrust: bool,
) -> Option<f64> {
    let (sa, ca) = contact_angle_rad.sin_cos();
    let dr = u[0].hypot(u[1]) * ca;
    // a radial displacement at the round-off level of the axial one is none
    let tiny = 1e-12 * u[0].abs().max(u[1].abs()).max(u[2].abs());
    if !thrust && dr > tiny {
        let eps = (u[2] * sa + dr - 0.5 * clearance_mm) / (2.0 * dr);
        (eps.is_finite() && eps > 0.0).then_some(eps)
    } else {
        None
    }
}

/// Every load component finite, else an error naming it (`load.fx_n`, `load.dz_mm`).
pub(crate) fn check_finite(load: &RingLoad) -> Result<()> {
    for (i, d) in load.dofs.iter().enumerate() {
        let (name, v) = match *d {
            Dof::Force(v) => (FORCE_NAMES[i], v),
            Dof::Displacement(v) => (DISPLACEMENT_NAMES[i], v),
        };
        if !v.is_finite() {
            return Err(Error::invalid(format!("load.{name}"), v, "a finite number"));
        }
    }
    Ok(())
}

/// A given start (checked finite, named `start.<component>`) with the prescribed
/// displacements put in and the directions without stiffness at 0.
pub(crate) fn warm_start(
    load: &RingLoad,
    start: [f64; 5],
    stiff: &[bool; 5],
) -> Result<Vector5<f64>> {
    for (i, v) in start.iter().enumerate() {
        if !v.is_finite() {
            return Err(Error::invalid(
                format!("start.{}", DISPLACEMENT_NAMES[i]),
                v,
                "a finite number",
            ));
        }
    }
    let mut u = Vector5::from(start);
    for (i, d) in load.dofs.iter().enumerate() {
        if let Dof::Displacement(v) = *d {
            u[i] = v;
        } else if !stiff[i] {
            u[i] = 0.0;
        }
    }
    Ok(u)
}

/// The free (force-controlled and stiff) components and the applied load on them.
pub(crate) fn free_and_target(load: &RingLoad, stiff: &[bool; 5]) -> ([bool; 5], Vector5<f64>) {
    let mut free = [false; 5];
    let mut target = Vector5::zeros();
    for (i, d) in load.dofs.iter().enumerate() {
        if let Dof::Force(v) = *d {
            free[i] = stiff[i];
            target[i] = v;
        }
    }
    (free, target)
}

/// The load scale of the applied forces and of the moments over the pitch radius `r`.
pub(crate) fn load_scale(target: &Vector5<f64>, r: f64) -> f64 {
    let f_ref = (0..3).map(|i| target[i].abs()).fold(0.0, f64::max);
    f_ref.max(target[3].hypot(target[4]) / r)
}

impl ConvexRing for RollerBearingSolver {
    fn evaluate(&mut self, u: &Vector5<f64>) -> (Vector5<f64>, Matrix5<f64>, f64) {
        RollerBearingSolver::evaluate(self, u)
    }

    fn probe(&self) -> &Matrix5<f64> {
        &self.probe
    }

    fn reference(&self, f_ref: f64) -> (f64, f64) {
        let d = (f_ref / (self.bearing.rollers as f64 * self.bearing.roller_stiffness())).powf(0.9);
        (d, EXP * self.c_s * d.powf(1.0 / 9.0))
    }

    fn touch(&self, step: &Vector5<f64>, d_ref: f64) -> f64 {
        let frames = self.frames.iter().map(|f| (&f.g0, &f.g1));
        slice_touch(frames, &self.x, &self.approach, step, d_ref)
    }

    fn limit(&self) -> f64 {
        self.bearing.roller_diameter_mm
    }
}

pub mod coupled;

#[cfg(test)]
mod tests;
