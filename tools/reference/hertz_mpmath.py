#!/usr/bin/env python3
"""Golden values for the exact elliptical Hertz contact, computed with mpmath.

Regenerate (from the workspace root):

    python3 -m pip install --user 'mpmath==1.3.0'     # or inside a venv
    python3 tools/reference/hertz_mpmath.py           # rewrites the JSON below
    python3 tools/reference/hertz_mpmath.py --check   # recompute, compare, write nothing

Output: crates/kontakt/tests/data/hertz_elliptic_mpmath.json, read by
crates/kontakt/tests/hertz_reference.rs. The date in the header is today's date unless
SOURCE_DATE_EPOCH is set; everything else is reproducible to the last digit.

Method (deliberately independent of kontakt's Carlson formulation):

* Relative curvature A <= B from Johnson (1982) eqs (51a/b), with the squared terms of
  (51b) as *differences* of principal curvatures (the printed sums are a misprint; see
  docs/hertz.md), evaluated in mpmath from the decimal input strings.
* Shape: the eccentricity e is the root of Johnson's eq. (57),
  B/A = [(a/b)^2 E(e) - K(e)] / [K(e) - E(e)], with Legendre's complete integrals
  K = mpmath.ellipk(m), E = mpmath.ellipe(m), m = e^2, found with mpmath.findroot.
* Size and load from eqs (56a) and (56c) with p0 = 3F/(2 pi a b):
  a^3 = 3 F (K - E) / (2 pi e^2 E* A), b = a sqrt(1 - e^2), delta = p0 b K / E*.
  Eq. (56b) is used as an independent check of every solution.
* B = A exactly (circle): the closed form a^3 = 3 F R / (4 E*), R = 1/(2A),
  delta = a^2 / R, p0 = 3F / (2 pi a^2) (Johnson 1985, eqs 3.39-3.41).

Every case is solved at two working precisions (WORK_DPS and CHECK_DPS digits); the two must
agree to 50 significant digits, and the recorded strings carry DIGITS significant digits.
The script also solves each case with its inputs rounded to IEEE doubles (what a Rust test
actually feeds the library) and records the largest relative change of any output as
`f64_input_sensitivity`, so that a test tolerance of 1e-9 is known to be meaningful.
"""

import argparse
import datetime
import json
import math
import os
import sys

try:
    import mpmath
    from mpmath import mp, mpf
except ImportError:  # pragma: no cover - exercised by people without mpmath
    sys.exit("mpmath is required: python3 -m pip install --user 'mpmath==1.3.0'")

ROOT = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."))
OUT = os.path.join(ROOT, "crates", "kontakt", "tests", "data", "hertz_elliptic_mpmath.json")

WORK_DPS = 70  # working precision [decimal digits]
CHECK_DPS = 100  # second, independent pass
AGREE_DIGITS = 50  # the two passes must agree to this many significant digits
DIGITS = 30  # significant digits written to the JSON

MATERIALS = {
    "steel": ("210000", "0.3"),
    "aluminium": ("70000", "0.33"),
    "ceramic": ("310000", "0.26"),  # silicon-nitride-like
    "boresi_steel": ("200000", "0.29"),
}
PAIRS = [("steel", "steel"), ("steel", "aluminium"), ("steel", "ceramic")]
LOADS = ["10", "100", "1000"]
RATIOS = ["1", "1.5", "3", "10", "30", "100", "1e3", "1e4", "1e5", "1e6", "1e7"]


def mul(x, rho):
    """Exact decimal product of two decimal strings, as a plain decimal string."""
    from decimal import Decimal, getcontext

    getcontext().prec = 50
    v = Decimal(x) * Decimal(rho)
    s = format(v.normalize(), "f")
    return s


def ratio_geometry(pair, rho):
    """Radii for an exact curvature ratio B/A = rho, a different construction per pair."""
    inf = "inf"
    if pair == ("steel", "steel"):
        # Ellipsoid on a flat; A along body 1's first direction.
        return "ellipsoid_on_flat", [mul("10", rho), "10"], [inf, inf], "0"
    if pair == ("steel", "aluminium"):
        # Convex toroid in a concave toroid of the same shape; A along body 1's y.
        return "toroid_in_concave_toroid", ["8", mul("8", rho)], ["-24", mul("-24", rho)], "0"
    # Two toroids with principal planes crossed at 90 degrees; A along body 1's y.
    return "crossed_toroids_90deg", ["5", mul("5", rho)], [mul("15", rho), "15"], "90"


def build_cases():
    cases = []
    for pair in PAIRS:
        for rho in RATIOS:
            family, r1, r2, ang = ratio_geometry(pair, rho)
            for f in LOADS:
                cases.append(
                    dict(
                        id=f"ratio_{rho}_{pair[0]}_{pair[1]}_F{f}",
                        family=f"{family} (B/A = {rho})",
                        body1_radii=r1,
                        body2_radii=r2,
                        angle_deg=ang,
                        materials=pair,
                        force=f,
                    )
                )
    # Crossed cylinders (axes along each body's first principal direction).
    for r1, r2, pair in [("10", "10", ("steel", "steel")), ("10", "25", ("steel", "aluminium"))]:
        for ang in ["15", "30", "45", "60", "90"]:
            for f in LOADS:
                cases.append(
                    dict(
                        id=f"crossed_cyl_R{r1}_R{r2}_{ang}deg_{pair[1]}_F{f}",
                        family=f"crossed cylinders R = {r1} and {r2} mm at {ang} deg",
                        body1_radii=["inf", r1],
                        body2_radii=["inf", r2],
                        angle_deg=ang,
                        materials=pair,
                        force=f,
                    )
                )
    # Ball (R = 6) in a groove of conformity 0.52 (-6.24): inner ring raceway radius 20,
    # outer ring raceway radius -50. All-steel and hybrid (ceramic ball).
    for ring, rr in [("inner", "20"), ("outer", "-50")]:
        for pair in [("steel", "steel"), ("ceramic", "steel")]:
            for f in LOADS:
                cases.append(
                    dict(
                        id=f"ball_groove_{ring}_{pair[0]}_{pair[1]}_F{f}",
                        family=f"ball R=6 in groove -6.24, {ring} raceway {rr} mm",
                        body1_radii=["6", "6"],
                        body2_radii=[rr, "-6.24"],
                        angle_deg="0",
                        materials=pair,
                        force=f,
                    )
                )
    # General geometries: four finite radii at an oblique angle.
    general = [
        ("oblique_a", ["10", "25"], ["40", "-60"], "23", ("steel", "ceramic")),
        # Boresi & Schmidt's example geometry (radii 60/130 and 80/200 mm at 60 deg).
        ("oblique_boresi", ["60", "130"], ["80", "200"], "60", ("boresi_steel", "boresi_steel")),
    ]
    for name, r1, r2, ang, pair in general:
        for f in LOADS + ["4500"]:
            cases.append(
                dict(
                    id=f"{name}_{pair[0]}_{pair[1]}_F{f}",
                    family=f"general: {r1} vs {r2} at {ang} deg",
                    body1_radii=r1,
                    body2_radii=r2,
                    angle_deg=ang,
                    materials=pair,
                    force=f,
                )
            )
    return cases


def curvature(r):
    """1/r for a radius given as an mpf or a decimal string ('inf' = flat)."""
    if isinstance(r, str):
        return mpf(0) if r in ("inf", "-inf") else 1 / mpf(r)
    return mpf(0) if mpmath.isinf(r) else 1 / r


def relative_curvature(r1, r2, angle_deg):
    """Johnson (1982) eqs (51a/b) with differences in the squared terms."""
    k11, k12 = curvature(r1[0]), curvature(r1[1])
    k21, k22 = curvature(r2[0]), curvature(r2[1])
    s = (k11 + k12 + k21 + k22) / 2  # A + B
    d1, d2 = k11 - k12, k21 - k22
    cos2t = mpmath.cospi(mpf(angle_deg) / 90)  # cos(2 theta), exact at multiples of 45 deg
    disc = d1 * d1 + d2 * d2 + 2 * d1 * d2 * cos2t
    dif = mpmath.sqrt(max(disc, mpf(0))) / 2  # B - A
    return (s - dif) / 2, (s + dif) / 2


def e_star(m1, m2, conv=mpf):
    (e1, n1), (e2, n2) = (MATERIALS[m] for m in (m1, m2))
    return 1 / ((1 - conv(n1) ** 2) / conv(e1) + (1 - conv(n2) ** 2) / conv(e2))


def shape_ratio(e):
    """Johnson eq. (57): B/A as a function of the eccentricity e (Legendre K, E)."""
    m = e * e
    k, ee = mpmath.ellipk(m), mpmath.ellipe(m)
    return (ee / (1 - m) - k) / (k - ee)


def solve_eccentricity(ratio):
    """Root of shape_ratio(e) = ratio on (0, 1)."""
    # Bisection on log(1 - e) narrows the bracket so that the bracketed Anderson-Bjorck
    # iteration of findroot starts close to the root for every B/A.
    lo, hi = mpf(10) ** -12, mpf(1) - mpf(10) ** (-(mp.dps - 10))
    g = lambda e: shape_ratio(e) - ratio
    if g(lo) > 0:
        raise ValueError(f"ratio {ratio} too close to 1 for the bracket")
    for _ in range(200):
        mid = 1 - mpmath.sqrt((1 - lo) * (1 - hi))  # geometric in (1 - e)
        if g(mid) > 0:
            hi = mid
        else:
            lo = mid
        if (hi - lo) / (1 - hi) < mpf(10) ** -6:
            break
    e = mpmath.findroot(g, (lo, hi), solver="anderson", tol=mpf(10) ** (-(mp.dps - 5)))
    res = abs(g(e) / ratio)
    if not (lo <= e <= hi) or res > mpf(10) ** (-(mp.dps - 15)):
        raise ValueError(f"eccentricity root failed for B/A = {ratio}: residual {res}")
    return e


def solve(case, rounded=False):
    """The Hertz solution of one case at the current mp.dps."""
    # rounded=True: every input is first rounded to the nearest IEEE double, exactly as the
    # Rust test parses it (the angle as f64 degrees -> f64::to_radians).
    conv = (lambda s: mpf(float(s))) if rounded else mpf
    r1 = [conv(s) for s in case["body1_radii"]]
    r2 = [conv(s) for s in case["body2_radii"]]
    ang = mpf(case["angle_deg"])
    if rounded:
        ang = mpf(math.radians(float(case["angle_deg"]))) * 180 / mpmath.pi
    a_coef, b_coef = relative_curvature(r1, r2, ang)
    es = e_star(*case["materials"], conv=conv)
    f = conv(case["force"])
    ratio = b_coef / a_coef
    if ratio - 1 < mpf(10) ** (-(mp.dps - 20)):
        # Circle: closed form.
        r = 1 / (2 * a_coef)
        a = mpmath.cbrt(3 * f * r / (4 * es))
        b = a
        e = mpf(0)
        delta = a * a / r
        p0 = 3 * f / (2 * mpmath.pi * a * b)
    else:
        e = solve_eccentricity(ratio)
        m = e * e
        k, ee = mpmath.ellipk(m), mpmath.ellipe(m)
        a = mpmath.cbrt(3 * f * (k - ee) / (2 * mpmath.pi * m * es * a_coef))  # eq. 56a
        b = a * mpmath.sqrt(1 - m)
        p0 = 3 * f / (2 * mpmath.pi * a * b)
        delta = p0 * b * k / es  # eq. 56c
        # Independent check with eq. (56b).
        b_check = (p0 / es) * (b / (a * a * m)) * ((a / b) ** 2 * ee - k)
        if abs(b_check / b_coef - 1) > mpf(10) ** (-(mp.dps - 20)):
            raise ValueError(f"{case['id']}: eq. 56b check failed ({b_check} vs {b_coef})")
    return dict(
        a=a,
        b=b,
        p0=p0,
        delta=delta,
        area=mpmath.pi * a * b,
        stiffness=3 * f / (2 * delta),
        mean_pressure=f / (mpmath.pi * a * b),
        B_over_A=ratio,
        b_over_a=b / a,
        eccentricity=e,
        A=a_coef,
        B=b_coef,
        e_star=es,
    )


def relerr(x, y):
    if x == y:
        return mpf(0)
    return abs(x - y) / max(abs(x), abs(y))


def compute(cases):
    out = []
    worst_sens = 0.0
    for c in cases:
        with mpmath.workdps(WORK_DPS):
            s = solve(c)
            s_f64 = solve(c, rounded=True)
        with mpmath.workdps(CHECK_DPS):
            s_chk = solve(c)
        with mpmath.workdps(CHECK_DPS):
            for k in s:
                if relerr(s[k], s_chk[k]) > mpf(10) ** (-AGREE_DIGITS):
                    raise SystemExit(f"{c['id']}: {k} differs between {WORK_DPS} and {CHECK_DPS} digits")
        keys = ["a", "b", "p0", "delta", "area", "stiffness"]
        with mpmath.workdps(WORK_DPS):
            sens = max(float(relerr(s[k], s_f64[k])) for k in keys)
        worst_sens = max(worst_sens, sens)
        with mpmath.workdps(WORK_DPS):
            expected = {k: mpmath.nstr(v, DIGITS, strip_zeros=False, min_fixed=-5, max_fixed=8)
                        for k, v in s_chk.items()}
        m1, m2 = c["materials"]
        out.append(
            dict(
                id=c["id"],
                family=c["family"],
                body1_radii=c["body1_radii"],
                body2_radii=c["body2_radii"],
                angle_deg=c["angle_deg"],
                body1=dict(name=m1, youngs_modulus=MATERIALS[m1][0], poisson_ratio=MATERIALS[m1][1]),
                body2=dict(name=m2, youngs_modulus=MATERIALS[m2][0], poisson_ratio=MATERIALS[m2][1]),
                force=c["force"],
                expected=expected,
                f64_input_sensitivity=f"{sens:.3e}",
            )
        )
    return out, worst_sens


def header(worst_sens, n):
    epoch = os.environ.get("SOURCE_DATE_EPOCH")
    day = (
        datetime.datetime.fromtimestamp(int(epoch), datetime.timezone.utc).date()
        if epoch
        else datetime.date.today()
    )
    return dict(
        source="tools/reference/hertz_mpmath.py (kontakt); independent of kontakt's Carlson formulation",
        method=(
            "Johnson (1982) Appendix 1: A, B from eqs (51a/b) (differences in the squared terms); "
            "eccentricity e from eq. (57) with Legendre K(m)=mpmath.ellipk(m), E(m)=mpmath.ellipe(m), "
            "m=e^2, root by mpmath.findroot (anderson, bracketed); a^3 = 3F(K-E)/(2 pi e^2 E* A) from "
            "eq. (56a) with p0 = 3F/(2 pi a b); delta = p0 b K / E* (eq. 56c); eq. (56b) checked for every "
            "case; circle (B = A) by the closed form a^3 = 3FR/(4E*), delta = a^2/R."
        ),
        equations="Johnson, K.L. (1982) One hundred years of Hertz contact, Proc. IMechE 196, 363-378, eqs (50)-(61)",
        units="mm, N, MPa; stiffness 3F/(2 delta) in N/mm; area pi a b in mm^2",
        conventions=(
            "radii: convex > 0, concave < 0, 'inf' flat; angle_deg from body 1's first principal "
            "direction to body 2's; 1/E* = (1-nu1^2)/E1 + (1-nu2^2)/E2"
        ),
        mpmath_version=mpmath.__version__,
        python_version=sys.version.split()[0],
        working_precision_digits=WORK_DPS,
        check_precision_digits=CHECK_DPS,
        agreement_digits=AGREE_DIGITS,
        recorded_digits=DIGITS,
        f64_input_sensitivity=(
            "largest relative change of a, b, p0, delta, area or stiffness when the inputs are rounded "
            f"to IEEE doubles (as the Rust test does); worst case over the file: {worst_sens:.3e}"
        ),
        date=day.isoformat(),
        regenerate="python3 -m pip install --user 'mpmath==1.3.0' && python3 tools/reference/hertz_mpmath.py",
        case_count=n,
    )


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--check", action="store_true", help="recompute and compare with the file; write nothing")
    ap.add_argument("--out", default=OUT)
    args = ap.parse_args()
    cases = build_cases()
    out, worst = compute(cases)
    doc = dict(header=header(worst, len(out)), cases=out)
    text = json.dumps(doc, indent=1) + "\n"
    if args.check:
        with open(args.out) as fh:
            old = json.load(fh)
        if old["cases"] != doc["cases"]:
            sys.exit(f"{args.out} differs from a fresh computation")
        print(f"{args.out}: {len(out)} cases reproduced exactly")
        return
    with open(args.out, "w") as fh:
        fh.write(text)
    print(f"wrote {len(out)} cases to {args.out}; worst f64-input sensitivity {worst:.3e}")


if __name__ == "__main__":
    main()
