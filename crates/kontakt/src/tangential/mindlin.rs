//! Cattaneo-Mindlin partial slip of a Hertz contact under a tangential force `Q < mu P`
//! at constant normal force `P`, and the Mindlin-Deresiewicz loading history.
//!
//! # Formulas
//! With `x = |Q|/(mu P)` and the Hertz pressure `p0` on the ellipse `a, b`
//! ([`ContactEllipse`]), the adhesion (stick) zone is the concentric similar ellipse
//! (Johnson (1982) eq. 32)
//!
//! $$\frac{a'}{a} = \frac{b'}{b} = (1 - x)^{1/3},$$
//!
//! and the traction, parallel to `Q`, is (eqs 30-31)
//!
//! $$q = \mu p_0\Big[\sqrt{1 - \tfrac{x^2}{a^2} - \tfrac{y^2}{b^2}} -
//!  \tfrac{a'}{a}\sqrt{1 - \tfrac{x^2}{a'^2} - \tfrac{y^2}{b'^2}}\,\Big]$$
//!
//! (second term only inside the stick ellipse). Its displacement in the stick zone is a
//! rigid shift
//!
//! $$\delta = \tfrac32\,\mu P\,C\,\big[1 - (1 - x)^{2/3}\big],$$
//!
//! where `C` \[mm/N\] is the *no-slip compliance* of the ellipse in the direction of `Q`
//! (Mindlin 1949). For a force along the major semi-axis `a_M` (eccentricity
//! `e² = 1 - (b_m/a_M)²`), with Carlson's `R_F = R_F(0, 1-e², 1) = K(e)` and
//! `R_D = R_D(0, 1-e², 1)`,
//!
//! $$C_{major} = \sum_{i=1,2}\frac{(1-\nu_i)R_F + \nu_i R_D/3}{2\pi a_M G_i},\qquad
//!   C_{minor} = \sum_{i=1,2}\frac{R_F - \nu_i R_D/3}{2\pi a_M G_i},$$
//!
//! i.e. Mindlin's `[K - nu (E - (1-e²)K)/e²]` and `[K - nu (K - E)/e²]` written without
//! cancellation. For a circle both equal `(2-nu)/(8 a G)` per body, so
//! `C = 1/(8 a G*)` with [`crate::material::effective_shear_modulus`] and
//! `delta = 3 mu P/(16 a G*) [1 - (1 - x)^{2/3}]` (Johnson 1985 §7.2). For a force at
//! an angle `psi` to `x`, `C = C_x cos² psi + C_y sin² psi` is the compliance along `Q`.
//!
//! The energy dissipated per cycle of an oscillation `Q = ±Q*` (Masing loop, below) is
//!
//! $$W = \tfrac{36}{5}\,\mu^2P^2C\Big[1 - (1-x)^{5/3} - \tfrac{5x}{6}\big(1 + (1-x)^{2/3}\big)\Big]
//!   = \tfrac{6}{5}\,\mu^2P^2C\,t^3(5 - 5t + t^2),\quad t = 1 - (1-x)^{1/3},$$
//!
//! for a circle `W = 9 mu² P²/(10 a G*) [...]` (Johnson 1985 §7.3, eq. 7.67 as cited in
//! issue 5), and
//! `W -> Q*³ C/(3 mu P)` `= Q*³/(36 a G* mu P)` for small amplitudes (`W ∝ P*³`, Johnson (1982)
//! eq. 33). The second form is free of cancellation. Derivations: `docs/tangential.md`.
//!
//! # Loading history (Mindlin-Deresiewicz)
//! [`MindlinHistory`] follows an arbitrary history of `Q` (or of the displacement) at
//! constant `P`: after a reversal at `(Q_r, delta_r)` the path is
//! `delta = delta_r + 2 f((Q - Q_r)/2)` with `f` the virgin curve above (Masing's rule;
//! the new counter-slip annulus has `a''/a = (1 - |Q - Q_r|/(2 mu P))^{1/3}`). A branch
//! that reaches the reversal point before the last one closes that loop and the earlier
//! branch continues (reversal memory); the first branch after virgin loading rejoins the
//! virgin curve at `-Q_r`. Under displacement control a displacement beyond the slip
//! limit makes the contact slide at `|Q| = mu P`.
//!
//! # Assumptions
//! Hertz contact of elastic half-spaces, Coulomb friction, constant normal force, no
//! normal-tangential coupling (beta = 0), traction in the slip annulus parallel to `Q`
//! (Cattaneo-Mindlin approximation; exact for the circle with nu = 0).
//!
//! # References
//! - Cattaneo (1938), Rend. Accad. Naz. Lincei 27, 342-348, 434-436, 474-478.
//! - Mindlin (1949), "Compliance of elastic bodies in contact", J. Appl. Mech. 16, 259-268.
//! - Mindlin & Deresiewicz (1953), "Elastic spheres in contact under varying oblique
//!   forces", J. Appl. Mech. 20, 327-344.
//! - Johnson (1982), eqs (30)-(33).
//! - Thesis "Study of the traction curves", eqs (2.15)-(2.18).
//! - Johnson, *Contact Mechanics* (1985), §7.2 (partial slip, compliance) and §7.3
//!   (oscillating forces, energy per cycle).

use super::{ContactEllipse, check_friction};
use crate::error::{Error, Result};
use crate::material::ElasticMaterial;
use crate::units::{Megapascal, Millimetre, Newton, NewtonMillimetre, Radian};
use std::f64::consts::PI;

/// A Hertz contact with friction under a tangential force in a fixed direction: the
/// Cattaneo-Mindlin solution (see the module docs).
///
/// # Example
/// Sphere (R = 10 mm) on flat, steel, 500 N, mu = 0.3: compliance and energy per cycle
/// against the circular closed forms.
/// ```
/// use kontakt::{hertz::{HertzPointContact, PointGeometry}, material::*};
/// use kontakt::tangential::{ContactEllipse, EllipseAxis, Mindlin};
/// let s = ElasticMaterial::STEEL;
/// let sol = HertzPointContact::new(PointGeometry::sphere_on_flat(10.0)?, s, s)?.solve_force(500.0)?;
/// let m = Mindlin::new(ContactEllipse::from_hertz(&sol, EllipseAxis::Major)?, s, s, 0.3)?;
/// let (a, g) = (sol.semi_axes[0], effective_shear_modulus(&s, &s));
/// assert!((m.no_slip_compliance() * 8.0 * a * g - 1.0).abs() < 1e-12);
/// let w = m.dissipated_energy_per_cycle(150.0)?; // full amplitude: x = 1
/// assert!((w / (9.0 * 150.0f64.powi(2) / (10.0 * a * g) / 6.0) - 1.0).abs() < 1e-12);
/// # Ok::<(), kontakt::Error>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct Mindlin {
    ellipse: ContactEllipse,
    friction: f64,
    direction: Radian,
    /// No-slip compliance for a force along x and along y \[mm/N\].
    axis_compliance: [f64; 2],
}

impl Mindlin {
    /// Plan the contact: the ellipse (from [`crate::hertz`]), the two materials and the
    /// friction coefficient `mu` \[-\] (finite, > 0). The tangential force acts along `x`
    /// unless [`with_load_direction`](Self::with_load_direction) says otherwise.
    ///
    /// # Errors
    /// [`Error::InvalidInput`] naming `friction_coefficient` or `materials` (two rigid
    /// bodies).
    pub fn new(
        ellipse: ContactEllipse,
        body1: ElasticMaterial,
        body2: ElasticMaterial,
        mu: f64,
    ) -> Result<Self> {
        let friction = check_friction(mu)?;
        let [m1, m2] = super::check_materials(&body1, &body2)?;
        let (a, b) = (ellipse.a(), ellipse.b());
        let (major, minor) = if a >= b { (a, b) } else { (b, a) };
        let y = (minor / major).powi(2);
        let (rf, rd) = if y == 1.0 {
            (0.5 * PI, 0.75 * PI)
        } else {
            let map = |what: &'static str| {
                move |msg: &'static str| {
                    Error::invalid(what, format!("y = {y} ({msg})"), "0 < (b/a)^2 <= 1")
                }
            };
            (
                ellip::elliprf(0.0, y, 1.0).map_err(map("elliprf"))?,
                ellip::elliprd(0.0, y, 1.0).map_err(map("elliprd"))?,
            )
        };
        let mut c_major = 0.0;
        let mut c_minor = 0.0;
        for m in [m1, m2] {
            let g = m.shear_modulus();
            if g.is_infinite() {
                continue;
            }
            let nu = m.poisson_ratio();
            let k = 1.0 / (2.0 * PI * major * g);
            c_major += k * ((1.0 - nu) * rf + nu * rd / 3.0);
            c_minor += k * (rf - nu * rd / 3.0);
        }
        let axis_compliance = if a >= b {
            [c_major, c_minor]
        } else {
            [c_minor, c_major]
        };
        Ok(Mindlin {
            ellipse,
            friction,
            direction: 0.0,
            axis_compliance,
        })
    }

    /// The same contact with the tangential force at the angle `angle` \[rad\] (finite)
    /// from `x`.
    ///
    /// # Errors
    /// [`Error::InvalidInput`] naming `load_direction`.
    pub fn with_load_direction(mut self, angle: Radian) -> Result<Self> {
        if !angle.is_finite() {
            return Err(Error::invalid(
                "load_direction",
                angle,
                "a finite angle [rad]",
            ));
        }
        self.direction = angle;
        Ok(self)
    }

    /// The contact ellipse.
    pub fn ellipse(&self) -> &ContactEllipse {
        &self.ellipse
    }
    /// Friction coefficient `mu` \[-\].
    pub fn friction_coefficient(&self) -> f64 {
        self.friction
    }
    /// Direction of the tangential force, angle from `x` \[rad\].
    pub fn load_direction(&self) -> Radian {
        self.direction
    }
    /// Limiting friction force `mu P` \[N\].
    pub fn limit_force(&self) -> Newton {
        self.friction * self.ellipse.normal_force()
    }

    /// No-slip compliances `[C_x, C_y]` \[mm/N\] for a force along `x` and along `y`.
    pub fn axis_compliances(&self) -> [f64; 2] {
        self.axis_compliance
    }

    /// No-slip compliance along the load direction, `C = C_x cos² psi + C_y sin² psi`
    /// \[mm/N\]: the initial slope `d delta/dQ` of the force-displacement curve.
    pub fn no_slip_compliance(&self) -> f64 {
        let (s, c) = self.direction.sin_cos();
        self.axis_compliance[0] * c * c + self.axis_compliance[1] * s * s
    }

    /// Displacement along the load direction at the onset of gross slip,
    /// `delta_s = 3 mu P C/2` \[mm\].
    pub fn slip_displacement(&self) -> Millimetre {
        1.5 * self.limit_force() * self.no_slip_compliance()
    }

    /// Check a tangential force: finite and `|Q| <= mu P`; returns `x = |Q|/(mu P)`.
    fn load_fraction(&self, q: Newton) -> Result<f64> {
        let limit = self.limit_force();
        if !(q.is_finite() && q.abs() <= limit) {
            return Err(Error::invalid(
                "tangential_force",
                q,
                format!("|Q| <= mu P = {limit} N"),
            ));
        }
        Ok(q.abs() / limit)
    }

    /// Stick-zone ratio `a'/a = b'/b = (1 - |Q|/(mu P))^(1/3)` \[-\] under monotone loading
    /// to the tangential force `q` \[N\].
    ///
    /// # Errors
    /// [`Error::InvalidInput`] naming `tangential_force` unless `|q| <= mu P`.
    pub fn stick_ratio(&self, q: Newton) -> Result<f64> {
        Ok(1.0 - t_of(self.load_fraction(q)?))
    }

    /// Semi-axes `[a', b']` \[mm\] of the stick ellipse at the tangential force `q` \[N\].
    ///
    /// # Errors
    /// As [`stick_ratio`](Self::stick_ratio).
    pub fn stick_semi_axes(&self, q: Newton) -> Result<[Millimetre; 2]> {
        let r = self.stick_ratio(q)?;
        Ok([r * self.ellipse.a(), r * self.ellipse.b()])
    }

    /// Tangential displacement \[mm\] along the load direction under monotone loading
    /// from zero to `q` \[N\] (signed like `q`), `delta = 3 mu P C/2 [1 - (1 - x)^(2/3)]`.
    ///
    /// # Errors
    /// As [`stick_ratio`](Self::stick_ratio).
    pub fn displacement(&self, q: Newton) -> Result<Millimetre> {
        self.load_fraction(q)?;
        Ok(self.virgin(q))
    }

    /// The displacement vector `[delta_x, delta_y]` \[mm\] of the stick zone for the
    /// force `q` \[N\] along the load direction; it is not parallel to the force when
    /// `C_x != C_y`.
    ///
    /// # Errors
    /// As [`stick_ratio`](Self::stick_ratio).
    pub fn displacement_vector(&self, q: Newton) -> Result<[Millimetre; 2]> {
        let x = self.load_fraction(q)?;
        let t = t_of(x);
        let scale = q.signum() * 1.5 * self.limit_force() * t * (2.0 - t);
        let (s, c) = self.direction.sin_cos();
        Ok([
            scale * self.axis_compliance[0] * c,
            scale * self.axis_compliance[1] * s,
        ])
    }

    /// The tangential force \[N\] that produces the displacement `delta` \[mm\] under
    /// monotone loading, `Q = mu P [1 - (1 - delta/delta_s)^(3/2)]` (the thesis' eq. 2.18).
    ///
    /// # Errors
    /// [`Error::InvalidInput`] naming `displacement` unless `|delta| <= delta_s`
    /// ([`slip_displacement`](Self::slip_displacement)).
    pub fn force_from_displacement(&self, delta: Millimetre) -> Result<Newton> {
        let ds = self.slip_displacement();
        if !(delta.is_finite() && delta.abs() <= ds) {
            return Err(Error::invalid(
                "displacement",
                delta,
                format!("|delta| <= 3 mu P C/2 = {ds} mm (gross slip beyond)"),
            ));
        }
        Ok(self.virgin_inverse(delta))
    }

    /// Tangential traction \[MPa\] along the load direction at `(x, y)` \[mm\] after
    /// monotone loading to `q` \[N\] (Johnson (1982) eq. 31); zero outside the contact.
    ///
    /// # Errors
    /// As [`stick_ratio`](Self::stick_ratio).
    pub fn traction_at(&self, q: Newton, x: Millimetre, y: Millimetre) -> Result<Megapascal> {
        let r = self.stick_ratio(q)?;
        Ok(q.signum() * (self.hertz_like(1.0, x, y) - self.hertz_like(r, x, y)))
    }

    /// Energy dissipated per cycle \[N·mm\] of an oscillating tangential force
    /// `Q = ±amplitude` \[N\], `0 <= amplitude <= mu P`, at constant `P` (module docs).
    ///
    /// # Errors
    /// [`Error::InvalidInput`] naming `tangential_force` unless `0 <= amplitude <= mu P`.
    pub fn dissipated_energy_per_cycle(&self, amplitude: Newton) -> Result<NewtonMillimetre> {
        if amplitude < 0.0 {
            return Err(Error::invalid(
                "tangential_force",
                amplitude,
                "an amplitude 0 <= Q* <= mu P",
            ));
        }
        let t = t_of(self.load_fraction(amplitude)?);
        let mp = self.limit_force();
        Ok(1.2 * mp * mp * self.no_slip_compliance() * t * t * t * (5.0 - t * (5.0 - t)))
    }

    /// A loading history that starts unloaded (`Q = 0`, `delta = 0`) on this contact.
    pub fn history(&self) -> MindlinHistory {
        MindlinHistory {
            contact: *self,
            virgin: true,
            turning: Vec::new(),
            force: 0.0,
            displacement: 0.0,
            direction: 0.0,
        }
    }

    /// The virgin curve `f(Q)`, odd, for `|Q| <= mu P` \[mm\].
    fn virgin(&self, q: Newton) -> Millimetre {
        let x = (q.abs() / self.limit_force()).min(1.0);
        let t = t_of(x);
        q.signum() * self.slip_displacement() * t * (2.0 - t)
    }

    /// Inverse of the virgin curve for `|delta| <= delta_s` \[N\].
    fn virgin_inverse(&self, delta: Millimetre) -> Newton {
        let r = (delta.abs() / self.slip_displacement()).min(1.0);
        // 1 - (1 - r)^(3/2), without cancellation for small r.
        let s = -f64::exp_m1(1.5 * f64::ln_1p(-r));
        delta.signum() * self.limit_force() * s
    }

    /// `mu p0 r sqrt(1 - x²/(r a)² - y²/(r b)²)` inside the scaled ellipse, else 0.
    fn hertz_like(&self, r: f64, x: Millimetre, y: Millimetre) -> Megapascal {
        if r <= 0.0 {
            return 0.0;
        }
        let s = (x / (r * self.ellipse.a())).powi(2) + (y / (r * self.ellipse.b())).powi(2);
        if s < 1.0 {
            self.friction * self.ellipse.max_pressure() * r * (1.0 - s).sqrt()
        } else {
            0.0
        }
    }
}

/// `t = 1 - (1 - x)^(1/3)` for `0 <= x <= 1`, accurate for small `x`.
fn t_of(x: f64) -> f64 {
    if x >= 1.0 {
        1.0
    } else {
        -f64::exp_m1(f64::ln_1p(-x) / 3.0)
    }
}

/// The state of a [`Mindlin`] contact along an arbitrary tangential loading history at
/// constant normal force (Mindlin-Deresiewicz with Masing's rules; module docs).
///
/// Drive it with [`apply_force`](Self::apply_force) (force control, `|Q| <= mu P`) or
/// [`apply_displacement`](Self::apply_displacement) (displacement control, gross slip
/// allowed). Each call treats the path from the current state to the new value as
/// monotone, so sample a history finely enough to catch its reversals.
///
/// # Example
/// One full cycle `0 -> Q* -> -Q* -> Q*`: the loop area `∮ Q d delta` equals the
/// closed-form energy per cycle.
/// ```
/// use kontakt::{material::ElasticMaterial, tangential::{ContactEllipse, Mindlin}};
/// let s = ElasticMaterial::STEEL;
/// let m = Mindlin::new(ContactEllipse::new(0.2, 0.2, 300.0)?, s, s, 0.25)?;
/// let mut h = m.history();
/// h.apply_force(50.0)?;
/// let (mut area, mut last) = (0.0, (h.force(), h.displacement()));
/// for i in 1..=4000 {
///     let q = 50.0 * (std::f64::consts::PI * i as f64 / 2000.0).cos();
///     let d = h.apply_force(q)?;
///     area += 0.5 * (q + last.0) * (d - last.1);
///     last = (q, d);
/// }
/// let w = m.dissipated_energy_per_cycle(50.0)?;
/// assert!((area / w - 1.0).abs() < 1e-4);
/// # Ok::<(), kontakt::Error>(())
/// ```
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct MindlinHistory {
    contact: Mindlin,
    /// The base of the history is the virgin curve (no gross slip yet).
    virgin: bool,
    /// Reversal points `[Q, delta]`, oldest first. Without `virgin`, the first one is the
    /// point where the contact last stopped sliding.
    turning: Vec<[f64; 2]>,
    force: Newton,
    displacement: Millimetre,
    /// Direction of the current branch: +1, -1, or 0 before the first movement.
    direction: f64,
}

impl MindlinHistory {
    /// The contact this history runs on.
    pub fn contact(&self) -> &Mindlin {
        &self.contact
    }
    /// Current tangential force \[N\] along the load direction.
    pub fn force(&self) -> Newton {
        self.force
    }
    /// Current displacement \[mm\] along the load direction.
    pub fn displacement(&self) -> Millimetre {
        self.displacement
    }
    /// The reversal points `[Q [N], delta [mm]]` still remembered, oldest first.
    pub fn reversal_points(&self) -> &[[f64; 2]] {
        &self.turning
    }
    /// Whether the contact is sliding (`|Q| = mu P` reached under displacement control,
    /// or at the end of a branch that reached `|Q| = mu P`).
    pub fn is_sliding(&self) -> bool {
        !self.virgin && self.turning.is_empty()
    }
    /// Back to the unloaded virgin state.
    pub fn reset(&mut self) {
        *self = self.contact.history();
    }

    /// Ratio `a''/a` \[-\] of the current stick zone: `(1 - |Q|/(mu P))^(1/3)` on the
    /// virgin curve, `(1 - |Q - Q_r|/(2 mu P))^(1/3)` after the reversal at `Q_r`, zero
    /// when sliding.
    pub fn stick_ratio(&self) -> f64 {
        let mp = self.contact.limit_force();
        match self.turning.last() {
            None if self.virgin => 1.0 - t_of(self.force.abs() / mp),
            None => 0.0,
            Some(t) => 1.0 - t_of((self.force - t[0]).abs() / (2.0 * mp)),
        }
    }

    /// Tangential traction \[MPa\] along the load direction at `(x, y)` \[mm\] in the
    /// current state: the superposition of the virgin traction (or the full-slip traction
    /// after gross slip) and one counter-slip term `±2 (H(a) - H(a''))` per branch.
    pub fn traction_at(&self, x: Millimetre, y: Millimetre) -> Megapascal {
        let c = &self.contact;
        let mp = c.limit_force();
        let full = c.hertz_like(1.0, x, y);
        let first = self.turning.first().map_or(self.force, |t| t[0]);
        let mut q = if self.virgin {
            first.signum() * (full - c.hertz_like(1.0 - t_of(first.abs() / mp), x, y))
        } else {
            first.signum() * full
        };
        let points = self
            .turning
            .iter()
            .map(|t| t[0])
            .chain(std::iter::once(self.force));
        let mut prev = first;
        for p in points.skip(1) {
            let d = p - prev;
            if d != 0.0 {
                let r = 1.0 - t_of((d.abs() / (2.0 * mp)).min(1.0));
                q += d.signum() * 2.0 * (full - c.hertz_like(r, x, y));
            }
            prev = p;
        }
        q
    }

    /// Move the tangential force monotonically from its current value to `q` \[N\]
    /// (`|q| <= mu P`) and return the new displacement \[mm\].
    ///
    /// # Errors
    /// [`Error::InvalidInput`] naming `tangential_force` unless `|q| <= mu P`; the state
    /// is then unchanged.
    pub fn apply_force(&mut self, q: Newton) -> Result<Millimetre> {
        self.contact.load_fraction(q)?;
        if q == self.force {
            return Ok(self.displacement);
        }
        let d = (q - self.force).signum();
        self.reverse_if_needed(d);
        // Close the loops that this move completes. A branch from the point where the
        // contact stopped sliding ends at the opposite slip limit: remember its end.
        let mut slip_end = None;
        while let Some(target) = self.closing_force() {
            if d * (q - target) >= 0.0 {
                if !self.virgin && self.turning.len() == 1 {
                    slip_end = self.closing_displacement();
                }
                self.pop_loop();
            } else {
                break;
            }
        }
        self.displacement = match self.turning.last() {
            Some(&[qr, dr]) => dr + 2.0 * self.contact.virgin(0.5 * (q - qr)),
            None if self.virgin => self.contact.virgin(q),
            // Sliding (force control cannot move it further): the branch end, or unchanged.
            None => slip_end.unwrap_or(self.displacement),
        };
        self.force = q;
        self.direction = d;
        Ok(self.displacement)
    }

    /// Move the displacement monotonically from its current value to `delta` \[mm\]
    /// (finite) and return the new tangential force \[N\]. Beyond the slip limit the
    /// contact slides at `|Q| = mu P`.
    ///
    /// # Errors
    /// [`Error::InvalidInput`] naming `displacement` for a non-finite value.
    pub fn apply_displacement(&mut self, delta: Millimetre) -> Result<Newton> {
        if !delta.is_finite() {
            return Err(Error::invalid(
                "displacement",
                delta,
                "a finite displacement [mm]",
            ));
        }
        if delta == self.displacement {
            return Ok(self.force);
        }
        let d = (delta - self.displacement).signum();
        self.reverse_if_needed(d);
        while let Some(target) = self.closing_displacement() {
            if d * (delta - target) >= 0.0 {
                self.pop_loop();
            } else {
                break;
            }
        }
        let ds = self.contact.slip_displacement();
        let mp = self.contact.limit_force();
        self.force = match self.turning.last() {
            Some(&[qr, dr]) => qr + 2.0 * self.contact.virgin_inverse(0.5 * (delta - dr)),
            None if self.virgin && delta.abs() <= ds => self.contact.virgin_inverse(delta),
            None => {
                // Gross slip: from the virgin curve beyond delta_s, or continued sliding.
                self.virgin = false;
                d * mp
            }
        };
        self.displacement = delta;
        self.direction = d;
        Ok(self.force)
    }

    /// Push the current point as a reversal point if a move in direction `d` reverses
    /// the current branch.
    fn reverse_if_needed(&mut self, d: f64) {
        let current = if self.turning.is_empty() {
            // Virgin curve or sliding: the branch runs away from zero.
            self.force.signum()
        } else {
            self.direction
        };
        if current != 0.0 && d != current {
            self.turning.push([self.force, self.displacement]);
        }
    }

    /// The force at which the current branch closes its loop, if it has a reversal point.
    fn closing_force(&self) -> Option<Newton> {
        match self.turning.as_slice() {
            [] => None,
            [only] => Some(-only[0]),
            [.., before, _] => Some(before[0]),
        }
    }

    /// The displacement at which the current branch closes its loop.
    fn closing_displacement(&self) -> Option<Millimetre> {
        match self.turning.as_slice() {
            [] => None,
            // The branch from the first reversal point ends at -Q_r on the virgin curve
            // (or at the opposite slip limit after gross slip).
            [only] => Some(only[1] - 2.0 * self.contact.virgin(only[0])),
            [.., before, _] => Some(before[1]),
        }
    }

    /// Forget the innermost loop: one point if it is the first one, else two.
    fn pop_loop(&mut self) {
        if self.turning.len() == 1 {
            self.turning.clear();
        } else {
            self.turning.truncate(self.turning.len() - 2);
        }
    }
}
