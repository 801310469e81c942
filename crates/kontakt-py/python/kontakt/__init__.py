"""kontakt: contact mechanics for rolling bearings (Python bindings of the Rust library).

Units: mm, N, MPa, mm/s, rad/s; angles in radians in the API, degrees in case files and
case dicts (as ``kontakt solve`` reads them). See docs/python.md.
"""

from __future__ import annotations

import os
from typing import Any, Mapping

from ._sweep import sweep
from ._kontakt import (
    Bearing,
    BearingElement,
    BearingElementResult,
    BearingResult,
    CaseResult,
    ContactElement,
    ConvergenceError,
    ElementResult,
    HalfSpace,
    HalfSpaceResult,
    HertzLine,
    HertzLineResult,
    HertzPoint,
    HertzPointResult,
    InputError,
    Material,
    Sweep,
    __version__,
    run_case,
    run_file,
    run_toml,
    to_toml,
)

__all__ = [
    "Bearing",
    "BearingElement",
    "BearingElementResult",
    "BearingResult",
    "CaseResult",
    "ContactElement",
    "ConvergenceError",
    "ElementResult",
    "HalfSpace",
    "HalfSpaceResult",
    "HertzLine",
    "HertzLineResult",
    "HertzPoint",
    "HertzPointResult",
    "InputError",
    "Material",
    "Sweep",
    "__version__",
    "run",
    "run_case",
    "run_file",
    "run_toml",
    "sweep",
    "to_toml",
]


def run(case: Mapping[str, Any] | str | os.PathLike[str]) -> CaseResult:
    """Run a case of any method (docs/case-schema.md) through the library's one dispatch.

    ``case`` is a dict with the keys of a case file, a path to a ``.toml`` case file, or
    TOML text (a string containing a newline). The result's ``to_dict()`` has the keys of
    ``kontakt solve CASE --json``.
    """
    if isinstance(case, Mapping):
        # the dict itself, not a copy: an error names the path from it (a dict that contains
        # itself is refused at the first repeat, `case.geometry.self`)
        return run_case(case if isinstance(case, dict) else dict(case))
    if isinstance(case, str) and "\n" in case:
        return run_toml(case)
    return run_file(os.fspath(case))
