#!/usr/bin/env python3
"""Check the tolerance mapping: how far each code's answer at its benchmark tolerance is from
its own fully converged answer (same code, same grid, a far tighter tolerance).

    bench/peers/.venv/bin/python bench/peers/calibrate.py --sizes 64,128,256,512
    bench/peers/.venv/bin/python bench/peers/calibrate.py --ladder --sizes 256 --only slippy

The benchmark is at equal accuracy when every code's solver error (relative change of p_max and
of the approach) is below the target (default 1e-7), i.e. far below the discretisation error
(about 2e-4 in p_max at N = 256, 5e-5 at N = 512), so the Hertz error columns of run.py compare
discretisations, not stopping rules. `--ladder` runs the decades between 1e-4 and the reference
tolerance and marks the loosest one that meets the target at that N.
"""

from __future__ import annotations

import argparse
import os
import sys

from run import (HERE, ONE_THREAD_ENV, Problem, kontakt_binary, kontakt_command, peer_command,
                 run_one, tolerances)
from peers import PEERS

# The tightest tolerance each code still terminates at (below it round-off stalls the iteration:
# tamaas at 1e-14 runs to its iteration limit at N = 256, kontakt at 1e-13 at N = 512).
REF_TOL = {"kontakt": 1e-12, "tamaas": 1e-13, "contactmechanics": 1e-12, "slippy": 1e-13}


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--sizes", default="64,128,256,512")
    ap.add_argument("--only", default="", help="comma-separated codes (default all)")
    ap.add_argument("--tol", default="", help="per-code benchmark tolerances, as for run.py")
    ap.add_argument("--ref-tol", default="", help="per-code reference tolerances, code=value,...")
    ap.add_argument("--target", type=float, default=1e-7)
    ap.add_argument("--ladder", action="store_true")
    ap.add_argument("--kontakt-bin", default=None)
    ap.add_argument("--no-build", action="store_true")
    ap.add_argument("--timeout", type=float, default=1800.0)
    args = ap.parse_args(argv)

    tol = tolerances(args.tol)
    ref = dict(REF_TOL)
    for item in filter(None, args.ref_tol.split(",")):
        code, _, value = item.partition("=")
        ref[code.strip()] = float(value)
    codes = [c for c in ("kontakt", *PEERS)
             if not args.only or c in {s.strip() for s in args.only.split(",")}]
    binary = None
    if "kontakt" in codes:
        binary = kontakt_binary(argparse.Namespace(kontakt_bin=args.kontakt_bin,
                                                   no_build=args.no_build))
        if binary is None:
            codes.remove("kontakt")
    env = dict(os.environ)
    env.update(ONE_THREAD_ENV)

    def solve(code, pb, t):
        if code == "kontakt":
            cmd = kontakt_command(binary, pb, t, 1, 1)
        else:
            cmd = peer_command(code, pb, t, 1)
        return run_one(cmd, args.timeout, env)

    print("| N | code | tolerance | iterations | p_max solver error | approach solver error "
          "| area change | meets target |")
    print("|---|---|---|---|---|---|---|---|")
    ok = True
    for n in (int(s) for s in args.sizes.split(",")):
        pb = Problem(n=n)
        for code in codes:
            r_ref = solve(code, pb, ref[code])
            if "error" not in r_ref and not r_ref.get("converged", True):
                r_ref = {"error": f"reference did not converge at {ref[code]:g}"}
            if "error" in r_ref:
                print(f"| {n} | {code} | {ref[code]:g} (reference) | failed: {r_ref['error']} "
                      "| | | | |")
                ok = False
                continue
            if args.ladder:
                ladder = [10.0 ** -k for k in range(4, 14) if 10.0 ** -k > ref[code] * 1.5]
            else:
                ladder = [tol[code]]
            met = None
            for t in ladder:
                r = solve(code, pb, t)
                if "error" in r:
                    print(f"| {n} | {code} | {t:g} | failed: {r['error']} | | | | |")
                    ok = False
                    continue
                dp = abs(r["p_max"] / r_ref["p_max"] - 1.0)
                dd = abs(r["approach"] / r_ref["approach"] - 1.0)
                da = abs(r["area"] / r_ref["area"] - 1.0)
                good = dp <= args.target and dd <= args.target and r.get("converged", True)
                mark = "yes" if good else "no"
                if good and met is None:
                    met = t
                    mark = "yes (loosest)" if args.ladder else "yes"
                if not args.ladder and not good:
                    ok = False
                print(f"| {n} | {code} | {t:g} | {r.get('iterations')} | {dp:.1e} | {dd:.1e} "
                      f"| {da:.1e} | {mark} |", flush=True)
            print(f"| {n} | {code} | {ref[code]:g} (reference) | {r_ref.get('iterations')} "
                  "| 0 | 0 | 0 | |", flush=True)
    return 0 if ok else 1


if __name__ == "__main__":
    sys.path.insert(0, str(HERE))
    sys.exit(main())
