"""Hertz point and line contact against Johnson's closed forms (Contact Mechanics, 1985)."""

import math

import numpy as np
import pytest

import kontakt as kt

STEEL = kt.Material(210_000.0, 0.3)


def test_material():
    assert STEEL.e == 210_000.0 and STEEL.nu == 0.3
    assert STEEL.shear_modulus == pytest.approx(210_000.0 / 2.6, rel=1e-15)
    # 1/E* = 2 (1 - nu²)/E
    assert STEEL.e_star(STEEL) == pytest.approx(210_000.0 / (2 * 0.91), rel=1e-15)
    assert kt.Material.steel() == STEEL


@pytest.mark.parametrize("radius,force", [(6.35, 100.0), (10.0, 1000.0), (3.0, 5.0)])
def test_sphere_on_flat_matches_johnson(radius, force):
    e_star = STEEL.e_star(STEEL)
    a = (3 * force * radius / (4 * e_star)) ** (1 / 3)  # Johnson eq. (4.22)
    p0 = 3 * force / (2 * math.pi * a * a)  # eq. (4.21)
    delta = a * a / radius  # eq. (4.23)
    r = kt.HertzPoint((radius, radius), (math.inf, math.inf), STEEL, STEEL).solve(force=force)
    # tolerance 1e-12: the library solves the general ellipse (Carlson form)
    assert r.a == pytest.approx(a, rel=1e-12)
    assert r.b == pytest.approx(a, rel=1e-12)
    assert r.p0 == pytest.approx(p0, rel=1e-12)
    assert r.approach == pytest.approx(delta, rel=1e-12)
    assert r.contact_area == pytest.approx(math.pi * a * a, rel=1e-12)
    assert r.stiffness == pytest.approx(1.5 * force / delta, rel=1e-12)


def test_approach_control_round_trips():
    h = kt.HertzPoint((6.0, 6.0), (20.0, -6.24))
    r = h.solve(force=1000.0)
    assert r.a > 3 * r.b  # a long ellipse across the groove
    assert h.solve(approach=r.approach).force == pytest.approx(1000.0, rel=1e-12)
    assert h.force_from_approach(h.approach_from_force(250.0)) == pytest.approx(250.0, rel=1e-12)


def test_pressure_on_points_is_numpy_and_broadcasts():
    r = kt.HertzPoint((6.35, 6.35), (math.inf, math.inf)).solve(force=100.0)
    x = np.linspace(-0.2, 0.2, 41)
    p = r.pressure(x[:, None], x[None, :])
    assert p.shape == (41, 41) and p.dtype == np.float64
    rr = np.hypot(x[:, None], x[None, :])
    expected = np.where(rr < r.a, r.p0 * np.sqrt(np.clip(1 - (rr / r.a) ** 2, 0, None)), 0.0)
    np.testing.assert_allclose(p, expected, rtol=1e-12, atol=1e-9)
    # float32, lists and non-contiguous views are converted
    assert r.pressure(np.float32(0.0), [0.0])[0] == pytest.approx(r.p0)
    assert r.pressure(x[::2], 0.0).shape == (21,)


def test_subsurface_circle_johnson():
    """tau_max = 0.31 p0 at z = 0.48 a for nu = 0.3 (Johnson 1985, Fig. 3.9)."""
    r = kt.HertzPoint((10.0, 10.0), (math.inf, math.inf)).solve(force=500.0)
    s = r.subsurface_peaks()
    assert s["max_shear_stress_mpa"] / r.p0 == pytest.approx(0.310, abs=0.001)
    assert s["max_shear_depth_mm"] / r.a == pytest.approx(0.481, abs=0.001)


def test_line_contact_matches_johnson():
    e_star = STEEL.e_star(STEEL)
    line = kt.HertzLine(5.0, math.inf, length=20.0)
    r = line.solve(line_load=500.0)
    b = math.sqrt(4 * 500.0 * 5.0 / (math.pi * e_star))  # Johnson eq. (4.43)
    assert r.b == pytest.approx(b, rel=1e-13)
    assert r.p0 == pytest.approx(2 * 500.0 / (math.pi * b), rel=1e-13)
    assert line.solve(force=10_000.0).line_load == pytest.approx(500.0, rel=1e-15)
    s = r.subsurface_peaks()
    assert s["max_shear_stress_mpa"] / r.p0 == pytest.approx(0.300, abs=0.001)
    assert s["max_shear_depth_mm"] / r.b == pytest.approx(0.786, abs=0.001)
    np.testing.assert_allclose(r.pressure(np.array([0.0, b, 2 * b])), [r.p0, 0.0, 0.0], atol=1e-9)


def test_to_dict_equals_cli_baseline(repo):
    """The same case as examples/ball_on_flat.toml, through the bindings: the CLI's keys and values."""
    import json

    base = json.loads((repo / "crates/kontakt-cli/tests/reports/solve_ball_on_flat.json").read_text())
    r = kt.HertzPoint((6.35, 6.35), (math.inf, math.inf)).solve(force=100.0)
    d = r.to_dict(yield_stress=base["inputs"]["yield_stress_mpa"])
    for key in ("force_n", "approach_mm", "max_pressure_mpa", "contact_area_mm2", "semi_axes_mm",
                "max_shear_stress_mpa", "max_von_mises_depth_mm", "first_yield_load_n", "e_star_mpa"):
        assert d[key] == base[key], key
    assert set(base) - {"name"} <= set(d)


def test_bad_input_names_field_value_and_range():
    with pytest.raises(kt.InputError) as e:
        kt.Material(210_000.0, 0.7)
    assert (e.value.field, e.value.value, e.value.valid) == ("nu", "0.7", "-1 < nu <= 0.5")
    assert str(e.value) == "invalid nu = 0.7: expected -1 < nu <= 0.5"
    assert isinstance(e.value, ValueError)
    with pytest.raises(kt.InputError, match="e = -1"):
        kt.Material(-1.0, 0.3)
    with pytest.raises(kt.InputError) as e:
        kt.HertzPoint((0.0, 5.0), (math.inf, math.inf))
    assert e.value.field.startswith("radii1")
    with pytest.raises(kt.InputError) as e:
        kt.HertzPoint((5.0, 5.0), (-4.0, -4.0))  # conformal: no Hertz contact
    assert e.value.field == "radii"
    h = kt.HertzPoint((5.0, 5.0), (math.inf, math.inf))
    with pytest.raises(kt.InputError, match="force"):
        h.solve(force=float("nan"))
    with pytest.raises(kt.InputError, match="exactly one"):
        h.solve(force=1.0, approach=1e-3)
    with pytest.raises(kt.InputError) as e:
        h.solve(force=1.0).to_dict(yield_stress=1000.0, criterion="rankine")
    assert e.value.field == "criterion"
    with pytest.raises(kt.InputError, match="length"):
        kt.HertzLine(5.0, math.inf).solve(force=100.0)


def test_results_carry_the_size_warning_and_refuse_an_oversize_contact():
    """Issue 30 item 3: the case reports' validity check on the classes' own results."""
    ball = kt.HertzPoint((6.35, 6.35), (math.inf, math.inf))
    assert ball.solve(force=100.0).warnings == []
    # a = 3.456 mm, 0.54 of the ball's radius: a warning, as in `kontakt hertz`.
    heavy = ball.solve(force=1e6)
    assert len(heavy.warnings) == 1 and "0.54 of body 1" in heavy.warnings[0]
    assert heavy.warnings == heavy.to_dict()["warnings"]
    with pytest.raises(kt.InputError, match="radii1"):
        ball.solve(force=1e8)  # a = 16 mm on a 6.35 mm ball
    roller = kt.HertzLine(10.0, math.inf)  # no length: Lundberg needs l >= 5 b
    assert roller.solve(line_load=100.0).warnings == []
    assert "0.47 of body 1" in roller.solve(line_load=2e5).warnings[0]  # b = 4.7 mm
    with pytest.raises(kt.InputError, match="radius1"):
        roller.solve(line_load=1e7)


def test_every_method_carries_the_size_warning_through_run(repo):
    """Issue 30 item 3: kt.run goes through the same check as the CLI, for the models that
    had none (mindlin, impact)."""
    tomllib = pytest.importorskip("tomllib")  # Python >= 3.11
    for example, key, value in [
        ("mindlin_fretting", ("load", "force_n"), 1e6),
        ("impact_oblique", ("impact", "speed_mm_per_s"), 1e6),
    ]:
        case = tomllib.loads((repo / "examples" / f"{example}.toml").read_text())
        case[key[0]][key[1]] = value
        r = kt.run(case)
        assert r.warnings and "contact size" in r.warnings[-1], r.warnings
        assert r.warnings == r.to_dict()["warnings"]
        case[key[0]][key[1]] = value * 100
        with pytest.raises(kt.InputError):
            kt.run(case)
