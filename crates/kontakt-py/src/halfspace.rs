//! The coupled elastic half-space solver on a gap or height map given as a NumPy array,
//! in the vocabulary of ContactMechanics / tamaas (`nb_grid_pts`, `physical_sizes`,
//! `external_force`, `mean_pressure`, `offset`).

use crate::args;
use crate::case::Fields;
use crate::errors::{invalid, to_py_with};
use kontakt::gap::{GapMap, MapKind};
use kontakt::halfspace::Boundary;
use kontakt::material::ElasticMaterial;
use kontakt_case::pimp_case::{BemSpec, GeometrySpec, MaterialSpec, PimpCase, PimpLoad};
use numpy::{IntoPyArray, PyArray1, PyArray2};
use pyo3::prelude::*;

const BOUNDARIES: &str = "\"free\" or \"periodic\"";

/// An elastic half-space problem on a uniform grid: `nb_grid_pts = (nx, ny)` cells over
/// `physical_sizes = (sx, sy)` [mm] (cell size sx/nx by sy/ny), `boundary` "free" (an
/// isolated contact, zero-padded FFT) or "periodic" (one period of a rough surface).
/// Elasticity: `e_star` [MPa] (the contact modulus) or two materials (steel by default).
#[pyclass(frozen, module = "kontakt._kontakt")]
pub struct HalfSpace {
    nb_grid_pts: [usize; 2],
    physical_sizes: [f64; 2],
    boundary: Boundary,
    materials: [ElasticMaterial; 2],
}

#[pymethods]
impl HalfSpace {
    #[new]
    #[pyo3(
        signature = (nb_grid_pts, physical_sizes, e_star = None, material1 = None, material2 = None, boundary = None),
        text_signature = "(nb_grid_pts, physical_sizes, e_star=None, material1=None, material2=None, boundary='free')"
    )]
    fn new(
        nb_grid_pts: &Bound<'_, PyAny>,
        physical_sizes: &Bound<'_, PyAny>,
        e_star: Option<&Bound<'_, PyAny>>,
        material1: Option<&Bound<'_, PyAny>>,
        material2: Option<&Bound<'_, PyAny>>,
        boundary: Option<&Bound<'_, PyAny>>,
    ) -> PyResult<Self> {
        let nb_grid_pts = args::sizes::<2>(nb_grid_pts, "nb_grid_pts", "8 <= n <= 4096")?;
        let physical_sizes =
            args::reals::<2>(physical_sizes, "physical_sizes", "a finite size > 0 mm")?;
        let e_star = args::opt_real(e_star, "e_star", "a finite contact modulus > 0 MPa")?;
        let material1 = crate::hertz::material_arg(material1, "material1")?;
        let material2 = crate::hertz::material_arg(material2, "material2")?;
        let boundary = args::text_or(boundary, "boundary", BOUNDARIES, "free")?;
        for (i, &n) in nb_grid_pts.iter().enumerate() {
            if !(8..=4096).contains(&n) {
                return Err(invalid(&format!("nb_grid_pts[{i}]"), n, "8 <= n <= 4096"));
            }
        }
        for (i, &s) in physical_sizes.iter().enumerate() {
            if !(s.is_finite() && s > 0.0) {
                return Err(invalid(
                    &format!("physical_sizes[{i}]"),
                    s,
                    "a finite size > 0 mm",
                ));
            }
        }
        let boundary = match boundary.as_str() {
            "free" => Boundary::Free,
            "periodic" => Boundary::Periodic,
            other => return Err(invalid("boundary", other, BOUNDARIES)),
        };
        let materials = match (e_star, material1, material2) {
            (Some(e), None, None) => {
                // Two identical bodies with nu = 0 and E = 2 E* have exactly the contact
                // modulus E*: 1/E* = 1/(2E*) + 1/(2E*).
                let m = ElasticMaterial::new(2.0 * e, 0.0)
                    .map_err(|_| invalid("e_star", e, "a finite contact modulus > 0 MPa"))?;
                [m, m]
            }
            (None, m1, m2) => [
                m1.map_or(ElasticMaterial::STEEL, |m| m.inner),
                m2.map_or(ElasticMaterial::STEEL, |m| m.inner),
            ],
            _ => {
                return Err(invalid(
                    "e_star",
                    "given with materials",
                    "either e_star or material1/material2, not both",
                ));
            }
        };
        // A subnormal e_star passes the material's check but its contact modulus
        // underflows to 0 (found by the fuzz harness): refused here, not at the solve.
        let e = kontakt::material::effective_modulus(&materials[0], &materials[1]);
        if !(e.is_finite() && e > 0.0) {
            return Err(match e_star {
                Some(v) => invalid("e_star", v, "a finite contact modulus > 0 MPa"),
                None => invalid(
                    "material1, material2",
                    e,
                    "materials whose contact modulus is a finite number > 0 MPa",
                ),
            });
        }
        Ok(HalfSpace {
            nb_grid_pts,
            physical_sizes,
            boundary,
            materials,
        })
    }

    /// Grid points (nx, ny).
    #[getter]
    fn nb_grid_pts(&self) -> (usize, usize) {
        (self.nb_grid_pts[0], self.nb_grid_pts[1])
    }

    /// Physical sizes (sx, sy) [mm].
    #[getter]
    fn physical_sizes(&self) -> (f64, f64) {
        (self.physical_sizes[0], self.physical_sizes[1])
    }

    /// Contact modulus E* [MPa].
    #[getter]
    fn e_star(&self) -> f64 {
        kontakt::material::effective_modulus(&self.materials[0], &self.materials[1])
    }

    /// Solve the contact of the map `gap` [mm], an array of shape (ny, nx) (row j is y,
    /// column i is x; any float dtype and memory order; converted to float64), which is the
    /// undeformed gap (`values="gap"`) or the combined surface height (`values="height"`,
    /// gap = max(h) - h). Load: exactly one of `external_force` [N], `mean_pressure` [MPa]
    /// (force over the whole domain sx·sy, as in tamaas) or `offset` [mm] (the rigid
    /// approach from the gap's zero level). The solver stops at the relative residual
    /// `tolerance` (1e-14..=1e-2) or after `max_iterations`; `threads` FFT threads (all
    /// cores when None). The GIL is released during the solve.
    #[pyo3(
        signature = (gap, *, external_force = None, mean_pressure = None, offset = None, values = None, tolerance = None, max_iterations = None, threads = None),
        text_signature = "($self, gap, *, external_force=None, mean_pressure=None, offset=None, values='gap', tolerance=1e-08, max_iterations=1000, threads=None)"
    )]
    #[allow(clippy::too_many_arguments)] // the keyword arguments of a Python method
    fn solve(
        &self,
        py: Python<'_>,
        gap: &Bound<'_, PyAny>,
        external_force: Option<&Bound<'_, PyAny>>,
        mean_pressure: Option<&Bound<'_, PyAny>>,
        offset: Option<&Bound<'_, PyAny>>,
        values: Option<&Bound<'_, PyAny>>,
        tolerance: Option<&Bound<'_, PyAny>>,
        max_iterations: Option<&Bound<'_, PyAny>>,
        threads: Option<&Bound<'_, PyAny>>,
    ) -> PyResult<HalfSpaceResult> {
        let [nx, ny] = self.nb_grid_pts;
        let shape = format!("({ny}, {nx}), i.e. (ny, nx) for nb_grid_pts = ({nx}, {ny})");
        let gap = args::array(gap, "gap", &format!("a map of shape {shape} in mm"))?;
        let a = gap.as_array();
        if a.shape() != [ny, nx] {
            return Err(invalid("gap.shape", args::shape(a.shape()), &shape));
        }
        let external_force =
            args::opt_real(external_force, "external_force", "a finite force > 0 N")?;
        let mean_pressure =
            args::opt_real(mean_pressure, "mean_pressure", "a finite pressure > 0 MPa")?;
        let offset = args::opt_real(offset, "offset", "a finite approach in mm")?;
        let values = args::text_or(values, "values", "\"gap\" or \"height\"", "gap")?;
        let tolerance =
            args::opt_real(tolerance, "tolerance", "1e-14 <= tolerance <= 1e-2")?.unwrap_or(1e-8);
        let max_iterations =
            args::opt_size(max_iterations, "max_iterations", "an iteration limit >= 1")?
                .unwrap_or(1000);
        let threads = args::opt_size(threads, "threads", &format!("1..={}", kontakt::MAX_THREADS))?;
        let kind = match values.as_str() {
            "gap" => MapKind::Gap,
            "height" => MapKind::Height,
            other => return Err(invalid("values", other, "\"gap\" or \"height\"")),
        };
        let [sx, sy] = self.physical_sizes;
        let load = match (external_force, mean_pressure, offset) {
            (Some(f), None, None) => PimpLoad {
                force_n: Some(f),
                approach_mm: None,
            },
            (None, Some(p), None) => {
                if !(p.is_finite() && p > 0.0) {
                    return Err(invalid("mean_pressure", p, "a finite pressure > 0 MPa"));
                }
                PimpLoad {
                    force_n: Some(p * sx * sy),
                    approach_mm: None,
                }
            }
            (None, None, Some(d)) => PimpLoad {
                force_n: None,
                approach_mm: Some(d),
            },
            _ => {
                return Err(invalid(
                    "external_force, mean_pressure, offset",
                    "none or more than one",
                    "exactly one of external_force [N], mean_pressure [MPa] or offset [mm]",
                ));
            }
        };
        // Row-major, x fastest, whatever the array's memory order.
        let flat: Vec<f64> = a.iter().copied().collect();
        let spacing = [sx / nx as f64, sy / ny as f64];
        let map = GapMap::new(nx, ny, spacing, flat, kind).map_err(|e| {
            to_py_with(e, |f| match f {
                "gap_map" => Some("gap".into()),
                _ => None,
            })
        })?;
        let spec = BemSpec {
            tolerance,
            max_iterations,
            threads,
            ..BemSpec::default()
        };
        let material = |m: &ElasticMaterial| MaterialSpec {
            e_mpa: m.youngs_modulus(),
            nu: m.poisson_ratio(),
        };
        let case = PimpCase {
            name: None,
            method: "bem".into(),
            geometry: GeometrySpec::Map {
                file: "(numpy array)".into(),
                spacing_mm: spacing,
                values: kind,
                boundary: self.boundary,
            },
            pimp: None,
            bem: Some(spec),
            body1: material(&self.materials[0]),
            body2: material(&self.materials[1]),
            load,
        };
        let outcome = py
            .detach(|| kontakt_case::run_bem_case_on_map(&case, map))
            .map_err(|e| {
                to_py_with(e, |f| match f {
                    "load.force_n" if mean_pressure.is_some() => Some("mean_pressure".into()),
                    "load.force_n" => Some("external_force".into()),
                    "load.approach_mm" => Some("offset".into()),
                    "bem.tolerance" => Some("tolerance".into()),
                    "bem.max_iterations" => Some("max_iterations".into()),
                    "bem.threads" => Some("threads".into()),
                    // The grid is this object's (the fuzz harness found the case keys
                    // leaking): too few cells across the contact, or a contact that
                    // reaches the border of the domain.
                    "bem.cells" => Some("nb_grid_pts".into()),
                    "bem.extent_mm" => Some("physical_sizes".into()),
                    _ => None,
                })
            })?;
        let report = serde_json::to_string(&outcome.report)
            .map_err(|e| pyo3::exceptions::PyRuntimeError::new_err(format!("report: {e}")))?;
        let s = &outcome.solution;
        let fields = Fields::of(s, Some(&s.detail.displacement), Some(&s.detail.gap));
        Ok(HalfSpaceResult {
            warnings: outcome.report.warnings.clone(),
            report,
            fields,
            force: s.force,
            offset: s.approach,
            max_pressure: s.max_pressure,
            mean_pressure: s.force / (sx * sy),
            contact_area: s.contact_area,
            iterations: s.status.iterations,
            residual: s.status.residual,
            converged: s.status.converged(),
        })
    }
}

/// A solved half-space contact: fields of shape (ny, nx) and the totals. Lengths mm, force
/// N, pressure MPa.
#[pyclass(frozen, module = "kontakt._kontakt")]
pub struct HalfSpaceResult {
    report: String,
    warnings: Vec<String>,
    fields: Fields,
    force: f64,
    offset: f64,
    max_pressure: f64,
    mean_pressure: f64,
    contact_area: f64,
    iterations: usize,
    residual: f64,
    converged: bool,
}

#[pymethods]
impl HalfSpaceResult {
    /// Contact pressure per cell [MPa], shape (ny, nx) (tamaas' traction).
    #[getter]
    fn pressure<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray2<f64>> {
        self.fields.pressure.clone().into_pyarray(py)
    }
    /// Elastic displacement of the two-body system per cell [mm], shape (ny, nx).
    #[getter]
    fn displacement<'py>(&self, py: Python<'py>) -> Option<Bound<'py, PyArray2<f64>>> {
        self.fields.displacement.clone().map(|a| a.into_pyarray(py))
    }
    /// Undeformed gap per cell [mm] (after `values="height"`: max(h) - h), shape (ny, nx).
    #[getter]
    fn gap<'py>(&self, py: Python<'py>) -> Option<Bound<'py, PyArray2<f64>>> {
        self.fields.gap.clone().map(|a| a.into_pyarray(py))
    }
    /// Cell centres along x [mm].
    #[getter]
    fn x<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray1<f64>> {
        PyArray1::from_slice(py, &self.fields.x)
    }
    /// Cell centres along y [mm].
    #[getter]
    fn y<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray1<f64>> {
        PyArray1::from_slice(py, &self.fields.y)
    }
    /// Normal force [N].
    #[getter]
    fn force(&self) -> f64 {
        self.force
    }
    /// Rigid approach from the gap's zero level [mm].
    #[getter]
    fn offset(&self) -> f64 {
        self.offset
    }
    /// Largest pressure [MPa].
    #[getter]
    fn max_pressure(&self) -> f64 {
        self.max_pressure
    }
    /// Force over the whole domain sx·sy [MPa] (tamaas' mean pressure).
    #[getter]
    fn mean_pressure(&self) -> f64 {
        self.mean_pressure
    }
    /// Area of the loaded cells [mm²].
    #[getter]
    fn contact_area(&self) -> f64 {
        self.contact_area
    }
    /// Conjugate-gradient iterations.
    #[getter]
    fn iterations(&self) -> usize {
        self.iterations
    }
    /// Final relative residual.
    #[getter]
    fn residual(&self) -> f64 {
        self.residual
    }
    /// Whether the residual reached the tolerance (always True: a failed solve raises
    /// ConvergenceError).
    #[getter]
    fn converged(&self) -> bool {
        self.converged
    }
    /// The record `kontakt solve` writes for the same map as a `method = "bem"` case with
    /// `[geometry] kind = "map"` (`--json`), as a dict.
    /// The size check's warnings (always empty for a map: its bodies are unknown, see
    /// docs/halfspace.md §10); also `to_dict()["warnings"]`.
    #[getter]
    fn warnings(&self) -> Vec<String> {
        self.warnings.clone()
    }
    fn to_dict<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        py.import("json")?
            .call_method1("loads", (self.report.as_str(),))
    }
    fn __repr__(&self) -> String {
        format!(
            "HalfSpaceResult(force={:.6} N, offset={:.6e} mm, max_pressure={:.6} MPa, contact_area={:.6e} mm², iterations={})",
            self.force, self.offset, self.max_pressure, self.contact_area, self.iterations
        )
    }
}
