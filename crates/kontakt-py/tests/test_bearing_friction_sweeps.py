"""Friction sweeps against load and temperature in a bearing case's [operating] (issue 29 §2):
kontakt.Bearing and kontakt.run give the same rows and the same warnings (one validity
path), and the friction section's bad input is an InputError naming the key."""

import pathlib
import tomllib

import pytest

import kontakt as kt

REPO = pathlib.Path(__file__).resolve().parents[3]
CASE = REPO / "examples/bearing_32216_friction.toml"


def test_radial_sweep_of_the_model_is_the_case_run():
    case = tomllib.loads(CASE.read_text())
    reference = kt.run(CASE).to_dict()["friction"]
    load = case["load"]
    result = kt.Bearing(CASE).solve(force=load["force_n"], prescribed=load["prescribed"])
    friction = result.to_dict()["friction"]
    rows = friction["radial_load_sweep"]
    assert [row["radial_load_n"] for row in rows] == case["operating"]["sweep_radial_n"]
    assert rows[0]["loaded_rollers"] == 16 and rows[-1]["loaded_rollers"] == 11
    assert [row["total_nmm"] for row in rows] == [
        row["total_nmm"] for row in reference["radial_load_sweep"]
    ]
    assert friction["warnings"] == reference["warnings"]
    # the torque falls as the load zone shrinks (Wingertszahn et al. 2023)
    assert rows[-1]["total_nmm"] < rows[0]["total_nmm"]


def test_friction_bad_input_names_the_key():
    case = tomllib.loads(CASE.read_text())
    case["operating"]["oil_level_mm"] = 80.0
    with pytest.raises(kt.InputError, match=r"operating\.oil_level_mm"):
        kt.run(case)
    case["operating"]["oil_level_mm"] = 8.5
    case["operating"]["sweep_temperature_c"] = [50.0]
    with pytest.raises(kt.InputError, match="one sweep at a time"):
        kt.run(case)
