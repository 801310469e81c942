//! The Newton iteration shared by the roller and the ball bearing solvers: both carry the
//! load `F(u) = ∇Φ(u)` of a convex potential Φ of the inner-ring displacement u, with the
//! stiffness `K = ∇²Φ` (`docs/bearing-model.md` §3 and §8).

use kontakt::solve::Termination;
use nalgebra::{Matrix5, Vector5};

/// What the iteration needs of a bearing model.
pub(crate) trait ConvexRing {
    /// The carried load, the stiffness and the potential at `u`; fills the model's
    /// per-element buffers (the approaches of the last evaluation).
    fn evaluate(&mut self, u: &Vector5<f64>) -> (Vector5<f64>, Matrix5<f64>, f64);
    /// The shape of the stiffness with every element in contact (`Σ g gᵀ`).
    fn probe(&self) -> &Matrix5<f64>;
    /// The reference approach (mm) of an element under the load scale `f_ref` shared by
    /// all elements, and the stiffness per unit of the probe there.
    fn reference(&self, f_ref: f64) -> (f64, f64);
    /// The smallest step fraction `t` at which an element approaching along `step` (by
    /// the last evaluation's approaches and their first-order rates) reaches `d_ref`;
    /// `∞` when none approaches.
    fn touch(&self, step: &Vector5<f64>, d_ref: f64) -> f64;
    /// The largest translation (mm) and the largest tilt times the pitch radius before the
    /// load is declared not carried (an element diameter).
    fn limit(&self) -> f64;
}

/// How an iteration ended.
pub(crate) struct Outcome {
    pub u: Vector5<f64>,
    pub termination: Termination,
    pub iterations: usize,
    pub residual: f64,
    pub note: Option<&'static str>,
    /// The load carried at `u` and its stiffness.
    pub f: Vector5<f64>,
    pub k: Matrix5<f64>,
    /// Whether the model's last evaluation was at `u` (its per-element buffers describe the
    /// solution); false only after a failed line search, whose last trial was elsewhere.
    pub buffers_at_u: bool,
}

/// The largest residual of a free component relative to the load scale: forces to
/// `f_ref`, moments to `f_ref r`.
pub(crate) fn relative_residual(
    f: &Vector5<f64>,
    target: &Vector5<f64>,
    free: &[bool; 5],
    f_ref: f64,
    r: f64,
) -> f64 {
    if f_ref == 0.0 {
        return 0.0;
    }
    (0..5)
        .filter(|&i| free[i])
        .map(|i| {
            let s = if i < 3 { f_ref } else { f_ref * r };
            (f[i] - target[i]).abs() / s
        })
        .fold(0.0, f64::max)
}

/// Newton's method on `F(u) = target` over the `free` components with the analytic
/// stiffness, the probe where a free direction has no contact stiffness, the free-flight
/// stretch and an Armijo backtracking line search on the merit `Φ(u) − target·u`.
/// `f_ref` is the load scale (0: set from the reaction at the start), `r` the pitch
/// radius (the moment scale).
#[allow(clippy::too_many_arguments)]
pub(crate) fn newton<M: ConvexRing>(
    model: &mut M,
    free: [bool; 5],
    target: Vector5<f64>,
    mut u: Vector5<f64>,
    mut f_ref: f64,
    r: f64,
    tolerance: f64,
    max_iterations: usize,
) -> Outcome {
    let limit = model.limit();
    let (mut f, mut k, mut phi) = model.evaluate(&u);
    if f_ref == 0.0 {
        // no applied load: the reaction to the prescribed displacements sets the scale, on
        // every component (filtered to the free ones it was round-off, 1e-13 N, and a
        // prescribed dx on a cylindrical bearing never converged; case test
        // `prescribed_displacement_returns_the_force`)
        f_ref = reaction_scale(&f, r);
    }
    let mut res = relative_residual(&f, &target, &free, f_ref, r);
    let mut termination = Termination::MaxIterations;
    let mut note = None;
    let mut iterations = 0;
    if f_ref == 0.0 {
        termination = Termination::Converged;
    }
    let (d_ref, scale) = model.reference(f_ref);
    let probe = *model.probe();
    let mut buffers_at_u = true;
    while termination == Termination::MaxIterations && iterations < max_iterations {
        if res <= tolerance {
            termination = Termination::Converged;
            break;
        }
        iterations += 1;
        let (jac, rhs, weak) = newton_system(&k, &f, &target, &free, scale, &probe);
        let Some(chol) = jac.cholesky() else {
            termination = Termination::Diverged;
            note = Some("the Newton system is singular: the load cannot be carried");
            break;
        };
        let mut step = chol.solve(&rhs);
        if weak {
            // free flight (a direction without contact): stretch the step until the
            // first element it closes reaches the reference approach
            let t_touch = model.touch(&step, d_ref);
            if t_touch.is_finite() && t_touch > 1.0 {
                step *= t_touch;
            }
        }
        // Armijo backtracking on Φ(u) − F·u (convex), whose gradient is −rhs
        let merit = phi - target.dot(&u);
        let slope = -rhs.dot(&step);
        let mut t = 1.0;
        let mut accepted = false;
        for _ in 0..60 {
            let trial = u + step * t;
            let (f2, k2, phi2) = model.evaluate(&trial);
            let merit2 = phi2 - target.dot(&trial);
            let res2 = relative_residual(&f2, &target, &free, f_ref, r);
            let slack = 1e-13 * (phi.abs() + target.dot(&u).abs());
            if merit2 <= merit + 1e-4 * t * slope + slack || res2 < 0.5 * res {
                u = trial;
                f = f2;
                k = k2;
                phi = phi2;
                res = res2;
                accepted = true;
                break;
            }
            t *= 0.5;
        }
        if !accepted {
            buffers_at_u = false;
            (termination, note) = no_decrease(res, tolerance);
            break;
        }
        if beyond_limit(&u, r, limit) {
            termination = Termination::Diverged;
            note = Some(BEYOND_LIMIT);
            break;
        }
    }
    if termination == Termination::MaxIterations && res <= tolerance {
        termination = Termination::Converged;
    }
    if termination == Termination::MaxIterations {
        note = Some("the iteration limit was reached before the tolerance");
    }
    Outcome {
        u,
        termination,
        iterations,
        residual: res,
        note,
        f,
        k,
        buffers_at_u,
    }
}

/// The Newton system `jac · step = rhs` on the `free` directions at the load `f` and
/// stiffness `k`: a direction without contact stiffness borrows the diagonal of the
/// all-elements-in-contact shape `probe` times `scale` (a descent direction still; only the
/// weak direction borrows, the others keep Newton's rate), every diagonal a 1e-12 of it, a
/// prescribed direction the identity. Also whether a direction was weak.
pub(crate) fn newton_system(
    k: &Matrix5<f64>,
    f: &Vector5<f64>,
    target: &Vector5<f64>,
    free: &[bool; 5],
    scale: f64,
    probe: &Matrix5<f64>,
) -> (Matrix5<f64>, Vector5<f64>, bool) {
    let mut rhs = Vector5::zeros();
    let mut jac = *k;
    let mut weak = false;
    for i in 0..5 {
        if free[i] {
            rhs[i] = target[i] - f[i];
            if !(k[(i, i)] > 1e-6 * scale * probe[(i, i)]) {
                weak = true;
                jac[(i, i)] += scale * probe[(i, i)];
            }
        }
    }
    for i in 0..5 {
        jac[(i, i)] += 1e-12 * scale * probe[(i, i)];
        if !free[i] {
            for j in 0..5 {
                jac[(i, j)] = 0.0;
                jac[(j, i)] = 0.0;
            }
            jac[(i, i)] = 1.0;
        }
    }
    (jac, rhs, weak)
}

/// How an iteration ends whose line search found no decrease at the residual `res`:
/// stagnated near the round-off floor (1000 times the tolerance), else diverged.
pub(crate) fn no_decrease(res: f64, tolerance: f64) -> (Termination, Option<&'static str>) {
    let termination = if res <= 1e3 * tolerance {
        Termination::Stagnated
    } else {
        Termination::Diverged
    };
    (
        termination,
        Some(
            "the line search found no decrease (round-off floor or a load the bearing cannot carry)",
        ),
    )
}

/// The note of a ring displacement beyond [`ConvexRing::limit`].
pub(crate) const BEYOND_LIMIT: &str = "the ring displacement exceeds the element diameter: the load cannot be carried (e.g. a moment or radial load a single row cannot balance; hold the tilts)";

/// Whether a translation of `u` or a tilt times the pitch radius `r` exceeds `limit` (mm).
pub(crate) fn beyond_limit(u: &Vector5<f64>, r: f64, limit: f64) -> bool {
    (0..3).any(|i| u[i].abs() > limit) || (3..5).any(|i| (u[i] * r).abs() > limit)
}

/// The load scale of a reaction `f`: its largest force, or moment over `r` (mm).
pub(crate) fn reaction_scale(f: &Vector5<f64>, r: f64) -> f64 {
    (0..5)
        .map(|i| if i < 3 { f[i].abs() } else { f[i].abs() / r })
        .fold(0.0, f64::max)
}

/// A nalgebra matrix as rows.
pub(crate) fn to_rows(k: &Matrix5<f64>) -> [[f64; 5]; 5] {
    let mut m = [[0.0; 5]; 5];
    for (i, row) in m.iter_mut().enumerate() {
        for (j, v) in row.iter_mut().enumerate() {
            *v = k[(i, j)];
        }
    }
    m
}
