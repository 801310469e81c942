"""The FMUs of `kontakt fmu` in an independent FMI importer, FMPy (issue 31 §2): valid
model descriptions, model exchange and co-simulation with an input table, the outputs equal
to kontakt's own Python results, a legal FMI call sequence, and bad input that gives an
error status with a logged message naming the variable, not a crash.

The FMUs are built by the `kontakt` executable that `cargo test --workspace` leaves in the
target folder, with the FMU library next to it (docs/fmi.md, "Building an FMU")."""

import os
import pathlib
import re
import subprocess
import tempfile

import numpy as np
import pytest

# pinned by tools/test: a missing install fails here, never skips
import fmpy
from fmpy.fmi1 import FMICallException
from fmpy.validation import validate_fmu

import kontakt as kt

REPO = pathlib.Path(__file__).resolve().parents[3]
BEARING_CASE = "examples/bearing_32008x.toml"
FRICTION_CASE = "examples/bearing_32008x_friction.toml"
CONTACT_CASE = "crates/kontakt-capi/examples/element_ball_on_flat.toml"
U = ["dx", "dy", "dz", "theta_x", "theta_y"]
R = ["Fx", "Fy", "Fz", "Mx", "My"]


def kontakt_executable(repo: pathlib.Path) -> pathlib.Path:
    target = pathlib.Path(os.environ.get("CARGO_TARGET_DIR", repo / "target"))
    exe = target / "debug" / "kontakt"
    assert exe.is_file(), f"{exe} missing: run `cargo test --workspace` (or cargo build --workspace) first"
    return exe


@pytest.fixture(scope="module")
def fmus():
    """Both FMUs, built once per module in a folder removed afterwards (each holds the
    debug library, about 60 MB)."""
    exe = kontakt_executable(REPO)
    with tempfile.TemporaryDirectory(prefix="kontakt-fmu-") as d:
        out = {}
        for kind, case in [("bearing", BEARING_CASE), ("contact", CONTACT_CASE), ("friction", FRICTION_CASE)]:
            path = pathlib.Path(d) / f"{kind}.fmu"
            run = subprocess.run(
                [exe, "fmu", REPO / case, "-o", path], capture_output=True, text=True
            )
            assert run.returncode == 0, run.stderr
            assert ("bearing" if kind == "friction" else kind) + " element" in run.stdout
            out[kind] = str(path)
        yield out


def test_fmpy_finds_no_problems(fmus):
    for kind, path in fmus.items():
        assert validate_fmu(path) == [], kind
        md = fmpy.read_model_description(path)
        assert md.fmiVersion == "2.0"
        assert md.modelExchange is not None and md.coSimulation is not None
        assert md.numberOfContinuousStates == 0  # ME without states: the host integrates
        units = {u.name for u in md.unitDefinitions}
        variables = {v.name: v for v in md.modelVariables}
        if kind != "contact":
            assert variables["dx"].unit == "mm" and variables["Mx"].unit == "N.mm"
            assert variables["damping_s"].causality == "parameter"
            assert variables["damping_s"].variability == "tunable"
        else:
            assert variables["pose1.z"].unit == "mm" and variables["friction_power"].unit == "W"
            assert float(variables["mu"].start) == 0.1
        assert {v.unit for v in md.modelVariables if v.unit} <= units


def simulate(path, fmi_type, table, output, step=0.05, stop_time=1.0, **kw):
    """FMPy's simulation from 0 to `stop_time` with the input table: outputs every `step`
    (model exchange) or steps of `step` (co-simulation)."""
    return fmpy.simulate_fmu(
        path, fmi_type=fmi_type, stop_time=stop_time, step_size=step, output_interval=step, input=table, output=output, **kw
    )


def bearing_input():
    """An input table of the 32008 X: radial, axial and tilt displacements that load the
    bearing and lift it off (dz < 0 pulls the cone out)."""
    t = np.linspace(0.0, 1.0, 11)
    table = np.zeros(len(t), dtype=[("time", float)] + [(n, float) for n in U])
    table["time"] = t
    table["dx"] = 0.02 * t
    table["dy"] = 0.004 * (t - 0.5)
    table["dz"] = -0.03 + 0.06 * t
    table["theta_x"] = 2e-4 * (t - 0.5)
    table["theta_y"] = -1e-4 * t
    return table


def kontakt_bearing_reaction(bearing, u):
    """The bearing's reaction on the inner ring, -F(u), from kontakt's Python bearing
    with all five degrees of freedom prescribed."""
    keys = ["dx_mm", "dy_mm", "dz_mm", "tilt_x_rad", "tilt_y_rad"]
    r = bearing.solve(prescribed=dict(zip(keys, map(float, u))))
    return -np.asarray(r.load_carried)[:5], r.max_element_load_n


def test_bearing_model_exchange_equals_kontakt(fmus, repo):
    result = simulate(fmus["bearing"], "ModelExchange", bearing_input(), U + R + ["max_element_load", "status"])
    bearing = kt.Bearing(repo / BEARING_CASE)
    loaded = 0
    for row in result:
        u = [row[n] for n in U]  # the inputs the FMU got (FMPy interpolates the table)
        want, max_load = kontakt_bearing_reaction(bearing, u)
        got = np.array([row[n] for n in R])
        scale = max(np.abs(want).max(), 1.0)
        assert np.abs(got - want).max() <= 1e-12 * scale, (row["time"], got, want)
        assert row["max_element_load"] == pytest.approx(max_load, rel=1e-12, abs=1e-9)
        loaded += row["status"] == 1.0
    # the table loads the bearing and lifts it off
    assert 0 < loaded < len(result)


def test_bearing_co_simulation_holds_the_inputs_over_a_step(fmus, repo):
    table = bearing_input()
    result = simulate(fmus["bearing"], "CoSimulation", table, U + R, step=0.1)
    bearing = kt.Bearing(repo / BEARING_CASE)
    # FMPy sets the inputs at t, steps to t + h and reads the variables: the row at t + h
    # holds the inputs of t (a communication-step delay) and the outputs of those inputs
    for before, row in zip(result[:-1], result[1:]):
        assert row["dz"] == pytest.approx(np.interp(before["time"], table["time"], table["dz"]), abs=1e-15)
        want, _ = kontakt_bearing_reaction(bearing, [row[n] for n in U])
        got = np.array([row[n] for n in R])
        assert np.abs(got - want).max() <= 1e-12 * max(np.abs(want).max(), 1.0), row["time"]


def test_bearing_run_up_with_friction_equals_kontakt(fmus, repo):
    """The lubricated 32008 X under a fixed displacement while the inner ring runs up
    from rest to 300 rad/s: the friction torque, its power and the moment about the axis
    equal kontakt's Python BearingElement at the same ring speeds."""
    t = np.linspace(0.0, 1.0, 11)
    table = np.zeros(len(t), dtype=[("time", float)] + [(n, float) for n in U + ["omega_inner", "omega_outer"]])
    table["time"] = t
    table["dx"], table["dz"] = 0.01, 0.015
    table["omega_inner"] = 300.0 * t
    out = ["omega_inner", "omega_outer", "Fx", "Fz", "Mz", "friction_torque", "friction_power"]
    result = simulate(fmus["friction"], "ModelExchange", table, out)
    element = kt.BearingElement(repo / FRICTION_CASE)
    for row in result:
        element.set_speeds(row["omega_inner"], row["omega_outer"])
        r = element.evaluate([0.01, 0.0, 0.015, 0.0, 0.0])
        want = [r.force[0], r.force[2], r.moment[2], r.friction_torque_nmm, r.friction_power_w]
        got = [row[n] for n in out[2:]]
        np.testing.assert_allclose(got, want, rtol=1e-12, atol=1e-12 * abs(r.force[0]))
    assert result[-1]["friction_power"] > 0.0 and result[-1]["Mz"] < 0.0


CONTACT_IN = [f"pose1.{c}" for c in ("x", "y", "z", "qw", "qx", "qy", "qz")] + [
    f"twist1.{c}" for c in ("vx", "vy", "vz", "wx", "wy", "wz")
]
CONTACT_OUT = [f"force1.{c}" for c in "xyz"] + [f"moment1.{c}" for c in "xyz"] + [
    "friction_power",
    "normal_force",
    "approach",
    "status",
]


def test_contact_model_exchange_equals_kontakt(fmus, repo):
    """A ball pressed onto the flat and sliding, spinning about a tilted axis; body 2 at
    rest at the origin (its inputs keep their start values)."""
    t = np.linspace(0.0, 1.0, 6)
    table = np.zeros(len(t), dtype=[("time", float)] + [(n, float) for n in CONTACT_IN])
    table["time"] = t
    table["pose1.x"] = 0.5 * t
    table["pose1.z"] = 10.002 - 0.01 * t  # separated at first, then 8 µm deep
    a = 0.3 * t  # a rotation about z: the quaternion stays a unit quaternion in the table
    table["pose1.qw"], table["pose1.qz"] = np.cos(a / 2), np.sin(a / 2)
    table["twist1.vx"] = 50.0
    table["twist1.wy"] = 3.0
    result = simulate(fmus["contact"], "ModelExchange", table, CONTACT_IN + CONTACT_OUT)
    element = kt.ContactElement.from_file(repo / CONTACT_CASE)
    touching = 0
    for row in result:
        q = np.array([row[f"pose1.{c}"] for c in ("qw", "qx", "qy", "qz")])
        q = q / np.linalg.norm(q)  # the FMU normalises the interpolated quaternion
        pose1 = ([row["pose1.x"], row["pose1.y"], row["pose1.z"]], q)
        twist1 = ([row["twist1.vx"], row["twist1.vy"], row["twist1.vz"]], [row["twist1.wx"], row["twist1.wy"], row["twist1.wz"]])
        r = element.evaluate(pose1, np.eye(4), twist1)
        want = np.concatenate([r.force1, r.moment1, [r.friction_power, r.normal_force, r.approach]])
        got = np.array([row[n] for n in CONTACT_OUT[:-1]])
        scale = max(np.abs(want).max(), 1.0)
        assert np.abs(got - want).max() <= 1e-12 * scale, (row["time"], got, want)
        assert row["status"] == {"separated": 0.0, "contact": 1.0}[r.status]
        touching += r.status == "contact"
    assert 0 < touching < len(result)


# The FMI 2.0 model-exchange state machine (the standard, section 3.2.3) for an FMU
# without states and events, as the calls FMPy makes may follow each other: the state
# after each function, from the states it is allowed in.
ME_TRANSITIONS = {
    "fmi2Instantiate": ({None}, "instantiated"),
    "fmi2SetupExperiment": ({"instantiated"}, "instantiated"),
    "fmi2EnterInitializationMode": ({"instantiated"}, "initialization"),
    "fmi2ExitInitializationMode": ({"initialization"}, "event"),
    "fmi2NewDiscreteStates": ({"event"}, "event"),
    "fmi2EnterEventMode": ({"event", "continuous"}, "event"),
    "fmi2EnterContinuousTimeMode": ({"event"}, "continuous"),
    "fmi2SetTime": ({"event", "continuous"}, None),
    "fmi2CompletedIntegratorStep": ({"continuous"}, "continuous"),
    "fmi2SetReal": ({"instantiated", "initialization", "event", "continuous"}, None),
    "fmi2GetReal": ({"initialization", "event", "continuous", "terminated"}, None),
    "fmi2GetDerivatives": ({"initialization", "event", "continuous", "terminated"}, None),
    "fmi2GetEventIndicators": ({"initialization", "event", "continuous", "terminated"}, None),
    "fmi2GetContinuousStates": ({"initialization", "event", "continuous", "terminated"}, None),
    "fmi2SetContinuousStates": ({"continuous"}, None),
    "fmi2Terminate": ({"event", "continuous"}, "terminated"),
    "fmi2FreeInstance": ({"instantiated", "initialization", "event", "continuous", "terminated"}, "freed"),
}


def test_the_call_sequence_is_legal_and_every_call_ok(fmus):
    calls = []
    simulate(fmus["bearing"], "ModelExchange", bearing_input(), R, step=0.1, stop_time=0.2, fmi_call_logger=calls.append)
    state = None
    names = []
    for line in calls:
        m = re.match(r"(fmi2\w+)\(.*\)(?: -> (\w+))?$", line)
        assert m, line
        name, status = m.groups()
        names.append(name)
        allowed, after = ME_TRANSITIONS[name]
        assert state in allowed, f"{name} in state {state}"
        state = after or state
        if name not in ("fmi2Instantiate", "fmi2FreeInstance"):
            assert status == "OK", line
    assert state == "freed"
    assert names.count("fmi2GetReal") >= 3 and "fmi2Terminate" in names


def failed_run(path, fmi_type, table):
    """Simulate until the FMU refuses: the FMPy exception and the messages the FMU's
    logger received (status, category, message)."""
    messages = []

    def logger(component, instance, status, category, message):
        messages.append((status, category.decode(), message.decode()))

    with pytest.raises(FMICallException) as e:
        simulate(path, fmi_type, table, R, step=0.1, logger=logger)
    return e.value, messages


def test_nan_input_is_an_error_with_a_logged_message_not_a_crash(fmus):
    table = bearing_input()
    table["dz"][3] = np.nan
    e, messages = failed_run(fmus["bearing"], "ModelExchange", table)
    assert e.function == "fmi2SetReal" and e.status == 3  # fmi2Error
    assert any(s == 3 and c == "logStatusError" and "dz = NaN" in m for s, c, m in messages), messages
    # the process lives on: the same FMU simulates again
    simulate(fmus["bearing"], "CoSimulation", bearing_input(), R, step=0.1, stop_time=0.1)


def test_a_displacement_beyond_validity_is_a_discard_naming_the_input(fmus):
    table = bearing_input()
    table["dx"][5:] = 7.0  # above the roller diameter (6.49 mm)
    e, messages = failed_run(fmus["bearing"], "CoSimulation", table)
    assert e.status == 2  # fmi2Discard
    assert any(
        s == 2 and c == "logStatusDiscard" and "invalid dx = " in m and "roller_diameter_mm" in m
        for s, c, m in messages
    ), messages


def test_tunable_damping_parameter(fmus, repo):
    """damping_s = beta: the reaction gains -beta K v (K the stiffness of kontakt's bearing)."""
    t = np.array([0.0, 1.0])
    table = np.zeros(2, dtype=[("time", float), ("dx", float), ("dz", float), ("vx", float)])
    table["time"], table["dx"], table["dz"], table["vx"] = t, 0.01, 0.02, 10.0
    result = simulate(fmus["bearing"], "ModelExchange", table, R, step=0.5, start_values={"damping_s": 1e-3})
    r = kt.Bearing(repo / BEARING_CASE).solve(
        prescribed={"dx_mm": 0.01, "dy_mm": 0.0, "dz_mm": 0.02, "tilt_x_rad": 0.0, "tilt_y_rad": 0.0}
    )
    k = np.asarray(r.stiffness)
    want = -np.asarray(r.load_carried)[:5] - 1e-3 * k[:, 0] * 10.0
    got = np.array([result[-1][n] for n in R])
    assert np.abs(got - want).max() <= 1e-9 * np.abs(want).max(), (got, want)


def test_directional_derivative_and_fmu_state_through_fmpy(fmus, repo):
    """FMPy's low-level API calls the C functions themselves: the directional derivative of
    the reaction is minus kontakt's stiffness, column by column, and an FMU state saved at
    one displacement restores its outputs."""
    import shutil

    from fmpy.fmi2 import FMU2Model

    path = fmus["bearing"]
    md = fmpy.read_model_description(path)
    vr = {v.name: v.valueReference for v in md.modelVariables}
    unzipped = fmpy.extract(path)
    fmu = FMU2Model(guid=md.guid, unzipDirectory=unzipped, modelIdentifier=md.modelExchange.modelIdentifier, instanceName="k")
    try:
        fmu.instantiate()
        fmu.setupExperiment(startTime=0.0)
        fmu.enterInitializationMode()
        fmu.exitInitializationMode()
        fmu.enterContinuousTimeMode()
        u = [0.01, 0.003, 0.02, 1e-4, -5e-5]
        fmu.setReal([vr[n] for n in U], u)
        before = fmu.getReal([vr[n] for n in R])
        keys = ["dx_mm", "dy_mm", "dz_mm", "tilt_x_rad", "tilt_y_rad"]
        k = np.asarray(kt.Bearing(repo / BEARING_CASE).solve(prescribed=dict(zip(keys, u))).stiffness)
        for j, name in enumerate(U):
            d = fmu.getDirectionalDerivative([vr[n] for n in R], [vr[name]], [1.0])
            np.testing.assert_allclose(d, -k[:, j], rtol=1e-12, atol=1e-12 * np.abs(k).max())
        state = fmu.getFMUstate()
        fmu.setReal([vr["dx"]], [0.02])
        assert fmu.getReal([vr["Fx"]])[0] != before[0]
        fmu.setFMUstate(state)
        assert fmu.getReal([vr[n] for n in R]) == before
        fmu.freeFMUstate(state)
        fmu.terminate()
    finally:
        fmu.freeInstance()
        shutil.rmtree(unzipped, ignore_errors=True)
