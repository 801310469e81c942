#!/usr/bin/env python3
"""Peer comparison: kontakt's half-space solver against tamaas, ContactMechanics and slippy.

    bench/peers/run.sh                         # N = 64, 128, 256, 512, 3 rounds
    bench/peers/run.sh --sizes 64,128 --rounds 2 --skip tamaas
    bench/peers/run.sh --large                 # adds N = 1024 (peers take 10-50 s per solve)

For every N it runs, in alternation and for several rounds, kontakt with 1 thread, kontakt with
2 threads and each peer, each in its own process, each timing the best of `--repeat` cold
solves. It prints a Markdown table (also written to results.md) and writes every raw result to
results.json. See README.md for the fairness rules and the tolerance mapping.
"""

from __future__ import annotations

import argparse
import datetime as _dt
import json
import os
import platform
import shutil
import statistics
import subprocess
import sys
from pathlib import Path

HERE = Path(__file__).resolve().parent
ROOT = HERE.parent.parent
sys.path.insert(0, str(HERE))

from peers import DEFAULT_TOL, PEERS, Problem, with_errors  # noqa: E402

KONTAKT_TOL = 1e-8
DEFAULT_SIZES = (64, 128, 256, 512)
LARGE_SIZE = 1024
# Codes that discretise with the same operator as kontakt (uniform pressure per cell, Love's
# influence coefficients, free boundary by zero padding): their converged solutions must agree
# to the solver tolerance, so their Hertz errors must agree too.
SAME_OPERATOR = ("kontakt", "contactmechanics", "slippy")

ONE_THREAD_ENV = {v: "1" for v in ("OMP_NUM_THREADS", "OPENBLAS_NUM_THREADS", "MKL_NUM_THREADS",
                                    "NUMBA_NUM_THREADS", "VECLIB_MAXIMUM_THREADS",
                                    "NUMEXPR_NUM_THREADS", "RAYON_NUM_THREADS")}


def parse_args(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0],
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--sizes", default=None,
                    help="comma-separated N (default 64,128,256,512)")
    ap.add_argument("--large", action="store_true", help=f"also run N = {LARGE_SIZE}")
    ap.add_argument("--rounds", type=int, default=3, help="alternating rounds per N (default 3)")
    ap.add_argument("--repeat", type=int, default=3,
                    help="cold solves per process, the best one counts (default 3)")
    ap.add_argument("--skip", default="",
                    help="comma-separated codes to leave out: kontakt, tamaas, contactmechanics, slippy")
    ap.add_argument("--tol", default="",
                    help="per-code tolerances, e.g. kontakt=1e-8,slippy=1e-8 (defaults: README)")
    ap.add_argument("--radius", type=float, default=Problem.radius)
    ap.add_argument("--force", type=float, default=Problem.force)
    ap.add_argument("--domain", type=float, default=Problem.domain)
    ap.add_argument("--kontakt-bin", default=None,
                    help="use this bem_peer binary instead of building the example")
    ap.add_argument("--no-build", action="store_true",
                    help="do not run cargo build; use target/release/examples/bem_peer as it is")
    ap.add_argument("--kontakt-threads", default="1,2",
                    help="thread counts for kontakt (default 1,2)")
    ap.add_argument("--timeout", type=float, default=900.0, help="seconds per process")
    ap.add_argument("--out-dir", default=str(HERE),
                    help="where results.md and results.json go (default bench/peers)")
    return ap.parse_args(argv)


def tolerances(spec: str) -> dict:
    tol = dict(DEFAULT_TOL)
    tol["kontakt"] = KONTAKT_TOL
    for item in filter(None, (s.strip() for s in spec.split(","))):
        code, _, value = item.partition("=")
        if code not in tol:
            raise SystemExit(f"--tol: unknown code {code!r}")
        tol[code] = float(value)
    return tol


# --------------------------------------------------------------------------------------------
# kontakt
# --------------------------------------------------------------------------------------------

def kontakt_binary(args) -> Path | None:
    if args.kontakt_bin:
        return Path(args.kontakt_bin).resolve()
    example = ROOT / "crates" / "kontakt" / "examples" / "bem_peer.rs"
    binary = ROOT / "target" / "release" / "examples" / "bem_peer"
    if not args.no_build:
        if not example.exists():
            print(f"note: {example.relative_to(ROOT)} does not exist yet: kontakt is skipped",
                  file=sys.stderr)
            return None
        if shutil.which("cargo") is None:
            print("note: cargo not found: kontakt is skipped", file=sys.stderr)
            return None
        cmd = ["cargo", "build", "--release", "-q", "-p", "kontakt", "--example", "bem_peer"]
        print("building:", " ".join(cmd), file=sys.stderr)
        done = subprocess.run(cmd, cwd=ROOT)
        if done.returncode != 0:
            print("note: the kontakt example did not build: kontakt is skipped", file=sys.stderr)
            return None
    if not binary.exists():
        print(f"note: {binary} not found: kontakt is skipped", file=sys.stderr)
        return None
    return binary


def kontakt_command(binary: Path, pb: Problem, tol: float, threads: int, repeat: int):
    return [str(binary), "--n", str(pb.n), "--tol", repr(tol), "--threads", str(threads),
            "--repeat", str(repeat), "--radius", repr(pb.radius), "--force", repr(pb.force),
            "--domain", repr(pb.domain)]


def peer_command(code: str, pb: Problem, tol: float, repeat: int):
    return [sys.executable, str(HERE / "peers.py"), "--code", code, "--n", str(pb.n),
            "--tol", repr(tol), "--repeat", str(repeat), "--radius", repr(pb.radius),
            "--force", repr(pb.force), "--domain", repr(pb.domain)]


def recorded(cmd) -> list:
    """The command as results.json records it: paths inside the repository relative to its
    root, any other absolute path (a Python outside the repository) by its file name, so the
    committed results name no machine's directories."""
    out = []
    for arg in cmd:
        p = Path(arg)
        if p.is_absolute():
            try:
                arg = p.relative_to(ROOT).as_posix()
            except ValueError:
                arg = p.name
        out.append(arg)
    return out


def run_one(cmd, timeout: float, env: dict) -> dict:
    try:
        done = subprocess.run(cmd, capture_output=True, text=True, timeout=timeout, env=env)
    except subprocess.TimeoutExpired:
        return {"error": f"timed out after {timeout:.0f} s"}
    if done.returncode != 0:
        tail = (done.stderr or done.stdout).strip().splitlines()[-5:]
        return {"error": f"exit {done.returncode}: " + " | ".join(tail)}
    for line in reversed(done.stdout.strip().splitlines()):
        line = line.strip()
        if line.startswith("{"):
            return json.loads(line)
    return {"error": "no JSON object on stdout"}


# --------------------------------------------------------------------------------------------
# Report
# --------------------------------------------------------------------------------------------

def label(entry: str) -> str:
    if entry.startswith("kontakt@"):
        t = int(entry.split("@")[1])
        return f"kontakt ({t} thread{'s' if t > 1 else ''})"
    return entry


def pct(x) -> str:
    return "—" if x is None else f"{100.0 * x:+.4f}"


def fmt_ratio(x) -> str:
    return "—" if x is None else f"{x:.2f}"


def fmt_seconds(s) -> str:
    if s is None:
        return "—"
    return f"{s * 1e3:.1f} ms" if s < 1.0 else f"{s:.2f} s"


def summarise(runs: list, entries: list, sizes: list) -> list:
    """One row per (N, entry): best time over the rounds and median paired ratios."""
    rows = []
    for n in sizes:
        by_round = {}
        for r in runs:
            if r["n"] == n and "error" not in r["result"]:
                by_round.setdefault(r["round"], {})[r["entry"]] = r["result"]
        for entry in entries:
            results = [rd[entry] for rd in by_round.values() if entry in rd]
            errors = [r["result"]["error"] for r in runs
                      if r["n"] == n and r["entry"] == entry and "error" in r["result"]]
            if not results:
                if errors:
                    rows.append({"n": n, "entry": entry, "error": errors[-1]})
                continue
            best = min(results, key=lambda x: x["seconds"])

            def paired(ref):
                ratios = [rd[entry]["seconds"] / rd[ref]["seconds"]
                          for rd in by_round.values() if entry in rd and ref in rd]
                return statistics.median(ratios) if ratios else None

            rows.append({
                "n": n, "entry": entry, "code": best["code"],
                "iterations": best.get("iterations"),
                "seconds": best["seconds"],
                "seconds_all": [x["seconds"] for x in results],
                "ratio_1t": paired("kontakt@1"),
                "ratio_2t": paired("kontakt@2"),
                "p_max": best["p_max"], "approach": best["approach"], "area": best["area"],
                "err_p_max": best["err_p_max"], "err_approach": best["err_approach"],
                "err_area": best["err_area"],
                "converged": all(x.get("converged", True) for x in results),
                "tol": best.get("tol"),
                "errors": errors,
            })
    return rows


def markdown(rows: list) -> str:
    head = ("| N | code | iterations | time | ratio to kontakt (1 thread) "
            "| ratio to kontakt (2 threads) | p_max error % | approach error % | area error % |")
    lines = [head, "|" + "---|" * 9]
    for r in rows:
        if "error" in r:
            lines.append(f"| {r['n']} | {label(r['entry'])} | failed: {r['error']} "
                         "| | | | | | |")
            continue
        it = "—" if r["iterations"] is None else str(r["iterations"])
        if not r["converged"]:
            it += " (not converged)"
        lines.append(
            f"| {r['n']} | {label(r['entry'])} | {it} | {fmt_seconds(r['seconds'])} "
            f"| {fmt_ratio(r['ratio_1t'])} | {fmt_ratio(r['ratio_2t'])} "
            f"| {pct(r['err_p_max'])} | {pct(r['err_approach'])} | {pct(r['err_area'])} |")
    return "\n".join(lines)


def consistency(rows: list) -> list:
    """Codes with the same operator must give the same p_max and approach: report the spread."""
    notes = []
    for n in sorted({r["n"] for r in rows}):
        same = [r for r in rows if r["n"] == n and "error" not in r
                and r["code"] in SAME_OPERATOR]
        if len({r["code"] for r in same}) < 2:
            continue
        for key in ("p_max", "approach"):
            vals = [r[key] for r in same]
            spread = (max(vals) - min(vals)) / abs(statistics.mean(vals))
            notes.append((n, key, spread, sorted({r["code"] for r in same})))
    return notes


def load_note(runs: list, cores) -> str:
    loads = [r["load"] for r in runs if "load" in r]
    if not loads:
        return ""
    text = (f"1-minute load average before each process: {min(loads):.1f} to {max(loads):.1f} "
            f"(median {statistics.median(loads):.1f}).")
    if cores and max(loads) > cores + 0.5:
        text += (" Other jobs shared the machine: absolute times are inflated and noisy; the "
                 "paired ratios are the figures to read.")
    return text


def machine() -> dict:
    cpu = platform.processor() or "?"
    try:
        for line in Path("/proc/cpuinfo").read_text().splitlines():
            if line.startswith("model name"):
                cpu = line.split(":", 1)[1].strip()
                break
    except OSError:
        pass
    return {"cpu": cpu, "cores": os.cpu_count(), "python": platform.python_version(),
            "platform": platform.platform()}


def main(argv=None) -> int:
    args = parse_args(argv)
    sizes = [int(s) for s in args.sizes.split(",")] if args.sizes else list(DEFAULT_SIZES)
    if args.large and LARGE_SIZE not in sizes:
        sizes.append(LARGE_SIZE)
    skip = {s.strip() for s in args.skip.split(",") if s.strip()}
    unknown = skip - {"kontakt", *PEERS}
    if unknown:
        raise SystemExit(f"--skip: unknown code(s) {sorted(unknown)}")
    tol = tolerances(args.tol)
    k_threads = [int(t) for t in args.kontakt_threads.split(",") if t.strip()]

    binary = None if "kontakt" in skip else kontakt_binary(args)
    entries = [f"kontakt@{t}" for t in k_threads] if binary else []
    entries += [p for p in PEERS if p not in skip]
    if not entries:
        raise SystemExit("nothing to run")

    env = dict(os.environ)
    env.update(ONE_THREAD_ENV)
    runs = []
    for n in sizes:
        pb = Problem(radius=args.radius, force=args.force, domain=args.domain, n=n)
        for rnd in range(args.rounds):
            # Alternate the codes, and rotate the order each round so that no code always runs
            # first (cold caches, turbo) or right after the heaviest one.
            order = entries[rnd % len(entries):] + entries[:rnd % len(entries)]
            for entry in order:
                if entry.startswith("kontakt@"):
                    threads = int(entry.split("@")[1])
                    cmd = kontakt_command(binary, pb, tol["kontakt"], threads, args.repeat)
                    run_env = dict(env)
                    run_env["RAYON_NUM_THREADS"] = str(threads)
                else:
                    cmd = peer_command(entry, pb, tol[entry], args.repeat)
                    run_env = env
                load = os.getloadavg()[0]
                res = run_one(cmd, args.timeout, run_env)
                if "error" not in res:
                    if entry.startswith("kontakt@"):
                        res.setdefault("tol", tol["kontakt"])
                        res = with_errors(res, pb)
                    msg = (f"{res['seconds']:.4f} s, {res.get('iterations')} it, "
                           f"p_max {100 * res['err_p_max']:+.4f} %")
                else:
                    msg = res["error"]
                print(f"N={n:5d} round {rnd + 1}/{args.rounds} {label(entry):22s} {msg}",
                      file=sys.stderr, flush=True)
                runs.append({"n": n, "round": rnd, "entry": entry, "cmd": recorded(cmd),
                             "load": load, "result": res})

    rows = summarise(runs, entries, sizes)
    pb0 = Problem(radius=args.radius, force=args.force, domain=args.domain)
    hz = pb0.hertz()
    table = markdown(rows)
    notes = consistency(rows)
    now = _dt.datetime.now().astimezone().isoformat(timespec="seconds")
    mach = machine()
    header = [
        f"# Peer comparison, Hertz sphere ({now})",
        "",
        f"R = {pb0.radius} mm, F = {pb0.force} N, E = {pb0.young} MPa, nu = {pb0.poisson} "
        f"(both bodies, E* = {pb0.e_star:.1f} MPa); a = {hz['a']:.6f} mm, "
        f"p0 = {hz['p0']:.3f} MPa, delta = {hz['delta']:.6e} mm. Square domain of side "
        f"{pb0.domain} a, N x N cells, free boundary, load control, one thread unless stated.",
        "",
        f"Machine: {mach['cpu']}, {mach['cores']} cores, Python {mach['python']}. "
        f"{args.rounds} alternating rounds, each process the best of {args.repeat} cold solves. "
        "Time: best over the rounds. Ratio: code time / kontakt time, median over the rounds of "
        "the paired measurements (> 1: kontakt is faster).",
        "",
        load_note(runs, mach["cores"]),
        "",
        "Tolerances: " + ", ".join(f"{c} {tol[c]:g}" for c in ["kontakt", *PEERS]
                                   if c in tol and (c != "kontakt" or binary)) + ".",
        "",
    ]
    footer = []
    if notes:
        footer += ["", "Same-operator check (kontakt, ContactMechanics, slippy discretise "
                   "identically; their p_max and approach must agree):", ""]
        for n, key, spread, codes in notes:
            footer.append(f"- N = {n}: {key} relative spread {spread:.1e} ({', '.join(codes)})")
    text = "\n".join(header) + "\n" + table + "\n" + "\n".join(footer) + "\n"
    print(text)

    out = Path(args.out_dir)
    out.mkdir(parents=True, exist_ok=True)
    (out / "results.md").write_text(text)
    (out / "results.json").write_text(json.dumps({
        "date": now, "machine": mach,
        "problem": {"radius": pb0.radius, "force": pb0.force, "young": pb0.young,
                    "poisson": pb0.poisson, "domain": pb0.domain, "hertz": hz},
        "sizes": sizes, "rounds": args.rounds, "repeat": args.repeat,
        "tolerances": tol, "summary": rows, "runs": runs,
    }, indent=1) + "\n")
    print(f"wrote {out / 'results.md'} and {out / 'results.json'}", file=sys.stderr)
    return 0


if __name__ == "__main__":
    sys.exit(main())
