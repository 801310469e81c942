#!/usr/bin/env python3
"""An angular-contact ball bearing under pure axial load at speed, centrifugal force only,
from an independent implementation: the ball's two-contact equilibrium of Jones (1960) as
Harris & Kotzalas (2006) present it, with the ring's axial equilibrium, solved by SciPy's
``fsolve``; the Hertz load coefficients of both contacts from the exact Hertz theory
(complete elliptic integrals, Johnson 1985), computed here, not taken from kontakt.

Run (numpy and scipy in any virtual environment):

    python3 -m venv <VENV> && <VENV>/bin/pip install numpy scipy
    <VENV>/bin/python tools/reference/ball_speed_reference.py          # rewrite the table
    <VENV>/bin/python tools/reference/ball_speed_reference.py --check  # compare only

Output (read by crates/kontakt-bearing/src/ball_speed/tests.rs):
crates/kontakt-bearing/tests/data/ball_speed_reference.csv, one row per speed and load.

The bearing is the 7205-class example of docs/bearing-model.md section 8.5
(representative data, not a manufacturer's): d_m 38.5 mm, Z 12 balls of D 7.938 mm,
f_i 0.52, f_o 0.53, free contact angle 40 deg, steel (E 210 000 MPa, nu 0.3,
7850 kg/m^3), outer ring fixed, the inner ring turning.

Model, written out from the sources (all balls alike under pure axial load):

* Outer groove centre at the origin of the ball's axial plane (r, z); inner groove centre
  at A = (B D cos a0, B D sin a0 + dz), dz the ring's axial displacement; ball centre X.
  delta_o = |X| - (f_o - 1/2) D, delta_i = |A - X| - (f_i - 1/2) D; the contact angles
  are the directions of X and of A - X; Q = K delta^1.5 per contact.
* K_i, K_o: exact Hertz point contacts at the free contact angle: ball radii D/2,
  raceway radii along the rolling direction +-(d_m/cos a0 -+ D)/2 (inner +, outer -), across
  the groove -f D.
* Outer-race control kinematics (Harris & Kotzalas 2006): tan(beta) = sin(a_o) /
  (cos(a_o) + D/d_m); the cage speed over the inner ring's speed
  w_c/w_i = (1 - g cos a_i)(cos a_o + tan(beta) sin a_o) /
           [(1 + g cos a_o)(cos a_i + tan(beta) sin a_i) + (1 - g cos a_i)(cos a_o + tan(beta) sin a_o)],
  g = D/d_m; F_c = m d_m w_c^2 / 2, m = rho pi D^3 / 6.
* Equations: Q_i cos a_i - Q_o cos a_o + F_c = 0, Q_i sin a_i - Q_o sin a_o = 0 (no
  gyroscopic moment), Z Q_i sin a_i = F_a.
"""

import argparse
import math
import sys
from pathlib import Path

import numpy as np
from scipy.optimize import brentq, fsolve
from scipy.special import ellipe, ellipkm1

DM, Z, D, FI, FO, A0_DEG = 38.5, 12, 7.938, 0.52, 0.53, 40.0
E, NU, RHO = 210_000.0, 0.3, 7850.0
SPEEDS_RPM = [0.0, 10_000.0, 20_000.0, 40_000.0]
LOADS_N = [500.0, 3000.0]
OUT = Path(__file__).resolve().parents[2] / "crates/kontakt-bearing/tests/data/ball_speed_reference.csv"


def hertz_load_coefficient(rho_x, rho_y, e_star):
    """K in Q = K delta^1.5 of a point contact with the curvature sums rho_x, rho_y (1/mm)
    in its two principal planes, contact modulus E* (MPa)."""
    a_curv, b_curv = 0.5 * min(rho_x, rho_y), 0.5 * max(rho_x, rho_y)

    # in the axis ratio kappa = b/a (the parameter m = e^2 = 1 - kappa^2 near 1 would lose
    # digits): K from ellipkm1(1 - m)
    def integrals(kappa):
        p1 = kappa * kappa
        return 1.0 - p1, ellipkm1(p1), ellipe(1.0 - p1)

    def ratio(kappa):
        m, k, ee = integrals(kappa)
        return (ee / (1.0 - m) - k) / (k - ee) - b_curv / a_curv

    kappa = brentq(ratio, 1e-4, 1.0 - 1e-9, xtol=1e-17, rtol=1e-15, maxiter=500)
    m, k, ee = integrals(kappa)
    p = 1.0  # N
    a3 = 3.0 * p * (k - ee) / (2.0 * math.pi * m * e_star * a_curv)
    a = a3 ** (1.0 / 3.0)
    delta = 3.0 * p * k / (2.0 * math.pi * a * e_star)
    return p / delta**1.5


def load_coefficients():
    e_star = 1.0 / (2.0 * (1.0 - NU * NU) / E)
    c = math.cos(math.radians(A0_DEG))
    ball = 2.0 / D
    out = []
    for sign, f in ((1.0, FI), (-1.0, FO)):
        r_roll = sign * 0.5 * (DM / c - sign * D)
        out.append(hertz_load_coefficient(ball + 1.0 / r_roll, ball - 1.0 / (f * D), e_star))
    return out


def solve(rpm, fa, k_i, k_o):
    g = D / DM
    a0 = math.radians(A0_DEG)
    bd = (FI + FO - 1.0) * D
    rho_i, rho_o = (FI - 0.5) * D, (FO - 0.5) * D
    w_i = rpm * math.pi / 30.0
    mass = RHO * math.pi * (D * 1e-3) ** 3 / 6.0  # kg

    def parts(v):
        xr, xz, dz = v
        ar, az = bd * math.cos(a0), bd * math.sin(a0) + dz
        lo, li = math.hypot(xr, xz), math.hypot(ar - xr, az - xz)
        ao, ai = math.atan2(xz, xr), math.atan2(az - xz, ar - xr)
        qo = k_o * max(lo - rho_o, 0.0) ** 1.5
        qi = k_i * max(li - rho_i, 0.0) ** 1.5
        tb = math.sin(ao) / (math.cos(ao) + g)
        co = math.cos(ao) + tb * math.sin(ao)
        ci = math.cos(ai) + tb * math.sin(ai)
        ratio = (1.0 - g * math.cos(ai)) * co / ((1.0 + g * math.cos(ao)) * ci + (1.0 - g * math.cos(ai)) * co)
        w_c = ratio * w_i
        fc = 0.5 * mass * (DM * 1e-3) * w_c * w_c  # N
        return ai, ao, qi, qo, fc

    def eqs(v):
        ai, ao, qi, qo, fc = parts(v)
        return [
            (qi * math.cos(ai) - qo * math.cos(ao) + fc) / fa,
            (qi * math.sin(ai) - qo * math.sin(ao)) / fa,
            (Z * qi * math.sin(ai) - fa) / fa,
        ]

    # start: the quasi-static split along the free contact angle
    delta = 1e-3  # mm
    x0 = [(rho_o + delta) * math.cos(a0), (rho_o + delta) * math.sin(a0), 2.0 * delta]
    v, info, ier, msg = fsolve(eqs, x0, full_output=True, xtol=1e-15)
    res = max(abs(r) for r in eqs(v))
    if ier != 1 and res > 1e-12:
        sys.exit(f"fsolve failed at {rpm} r/min, {fa} N: {msg} (residual {res})")
    ai, ao, qi, qo, fc = parts(v)
    return [rpm, fa, math.degrees(ai), math.degrees(ao), qi, qo, fc, v[2]], res


def table():
    k_i, k_o = load_coefficients()
    rows = []
    worst = 0.0
    for rpm in SPEEDS_RPM:
        for fa in LOADS_N:
            row, res = solve(rpm, fa, k_i, k_o)
            worst = max(worst, res)
            rows.append(row)
    head = [
        "# Independent reference: tools/reference/ball_speed_reference.py (numpy "
        f"{np.__version__}, SciPy fsolve); 7205-class ACBB, pure axial load, outer ring fixed,",
        f"# centrifugal force only; K_i = {k_i:.10g}, K_o = {k_o:.10g} N/mm^1.5 (exact Hertz); "
        f"largest relative equation residual {worst:.1e}",
        "rpm,fa_n,inner_contact_angle_deg,outer_contact_angle_deg,inner_load_n,outer_load_n,centrifugal_force_n,dz_mm",
    ]
    body = [",".join(f"{x:.15g}" for x in r) for r in rows]
    return "\n".join(head + body) + "\n"


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--check", action="store_true", help="compare with the stored table, write nothing")
    args = ap.parse_args()
    text = table()
    if args.check:
        old = [l for l in OUT.read_text().splitlines() if not l.startswith("#")]
        new = [l for l in text.splitlines() if not l.startswith("#")]
        for a, b in zip(old, new):
            va = [float(x) for x in a.split(",")] if not a.startswith("rpm") else []
            vb = [float(x) for x in b.split(",")] if not b.startswith("rpm") else []
            for x, y in zip(va, vb):
                if abs(x - y) > 1e-9 * max(abs(y), 1e-12):
                    sys.exit(f"differs: {a} vs {b}")
        print("the stored table matches")
        return
    OUT.write_text(text)
    print(text, end="")


if __name__ == "__main__":
    main()
