#!/usr/bin/env python3
"""Solve the Hertz benchmark with one peer code and print one JSON object.

    .venv/bin/python peers.py --code slippy --n 256 --tol 1e-8 --repeat 5

The problem (the same one `crates/kontakt/examples/bem_peer.rs` solves): a sphere of radius R
on a flat, both steel, under a normal force F; a square domain of side `domain * a` centred on
the contact, N x N cells, gap h = r^2 / (2R) sampled at the cell centres, free (non-periodic)
boundary, load control. Units mm, N, MPa.

Every peer is run cold: the solver state is rebuilt (or its pressure reset) before every timed
solve, and what can be planned once (influence matrix, FFT plans, the periodic model) is built
outside the timing, as for kontakt. `seconds` is the best of `--repeat` solves; `plan_seconds`
is the set-up, including importing the package.

The JSON has the same keys as kontakt's example: code, n, threads, iterations, seconds,
plan_seconds, p_max, approach, area, converged; plus the Hertz values and relative errors
(see `hertz` and `with_errors`), so that every number in the report is computed in one place.
"""

from __future__ import annotations

import os

# One thread everywhere, set before numpy / numba / FFTW load.
for _var in ("OMP_NUM_THREADS", "OPENBLAS_NUM_THREADS", "MKL_NUM_THREADS",
             "NUMBA_NUM_THREADS", "VECLIB_MAXIMUM_THREADS", "NUMEXPR_NUM_THREADS"):
    os.environ[_var] = "1"

import argparse  # noqa: E402
import json  # noqa: E402
import math  # noqa: E402
import sys  # noqa: E402
import time  # noqa: E402
from dataclasses import dataclass  # noqa: E402

import numpy as np  # noqa: E402

PEERS = ("tamaas", "contactmechanics", "slippy")


# --------------------------------------------------------------------------------------------
# The problem and its analytic solution
# --------------------------------------------------------------------------------------------

@dataclass(frozen=True)
class Problem:
    radius: float = 10.0        # mm
    force: float = 300.0        # N
    young: float = 210000.0     # MPa, both bodies
    poisson: float = 0.3        # both bodies
    domain: float = 8.0         # side of the square domain, in Hertz radii
    n: int = 256                # cells per side

    @property
    def e_star(self) -> float:
        """Contact modulus 1/E* = (1-nu1^2)/E1 + (1-nu2^2)/E2 (MPa)."""
        return self.young / (2.0 * (1.0 - self.poisson ** 2))

    def hertz(self) -> dict:
        a = (3.0 * self.force * self.radius / (4.0 * self.e_star)) ** (1.0 / 3.0)
        return {
            "a": a,
            "p0": 3.0 * self.force / (2.0 * math.pi * a * a),
            "delta": a * a / self.radius,
            "area": math.pi * a * a,
        }

    @property
    def side(self) -> float:
        return self.domain * self.hertz()["a"]

    @property
    def dx(self) -> float:
        return self.side / self.n

    def centres(self) -> np.ndarray:
        """Cell-centre coordinates along one axis, origin at the contact centre."""
        return (np.arange(self.n) + 0.5) * self.dx - 0.5 * self.side

    def gap(self) -> np.ndarray:
        """Initial gap h = r^2/(2R) at the cell centres (N x N, mm)."""
        x = self.centres()
        return (x[:, None] ** 2 + x[None, :] ** 2) / (2.0 * self.radius)


# --------------------------------------------------------------------------------------------
# A free-space operator of our own: used to recompute the approach from a peer's pressure
# where the peer does not give a free-space approach (tamaas is periodic, slippy gives none).
# Uniform pressure on each square cell (Love 1929), displacement at the cell centres, linear
# convolution by zero padding to 2N x 2N. This is the operator kontakt and ContactMechanics use.
# --------------------------------------------------------------------------------------------

def love_kernel(n: int, dx: float, e_star: float) -> np.ndarray:
    """Displacement at offsets (i, j) * dx from a unit pressure on a dx x dx cell, wrapped on 2n."""
    idx = np.arange(2 * n)
    idx = np.where(idx <= n, idx, idx - 2 * n) * dx
    x = idx[:, None]
    y = idx[None, :]
    h = 0.5 * dx

    # Integral of 1/r over the cell by the corner formula G(x+h, y+h) - G(x-h, y+h) - G(x+h, y-h)
    # + G(x-h, y-h), with the antiderivative G(u, v) = u ln(v + r) + v ln(u + r), r = |(u, v)|.
    # Cell corners are never at the origin: u, v are odd multiples of h.
    def g(u, v):
        r = np.sqrt(u * u + v * v)
        return u * np.log(v + r) + v * np.log(u + r)

    integral = g(x + h, y + h) - g(x - h, y + h) - g(x + h, y - h) + g(x - h, y - h)
    return integral / (math.pi * e_star)


class FreeOperator:
    def __init__(self, n: int, dx: float, e_star: float):
        self.n = n
        self.kernel_hat = np.fft.rfft2(love_kernel(n, dx, e_star))

    def __call__(self, p: np.ndarray) -> np.ndarray:
        n = self.n
        return np.fft.irfft2(np.fft.rfft2(p, s=(2 * n, 2 * n)) * self.kernel_hat,
                             s=(2 * n, 2 * n))[:n, :n]


def approach_from_pressure(p: np.ndarray, h: np.ndarray, op: FreeOperator) -> float:
    """Rigid approach delta = mean over the contact cells of h + u(p) (gap = h + u - delta = 0)."""
    contact = p > 0.0
    return float(np.mean((h + op(p))[contact]))


# --------------------------------------------------------------------------------------------
# Peers. Each `prepare_*` builds what may be planned once and returns a `solve()` closure that
# runs one cold solve and returns (pressure N x N in MPa, iterations or None, approach or None,
# converged).
# --------------------------------------------------------------------------------------------

def prepare_tamaas(pb: Problem, tol: float):
    """tamaas PolonskyKeerRey on a 2N x 2N periodic model (the wheels have no free boundary).

    The N x N body sits in one quarter of a periodic cell twice its size, so the nearest
    periodic image of the contact is 2 * domain * a away. The pressure is reset before each
    solve (tamaas otherwise warm-starts), and the approach is recomputed from the pressure with
    the free-space operator, because tamaas measures its own against the periodic mean.
    """
    import tamaas as tm

    tm.set_log_level(tm.LogLevel.error)
    n, m = pb.n, 2 * pb.n
    model = tm.ModelFactory.createModel(tm.model_type.basic_2d, [2 * pb.side, 2 * pb.side], [m, m])
    # Rigid indenter on an elastic half-space of modulus E*: nu = 0, E = E*.
    model.E = pb.e_star
    model.nu = 0.0
    h = pb.gap()
    surface = np.full((m, m), -h.max())
    surface[:n, :n] = -h                      # tamaas: heights, contact where highest
    solver = tm.PolonskyKeerRey(model, surface, tol)
    solver.max_iter = 100000
    mean_pressure = pb.force / (2.0 * pb.side) ** 2
    op = FreeOperator(n, pb.dx, pb.e_star)

    def cold_solve():
        model.traction[...] = 0.0
        model.displacement[...] = 0.0
        t0 = time.perf_counter()
        solver.solve(mean_pressure)
        return time.perf_counter() - t0

    def solve():
        t = cold_solve()
        p_full = np.array(model.traction, copy=True).reshape(m, m)
        p = p_full[:n, :n]
        outside = float(np.abs(p_full).sum() - np.abs(p).sum())
        if outside > 1e-9 * np.abs(p).sum():
            raise RuntimeError("tamaas: pressure outside the N x N window")
        return t, p, None, None, True

    def iterations():
        # tamaas does not return its iteration count; it prints it at log level info. Count it
        # with one more (untimed, identical) cold solve whose C++ output is captured.
        tm.set_log_level(tm.LogLevel.info)
        solver.dump_freq = 1 << 30
        try:
            text = _capture_fd_output(cold_solve)
        finally:
            tm.set_log_level(tm.LogLevel.error)
        rows = [line.split() for line in text.splitlines()]
        its = [int(r[0]) for r in rows if len(r) == 3 and r[0].isdigit()]
        return its[-1] if its else None

    solve.iterations = iterations
    return solve, op, h


def _capture_fd_output(fn) -> str:
    """Run fn() with the process' stdout and stderr file descriptors sent to a temporary file."""
    import tempfile
    sys.stdout.flush()
    sys.stderr.flush()
    saved = (os.dup(1), os.dup(2))
    with tempfile.TemporaryFile(mode="w+") as tmp:
        try:
            os.dup2(tmp.fileno(), 1)
            os.dup2(tmp.fileno(), 2)
            fn()
        finally:
            sys.stdout.flush()
            sys.stderr.flush()
            os.dup2(saved[0], 1)
            os.dup2(saved[1], 2)
            os.close(saved[0])
            os.close(saved[1])
        tmp.seek(0)
        return tmp.read()


def prepare_contactmechanics(pb: Problem, tol: float):
    """ContactMechanics FreeFFTElasticHalfSpace + constrained_conjugate_gradients, load control.

    Tolerances (see README): penetration tolerance `tol * delta_hertz` (mm), force tolerance
    `tol * F / N^2` (N per cell), thermodynamic (relative offset change) tolerance `tol`.
    """
    from ContactMechanics import FreeFFTElasticHalfSpace
    from ContactMechanics.Optimization import constrained_conjugate_gradients

    n = pb.n
    substrate = FreeFFTElasticHalfSpace((n, n), pb.e_star, (pb.side, pb.side))
    h = pb.gap()
    heights = -h                            # rigid indenter heights (apex at 0)
    hz = pb.hertz()
    pentol = tol * hz["delta"]
    forcetol = tol * pb.force / (n * n)

    def solve():
        t0 = time.perf_counter()
        res = constrained_conjugate_gradients(
            substrate, heights, external_force=pb.force, pentol=pentol,
            forcetol=forcetol, thermotol=tol, maxiter=100000)
        t = time.perf_counter() - t0
        forces = np.asarray(res.jac)[:n, :n]    # N per cell, compressive positive
        p = forces / (pb.dx * pb.dx)
        return t, p, int(res.nit), float(res.offset), bool(res.success)

    return solve, FreeOperator(n, pb.dx, pb.e_star), h


def prepare_slippy(pb: Problem, tol: float):
    """slippy.core.polonsky_and_keer with a planned free-space FFTW convolution.

    The influence matrix is slippy's own real-space one (elastic_influence_matrix_spatial, span
    2N x 2N), so `plan_convolve` must be told `fft_im=False`; its default assumes a matrix that
    is already Fourier-transformed and silently gives wrong results with a real-space one.
    Stopping rule: Polonsky-Keer's own, relative L1 change of the pressure < tol.
    """
    import slippy
    slippy.CORES = 1                        # FFTW threads
    slippy.CUDA = False
    import slippy.core as core

    n = pb.n
    # Two steel bodies: the combined matrix of both surfaces.
    g = pb.young / (2.0 * (1.0 + pb.poisson))
    im = core.elastic_influence_matrix_spatial(
        "zz", (2 * n, 2 * n), (pb.dx, pb.dx), g, pb.poisson, shear_mod_2=g, v_2=pb.poisson)
    h = pb.gap()
    p_init = np.ones((n, n))
    conv = core.plan_convolve(p_init, im, domain=None, circular=[False, False], fft_im=False)
    # polonsky_and_keer scales the pressure so that cell_area * sum(p) = target_load: the
    # target is the total force.
    counter = {"calls": 0}

    def f(p):
        counter["calls"] += 1
        return conv(p)

    def solve():
        counter["calls"] = 0
        t0 = time.perf_counter()
        failed, p, _gap = core.polonsky_and_keer(f, p_init, h, pb.force, pb.dx, eps_0=tol,
                                                 max_it=100000)
        t = time.perf_counter() - t0
        # two convolutions per iteration
        return t, np.asarray(p), counter["calls"] // 2, None, not failed

    return solve, FreeOperator(n, pb.dx, pb.e_star), h


PREPARE = {
    "tamaas": prepare_tamaas,
    "contactmechanics": prepare_contactmechanics,
    "slippy": prepare_slippy,
}


def version_of(code: str) -> str:
    from importlib.metadata import version
    name = {"tamaas": "tamaas", "contactmechanics": "ContactMechanics", "slippy": "slippy"}[code]
    try:
        return version(name)
    except Exception:  # pragma: no cover
        return "?"


# --------------------------------------------------------------------------------------------
# Errors against Hertz: one place for every code, kontakt included (run.py calls this).
# --------------------------------------------------------------------------------------------

def with_errors(result: dict, pb: Problem) -> dict:
    hz = pb.hertz()
    out = dict(result)
    out["hertz"] = {"p0": hz["p0"], "delta": hz["delta"], "area": hz["area"], "a": hz["a"]}
    out["err_p_max"] = (result["p_max"] - hz["p0"]) / hz["p0"]
    out["err_approach"] = (result["approach"] - hz["delta"]) / hz["delta"]
    out["err_area"] = (result["area"] - hz["area"]) / hz["area"]
    return out


def run(code: str, pb: Problem, tol: float, repeat: int) -> dict:
    t0 = time.perf_counter()
    solve, op, h = PREPARE[code](pb, tol)
    plan_seconds = time.perf_counter() - t0
    best = math.inf
    for _ in range(max(1, repeat)):
        t, p, iterations, approach, converged = solve()
        best = min(best, t)
    if iterations is None and hasattr(solve, "iterations"):
        iterations = solve.iterations()
    total = float(p.sum() * pb.dx * pb.dx)
    if approach is None:
        approach = approach_from_pressure(p, h, op)
    result = {
        "code": code,
        "version": version_of(code),
        "n": pb.n,
        "threads": 1,
        "tol": tol,
        "iterations": iterations,
        "seconds": best,
        "plan_seconds": plan_seconds,
        "p_max": float(p.max()),
        "approach": float(approach),
        "area": float(np.count_nonzero(p > 0.0) * pb.dx * pb.dx),
        "force": total,
        "converged": bool(converged),
    }
    return with_errors(result, pb)


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--code", required=True, choices=PEERS)
    ap.add_argument("--n", type=int, default=256)
    ap.add_argument("--tol", type=float, default=None,
                    help="the peer's own stopping tolerance (default: DEFAULT_TOL[code])")
    ap.add_argument("--repeat", type=int, default=3)
    ap.add_argument("--radius", type=float, default=Problem.radius)
    ap.add_argument("--force", type=float, default=Problem.force)
    ap.add_argument("--domain", type=float, default=Problem.domain)
    args = ap.parse_args(argv)
    pb = Problem(radius=args.radius, force=args.force, domain=args.domain, n=args.n)
    tol = DEFAULT_TOL[args.code] if args.tol is None else args.tol
    print(json.dumps(run(args.code, pb, tol, args.repeat)))
    return 0


# Stopping tolerances, each in the peer's own measure, chosen so that every code is converged
# to well below the discretisation error (see README, "Tolerances"; `run.py --calibrate`).
DEFAULT_TOL = {
    "tamaas": 1e-9,
    "contactmechanics": 1e-8,
    "slippy": 1e-8,
}

if __name__ == "__main__":
    sys.exit(main())
