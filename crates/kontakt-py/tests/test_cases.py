"""Cases through the library's one dispatch: the reports equal the CLI's JSON baselines."""

import json
import math
from pathlib import Path

import numpy as np
import pytest

import kontakt as kt

# example file -> the CLI's recorded JSON (crates/kontakt-cli/tests/reports)
EXAMPLES = {
    "ball_on_flat": "solve_ball_on_flat",
    "ball_inner_race": "solve_ball_inner_race",
    "roller_line": "solve_roller_line",
    "pimp_sphere_on_torus": "solve_pimp_sphere_on_torus",
    "roller_rib_torus_torus": "solve_roller_rib_torus_torus",
    "bem_wavy_map": "solve_bem_wavy_map",
    "traction_twin_disc": "solve_traction_twin_disc",
    "rib_friction": "solve_rib_friction",
    "mindlin_fretting": "solve_mindlin_fretting",
    "impact_oblique": "solve_impact_oblique",
    "rough_self_affine": "solve_rough_self_affine",
    "bearing_32216": "solve_bearing_32216",
}

def new_keys():
    """Keys a report may gain over its baseline: the list the CLI's report test reads."""
    root = Path(__file__).resolve().parents[3]
    text = (root / "crates/kontakt-cli/tests/reports/new_keys.txt").read_text()
    return {l.strip() for l in text.splitlines() if l.strip() and not l.startswith("#")}


NEW_KEYS = new_keys()


def same(new, old, path="report"):
    if isinstance(old, dict):
        assert isinstance(new, dict), path
        for k, v in old.items():
            if k == "kontakt_version":
                continue
            assert k in new, f"{path}.{k} missing"
            same(new[k], v, f"{path}.{k}")
        assert set(new) - set(old) <= NEW_KEYS, f"{path}: new keys {set(new) - set(old)}"
    elif isinstance(old, list):
        assert len(new) == len(old), path
        for i, (a, b) in enumerate(zip(new, old)):
            same(a, b, f"{path}[{i}]")
    else:
        assert new == old, f"{path}: {new!r} != {old!r}"


@pytest.mark.parametrize("example", sorted(EXAMPLES))
def test_examples_match_cli_baselines(repo, example):
    result = kt.run(repo / "examples" / f"{example}.toml")
    base = json.loads((repo / "crates/kontakt-cli/tests/reports" / f"{EXAMPLES[example]}.json").read_text())
    same(result.to_dict(), base)
    assert json.loads(result.to_json()) == result.to_dict()


def test_bearing_case_through_run(repo):
    """A whole bearing through the one dispatch: the rollers carry the applied radial and
    axial force (1e-9), a dict case works, and an axial load on a CRB names its key."""
    result = kt.run(repo / "examples" / "bearing_32216.toml")
    r = result.to_dict()
    assert r["method"] == "bearing" and r["solver"]["converged"]
    alpha = math.radians(r["contact_angle_deg"])
    fx = sum(row["outer_load_n"] * math.cos(alpha) * math.cos(math.radians(row["azimuth_deg"]))
             for row in r["roller_loads"])
    fz = sum(row["outer_load_n"] * math.sin(alpha) for row in r["roller_loads"])
    assert abs(fx - 20000.0) < 1e-9 * 20000.0 and abs(fz - 10000.0) < 1e-9 * 20000.0
    assert len(r["stiffness_matrix"]) == 5 and r["stiffness_units"][0][0] == "N/mm"
    case = {
        "method": "bearing",
        "bearing": {"type": "cylindrical", "pitch_diameter_mm": 60.0, "rollers": 14,
                    "roller_diameter_mm": 11.0, "roller_length_mm": 11.0},
        "load": {"force_n": [10000.0, 0.0, 500.0], "prescribed": {"tilt_x_rad": 0.0, "tilt_y_rad": 0.0}},
    }
    with pytest.raises(kt.InputError, match=r"load\.force_n\[2\]"):
        kt.run(case)
    case["load"]["force_n"][2] = 0.0
    assert kt.run(case).to_dict()["load_zone_epsilon"] > 0.0


def test_pimp_fields_and_dict_case(repo):
    case = {
        "method": "pimp",
        "geometry": {"kind": "roller_rib", "pairing": "torus-torus-14"},
        "body1": {"e_mpa": 210000.0, "nu": 0.3},
        "body2": {"e_mpa": 210000.0, "nu": 0.3},
        "load": {"force_n": 250.0},
    }
    r = kt.run(case)
    assert r.method == "pimp"
    assert r.pressure.shape == (r.y.size, r.x.size)
    d = r.to_dict()
    assert d["max_pressure_mpa"] == pytest.approx(r.pressure.max(), rel=1e-12)
    # the same case from its file gives the same record (the CLI's README numbers)
    f = kt.run(repo / "examples/roller_rib_torus_torus.toml").to_dict()
    assert d["max_pressure_mpa"] == f["max_pressure_mpa"] and d["force_n"] == 250.0


def test_dict_case_with_infinite_radius_and_numpy_values():
    r = kt.run_case({
        "contact": {"kind": "point"},
        "body1": {"radii_mm": np.array([6.35, 6.35]), "e_mpa": 210000.0, "nu": 0.3},
        "body2": {"radii_mm": [math.inf, math.inf], "e_mpa": np.float64(210000.0), "nu": 0.3},
        "load": {"force_n": 100},
    }).to_dict()
    assert r["max_pressure_mpa"] == pytest.approx(1855.6, abs=0.01)


def test_case_errors_name_the_key():
    with pytest.raises(kt.InputError) as e:
        kt.run_case({
            "contact": {"kind": "point"},
            "body1": {"radii_mm": [6.35, 6.35], "e_mpa": 210000.0, "nu": 0.3},
            "body2": {"radii_mm": [math.inf, math.inf], "e_mpa": 210000.0, "nu": 0.7},
            "load": {"force_n": 100.0},
        })
    assert e.value.field == "body2.nu" and e.value.value == "0.7"
    with pytest.raises(kt.InputError) as e:
        kt.run_toml('method = "magic"\n')
    assert e.value.field == "method"
    with pytest.raises(kt.InputError) as e:
        kt.run_toml('[contact]\nkind = "point"\ncolour = "red"\n')
    assert e.value.field == "contact.colour"
    assert str(e.value).startswith("line 3: unknown key `contact.colour`; [contact] takes")
    with pytest.raises(kt.InputError) as e:
        kt.run_file("/nonexistent/case.toml")
    assert e.value.field == "path"
    with pytest.raises(kt.InputError):
        kt.run_case({"contact": {"kind": object()}})


def groove_case(method: str, groove: float, force: float) -> dict:
    """The 6205 inner-race contact (ball 3.969 mm in a groove) as a PimP or bem case."""
    options = {"cells": [48, 48]} if method == "pimp" else {"cells": [48, 48], "threads": 1}
    return {
        "method": method,
        "geometry": {"kind": "hertz", "radii1_mm": [3.969, 3.969], "radii2_mm": [15.281, groove]},
        method: options,
        "body1": {"e_mpa": 210000.0, "nu": 0.3},
        "body2": {"e_mpa": 210000.0, "nu": 0.3},
        "load": {"force_n": force},
    }


@pytest.mark.parametrize("method", ["pimp", "bem"])
def test_field_results_carry_the_size_check(method):
    """PimP and bem results warn at a tenfold overload (docs/pimp.md §5) and refuse a
    groove conforming to within 1 µm, naming the key; a plain result has no warning."""
    plain = kt.run_case(groove_case(method, -4.128, 1000.0))
    assert plain.warnings == [] and plain.to_dict()["warnings"] == []
    heavy = kt.run_case(groove_case(method, -4.128, 10000.0))
    assert len(heavy.warnings) == 1 and heavy.warnings == heavy.to_dict()["warnings"]
    assert "radius of curvature 3.969 mm" in heavy.warnings[0]
    with pytest.raises(kt.InputError) as e:
        kt.run_case(groove_case(method, -3.970, 1000.0))
    assert e.value.field == "geometry.radii1_mm"


def test_hertz_warnings_on_case_result(repo):
    r = kt.run(repo / "examples/rib_friction.toml")
    assert r.warnings == r.to_dict()["warnings"]
    assert kt.run(repo / "examples/ball_on_flat.toml").warnings == []


def test_friction_under_combined_load_sums_over_the_rollers(repo, tmp_path):
    """issue 28 §5: the rib friction of every roller under a radial and an axial load."""
    text = (repo / "examples/rib_friction.toml").read_text()
    text = text.replace("centrifugal = true", "centrifugal = false\nradial_n = 30000.0")
    text = text.replace('models = ["hertz", "pimp", "halfspace"]', 'models = ["hertz"]')
    case = tmp_path / "combined.toml"
    case.write_text(text)
    r = kt.run(case).to_dict()
    assert r["radial_load_n"] == 30000.0 and not r["bearing"]["closed_form"]
    for row in r["rows"]:
        mine = [t for t in r["roller_table"] if t["inner_speed_rpm"] == row["speed_rpm"]]
        assert len(mine) == r["rollers"]
        power = sum(t["roller_power_w"] for t in mine)
        assert abs(row["bearing_power_w"] - power) <= 1e-12 * power
        assert all((t["cup_load_n"] == 0) == (t["roller_rib_load_n"] == 0) for t in mine)
        assert row["rib_contacts"] < r["rollers"]
