import pathlib
import sys
import threading
import time

import pytest

REPO = pathlib.Path(__file__).resolve().parents[3]


@pytest.fixture
def repo() -> pathlib.Path:
    return REPO


@pytest.fixture(scope="module")
def client():
    """A Dask LocalCluster of two worker processes, one per test module that asks for it
    (test_sweep.py, test_sweep_bearing.py)."""
    # dask.distributed is pinned by tools/test: a missing install fails here, never skips.
    from dask.distributed import Client, LocalCluster

    cluster = LocalCluster(
        n_workers=2, threads_per_worker=1, processes=True, dashboard_address=None
    )
    c = Client(cluster)
    yield c
    c.close()
    cluster.close()


def gil_fractions(call, n: int = 5) -> list[float]:
    """For each of n calls of `call(i)`: when, as a fraction of the call's time, a Python
    thread that ticks in a loop first ran after the call started. A call that releases the
    GIL lets the thread run early in it; one that holds the GIL only after it (measured:
    at 80 % of the call's time)."""
    ticks: list[float] = []
    stop = threading.Event()

    def tick():
        while not stop.is_set():
            ticks.append(time.perf_counter())

    interval = sys.getswitchinterval()
    sys.setswitchinterval(0.001)
    t = threading.Thread(target=tick)
    t.start()
    try:
        fractions = []
        for i in range(n):
            t0 = time.perf_counter()
            call(i)
            t1 = time.perf_counter()
            first = next((x for x in ticks[-2000000:] if x > t0), t1)
            fractions.append((first - t0) / (t1 - t0))
    finally:
        stop.set()
        t.join()
        sys.setswitchinterval(interval)
    return fractions
