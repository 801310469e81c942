//! The contact element for multi-body codes (`kontakt::element::ContactElement`), planned
//! from an element case (`method = "element"`, docs/mbs.md), as the C API does.

use crate::args;
use crate::errors::{invalid, to_py};
use kontakt::element::{ContactStatus, ElementResult as Result_};
use kontakt::geometry::Twist;
use nalgebra::{Isometry3, Matrix3, Quaternion, Rotation3, Translation3, UnitQuaternion, Vector3};
use numpy::PyArray1;
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyTuple};

/// A contact element: two surfaces on two bodies, planned once from an element case;
/// `evaluate` takes the bodies' poses and twists (world frame) and returns force, moments,
/// friction and status. mm, N, N·mm, mm/s, rad/s, MPa, mm², W.
#[pyclass(module = "kontakt._kontakt")]
pub struct ContactElement {
    inner: kontakt::element::ContactElement,
}

/// A pose from a 4×4 homogeneous matrix (rotation body → world, translation [mm]) or a
/// pair (translation (3,) [mm], unit quaternion (w, x, y, z)).
fn pose(v: &Bound<'_, PyAny>, name: &str) -> PyResult<Isometry3<f64>> {
    if let Ok(t) = v.cast::<PyTuple>()
        && t.len() == 2
    {
        let tr = vector::<3>(&t.get_item(0)?, &format!("{name}[0]"))?;
        let q = vector::<4>(&t.get_item(1)?, &format!("{name}[1]"))?;
        // Taken as given: the element refuses a non-unit quaternion, naming the pose.
        return Ok(Isometry3::from_parts(
            Translation3::new(tr[0], tr[1], tr[2]),
            UnitQuaternion::new_unchecked(Quaternion::new(q[0], q[1], q[2], q[3])),
        ));
    }
    let m = args::array(
        v,
        name,
        "a 4x4 homogeneous matrix or a tuple (translation (3,), quaternion (w, x, y, z))",
    )?;
    let m = m.as_array();
    if m.shape() != [4, 4] {
        return Err(invalid(
            &format!("{name}.shape"),
            args::shape(m.shape()),
            "(4, 4)",
        ));
    }
    if m.iter().any(|x| !x.is_finite()) {
        return Err(invalid(name, "a non-finite entry", "finite entries"));
    }
    let r = Matrix3::from_fn(|i, j| m[[i, j]]);
    let err = (r.transpose() * r - Matrix3::identity()).abs().max();
    let last = [m[[3, 0]], m[[3, 1]], m[[3, 2]], m[[3, 3]]];
    if err > 1e-9 || r.determinant() < 0.0 || last != [0.0, 0.0, 0.0, 1.0] {
        return Err(invalid(
            name,
            format!("a matrix with |RᵀR - I| = {err:.1e}, last row {last:?}"),
            "a rigid transform: orthonormal rotation (det +1, |RᵀR - I| <= 1e-9), last row (0, 0, 0, 1)",
        ));
    }
    let rotation = UnitQuaternion::from_rotation_matrix(&Rotation3::from_matrix_unchecked(r));
    Ok(Isometry3::from_parts(
        Translation3::new(m[[0, 3]], m[[1, 3]], m[[2, 3]]),
        rotation,
    ))
}

fn vector<const N: usize>(v: &Bound<'_, PyAny>, name: &str) -> PyResult<[f64; N]> {
    let a = args::array(v, name, &format!("{N} numbers"))?;
    let a = a.as_array();
    if a.ndim() != 1 || a.len() != N {
        return Err(invalid(
            &format!("{name}.shape"),
            args::shape(a.shape()),
            &format!("({N},)"),
        ));
    }
    let mut out = [0.0; N];
    for (o, x) in out.iter_mut().zip(a.iter()) {
        *o = *x;
    }
    Ok(out)
}

/// A twist from 6 numbers (v [mm/s], ω [rad/s]) or a pair (v (3,), ω (3,)); None: at rest.
fn twist(v: Option<&Bound<'_, PyAny>>, name: &str) -> PyResult<Twist> {
    let Some(v) = v else {
        return Ok(Twist::new(Vector3::zeros(), Vector3::zeros()));
    };
    if let Ok(t) = v.cast::<PyTuple>()
        && t.len() == 2
    {
        let l = vector::<3>(&t.get_item(0)?, &format!("{name}[0]"))?;
        let a = vector::<3>(&t.get_item(1)?, &format!("{name}[1]"))?;
        return Ok(Twist::new(Vector3::from(l), Vector3::from(a)));
    }
    let t = vector::<6>(v, name)?;
    Ok(Twist::new(
        Vector3::new(t[0], t[1], t[2]),
        Vector3::new(t[3], t[4], t[5]),
    ))
}

/// Plan an element from an element case's TOML text.
fn plan(text: &str) -> PyResult<ContactElement> {
    kontakt_case::element_from_toml(text)
        .map(|inner| ContactElement { inner })
        .map_err(to_py)
}

#[pymethods]
impl ContactElement {
    /// Plan an element from an element case as TOML text (`method = "element"`).
    #[staticmethod]
    fn from_toml(text: &Bound<'_, PyAny>) -> PyResult<Self> {
        plan(&args::text(text, "text", "an element case as TOML text")?)
    }

    /// Plan an element from an element case file.
    #[staticmethod]
    fn from_file(path: &Bound<'_, PyAny>) -> PyResult<Self> {
        let path = args::path(path, "path")?;
        let text = kontakt_case::read_case_file(&path).map_err(to_py)?;
        plan(&text)
    }

    /// Evaluate at the poses `pose1`, `pose2` (4×4 matrices, or (translation [mm],
    /// quaternion (w, x, y, z)) pairs; body → world) and twists `twist1`, `twist2` of the
    /// reference points (6 numbers v [mm/s], ω [rad/s], or (v, ω) pairs; None: at rest).
    /// The GIL is released during the evaluation.
    #[pyo3(signature = (pose1, pose2, twist1 = None, twist2 = None))]
    fn evaluate(
        &mut self,
        py: Python<'_>,
        pose1: &Bound<'_, PyAny>,
        pose2: &Bound<'_, PyAny>,
        twist1: Option<&Bound<'_, PyAny>>,
        twist2: Option<&Bound<'_, PyAny>>,
    ) -> PyResult<ElementResult> {
        let (p1, p2) = (pose(pose1, "pose1")?, pose(pose2, "pose2")?);
        let (t1, t2) = (twist(twist1, "twist1")?, twist(twist2, "twist2")?);
        let inner = &mut self.inner;
        let r = py
            .detach(|| inner.evaluate(&p1, &p2, &t1, &t2))
            .map_err(to_py)?;
        Ok(ElementResult { inner: r })
    }

    /// Forget the last contact point (the next evaluation searches from scratch).
    fn reset(&mut self) {
        self.inner.reset();
    }
}

/// What an evaluation returns (world frame): mm, N, N·mm, MPa, mm², W.
#[pyclass(frozen, module = "kontakt._kontakt")]
pub struct ElementResult {
    inner: Result_,
}

fn v3<'py>(py: Python<'py>, v: &Vector3<f64>) -> Bound<'py, PyArray1<f64>> {
    PyArray1::from_slice(py, v.as_slice())
}

#[pymethods]
impl ElementResult {
    /// "separated", "contact" or "out_of_validity".
    #[getter]
    fn status(&self) -> &'static str {
        match self.inner.status {
            ContactStatus::Separated => "separated",
            ContactStatus::Contact => "contact",
            ContactStatus::OutOfValidity => "out_of_validity",
        }
    }
    /// Signed separation [mm]: > 0 apart, < 0 overlapping.
    #[getter]
    fn separation(&self) -> f64 {
        self.inner.separation
    }
    /// Approach max(-separation, 0) [mm].
    #[getter]
    fn approach(&self) -> f64 {
        self.inner.approach
    }
    /// Contact point [mm], shape (3,).
    #[getter]
    fn point<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray1<f64>> {
        v3(py, &self.inner.point.coords)
    }
    /// Unit normal from body 2 into body 1, shape (3,).
    #[getter]
    fn normal<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray1<f64>> {
        v3(py, &self.inner.normal)
    }
    /// Elastic normal force [N].
    #[getter]
    fn normal_force(&self) -> f64 {
        self.inner.normal_force
    }
    /// Damping force along the normal [N].
    #[getter]
    fn damping_force(&self) -> f64 {
        self.inner.damping_force
    }
    /// Friction force on body 1 [N], shape (3,).
    #[getter]
    fn friction_force<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray1<f64>> {
        v3(py, &self.inner.friction_force)
    }
    /// Moment of the friction stresses on body 1 about the contact point [N·mm], shape
    /// (3,), along the normal (the spin friction torque).
    #[getter]
    fn friction_moment<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray1<f64>> {
        v3(py, &self.inner.friction_moment)
    }
    /// Friction power [W].
    #[getter]
    fn friction_power(&self) -> f64 {
        self.inner.friction_power
    }
    /// Total force on body 1 [N], shape (3,); body 2 gets minus this.
    #[getter]
    fn force1<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray1<f64>> {
        v3(py, &self.inner.force1)
    }
    /// Moment on body 1 about its reference point [N·mm], shape (3,).
    #[getter]
    fn moment1<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray1<f64>> {
        v3(py, &self.inner.moment1)
    }
    /// Moment on body 2 about its reference point [N·mm], shape (3,).
    #[getter]
    fn moment2<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray1<f64>> {
        v3(py, &self.inner.moment2)
    }
    /// Largest pressure [MPa].
    #[getter]
    fn max_pressure(&self) -> f64 {
        self.inner.max_pressure
    }
    /// Contact area [mm²].
    #[getter]
    fn contact_area(&self) -> f64 {
        self.inner.contact_area
    }
    /// Iterations of the back-end's solver (0 for Hertz).
    #[getter]
    fn iterations(&self) -> usize {
        self.inner.iterations
    }
    /// Why the status is out of validity (empty otherwise).
    #[getter]
    fn message(&self) -> &str {
        &self.inner.message
    }
    /// Every field, keys with unit suffixes (vectors as lists).
    fn to_dict<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyDict>> {
        let r = &self.inner;
        let v = |x: &Vector3<f64>| vec![x.x, x.y, x.z];
        let d = PyDict::new(py);
        d.set_item("status", self.status())?;
        d.set_item("separation_mm", r.separation)?;
        d.set_item("approach_mm", r.approach)?;
        d.set_item("point_mm", v(&r.point.coords))?;
        d.set_item("normal", v(&r.normal))?;
        d.set_item("normal_force_n", r.normal_force)?;
        d.set_item("damping_force_n", r.damping_force)?;
        d.set_item("friction_force_n", v(&r.friction_force))?;
        d.set_item("friction_moment_nmm", v(&r.friction_moment))?;
        d.set_item("friction_power_w", r.friction_power)?;
        d.set_item("force1_n", v(&r.force1))?;
        d.set_item("moment1_nmm", v(&r.moment1))?;
        d.set_item("moment2_nmm", v(&r.moment2))?;
        d.set_item("max_pressure_mpa", r.max_pressure)?;
        d.set_item("contact_area_mm2", r.contact_area)?;
        d.set_item("iterations", r.iterations)?;
        d.set_item("message", &r.message)?;
        Ok(d)
    }
    fn __repr__(&self) -> String {
        format!(
            "ElementResult(status={:?}, approach={:.6e} mm, normal_force={:.6} N)",
            self.status(),
            self.inner.approach,
            self.inner.normal_force
        )
    }
}
