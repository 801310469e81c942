import pathlib

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
