//! Deterministic rough contact: a periodic rough surface (a [`GapMap`] of heights, from
//! [`super::SelfAffineSpec`] or a measurement) pressed against a flat on the periodic
//! elastic half-space solver, at given nominal pressures.
//!
//! # Model
//! The combined topography `z(x, y)` of the two surfaces touches a rigid flat with the
//! contact modulus `E*` of the pair (the usual reduction of two rough elastic half-spaces;
//! Johnson 1985 §13.1). The gap is `max(z) - z`; the periodic half-space solver
//! ([`crate::halfspace`], Polonsky and Keer 1999 with Vollebregt's preconditioner) finds
//! the pressure for the force `p̄ L_x L_y`. The real contact area is the number of loaded
//! cells times the cell area.
//!
//! At small loads the real area grows in proportion to the load,
//! `A/A0 = κ p̄/(E* h'_rms)`: boundary-element and GFMD solvers give `κ ≈ 2` (Hyun et al.
//! 2004; Monti, Sanner and Pastewka 2021), Persson's theory
//! `A/A0 = erf(√2 p̄/(E* h'_rms))`, i.e. `κ = √(8/π) = 1.60` ([`persson_area_fraction`]).
//!
//! # Units
//! mm, N, MPa.

use crate::error::{Error, Result, positive_as};
use crate::field::ContactZone;
use crate::gap::GapMap;
use crate::halfspace::{Boundary, Control, HalfSpaceSolver, SolverOptions, Start};
use crate::solve::SolveStatus;

/// One load of a [`RoughContact`].
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct RoughContactPoint {
    /// Nominal (mean) pressure `p̄` \[MPa\].
    pub mean_pressure: f64,
    /// Normal force on the periodic cell \[N\].
    pub force: f64,
    /// Real contact area over the nominal area `A/A0` \[-\].
    pub area_fraction: f64,
    /// `κ = (A/A0) / (p̄/(E* h'_rms))` \[-\].
    pub kappa: f64,
    /// Persson's `A/A0` at this load \[-\].
    pub persson_area_fraction: f64,
    /// Largest pressure \[MPa\].
    pub max_pressure: f64,
    /// Mean pressure on the real contact area `p̄ A0/A` \[MPa\].
    pub real_mean_pressure: f64,
    /// Contact patches: groups of loaded cells joined by their sides, across the periodic
    /// borders too.
    pub patches: usize,
    /// Mean area of a patch \[mm²\].
    pub mean_patch_area: f64,
    /// Area of the largest patch \[mm²\].
    pub largest_patch_area: f64,
    /// Mean gap between the deformed surfaces over the nominal area \[mm\].
    pub mean_gap: f64,
    /// The solver's termination, iterations and residual.
    pub status: SolveStatus,
}

/// A periodic rough surface on the half-space solver, planned once and solved at many
/// loads (each load warm-starts from the last).
#[derive(Debug)]
pub struct RoughContact {
    gap: Vec<f64>,
    grid: crate::geometry::Grid2,
    e_star: f64,
    rms_slope: f64,
    solver: HalfSpaceSolver,
    warm: bool,
}

impl RoughContact {
    /// Plan the contact of the height map `heights` (a [`GapMap`] of kind height; its
    /// values are used as the gap `max(z) - z`) against a flat, with the contact modulus
    /// `e_star` \[MPa\], the rms slope `rms_slope` \[-\] used to normalise the load (the
    /// surface's own, e.g. [`super::SelfAffineSurface::rms_slope`]), and the solver's
    /// `options` (tolerance, iterations, threads, preconditioner; the boundary is always
    /// periodic).
    ///
    /// # Errors
    /// [`Error::InvalidInput`] naming `e_star`, `rms_slope` or a solver option.
    pub fn new(
        heights: &GapMap,
        e_star: f64,
        rms_slope: f64,
        options: SolverOptions,
    ) -> Result<Self> {
        positive_as("e_star", e_star, "a finite contact modulus > 0 MPa")?;
        positive_as("rms_slope", rms_slope, "a finite rms slope > 0")?;
        let grid = *heights.grid();
        let solver = HalfSpaceSolver::new(
            grid,
            e_star,
            SolverOptions {
                boundary: Boundary::Periodic,
                ..options
            },
        )?;
        let mut gap = crate::error::try_filled("grid", grid.len(), 0.0)?;
        gap.copy_from_slice(heights.values());
        Ok(RoughContact {
            gap,
            grid,
            e_star,
            rms_slope,
            solver,
            warm: false,
        })
    }

    /// The bytes a contact of `points = [nx, ny]` cells with the solver's `options` will
    /// hold while it solves, counted before anything is allocated: the solver's arrays
    /// ([`HalfSpaceSolver::memory_estimate`], periodic, no secant history), the gap (8 bytes
    /// per cell) and the patch search of each solve (a flag and at most one index per
    /// cell: 9 bytes). About 121 bytes per cell with the default FFT preconditioner.
    ///
    /// # Errors
    /// [`Error::InvalidInput`] for a thread count outside 1..=[`crate::MAX_THREADS`].
    pub fn memory_estimate(points: [usize; 2], options: &SolverOptions) -> Result<u64> {
        let periodic = SolverOptions {
            boundary: Boundary::Periodic,
            ..*options
        };
        let n = (points[0] as u64).saturating_mul(points[1] as u64);
        let solver = HalfSpaceSolver::memory_estimate(points[0], points[1], &periodic, false)?;
        Ok(solver.saturating_add(n.saturating_mul(17)))
    }

    /// The grid \[mm\].
    pub fn grid(&self) -> &crate::geometry::Grid2 {
        &self.grid
    }

    /// The pressure per cell \[MPa\] of the last solve, row-major with x fastest.
    pub fn pressure(&self) -> &[f64] {
        self.solver.pressure()
    }

    /// Solve at the nominal pressure `mean_pressure` \[MPa\], warm-started from the last
    /// solve.
    ///
    /// # Errors
    /// [`Error::InvalidInput`] naming `mean_pressure` (not finite and > 0);
    /// [`Error::NotConverged`] when the solver does not reach its tolerance.
    pub fn solve(&mut self, mean_pressure: f64) -> Result<RoughContactPoint> {
        positive_as(
            "mean_pressure",
            mean_pressure,
            "a finite nominal pressure > 0 MPa",
        )?;
        let n = self.grid.len() as f64;
        let nominal = n * self.grid.cell_area();
        let force = mean_pressure * nominal;
        if !force.is_finite() {
            return Err(Error::invalid(
                "mean_pressure",
                mean_pressure,
                "a pressure whose force on the cell is finite",
            ));
        }
        let start = if self.warm { Start::Warm } else { Start::Cold };
        let report = self
            .solver
            .solve(&self.gap, Control::Force(force), start)?
            .require_converged()?;
        self.warm = true;
        let p = self.solver.pressure();
        let zone = ContactZone::analyse(&self.grid, p)?;
        let sizes = periodic_patches(self.grid.nx(), self.grid.ny(), p);
        let cell = self.grid.cell_area();
        let loaded = p.iter().filter(|&&x| x > 0.0).count() as f64;
        let area_fraction = loaded / n;
        let load = mean_pressure / (self.e_star * self.rms_slope);
        let u = self.solver.displacement();
        let mean_gap = self
            .gap
            .iter()
            .zip(u)
            .map(|(g, d)| (g + d - report.approach).max(0.0))
            .sum::<f64>()
            / n;
        Ok(RoughContactPoint {
            mean_pressure,
            force: report.force,
            area_fraction,
            kappa: area_fraction / load,
            persson_area_fraction: persson_area_fraction(
                mean_pressure,
                self.e_star,
                self.rms_slope,
            ),
            max_pressure: zone.max_pressure,
            real_mean_pressure: if area_fraction > 0.0 {
                mean_pressure / area_fraction
            } else {
                0.0
            },
            patches: sizes.len(),
            mean_patch_area: if sizes.is_empty() {
                0.0
            } else {
                cell * sizes.iter().sum::<usize>() as f64 / sizes.len() as f64
            },
            largest_patch_area: cell * sizes.iter().copied().max().unwrap_or(0) as f64,
            mean_gap,
            status: report.status,
        })
    }
}

/// The cell counts of the contact patches of `pressure` (`nx × ny`, row-major, x fastest):
/// loaded cells joined through their four sides, across the periodic borders too.
pub(crate) fn periodic_patches(nx: usize, ny: usize, pressure: &[f64]) -> Vec<usize> {
    let mut seen = vec![false; pressure.len()];
    let mut sizes = Vec::new();
    let mut stack = Vec::new();
    for start in 0..pressure.len() {
        if seen[start] || !(pressure[start] > 0.0) {
            continue;
        }
        seen[start] = true;
        stack.push(start);
        let mut size = 0;
        while let Some(k) = stack.pop() {
            size += 1;
            let (i, j) = (k % nx, k / nx);
            for (di, dj) in [(1, 0), (nx - 1, 0), (0, 1), (0, ny - 1)] {
                let n = (j + dj) % ny * nx + (i + di) % nx;
                if !seen[n] && pressure[n] > 0.0 {
                    seen[n] = true;
                    stack.push(n);
                }
            }
        }
        sizes.push(size);
    }
    sizes
}

/// Persson's real-area fraction `A/A0 = erf(√2 p̄/(E* h'_rms))` \[-\] for the nominal
/// pressure `mean_pressure` \[MPa\], contact modulus `e_star` \[MPa\] and rms slope
/// `rms_slope` (Persson 2001; the small-load slope is `√(8/π)`).
pub fn persson_area_fraction(mean_pressure: f64, e_star: f64, rms_slope: f64) -> f64 {
    libm::erf(std::f64::consts::SQRT_2 * mean_pressure / (e_star * rms_slope))
}

#[cfg(test)]
mod tests {
    use super::periodic_patches;

    /// A patch across the left/right and the top/bottom borders is one patch; a separate
    /// one is another; diagonal neighbours do not join.
    #[test]
    fn patches_join_across_periodic_borders() {
        let (nx, ny) = (6, 5);
        let mut p = vec![0.0; nx * ny];
        for (i, j) in [(0, 0), (5, 0), (0, 4), (5, 4), (1, 0)] {
            p[j * nx + i] = 1.0; // one patch of 5 cells through both borders
        }
        p[2 * nx + 3] = 2.0; // a single cell
        p[3 * nx + 4] = 2.0; // its diagonal neighbour: a third patch
        let mut sizes = periodic_patches(nx, ny, &p);
        sizes.sort_unstable();
        assert_eq!(sizes, vec![1, 1, 5]);
        assert!(periodic_patches(nx, ny, &vec![0.0; nx * ny]).is_empty());
    }
}
