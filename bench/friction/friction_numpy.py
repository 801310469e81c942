"""The friction integral of kontakt's `grid_friction` written the way a NumPy user would,
on the case of the criterion benchmark `friction/map_64x64_coulomb_ellipse`
(crates/kontakt/benches/friction.rs):

- a Hertz ellipse p = p0 sqrt(1 - x^2/a^2 - y^2/b^2), p0 = 700 MPa, a = 1.2 mm, b = 0.3 mm,
  sampled at the centres of a 64 x 64 grid over [-1.05 a, 1.05 a] x [-1.05 b, 1.05 b];
- the sliding field of a spin omega = 300 rad/s about the normal through (0, -e), e = 2.76 mm:
  v = omega (-(y + e), x) [mm/s];
- Coulomb friction mu = 0.1 with the regularised direction v / sqrt(|v|^2 + v_eps^2),
  v_eps = 1 mm/s.

Prints the friction force [N], the moment about the grid origin [N mm], the power [W] and
the best time per call [us] over repeated runs (timeit). Units: mm, N, MPa, mm/s.
"""
import json
import sys
import timeit

import numpy as np

P0, A, B, OMEGA, E, MU, V_EPS, N = 700.0, 1.2, 0.3, 300.0, 2.76, 0.1, 1.0, 64


def setup():
    hx, hy = 1.05 * A, 1.05 * B
    dx, dy = 2 * hx / N, 2 * hy / N
    x = -hx + (np.arange(N) + 0.5) * dx
    y = -hy + (np.arange(N) + 0.5) * dy
    X, Y = np.meshgrid(x, y)  # row-major, x fastest
    p = P0 * np.sqrt(np.clip(1 - (X / A) ** 2 - (Y / B) ** 2, 0.0, None))
    return X, Y, p, dx * dy


def friction(X, Y, p, area):
    vx = -OMEGA * (Y + E)
    vy = OMEGA * X
    s2 = vx * vx + vy * vy
    k = MU * p / np.sqrt(s2 + V_EPS * V_EPS)
    tx, ty = -k * vx, -k * vy
    fx, fy = tx.sum() * area, ty.sum() * area
    m = (X * ty - Y * tx).sum() * area
    power = (k * s2).sum() * area * 1e-3
    return fx, fy, m, power


def main():
    X, Y, p, area = setup()
    fx, fy, m, power = friction(X, Y, p, area)
    timer = timeit.Timer(lambda: friction(X, Y, p, area))
    loops, _ = timer.autorange()
    best = min(timer.repeat(repeat=7, number=loops)) / loops
    json.dump(
        {
            "numpy": np.__version__,
            "force_n": [fx, fy],
            "moment_nmm": m,
            "power_w": power,
            "time_us": best * 1e6,
        },
        sys.stdout,
    )
    print()


if __name__ == "__main__":
    main()
