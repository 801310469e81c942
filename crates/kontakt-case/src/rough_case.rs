//! Rough-contact cases (`method = "rough"`, `schema_version = 1`): a periodic rough
//! surface (generated self-affine, or a measured height map) pressed against a flat on the
//! periodic half-space solver at several nominal pressures, and its report: the real
//! contact area, κ of `A/A0 = κ p̄/(E* h'_rms)`, Persson's area, patches and the mean gap per
//! load. The physics is [`kontakt::rough::SelfAffineSpec`] and
//! [`kontakt::rough::RoughContact`] (docs/rough.md §5).
//!
//! ```toml
//! name = "self-affine surface, H = 0.8"
//! method = "rough"
//!
//! [surface]
//! kind = "self_affine"          # or kind = "map": file, spacing_mm (heights, periodic)
//! points = [256, 256]
//! size_mm = [0.5, 0.5]
//! hurst = 0.8
//! long_cutoff_mm = 0.5
//! rolloff_mm = 0.5              # optional, default long_cutoff_mm (no plateau)
//! short_cutoff_mm = 0.015625    # at least two cells
//! rms_slope = 0.1               # or rms_height_mm
//! seed = 1
//!
//! [body1]
//! e_mpa = 210000.0
//! nu = 0.3
//! [body2]
//! e_mpa = 210000.0
//! nu = 0.3
//!
//! [load]
//! mean_pressure_mpa = [50.0, 100.0, 200.0, 400.0]   # nominal pressures, ascending
//!
//! [solver]                      # optional
//! tolerance = 1e-6
//! max_iterations = 3000
//! ```

use crate::common::{MaterialSpec, SCHEMA_VERSION, material, parse_toml};
use kontakt::gap::{GapMap, MapKind};
use kontakt::material::effective_modulus;
use kontakt::rough::{Amplitude, RoughContact, SelfAffineSpec};
use kontakt::{Error, Result};
use serde::{Deserialize, Serialize};
use std::path::Path;

/// A rough-contact case, as read from TOML.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RoughCase {
    /// Optional label echoed in the report.
    #[serde(default)]
    pub name: Option<String>,
    /// Must be `"rough"`.
    pub method: String,
    /// The rough surface (the combined topography of both bodies).
    pub surface: SurfaceSpec,
    /// Body 1 material.
    pub body1: MaterialSpec,
    /// Body 2 material.
    pub body2: MaterialSpec,
    /// The nominal pressures.
    pub load: RoughLoad,
    /// Solver options.
    #[serde(default)]
    pub solver: RoughSolverSpec,
}

/// `[surface]`.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(tag = "kind", rename_all = "snake_case", deny_unknown_fields)]
pub enum SurfaceSpec {
    /// A random self-affine surface ([`kontakt::rough::SelfAffineSpec`]).
    SelfAffine {
        /// Grid points `[nx, ny]`, even, 4..=16384.
        points: [usize; 2],
        /// Size of the periodic cell \[mm\].
        size_mm: [f64; 2],
        /// Hurst exponent, 0 < H < 1.
        hurst: f64,
        /// Long-wavelength cut-off \[mm\].
        long_cutoff_mm: f64,
        /// Roll-off wavelength \[mm\] (default: the long cut-off).
        #[serde(default)]
        rolloff_mm: Option<f64>,
        /// Short-wavelength cut-off \[mm\].
        short_cutoff_mm: f64,
        /// Rms slope \[-\] (exactly one of `rms_slope`, `rms_height_mm`).
        #[serde(default)]
        rms_slope: Option<f64>,
        /// Rms height \[mm\].
        #[serde(default)]
        rms_height_mm: Option<f64>,
        /// Seed of the random phases.
        seed: u64,
    },
    /// A measured height map, periodic: a CSV matrix or `.npy` array (with `spacing_mm`),
    /// or a file that carries its grid, `.xyz` or ISO 25178-71 ASCII `.sdf`
    /// ([`crate::topography`]).
    Map {
        /// The file, relative to the case file's folder.
        file: String,
        /// Cell size `[dx, dy]` \[mm\]: needed for CSV and `.npy`, refused for `.xyz` and
        /// `.sdf` (their files give it).
        #[serde(default)]
        spacing_mm: Option<[f64; 2]>,
    },
}

/// `[load]`.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RoughLoad {
    /// Nominal pressures \[MPa\], ascending, each > 0; 1..=100 of them.
    pub mean_pressure_mpa: Vec<f64>,
}

/// `[solver]`.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct RoughSolverSpec {
    /// Relative residual, 1e-14..=1e-2 (default 1e-6).
    pub tolerance: f64,
    /// Most iterations per load (default 3000).
    pub max_iterations: usize,
}

impl Default for RoughSolverSpec {
    fn default() -> Self {
        RoughSolverSpec {
            tolerance: 1e-6,
            max_iterations: 3000,
        }
    }
}

/// One load of a [`RoughReport`].
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct RoughRow {
    /// Nominal pressure \[MPa\].
    pub mean_pressure_mpa: f64,
    /// `p̄/(E* h'_rms)` \[-\].
    pub reduced_pressure: f64,
    /// Force on the periodic cell \[N\].
    pub force_n: f64,
    /// Real contact area over the nominal area \[-\].
    pub area_fraction: f64,
    /// `κ` \[-\].
    pub kappa: f64,
    /// Persson's area fraction \[-\].
    pub persson_area_fraction: f64,
    /// Largest pressure \[MPa\].
    pub max_pressure_mpa: f64,
    /// Mean pressure on the real contact area \[MPa\].
    pub real_mean_pressure_mpa: f64,
    /// Contact patches (joined by cell sides, across the periodic borders too).
    pub patches: usize,
    /// Mean patch area \[mm²\].
    pub mean_patch_area_mm2: f64,
    /// Largest patch area \[mm²\].
    pub largest_patch_area_mm2: f64,
    /// Mean gap \[mm\].
    pub mean_gap_mm: f64,
    /// Solver iterations.
    pub iterations: usize,
}

/// The result of a rough-contact case. Keys carry their units.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct RoughReport {
    /// Version of kontakt that produced the record.
    pub kontakt_version: &'static str,
    /// Version of this schema.
    pub schema_version: u32,
    /// The case's name, if any.
    pub name: Option<String>,
    /// `"rough"`.
    pub method: &'static str,
    /// `"self_affine"` or `"map"`.
    pub surface: &'static str,
    /// Grid points `[nx, ny]`.
    pub points: [usize; 2],
    /// Cell size `[dx, dy]` \[mm\].
    pub spacing_mm: [f64; 2],
    /// Rms height \[mm\].
    pub rms_height_mm: f64,
    /// Rms slope \[-\] (self-affine: spectral; map: central differences, periodic).
    pub rms_slope: f64,
    /// Contact modulus E* \[MPa\].
    pub e_star_mpa: f64,
    /// One row per load, in the case's order.
    pub rows: Vec<RoughRow>,
}

/// A rough case's report and the pressure field at its highest load (for maps).
#[derive(Debug, Clone, PartialEq)]
pub struct RoughOutcome {
    /// The report.
    pub report: RoughReport,
    /// The grid \[mm\].
    pub grid: kontakt::geometry::Grid2,
    /// The pressure per cell at the last (highest) load \[MPa\].
    pub pressure: Vec<f64>,
}

impl RoughCase {
    /// Parse a rough-contact case from TOML text.
    ///
    /// # Errors
    /// [`Error::CaseFile`] (line, key path, what the schema takes) for malformed TOML,
    /// unknown keys or wrong types.
    pub fn from_toml_str(text: &str) -> Result<Self> {
        parse_toml(text)
    }
}

/// Run a rough-contact case; a map file is read relative to `base_dir`.
///
/// # Errors
/// [`Error::InvalidInput`] naming the case key (`surface.hurst`, `surface.short_cutoff_mm`,
/// `load.mean_pressure_mpa[2]`, ...), a map that cannot be read, and
/// [`Error::NotConverged`].
pub fn run_rough_case(case: &RoughCase, base_dir: &Path) -> Result<RoughOutcome> {
    crate::validity::checked(run_rough_case_unchecked(case, base_dir)?)
}

/// [`run_rough_case`] before the validity check of [`crate::validity::checked`].
pub(crate) fn run_rough_case_unchecked(case: &RoughCase, base_dir: &Path) -> Result<RoughOutcome> {
    if case.method != "rough" {
        return Err(Error::invalid(
            "method",
            &case.method,
            "\"rough\" for this schema",
        ));
    }
    let m1 = material(&case.body1, "body1")?;
    let m2 = material(&case.body2, "body2")?;
    let e_star = effective_modulus(&m1, &m2);
    let loads = &case.load.mean_pressure_mpa;
    if loads.is_empty() || loads.len() > 100 {
        return Err(Error::invalid(
            "load.mean_pressure_mpa",
            format!("{} values", loads.len()),
            "1..=100 nominal pressures [MPa]",
        ));
    }
    for (i, w) in loads.windows(2).enumerate() {
        if w[1] <= w[0] {
            return Err(Error::invalid(
                format!("load.mean_pressure_mpa[{}]", i + 1),
                w[1],
                format!("ascending pressures, > {} MPa", w[0]),
            ));
        }
    }
    let (label, map, rms_height, rms_slope) = match &case.surface {
        SurfaceSpec::SelfAffine {
            points,
            size_mm,
            hurst,
            long_cutoff_mm,
            rolloff_mm,
            short_cutoff_mm,
            rms_slope,
            rms_height_mm,
            seed,
        } => {
            let amplitude = match (rms_slope, rms_height_mm) {
                (Some(s), None) => Amplitude::RmsSlope(*s),
                (None, Some(h)) => Amplitude::RmsHeight(*h),
                (s, _) => {
                    return Err(Error::invalid(
                        "surface",
                        if s.is_some() {
                            "both rms_slope and rms_height_mm"
                        } else {
                            "neither rms_slope nor rms_height_mm"
                        },
                        "exactly one of rms_slope [-] or rms_height_mm [mm]",
                    ));
                }
            };
            let spec = SelfAffineSpec {
                points: *points,
                size: *size_mm,
                hurst: *hurst,
                long_cutoff: *long_cutoff_mm,
                rolloff: rolloff_mm.unwrap_or(*long_cutoff_mm),
                short_cutoff: *short_cutoff_mm,
                amplitude,
                seed: *seed,
            };
            let s = spec.generate().map_err(|e| {
                e.map_field(|f| match f {
                    "amplitude.rms_slope" => "surface.rms_slope".into(),
                    "amplitude.rms_height" => "surface.rms_height_mm".into(),
                    "size[0]" => "surface.size_mm[0]".into(),
                    "size[1]" => "surface.size_mm[1]".into(),
                    "points[0]" => "surface.points[0]".into(),
                    "points[1]" => "surface.points[1]".into(),
                    "long_cutoff" | "rolloff" | "short_cutoff" => format!("surface.{f}_mm"),
                    other => format!("surface.{other}"),
                })
            })?;
            ("self_affine", s.height_map()?, s.rms_height, s.rms_slope)
        }
        SurfaceSpec::Map { file, spacing_mm } => {
            let path = base_dir.join(file);
            let map = match (crate::topography::carries_grid(&path), spacing_mm) {
                (true, None) => crate::topography::read_topography(&path)?,
                (true, Some(s)) => {
                    return Err(Error::invalid(
                        "surface.spacing_mm",
                        format!("{s:?}"),
                        "no spacing_mm for an .xyz or .sdf file (the file gives its grid)",
                    ));
                }
                (false, None) => {
                    return Err(Error::invalid(
                        "surface.spacing_mm",
                        "missing",
                        "the cell size [dx, dy] in mm of a CSV or .npy map",
                    ));
                }
                (false, Some(spacing)) => {
                    crate::maps::read_gap_map(&path, *spacing, MapKind::Height).map_err(|e| {
                        e.map_field(|f| match f {
                            "spacing[0]" => "surface.spacing_mm[0]".into(),
                            "spacing[1]" => "surface.spacing_mm[1]".into(),
                            _ => "surface.file".into(),
                        })
                    })?
                }
            };
            let spacing = [map.grid().dx(), map.grid().dy()];
            let (h, s) = map_roughness(&map, spacing);
            if !(s > 0.0) {
                return Err(Error::invalid(
                    "surface.file",
                    file,
                    "a height map that is not flat (its rms slope is 0)",
                ));
            }
            ("map", map, h, s)
        }
    };
    let mut contact = RoughContact::new(
        &map,
        e_star,
        rms_slope,
        kontakt::halfspace::SolverOptions {
            tolerance: case.solver.tolerance,
            max_iterations: case.solver.max_iterations,
            ..Default::default()
        },
    )
    .map_err(|e| e.map_field(|f| format!("solver.{f}")))?;
    let mut rows = Vec::with_capacity(loads.len());
    for (i, &p) in loads.iter().enumerate() {
        let r = contact
            .solve(p)
            .map_err(|e| e.map_field(|_| format!("load.mean_pressure_mpa[{i}]")))?;
        rows.push(RoughRow {
            mean_pressure_mpa: p,
            reduced_pressure: p / (e_star * rms_slope),
            force_n: r.force,
            area_fraction: r.area_fraction,
            kappa: r.kappa,
            persson_area_fraction: r.persson_area_fraction,
            max_pressure_mpa: r.max_pressure,
            real_mean_pressure_mpa: r.real_mean_pressure,
            patches: r.patches,
            mean_patch_area_mm2: r.mean_patch_area,
            largest_patch_area_mm2: r.largest_patch_area,
            mean_gap_mm: r.mean_gap,
            iterations: r.status.iterations,
        });
    }
    let grid = *contact.grid();
    Ok(RoughOutcome {
        report: RoughReport {
            kontakt_version: kontakt::VERSION,
            schema_version: SCHEMA_VERSION,
            name: case.name.clone(),
            method: "rough",
            surface: label,
            points: [grid.nx(), grid.ny()],
            spacing_mm: [grid.dx(), grid.dy()],
            rms_height_mm: rms_height,
            rms_slope,
            e_star_mpa: e_star,
            rows,
        },
        grid,
        pressure: contact.pressure().to_vec(),
    })
}

/// Rms height and rms slope (central differences, periodic) of a height map. The map's
/// values are the gap `max(z) - z`, whose deviations are those of `z` with the sign
/// reversed: the same rms values.
fn map_roughness(map: &GapMap, spacing: [f64; 2]) -> (f64, f64) {
    let (nx, ny) = (map.grid().nx(), map.grid().ny());
    let v = map.values();
    let n = v.len() as f64;
    let mean = v.iter().sum::<f64>() / n;
    let rms_h = (v.iter().map(|x| (x - mean) * (x - mean)).sum::<f64>() / n).sqrt();
    let at = |i: usize, j: usize| v[(j % ny) * nx + (i % nx)];
    let mut s2 = 0.0;
    for j in 0..ny {
        for i in 0..nx {
            let gx = (at(i + 1, j) - at(i + nx - 1, j)) / (2.0 * spacing[0]);
            let gy = (at(i, j + 1) - at(i, j + ny - 1)) / (2.0 * spacing[1]);
            s2 += gx * gx + gy * gy;
        }
    }
    (rms_h, (s2 / n).sqrt())
}
