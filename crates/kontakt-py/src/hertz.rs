//! Materials and closed-form Hertz contacts (point and line).

use crate::args;
use crate::case::json_to_py;
use crate::errors::{invalid, to_py, to_py_with};
use kontakt::hertz::line::{LineContact, LineSolution};
use kontakt::hertz::subsurface::{StressPeaks, YieldCriterion};
use kontakt::hertz::{HertzPointContact, HertzPointSolution, PointGeometry};
use kontakt::material::{ElasticMaterial, effective_modulus};
use kontakt_case::case::{
    BodySpec, CaseFile, ContactKind, ContactSpec, LoadSpec, Method, YieldSpec,
};
use numpy::ndarray::{ArrayD, Zip};
use numpy::{AllowTypeChange, IntoPyArray, PyArrayDyn, PyArrayLikeDyn};
use pyo3::prelude::*;
use pyo3::types::PyDict;

/// An optional `kontakt.Material` argument (here beside the class, so that the argument
/// converter `args` need not import the classes that use it).
pub(crate) fn material_arg(v: Option<&Bound<'_, PyAny>>, name: &str) -> PyResult<Option<Material>> {
    args::given(v)
        .map(|v| {
            v.extract::<Material>()
                .map_err(|_| args::wrong_type(name, v, "a kontakt.Material or None"))
        })
        .transpose()
}

/// A linear-elastic isotropic material: Young's modulus `e` [MPa] (finite, > 0) and
/// Poisson's ratio `nu` (-1 < nu <= 0.5).
#[pyclass(frozen, module = "kontakt._kontakt", from_py_object)]
#[derive(Clone, Copy)]
pub struct Material {
    pub(crate) inner: ElasticMaterial,
}

fn material_field(f: &str) -> Option<String> {
    match f {
        "youngs_modulus" => Some("e".into()),
        "poisson_ratio" => Some("nu".into()),
        _ => None,
    }
}

#[pymethods]
impl Material {
    #[new]
    #[pyo3(signature = (e, nu))]
    fn new(e: &Bound<'_, PyAny>, nu: &Bound<'_, PyAny>) -> PyResult<Self> {
        let e = args::real(e, "e", "a finite modulus > 0 MPa")?;
        let nu = args::real(nu, "nu", "-1 < nu <= 0.5")?;
        ElasticMaterial::new(e, nu)
            .map(|inner| Material { inner })
            .map_err(|err| to_py_with(err, material_field))
    }

    /// Bearing steel: E = 210 000 MPa, nu = 0.3.
    #[staticmethod]
    fn steel() -> Self {
        Material {
            inner: ElasticMaterial::STEEL,
        }
    }

    /// Young's modulus E [MPa].
    #[getter]
    fn e(&self) -> f64 {
        self.inner.youngs_modulus()
    }

    /// Poisson's ratio nu [-].
    #[getter]
    fn nu(&self) -> f64 {
        self.inner.poisson_ratio()
    }

    /// Shear modulus G = E / (2 (1 + nu)) [MPa].
    #[getter]
    fn shear_modulus(&self) -> f64 {
        self.inner.shear_modulus()
    }

    /// Contact modulus E* [MPa] of this material against `other`:
    /// 1/E* = (1 - nu1²)/E1 + (1 - nu2²)/E2.
    fn e_star(&self, other: &Bound<'_, PyAny>) -> PyResult<f64> {
        let other = material_arg(Some(other), "other")?
            .ok_or_else(|| args::wrong_type("other", other, "a kontakt.Material"))?;
        Ok(effective_modulus(&self.inner, &other.inner))
    }

    fn __repr__(&self) -> String {
        format!("Material(e={:?}, nu={:?})", self.e(), self.nu())
    }

    fn __eq__(&self, other: &Material) -> bool {
        self.inner == other.inner
    }
}

const FORCE: &str = "a finite force > 0 N";
const APPROACH: &str = "a finite approach > 0 mm";
const RADIUS: &str = "a radius in mm (> 0 convex, < 0 concave, inf flat)";
const CRITERIA: &str = "\"von_mises\" or \"tresca\"";

fn material_or_steel(m: Option<Material>) -> ElasticMaterial {
    m.map_or(ElasticMaterial::STEEL, |m| m.inner)
}

fn criterion(name: &str) -> PyResult<YieldCriterion> {
    match name {
        "von_mises" => Ok(YieldCriterion::VonMises),
        "tresca" => Ok(YieldCriterion::Tresca),
        other => Err(invalid("criterion", other, CRITERIA)),
    }
}

/// The peak subsurface stresses of a solved contact (or the library's error) as the dict
/// both result classes return.
fn peaks_dict<'py>(
    py: Python<'py>,
    peaks: Result<(StressPeaks, usize), kontakt::Error>,
) -> PyResult<Bound<'py, PyDict>> {
    let (p, body) = peaks.map_err(to_py)?;
    let d = PyDict::new(py);
    d.set_item("max_shear_stress_mpa", p.max_shear)?;
    d.set_item("max_shear_depth_mm", p.max_shear_depth)?;
    d.set_item("max_von_mises_stress_mpa", p.max_von_mises)?;
    d.set_item("max_von_mises_depth_mm", p.max_von_mises_depth)?;
    d.set_item("body", body)?;
    Ok(d)
}

/// A body of a Hertz case: its radii [mm] and material.
fn body_spec(radii: &[f64], m: ElasticMaterial) -> BodySpec {
    BodySpec {
        radii_mm: radii.to_vec(),
        e_mpa: m.youngs_modulus(),
        nu: m.poisson_ratio(),
    }
}

/// The CLI's JSON record (`kontakt hertz ... --json`) of the Hertz case `contact` between
/// `bodies` under `load`, with first yield when `yield_stress` [MPa] is given: `to_dict()`
/// of both result classes, through the case layer's one Hertz report.
fn hertz_record<'py>(
    py: Python<'py>,
    contact: ContactSpec,
    [body1, body2]: [BodySpec; 2],
    load: LoadSpec,
    yield_stress: Option<f64>,
    criterion: &str,
) -> PyResult<Bound<'py, PyAny>> {
    let case = CaseFile {
        name: None,
        method: Method::Hertz,
        contact,
        body1,
        body2,
        load,
        yield_check: yield_criterion(yield_stress, criterion)?,
    };
    let report = kontakt_case::run_case(&case).map_err(to_py)?;
    json_to_py(py, &report)
}

/// Evaluate `f` over `x` and `y` broadcast against each other (NumPy rules for two
/// operands), as a float64 array of the broadcast shape.
fn broadcast2<'py>(
    py: Python<'py>,
    x: PyArrayLikeDyn<'py, f64, AllowTypeChange>,
    y: PyArrayLikeDyn<'py, f64, AllowTypeChange>,
    f: impl Fn(f64, f64) -> f64,
) -> PyResult<Bound<'py, PyArrayDyn<f64>>> {
    let (x, y) = (x.as_array(), y.as_array());
    let shape = broadcast_shape(x.shape(), y.shape()).ok_or_else(|| {
        invalid(
            "x, y",
            format!(
                "shapes {} and {}",
                args::shape(x.shape()),
                args::shape(y.shape())
            ),
            "arrays of shapes that broadcast against each other",
        )
    })?;
    let (xb, yb) = match (x.broadcast(shape.clone()), y.broadcast(shape.clone())) {
        (Some(xb), Some(yb)) => (xb, yb),
        _ => {
            return Err(invalid(
                "x, y",
                "shapes that do not broadcast",
                "broadcastable",
            ));
        }
    };
    let mut out = ArrayD::<f64>::zeros(shape);
    Zip::from(&mut out)
        .and(&xb)
        .and(&yb)
        .for_each(|o, &a, &b| *o = f(a, b));
    Ok(out.into_pyarray(py))
}

fn broadcast_shape(a: &[usize], b: &[usize]) -> Option<Vec<usize>> {
    let n = a.len().max(b.len());
    let dim = |s: &[usize], i: usize| {
        let k = n - s.len();
        if i < k { 1 } else { s[i - k] }
    };
    (0..n)
        .map(|i| match (dim(a, i), dim(b, i)) {
            (p, q) if p == q => Some(p),
            (1, q) => Some(q),
            (p, 1) => Some(p),
            _ => None,
        })
        .collect()
}

fn point_field(f: &str) -> Option<String> {
    let f = f
        .replace("body1.radii", "radii1")
        .replace("body2.radii", "radii2");
    Some(match f.as_str() {
        "youngs_modulus" => "e".into(),
        "poisson_ratio" => "nu".into(),
        _ => f,
    })
}

/// A planned Hertz point contact (elliptical or circular): the principal radii [mm] of
/// the two bodies (convex > 0, concave < 0, `inf` for flat), the angle `angle` [rad] from
/// body 1's first principal direction to body 2's, and the materials (steel by default).
#[pyclass(frozen, module = "kontakt._kontakt")]
pub struct HertzPoint {
    inner: HertzPointContact,
}

#[pymethods]
impl HertzPoint {
    #[new]
    #[pyo3(
        signature = (radii1, radii2, material1 = None, material2 = None, angle = None),
        text_signature = "(radii1, radii2, material1=None, material2=None, angle=0.0)"
    )]
    fn new(
        radii1: &Bound<'_, PyAny>,
        radii2: &Bound<'_, PyAny>,
        material1: Option<&Bound<'_, PyAny>>,
        material2: Option<&Bound<'_, PyAny>>,
        angle: Option<&Bound<'_, PyAny>>,
    ) -> PyResult<Self> {
        let radii1 = args::reals::<2>(radii1, "radii1", RADIUS)?;
        let radii2 = args::reals::<2>(radii2, "radii2", RADIUS)?;
        let material1 = material_arg(material1, "material1")?;
        let material2 = material_arg(material2, "material2")?;
        let angle = args::opt_real(angle, "angle", "a finite angle in rad")?.unwrap_or(0.0);
        let g =
            PointGeometry::new(radii1, radii2, angle).map_err(|e| to_py_with(e, point_field))?;
        let inner = HertzPointContact::new(
            g,
            material_or_steel(material1),
            material_or_steel(material2),
        )
        .map_err(to_py)?;
        Ok(HertzPoint { inner })
    }

    /// Contact modulus E* [MPa].
    #[getter]
    fn e_star(&self) -> f64 {
        self.inner.e_star()
    }

    /// Axis ratio b/a of the contact ellipse (load independent).
    #[getter]
    fn axis_ratio(&self) -> f64 {
        self.inner.axis_ratio()
    }

    /// Relative curvature (A, B) [1/mm], A <= B: the gap is A x'² + B y'².
    #[getter]
    fn relative_curvature(&self) -> (f64, f64) {
        let k = self.inner.geometry().curvature();
        (k.a_coef, k.b_coef)
    }

    /// Approach [mm] for a normal force `force` [N] (> 0).
    fn approach_from_force(&self, force: &Bound<'_, PyAny>) -> PyResult<f64> {
        let force = args::real(force, "force", FORCE)?;
        self.inner.approach_from_force(force).map_err(to_py)
    }

    /// Normal force [N] for an approach `approach` [mm] (> 0).
    fn force_from_approach(&self, approach: &Bound<'_, PyAny>) -> PyResult<f64> {
        let approach = args::real(approach, "approach", APPROACH)?;
        self.inner.force_from_approach(approach).map_err(to_py)
    }

    /// Solve for a normal force `force` [N] or an approach `approach` [mm] (exactly one).
    #[pyo3(signature = (force = None, approach = None))]
    fn solve(
        &self,
        force: Option<&Bound<'_, PyAny>>,
        approach: Option<&Bound<'_, PyAny>>,
    ) -> PyResult<HertzPointResult> {
        let force = args::opt_real(force, "force", FORCE)?;
        let approach = args::opt_real(approach, "approach", APPROACH)?;
        let (solution, by_approach) = match (force, approach) {
            (Some(f), None) => (self.inner.solve_force(f), false),
            (None, Some(d)) => (self.inner.solve_approach(d), true),
            _ => {
                return Err(invalid(
                    "force, approach",
                    "none or both",
                    "exactly one of force [N] or approach [mm]",
                ));
            }
        };
        let solution = solution.map_err(to_py)?;
        let size = kontakt::hertz::validity::point_size(self.inner.geometry(), &solution);
        let warnings = size_verdict(size, ["radii1", "radii2"])?;
        Ok(HertzPointResult {
            contact: self.inner,
            solution,
            by_approach,
            warnings,
        })
    }
}

/// The methods both solved Hertz contacts share (`p0`, `mean_pressure`, `warnings`,
/// `subsurface_peaks`, `to_dict`), written once; `$ty` says how it is a Hertz case
/// (`HertzCase`), and `$($own)*` are its own methods (one `#[pymethods]` block per class).
macro_rules! hertz_result {
    ($ty:ident, mean_pressure = $mean_doc:literal, peaks = $peaks_doc:literal, to_dict = $dict_doc:literal, { $($own:tt)* }) => {
        #[pymethods]
        impl $ty {
            /// Maximum (central) pressure p0 [MPa].
            #[getter]
            fn p0(&self) -> f64 {
                self.solution.max_pressure
            }
            #[doc = $mean_doc]
            #[getter]
            fn mean_pressure(&self) -> f64 {
                self.solution.mean_pressure
            }
            /// Where the result is outside Hertz theory's comfortable range (a contact
            /// above 0.4 of a body's radius of curvature), as the case reports' `warnings`;
            /// empty when none applies (at 1 or more `solve` raises `InputError`).
            #[getter]
            fn warnings(&self) -> Vec<String> {
                self.warnings.clone()
            }
            #[doc = $peaks_doc]
            fn subsurface_peaks<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyDict>> {
                peaks_dict(py, self.contact.subsurface_peaks(&self.solution))
            }
            #[doc = $dict_doc]
            #[pyo3(
                signature = (yield_stress = None, criterion = None),
                text_signature = "($self, yield_stress=None, criterion='von_mises')"
            )]
            fn to_dict<'py>(
                &self,
                py: Python<'py>,
                yield_stress: Option<&Bound<'py, PyAny>>,
                criterion: Option<&Bound<'py, PyAny>>,
            ) -> PyResult<Bound<'py, PyAny>> {
                let yield_stress =
                    args::opt_real(yield_stress, "yield_stress", "a finite stress > 0 MPa")?;
                let criterion = args::text_or(criterion, "criterion", CRITERIA, "von_mises")?;
                let (contact, bodies, load) = self.case();
                hertz_record(py, contact, bodies, load, yield_stress, &criterion)
            }
            $($own)*
        }
    };
}

/// A solved Hertz point contact. Lengths mm, force N, pressure MPa, angle rad.
#[pyclass(frozen, module = "kontakt._kontakt")]
pub struct HertzPointResult {
    contact: HertzPointContact,
    solution: HertzPointSolution,
    by_approach: bool,
    warnings: Vec<String>,
}

impl HertzPointResult {
    /// This contact as a Hertz case: contact, bodies, and the load it was solved for.
    fn case(&self) -> (ContactSpec, [BodySpec; 2], LoadSpec) {
        let g = self.contact.geometry();
        let [m1, m2] = self.contact.materials();
        let load = if self.by_approach {
            LoadSpec {
                approach_mm: Some(self.solution.approach),
                ..LoadSpec::default()
            }
        } else {
            LoadSpec {
                force_n: Some(self.solution.force),
                ..LoadSpec::default()
            }
        };
        let contact = ContactSpec {
            kind: ContactKind::Point,
            angle_deg: g.angle().to_degrees(),
            length_mm: None,
        };
        let bodies = [
            body_spec(&g.body1_radii(), m1),
            body_spec(&g.body2_radii(), m2),
        ];
        (contact, bodies, load)
    }
}

/// The case layer's validity check of a contact's size, with the arguments named as the
/// Python signature does: the warnings, or `InputError` naming the radius argument.
fn size_verdict(
    size: kontakt::hertz::validity::SizeCheck,
    keys: [&str; 2],
) -> PyResult<Vec<String>> {
    use kontakt_case::validity::{ContactSize, Size};
    let verdict = ContactSize::new(Size::Hertz(size), keys).verdict();
    Ok(verdict.map_err(to_py)?.into_iter().collect())
}

hertz_result!(
    HertzPointResult,
    mean_pressure = "Mean pressure F / (pi a b) [MPa].",
    peaks = "Peak subsurface stresses on the load axis (MPa, mm; tension positive, so the \
             von Mises and shear peaks are magnitudes) and the body (1 or 2) they belong to.",
    to_dict = "The CLI's JSON record of this contact (`kontakt hertz ... --json`), as a \
               dict; with `yield_stress` [MPa] it includes first yield by `criterion`.",
    {
        /// Semi-major axis a [mm].
        #[getter]
        fn a(&self) -> f64 {
            self.solution.semi_axes[0]
        }
        /// Semi-minor axis b [mm].
        #[getter]
        fn b(&self) -> f64 {
            self.solution.semi_axes[1]
        }
        /// Normal force F [N].
        #[getter]
        fn force(&self) -> f64 {
            self.solution.force
        }
        /// Approach of distant points [mm].
        #[getter]
        fn approach(&self) -> f64 {
            self.solution.approach
        }
        /// Contact area pi a b [mm²].
        #[getter]
        fn contact_area(&self) -> f64 {
            self.solution.contact_area
        }
        /// Contact stiffness dF/d(approach) [N/mm].
        #[getter]
        fn stiffness(&self) -> f64 {
            self.solution.stiffness
        }
        /// Angle from body 1's first principal direction to the major axis [rad].
        #[getter]
        fn orientation(&self) -> f64 {
            self.solution.orientation
        }

        /// Hertz pressure [MPa] at the points (x, y) [mm] of the contact frame (x along body
        /// 1's first principal direction); x and y broadcast as in NumPy.
        fn pressure<'py>(
            &self,
            py: Python<'py>,
            x: &Bound<'py, PyAny>,
            y: &Bound<'py, PyAny>,
        ) -> PyResult<Bound<'py, PyArrayDyn<f64>>> {
            let x = args::array(x, "x", "positions in mm")?;
            let y = args::array(y, "y", "positions in mm")?;
            let s = self.solution;
            broadcast2(py, x, y, |x, y| s.pressure_at(x, y))
        }

        fn __repr__(&self) -> String {
            format!(
                "HertzPointResult(force={:?} N, a={:.6e} mm, b={:.6e} mm, p0={:.6} MPa, approach={:.6e} mm)",
                self.solution.force,
                self.a(),
                self.b(),
                self.p0(),
                self.approach()
            )
        }
    }
);

fn yield_criterion(yield_stress: Option<f64>, name: &str) -> PyResult<Option<YieldSpec>> {
    let criterion = criterion(name)?;
    Ok(yield_stress.map(|stress_mpa| YieldSpec {
        stress_mpa,
        criterion,
    }))
}

/// A planned line contact of two parallel cylinders: radii [mm] (convex > 0, concave < 0,
/// `inf` for flat), materials (steel by default), and the contact length `length` [mm]
/// (optional; needed for a total force, the approach and the area).
#[pyclass(frozen, module = "kontakt._kontakt")]
pub struct HertzLine {
    inner: LineContact,
    length: Option<f64>,
}

#[pymethods]
impl HertzLine {
    #[new]
    #[pyo3(signature = (radius1, radius2, material1 = None, material2 = None, length = None))]
    fn new(
        radius1: &Bound<'_, PyAny>,
        radius2: &Bound<'_, PyAny>,
        material1: Option<&Bound<'_, PyAny>>,
        material2: Option<&Bound<'_, PyAny>>,
        length: Option<&Bound<'_, PyAny>>,
    ) -> PyResult<Self> {
        let radius1 = args::real(radius1, "radius1", RADIUS)?;
        let radius2 = args::real(radius2, "radius2", RADIUS)?;
        let material1 = material_arg(material1, "material1")?;
        let material2 = material_arg(material2, "material2")?;
        let length = args::opt_real(length, "length", "a finite length > 0 mm")?;
        if let Some(l) = length {
            kontakt::error::positive_as("length", l, "a finite length > 0 mm").map_err(to_py)?;
        }
        let inner = LineContact::new(
            radius1,
            radius2,
            material_or_steel(material1),
            material_or_steel(material2),
        )
        .map_err(|e| {
            to_py_with(e, |f| match f {
                "body1.radius" => Some("radius1".into()),
                "body2.radius" => Some("radius2".into()),
                _ => None,
            })
        })?;
        Ok(HertzLine { inner, length })
    }

    /// Effective radius R = 1/(1/R1 + 1/R2) [mm].
    #[getter]
    fn effective_radius(&self) -> f64 {
        self.inner.effective_radius()
    }

    /// Contact modulus E* [MPa].
    #[getter]
    fn e_star(&self) -> f64 {
        self.inner.e_star()
    }

    /// Solve for a line load `line_load` [N/mm] or a force `force` [N] over the length
    /// (exactly one).
    #[pyo3(signature = (line_load = None, force = None))]
    fn solve(
        &self,
        line_load: Option<&Bound<'_, PyAny>>,
        force: Option<&Bound<'_, PyAny>>,
    ) -> PyResult<HertzLineResult> {
        let line_load = args::opt_real(line_load, "line_load", "a finite line load > 0 N/mm")?;
        let force = args::opt_real(force, "force", FORCE)?;
        let (q, by_force) = match (line_load, force, self.length) {
            (Some(q), None, _) => (q, false),
            (None, Some(f), Some(l)) => {
                kontakt::error::positive_as("force", f, "a finite force > 0 N").map_err(to_py)?;
                (f / l, true)
            }
            (None, Some(_), None) => {
                return Err(invalid(
                    "length",
                    "None",
                    "a contact length [mm] to solve for a force",
                ));
            }
            _ => {
                return Err(invalid(
                    "line_load, force",
                    "none or both",
                    "exactly one of line_load [N/mm] or force [N]",
                ));
            }
        };
        let solution = self.inner.solve(q).map_err(|e| {
            to_py_with(e, |f| {
                (f == "line_load" && by_force).then(|| "force".into())
            })
        })?;
        let approach = match self.length {
            Some(l) => Some(self.inner.lundberg_approach(q * l, l).map_err(to_py)?),
            None => None,
        };
        let size = kontakt::hertz::validity::line_size(self.inner.radii(), &solution);
        let warnings = size_verdict(size, ["radius1", "radius2"])?;
        Ok(HertzLineResult {
            contact: self.inner,
            solution,
            length: self.length,
            approach,
            by_force,
            warnings,
        })
    }
}

/// A solved line contact. Lengths mm, line load N/mm, pressure MPa.
#[pyclass(frozen, module = "kontakt._kontakt")]
pub struct HertzLineResult {
    contact: LineContact,
    solution: LineSolution,
    length: Option<f64>,
    approach: Option<f64>,
    by_force: bool,
    warnings: Vec<String>,
}

impl HertzLineResult {
    /// This contact as a Hertz case: contact, bodies, and the load it was solved for.
    fn case(&self) -> (ContactSpec, [BodySpec; 2], LoadSpec) {
        let [m1, m2] = self.contact.materials();
        let [r1, r2] = self.contact.radii();
        let load = match (self.by_force, self.length) {
            (true, Some(l)) => LoadSpec {
                force_n: Some(self.solution.line_load * l),
                ..LoadSpec::default()
            },
            _ => LoadSpec {
                line_load_n_per_mm: Some(self.solution.line_load),
                ..LoadSpec::default()
            },
        };
        let contact = ContactSpec {
            kind: ContactKind::Line,
            angle_deg: 0.0,
            length_mm: self.length,
        };
        (contact, [body_spec(&[r1], m1), body_spec(&[r2], m2)], load)
    }
}

hertz_result!(
    HertzLineResult,
    mean_pressure = "Mean pressure P'/(2b) [MPa].",
    peaks = "Peak subsurface stresses on the load axis (plane strain; MPa, mm) and the body.",
    to_dict = "The CLI's JSON record of this contact, as a dict (first yield with `yield_stress`).",
    {
        /// Half-width b of the contact strip [mm].
        #[getter]
        fn b(&self) -> f64 {
            self.solution.half_width
        }
        /// Line load P' [N/mm].
        #[getter]
        fn line_load(&self) -> f64 {
            self.solution.line_load
        }
        /// Approach [mm] by Lundberg's formula (None without a length).
        #[getter]
        fn approach(&self) -> Option<f64> {
            self.approach
        }

        /// Pressure [MPa] at distances `x` [mm] from the centre line (any array shape).
        fn pressure<'py>(
            &self,
            py: Python<'py>,
            x: &Bound<'py, PyAny>,
        ) -> PyResult<Bound<'py, PyArrayDyn<f64>>> {
            let x = args::array(x, "x", "distances in mm")?;
            let s = self.solution;
            Ok(x.as_array().mapv(|x| s.pressure_at(x)).into_pyarray(py))
        }

        fn __repr__(&self) -> String {
            format!(
                "HertzLineResult(line_load={:?} N/mm, b={:.6e} mm, p0={:.6} MPa)",
                self.solution.line_load,
                self.b(),
                self.p0()
            )
        }
    }
);
