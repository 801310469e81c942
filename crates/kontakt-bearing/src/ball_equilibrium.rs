//! The quasi-static equilibrium of a ball bearing's inner ring relative to its outer ring
//! in five degrees of freedom, after Jones (1960) and Harris & Kotzalas (2006), without
//! speed effects (no centrifugal force, no gyroscopic moment).
//!
//! **Frames and signs** as for the roller bearings ([`crate::equilibrium`]): the outer ring
//! is fixed, z is the bearing axis, the inner ring moves by `u = (δx, δy, δz, θx, θy)` (mm,
//! rad) and carries the applied load `(Fx, Fy, Fz, Mx, My)` (N, N·mm); ball j sits at the
//! azimuth ψ_j. In the ball's axial plane `(e_r, e_z)` the inner groove's curvature centre
//! lies at `A_j = a + G_j u` from the outer groove's (`a` the unloaded offset,
//! [`BallBearing::unloaded_centre_offset`]; `G_j` the 2 × 5 map of the ring's rigid
//! motion at the inner centre, `docs/bearing-model.md` §8). The ball is pressed by the
//! approach `δ_j = |A_j| − B D` and carries `Q_j = K_n δ_j^1.5` along `A_j/|A_j|`, which
//! makes the contact angle `α_j = atan2(A_z, A_r)`; `K_n` is the series stiffness of the
//! two exact Hertz contacts from `kontakt::hertz` ([`BallBearing::ball_stiffness`]).
//!
//! **Solver.** The carried load is the gradient of the convex potential
//! `Φ(u) = Σ (2/5) K_n δ₊^2.5` (|A_j| is convex in u); the stiffness is its Hessian
//! `Σ [1.5 K_n δ^0.5 g gᵀ + (Q/|A|) t tᵀ]` with `g = G_jᵀ n`, `t = G_jᵀ n⊥`: the second
//! term is the turn of the load's direction with the contact angle. Newton with that
//! Jacobian and an Armijo line search, shared with the roller solver.

use crate::equilibrium::{Dof, RingLoad, check_finite, free_and_target, load_scale, warm_start};
use crate::geometry::{BallBearing, BallBearingKind};
use crate::newton::{ConvexRing, Outcome, newton, to_rows};
use kontakt::solve::{SolveStatus, Termination};
use kontakt::{Error, Result};
use nalgebra::{Matrix5, Vector5};
use std::f64::consts::PI;

/// The loads of one ball at the solution.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct BallLoad {
    /// Azimuth ψ_j, rad.
    pub azimuth_rad: f64,
    /// The ball's load Q on either raceway (no speed effects: the same on both), N.
    pub load_n: f64,
    /// The loaded contact angle α_j, rad (negative: the deep groove's other shoulder).
    pub contact_angle_rad: f64,
    /// The total approach of both contacts, mm (negative: lifted off by that much).
    pub approach_mm: f64,
    /// Maximum Hertz pressure on the inner raceway, MPa.
    pub inner_max_pressure_mpa: f64,
    /// Maximum Hertz pressure on the outer raceway, MPa.
    pub outer_max_pressure_mpa: f64,
}

/// The result of a solve.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct BallSolution {
    /// Inner-ring displacement `(δx, δy, δz, θx, θy)`, mm and rad.
    pub displacement: [f64; 5],
    /// The load the balls carry, `(Fx, Fy, Fz, Mx, My)`, N and N·mm.
    pub load: [f64; 5],
    /// The 5 × 5 stiffness matrix `∂load/∂displacement` (N/mm, N, N·mm/rad), symmetric.
    pub stiffness: [[f64; 5]; 5],
    /// How the solve ended (residual as for the roller bearings).
    pub status: SolveStatus,
    /// A message when the status is not plain convergence or every ball lifted off.
    pub note: Option<&'static str>,
    /// The largest ball load, N (at speed, [`crate::ball_speed`], the largest on the inner
    /// ring: 0 when every ball is lifted off it).
    pub max_ball_load_n: f64,
    /// The largest Hertz pressure on the inner and on the outer raceway, MPa.
    pub max_pressure_mpa: [f64; 2],
    /// The load-zone parameter ε (Sjövall 1933) along the radial displacement, from the
    /// balls' approach around the ring (`docs/bearing-model.md` §16.5); `None` without a
    /// radial displacement or with no ball loaded there. Exact for rigid rings without
    /// tilt.
    pub load_zone: Option<f64>,
}

/// Per ball: the rows of `G` (radial and axial motion of the inner groove centre).
#[derive(Debug, Clone, Copy)]
pub(crate) struct BallFrame {
    pub(crate) gr: Vector5<f64>,
    pub(crate) gz: Vector5<f64>,
}

/// The solver of one ball bearing.
#[derive(Debug, Clone)]
pub struct BallBearingSolver {
    bearing: BallBearing,
    /// The inner groove's curvature centre at rest `(ℜ_i, z_i)`, mm.
    centre: [f64; 2],
    frames: Vec<BallFrame>,
    offset: [f64; 2],
    a0: f64,
    k_n: f64,
    /// Hertz max pressure at 1 N, inner and outer, MPa.
    p_unit: [f64; 2],
    probe: Matrix5<f64>,
    approach: Vec<f64>,
    angle: Vec<f64>,
    balls: Vec<BallLoad>,
    /// Largest relative residual accepted as converged (default 1e-11).
    pub tolerance: f64,
    /// Iteration limit (default 100).
    pub max_iterations: usize,
}

impl BallBearingSolver {
    /// Validate the bearing, plan the Hertz contacts and set up the frames and buffers.
    ///
    /// # Errors
    /// As [`BallBearing::validate`].
    pub fn new(bearing: BallBearing) -> Result<Self> {
        bearing.validate()?;
        let z = bearing.balls;
        let r = 0.5 * bearing.pitch_diameter_mm;
        let offset = bearing.unloaded_centre_offset();
        let alpha_n = offset[1].atan2(offset[0]);
        // the inner groove centre at rest, (radial, axial), about the bearing centre
        let lever = (bearing.inner_osculation - 0.5) * bearing.ball_diameter_mm;
        let centre = [r + lever * alpha_n.cos(), lever * alpha_n.sin()];
        let frames: Vec<BallFrame> = (0..z)
            .map(|j| {
                let psi = bearing.first_ball_azimuth_rad + 2.0 * PI * j as f64 / z as f64;
                frame_at(centre, psi)
            })
            .collect();
        let probe = frames.iter().fold(Matrix5::zeros(), |p, f| {
            p + f.gr * f.gr.transpose() + f.gz * f.gz.transpose()
        });
        let alpha_k = bearing.stiffness_contact_angle();
        let k_n = bearing.ball_stiffness(alpha_k)?;
        let [ci, co] = bearing.contacts(alpha_k)?;
        Ok(BallBearingSolver {
            centre,
            frames,
            offset,
            a0: bearing.centre_distance_mm(),
            k_n,
            p_unit: [
                ci.max_pressure_at_unit_force(),
                co.max_pressure_at_unit_force(),
            ],
            probe,
            approach: vec![0.0; z],
            angle: vec![0.0; z],
            balls: vec![BallLoad::default(); z],
            bearing,
            tolerance: 1e-11,
            max_iterations: 100,
        })
    }

    /// The bearing.
    pub fn bearing(&self) -> &BallBearing {
        &self.bearing
    }

    /// The ball's load coefficient K_n (N/mm^1.5) of both contacts in series.
    pub fn ball_stiffness(&self) -> f64 {
        self.k_n
    }

    /// Per-ball loads of the last solve.
    pub fn ball_loads(&self) -> &[BallLoad] {
        &self.balls
    }

    /// The map `G` of a ball at the azimuth `psi` (rad); the balls' own in
    /// [`BallBearingSolver::frames`].
    pub(crate) fn frame(&self, psi: f64) -> BallFrame {
        frame_at(self.centre, psi)
    }

    /// The maps `G_j` of the balls.
    pub(crate) fn frames(&self) -> &[BallFrame] {
        &self.frames
    }

    /// The unloaded offset `a` of the groove centres and their distance `B D` with both
    /// grooves touching, mm.
    pub(crate) fn offsets(&self) -> ([f64; 2], f64) {
        (self.offset, self.a0)
    }

    /// The load the balls carry at `u`, the stiffness and the potential; fills the
    /// approach and contact-angle buffers.
    fn evaluate(&mut self, u: &Vector5<f64>) -> (Vector5<f64>, Matrix5<f64>, f64) {
        let mut f = Vector5::zeros();
        let mut k = Matrix5::zeros();
        let mut phi = 0.0;
        for (j, fr) in self.frames.iter().enumerate() {
            let ar = self.offset[0] + fr.gr.dot(u);
            let az = self.offset[1] + fr.gz.dot(u);
            let len = ar.hypot(az);
            let d = len - self.a0;
            let (nr, nz) = (ar / len, az / len);
            self.approach[j] = d;
            self.angle[j] = az.atan2(ar);
            if d > 0.0 {
                let sd = d.sqrt();
                let q = self.k_n * d * sd;
                let g = fr.gr * nr + fr.gz * nz;
                let t = fr.gz * nr - fr.gr * nz;
                f += g * q;
                k += g * g.transpose() * (1.5 * self.k_n * sd) + t * t.transpose() * (q / len);
                phi += 0.4 * q * d;
            }
        }
        (f, k, phi)
    }

    /// The load `(Fx, Fy, Fz, Mx, My)` (N, N·mm) the balls carry at the inner-ring
    /// displacement `u` (mm, rad), and the stiffness matrix there.
    pub fn load_at(&mut self, u: [f64; 5]) -> ([f64; 5], [[f64; 5]; 5]) {
        let (f, k, _) = self.evaluate(&Vector5::from(u));
        (f.into(), to_rows(&k))
    }

    pub(crate) fn check_load(&self, load: &RingLoad) -> Result<()> {
        check_finite(load)?;
        if self.bearing.kind == BallBearingKind::AngularContact
            && let Dof::Force(fz) = load.dofs[2]
            && fz < 0.0
        {
            return Err(Error::invalid(
                "load.fz_n",
                fz,
                "a load >= 0 N: a single-row angular-contact ball bearing carries axial load in +z only (pushing the inner ring into the outer)",
            ));
        }
        // issue 28, bad input: every loaded ball of a single row pushes in +z, so without
        // an axial load no ball is loaded and no radial load or moment is carried
        if self.bearing.kind == BallBearingKind::AngularContact && load.dofs[2] == Dof::Force(0.0) {
            let f = |i: usize| match load.dofs[i] {
                Dof::Force(v) => v,
                Dof::Displacement(_) => 0.0,
            };
            if let Some(i) = [0, 1, 3, 4].into_iter().find(|&i| f(i) != 0.0) {
                let what = if i < 3 { "a radial load" } else { "a moment" };
                return Err(Error::invalid(
                    "load.fz_n",
                    0.0,
                    format!(
                        "an axial load > 0 N: a single-row angular-contact ball bearing carries {what} only together with an axial load pushing the inner ring into the outer (or prescribe dz_mm)"
                    ),
                ));
            }
        }
        Ok(())
    }

    /// Solve the inner ring's equilibrium under `load`, starting from the closed forms.
    ///
    /// # Errors
    /// [`Error::InvalidInput`] naming the load component for a non-finite value or a
    /// negative axial force on an angular-contact bearing. Loads that cannot be carried
    /// end with [`Termination::Diverged`] and a note, as does an angular-contact bearing
    /// whose loaded balls run over the low shoulder (a contact angle ≤ 0: too little axial
    /// load for the radial load).
    pub fn solve(&mut self, load: &RingLoad) -> Result<BallSolution> {
        self.check_load(load)?;
        let start = self.start(load);
        Ok(self.iterate(load, start))
    }

    /// Solve from the displacement `start` (mm, rad), e.g. a nearby solution.
    ///
    /// # Errors
    /// As [`BallBearingSolver::solve`], and `start` must be finite.
    pub fn solve_from(&mut self, load: &RingLoad, start: [f64; 5]) -> Result<BallSolution> {
        self.check_load(load)?;
        let u = warm_start(load, start, &[true; 5])?;
        Ok(self.iterate(load, u))
    }

    /// A start from the closed forms: the axial displacement from Harris's pure axial
    /// relation with an estimated contact angle, the radial one for
    /// `Q_max = 4.37 F_r/(Z cos α)`, the tilts for the moment carried by the axial
    /// components.
    fn start(&self, load: &RingLoad) -> Vector5<f64> {
        let z = self.bearing.balls as f64;
        let kn = self.k_n;
        let approach = |q: f64| (q.max(0.0) / kn).powf(2.0 / 3.0);
        let force = |i: usize| match load.dofs[i] {
            Dof::Force(v) => v,
            Dof::Displacement(_) => 0.0,
        };
        let [ar, az] = self.offset;
        let mut alpha = az.atan2(ar);
        let mut u = Vector5::zeros();
        let fz = force(2);
        if fz != 0.0 {
            // small angles: F_a ≈ Z K (BD)^1.5 α⁴/2^1.5 from a zero free angle
            let small = (2f64.powf(1.5) * fz.abs() / (z * kn * self.a0.powf(1.5))).powf(0.25);
            alpha = alpha.max(small).min(1.2);
            let d = approach(fz.abs() / (z * alpha.sin()));
            let axial = ((self.a0 + d).powi(2) - ar * ar).max(0.0).sqrt();
            u[2] = fz.signum() * axial - az;
        }
        let (fx, fy) = (force(0), force(1));
        let fr = fx.hypot(fy);
        if fr > 0.0 {
            let ca = alpha.cos();
            let d = (approach(4.37 * fr / (z * ca)) + (self.a0 - ar.hypot(az)).max(0.0)) / ca;
            u[0] = d * fx / fr;
            u[1] = d * fy / fr;
        }
        let r = 0.5 * self.bearing.pitch_diameter_mm;
        let sa = alpha.sin();
        for i in 3..5 {
            let m = force(i);
            if m != 0.0 && sa > 0.05 {
                u[i] = m.signum() * approach(2.0 * m.abs() / (z * r * sa)) / (r * sa);
            }
        }
        for (i, d) in load.dofs.iter().enumerate() {
            if let Dof::Displacement(v) = *d {
                u[i] = v;
            }
        }
        u
    }

    fn iterate(&mut self, load: &RingLoad, u: Vector5<f64>) -> BallSolution {
        let r = 0.5 * self.bearing.pitch_diameter_mm;
        let (free, target) = free_and_target(load, &[true; 5]);
        let mut f_ref = load_scale(&target, r);
        let preload = self.a0 - self.offset[0].hypot(self.offset[1]);
        if preload < 0.0 {
            f_ref = f_ref.max(self.bearing.balls as f64 * self.k_n * (-preload).powf(1.5));
        }
        let (tolerance, max_iterations) = (self.tolerance, self.max_iterations);
        let Outcome {
            u,
            mut termination,
            iterations,
            residual,
            mut note,
            f,
            k,
            buffers_at_u,
        } = newton(self, free, target, u, f_ref, r, tolerance, max_iterations);
        // the per-element buffers hold the last evaluation: at u unless a line search
        // failed (Newton's last trial was elsewhere), the only case evaluated again
        if !buffers_at_u {
            self.evaluate(&u);
        }
        let mut qmax: f64 = 0.0;
        let mut pmax = [0.0f64; 2];
        let mut over_shoulder = false;
        for (j, fr) in self.frames.iter().enumerate() {
            let d = self.approach[j];
            let q = if d > 0.0 {
                self.k_n * d * d.sqrt()
            } else {
                0.0
            };
            let c = q.cbrt();
            let b = BallLoad {
                azimuth_rad: fr.gr[1].atan2(fr.gr[0]),
                load_n: q,
                contact_angle_rad: self.angle[j],
                approach_mm: d,
                inner_max_pressure_mpa: self.p_unit[0] * c,
                outer_max_pressure_mpa: self.p_unit[1] * c,
            };
            over_shoulder |= q > 0.0
                && self.bearing.kind == BallBearingKind::AngularContact
                && b.contact_angle_rad <= 0.0;
            qmax = qmax.max(q);
            pmax[0] = pmax[0].max(b.inner_max_pressure_mpa);
            pmax[1] = pmax[1].max(b.outer_max_pressure_mpa);
            self.balls[j] = b;
        }
        if over_shoulder && termination == Termination::Converged {
            termination = Termination::Diverged;
            note = Some(
                "a loaded ball of the angular-contact bearing has a contact angle <= 0: it runs over the low shoulder; the radial load needs more axial load (or prescribe dz_mm)",
            );
        }
        if termination == Termination::Converged && qmax == 0.0 {
            note = Some("every ball is lifted off: zero load");
        }
        let (offset, a0) = (self.offset, self.a0);
        let load_zone = crate::load_zone::load_zone(&u, |psi| {
            let fr = frame_at(self.centre, psi);
            (offset[0] + fr.gr.dot(&u)).hypot(offset[1] + fr.gz.dot(&u)) - a0
        });
        BallSolution {
            displacement: u.into(),
            load: f.into(),
            stiffness: to_rows(&k),
            status: SolveStatus::new(termination, iterations, residual),
            note,
            max_ball_load_n: qmax,
            max_pressure_mpa: pmax,
            load_zone,
        }
    }
}

/// The rows of `G` of a ball at the azimuth `psi` (rad) for the inner groove centre at
/// rest `centre = (ℜ_i, z_i)` (mm), `docs/bearing-model.md` §8.2.
fn frame_at(centre: [f64; 2], psi: f64) -> BallFrame {
    let [pr, pz] = centre;
    let (s, c) = psi.sin_cos();
    BallFrame {
        gr: Vector5::new(c, s, 0.0, -pz * s, pz * c),
        gz: Vector5::new(0.0, 0.0, 1.0, pr * s, -pr * c),
    }
}

impl ConvexRing for BallBearingSolver {
    fn evaluate(&mut self, u: &Vector5<f64>) -> (Vector5<f64>, Matrix5<f64>, f64) {
        BallBearingSolver::evaluate(self, u)
    }

    fn probe(&self) -> &Matrix5<f64> {
        &self.probe
    }

    fn reference(&self, f_ref: f64) -> (f64, f64) {
        let d = (f_ref / (self.bearing.balls as f64 * self.k_n)).powf(2.0 / 3.0);
        (d, 1.5 * self.k_n * d.sqrt())
    }

    fn touch(&self, step: &Vector5<f64>, d_ref: f64) -> f64 {
        let mut t_touch = f64::INFINITY;
        for (j, fr) in self.frames.iter().enumerate() {
            let (s, c) = self.angle[j].sin_cos();
            let rate = c * fr.gr.dot(step) + s * fr.gz.dot(step);
            if rate > 0.0 {
                t_touch = t_touch.min((d_ref - self.approach[j]) / rate);
            }
        }
        t_touch
    }

    fn limit(&self) -> f64 {
        self.bearing.ball_diameter_mm
    }
}

#[cfg(test)]
mod tests;
