"""Parameter sweeps from Python, locally or on a Dask cluster (docs/sweep.md, docs/python.md).

A sweep is split into chunks of thousands of cases (one contact solve is far cheaper than a
Dask task). Each chunk is computed by the Rust library, its cases in parallel, and written
atomically as ``OUT/chunks/chunk-NNNNNN.parquet``; ``OUT/sweep.json`` records the sweep's
hash, so a directory holding another sweep is refused. A rerun computes only the missing
chunks, whether the interruption was a Ctrl-C, a killed process or a lost Dask worker, and
the final ``OUT/results.parquet`` (or ``.csv``) has every case exactly once, in case order.
The files are those of ``kontakt sweep``: a sweep started from one side resumes from the other.
"""

from __future__ import annotations

import os
from pathlib import Path
from typing import Any, Callable, Mapping, Sequence

from ._kontakt import Sweep, to_toml

__all__ = ["sweep"]

# What a worker needs to rebuild the sweep: ("file", path, max_cases, fields) or
# ("toml", text, base_dir, max_cases, fields). Plain strings and numbers, so Dask can ship them.
_Source = tuple[Any, ...]


def _load(source: _Source) -> Sweep:
    if source[0] == "file":
        return Sweep.from_file(source[1], source[2], source[3])
    return Sweep.from_toml(source[1], source[2], source[3], source[4])


def _run_chunk(source: _Source, index: int, out: str) -> dict[str, Any]:
    """One chunk on a worker: rebuild the sweep from its source and run the chunk on as many
    threads as the worker has (``nthreads``), so that the workers of one machine share its
    cores instead of each starting a thread per core."""
    threads: int | None = None
    try:
        from dask.distributed import get_worker

        threads = max(1, int(get_worker().state.nthreads))
    except (ImportError, ValueError, AttributeError):
        threads = None
    return _load(source).run_chunk(index, out, threads)


def sweep(
    definition: Mapping[str, Any] | str | os.PathLike[str],
    out: str | os.PathLike[str],
    *,
    client: Any = None,
    format: str = "parquet",
    max_cases: int | None = None,
    base_dir: str | os.PathLike[str] = ".",
    retries: int = 3,
    fields: str | None = None,
    on_chunk: Callable[[dict[str, Any]], None] | None = None,
) -> str:
    """Run a sweep into the folder ``out`` and return the path of the combined table.

    ``definition`` is a sweep file (TOML, docs/sweep.md), TOML text (a string with a
    newline) or a dict with the keys of a sweep file (as ``kontakt.run`` takes a case dict);
    the relative paths of text and dicts are taken from ``base_dir``. Without ``client``
    the missing chunks run here, one after the other, each on all local cores. With a
    ``dask.distributed.Client`` each missing chunk is one task on the cluster (``retries``
    more tries on an error; a task on a worker that dies is rescheduled by Dask); the
    workers need the ``kontakt`` package and access to ``out``. ``on_chunk`` is called with
    each finished chunk's summary (``index``, ``cases``, ``not_ok``, ``path``, ``seconds``).
    ``format`` is ``"parquet"`` or ``"csv"`` for the combined table. ``fields="npy"``
    also stores every case's fields (pimp and bem cases: pressure [MPa]; bem also the
    displacement and the gap [mm]) as ``out/fields/chunk-NNNNNN/case-NNNNNNNNN-<field>.npy``
    (float64, shape ``[ny, nx]``, the grid of the row's ``grid.*`` columns); ``None`` keeps
    the sweep file's ``fields`` (default ``"none"``).

    Raises ``kontakt.InputError`` for a bad sweep file or an ``out`` that holds another
    sweep, ``OSError`` when a file cannot be written.
    """
    source: _Source
    if isinstance(definition, Mapping):
        source = ("toml", to_toml(dict(definition)), os.fspath(base_dir), max_cases, fields)
    elif isinstance(definition, (str, os.PathLike)):
        text = os.fspath(definition)
        if "\n" in text:
            source = ("toml", text, os.fspath(base_dir), max_cases, fields)
        else:
            source = ("file", text, max_cases, fields)
    else:
        raise TypeError(
            f"invalid definition = {definition!r} ({type(definition).__name__}): "
            "expected a sweep file path, TOML text or a dict"
        )
    s = _load(source)
    out_dir = os.fspath(Path(out))
    s.prepare(out_dir)
    missing: Sequence[int] = s.missing_chunks(out_dir)
    if client is None:
        for index in missing:
            summary = s.run_chunk(index, out_dir)
            if on_chunk is not None:
                on_chunk(summary)
    elif missing:
        from dask.distributed import as_completed

        futures = client.map(
            _run_chunk,
            [source] * len(missing),
            list(missing),
            [out_dir] * len(missing),
            pure=False,
            retries=retries,
        )
        for future in as_completed(futures):
            summary = future.result()
            if on_chunk is not None:
                on_chunk(summary)
    return s.combine(out_dir, format)
