"""Fuzzing of kontakt.BearingElement with the harness of test_fuzz.py (docs/RELIABILITY.md):
hostile displacements, velocities and damping give finite results or a documented, named
error; never a panic, NaN or inf. Deterministic, like the rest of the harness."""

from __future__ import annotations

import pathlib

import numpy as np
from hypothesis import given
from hypothesis import strategies as st
from test_fuzz import FUZZ, call, finite_result, hostile, mostly

import kontakt as kt

REPO = pathlib.Path(__file__).resolve().parents[3]
ELEMENTS = [kt.BearingElement(REPO / f"examples/{name}.toml") for name in ("bearing_32008x", "bearing_nu_crb", "bearing_7205")]

# displacements about the loaded range (tens of µm, tenths of mrad), sometimes far beyond
# the validity (a ball's diameter), sometimes hostile
component = mostly(st.floats(-0.05, 0.05), st.one_of(st.floats(-20.0, 20.0), hostile))
tilt = mostly(st.floats(-1e-3, 1e-3), st.one_of(st.floats(-1.0, 1.0), hostile))
real = mostly(st.floats(-0.05, 0.05), st.floats(allow_nan=True, allow_infinity=True))
five = st.one_of(
    st.tuples(component, component, component, tilt, tilt),
    # float64 arrays of shape (5,), the fast path read without the item checks
    st.tuples(real, real, real, real, real).map(lambda t: np.array(t, dtype=float)),
    hostile,
    st.lists(st.floats(-0.01, 0.01), max_size=6),
)
velocity = st.one_of(st.none(), five, st.tuples(*[mostly(st.floats(-1e4, 1e4))] * 5))
damping = st.one_of(st.none(), mostly(st.floats(0.0, 1e-3)))


@FUZZ
@given(which=st.integers(0, len(ELEMENTS) - 1), displacement=five, v=velocity, beta=damping, reset=st.booleans())
def test_bearing_element_evaluate(which, displacement, v, beta, reset):
    e = ELEMENTS[which]
    if reset:
        e.reset()
    if beta is not None:
        call(setattr, e, "damping_s", beta, _fields={"damping_s"})
    finite_result(call(e.evaluate, displacement, v, _fields={"displacement", "velocity"}))
