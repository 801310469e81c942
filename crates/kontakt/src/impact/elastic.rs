//! Elastic oblique impact of a sphere on a flat with friction: Hertz normal compliance
//! coupled with Mindlin-Deresiewicz tangential compliance, integrated over the impact
//! (the analysis of Maw, Barber and Fawcett 1976; Johnson 1982 Fig. 11b).
//!
//! # Model
//! Frame, signs and the non-dimensional $\psi$, $\chi$, $\kappa$ as in [`crate::impact`].
//! - **Normal**: $m\ddot\delta = -P$, $P = \tfrac43E^*\sqrt R\,\delta^{3/2}$, contact radius
//!   $a = \sqrt{R\delta}$, $\dot\delta(0) = V$ (quasi-static Hertz impact, uncoupled from the
//!   tangential problem since the Dundurs constant $\beta$ is neglected; it is integrated
//!   numerically here and checked against [`crate::hertz::impact`]).
//! - **Tangential**: the peripheral velocity obeys $m_t\dot w = -Q$, and the relative
//!   tangential displacement of the two bodies far from the contact grows at the rate $w$.
//!   $Q$ follows from the whole history of $P$ and of that displacement by the
//!   Mindlin-Deresiewicz theory in the Cattaneo-Mindlin approximation (traction parallel to
//!   $x$, no normal-tangential coupling). That theory is evaluated **exactly in the form of
//!   the method of dimensionality reduction** (Popov & Heß 2015; the equivalence with the
//!   Cattaneo-Mindlin-Deresiewicz superposition is due to Jäger and Ciavarella, 1998): the
//!   circle of radius $a$ maps to a line $|x| < a$ of independent springs with normal
//!   stiffness $E^*$ and tangential stiffness $4G^*$ per unit length, normal indentation
//!   $\delta - x^2/R$; each spring sticks while its tangential force is below $\mu$ times its
//!   normal force and slides at that limit otherwise; a spring that comes into contact
//!   starts free of tangential force, one that leaves contact releases its force. This
//!   reproduces the Cattaneo-Mindlin stick radius, the Mindlin-Deresiewicz loading,
//!   unloading and reloading curves, and the behaviour of a contact whose area grows and
//!   shrinks, for any history; it is not the annular-slip simplification.
//!
//! # Integration scheme and accuracy
//! The line $0 \le x \le 1.1\,a^*$ ($a^*$ the Hertz maximum contact radius) is cut into
//! [`ElasticImpactOptions::cells`] cells; each carries one tangential force, and its normal
//! force is the exact integral of $E^*(\delta - x^2/R)$ over its part in contact, so that the
//! cells' normal forces sum to the Hertz $P$ exactly. Time is advanced with
//! velocity-Verlet (kick-drift-kick) steps of $h = T/N$, $T$ the Hertz contact duration and
//! $N$ = [`ElasticImpactOptions::steps`]; in each drift the cells receive the tangential
//! increment $4G^*\,c\,h\,w_{n+1/2}$ ($c$ the covered length), a shrinking cell gives up the
//! share of force of its uncovered part, and each cell's force is clipped to $\pm\mu f$
//! (return mapping). The contact ends at the first step with $\delta \le 0$; its instant is
//! interpolated linearly. Measured errors (tests `oblique_impact.rs`, `docs/impact.md`
//! §3.6): with the defaults ($N = 4000$, 400 cells) the normal duration, peak force and
//! peak approach agree with the closed form to 3e-8 (the normal part is second order), the
//! gross-sliding rebound with the rigid sliding result to < 1e-11, and with partial slip the
//! scheme is first order in $h$ and in the cell size, with an error of at most 3e-4 in
//! $\psi_2$ (below $\psi_1 = 1.5$; 1e-5 above), estimated by Richardson extrapolation.
//!
//! # Assumptions
//! Quasi-static elastic contact (no waves, $e = 1$ in the normal direction), Hertz contact
//! of a sphere and a flat (or any two spheres with their effective radius and a fixed
//! second body), Coulomb friction with one coefficient, $\beta = 0$ (similar materials or
//! one rigid body), motion in one plane ($w$ parallel to $x$).
//!
//! # References
//! - Maw, Barber & Fawcett (1976), "The oblique impact of elastic spheres", Wear 38, 101-114.
//! - Maw, Barber & Fawcett (1981), "The role of elastic tangential compliance in oblique
//!   impact", J. Lubr. Technol. 103, 74-80.
//! - Mindlin & Deresiewicz (1953), J. Appl. Mech. 20, 327-344.
//! - Jäger (1998), "A new principle in contact mechanics", J. Tribol. 120, 677-684, and
//!   Ciavarella (1998), Int. J. Solids Struct. 35, 2349-2362 (superposition of
//!   Cattaneo-Mindlin solutions).
//! - Popov & Heß (2015), *Method of Dimensionality Reduction in Contact Mechanics and
//!   Friction*, Springer, ch. 4 and 5.
//! - Johnson (1982), §7 and Fig. 11b; Johnson, *Contact Mechanics* (1985), §11.4.

use super::{IncidentMotion, SphereBody, check_friction, stiffness_ratio};
use crate::error::{Error, Result};
use crate::hertz::impact::HERTZ_IMPACT_DURATION_CONSTANT;
use crate::material::{ElasticMaterial, effective_modulus, effective_shear_modulus};
use crate::units::{Megapascal, Millimetre, MillimetrePerSecond, Newton, NewtonMillimetre, Second};

/// Resolution of the elastic integration (see the module's *Integration scheme*).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct ElasticImpactOptions {
    /// $N$, time steps per Hertz contact duration \[-\], 100 ..= 10 000 000 (default 4000).
    pub steps: usize,
    /// Cells on the line $0 \le x \le 1.1a^*$ \[-\], 10 ..= 1 000 000 (default 400).
    pub cells: usize,
}

impl Default for ElasticImpactOptions {
    fn default() -> Self {
        ElasticImpactOptions {
            steps: 4000,
            cells: 400,
        }
    }
}

impl ElasticImpactOptions {
    /// Check the ranges documented on the fields.
    ///
    /// # Errors
    /// [`Error::InvalidInput`] naming `steps` or `cells`.
    pub fn validate(&self) -> Result<()> {
        if !(100..=10_000_000).contains(&self.steps) {
            return Err(Error::invalid(
                "steps",
                self.steps,
                "100 <= steps <= 10000000",
            ));
        }
        if !(10..=1_000_000).contains(&self.cells) {
            return Err(Error::invalid(
                "cells",
                self.cells,
                "10 <= cells <= 1000000",
            ));
        }
        Ok(())
    }
}

/// An elastic sphere striking an elastic (or rigid) flat obliquely, with friction (see the
/// module docs).
///
/// # Example
/// A steel ball on a steel plate, mu = 0.3, at 30° without spin ($\psi_1 = 1.59$, below the
/// rigid sliding threshold $4\chi = 5.76$, where the rigid theory gives $w_2 = 0$): the
/// contact point springs back, $w_2 < 0$ (the superball effect).
/// ```
/// use kontakt::impact::{ElasticImpactOptions, ElasticObliqueImpact, IncidentMotion, SphereBody};
/// use kontakt::material::ElasticMaterial;
/// let s = ElasticMaterial::STEEL;
/// let ball = SphereBody::solid_sphere(5.0, 4.11e-6)?;
/// let imp = ElasticObliqueImpact::new(ball, s, s, 0.3, ElasticImpactOptions::default())?;
/// let r = imp.rebound(&IncidentMotion::from_angle(1000.0, 30f64.to_radians(), 0.0)?)?;
/// assert!((r.psi1 - 1.585).abs() < 1e-3 && r.psi2 < -0.3);
/// assert!((r.normal_velocity / 1000.0 / 30f64.to_radians().cos() - 1.0).abs() < 1e-6);
/// # Ok::<(), kontakt::Error>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct ElasticObliqueImpact {
    body: SphereBody,
    e_star: Megapascal,
    g_star: Megapascal,
    kappa: f64,
    friction: f64,
    options: ElasticImpactOptions,
}

/// The outcome of an elastic oblique impact (plain data).
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct ElasticRebound {
    /// Normal rebound speed of the centre, away from the flat \[mm/s\] (= $V$ up to the
    /// integration error: the model is elastic).
    pub normal_velocity: MillimetrePerSecond,
    /// $u_2$, tangential velocity of the centre after the impact \[mm/s\].
    pub tangential_velocity: MillimetrePerSecond,
    /// $\omega_2$ \[rad/s\], sign convention of [`crate::impact`].
    pub angular_velocity: f64,
    /// $w_2 = u_2 + \omega_2R$, peripheral velocity after the impact \[mm/s\].
    pub peripheral_velocity: MillimetrePerSecond,
    /// $\psi_1 = \kappa w_1/(\mu V)$ \[-\].
    pub psi1: f64,
    /// $\psi_2 = \kappa w_2/(\mu V)$ \[-\].
    pub psi2: f64,
    /// Duration of contact \[s\] (numerical).
    pub contact_duration: Second,
    /// Largest normal force \[N\] (numerical).
    pub max_force: Newton,
    /// Largest approach $\delta$ \[mm\] (numerical).
    pub max_approach: Millimetre,
    /// Largest magnitude of the tangential force \[N\].
    pub max_tangential_force: Newton,
    /// $\int P\,dt$, normal impulse \[N·s\].
    pub normal_impulse: f64,
    /// Friction impulse on the sphere along $+x$ \[N·s\].
    pub friction_impulse: f64,
    /// Kinetic energy lost to friction \[N·mm\] (≥ 0 up to the integration error).
    pub energy_loss: NewtonMillimetre,
    /// `true` when every part of the contact slid at every step (gross sliding throughout,
    /// the regime of the rigid sliding result).
    pub slid_throughout: bool,
    /// Time steps taken.
    pub steps: usize,
}

impl ElasticObliqueImpact {
    /// Plan an elastic oblique impact.
    ///
    /// # Arguments
    /// - `body` — the sphere ([`SphereBody`]); its radius is the Hertz radius $R$.
    /// - `sphere_material`, `flat_material` — the two materials (at most one rigid).
    /// - `friction_coefficient` — $\mu$ \[-\], finite, > 0.
    /// - `options` — resolution ([`ElasticImpactOptions::default`] for 4000 steps, 400
    ///   cells).
    ///
    /// # Errors
    /// [`Error::InvalidInput`] naming `friction_coefficient`, `materials` (two rigid
    /// bodies), `steps` or `cells`.
    pub fn new(
        body: SphereBody,
        sphere_material: ElasticMaterial,
        flat_material: ElasticMaterial,
        friction_coefficient: f64,
        options: ElasticImpactOptions,
    ) -> Result<Self> {
        let friction = check_friction(friction_coefficient)?;
        options.validate()?;
        let kappa = stiffness_ratio(&sphere_material, &flat_material)?;
        Ok(ElasticObliqueImpact {
            body,
            e_star: effective_modulus(&sphere_material, &flat_material),
            g_star: effective_shear_modulus(&sphere_material, &flat_material),
            kappa,
            friction,
            options,
        })
    }

    /// The sphere.
    pub fn body(&self) -> &SphereBody {
        &self.body
    }

    /// $\kappa = 4G^*/E^*$ \[-\].
    pub fn kappa(&self) -> f64 {
        self.kappa
    }

    /// $\chi = \tfrac\kappa2(1 + R^2/k^2)$ \[-\].
    pub fn chi(&self) -> f64 {
        self.body.chi(self.kappa)
    }

    /// $E^*$ \[MPa\].
    pub fn e_star(&self) -> Megapascal {
        self.e_star
    }

    /// $G^*$ \[MPa\] ($1/G^* = \sum(2-\nu_i)/G_i$).
    pub fn g_star(&self) -> Megapascal {
        self.g_star
    }

    /// $\mu$ \[-\].
    pub fn friction_coefficient(&self) -> f64 {
        self.friction
    }

    /// Integrate the impact with incident motion `incident`.
    ///
    /// # Returns
    /// [`ElasticRebound`]: rebound velocities, $\psi_1$, $\psi_2$, duration, peak forces,
    /// impulses, energy lost.
    ///
    /// # Errors
    /// [`Error::InvalidInput`] naming `incident` when the inputs overflow or underflow f64;
    /// [`Error::NotConverged`] if the contact has not ended after twice the Hertz duration
    /// (not expected).
    pub fn rebound(&self, incident: &IncidentMotion) -> Result<ElasticRebound> {
        let b = &self.body;
        let v = incident.normal_speed();
        let w1 = incident.peripheral_velocity(b.radius());
        let core = Core {
            mass: b.mass(),
            tangential_mass: b.effective_tangential_mass(),
            radius: b.radius(),
            e_star: self.e_star,
            g_star: self.g_star,
            mu: self.friction,
            v,
            w1,
        };
        let out = integrate(&core, &self.options).map_err(|e| match e {
            Error::InvalidInput { .. } => Error::invalid(
                "incident",
                format!("V = {v}, w1 = {w1}"),
                "an impact whose Hertz scales are finite, non-zero f64 values",
            ),
            other => other,
        })?;
        let (u1, om1) = (incident.tangential_velocity(), incident.angular_velocity());
        let u2 = u1 + out.friction_impulse / b.mass();
        let om2 = om1 + out.friction_impulse * b.radius() / b.inertia();
        let ke1 = b.kinetic_energy(v, u1, om1);
        let ke2 = b.kinetic_energy(out.normal_velocity, u2, om2);
        let scale = self.kappa / (self.friction * v);
        let values = [u2, om2, ke1 - ke2, scale * w1, scale * out.w2];
        if !values.iter().all(|x| x.is_finite()) {
            return Err(Error::invalid(
                "incident",
                format!("V = {v}, w1 = {w1} (mu = {})", self.friction),
                "an impact whose rebound, energy and psi values are finite f64 values",
            ));
        }
        Ok(ElasticRebound {
            normal_velocity: out.normal_velocity,
            tangential_velocity: u2,
            angular_velocity: om2,
            peripheral_velocity: out.w2,
            psi1: scale * w1,
            psi2: scale * out.w2,
            contact_duration: out.duration,
            max_force: out.max_force,
            max_approach: out.max_approach,
            max_tangential_force: out.max_tangential_force,
            normal_impulse: out.normal_impulse,
            friction_impulse: out.friction_impulse,
            energy_loss: ke1 - ke2,
            slid_throughout: out.slid_throughout,
            steps: out.steps,
        })
    }
}

/// The rebound $\psi_2$ of the elastic analysis in the non-dimensional form of Maw, Barber
/// and Fawcett, for an incidence $\psi_1$ and a body parameter $\chi$ (see
/// [`crate::impact`]). The result depends on these two numbers only.
///
/// # Arguments
/// - `psi1` — $\psi_1 = \kappa w_1/(\mu V)$ \[-\], finite, $|\psi_1| \le 10^6$.
/// - `chi` — $\chi = \tfrac\kappa2(1 + R^2/k^2)$ \[-\], in $(0, 10^6]$ (1.441 for a solid
///   sphere with $\nu = 0.3$).
/// - `options` — resolution.
///
/// # Errors
/// [`Error::InvalidInput`] naming `psi1`, `chi`, `steps` or `cells`.
///
/// # Example
/// ```
/// use kontakt::impact::{ElasticImpactOptions, elastic::elastic_rebound_psi};
/// let chi = 0.7 / 1.7 * 3.5;
/// let o = ElasticImpactOptions::default();
/// // gross sliding throughout: the rigid result psi2 = psi1 - 4 chi
/// assert!((elastic_rebound_psi(8.0, chi, o)? - (8.0 - 4.0 * chi)).abs() < 1e-4);
/// // below the sliding threshold: negative rebound (superball)
/// assert!(elastic_rebound_psi(2.0, chi, o)? < -0.8);
/// # Ok::<(), kontakt::Error>(())
/// ```
pub fn elastic_rebound_psi(psi1: f64, chi: f64, options: ElasticImpactOptions) -> Result<f64> {
    if !(psi1.is_finite() && psi1.abs() <= 1e6) {
        return Err(Error::invalid(
            "psi1",
            psi1,
            "a finite number, |psi1| <= 1e6",
        ));
    }
    if !(chi.is_finite() && chi > 0.0 && chi <= 1e6) {
        return Err(Error::invalid("chi", chi, "0 < chi <= 1e6"));
    }
    options.validate()?;
    // Unit problem: m = R = V = mu = E* = 1, G* = 1/4 (kappa = 1), m_t = 1/(2 chi),
    // so that psi = w.
    let core = Core {
        mass: 1.0,
        tangential_mass: 0.5 / chi,
        radius: 1.0,
        e_star: 1.0,
        g_star: 0.25,
        mu: 1.0,
        v: 1.0,
        w1: psi1,
    };
    Ok(integrate(&core, &options)?.w2)
}

/// Inputs of the dimensional integration.
struct Core {
    mass: f64,
    tangential_mass: f64,
    radius: f64,
    e_star: f64,
    g_star: f64,
    mu: f64,
    v: f64,
    w1: f64,
}

/// Results of the dimensional integration.
struct CoreOut {
    normal_velocity: f64,
    w2: f64,
    duration: f64,
    max_force: f64,
    max_approach: f64,
    max_tangential_force: f64,
    normal_impulse: f64,
    friction_impulse: f64,
    slid_throughout: bool,
    steps: usize,
}

/// The cells of the spring line: covered length and tangential force of each.
struct Cells {
    dx: f64,
    covered: Vec<f64>,
    force: Vec<f64>,
    /// One past the last cell that may be in contact.
    active: usize,
    /// The approach of the previous update \[mm\].
    delta: f64,
}

impl Cells {
    /// Move the cells to approach `delta` and tangential displacement increment `ds`;
    /// returns the tangential force on the whole contact (both halves) and whether every
    /// cell in contact slid.
    fn update(&mut self, c: &Core, delta: f64, ds: f64) -> Result<(f64, bool)> {
        let n = self.covered.len();
        let a = if delta > 0.0 {
            (c.radius * delta).sqrt()
        } else {
            0.0
        };
        let reach = ((a / self.dx).ceil() as usize).min(n);
        if a > self.dx * n as f64 {
            return Err(Error::NotConverged {
                what: "elastic oblique impact (the contact outgrew the cell line)".into(),
                iterations: 0,
                residual: a / (self.dx * n as f64),
            });
        }
        let upto = self.active.max(reach);
        let kt = 4.0 * c.g_star;
        let inv3r = 1.0 / (3.0 * c.radius);
        let mut q_sum = 0.0;
        let mut all_slide = true;
        for i in 0..upto {
            let x0 = i as f64 * self.dx;
            let (cov, f) = if x0 < a {
                let x1 = (x0 + self.dx).min(a);
                let f = c.e_star * (delta * (x1 - x0) - (x1 * x1 * x1 - x0 * x0 * x0) * inv3r);
                (x1 - x0, f.max(0.0))
            } else {
                (0.0, 0.0)
            };
            let old = self.covered[i];
            let mut q = self.force[i];
            if cov < old {
                // The uncovered part leaves with its share of the force, taken in
                // proportion to the normal force it carried at the previous approach
                // (exact for a sliding cell, whose traction is mu times the pressure).
                let g = |x1: f64| self.delta * (x1 - x0) - (x1 * x1 * x1 - x0 * x0 * x0) * inv3r;
                let (kept, had) = (g(x0 + cov), g(x0 + old));
                let ratio = if had > 0.0 {
                    (kept / had).clamp(0.0, 1.0)
                } else {
                    cov / old
                };
                q *= ratio;
            }
            if cov > 0.0 {
                q += kt * cov * ds;
                let limit = c.mu * f;
                if q.abs() >= limit {
                    q = limit.copysign(q);
                } else {
                    all_slide = false;
                }
            } else {
                q = 0.0;
            }
            self.covered[i] = cov;
            self.force[i] = q;
            q_sum += q;
        }
        self.active = reach;
        self.delta = delta;
        Ok((2.0 * q_sum, all_slide))
    }
}

/// Velocity-Verlet integration of the coupled normal and tangential impact (module docs).
fn integrate(c: &Core, options: &ElasticImpactOptions) -> Result<CoreOut> {
    let k = 4.0 / 3.0 * c.e_star * c.radius.sqrt();
    let delta_star = (1.25 * c.mass / k).powf(0.4) * c.v.powf(0.8);
    let duration_est = HERTZ_IMPACT_DURATION_CONSTANT * delta_star / c.v;
    let a_star = (c.radius * delta_star).sqrt();
    let h = duration_est / options.steps as f64;
    let force_star = k * delta_star * delta_star.sqrt();
    let scales_ok = [
        k,
        delta_star,
        duration_est,
        a_star,
        h,
        c.w1 * h,
        c.tangential_mass,
        force_star,
        force_star * duration_est / c.tangential_mass,
        c.mass * c.v * c.v,
    ]
    .iter()
    .all(|x| x.is_finite())
        && delta_star > 0.0
        && h > 0.0
        && a_star > 0.0;
    if !scales_ok {
        return Err(Error::invalid(
            "incident",
            c.v,
            "an impact whose Hertz scales are finite, non-zero f64 values",
        ));
    }
    let cells = options.cells;
    let mut line = Cells {
        dx: 1.1 * a_star / cells as f64,
        covered: vec![0.0; cells],
        force: vec![0.0; cells],
        active: 0,
        delta: 0.0,
    };
    let (m, mt) = (c.mass, c.tangential_mass);
    let (mut delta, mut vd, mut w) = (0.0_f64, c.v, c.w1);
    let (mut p, mut q) = (0.0_f64, 0.0_f64);
    let (mut jn, mut jt) = (0.0_f64, 0.0_f64);
    let (mut max_p, mut max_q, mut max_d) = (0.0_f64, 0.0_f64, 0.0_f64);
    let mut slid_throughout = true;
    let max_steps = 2 * options.steps + 16;
    for n in 0..max_steps {
        let vd_half = vd - 0.5 * h * p / m;
        let w_half = w - 0.5 * h * q / mt;
        let new_delta = delta + h * vd_half;
        let (new_q, all_slide) = line.update(c, new_delta, h * w_half)?;
        let new_p = if new_delta > 0.0 {
            k * new_delta * new_delta.sqrt()
        } else {
            0.0
        };
        vd = vd_half - 0.5 * h * new_p / m;
        w = w_half - 0.5 * h * new_q / mt;
        jn += 0.5 * h * (p + new_p);
        jt -= 0.5 * h * (q + new_q);
        if new_delta > 0.0 {
            slid_throughout &= all_slide;
        }
        max_p = max_p.max(new_p);
        max_q = max_q.max(new_q.abs());
        max_d = max_d.max(new_delta);
        if new_delta <= 0.0 {
            // Linear interpolation of the instant at which delta returns to zero.
            let frac = delta / (delta - new_delta);
            let finite = [vd, w, jn, jt, max_p, max_q, frac]
                .iter()
                .all(|x| x.is_finite());
            if !finite {
                return Err(Error::invalid(
                    "incident",
                    c.v,
                    "an impact whose forces and velocities stay finite f64 values",
                ));
            }
            return Ok(CoreOut {
                normal_velocity: -vd,
                w2: w,
                duration: h * (n as f64 + frac),
                max_force: max_p,
                max_approach: max_d,
                max_tangential_force: max_q,
                normal_impulse: jn,
                friction_impulse: jt,
                slid_throughout,
                steps: n + 1,
            });
        }
        delta = new_delta;
        p = new_p;
        q = new_q;
    }
    Err(Error::NotConverged {
        what: "elastic oblique impact (contact did not end within twice the Hertz duration)".into(),
        iterations: max_steps,
        residual: delta / delta_star,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    fn unit_core(mu: f64) -> Core {
        Core {
            mass: 1.0,
            tangential_mass: 0.3,
            radius: 2.0,
            e_star: 3.0,
            g_star: 0.7,
            mu,
            v: 1.0,
            w1: 0.0,
        }
    }

    /// The cells' normal forces are exact integrals: when every cell slides, the tangential
    /// force is mu times the Hertz load 4/3 E* sqrt(R) delta^1.5 to rounding, for a
    /// contact edge anywhere in a cell, growing and shrinking.
    #[test]
    fn sliding_cells_carry_mu_times_the_hertz_load() {
        let c = unit_core(0.4);
        let mut line = Cells {
            dx: 0.013,
            covered: vec![0.0; 200],
            force: vec![0.0; 200],
            active: 0,
            delta: 0.0,
        };
        let k = 4.0 / 3.0 * c.e_star * c.radius.sqrt();
        for delta in [1e-4, 3e-3, 0.01, 0.02, 0.015, 0.004, 2e-5] {
            let (q, all) = line.update(&c, delta, 1e3).expect("fits");
            let p = k * delta * f64::sqrt(delta);
            assert!(all);
            assert!(
                (q / (c.mu * p) - 1.0).abs() < 1e-12,
                "{delta}: {q} vs {}",
                c.mu * p
            );
        }
        // out of contact: no force anywhere
        let (q, _) = line.update(&c, -1e-6, 1.0).expect("fits");
        assert_eq!(q, 0.0);
        assert!(line.force.iter().all(|f| *f == 0.0));
    }

    /// A contact that outgrows the cell line is reported, not truncated.
    #[test]
    fn outgrown_line_is_an_error() {
        let c = unit_core(0.4);
        let mut line = Cells {
            dx: 0.001,
            covered: vec![0.0; 10],
            force: vec![0.0; 10],
            active: 0,
            delta: 0.0,
        };
        assert!(matches!(
            line.update(&c, 1.0, 0.0),
            Err(Error::NotConverged { .. })
        ));
    }

    /// Absurdly small friction makes psi overflow: an error, not inf.
    #[test]
    fn overflowing_psi_is_an_error() {
        let s = ElasticMaterial::STEEL;
        let ball = SphereBody::solid_sphere(5.0, 4.1e-6).expect("ball");
        let imp = ElasticObliqueImpact::new(ball, s, s, 1e-310, ElasticImpactOptions::default())
            .expect("impact");
        let inc = IncidentMotion::new(1000.0, 100.0, 0.0).expect("motion");
        assert!(imp.rebound(&inc).is_err());
    }
}
