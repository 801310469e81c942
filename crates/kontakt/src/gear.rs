//! Deflection of a pair of spur-gear teeth in contact at the pitch point: bending of the
//! teeth as cantilevers plus the contact (Hertz line-contact) deflection
//! (Johnson 1982 §4 eqs 22-24 and Appendix 2, eqs 62-63).
//!
//! # Formulas
//! The load is $P'$, the normal load per unit face width along the line of action
//! \[N/mm\]; both deflections are measured along the line of action and are those of the
//! **pair** (sum of both teeth).
//!
//! **Bending.** A tooth is a cantilever of length $l$, thickness $t$ and face width $b$,
//! in plane strain, loaded at its tip by the component $P'b\cos\phi$ of the load normal to
//! its centreline ($\phi$ the pressure angle): $\delta = Fl^3(1-\nu^2)/(3EI)$,
//! $I = bt^3/12$. Summed over both teeth and projected back on the line of action,
//!
//! $$\delta_B = K\,\frac{P'}{E^*},\qquad K = 4\cos^2\phi\,(l/t)^3 \;\text{(cantilever)},$$
//!
//! independent of the module because $l$ and $t$ scale with it (eq. 62). Johnson takes
//! $K \approx 6$ ([`JOHNSON_BENDING_COEFFICIENT`]) for standard teeth; the bare cantilever
//! ([`cantilever_bending_coefficient`]) gives less (no shear deflection, no rotation of
//! the root), so $K$ is an input.
//!
//! **Contact.** The displacement of the surface of a body under a line load $P'$ relative
//! to a point at depth $h$ below the contact (Johnson 1982 eq. 22, plane strain) is
//! $P'\frac{1-\nu^2}{\pi E}\left[2\ln\frac{h}{a} - \frac{\nu}{1-\nu}\right]$, with the Hertz
//! semi-width $a = 2\sqrt{P'R/(\pi E^*)}$. For the pair,
//!
//! $$\delta_C = \sum_{i=1,2} P'\,\frac{1-\nu_i^2}{\pi E_i}\left[2\ln\frac{h}{a} -
//!   \frac{\nu_i}{1-\nu_i}\right].$$
//!
//! With Johnson's choices $h = \tfrac14\pi m$ (half the tooth thickness, $m$ the module)
//! and $R = 2m$ (1:1 gear, 24 teeth), $h/a = \tfrac{\pi}{8}\sqrt{\pi/2}\,(mE^*/P')^{1/2}
//! = 0.4922\,(mE^*/P')^{1/2}$ and, for one Poisson's ratio $\nu = 0.3$,
//!
//! $$\delta_C = \frac{P'}{\pi E^*}\left[\ln\frac{mE^*}{P'} - 1.846\right].$$
//!
//! Eq. (63) as printed reads $\frac{P'\cos\phi}{E^*}[\ln(mE^*/P') - 1.8]$: the constant
//! agrees, the factor $1/\pi$ is missing (without it the contact deflection would equal
//! the bending one, against the paper's own remark that it is "roughly one-third" of it),
//! and the $\cos\phi$ has no counterpart in eq. (22), of which eq. (63) is the special case.
//! We follow eq. (22); see `docs/impact.md`.
//!
//! # Assumptions
//! Contact at the pitch point, one tooth pair carrying the load, plane strain (wide face),
//! teeth as uniform cantilevers (bending) and as elastic half-planes down to the datum
//! depth $h$ (contact), Hertz line contact ($a \ll h$, checked: $h > a$ is required), no
//! friction, no shear or root-rotation terms unless included in $K$.
//!
//! # References
//! - Johnson (1982), "One hundred years of Hertz contact", Proc. IMechE 196, eqs (22)-(24),
//!   Appendix 2 eqs (62)-(63), Fig. 5.
//! - Johnson, *Contact Mechanics* (1985), §5.8 (line load on a half-plane, datum depth).

use crate::error::{Error, Result, positive_as};
use crate::material::{ElasticMaterial, effective_modulus};
use crate::units::{Megapascal, Millimetre, NewtonPerMillimetre, Radian};
use std::f64::consts::{FRAC_PI_2, PI};

/// Johnson's (1982) bending constant of a pair of standard involute teeth, $K \approx 6$
/// \[-\] (eq. 23 / 62).
pub const JOHNSON_BENDING_COEFFICIENT: f64 = 6.0;

/// The bending deflection of a tooth pair, $\delta_B = KP'/E^*$ \[mm\] (eq. 62).
///
/// # Arguments
/// - `line_load` — $P'$, normal load per unit face width \[N/mm\], finite, > 0.
/// - `e_star` — $E^*$ of the two gears \[MPa\], finite, > 0.
/// - `bending_coefficient` — $K$ \[-\], finite, > 0 ([`JOHNSON_BENDING_COEFFICIENT`] or
///   [`cantilever_bending_coefficient`]).
///
/// # Errors
/// [`Error::InvalidInput`] naming the bad argument.
///
/// # Example
/// ```
/// use kontakt::gear::{bending_deflection, JOHNSON_BENDING_COEFFICIENT};
/// let d = bending_deflection(200.0, 115_384.615, JOHNSON_BENDING_COEFFICIENT)?;
/// assert!((d - 0.0104).abs() < 1e-7);   // mm
/// # Ok::<(), kontakt::Error>(())
/// ```
pub fn bending_deflection(
    line_load: NewtonPerMillimetre,
    e_star: Megapascal,
    bending_coefficient: f64,
) -> Result<Millimetre> {
    positive_as("line_load", line_load, "a finite load per width > 0 N/mm")?;
    positive_as("e_star", e_star, "a finite contact modulus > 0 MPa")?;
    positive_as(
        "bending_coefficient",
        bending_coefficient,
        "a finite constant K > 0",
    )?;
    finite(
        bending_coefficient * line_load / e_star,
        "line_load",
        line_load,
    )
}

/// The bending constant of a pair of teeth modelled as plain cantilevers,
/// $K = 4\cos^2\phi\,(l/t)^3$ \[-\] (module docs).
///
/// # Arguments
/// - `arm` — $l/m$, distance from the root section to the load, in modules \[-\], finite, > 0
///   (about 1.25 to the pitch point of a standard tooth).
/// - `thickness` — $t/m$, thickness of the cantilever in modules \[-\], finite, > 0
///   ($\pi/2$ at the pitch circle of a standard tooth).
/// - `pressure_angle` — $\phi$ \[rad\], in $[0, \pi/2)$.
///
/// # Errors
/// [`Error::InvalidInput`] naming the bad argument.
///
/// # Example
/// ```
/// use kontakt::gear::cantilever_bending_coefficient;
/// let k = cantilever_bending_coefficient(1.0, 1.0, 0.0)?;
/// assert_eq!(k, 4.0);
/// # Ok::<(), kontakt::Error>(())
/// ```
pub fn cantilever_bending_coefficient(
    arm: f64,
    thickness: f64,
    pressure_angle: Radian,
) -> Result<f64> {
    positive_as("arm", arm, "a finite arm l/m > 0 (in modules)")?;
    positive_as(
        "thickness",
        thickness,
        "a finite thickness t/m > 0 (in modules)",
    )?;
    check_pressure_angle(pressure_angle)?;
    let c = pressure_angle.cos();
    finite(4.0 * c * c * (arm / thickness).powi(3), "arm", arm)
}

/// The contact deflection of a pair of bodies in line contact relative to datum points at
/// depth $h$ in each \[mm\] (Johnson 1982 eq. 22 summed over the two bodies; module docs).
///
/// # Arguments
/// - `line_load` — $P'$ \[N/mm\], finite, > 0.
/// - `relative_radius` — $R$, $1/R = 1/R_1 + 1/R_2$ \[mm\], finite, > 0.
/// - `datum_depth` — $h$ \[mm\], finite, > $a$ (the Hertz semi-width).
/// - `body1`, `body2` — the materials (at most one rigid).
///
/// # Errors
/// [`Error::InvalidInput`] naming the bad argument, `materials` for two rigid bodies, or
/// `line_load` when $a \ge h$ (the datum would lie inside the contact stress field).
///
/// # Example
/// ```
/// use kontakt::{gear::contact_deflection, material::ElasticMaterial};
/// let s = ElasticMaterial::STEEL;
/// let d = contact_deflection(200.0, 8.0, std::f64::consts::PI, &s, &s)?;
/// assert!((d - 3.2540e-3).abs() < 1e-7);   // mm
/// # Ok::<(), kontakt::Error>(())
/// ```
pub fn contact_deflection(
    line_load: NewtonPerMillimetre,
    relative_radius: Millimetre,
    datum_depth: Millimetre,
    body1: &ElasticMaterial,
    body2: &ElasticMaterial,
) -> Result<Millimetre> {
    positive_as("line_load", line_load, "a finite load per width > 0 N/mm")?;
    positive_as(
        "relative_radius",
        relative_radius,
        "a finite relative radius > 0 mm",
    )?;
    positive_as("datum_depth", datum_depth, "a finite depth > 0 mm")?;
    let e_star = check_e_star(body1, body2)?;
    let a = 2.0 * (line_load * relative_radius / (PI * e_star)).sqrt();
    if !(a > 0.0 && a < datum_depth) {
        return Err(Error::invalid(
            "line_load",
            line_load,
            "a load whose Hertz semi-width a = 2 sqrt(P'R/(pi E*)) is below the datum depth h",
        ));
    }
    let log2 = 2.0 * (datum_depth / a).ln();
    let body = |m: &ElasticMaterial| {
        let nu = m.poisson_ratio();
        let c = m.compliance(); // (1 - nu^2)/E, 0 for a rigid body
        if c == 0.0 {
            0.0
        } else {
            c / PI * (log2 - nu / (1.0 - nu))
        }
    };
    finite(
        line_load * (body(body1) + body(body2)),
        "line_load",
        line_load,
    )
}

/// The deflections of a tooth pair (plain data), all along the line of action \[mm\].
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct ToothPairDeflection {
    /// $\delta_B = KP'/E^*$ \[mm\].
    pub bending: Millimetre,
    /// $\delta_C$ \[mm\], eq. (22) with $h = \pi m/4$, $R = 2m$.
    pub contact: Millimetre,
    /// $\delta_B + \delta_C$ \[mm\].
    pub total: Millimetre,
    /// Hertz semi-width $a$ of the line contact \[mm\].
    pub half_width: Millimetre,
}

/// The deflection of a pair of standard spur-gear teeth at the pitch point with Johnson's
/// (1982, Appendix 2) choices: datum depth $h = \pi m/4$, relative radius $R = 2m$
/// (1:1 gear with 24 teeth), bending constant $K$.
///
/// # Arguments
/// - `line_load` — $P'$ \[N/mm\], finite, > 0.
/// - `module` — $m$ \[mm\], finite, > 0.
/// - `bending_coefficient` — $K$ \[-\], finite, > 0 (Johnson: 6).
/// - `body1`, `body2` — the materials of the two gears (at most one rigid).
///
/// # Errors
/// As [`bending_deflection`] and [`contact_deflection`] (`module` for a bad module).
///
/// # Example
/// Steel gears, module 4 mm, 200 N/mm: the contact deflection is about one third of the
/// bending deflection, as Johnson remarks.
/// ```
/// use kontakt::{gear::tooth_pair_deflection, material::ElasticMaterial};
/// let s = ElasticMaterial::STEEL;
/// let d = tooth_pair_deflection(200.0, 4.0, 6.0, &s, &s)?;
/// assert!((d.contact / d.bending - 0.31).abs() < 0.01);
/// # Ok::<(), kontakt::Error>(())
/// ```
pub fn tooth_pair_deflection(
    line_load: NewtonPerMillimetre,
    module: Millimetre,
    bending_coefficient: f64,
    body1: &ElasticMaterial,
    body2: &ElasticMaterial,
) -> Result<ToothPairDeflection> {
    positive_as("module", module, "a finite module > 0 mm")?;
    let e_star = check_e_star(body1, body2)?;
    let bending = bending_deflection(line_load, e_star, bending_coefficient)?;
    let r = 2.0 * module;
    let contact = contact_deflection(line_load, r, 0.25 * PI * module, body1, body2)?;
    Ok(ToothPairDeflection {
        bending,
        contact,
        total: bending + contact,
        half_width: 2.0 * (line_load * r / (PI * e_star)).sqrt(),
    })
}

fn check_e_star(body1: &ElasticMaterial, body2: &ElasticMaterial) -> Result<Megapascal> {
    let e_star = effective_modulus(body1, body2);
    if e_star.is_finite() && e_star > 0.0 {
        Ok(e_star)
    } else {
        Err(Error::invalid(
            "materials",
            "two rigid bodies",
            "at least one elastic body (finite Young's modulus)",
        ))
    }
}

fn check_pressure_angle(angle: Radian) -> Result<Radian> {
    if angle.is_finite() && (0.0..FRAC_PI_2).contains(&angle) {
        Ok(angle)
    } else {
        Err(Error::invalid(
            "pressure_angle",
            angle,
            "0 <= pressure angle < pi/2 rad (20 deg = 0.349 rad for standard gears)",
        ))
    }
}

fn finite(x: f64, field: &'static str, value: f64) -> Result<f64> {
    if x.is_finite() {
        Ok(x)
    } else {
        Err(crate::error::overflow(field, value))
    }
}
