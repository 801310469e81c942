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
//! Kalker (1990) §1.6 (combined constants, difference parameter); the FFT convolution is
//! the normal solver's (docs/halfspace.md).

use super::influence::quadrant_tables;
use crate::error::{Error, Result};
use crate::geometry::Grid2;
use crate::halfspace::{HalfSpacePlan, OperatorScratch, Parity};
use crate::material::ElasticMaterial;
use crate::tangential::KalkerMaterial;
use std::sync::Arc;

/// Kalker's difference parameter of two bodies (dimensionless; Kalker 1990 §1.6):
///
/// ```text
/// K = (G/4) [(1-2ν1)/G1 - (1-2ν2)/G2],   1/G = (1/G1 + 1/G2)/2,
/// ```
///
/// zero for equal materials ("quasi-identical" bodies). The solvers of
/// [`crate::rolling`] neglect it (normal and tangential problems decoupled); this reports
/// its size. The combined `G` and `ν` are [`KalkerMaterial`]'s.
///
/// # Errors
/// [`Error::InvalidInput`] naming `materials` if both bodies are rigid.
pub fn difference_parameter(body1: &ElasticMaterial, body2: &ElasticMaterial) -> Result<f64> {
    let m = KalkerMaterial::new(body1, body2)?;
    // A rigid body contributes zero compliance.
    let term = |b: &ElasticMaterial| {
        let g = b.shear_modulus();
        if g.is_infinite() {
            0.0
        } else {
            (1.0 - 2.0 * b.poisson_ratio()) / g
        }
    };
    Ok(0.25 * m.shear_modulus * (term(body1) - term(body2)))
}

/// Check the combined constants (their fields are public).
pub(super) fn check_material(m: &KalkerMaterial) -> Result<()> {
    crate::error::positive_as(
        "shear_modulus",
        m.shear_modulus,
        "a finite combined shear modulus > 0 MPa",
    )?;
    let nu = m.poisson_ratio;
    if !(nu > -1.0 && nu <= 0.5) {
        return Err(Error::invalid("poisson_ratio", nu, "-1 < nu <= 0.5"));
    }
    Ok(())
}

/// Power-iteration steps of the eigenvalue estimate at planning.
const POWER_ITERATIONS: usize = 60;

/// Margin on the power-iteration estimate of the largest eigenvalue (a lower bound that
/// converges from below): the step `1/L` of the projected gradients must not exceed the
/// inverse of the true eigenvalue.
const POWER_SAFETY: f64 = 1.1;

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
    /// [`Error::InvalidInput`] for `threads` outside 1..=[`crate::MAX_THREADS`] or
    /// constants out of range.
    pub fn new(grid: &Grid2, material: KalkerMaterial, threads: Option<usize>) -> Result<Self> {
        check_material(&material)?;
        let (g, nu) = (material.shear_modulus, material.poisson_ratio);
        let (nx, ny) = (grid.nx(), grid.ny());
        let [qxx, qyy, qxy] = quadrant_tables(nx, ny, grid.dx(), grid.dy(), g, nu);
        let xx = HalfSpacePlan::from_quadrant(grid, g, &qxx, Parity::Even, threads)?;
        let yy = HalfSpacePlan::from_quadrant(grid, g, &qyy, Parity::Even, threads)?;
        let xy = if nu != 0.0 {
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
        let mut op = TangentialOperator {
            xx,
            yy,
            xy,
            scratch,
            tmp: vec![0.0; nx * ny],
            material,
            bound,
        };
        op.bound = bound.min(POWER_SAFETY * op.power_estimate()?);
        Ok(op)
    }

    /// A lower estimate \[mm/MPa\] of the largest eigenvalue: `|A t|/|t|` after
    /// [`POWER_ITERATIONS`] steps of the power iteration from a uniform traction
    /// (the top eigenvector is smooth, so the start is close to it).
    fn power_estimate(&mut self) -> Result<f64> {
        let n = self.tmp.len();
        let (mut tx, mut ty) = (vec![1.0; n], vec![1.0; n]);
        let (mut ux, mut uy) = (vec![0.0; n], vec![0.0; n]);
        let mut lambda = 0.0;
        for _ in 0..POWER_ITERATIONS {
            let t = tx.iter().chain(&ty).map(|v| v * v).sum::<f64>().sqrt();
            self.apply(&tx, &ty, &mut ux, &mut uy)?;
            let u = ux.iter().chain(&uy).map(|v| v * v).sum::<f64>().sqrt();
            if !(u > 0.0 && t > 0.0) {
                break;
            }
            lambda = u / t;
            tx.iter_mut().zip(&ux).for_each(|(t, u)| *t = u / lambda);
            ty.iter_mut().zip(&uy).for_each(|(t, u)| *t = u / lambda);
        }
        Ok(lambda)
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

    /// An upper bound \[mm/MPa\] of the operator's largest eigenvalue: the smaller of
    /// the largest eigenvalue of its circulant embedding on the padded grid (a strict
    /// bound, about twice too large) and 1.1 times a 60-step power-iteration estimate.
    /// The step length of the projected-gradient solvers is its inverse.
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
            let m = KalkerMaterial {
                shear_modulus: 8.0e4,
                poisson_ratio: nu,
            };
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
        let m = KalkerMaterial {
            shear_modulus: 8.0e4,
            poisson_ratio: 0.3,
        };
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
        assert!(
            lambda <= bound && lambda > 0.85 * bound,
            "{lambda} vs {bound}"
        );
    }

    #[test]
    fn difference_parameter_and_bad_constants() {
        let steel = ElasticMaterial::STEEL;
        assert_eq!(difference_parameter(&steel, &steel).unwrap(), 0.0);
        // Steel on a rigid body: K = (G/4)(1 - 2ν)/G1 with G = 2 G1.
        let k = difference_parameter(&steel, &ElasticMaterial::RIGID).unwrap();
        assert!((k - 0.5 * (1.0 - 2.0 * 0.3)).abs() < 1e-12, "{k}");
        let rigid = ElasticMaterial::RIGID;
        assert!(difference_parameter(&rigid, &rigid).is_err());
        let grid = Grid2::centered(1.0, 1.0, 4, 4).unwrap();
        for (g, nu) in [
            (-1.0, 0.3),
            (f64::INFINITY, 0.3),
            (1.0, f64::NAN),
            (1.0, 0.6),
        ] {
            let m = KalkerMaterial {
                shear_modulus: g,
                poisson_ratio: nu,
            };
            assert!(TangentialOperator::new(&grid, m, Some(1)).is_err());
        }
    }
}
