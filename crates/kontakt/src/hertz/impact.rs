//! Quasi-static Hertz impact: two elastic bodies that meet with a relative normal velocity
//! and rebound, with the static Hertz force law holding at every instant.
//!
//! # Formulas
//! For any Hertz contact the force–approach law is $F = k\,\delta^{3/2}$ (for two spheres
//! $k = \tfrac43 E^*\sqrt{R}$, Johnson 1982 eq. 15; an elliptical contact has its own $k$).
//! With the effective mass $m = m_1 m_2/(m_1+m_2)$ and the relative impact velocity $V$,
//! energy conservation $\tfrac12 m\dot\delta^2 + \tfrac25 k\delta^{5/2} = \tfrac12 m V^2$
//! gives
//!
//! $$\delta^* = \left(\frac{5 m V^2}{4 k}\right)^{2/5},\qquad
//!   F^* = k\,\delta^{*3/2},\qquad
//!   T = c\,\frac{\delta^*}{V},\qquad
//!   c = 2\int_0^1\frac{dx}{\sqrt{1-x^{5/2}}} = \frac45 B\!\left(\tfrac25,\tfrac12\right)
//!     = \frac{4\,\Gamma(2/5)\,\Gamma(1/2)}{5\,\Gamma(9/10)} = 2.943\,275\ldots$$
//!
//! (Johnson 1982 eq. 36 prints $T = 2.94\,\delta^*/V$). The history $\delta(t)$ inverts
//! $t(\delta) = (\delta^*/V)\,I(\delta/\delta^*)$ with
//! $I(x) = \int_0^x (1-s^{5/2})^{-1/2}\,ds = \tfrac25 B_{x^{5/2}}(\tfrac25, \tfrac12)$,
//! an incomplete Beta function evaluated by two rapidly convergent series (one about the
//! start of the impact, one about the instant of maximum compression), so that
//! $\delta(t)$ is accurate to a few ulp everywhere, including at the turning point.
//!
//! The derivations, the constants to 30 digits and the check of Johnson's eqs 37 and 38
//! are in `docs/impact_adhesion.md`.
//!
//! # Assumptions
//! Quasi-static: elastic waves are neglected, which needs $V \ll c_0$ and a contact time
//! long compared with the wave transit time through the bodies (Johnson 1982 §7). Each
//! body moves as a rigid body outside the contact zone; frictionless, perfectly elastic
//! (no yield): the **coefficient of restitution is exactly 1**
//! ([`COEFFICIENT_OF_RESTITUTION`]) and the motion is symmetric about $T/2$.
//!
//! # References
//! - Hertz (1882), J. reine angew. Math. 92, 156-171 (impact section).
//! - Johnson (1982), "One hundred years of Hertz contact", Proc. IMechE 196, 363-378,
//!   §7, eqs (15), (36)-(38). doi:10.1243/PIME_PROC_1982_196_039_02
//! - Johnson, *Contact Mechanics* (1985), ch. 11.
//! - DLMF §8.17 (incomplete Beta function), §5.12 (Beta function).

use crate::error::{Error, Result};
use crate::units::{
    Megapascal, Millimetre, MillimetrePerSecond, Newton, NewtonMillimetre, Second, Tonne,
    TonnePerCubicMillimetre,
};
use std::f64::consts::PI;

/// $c = 2\int_0^1 (1-x^{5/2})^{-1/2}\,dx = \tfrac45 B(\tfrac25,\tfrac12)
/// = 4\,\Gamma(\tfrac25)\Gamma(\tfrac12) / (5\,\Gamma(\tfrac9{10}))$ [-]: the contact
/// duration in units of $\delta^*/V$.
///
/// Value 2.943 275 184 324 704 657 381 787 300 08… computed with mpmath at 40 digits (Beta
/// function and, independently, adaptive quadrature of the integral); see
/// `docs/impact_adhesion.md`. Johnson (1982) eq. (36) prints 2.94.
pub const HERTZ_IMPACT_DURATION_CONSTANT: f64 = 2.943_275_184_324_704_7;

/// Coefficient of restitution of a quasi-static Hertz impact [-]: exactly 1, since the
/// model is perfectly elastic and ignores wave losses (see the module *Assumptions*).
pub const COEFFICIENT_OF_RESTITUTION: f64 = 1.0;

/// Default ratio $p_{0Y}/Y$ of the maximum Hertz pressure at first yield to the uniaxial
/// yield stress for a circular contact (von Mises, $\nu = 0.3$): 1.60. Johnson (1982) §3,
/// eq. (21a), $P_Y = 21R^2Y^3/E^{*2}$, is the same statement ($p_{0Y} = 1.596\,Y$). The
/// subsurface-stress module computes the ratio for other Poisson's ratios; pass
/// `ratio * Y` as `yield_pressure`.
pub const DEFAULT_YIELD_PRESSURE_RATIO: f64 = 1.60;

/// Johnson's (1982) coefficient in eq. (38), $\rho V_Y^2/Y = 85\,(Y/E^*)^4$, as printed.
/// The exact value for $p_{0Y} = 1.60\,Y$ is 25.5 (see [`yield_velocity_sphere_on_flat`]).
pub const JOHNSON_YIELD_VELOCITY_COEFFICIENT: f64 = 85.0;

/// Geometry of a spherical impact, kept to report the contact radius and pressure.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
struct SphereData {
    r_eff: Millimetre,
    e_star: Megapascal,
}

/// A planned quasi-static Hertz impact with force law $F = k\,\delta^{3/2}$.
///
/// Build it with [`HertzImpact::new`] (any Hertz contact, given its load coefficient $k$)
/// or [`HertzImpact::sphere`] (two spheres or a sphere on a flat). The peak values are
/// solved once in the constructor ([`result`](Self::result)); the history
/// ([`approach_at`](Self::approach_at), [`force_at`](Self::force_at),
/// [`approach_rate_at`](Self::approach_rate_at), [`time_at_approach`](Self::time_at_approach))
/// costs two short series and a few Newton steps per call.
///
/// # Example
/// A 12.7 mm steel ball (R = 6.35 mm) dropped onto a massive steel plate at 1 m/s:
/// ```
/// use kontakt::hertz::impact::{HertzImpact, sphere_mass};
/// use kontakt::material::{ElasticMaterial, effective_modulus};
/// let s = ElasticMaterial::STEEL;
/// let m = sphere_mass(6.35, 7.85e-9)?;                       // t
/// let imp = HertzImpact::sphere(6.35, effective_modulus(&s, &s), m, 1000.0)?;
/// let r = imp.result();
/// assert!((r.max_approach - 0.014910).abs() < 1e-6);       // mm
/// assert!((r.max_force - 705.83).abs() < 0.01);             // N
/// assert!((r.contact_duration - 43.885e-6).abs() < 1e-9);   // s
/// assert!((r.max_pressure.unwrap() - 3559.5).abs() < 0.1);  // MPa: above first yield
/// // symmetric in time, and back to zero at the end
/// let t = 0.3 * r.contact_duration;
/// let d1 = imp.approach_at(t)?;
/// let d2 = imp.approach_at(r.contact_duration - t)?;
/// assert!((d1 - d2).abs() <= 1e-15 * d1);
/// # Ok::<(), kontakt::Error>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct HertzImpact {
    load_coefficient: f64,
    effective_mass: Tonne,
    impact_velocity: MillimetrePerSecond,
    sphere: Option<SphereData>,
    result: ImpactResult,
}

/// Peak values of a quasi-static Hertz impact (plain data).
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct ImpactResult {
    /// $\delta^*$, maximum approach (compression) \[mm\].
    pub max_approach: Millimetre,
    /// $F^* = k\,\delta^{*3/2}$, maximum contact force \[N\].
    pub max_force: Newton,
    /// $T = c\,\delta^*/V$, duration of contact \[s\].
    pub contact_duration: Second,
    /// $T/2$, the instant of maximum approach \[s\].
    pub time_of_max_approach: Second,
    /// $\tfrac12 m V^2$, kinetic energy of the relative motion = elastic energy stored at
    /// maximum approach \[N·mm\].
    pub kinetic_energy: NewtonMillimetre,
    /// $a^* = \sqrt{R\,\delta^*}$, maximum contact radius \[mm\]; `Some` only for
    /// [`HertzImpact::sphere`] (for a general $k$ solve the contact at `max_force`).
    pub max_contact_radius: Option<Millimetre>,
    /// $p_0^* = 2E^*a^*/(\pi R)$, maximum Hertz pressure \[MPa\]; `Some` only for
    /// [`HertzImpact::sphere`].
    pub max_pressure: Option<Megapascal>,
}

impl HertzImpact {
    /// An impact with a general Hertz force law $F = k\,\delta^{3/2}$.
    ///
    /// $$\delta^* = \left(\frac{5mV^2}{4k}\right)^{2/5},\quad F^* = k\delta^{*3/2},\quad
    /// T = 2.943\,275\ldots\,\frac{\delta^*}{V}$$
    ///
    /// # Arguments
    /// - `load_coefficient` — $k$ \[N/mm^1.5\], finite, > 0 (spheres: $\tfrac43E^*\sqrt R$).
    /// - `effective_mass` — $m = m_1m_2/(m_1+m_2)$ \[t\], finite, > 0 (see [`effective_mass`]).
    /// - `impact_velocity` — $V$, relative normal approach velocity at first touch \[mm/s\],
    ///   finite, > 0.
    ///
    /// # Returns
    /// The planned impact; its peak values are in [`result`](Self::result).
    ///
    /// # Errors
    /// [`Error::InvalidInput`] naming the argument that is zero, negative, NaN or infinite;
    /// or naming `impact_velocity` when the combination makes $\delta^*$, $F^*$ or $T$
    /// overflow or underflow to zero.
    ///
    /// # Assumptions
    /// See the module docs: quasi-static, elastic, frictionless.
    ///
    /// # Example
    /// ```
    /// use kontakt::hertz::impact::{HertzImpact, HERTZ_IMPACT_DURATION_CONSTANT};
    /// let imp = HertzImpact::new(5.0e5, 1.0e-5, 500.0)?;   // k, m, V
    /// let r = imp.result();
    /// // delta* = (5 m V^2 / 4k)^(2/5) = (6.25e-6)^(0.4)
    /// assert!((r.max_approach - 6.25e-6_f64.powf(0.4)).abs() < 1e-15);
    /// assert!((r.contact_duration * 500.0 / r.max_approach - 2.943_275).abs() < 1e-6);
    /// assert!(HertzImpact::new(5.0e5, -1.0, 500.0).is_err());
    /// # Ok::<(), kontakt::Error>(())
    /// ```
    ///
    /// # References
    /// Johnson (1982), eqs (15), (36); Johnson (1985), ch. 11.
    pub fn new(
        load_coefficient: f64,
        effective_mass: Tonne,
        impact_velocity: MillimetrePerSecond,
    ) -> Result<Self> {
        Self::build(load_coefficient, effective_mass, impact_velocity, None)
    }

    /// An impact of two spheres, or a sphere on a flat, with $k = \tfrac43 E^*\sqrt{R}$.
    ///
    /// $$F = \tfrac43 E^* \sqrt{R}\,\delta^{3/2},\qquad a^* = \sqrt{R\delta^*},\qquad
    /// p_0^* = \frac{2E^*a^*}{\pi R}$$
    ///
    /// # Arguments
    /// - `r_eff` — $R$, effective radius $1/R = 1/R_1 + 1/R_2$ \[mm\], finite, > 0.
    /// - `e_star` — $E^*$, contact modulus \[MPa\], finite, > 0
    ///   (see [`crate::material::effective_modulus`]).
    /// - `effective_mass` — $m$ \[t\], finite, > 0.
    /// - `impact_velocity` — $V$ \[mm/s\], finite, > 0.
    ///
    /// # Returns
    /// The planned impact; [`ImpactResult::max_contact_radius`] and
    /// [`ImpactResult::max_pressure`] are `Some`.
    ///
    /// # Errors
    /// [`Error::InvalidInput`] naming the bad argument (zero, negative, NaN, infinite), or
    /// `impact_velocity` if a result would overflow or underflow.
    ///
    /// # Assumptions
    /// Hertz: contact radius ≪ R; quasi-static impact (module docs).
    ///
    /// # Example
    /// Two identical steel balls of radius 10 mm colliding head-on at 0.5 m/s:
    /// ```
    /// use kontakt::hertz::impact::{HertzImpact, effective_mass, sphere_mass};
    /// let m1 = sphere_mass(10.0, 7.85e-9)?;
    /// let imp = HertzImpact::sphere(5.0, 115_384.615, effective_mass(m1, m1)?, 500.0)?;
    /// let r = imp.result();
    /// assert!((r.max_force - 437.62).abs() < 0.01);                  // N
    /// assert!((r.contact_duration - 69.110e-6).abs() < 1e-9);        // s
    /// # Ok::<(), kontakt::Error>(())
    /// ```
    ///
    /// # References
    /// Johnson (1982), eqs (13)-(15), (36).
    pub fn sphere(
        r_eff: Millimetre,
        e_star: Megapascal,
        effective_mass: Tonne,
        impact_velocity: MillimetrePerSecond,
    ) -> Result<Self> {
        crate::error::positive_as("r_eff", r_eff, "a finite effective radius > 0 mm")?;
        crate::error::positive_as("e_star", e_star, "a finite contact modulus > 0 MPa")?;
        let k = 4.0 / 3.0 * e_star * r_eff.sqrt();
        if !(k.is_finite() && k > 0.0) {
            return Err(Error::invalid(
                "e_star",
                format!("{e_star} (with r_eff = {r_eff}: k = {k})"),
                "a value for which k = 4/3 E* sqrt(R) is finite and > 0",
            ));
        }
        Self::build(
            k,
            effective_mass,
            impact_velocity,
            Some(SphereData { r_eff, e_star }),
        )
    }

    fn build(k: f64, m: Tonne, v: MillimetrePerSecond, sphere: Option<SphereData>) -> Result<Self> {
        crate::error::positive_as("load_coefficient", k, "a finite number > 0 N/mm^1.5")?;
        crate::error::positive_as("effective_mass", m, "a finite mass > 0 t")?;
        crate::error::positive_as("impact_velocity", v, "a finite velocity > 0 mm/s")?;
        // Written to avoid v^2 under/overflow: delta* = (5m/4k)^(2/5) v^(4/5).
        let scale = (1.25 * m / k).powf(0.4);
        let max_approach = scale * v.powf(0.8);
        let max_force = k * max_approach * max_approach.sqrt();
        let contact_duration = HERTZ_IMPACT_DURATION_CONSTANT * scale * v.powf(-0.2);
        let kinetic_energy = 0.5 * m * v * v;
        let (max_contact_radius, max_pressure) = match sphere {
            Some(s) => {
                let a = (s.r_eff * max_approach).sqrt();
                (Some(a), Some(2.0 * s.e_star * a / (PI * s.r_eff)))
            }
            None => (None, None),
        };
        let all_ok = [max_approach, max_force, contact_duration]
            .iter()
            .chain(max_contact_radius.iter())
            .chain(max_pressure.iter())
            .all(|x| x.is_finite() && *x > 0.0);
        if !all_ok || !kinetic_energy.is_finite() {
            return Err(Error::invalid(
                "impact_velocity",
                format!("{v} (with load_coefficient = {k}, effective_mass = {m})"),
                "a combination for which max approach, force and duration are finite and > 0 \
                 (these inputs overflow or underflow f64)",
            ));
        }
        Ok(HertzImpact {
            load_coefficient: k,
            effective_mass: m,
            impact_velocity: v,
            sphere,
            result: ImpactResult {
                max_approach,
                max_force,
                contact_duration,
                time_of_max_approach: 0.5 * contact_duration,
                kinetic_energy,
                max_contact_radius,
                max_pressure,
            },
        })
    }

    /// The load coefficient $k$ \[N/mm^1.5\] of $F = k\delta^{3/2}$.
    pub fn load_coefficient(&self) -> f64 {
        self.load_coefficient
    }

    /// The effective mass $m$ \[t\].
    pub fn effective_mass(&self) -> Tonne {
        self.effective_mass
    }

    /// The impact velocity $V$ \[mm/s\].
    pub fn impact_velocity(&self) -> MillimetrePerSecond {
        self.impact_velocity
    }

    /// The rebound velocity \[mm/s\]: $e\,V = V$ (perfectly elastic,
    /// [`COEFFICIENT_OF_RESTITUTION`] = 1).
    pub fn rebound_velocity(&self) -> MillimetrePerSecond {
        COEFFICIENT_OF_RESTITUTION * self.impact_velocity
    }

    /// Peak values: maximum approach, force, contact radius and pressure (spheres), contact
    /// duration (see [`ImpactResult`]).
    pub fn result(&self) -> ImpactResult {
        self.result
    }

    /// Approach $\delta(t)$ \[mm\] at time `time` after first contact.
    ///
    /// $$t = \frac{\delta^*}{V}\,I\!\left(\frac{\delta}{\delta^*}\right),\qquad
    /// I(x) = \int_0^x\frac{ds}{\sqrt{1-s^{5/2}}},\qquad \delta(T-t) = \delta(t)$$
    ///
    /// inverted by safeguarded Newton iteration on series for the incomplete Beta function;
    /// relative error a few ulp (tested against an independent ODE integration to 1e-10).
    ///
    /// # Arguments
    /// - `time` — $t$ \[s\], $0 \le t \le T$ (= [`ImpactResult::contact_duration`]).
    ///
    /// # Returns
    /// $\delta(t)$ \[mm\], $0 \le \delta \le \delta^*$; zero at $t = 0$ and $t = T$.
    ///
    /// # Errors
    /// [`Error::InvalidInput`] naming `time` outside $[0, T]$ or not finite.
    ///
    /// # Example
    /// ```
    /// use kontakt::hertz::impact::HertzImpact;
    /// let imp = HertzImpact::new(1.0e6, 2.0e-5, 800.0)?;
    /// let r = imp.result();
    /// assert_eq!(imp.approach_at(r.time_of_max_approach)?, r.max_approach);
    /// assert_eq!(imp.approach_at(0.0)?, 0.0);
    /// assert!(imp.approach_at(1.01 * r.contact_duration).is_err());
    /// # Ok::<(), kontakt::Error>(())
    /// ```
    ///
    /// # References
    /// Johnson (1982) §7; DLMF §8.17 (series of the incomplete Beta function).
    pub fn approach_at(&self, time: Second) -> Result<Millimetre> {
        let state = self.state_at(time)?;
        Ok(self.result.max_approach * state.x)
    }

    /// Contact force $F(t) = k\,\delta(t)^{3/2}$ \[N\] at time `time`.
    ///
    /// # Arguments
    /// - `time` — $t$ \[s\], $0 \le t \le T$.
    ///
    /// # Errors
    /// [`Error::InvalidInput`] naming `time` outside $[0, T]$ or not finite.
    ///
    /// # Example
    /// ```
    /// use kontakt::hertz::impact::HertzImpact;
    /// let imp = HertzImpact::new(1.0e6, 2.0e-5, 800.0)?;
    /// let r = imp.result();
    /// assert_eq!(imp.force_at(r.time_of_max_approach)?, r.max_force);
    /// # Ok::<(), kontakt::Error>(())
    /// ```
    ///
    /// # References
    /// Johnson (1982) eqs (15), (36).
    pub fn force_at(&self, time: Second) -> Result<Newton> {
        let state = self.state_at(time)?;
        Ok(self.result.max_force * state.x * state.x.sqrt())
    }

    /// Rate of approach $\dot\delta(t)$ \[mm/s\] at time `time`: $+V\sqrt{1-(\delta/\delta^*)^{5/2}}$
    /// during compression ($t < T/2$), the negative of that during restitution; $+V$ at
    /// $t=0$ and $-V$ at $t=T$.
    ///
    /// # Arguments
    /// - `time` — $t$ \[s\], $0 \le t \le T$.
    ///
    /// # Errors
    /// [`Error::InvalidInput`] naming `time` outside $[0, T]$ or not finite.
    ///
    /// # Example
    /// ```
    /// use kontakt::hertz::impact::HertzImpact;
    /// let imp = HertzImpact::new(1.0e6, 2.0e-5, 800.0)?;
    /// let t_end = imp.result().contact_duration;
    /// assert_eq!(imp.approach_rate_at(0.0)?, 800.0);
    /// assert_eq!(imp.approach_rate_at(t_end)?, -800.0);
    /// # Ok::<(), kontakt::Error>(())
    /// ```
    ///
    /// # References
    /// Johnson (1982) §7 (energy equation).
    pub fn approach_rate_at(&self, time: Second) -> Result<MillimetrePerSecond> {
        let state = self.state_at(time)?;
        let rate = self.impact_velocity * state.z;
        Ok(if state.restitution { -rate } else { rate })
    }

    /// Time \[s\] after first contact at which the approach first reaches `approach`
    /// (during compression); it is reached again, during restitution, at $T - t$.
    ///
    /// $$t(\delta) = \frac{\delta^*}{V}\int_0^{\delta/\delta^*}\frac{dx}{\sqrt{1-x^{5/2}}}$$
    ///
    /// # Arguments
    /// - `approach` — $\delta$ \[mm\], $0 \le \delta \le \delta^*$.
    ///
    /// # Errors
    /// [`Error::InvalidInput`] naming `approach` outside $[0, \delta^*]$ or not finite.
    ///
    /// # Example
    /// ```
    /// use kontakt::hertz::impact::HertzImpact;
    /// let imp = HertzImpact::new(1.0e6, 2.0e-5, 800.0)?;
    /// let t = imp.time_at_approach(0.5 * imp.result().max_approach)?;
    /// assert!((imp.approach_at(t)? / imp.result().max_approach - 0.5).abs() < 1e-15);
    /// # Ok::<(), kontakt::Error>(())
    /// ```
    ///
    /// # References
    /// Johnson (1982) §7; DLMF §8.17.
    pub fn time_at_approach(&self, approach: Millimetre) -> Result<Second> {
        let d_max = self.result.max_approach;
        if !(approach.is_finite() && (0.0..=d_max).contains(&approach)) {
            return Err(Error::invalid(
                "approach",
                approach,
                format!("0 <= approach <= max_approach = {d_max} mm"),
            ));
        }
        let x = approach / d_max;
        let u = x.powf(2.5);
        let tau = if u <= SPLIT_U {
            normalized_time_from_start(x, u)
        } else {
            // y = 1 - u, computed without cancellation.
            let y = -(2.5 * x.ln()).exp_m1();
            0.5 * HERTZ_IMPACT_DURATION_CONSTANT - normalized_time_to_peak(y.max(0.0).sqrt())
        };
        Ok((tau * d_max / self.impact_velocity).min(self.result.time_of_max_approach))
    }

    /// Normalised state at `time`: x = delta/delta*, z = sqrt(1 - x^(5/2)), phase.
    fn state_at(&self, time: Second) -> Result<NormalizedState> {
        let t_end = self.result.contact_duration;
        if !(time.is_finite() && (0.0..=t_end).contains(&time)) {
            return Err(Error::invalid(
                "time",
                time,
                format!("0 <= time <= contact_duration = {t_end} s"),
            ));
        }
        // Fold the restitution half onto the compression half (exact symmetry).
        let restitution = time > self.result.time_of_max_approach;
        let t = if restitution { t_end - time } else { time };
        let tau = t * self.impact_velocity / self.result.max_approach;
        let (x, z) = invert_normalized_time(tau)?;
        Ok(NormalizedState { x, z, restitution })
    }
}

#[derive(Debug, Clone, Copy)]
struct NormalizedState {
    x: f64,
    z: f64,
    restitution: bool,
}

/// The series about the start converge like SPLIT_U^n, those about the peak like
/// (1 - SPLIT_U)^n; 1/2 balances both (about 55 terms for 1 ulp).
const SPLIT_U: f64 = 0.5;
const SERIES_MAX_TERMS: usize = 200;

/// $I(x) = \int_0^x (1-s^{5/2})^{-1/2} ds = \tfrac25 B_u(\tfrac25,\tfrac12)$ with
/// $u = x^{5/2} \le 1/2$:
/// $I = x \sum_n \frac{(1/2)_n}{n!}\,\frac{(2/5)\,u^n}{n + 2/5}$ (binomial series, DLMF §8.17).
fn normalized_time_from_start(x: f64, u: f64) -> f64 {
    let mut coef = 1.0; // (1/2)_n / n!
    let mut un = 1.0;
    let mut sum = 0.0;
    for n in 0..SERIES_MAX_TERMS {
        let nf = n as f64;
        let term = coef * un / (nf + 0.4);
        sum += term;
        if term <= 1e-17 * sum {
            break;
        }
        coef *= (nf + 0.5) / (nf + 1.0);
        un *= u;
    }
    0.4 * x * sum
}

/// $c/2 - I(x)$ written in $z = \sqrt{1-x^{5/2}}$, $y = z^2 \le 1/2$:
/// $G(z) = \tfrac25 B_{y}(\tfrac12,\tfrac25) = \tfrac25 z \sum_n \frac{(3/5)_n}{n!}\,
/// \frac{y^n}{n + 1/2}$.
fn normalized_time_to_peak(z: f64) -> f64 {
    let y = z * z;
    let mut coef = 1.0; // (3/5)_n / n!
    let mut yn = 1.0;
    let mut sum = 0.0;
    for n in 0..SERIES_MAX_TERMS {
        let nf = n as f64;
        let term = coef * yn / (nf + 0.5);
        sum += term;
        if term <= 1e-17 * sum {
            break;
        }
        coef *= (nf + 0.6) / (nf + 1.0);
        yn *= y;
    }
    0.4 * z * sum
}

/// Solve $I(x) = \tau$ for $0 \le \tau \le c/2$; returns (x, z = sqrt(1 - x^{5/2})).
///
/// Both branch functions are increasing and convex, so Newton's method started to the
/// right of the root decreases monotonically onto it; the loop stops when the iterate no
/// longer decreases.
fn invert_normalized_time(tau: f64) -> Result<(f64, f64)> {
    const MAX_ITER: usize = 100;
    let half = 0.5 * HERTZ_IMPACT_DURATION_CONSTANT;
    let x_split = SPLIT_U.powf(0.4);
    let tau_split = normalized_time_from_start(x_split, SPLIT_U);
    if tau <= 0.0 {
        return Ok((0.0, 1.0));
    }
    if tau <= tau_split {
        // I(x) >= x, so x0 = tau is right of the root; I'(x) = 1/sqrt(1-u).
        let mut x = tau.min(x_split);
        for _ in 0..MAX_ITER {
            let u = x.powf(2.5);
            let f = normalized_time_from_start(x, u) - tau;
            let next = x - f * (1.0 - u).sqrt();
            if next.is_nan() || next >= x || f <= 0.0 {
                let u = x.powf(2.5);
                return Ok((x, (1.0 - u).sqrt()));
            }
            x = next.max(0.0);
        }
        return Err(not_converged(tau));
    }
    let tau_r = (half - tau).max(0.0);
    if tau_r == 0.0 {
        return Ok((1.0, 0.0));
    }
    // G(z) >= 4z/5, so z0 = 5 tau_r / 4 is right of the root; G'(z) = (4/5)(1-z^2)^(-3/5).
    let z_split = (1.0 - SPLIT_U).sqrt();
    let mut z = (1.25 * tau_r).min(z_split);
    for _ in 0..MAX_ITER {
        let y = z * z;
        let f = normalized_time_to_peak(z) - tau_r;
        let next = z - f / (0.8 * (1.0 - y).powf(-0.6));
        if next.is_nan() || next >= z || f <= 0.0 {
            let x = (0.4 * (-y).ln_1p()).exp();
            return Ok((x.min(1.0), z));
        }
        z = next.max(0.0);
    }
    Err(not_converged(tau))
}

fn not_converged(tau: f64) -> Error {
    Error::NotConverged {
        what: "Hertz impact time inversion".into(),
        iterations: 100,
        residual: tau,
    }
}

/// Mass of a solid sphere, $m = \tfrac43\pi R^3\rho$ \[t\].
///
/// # Arguments
/// - `radius` — $R$ \[mm\], finite, > 0.
/// - `density` — $\rho$ \[t/mm³\], finite, > 0 (steel 7.85e-9).
///
/// # Errors
/// [`Error::InvalidInput`] naming `radius` or `density`, or `radius` if the mass overflows.
///
/// # Example
/// ```
/// let m = kontakt::hertz::impact::sphere_mass(10.0, 7.85e-9)?;
/// assert!((m - 3.2882e-5).abs() < 1e-9);   // t (= 32.88 g)
/// # Ok::<(), kontakt::Error>(())
/// ```
pub fn sphere_mass(radius: Millimetre, density: TonnePerCubicMillimetre) -> Result<Tonne> {
    crate::error::positive_as("radius", radius, "a finite radius > 0 mm")?;
    crate::error::positive_as(
        "density",
        density,
        "a finite density > 0 t/mm^3 (steel 7.85e-9)",
    )?;
    let m = 4.0 / 3.0 * PI * radius * radius * radius * density;
    if m.is_finite() && m > 0.0 {
        Ok(m)
    } else {
        Err(Error::invalid(
            "radius",
            format!("{radius} (with density = {density})"),
            "a value for which 4/3 pi R^3 rho is finite and > 0",
        ))
    }
}

/// Effective (reduced) mass of two colliding bodies, $m = m_1 m_2/(m_1+m_2)$ \[t\].
///
/// A massive, fixed body (a flat on the ground) is `f64::INFINITY`; then $m = m_1$.
///
/// # Arguments
/// - `mass1`, `mass2` — \[t\], each > 0 and not NaN; at most one of them infinite.
///
/// # Errors
/// [`Error::InvalidInput`] naming `mass1` or `mass2`.
///
/// # Example
/// ```
/// use kontakt::hertz::impact::effective_mass;
/// assert_eq!(effective_mass(2.0e-5, 2.0e-5)?, 1.0e-5);
/// assert_eq!(effective_mass(2.0e-5, f64::INFINITY)?, 2.0e-5);
/// # Ok::<(), kontakt::Error>(())
/// ```
pub fn effective_mass(mass1: Tonne, mass2: Tonne) -> Result<Tonne> {
    let ok = |m: f64| m > 0.0; // rejects NaN, zero, negative; allows +inf
    if !ok(mass1) {
        return Err(Error::invalid(
            "mass1",
            mass1,
            "a mass > 0 t (infinite = fixed)",
        ));
    }
    if !ok(mass2) {
        return Err(Error::invalid(
            "mass2",
            mass2,
            "a mass > 0 t (infinite = fixed)",
        ));
    }
    match (mass1.is_finite(), mass2.is_finite()) {
        (true, true) => {
            // m1 m2 / (m1 + m2) without overflow of the product.
            let (lo, hi) = if mass1 <= mass2 {
                (mass1, mass2)
            } else {
                (mass2, mass1)
            };
            Ok(lo / (1.0 + lo / hi))
        }
        (true, false) => Ok(mass1),
        (false, true) => Ok(mass2),
        (false, false) => Err(Error::invalid(
            "mass2",
            mass2,
            "a finite mass > 0 t (both bodies cannot be fixed)",
        )),
    }
}

/// Impact velocity \[mm/s\] at which the maximum Hertz pressure of a spherical impact reaches
/// `yield_pressure`: the exact elastic limit for any effective mass.
///
/// $$a_Y = \frac{\pi R\,p_{0Y}}{2E^*},\qquad \delta_Y = \frac{a_Y^2}{R},\qquad
/// V_Y = \sqrt{\frac{4k\,\delta_Y^{5/2}}{5m}},\quad k = \tfrac43E^*\sqrt R$$
///
/// # Arguments
/// - `r_eff` — $R$, effective radius \[mm\], finite, > 0.
/// - `e_star` — $E^*$ \[MPa\], finite, > 0.
/// - `effective_mass` — $m$ \[t\], finite, > 0.
/// - `yield_pressure` — $p_{0Y}$, maximum Hertz pressure at first yield \[MPa\], finite and
///   positive; for a circular contact $p_{0Y} = 1.60\,Y$ at $\nu = 0.3$
///   ([`DEFAULT_YIELD_PRESSURE_RATIO`]).
///
/// # Returns
/// $V_Y$ \[mm/s\]. Below it the impact is fully elastic.
///
/// # Errors
/// [`Error::InvalidInput`] naming the bad argument, or `yield_pressure` on overflow.
///
/// # Assumptions
/// Quasi-static Hertz impact (module docs); yield is judged by $p_0$ alone.
///
/// # Example
/// ```
/// use kontakt::hertz::impact::{HertzImpact, yield_velocity};
/// let v = yield_velocity(5.0, 115_384.6, 1.0e-5, 1600.0)?;
/// let p0 = HertzImpact::sphere(5.0, 115_384.6, 1.0e-5, v)?.result().max_pressure.unwrap();
/// assert!((p0 - 1600.0).abs() < 1e-9);
/// # Ok::<(), kontakt::Error>(())
/// ```
///
/// # References
/// Johnson (1982) §7 and eq. (14); Johnson (1985) ch. 11.
pub fn yield_velocity(
    r_eff: Millimetre,
    e_star: Megapascal,
    effective_mass: Tonne,
    yield_pressure: Megapascal,
) -> Result<MillimetrePerSecond> {
    crate::error::positive_as("r_eff", r_eff, "a finite effective radius > 0 mm")?;
    crate::error::positive_as("e_star", e_star, "a finite contact modulus > 0 MPa")?;
    crate::error::positive_as("effective_mass", effective_mass, "a finite mass > 0 t")?;
    crate::error::positive_as(
        "yield_pressure",
        yield_pressure,
        "a finite pressure > 0 MPa",
    )?;
    // delta_Y / R = (pi p0Y / (2 E*))^2 =: s^2;  V^2 = (16/15) E* R^3 s^5 / m.
    let s = PI * yield_pressure / (2.0 * e_star);
    let v = (16.0 / 15.0 * e_star / effective_mass).sqrt() * r_eff.powf(1.5) * s.powf(2.5);
    finite_velocity(v, "yield_pressure", yield_pressure)
}

/// Yield velocity \[mm/s\] of a solid sphere striking a massive flat (same or different
/// material), exact within Hertz theory; independent of the sphere radius:
///
/// $$\frac{\rho V_Y^2}{Y} = \frac{4}{5\pi}\left(\frac{\pi}{2}\frac{p_{0Y}}{Y}\right)^5
///   \left(\frac{Y}{E^*}\right)^4, \qquad
///   V_Y = \sqrt{\frac{4E^*}{5\pi\rho}}\left(\frac{\pi p_{0Y}}{2E^*}\right)^{5/2}$$
///
/// With $p_{0Y} = 1.60\,Y$ the coefficient is 25.5, not the 85 printed in Johnson (1982)
/// eq. (38) (see `docs/impact_adhesion.md`; [`yield_velocity_johnson`] gives the printed
/// formula).
///
/// # Arguments
/// - `density` — $\rho$ of the sphere \[t/mm³\], finite, > 0.
/// - `e_star` — $E^*$ of sphere and flat \[MPa\], finite, > 0.
/// - `yield_pressure` — $p_{0Y}$ \[MPa\], finite, > 0 (e.g. `1.60 * Y`).
///
/// # Returns
/// $V_Y$ \[mm/s\].
///
/// # Errors
/// [`Error::InvalidInput`] naming the bad argument, or `yield_pressure` on overflow.
///
/// # Assumptions
/// Quasi-static Hertz impact; the flat does not move (infinite mass).
///
/// # Example
/// Steel (E = 210 GPa, nu = 0.3, rho = 7850 kg/m³) with Y = 1000 MPa: 0.135 m/s.
/// ```
/// use kontakt::hertz::impact::yield_velocity_sphere_on_flat;
/// let v = yield_velocity_sphere_on_flat(7.85e-9, 210_000.0 / 1.82, 1.60 * 1000.0)?;
/// assert!((v - 135.47).abs() < 0.01);   // mm/s
/// # Ok::<(), kontakt::Error>(())
/// ```
///
/// # References
/// Johnson (1982) §7, eq. (38) (printed coefficient 85); Johnson (1985) ch. 11.
pub fn yield_velocity_sphere_on_flat(
    density: TonnePerCubicMillimetre,
    e_star: Megapascal,
    yield_pressure: Megapascal,
) -> Result<MillimetrePerSecond> {
    crate::error::positive_as("density", density, "a finite density > 0 t/mm^3")?;
    // V_Y does not depend on the radius (m ∝ R³ cancels R^(3/2) twice): evaluate the
    // general formula for a unit sphere.
    yield_velocity(1.0, e_star, sphere_mass(1.0, density)?, yield_pressure)
}

/// Johnson's (1982) approximation, eq. (38), for the velocity at which a sphere striking a
/// massive flat starts to yield \[mm/s\]:
///
/// $$\frac{\rho V_Y^2}{Y} = 85\left(\frac{Y}{E^*}\right)^4$$
///
/// exactly as printed. The exact Hertz value ([`yield_velocity_sphere_on_flat`] with
/// $p_{0Y} = 1.60\,Y$) has 25.5 in place of 85, so this returns a velocity
/// $\sqrt{85/25.5} = 1.82$ times higher; the paper's example (steel, $Y$ = 1000 MPa,
/// "$V_Y \approx 0.8$ m/s") is reproduced by neither (this gives 0.247 m/s, the exact
/// value 0.135 m/s). Use this only to compare with the paper.
///
/// # Arguments
/// - `density` — $\rho$ \[t/mm³\], finite, > 0.
/// - `e_star` — $E^*$ \[MPa\], finite, > 0.
/// - `yield_stress` — $Y$, uniaxial yield stress of the softer body \[MPa\], finite, > 0.
///
/// # Returns
/// $V_Y$ \[mm/s\].
///
/// # Errors
/// [`Error::InvalidInput`] naming the bad argument, or `yield_stress` on overflow.
///
/// # Example
/// ```
/// use kontakt::hertz::impact::yield_velocity_johnson;
/// let v = yield_velocity_johnson(7.85e-9, 210_000.0 / 1.82, 1000.0)?;
/// assert!((v - 247.16).abs() < 0.01);   // mm/s
/// # Ok::<(), kontakt::Error>(())
/// ```
///
/// # References
/// Johnson (1982), eq. (38).
pub fn yield_velocity_johnson(
    density: TonnePerCubicMillimetre,
    e_star: Megapascal,
    yield_stress: Megapascal,
) -> Result<MillimetrePerSecond> {
    crate::error::positive_as("density", density, "a finite density > 0 t/mm^3")?;
    crate::error::positive_as("e_star", e_star, "a finite contact modulus > 0 MPa")?;
    crate::error::positive_as("yield_stress", yield_stress, "a finite stress > 0 MPa")?;
    let r = yield_stress / e_star;
    let v = (JOHNSON_YIELD_VELOCITY_COEFFICIENT * yield_stress / density).sqrt() * r * r;
    finite_velocity(v, "yield_stress", yield_stress)
}

fn finite_velocity(v: f64, field: &'static str, value: f64) -> Result<MillimetrePerSecond> {
    if v.is_finite() && v > 0.0 {
        Ok(v)
    } else {
        Err(Error::invalid(
            field,
            value,
            "a value for which the yield velocity is finite and > 0 (overflow/underflow)",
        ))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn series_branches_meet_at_the_split() {
        let x = SPLIT_U.powf(0.4);
        let from_start = normalized_time_from_start(x, SPLIT_U);
        let to_peak =
            0.5 * HERTZ_IMPACT_DURATION_CONSTANT - normalized_time_to_peak((1.0 - SPLIT_U).sqrt());
        assert!(
            (from_start - to_peak).abs() < 4e-16,
            "{from_start} {to_peak}"
        );
    }

    #[test]
    fn inversion_round_trips_over_the_half_period() {
        for i in 0..=1000 {
            let tau = 0.5 * HERTZ_IMPACT_DURATION_CONSTANT * f64::from(i) / 1000.0;
            let (x, z) = invert_normalized_time(tau).expect("invariant: tau in range");
            assert!((z * z + x.powf(2.5) - 1.0).abs() < 1e-15);
            let back = if x.powf(2.5) <= SPLIT_U {
                normalized_time_from_start(x, x.powf(2.5))
            } else {
                0.5 * HERTZ_IMPACT_DURATION_CONSTANT - normalized_time_to_peak(z)
            };
            assert!((back - tau).abs() < 1e-15, "tau {tau}: {back}");
        }
    }
}
