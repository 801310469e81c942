//! PimP cases (`method = "pimp"`, `schema_version = 1`) and their JSON report.
//!
//! ```toml
//! name = "torus/torus, r_R = 14 mm"
//! method = "pimp"
//!
//! [geometry]                 # one of three kinds
//! kind = "roller_rib"        # built-in pairing of Wirsching et al. (2020) Table 1 ...
//! pairing = "torus-torus-14"
//! # ... or explicit: face = { shape = "torus", radius_mm = 14.0, eccentricity_mm = 2.0 },
//! #                  rib = { shape = "torus", radius_mm = 30.0 }, contact_height_mm = 2.75
//! #                  (or rib_angle_deg = 89.0), bearing = { bore_mm = 60.0, ... }
//! # kind = "hertz": radii1_mm = [10, 10], radii2_mm = [inf, inf], angle_deg = 0
//! # kind = "surfaces": [geometry.body1] / [geometry.body2] placed surfaces (see below)
//!
//! [pimp]                     # optional
//! mode = "corrected"         # or "published"
//! cells = [64, 64]
//! # extent_mm = [1.0, 0.5]   # fixed half-extents; adaptive when left out
//!
//! [body1]
//! e_mpa = 210000.0
//! nu = 0.3
//! [body2]
//! e_mpa = 210000.0
//! nu = 0.3
//!
//! [load]
//! force_n = 250.0            # or approach_mm; for kind = "surfaces" leave both out to
//!                            # take the approach from the poses (multi-body path)
//! ```
//!
//! A placed surface (`kind = "surfaces"`):
//! ```toml
//! [geometry.body1]
//! shape = "sphere"           # plane | sphere | cone | torus | crowned
//! radius_mm = 10.0           # sphere; torus: major_mm, minor_mm; cone: half_angle_deg;
//!                            # crowned: radius_mm, crown_radius_mm, half_length_mm
//! material = "inside"        # or "outside" (a cup, a groove)
//! origin_mm = [0.0, 0.0, 10.0]
//! axis = [0.0, 0.0, 1.0]     # the surface's axis (local z) in the world
//! ```

pub use crate::common::MaterialSpec;
pub(crate) use crate::common::material;
use crate::common::{SCHEMA_VERSION, in_degrees};
use crate::validity::{ContactSize, Size, checked_report};
use kontakt::bearing::{FaceShape, RibShape, RollerRib, RollerRibSpec, TaperedRollerBearing};
use kontakt::field::NormalSolution;
use kontakt::geometry::RelativeCurvature;
use kontakt::geometry::surface::{Material, PlacedSurface, Profile, Surface};
use kontakt::halfspace::BemOptions;
use kontakt::halfspace::{Boundary, MapKind};
use kontakt::hertz::{HertzPointContact, PointGeometry};
use kontakt::material::ElasticMaterial;
use kontakt::pimp::{
    GapSource, Mode, Pimp, PimpOptions, PimpSolution, QuadraticGap, SurfacePairGap,
};
use kontakt::solve::SolveStatus;
use kontakt::{Error, Result};
use nalgebra::{Point3, Unit, Vector3};
use serde::{Deserialize, Serialize};

/// A PimP case, as read from TOML.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize, schemars::JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct PimpCase {
    /// Optional label echoed in the report.
    #[serde(default)]
    pub name: Option<String>,
    /// `"pimp"`, or `"bem"` for the coupled half-space solver (see
    /// [`crate::bem_case`]).
    pub method: String,
    /// The two surfaces.
    pub geometry: GeometrySpec,
    /// PimP options (`method = "pimp"` only; refused in a `"bem"` case).
    #[serde(default)]
    pub pimp: Option<PimpSpec>,
    /// Half-space solver options (`method = "bem"` only; refused in a `"pimp"` case).
    #[serde(default)]
    pub bem: Option<BemSpec>,
    /// Body 1 material (the roller for `roller_rib`).
    pub body1: MaterialSpec,
    /// Body 2 material (the ring for `roller_rib`).
    pub body2: MaterialSpec,
    /// Load control.
    #[serde(default)]
    pub load: PimpLoad,
}

/// `[load]`: a force, an approach, or neither (the approach of the poses).
#[derive(Debug, Clone, Copy, PartialEq, Default, Serialize, Deserialize, schemars::JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct PimpLoad {
    /// Normal force \[N\].
    #[serde(default)]
    pub force_n: Option<f64>,
    /// Rigid approach from first touch \[mm\].
    #[serde(default)]
    pub approach_mm: Option<f64>,
}

/// `[pimp]`: solver options.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize, schemars::JsonSchema)]
#[serde(deny_unknown_fields, default)]
pub struct PimpSpec {
    /// Bedding law.
    pub mode: Mode,
    /// Grid cells `[nx, ny]`.
    pub cells: [usize; 2],
    /// Fixed half-extents \[mm\]; adaptive when absent.
    pub extent_mm: Option<[f64; 2]>,
}

impl Default for PimpSpec {
    fn default() -> Self {
        let o = PimpOptions::default();
        PimpSpec {
            mode: o.mode,
            cells: o.cells,
            extent_mm: o.extent,
        }
    }
}

/// `[geometry]`.
#[allow(clippy::large_enum_variant)] // parsed once per case file
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize, schemars::JsonSchema)]
#[serde(tag = "kind", rename_all = "snake_case", deny_unknown_fields)]
pub enum GeometrySpec {
    /// Roller end face against the rib (Wirsching et al. 2020).
    RollerRib {
        /// A built-in pairing of Table 1 (then leave out face and rib).
        #[serde(default)]
        pairing: Option<String>,
        /// Roller face.
        #[serde(default)]
        face: Option<FaceShape>,
        /// Rib.
        #[serde(default)]
        rib: Option<RibShape>,
        /// Contact height \[mm\]: the distance of the contact from the roller axis (default
        /// 2.75 mm, the height of Table 1); or give `rib_angle_deg`.
        #[serde(default)]
        contact_height_mm: Option<f64>,
        /// Rib angle between raceway and rib \[deg\], as a drawing gives it: the contact
        /// height follows ([`RollerRibSpec::contact_height_for_rib_angle`]); not with
        /// `contact_height_mm`.
        #[serde(default)]
        rib_angle_deg: Option<f64>,
        /// Bearing data (default: the 60 mm bore bearing of docs/bearing.md).
        #[serde(default)]
        bearing: Option<TaperedRollerBearing>,
    },
    /// The Hertz gap of two bodies given by principal radii (convex > 0, inf flat).
    Hertz {
        /// Body 1 principal radii \[mm\].
        radii1_mm: [f64; 2],
        /// Body 2 principal radii \[mm\].
        radii2_mm: [f64; 2],
        /// Angle between the principal planes \[deg\].
        #[serde(default)]
        angle_deg: f64,
    },
    /// A gap or height map read from a file (`method = "bem"` only).
    Map {
        /// CSV or `.npy` file, relative to the case file's folder.
        file: String,
        /// Cell size `[dx, dy]` \[mm\].
        spacing_mm: [f64; 2],
        /// What the values are: `gap` (default) or `height` (combined topography).
        #[serde(default)]
        values: MapKind,
        /// `free` (default: an isolated contact) or `periodic` (a rough surface).
        #[serde(default)]
        boundary: Boundary,
    },
    /// Two placed analytic surfaces.
    Surfaces {
        /// Body 1.
        body1: SurfaceSpec,
        /// Body 2.
        body2: SurfaceSpec,
        /// Optional start point for the contact search \[mm\].
        #[serde(default)]
        guess_mm: Option<[f64; 3]>,
    },
}

/// A placed analytic surface in a case file.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize, schemars::JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct SurfaceSpec {
    /// `plane`, `sphere`, `cone`, `torus` or `crowned`.
    pub shape: String,
    /// Sphere radius; crowned: cylinder radius \[mm\].
    #[serde(default)]
    pub radius_mm: Option<f64>,
    /// Cone half-angle \[deg\].
    #[serde(default)]
    pub half_angle_deg: Option<f64>,
    /// Torus centre-circle radius \[mm\].
    #[serde(default)]
    pub major_mm: Option<f64>,
    /// Torus tube radius \[mm\].
    #[serde(default)]
    pub minor_mm: Option<f64>,
    /// Crowned roller: crown radius \[mm\].
    #[serde(default)]
    pub crown_radius_mm: Option<f64>,
    /// Crowned roller: half length \[mm\].
    #[serde(default)]
    pub half_length_mm: Option<f64>,
    /// Side of the material (default inside).
    #[serde(default = "inside")]
    pub material: Material,
    /// Origin of the surface's local frame in the world \[mm\].
    #[serde(default)]
    pub origin_mm: [f64; 3],
    /// The local z axis (axis of revolution, plane normal) in the world.
    #[serde(default = "z_axis")]
    pub axis: [f64; 3],
}

fn inside() -> Material {
    Material::Inside
}
fn z_axis() -> [f64; 3] {
    [0.0, 0.0, 1.0]
}

impl SurfaceSpec {
    /// A key of another shape (a cone's `half_angle_deg` on a sphere) is an error, as an
    /// unknown key is: it would otherwise be ignored without a word.
    fn reject_other_shapes_keys(&self, prefix: &str) -> Result<()> {
        let takes: &[&str] = match self.shape.as_str() {
            "plane" => &[],
            "sphere" => &["radius_mm"],
            "cone" => &["half_angle_deg"],
            "torus" => &["major_mm", "minor_mm"],
            "crowned" => &["radius_mm", "crown_radius_mm", "half_length_mm"],
            // An unknown shape is reported by `build` with the valid ones.
            _ => return Ok(()),
        };
        let given = [
            ("radius_mm", self.radius_mm),
            ("half_angle_deg", self.half_angle_deg),
            ("major_mm", self.major_mm),
            ("minor_mm", self.minor_mm),
            ("crown_radius_mm", self.crown_radius_mm),
            ("half_length_mm", self.half_length_mm),
        ];
        match given
            .iter()
            .find(|(key, v)| v.is_some() && !takes.contains(key))
        {
            None => Ok(()),
            Some((key, v)) => Err(Error::invalid(
                format!("{prefix}.{key}"),
                v.unwrap_or_default(),
                format!(
                    "no {key} for shape = \"{}\" (it takes {}; remove the key or change the \
                     shape)",
                    self.shape,
                    if takes.is_empty() {
                        "no size keys".to_string()
                    } else {
                        takes.join(", ")
                    }
                ),
            )),
        }
    }
}

fn need(field: String, v: Option<f64>, shape: &str) -> Result<f64> {
    v.ok_or_else(|| Error::invalid(field, "missing", format!("a value for shape = \"{shape}\"")))
}

impl SurfaceSpec {
    /// Build the placed surface; `prefix` names it in errors (`geometry.body1`).
    ///
    /// # Errors
    /// A missing or invalid parameter, an unknown shape, or a non-finite/zero axis.
    pub fn build(&self, prefix: &str) -> Result<PlacedSurface> {
        let f = |k: &str| format!("{prefix}.{k}");
        let s = self.shape.as_str();
        self.reject_other_shapes_keys(prefix)?;
        let surface = match s {
            "plane" => Ok(Surface::plane(self.material)),
            "sphere" => Surface::sphere(need(f("radius_mm"), self.radius_mm, s)?, self.material),
            "cone" => {
                let deg = need(f("half_angle_deg"), self.half_angle_deg, s)?;
                Surface::cone(deg.to_radians(), self.material)
                    .map_err(|e| in_degrees(e, "half_angle", "half_angle_deg", deg))
            }
            "torus" => Surface::torus(
                need(f("major_mm"), self.major_mm, s)?,
                need(f("minor_mm"), self.minor_mm, s)?,
                self.material,
            ),
            "crowned" => Surface::revolution(
                Profile::Crowned {
                    radius: need(f("radius_mm"), self.radius_mm, s)?,
                    crown_radius: need(f("crown_radius_mm"), self.crown_radius_mm, s)?,
                    half_length: need(f("half_length_mm"), self.half_length_mm, s)?,
                },
                self.material,
            ),
            other => {
                return Err(Error::invalid(
                    f("shape"),
                    other,
                    "one of plane, sphere, cone, torus, crowned",
                ));
            }
        }
        .map_err(|e| {
            e.map_field(|k| {
                let key = match k {
                    "radius" => "radius_mm",
                    "major" => "major_mm",
                    "minor" => "minor_mm",
                    "half_angle" => "half_angle_deg",
                    "crown_radius" => "crown_radius_mm",
                    "half_length" => "half_length_mm",
                    other => other,
                };
                format!("{prefix}.{key}")
            })
        })?;
        let axis = Vector3::from(self.axis);
        let axis = if axis.iter().all(|c| c.is_finite()) {
            Unit::try_new(axis, 1e-12)
        } else {
            None
        }
        .ok_or_else(|| {
            Error::invalid(
                f("axis"),
                format!("{:?}", self.axis),
                "a finite, non-zero direction",
            )
        })?;
        if !self.origin_mm.iter().all(|c| c.is_finite()) {
            return Err(Error::invalid(
                f("origin_mm"),
                format!("{:?}", self.origin_mm),
                "finite coordinates in mm",
            ));
        }
        let pose = kontakt::bearing::roller_rib::frame_along(Point3::from(self.origin_mm), &axis);
        PlacedSurface::new(surface, pose).map_err(|e| e.map_field(|k| format!("{prefix}.{k}")))
    }
}

/// The JSON record of a PimP case: the Hertz report's keys where they apply, plus the
/// zone shape, the grid and the iteration counts. Units in every key.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct PimpReport {
    /// Version of kontakt.
    pub kontakt_version: &'static str,
    /// Schema version (shared with the Hertz report).
    pub schema_version: u32,
    /// The case's name.
    pub name: Option<String>,
    /// `"pimp"` or `"bem"`.
    pub method: &'static str,
    /// PimP's bedding law, `"published"` or `"corrected"` (null for `bem`).
    pub mode: Option<Mode>,
    /// What was solved, e.g. `roller_rib torus-torus-14`.
    pub geometry: String,
    /// Contact modulus E* \[MPa\].
    pub e_star_mpa: f64,
    /// Relative curvature [A, B] at the contact point [1/mm] (null for a gap map).
    pub relative_curvature_per_mm: Option<[f64; 2]>,
    /// Half-extents of the zone along the grid axes \[mm\].
    pub semi_axes_mm: [f64; 2],
    /// Ratio of the half-extents (y / x).
    pub axis_ratio: f64,
    /// Angle from body 1's first principal direction to the grid's x axis \[deg\].
    pub orientation_deg: f64,
    /// Normal force \[N\].
    pub force_n: f64,
    /// Rigid approach from first touch \[mm\].
    pub approach_mm: f64,
    /// Largest pressure \[MPa\].
    pub max_pressure_mpa: f64,
    /// Mean pressure \[MPa\].
    pub mean_pressure_mpa: f64,
    /// Contact area \[mm²\].
    pub contact_area_mm2: f64,
    /// Number of separate contact patches.
    pub patches: usize,
    /// Centre of pressure in the grid frame \[mm\].
    pub centroid_mm: [f64; 2],
    /// Zone extents `[[x_min, x_max], [y_min, y_max]]` \[mm\].
    pub extents_mm: [[f64; 2]; 2],
    /// Curvature of the zone's centre line [1/mm] (null: fewer than 5 columns).
    pub centre_line_curvature_per_mm: Option<f64>,
    /// The grid.
    pub grid: GridEcho,
    /// PimP: force evaluations of the equilibrium iteration; bem: solver iterations.
    pub iterations: usize,
    /// Why the solver's iteration stopped (`termination`: converged, max_iterations,
    /// stagnated, diverged), its iterations and final relative residual.
    pub status: SolveStatus,
    /// The half-space solver's convergence record (null for PimP).
    pub solver: Option<SolverEcho>,
    /// PimP: resizes of the adaptive grid; bem: domains tried.
    pub grid_rounds: usize,
    /// Separation of the given poses \[mm\] (surfaces only; < 0: interpenetration).
    pub separation_mm: Option<f64>,
    /// Rib angle alpha (roller/rib only) \[deg\].
    pub rib_angle_deg: Option<f64>,
    /// The Hertz solution for the curvature at the contact point, same load.
    pub hertz: Option<HertzEcho>,
    /// Where the result is outside the method's comfortable range: a zone large against a
    /// body's radius of curvature or close to the edge of a face
    /// (`kontakt::field::validity`). Empty when none applies (always for a gap map, whose
    /// bodies are unknown).
    pub warnings: Vec<String>,
    /// The zone's size against the bodies, for the validity check ([`crate::validity`]);
    /// not in the JSON.
    #[serde(skip)]
    pub contacts: Vec<ContactSize>,
}

checked_report!(PimpReport);

/// The grid of a PimP result.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct GridEcho {
    /// Cells along x and y.
    pub cells: [usize; 2],
    /// Cell size \[mm\].
    pub cell_mm: [f64; 2],
    /// x range \[mm\].
    pub x_range_mm: [f64; 2],
    /// y range \[mm\].
    pub y_range_mm: [f64; 2],
}

/// Hertz values for comparison.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct HertzEcho {
    /// p0 \[MPa\].
    pub max_pressure_mpa: f64,
    /// pi a b \[mm²\].
    pub contact_area_mm2: f64,
    /// Approach \[mm\].
    pub approach_mm: f64,
    /// [a, b] \[mm\].
    pub semi_axes_mm: [f64; 2],
}

/// A solved PimP case: the report and the full solution (pressure field for CSV/plots).
#[derive(Debug, Clone, PartialEq)]
pub struct PimpOutcome {
    /// The JSON record.
    pub report: PimpReport,
    /// The solution with its pressure field.
    pub solution: PimpSolution,
}

/// Build a roller/rib pair from a `[geometry]` table of kind `roller_rib`.
///
/// # Errors
/// An unknown pairing, a pairing combined with explicit shapes, or invalid dimensions.
pub fn roller_rib_from_spec(geometry: &GeometrySpec) -> Result<Option<(String, RollerRib)>> {
    let GeometrySpec::RollerRib {
        pairing,
        face,
        rib,
        contact_height_mm,
        rib_angle_deg,
        bearing,
    } = geometry
    else {
        return Ok(None);
    };
    let (label, mut spec) = match (pairing, face, rib) {
        (Some(p), None, None) => (
            p.clone(),
            RollerRibSpec::builtin(p).map_err(|e| e.map_field(|_| "geometry.pairing".into()))?,
        ),
        (None, Some(face), Some(rib)) => (
            "custom".to_string(),
            RollerRibSpec {
                bearing: TaperedRollerBearing::default(),
                face: *face,
                rib: *rib,
                contact_height: kontakt::bearing::CONTACT_HEIGHT,
            },
        ),
        _ => {
            return Err(Error::invalid(
                "geometry.pairing",
                "given together with face/rib, or face/rib incomplete",
                "either `pairing` or both `face` and `rib`",
            ));
        }
    };
    if let Some(b) = bearing {
        spec.bearing = *b;
    }
    match (contact_height_mm, rib_angle_deg) {
        (Some(_), Some(_)) => {
            return Err(Error::invalid(
                "geometry.rib_angle_deg",
                "given together with contact_height_mm",
                "either contact_height_mm or rib_angle_deg (the height follows from the angle)",
            ));
        }
        (Some(h), None) => spec.contact_height = *h,
        (None, Some(alpha)) => {
            spec.contact_height = spec
                .contact_height_for_rib_angle(*alpha)
                .map_err(|e| e.map_field(roller_rib_key))?;
        }
        (None, None) => {}
    }
    let pair = RollerRib::new(spec).map_err(|e| e.map_field(roller_rib_key))?;
    Ok(Some((label, pair)))
}

/// The case-file key of a [`RollerRib`] field: `bearing.bore` is `geometry.bearing.bore_mm`,
/// `face.radius` is `geometry.face.radius_mm` (the library's names carry no unit suffix).
fn roller_rib_key(f: &str) -> String {
    let key = match f {
        "bearing.bore"
        | "bearing.outside_diameter"
        | "bearing.roller_large_end_radius"
        | "bearing.inner_raceway_radius"
        | "face.radius"
        | "face.eccentricity"
        | "rib.radius"
        | "contact_height" => format!("{f}_mm"),
        other => other.to_string(),
    };
    format!("geometry.{key}")
}

/// Solve a PimP case.
///
/// # Errors
/// Invalid input (named by its case-file key), bodies that do not touch under pose
/// control (the error states the separation), grid and convergence failures.
pub fn run_pimp_case(case: &PimpCase) -> Result<PimpOutcome> {
    crate::validity::checked(run_pimp_case_unchecked(case)?)
}

checked_report!(PimpOutcome, report);

/// [`run_pimp_case`] before the validity check of [`crate::validity::checked`].
pub(crate) fn run_pimp_case_unchecked(case: &PimpCase) -> Result<PimpOutcome> {
    if case.method != "pimp" {
        return Err(Error::invalid(
            "method",
            &case.method,
            "\"pimp\" for this schema",
        ));
    }
    if case.bem.is_some() {
        return Err(Error::invalid(
            "bem",
            "a [bem] table",
            "no [bem] table in a method = \"pimp\" case (it holds the half-space solver's \
             options: use method = \"bem\", or [pimp] for PimP's)",
        ));
    }
    let pimp = case.pimp.unwrap_or_default();
    let m1 = material(&case.body1, "body1")?;
    let m2 = material(&case.body2, "body2")?;
    let options = PimpOptions {
        mode: pimp.mode,
        cells: pimp.cells,
        extent: pimp.extent_mm,
        ..PimpOptions::default()
    };
    let pimp = Pimp::new(m1, m2, options).map_err(|e| {
        e.map_field(|f| match f {
            "extent[0]" => "pimp.extent_mm[0]".into(),
            "extent[1]" => "pimp.extent_mm[1]".into(),
            other => format!("pimp.{other}"),
        })
    })?;
    let GapSetup {
        label,
        source,
        separation,
        rib_angle,
    } = gap_setup(&case.geometry)?;
    let map_load = |e: Error| {
        e.map_field(|f| match f {
            "force" => "load.force_n".into(),
            "approach" => "load.approach_mm".into(),
            "cells" => "pimp.cells".into(),
            "extent" => "pimp.extent_mm".into(),
            other => other.into(),
        })
    };
    precheck(
        &case.geometry,
        source.as_ref(),
        m1,
        m2,
        &case.load,
        separation,
    )?;
    let solution = match (case.load.force_n, case.load.approach_mm, separation) {
        (Some(f), None, _) => pimp.solve_force(source.as_ref(), f).map_err(map_load)?,
        (None, Some(d), _) => pimp.solve_approach(source.as_ref(), d).map_err(map_load)?,
        (None, None, Some(sep)) => {
            if sep >= 0.0 {
                return Err(Error::Geometry {
                    field: "geometry".into(),
                    reason: format!(
                        "the bodies do not touch: separation = {sep:.6e} mm (give load.force_n or \
                         load.approach_mm to press them together)"
                    ),
                });
            }
            pimp.solve_approach(source.as_ref(), -sep)
                .map_err(map_load)?
        }
        _ => {
            return Err(Error::invalid(
                "load",
                "none or both of force_n and approach_mm",
                "exactly one of force_n or approach_mm (or neither for surfaces placed in contact)",
            ));
        }
    };
    let (warnings, contacts) = zone_warnings(&case.geometry, source.as_ref(), &solution)?;
    let k = source.curvature();
    let hertz = hertz_echo(k, m1, m2, solution.force);
    let report = PimpReport::assemble(
        ReportMeta {
            name: case.name.clone(),
            method: "pimp",
            mode: Some(solution.detail.mode),
            geometry: label,
            e_star_mpa: kontakt::material::effective_modulus(&m1, &m2),
            relative_curvature_per_mm: Some([k.a_coef, k.b_coef]),
            solver: None,
            separation_mm: separation,
            rib_angle_deg: rib_angle,
            hertz,
            grid_rounds: solution.domains - 1,
            warnings,
            contacts,
        },
        &solution,
    );
    Ok(PimpOutcome { report, solution })
}

/// Smallest Hertz approach of a PimP or half-space case over the radius of relative
/// curvature: the gap of surfaces placed at coordinates of the bodies' size is resolved to
/// about 1e-16 of that size, so an approach of 1e-12 of it keeps four digits.
pub const MIN_RELATIVE_APPROACH: f64 = 1e-12;

/// Before a solve: the size check on the Hertz ellipse of the local curvature under the
/// case's load (`kontakt::field::validity::ellipse_size_check`), so that a contact far
/// larger than the bodies (a groove conforming to within micrometres) is refused naming
/// the body, not left to fail on the solver's grid. Only refusals: the warnings come from
/// the solution.
pub(crate) fn precheck(
    geometry: &GeometrySpec,
    source: &dyn GapSource,
    m1: ElasticMaterial,
    m2: ElasticMaterial,
    load: &PimpLoad,
    separation: Option<f64>,
) -> Result<()> {
    let Ok(hertz) =
        HertzPointContact::new(PointGeometry::from_curvature(source.curvature()), m1, m2)
    else {
        return Ok(());
    };
    let approach = load
        .approach_mm
        .or(separation.filter(|s| *s < 0.0).map(|s| -s));
    let sol = match (load.force_n, approach) {
        (Some(f), _) => hertz.solve_force(f),
        (None, Some(d)) => hertz.solve_approach(d),
        _ => return Ok(()),
    };
    // An invalid load is reported by the solver with its key.
    let Ok(sol) = sol else { return Ok(()) };
    // The approach must be resolved by the gap, which is computed from surfaces placed at
    // coordinates of the bodies' size: below MIN_RELATIVE_APPROACH of the radius of
    // relative curvature the solvers iterated on rounding noise and ended as "did not
    // converge" (a hostile probe: 1e-30 N on the example sphere/torus).
    let k = source.curvature();
    let radius = 0.5 / k.a_coef.max(k.b_coef);
    if sol.approach < MIN_RELATIVE_APPROACH * radius {
        let (key, value) = match (load.force_n, approach) {
            (Some(f), _) => ("load.force_n", format!("{f:e} N")),
            (None, Some(d)) if load.approach_mm.is_some() => {
                ("load.approach_mm", format!("{d:e} mm"))
            }
            (None, _) => (
                "geometry",
                format!("a separation of {:e} mm", -approach.unwrap_or(0.0)),
            ),
        };
        return Err(Error::invalid(
            key,
            value,
            format!(
                "a load whose Hertz approach ({:e} mm) is at least {MIN_RELATIVE_APPROACH:e} of \
                 the radius of relative curvature {radius:e} mm (below it the gap is not \
                 resolved in double precision)",
                sol.approach
            ),
        ));
    }
    kontakt::field::validity::ellipse_size_check(source, sol.semi_axes, sol.orientation)
        .map_err(|e| e.map_field(|f| size_field(geometry, f)))?;
    Ok(())
}

/// The case-file key of a size check's field (`body1.radii`, an edge's quantity).
pub(crate) fn size_field(geometry: &GeometrySpec, f: &str) -> String {
    let body = if f.starts_with("body2") { 2 } else { 1 };
    match (geometry, f) {
        (GeometrySpec::RollerRib { .. }, "bearing.roller_large_end_radius") => {
            "geometry.bearing.roller_large_end_radius_mm".into()
        }
        (
            GeometrySpec::RollerRib {
                pairing: Some(_), ..
            },
            _,
        ) => "geometry.pairing".into(),
        (GeometrySpec::RollerRib { .. }, _) if body == 1 => "geometry.face".into(),
        (GeometrySpec::RollerRib { .. }, _) => "geometry.rib".into(),
        (GeometrySpec::Hertz { .. }, _) => format!("geometry.radii{body}_mm"),
        (GeometrySpec::Surfaces { .. }, f) if f.ends_with(".half_length") => {
            format!("geometry.body{body}.half_length_mm")
        }
        _ => format!("geometry.body{body}"),
    }
}

/// The size check of a solution against the bodies of its geometry
/// (`kontakt::field::validity`): the report's warnings about a face's edge and the zone's
/// size against the bodies' curvature (warned about by [`crate::validity::checked`]), or
/// the error naming the case-file key of the body's radii or the face's edge.
pub(crate) fn zone_warnings<D>(
    geometry: &GeometrySpec,
    source: &dyn GapSource,
    solution: &NormalSolution<D>,
) -> Result<(Vec<String>, Vec<ContactSize>)> {
    let check = kontakt::field::validity::zone_size_check(source, solution)
        .map_err(|e| e.map_field(|f| size_field(geometry, f)))?;
    let edge = kontakt::field::validity::ZoneCheck {
        curvature: None,
        ..check
    };
    let keys = [
        size_field(geometry, "body1.radii"),
        size_field(geometry, "body2.radii"),
    ];
    let contacts = check
        .curvature
        .map(|c| ContactSize {
            at: None,
            size: Size::HalfSpace(c),
            keys,
        })
        .into_iter()
        .collect();
    Ok((edge.warnings(), contacts))
}

/// The axes `[x, y]` of a case's field grid as unit vectors in the bearing frame (`X`
/// radial, `Y` circumferential at the contact point, `Z` the ring axis) for a roller/rib
/// geometry, built-in pairing or custom face and rib alike, so that its maps name their
/// axes along and across the rib as the demo's do; `None` for the other kinds (no bearing).
///
/// # Errors
/// Those of [`roller_rib_from_spec`] and of the pair's gap.
pub fn bearing_axes(geometry: &GeometrySpec) -> Result<Option<[[f64; 3]; 2]>> {
    let Some((_, pair)) = roller_rib_from_spec(geometry)? else {
        return Ok(None);
    };
    Ok(Some(pair.gap()?.principal_axes()))
}

/// The substitute geometry of a case and what the report echoes about it.
pub(crate) struct GapSetup {
    pub label: String,
    pub source: Box<dyn GapSource>,
    pub separation: Option<f64>,
    pub rib_angle: Option<f64>,
}

/// Build the gap source of a `[geometry]` table (every kind but `map`).
pub(crate) fn gap_setup(geometry: &GeometrySpec) -> Result<GapSetup> {
    let (label, source, separation, rib_angle): (
        String,
        Box<dyn GapSource>,
        Option<f64>,
        Option<f64>,
    ) = match geometry {
        g @ GeometrySpec::RollerRib { .. } => {
            let (label, pair) = roller_rib_from_spec(g)?.ok_or_else(|| {
                Error::invalid("geometry.kind", "roller_rib", "a roller/rib geometry")
            })?;
            let angle = pair.rib_angle_deg;
            let gap = pair.gap().map_err(|e| {
                e.map_field(|f| match f {
                    "surfaces" => "geometry.pairing".into(),
                    other => other.into(),
                })
            })?;
            (
                format!("roller_rib {label}"),
                Box::new(gap),
                None,
                Some(angle),
            )
        }
        GeometrySpec::Hertz {
            radii1_mm,
            radii2_mm,
            angle_deg,
        } => {
            let gap = QuadraticGap::of_bodies(*radii1_mm, *radii2_mm, angle_deg.to_radians())
                .map_err(|e| {
                    e.map_field(|f| match f {
                        "radii" => "geometry.radii1_mm, geometry.radii2_mm".into(),
                        f => f
                            .replace("body1.radii", "geometry.radii1_mm")
                            .replace("body2.radii", "geometry.radii2_mm"),
                    })
                })?;
            ("hertz gap".into(), Box::new(gap), None, None)
        }
        GeometrySpec::Surfaces {
            body1,
            body2,
            guess_mm,
        } => {
            let s1 = body1.build("geometry.body1")?;
            let s2 = body2.build("geometry.body2")?;
            let gap =
                SurfacePairGap::from_poses(s1, s2, guess_mm.map(Point3::from)).map_err(|e| {
                    e.map_field(|f| match f {
                        "surfaces" => "geometry".into(),
                        other => other.into(),
                    })
                })?;
            let sep = gap.separation();
            (
                format!("surfaces {} / {}", body1.shape, body2.shape),
                Box::new(gap),
                Some(sep),
                None,
            )
        }
        GeometrySpec::Map { .. } => {
            return Err(Error::invalid(
                "geometry.kind",
                "map",
                "roller_rib, hertz or surfaces (a gap map needs method = \"bem\")",
            ));
        }
    };
    Ok(GapSetup {
        label,
        source,
        separation,
        rib_angle,
    })
}

impl GridEcho {
    /// The echo of `g`.
    pub fn of(g: &kontakt::geometry::Grid2) -> Self {
        GridEcho {
            cells: [g.nx(), g.ny()],
            cell_mm: [g.dx(), g.dy()],
            x_range_mm: [g.x(0) - 0.5 * g.dx(), g.x(g.nx() - 1) + 0.5 * g.dx()],
            y_range_mm: [g.y(0) - 0.5 * g.dy(), g.y(g.ny() - 1) + 0.5 * g.dy()],
        }
    }
}

/// The Hertz solution for the curvature `k` at the contact point under `force` \[N\]
/// (none when the curvature admits no Hertz contact).
pub(crate) fn hertz_echo(
    k: RelativeCurvature,
    m1: ElasticMaterial,
    m2: ElasticMaterial,
    force: f64,
) -> Option<HertzEcho> {
    HertzPointContact::new(PointGeometry::from_curvature(k), m1, m2)
        .and_then(|h| h.solve_force(force))
        .ok()
        .map(|h| HertzEcho {
            max_pressure_mpa: h.max_pressure,
            contact_area_mm2: h.contact_area,
            approach_mm: h.approach,
            semi_axes_mm: h.semi_axes,
        })
}

/// What a report says about the case and the method (the rest comes from the solution).
pub(crate) struct ReportMeta {
    pub name: Option<String>,
    pub method: &'static str,
    pub mode: Option<Mode>,
    pub geometry: String,
    pub e_star_mpa: f64,
    pub relative_curvature_per_mm: Option<[f64; 2]>,
    pub solver: Option<SolverEcho>,
    pub separation_mm: Option<f64>,
    pub rib_angle_deg: Option<f64>,
    pub hertz: Option<HertzEcho>,
    /// The report's `grid_rounds`: PimP counts grid resizes, bem the domains tried.
    pub grid_rounds: usize,
    /// The size check's warnings (a face's edge).
    pub warnings: Vec<String>,
    /// The zone's size against the bodies.
    pub contacts: Vec<ContactSize>,
}

impl PimpReport {
    /// One report layout for both methods.
    pub(crate) fn assemble<D>(meta: ReportMeta, s: &NormalSolution<D>) -> Self {
        PimpReport {
            kontakt_version: kontakt::VERSION,
            schema_version: SCHEMA_VERSION,
            name: meta.name,
            method: meta.method,
            mode: meta.mode,
            geometry: meta.geometry,
            e_star_mpa: meta.e_star_mpa,
            relative_curvature_per_mm: meta.relative_curvature_per_mm,
            semi_axes_mm: s.semi_axes,
            axis_ratio: s.semi_axes[1] / s.semi_axes[0],
            orientation_deg: s.orientation.to_degrees(),
            force_n: s.force,
            approach_mm: s.approach,
            max_pressure_mpa: s.max_pressure,
            mean_pressure_mpa: s.mean_pressure,
            contact_area_mm2: s.contact_area,
            patches: s.zone.patches,
            centroid_mm: s.zone.centroid,
            extents_mm: s.zone.extents,
            centre_line_curvature_per_mm: s.zone.centre_line_curvature,
            grid: GridEcho::of(&s.grid),
            iterations: s.status.iterations,
            status: s.status,
            solver: meta.solver,
            grid_rounds: meta.grid_rounds,
            separation_mm: meta.separation_mm,
            rib_angle_deg: meta.rib_angle_deg,
            hertz: meta.hertz,
            warnings: meta.warnings,
            contacts: meta.contacts,
        }
    }
}

/// `[bem]`: options of the half-space solver.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize, schemars::JsonSchema)]
#[serde(deny_unknown_fields, default)]
pub struct BemSpec {
    /// Grid cells `[nx, ny]`, each in 8..=4096.
    pub cells: [usize; 2],
    /// Relative residual, in \[1e-14, 1e-2\].
    pub tolerance: f64,
    /// Fixed half-extents \[mm\]; adaptive when absent.
    pub extent_mm: Option<[f64; 2]>,
    /// Adaptive domain over the contact's extent, in \[1.05, 4\].
    pub margin: f64,
    /// FFT threads; all cores when absent.
    pub threads: Option<usize>,
    /// Most iterations.
    pub max_iterations: usize,
}

impl Default for BemSpec {
    fn default() -> Self {
        let o = BemOptions::default();
        BemSpec {
            cells: o.cells,
            tolerance: o.tolerance,
            extent_mm: o.extent,
            margin: o.margin,
            threads: o.threads,
            max_iterations: o.max_iterations,
        }
    }
}

/// The solver's record in a `bem` report.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct SolverEcho {
    /// Whether the residual reached the tolerance (always true in a report: a failed
    /// solve is an error).
    pub converged: bool,
    /// Final relative residual.
    pub residual: f64,
    /// The tolerance asked for.
    pub tolerance: f64,
    /// FFT convolutions performed.
    pub operator_applications: usize,
    /// Largest remaining interpenetration on an unloaded cell \[mm\].
    pub max_overlap_mm: f64,
    /// `"free"` or `"periodic"`.
    pub boundary: kontakt::halfspace::Boundary,
}
