"""Python call overhead against the Rust call, and the Dask sweep against the local one.

Run by bench/python/run.sh, which builds the extension in release and runs the criterion
benches first (their estimates are read from --criterion). Prints a Markdown table for
docs/PERFORMANCE.md. Times are per call, best of several repeats (timeit), so that the
ratios are not swamped by the noise of a shared machine.
"""

from __future__ import annotations

import argparse
import json
import os
import platform
import shutil
import tempfile
import time
import timeit
from pathlib import Path

import kontakt as kt

ROOT = Path(__file__).resolve().parents[2]


def criterion_ns(root: Path, name: str) -> float:
    est = json.loads((root / "hertz_point" / name / "new" / "estimates.json").read_text())
    return float(est["median"]["point_estimate"])


def best_ns(stmt, number: int = 200_000, repeat: int = 7) -> float:
    return min(timeit.repeat(stmt, number=number, repeat=repeat)) / number * 1e9


def sweep_text(cases: int, chunk: int) -> str:
    base = (ROOT / "examples" / "ball_on_flat.toml").as_posix()
    return f"""
name = "bench: Hertz load"
chunk_size = {chunk}
base = "{base}"
[[parameter]]
key = "load.force_n"
start = 1.0
stop = 10000.0
count = {cases}
spacing = "log"
"""


def main() -> None:
    ap = argparse.ArgumentParser()
    ap.add_argument("--criterion", type=Path, required=True)
    ap.add_argument("--cases", type=int, default=200_000)
    ap.add_argument("--chunk", type=int, default=10_000)
    ap.add_argument("--workers", type=int, default=2)
    args = ap.parse_args()

    print(f"date {time.strftime('%Y-%m-%d %H:%M UTC', time.gmtime())}, {platform.processor() or platform.machine()}, "
          f"{os.cpu_count()} cores, Python {platform.python_version()}, kontakt {kt.__version__}")

    # 1. Call overhead: the same planned Hertz contact as the criterion bench (a 6.35 mm
    #    ball on a flat, steel on steel; force 100 N, approach 1 µm).
    hp = kt.HertzPoint((6.35, 6.35), (float("inf"), float("inf")))
    rows = []
    for name, stmt in [
        ("force_from_approach_planned", lambda: hp.force_from_approach(0.001)),
        ("solve_force_planned", lambda: hp.solve(force=100.0)),
    ]:
        rust = criterion_ns(args.criterion, name)
        py = best_ns(stmt)
        rows.append((name, rust, py))
    print()
    print("| call | Rust (criterion) | Python | overhead | target |")
    print("|---|---|---|---|---|")
    for name, rust, py in rows:
        print(f"| `{name}` | {rust:.0f} ns | {py:.0f} ns | {py - rust:.0f} ns | <= 2000 ns |")

    # 2. Dask against local at equal cores, chunks of args.chunk cases.
    text = sweep_text(args.cases, args.chunk)
    tmp = Path(tempfile.mkdtemp(prefix="kontakt-bench-"))
    try:
        t0 = time.perf_counter()
        kt.sweep(text, tmp / "local")
        local = time.perf_counter() - t0

        from dask.distributed import Client, LocalCluster

        with LocalCluster(n_workers=args.workers, threads_per_worker=1, processes=True,
                          dashboard_address=":0") as cluster, Client(cluster) as client:
            client.run(lambda: __import__("kontakt"))  # workers import the package first
            t0 = time.perf_counter()
            kt.sweep(text, tmp / "dask", client=client)
            dask = time.perf_counter() - t0
    finally:
        shutil.rmtree(tmp, ignore_errors=True)
    print()
    print("| sweep | cases | chunks | local | Dask | Dask overhead | target |")
    print("|---|---|---|---|---|---|---|")
    print(f"| Hertz load | {args.cases} | {args.cases // args.chunk} of {args.chunk} | {local:.2f} s | "
          f"{dask:.2f} s | {100 * (dask / local - 1):+.0f} % | <= 15 % |")


if __name__ == "__main__":
    main()
