//! JKR adhesion: the contact of elastic spheres whose surfaces attract each other
//! (Johnson, Kendall and Roberts 1971).
//!
//! # Formulas
//! With the effective radius $R$, the contact modulus $E^*$ and the work of adhesion
//! $w = 2\gamma$ (energy per unit area needed to separate the surfaces; Johnson 1982 writes
//! $2\gamma$ with $\gamma$ the surface energy of each surface), the pressure is the Hertz
//! distribution of the contact radius $a$ minus a flat-punch (tensile) distribution
//! (Johnson 1982 eqs 42, 47):
//!
//! $$p(r) = p_0\sqrt{1-\frac{r^2}{a^2}} - \frac{p_0'}{\sqrt{1-r^2/a^2}},\qquad
//!   p_0 = \frac{2E^*a}{\pi R},\qquad p_0' = \sqrt{\frac{2wE^*}{\pi a}}
//!   = \sqrt{\frac{4\gamma E^*}{\pi a}}$$
//!
//! and the load, approach and contact radius are related by (eqs 44, 48)
//!
//! $$P = \frac{4E^*a^3}{3R} - \sqrt{8\pi w E^* a^3},\qquad
//!   \delta = \frac{a^2}{R} - \sqrt{\frac{2\pi w a}{E^*}}.$$
//!
//! Under load control the contact breaks where $dP/da = 0$, at
//! $P_c = -\tfrac32\pi w R = -3\pi\gamma R$ (eq. 49) and
//! $a_c = (9\pi w R^2/(8E^*))^{1/3} = (9\pi\gamma R^2/(4E^*))^{1/3}$ (Fig. 13 caption); at
//! zero load $a_0 = (9\pi w R^2/(2E^*))^{1/3} = 4^{1/3}a_c$. Under displacement control it
//! breaks where $d\delta/da = 0$: $a = a_0/36^{1/3}$, $P = -\tfrac56\pi wR$.
//!
//! Eqs (42)-(49) of Johnson (1982) were checked against each other symbolically (strain
//! energy of eq. 42 → eq. 43, displacement → eq. 44, $\partial U_T/\partial a|_\delta = 0$
//! → eq. 47, force integral → eq. 48, $dP/da = 0$ → eq. 49): they are consistent. Two
//! notational traps, not misprints: the $p_0$ of eq. (42) is the Hertz pressure of the
//! *contact radius* $a$ (i.e. of the apparent Hertz load $4E^*a^3/3R$), not of the actual
//! load $P$ through eq. (14); and the Fig. 13 caption's $a_c$, $P_c = 3\pi\gamma R$ are the
//! pull-off point B (with $P_c$ as a positive magnitude), not point C at zero load. See
//! `docs/impact_adhesion.md`.
//!
//! # Assumptions
//! Linear elastic, isotropic half-spaces (contact radius ≪ R), paraboloidal profile,
//! frictionless; adhesion acts only inside the contact with zero range (the JKR limit:
//! large, soft spheres with a Tabor parameter $\mu = (Rw^2/(E^{*2}z_0^3))^{1/3} \gtrsim 5$).
//! The tensile pressure is singular at the edge, like a crack tip
//! ([`Jkr::stress_intensity_factor`]); the energy balance is unaffected (Johnson 1982 §9).
//!
//! # References
//! - Johnson, Kendall, Roberts (1971), "Surface energy and the contact of elastic solids",
//!   Proc. R. Soc. Lond. A 324, 301-313. doi:10.1098/rspa.1971.0141
//! - Johnson (1982), "One hundred years of Hertz contact", Proc. IMechE 196, 363-378, §9,
//!   eqs (42)-(49), Fig. 13. doi:10.1243/PIME_PROC_1982_196_039_02
//! - Johnson, *Contact Mechanics* (1985), ch. 5.
//! - Maugis (2000), *Contact, Adhesion and Rupture of Elastic Solids*, Springer, ch. 5
//!   (fixed-grip instability, stress intensity factor).

use crate::error::{Error, Result};
use crate::units::{Megapascal, Millimetre, Newton, NewtonPerMillimetre};
use std::f64::consts::PI;

/// JKR adhesive contact of two elastic spheres (or a sphere on a flat).
///
/// Holds $R$, $E^*$ and $w$; every method is a closed form (no iteration except
/// [`radius_from_approach`](Self::radius_from_approach), a few Newton steps).
///
/// # Example
/// A rubber ball (R = 10 mm, E* = 1 MPa) on glass with w = 0.05 J/m² = 5e-5 N/mm:
/// ```
/// use kontakt::hertz::adhesion::Jkr;
/// let jkr = Jkr::new(10.0, 1.0, 5.0e-5)?;
/// assert!((jkr.pull_off_force() + 2.356_19e-3).abs() < 1e-8);      // N, = -3/2 pi w R
/// assert!((jkr.radius_at_zero_load() - 0.413_470).abs() < 1e-6);    // mm
/// let a = jkr.radius_from_load(0.01)?;                              // 10 mN pressing
/// assert!((jkr.load_from_radius(a)? - 0.01).abs() < 1e-15);
/// assert!(a > (3.0 * 0.01 * 10.0 / 4.0_f64).cbrt());               // larger than Hertz
/// # Ok::<(), kontakt::Error>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct Jkr {
    r_eff: Millimetre,
    e_star: Megapascal,
    work_of_adhesion: NewtonPerMillimetre,
}

/// The state of a JKR contact at one contact radius (plain data).
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct JkrState {
    /// $a$, contact radius \[mm\].
    pub contact_radius: Millimetre,
    /// $P$, normal load \[N\], positive in compression, negative (tensile) below the
    /// zero-load radius.
    pub load: Newton,
    /// $\delta$, approach \[mm\] (may be negative: the adhering sphere is pulled out).
    pub approach: Millimetre,
    /// $p_0 = 2E^*a/(\pi R)$, the Hertz pressure of radius $a$ \[MPa\].
    pub hertz_pressure: Megapascal,
    /// $p_0' = \sqrt{2wE^*/(\pi a)}$, the coefficient of the tensile flat-punch term \[MPa\].
    pub adhesive_pressure: Megapascal,
}

impl JkrState {
    /// Contact pressure $p(r)$ \[MPa\] at radius `r` (positive in compression), Johnson (1982)
    /// eq. (42):
    ///
    /// $$p(r) = p_0\sqrt{1-r^2/a^2} - \frac{p_0'}{\sqrt{1-r^2/a^2}}\quad (r < a),
    ///   \qquad p = 0\quad (r \ge a)$$
    ///
    /// The tensile term is singular (integrably) at $r \to a^-$; at $r = a$ and outside the
    /// contact the function returns 0, the value outside the open contact disc.
    ///
    /// # Arguments
    /// - `r` — radial distance from the contact centre \[mm\], finite, >= 0.
    ///
    /// # Returns
    /// $p(r)$ \[MPa\]; finite for every valid `r`.
    ///
    /// # Errors
    /// [`Error::InvalidInput`] naming `r` if it is negative or not finite.
    ///
    /// # Example
    /// ```
    /// use kontakt::hertz::adhesion::Jkr;
    /// let s = Jkr::new(10.0, 1.0, 5.0e-5)?.state_from_load(0.0)?;
    /// // at zero load the centre is still in compression: p(0) = p0 - p0'
    /// let p_centre = s.pressure(0.0)?;
    /// assert!((p_centre - (s.hertz_pressure - s.adhesive_pressure)).abs() < 1e-15);
    /// assert!(s.pressure(0.999 * s.contact_radius)? < 0.0);   // tension near the edge
    /// assert_eq!(s.pressure(2.0 * s.contact_radius)?, 0.0);
    /// # Ok::<(), kontakt::Error>(())
    /// ```
    ///
    /// # References
    /// Johnson (1982), eqs (42), (47); Johnson, Kendall, Roberts (1971).
    pub fn pressure(&self, r: Millimetre) -> Result<Megapascal> {
        if !(r.is_finite() && r >= 0.0) {
            return Err(Error::invalid("r", r, "a finite radius >= 0 mm"));
        }
        let a = self.contact_radius;
        if r >= a {
            return Ok(0.0);
        }
        let rho = r / a;
        let root = ((1.0 - rho) * (1.0 + rho)).sqrt();
        Ok(self.hertz_pressure * root - self.adhesive_pressure / root)
    }
}

impl Jkr {
    /// A JKR contact.
    ///
    /// $$\frac{1}{R} = \frac{1}{R_1} + \frac{1}{R_2},\qquad
    ///   \frac{1}{E^*} = \frac{1-\nu_1^2}{E_1} + \frac{1-\nu_2^2}{E_2},\qquad w = 2\gamma$$
    ///
    /// # Arguments
    /// - `r_eff` — $R$, effective radius \[mm\], finite, > 0.
    /// - `e_star` — $E^*$, contact modulus \[MPa\], finite, > 0
    ///   (see [`crate::material::effective_modulus`]).
    /// - `work_of_adhesion` — $w = 2\gamma$ \[N/mm\] (1 J/m² = 1e-3 N/mm), finite, > 0. For
    ///   $w = 0$ use Hertz theory; JKR tends to it as $w \to 0$.
    ///
    /// # Errors
    /// [`Error::InvalidInput`] naming the argument that is zero, negative, NaN or infinite,
    /// or `work_of_adhesion` if the characteristic radius or pull-off force would overflow.
    ///
    /// # Example
    /// ```
    /// use kontakt::hertz::adhesion::Jkr;
    /// assert!(Jkr::new(10.0, 1.0, 5.0e-5).is_ok());
    /// let e = Jkr::new(10.0, 1.0, -5.0e-5).unwrap_err();
    /// assert_eq!(e.field(), Some("work_of_adhesion"));
    /// ```
    ///
    /// # References
    /// Johnson (1982) §9; Johnson, Kendall, Roberts (1971).
    pub fn new(
        r_eff: Millimetre,
        e_star: Megapascal,
        work_of_adhesion: NewtonPerMillimetre,
    ) -> Result<Self> {
        crate::error::positive_as("r_eff", r_eff, "a finite effective radius > 0 mm")?;
        crate::error::positive_as("e_star", e_star, "a finite contact modulus > 0 MPa")?;
        crate::error::positive_as(
            "work_of_adhesion",
            work_of_adhesion,
            "a finite work of adhesion w = 2*gamma > 0 N/mm (1 J/m^2 = 1e-3 N/mm)",
        )?;
        let jkr = Jkr {
            r_eff,
            e_star,
            work_of_adhesion,
        };
        let derived = [
            jkr.radius_at_zero_load(),
            jkr.pull_off_force(),
            jkr.approach_at_pull_off_fixed_grips(),
            jkr.stress_intensity_factor(),
            jkr.stiffness_coefficient(),
            jkr.adhesion_coefficient(),
        ];
        if derived.iter().all(|x| x.is_finite() && *x != 0.0) {
            Ok(jkr)
        } else {
            Err(Error::invalid(
                "work_of_adhesion",
                format!("{work_of_adhesion} (with r_eff = {r_eff}, e_star = {e_star})"),
                "a combination for which a0, the pull-off force and approach are finite and \
                 non-zero (these inputs overflow or underflow f64)",
            ))
        }
    }

    /// Effective radius $R$ \[mm\].
    pub fn r_eff(&self) -> Millimetre {
        self.r_eff
    }

    /// Contact modulus $E^*$ \[MPa\].
    pub fn e_star(&self) -> Megapascal {
        self.e_star
    }

    /// Work of adhesion $w = 2\gamma$ \[N/mm\].
    pub fn work_of_adhesion(&self) -> NewtonPerMillimetre {
        self.work_of_adhesion
    }

    /// $K = 4E^*/(3R)$ \[N/mm³\].
    fn stiffness_coefficient(&self) -> f64 {
        4.0 * self.e_star / (3.0 * self.r_eff)
    }

    /// $s = \sqrt{8\pi w E^*}$ \[N/mm^1.5\].
    fn adhesion_coefficient(&self) -> f64 {
        (8.0 * PI * self.work_of_adhesion).sqrt() * self.e_star.sqrt()
    }

    /// Load \[N\] at contact radius `contact_radius`, Johnson (1982) eq. (48) solved for $P$
    /// on its physical branch ($P \le 4E^*a^3/3R$):
    ///
    /// $$P = \frac{4E^*a^3}{3R} - \sqrt{8\pi w E^* a^3}$$
    ///
    /// # Arguments
    /// - `contact_radius` — $a$ \[mm\], finite, > 0.
    ///
    /// # Returns
    /// $P$ \[N\], compressive positive; any $a > 0$ is an equilibrium (stable under load
    /// control only for $a \ge a_c$, see [`radius_at_pull_off`](Self::radius_at_pull_off)).
    ///
    /// # Errors
    /// [`Error::InvalidInput`] naming `contact_radius` if it is not finite and > 0 or the
    /// load overflows.
    ///
    /// # Example
    /// ```
    /// use kontakt::hertz::adhesion::Jkr;
    /// let jkr = Jkr::new(10.0, 1.0, 5.0e-5)?;
    /// assert!(jkr.load_from_radius(jkr.radius_at_zero_load())?.abs() < 1e-15);
    /// assert!((jkr.load_from_radius(jkr.radius_at_pull_off())? - jkr.pull_off_force()).abs()
    ///     < 1e-15);
    /// # Ok::<(), kontakt::Error>(())
    /// ```
    ///
    /// # References
    /// Johnson (1982), eq. (48); Johnson, Kendall, Roberts (1971), eq. (6).
    pub fn load_from_radius(&self, contact_radius: Millimetre) -> Result<Newton> {
        let a =
            crate::error::positive_as("contact_radius", contact_radius, "a finite radius > 0 mm")?;
        let x = a * a.sqrt(); // a^(3/2)
        let p = x * (self.stiffness_coefficient() * x - self.adhesion_coefficient());
        finite("contact_radius", a, p)
    }

    /// Contact radius \[mm\] at load `load` on the stable branch (the larger root of eq. 48):
    ///
    /// $$a^{3/2} = \frac{\sqrt{8\pi wE^*} + \sqrt{\tfrac{16E^*}{3R}(P - P_c)}}{8E^*/(3R)},
    ///   \qquad P_c = -\tfrac32\pi wR$$
    ///
    /// # Arguments
    /// - `load` — $P$ \[N\], finite, $P \ge P_c$ ([`pull_off_force`](Self::pull_off_force));
    ///   negative values are tensile.
    ///
    /// # Returns
    /// $a \ge a_c$ \[mm\]; $a = a_c$ at $P = P_c$, $a_0$ at $P = 0$.
    ///
    /// # Errors
    /// [`Error::InvalidInput`] naming `load` if it is not finite, below the pull-off force
    /// (the surfaces have separated) or the radius overflows.
    ///
    /// # Example
    /// ```
    /// use kontakt::hertz::adhesion::Jkr;
    /// let jkr = Jkr::new(10.0, 1.0, 5.0e-5)?;
    /// let a = jkr.radius_from_load(-1.0e-3)?;
    /// assert!(a > jkr.radius_at_pull_off() && a < jkr.radius_at_zero_load());
    /// assert!(jkr.radius_from_load(1.01 * jkr.pull_off_force()).is_err());
    /// # Ok::<(), kontakt::Error>(())
    /// ```
    ///
    /// # References
    /// Johnson (1982), eqs (48), (49); Johnson, Kendall, Roberts (1971), eq. (6).
    pub fn radius_from_load(&self, load: Newton) -> Result<Millimetre> {
        let pc = self.pull_off_force();
        if !(load.is_finite() && load >= pc) {
            return Err(Error::invalid(
                "load",
                load,
                format!(
                    "a finite load >= the pull-off force {pc} N (= -3/2 pi w R); below it the \
                     surfaces separate"
                ),
            ));
        }
        let k = self.stiffness_coefficient();
        // Discriminant s^2 + 4 K P written as 4 K (P - Pc): exact zero at pull-off.
        let disc = 4.0 * k * (load - pc);
        let x = (self.adhesion_coefficient() + disc.sqrt()) / (2.0 * k);
        finite("load", load, x.powf(2.0 / 3.0))
    }

    /// Approach \[mm\] at contact radius `contact_radius`, Johnson (1982) eq. (44) with eqs
    /// (42), (47):
    ///
    /// $$\delta = \frac{\pi a (p_0 - 2p_0')}{2E^*} = \frac{a^2}{R} - \sqrt{\frac{2\pi w a}{E^*}}$$
    ///
    /// # Arguments
    /// - `contact_radius` — $a$ \[mm\], finite, > 0.
    ///
    /// # Returns
    /// $\delta$ \[mm\], positive when pressed together; negative for small $a$ (the adhering
    /// surfaces are pulled out of the undeformed touching position).
    ///
    /// # Errors
    /// [`Error::InvalidInput`] naming `contact_radius` if not finite and > 0, or on overflow.
    ///
    /// # Example
    /// ```
    /// use kontakt::hertz::adhesion::Jkr;
    /// let jkr = Jkr::new(10.0, 1.0, 5.0e-5)?;
    /// // at zero load delta = a0^2 / (3R)
    /// let a0 = jkr.radius_at_zero_load();
    /// assert!((jkr.approach_from_radius(a0)? - a0 * a0 / 30.0).abs() < 1e-15);
    /// # Ok::<(), kontakt::Error>(())
    /// ```
    ///
    /// # References
    /// Johnson (1982), eqs (44), (47); Johnson, Kendall, Roberts (1971).
    pub fn approach_from_radius(&self, contact_radius: Millimetre) -> Result<Millimetre> {
        let a =
            crate::error::positive_as("contact_radius", contact_radius, "a finite radius > 0 mm")?;
        let d = a * a / self.r_eff - (2.0 * PI * self.work_of_adhesion * a / self.e_star).sqrt();
        finite("contact_radius", a, d)
    }

    /// Contact radius \[mm\] at approach `approach` on the branch that is stable under
    /// displacement control ($a \ge a_0/36^{1/3}$), inverting
    /// $\delta = a^2/R - \sqrt{2\pi wa/E^*}$ by Newton's method in $\sqrt a$ (convex, started
    /// to the right of the root, so it converges monotonically).
    ///
    /// # Arguments
    /// - `approach` — $\delta$ \[mm\], finite, $\delta \ge \delta_c$
    ///   ([`approach_at_pull_off_fixed_grips`](Self::approach_at_pull_off_fixed_grips)
    ///   $= -\tfrac34(\pi^2w^2R/E^{*2})^{1/3}$).
    ///
    /// # Returns
    /// $a$ \[mm\].
    ///
    /// # Errors
    /// [`Error::InvalidInput`] naming `approach` if it is not finite or below $\delta_c$
    /// (the surfaces separate); [`Error::NotConverged`] should never occur (the iteration
    /// is monotone and capped at 200 steps).
    ///
    /// # Example
    /// ```
    /// use kontakt::hertz::adhesion::Jkr;
    /// let jkr = Jkr::new(10.0, 1.0, 5.0e-5)?;
    /// let a = jkr.radius_from_approach(0.0)?;
    /// assert!(jkr.approach_from_radius(a)?.abs() < 1e-15);
    /// # Ok::<(), kontakt::Error>(())
    /// ```
    ///
    /// # References
    /// Johnson (1982), eq. (44); Maugis (2000) ch. 5.
    pub fn radius_from_approach(&self, approach: Millimetre) -> Result<Millimetre> {
        let d_min = self.approach_at_pull_off_fixed_grips();
        if !(approach.is_finite() && approach >= d_min) {
            return Err(Error::invalid(
                "approach",
                approach,
                format!(
                    "a finite approach >= {d_min} mm (= -3/4 (pi^2 w^2 R / E*^2)^(1/3), the \
                     fixed-grip pull-off); below it the surfaces separate"
                ),
            ));
        }
        // f(s) = s^4 / R - q s - delta with s = sqrt(a), q = sqrt(2 pi w / E*).
        let r = self.r_eff;
        let q = (2.0 * PI * self.work_of_adhesion / self.e_star).sqrt();
        let s_min = self.radius_at_pull_off_fixed_grips().sqrt();
        // Upper bound: s^4/R >= 2 max(delta, 0) and s^4/R >= 2 q s imply f(s) >= 0.
        let mut s = (2.0 * r * approach.max(0.0))
            .sqrt()
            .sqrt()
            .max((2.0 * q * r).cbrt())
            .max(s_min);
        for _ in 0..200 {
            let s2 = s * s;
            let f = s2 * s2 / r - q * s - approach;
            let df = 4.0 * s2 * s / r - q;
            if f <= 0.0 || df <= 0.0 {
                return finite("approach", approach, s * s);
            }
            let next = (s - f / df).max(s_min);
            if next.is_nan() || next >= s {
                return finite("approach", approach, s * s);
            }
            s = next;
        }
        Err(Error::NotConverged {
            what: "JKR radius from approach".into(),
            iterations: 200,
            residual: s * s * s * s / r - q * s - approach,
        })
    }

    /// The state (radius, load, approach, pressure coefficients) at contact radius
    /// `contact_radius`.
    ///
    /// # Arguments
    /// - `contact_radius` — $a$ \[mm\], finite, > 0.
    ///
    /// # Errors
    /// As [`load_from_radius`](Self::load_from_radius).
    ///
    /// # Example
    /// ```
    /// use kontakt::hertz::adhesion::Jkr;
    /// let jkr = Jkr::new(10.0, 1.0, 5.0e-5)?;
    /// let s = jkr.state_from_radius(0.5)?;
    /// // eq. 48 by its parts: P = (2/3 p0 - 2 p0') pi a^2
    /// let p = (2.0 / 3.0 * s.hertz_pressure - 2.0 * s.adhesive_pressure)
    ///     * std::f64::consts::PI * 0.25;
    /// assert!((p - s.load).abs() < 1e-15);
    /// # Ok::<(), kontakt::Error>(())
    /// ```
    ///
    /// # References
    /// Johnson (1982), eqs (42)-(48).
    pub fn state_from_radius(&self, contact_radius: Millimetre) -> Result<JkrState> {
        let load = self.load_from_radius(contact_radius)?;
        let approach = self.approach_from_radius(contact_radius)?;
        let a = contact_radius;
        Ok(JkrState {
            contact_radius: a,
            load,
            approach,
            hertz_pressure: 2.0 * self.e_star * a / (PI * self.r_eff),
            adhesive_pressure: (2.0 * self.work_of_adhesion * self.e_star / (PI * a)).sqrt(),
        })
    }

    /// The state at load `load` on the stable (load-controlled) branch.
    ///
    /// # Arguments
    /// - `load` — $P$ \[N\], finite, $\ge P_c$.
    ///
    /// # Errors
    /// As [`radius_from_load`](Self::radius_from_load).
    ///
    /// # Example
    /// ```
    /// use kontakt::hertz::adhesion::Jkr;
    /// let jkr = Jkr::new(10.0, 1.0, 5.0e-5)?;
    /// let s = jkr.state_from_load(jkr.pull_off_force())?;
    /// assert!((s.contact_radius - jkr.radius_at_pull_off()).abs() < 1e-15);
    /// # Ok::<(), kontakt::Error>(())
    /// ```
    ///
    /// # References
    /// Johnson (1982), eqs (42)-(49).
    pub fn state_from_load(&self, load: Newton) -> Result<JkrState> {
        let a = self.radius_from_load(load)?;
        let mut state = self.state_from_radius(a)?;
        state.load = load; // the requested load, not its round-trip
        Ok(state)
    }

    /// Contact radius at zero load \[mm\] (point C of Johnson's Fig. 13):
    ///
    /// $$a_0 = \left(\frac{9\pi wR^2}{2E^*}\right)^{1/3} = \left(\frac{9\pi\gamma R^2}{E^*}\right)^{1/3}$$
    ///
    /// # Example
    /// ```
    /// use kontakt::hertz::adhesion::Jkr;
    /// let jkr = Jkr::new(10.0, 1.0, 5.0e-5)?;
    /// assert!((jkr.radius_at_zero_load() - 0.413_470).abs() < 1e-6);
    /// # Ok::<(), kontakt::Error>(())
    /// ```
    ///
    /// # References
    /// Johnson (1982), eq. (48) with $P = 0$; Johnson, Kendall, Roberts (1971).
    pub fn radius_at_zero_load(&self) -> Millimetre {
        // R^(2/3) factored out so that R^2 cannot overflow.
        self.r_eff.cbrt().powi(2) * (4.5 * PI * self.work_of_adhesion / self.e_star).cbrt()
    }

    /// Pull-off force under load control \[N\] (negative, tensile), Johnson (1982) eq. (49):
    ///
    /// $$P_c = -\tfrac32\pi wR = -3\pi\gamma R$$
    ///
    /// independent of the elastic moduli.
    ///
    /// # Example
    /// ```
    /// use kontakt::hertz::adhesion::Jkr;
    /// let jkr = Jkr::new(10.0, 1.0, 5.0e-5)?;
    /// assert!((jkr.pull_off_force() + 1.5 * std::f64::consts::PI * 5.0e-4).abs() < 1e-18);
    /// # Ok::<(), kontakt::Error>(())
    /// ```
    ///
    /// # References
    /// Johnson (1982), eq. (49) and Fig. 13 (caption gives the magnitude $3\pi\gamma R$);
    /// Johnson, Kendall, Roberts (1971).
    pub fn pull_off_force(&self) -> Newton {
        -1.5 * PI * self.work_of_adhesion * self.r_eff
    }

    /// Contact radius at pull-off under load control \[mm\] (point B of Fig. 13, where
    /// $dP/da = 0$):
    ///
    /// $$a_c = \left(\frac{9\pi wR^2}{8E^*}\right)^{1/3} = \frac{a_0}{4^{1/3}}
    ///   = \left(\frac{9\pi\gamma R^2}{4E^*}\right)^{1/3}$$
    ///
    /// # Example
    /// ```
    /// use kontakt::hertz::adhesion::Jkr;
    /// let jkr = Jkr::new(10.0, 1.0, 5.0e-5)?;
    /// let ratio = jkr.radius_at_zero_load() / jkr.radius_at_pull_off();
    /// assert!((ratio - 4.0_f64.cbrt()).abs() < 1e-15);
    /// # Ok::<(), kontakt::Error>(())
    /// ```
    ///
    /// # References
    /// Johnson (1982), Fig. 13 caption; eq. (48) with $dP/da = 0$.
    pub fn radius_at_pull_off(&self) -> Millimetre {
        self.radius_at_zero_load() / 4.0_f64.cbrt()
    }

    /// Pull-off force under displacement control (fixed grips) \[N\]: $-\tfrac56\pi wR$,
    /// reached at [`radius_at_pull_off_fixed_grips`](Self::radius_at_pull_off_fixed_grips).
    ///
    /// # Example
    /// ```
    /// use kontakt::hertz::adhesion::Jkr;
    /// let jkr = Jkr::new(10.0, 1.0, 5.0e-5)?;
    /// assert!((jkr.pull_off_force_fixed_grips() / jkr.pull_off_force() - 5.0 / 9.0).abs()
    ///     < 1e-15);
    /// # Ok::<(), kontakt::Error>(())
    /// ```
    ///
    /// # References
    /// Derived from eqs (44), (47), (48) of Johnson (1982) with $d\delta/da = 0$
    /// (`docs/impact_adhesion.md`); Maugis (2000) ch. 5.
    pub fn pull_off_force_fixed_grips(&self) -> Newton {
        -5.0 / 6.0 * PI * self.work_of_adhesion * self.r_eff
    }

    /// Contact radius where the contact breaks under displacement control \[mm\], where
    /// $d\delta/da = 0$:
    ///
    /// $$a = \left(\frac{\pi w R^2}{8E^*}\right)^{1/3} = \frac{a_0}{36^{1/3}}$$
    ///
    /// # Example
    /// ```
    /// use kontakt::hertz::adhesion::Jkr;
    /// let jkr = Jkr::new(10.0, 1.0, 5.0e-5)?;
    /// let a = jkr.radius_at_pull_off_fixed_grips();
    /// assert!((jkr.load_from_radius(a)? - jkr.pull_off_force_fixed_grips()).abs() < 1e-15);
    /// # Ok::<(), kontakt::Error>(())
    /// ```
    ///
    /// # References
    /// As [`pull_off_force_fixed_grips`](Self::pull_off_force_fixed_grips).
    pub fn radius_at_pull_off_fixed_grips(&self) -> Millimetre {
        self.radius_at_zero_load() / 36.0_f64.cbrt()
    }

    /// Approach at pull-off under displacement control \[mm\], the minimum of $\delta(a)$:
    ///
    /// $$\delta_c = -\frac34\left(\frac{\pi^2 w^2 R}{E^{*2}}\right)^{1/3}$$
    ///
    /// # Example
    /// ```
    /// use kontakt::hertz::adhesion::Jkr;
    /// let jkr = Jkr::new(10.0, 1.0, 5.0e-5)?;
    /// let a = jkr.radius_at_pull_off_fixed_grips();
    /// let d = jkr.approach_from_radius(a)?;
    /// assert!((d - jkr.approach_at_pull_off_fixed_grips()).abs() < 1e-15);
    /// # Ok::<(), kontakt::Error>(())
    /// ```
    ///
    /// # References
    /// As [`pull_off_force_fixed_grips`](Self::pull_off_force_fixed_grips).
    pub fn approach_at_pull_off_fixed_grips(&self) -> Millimetre {
        let q = PI * self.work_of_adhesion / self.e_star;
        -0.75 * q.cbrt().powi(2) * self.r_eff.cbrt()
    }

    /// Mode-I stress intensity factor at the edge of the contact \[MPa·mm^½\], the same at
    /// every contact radius:
    ///
    /// $$K_I = \lim_{r\to a}\sqrt{2\pi(a-r)}\,\bigl(-p(r)\bigr) = p_0'\sqrt{\pi a} = \sqrt{2E^*w}$$
    ///
    /// so that the energy release rate $K_I^2/(2E^*)$ equals $w$: the Griffith reading of
    /// eq. (47).
    ///
    /// # Example
    /// ```
    /// use kontakt::hertz::adhesion::Jkr;
    /// let jkr = Jkr::new(10.0, 1.0, 5.0e-5)?;
    /// assert!((jkr.stress_intensity_factor() - 1.0e-2).abs() < 1e-17);
    /// # Ok::<(), kontakt::Error>(())
    /// ```
    ///
    /// # References
    /// Johnson (1982) §9 (the crack analogy); Maugis (2000) ch. 5.
    pub fn stress_intensity_factor(&self) -> f64 {
        (2.0 * self.e_star).sqrt() * self.work_of_adhesion.sqrt()
    }
}

fn finite(field: &'static str, input: f64, output: f64) -> Result<f64> {
    if output.is_finite() {
        Ok(output)
    } else {
        Err(crate::error::overflow(field, input))
    }
}
