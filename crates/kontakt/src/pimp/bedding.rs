//! The bedding laws: how an overlap becomes a pressure (PimP Steps 3 and 4).
//!
//! Both laws are local: the pressure in a cell depends on that cell's overlap only (the
//! springs are not coupled, as in the paper). The derivation of both is in
//! `docs/pimp.md`.
//!
//! - [`Mode::Published`]: Wirsching et al. (2020) eqs (5)-(7) read as
//!   `p = E* u (X + Y) / 2`, `u = d - g`, with the strip weights `X = 4 / (pi a)`,
//!   `Y = 4 / (pi b)` taken from the half-extents `a`, `b` of the cut footprint
//!   `{g < d}` along the principal axes, and `d` the rigid penetration (the approach).
//! - [`Mode::Corrected`]: the square-root bedding `p = c E* sqrt(A' u)`,
//!   `u = kappa delta - g - (A' - A) x'²`, whose constants make force-approach,
//!   semi-axes and maximum pressure exact for every elliptical Hertz contact.

use crate::error::Result;
use crate::geometry::RelativeCurvature;
use crate::hertz::{HertzPointContact, PointGeometry};
use crate::material::ElasticMaterial;
use crate::units::{Megapascal, Millimetre, Newton};
use std::f64::consts::PI;

/// Which bedding law the PimP solver uses.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
#[cfg_attr(
    feature = "serde",
    derive(serde::Serialize, serde::Deserialize, schemars::JsonSchema)
)]
#[cfg_attr(feature = "serde", serde(rename_all = "snake_case"))]
pub enum Mode {
    /// The method as published (Wirsching et al. 2020, eqs 5-7; Wirsching et al. 2019, eqs 4-6), with the reading
    /// documented in `docs/pimp.md`: linear springs, strip weights from the footprint,
    /// cut at the rigid penetration.
    Published,
    /// Square-root bedding with an anisotropic overlap correction, exact for elliptical
    /// Hertz contact (force, approach, semi-axes, maximum pressure and the pressure
    /// distribution itself); the default.
    #[default]
    Corrected,
}

impl Mode {
    /// The name used in case files and reports.
    pub fn as_str(self) -> &'static str {
        match self {
            Mode::Published => "published",
            Mode::Corrected => "corrected",
        }
    }
}

/// The bedding law planned for one gap shape and material pair.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) enum Bedding {
    /// `p = E* (2/pi) (1/a + 1/b) u`.
    Published { e_star: Megapascal },
    /// `p = stiffness sqrt(kappa delta - g̃)`, `g̃ = g + (A' - A) x'²`.
    Corrected {
        /// `c_p E* sqrt(A')` \[MPa / mm^0.5\].
        stiffness: f64,
        /// Cut fraction `h / delta` (1/2 for the circle).
        kappa: f64,
        /// `A' - A` \[1/mm\] (<= 0): the correction of the gap along the major axis.
        d_a: f64,
    },
}

impl Bedding {
    /// Plan the law for a gap whose quadratic form at the contact point is `curvature`.
    ///
    /// # Errors
    /// Only the Hertz shape inversion can fail, which it does not in the valid range of
    /// [`RelativeCurvature`].
    pub(crate) fn new(
        mode: Mode,
        curvature: RelativeCurvature,
        body1: ElasticMaterial,
        body2: ElasticMaterial,
    ) -> Result<Self> {
        let hertz = HertzPointContact::new(PointGeometry::from_curvature(curvature), body1, body2)?;
        Self::from_hertz(mode, curvature, &hertz)
    }

    /// Plan the law from a planned Hertz contact of the same curvature (saves the shape
    /// inversion when the caller has one).
    ///
    /// # Errors
    /// As [`Bedding::new`].
    pub(crate) fn from_hertz(
        mode: Mode,
        curvature: RelativeCurvature,
        hertz: &HertzPointContact,
    ) -> Result<Self> {
        let e_star = hertz.e_star();
        Ok(match mode {
            Mode::Published => Bedding::Published { e_star },
            Mode::Corrected => {
                let unit = hertz.solve_force(1.0)?;
                let [a, _] = unit.semi_axes;
                let k = hertz.axis_ratio();
                // Corrected quadratic form: B' = B, A' = B (b/a)² so that its contours
                // have the Hertz axis ratio; only the direction of the major axis changes.
                let b_p = curvature.b_coef;
                let a_p = b_p * k * k;
                let kappa = a_p * a * a / unit.approach;
                let c_p = unit.max_pressure / (e_star * a_p * a);
                Bedding::Corrected {
                    stiffness: c_p * e_star * a_p.sqrt(),
                    kappa,
                    d_a: a_p - curvature.a_coef,
                }
            }
        })
    }

    pub(crate) fn mode(&self) -> Mode {
        match self {
            Bedding::Published { .. } => Mode::Published,
            Bedding::Corrected { .. } => Mode::Corrected,
        }
    }

    /// The cut level for an approach: `d` (published) or `kappa delta` (corrected) \[mm\].
    pub(crate) fn cut(&self, approach: Millimetre) -> Millimetre {
        match *self {
            Bedding::Published { .. } => approach,
            Bedding::Corrected { kappa, .. } => kappa * approach,
        }
    }

    /// Pressure \[MPa\] of a cell with overlap `u = cut - g̃ > 0` \[mm\]; `inv_extent_sum`
    /// is `1/a + 1/b` \[1/mm\] of the footprint (published mode only).
    #[inline]
    pub(crate) fn pressure(&self, overlap: Millimetre, inv_extent_sum: f64) -> Megapascal {
        match *self {
            Bedding::Published { e_star } => e_star * (2.0 / PI) * inv_extent_sum * overlap,
            Bedding::Corrected { stiffness, .. } => stiffness * overlap.sqrt(),
        }
    }
}

/// A gap sampled on a grid and prepared for one bedding law: the multi-body path.
///
/// Evaluating the force for an approach touches every cell once and allocates nothing.
#[derive(Debug, Clone, PartialEq)]
pub struct SampledGap {
    pub(crate) grid: crate::geometry::Grid2,
    pub(crate) rotation: f64,
    /// `g` (published) or the corrected `g̃` (corrected) per cell \[mm\].
    pub(crate) effective: Vec<f64>,
    pub(crate) bedding: Bedding,
    /// Start value of the equilibrium iteration at 1 N \[mm\]: the Hertz approach of the
    /// contact point's curvature (times 0.6 for the published law); scales as F^(2/3).
    pub(crate) start_unit: Millimetre,
}

/// Footprint statistics of one evaluation.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Footprint {
    pub force: f64,
    pub inv_extent_sum: f64,
}

impl SampledGap {
    /// The grid \[mm\], in the principal frame of the gap (see [`SampledGap::rotation`]).
    pub fn grid(&self) -> &crate::geometry::Grid2 {
        &self.grid
    }

    /// Angle \[rad\] from the gap source's `x` axis to the grid's `x` axis (the direction
    /// of least relative curvature at the contact point).
    pub fn rotation(&self) -> f64 {
        self.rotation
    }

    /// The bedding law this gap was prepared for.
    pub fn mode(&self) -> Mode {
        self.bedding.mode()
    }

    /// The normal force \[N\] for a rigid approach `approach` \[mm\] (>= 0; 0 N below
    /// first contact). No allocation.
    pub fn force(&self, approach: Millimetre) -> Newton {
        self.footprint(approach).force
    }

    pub(crate) fn footprint(&self, approach: Millimetre) -> Footprint {
        let cut = self.bedding.cut(approach);
        let nx = self.grid.nx();
        let (mut sum, mut cells) = (0.0, 0usize);
        let (mut i0, mut i1, mut j0, mut j1) = (usize::MAX, 0, usize::MAX, 0);
        match self.bedding {
            Bedding::Published { .. } => {
                for (j, row) in self.effective.chunks_exact(nx).enumerate() {
                    let mut row_cells = 0usize;
                    for (i, &g) in row.iter().enumerate() {
                        if g < cut {
                            sum += cut - g;
                            row_cells += 1;
                            i0 = i0.min(i);
                            i1 = i1.max(i);
                        }
                    }
                    if row_cells > 0 {
                        cells += row_cells;
                        j0 = j0.min(j);
                        j1 = j1.max(j);
                    }
                }
            }
            Bedding::Corrected { .. } => {
                // Branch-free, four independent accumulators so the loop vectorises:
                // sum of max(0, u)^(1/2).
                let mut acc = [0.0f64; 4];
                let chunks = self.effective.chunks_exact(4);
                let rest = chunks.remainder();
                for c in chunks {
                    for (a, &g) in acc.iter_mut().zip(c) {
                        *a += (cut - g).max(0.0).sqrt();
                    }
                }
                for &g in rest {
                    acc[0] += (cut - g).max(0.0).sqrt();
                }
                sum = (acc[0] + acc[1]) + (acc[2] + acc[3]);
                cells = usize::from(sum > 0.0);
            }
        }
        let inv_extent_sum = if cells > 0 && matches!(self.bedding, Bedding::Published { .. }) {
            let a = 0.5 * (i1 - i0 + 1) as f64 * self.grid.dx();
            let b = 0.5 * (j1 - j0 + 1) as f64 * self.grid.dy();
            1.0 / a + 1.0 / b
        } else {
            0.0
        };
        let force = if cells == 0 {
            0.0
        } else {
            // Both laws are homogeneous in their summand: p(u) = p(1) * (u or sqrt u).
            self.bedding.pressure(1.0, inv_extent_sum) * sum * self.grid.cell_area()
        };
        Footprint {
            force,
            inv_extent_sum,
        }
    }

    /// Extents `[[x_min, x_max], [y_min, y_max]]` \[mm\] of the footprint at `approach`,
    /// with the boundary placed where the overlap, linearly interpolated between a loaded
    /// cell and its unloaded neighbour, vanishes (a loaded cell on the grid border
    /// extends to the border). `None` when nothing is loaded.
    pub(crate) fn extents(&self, approach: Millimetre) -> Option<[[f64; 2]; 2]> {
        let cut = self.bedding.cut(approach);
        let (nx, ny) = (self.grid.nx(), self.grid.ny());
        let (dx, dy) = (self.grid.dx(), self.grid.dy());
        let u = |i: usize, j: usize| cut - self.effective[j * nx + i];
        let mut ext = [[f64::INFINITY, f64::NEG_INFINITY]; 2];
        let mut loaded = false;
        for j in 0..ny {
            for i in 0..nx {
                let ui = u(i, j);
                if !(ui > 0.0) {
                    continue;
                }
                loaded = true;
                let (x, y) = (self.grid.x(i), self.grid.y(j));
                // Crossing towards a neighbour at offset `step`, whose overlap is `un`.
                let edge = |un: Option<f64>, half: f64| match un {
                    Some(un) if !(un > 0.0) => {
                        if un.is_finite() {
                            2.0 * half * ui / (ui - un)
                        } else {
                            half
                        }
                    }
                    Some(_) => 0.0,
                    None => half,
                };
                let left = edge((i > 0).then(|| u(i - 1, j)), 0.5 * dx);
                let right = edge((i + 1 < nx).then(|| u(i + 1, j)), 0.5 * dx);
                let down = edge((j > 0).then(|| u(i, j - 1)), 0.5 * dy);
                let up = edge((j + 1 < ny).then(|| u(i, j + 1)), 0.5 * dy);
                ext[0][0] = ext[0][0].min(x - left);
                ext[0][1] = ext[0][1].max(x + right);
                ext[1][0] = ext[1][0].min(y - down);
                ext[1][1] = ext[1][1].max(y + up);
            }
        }
        loaded.then_some(ext)
    }

    /// The pressure field \[MPa\] at `approach` \[mm\] into `out` (`len == grid.len()`).
    pub(crate) fn pressure_into(&self, approach: Millimetre, out: &mut [f64]) {
        let fp = self.footprint(approach);
        let cut = self.bedding.cut(approach);
        for (o, &g) in out.iter_mut().zip(&self.effective) {
            *o = if g < cut {
                self.bedding.pressure(cut - g, fp.inv_extent_sum)
            } else {
                0.0
            };
        }
    }
}
