"""kontakt.BearingElement: a bearing case as one force element of a multi-body code. Its
reaction is minus the load kontakt.Bearing carries at the same prescribed displacement, its
stiffness that load's derivative, its damping -beta K v; arguments are named in errors."""

import math
import pathlib
import tomllib

import numpy as np
import pytest

import kontakt as kt
from conftest import gil_fractions

REPO = pathlib.Path(__file__).resolve().parents[3]
ACBB = REPO / "examples/bearing_7205.toml"
TRB = REPO / "examples/bearing_32008x.toml"
KEYS = ("dx_mm", "dy_mm", "dz_mm", "tilt_x_rad", "tilt_y_rad")

# loaded displacements of each bearing (mm, rad): pushed into its cup/outer ring, shifted, tilted
POINTS = {
    ACBB: [(0.005, -0.002, 0.012, 1e-4, -2e-4), (0.0, 0.0, 0.01, 0.0, 0.0), (-0.01, 0.004, 0.008, -3e-4, 1e-4)],
    TRB: [(0.01, 0.0, 0.02, 0.0, 1e-4), (-0.004, 0.006, 0.015, -1e-4, 0.0)],
}


def reaction(r) -> np.ndarray:
    return np.concatenate([r.force, r.moment[:2]])


@pytest.mark.parametrize("path", [ACBB, TRB], ids=lambda p: p.stem)
def test_the_reaction_is_minus_the_load_kontakt_bearing_carries(path):
    """Independent route: kontakt.Bearing solves the case with all five degrees of freedom
    prescribed; the element's reaction is minus the load carried, to round-off, and the
    stiffness is the same matrix."""
    element, bearing = kt.BearingElement(path), kt.BearingElement(path)
    bearing = kt.Bearing(path)
    for u in POINTS[path]:
        r = element.evaluate(np.array(u))
        b = bearing.solve(prescribed=dict(zip(KEYS, u)))
        carried = b.load_carried
        assert r.status == "loaded" and r.message == ""
        assert np.max(np.abs(reaction(r) + carried)) <= 1e-9 * np.max(np.abs(carried))
        assert r.moment[2] == 0.0
        assert np.max(np.abs(r.stiffness - b.stiffness)) <= 1e-9 * np.max(np.abs(b.stiffness))
        assert r.max_element_load_n == pytest.approx(b.max_element_load_n, rel=1e-9)


@pytest.mark.parametrize("path", [ACBB, TRB], ids=lambda p: p.stem)
def test_the_stiffness_is_the_derivative_of_the_reaction(path):
    """Central differences of the reaction (steps 1e-7 mm and 1e-8 rad) give -K to 1e-5 of
    the largest entry of each column, scaled by the step."""
    e = kt.BearingElement(path)
    u = np.array(POINTS[path][0])
    k = e.evaluate(u).stiffness
    steps = np.array([1e-7, 1e-7, 1e-7, 1e-8, 1e-8])
    for j in range(5):
        du = np.zeros(5)
        du[j] = steps[j]
        fd = (reaction(e.evaluate(u + du)) - reaction(e.evaluate(u - du))) / (2 * steps[j])
        assert np.max(np.abs(fd + k[:, j])) <= 1e-5 * np.max(np.abs(k[:, j])), j


def test_damping_is_beta_times_the_stiffness_times_the_velocity():
    beta = 2e-5
    damped, undamped = kt.BearingElement(ACBB, damping_s=beta), kt.BearingElement(ACBB)
    assert damped.damping_s == beta and undamped.damping_s == 0.0
    u = np.array(POINTS[ACBB][0])
    v = np.array([3.0, -1.0, 2.0, 0.01, -0.02])
    r, r0 = damped.evaluate(u, v), undamped.evaluate(u, v)
    expected = -beta * r0.stiffness @ v
    assert np.allclose(r.damping, expected, rtol=1e-12, atol=0.0)
    assert np.allclose(reaction(r) - reaction(r0), expected, rtol=1e-9, atol=1e-12)
    assert np.all(r0.damping == 0.0)
    undamped.damping_s = beta
    assert np.allclose(undamped.evaluate(u, v).damping, expected, rtol=1e-12, atol=0.0)


def test_lists_arrays_and_dicts_give_the_same_answer():
    case = tomllib.loads(ACBB.read_text())
    del case["load"]
    u = POINTS[ACBB][0]
    a = kt.BearingElement(case).evaluate(list(u), [0.0] * 5)
    b = kt.BearingElement(ACBB.read_text()).evaluate(np.array(u))
    c = kt.BearingElement(str(ACBB)).evaluate(tuple(u), np.zeros(5, dtype=np.int64))
    assert np.array_equal(reaction(a), reaction(b)) and np.array_equal(reaction(a), reaction(c))
    d = a.to_dict()
    assert d["status"] == "loaded" and d["force_n"] == list(a.force) and len(d["stiffness"]) == 5
    assert "BearingElementResult(status=\"loaded\"" in repr(a)
    assert kt.BearingElement(ACBB).bearing_type == "angular_contact_ball"


def test_a_lifted_off_bearing_gives_zero_force_and_stiffness():
    e = kt.BearingElement(ACBB)
    r = e.evaluate(np.array([0.0, 0.0, -0.01, 0.0, 0.0]))
    assert r.status == "lifted_off" and r.message
    assert np.all(r.force == 0.0) and np.all(r.stiffness == 0.0) and r.max_element_load_n == 0.0


def test_a_closed_cycle_does_no_work():
    """The reaction is conservative: its work around a closed loop in the five displacements
    (an ellipse through every component, 400 points, periodic trapezoidal rule) is below
    1e-9 of the work along half of it."""
    e = kt.BearingElement(ACBB)
    centre = np.array([0.004, -0.002, 0.012, 1e-4, -1e-4])
    amp_c = np.array([0.003, 0.001, 0.002, 5e-5, 1e-4])
    amp_s = np.array([-0.001, 0.003, 0.001, 1e-4, 5e-5])
    n = 400
    phi = 2 * np.pi * np.arange(n) / n
    work = 0.0
    half = 0.0
    for k, p in enumerate(phi):
        du = (-np.sin(p) * amp_c + np.cos(p) * amp_s) * (2 * np.pi / n)
        dw = reaction(e.evaluate(centre + np.cos(p) * amp_c + np.sin(p) * amp_s)) @ du
        work += dw
        half += abs(dw) if k < n // 2 else 0.0
    assert abs(work) <= 1e-9 * half, (work, half)


def test_the_gil_is_released_during_an_evaluation():
    """A Python thread keeps running while the main thread is inside evaluate (a TRB of
    10001 slices: some 40 ms a call in the debug build)."""
    case = tomllib.loads(TRB.read_text())
    case["bearing"]["slices"] = 10001
    e = kt.BearingElement(case)

    def evaluate(i):
        e.reset()
        e.evaluate(np.array([0.01, 0.0, 0.02 + 1e-4 * i, 0.0, 0.0]))

    fractions = gil_fractions(evaluate)
    assert sorted(fractions)[2] < 0.5, fractions


@pytest.mark.parametrize(
    ("args", "exc", "named"),
    [
        (((0.0, 0.0, math.nan, 0.0, 0.0),), kt.InputError, "displacement[2]"),
        ((np.array([0.0, 0.0, 0.01, math.inf, 0.0]),), kt.InputError, "displacement[3]"),
        (((0.0, 0.0, 0.01, 0.0),), kt.InputError, "displacement"),
        ((np.zeros((1, 5)),), kt.InputError, "displacement"),
        (((0.0, 0.0, 9.0, 0.0, 0.0),), kt.InputError, "displacement[2]"),
        (((0.0, 0.0, 0.01, 0.0, 0.9),), kt.InputError, "displacement[4]"),
        (((0.0, 0.0, 0.01, 0.0, 0.0), (0.0, 0.0, 0.0, 0.0, math.nan)), kt.InputError, "velocity[4]"),
        (((0.0, 0.0, 0.01, 0.0, 0.0), (0.0, 0.0)), kt.InputError, "velocity"),
        (((True, 0.0, 0.01, 0.0, 0.0),), TypeError, "invalid displacement[0] = True (bool)"),
        (("0.01",), TypeError, "invalid displacement = '0.01' (str)"),
        ((np.zeros(5, dtype=bool),), TypeError, "invalid displacement[0] = "),
    ],
)
def test_bad_arguments_are_named(args, exc, named):
    e = kt.BearingElement(ACBB)
    with pytest.raises(exc) as err:
        e.evaluate(*args)
    assert "\n" not in str(err.value)
    if exc is kt.InputError:
        assert err.value.field == named, str(err.value)
    else:
        assert str(err.value).startswith(named), str(err.value)
    # the element still works after a refused call
    assert e.evaluate(np.array([0.0, 0.0, 0.01, 0.0, 0.0])).status == "loaded"


def test_bad_cases_and_damping_are_named():
    bad = tomllib.loads(ACBB.read_text())
    bad["bearing"]["ball_diameter_mm"] = -1.0
    refused = [((REPO / "examples/ball_on_flat.toml",), "case.method"), ((bad,), "bearing.ball_diameter_mm")]
    refused += [((ACBB, value), "damping_s") for value in (-1.0, math.nan, math.inf)]
    for args, named in refused:
        with pytest.raises(kt.InputError) as e:
            kt.BearingElement(*args)
        assert e.value.field == named and "\n" not in str(e.value), str(e.value)
    with pytest.raises(TypeError, match=r"^invalid case = 3\.0 \(float\)"):
        kt.BearingElement(3.0)
    el = kt.BearingElement(ACBB, damping_s=1e-5)
    with pytest.raises(kt.InputError) as e:
        el.damping_s = -1e-5
    assert e.value.field == "damping_s" and el.damping_s == 1e-5
    with pytest.raises(TypeError, match=r"^invalid damping_s = True \(bool\)"):
        el.damping_s = True


FRICTION = REPO / "examples/bearing_32008x_friction.toml"


def test_the_friction_torque_is_the_case_reports_at_its_equilibrium():
    """A lubricated case: at the displacement the case's own solve finds, the element's
    friction torque is the report's (kontakt.run, the same load distribution and speeds) to
    1e-9; Mz is the friction moment on the inner ring (minus the report's driving torque
    on it), the power is M |Δω|, the breakdown adds up; equal speeds give the starting
    torque, reported and not applied."""
    report = kt.run(FRICTION).to_dict()
    f = report["friction"]
    e = kt.BearingElement(FRICTION)
    r = e.evaluate(np.array(report["displacement_mm"] + report["tilt_rad"]))
    assert r.friction_status == "running"
    assert r.friction_torque_nmm == pytest.approx(f["total_nmm"], rel=1e-9)
    assert r.moment[2] == r.friction_inner_ring_nmm == pytest.approx(-f["inner_ring_nmm"], rel=1e-9)
    dw = (f["inner_rpm"] - f["outer_rpm"]) * math.pi / 30.0
    assert r.friction_power_w == pytest.approx(1e-3 * r.friction_torque_nmm * dw, rel=1e-12)
    assert r.friction_power_w == pytest.approx(f["power_w"], rel=1e-9)
    assert np.sum(r.friction_breakdown) == pytest.approx(r.friction_torque_nmm, rel=1e-12)
    np.testing.assert_allclose(r.ring_speeds, [dw, 0.0], rtol=1e-15)
    e.set_speeds(5.0, 5.0)
    s = e.evaluate(np.array(report["displacement_mm"] + report["tilt_rad"]))
    assert s.friction_status == "starting" and s.friction_torque_nmm > 0.0
    assert s.moment[2] == 0.0 and s.friction_power_w == 0.0
    assert s.to_dict()["friction_status"] == "starting"


def test_ring_speeds_are_named_when_bad():
    e = kt.BearingElement(FRICTION)
    with pytest.raises(ValueError, match="outer_rad_s"):
        e.set_speeds(10.0, float("nan"))
    with pytest.raises(ValueError, match="inner_rad_s"):
        e.set_speeds(1e9, 0.0)


def test_without_a_lubricant_the_friction_is_off():
    r = kt.BearingElement(TRB).evaluate(np.array(POINTS[TRB][0]))
    assert r.friction_status == "off" and r.friction_torque_nmm == 0.0 and r.moment[2] == 0.0
