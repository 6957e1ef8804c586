"""Orientations of the bowls: quaternions (x, y, z, w) from the
vocabulary's angles, their product and interpolation, the smoothstep of
the source's path, tilts between orientations and points in a body's own
frame."""
from __future__ import annotations

import math
from typing import Any, Optional

import numpy as np


def quat(roll: float, pitch: float, yaw: float) -> np.ndarray:
    """The source's orientation (x, y, z, w) from the vocabulary's angles
    (degrees): turned by yaw about its own axis, rolled sideways about x,
    and tipped by pitch towards -x (the destination) about y."""
    def axis_angle(axis: int, deg: float) -> np.ndarray:
        q = np.zeros(4)
        q[axis] = math.sin(math.radians(deg) / 2)
        q[3] = math.cos(math.radians(deg) / 2)
        return q
    return qmul(qmul(axis_angle(1, -pitch), axis_angle(0, roll)), axis_angle(2, yaw))


def qmul(a: np.ndarray, b: np.ndarray) -> np.ndarray:
    ax, ay, az, aw = a
    bx, by, bz, bw = b
    return np.array([aw * bx + ax * bw + ay * bz - az * by,
                     aw * by - ax * bz + ay * bw + az * bx,
                     aw * bz + ax * by - ay * bx + az * bw,
                     aw * bw - ax * bx - ay * by - az * bz])


def slerp(a: np.ndarray, b: np.ndarray, s: float) -> np.ndarray:
    d = float(np.dot(a, b))
    if d < 0:
        b, d = -b, -d
    if d > 0.9995:
        q = a + s * (b - a)
        return q / np.linalg.norm(q)
    th = math.acos(d)
    return (math.sin((1 - s) * th) * a + math.sin(s * th) * b) / math.sin(th)


def smoothstep(s: float) -> float:
    s = min(1.0, max(0.0, s))
    return s * s * (3 - 2 * s)


def tilt_deg(q_a: np.ndarray, q_b: Optional[np.ndarray] = None) -> float:
    """The angle between the z axes of two orientations (or of one and the
    vertical)."""
    def up(q: np.ndarray) -> np.ndarray:
        x, y, z, w = q
        return np.array([2 * (x * z + w * y), 2 * (y * z - w * x), 1 - 2 * (x * x + y * y)])
    b = up(q_b) if q_b is not None else np.array([0.0, 0.0, 1.0])
    return math.degrees(math.acos(max(-1.0, min(1.0, float(np.dot(up(q_a), b))))))


def to_local(points: np.ndarray, pos: np.ndarray, orn: np.ndarray, client: Any) -> np.ndarray:
    """`points` (n, 3) in the frame of a body at (pos, orn)."""
    rot = np.array(client.getMatrixFromQuaternion(list(orn))).reshape(3, 3)
    return (points - pos) @ rot
