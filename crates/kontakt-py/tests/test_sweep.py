"""kontakt.sweep: local and on a Dask LocalCluster, resumable, each case exactly once; the
Hertz rows against Johnson's closed form; a lost worker loses no results."""

from __future__ import annotations

import csv
import math
import os
from pathlib import Path

import pytest

import kontakt as kt

ROOT = Path(__file__).resolve().parents[3]
E_STAR = 210000.0 / (2.0 * (1.0 - 0.3**2))  # steel on steel [MPa]


def sweep_text(chunk_size: int, count: int = 200, radii: str = "3.175, 6.35, 12.7") -> str:
    """The Hertz load sweep of examples/sweeps with a chosen chunk size."""
    base = (ROOT / "examples" / "ball_on_flat.toml").as_posix()
    return f"""
name = "ball on flat"
mode = "grid"
chunk_size = {chunk_size}
base = "{base}"

[[parameter]]
key = ["body1.radii_mm[0]", "body1.radii_mm[1]"]
name = "ball_radius_mm"
values = [{radii}]

[[parameter]]
key = "load.force_n"
start = 1.0
stop = 10000.0
count = {count}
spacing = "log"
"""


def read_rows(path: str) -> list[dict[str, str]]:
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


def check_hertz_rows(rows: list[dict[str, str]], n: int) -> None:
    """Every case once, in order; p0 = (6 F E*² / π³ R²)^(1/3), Hertz (Johnson 1985, ch. 4)."""
    assert [int(r["case"]) for r in rows] == list(range(n))
    for r in rows:
        # Solved; "warning" with the report's warnings (above first yield).
        assert r["status"] == ("warning" if r.get("warnings[0]") else "ok"), r
        force = float(r["load.force_n"])
        radius = float(r["ball_radius_mm"])
        p0 = (6.0 * force * E_STAR**2 / (math.pi**3 * radius**2)) ** (1.0 / 3.0)
        assert float(r["max_pressure_mpa"]) == pytest.approx(p0, rel=1e-12)


def test_local_sweep_matches_the_closed_form_and_resumes(tmp_path: Path) -> None:
    out = tmp_path / "local"
    done: list[int] = []
    path = kt.sweep(sweep_text(100), out, format="csv", on_chunk=lambda s: done.append(s["index"]))
    assert Path(path).name == "results.csv"
    assert done == list(range(6))
    check_hertz_rows(read_rows(path), 600)
    # Lose two chunks: the rerun computes exactly those and the table is whole again.
    for i in (1, 4):
        (out / "chunks" / f"chunk-{i:06d}.parquet").unlink()
    again: list[int] = []
    path = kt.sweep(sweep_text(100), out, format="csv", on_chunk=lambda s: again.append(s["index"]))
    assert again == [1, 4]
    check_hertz_rows(read_rows(path), 600)
    # Nothing missing: nothing computed.
    third: list[int] = []
    kt.sweep(sweep_text(100), out, format="csv", on_chunk=lambda s: third.append(s["index"]))
    assert third == []


def test_the_sweep_object_and_bad_input(tmp_path: Path) -> None:
    s = kt.Sweep.from_toml(sweep_text(64))
    assert len(s) == 600 and s.chunk_size == 64 and s.chunk_count == 10
    assert s.chunk_range(9) == (576, 600)
    with pytest.raises(kt.InputError):
        s.chunk_range(10)
    # A directory holding another sweep is refused.
    kt.sweep(sweep_text(100, count=2), tmp_path / "a", format="csv")
    with pytest.raises(kt.InputError, match="sweep"):
        kt.sweep(sweep_text(100, count=3), tmp_path / "a")
    # An unknown key, an empty range, a sweep above max_cases.
    with pytest.raises(kt.InputError, match="load.force_nn"):
        kt.Sweep.from_toml(sweep_text(100).replace('"load.force_n"', '"load.force_nn"'))
    with pytest.raises(kt.InputError, match="count"):
        kt.Sweep.from_toml(sweep_text(100, count=0))
    with pytest.raises(kt.InputError, match="max_cases|cases"):
        kt.Sweep.from_toml(sweep_text(100), max_cases=10)
    with pytest.raises(kt.InputError, match="format"):
        kt.sweep(sweep_text(100, count=2), tmp_path / "a", format="xlsx")


def test_dask_sweep_equals_the_local_one(client, tmp_path: Path) -> None:
    local = read_rows(kt.sweep(sweep_text(50), tmp_path / "local", format="csv"))
    remote = read_rows(kt.sweep(sweep_text(50), tmp_path / "dask", client=client, format="csv"))
    assert remote == local
    check_hertz_rows(remote, 600)


def test_a_lost_worker_loses_no_results(client, tmp_path: Path) -> None:
    """One worker process is killed after the first chunk is in; Dask reschedules what it
    held (its nanny starts a new one) and the table still has every case exactly once."""
    killed: list[str] = []

    def kill_one(summary: dict) -> None:
        if not killed:
            victim = sorted(client.scheduler_info()["workers"])[0]
            killed.append(victim)
            try:
                client.run(os._exit, 1, workers=[victim])
            except Exception:
                pass  # the worker died while answering: that is the point

    # 20 chunks of 400 cases: tens of milliseconds each, so most are queued or running
    # when the worker dies.
    text = sweep_text(400, count=2000, radii="3.175, 6.35, 12.7, 25.4")
    path = kt.sweep(text, tmp_path / "lost", client=client, format="csv", on_chunk=kill_one)
    assert killed
    assert killed[0] not in client.scheduler_info()["workers"], "the worker did not die"
    check_hertz_rows(read_rows(path), 8000)


def test_fields_npy_holds_each_case_pressure(tmp_path: Path) -> None:
    """fields="npy": one float64 [ny, nx] pressure file per PimP case whose integral is the
    row's force and whose maximum is the row's peak (the same files as `kontakt sweep
    --fields npy`); a Hertz sweep has no field and is refused with field = "sweep"."""
    import numpy as np

    out = tmp_path / "fields"
    path = kt.sweep(
        ROOT / "examples" / "sweeps" / "pimp_roller_rib.toml", out, format="csv", fields="npy"
    )
    rows = read_rows(path)
    assert len(rows) == 14
    for r in rows:
        p = np.load(out / "fields" / "chunk-000000" / f"case-{int(r['case']):09d}-pressure.npy")
        assert p.dtype == np.float64
        assert p.shape == (int(r["grid.cells[1]"]), int(r["grid.cells[0]"]))
        cell = float(r["grid.cell_mm[0]"]) * float(r["grid.cell_mm[1]"])
        assert p.sum() * cell == pytest.approx(float(r["force_n"]), rel=1e-9)
        assert p.max() == float(r["max_pressure_mpa"])
    with pytest.raises(kt.InputError, match="no field") as e:
        kt.sweep(sweep_text(4096, count=2), tmp_path / "hertz", fields="npy")
    assert e.value.field == "sweep"
    with pytest.raises(kt.InputError) as e:
        kt.sweep(sweep_text(4096, count=2), tmp_path / "hertz", fields="zarr")
    assert e.value.field == "fields"


def test_run_chunk_on_a_given_number_of_threads(tmp_path: Path) -> None:
    """run_chunk(threads=1) (what a Dask worker with one thread calls) writes the same rows
    as on all cores; threads = 0 or above the library's bound is an InputError."""
    s = kt.Sweep.from_toml(sweep_text(300, count=200), ".")
    one, all_ = tmp_path / "one", tmp_path / "all"
    for out, threads in [(one, 1), (all_, None)]:
        s.prepare(out)
        for i in range(s.chunk_count):
            s.run_chunk(i, out, threads)
    a = read_rows(s.combine(one, "csv"))
    b = read_rows(s.combine(all_, "csv"))
    assert a == b and len(a) == 600
    for bad in (0, 100_000):
        with pytest.raises(kt.InputError) as e:
            s.run_chunk(0, one, bad)
        assert e.value.field == "threads"
