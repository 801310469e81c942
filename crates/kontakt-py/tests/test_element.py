"""The contact element: poses as 4x4 matrices or (translation, quaternion), against Hertz."""

import math

import numpy as np
import pytest

import kontakt as kt


@pytest.fixture
def element(repo):
    return kt.ContactElement.from_file(repo / "crates/kontakt-capi/examples/element_ball_on_flat.toml")


def test_ball_on_flat_is_hertz(element):
    delta = 0.005
    r = element.evaluate(((0.0, 0.0, 10.0 - delta), (1.0, 0.0, 0.0, 0.0)), np.eye(4))
    assert r.status == "contact"
    assert r.approach == pytest.approx(delta, rel=1e-9)
    hertz = kt.HertzPoint((10.0, 10.0), (math.inf, math.inf))
    assert r.normal_force == pytest.approx(hertz.force_from_approach(delta), rel=1e-6)
    np.testing.assert_allclose(r.normal, [0.0, 0.0, 1.0], atol=1e-12)
    assert r.to_dict()["normal_force_n"] == r.normal_force


def test_matrix_and_quaternion_poses_agree(element):
    a = 0.3  # a rotation about z does not change a sphere on a plane
    q = (math.cos(a / 2), 0.0, 0.0, math.sin(a / 2))
    m = np.eye(4)
    m[:2, :2] = [[math.cos(a), -math.sin(a)], [math.sin(a), math.cos(a)]]
    m[2, 3] = 10.0 - 0.004
    r1 = element.evaluate(((0.0, 0.0, 10.0 - 0.004), q), np.eye(4), np.zeros(6), ((0, 0, 0), (0, 0, 0)))
    element.reset()
    r2 = element.evaluate(np.asfortranarray(m), np.eye(4, dtype=np.float32))
    assert r1.normal_force == pytest.approx(r2.normal_force, rel=1e-12)


def test_separated_and_bad_poses(element):
    r = element.evaluate(((0.0, 0.0, 10.5), (1.0, 0.0, 0.0, 0.0)), np.eye(4))
    assert r.status == "separated" and r.normal_force == 0.0
    with pytest.raises(kt.InputError) as e:
        element.evaluate(((math.nan, 0.0, 10.0), (1.0, 0.0, 0.0, 0.0)), np.eye(4))
    assert e.value.field.startswith("pose1")
    with pytest.raises(kt.InputError) as e:
        element.evaluate(np.eye(4), 2 * np.eye(4))
    assert e.value.field == "pose2"
    with pytest.raises(kt.InputError) as e:
        element.evaluate(np.eye(3), np.eye(4))
    assert e.value.field == "pose1.shape"
    with pytest.raises(kt.InputError) as e:
        element.evaluate(np.eye(4), np.eye(4), twist1=np.zeros(5))
    assert e.value.field == "twist1.shape"


def test_spin_friction_moment(repo):
    """A ball spinning about the normal, exact Coulomb (no regularisation speed): the
    friction moment about the contact point is the spin torque -(3 pi / 16) mu F a over the
    Hertz circle, it is all of moment1 (the normal force passes through the centre, the
    friction force vanishes), and to_dict carries it."""
    text = (repo / "crates/kontakt-capi/examples/element_ball_on_flat.toml").read_text()
    assert "mu = 0.1\n" in text
    element = kt.ContactElement.from_toml(text.replace("mu = 0.1\n", "mu = 0.1\nregularisation_speed_mm_s = 0.0\n"))
    delta = 0.005
    r = element.evaluate(((0.0, 0.0, 10.0 - delta), (1.0, 0.0, 0.0, 0.0)), np.eye(4), ((0, 0, 0), (0, 0, 50.0)))
    a = math.sqrt(10.0 * delta)
    exact = -3.0 * math.pi / 16.0 * 0.1 * r.normal_force * a
    assert r.friction_moment[2] == pytest.approx(exact, rel=1e-9)
    np.testing.assert_allclose(r.friction_moment[:2], [0.0, 0.0], atol=1e-12 * abs(exact))
    np.testing.assert_allclose(r.moment1, r.friction_moment, atol=1e-9 * abs(exact))
    assert r.to_dict()["friction_moment_nmm"] == list(r.friction_moment)
