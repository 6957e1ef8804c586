"""oracle/rotations.py: the source's orientation from the vocabulary's
angles, quaternion products and interpolation, the smoothstep of its path,
tilts, and points in a body's own frame."""
from __future__ import annotations

import math

import numpy as np
import pytest

from pantarhei.oracle.rotations import qmul, quat, slerp, smoothstep, tilt_deg, to_local


def up(q):
    """The body's z axis in the world frame."""
    x, y, z, w = q
    return np.array([2 * (x * z + w * y), 2 * (y * z - w * x), 1 - 2 * (x * x + y * y)])


def conjugate(q):
    return q * np.array([-1, -1, -1, 1])


@pytest.mark.parametrize("pitch", [-30, 10, 45, 90, 135, 180])
def test_pitch_tips_the_source_towards_the_destination(pitch):
    """The destination is towards -x: pitching tips the source's axis there."""
    a = math.radians(pitch)
    assert np.allclose(up(quat(0, pitch, 0)), [-math.sin(a), 0, math.cos(a)])
    assert tilt_deg(quat(0, pitch, 0)) == pytest.approx(abs(pitch))


def test_roll_tilts_sideways_and_yaw_turns_about_the_axis():
    assert np.allclose(up(quat(20, 0, 0)), [0, -math.sin(math.radians(20)), math.cos(math.radians(20))])
    assert np.allclose(quat(0, 0, 0), [0, 0, 0, 1])
    assert tilt_deg(quat(0, 0, 170)) == pytest.approx(0, abs=1e-6)
    # yaw first, about the source's own axis: it does not change where pitch tips it
    assert np.allclose(up(quat(0, 60, 123)), up(quat(0, 60, 0)))


def test_a_quaternion_times_its_conjugate_is_no_turn():
    q = quat(12, 70, -40)
    assert np.allclose(qmul(q, conjugate(q)), [0, 0, 0, 1])
    assert np.linalg.norm(q) == pytest.approx(1)
    # turns compose: pitching by 30 then by 40 is pitching by 70
    assert np.allclose(qmul(quat(0, 40, 0), quat(0, 30, 0)), quat(0, 70, 0))


def test_slerp_turns_at_a_constant_rate_along_the_shorter_way():
    a, b = quat(0, 0, 0), quat(0, 120, 0)
    assert np.allclose(slerp(a, b, 0), a) and np.allclose(slerp(a, b, 1), b)
    for s in (0.1, 0.25, 0.5, 0.9):
        assert tilt_deg(slerp(a, b, s)) == pytest.approx(120 * s)
    # -b is the same orientation as b: still the 120 degree way, not the 240 degree one
    assert tilt_deg(slerp(a, -b, 0.5)) == pytest.approx(60)


def test_smoothstep_starts_and_stops_gently():
    assert smoothstep(0) == 0 and smoothstep(0.5) == 0.5 and smoothstep(1) == 1
    assert smoothstep(-2) == 0 and smoothstep(3) == 1
    h = 1e-6
    assert smoothstep(h) / h < 1e-3 and (1 - smoothstep(1 - h)) / h < 1e-3
    assert smoothstep(0.25) + smoothstep(0.75) == pytest.approx(1)


def test_tilt_between_two_orientations():
    assert tilt_deg(quat(0, 30, 0), quat(0, 100, 0)) == pytest.approx(70)
    assert tilt_deg(quat(0, 90, 0), quat(0, -90, 0)) == pytest.approx(180)


def test_points_in_a_body_frame():
    import pybullet

    pos, orn = np.array([0.1, -0.2, 0.3]), quat(0, 90, 0)
    # the body's own z axis, one unit out from its origin
    points = np.array([pos + up(orn), pos])
    assert np.allclose(to_local(points, pos, orn, pybullet), [[0, 0, 1], [0, 0, 0]], atol=1e-12)
