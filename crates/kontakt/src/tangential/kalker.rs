//! Kalker's linear theory of rolling contact: the creepage coefficients `C11`, `C22`,
//! `C23` of an elliptical contact (Kalker 1990, Table E.3) and the creep forces
//!
//! ```text
//! F_x = -G c² C₁₁ ξ_x,   F_y = -G c² (C₂₂ ξ_y + c C₂₃ φ),   c = √(a b).
//! ```
//!
//! # The table and its interpolation
//! [`creep_coefficients`] reads the table of Kalker (1990)
//! (Table E.3; the same values as Kalker 1967 and Johnson 1985, Table 8.1):
//! two halves, one for `g = a/b <= 1` and one for `g = b/a <= 1`, rows `g = 0.1 ... 1.0`,
//! columns `nu = 0, 1/4, 1/2`. The rule:
//!
//! - linear in `g` between rows;
//! - in `nu`, a parabola through the three columns taken in `1/C`:
//!   `1/C(ν) = 8(ν - ¼)(ν - ½)/C(0) - 16ν(ν - ½)/C(¼) + 8ν(ν - ¼)/C(½)`;
//! - for `g < 0.1` the asymptotic expressions of the reference (`a << b` and `a >> b`). They
//!   join the table at `g = 0.1` with a jump of up to 6 % (largest for `C23`, `a << b`,
//!   `nu = 0.5`), which is the accuracy of the asymptotes there.
//!
//! The spin-moment coefficient `C33` is not in the reference table, so [`KalkerLinear`]
//! gives the forces but not the spin moment `Mz` (use [`super::Fastsim`] for `Mz`).
//!
//! # Dissimilar materials
//! Kalker's combined moduli ([`KalkerMaterial`]): `2/G = 1/G₁ + 1/G₂`,
//! `ν = (G/2)(ν₁/G₁ + ν₂/G₂)`. The coupling through Dundurs' beta is
//! neglected (exact for quasi-identical bodies, beta = 0).
//!
//! # References
//! - Kalker, *Three-dimensional elastic bodies in rolling contact* (1990), Table E.3.
//! - Kalker (1967), *On the rolling contact of two elastic bodies in the presence of dry
//!   friction*, thesis, TH Delft.
//! - Johnson (1982), eqs (34a, b) (there normalized by `mu P`).
//! - Johnson, *Contact Mechanics* (1985), §8.4 and Table 8.1.

use super::{ContactEllipse, Creepage, TractionCurve, check_creepage, check_friction};
use crate::error::{Error, Result};
use crate::material::ElasticMaterial;
use crate::units::{Megapascal, Newton};
use std::f64::consts::PI;

/// Rows of the table: `g = 0.1, 0.2, ..., 1.0`.
pub const TABLE_G: [f64; 10] = [0.1, 0.2, 0.3, 0.4, 0.5, 0.6, 0.7, 0.8, 0.9, 1.0];

/// Columns of the table: `nu = 0, 0.25, 0.5`.
pub const TABLE_NU: [f64; 3] = [0.0, 0.25, 0.5];

/// One row of the table: `[C11, C22, C23]`, each at `nu = [0, 0.25, 0.5]`.
type Row = [[f64; 3]; 3];

/// Kalker's Table E.3, case `g = a/b <= 1` (contact short in the rolling direction).
/// `TABLE_A_OVER_B[i][k][j]`: row `g = TABLE_G[i]`, coefficient `k` (0: C11, 1: C22,
/// 2: C23), `nu = TABLE_NU[j]`.
#[allow(clippy::approx_constant)] // 3.14 is a published table value, not pi
pub const TABLE_A_OVER_B: [Row; 10] = [
    [
        [2.51, 3.31, 4.85],
        [2.51, 2.52, 2.53],
        [0.334, 0.473, 0.731],
    ],
    [
        [2.59, 3.37, 4.81],
        [2.59, 2.63, 2.66],
        [0.483, 0.603, 0.809],
    ],
    [
        [2.68, 3.44, 4.80],
        [2.68, 2.75, 2.81],
        [0.607, 0.715, 0.889],
    ],
    [
        [2.78, 3.53, 4.82],
        [2.78, 2.88, 2.98],
        [0.720, 0.823, 0.977],
    ],
    [[2.88, 3.62, 4.83], [2.88, 3.01, 3.14], [0.827, 0.929, 1.07]],
    [[2.98, 3.72, 4.91], [2.98, 3.14, 3.31], [0.930, 1.03, 1.18]],
    [[3.09, 3.81, 4.97], [3.09, 3.28, 3.48], [1.03, 1.14, 1.29]],
    [[3.19, 3.91, 5.05], [3.19, 3.41, 3.65], [1.13, 1.25, 1.40]],
    [[3.29, 4.01, 5.12], [3.29, 3.54, 3.82], [1.23, 1.36, 1.51]],
    [[3.40, 4.12, 5.20], [3.40, 3.67, 3.98], [1.33, 1.47, 1.63]],
];

/// Kalker's Table E.3, case `g = b/a <= 1` (contact long in the rolling direction).
/// Indexing as [`TABLE_A_OVER_B`].
pub const TABLE_B_OVER_A: [Row; 10] = [
    [[10.7, 11.7, 12.9], [10.7, 12.8, 16.0], [12.2, 14.6, 18.0]],
    [[6.96, 7.78, 8.82], [6.96, 8.14, 9.79], [5.72, 6.63, 7.89]],
    [[5.57, 6.34, 7.34], [5.57, 6.40, 7.51], [3.79, 4.32, 5.01]],
    [[4.84, 5.57, 6.57], [4.84, 5.48, 6.31], [2.88, 3.24, 3.70]],
    [[4.37, 5.10, 6.11], [4.37, 4.90, 5.56], [2.35, 2.62, 2.96]],
    [[4.06, 4.78, 5.80], [4.06, 4.50, 5.04], [2.01, 2.23, 2.50]],
    [[3.82, 4.54, 5.58], [3.82, 4.21, 4.67], [1.76, 1.95, 2.18]],
    [[3.65, 4.36, 5.42], [3.65, 3.99, 4.39], [1.58, 1.75, 1.94]],
    [[3.51, 4.22, 5.30], [3.51, 3.81, 4.16], [1.44, 1.59, 1.77]],
    [[3.40, 4.12, 5.20], [3.40, 3.67, 3.98], [1.33, 1.47, 1.63]],
];

/// Kalker's creepage coefficients of one contact \[-\].
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct CreepCoefficients {
    /// `C11`: longitudinal force per longitudinal creepage.
    pub c11: f64,
    /// `C22`: lateral force per lateral creepage.
    pub c22: f64,
    /// `C23`: lateral force per spin creepage (times `c`).
    pub c23: f64,
}

/// Kalker's creepage coefficients for an ellipse of axis ratio `axis_ratio` `= a/b` \[-\]
/// (`a` in the rolling direction; finite, > 0) and Poisson's ratio `nu` \[-\]
/// (`0 <= nu <= 0.5`, the range of the table), by the interpolation rule of the module
/// docs.
///
/// # Errors
/// [`Error::InvalidInput`] naming `axis_ratio` or `poisson_ratio`.
///
/// # Example
/// The worked values of the reference table, `nu = 0.28`, `a/b = 0.5`:
/// ```
/// use kontakt::tangential::creep_coefficients;
/// let c = creep_coefficients(0.5, 0.28)?;
/// assert!((c.c11 - 3.734).abs() < 5e-4 && (c.c22 - 3.026).abs() < 5e-4);
/// assert!((c.c23 - 0.943).abs() < 5e-4);
/// # Ok::<(), kontakt::Error>(())
/// ```
pub fn creep_coefficients(axis_ratio: f64, nu: f64) -> Result<CreepCoefficients> {
    if !(axis_ratio.is_finite() && axis_ratio > 0.0) {
        return Err(Error::invalid(
            "axis_ratio",
            axis_ratio,
            "a finite axis ratio a/b > 0",
        ));
    }
    if !(nu.is_finite() && (0.0..=0.5).contains(&nu)) {
        return Err(Error::invalid(
            "poisson_ratio",
            nu,
            "0 <= nu <= 0.5 (the range of Kalker's table)",
        ));
    }
    let (g, table) = if axis_ratio <= 1.0 {
        (axis_ratio, &TABLE_A_OVER_B)
    } else {
        (1.0 / axis_ratio, &TABLE_B_OVER_A)
    };
    if g < TABLE_G[0] {
        return Ok(if axis_ratio <= 1.0 {
            asymptote_short(g, nu)
        } else {
            asymptote_long(g, nu)
        });
    }
    // Row interval: g in [TABLE_G[i], TABLE_G[i+1]].
    let i = (((g - 0.1) / 0.1).floor() as usize).min(8);
    let t = (g - TABLE_G[i]) / (TABLE_G[i + 1] - TABLE_G[i]);
    let at = |k: usize| {
        let lo = interpolate_nu(table[i][k], nu);
        let hi = interpolate_nu(table[i + 1][k], nu);
        lo + t * (hi - lo)
    };
    Ok(CreepCoefficients {
        c11: at(0),
        c22: at(1),
        c23: at(2),
    })
}

/// The parabola in `1/C` through the three columns `nu = 0, 1/4, 1/2`.
fn interpolate_nu(c: [f64; 3], nu: f64) -> f64 {
    let inv = 8.0 * (nu - 0.25) * (nu - 0.5) / c[0] - 16.0 * nu * (nu - 0.5) / c[1]
        + 8.0 * nu * (nu - 0.25) / c[2];
    1.0 / inv
}

/// Asymptotes for `a << b` (`g = a/b < 0.1`).
fn asymptote_short(g: f64, nu: f64) -> CreepCoefficients {
    CreepCoefficients {
        c11: PI * PI / (4.0 * (1.0 - nu)),
        c22: PI * PI / 4.0,
        c23: PI * g.sqrt() / (3.0 * (1.0 - nu)) * (1.0 + nu * ((16.0 / g).ln() - 5.0)),
    }
}

/// Asymptotes for `a >> b` (`g = b/a < 0.1`), with `L = ln(16/g²)`.
fn asymptote_long(g: f64, nu: f64) -> CreepCoefficients {
    let l = (16.0 / (g * g)).ln();
    let k = 3.0 - 4f64.ln();
    let m = (1.0 - nu) * l + 2.0 * nu;
    CreepCoefficients {
        c11: 2.0 * PI / ((l - 2.0 * nu) * g) * (1.0 + k / (l - 2.0 * nu)),
        c22: 2.0 * PI / g * (1.0 + (1.0 - nu) * k / m) / m,
        c23: 2.0 * PI / (3.0 * g.powf(1.5) * ((1.0 - nu) * l - 2.0 + 4.0 * nu)),
    }
}

/// Kalker's combined elastic constants of two bodies: $2/G = 1/G_1 + 1/G_2$ \[MPa\] and
/// $\nu = \tfrac{G}{2}(\nu_1/G_1 + \nu_2/G_2)$ \[-\]. For identical bodies they are the
/// bodies' own `G` and `nu`; against a rigid body `G = 2 G_1` and `nu = nu_1`.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct KalkerMaterial {
    /// Combined shear modulus `G` \[MPa\].
    pub shear_modulus: Megapascal,
    /// Combined Poisson's ratio `nu` \[-\].
    pub poisson_ratio: f64,
}

impl KalkerMaterial {
    /// Combine two materials.
    ///
    /// # Errors
    /// [`Error::InvalidInput`] naming `materials` if both bodies are rigid.
    ///
    /// # Example
    /// ```
    /// use kontakt::{material::ElasticMaterial, tangential::KalkerMaterial};
    /// let s = ElasticMaterial::STEEL;
    /// let k = KalkerMaterial::new(&s, &s)?;
    /// assert!((k.shear_modulus - s.shear_modulus()).abs() < 1e-9 && k.poisson_ratio == 0.3);
    /// # Ok::<(), kontakt::Error>(())
    /// ```
    pub fn new(body1: &ElasticMaterial, body2: &ElasticMaterial) -> Result<Self> {
        let [m1, m2] = super::check_materials(body1, body2)?;
        // 1/G and nu/G of each body; a rigid body contributes zero to both.
        let inv = |m: &ElasticMaterial| {
            let g = m.shear_modulus();
            if g.is_infinite() { 0.0 } else { 1.0 / g }
        };
        let (i1, i2) = (inv(&m1), inv(&m2));
        let shear_modulus = 2.0 / (i1 + i2);
        let poisson_ratio =
            0.5 * shear_modulus * (m1.poisson_ratio() * i1 + m2.poisson_ratio() * i2);
        Ok(KalkerMaterial {
            shear_modulus,
            poisson_ratio,
        })
    }
}

/// The linear creep forces of Kalker's theory, valid for creepages small enough that the
/// whole contact adheres (`|F| << mu P`).
///
/// ```text
/// F_x = -G c² C₁₁ ξ_x,   F_y = -G c² (C₂₂ ξ_y + c C₂₃ φ)
/// ```
///
/// with `c = sqrt(a b)` \[mm\], `G` \[MPa\] the combined shear modulus ([`KalkerMaterial`]),
/// forces \[N\] on body 1.
///
/// # Example
/// A circular steel contact, a = b = 1 mm: `Fx = -G · 4.300 · xi` (nu = 0.3).
/// ```
/// use kontakt::{material::ElasticMaterial, tangential::{ContactEllipse, KalkerLinear}};
/// use kontakt::tangential::Creepage;
/// let s = ElasticMaterial::STEEL;
/// let k = KalkerLinear::new(ContactEllipse::new(1.0, 1.0, 1000.0)?, &s, &s, 0.3)?;
/// let [fx, fy] = k.forces(&Creepage::longitudinal(1e-4))?;
/// assert!((fx / (-s.shear_modulus() * 1e-4) - 4.300).abs() < 5e-4);
/// assert_eq!(fy, 0.0);
/// # Ok::<(), kontakt::Error>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct KalkerLinear {
    ellipse: ContactEllipse,
    material: KalkerMaterial,
    coefficients: CreepCoefficients,
    friction: f64,
}

impl KalkerLinear {
    /// Plan the linear theory for an ellipse (`a` along the rolling direction), two
    /// materials and the friction coefficient `mu` \[-\] (> 0; used only to normalize the
    /// traction curve).
    ///
    /// # Errors
    /// [`Error::InvalidInput`] naming `friction_coefficient`, `materials` (two rigid
    /// bodies) or `poisson_ratio` (combined nu outside 0..=0.5, the table's range).
    pub fn new(
        ellipse: ContactEllipse,
        body1: &ElasticMaterial,
        body2: &ElasticMaterial,
        mu: f64,
    ) -> Result<Self> {
        let friction = check_friction(mu)?;
        let material = KalkerMaterial::new(body1, body2)?;
        let coefficients = creep_coefficients(ellipse.axis_ratio(), material.poisson_ratio)?;
        Ok(KalkerLinear {
            ellipse,
            material,
            coefficients,
            friction,
        })
    }

    /// The contact ellipse.
    pub fn ellipse(&self) -> &ContactEllipse {
        &self.ellipse
    }
    /// The combined material.
    pub fn material(&self) -> KalkerMaterial {
        self.material
    }
    /// The creepage coefficients.
    pub fn coefficients(&self) -> CreepCoefficients {
        self.coefficients
    }
    /// The friction coefficient \[-\].
    pub fn friction_coefficient(&self) -> f64 {
        self.friction
    }

    /// Longitudinal creep coefficient `G c² C11` \[N\] (force per unit creepage).
    pub fn longitudinal_stiffness(&self) -> Newton {
        self.material.shear_modulus * self.ellipse.a() * self.ellipse.b() * self.coefficients.c11
    }

    /// The creep forces `[Fx, Fy]` \[N\] on body 1 for the creepages `creepage`.
    ///
    /// # Errors
    /// A non-finite creepage component (see [`Creepage::validate`]).
    pub fn forces(&self, creepage: &Creepage) -> Result<[Newton; 2]> {
        creepage.validate()?;
        let g = self.material.shear_modulus;
        let c = self.ellipse.mean_semi_axis();
        let k = self.coefficients;
        let gc2 = g * c * c;
        Ok([
            -gc2 * k.c11 * creepage.longitudinal,
            -gc2 * (k.c22 * creepage.lateral + c * k.c23 * creepage.spin),
        ])
    }

    /// The longitudinal creepage \[-\] at which the linear force reaches `mu P`:
    /// `xi = mu P/(G c² C11)`; beyond it the linear theory has no meaning.
    pub fn saturation_creepage(&self) -> f64 {
        self.friction * self.ellipse.normal_force() / self.longitudinal_stiffness()
    }
}

impl TractionCurve for KalkerLinear {
    fn name(&self) -> &'static str {
        "kalker_linear"
    }

    /// `G c² C11 xi/(mu P)`, unclipped (the linear theory, meaningful below 1).
    ///
    /// # Errors
    /// A non-finite creepage, or one so large that the unclipped line leaves f64 (about
    /// 1e308 times the saturation creepage), naming `creepage`.
    fn normalized_force(&self, creepage: f64) -> Result<f64> {
        check_creepage(creepage)?;
        let f = creepage / self.saturation_creepage();
        if f.is_finite() {
            Ok(f)
        } else {
            Err(Error::invalid(
                "creepage",
                creepage,
                "a creepage whose linear creep force is a finite number (the linear theory \
                 means nothing beyond its saturation creepage anyway)",
            ))
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn table_nodes_are_reproduced() {
        for (i, &g) in TABLE_G.iter().enumerate() {
            for (j, &nu) in TABLE_NU.iter().enumerate() {
                let c = creep_coefficients(g, nu).unwrap();
                let d = creep_coefficients(1.0 / g, nu).unwrap();
                for (k, v) in [c.c11, c.c22, c.c23].into_iter().enumerate() {
                    assert!((v - TABLE_A_OVER_B[i][k][j]).abs() < 1e-12, "{g} {nu} {k}");
                }
                for (k, v) in [d.c11, d.c22, d.c23].into_iter().enumerate() {
                    assert!((v - TABLE_B_OVER_A[i][k][j]).abs() < 1e-12, "{g} {nu} {k}");
                }
            }
        }
    }

    #[test]
    fn bad_inputs() {
        assert_eq!(
            creep_coefficients(0.0, 0.3).unwrap_err().field(),
            Some("axis_ratio")
        );
        assert_eq!(
            creep_coefficients(1.0, 0.51).unwrap_err().field(),
            Some("poisson_ratio")
        );
        assert_eq!(
            creep_coefficients(1.0, -0.1).unwrap_err().field(),
            Some("poisson_ratio")
        );
        let r = ElasticMaterial::RIGID;
        assert_eq!(
            KalkerMaterial::new(&r, &r).unwrap_err().field(),
            Some("materials")
        );
    }

    #[test]
    fn rigid_partner_doubles_g() {
        let s = ElasticMaterial::STEEL;
        let k = KalkerMaterial::new(&s, &ElasticMaterial::RIGID).unwrap();
        assert!((k.shear_modulus - 2.0 * s.shear_modulus()).abs() < 1e-9);
        assert!((k.poisson_ratio - 0.3).abs() < 1e-15);
    }
}
