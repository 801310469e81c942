#!/usr/bin/env python3
"""The sliding power of one ball-raceway contact from an independent implementation:
the rigid-body velocities of ball and ring written out as 3-D cross products (not the
closed forms of crates/kontakt-bearing/src/friction/ball.rs), the mixed friction law
written out from docs/friction.md, and SciPy's adaptive ``dblquad`` over the Hertz ellipse
in Cartesian coordinates.

Run (numpy and scipy in any virtual environment):

    python3 -m venv <VENV> && <VENV>/bin/pip install numpy scipy
    <VENV>/bin/python tools/reference/ball_contact_power_reference.py          # rewrite
    <VENV>/bin/python tools/reference/ball_contact_power_reference.py --check  # compare

Output (read by crates/kontakt-bearing/src/friction/ball_tests.rs):
crates/kontakt-bearing/tests/data/ball_contact_power_reference.csv, one row per contact.

Model:

* The ball's axial plane (e_r, e_z), e_t = e_z x e_r, origin on the bearing axis; ball
  centre C = (d_m/2) e_r; ball angular velocity relative to the cage w_R a,
  a = -sin(beta) e_r + cos(beta) e_z; ring angular velocity relative to the cage W e_z.
* Contact normal n = cos(alpha) e_r + sin(alpha) e_z; contact centre P0 = C + (D/2) n
  (outer) or C - (D/2) n (inner); transverse tangent t = -sin(alpha) e_r + cos(alpha) e_z.
  A point (x, y) of the contact: P = P0 + x e_t + y t + y^2/(2 R_c) d, d = -n (outer) or
  +n (inner), R_c = 2 f D/(2 f + 1).
* Sliding of ball over ring v = w_R a x (P - C) - W e_z x P, its components along e_t and t.
* Hertz pressure p = p0 sqrt(1 - (x/b_x)^2 - (y/a_y)^2) (a_y across, b_x along the rolling).
* Law: tau = phi mu p v/sqrt(|v|^2 + eps^2) + (1 - phi) tau0 asinh(eta0 exp(alpha_p p) |v|
  / (h tau0)) v/|v|, phi = exp(-1.90 Lambda^0.99).
* Power = integral of tau . v dA, N mm/s -> W (x 1e-3).
"""

import argparse
import csv
import os
import sys

import numpy as np
from scipy import integrate

HERE = os.path.dirname(os.path.abspath(__file__))
OUT = os.path.join(HERE, "..", "..", "crates", "kontakt-bearing", "tests", "data",
                   "ball_contact_power_reference.csv")

# Contacts: (inner, D, d_m, f, alpha, beta, w_R, W, a_y, b_x, p0)
CONTACTS = [
    (True, 7.938, 38.5, 0.52, 0.30, 0.20, -3500.0, 800.0, 0.90, 0.12, 1000.0),
    (False, 7.938, 38.5, 0.53, 0.25, 0.40, -3500.0, -600.0, 1.10, 0.15, 900.0),
]
# Law: mu, Lambda, eps (mm/s), tau0 (MPa), h (mm), eta0 (MPa s), alpha_p (1/MPa)
LAW = (0.1, 0.8, 200.0, 4.0, 2.0e-4, 0.02e-6, 0.005)


def sliding(c):
    inner, d, dm, f, al, be, wr, om = c[:8]
    er, et, ez = np.eye(3)
    centre = 0.5 * dm * er
    axis = -np.sin(be) * er + np.cos(be) * ez
    n = np.cos(al) * er + np.sin(al) * ez
    t = -np.sin(al) * er + np.cos(al) * ez
    p0 = centre - 0.5 * d * n if inner else centre + 0.5 * d * n
    dvec = n if inner else -n
    rc = 2.0 * f * d / (2.0 * f + 1.0)

    def v(x, y):
        p = p0 + x * et + y * t + y * y / (2.0 * rc) * dvec
        rel = wr * np.cross(axis, p - centre) - om * np.cross(ez, p)
        return rel @ et, rel @ t

    return v


def power(c):
    mu, lam, eps, tau0, h, eta0, alpha_p = LAW
    phi = np.exp(-1.90 * lam ** 0.99)
    v = sliding(c)
    ay, bx, p0 = c[8:11]

    def density(x, y):
        r2 = 1.0 - (x / bx) ** 2 - (y / ay) ** 2
        if r2 <= 0.0:
            return 0.0
        p = p0 * np.sqrt(r2)
        vx, vy = v(x, y)
        s = np.hypot(vx, vy)
        boundary = phi * mu * p * s * s / np.sqrt(s * s + eps * eps)
        fluid = (1.0 - phi) * tau0 * np.arcsinh(eta0 * np.exp(alpha_p * p) * s / (h * tau0)) * s
        return boundary + fluid

    # y outer, x inner over the ellipse.
    val, err = integrate.dblquad(
        lambda x, y: density(x, y),
        -ay, ay,
        lambda y: -bx * np.sqrt(max(0.0, 1.0 - (y / ay) ** 2)),
        lambda y: bx * np.sqrt(max(0.0, 1.0 - (y / ay) ** 2)),
        epsabs=0.0, epsrel=1e-12,
    )
    return val * 1e-3, err * 1e-3


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--check", action="store_true")
    args = ap.parse_args()
    rows = []
    for c in CONTACTS:
        p, e = power(c)
        rows.append(list(c) + [p])
        print(f"contact inner={c[0]}: power {p:.15e} W (quadrature error estimate {e:.1e})")
    if args.check:
        with open(OUT) as fh:
            old = [r for r in csv.reader(fh) if r and not r[0].startswith("#")][1:]
        for r, o in zip(rows, old):
            if abs(float(o[-1]) / r[-1] - 1.0) > 1e-12:
                sys.exit(f"changed: {o[-1]} -> {r[-1]}")
        print("unchanged")
        return
    with open(OUT, "w") as fh:
        fh.write("# tools/reference/ball_contact_power_reference.py; law " +
                 " ".join(str(x) for x in LAW) + "\n")
        w = csv.writer(fh, lineterminator="\n")
        w.writerow(["inner", "D", "dm", "f", "alpha", "beta", "w_R", "W", "a_y", "b_x",
                    "p0", "power_w"])
        for r in rows:
            w.writerow([int(r[0])] + [repr(float(x)) for x in r[1:]])


if __name__ == "__main__":
    main()
