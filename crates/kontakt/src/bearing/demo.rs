//! The roller-end/rib demo study (`kontakt demo`): the eight pairings of Wirsching et al. (2020) Table 1,
//! both bedding laws of PimP, every force of a list \[N\] (the demo uses
//! [`super::STUDY_FORCES`], 100-400 N: 8 x 2 x 7 = 112 solves), each beside Hertz at the
//! curvature of the contact point.
//!
//! [`demo_study`] returns plain rows (maximum pressure \[MPa\], area \[mm²\], approach
//! \[mm\], half-extents \[mm\], patches, centre-line curvature \[1/mm\], Hertz p0 \[MPa\] and
//! area \[mm²\]) and the corrected pressure field of each pairing at the largest force, for
//! maps. Rendering (tables, plots, CSV, Markdown) is the CLI's.
//!
//! Assumptions: both bodies steel ([`ElasticMaterial::STEEL`]), the default bearing and
//! contact height of [`super::RollerRibSpec::builtin`], PimP's default options otherwise.
//! Hertz is exact for the quadratic gap at the contact point; on the Hertzian pairings the
//! corrected PimP agrees with it (docs/VALIDATION.md, "PimP against Hertz").

use crate::error::{Error, Result};
use crate::geometry::Grid2;
use crate::hertz::{HertzPointContact, PointGeometry};
use crate::material::ElasticMaterial;
use crate::pimp::{GapSource, Mode, Pimp, PimpOptions, SurfacePairGap};

use super::{RollerRib, RollerRibSpec, TABLE1};

/// One row of the demo study: one pairing, one bedding law, one force. Field names are
/// the columns of the demo's `results.csv`.
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct DemoRow {
    /// Pairing name (Wirsching et al. 2020, Table 1).
    pub pairing: &'static str,
    /// Bedding law (`corrected` or `published`).
    pub mode: &'static str,
    /// Rib angle \[deg\].
    pub rib_angle_deg: f64,
    /// Force \[N\].
    pub force_n: f64,
    /// PimP maximum pressure \[MPa\].
    pub max_pressure_mpa: f64,
    /// PimP contact area \[mm²\].
    pub contact_area_mm2: f64,
    /// PimP approach \[mm\].
    pub approach_mm: f64,
    /// Half-extent of the zone along its first axis \[mm\].
    pub semi_axis_a_mm: f64,
    /// Half-extent of the zone along its second axis \[mm\].
    pub semi_axis_b_mm: f64,
    /// Number of contact patches.
    pub patches: usize,
    /// Centre-line curvature of a curved zone [1/mm], if fitted.
    pub centre_line_curvature_per_mm: Option<f64>,
    /// Hertz p0 at the contact point's curvature \[MPa\].
    pub hertz_max_pressure_mpa: f64,
    /// Hertz contact area \[mm²\].
    pub hertz_contact_area_mm2: f64,
}

/// The corrected PimP pressure field of one pairing at the study's largest force.
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct DemoMap {
    /// Pairing name.
    pub pairing: &'static str,
    /// Force \[N\].
    pub force_n: f64,
    /// PimP's grid \[mm\].
    pub grid: Grid2,
    /// Pressure on the grid \[MPa\].
    pub pressure: Vec<f64>,
    /// Semi-axes [a, b] \[mm\] of the Hertz ellipse at the contact point's curvature and
    /// this force; in the grid's frame `a` lies along `x`, `b` along `y`, centred at the
    /// origin (the contact point).
    pub hertz_semi_axes_mm: [f64; 2],
    /// The grid's `x` and `y` axes as unit vectors in the bearing frame (`X` radial, `Y`
    /// circumferential at the contact point, `Z` the ring axis).
    pub axes: [[f64; 3]; 2],
}

/// The result of [`demo_study`].
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct DemoStudy {
    /// Rows in the order pairing (Table 1), mode (corrected, published), force (as given).
    pub rows: Vec<DemoRow>,
    /// One map per pairing (Table 1 order).
    pub maps: Vec<DemoMap>,
}

/// Run the demo study over every pairing of [`TABLE1`], both bedding laws and `forces`
/// \[N\] (each finite, > 0), steel on steel; maps of the corrected mode at the largest
/// force.
///
/// # Errors
/// An empty force list ([`Error::InvalidInput`], field `forces`) and the errors of the
/// solvers (e.g. a non-positive force).
pub fn demo_study(forces: &[f64]) -> Result<DemoStudy> {
    let map_force = forces
        .iter()
        .copied()
        .reduce(f64::max)
        .ok_or_else(|| Error::invalid("forces", "an empty list", "at least one force > 0 N"))?;
    let steel = ElasticMaterial::STEEL;
    let mut rows = Vec::new();
    let mut maps = Vec::new();
    for &(name, ..) in TABLE1.iter() {
        let pair = RollerRib::new(RollerRibSpec::builtin(name)?)?;
        let angle = pair.rib_angle_deg;
        let gap = SurfacePairGap::new(pair.face, pair.rib, pair.contact)?;
        let hertz = HertzPointContact::new(
            PointGeometry::from_curvature(GapSource::curvature(&gap)),
            steel,
            steel,
        )?;
        for mode in [Mode::Corrected, Mode::Published] {
            let pimp = Pimp::new(
                steel,
                steel,
                PimpOptions {
                    mode,
                    ..Default::default()
                },
            )?;
            for &f in forces {
                let s = pimp.solve_force(&gap, f)?;
                let h = hertz.solve_force(f)?;
                rows.push(DemoRow {
                    pairing: name,
                    mode: mode.as_str(),
                    rib_angle_deg: angle,
                    force_n: f,
                    max_pressure_mpa: s.max_pressure,
                    contact_area_mm2: s.contact_area,
                    approach_mm: s.approach,
                    semi_axis_a_mm: s.semi_axes[0],
                    semi_axis_b_mm: s.semi_axes[1],
                    patches: s.zone.patches,
                    centre_line_curvature_per_mm: s.zone.centre_line_curvature,
                    hertz_max_pressure_mpa: h.max_pressure,
                    hertz_contact_area_mm2: h.contact_area,
                });
                if mode == Mode::Corrected
                    && f == map_force
                    && maps.last().is_none_or(|m: &DemoMap| m.pairing != name)
                {
                    maps.push(DemoMap {
                        pairing: name,
                        force_n: f,
                        grid: s.grid,
                        pressure: s.pressure,
                        hertz_semi_axes_mm: h.semi_axes,
                        axes: gap.principal_axes(),
                    });
                }
            }
        }
    }
    Ok(DemoStudy { rows, maps })
}
