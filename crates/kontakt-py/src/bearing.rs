//! A whole bearing solved for many loads (`kontakt_case::BearingModel`): planned once from
//! a bearing case (`method = "bearing"`), each solve warm-started from the last
//! equilibrium, with the GIL released; the result as NumPy arrays and as the case report.

use crate::args;
use crate::case::{dict_toml, json_to_py, parse_dict_text};
use crate::errors::{invalid, to_py, to_py_with};
use kontakt_case::bearing_case::{
    BallRow, BearingElements, BearingLoadSpec, PrescribedSpec, RollerRow,
};
use kontakt_case::{BearingModel, BearingReport, Case};
use numpy::ndarray::Array2;
use numpy::{IntoPyArray, PyArray1, PyArray2};
use pyo3::exceptions::PyTypeError;
use pyo3::prelude::*;
use pyo3::types::{PyBool, PyDict, PyString};

/// The keys of `prescribed`, the case's `[load.prescribed]`: mm and rad.
const PRESCRIBED: [&str; 5] = ["dx_mm", "dy_mm", "dz_mm", "tilt_x_rad", "tilt_y_rad"];

/// The case key of a load component (`load.force_n[2]`, `load.prescribed.dx_mm`) as the
/// argument of `Bearing.solve` (`force[2]`, `prescribed.dx_mm`).
fn argument(key: &str) -> Option<String> {
    if let Some(rest) = key.strip_prefix("load.force_n") {
        return Some(format!("force{rest}"));
    }
    if let Some(rest) = key.strip_prefix("load.moment_nmm") {
        return Some(format!("moment{rest}"));
    }
    key.strip_prefix("load.prescribed.")
        .map(|k| format!("prescribed.{k}"))
}

/// A case given as a dict, TOML text (a str with a newline) or a path, as `kontakt.run`
/// takes it, parsed by the case layer; a case without `[load]` gets the empty one.
fn parse(case: &Bound<'_, PyAny>) -> PyResult<Case> {
    let py = case.py();
    let mapping = py.import("collections.abc")?.getattr("Mapping")?;
    if case.is_instance(&mapping)? {
        let dict = if case.is_instance_of::<PyDict>() {
            case.clone()
        } else {
            py.import("builtins")?.getattr("dict")?.call1((case,))?
        };
        return parse_dict_text(&with_load(dict_toml(&dict, "case")?));
    }
    let inline = case.is_instance_of::<PyString>() && case.extract::<String>()?.contains('\n');
    let text = if inline {
        case.extract::<String>()?
    } else if case.is_instance_of::<PyString>() || case.hasattr("__fspath__")? {
        let path = args::path(case, "case")?;
        kontakt_case::read_case_file(&path).map_err(to_py)?
    } else {
        return Err(args::wrong_type(
            "case",
            case,
            "a bearing case: a dict with the keys of a case file, TOML text or a path to a .toml file",
        ));
    };
    Case::from_toml_str(&with_load(text)).map_err(to_py)
}

/// `text` with an empty `[load]` table appended when it has none (the load is given to
/// `solve`); text that is not TOML is left to the case parser's message.
fn with_load(text: String) -> String {
    match text.parse::<toml::Table>() {
        Ok(t) if !t.contains_key("load") => format!("{text}\n[load]\n"),
        _ => text,
    }
}

/// The bearing of a case given as `kontakt.Bearing` takes it, planned; `class` names the
/// caller in the error for a case of another method.
pub(crate) fn plan(case: &Bound<'_, PyAny>, class: &str) -> PyResult<BearingModel> {
    let case = parse(case)?;
    let Case::Bearing(case) = case else {
        return Err(invalid(
            "case.method",
            format!("\"{}\"", case.method()),
            &format!("\"bearing\": {class} takes a bearing case (kontakt.run takes the others)"),
        ));
    };
    BearingModel::new(&case).map_err(to_py)
}

/// A whole rolling bearing, planned once from a bearing case (`method = "bearing"`,
/// docs/case-schema.md): `case` is a dict with the keys of a case file, TOML text or a
/// path to a `.toml` file, as `kontakt.run` takes it; its `[load]` table is optional and
/// not used. `solve` gives the equilibrium of the inner ring under a load, starting from
/// the last equilibrium (a warm start). Units: mm, N, N·mm, rad.
#[pyclass(module = "kontakt._kontakt")]
pub struct Bearing {
    inner: BearingModel,
}

#[pymethods]
impl Bearing {
    #[new]
    fn new(case: &Bound<'_, PyAny>) -> PyResult<Self> {
        plan(case, "kontakt.Bearing").map(|inner| Bearing { inner })
    }

    /// The bearing type of the case: "cylindrical", "tapered", "thrust",
    /// "deep_groove_ball" or "angular_contact_ball".
    #[getter]
    fn bearing_type(&self) -> &'static str {
        self.inner.bearing_type()
    }

    /// Solve the equilibrium of the inner ring (the outer ring fixed, z the bearing axis)
    /// under `force` (Fx, Fy, Fz) [N] and `moment` (Mx, My) [N·mm]. `prescribed` holds
    /// degrees of freedom at a displacement instead, with the keys of the case's
    /// `[load.prescribed]`: "dx_mm", "dy_mm", "dz_mm" [mm], "tilt_x_rad", "tilt_y_rad"
    /// [rad] (the force or moment on such a degree of freedom must be 0; the result gives
    /// the reaction). `hold_tilts=True` holds both tilts at 0 (the shaft takes the
    /// moment). The solve starts from the last converged equilibrium (`reset()` forgets
    /// it) and releases the GIL.
    #[pyo3(signature = (force = None, moment = None, prescribed = None, hold_tilts = None))]
    fn solve(
        &mut self,
        py: Python<'_>,
        force: Option<&Bound<'_, PyAny>>,
        moment: Option<&Bound<'_, PyAny>>,
        prescribed: Option<&Bound<'_, PyAny>>,
        hold_tilts: Option<&Bound<'_, PyAny>>,
    ) -> PyResult<BearingResult> {
        let load = load(force, moment, prescribed, hold_tilts)?;
        let model = &mut self.inner;
        let report = py
            .detach(|| model.solve(&load))
            .map_err(|e| to_py_with(e, argument))?;
        BearingResult::new(report)
    }

    /// Forget the last equilibrium: the next `solve` starts from the closed forms.
    fn reset(&mut self) {
        self.inner.reset();
    }

    fn __repr__(&self) -> String {
        format!("Bearing(bearing_type={:?})", self.inner.bearing_type())
    }
}

/// The arguments of `Bearing.solve` as the case's `[load]`.
fn load<'py>(
    force: Option<&Bound<'py, PyAny>>,
    moment: Option<&Bound<'py, PyAny>>,
    prescribed: Option<&Bound<'py, PyAny>>,
    hold_tilts: Option<&Bound<'py, PyAny>>,
) -> PyResult<BearingLoadSpec> {
    fn given<'py>(v: Option<&Bound<'py, PyAny>>) -> Option<Bound<'py, PyAny>> {
        v.filter(|v| !v.is_none()).cloned()
    }
    let force_n = given(force)
        .map(|v| args::reals::<3>(&v, "force", "finite forces (Fx, Fy, Fz) [N]"))
        .transpose()?
        .unwrap_or_default();
    let moment_nmm = given(moment)
        .map(|v| args::reals::<2>(&v, "moment", "finite moments (Mx, My) [N·mm]"))
        .transpose()?
        .unwrap_or_default();
    let mut held = [None; 5];
    if let Some(p) = given(prescribed) {
        let valid =
            "a dict of displacements: dx_mm, dy_mm, dz_mm [mm], tilt_x_rad, tilt_y_rad [rad]";
        let d = p
            .cast::<PyDict>()
            .map_err(|_| args::wrong_type("prescribed", &p, valid))?;
        for (k, v) in d.iter() {
            let key = k
                .extract::<String>()
                .ok()
                .and_then(|k| PRESCRIBED.iter().position(|n| *n == k))
                .ok_or_else(|| {
                    invalid("prescribed", format!("a key {}", args::shown(&k)), valid)
                })?;
            let name = format!("prescribed.{}", PRESCRIBED[key]);
            held[key] = Some(args::real(
                &v,
                &name,
                "a finite displacement [mm] or tilt [rad]",
            )?);
        }
    }
    if let Some(h) = given(hold_tilts) {
        if !h.is_instance_of::<PyBool>() {
            return Err(PyTypeError::new_err(format!(
                "invalid hold_tilts = {}: expected a bool",
                args::shown(&h)
            )));
        }
        if h.extract::<bool>()? {
            for i in 3..5 {
                if let Some(v) = held[i] {
                    return Err(invalid(
                        "hold_tilts",
                        "True",
                        &format!(
                            "False when prescribed.{} = {v} gives the tilt",
                            PRESCRIBED[i]
                        ),
                    ));
                }
                held[i] = Some(0.0);
            }
        }
    }
    Ok(BearingLoadSpec {
        force_n,
        moment_nmm,
        prescribed: PrescribedSpec {
            dx_mm: held[0],
            dy_mm: held[1],
            dz_mm: held[2],
            tilt_x_rad: held[3],
            tilt_y_rad: held[4],
        },
    })
}

/// One equilibrium of a `Bearing`: the inner ring's displacement, the load the rolling
/// elements carry, the stiffness, per element and per slice of the most loaded roller;
/// `to_dict()` is the case report (`kontakt bearing CASE --json`).
#[pyclass(frozen, module = "kontakt._kontakt")]
pub struct BearingResult {
    report: BearingReport,
}

impl BearingResult {
    fn new(report: BearingReport) -> PyResult<Self> {
        Ok(BearingResult { report })
    }

    /// A column of the element table: `roller` of a roller bearing's row, `ball` of a ball
    /// bearing's.
    fn column<'py>(
        &self,
        py: Python<'py>,
        roller: impl Fn(&RollerRow) -> f64,
        ball: impl Fn(&BallRow) -> f64,
    ) -> Bound<'py, PyArray1<f64>> {
        let v: Vec<f64> = match &self.report.elements {
            BearingElements::Rollers(r) => r.roller_loads.iter().map(roller).collect(),
            BearingElements::Balls(b) => b.ball_loads.iter().map(ball).collect(),
        };
        v.into_pyarray(py)
    }
}

#[pymethods]
impl BearingResult {
    /// The bearing type (the report's `bearing_type`).
    #[getter]
    fn bearing_type(&self) -> &'static str {
        self.report.bearing_type
    }
    /// The inner ring's displacement (δx, δy, δz [mm], θx, θy [rad]), shape (5,).
    #[getter]
    fn displacement<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray1<f64>> {
        let (d, t) = (self.report.displacement_mm, self.report.tilt_rad);
        PyArray1::from_slice(py, &[d[0], d[1], d[2], t[0], t[1]])
    }
    /// The load the rolling elements carry (Fx, Fy, Fz [N], Mx, My [N·mm]), shape (5,):
    /// the applied load on force-controlled components (to the residual), the reaction
    /// on prescribed ones.
    #[getter]
    fn load_carried<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray1<f64>> {
        let (f, m) = (self.report.force_n, self.report.moment_nmm);
        PyArray1::from_slice(py, &[f[0], f[1], f[2], m[0], m[1]])
    }
    /// The stiffness matrix ∂(load carried)/∂(displacement), shape (5, 5), in the order of
    /// `displacement`: N/mm, N/rad, N, N·mm/rad.
    #[getter]
    fn stiffness<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray2<f64>> {
        let k = &self.report.stiffness_matrix;
        Array2::from_shape_fn((5, 5), |(i, j)| k[i][j]).into_pyarray(py)
    }
    /// Azimuth of each rolling element from x toward y [deg], shape (Z,).
    #[getter]
    fn azimuth_deg<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray1<f64>> {
        self.column(py, |r| r.azimuth_deg, |b| b.azimuth_deg)
    }
    /// Inner raceway load of each element [N] (a ball's load is the same on both
    /// raceways at rest), shape (Z,).
    #[getter]
    fn inner_load_n<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray1<f64>> {
        self.column(py, |r| r.inner_load_n, |b| b.inner_load_n)
    }
    /// Outer raceway load of each element [N] (a ball's carries its centrifugal force
    /// too at speed), shape (Z,).
    #[getter]
    fn outer_load_n<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray1<f64>> {
        self.column(py, |r| r.outer_load_n, |b| b.outer_load_n)
    }
    /// Inner contact angle of each element [deg] (a ball's; a roller's cone angle),
    /// shape (Z,).
    #[getter]
    fn inner_contact_angle_deg<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray1<f64>> {
        let cone = self.report.rollers().map_or(0.0, |r| r.cone_angle_deg);
        self.column(py, |_| cone, |b| b.inner_contact_angle_deg)
    }
    /// Outer contact angle of each element [deg] (a ball's, falling with speed; a
    /// roller's cup angle), shape (Z,).
    #[getter]
    fn outer_contact_angle_deg<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray1<f64>> {
        let cup = self.report.rollers().map_or(0.0, |r| r.contact_angle_deg);
        self.column(py, |_| cup, |b| b.outer_contact_angle_deg)
    }
    /// Centrifugal force of each ball [N] (0 at rest and for rollers), shape (Z,).
    #[getter]
    fn centrifugal_force_n<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray1<f64>> {
        self.column(py, |_| 0.0, |b| b.centrifugal_force_n)
    }
    /// Gyroscopic moment of each ball [N·mm] (0 at rest and for rollers), shape (Z,).
    #[getter]
    fn gyroscopic_moment_nmm<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray1<f64>> {
        self.column(py, |_| 0.0, |b| b.gyroscopic_moment_nmm)
    }
    /// Rib load of each element [N] (tapered rollers; 0 otherwise), shape (Z,).
    #[getter]
    fn rib_load_n<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray1<f64>> {
        self.column(py, |r| r.rib_load_n, |_| 0.0)
    }
    /// The contact angle of each element [deg] (a ball's loaded angle; a roller's cup
    /// angle), shape (Z,).
    #[getter]
    fn contact_angle_deg<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray1<f64>> {
        let cup = self.report.rollers().map_or(0.0, |r| r.contact_angle_deg);
        self.column(py, |_| cup, |b| b.contact_angle_deg)
    }
    /// The approach of each element [mm] (a roller's largest slice approach; negative:
    /// lifted off), shape (Z,).
    #[getter]
    fn approach_mm<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray1<f64>> {
        self.column(py, |r| r.approach_mm, |b| b.approach_mm)
    }
    /// Every column of the report's element table (`roller_loads` or `ball_loads`) as an
    /// array of shape (Z,), by its report key.
    #[getter]
    fn elements<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyDict>> {
        let rows = match &self.report.elements {
            BearingElements::Rollers(r) => serde_json::to_value(&r.roller_loads),
            BearingElements::Balls(b) => serde_json::to_value(&b.ball_loads),
        }
        .map_err(|e| pyo3::exceptions::PyRuntimeError::new_err(format!("report: {e}")))?;
        let d = PyDict::new(py);
        let rows = rows.as_array().cloned().unwrap_or_default();
        if let Some(serde_json::Value::Object(first)) = rows.first() {
            for key in first.keys() {
                let v: Vec<f64> = rows
                    .iter()
                    .map(|r| r[key].as_f64().unwrap_or(f64::NAN))
                    .collect();
                d.set_item(key, v.into_pyarray(py))?;
            }
        }
        Ok(d)
    }
    /// The largest slice load per unit length of each roller [N/mm], shape (Z,); None for
    /// a ball bearing.
    #[getter]
    fn max_load_per_length_n_per_mm<'py>(
        &self,
        py: Python<'py>,
    ) -> Option<Bound<'py, PyArray1<f64>>> {
        self.report.rollers().map(|r| {
            let v: Vec<f64> = r
                .roller_loads
                .iter()
                .map(|r| r.max_load_per_length_n_per_mm)
                .collect();
            v.into_pyarray(py)
        })
    }
    /// The slices of the most loaded roller: a dict with "roller" (its index) and arrays
    /// "position_mm" (slice centres from the roller centre [mm]), "load_n" [N],
    /// "load_per_length_n_per_mm" [N/mm], "approach_mm" [mm], "inner_pressure_mpa" and
    /// "outer_pressure_mpa" (Hertz [MPa]); None for a ball bearing.
    #[getter]
    fn slices<'py>(&self, py: Python<'py>) -> PyResult<Option<Bound<'py, PyDict>>> {
        let Some(r) = self.report.rollers() else {
            return Ok(None);
        };
        let s = &r.most_loaded_roller;
        let d = PyDict::new(py);
        d.set_item("roller", s.roller)?;
        d.set_item("position_mm", PyArray1::from_slice(py, &s.position_mm))?;
        d.set_item("load_n", PyArray1::from_slice(py, &s.load_n))?;
        d.set_item(
            "load_per_length_n_per_mm",
            PyArray1::from_slice(py, &s.load_per_length_n_per_mm),
        )?;
        d.set_item("approach_mm", PyArray1::from_slice(py, &s.approach_mm))?;
        d.set_item(
            "inner_pressure_mpa",
            PyArray1::from_slice(py, &s.inner_pressure_mpa),
        )?;
        d.set_item(
            "outer_pressure_mpa",
            PyArray1::from_slice(py, &s.outer_pressure_mpa),
        )?;
        Ok(Some(d))
    }
    /// The largest Hertz pressure of each element on the inner raceway [MPa] (a roller's
    /// largest slice pressure), shape (Z,).
    #[getter]
    fn inner_max_pressure_mpa<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray1<f64>> {
        self.column(
            py,
            |r| r.inner_max_pressure_mpa,
            |b| b.inner_max_pressure_mpa,
        )
    }
    /// The largest Hertz pressure of each element on the outer raceway [MPa], shape (Z,).
    #[getter]
    fn outer_max_pressure_mpa<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray1<f64>> {
        self.column(
            py,
            |r| r.outer_max_pressure_mpa,
            |b| b.outer_max_pressure_mpa,
        )
    }
    /// Static safety and rating lives: a dict with the keys of the report's `rating`
    /// (`static_safety_from_pressure`, `l10_mrev`, `l10r_mrev`, `static_safety`, ...;
    /// absent keys need `[bearing.rating]`'s `dynamic_n` or `static_n`), loads in N, pressures
    /// in MPa, lives in millions of revolutions.
    #[getter]
    fn rating<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        json_to_py(py, &self.report.rating)
    }
    /// The largest rolling-element load [N] (a roller's outer raceway load, a ball's load).
    #[getter]
    fn max_element_load_n(&self) -> f64 {
        max_load(&self.report)
    }
    /// The load-zone parameter ε (Sjövall 1933); None without a radial displacement and
    /// for thrust bearings.
    #[getter]
    fn load_zone_epsilon(&self) -> Option<f64> {
        self.report.load_zone_epsilon
    }
    /// How the solve ended: "converged" or "stagnated" (with a warning); the others raise
    /// `ConvergenceError`.
    #[getter]
    fn status(&self) -> &'static str {
        self.report.solver.termination
    }
    /// Newton iterations of this solve.
    #[getter]
    fn iterations(&self) -> usize {
        self.report.solver.iterations
    }
    /// The largest residual of a force-controlled component over the load scale.
    #[getter]
    fn residual(&self) -> f64 {
        self.report.solver.residual
    }
    /// Results to treat with care (the report's `warnings`); empty when none applies.
    #[getter]
    fn warnings(&self) -> Vec<String> {
        self.report.warnings.clone()
    }
    /// The report as a JSON string, as `kontakt bearing CASE --json` writes it (compact).
    fn to_json(&self) -> PyResult<String> {
        serde_json::to_string(&self.report)
            .map_err(|e| pyo3::exceptions::PyRuntimeError::new_err(format!("report: {e}")))
    }
    /// The report as a dict with the keys of `kontakt bearing CASE --json`.
    fn to_dict<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        json_to_py(py, &self.report)
    }
    fn __repr__(&self) -> String {
        let r = &self.report;
        let u: Vec<String> = [
            r.displacement_mm[0],
            r.displacement_mm[1],
            r.displacement_mm[2],
            r.tilt_rad[0],
            r.tilt_rad[1],
        ]
        .iter()
        .map(|x| format!("{x:.6e}"))
        .collect();
        format!(
            "BearingResult(bearing_type={:?}, status={:?}, iterations={}, displacement=[{}], max_element_load_n={:.6}, warnings={:?})",
            r.bearing_type,
            r.solver.termination,
            r.solver.iterations,
            u.join(", "),
            max_load(r),
            r.warnings
        )
    }
}

/// The largest rolling-element load of a report, N.
fn max_load(r: &BearingReport) -> f64 {
    match &r.elements {
        BearingElements::Rollers(p) => p.max_roller_load_n,
        BearingElements::Balls(p) => p.max_ball_load_n,
    }
}
