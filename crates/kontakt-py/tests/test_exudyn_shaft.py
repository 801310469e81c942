"""A rigid shaft on two kontakt bearings in Exudyn, an independent multibody code
(examples/python/exudyn_shaft.py, docs/exudyn.md): two preloaded 7205-class angular-contact
ball bearings in an O arrangement, kontakt.BearingElement as Exudyn's user force and
torque. Checked against kontakt alone: the static equilibrium (Exudyn's static solver
against a Newton solve on the shaft's five degrees of freedom, and the symmetric case
against kontakt.Bearing), the natural frequencies (Exudyn's free vibration against
kontakt's stiffness matrices), energy conservation without damping, and a run-up under a
load step that settles on the static equilibrium. exudyn is pinned in tools/test: a
missing install fails here, never skips."""

import importlib.util
import pathlib
import sys

import numpy as np
import pytest

import exudyn  # noqa: F401  (pinned by tools/test)
import kontakt as kt

REPO = pathlib.Path(__file__).resolve().parents[3]
spec = importlib.util.spec_from_file_location("exudyn_shaft", REPO / "examples/python/exudyn_shaft.py")
ex = importlib.util.module_from_spec(spec)
sys.modules["exudyn_shaft"] = ex  # dataclasses look their module up
spec.loader.exec_module(ex)


@pytest.fixture(scope="module")
def shaft():
    return ex.Shaft()


def test_exudyn_is_the_pinned_version():
    assert exudyn.__version__ == "1.13.6"


def test_both_routes_give_the_same_bearing_displacements(shaft):
    """The kinematics twice: Exudyn's route (rotation matrix, mirror matrices) and the
    reference's (closed-form Jacobian) give the same u at a tilted, shifted, spun pose, and
    the reference Jacobian is the derivative of u."""
    q = np.array([0.004, -0.003, 0.002, 2e-4, -3e-4])
    gamma = 0.7  # the spin changes nothing
    R = ex.rotation_xyz(q[3], q[4], gamma)
    for i in range(2):
        u_exu = ex.bearing_inputs(shaft, i, 1e-3 * q[:3], R, np.zeros(3), np.zeros(3))[0]
        u_ref, J = ex.shaft_kinematics(shaft, q, i)
        assert np.max(np.abs(u_exu - u_ref)) <= 1e-15
        h = 1e-7
        for k in range(5):
            dq = np.zeros(5)
            dq[k] = h
            fd = (ex.shaft_kinematics(shaft, q + dq, i)[0] - ex.shaft_kinematics(shaft, q - dq, i)[0]) / (2 * h)
            assert np.max(np.abs(fd - J[:, k])) <= 1e-6 * max(1.0, np.max(np.abs(J[:, k])))
    # the mirror: a pure axial shift pushes bearing 1 in and pulls bearing 2 out
    u1 = ex.shaft_kinematics(shaft, np.array([0, 0, 0.001, 0, 0]), 0)[0]
    u2 = ex.shaft_kinematics(shaft, np.array([0, 0, 0.001, 0, 0]), 1)[0]
    assert u1[2] == pytest.approx(shaft.preload_mm + 0.001) and u2[2] == pytest.approx(shaft.preload_mm - 0.001)


def test_static_equilibrium_equals_kontakts_load_distribution(shaft):
    """(a) Exudyn's static solver on the shaft with the bearing elements as user loads
    reaches the pose of the reference Newton on the shaft's five degrees of freedom (the
    elements' reactions and stiffnesses) to 1e-6 of each component (measured: 1e-12);
    the forces and torques Exudyn applies then balance the load."""
    load = np.array(shaft.load_n)
    q_ref, _, _ = ex.reference_equilibrium(shaft, load)
    q_exu = ex.solve_static(shaft, load)
    assert np.all(np.abs(q_exu - q_ref) <= 1e-6 * np.abs(q_ref)), (q_exu, q_ref)
    # the balance in Exudyn's terms: forces and torques about the centre of mass
    R = ex.rotation_xyz(q_ref[3], q_ref[4])
    total_f = load.copy()
    total_m = np.cross(R @ [0.0, 0.0, shaft.load_point_mm], load)  # N·mm
    for i, e in enumerate(shaft.elements):
        u, _, b = ex.bearing_inputs(shaft, i, 1e-3 * q_ref[:3], R, np.zeros(3), np.zeros(3))
        f, t = ex.bearing_loads(e.evaluate(u), i, b)
        total_f += f
        total_m += 1e3 * t + np.cross(R @ [0.0, 0.0, shaft.z_mm[i]], f)
    assert np.max(np.abs(total_f)) <= 1e-9 * np.max(np.abs(load))
    assert np.max(np.abs(total_m)) <= 1e-9 * np.max(np.abs(load)) * shaft.span_mm
    # both bearings carry load (the preload holds the unloaded side)
    for i, e in enumerate(shaft.elements):
        assert e.evaluate(ex.shaft_kinematics(shaft, q_ref, i)[0]).status == "loaded"


def test_symmetric_load_equals_kontakt_bearing_solve():
    """(a) A radial load at mid-span: by symmetry each bearing carries half of it at its
    preload with no tilt, which kontakt.Bearing solves on its own (the axial displacement
    and the tilts prescribed, the radial force given). Exudyn's static solver gives the same
    radial displacement to 1e-6 (measured: 1.7e-15), and zero tilt and axial shift."""
    shaft = ex.Shaft(load_point_mm=0.0)
    fx = 2000.0
    b = kt.Bearing(ex.CASE).solve(
        force=(0.5 * fx, 0.0, 0.0),
        prescribed={"dz_mm": shaft.preload_mm, "tilt_x_rad": 0.0, "tilt_y_rad": 0.0},
    )
    q = ex.solve_static(shaft, np.array([fx, 0.0, 0.0]))
    dx = b.displacement[0]
    assert abs(q[0] - dx) <= 1e-6 * abs(dx), (q[0], dx)
    assert np.all(np.abs(q[1:3]) <= 1e-9 * abs(dx)) and np.all(np.abs(q[3:]) <= 1e-9 * abs(dx) / shaft.span_mm)


@pytest.mark.parametrize("mode", [0, 4])
def test_natural_frequency_equals_kontakts_stiffness(shaft, mode):
    """(b) A free vibration in Exudyn (explicit RK4, 50 steps a period, 10 periods,
    amplitude 1e-4 mm), started in a mode shape of kontakt's linearised shaft (the bearing
    stiffness matrices mapped to the shaft, with the geometric part, against the rigid
    shaft's mass matrix): the frequency from the zero crossings of the modal coordinate
    equals kontakt's within 1 % (measured: 4e-5 and 5e-7 for the lowest and highest)."""
    f_kontakt, f_exudyn = ex.free_vibration(shaft, np.array(shaft.load_n), mode)
    assert abs(f_exudyn / f_kontakt - 1.0) <= 0.01, (f_kontakt, f_exudyn)
    assert 500.0 < f_kontakt < 3000.0


def test_energy_is_conserved_to_the_integrators_error(shaft):
    """(c) Undamped, spinning at 300 rad/s, started 2 µm off its equilibrium: the kinetic
    energy plus the bearings' elastic energy (minus the work of each element's reaction
    along a straight path, 48-point Gauss) minus the load's work stays constant to RK4's
    error: halving the step divides the largest drift by more than 8 (fourth order: 16),
    and at 1e-5 s it is below 2e-5 of the vibration's kinetic energy. A coupling that is
    not conservative (a torque with a wrong part) would leave a drift that does not shrink
    with the step."""
    load = np.array(shaft.load_n)
    q_eq, _, _ = ex.reference_equilibrium(shaft, load)
    q0 = ex.to_q0(q_eq + np.array([2e-3, -1e-3, 1e-3, 1e-5, -2e-5]))
    v0 = [0.0, 0.0, 0.0, 0.0, 0.0, 300.0]
    drift = []
    for h in (2e-5, 1e-5):
        run = ex.simulate(shaft, 0.003, h, load=lambda t: load, q0=q0, v0=v0)
        every = int(round(1e-4 / h))
        sub = ex.Run(run.t[::every], run.q[::every], run.qd[::every], 0)
        e = ex.energy(shaft, sub, load, gauss_points=48)
        vibration = np.max(0.5 * shaft.mass_kg * np.sum(run.qd[:, :3] ** 2, axis=1))
        drift.append(np.max(np.abs(e)) / vibration)
    assert drift[0] / drift[1] > 8.0, drift
    assert drift[1] < 2e-5, drift


def test_run_up_under_a_load_step_settles_on_the_static_equilibrium():
    """A run-up to 300 rad/s in 20 ms with the load stepping from 500 N radial to the
    gear load at 10 ms, the bearings damped (beta = 5e-5 s): before the step the shaft
    stays on the first equilibrium, after 30 ms it has settled on the second (within
    1e-6 of the step's displacement; the quasi-static element does not depend on the
    speed, and the gyroscopic moments vanish once the whirl has decayed), at full speed."""
    shaft = ex.Shaft(damping_s=5e-5)
    before, after = np.array([500.0, 0.0, 0.0]), np.array(shaft.load_n)
    q0, _, _ = ex.reference_equilibrium(shaft, before)
    q1, _, _ = ex.reference_equilibrium(shaft, after)
    run = ex.run_up(shaft, before, after, end_s=0.04)
    scale = np.abs(q1 - q0)
    i = np.searchsorted(run.t, 0.0099)
    assert np.all(np.abs(ex.to_q_mm(run.q[i]) - q0) <= 1e-6 * scale)
    assert np.all(np.abs(ex.to_q_mm(run.q[-1]) - q1) <= 1e-6 * scale)
    # mid-way the step has moved the shaft: the check above can fail
    j = np.searchsorted(run.t, 0.0105)
    assert np.max(np.abs(ex.to_q_mm(run.q[j]) - q1) / scale) > 1e-2
    assert run.qd[-1, 5] == pytest.approx(300.0, rel=1e-3)
