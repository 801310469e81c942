"""Argument conversion (crates/kontakt-py/src/args.rs) and case dicts: every error is one
line naming the argument, the value and what is valid (issue 30 items 8 and 11); `sweep`
takes a dict as `run` does and a `CaseResult` shows its numbers (item 16)."""

from __future__ import annotations

import csv
import itertools
import math
import pathlib
import subprocess
import sys

import numpy as np
import pytest

import kontakt as kt

REPO = pathlib.Path(__file__).resolve().parents[3]
STEEL = {"e_mpa": 210000.0, "nu": 0.3}
HERTZ_CASE = {
    "contact": {"kind": "point", "angle_deg": 0.0},
    "body1": {"radii_mm": [6.35, 6.35], **STEEL},
    "body2": {"radii_mm": [math.inf, math.inf], **STEEL},
    "load": {"force_n": 100.0},
}


def one_line(e: BaseException, *words: str) -> str:
    """The message of ``e``: one line that contains each of ``words``."""
    msg = str(e)
    assert "\n" not in msg, f"not one line: {msg!r}"
    for w in words:
        assert w in msg, f"{w!r} not in {msg!r}"
    return msg


def ball() -> kt.HertzPoint:
    return kt.HertzPoint((6.35, 6.35), (math.inf, math.inf))


# --- item 8: a case dict that contains itself ---------------------------------------------


def test_case_dict_that_contains_itself_is_an_input_error_not_a_crash():
    # in a subprocess: before the fix the interpreter died with SIGSEGV
    code = """
import copy, kontakt as kt
case = {"contact": {"kind": "point"}, "geometry": {}, "load": {"force_n": 1.0}}
case["geometry"]["self"] = case
try:
    kt.run(case)
except kt.InputError as e:
    print(e.field, "|", e)
"""
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=60)
    assert out.returncode == 0, f"exit {out.returncode}: {out.stderr[-500:]}"
    field, msg = out.stdout.strip().split(" | ")
    assert field == "case.geometry.self"
    assert msg == "invalid case.geometry.self = case itself: expected a value, not a dict or list that contains itself"


def test_list_that_contains_itself_and_deep_nesting_are_refused():
    case = dict(HERTZ_CASE)
    loop: list = [1.0]
    loop.append(loop)
    with pytest.raises(kt.InputError) as e:
        kt.run({**case, "extra": loop})
    assert e.value.field == "case.extra[1]"
    one_line(e.value, "case.extra itself")

    deep: dict = {}
    node = deep
    for _ in range(100):
        node["a"] = {}
        node = node["a"]
    with pytest.raises(kt.InputError) as e:
        kt.run({**case, "deep": deep})
    one_line(e.value, "nested at most 64 deep")
    assert e.value.field.startswith("case.deep.a.a")

    # a dict shared twice (not a cycle) is fine: it is converted twice
    shared = {"kind": "point", "angle_deg": 0.0}
    assert kt.run({**case, "contact": shared}).to_dict()["max_pressure_mpa"] > 0
    with pytest.raises(TypeError) as e:
        kt.to_toml([1, 2])  # type: ignore[arg-type]
    one_line(e.value, "invalid definition = [1, 2] (list)")


# --- item 11: conversion errors name the argument -----------------------------------------


@pytest.mark.parametrize(
    "call, name",
    [
        (lambda: ball().solve(force=True), "force"),
        (lambda: ball().solve(approach=np.bool_(True)), "approach"),
        (lambda: ball().approach_from_force(False), "force"),
        (lambda: kt.Material(e=True, nu=0.3), "e"),
        (lambda: kt.HertzPoint((True, 6.0), (math.inf, math.inf)), "radii1[0]"),
        (lambda: kt.HertzPoint((6.0, 6.0), (math.inf, math.inf), angle=True), "angle"),
        (lambda: kt.HertzLine(5.0, math.inf, length=True), "length"),
        (lambda: kt.HertzLine(5.0, math.inf).solve(line_load=True), "line_load"),
        (lambda: kt.HalfSpace((16, 16), (1.0, 1.0), e_star=True), "e_star"),
        (lambda: kt.HalfSpace((True, 16), (1.0, 1.0)), "nb_grid_pts[0]"),
        (lambda: kt.HalfSpace((16, 16), (1.0, 1.0)).solve(np.zeros((16, 16)), external_force=True), "external_force"),
        (lambda: ball().solve(force=100.0).to_dict(yield_stress=True), "yield_stress"),
    ],
)
def test_a_bool_is_not_a_number(call, name):
    with pytest.raises(TypeError) as e:
        call()
    one_line(e.value, f"invalid {name} = ", "(bool)", "expected ")


def test_bools_inside_lists_and_numpy_integers():
    r = ball().solve(force=100.0)
    with pytest.raises(TypeError) as e:
        r.pressure([0.0, [True, 0.0]], 0.0)
    one_line(e.value, "invalid x[1][0] = True (bool)")
    loop: list = [0.0]
    loop.append(loop)
    with pytest.raises(kt.InputError) as e:
        r.pressure(loop, 0.0)
    one_line(e.value, "invalid x = ")
    # NumPy's integers count; floats do not
    hs = kt.HalfSpace((np.int64(16), np.uint16(16)), (np.float32(2.0), 2))
    assert hs.nb_grid_pts == (16, 16) and hs.physical_sizes == (2.0, 2.0)
    with pytest.raises(TypeError) as e:
        kt.HalfSpace((16.0, 16), (2.0, 2.0))
    one_line(e.value, "invalid nb_grid_pts[0] = 16.0 (float): expected an int: 8 <= n <= 4096")


def test_case_dict_schema_errors_name_the_key_not_a_line_of_generated_text():
    with pytest.raises(kt.InputError) as e:
        kt.run({**HERTZ_CASE, "load": {"force_n": True}})
    msg = one_line(e.value, "load.force_n")
    assert "line " not in msg
    # TOML text keeps its line numbers
    with pytest.raises(kt.InputError) as e:
        kt.run(kt.to_toml({**HERTZ_CASE, "load": {"force_n": True}}))
    one_line(e.value, "line ", "load.force_n")


def test_complex_values_are_refused_not_truncated():
    r = ball().solve(force=100.0)
    with pytest.raises(TypeError) as e:
        r.pressure(np.zeros(3) + 1j, 0.0)
    one_line(e.value, "invalid x = an array of dtype complex128: expected an array of real numbers")
    with pytest.raises(TypeError) as e:
        kt.HertzLine(5.0, math.inf).solve(line_load=500.0).pressure([0.0, 1j])
    one_line(e.value, "invalid x = ", "complex128")
    hs = kt.HalfSpace((16, 16), (1.0, 1.0))
    with pytest.raises(TypeError) as e:
        hs.solve(np.zeros((16, 16), dtype=complex), external_force=1.0)
    one_line(e.value, "invalid gap = an array of dtype complex128")
    with pytest.raises(TypeError) as e:
        hs.solve(np.zeros((16, 16), dtype=bool), external_force=1.0)
    one_line(e.value, "invalid gap = an array of dtype bool")
    with pytest.raises(TypeError) as e:
        ball().solve(force=100 + 0j)
    one_line(e.value, "invalid force = (100+0j) (complex)")


def test_counts_out_of_range_name_the_argument_and_the_range():
    with pytest.raises(kt.InputError) as e:
        kt.HalfSpace((-1, 8), (1.0, 1.0))
    assert (e.value.field, e.value.valid) == ("nb_grid_pts[0]", "8 <= n <= 4096")
    one_line(e.value, "invalid nb_grid_pts[0] = -1 (int): expected 8 <= n <= 4096")
    hs = kt.HalfSpace((16, 16), (2.0, 2.0))
    gap = np.zeros((16, 16))
    with pytest.raises(kt.InputError) as e:
        hs.solve(gap, external_force=1.0, threads=-1)
    assert e.value.field == "threads"
    one_line(e.value, "invalid threads = -1 (int): expected 1..=")
    with pytest.raises(kt.InputError) as e:
        hs.solve(gap, external_force=1.0, max_iterations=2**70)
    assert e.value.field == "max_iterations"
    with pytest.raises(TypeError) as e:
        hs.solve(gap, external_force=1.0, max_iterations=10.0)
    one_line(e.value, "invalid max_iterations = 10.0 (float): expected an int")
    with pytest.raises(kt.InputError) as e:
        kt.Sweep.from_file(REPO / "examples/sweeps/hertz_load.toml", max_cases=-5)
    assert e.value.field == "max_cases"
    with pytest.raises(kt.InputError) as e:
        ball().solve(force=10**400)
    one_line(e.value, "invalid force = 1000")


def test_shape_errors_are_one_line_with_the_shapes_expected_and_found():
    hs = kt.HalfSpace((16, 8), (2.0, 1.0))
    with pytest.raises(kt.InputError) as e:
        hs.solve(np.zeros(5), external_force=1.0)
    assert (e.value.field, e.value.value) == ("gap.shape", "(5,)")
    one_line(e.value, "invalid gap.shape = (5,): expected (8, 16), i.e. (ny, nx) for nb_grid_pts = (16, 8)")
    with pytest.raises(kt.InputError) as e:
        hs.solve(np.zeros((16, 8)), external_force=1.0)
    one_line(e.value, "gap.shape = (16, 8)")
    with pytest.raises(kt.InputError) as e:
        kt.HertzPoint((6.0,), (math.inf, math.inf))
    one_line(e.value, "invalid radii1 = (6.0,) (tuple) of 1 items: expected a sequence of 2")
    with pytest.raises(kt.InputError) as e:
        kt.HertzPoint(itertools.count(1), (math.inf, math.inf))
    one_line(e.value, "invalid radii1 = count(1) (count) of more than 2 items")
    with pytest.raises(kt.InputError) as e:
        ball().solve(force=100.0).pressure(np.zeros(3), np.zeros(4))
    one_line(e.value, "invalid x, y = shapes (3,) and (4,)")


def test_wrong_types_name_the_argument():
    cases = [
        (lambda: ball().solve(force="100"), "invalid force = '100' (str)"),
        (lambda: kt.HertzPoint("ab", (1.0, 1.0)), "invalid radii1 = 'ab' (str)"),
        (lambda: kt.HertzPoint((6.0, 6.0), (1.0, 1.0), material1="steel"), "invalid material1 = 'steel' (str)"),
        (lambda: kt.Material.steel().e_star(3), "invalid other = 3 (int)"),
        (lambda: ball().solve(force=100.0).to_dict(criterion=3), "invalid criterion = 3 (int)"),
        (lambda: kt.HalfSpace((16, 16), (1.0, 1.0), boundary=None or 1), "invalid boundary = 1 (int)"),
        (lambda: kt.run_file(3), "invalid path = 3 (int)"),
        (lambda: kt.run_toml(b"x"), "invalid text = b'x' (bytes)"),
        (lambda: kt.run_case([1]), "invalid case = [1] (list)"),
        (lambda: kt.ContactElement.from_toml(None), "invalid text = None (NoneType)"),
        (lambda: kt.Sweep.from_toml("x = 1\n", fields=3), "invalid fields = 3 (int)"),
        (lambda: kt.HalfSpace((16, 16), (1.0, 1.0)).solve(object(), external_force=1.0), "invalid gap = <object object"),
    ]
    for call, words in cases:
        with pytest.raises((TypeError, kt.InputError)) as e:
            call()
        one_line(e.value, words, ": expected ")


def test_defaults_are_unchanged():
    """Arguments taken as objects keep their documented defaults (stubtest checks the
    signatures; these check the values)."""
    assert kt.HertzPoint((6.0, 6.0), (math.inf, math.inf)).solve(force=1.0).orientation == 0.0
    x = (np.arange(16) + 0.5) / 8.0 - 1.0
    bowl = (x[None, :] ** 2 + x[:, None] ** 2) / 200.0
    r = kt.HalfSpace((16, 16), (2.0, 2.0)).solve(bowl, external_force=300.0)
    assert r.converged and r.residual <= 1e-8 and r.to_dict()["geometry"].startswith("gap map")
    d = ball().solve(force=100.0).to_dict(yield_stress=1500.0)
    assert d["inputs"]["yield_criterion"] == "von_mises"


# --- item 16: sweep takes a dict, CaseResult shows its numbers ----------------------------


def test_sweep_takes_a_dict_as_run_does(tmp_path):
    sweep = {
        "name": "two loads",
        "base": HERTZ_CASE,
        "parameter": [{"key": "load.force_n", "values": [100.0, 200.0]}],
    }
    text = kt.to_toml(sweep)
    assert "[base.load]" in text and "force_n = 100.0" in text
    table = kt.sweep(sweep, tmp_path / "dict", format="csv")
    rows = list(csv.DictReader(open(table)))
    assert [float(r["load.force_n"]) for r in rows] == [100.0, 200.0]
    assert [r["status"] for r in rows] == ["ok", "ok"]
    # the same as the TOML text of the dict
    again = kt.sweep(text, tmp_path / "text", format="csv")
    assert list(csv.DictReader(open(again))) == rows
    with pytest.raises(TypeError) as e:
        kt.sweep(3, tmp_path / "x")  # type: ignore[arg-type]
    one_line(e.value, "invalid definition = 3 (int)")


def test_case_result_repr_shows_the_main_numbers_and_warnings():
    r = kt.run(HERTZ_CASE)
    text = repr(r)
    assert str(r) == text and "\n" not in text
    assert text.startswith('CaseResult(method="hertz", force_n=100, max_pressure_mpa=1855.6, ')
    assert "semi_axes_mm=[0.160409, 0.160409]" in text and text.endswith("warnings=[])")
    friction = kt.run(REPO / "examples/rib_friction.toml")
    text = repr(friction)
    assert 'method="friction"' in text and "axial_load_n=15000" in text and "rows=<" in text
    assert all(w in text for w in friction.warnings)
