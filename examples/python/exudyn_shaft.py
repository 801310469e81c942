"""A rigid shaft on two kontakt bearings in Exudyn (docs/exudyn.md).

Two 7205-class angular-contact ball bearings (examples/bearing_7205.toml) in an O
arrangement (back to back), axially preloaded, carry a rigid shaft. Exudyn (Gerstmayr
2024, an independent multibody code) integrates the shaft; kontakt's
`kontakt.BearingElement` gives each bearing's reaction and stiffness at the shaft's
pose. The shaft runs up to speed under a load step.

Units: Exudyn works in SI (m, kg, s, N, N·m); the bearing element in mm, N, N·mm, rad.
The conversions are in `bearing_inputs` and `bearing_loads` and nowhere else.

Frames (housing frame = Exudyn's global frame at the reference): the shaft axis is z,
bearing 1 sits at z = -span/2, bearing 2 at z = +span/2. Bearing i's own frame (z its
axis, +z pushing its inner ring into its outer ring) is the global frame turned by C_i:
C_1 = identity, C_2 = a half turn about x (x' = x, y' = -y, z' = -z), the mirror image
that makes the pair an O arrangement. The inner ring's displacement in bearing i's frame:

    d_i  = C_i^T (p + R r_i - r_i) + (0, 0, preload)      translation, mm
    b_i  = C_i^T R C_i e_z                                 the inner ring's axis
    θx_i = -b_i,y,  θy_i = b_i,x                           tilts, rad

with p the shaft's position, R its rotation, r_i = (0, 0, z_i) the bearing centre on the
shaft axis. The spin about the axis drops out (b_i does not see it). The bearing's
reaction (F', Mx', My') on the inner ring acts on the shaft as the force C_i F' at the
bearing centre and the torque C_i (Mx' b_z, My' b_z, -Mx' b_x - My' b_y): the virtual
work of these on any virtual motion of the shaft is exactly F'·δd + Mx' δθx + My' δθy,
so the coupling is conservative whenever the element is (its stiffness is symmetric).

Run: python examples/python/exudyn_shaft.py  (needs `pip install exudyn==1.13.6 kontakt`)
"""

from __future__ import annotations

import math
import pathlib
from dataclasses import dataclass, field

import numpy as np

import kontakt as kt

HERE = pathlib.Path(__file__).resolve().parent
CASE = HERE.parent / "bearing_7205.toml"

# The two bearings' frames: bearing 2 mirrored by a half turn about x.
C = (np.eye(3), np.diag([1.0, -1.0, -1.0]))


@dataclass
class Shaft:
    """The shaft, its bearings and its load (SI unless the name says mm)."""

    mass_kg: float = 3.0
    inertia_transverse_kgm2: float = 0.01  # about x and y through the centre of mass
    inertia_polar_kgm2: float = 0.002  # about the shaft axis z
    span_mm: float = 100.0  # distance between the bearing centres
    preload_mm: float = 0.008  # axial preload displacement of each inner ring
    load_point_mm: float = 30.0  # z of the gear mesh on the shaft (from mid-span)
    load_n: tuple[float, float, float] = (1500.0, -400.0, 300.0)  # the load after the step
    damping_s: float = 0.0  # the bearings' stiffness-proportional damping β
    case: pathlib.Path = CASE
    elements: list = field(default_factory=list)

    def __post_init__(self) -> None:
        self.elements = [kt.BearingElement(self.case), kt.BearingElement(self.case)]
        for e in self.elements:
            e.damping_s = self.damping_s

    @property
    def z_mm(self) -> tuple[float, float]:
        """The bearing centres on the shaft axis, mm from the centre of mass."""
        return (-0.5 * self.span_mm, 0.5 * self.span_mm)


def rotation_xyz(alpha: float, beta: float, gamma: float = 0.0) -> np.ndarray:
    """R = Rx(α) Ry(β) Rz(γ), Exudyn's Tait-Bryan xyz angles (NodeRigidBodyRxyz)."""
    ca, sa, cb, sb, cg, sg = (
        math.cos(alpha),
        math.sin(alpha),
        math.cos(beta),
        math.sin(beta),
        math.cos(gamma),
        math.sin(gamma),
    )
    rx = np.array([[1, 0, 0], [0, ca, -sa], [0, sa, ca]])
    ry = np.array([[cb, 0, sb], [0, 1, 0], [-sb, 0, cb]])
    rz = np.array([[cg, -sg, 0], [sg, cg, 0], [0, 0, 1]])
    return rx @ ry @ rz


def cross(a, b) -> np.ndarray:
    """a × b of two 3-vectors (numpy's `cross` costs more than the bearing element)."""
    return np.array(
        [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]
    )


def bearing_inputs(shaft: Shaft, i: int, p_m, R, v_m, omega):
    """Bearing i's displacement (mm, rad) and velocity (mm/s, rad/s) in its own frame from
    the shaft's position p [m], rotation R, velocity v [m/s] and angular velocity ω
    [rad/s] (all global); also the inner ring's axis b in the bearing frame."""
    Ci = C[i]
    r = np.array([0.0, 0.0, shaft.z_mm[i]])
    Rr = R @ r
    d = Ci.T @ (1000.0 * np.asarray(p_m) + Rr - r)
    d[2] += shaft.preload_mm
    b = Ci.T @ R @ Ci[:, 2]
    u = np.array([d[0], d[1], d[2], -b[1], b[0]])
    # rates: ḋ = C^T (v + ω × R r), ḃ = C^T (ω × R C e_z)
    dd = Ci.T @ (1000.0 * np.asarray(v_m) + cross(omega, Rr))
    db = Ci.T @ cross(omega, R @ Ci[:, 2])
    ud = np.array([dd[0], dd[1], dd[2], -db[1], db[0]])
    return u, ud, b


def bearing_loads(res, i: int, b) -> tuple[np.ndarray, np.ndarray]:
    """The force [N] at bearing i's centre and the torque [N·m] on the shaft (global) from
    the element's reaction `res` (N, N·mm, bearing i's frame) and the ring's axis b."""
    f = res.force
    m = res.moment * 1e-3
    t_local = np.array([m[0] * b[2], m[1] * b[2], -m[0] * b[0] - m[1] * b[1]])
    return C[i] @ f, C[i] @ t_local


# --- the reference: the shaft's static equilibrium without Exudyn -------------------------


def shaft_kinematics(shaft: Shaft, q_mm: np.ndarray, i: int):
    """Bearing i's displacement u (5,) and its Jacobian ∂u/∂q (5×5) at the shaft's pose
    q = (x, y, z [mm], α, β [rad]) (R = Rx(α) Ry(β), no spin)."""
    x, y, z, al, be = q_mm
    ca, sa, cb, sb = math.cos(al), math.sin(al), math.cos(be), math.sin(be)
    a = np.array([sb, -sa * cb, ca * cb])  # the shaft axis R e_z
    a_al = np.array([0.0, -ca * cb, -sa * cb])
    a_be = np.array([cb, sa * sb, -ca * sb])
    zi = shaft.z_mm[i]
    Ci = C[i]
    d = Ci.T @ (np.array([x, y, z]) + zi * a - np.array([0.0, 0.0, zi]))
    d[2] += shaft.preload_mm
    s = Ci[2, 2]  # b = C^T R C e_z = s C^T a (C e_z = s e_z)
    b = s * (Ci.T @ a)
    u = np.array([d[0], d[1], d[2], -b[1], b[0]])
    J = np.zeros((5, 5))
    J[:3, :3] = Ci.T
    J[:3, 3] = zi * (Ci.T @ a_al)
    J[:3, 4] = zi * (Ci.T @ a_be)
    for k, da in ((3, a_al), (4, a_be)):
        db = s * (Ci.T @ da)
        J[3, k] = -db[1]
        J[4, k] = db[0]
    return u, J


def load_jacobian(shaft: Shaft, q_mm: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """The load point's position p + R r_F [mm] and its Jacobian ∂/∂q (3×5)."""
    x, y, z, al, be = q_mm
    ca, sa, cb, sb = math.cos(al), math.sin(al), math.cos(be), math.sin(be)
    zf = shaft.load_point_mm
    pos = np.array([x, y, z]) + zf * np.array([sb, -sa * cb, ca * cb])
    J = np.zeros((3, 5))
    J[:, :3] = np.eye(3)
    J[:, 3] = zf * np.array([0.0, -ca * cb, -sa * cb])
    J[:, 4] = zf * np.array([cb, sa * sb, -ca * sb])
    return pos, J


def reference_equilibrium(shaft: Shaft, load_n, tol: float = 1e-13, q0=None):
    """The shaft's static equilibrium under `load_n` at the load point, by Newton on its
    five degrees of freedom with kontakt's bearing elements (their reactions and
    stiffnesses) and the kinematics of `shaft_kinematics`. Returns q (mm, rad), the
    shaft's stiffness matrix ∂(-residual)/∂q (N/mm, ...) and the iterations."""
    elements = [kt.BearingElement(shaft.case), kt.BearingElement(shaft.case)]
    q = np.zeros(5) if q0 is None else np.array(q0, dtype=float)
    load = np.asarray(load_n, dtype=float)
    for it in range(100):
        g = np.zeros(5)
        K = np.zeros((5, 5))
        for i, e in enumerate(elements):
            u, J = shaft_kinematics(shaft, q, i)
            r = e.evaluate(u)
            g += J.T @ np.concatenate([r.force, r.moment[:2]])
            K += J.T @ r.stiffness @ J
        _, JF = load_jacobian(shaft, q)
        g += JF.T @ load
        step = np.linalg.solve(K, g)
        q += step
        scale = np.array([1.0, 1.0, 1.0, shaft.span_mm, shaft.span_mm])
        if np.max(np.abs(step * scale)) < tol:
            return q, K, it + 1
    raise RuntimeError("the reference Newton did not converge")


def shaft_stiffness(shaft: Shaft, q_mm: np.ndarray, load_n) -> np.ndarray:
    """The shaft's stiffness at q: Σ Jᵢᵀ Kᵢ Jᵢ from kontakt's bearing stiffness matrices,
    plus the geometric part (the bearings' and the load's forces times the curvature of
    the kinematics, by central differences of the Jacobians)."""
    elements = [kt.BearingElement(shaft.case), kt.BearingElement(shaft.case)]
    K = np.zeros((5, 5))
    h = 1e-6
    for i, e in enumerate(elements):
        u, J = shaft_kinematics(shaft, q_mm, i)
        r = e.evaluate(u)
        K += J.T @ r.stiffness @ J
        reaction = np.concatenate([r.force, r.moment[:2]])
        for k in (3, 4):
            dq = np.zeros(5)
            dq[k] = h
            Jp = shaft_kinematics(shaft, q_mm + dq, i)[1]
            Jm = shaft_kinematics(shaft, q_mm - dq, i)[1]
            K[:, k] -= (Jp - Jm).T @ reaction / (2 * h)
    for k in (3, 4):
        dq = np.zeros(5)
        dq[k] = h
        Jp = load_jacobian(shaft, q_mm + dq)[1]
        Jm = load_jacobian(shaft, q_mm - dq)[1]
        K[:, k] -= (Jp - Jm).T @ np.asarray(load_n) / (2 * h)
    return K


def mass_matrix(shaft: Shaft) -> np.ndarray:
    """The shaft's mass matrix in q = (x, y, z [mm], α, β [rad]) at small angles: t and
    t·mm² (so that K [N/mm] / M gives 1/s²)."""
    m = shaft.mass_kg * 1e-3
    j = shaft.inertia_transverse_kgm2 * 1e3
    return np.diag([m, m, m, j, j])


# --- the Exudyn model ---------------------------------------------------------------------


@dataclass
class Run:
    """What `simulate` returns: time [s] and the shaft's coordinates (x, y, z [m], α, β,
    γ [rad]) and their rates, one row per stored step."""

    t: np.ndarray
    q: np.ndarray
    qd: np.ndarray
    evaluations: int


def build(shaft: Shaft, load=None, q0=None, v0=None, motor=None):
    """An Exudyn system of the shaft on its two bearings. `load(t)` gives the load at the
    load point [N] (global), `motor(t)` the drive torque about the shaft axis [N·m];
    `q0`, `v0`: the node's initial coordinates and rates (SI; Tait-Bryan xyz angles)."""
    import exudyn as exu
    from exudyn.itemInterface import (
        LoadForceVector,
        LoadTorqueVector,
        MarkerBodyRigid,
        NodeRigidBodyRxyz,
        ObjectRigidBody,
    )

    SC = exu.SystemContainer()
    mbs = SC.AddSystem()
    jt, jp = shaft.inertia_transverse_kgm2, shaft.inertia_polar_kgm2
    node = mbs.AddNode(
        NodeRigidBodyRxyz(
            referenceCoordinates=[0.0] * 6,
            initialCoordinates=list(q0) if q0 is not None else [0.0] * 6,
            initialVelocities=list(v0) if v0 is not None else [0.0] * 6,
        )
    )
    body = mbs.AddObject(
        ObjectRigidBody(
            mass=shaft.mass_kg, inertia=[jt, jt, jp, 0.0, 0.0, 0.0], nodeNumber=node
        )
    )
    state = {"key": None, "loads": None, "evaluations": 0}
    current = exu.ConfigurationType.Current

    def bearings():
        """Both bearings' loads at the current state, evaluated once per state."""
        q = mbs.systemData.GetODE2Coordinates(configuration=current)
        qd = mbs.systemData.GetODE2Coordinates_t(configuration=current)
        key = (tuple(q), tuple(qd))
        if key != state["key"]:
            # the shaft is the system's only node with coordinates: (x, y, z, α, β, γ)
            p, R = q[:3], rotation_xyz(q[3], q[4], q[5])
            v, w = qd[:3], angular_velocity(q, qd)
            out = []
            for i, e in enumerate(shaft.elements):
                u, ud, b = bearing_inputs(shaft, i, p, R, v, w)
                out.append(bearing_loads(e.evaluate(u, ud), i, b))
                state["evaluations"] += 1
            state["key"], state["loads"] = key, out
        return state["loads"]

    for i in range(2):
        marker = mbs.AddMarker(
            MarkerBodyRigid(bodyNumber=body, localPosition=[0.0, 0.0, 1e-3 * shaft.z_mm[i]])
        )
        mbs.AddLoad(
            LoadForceVector(
                markerNumber=marker,
                loadVectorUserFunction=lambda mbs_, t, lv, i=i: list(bearings()[i][0]),
            )
        )
        mbs.AddLoad(
            LoadTorqueVector(
                markerNumber=marker,
                loadVectorUserFunction=lambda mbs_, t, lv, i=i: list(bearings()[i][1]),
            )
        )
    load_marker = mbs.AddMarker(
        MarkerBodyRigid(bodyNumber=body, localPosition=[0.0, 0.0, 1e-3 * shaft.load_point_mm])
    )
    if load is not None:
        mbs.AddLoad(
            LoadForceVector(
                markerNumber=load_marker,
                loadVectorUserFunction=lambda mbs_, t, lv: list(load(t)),
            )
        )
    if motor is not None:
        # about the body's own axis: bodyFixed torque (0, 0, M)
        mbs.AddLoad(
            LoadTorqueVector(
                markerNumber=load_marker,
                bodyFixed=True,
                loadVectorUserFunction=lambda mbs_, t, lv: [0.0, 0.0, motor(t)],
            )
        )
    mbs.Assemble()
    return SC, mbs, node, state


def quiet_settings():
    """Exudyn's simulation settings without console output or files."""
    import exudyn as exu

    s = exu.SimulationSettings()
    s.show.computationTime = False
    s.show.statistics = False
    s.linearSolver.solverType = exu.LinearSolverType.EXUdense
    s.staticSolver.verboseMode = 0
    s.timeIntegration.verboseMode = 0
    s.solution.file.write = False
    s.solution.sensors.writePeriod = 0.0  # every step
    return s


def simulate(shaft: Shaft, end_s: float, step_s: float, load=None, q0=None, v0=None, motor=None, solver="RK44") -> Run:
    """Integrate the shaft with Exudyn's explicit solver `solver` (fixed step `step_s` [s])
    from the initial state (q0, v0) (SI, Tait-Bryan xyz angles) to `end_s`; every step is
    stored."""
    import exudyn as exu
    from exudyn.itemInterface import SensorNode

    SC, mbs, node, state = build(shaft, load=load, q0=q0, v0=v0, motor=motor)
    sq = mbs.AddSensor(SensorNode(nodeNumber=node, storeInternal=True, outputVariableType=exu.OutputVariableType.Coordinates))
    sv = mbs.AddSensor(SensorNode(nodeNumber=node, storeInternal=True, outputVariableType=exu.OutputVariableType.Coordinates_t))
    mbs.Assemble()
    s = quiet_settings()
    s.timeIntegration.endTime = end_s
    s.timeIntegration.numberOfSteps = int(round(end_s / step_s))
    s.timeIntegration.automaticStepSize = False
    s.timeIntegration.verboseMode = 0
    exu.SolveDynamic(mbs, s, solverType=getattr(exu.DynamicSolverType, solver))
    q = np.asarray(mbs.GetSensorStoredData(sq))
    qd = np.asarray(mbs.GetSensorStoredData(sv))
    return Run(t=q[:, 0], q=q[:, 1:], qd=qd[:, 1:], evaluations=state["evaluations"])


def solve_static(shaft: Shaft, load_n, tol: float = 1e-12) -> np.ndarray:
    """The shaft's equilibrium under a constant load from Exudyn's static solver, as
    q = (x, y, z [mm], α, β [rad]). The spin γ, on which no force depends, is held by a
    coordinate constraint (its reaction is zero)."""
    import exudyn as exu
    from exudyn.itemInterface import CoordinateConstraint, MarkerNodeCoordinate, NodePointGround

    SC, mbs, node, state = build(shaft, load=lambda t: load_n)
    ground = mbs.AddNode(NodePointGround())
    mg = mbs.AddMarker(MarkerNodeCoordinate(nodeNumber=ground, coordinate=0))
    ms = mbs.AddMarker(MarkerNodeCoordinate(nodeNumber=node, coordinate=5))
    mbs.AddObject(CoordinateConstraint(markerNumbers=[mg, ms]))
    mbs.Assemble()
    s = quiet_settings()
    s.staticSolver.newton.relativeTolerance = tol
    s.staticSolver.newton.absoluteTolerance = tol
    s.staticSolver.newton.useModifiedNewton = False
    # the bearings' stiffness enters the static solver's Jacobian through the user loads
    # (numerical differentiation of the loads; Exudyn's default for the static solver)
    s.staticSolver.computeLoadsJacobian = True
    s.staticSolver.newton.maxIterations = 50
    s.staticSolver.numberOfLoadSteps = 1
    exu.SolveStatic(mbs, s)
    q = mbs.systemData.GetODE2Coordinates()
    return np.array([1e3 * q[0], 1e3 * q[1], 1e3 * q[2], q[3], q[4]])


def angular_velocity(q, qd) -> np.ndarray:
    """The angular velocity [rad/s] (global) from Tait-Bryan xyz angles and rates:
    ω = α̇ e_x + β̇ Rx(α) e_y + γ̇ Rx(α) Ry(β) e_z."""
    al, be = q[3], q[4]
    ex = np.array([1.0, 0.0, 0.0])
    ey = rotation_xyz(al, 0.0) @ np.array([0.0, 1.0, 0.0])
    ez = rotation_xyz(al, be) @ np.array([0.0, 0.0, 1.0])
    return qd[3] * ex + qd[4] * ey + qd[5] * ez


def energy(shaft: Shaft, run: Run, load_n, gauss_points: int = 16) -> np.ndarray:
    """The change of the shaft's mechanical energy since the first stored step [J]:
    kinetic energy, plus the bearings' elastic energy (minus the work of each element's
    reaction along the straight path in its u from the first step's u, Gauss-Legendre
    quadrature; the path does not matter for a conservative element), minus the work of
    the constant load at the load point."""
    elements = [kt.BearingElement(shaft.case), kt.BearingElement(shaft.case)]
    s, w = np.polynomial.legendre.leggauss(gauss_points)
    s, w = 0.5 * (s + 1.0), 0.5 * w
    jt, jp = shaft.inertia_transverse_kgm2, shaft.inertia_polar_kgm2
    zero = np.zeros(3)
    u0 = None
    xf0 = None
    out = np.zeros(len(run.t))
    for n, (q, qd) in enumerate(zip(run.q, run.qd)):
        R = rotation_xyz(q[3], q[4], q[5])
        wb = R.T @ angular_velocity(q, qd)
        kinetic = 0.5 * shaft.mass_kg * qd[:3] @ qd[:3] + 0.5 * (jt * wb[0] ** 2 + jt * wb[1] ** 2 + jp * wb[2] ** 2)
        us = [bearing_inputs(shaft, i, q[:3], R, zero, zero)[0] for i in range(2)]
        xf = 1e3 * q[:3] + R @ np.array([0.0, 0.0, shaft.load_point_mm])
        if u0 is None:
            u0, xf0 = us, xf
        elastic = 0.0  # N·mm
        for i, e in enumerate(elements):
            du = us[i] - u0[i]
            for sk, wk in zip(s, w):
                r = e.evaluate(u0[i] + sk * du)
                elastic -= wk * (np.concatenate([r.force, r.moment[:2]]) @ du)
        out[n] = kinetic + 1e-3 * (elastic - np.asarray(load_n) @ (xf - xf0))
    return out - out[0]


def to_q0(q_mm, spin: float = 0.0) -> list[float]:
    """Exudyn's node coordinates (SI, Tait-Bryan xyz) of the pose q (mm, rad), spin γ."""
    return [1e-3 * q_mm[0], 1e-3 * q_mm[1], 1e-3 * q_mm[2], q_mm[3], q_mm[4], spin]


def to_q_mm(q) -> np.ndarray:
    """The pose (x, y, z [mm], α, β [rad]) of Exudyn's node coordinates (rows or one)."""
    q = np.asarray(q)
    return np.concatenate([1e3 * q[..., :3], q[..., 3:5]], axis=-1)


def modes(shaft: Shaft, q_mm, load_n):
    """The shaft's natural frequencies [Hz] at rest on its bearings from kontakt's stiffness
    matrices (`shaft_stiffness`) and the mass matrix, ascending, with the mode shapes as
    columns."""
    lam, vec = np.linalg.eig(np.linalg.solve(mass_matrix(shaft), shaft_stiffness(shaft, q_mm, load_n)))
    order = np.argsort(lam.real)
    return np.sqrt(lam.real[order]) / (2 * np.pi), vec.real[:, order]


def measured_frequency(run: Run, q_eq_mm, left_vector) -> float:
    """The frequency [Hz] of a free vibration about q_eq from the zero crossings (linearly
    interpolated) of the modal coordinate η = w·(q - q_eq), w a left eigenvector."""
    eta = (to_q_mm(run.q) - q_eq_mm) @ left_vector
    i = np.where(np.sign(eta[:-1]) * np.sign(eta[1:]) < 0)[0]
    tc = run.t[i] - eta[i] * (run.t[i + 1] - run.t[i]) / (eta[i + 1] - eta[i])
    return 0.5 * (len(tc) - 1) / (tc[-1] - tc[0])


def free_vibration(shaft: Shaft, load_n, mode: int, amplitude_mm: float = 1e-4, periods: int = 10, steps_per_period: int = 50):
    """Exudyn's free vibration of the shaft at rest about its equilibrium, started in a mode
    shape: (kontakt's frequency, Exudyn's frequency) in Hz."""
    q_eq, _, _ = reference_equilibrium(shaft, load_n)
    f, vec = modes(shaft, q_eq, load_n)
    phi = vec[:, mode] / np.max(np.abs(vec[:, mode] * [1.0, 1.0, 1.0, shaft.span_mm, shaft.span_mm]))
    run = simulate(shaft, periods / f[mode], 1.0 / (f[mode] * steps_per_period), load=lambda t: load_n, q0=to_q0(q_eq + amplitude_mm * phi))
    return f[mode], measured_frequency(run, q_eq, np.linalg.inv(vec)[mode])


def run_up(shaft: Shaft, load_before, load_after, step_at_s: float = 0.01, speed_rad_s: float = 300.0, ramp_s: float = 0.02, end_s: float = 0.04, step_s: float = 2e-5) -> Run:
    """The shaft at rest in equilibrium under `load_before`; a motor torque about its axis
    runs it up to `speed_rad_s` in `ramp_s` (constant acceleration), and the load steps to
    `load_after` at `step_at_s`."""
    q0, _, _ = reference_equilibrium(shaft, load_before)
    torque = shaft.inertia_polar_kgm2 * speed_rad_s / ramp_s
    return simulate(
        shaft,
        end_s,
        step_s,
        load=lambda t: load_before if t < step_at_s else load_after,
        q0=to_q0(q0),
        motor=lambda t: torque if t < ramp_s - 0.5 * step_s else 0.0,
    )


if __name__ == "__main__":
    import time

    shaft = Shaft()
    load = np.array(shaft.load_n)
    q_ref, _, its = reference_equilibrium(shaft, load)
    q_exu = solve_static(shaft, load)
    print(f"static equilibrium under {load} N at z = {shaft.load_point_mm} mm (x, y, z mm; α, β rad):")
    print("  kontakt (Newton on 5 DoF):", q_ref, f"({its} iterations)")
    print("  Exudyn (static solver):   ", q_exu, " largest relative difference", np.max(np.abs(q_exu - q_ref) / np.abs(q_ref)))
    for mode in (0, 4):
        f_k, f_e = free_vibration(shaft, load, mode)
        print(f"mode {mode}: kontakt's stiffness {f_k:.3f} Hz, Exudyn's free vibration {f_e:.3f} Hz ({f_e / f_k - 1:+.1e})")
    damped = Shaft(damping_s=5e-5)
    t0 = time.perf_counter()
    run = run_up(damped, np.array([500.0, 0.0, 0.0]), load)
    q1, _, _ = reference_equilibrium(shaft, load)
    print(f"run-up to {run.qd[-1, 5]:.2f} rad/s with a load step: {time.perf_counter() - t0:.1f} s, {run.evaluations} bearing evaluations")
    print("  end pose - static equilibrium:", to_q_mm(run.q[-1]) - q1)
