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
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize, schemars::JsonSchema)]
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
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize, schemars::JsonSchema)]
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
        /// Unit of the file's lengths: `"mm"` (default), `"um"` (or `"µm"`), `"nm"`, `"m"`;
        /// the heights of a CSV or `.npy` map, `x`, `y` and `z` of an `.xyz` file. Refused
        /// for `.sdf` (its header gives the scales).
        #[serde(default)]
        unit: Option<String>,
        /// Factor on the heights after `unit` (a profilometer's raw counts), > 0, default 1.
        #[serde(default)]
        scale: Option<f64>,
    },
}

/// `[load]`.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize, schemars::JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct RoughLoad {
    /// Nominal pressures \[MPa\], ascending, each > 0; 1..=100 of them.
    pub mean_pressure_mpa: Vec<f64>,
    /// Indentation hardness of the softer body \[MPa\] (optional, > 0): the report warns at
    /// each load whose largest pressure exceeds it (plastic flow of the summits, outside the
    /// elastic solution). Without it the report warns above `0.1 E*`, above the hardness of
    /// any metal.
    #[serde(default)]
    pub hardness_mpa: Option<f64>,
}

/// `[solver]`.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize, schemars::JsonSchema)]
#[serde(deny_unknown_fields, default)]
pub struct RoughSolverSpec {
    /// Relative residual, 1e-14..=1e-2 (default 1e-6).
    pub tolerance: f64,
    /// Most iterations per load (default 3000).
    pub max_iterations: usize,
    /// Memory budget \[GiB\] (default [`DEFAULT_MEMORY_GIB`]): a grid whose estimated
    /// memory ([`memory_estimate`]) exceeds it is refused before anything is allocated.
    pub max_memory_gib: f64,
}

impl Default for RoughSolverSpec {
    fn default() -> Self {
        RoughSolverSpec {
            tolerance: 1e-6,
            max_iterations: 3000,
            max_memory_gib: DEFAULT_MEMORY_GIB,
        }
    }
}

/// Default memory budget of a rough case \[GiB\]: 16, two thirds of a 24 GiB machine (the
/// rest for the system and the plots). 8192 × 8192 cells take about 9 GiB; 16384 × 16384
/// about 35 GiB, refused.
pub const DEFAULT_MEMORY_GIB: f64 = 16.0;

/// The bytes a rough case of `points` cells will hold while it solves: the contact
/// ([`RoughContact::memory_estimate`]: solver, gap, patch search), the height map and the
/// pressure copied into the outcome (8 bytes per cell each). About 137 bytes per cell.
///
/// # Errors
/// [`Error::InvalidInput`] for a thread count outside its range.
pub fn memory_estimate(
    points: [usize; 2],
    options: &kontakt::halfspace::SolverOptions,
) -> Result<u64> {
    let n = (points[0] as u64).saturating_mul(points[1] as u64);
    Ok(RoughContact::memory_estimate(points, options)?.saturating_add(n.saturating_mul(16)))
}

/// Refuse a grid whose [`memory_estimate`] exceeds `solver.max_memory_gib`, naming `key`
/// (the case key the grid comes from) with the estimate and the budget.
fn check_memory(
    key: &'static str,
    points: [usize; 2],
    budget_gib: f64,
    options: &kontakt::halfspace::SolverOptions,
) -> Result<()> {
    let bytes = memory_estimate(points, options)?;
    let gib = bytes as f64 / f64::from(1u32 << 30);
    if gib > budget_gib {
        let per_cell = bytes as f64 / (points[0] as f64 * points[1] as f64);
        let side = ((budget_gib * f64::from(1u32 << 30) / per_cell).sqrt() as usize) & !1;
        return Err(Error::invalid(
            key,
            format!("{points:?}"),
            format!(
                "a grid whose estimated memory fits solver.max_memory_gib = {budget_gib} GiB; \
                 {} x {} cells need about {} ({per_cell:.0} bytes per cell), the budget \
                 holds about {side} x {side}",
                points[0],
                points[1],
                if gib >= 1.0 {
                    format!("{gib:.1} GiB")
                } else {
                    format!("{:.1} MiB", gib * 1024.0)
                }
            ),
        ));
    }
    Ok(())
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
    /// What the user should know about the input or the result: header lines skipped in
    /// the map file, a map that is not periodic, pressures above the hardness.
    pub warnings: Vec<String>,
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
    let budget = case.solver.max_memory_gib;
    if !(budget.is_finite() && budget > 0.0) {
        return Err(Error::invalid(
            "solver.max_memory_gib",
            budget,
            "a finite memory budget > 0 GiB",
        ));
    }
    let options = kontakt::halfspace::SolverOptions {
        tolerance: case.solver.tolerance,
        max_iterations: case.solver.max_iterations,
        ..Default::default()
    };
    let hardness = match case.load.hardness_mpa {
        Some(h) if !(h.is_finite() && h > 0.0) => {
            return Err(Error::invalid(
                "load.hardness_mpa",
                h,
                "a finite hardness > 0 MPa",
            ));
        }
        h => h,
    };
    let mut warnings = Vec::new();
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
            let name_key = |e: Error| {
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
            };
            // Checked, then counted before the surface is generated: nothing is allocated
            // for a grid beyond the budget (16384² aborted the process on an allocation
            // failure).
            spec.validate().map_err(name_key)?;
            check_memory("surface.points", *points, budget, &options)?;
            let s = spec.generate().map_err(name_key)?;
            ("self_affine", s.height_map()?, s.rms_height, s.rms_slope)
        }
        SurfaceSpec::Map {
            file,
            spacing_mm,
            unit,
            scale,
        } => {
            let path = base_dir.join(file);
            let is_sdf = path
                .extension()
                .is_some_and(|e| e.eq_ignore_ascii_case("sdf"));
            let to_mm = match unit.as_deref() {
                Some(u) if is_sdf => {
                    return Err(Error::invalid(
                        "surface.unit",
                        u,
                        "no unit for an .sdf file (its header gives the scales in metres)",
                    ));
                }
                None | Some("mm") => 1.0,
                Some("um" | "µm" | "μm") => 1e-3,
                Some("nm") => 1e-6,
                Some("m") => 1e3,
                Some(u) => {
                    return Err(Error::invalid(
                        "surface.unit",
                        u,
                        "\"mm\", \"um\" (or \"µm\"), \"nm\" or \"m\"",
                    ));
                }
            };
            let scale = match *scale {
                None => 1.0,
                Some(s) if s.is_finite() && s > 0.0 => s,
                Some(s) => {
                    return Err(Error::invalid(
                        "surface.scale",
                        s,
                        "a finite factor > 0 on the heights",
                    ));
                }
            };
            let (map, skipped) = match (crate::topography::carries_grid(&path), spacing_mm) {
                (true, None) => {
                    let t = crate::topography::read_topography(&path, to_mm)?;
                    (t.map, t.skipped_lines)
                }
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
                    let m = crate::maps::read_gap_map(&path, *spacing, MapKind::Height, to_mm)
                        .map_err(|e| {
                            e.map_field(|f| match f {
                                "spacing[0]" => "surface.spacing_mm[0]".into(),
                                "spacing[1]" => "surface.spacing_mm[1]".into(),
                                _ => "surface.file".into(),
                            })
                        })?;
                    (m.map, m.skipped_lines)
                }
            };
            warnings.extend(crate::maps::skipped_note("surface.file", skipped));
            check_memory(
                "surface.file",
                [map.grid().nx(), map.grid().ny()],
                budget,
                &options,
            )?;
            let map = if scale == 1.0 {
                map
            } else {
                // The values are gaps max(z) - z: a factor > 0 on z is the same on them.
                let g = map.grid();
                let values = map.values().iter().map(|v| v * scale).collect();
                GapMap::new(g.nx(), g.ny(), [g.dx(), g.dy()], values, MapKind::Gap)
                    .map_err(|e| e.map_field(|_| "surface.scale".into()))?
            };
            warnings.extend(periodicity_warning(&map));
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
    let mut contact = RoughContact::new(&map, e_star, rms_slope, options).map_err(|e| {
        e.map_field(|f| match (f, &case.surface) {
            ("grid", SurfaceSpec::SelfAffine { .. }) => "surface.points".into(),
            ("grid", SurfaceSpec::Map { .. }) => "surface.file".into(),
            _ => format!("solver.{f}"),
        })
    })?;
    let mut rows = Vec::with_capacity(loads.len());
    let mut above = Vec::new();
    for (i, &p) in loads.iter().enumerate() {
        let r = contact
            .solve(p)
            .map_err(|e| e.map_field(|_| format!("load.mean_pressure_mpa[{i}]")))?;
        let limit = hardness.unwrap_or(METAL_HARDNESS_OVER_E_STAR * e_star);
        if r.max_pressure > limit {
            above.push((i, r.max_pressure, share_above(contact.pressure(), limit)));
        }
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
    warnings.extend(hardness_warning(&above, hardness, e_star));
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
            warnings,
        },
        grid,
        pressure: contact.pressure().to_vec(),
    })
}

/// Largest `H/E*` of engineering metals: hardened bearing steel has H ≈ 7-8 GPa against
/// E* ≈ 115 GPa (0.065); softer metals lie lower. Above `0.1 E*` no metal stays elastic.
const METAL_HARDNESS_OVER_E_STAR: f64 = 0.1;

/// The warning when the largest pressure of some loads exceeds the hardness (given, or
/// `0.1 E*` for any metal when not): there the elastic solution holds no longer, the summits
/// flow plastically (Johnson 1985 §6.1: a fully plastic indentation's mean pressure is the
/// hardness), so the real contact area is larger and the pressures lower than reported.
/// `above` holds per such load its index, its largest pressure \[MPa\] and the fraction of
/// its real contact area above the limit.
fn hardness_warning(
    above: &[(usize, f64, f64)],
    hardness: Option<f64>,
    e_star: f64,
) -> Option<String> {
    let (first, last) = (above.first()?, above.last()?);
    let limit = match hardness {
        Some(h) => format!("load.hardness_mpa = {h} MPa"),
        None => format!(
            "0.1 E* = {:.0} MPa, above the hardness of any metal (give load.hardness_mpa)",
            METAL_HARDNESS_OVER_E_STAR * e_star
        ),
    };
    let share = above.iter().map(|a| a.2).fold(0.0, f64::max);
    let loads = if above.len() == 1 {
        format!("load.mean_pressure_mpa[{}]", first.0)
    } else {
        format!(
            "{} loads (load.mean_pressure_mpa[{}..={}])",
            above.len(),
            first.0,
            last.0
        )
    };
    Some(format!(
        "the largest pressure exceeds {limit} at {loads}: up to {:.0} MPa, on up to {:.1} % \
         of the real contact area; the summits flow plastically there, so the real area is \
         larger and the pressures lower than this elastic solution",
        above.iter().map(|a| a.1).fold(0.0, f64::max),
        100.0 * share
    ))
}

/// The fraction of the loaded cells whose pressure exceeds `limit`.
fn share_above(pressure: &[f64], limit: f64) -> f64 {
    let loaded = pressure.iter().filter(|&&q| q > 0.0).count().max(1);
    pressure.iter().filter(|&&q| q > limit).count() as f64 / loaded as f64
}

/// A warning when a measured map is not periodic: the solver joins its opposite edges, so
/// a height step across that border (a tilt, a form, a cut through a random surface) is a
/// ridge that carries spurious pressure along the border. The rms height jump across each
/// border is compared with the rms step between neighbouring cells inside the map; above
/// [`PERIODIC_JUMP_RATIO`] times, the map is named not periodic.
fn periodicity_warning(map: &GapMap) -> Option<String> {
    let (nx, ny) = (map.grid().nx(), map.grid().ny());
    let v = map.values();
    let rms = |pairs: &mut dyn Iterator<Item = (f64, f64)>| {
        let (mut s, mut n) = (0.0, 0usize);
        for (a, b) in pairs {
            s += (a - b) * (a - b);
            n += 1;
        }
        (s / n.max(1) as f64).sqrt()
    };
    let at = |i: usize, j: usize| v[j * nx + i];
    let jump_x = rms(&mut (0..ny).map(|j| (at(0, j), at(nx - 1, j))));
    let step_x = rms(&mut (0..ny).flat_map(|j| (1..nx).map(move |i| (at(i, j), at(i - 1, j)))));
    let jump_y = rms(&mut (0..nx).map(|i| (at(i, 0), at(i, ny - 1))));
    let step_y = rms(&mut (0..nx).flat_map(|i| (1..ny).map(move |j| (at(i, j), at(i, j - 1)))));
    let ratio = |jump: f64, step: f64| if step > 0.0 { jump / step } else { 0.0 };
    let (rx, ry) = (ratio(jump_x, step_x), ratio(jump_y, step_y));
    (rx > PERIODIC_JUMP_RATIO || ry > PERIODIC_JUMP_RATIO).then(|| {
        format!(
            "surface.file: the map is not periodic (the rms height jump across its opposite \
             edges is {rx:.1} x (x) and {ry:.1} x (y) the rms step between neighbouring cells); \
             the solver joins the edges, so pressures along the borders are spurious: remove \
             the form and tilt, or cut or window the measurement to a periodic patch"
        )
    })
}

/// The ratio of the rms jump across a map's border to its rms step between neighbours above
/// which [`periodicity_warning`] warns. A periodic map has a ratio about 1 (the border is
/// one more step); a self-affine surface cut from a larger one has a jump of about its rms
/// height, many steps.
const PERIODIC_JUMP_RATIO: f64 = 3.0;

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
