//! Oblique impact with friction of a sphere (or any body with a spherical contact
//! surface) on a massive flat: the rigid-body theory ([`rigid`]) and the elastic analysis of
//! Maw, Barber and Fawcett with Hertz normal and Mindlin-Deresiewicz tangential compliance
//! ([`elastic`]). The normal, frictionless Hertz impact is [`crate::hertz::impact`].
//!
//! # Frame and signs
//! The flat is fixed; `z` is its outward normal (into the sphere), `x` lies in the plane of
//! motion. The sphere of radius $R$ (the radius of its contact surface), mass $m$ and radius
//! of gyration $k$ ($I = mk^2$ about a diameter; $k^2 = \tfrac25R^2$ for a solid sphere)
//! arrives with
//! - the **normal approach speed** $V$ \[mm/s\] > 0 (its centre moves towards the flat),
//! - the **tangential velocity** $u$ of its centre along $x$ \[mm/s\], any sign,
//! - the **angular velocity** $\omega$ \[rad/s\], positive for the spin that moves the
//!   contact point along $+x$ (Johnson's *back-spin positive* when $u > 0$; in a
//!   right-handed frame it is the rotation about $-y$).
//!
//! The **peripheral velocity** (tangential velocity of the sphere's material point at the
//! contact, relative to the flat, Johnson 1982 eq. 39 / 64) is
//!
//! $$w = u + \omega R .$$
//!
//! A tangential (friction) impulse $J$ on the sphere along $+x$ changes
//! $u$ by $J/m$, $\omega$ by $JR/I$ and so $w$ by $J(1 + R^2/k^2)/m = J/m_t$ with the
//! **effective tangential mass** $m_t = m/(1 + R^2/k^2)$ ($\tfrac27 m$ for a solid sphere);
//! the angular momentum about the contact point, $I\omega - muR$, is unchanged by any
//! impulse at the contact (Johnson 1982 eq. 67).
//!
//! # Non-dimensional form (Maw, Barber and Fawcett 1976)
//! With the ratio of the tangential to the normal contact stiffness of a Hertz contact,
//! $\kappa = k_x/k_z = 8G^*a / (2E^*a) = 4G^*/E^*$ (material constants of
//! [`crate::material`]; $\kappa = 2(1-\nu)/(2-\nu)$ for two bodies of one Poisson's ratio or
//! an elastic sphere on a rigid flat), the incident and rebound peripheral velocities are
//! measured by
//!
//! $$\psi_1 = \frac{\kappa\,w_1}{\mu V},\qquad \psi_2 = \frac{\kappa\,w_2}{\mu V},\qquad
//!   \chi = \frac{\kappa}{2}\Big(1 + \frac{R^2}{k^2}\Big)
//!   \;\Big(= \frac{1-\nu}{2-\nu}\Big(1 + \frac{mR^2}{I}\Big)\Big),$$
//!
//! ($V$ the incident normal speed), and the rebound depends on $\psi_1$ and $\chi$ alone.
//! For a solid sphere with $\nu = 0.3$, $\chi = 1.441$. See [`stiffness_ratio`] and
//! [`SphereBody::chi`].
//!
//! # References
//! - Johnson (1982), "One hundred years of Hertz contact", Proc. IMechE 196, 363-378, §7,
//!   eqs (39)-(40), Appendix 3 eqs (64)-(70), Fig. 11.
//! - Maw, Barber & Fawcett (1976), "The oblique impact of elastic spheres", Wear 38,
//!   101-114.
//! - Maw, Barber & Fawcett (1981), "The role of elastic tangential compliance in oblique
//!   impact", J. Lubr. Technol. 103, 74-80.
//! - Johnson, *Contact Mechanics* (1985), §11.4.
//!
//! Derivations and checks: `docs/impact.md`.

pub mod elastic;
pub mod rigid;

pub use elastic::{
    ElasticImpactOptions, ElasticObliqueImpact, ElasticRebound, elastic_rebound_psi,
};
pub use rigid::{RigidObliqueImpact, RigidRebound, RigidRegime, rigid_rebound_psi};

use crate::error::{Error, Result, positive_as};
use crate::material::{ElasticMaterial, effective_modulus, effective_shear_modulus};
use crate::units::{Millimetre, MillimetrePerSecond, NewtonMillimetre, Radian, Tonne};
use std::f64::consts::FRAC_PI_2;

/// $k^2/R^2$ of a solid (homogeneous) sphere, $\tfrac25$ \[-\].
pub const SOLID_SPHERE_GYRATION_RATIO_SQUARED: f64 = 0.4;

/// The impacting body: radius of its spherical contact surface, mass and radius of gyration
/// about a diameter (plain data, validated).
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct SphereBody {
    radius: Millimetre,
    mass: Tonne,
    radius_of_gyration: Millimetre,
}

impl SphereBody {
    /// A body with a spherical contact surface.
    ///
    /// # Arguments
    /// - `radius` — $R$, radius of the contact surface about the centre of mass \[mm\],
    ///   finite, > 0.
    /// - `mass` — $m$ \[t\], finite, > 0.
    /// - `radius_of_gyration` — $k$, with $I = mk^2$ about the axis of spin \[mm\],
    ///   finite, > 0 ($\sqrt{2/5}\,R$ for a solid sphere, $\sqrt{2/3}\,R$ for a thin
    ///   shell, $R/\sqrt2$ for a thin disc spinning in its plane).
    ///
    /// # Errors
    /// [`Error::InvalidInput`] naming the argument that is zero, negative or not finite.
    pub fn new(radius: Millimetre, mass: Tonne, radius_of_gyration: Millimetre) -> Result<Self> {
        positive_as("radius", radius, "a finite radius > 0 mm")?;
        positive_as("mass", mass, "a finite mass > 0 t")?;
        positive_as(
            "radius_of_gyration",
            radius_of_gyration,
            "a finite radius of gyration > 0 mm",
        )?;
        let body = SphereBody {
            radius,
            mass,
            radius_of_gyration,
        };
        let (mt, inertia) = (body.effective_tangential_mass(), body.inertia());
        if !(mt > 0.0 && mt.is_finite() && inertia > 0.0 && inertia.is_finite()) {
            return Err(Error::invalid(
                "radius_of_gyration",
                radius_of_gyration,
                "a value for which I = m k^2 and m / (1 + R^2/k^2) are finite and > 0 (no over- or underflow)",
            ));
        }
        Ok(body)
    }

    /// A solid homogeneous sphere, $k^2 = \tfrac25 R^2$.
    ///
    /// # Errors
    /// As [`SphereBody::new`].
    pub fn solid_sphere(radius: Millimetre, mass: Tonne) -> Result<Self> {
        positive_as("radius", radius, "a finite radius > 0 mm")?;
        Self::new(
            radius,
            mass,
            radius * SOLID_SPHERE_GYRATION_RATIO_SQUARED.sqrt(),
        )
    }

    /// $R$ \[mm\].
    pub fn radius(&self) -> Millimetre {
        self.radius
    }

    /// $m$ \[t\].
    pub fn mass(&self) -> Tonne {
        self.mass
    }

    /// $k$ \[mm\].
    pub fn radius_of_gyration(&self) -> Millimetre {
        self.radius_of_gyration
    }

    /// $I = mk^2$ \[t·mm²\].
    pub fn inertia(&self) -> f64 {
        self.mass * self.radius_of_gyration * self.radius_of_gyration
    }

    /// $m_t = m/(1 + R^2/k^2)$ \[t\], the mass that the peripheral velocity $w$ sees.
    pub fn effective_tangential_mass(&self) -> Tonne {
        let r = self.radius / self.radius_of_gyration;
        self.mass / (1.0 + r * r)
    }

    /// $\chi = \tfrac{\kappa}{2}(1 + R^2/k^2)$ \[-\] for a stiffness ratio `kappa`
    /// ([`stiffness_ratio`]).
    pub fn chi(&self, kappa: f64) -> f64 {
        let r = self.radius / self.radius_of_gyration;
        0.5 * kappa * (1.0 + r * r)
    }

    /// Kinetic energy of a motion \[N·mm\]:
    /// $\tfrac12 m(u^2 + v_n^2) + \tfrac12 I\omega^2$.
    pub fn kinetic_energy(
        &self,
        normal_velocity: MillimetrePerSecond,
        tangential_velocity: MillimetrePerSecond,
        angular_velocity: f64,
    ) -> NewtonMillimetre {
        0.5 * self.mass
            * (normal_velocity * normal_velocity + tangential_velocity * tangential_velocity)
            + 0.5 * self.inertia() * angular_velocity * angular_velocity
    }

    /// Angular momentum about the contact point, $I\omega - muR$ \[t·mm²/s\] (conserved
    /// through any impact on the flat; sign convention of the module docs).
    pub fn angular_momentum_about_contact(
        &self,
        tangential_velocity: MillimetrePerSecond,
        angular_velocity: f64,
    ) -> f64 {
        self.inertia() * angular_velocity - self.mass * tangential_velocity * self.radius
    }
}

/// The motion of the body at first contact (plain data, validated).
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct IncidentMotion {
    normal_speed: MillimetrePerSecond,
    tangential_velocity: MillimetrePerSecond,
    angular_velocity: f64,
}

impl IncidentMotion {
    /// The incident motion from its components.
    ///
    /// # Arguments
    /// - `normal_speed` — $V$, approach speed of the centre towards the flat \[mm/s\],
    ///   finite, > 0.
    /// - `tangential_velocity` — $u_1$ along $x$ \[mm/s\], finite (any sign).
    /// - `angular_velocity` — $\omega_1$ \[rad/s\], finite, positive when it moves the
    ///   contact point along $+x$ (module docs).
    ///
    /// # Errors
    /// [`Error::InvalidInput`] naming the argument: `normal_speed` zero, negative or not
    /// finite; the others not finite.
    pub fn new(
        normal_speed: MillimetrePerSecond,
        tangential_velocity: MillimetrePerSecond,
        angular_velocity: f64,
    ) -> Result<Self> {
        positive_as(
            "normal_speed",
            normal_speed,
            "a finite approach speed > 0 mm/s",
        )?;
        if !tangential_velocity.is_finite() {
            return Err(Error::invalid(
                "tangential_velocity",
                tangential_velocity,
                "a finite velocity in mm/s",
            ));
        }
        if !angular_velocity.is_finite() {
            return Err(Error::invalid(
                "angular_velocity",
                angular_velocity,
                "a finite angular velocity in rad/s",
            ));
        }
        Ok(IncidentMotion {
            normal_speed,
            tangential_velocity,
            angular_velocity,
        })
    }

    /// The incident motion from the speed of the centre and its angle of incidence.
    ///
    /// $V = v\cos\theta$, $u_1 = v\sin\theta$.
    ///
    /// # Arguments
    /// - `speed` — $v$ \[mm/s\], finite, > 0.
    /// - `incidence_angle` — $\theta$, from the normal of the flat \[rad\], in
    ///   $(-\pi/2, \pi/2)$ (0: normal impact; $\pm\pi/2$, grazing, has no normal
    ///   velocity and is rejected).
    /// - `angular_velocity` — $\omega_1$ \[rad/s\], finite.
    ///
    /// # Errors
    /// [`Error::InvalidInput`] naming `speed`, `incidence_angle` or `angular_velocity`.
    pub fn from_angle(
        speed: MillimetrePerSecond,
        incidence_angle: Radian,
        angular_velocity: f64,
    ) -> Result<Self> {
        positive_as("speed", speed, "a finite speed > 0 mm/s")?;
        if !(incidence_angle.is_finite() && incidence_angle.abs() < FRAC_PI_2) {
            return Err(Error::invalid(
                "incidence_angle",
                incidence_angle,
                "-pi/2 < angle < pi/2 rad (from the normal of the flat)",
            ));
        }
        let normal_speed = speed * incidence_angle.cos();
        if !(normal_speed > 0.0) {
            return Err(Error::invalid(
                "incidence_angle",
                incidence_angle,
                "an angle whose cosine times the speed is > 0 (not grazing)",
            ));
        }
        Self::new(
            normal_speed,
            speed * incidence_angle.sin(),
            angular_velocity,
        )
    }

    /// $V$ \[mm/s\].
    pub fn normal_speed(&self) -> MillimetrePerSecond {
        self.normal_speed
    }

    /// $u_1$ \[mm/s\].
    pub fn tangential_velocity(&self) -> MillimetrePerSecond {
        self.tangential_velocity
    }

    /// $\omega_1$ \[rad/s\].
    pub fn angular_velocity(&self) -> f64 {
        self.angular_velocity
    }

    /// $w_1 = u_1 + \omega_1 R$ \[mm/s\] for a contact radius $R$.
    pub fn peripheral_velocity(&self, radius: Millimetre) -> MillimetrePerSecond {
        self.tangential_velocity + self.angular_velocity * radius
    }
}

/// The ratio of the no-slip tangential to the normal stiffness of a Hertz contact,
/// $\kappa = 4G^*/E^*$ \[-\], with $1/E^* = \sum(1-\nu_i^2)/E_i$ and
/// $1/G^* = \sum(2-\nu_i)/G_i$ ([`crate::material`]).
///
/// Equal to $2(1-\nu)/(2-\nu)$ for two bodies of one Poisson's ratio, or for an elastic
/// body on a rigid one.
///
/// # Errors
/// [`Error::InvalidInput`] naming `materials` when both bodies are rigid.
///
/// # Example
/// ```
/// use kontakt::{impact::stiffness_ratio, material::ElasticMaterial};
/// let s = ElasticMaterial::STEEL;
/// assert!((stiffness_ratio(&s, &s)? - 1.4 / 1.7).abs() < 1e-15);
/// assert!((stiffness_ratio(&s, &ElasticMaterial::RIGID)? - 1.4 / 1.7).abs() < 1e-15);
/// # Ok::<(), kontakt::Error>(())
/// ```
pub fn stiffness_ratio(body1: &ElasticMaterial, body2: &ElasticMaterial) -> Result<f64> {
    let e_star = effective_modulus(body1, body2);
    let g_star = effective_shear_modulus(body1, body2);
    let kappa = 4.0 * g_star / e_star;
    if !(e_star.is_finite() && g_star.is_finite() && kappa.is_finite() && kappa > 0.0) {
        return Err(Error::invalid(
            "materials",
            format!("E* = {e_star}, G* = {g_star}"),
            "at least one elastic body (finite E* and G*)",
        ));
    }
    Ok(kappa)
}

/// Check a friction coefficient: finite, > 0.
fn check_friction(mu: f64) -> Result<f64> {
    positive_as(
        "friction_coefficient",
        mu,
        "a finite friction coefficient mu > 0",
    )
}
