//! The PimP method ("Pressungsverteilung im Punktkontakt", Wirsching, Schwarz & Tremmel
//! 2020, §2.2; Wirsching et al. 2019): the pressure between two
//! analytic surfaces from a substitute geometry pressed into a Winkler bedding.
//!
//! The four steps of the paper map onto this module as follows.
//!
//! 1. **Contact point** from the poses of the bodies:
//!    [`crate::geometry::contact_point::find_contact`].
//! 2. **Local geometry**: the contact plane at the contact point, ray-cast distance
//!    functions `g1`, `g2` and the substitute geometry `g = g1 - g2` (a [`GapSource`],
//!    sampled on a grid in the principal frame of the gap).
//! 3. **Contact force**: the overlap `u = delta - g` pressed into uncoupled springs
//!    (the [`Mode`] decides the law), the approach `delta` iterated to force
//!    equilibrium by a bracketing root finder.
//! 4. **Pressure distribution** and the contact zone ([`ContactZone`]): area, maximum
//!    pressure, extents, centre of pressure, separate patches, centre-line curvature.
//!
//! Units: mm, N, MPa. The derivation of both bedding laws, and the reading of the
//! paper's garbled equations, are in `docs/pimp.md`.
//!
//! # Example
//! A 20 mm steel ball on a steel flat at 200 N, corrected mode, against Hertz:
//! ```
//! use kontakt::pimp::{Pimp, PimpOptions, QuadraticGap};
//! use kontakt::geometry::RelativeCurvature;
//! use kontakt::hertz::{HertzPointContact, PointGeometry};
//! use kontakt::material::ElasticMaterial;
//! let inf = f64::INFINITY;
//! let k = RelativeCurvature::from_radii([20.0, 20.0], [inf, inf], 0.0)?;
//! let steel = ElasticMaterial::STEEL;
//! let pimp = Pimp::new(steel, steel, PimpOptions::default())?;
//! let s = pimp.solve_force(&QuadraticGap::new(k), 200.0)?;
//! let h = HertzPointContact::new(PointGeometry::from_curvature(k), steel, steel)?
//!     .solve_force(200.0)?;
//! assert!((s.max_pressure / h.max_pressure - 1.0).abs() < 0.01);
//! assert!((s.approach / h.approach - 1.0).abs() < 0.01);
//! # Ok::<(), kontakt::Error>(())
//! ```

mod bedding;
mod tracker;

pub use crate::field::ContactZone;
pub use crate::field::domain::MIN_CELLS_ACROSS;
pub use crate::gap::{FnGap, GapSource, QuadraticGap, SurfacePairGap};
pub use bedding::{Mode, SampledGap};
pub use tracker::{FADE_TRAVEL, GapSampling, NODES_X, NODES_Y, PimpTracker, TrackedField};

use crate::error::{Error, Result, positive_as};
use crate::field::NormalSolution;
use crate::field::domain::{self, Policy, Shrink, Trial};
use crate::geometry::Grid2;
use crate::hertz::{HertzPointContact, PointGeometry};
use crate::load::LoadControl;
use crate::material::ElasticMaterial;
use crate::solve::{SolveStatus, Termination};
use crate::units::{Millimetre, Newton};
use bedding::Bedding;

/// The adaptive grid: it grows until it holds the zone and zooms in once, about the
/// contact point, when the zone reaches less than 60 % of it (to 1.15 times the zone).
const POLICY: Policy = Policy {
    max_domains: 12,
    shrink: Shrink::AboutOrigin {
        trigger: 0.6,
        factor: 1.15,
    },
};

/// Options of the PimP solver.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(
    feature = "serde",
    derive(serde::Serialize, serde::Deserialize, schemars::JsonSchema)
)]
#[cfg_attr(feature = "serde", serde(deny_unknown_fields, default))]
pub struct PimpOptions {
    /// The bedding law.
    pub mode: Mode,
    /// Cells `[nx, ny]` of the grid, each in 8..=4096 (default 64 × 64).
    pub cells: [usize; 2],
    /// Fixed half-extents `[x, y]` \[mm\] of the grid along the principal axes of the
    /// gap; `None` (default) adapts the extent to the contact: it starts from the Hertz
    /// estimate, grows when the zone reaches the border and shrinks once when the zone
    /// fills less than half of it.
    pub extent: Option<[Millimetre; 2]>,
    /// Relative force tolerance of the equilibrium iteration (default 1e-7), in
    /// (0, 1e-3\]. The reported field is then scaled so that its force equals the target
    /// exactly; the scale differs from 1 by at most the tolerance.
    pub tolerance: f64,
    /// Most force evaluations of the equilibrium iteration (default 200), >= 10.
    pub max_iterations: usize,
}

impl Default for PimpOptions {
    fn default() -> Self {
        PimpOptions {
            mode: Mode::Corrected,
            cells: [64, 64],
            extent: None,
            tolerance: 1e-7,
            max_iterations: 200,
        }
    }
}

impl PimpOptions {
    /// Check every option; errors name the field, the value and the valid range.
    ///
    /// # Errors
    /// [`Error::InvalidInput`] for an option out of range.
    pub fn validate(&self) -> Result<()> {
        for (field, n) in [("cells[0]", self.cells[0]), ("cells[1]", self.cells[1])] {
            if !(8..=4096).contains(&n) {
                return Err(Error::invalid(field, n, "8 <= cells <= 4096"));
            }
        }
        if let Some([x, y]) = self.extent {
            positive_as("extent[0]", x, "a finite half-extent > 0 mm")?;
            positive_as("extent[1]", y, "a finite half-extent > 0 mm")?;
        }
        if !(self.tolerance > 0.0 && self.tolerance <= 1e-3) {
            return Err(Error::invalid(
                "tolerance",
                self.tolerance,
                "0 < tolerance <= 1e-3",
            ));
        }
        if self.max_iterations < 10 {
            return Err(Error::invalid(
                "max_iterations",
                self.max_iterations,
                ">= 10",
            ));
        }
        Ok(())
    }
}

/// The PimP solver for one pair of materials: plan once, solve many.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Pimp {
    body1: ElasticMaterial,
    body2: ElasticMaterial,
    options: PimpOptions,
}

/// What only PimP gives in a [`NormalSolution`].
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct PimpDetail {
    /// The bedding law used.
    pub mode: Mode,
}

/// The PimP result at one load. `status` is the force equilibrium's: iterations are
/// force evaluations (0 under approach control), the residual the relative force error
/// before the field is scaled to the target. `domains - 1` is the number of grid resizes.
pub type PimpSolution = NormalSolution<PimpDetail>;

impl Pimp {
    /// A solver for body 1 against body 2 with `options`.
    ///
    /// # Errors
    /// [`Error::InvalidInput`] for an invalid option (see [`PimpOptions::validate`]).
    pub fn new(
        body1: ElasticMaterial,
        body2: ElasticMaterial,
        options: PimpOptions,
    ) -> Result<Self> {
        options.validate()?;
        Ok(Pimp {
            body1,
            body2,
            options,
        })
    }

    /// The options.
    pub fn options(&self) -> &PimpOptions {
        &self.options
    }

    /// Sample `source` on `grid` (in the principal frame of the gap) and prepare it for
    /// the bedding law: the set-up of the multi-body path. Then
    /// [`SampledGap::force`] gives the force for any approach without allocating.
    ///
    /// # Errors
    /// Errors of the source.
    pub fn sample(&self, source: &dyn GapSource, grid: Grid2) -> Result<SampledGap> {
        let curvature = source.curvature();
        let bedding = Bedding::new(self.options.mode, curvature, self.body1, self.body2)?;
        let hertz = HertzPointContact::new(
            PointGeometry::from_curvature(curvature),
            self.body1,
            self.body2,
        )?;
        let start_unit = hertz.approach_from_force(1.0)?
            * match self.options.mode {
                Mode::Corrected => 1.0,
                Mode::Published => 0.6,
            };
        let mut effective = vec![0.0; grid.len()];
        source.sample(&grid, curvature.orientation, &mut effective)?;
        if let Bedding::Corrected { d_a, .. } = bedding {
            // Along the major axis only: exact on the quadratic part, and a zone displaced
            // across the major axis is left untouched (docs/pimp.md §3).
            for (k, (x, _)) in grid.points().enumerate() {
                effective[k] += d_a * x * x;
            }
        }
        Ok(SampledGap {
            grid,
            rotation: curvature.orientation,
            effective,
            bedding,
            start_unit,
        })
    }

    /// Solve for a normal force `force` \[N\] (> 0): the approach is iterated to force
    /// equilibrium.
    ///
    /// # Errors
    /// - [`Error::InvalidInput`] for a non-positive force.
    /// - [`Error::Geometry`] when the zone reaches the border of a fixed grid, spans
    ///   fewer than [`MIN_CELLS_ACROSS`] cells, or the adaptive grid cannot contain it.
    /// - [`Error::NotConverged`] when the equilibrium iteration fails.
    pub fn solve_force(&self, source: &dyn GapSource, force: Newton) -> Result<PimpSolution> {
        positive_as("force", force, "a finite force > 0 N")?;
        self.solve(source, LoadControl::Force(force))
    }

    /// Solve for a rigid approach `approach` \[mm\] (> 0) from first touch.
    ///
    /// # Errors
    /// As [`Pimp::solve_force`], for `approach`.
    pub fn solve_approach(
        &self,
        source: &dyn GapSource,
        approach: Millimetre,
    ) -> Result<PimpSolution> {
        positive_as("approach", approach, "a finite approach > 0 mm")?;
        self.solve(source, LoadControl::Approach(approach))
    }

    /// Solve under `control` (a force or an approach; see [`LoadControl::point`]).
    ///
    /// # Errors
    /// As [`Pimp::solve_force`].
    pub fn solve(&self, source: &dyn GapSource, control: LoadControl) -> Result<PimpSolution> {
        let control = control.point()?;

        let curvature = source.curvature();
        let hertz = HertzPointContact::new(
            PointGeometry::from_curvature(curvature),
            self.body1,
            self.body2,
        )?;
        let estimate = match control {
            LoadControl::Force(f) => hertz.solve_force(f)?,
            // (a line load was refused by `point()`)
            LoadControl::Approach(d) | LoadControl::LineLoad(d) => hertz.solve_approach(d)?,
        };
        let half = match (self.options.extent, self.options.mode) {
            (Some(e), _) => e,
            (None, Mode::Corrected) => [1.25 * estimate.semi_axes[0], 1.25 * estimate.semi_axes[1]],
            (None, Mode::Published) => {
                // The published footprint is the contour g = d of the gap, d ≈ 0.6-1 delta.
                let d = match control {
                    LoadControl::Force(_) => 0.7 * estimate.approach,
                    LoadControl::Approach(d) | LoadControl::LineLoad(d) => d,
                };
                [
                    1.25 * (d / curvature.a_coef).sqrt(),
                    1.25 * (d / curvature.b_coef).sqrt(),
                ]
            }
        };
        let mut guess = estimate.approach
            * match self.options.mode {
                Mode::Corrected => 1.0,
                Mode::Published => 0.6,
            };
        let adapted = domain::adapt(
            [[-half[0], half[0]], [-half[1], half[1]]],
            self.options.extent.is_some(),
            self.options.cells,
            POLICY,
            |grid, _| {
                let sampled = self.sample(source, *grid)?;
                let (approach, status, scale) = match control {
                    LoadControl::Force(f) => {
                        let (d, status) = equilibrium(&sampled, f, guess, &self.options);
                        let status = status.require_converged("PimP force equilibrium")?;
                        let achieved = sampled.force(d);
                        (d, status, f / achieved)
                    }
                    LoadControl::Approach(d) | LoadControl::LineLoad(d) => {
                        (d, SolveStatus::new(Termination::Converged, 0, 0.0), 1.0)
                    }
                };
                let mut pressure = vec![0.0; grid.len()];
                sampled.pressure_into(approach, &mut pressure);
                if scale != 1.0 {
                    // The field is scaled so its force is the target exactly: by at most
                    // the tolerance, or, in published mode at a jump of the strip weights
                    // (the footprint gaining a column), by interpolating the weights
                    // (docs/pimp.md).
                    pressure.iter_mut().for_each(|p| *p *= scale);
                }
                let zone = ContactZone::analyse(grid, &pressure)?;
                guess = approach;
                Ok(Trial {
                    result: (sampled, approach, status, pressure),
                    zone,
                })
            },
        )?;
        let (sampled, approach, status, pressure) = adapted.result;
        let mut zone = adapted.zone;
        if let Some(e) = sampled.extents(approach) {
            zone.extents = e;
        }
        let force = match control {
            LoadControl::Force(f) => f,
            LoadControl::Approach(_) | LoadControl::LineLoad(_) => zone.force,
        };
        Ok(NormalSolution {
            force,
            approach,
            max_pressure: zone.max_pressure,
            mean_pressure: force / zone.area,
            contact_area: zone.area,
            semi_axes: zone.half_extents(),
            orientation: sampled.rotation,
            zone,
            status,
            domains: adapted.domains,
            grid: adapted.grid,
            pressure,
            detail: PimpDetail {
                mode: self.options.mode,
            },
        })
    }
}

/// PimP's estimate of the contact zone, as the half-space solver's adaptive domain takes
/// it (`halfspace::Bem::with_estimate`): the bounding box
/// `[[x0, x1], [y0, y1]]` \[mm\] of the corrected-mode zone on a 48 × 48 grid, in the
/// principal frame of the gap. A PimP solve costs a small fraction of a half-space solve
/// and places the domain on curved, off-centre zones that a Hertz ellipse misses.
///
/// # Errors
/// None when built; the estimate itself fails as [`Pimp::solve`] does.
pub fn zone_estimate(
    body1: ElasticMaterial,
    body2: ElasticMaterial,
) -> Result<domain::ZoneEstimate> {
    let pimp = Pimp::new(
        body1,
        body2,
        PimpOptions {
            mode: Mode::Corrected,
            cells: [48, 48],
            ..PimpOptions::default()
        },
    )?;
    Ok(std::sync::Arc::new(
        move |source: &dyn GapSource, control: LoadControl| {
            Ok(pimp.solve(source, control)?.zone.extents)
        },
    ))
}

impl SampledGap {
    /// The approach \[mm\] at which this sampled gap carries `force` \[N\] (> 0), and the
    /// number of force evaluations it took; the grid is not adapted (the multi-body
    /// path: sample once per pose, then solve for forces).
    ///
    /// # Errors
    /// [`Error::InvalidInput`] for a non-positive force, [`Error::NotConverged`] when the
    /// force cannot be reached within `options.max_iterations` evaluations.
    pub fn approach_for_force(
        &self,
        force: Newton,
        options: &PimpOptions,
    ) -> Result<(Millimetre, usize)> {
        positive_as("force", force, "a finite force > 0 N")?;
        let start = self.start_unit * force.cbrt().powi(2);
        let (d, status) = equilibrium(self, force, start, options);
        let status = status.require_converged("PimP force equilibrium")?;
        Ok((d, status.iterations))
    }
}

/// Find the approach at which `sampled` carries `force`: expand a bracket from `guess`,
/// then the Illinois variant of regula falsi (superlinear, never leaves the bracket).
/// Returns the approach and the status: iterations are force evaluations, the residual
/// is the relative force error `|F(d) - F| / F` (converged), or the bracket's relative
/// width (not converged).
fn equilibrium(
    sampled: &SampledGap,
    force: Newton,
    guess: Millimetre,
    options: &PimpOptions,
) -> (Millimetre, SolveStatus) {
    let f = |d: f64| sampled.force(d) - force;
    let tol = options.tolerance * force;
    let mut evals = 0;
    let (mut lo, mut flo) = (0.0, -force);
    let mut hi = guess;
    let mut fhi = f(hi);
    evals += 1;
    while fhi < 0.0 {
        if evals >= options.max_iterations {
            // No approach carries the force within the budget.
            return (
                hi,
                SolveStatus::new(Termination::Diverged, evals, -fhi / force),
            );
        }
        (lo, flo) = (hi, fhi);
        // Extrapolate with F ∝ delta^(3/2) and a margin; double when nothing is loaded.
        let loaded = fhi + force;
        hi = if loaded > 0.0 {
            (hi * (force / loaded).powf(2.0 / 3.0) * 1.02).min(2.0 * hi)
        } else {
            2.0 * hi
        };
        fhi = f(hi);
        evals += 1;
    }
    if fhi.abs() <= tol {
        return (
            hi,
            SolveStatus::new(Termination::Converged, evals, fhi.abs() / force),
        );
    }
    // `flo`/`fhi` are scaled by the Illinois rule; only `fd` is a true residual.
    let mut side = 0i8;
    let mut side_repeats = 0;
    let mut last = (hi, fhi + force);
    let mut prev: Option<(f64, f64)> = None;
    while evals < options.max_iterations {
        if hi - lo <= 4.0 * f64::EPSILON * hi {
            // A jump of the published weights: the root is at the jump (the residual is
            // the jump's, measured once more, not counted as an evaluation).
            let residual = (sampled.force(hi) - force).abs() / force;
            return (
                hi,
                SolveStatus::new(Termination::Converged, evals, residual),
            );
        }
        // Power-law step from the last evaluation (exact for F ∝ delta^(3/2), the law of
        // every quadratic gap under both beddings), else Illinois, else bisection.
        // The exponent is estimated from the last two evaluations (a secant in log-log
        // coordinates, superlinear), 3/2 until there are two.
        let exponent = match prev {
            Some((d0, f0)) if f0 > 0.0 && last.1 > 0.0 && d0 != last.0 => {
                let n = (last.1 / f0).ln() / (last.0 / d0).ln();
                if n.is_finite() && n > 0.5 && n < 5.0 {
                    n
                } else {
                    1.5
                }
            }
            _ => 1.5,
        };
        let mut d = last.0 * (force / last.1).powf(1.0 / exponent);
        if !(last.1 > 0.0 && d > lo && d < hi) || side_repeats >= 3 {
            d = (lo * fhi - hi * flo) / (fhi - flo);
        }
        if !(d > lo && d < hi) {
            d = 0.5 * (lo + hi);
        }
        let fd = f(d);
        evals += 1;
        if fd.abs() <= tol {
            return (
                d,
                SolveStatus::new(Termination::Converged, evals, fd.abs() / force),
            );
        }
        prev = Some(last);
        last = (d, fd + force);
        let new_side = if fd < 0.0 { -1 } else { 1 };
        side_repeats = if new_side == side {
            side_repeats + 1
        } else {
            0
        };
        if fd < 0.0 {
            (lo, flo) = (d, fd);
            if side == -1 {
                fhi *= 0.5;
            }
        } else {
            (hi, fhi) = (d, fd);
            if side == 1 {
                flo *= 0.5;
            }
        }
        side = new_side;
    }
    (
        hi,
        SolveStatus::new(Termination::MaxIterations, evals, (hi - lo) / hi),
    )
}
