//! Elastic materials and the moduli derived from a pair of them.
//!
//! Each modulus has exactly one definition here (see the crate-level *Conventions*):
//!
//! - shear modulus $G = E / (2(1+\nu))$;
//! - plane-strain modulus $E / (1-\nu^2)$;
//! - contact (composite) modulus $1/E^* = (1-\nu_1^2)/E_1 + (1-\nu_2^2)/E_2$ (Johnson's
//!   $E^*$; Hamrock's $E'$ is $2E^*$);
//! - Dundurs' mismatch parameter $\beta$ (Johnson 1982, eq. 35).

use crate::error::{Error, Result};
use crate::units::Megapascal;

/// A linear-elastic isotropic material.
///
/// Construct with [`ElasticMaterial::new`], which validates `E > 0` (finite) and
/// `-1 < nu <= 0.5`.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct ElasticMaterial {
    youngs_modulus: Megapascal,
    poisson_ratio: f64,
}

impl ElasticMaterial {
    /// Bearing steel: E = 210 000 MPa, nu = 0.3 (the material of the PimP papers, Wirsching et al.
    /// 2019, 2020).
    pub const STEEL: ElasticMaterial = ElasticMaterial {
        youngs_modulus: crate::units::STEEL_YOUNGS_MODULUS,
        poisson_ratio: crate::units::STEEL_POISSON_RATIO,
    };

    /// A material from Young's modulus and Poisson's ratio.
    ///
    /// # Arguments
    /// - `youngs_modulus` — E \[MPa\], finite and > 0.
    /// - `poisson_ratio` — nu [-], -1 < nu <= 0.5 (0.5 is incompressible).
    ///
    /// # Errors
    /// [`Error::InvalidInput`] naming `youngs_modulus` or `poisson_ratio`.
    ///
    /// # Example
    /// ```
    /// use kontakt::material::ElasticMaterial;
    /// let steel = ElasticMaterial::new(210_000.0, 0.3)?;
    /// assert!((steel.shear_modulus() - 80_769.23).abs() < 0.01);
    /// assert!(ElasticMaterial::new(210_000.0, 0.7).is_err());
    /// # Ok::<(), kontakt::Error>(())
    /// ```
    pub fn new(youngs_modulus: Megapascal, poisson_ratio: f64) -> Result<Self> {
        // A subnormal modulus (5e-324 MPa, found by probing) is > 0 but makes E* and every
        // contact size overflow; the error then named the force. It is the modulus's.
        if !(youngs_modulus.is_finite() && youngs_modulus >= f64::MIN_POSITIVE) {
            return Err(Error::invalid(
                "youngs_modulus",
                youngs_modulus,
                "a finite modulus > 0 MPa (at least 2.2e-308, the smallest normal f64)",
            ));
        }
        if !(poisson_ratio.is_finite() && poisson_ratio > -1.0 && poisson_ratio <= 0.5) {
            return Err(Error::invalid(
                "poisson_ratio",
                poisson_ratio,
                "-1 < nu <= 0.5",
            ));
        }
        Ok(ElasticMaterial {
            youngs_modulus,
            poisson_ratio,
        })
    }

    /// A rigid body (E = infinity) with Poisson's ratio 0.5 for the purpose of Dundurs'
    /// parameters. A rigid body contributes nothing to [`effective_modulus`].
    pub const RIGID: ElasticMaterial = ElasticMaterial {
        youngs_modulus: f64::INFINITY,
        poisson_ratio: 0.5,
    };

    /// Young's modulus E \[MPa\].
    pub fn youngs_modulus(&self) -> Megapascal {
        self.youngs_modulus
    }

    /// Poisson's ratio nu [-].
    pub fn poisson_ratio(&self) -> f64 {
        self.poisson_ratio
    }

    /// Shear modulus G = E / (2 (1 + nu)) \[MPa\].
    pub fn shear_modulus(&self) -> Megapascal {
        self.youngs_modulus / (2.0 * (1.0 + self.poisson_ratio))
    }

    /// Plane-strain modulus E / (1 - nu²) \[MPa\] (infinite for nu = ±1 is excluded by
    /// validation; infinite for a rigid body).
    pub fn plane_strain_modulus(&self) -> Megapascal {
        self.youngs_modulus / (1.0 - self.poisson_ratio * self.poisson_ratio)
    }

    /// Compliance (1 - nu²)/E [1/MPa]; zero for a rigid body.
    pub fn compliance(&self) -> f64 {
        (1.0 - self.poisson_ratio * self.poisson_ratio) / self.youngs_modulus
    }
}

/// Contact (composite) modulus $E^*$ of two bodies \[MPa\]:
///
/// ```text
/// 1/E* = (1 - ν₁²)/E₁ + (1 - ν₂²)/E₂
/// ```
///
/// # Example
/// Steel on steel: E* = 210000 / (2 · 0.91) = 115 384.6 MPa.
/// ```
/// use kontakt::material::{effective_modulus, ElasticMaterial};
/// let s = ElasticMaterial::STEEL;
/// assert!((effective_modulus(&s, &s) - 115_384.615).abs() < 1e-3);
/// ```
///
/// # References
/// Johnson (1982), "One hundred years of Hertz contact", eq. (5); Johnson, *Contact
/// Mechanics* (1985), eq. (3.48).
pub fn effective_modulus(body1: &ElasticMaterial, body2: &ElasticMaterial) -> Megapascal {
    1.0 / (body1.compliance() + body2.compliance())
}

/// Effective shear compliance used by Mindlin and Kalker:
/// ```text
/// 1/G* = (2 - ν₁)/G₁ + (2 - ν₂)/G₂      [MPa]
/// ```
///
/// # References
/// Johnson, *Contact Mechanics* (1985), eq. (7.41).
pub fn effective_shear_modulus(body1: &ElasticMaterial, body2: &ElasticMaterial) -> Megapascal {
    let c = |m: &ElasticMaterial| (2.0 - m.poisson_ratio) / m.shear_modulus();
    1.0 / (c(body1) + c(body2))
}

/// Dundurs' mismatch parameter $\beta$ [-]:
///
/// ```text
/// β = ½ · [(1 - 2ν₁)/G₁ - (1 - 2ν₂)/G₂] / [(1 - ν₁)/G₁ + (1 - ν₂)/G₂]
/// ```
///
/// Zero for identical materials and for an incompressible body against a rigid one;
/// antisymmetric under swapping the bodies; |beta| <= 0.5.
///
/// # Example
/// Johnson (1982) Table 1: glass (G = 22 GPa, nu = 0.25) on steel (G = 80 GPa, nu = 0.30)
/// gives beta = 0.21.
/// ```
/// use kontakt::material::{dundurs_beta, ElasticMaterial};
/// let glass = ElasticMaterial::new(2.0 * 22_000.0 * 1.25, 0.25)?;
/// let steel = ElasticMaterial::new(2.0 * 80_000.0 * 1.30, 0.30)?;
/// assert!((dundurs_beta(&glass, &steel) - 0.21).abs() < 0.005);
/// # Ok::<(), kontakt::Error>(())
/// ```
///
/// # References
/// Johnson (1982), eq. (35) and Table 1; Dundurs (1969), J. Appl. Mech. 36, 650-652.
pub fn dundurs_beta(body1: &ElasticMaterial, body2: &ElasticMaterial) -> f64 {
    let g1 = body1.shear_modulus();
    let g2 = body2.shear_modulus();
    let num = (1.0 - 2.0 * body1.poisson_ratio) / g1 - (1.0 - 2.0 * body2.poisson_ratio) / g2;
    let den = (1.0 - body1.poisson_ratio) / g1 + (1.0 - body2.poisson_ratio) / g2;
    0.5 * num / den
}

/// Dundurs' first parameter $\alpha$ [-], the plane-strain modulus mismatch:
/// ```text
/// α = [E₁/(1 - ν₁²) - E₂/(1 - ν₂²)] / [E₁/(1 - ν₁²) + E₂/(1 - ν₂²)]
/// ```
///
/// # References
/// Dundurs (1969); Johnson, *Contact Mechanics* (1985), eq. (5.3).
pub fn dundurs_alpha(body1: &ElasticMaterial, body2: &ElasticMaterial) -> f64 {
    // Written with compliances so that a rigid body (compliance 0) gives alpha = ±1.
    let c1 = body1.compliance();
    let c2 = body2.compliance();
    (c2 - c1) / (c1 + c2)
}

#[cfg(test)]
mod tests {
    use super::*;
    use approx::assert_relative_eq;

    #[test]
    fn validation_edges() {
        assert!(ElasticMaterial::new(1.0, 0.5).is_ok());
        assert!(ElasticMaterial::new(1.0, 0.5 + 1e-12).is_err());
        assert!(ElasticMaterial::new(1.0, -1.0).is_err());
        assert!(ElasticMaterial::new(1.0, -1.0 + 1e-12).is_ok());
        assert!(ElasticMaterial::new(0.0, 0.3).is_err());
        assert!(ElasticMaterial::new(-5.0, 0.3).is_err());
        assert!(ElasticMaterial::new(f64::NAN, 0.3).is_err());
        assert!(ElasticMaterial::new(f64::INFINITY, 0.3).is_err());
        assert!(ElasticMaterial::new(1.0, f64::NAN).is_err());
        let e = ElasticMaterial::new(-5.0, 0.3).unwrap_err();
        assert_eq!(e.field(), Some("youngs_modulus"));
        assert!(e.to_string().contains("-5"));
    }

    /// Johnson (1982) Table 1, rows with finite moduli, to the printed two digits.
    ///
    /// The tungsten-carbide row (G = 220 GPa, nu = 0.22, beta = -0.14) is not
    /// self-consistent: eq. (35) gives -0.100 for the printed moduli, and -0.14 needs
    /// G ≈ 300 GPa (a more typical value for WC). It is checked separately below.
    #[test]
    fn dundurs_beta_matches_johnson_table_1() {
        let from_g = |g_gpa: f64, nu: f64| {
            ElasticMaterial::new(2.0 * g_gpa * 1000.0 * (1.0 + nu), nu).unwrap()
        };
        let steel = from_g(80.0, 0.30);
        for (g, nu, beta) in [
            (0.97, 0.38, 0.19),
            (22.0, 0.25, 0.21),
            (28.0, 0.32, 0.12),
            (45.0, 0.25, 0.12),
        ] {
            let b = dundurs_beta(&from_g(g, nu), &steel);
            assert!(
                (b - beta).abs() <= 0.005 + 1e-12,
                "G={g} nu={nu}: {b} vs {beta}"
            );
        }
        // WC row: printed moduli give -0.0998; G = 300 GPa gives the printed -0.14.
        assert!((dundurs_beta(&from_g(220.0, 0.22), &steel) + 0.0998).abs() < 5e-4);
        assert!((dundurs_beta(&from_g(300.0, 0.22), &steel) + 0.14).abs() < 0.005);
        // Rubber (nu = 0.5) on rigid metal: beta = 0.
        let rubber = ElasticMaterial::new(3.0, 0.5).unwrap();
        assert_relative_eq!(dundurs_beta(&rubber, &ElasticMaterial::RIGID), 0.0);
    }

    #[test]
    fn dundurs_antisymmetry_and_identity() {
        let a = ElasticMaterial::new(70_000.0, 0.33).unwrap();
        let b = ElasticMaterial::STEEL;
        assert_relative_eq!(dundurs_beta(&a, &b), -dundurs_beta(&b, &a), epsilon = 1e-15);
        assert_relative_eq!(dundurs_beta(&a, &a), 0.0);
        assert_relative_eq!(
            dundurs_alpha(&a, &b),
            -dundurs_alpha(&b, &a),
            epsilon = 1e-15
        );
        assert_relative_eq!(dundurs_alpha(&b, &ElasticMaterial::RIGID), -1.0);
    }

    #[test]
    fn effective_moduli() {
        let s = ElasticMaterial::STEEL;
        assert_relative_eq!(
            effective_modulus(&s, &s),
            210_000.0 / 1.82,
            max_relative = 1e-15
        );
        // Rigid partner: E* = E/(1-nu^2).
        assert_relative_eq!(
            effective_modulus(&s, &ElasticMaterial::RIGID),
            s.plane_strain_modulus(),
            max_relative = 1e-15
        );
        // G* for identical steel: G/(2(2-nu)).
        assert_relative_eq!(
            effective_shear_modulus(&s, &s),
            s.shear_modulus() / (2.0 * 1.7),
            max_relative = 1e-15
        );
    }
}
