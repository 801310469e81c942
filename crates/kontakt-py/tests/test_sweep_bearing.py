"""kontakt.sweep of bearing cases (issue 28): the rows of a load sweep are the equilibria
of kontakt.Bearing, the same locally and on a Dask LocalCluster; a case whose elements
all lift off is a `lifted_off` row with zero force, not an error."""

from __future__ import annotations

import csv
from pathlib import Path

import pytest

import kontakt as kt

ROOT = Path(__file__).resolve().parents[3]
TRB_SWEEP = ROOT / "examples" / "sweeps" / "bearing_trb_loads.toml"
CRB_SWEEP = ROOT / "examples" / "sweeps" / "bearing_crb_lift_off.toml"


def read_rows(path: str) -> list[dict[str, str]]:
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


def test_trb_rows_are_the_bearing_equilibria(tmp_path: Path) -> None:
    rows = read_rows(kt.sweep(TRB_SWEEP, tmp_path / "trb", format="csv"))
    assert [int(r["case"]) for r in rows] == list(range(165))
    assert {r["status"] for r in rows} == {"ok"}
    base = ROOT / "examples" / "bearing_32008x.toml"
    text = base.read_text()
    for r in rows[::16]:
        case = text.replace("clearance_mm = 0.0", f"clearance_mm = {r['bearing.clearance_mm']}")
        b = kt.Bearing(_toml(case))
        rep = b.solve(
            force=(float(r["load.force_n[0]"]), 0.0, float(r["load.force_n[2]"])),
            hold_tilts=True,
        ).to_dict()
        q = rep["max_roller_load_n"]
        assert float(r["max_element_load_n"]) == pytest.approx(q, rel=1e-9)
        for i in range(3):
            assert float(r[f"displacement_mm[{i}]"]) == pytest.approx(
                rep["displacement_mm"][i], rel=1e-9, abs=1e-12
            )
        assert float(r["stiffness_z_n_per_mm"]) == pytest.approx(
            rep["stiffness_matrix"][2][2], rel=1e-8
        )


def _toml(text: str) -> dict:
    import tomllib

    return tomllib.loads(text)


def test_lifted_off_is_a_row_not_an_error(tmp_path: Path) -> None:
    rows = read_rows(kt.sweep(CRB_SWEEP, tmp_path / "crb", format="csv"))
    assert len(rows) == 62
    for r in rows:
        off = float(r["load.prescribed.dx_mm"]) <= 0.01 + 1e-15
        assert r["status"] == ("lifted_off" if off else "ok"), r
        assert r["error"] == ""
        if off:
            assert float(r["force_n[0]"]) == 0.0
            assert r["warnings"] == "every roller is lifted off: zero load"


def test_dask_bearing_sweep_equals_the_local_one(client, tmp_path: Path) -> None:
    # chunks of 40 cases: 5 Dask tasks, each chunk cut across the warm-start blocks the
    # same way locally and remotely, so the rows are equal bit for bit
    text = TRB_SWEEP.read_text().replace(
        'base = "../bearing_32008x.toml"',
        f'base = "{(ROOT / "examples" / "bearing_32008x.toml").as_posix()}"\nchunk_size = 40',
    )
    local = read_rows(kt.sweep(text, tmp_path / "local", format="csv"))
    remote = read_rows(kt.sweep(text, tmp_path / "dask", client=client, format="csv"))
    assert remote == local
    assert len(local) == 165
