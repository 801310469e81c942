//! Tangential contact: Cattaneo-Mindlin partial slip (with Mindlin-Deresiewicz loading
//! history), Carter's two-dimensional creep curve, Kalker's linear creep theory and
//! Kalker's FASTSIM algorithm, with a common [`TractionCurve`] interface for traction
//! curves.
//!
//! # Conventions
//! These add to the crate-level *Conventions* (mm, N, MPa, rad).
//!
//! **Frame.** The contact ellipse lies in the `x, y` plane of the contact frame with its
//! semi-axis `a` along `x` and `b` along `y` ([`ContactEllipse`]). For rolling, `x` is the
//! *rolling direction*: the contact moves in `+x` over both surfaces, so material enters
//! the contact at the leading edge `x = +a` and leaves it at the trailing edge `x = -a`.
//! `a` may be the major or the minor semi-axis (Kalker's coefficients are tabulated for
//! both, `a/b` from 0.1 to 10).
//!
//! **Creepages** ([`Creepage`]) are Kalker's rigid slip velocities of body 1 relative to
//! body 2, divided by the rolling speed `V` (the mean of the two surface speeds):
//! longitudinal `xi_x = (v1x - v2x)/V` and lateral `xi_y = (v1y - v2y)/V` \[-\], spin
//! `phi = (omega1z - omega2z)/V` \[1/mm\]. The rigid slip at `(x, y)` is
//! `w = (xi_x - phi y, xi_y + phi x)`. For two discs rolling on each other the
//! longitudinal creepage is the *slide-to-roll ratio* `SRR = (u1 - u2)/((u1 + u2)/2)`.
//!
//! **Forces** `Fx`, `Fy` \[N\] and the spin moment `Mz` \[N·mm\] are the tangential
//! tractions acting *on body 1*, integrated over the contact; they oppose the creepage
//! (`Fx = -G c² C11 xi_x` in the linear theory). A **traction curve**
//! ([`TractionCurve`]) reports the normalized force `F_T/(mu F_N)` with `F_T = -Fx`,
//! i.e. positive for a positive creepage and bounded by 1.
//!
//! **Moduli.** Mindlin's compliance uses the two bodies' `G_i, nu_i` separately (its
//! circular limit is `1/(8 a G*)` with [`crate::material::effective_shear_modulus`]).
//! Kalker's theory uses the combined `G` and `nu` of [`KalkerMaterial`]. Carter's curve
//! uses `E*` ([`crate::material::effective_modulus`]). The normal-tangential coupling of
//! dissimilar materials (Dundurs' beta, Johnson (1982) eq. 35) is neglected throughout, as in
//! all four theories.
//!
//! # Models
//! | item | what | source |
//! |---|---|---|
//! | [`mindlin::Mindlin`] | stick zone, traction, compliance, energy per cycle of a Hertz ellipse under `Q < mu P` | Johnson (1982) eqs 30-33; Mindlin (1949); Johnson (1985) §7.2 |
//! | [`mindlin::MindlinHistory`] | arbitrary `Q(t)` or `delta(t)` history with Masing reversal memory and gross slip | Mindlin & Deresiewicz (1953) |
//! | [`carter::Carter`] | 2D rolling creep curve of a line contact, closed form | Carter (1926); the thesis' eq. 3.8; Johnson (1985) §8.3 |
//! | [`kalker`] | Kalker's creepage coefficients `C11, C22, C23` (Table E.3) and linear creep forces | Kalker (1967; 1990, Table E.3) |
//! | [`fastsim::Fastsim`] | Kalker's simplified theory by strip marching: forces, adhesion area, traction field | Kalker (1982) |
//!
//! The derivations, the readings of formulas garbled in the sources' text and the validation table
//! are in `docs/tangential.md`.
//!
//! # Example
//! A steel ball (R = 10 mm) on a flat, 500 N, mu = 0.3, tangential force 90 N:
//! ```
//! use kontakt::{hertz::{HertzPointContact, PointGeometry}, material::ElasticMaterial};
//! use kontakt::tangential::{ContactEllipse, EllipseAxis, mindlin::Mindlin};
//! let steel = ElasticMaterial::STEEL;
//! let hertz = HertzPointContact::new(PointGeometry::sphere_on_flat(10.0)?, steel, steel)?;
//! let ellipse = ContactEllipse::from_hertz(&hertz.solve_force(500.0)?, EllipseAxis::Major)?;
//! let contact = Mindlin::new(ellipse, steel, steel, 0.3)?;
//! // stick radius a'/a = (1 - Q/(mu P))^(1/3) = 0.4^(1/3)
//! assert!((contact.stick_ratio(90.0)? - 0.4f64.cbrt()).abs() < 1e-12);
//! # Ok::<(), kontakt::Error>(())
//! ```
//!
//! # References
//! - Johnson (1982), "One hundred years of Hertz contact", Proc. IMechE 196, §6.
//! - Master thesis "Study of the traction curves", eqs 2.15-2.18 and 3.8.
//! - Johnson, *Contact Mechanics* (1985), §§7.2-7.3, 8.3-8.4.
//! - Kalker, *Three-dimensional elastic bodies in rolling contact* (1990), Table E.3.
//! - Kalker (1982), "A fast algorithm for the simplified theory of rolling contact",
//!   Vehicle System Dynamics 11, 1-13. doi:10.1080/00423118208968684

use crate::error::{Error, Result, positive_as};
use crate::hertz::HertzPointSolution;
use crate::material::ElasticMaterial;
use crate::units::{Megapascal, Millimetre, Newton};
use std::f64::consts::PI;

pub mod carter;
pub mod fastsim;
pub mod kalker;
pub mod mindlin;

pub use carter::Carter;
pub use fastsim::{Fastsim, FastsimField, FastsimOptions, FastsimSolution, PressureShape};
pub use kalker::{CreepCoefficients, KalkerLinear, KalkerMaterial, creep_coefficients};
pub use mindlin::{Mindlin, MindlinHistory};

/// Which semi-axis of a Hertz contact ellipse lies along the tangential `x` direction (the
/// rolling direction, or the direction of the tangential force).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
#[cfg_attr(feature = "serde", serde(rename_all = "snake_case"))]
pub enum EllipseAxis {
    /// `x` along the major semi-axis: `a >= b`.
    Major,
    /// `x` along the minor semi-axis: `a <= b`.
    Minor,
}

/// A Hertz contact ellipse as the tangential models see it: semi-axis `a` \[mm\] along the
/// tangential `x` direction, `b` \[mm\] along `y`, and the normal force `P` \[N\], with
/// the Hertz pressure $p = p_0\sqrt{1 - x^2/a^2 - y^2/b^2}$, $p_0 = 3P/(2\pi a b)$.
///
/// Build it from a [`HertzPointSolution`] with [`from_hertz`](Self::from_hertz) (the normal
/// problem is solved by [`crate::hertz`], not here) or from given semi-axes with
/// [`new`](Self::new).
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct ContactEllipse {
    a: Millimetre,
    b: Millimetre,
    normal_force: Newton,
}

impl ContactEllipse {
    /// An ellipse from its semi-axes `a` (along `x`) and `b` (along `y`) \[mm\], both
    /// finite and > 0, and the normal force `normal_force` \[N\], finite and > 0.
    ///
    /// # Errors
    /// [`Error::InvalidInput`] naming `semi_axes[0]`, `semi_axes[1]` or `normal_force`.
    pub fn new(a: Millimetre, b: Millimetre, normal_force: Newton) -> Result<Self> {
        positive_as("semi_axes[0]", a, "a finite semi-axis > 0 mm")?;
        positive_as("semi_axes[1]", b, "a finite semi-axis > 0 mm")?;
        positive_as("normal_force", normal_force, "a finite force > 0 N")?;
        Ok(ContactEllipse { a, b, normal_force })
    }

    /// The ellipse of a Hertz solution, with `x_axis` saying whether the tangential `x`
    /// direction runs along its major or its minor semi-axis.
    ///
    /// # Errors
    /// Only if the solution holds non-finite values (it cannot when it comes from
    /// [`crate::hertz::HertzPointContact`]).
    pub fn from_hertz(solution: &HertzPointSolution, x_axis: EllipseAxis) -> Result<Self> {
        let [major, minor] = solution.semi_axes;
        match x_axis {
            EllipseAxis::Major => Self::new(major, minor, solution.force),
            EllipseAxis::Minor => Self::new(minor, major, solution.force),
        }
    }

    /// Semi-axis `a` along `x` \[mm\].
    pub fn a(&self) -> Millimetre {
        self.a
    }
    /// Semi-axis `b` along `y` \[mm\].
    pub fn b(&self) -> Millimetre {
        self.b
    }
    /// Normal force `P` \[N\].
    pub fn normal_force(&self) -> Newton {
        self.normal_force
    }
    /// Kalker's mean semi-axis `c = sqrt(a b)` \[mm\].
    pub fn mean_semi_axis(&self) -> Millimetre {
        (self.a * self.b).sqrt()
    }
    /// Axis ratio `a/b` [-] (may exceed 1).
    pub fn axis_ratio(&self) -> f64 {
        self.a / self.b
    }
    /// Hertz maximum pressure `p0 = 3P/(2 pi a b)` \[MPa\].
    pub fn max_pressure(&self) -> Megapascal {
        1.5 * self.normal_force / (PI * self.a * self.b)
    }
    /// Contact area `pi a b` \[mm²\].
    pub fn area(&self) -> f64 {
        PI * self.a * self.b
    }
    /// Hertz pressure \[MPa\] at `(x, y)` \[mm\]; zero outside the ellipse.
    pub fn pressure_at(&self, x: Millimetre, y: Millimetre) -> Megapascal {
        let r2 = (x / self.a).powi(2) + (y / self.b).powi(2);
        if r2 < 1.0 {
            self.max_pressure() * (1.0 - r2).sqrt()
        } else {
            0.0
        }
    }
}

/// The creepages of a rolling contact (see the module *Conventions*): longitudinal
/// `xi_x` \[-\], lateral `xi_y` \[-\] and spin `phi` \[1/mm\].
#[derive(Debug, Clone, Copy, PartialEq, Default)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct Creepage {
    /// Longitudinal creepage `xi_x` \[-\] (slide-to-roll ratio for pure rolling along `x`).
    pub longitudinal: f64,
    /// Lateral creepage `xi_y` \[-\].
    pub lateral: f64,
    /// Spin creepage `phi` \[1/mm\].
    pub spin: f64,
}

impl Creepage {
    /// Pure longitudinal creepage `xi_x` \[-\].
    pub fn longitudinal(xi_x: f64) -> Self {
        Creepage {
            longitudinal: xi_x,
            ..Creepage::default()
        }
    }

    /// Check that every component is finite.
    ///
    /// # Errors
    /// [`Error::InvalidInput`] naming `creepage.longitudinal`, `creepage.lateral` or
    /// `creepage.spin`.
    pub fn validate(&self) -> Result<()> {
        for (field, v, unit) in [
            (
                "creepage.longitudinal",
                self.longitudinal,
                "a finite creepage [-]",
            ),
            ("creepage.lateral", self.lateral, "a finite creepage [-]"),
            ("creepage.spin", self.spin, "a finite spin creepage [1/mm]"),
        ] {
            if !v.is_finite() {
                return Err(Error::invalid(field, v, unit));
            }
        }
        Ok(())
    }
}

/// A model that gives a traction curve: the normalized tangential force
/// `F_T/(mu F_N)` \[-\] against the longitudinal creepage `xi` \[-\] (the slide-to-roll
/// ratio when the bodies roll along `x`).
///
/// `F_T` is the tangential force on body 1 that opposes the creepage, so the curve is odd,
/// positive for `xi > 0`, and bounded by 1 for the models with friction saturation
/// ([`Carter`], [`Fastsim`]). [`KalkerLinear`] is the linear theory: its curve is the
/// straight line `G c² C11 xi/(mu F_N)` and is *not* clipped at 1 (its meaning ends where
/// it reaches 1, at [`KalkerLinear::saturation_creepage`]; the CLI draws it up to there).
///
/// Further models (for example a rough-surface traction model) can implement this trait
/// and be plotted by `kontakt traction` alongside.
///
/// `Send + Sync`: a curve is a planned model, evaluated read-only from many threads (a
/// sweep, a multi-body simulation).
pub trait TractionCurve: Send + Sync {
    /// A short, stable model name (`carter`, `kalker_linear`, `fastsim`, ...).
    fn name(&self) -> &'static str;

    /// The normalized tangential force `F_T/(mu F_N)` \[-\] at the longitudinal creepage
    /// `creepage` \[-\].
    ///
    /// # Errors
    /// [`Error::InvalidInput`] naming `creepage` for a non-finite creepage.
    fn normalized_force(&self, creepage: f64) -> Result<f64>;

    /// The curve at every creepage of `creepages` \[-\].
    ///
    /// # Errors
    /// As [`normalized_force`](Self::normalized_force), for the first bad creepage.
    fn traction_curve(&self, creepages: &[f64]) -> Result<Vec<f64>> {
        creepages
            .iter()
            .map(|&xi| self.normalized_force(xi))
            .collect()
    }
}

/// Check a friction coefficient: finite and > 0.
pub fn check_friction(mu: f64) -> Result<f64> {
    positive_as(
        "friction_coefficient",
        mu,
        "a finite friction coefficient mu > 0",
    )
}

/// Check a scalar creepage: finite.
pub fn check_creepage(creepage: f64) -> Result<f64> {
    if creepage.is_finite() {
        Ok(creepage)
    } else {
        Err(Error::invalid(
            "creepage",
            creepage,
            "a finite creepage [-]",
        ))
    }
}

/// The pair of materials as an array, checking that at least one body is elastic.
pub(crate) fn check_materials(
    body1: &ElasticMaterial,
    body2: &ElasticMaterial,
) -> Result<[ElasticMaterial; 2]> {
    if body1.youngs_modulus().is_infinite() && body2.youngs_modulus().is_infinite() {
        return Err(Error::invalid(
            "materials",
            "two rigid bodies",
            "at least one elastic body (finite Young's modulus)",
        ));
    }
    Ok([*body1, *body2])
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn ellipse_validation_and_pressure() {
        assert_eq!(
            ContactEllipse::new(0.0, 1.0, 1.0).unwrap_err().field(),
            Some("semi_axes[0]")
        );
        assert_eq!(
            ContactEllipse::new(1.0, f64::NAN, 1.0).unwrap_err().field(),
            Some("semi_axes[1]")
        );
        assert_eq!(
            ContactEllipse::new(1.0, 1.0, 0.0).unwrap_err().field(),
            Some("normal_force")
        );
        let e = ContactEllipse::new(0.4, 0.2, 100.0).unwrap();
        assert!((e.pressure_at(0.0, 0.0) - 1.5 * 100.0 / (PI * 0.08)).abs() < 1e-9);
        assert_eq!(e.pressure_at(0.4, 0.0), 0.0);
        assert!((e.mean_semi_axis() - 0.08f64.sqrt()).abs() < 1e-15);
    }

    #[test]
    fn creepage_validation() {
        assert!(Creepage::longitudinal(0.01).validate().is_ok());
        let bad = Creepage {
            spin: f64::NAN,
            ..Creepage::default()
        };
        assert_eq!(bad.validate().unwrap_err().field(), Some("creepage.spin"));
        assert_eq!(
            check_creepage(f64::INFINITY).unwrap_err().field(),
            Some("creepage")
        );
        assert_eq!(
            check_friction(0.0).unwrap_err().field(),
            Some("friction_coefficient")
        );
    }
}
