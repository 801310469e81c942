//! Rigid-body oblique impact with Coulomb friction of a sphere on a massive flat
//! (Johnson 1982 eqs 39-40 and Appendix 3, eqs 64-70, generalised to a restitution
//! coefficient $e$ and any radius of gyration $k$).
//!
//! # Formulas
//! Frame and signs as in [`crate::impact`]: normal approach speed $V$, tangential velocity
//! $u$, angular velocity $\omega$ (positive when it moves the contact point along $+x$),
//! peripheral velocity $w = u + \omega R$, $m_t = m/(1 + R^2/k^2)$.
//! The normal impulse is $\hat P = m(1+e)V$ (the normal rebound speed is $eV$). A friction
//! impulse $\hat Q$ opposing $w_1$ changes the peripheral velocity by
//! $\hat Q/m_t$; it cannot exceed $\mu\hat P$. Hence, with the **critical peripheral
//! velocity**
//!
//! $$w_c = \mu(1+e)V\Big(1 + \frac{R^2}{k^2}\Big)\qquad(= 7\mu V \text{ for a solid
//!   sphere with } e = 1),$$
//!
//! - **gross sliding** throughout the impact when $|w_1| \ge w_c$ (Johnson's eq. 40b / 69):
//!   $\hat Q = \mu\hat P$, $\;w_2 = w_1 - \operatorname{sgn}(w_1)\,w_c$;
//! - **sliding, then rolling** when $|w_1| < w_c$: sliding stops during the impact and the
//!   contact point leaves at rest (eq. 40a / 70): $w_2 = 0$, $\hat Q = m_t|w_1|$.
//!
//! In both, $u_2 = u_1 + J/m$ and $\omega_2 = \omega_1 + JR/I$ with the friction impulse
//! on the sphere along $+x$, $J = -\operatorname{sgn}(w_1)\hat Q$. The two regimes meet
//! continuously at $|w_1| = w_c$. The angular momentum about the contact point,
//! $I\omega - muR$, is conserved (eq. 67); the kinetic energy lost is
//! $\tfrac12 m(1-e^2)V^2 + \tfrac12 m_t(w_1^2 - w_2^2)$.
//!
//! Non-dimensionally ([`crate::impact`], $\psi = \kappa w/(\mu V)$): $\psi_2 = \psi_1 -
//! \operatorname{sgn}(\psi_1)\,2\chi(1+e)$ for $|\psi_1| \ge 2\chi(1+e)$, else 0
//! ([`rigid_rebound_psi`]).
//!
//! # Assumptions
//! Rigid bodies meeting at one point, impulsive forces only (gravity and the duration of
//! the impact ignored), Coulomb friction with one coefficient for sliding and for the
//! onset of sticking (once the contact point stops it stays at rest: the static
//! friction needed is zero), Newton/Poisson restitution on the normal impulse (the
//! normal impulse passes through the centre, so the two coincide). The flat does not move.
//!
//! # References
//! - Johnson (1982), "One hundred years of Hertz contact", Proc. IMechE 196, eqs (39),
//!   (40a,b), (64)-(70).
//! - Johnson, *Contact Mechanics* (1985), §11.4.

use super::{IncidentMotion, SphereBody, check_friction};
use crate::error::{Error, Result};
use crate::units::{MillimetrePerSecond, NewtonMillimetre};

/// Which of the two rigid-body regimes an impact falls in.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub enum RigidRegime {
    /// $|w_1| \ge w_c$: the contact point slides throughout, $\hat Q = \mu\hat P$.
    GrossSliding,
    /// $|w_1| < w_c$: sliding stops during the impact, the sphere leaves rolling ($w_2 = 0$).
    SlidingThenRolling,
}

/// Rigid-body oblique impact of a sphere on a flat with Coulomb friction and a normal
/// coefficient of restitution (see the module docs).
///
/// # Example
/// A solid sphere without spin, incident at 30° to the normal, mu = 0.3, e = 1: the contact
/// point stops ($w_1 = 0.5v < 7\mu V = 1.82v$) and the sphere leaves rolling with
/// $u_2 = \tfrac57 u_1$.
/// ```
/// use kontakt::impact::{IncidentMotion, RigidObliqueImpact, RigidRegime, SphereBody};
/// let ball = SphereBody::solid_sphere(10.0, 3.3e-5)?;
/// let impact = RigidObliqueImpact::new(ball, 0.3, 1.0)?;
/// let inc = IncidentMotion::from_angle(1000.0, 30f64.to_radians(), 0.0)?;
/// let r = impact.rebound(&inc)?;
/// assert_eq!(r.regime, RigidRegime::SlidingThenRolling);
/// assert!((r.tangential_velocity - 5.0 / 7.0 * 500.0).abs() < 1e-9);   // mm/s
/// assert!((r.angular_velocity + r.tangential_velocity / 10.0).abs() < 1e-9); // rolling
/// # Ok::<(), kontakt::Error>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct RigidObliqueImpact {
    body: SphereBody,
    friction: f64,
    restitution: f64,
}

/// The outcome of a rigid-body oblique impact (plain data).
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct RigidRebound {
    /// Normal rebound speed of the centre, away from the flat, $eV$ \[mm/s\].
    pub normal_velocity: MillimetrePerSecond,
    /// $u_2$, tangential velocity of the centre after the impact \[mm/s\].
    pub tangential_velocity: MillimetrePerSecond,
    /// $\omega_2$ \[rad/s\], sign convention of [`crate::impact`].
    pub angular_velocity: f64,
    /// $w_2 = u_2 + \omega_2 R$, peripheral velocity after the impact \[mm/s\].
    pub peripheral_velocity: MillimetrePerSecond,
    /// $\hat P = m(1+e)V$, normal impulse on the sphere \[N·s\].
    pub normal_impulse: f64,
    /// $J$, friction impulse on the sphere along $+x$ \[N·s\] ($|J| \le \mu\hat P$).
    pub friction_impulse: f64,
    /// Kinetic energy lost (normal restitution and friction) \[N·mm\], ≥ 0.
    pub energy_loss: NewtonMillimetre,
    /// The regime.
    pub regime: RigidRegime,
}

impl RigidObliqueImpact {
    /// Plan a rigid-body impact.
    ///
    /// # Arguments
    /// - `body` — the sphere ([`SphereBody`]).
    /// - `friction_coefficient` — $\mu$ \[-\], finite, > 0.
    /// - `restitution` — normal coefficient of restitution $e$ \[-\], in \[0, 1\].
    ///
    /// # Errors
    /// [`Error::InvalidInput`] naming `friction_coefficient` or `restitution`.
    pub fn new(body: SphereBody, friction_coefficient: f64, restitution: f64) -> Result<Self> {
        let friction = check_friction(friction_coefficient)?;
        if !(0.0..=1.0).contains(&restitution) {
            return Err(Error::invalid(
                "restitution",
                restitution,
                "a coefficient of restitution 0 <= e <= 1",
            ));
        }
        Ok(RigidObliqueImpact {
            body,
            friction,
            restitution,
        })
    }

    /// The sphere.
    pub fn body(&self) -> &SphereBody {
        &self.body
    }

    /// $\mu$ \[-\].
    pub fn friction_coefficient(&self) -> f64 {
        self.friction
    }

    /// $e$ \[-\].
    pub fn restitution(&self) -> f64 {
        self.restitution
    }

    /// $w_c = \mu(1+e)V(1 + R^2/k^2)$ \[mm/s\]: the smallest $|w_1|$ for which the contact
    /// slides throughout an impact at normal speed `normal_speed` \[mm/s\] (any finite
    /// value; its magnitude is used).
    pub fn critical_peripheral_velocity(
        &self,
        normal_speed: MillimetrePerSecond,
    ) -> MillimetrePerSecond {
        let b = &self.body;
        self.friction * (1.0 + self.restitution) * normal_speed.abs() * b.mass
            / b.effective_tangential_mass()
    }

    /// The rebound after an impact with incident motion `incident`.
    ///
    /// # Returns
    /// [`RigidRebound`]: rebound velocities, impulses, energy loss and regime.
    ///
    /// # Errors
    /// [`Error::InvalidInput`] naming `incident` if a result overflows f64.
    pub fn rebound(&self, incident: &IncidentMotion) -> Result<RigidRebound> {
        let b = &self.body;
        let (m, mt, r) = (b.mass(), b.effective_tangential_mass(), b.radius());
        let v = incident.normal_speed();
        let (u1, om1) = (incident.tangential_velocity(), incident.angular_velocity());
        let w1 = incident.peripheral_velocity(r);
        let normal_impulse = m * (1.0 + self.restitution) * v;
        let wc = self.critical_peripheral_velocity(v);
        let (regime, q_hat) = if w1.abs() >= wc {
            (RigidRegime::GrossSliding, self.friction * normal_impulse)
        } else {
            (RigidRegime::SlidingThenRolling, mt * w1.abs())
        };
        let j = -w1.signum() * q_hat;
        let j = if w1 == 0.0 { 0.0 } else { j };
        let u2 = u1 + j / m;
        let om2 = om1 + j * r / b.inertia();
        let w2 = match regime {
            RigidRegime::GrossSliding => w1 - w1.signum() * wc,
            RigidRegime::SlidingThenRolling => 0.0,
        };
        let normal_velocity = self.restitution * v;
        let energy_loss = 0.5 * m * (1.0 - self.restitution * self.restitution) * v * v
            + 0.5 * mt * (w1 * w1 - w2 * w2);
        let out = RigidRebound {
            normal_velocity,
            tangential_velocity: u2,
            angular_velocity: om2,
            peripheral_velocity: w2,
            normal_impulse,
            friction_impulse: j,
            energy_loss,
            regime,
        };
        let all_finite = [u2, om2, w2, normal_impulse, j, energy_loss]
            .iter()
            .all(|x| x.is_finite());
        if all_finite {
            Ok(out)
        } else {
            Err(Error::invalid(
                "incident",
                format!("V = {v}, u = {u1}, omega = {om1}"),
                "velocities for which the rebound is a finite f64",
            ))
        }
    }
}

/// The rigid-body rebound in the non-dimensional form of Maw, Barber and Fawcett:
///
/// $$\psi_2 = \psi_1 - \operatorname{sgn}(\psi_1)\,2\chi(1+e)\quad
///   (|\psi_1| \ge 2\chi(1+e)),\qquad \psi_2 = 0\quad\text{otherwise}.$$
///
/// With $e = 1$: $\psi_2 = \psi_1 - 4\chi$ for $\psi_1 \ge 4\chi$.
///
/// # Arguments
/// - `psi1` — $\psi_1 = \kappa w_1/(\mu V)$ \[-\], finite.
/// - `chi` — $\chi = \tfrac\kappa2(1 + R^2/k^2)$ \[-\], finite, > 0.
/// - `restitution` — $e$ \[-\], in \[0, 1\].
///
/// # Errors
/// [`Error::InvalidInput`] naming the argument out of range.
///
/// # Example
/// ```
/// use kontakt::impact::rigid_rebound_psi;
/// let chi = 0.7 / 1.7 * 3.5;                      // solid sphere, nu = 0.3
/// assert!((rigid_rebound_psi(8.0, chi, 1.0)? - (8.0 - 4.0 * chi)).abs() < 1e-15);
/// assert_eq!(rigid_rebound_psi(2.0, chi, 1.0)?, 0.0);
/// # Ok::<(), kontakt::Error>(())
/// ```
pub fn rigid_rebound_psi(psi1: f64, chi: f64, restitution: f64) -> Result<f64> {
    if !psi1.is_finite() {
        return Err(Error::invalid("psi1", psi1, "a finite number"));
    }
    crate::error::positive_as("chi", chi, "a finite number > 0")?;
    if !(0.0..=1.0).contains(&restitution) {
        return Err(Error::invalid(
            "restitution",
            restitution,
            "a coefficient of restitution 0 <= e <= 1",
        ));
    }
    let c = 2.0 * chi * (1.0 + restitution);
    Ok(if psi1.abs() >= c {
        psi1 - psi1.signum() * c
    } else {
        0.0
    })
}
