#!/usr/bin/env python3
"""Independent reference for the no-slip limit of the elastic oblique impact
(crates/kontakt/tests/oblique_impact.rs, docs/impact.md).

With mu -> infinity every point of the contact sticks from the instant it enters the
contact; the tangential force is then (method of dimensionality reduction, Popov & Hess 2015)

    Q(t) = 8 G* int_0^a(t) ( s(t) - s(t_in(x)) ) dx,

s the relative tangential displacement (ds/dt = w), t_in(x) the instant at which the contact
radius first reached x. A point leaving the contact releases its force. This script keeps the
history of s on the time grid (not on a grid of cells as the library does) and integrates the
unit problem m = R = V = E* = 1, G* = 1/4 (kappa = 1), m_t = 1/(2 chi) with velocity-Verlet
steps. It prints w2/w1 = psi2/psi1 in the limit psi1 -> 0.

Usage: python3 oblique_impact_noslip.py CHI STEPS      (pure Python, O(STEPS^2))
Results (2026-11-24): chi = 1.441176 (solid sphere, nu = 0.3): 0.231664 (2000 steps),
0.231668 (4000); chi = 2: 0.348331 (2000); chi = 0.5: -1.000000 (exact: -1).
"""
import math
import sys


def no_slip_ratio(chi, steps):
    m, r, e_star, g_star = 1.0, 1.0, 1.0, 0.25
    mt = 0.5 / chi
    k = 4.0 / 3.0 * e_star * math.sqrt(r)
    delta_star = (1.25 * m / k) ** 0.4
    h = 2.943275184324705 * delta_star / steps
    d, vd, s, w = 0.0, 1.0, 0.0, 1.0
    hist_a, hist_s = [0.0], [0.0]  # loading history: radius reached, s at that instant

    def tangential(d, s):
        if d <= 0.0:
            return 0.0
        a = math.sqrt(r * d)
        total = 0.0
        for i in range(1, len(hist_a)):
            x0, x1 = hist_a[i - 1], min(hist_a[i], a)
            if x1 <= x0:
                break
            total += (x1 - x0) * (s - 0.5 * (hist_s[i - 1] + hist_s[i]))
        if a > hist_a[-1]:
            total += (a - hist_a[-1]) * 0.5 * (s - hist_s[-1])
        return 8.0 * g_star * total

    def normal(d):
        return k * d ** 1.5 if d > 0.0 else 0.0

    for _ in range(4 * steps):
        q, p = tangential(d, s), normal(d)
        vdh, wh = vd - 0.5 * h * p / m, w - 0.5 * h * q / mt
        d += h * vdh
        s += h * wh
        if d > 0.0 and math.sqrt(r * d) > hist_a[-1]:
            hist_a.append(math.sqrt(r * d))
            hist_s.append(s)
        q, p = tangential(d, s), normal(d)
        vd, w = vdh - 0.5 * h * p / m, wh - 0.5 * h * q / mt
        if d <= 0.0:
            return w
    raise RuntimeError("contact did not end")


if __name__ == "__main__":
    chi = float(sys.argv[1]) if len(sys.argv) > 1 else 0.7 / 1.7 * 3.5
    steps = int(sys.argv[2]) if len(sys.argv) > 2 else 2000
    print(f"chi = {chi:.6f}, steps = {steps}: w2/w1 = {no_slip_ratio(chi, steps):.6f}")
