//! The PimP-versus-reference study of Wirsching et al. (2020) (Figures 7-10), with the coupled
//! elastic half-space solver in the place of FEM.
//!
//! For a roller-end/rib pairing and a list of forces \[N\], [`validate_pairing`] solves
//! the same substitute geometry with the half-space solver (the reference), with PimP in
//! both bedding laws, and with Hertz at the contact point's curvature, and returns the
//! maximum pressure \[MPa\], the area \[mm²\] and the approach \[mm\] of each, plus the
//! contact shapes at the largest force on one grid for overlays.

use crate::error::{Error, Result};
use crate::field::NormalSolution;
use crate::geometry::Grid2;
use crate::halfspace::{Bem, BemOptions};
use crate::hertz::{HertzPointContact, PointGeometry};
use crate::material::ElasticMaterial;
use crate::pimp::{GapSource, Mode, Pimp, PimpOptions, SurfacePairGap};

use super::{RollerRib, RollerRibSpec};

/// One method's headline numbers at one load.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct Headline {
    /// Largest pressure \[MPa\].
    pub max_pressure_mpa: f64,
    /// Contact area \[mm²\].
    pub contact_area_mm2: f64,
    /// Rigid approach \[mm\].
    pub approach_mm: f64,
    /// Half-extents of the zone (Hertz: semi-axes) \[mm\].
    pub semi_axes_mm: [f64; 2],
}

impl Headline {
    /// The headline numbers of any field solver's solution (PimP, the half-space solver).
    fn of<D>(s: &NormalSolution<D>) -> Self {
        Headline {
            max_pressure_mpa: s.max_pressure,
            contact_area_mm2: s.contact_area,
            approach_mm: s.approach,
            semi_axes_mm: s.semi_axes,
        }
    }
}

/// All methods at one load.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct ValidationRow {
    /// Normal force \[N\].
    pub force_n: f64,
    /// The coupled half-space solution (the reference).
    pub bem: Headline,
    /// PimP with the paper's bedding (Wirsching et al. (2020) eq. 7).
    pub pimp_published: Headline,
    /// PimP with the corrected bedding (docs/pimp.md).
    pub pimp_corrected: Headline,
    /// Hertz at the curvature of the contact point.
    pub hertz: Headline,
    /// Half-space solver iterations.
    pub bem_iterations: usize,
}

impl ValidationRow {
    /// `method / reference - 1` of the maximum pressure and the area, for PimP published,
    /// PimP corrected and Hertz (Wirsching et al. (2020) Figures 7-10 b and d).
    pub fn deviations(&self) -> [[f64; 2]; 3] {
        let rel = |h: &Headline| {
            [
                h.max_pressure_mpa / self.bem.max_pressure_mpa - 1.0,
                h.contact_area_mm2 / self.bem.contact_area_mm2 - 1.0,
            ]
        };
        [
            rel(&self.pimp_published),
            rel(&self.pimp_corrected),
            rel(&self.hertz),
        ]
    }
}

/// The contact shapes at one load on the half-space solver's grid (PimP's pressures
/// sampled at its cell centres), for overlays (Wirsching et al. (2020) Figures 7-10 c).
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct ShapeOverlay {
    /// Normal force \[N\].
    pub force_n: f64,
    /// The grid \[mm\] in the principal frame of the gap.
    pub grid: Grid2,
    /// Half-space pressure \[MPa\].
    pub bem: Vec<f64>,
    /// PimP (published) pressure on the same grid \[MPa\].
    pub pimp_published: Vec<f64>,
    /// PimP (corrected) pressure on the same grid \[MPa\].
    pub pimp_corrected: Vec<f64>,
    /// The grid's `x` and `y` axes as unit vectors in the bearing frame (`X` radial, `Y`
    /// circumferential at the contact point, `Z` the ring axis).
    pub axes: [[f64; 3]; 2],
}

/// The study of one pairing.
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct PairingStudy {
    /// The built-in pairing's name (Wirsching et al. (2020) Table 1).
    pub pairing: String,
    /// Rib angle \[deg\].
    pub rib_angle_deg: f64,
    /// One row per force.
    pub rows: Vec<ValidationRow>,
    /// Shapes at the largest force.
    pub overlay: ShapeOverlay,
}

impl PairingStudy {
    /// Mean, smallest and largest of [`ValidationRow::deviations`] over the rows (the
    /// loads): `[method][quantity] -> (mean, min, max)`, methods PimP published, PimP
    /// corrected, Hertz; quantities maximum pressure, area; each `method / reference - 1`
    /// \[-\]. No rows: means 0, min `inf`, max `-inf`.
    pub fn deviation_stats(&self) -> [[(f64, f64, f64); 2]; 3] {
        let mut out = [[(0.0, f64::INFINITY, f64::NEG_INFINITY); 2]; 3];
        for r in &self.rows {
            let d = r.deviations();
            for m in 0..3 {
                for k in 0..2 {
                    let (sum, lo, hi) = &mut out[m][k];
                    *sum += d[m][k];
                    *lo = lo.min(d[m][k]);
                    *hi = hi.max(d[m][k]);
                }
            }
        }
        let n = self.rows.len().max(1) as f64;
        for row in &mut out {
            for (sum, ..) in row.iter_mut() {
                *sum /= n;
            }
        }
        out
    }
}

/// Run the study for the built-in `pairing` (see [`super::TABLE1`]) at `forces` \[N\]
/// with the half-space solver's `options`, both bodies steel.
///
/// # Errors
/// An unknown pairing, an empty or invalid force list, and the solvers' errors.
pub fn validate_pairing(
    pairing: &str,
    forces: &[f64],
    options: BemOptions,
) -> Result<PairingStudy> {
    if forces.is_empty() {
        return Err(Error::invalid(
            "forces",
            "an empty list",
            "at least one force > 0 N",
        ));
    }
    let steel = ElasticMaterial::STEEL;
    let pair = RollerRib::new(RollerRibSpec::builtin(pairing)?)?;
    let gap = SurfacePairGap::new(pair.face, pair.rib, pair.contact)?;
    let bem =
        Bem::new(steel, steel, options)?.with_estimate(crate::pimp::zone_estimate(steel, steel)?);
    let pimp = |mode| {
        Pimp::new(
            steel,
            steel,
            PimpOptions {
                mode,
                ..PimpOptions::default()
            },
        )
    };
    let (published, corrected) = (pimp(Mode::Published)?, pimp(Mode::Corrected)?);
    let hertz =
        HertzPointContact::new(PointGeometry::from_curvature(gap.curvature()), steel, steel)?;
    let mut rows = Vec::with_capacity(forces.len());
    let mut last = None;
    for &f in forces {
        let b = bem.solve_force(&gap, f)?;
        let p = published.solve_force(&gap, f)?;
        let c = corrected.solve_force(&gap, f)?;
        let h = hertz.solve_force(f)?;
        rows.push(ValidationRow {
            force_n: f,
            bem: Headline::of(&b),
            pimp_published: Headline::of(&p),
            pimp_corrected: Headline::of(&c),
            hertz: Headline {
                max_pressure_mpa: h.max_pressure,
                contact_area_mm2: h.contact_area,
                approach_mm: h.approach,
                semi_axes_mm: h.semi_axes,
            },
            bem_iterations: b.status.iterations,
        });
        if last
            .as_ref()
            .is_none_or(|(lf, ..): &(f64, _, _, _)| f >= *lf)
        {
            last = Some((f, b, p, c));
        }
    }
    let (force_n, b, p, c) = last.ok_or_else(|| Error::invalid("forces", "none", "> 0 N"))?;
    let overlay = ShapeOverlay {
        force_n,
        grid: b.grid,
        pimp_published: resample(&p.grid, &p.pressure, &b.grid),
        pimp_corrected: resample(&c.grid, &c.pressure, &b.grid),
        bem: b.pressure,
        axes: gap.principal_axes(),
    };
    Ok(PairingStudy {
        pairing: pairing.to_string(),
        rib_angle_deg: pair.rib_angle_deg,
        rows,
        overlay,
    })
}

/// Sample `values` on `from` at the cell centres of `to` (nearest cell; zero outside).
/// Both grids must share the frame.
pub fn resample(from: &Grid2, values: &[f64], to: &Grid2) -> Vec<f64> {
    let (x0, y0) = (from.x(0) - 0.5 * from.dx(), from.y(0) - 0.5 * from.dy());
    to.points()
        .map(|(x, y)| {
            let (fi, fj) = ((x - x0) / from.dx(), (y - y0) / from.dy());
            if fi < 0.0 || fj < 0.0 {
                return 0.0;
            }
            let (i, j) = (fi as usize, fj as usize);
            if i < from.nx() && j < from.ny() {
                values[j * from.nx() + i]
            } else {
                0.0
            }
        })
        .collect()
}

#[cfg(test)]
mod tests {
    #![allow(clippy::unwrap_used)]
    use super::*;

    fn headline(p: f64, a: f64) -> Headline {
        Headline {
            max_pressure_mpa: p,
            contact_area_mm2: a,
            approach_mm: 0.01,
            semi_axes_mm: [0.1, 0.1],
        }
    }

    /// Two loads with deviations known exactly in binary (±0.5, ±0.25, 0): mean, min and
    /// max per method and quantity (exact).
    #[test]
    fn deviation_stats_are_mean_min_max_over_the_loads() {
        let row = |f, pub_p, corr_a, hertz_p| ValidationRow {
            force_n: f,
            bem: headline(1000.0, 1.0),
            pimp_published: headline(pub_p, 1.0),
            pimp_corrected: headline(1000.0, corr_a),
            hertz: headline(hertz_p, 1.0),
            bem_iterations: 1,
        };
        let grid = Grid2::centered(1.0, 1.0, 2, 2).unwrap();
        let study = PairingStudy {
            pairing: "test".into(),
            rib_angle_deg: 90.0,
            rows: vec![
                row(100.0, 1500.0, 0.75, 1000.0),
                row(200.0, 1250.0, 1.5, 500.0),
            ],
            overlay: ShapeOverlay {
                force_n: 200.0,
                grid,
                bem: vec![0.0; 4],
                pimp_published: vec![0.0; 4],
                pimp_corrected: vec![0.0; 4],
                axes: [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0]],
            },
        };
        let d = study.deviation_stats();
        assert_eq!(d[0][0], (0.375, 0.25, 0.5));
        assert_eq!(d[0][1], (0.0, 0.0, 0.0));
        assert_eq!(d[1][0], (0.0, 0.0, 0.0));
        assert_eq!(d[1][1], (0.125, -0.25, 0.5));
        assert_eq!(d[2][0], (-0.25, -0.5, 0.0));
        assert_eq!(d[2][1], (0.0, 0.0, 0.0));
    }
}
