#!/usr/bin/env python3
"""Roller loads of a cylindrical roller bearing under radial load from an independent
implementation: ``fcylrolbear`` of Moritz Ploss's ``tribology`` package
(https://github.com/moritzploss/tribology, tribology/roller_bearings.py, MIT licence).

The tribology source is NOT part of kontakt. Fetch it yourself and pass the directory that
contains its ``tribology/`` package folder:

    git clone https://github.com/moritzploss/tribology <SRC>
    python3 -m venv <VENV> && <VENV>/bin/pip install numpy scipy numexpr
    <VENV>/bin/python tools/reference/crb_fcylrolbear.py --tribology <SRC> [--commit HASH]
    <VENV>/bin/python tools/reference/crb_fcylrolbear.py --tribology <SRC> --check

(or set TRIBOLOGY_SRC instead of --tribology). The PyPI package pins an old numpy; the
source imports fine with a recent one. Only ``tribology.roller_bearings`` and the module it
imports (``tribology.boundary_element``, which needs numpy, scipy and numexpr at import
time) are loaded; the package's ``__init__`` (which imports everything) is bypassed.

Output (read by crates/kontakt-bearing/tests/fcylrolbear.rs):

* crates/kontakt-bearing/tests/data/crb_fcylrolbear.csv: one row per roller and case;
* crates/kontakt-bearing/tests/data/crb_fcylrolbear_profile.csv: the combined profile
  handed to fcylrolbear for the crowned cases, slice by slice.

The header comment of the first file records the tribology commit, the date and the
command. The date is today's unless SOURCE_DATE_EPOCH is set.

How the inputs map onto fcylrolbear's model (see docs/bearing-model.md, "Cross-check
against fcylrolbear"):

* ``ang_pos``: Z rollers at psi_j = 2 pi j / Z, roller 0 on the load line.
* ``ax_rol``: only its span (max - min, the roller length in the ISO stiffness
  35948 L^(8/9)) and its length (the slice count) enter fcylrolbear when the roller does
  not tilt (its tilt psi_j stays 0), so it is ``linspace(-L/2, L/2, n)``: span exactly L.
* ``comb_prof``: fcylrolbear subtracts 2 * comb_prof from the slice approach (the same
  drop on the inner and the outer contact), so comb_prof is the roller's own drop with
  straight raceways, evaluated here at the slice centres x_k = -L/2 + (k + 1/2) L/n
  (the ISO/TS 16281 logarithmic profile for L <= 2.5 D_we:
  P(x) = 0.00035 D_we ln[1 / (1 - (2x/L)^2)], computed here from that formula).
* ``rad_clear``: enters the roller approach as delta_r cos psi - rad_clear/2, i.e. it is
  the clearance of both sides together (ISO 5753 radial internal clearance, Harris's
  diametral clearance P_d), which is what kontakt calls ``clearance_mm``; negative is a
  preload in both.
* ``max_dif``: fcylrolbear iterates (secant on the ring displacement) until
  |F_r - sum_j Q_j cos psi_j| <= max_dif * F_r (a fraction, although its docstring says
  percent); the residual delta_f it returns is recorded per case.
"""

import argparse
import datetime
import importlib
import math
import os
import subprocess
import sys
import types

import numpy as np

PITCH_MM = 60.0
ROLLERS = 14
ROLLER_D_MM = 11.0
ROLLER_L_MM = 11.0
SLICES = 31
CLEARANCES_MM = [-0.010, 0.0, 0.010, 0.020]  # negative: preload
LOADS_N = [1000.0, 5000.0, 10000.0, 20000.0]
PROFILES = ["straight", "iso"]
MAX_DIF = 1e-9

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
OUT = os.path.join(ROOT, "crates", "kontakt-bearing", "tests", "data", "crb_fcylrolbear.csv")
OUT_PROFILE = os.path.join(
    ROOT, "crates", "kontakt-bearing", "tests", "data", "crb_fcylrolbear_profile.csv"
)


def load_fcylrolbear(src):
    """Import tribology.roller_bearings from the source directory without running the
    package's __init__ (which imports every module and their dependencies)."""
    pkg_dir = os.path.join(src, "tribology")
    if not os.path.isfile(os.path.join(pkg_dir, "roller_bearings.py")):
        sys.exit(f"--tribology {src}: no tribology/roller_bearings.py below it")
    pkg = types.ModuleType("tribology")
    pkg.__path__ = [pkg_dir]
    sys.modules["tribology"] = pkg
    return importlib.import_module("tribology.roller_bearings").fcylrolbear


def slice_centres(length, n):
    w = length / n
    return np.array([-0.5 * length + (k + 0.5) * w for k in range(n)])


def iso_drop(x, length, diameter):
    """ISO/TS 16281 logarithmic roller profile for L <= 2.5 D."""
    assert length <= 2.5 * diameter
    u = 2.0 * np.abs(x) / length
    return -0.00035 * diameter * np.log1p(-u * u)


def commit_of(src, given):
    if given:
        return given
    try:
        out = subprocess.run(
            ["git", "-C", src, "rev-parse", "HEAD"], capture_output=True, text=True, check=True
        )
        return out.stdout.strip()
    except (OSError, subprocess.CalledProcessError):
        return "unknown (pass --commit)"


def check(rows):
    """Compare freshly computed rows with the recorded file: the same cases, every roller
    load to 1e-12 of F_r."""
    with open(OUT, encoding="utf-8") as f:
        old = [l.strip() for l in f if not l.startswith("#")][1:]
    if len(old) != len(rows):
        sys.exit(f"check: {len(rows)} rows computed, {len(old)} recorded")
    worst = 0.0
    for a, b in zip(rows, old):
        ra, rb = a.split(","), b.split(",")
        if ra[:6] != rb[:6]:
            sys.exit(f"check: case {ra[:6]} computed, {rb[:6]} recorded")
        worst = max(worst, abs(float(ra[6]) - float(rb[6])) / float(ra[3]))
    print(f"check: largest roller-load difference {worst:.3e} F_r")
    if worst > 1e-12:
        sys.exit("check: FAILED (> 1e-12 F_r)")


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument(
        "--tribology",
        default=os.environ.get("TRIBOLOGY_SRC"),
        help="directory containing the tribology/ package source (or TRIBOLOGY_SRC)",
    )
    ap.add_argument("--commit", help="the tribology commit hash, if SRC is not a git clone")
    ap.add_argument(
        "--check",
        action="store_true",
        help="recompute and compare with the recorded roller loads, write nothing",
    )
    args = ap.parse_args()
    if not args.tribology:
        sys.exit("give --tribology DIR or TRIBOLOGY_SRC")
    fcylrolbear = load_fcylrolbear(args.tribology)
    commit = commit_of(args.tribology, args.commit)

    ang_pos = np.array([2.0 * math.pi * j / ROLLERS for j in range(ROLLERS)])
    ax_rol = np.linspace(-0.5 * ROLLER_L_MM, 0.5 * ROLLER_L_MM, SLICES)
    assert ax_rol.max() - ax_rol.min() == ROLLER_L_MM
    x = slice_centres(ROLLER_L_MM, SLICES)
    profiles = {
        "straight": np.zeros(SLICES),
        "iso": iso_drop(x, ROLLER_L_MM, ROLLER_D_MM),
    }

    rows = []
    worst = 0.0
    for prof in PROFILES:
        for clear in CLEARANCES_MM:
            for f_rad in LOADS_N:
                q, _, delta_f = fcylrolbear(
                    ang_pos, profiles[prof], ax_rol, f_rad, rad_clear=clear, max_dif=MAX_DIF
                )
                assert abs(delta_f) <= MAX_DIF * f_rad
                worst = max(worst, abs(delta_f) / f_rad)
                case = f"{prof}_c{round(clear * 1000):d}um_{f_rad / 1000:g}kN"
                for j in range(ROLLERS):
                    rows.append(
                        f"{case},{prof},{clear!r},{f_rad!r},{j},{float(ang_pos[j])!r},"
                        f"{float(q[j])!r},{float(delta_f)!r}"
                    )
                print(f"{case:24s} Q_max = {q.max():.6f} N  delta_f = {delta_f:.3e} N")

    if args.check:
        check(rows)
        return
    if "SOURCE_DATE_EPOCH" in os.environ:
        stamp = datetime.datetime.fromtimestamp(
            int(os.environ["SOURCE_DATE_EPOCH"]), datetime.timezone.utc
        )
    else:
        stamp = datetime.datetime.now(datetime.timezone.utc)
    # the command as run, with the machine-specific source directory written as <SRC>
    cmd = "python3 tools/reference/crb_fcylrolbear.py --tribology <SRC>"
    if args.commit:
        cmd += f" --commit {args.commit}"
    header = [
        "# Roller loads of a cylindrical roller bearing under radial load by fcylrolbear of",
        "# moritzploss/tribology (tribology/roller_bearings.py), an independent implementation",
        "# of the DIN/ISO 26281 (ISO/TS 16281) slice model.",
        f"# tribology commit: {commit} (package version 0.5.16 in its setup.py)",
        f"# generated: {stamp.strftime('%Y-%m-%d')} with numpy {np.__version__}, Python "
        f"{sys.version.split()[0]}",
        f"# command: {cmd}",
        f"# bearing: Z = {ROLLERS}, d_m = {PITCH_MM} mm, D_we = {ROLLER_D_MM} mm, "
        f"L_we = {ROLLER_L_MM} mm, {SLICES} slices, rollers at psi_j = 2 pi j/Z, load along psi = 0",
        "# profile straight: comb_prof = 0; iso: comb_prof = the ISO/TS 16281 roller drop at",
        "#   the slice centres (crb_fcylrolbear_profile.csv), straight raceways",
        "# clearance_mm: fcylrolbear's rad_clear (enters as delta_r cos psi - rad_clear/2; < 0: preload)",
        f"# max_dif = {MAX_DIF!r}: |F_r - sum Q_j cos psi_j| <= max_dif F_r; delta_f_n is the",
        f"#   residual fcylrolbear returned (largest |delta_f|/F_r: {worst:.3e})",
        "case,profile,clearance_mm,fr_n,roller,azimuth_rad,q_n,delta_f_n",
    ]
    with open(OUT, "w", encoding="utf-8") as f:
        f.write("\n".join(header + rows) + "\n")
    with open(OUT_PROFILE, "w", encoding="utf-8") as f:
        f.write(
            "# The combined profile comb_prof (mm) handed to fcylrolbear for profile = iso:\n"
            "# ISO/TS 16281 logarithmic roller drop 0.00035 D ln[1/(1 - (2x/L)^2)],\n"
            f"# D = {ROLLER_D_MM} mm, L = {ROLLER_L_MM} mm, at the slice centres x_k. "
            "Written by tools/reference/crb_fcylrolbear.py.\n"
            "slice,x_mm,comb_prof_mm\n"
        )
        for k in range(SLICES):
            f.write(f"{k},{float(x[k])!r},{float(profiles['iso'][k])!r}\n")
    print(f"wrote {os.path.relpath(OUT, ROOT)} and {os.path.relpath(OUT_PROFILE, ROOT)}")


if __name__ == "__main__":
    main()
