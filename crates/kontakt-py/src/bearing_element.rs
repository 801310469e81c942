//! A whole bearing as one force element of a multi-body code
//! (`kontakt_case::BearingElement`, docs/mbs.md): the inner ring's displacement and
//! velocity relative to the outer ring in, the bearing's reaction on the inner ring and its
//! 5 × 5 stiffness out. Planned once from a bearing case like `kontakt.Bearing`; each
//! evaluation releases the GIL. A thin layer: no physics here.

use crate::args;
use crate::bearing::plan;
use crate::errors::to_py;
use kontakt_case::bearing_model::BearingElement as Element;
use kontakt_case::bearing_model::{
    BearingElementOutput, BearingElementStatus, ElementFrictionStatus,
};
use numpy::ndarray::Array2;
use numpy::{IntoPyArray, PyArray1, PyArray2, PyArrayMethods};
use pyo3::prelude::*;
use pyo3::types::PyDict;

/// A whole rolling bearing as one force element between a shaft (the inner ring) and a
/// housing (the outer ring), planned once from a bearing case (`method = "bearing"`; a
/// dict, TOML text or a path, as `kontakt.Bearing` takes it; `[load]` optional and not
/// used). `evaluate(displacement, velocity)` gives the bearing's reaction on the inner ring
/// at the inner ring's displacement relative to the outer ring, in the bearing frame (z the
/// axis): mm, rad, mm/s, rad/s in; N, N·mm, N/mm, N/rad, N, N·mm/rad out.
#[pyclass(module = "kontakt._kontakt")]
pub struct BearingElement {
    inner: Element,
}

#[pymethods]
impl BearingElement {
    #[new]
    #[pyo3(signature = (case, damping_s = None))]
    fn new(case: &Bound<'_, PyAny>, damping_s: Option<&Bound<'_, PyAny>>) -> PyResult<Self> {
        let mut inner = Element::new(plan(case, "kontakt.BearingElement")?).map_err(to_py)?;
        let valid = "a finite damping coefficient beta >= 0 s (the damping matrix is beta times the stiffness)";
        if let Some(b) = args::opt_real(damping_s, "damping_s", valid)? {
            inner.set_damping(b).map_err(to_py)?;
        }
        Ok(BearingElement { inner })
    }

    /// The bearing type of the case: "cylindrical", "tapered", "thrust",
    /// "deep_groove_ball" or "angular_contact_ball".
    #[getter]
    fn bearing_type(&self) -> &'static str {
        self.inner.model().bearing_type()
    }

    /// The damping coefficient β [s]: the damping matrix is β K(u) (default 0, undamped).
    #[getter]
    fn get_damping_s(&self) -> f64 {
        self.inner.damping_s()
    }

    #[setter]
    fn set_damping_s(&mut self, value: &Bound<'_, PyAny>) -> PyResult<()> {
        let valid = "a finite damping coefficient beta >= 0 s (the damping matrix is beta times the stiffness)";
        let b = args::real(value, "damping_s", valid)?;
        self.inner.set_damping(b).map_err(to_py)
    }

    /// The reaction of the bearing on the inner ring at `displacement` = (δx, δy, δz [mm],
    /// θx, θy [rad]) of the inner ring relative to the outer ring and its rate `velocity`
    /// [mm/s, rad/s] (None: at rest), in the bearing frame. The GIL is released.
    #[pyo3(signature = (displacement, velocity = None))]
    fn evaluate(
        &mut self,
        py: Python<'_>,
        displacement: &Bound<'_, PyAny>,
        velocity: Option<&Bound<'_, PyAny>>,
    ) -> PyResult<BearingElementResult> {
        let u = five(
            displacement,
            "displacement",
            "finite numbers (dx, dy, dz [mm], tilt_x, tilt_y [rad])",
        )?;
        let v = args::given(velocity)
            .map(|v| {
                five(
                    v,
                    "velocity",
                    "finite numbers (vx, vy, vz [mm/s], tilt rates [rad/s])",
                )
            })
            .transpose()?
            .unwrap_or_default();
        let element = &mut self.inner;
        let out = py.detach(|| element.evaluate(u, v)).map_err(to_py)?;
        Ok(BearingElementResult { out })
    }

    /// Set the ring speeds `inner_rad_s`, `outer_rad_s` [rad/s about +z] of the friction
    /// torque (a lubricated case; they start at the case's `[speed]`). They change the
    /// friction only, not the load distribution. Equal speeds give the starting torque.
    fn set_speeds(
        &mut self,
        inner_rad_s: &Bound<'_, PyAny>,
        outer_rad_s: &Bound<'_, PyAny>,
    ) -> PyResult<()> {
        let valid = "a finite ring speed in rad/s, |omega| <= 100000 r/min";
        let wi = args::real(inner_rad_s, "inner_rad_s", valid)?;
        let wo = args::real(outer_rad_s, "outer_rad_s", valid)?;
        self.inner.set_speeds(wi, wo).map_err(to_py)
    }

    /// Forget the last evaluation's warm start.
    fn reset(&mut self) {
        self.inner.reset();
    }

    fn __repr__(&self) -> String {
        format!(
            "BearingElement(bearing_type={:?}, damping_s={})",
            self.inner.model().bearing_type(),
            self.inner.damping_s()
        )
    }
}

/// Five real numbers: a float64 array of shape (5,) read directly (the per-step call of a
/// multi-body code), anything else through `args::reals`, which names the argument.
fn five(v: &Bound<'_, PyAny>, name: &str, valid: &str) -> PyResult<[f64; 5]> {
    if let Ok(a) = v.cast::<PyArray1<f64>>()
        && let Ok(r) = a.try_readonly()
        && let Ok(&[a0, a1, a2, a3, a4]) = r.as_slice()
    {
        return Ok([a0, a1, a2, a3, a4]);
    }
    args::reals::<5>(v, name, valid)
}

/// One evaluation of a `BearingElement`: the bearing's reaction on the inner ring (bearing
/// frame; the outer ring gets minus it) and the stiffness.
#[pyclass(frozen, module = "kontakt._kontakt")]
pub struct BearingElementResult {
    out: BearingElementOutput,
}

#[pymethods]
impl BearingElementResult {
    /// "loaded" or "lifted_off" (every rolling element off the inner ring: zero force and
    /// stiffness).
    #[getter]
    fn status(&self) -> &'static str {
        match self.out.status {
            BearingElementStatus::Loaded => "loaded",
            BearingElementStatus::LiftedOff => "lifted_off",
        }
    }
    /// Force on the inner ring (Fx, Fy, Fz) [N], elastic plus damping, shape (3,).
    #[getter]
    fn force<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray1<f64>> {
        PyArray1::from_slice(py, &self.out.force_n)
    }
    /// Moment on the inner ring about the bearing centre (Mx, My, Mz) [N·mm], shape (3,);
    /// Mz is the friction moment `friction_inner_ring_nmm` (0 without a lubricant).
    #[getter]
    fn moment<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray1<f64>> {
        PyArray1::from_slice(py, &self.out.moment_nmm)
    }
    /// The damping part −β K v of the reaction (Fx, Fy, Fz [N], Mx, My [N·mm]), shape (5,).
    #[getter]
    fn damping<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray1<f64>> {
        PyArray1::from_slice(py, &self.out.damping)
    }
    /// The stiffness K = ∂(load carried)/∂(displacement) = −∂(reaction)/∂(displacement),
    /// shape (5, 5), rows and columns (x, y, z, θx, θy): N/mm, N/rad, N, N·mm/rad.
    #[getter]
    fn stiffness<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray2<f64>> {
        let k = &self.out.stiffness;
        Array2::from_shape_fn((5, 5), |(i, j)| k[i][j]).into_pyarray(py)
    }
    /// The largest rolling-element load [N].
    #[getter]
    fn max_element_load_n(&self) -> f64 {
        self.out.max_element_load_n
    }
    /// Newton iterations of the evaluation (0: every degree of freedom is prescribed).
    #[getter]
    fn iterations(&self) -> usize {
        self.out.iterations
    }
    /// Why the status is what it is; empty when loaded.
    #[getter]
    fn message(&self) -> &'static str {
        self.out.message
    }
    /// The friction model's status: "off" (no `[lubricant]` in the case), "running",
    /// "starting" (equal ring speeds: `friction_torque_nmm` is the starting torque, not
    /// applied) or "not_built" (no friction model for this bearing type yet).
    #[getter]
    fn friction_status(&self) -> &'static str {
        match self.out.friction.status {
            ElementFrictionStatus::Off => "off",
            ElementFrictionStatus::Running => "running",
            ElementFrictionStatus::Starting => "starting",
            ElementFrictionStatus::NotBuilt => "not_built",
        }
    }
    /// The bearing's friction torque M >= 0 [N·mm] (running, or the starting torque).
    #[getter]
    fn friction_torque_nmm(&self) -> f64 {
        self.out.friction.torque_nmm
    }
    /// The friction moment on the inner ring about +z, -M sign(ω_i - ω_o) [N·mm] (= Mz).
    #[getter]
    fn friction_inner_ring_nmm(&self) -> f64 {
        self.out.friction.inner_ring_nmm
    }
    /// The friction power M |ω_i - ω_o| [W].
    #[getter]
    fn friction_power_w(&self) -> f64 {
        self.out.friction.power_w
    }
    /// The ring speeds (ω_i, ω_o) [rad/s] the friction used, shape (2,).
    #[getter]
    fn ring_speeds<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray1<f64>> {
        let f = &self.out.friction;
        PyArray1::from_slice(py, &[f.inner_speed_rad_s, f.outer_speed_rad_s])
    }
    /// The torque's shares (cone, cup, rib, drag) [N·mm], shape (4,), summing to
    /// `friction_torque_nmm`.
    #[getter]
    fn friction_breakdown<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray1<f64>> {
        let f = &self.out.friction;
        PyArray1::from_slice(py, &[f.cone_nmm, f.cup_nmm, f.rib_nmm, f.drag_nmm])
    }
    /// Every field, keys with unit suffixes (arrays as lists).
    fn to_dict<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyDict>> {
        let o = &self.out;
        let d = PyDict::new(py);
        d.set_item("status", self.status())?;
        d.set_item("force_n", o.force_n.to_vec())?;
        d.set_item("moment_nmm", o.moment_nmm.to_vec())?;
        d.set_item("damping", o.damping.to_vec())?;
        d.set_item(
            "stiffness",
            o.stiffness.iter().map(|r| r.to_vec()).collect::<Vec<_>>(),
        )?;
        d.set_item("max_element_load_n", o.max_element_load_n)?;
        d.set_item("iterations", o.iterations)?;
        d.set_item("message", o.message)?;
        let f = &o.friction;
        d.set_item("friction_status", self.friction_status())?;
        d.set_item("friction_torque_nmm", f.torque_nmm)?;
        d.set_item("friction_inner_ring_nmm", f.inner_ring_nmm)?;
        d.set_item("friction_power_w", f.power_w)?;
        d.set_item(
            "ring_speeds_rad_s",
            vec![f.inner_speed_rad_s, f.outer_speed_rad_s],
        )?;
        d.set_item(
            "friction_breakdown_nmm",
            vec![f.cone_nmm, f.cup_nmm, f.rib_nmm, f.drag_nmm],
        )?;
        Ok(d)
    }
    fn __repr__(&self) -> String {
        let f = self.out.force_n;
        let m = self.out.moment_nmm;
        format!(
            "BearingElementResult(status={:?}, force=[{:.6e}, {:.6e}, {:.6e}], moment=[{:.6e}, {:.6e}, {:.6e}], max_element_load_n={:.6})",
            self.status(),
            f[0],
            f[1],
            f[2],
            m[0],
            m[1],
            m[2],
            self.out.max_element_load_n
        )
    }
}
