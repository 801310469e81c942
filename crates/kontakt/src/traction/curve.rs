//! The asperity model as a traction curve of [`crate::tangential`], and how the creep
//! models of a Hertz contact ellipse are oriented.
//!
//! [`AsperityCurve`] implements [`TractionCurve`]: the normalized tangential force
//! $F_T/(\mu F_N)$ \[-\] of [`AsperityTraction::traction_ratio`] at the slide-to-roll
//! ratio $|\xi|$, extended as an odd function to negative creepage
//! ($F_T(-\xi) = -F_T(\xi)$: reversing the slip reverses the force). [`nominal_of_ellipse`]
//! says when a contact ellipse is the circle the model accepts; [`rolling_axis`] which
//! semi-axis of a Hertz ellipse lies along the rolling direction.

use super::asperity::CIRCULARITY_TOLERANCE;
use super::{AsperityTraction, NominalContact};
use crate::error::Result;
use crate::hertz::HertzPointSolution;
use crate::tangential::{ContactEllipse, EllipseAxis, TractionCurve};

/// Largest |sin| (or |cos|) of the angle between body 1's first principal direction and
/// the major axis of a Hertz ellipse still read as 0 (or 90) degrees by [`rolling_axis`].
pub const AXIS_ALIGNMENT_TOLERANCE: f64 = 1e-9;

/// The asperity micro-slip model ([`AsperityTraction`]) as a [`TractionCurve`] named
/// `asperity`: $F_T/(\mu F_N)(\xi) = \operatorname{sign}(\xi)\,R(|\xi|)$ \[-\] with $R$ the
/// planned model's traction ratio at the slide-to-roll ratio (creepage) $\xi$ \[-\].
///
/// # Assumptions
/// Those of [`AsperityTraction`] (the thesis "Study of the traction curves", §3.1.2.2); the model is defined for
/// $\xi \ge 0$ and is extended as an odd function.
#[derive(Debug, Clone, PartialEq)]
pub struct AsperityCurve(AsperityTraction);

impl AsperityCurve {
    /// The curve of a planned model.
    pub fn new(model: AsperityTraction) -> Self {
        AsperityCurve(model)
    }

    /// The planned model.
    pub fn model(&self) -> &AsperityTraction {
        &self.0
    }
}

impl From<AsperityTraction> for AsperityCurve {
    fn from(model: AsperityTraction) -> Self {
        AsperityCurve(model)
    }
}

impl TractionCurve for AsperityCurve {
    fn name(&self) -> &'static str {
        "asperity"
    }

    /// $\operatorname{sign}(\xi)\,R(|\xi|)$ \[-\] at the creepage `creepage` \[-\].
    ///
    /// # Errors
    /// [`crate::Error::InvalidInput`] naming `creepage` for a non-finite creepage; errors
    /// of [`AsperityTraction::traction_ratio`].
    fn normalized_force(&self, creepage: f64) -> Result<f64> {
        crate::tangential::check_creepage(creepage)?;
        Ok(creepage.signum() * self.0.traction_ratio(creepage.abs())?)
    }
}

/// The asperity model's nominal contact for a contact ellipse: the circle of radius `a`
/// \[mm\] (pressure from the load) when $|a - b|/a \le$ [`CIRCULARITY_TOLERANCE`], else
/// `None` (the model covers circular and line contacts only).
pub fn nominal_of_ellipse(ellipse: &ContactEllipse) -> Option<NominalContact> {
    let circular = ((ellipse.a() - ellipse.b()) / ellipse.a()).abs() <= CIRCULARITY_TOLERANCE;
    circular.then(|| NominalContact::Circular {
        half_width: ellipse.a(),
        max_pressure: None,
    })
}

/// Which semi-axis of the Hertz ellipse of `solution` lies along the rolling direction,
/// taken as body 1's first principal direction: [`EllipseAxis::Major`] for a circle or
/// when the ellipse's orientation (angle from that direction to the major axis \[rad\])
/// has |sin| < [`AXIS_ALIGNMENT_TOLERANCE`], [`EllipseAxis::Minor`] when |cos| is below
/// it; `None` when the rolling direction lies along neither axis (the creep models of
/// [`crate::tangential`] need it along one).
pub fn rolling_axis(solution: &HertzPointSolution) -> Option<EllipseAxis> {
    let (s, c) = solution.orientation.sin_cos();
    if solution.semi_axes[0] == solution.semi_axes[1] || s.abs() < AXIS_ALIGNMENT_TOLERANCE {
        Some(EllipseAxis::Major)
    } else if c.abs() < AXIS_ALIGNMENT_TOLERANCE {
        Some(EllipseAxis::Minor)
    } else {
        None
    }
}

#[cfg(test)]
mod tests {
    #![allow(clippy::unwrap_used)]
    use super::*;
    use crate::hertz::{HertzPointContact, PointGeometry};
    use crate::material::ElasticMaterial;
    use crate::traction::AsperityTractionParams;

    fn model() -> AsperityTraction {
        let nominal = NominalContact::Circular {
            half_width: 0.4,
            max_pressure: None,
        };
        let params = AsperityTractionParams::new(
            nominal,
            680.0,
            0.3,
            ElasticMaterial::STEEL,
            [0.02, 0.02],
            0.05,
        );
        AsperityTraction::new(params).unwrap()
    }

    /// The curve is the model's ratio for ξ >= 0 and odd (both exact); 0 at 0; a
    /// non-finite creepage is an error naming `creepage`.
    #[test]
    fn curve_is_the_odd_extension_of_the_traction_ratio() {
        let m = model();
        let c = AsperityCurve::new(m.clone());
        assert_eq!(c.name(), "asperity");
        for xi in [1e-4, 1e-3, 5e-3, 0.1] {
            let r = m.traction_ratio(xi).unwrap();
            assert!(r > 0.0);
            assert_eq!(c.normalized_force(xi).unwrap(), r);
            assert_eq!(c.normalized_force(-xi).unwrap(), -r);
        }
        assert_eq!(c.normalized_force(0.0).unwrap(), 0.0);
        assert_eq!(
            c.normalized_force(f64::NAN).unwrap_err().field(),
            Some("creepage")
        );
    }

    /// A circle becomes the circular nominal contact of radius a; an ellipse b/a = 0.5
    /// does not.
    #[test]
    fn only_circles_are_nominal_contacts() {
        let circle = ContactEllipse::new(0.3, 0.3, 100.0).unwrap();
        assert_eq!(
            nominal_of_ellipse(&circle),
            Some(NominalContact::Circular {
                half_width: 0.3,
                max_pressure: None
            })
        );
        let ellipse = ContactEllipse::new(0.3, 0.15, 100.0).unwrap();
        assert_eq!(nominal_of_ellipse(&ellipse), None);
    }

    /// Barrel on a flat: the major axis lies along the smaller curvature. Radii [10, 40]
    /// put it across body 1's first direction (rolling along the minor axis), [40, 10]
    /// along it; a second barrel crossed at 45 deg turns the ellipse off both.
    #[test]
    fn rolling_axis_follows_the_orientation() {
        let s = ElasticMaterial::STEEL;
        let axis = |r1: [f64; 2], r2: [f64; 2], angle_deg: f64| {
            let g = PointGeometry::new(r1, r2, angle_deg.to_radians()).unwrap();
            let sol = HertzPointContact::new(g, s, s)
                .unwrap()
                .solve_force(500.0)
                .unwrap();
            rolling_axis(&sol)
        };
        let flat = [f64::INFINITY; 2];
        assert_eq!(axis([10.0, 40.0], flat, 0.0), Some(EllipseAxis::Minor));
        assert_eq!(axis([40.0, 10.0], flat, 0.0), Some(EllipseAxis::Major));
        assert_eq!(axis([10.0, 10.0], flat, 0.0), Some(EllipseAxis::Major));
        assert_eq!(axis([10.0, 40.0], [f64::INFINITY, 20.0], 45.0), None);
    }
}
