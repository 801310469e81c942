//! Closed-form Hertz theory: the exact elliptical and circular point contact, line
//! contact, the classic approximations, subsurface stresses and first yield, impact and
//! JKR adhesion.
//!
//! All functions follow the crate-level *Conventions* (mm, N, MPa; convex radii positive;
//! tension-positive stresses). The analytic solutions here are pure functions with no
//! solver, I/O or plotting dependencies, so that both users and the numerical solvers'
//! tests can call them as references.

pub mod adhesion;
pub mod approximation;
mod elliptic;
pub mod impact;
pub mod line;
pub mod point;
pub mod point_stress;
pub mod subsurface;
pub mod validity;

pub use point::{HertzPointContact, HertzPointSolution, PointGeometry, curvature_ratio};

/// The curvatures `[A, B]` \[1/mm\] of the undeformed gap `h = A x² + B y²` \[mm\] whose
/// frictionless contact under the normal force `force` \[N\] with the contact modulus
/// `e_star` \[MPa\] is the Hertz ellipse of semi-axes `a` along `x` and `b` along `y`
/// \[mm\] (all finite and > 0). Hertz's displacement of the pressure
/// `p0 sqrt(1 − x²/a² − y²/b²)`, `p0 = 3F/(2π a b)`, is quadratic inside the ellipse
/// (Johnson 1985, eq. 3.63); with the major semi-axis `a'`, the minor `b'`, `y = (b'/a')²`
/// and Carlson's `R_F`, `R_D` at `(0, y, 1)`, the curvature along the major axis is
/// `p0 b' R_D/(3 E* a'²)` and along the minor axis `p0 b' (R_F − R_D/3)/(y E* a'²)`.
/// A circle of radius `a` gives `A = B = π p0/(4 E* a) = 1/(2R)`.
///
/// # Errors
/// [`crate::Error::InvalidInput`] only if the axis ratio is not representable.
pub(crate) fn ellipse_gap_curvatures(
    a: f64,
    b: f64,
    force: f64,
    e_star: f64,
) -> crate::error::Result<[f64; 2]> {
    let p0 = 1.5 * force / (std::f64::consts::PI * a * b);
    let (major, minor) = if a >= b { (a, b) } else { (b, a) };
    let y = (minor / major) * (minor / major);
    let (rf, rd) = elliptic::rf_rd(y)?;
    let c = p0 * minor / (e_star * major * major);
    let along_major = c * rd / 3.0;
    let along_minor = c * (rf - rd / 3.0) / y;
    Ok(if a >= b {
        [along_major, along_minor]
    } else {
        [along_minor, along_major]
    })
}

#[cfg(test)]
mod gap_tests {
    #![allow(clippy::unwrap_used)]
    use super::*;

    /// The gap of a Hertz solution's ellipse is the geometry's: `A, B = 1/(2R)` of the
    /// principal relative radii, for a circle and for an ellipse (rounding only).
    #[test]
    fn ellipse_gap_curvatures_invert_hertz() {
        let (r, e_star, f): (f64, f64, f64) = (10.0, 115_384.6, 200.0);
        let a = (3.0 * f * r / (4.0 * e_star)).cbrt();
        let [ca, cb] = ellipse_gap_curvatures(a, a, f, e_star).unwrap();
        assert!((ca * 2.0 * r - 1.0).abs() < 1e-12 && (cb * 2.0 * r - 1.0).abs() < 1e-12);
        // Crossed radii 20 mm and 50 mm (relative curvatures 1/40 and 1/100 in 1/mm):
        // the exact Hertz ellipse, then back.
        let (rx, ry) = (20.0, 50.0);
        let (major, minor, force) = {
            let steel = crate::material::ElasticMaterial::new(210_000.0, 0.3).unwrap();
            let contact = HertzPointContact::new(
                PointGeometry::new([rx, ry], [f64::INFINITY, f64::INFINITY], 0.0).unwrap(),
                steel,
                steel,
            )
            .unwrap();
            let s = contact.solve_force(1000.0).unwrap();
            (s.semi_axes[0], s.semi_axes[1], s.force)
        };
        let e_star = crate::material::effective_modulus(
            &crate::material::ElasticMaterial::new(210_000.0, 0.3).unwrap(),
            &crate::material::ElasticMaterial::new(210_000.0, 0.3).unwrap(),
        );
        let [c_major, c_minor] = ellipse_gap_curvatures(major, minor, force, e_star).unwrap();
        // The major axis lies along the flatter direction (R = 50 mm).
        assert!((c_major * 2.0 * ry - 1.0).abs() < 1e-9, "{c_major}");
        assert!((c_minor * 2.0 * rx - 1.0).abs() < 1e-9, "{c_minor}");
        let [c_x, c_y] = ellipse_gap_curvatures(minor, major, force, e_star).unwrap();
        assert_eq!([c_x, c_y], [c_minor, c_major]);
    }
}
