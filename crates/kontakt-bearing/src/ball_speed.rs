//! Ball bearings at speed: the high-speed ball model of Jones (1960) as Harris & Kotzalas
//! (2006) present it. Each ball has its own inner and outer contact, with their own
//! contact angles and loads, and is held in equilibrium against its centrifugal force and
//! gyroscopic moment; the inner ring is in equilibrium with the balls' inner contact
//! forces. At rest it is the quasi-static model of [`crate::ball_equilibrium`].
//!
//! **Frames and signs** as [`crate::ball_equilibrium`] (`docs/bearing-model.md` §8 and
//! §16): the outer ring is fixed in space (it may turn about z), the inner ring moves by
//! `u = (δx, δy, δz, θx, θy)` (mm, rad) and carries `(Fx, Fy, Fz, Mx, My)` (N, N·mm). In
//! the axial plane `(e_r, e_z)` of ball j, with the outer groove's curvature centre at the
//! origin, the inner groove's is at `A_j = a + G_j u` and the ball's centre at
//! `X_j = (X_r, X_z)` (Jones's two unknowns per ball, mm). The outer contact deforms by
//! `δ_o = |X| − (f_o − ½) D` along `n_o = X/|X|` (contact angle `α_o = atan2(X_z, X_r)`),
//! the inner by `δ_i = |A − X| − (f_i − ½) D` along `n_i = (A − X)/|A − X|` (α_i); both
//! Hertz contacts `Q = K δ^1.5` with the exact `K_i`, `K_o` of `kontakt::hertz` at the
//! stiffness contact angle ([`BallBearing::contacts`], as the quasi-static model).
//!
//! **Speed.** The ring speeds ω_i, ω_o (rad/s, about +z) set the cage speed ω_c and the
//! ball's speed ω_R about its axis of pitch β ([`crate::speed`]), under **outer-race
//! control** (Jones 1960; Harris & Kotzalas 2006): the ball does not spin about the outer
//! contact normal, `tan β = sin α_o/(cos α_o + D/d_m)`, and the outer contact's friction
//! holds the whole gyroscopic moment `M_g = J ω_R ω_c sin β` (`J = m D²/10`) as the
//! tangential force `T_o = 2 M_g/D` along `t_o = (−sin α_o, cos α_o)` (friction assumed
//! sufficient). The centrifugal force is `F_c = ½ m d_m ω_c²` along `e_r`
//! (`m = ρ π D³/6`). The ball's equilibrium
//!
//! ```text
//! R(X; A) = Q_i n_i − Q_o n_o + F_c e_r + T_o t_o = 0
//! ```
//!
//! is solved per ball by Newton in X (warm-started from the ball's last centre), inside
//! the ring's Newton on `F(u) = Σ G_jᵀ Q_i n_i = F_applied`, whose Jacobian is the
//! condensed `K = Σ G_jᵀ H_i (I + R_X⁻¹ R_A) G_j` (the ball's centre eliminated by the
//! implicit function theorem; `H_i = ∂(Q_i n_i)/∂(A − X)`), exact including the
//! derivatives of F_c and M_g through the contact angles. K is not symmetric at speed (the
//! gyroscopic friction is not conservative); the ring Newton solves it by LU with a
//! backtracking line search on the residual. The solve starts from the quasi-static
//! equilibrium.

use crate::ball_equilibrium::{BallBearingSolver, BallSolution};
use crate::equilibrium::{RingLoad, free_and_target, load_scale, warm_start};
use crate::geometry::{BallBearing, BallBearingKind};
use crate::load_zone::load_zone;
use crate::newton::{
    BEYOND_LIMIT, ConvexRing, beyond_limit, newton_system, no_decrease, reaction_scale,
    relative_residual, to_rows,
};
use crate::speed::{ElementKinematics, RingSpeeds, centrifugal_force, density_n_s2_per_mm4};
use kontakt::Result;
use kontakt::solve::{SolveStatus, Termination};
use nalgebra::{Matrix2, Matrix5, Vector2, Vector5};
use std::f64::consts::PI;

/// Which contact holds the ball's gyroscopic moment.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "serde", serde(rename_all = "snake_case"))]
pub enum RaceControl {
    /// Outer-race control (Jones 1960): no spin about the outer contact normal, and the
    /// outer contact's friction holds the whole gyroscopic moment (`λ_o = 2, λ_i = 0` in
    /// Harris & Kotzalas 2006). The default.
    #[default]
    Outer,
    /// The kinematics of outer-race control with the gyroscopic moment left out of the
    /// ball's equilibrium (held elsewhere, e.g. by the cage): centrifugal force only.
    OuterWithoutGyroscopic,
}

/// The loads of one ball at speed.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct BallSpeedLoad {
    /// Azimuth ψ_j, rad.
    pub azimuth_rad: f64,
    /// Inner raceway load Q_i, N.
    pub inner_load_n: f64,
    /// Outer raceway load Q_o, N.
    pub outer_load_n: f64,
    /// Inner contact angle α_i, rad: the direction of the ball's force on the inner ring.
    pub inner_contact_angle_rad: f64,
    /// Outer contact angle α_o, rad.
    pub outer_contact_angle_rad: f64,
    /// Approaches `[δ_i, δ_o]` of the inner and outer contact, mm (negative: open).
    pub approach_mm: [f64; 2],
    /// Centrifugal force F_c, N.
    pub centrifugal_force_n: f64,
    /// Gyroscopic moment `M_g = J ω_R ω_c sin β`, N·mm (signed as ω_R; 0 when
    /// [`RaceControl::OuterWithoutGyroscopic`] leaves it out).
    pub gyroscopic_moment_nmm: f64,
    /// Cage speed ω_c, rad/s.
    pub cage_speed_rad_s: f64,
    /// The ball's speed ω_R about its own axis relative to the cage, rad/s.
    pub ball_speed_rad_s: f64,
    /// The pitch β of the ball's axis, rad.
    pub ball_axis_pitch_rad: f64,
    /// Maximum Hertz pressure on the inner raceway, MPa.
    pub inner_max_pressure_mpa: f64,
    /// Maximum Hertz pressure on the outer raceway, MPa.
    pub outer_max_pressure_mpa: f64,
}

/// The per-ball model: contacts, mass, speeds.
#[derive(Debug, Clone, Copy)]
struct BallModel {
    /// Hertz load coefficients `[K_i, K_o]`, N/mm^1.5, and of both in series.
    k: [f64; 2],
    k_n: f64,
    /// `[(f_i − ½) D, (f_o − ½) D]`, mm.
    rho: [f64; 2],
    d: f64,
    dm: f64,
    /// Mass (N·s²/mm) and moment of inertia `m D²/10` (N·s²·mm).
    mass: f64,
    inertia: f64,
    speeds: RingSpeeds,
    gyroscopic: bool,
    /// The inner approach δ_b (mm) over which the kinematics pass from the outer contact
    /// angle (inner contact open) to the inner one (pressed): `1e-5 D`.
    blend: f64,
}

/// The speed terms of a ball and their derivatives by `(α_i, α_o)`.
#[derive(Debug, Clone, Copy)]
struct SpeedTerms {
    fc: f64,
    to: f64,
    mg: f64,
    kin: ElementKinematics,
    dfc: [f64; 2],
    dto: [f64; 2],
}

/// One ball's equilibrium: its centre, loads and the derivative of its inner contact
/// force `Q_i n_i` by A.
#[derive(Debug, Clone, Copy, Default)]
struct BallState {
    x: [f64; 2],
    valid: bool,
    q: [f64; 2],
    delta: [f64; 2],
    alpha: [f64; 2],
    fc: f64,
    mg: f64,
    kin: [f64; 3],
    /// `Q_i n_i`, N.
    p: [f64; 2],
    /// `∂(Q_i n_i)/∂A`, rows.
    dp: [[f64; 2]; 2],
    converged: bool,
}

/// The residual of a ball's equilibrium and its Jacobians.
struct Eval {
    r: Vector2<f64>,
    r_x: Matrix2<f64>,
    r_a: Matrix2<f64>,
    h_i: Matrix2<f64>,
    st: SpeedTerms,
    q: [f64; 2],
    delta: [f64; 2],
    n_i: Vector2<f64>,
    n_o: Vector2<f64>,
}

/// A Hertz contact along `w` (mm) with free length `rho`: the approach, the force `Q w/|w|`
/// and its derivative by w.
fn contact(k: f64, rho: f64, w: Vector2<f64>) -> (f64, f64, Vector2<f64>, Matrix2<f64>, f64) {
    let l = w.norm();
    let n = w / l;
    let d = l - rho;
    if d > 0.0 {
        let sd = d.sqrt();
        let q = k * d * sd;
        let nn = n * n.transpose();
        let h = nn * (1.5 * k * sd) + (Matrix2::identity() - nn) * (q / l);
        (d, q, n, h, l)
    } else {
        (d, 0.0, n, Matrix2::zeros(), l)
    }
}

impl BallModel {
    fn at_rest(&self) -> bool {
        self.speeds.is_zero()
    }

    /// F_c, T_o, M_g and the kinematics at the contact angles `(α_i, α_o)`, given as the
    /// unit normals `n_i = (cos α_i, sin α_i)` and `n_o`, with their derivatives by
    /// `(α_i, α_o)` (`docs/bearing-model.md` §16.2). The same formulas as
    /// [`crate::speed::kinematics`], written with the normals' components (no
    /// trigonometric function in the ball's Newton).
    fn speed_terms(&self, n_i: Vector2<f64>, n_o: Vector2<f64>) -> SpeedTerms {
        let g = self.d / self.dm;
        let (ci, si, co, so) = (n_i[0], n_i[1], n_o[0], n_o[1]);
        // outer-race control: tan β = sin α_o/(cos α_o + γ)
        let h = so.hypot(co + g);
        let (sb, cb) = (so / h, (co + g) / h);
        if self.at_rest() {
            return SpeedTerms {
                fc: 0.0,
                to: 0.0,
                mg: 0.0,
                kin: ElementKinematics {
                    cage_rad_s: 0.0,
                    element_rad_s: 0.0,
                    pitch_rad: sb.atan2(cb),
                },
                dfc: [0.0; 2],
                dto: [0.0; 2],
            };
        }
        let db = (1.0 + g * co) / (h * h);
        // cos and sin of α_o − β and α_i − β
        let (cbo, sbo) = (co * cb + so * sb, so * cb - co * sb);
        let (cbi, sbi) = (ci * cb + si * sb, si * cb - ci * sb);
        let (uo, ui) = (1.0 + g * co, 1.0 - g * ci);
        let (xo, xi) = (cbo / uo, cbi / ui);
        // derivatives of X_o, X_i by (α_i, α_o)
        let dxo = [0.0, (-sbo * (1.0 - db) * uo + cbo * g * so) / (uo * uo)];
        let dxi = [(-sbi * ui - cbi * g * si) / (ui * ui), sbi * db / ui];
        let (wi, wo) = (self.speeds.inner_rad_s, self.speeds.outer_rad_s);
        let s = xo + xi;
        let wc = (wi * xo + wo * xi) / s;
        let wr = (wo - wi) / (g * s);
        let kin = ElementKinematics {
            cage_rad_s: wc,
            element_rad_s: wr,
            pitch_rad: sb.atan2(cb),
        };
        let j = if self.gyroscopic { self.inertia } else { 0.0 };
        let mut dfc = [0.0; 2];
        let mut dto = [0.0; 2];
        for k in 0..2 {
            let dwc = ((wo - wc) * dxi[k] + (wi - wc) * dxo[k]) / s;
            let dwr = -wr * (dxo[k] + dxi[k]) / s;
            let dbeta = if k == 1 { db } else { 0.0 };
            dfc[k] = self.mass * self.dm * wc * dwc;
            let dmg = j * (dwr * wc * sb + wr * dwc * sb + wr * wc * cb * dbeta);
            dto[k] = 2.0 * dmg / self.d;
        }
        let mg = j * wr * wc * sb + 0.0; // + 0: no −0 in the report
        SpeedTerms {
            fc: centrifugal_force(self.mass, self.dm, wc),
            to: 2.0 * mg / self.d,
            mg,
            kin,
            dfc,
            dto,
        }
    }

    /// The ball's residual at its centre `x` with the inner groove centre at `a`.
    fn eval(&self, a: Vector2<f64>, x: Vector2<f64>) -> Eval {
        let (d_o, q_o, n_o, h_o, l_o) = contact(self.k[1], self.rho[1], x);
        let (d_i, q_i, n_i, h_i, l_i) = contact(self.k[0], self.rho[0], a - x);
        let t_o = Vector2::new(-n_o[1], n_o[0]);
        let t_i = Vector2::new(-n_i[1], n_i[0]);
        let e_r = Vector2::new(1.0, 0.0);
        // the inner angle of the kinematics α_k: the inner contact's while it is pressed
        // (δ_i >= δ_b), the outer one's while it is open (a ball lifted off the inner ring
        // is not driven by it), a smoothstep w(δ_i/δ_b) between (§16.3)
        let (ai, ao) = (n_i[1].atan2(n_i[0]), n_o[1].atan2(n_o[0]));
        let sb = (d_i / self.blend).clamp(0.0, 1.0);
        let w = sb * sb * (3.0 - 2.0 * sb);
        let dw = 6.0 * sb * (1.0 - sb) / self.blend;
        let n_k = if w == 1.0 {
            n_i
        } else {
            let ak = ao + w * (ai - ao);
            Vector2::new(ak.cos(), ak.sin())
        };
        let st = self.speed_terms(n_k, n_o);
        let r = n_i * q_i - n_o * q_o + e_r * st.fc + t_o * st.to;
        let ds_dao = e_r * st.dfc[1] + t_o * st.dto[1] - n_o * st.to;
        let ds_dak = e_r * st.dfc[0] + t_o * st.dto[0];
        // ∂α_k/∂A and ∂α_k/∂X (δ_i = |A − X| − ρ_i, α_i the direction of A − X)
        let gk_a = t_i * (w / l_i) + n_i * (dw * (ai - ao));
        let gk_x = t_o * ((1.0 - w) / l_o) - gk_a;
        let r_x = -h_i - h_o + ds_dao * (t_o / l_o).transpose() + ds_dak * gk_x.transpose();
        let r_a = h_i + ds_dak * gk_a.transpose();
        Eval {
            r,
            r_x,
            r_a,
            h_i,
            st,
            q: [q_i, q_o],
            delta: [d_i, d_o],
            n_i,
            n_o,
        }
    }

    /// A start: the ball on the line of the groove centres, the approach split as the
    /// quasi-static model's, pushed out by the centrifugal force at that angle.
    fn start(&self, a: Vector2<f64>) -> Vector2<f64> {
        let len = a.norm();
        let n = a / len;
        let delta = len - self.rho[0] - self.rho[1];
        let mut d_o = if delta > 0.0 {
            delta * (self.k_n / self.k[1]).powf(2.0 / 3.0)
        } else {
            0.5 * delta
        };
        if !self.at_rest() {
            let fc = self.speed_terms(n, n).fc;
            d_o = d_o.max((fc / self.k[1]).powf(2.0 / 3.0));
        }
        n * (self.rho[1] + d_o)
    }

    /// Solve the ball's equilibrium for the inner groove centre at `a` (mm), from `warm`
    /// (the ball's last centre) when given.
    fn solve(&self, a: Vector2<f64>, warm: Option<[f64; 2]>) -> BallState {
        // the warm start, then the pressed start, then the ball at the outer groove's bottom
        // (a start that ends at no equilibrium, e.g. in a fold of the branch it starts on,
        // hands over to the next)
        let pressed = self.start(a);
        let lifted = {
            let fc = self
                .speed_terms(Vector2::new(1.0, 0.0), Vector2::new(1.0, 0.0))
                .fc;
            Vector2::new(self.rho[1] + (fc / self.k[1]).powf(2.0 / 3.0), 0.0)
        };
        let starts = [warm.map(Vector2::from), Some(pressed), Some(lifted)];
        let mut best = None;
        for x0 in starts.into_iter().flatten() {
            let (x, e, converged) = self.newton(a, x0);
            if converged {
                return self.state(x, e, true);
            }
            best.get_or_insert((x, e));
        }
        let (x, e) = best.unwrap_or_else(|| (pressed, self.eval(a, pressed)));
        self.state(x, e, false)
    }

    /// Newton on the ball's centre from `x0`: the centre, its evaluation and whether it
    /// converged.
    fn newton(&self, a: Vector2<f64>, x0: Vector2<f64>) -> (Vector2<f64>, Eval, bool) {
        let mut x = x0;
        let mut e = self.eval(a, x);
        let mut converged = false;
        if self.at_rest() && e.q == [0.0, 0.0] && a.norm() <= self.rho[0] + self.rho[1] {
            // at rest and not pressed: the ball is anywhere between the grooves, unloaded
            x = self.start(a);
            e = self.eval(a, x);
            converged = true;
        }
        let mut it = 0;
        while !converged && it < 60 {
            it += 1;
            let scale = e.q[0] + e.q[1] + e.st.fc + e.st.to.abs();
            let res = e.r.norm();
            if res <= 1e-14 * scale {
                converged = true;
                break;
            }
            // Newton in the centre's polar coordinates about the outer groove centre,
            // (|X|, α_o): the outer contact's stiff normal and the soft roll of the ball
            // along the groove are apart, so a ball lifted off the inner ring rolls down the
            // groove in a few steps (in X a straight step leaves the groove's circle and
            // the line search crawls)
            let l = x.norm();
            let (n_o, t_o) = (x / l, Vector2::new(-x[1], x[0]) / l);
            let jac = Matrix2::from_columns(&[e.r_x * n_o, e.r_x * t_o * l]);
            let Some(inv) = jac.try_inverse() else {
                break;
            };
            let step = -(inv * e.r);
            let alpha = x[1].atan2(x[0]);
            let mut t = 1.0;
            let mut accepted = false;
            for _ in 0..40 {
                let (sa, ca) = (alpha + t * step[1]).sin_cos();
                let trial = Vector2::new(ca, sa) * (l + t * step[0]);
                let e2 = self.eval(a, trial);
                if e2.r.norm() < (1.0 - 1e-4 * t) * res {
                    x = trial;
                    e = e2;
                    accepted = true;
                    break;
                }
                t *= 0.5;
            }
            if !accepted {
                // the round-off floor: accept a residual near it
                converged = res <= 1e-11 * scale;
                break;
            }
            if (step[0].abs() + l * step[1].abs()) * t <= 1e-15 * (self.rho[0] + self.rho[1]) {
                converged = e.r.norm() <= 1e-11 * scale;
                break;
            }
        }
        (x, e, converged)
    }

    /// The ball's state at its centre `x` with the evaluation `e` there.
    fn state(&self, x: Vector2<f64>, e: Eval, converged: bool) -> BallState {
        // the derivative of the ring's force Q_i n_i by A with X eliminated
        let dp = if e.q[0] > 0.0 {
            match e.r_x.try_inverse() {
                Some(inv) => e.h_i * (Matrix2::identity() + inv * e.r_a),
                None => Matrix2::zeros(),
            }
        } else {
            Matrix2::zeros()
        };
        let p = e.n_i * e.q[0];
        BallState {
            x: x.into(),
            valid: true,
            q: e.q,
            delta: e.delta,
            alpha: [e.n_i[1].atan2(e.n_i[0]), e.n_o[1].atan2(e.n_o[0])],
            fc: e.st.fc,
            mg: e.st.mg,
            kin: [
                e.st.kin.cage_rad_s,
                e.st.kin.element_rad_s,
                e.st.kin.pitch_rad,
            ],
            p: p.into(),
            dp: [[dp[(0, 0)], dp[(0, 1)]], [dp[(1, 0)], dp[(1, 1)]]],
            converged,
        }
    }
}

/// The solver of a ball bearing at speed.
#[derive(Debug, Clone)]
pub struct BallSpeedSolver {
    qs: BallBearingSolver,
    model: BallModel,
    race_control: RaceControl,
    p_unit: [f64; 2],
    state: Vec<BallState>,
    balls: Vec<BallSpeedLoad>,
    /// Largest relative residual accepted as converged (default 1e-11).
    pub tolerance: f64,
    /// Iteration limit of the ring's Newton (default 100).
    pub max_iterations: usize,
}

impl BallSpeedSolver {
    /// Validate the bearing and the speeds, plan the Hertz contacts.
    ///
    /// # Errors
    /// As [`BallBearing::validate`] and [`RingSpeeds::validate`].
    pub fn new(
        bearing: BallBearing,
        speeds: RingSpeeds,
        race_control: RaceControl,
    ) -> Result<Self> {
        speeds.validate()?;
        let qs = BallBearingSolver::new(bearing)?;
        let b = qs.bearing();
        let alpha_k = b.stiffness_contact_angle();
        let [ci, co] = b.contacts(alpha_k)?;
        let d = b.ball_diameter_mm;
        let mass = density_n_s2_per_mm4(b.ball_density_kg_m3) * PI * d.powi(3) / 6.0;
        let model = BallModel {
            k: [ci.load_coefficient(), co.load_coefficient()],
            k_n: qs.ball_stiffness(),
            rho: [
                (b.inner_osculation - 0.5) * d,
                (b.outer_osculation - 0.5) * d,
            ],
            d,
            dm: b.pitch_diameter_mm,
            mass,
            inertia: 0.1 * mass * d * d,
            speeds,
            gyroscopic: race_control == RaceControl::Outer,
            blend: 1e-5 * d,
        };
        let z = b.balls;
        Ok(BallSpeedSolver {
            p_unit: [
                ci.max_pressure_at_unit_force(),
                co.max_pressure_at_unit_force(),
            ],
            model,
            race_control,
            state: vec![BallState::default(); z],
            balls: vec![BallSpeedLoad::default(); z],
            qs,
            tolerance: 1e-11,
            max_iterations: 100,
        })
    }

    /// The bearing.
    pub fn bearing(&self) -> &BallBearing {
        self.qs.bearing()
    }

    /// The ring speeds.
    pub fn speeds(&self) -> RingSpeeds {
        self.model.speeds
    }

    /// The race-control assumption.
    pub fn race_control(&self) -> RaceControl {
        self.race_control
    }

    /// Set new ring speeds (rad/s); the next solve starts from the balls' last centres.
    ///
    /// # Errors
    /// As [`RingSpeeds::validate`].
    pub fn set_speeds(&mut self, speeds: RingSpeeds) -> Result<()> {
        speeds.validate()?;
        self.model.speeds = speeds;
        Ok(())
    }

    /// The ball's load coefficient K_n (N/mm^1.5) of both contacts in series.
    pub fn ball_stiffness(&self) -> f64 {
        self.model.k_n
    }

    /// The ball's mass, kg.
    pub fn ball_mass_kg(&self) -> f64 {
        self.model.mass * 1e3
    }

    /// Per-ball loads of the last solve.
    pub fn ball_loads(&self) -> &[BallSpeedLoad] {
        &self.balls
    }

    /// The quasi-static solver of the same bearing (the start of every cold solve).
    pub fn quasi_static(&mut self) -> &mut BallBearingSolver {
        &mut self.qs
    }

    /// The carried load `Σ G_jᵀ Q_i n_i` and the condensed stiffness at `u`; updates the
    /// balls' states (warm-started from them).
    fn evaluate(&mut self, u: &Vector5<f64>) -> (Vector5<f64>, Matrix5<f64>, bool) {
        let (offset, _) = self.qs.offsets();
        let mut f = Vector5::zeros();
        let mut k = Matrix5::zeros();
        let mut all = true;
        for (fr, st) in self.qs.frames().iter().zip(self.state.iter_mut()) {
            let a = Vector2::new(offset[0] + fr.gr.dot(u), offset[1] + fr.gz.dot(u));
            let warm = st.valid.then_some(st.x);
            *st = self.model.solve(a, warm);
            all &= st.converged;
            f += fr.gr * st.p[0] + fr.gz * st.p[1];
            let dp = st.dp;
            k += (fr.gr * dp[0][0] + fr.gz * dp[1][0]) * fr.gr.transpose()
                + (fr.gr * dp[0][1] + fr.gz * dp[1][1]) * fr.gz.transpose();
        }
        (f, k, all)
    }

    /// The load `(Fx, Fy, Fz, Mx, My)` (N, N·mm) the balls carry at the inner-ring
    /// displacement `u` (mm, rad), and the (not symmetric) stiffness there.
    pub fn load_at(&mut self, u: [f64; 5]) -> ([f64; 5], [[f64; 5]; 5]) {
        let (f, k, _) = self.evaluate(&Vector5::from(u));
        (f.into(), to_rows(&k))
    }

    /// Solve the inner ring's equilibrium under `load` at the solver's speeds, starting
    /// from the quasi-static equilibrium (the balls' centres from scratch).
    ///
    /// # Errors
    /// As [`BallBearingSolver::solve`]; a solve that does not converge ends with its
    /// status and a note, as there.
    pub fn solve(&mut self, load: &RingLoad) -> Result<BallSolution> {
        let start = self.qs.solve(load)?;
        for s in &mut self.state {
            s.valid = false;
        }
        Ok(self.iterate(load, Vector5::from(start.displacement)))
    }

    /// Solve from the displacement `start` (mm, rad), e.g. a nearby solution, with the
    /// balls' centres warm from the last solve.
    ///
    /// # Errors
    /// As [`BallSpeedSolver::solve`], and `start` must be finite.
    pub fn solve_from(&mut self, load: &RingLoad, start: [f64; 5]) -> Result<BallSolution> {
        self.qs.check_load(load)?;
        let u = warm_start(load, start, &[true; 5])?;
        Ok(self.iterate(load, u))
    }

    fn iterate(&mut self, load: &RingLoad, mut u: Vector5<f64>) -> BallSolution {
        let b = self.qs.bearing();
        let r = 0.5 * b.pitch_diameter_mm;
        let z = b.balls as f64;
        let angular = b.kind == BallBearingKind::AngularContact;
        let (offset, a0) = self.qs.offsets();
        let (free, target) = free_and_target(load, &[true; 5]);
        let mut f_ref = load_scale(&target, r);
        let preload = a0 - offset[0].hypot(offset[1]);
        if preload < 0.0 {
            f_ref = f_ref.max(z * self.model.k_n * (-preload).powf(1.5));
        }
        let limit = self.qs.limit();
        let probe = *self.qs.probe();
        let (mut f, mut k, mut balls_ok) = self.evaluate(&u);
        if f_ref == 0.0 {
            f_ref = reaction_scale(&f, r);
        }
        let (_, scale) = self.qs.reference(f_ref);
        let merit = |f: &Vector5<f64>| -> f64 {
            (0..5)
                .filter(|&i| free[i])
                .map(|i| {
                    let s = if i < 3 { f_ref } else { f_ref * r };
                    ((f[i] - target[i]) / s).powi(2)
                })
                .sum()
        };
        let mut res = relative_residual(&f, &target, &free, f_ref, r);
        // no load and no reaction: nothing to iterate
        let mut termination = match f_ref {
            0.0 => Termination::Converged,
            _ => Termination::MaxIterations,
        };
        let (mut note, mut iterations, mut at_u) = (None, 0, true);
        while termination == Termination::MaxIterations && iterations < self.max_iterations {
            if res <= self.tolerance && balls_ok {
                termination = Termination::Converged;
                break;
            }
            iterations += 1;
            let (jac, rhs, _) = newton_system(&k, &f, &target, &free, scale, &probe);
            let Some(step) = jac.lu().solve(&rhs) else {
                termination = Termination::Diverged;
                note = Some("the Newton system is singular: the load cannot be carried");
                break;
            };
            let m0 = merit(&f);
            let mut t = 1.0;
            let mut accepted = false;
            for _ in 0..50 {
                let trial = u + step * t;
                let (f2, k2, ok2) = self.evaluate(&trial);
                let res2 = relative_residual(&f2, &target, &free, f_ref, r);
                if merit(&f2) <= (1.0 - 1e-4 * t) * m0 || res2 <= self.tolerance {
                    u = trial;
                    f = f2;
                    k = k2;
                    balls_ok = ok2;
                    res = res2;
                    accepted = true;
                    break;
                }
                t *= 0.5;
            }
            if !accepted {
                at_u = false;
                (termination, note) = no_decrease(res, self.tolerance);
                break;
            }
            if beyond_limit(&u, r, limit) {
                termination = Termination::Diverged;
                note = Some(BEYOND_LIMIT);
                break;
            }
        }
        if termination == Termination::MaxIterations && res <= self.tolerance && balls_ok {
            termination = Termination::Converged;
        }
        if termination == Termination::MaxIterations {
            note = Some("the iteration limit was reached before the tolerance");
        }
        if !at_u {
            let (f2, k2, ok2) = self.evaluate(&u);
            f = f2;
            k = k2;
            balls_ok = ok2;
        }
        if !balls_ok && termination == Termination::Converged {
            termination = Termination::Diverged;
            note = Some("a ball's own equilibrium did not converge");
        }
        let mut qmax: f64 = 0.0;
        let mut pmax = [0.0f64; 2];
        let mut over_shoulder = false;
        for (j, (fr, st)) in self.qs.frames().iter().zip(&self.state).enumerate() {
            let ci = st.q[0].cbrt();
            let co = st.q[1].cbrt();
            let row = BallSpeedLoad {
                azimuth_rad: fr.gr[1].atan2(fr.gr[0]),
                inner_load_n: st.q[0],
                outer_load_n: st.q[1],
                inner_contact_angle_rad: st.alpha[0],
                outer_contact_angle_rad: st.alpha[1],
                approach_mm: st.delta,
                centrifugal_force_n: st.fc,
                gyroscopic_moment_nmm: st.mg,
                cage_speed_rad_s: st.kin[0],
                ball_speed_rad_s: st.kin[1],
                ball_axis_pitch_rad: st.kin[2],
                inner_max_pressure_mpa: self.p_unit[0] * ci,
                outer_max_pressure_mpa: self.p_unit[1] * co,
            };
            over_shoulder |= angular && st.q[0] > 0.0 && st.alpha[0] <= 0.0;
            // the largest load on the inner ring (as at rest: 0 when every ball is lifted off it)
            qmax = qmax.max(st.q[0]);
            pmax[0] = pmax[0].max(row.inner_max_pressure_mpa);
            pmax[1] = pmax[1].max(row.outer_max_pressure_mpa);
            self.balls[j] = row;
        }
        if over_shoulder && termination == Termination::Converged {
            termination = Termination::Diverged;
            note = Some(
                "a loaded ball of the angular-contact bearing has an inner contact angle <= 0: it runs over the low shoulder; the radial load needs more axial load (or prescribe dz_mm)",
            );
        }
        if termination == Termination::Converged && self.balls.iter().all(|b| b.inner_load_n == 0.0)
        {
            note = Some("every ball is lifted off the inner ring: zero load");
        }
        let model = self.model;
        let qs = &self.qs;
        let states = &self.state;
        let psi_first = qs.bearing().first_ball_azimuth_rad;
        let load_zone = load_zone(&u, |psi| {
            let fr = qs.frame(psi);
            let a = Vector2::new(offset[0] + fr.gr.dot(&u), offset[1] + fr.gz.dot(&u));
            if model.at_rest() {
                a.norm() - a0
            } else {
                // warm from the nearest ball: with the gyroscopic friction a ball at the
                // edge of the load zone may also rest lifted off; follow the solution's
                let j = ((psi - psi_first) * z / (2.0 * PI)).round().rem_euclid(z) as usize;
                let warm = states.get(j).map(|s| s.x);
                model.solve(a, warm).delta[0]
            }
        });
        BallSolution {
            displacement: u.into(),
            load: f.into(),
            stiffness: to_rows(&k),
            status: SolveStatus::new(termination, iterations, res),
            note,
            max_ball_load_n: qmax,
            max_pressure_mpa: pmax,
            load_zone,
        }
    }
}

#[cfg(test)]
mod tests;
