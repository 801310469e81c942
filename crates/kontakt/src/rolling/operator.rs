//! The tangential elastic operator `u = A τ` by FFT, and Kalker's combined constants.
//!
//! # Formula
//! For tractions `τ = (τ_x, τ_y)` \[MPa\] on body 1 (uniform per cell of the grid, row-major,
//! x fastest) the tangential displacement difference `u = u(body 1) - u(body 2)` \[mm\]
//! at the cell centres is
//!
//! ```text
//! u_x = A_xx * τ_x + A_xy * τ_y,    u_y = A_xy * τ_x + A_yy * τ_y,
//! ```
//!
//! each `*` a discrete convolution with Cerruti's coefficients of [`super::influence`]. It
//! is applied with the free-boundary FFT plans of the normal solver
//! ([`crate::halfspace::HalfSpacePlan`]: zero padding to `2nx × 2ny`, real FFT along `x`,
//! complex along `y`, a real kernel spectrum): `A_xx`, `A_yy` are even and `A_xy` odd
//! in both directions, so all three spectra are real. Four convolutions per application
//! (two when `ν = 0`, where `A_xy = 0`).
//!
//! # Assumptions
//! Quasi-identical bodies (Kalker's difference parameter `K = 0`): the normal and
//! tangential problems decouple (see [`super::influence`]). Free boundary only.
//!
//! # References
//! Kalker (1990) §1.6 (combined constants, difference parameter); Vollebregt (2014)
//! (FFT-based convolution of the influence numbers in CONTACT).

use super::influence::quadrant_tables;
use crate::error::{Error, Result};
use crate::geometry::Grid2;
use crate::halfspace::{HalfSpacePlan, OperatorScratch, Parity};
use crate::material::ElasticMaterial;
use crate::units::Megapascal;
use std::sync::Arc;

/// Kalker's combined elastic constants of two bodies for the tangential problem.
///
/// ```text
/// 1/G = (1/G1 + 1/G2)/2,   ν = G (ν1/G1 + ν2/G2)/2,   K = (G/4) [(1-2ν1)/G1 - (1-2ν2)/G2]
/// ```
///
/// with `G` \[MPa\] the combined shear modulus, `ν` the combined Poisson's ratio and `K`
/// the difference parameter (dimensionless; `K = 0` for equal materials, "quasi-identical"
/// bodies). The tangential solvers of [`crate::rolling`] neglect `K` (normal and
/// tangential problems decoupled); [`KalkerMaterial::difference_parameter`] reports it.
///
/// Reference: Kalker (1990) §1.6; the same combination is used in CONTACT.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct KalkerMaterial {
    g: Megapascal,
    nu: f64,
    k: f64,
}

impl KalkerMaterial {
    /// The combined constants of two bodies.
    ///
    /// # Errors
    /// [`Error::InvalidInput`] when both bodies are rigid (no finite combined modulus).
    pub fn new(body1: &ElasticMaterial, body2: &ElasticMaterial) -> Result<Self> {
        let (g1, g2) = (body1.shear_modulus(), body2.shear_modulus());
        let (c1, c2) = (1.0 / g1, 1.0 / g2);
        let g = 2.0 / (c1 + c2);
        if !(g.is_finite() && g > 0.0) {
            return Err(Error::invalid(
                "materials",
                "two rigid bodies",
                "at least one elastic body (finite shear modulus)",
            ));
        }
        let (n1, n2) = (body1.poisson_ratio(), body2.poisson_ratio());
        let nu = 0.5 * g * (n1 * c1 + n2 * c2);
        let k = 0.25 * g * ((1.0 - 2.0 * n1) * c1 - (1.0 - 2.0 * n2) * c2);
        Ok(KalkerMaterial { g, nu, k })
    }

    /// Combined constants given directly: shear modulus `g` \[MPa\] and Poisson's ratio
    /// `nu`, with `K = 0`.
    ///
    /// # Errors
    /// [`Error::InvalidInput`] for `g` not finite and > 0, or `nu` outside `-1 < nu <= 0.5`.
    pub fn from_constants(g: Megapascal, nu: f64) -> Result<Self> {
        crate::error::positive_as("shear_modulus", g, "a finite shear modulus > 0 MPa")?;
        if !(nu > -1.0 && nu <= 0.5) {
            return Err(Error::invalid("poisson_ratio", nu, "-1 < nu <= 0.5"));
        }
        Ok(KalkerMaterial { g, nu, k: 0.0 })
    }

    /// Combined shear modulus `G` \[MPa\].
    pub fn shear_modulus(&self) -> Megapascal {
        self.g
    }

    /// Combined Poisson's ratio `ν`.
    pub fn poisson_ratio(&self) -> f64 {
        self.nu
    }

    /// Kalker's difference parameter `K` (dimensionless), neglected by the solvers.
    pub fn difference_parameter(&self) -> f64 {
        self.k
    }
}

/// The tangential operator of one grid: `u = A τ` (see the module docs), planned once
/// and applied without allocating.
pub struct TangentialOperator {
    /// `A_xx`, `A_yy`, `A_xy` plans; `A_xy` is `None` when `ν = 0`.
    xx: Arc<HalfSpacePlan>,
    yy: Arc<HalfSpacePlan>,
    xy: Option<Arc<HalfSpacePlan>>,
    scratch: OperatorScratch,
    tmp: Vec<f64>,
    material: KalkerMaterial,
    bound: f64,
}

impl std::fmt::Debug for TangentialOperator {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("TangentialOperator")
            .field("cells", &self.cells())
            .field("material", &self.material)
            .field("spectral_bound", &self.bound)
            .finish()
    }
}

impl TangentialOperator {
    /// Plan the operator for `grid` \[mm\] and the combined constants `material`.
    /// `threads` as for [`HalfSpacePlan::new`] (grids below 96 × 96 cells run serially).
    ///
    /// # Errors
    /// [`Error::InvalidInput`] for `threads` outside 1..=[`crate::MAX_THREADS`].
    pub fn new(grid: &Grid2, material: KalkerMaterial, threads: Option<usize>) -> Result<Self> {
        let (nx, ny) = (grid.nx(), grid.ny());
        let [qxx, qyy, qxy] = quadrant_tables(
            nx,
            ny,
            grid.dx(),
            grid.dy(),
            material.g,
            material.nu,
        );
        let g = material.g;
        let xx = HalfSpacePlan::from_quadrant(grid, g, &qxx, Parity::Even, threads)?;
        let yy = HalfSpacePlan::from_quadrant(grid, g, &qyy, Parity::Even, threads)?;
        let xy = if material.nu != 0.0 {
            Some(HalfSpacePlan::from_quadrant(
                grid,
                g,
                &qxy,
                Parity::OddOdd,
                threads,
            )?)
        } else {
            None
        };
        // The largest eigenvalue of the 2 × 2 symbol [[a, c], [c, b]] per wave vector.
        let bound = match &xy {
            Some(xy) => xx
                .spectrum()
                .zip(yy.spectrum())
                .zip(xy.spectrum())
                .map(|((a, b), c)| 0.5 * (a + b) + (0.25 * (a - b) * (a - b) + c * c).sqrt())
                .fold(0.0, f64::max),
            None => xx.spectrum().chain(yy.spectrum()).fold(0.0, f64::max),
        };
        let scratch = xx.scratch();
        Ok(TangentialOperator {
            xx,
            yy,
            xy,
            scratch,
            tmp: vec![0.0; nx * ny],
            material,
            bound,
        })
    }

    /// Cells `[nx, ny]` of the grid.
    pub fn cells(&self) -> [usize; 2] {
        self.xx.cells()
    }

    /// The grid \[mm\] the operator was planned for.
    pub fn grid(&self) -> &Grid2 {
        self.xx.grid()
    }

    /// The combined constants.
    pub fn material(&self) -> KalkerMaterial {
        self.material
    }

    /// An upper bound \[mm/MPa\] of the operator's largest eigenvalue (the largest
    /// eigenvalue of its circulant embedding on the padded grid): the step length of
    /// the projected-gradient solvers is its inverse.
    pub fn spectral_bound(&self) -> f64 {
        self.bound
    }

    /// `u = A τ`: the displacement difference `[u_x, u_y]` \[mm\] for the tractions
    /// `[τ_x, τ_y]` \[MPa\] on body 1 (each row-major, x fastest, length `nx·ny`).
    /// Allocates nothing.
    ///
    /// # Errors
    /// [`Error::InvalidInput`] when a length differs from `nx·ny`.
    pub fn apply(&mut self, tx: &[f64], ty: &[f64], ux: &mut [f64], uy: &mut [f64]) -> Result<()> {
        let TangentialOperator {
            xx,
            yy,
            xy,
            scratch,
            tmp,
            ..
        } = self;
        xx.apply_with_scratch(tx, ux, scratch)?;
        yy.apply_with_scratch(ty, uy, scratch)?;
        if let Some(xy) = xy {
            xy.apply_with_scratch(ty, tmp, scratch)?;
            ux.iter_mut().zip(tmp.iter()).for_each(|(u, t)| *u += t);
            xy.apply_with_scratch(tx, tmp, scratch)?;
            uy.iter_mut().zip(tmp.iter()).for_each(|(u, t)| *u += t);
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::rolling::influence::cerruti;

    fn pseudo_random(n: usize, seed: u64) -> Vec<f64> {
        let mut s = seed;
        (0..n)
            .map(|_| {
                s = s
                    .wrapping_mul(6364136223846793005)
                    .wrapping_add(1442695040888963407);
                (s >> 11) as f64 / (1u64 << 53) as f64 - 0.5
            })
            .collect()
    }

    #[test]
    fn fft_equals_the_dense_sum() {
        for &(nx, ny, nu) in &[(7, 5, 0.3), (12, 9, 0.0), (10, 16, 0.5)] {
            let grid = Grid2::centered(0.7, 0.4, nx, ny).unwrap();
            let m = KalkerMaterial::from_constants(8.0e4, nu).unwrap();
            let mut op = TangentialOperator::new(&grid, m, Some(1)).unwrap();
            let n = nx * ny;
            let (tx, ty) = (pseudo_random(n, 1), pseudo_random(n, 2));
            let (mut ux, mut uy) = (vec![0.0; n], vec![0.0; n]);
            op.apply(&tx, &ty, &mut ux, &mut uy).unwrap();
            let scale = ux.iter().chain(&uy).fold(0.0f64, |a, v| a.max(v.abs()));
            for i in 0..n {
                let (ix, iy) = ((i % nx) as f64, (i / nx) as f64);
                let (mut dx_, mut dy_) = (0.0, 0.0);
                for j in 0..n {
                    let (jx, jy) = ((j % nx) as f64, (j / nx) as f64);
                    let c = cerruti(
                        (ix - jx) * grid.dx(),
                        (iy - jy) * grid.dy(),
                        grid.dx(),
                        grid.dy(),
                        8.0e4,
                        nu,
                    );
                    dx_ += c.xx * tx[j] + c.xy * ty[j];
                    dy_ += c.xy * tx[j] + c.yy * ty[j];
                }
                assert!((ux[i] - dx_).abs() < 1e-12 * scale, "{nx}x{ny} ux {i}");
                assert!((uy[i] - dy_).abs() < 1e-12 * scale, "{nx}x{ny} uy {i}");
            }
        }
    }

    #[test]
    fn the_bound_exceeds_the_rayleigh_quotient() {
        let grid = Grid2::centered(1.0, 1.0, 16, 16).unwrap();
        let m = KalkerMaterial::from_constants(8.0e4, 0.3).unwrap();
        let mut op = TangentialOperator::new(&grid, m, Some(1)).unwrap();
        let n = grid.len();
        // Power iteration: the largest eigenvalue of A is below the bound, and close.
        let (mut tx, mut ty) = (vec![1.0; n], pseudo_random(n, 3));
        let (mut ux, mut uy) = (vec![0.0; n], vec![0.0; n]);
        let mut lambda = 0.0;
        for _ in 0..200 {
            op.apply(&tx, &ty, &mut ux, &mut uy).unwrap();
            let norm = ux.iter().chain(&uy).map(|v| v * v).sum::<f64>().sqrt();
            let t2 = tx.iter().chain(&ty).map(|v| v * v).sum::<f64>().sqrt();
            lambda = norm / t2;
            tx.iter_mut().zip(&ux).for_each(|(t, u)| *t = u / norm);
            ty.iter_mut().zip(&uy).for_each(|(t, u)| *t = u / norm);
        }
        let bound = op.spectral_bound();
        assert!(lambda <= bound && lambda > 0.8 * bound, "{lambda} vs {bound}");
    }

    #[test]
    fn combined_constants() {
        let steel = ElasticMaterial::STEEL;
        let m = KalkerMaterial::new(&steel, &steel).unwrap();
        assert!((m.shear_modulus() - steel.shear_modulus()).abs() < 1e-9);
        assert!((m.poisson_ratio() - steel.poisson_ratio()).abs() < 1e-15);
        assert_eq!(m.difference_parameter(), 0.0);
        let soft = ElasticMaterial::new(70_000.0, 0.33).unwrap();
        let d = KalkerMaterial::new(&steel, &soft).unwrap();
        assert!(d.difference_parameter().abs() > 0.0);
        assert!(KalkerMaterial::new(&ElasticMaterial::RIGID, &ElasticMaterial::RIGID).is_err());
        assert!(KalkerMaterial::from_constants(-1.0, 0.3).is_err());
        assert!(KalkerMaterial::from_constants(1.0, f64::NAN).is_err());
    }
}
