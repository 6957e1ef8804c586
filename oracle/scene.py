"""The scene of a pour: two concave bowls, a ground plane and the liquid.

The geometry comes from the `scene/3` facts (mm). A bowl is a compound
collision shape: a round base (a flat cylinder) and a ring of box-shaped wall
segments, so that it is really concave (things fall into it and stay there).
Its frame is at the centre of the base's underside, z along the bowl's axis.

World frame (metres inside the simulation): the origin is the centre of the
destination's rim, x points from the destination towards where the source
comes from, z up; the ground is at z = -destination_height.
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from functools import lru_cache
from typing import Any

import numpy as np

from pantarhei.theory.lexicon import load_vocabulary

#: metres per millimetre
MM = 0.001
#: wall segments per bowl (with the base, 16 shapes: PyBullet's most in one
#: compound visual shape)
SEGMENTS = 15


@dataclass(frozen=True)
class Bowl:
    """A bowl's outer radius and height and its wall thickness (mm)."""
    radius: float
    height: float
    wall: float

    @property
    def inner_radius(self) -> float:
        return self.radius - self.wall

    def contains(self, local: np.ndarray, margin: float) -> np.ndarray:
        """Which points (n, 3), in the bowl's frame (mm), are inside its
        hollow: within the inner radius, above the base and at most `margin`
        above the rim."""
        r = np.hypot(local[:, 0], local[:, 1])
        return (r < self.inner_radius) & (local[:, 2] > self.wall - margin) & \
            (local[:, 2] < self.height + margin)


@dataclass(frozen=True)
class Geometry:
    destination: Bowl
    source: Bowl
    particle_radius: float

    @property
    def ground_z(self) -> float:
        """Height of the ground in the world frame (mm)."""
        return -self.destination.height


@lru_cache(maxsize=1)
def geometry() -> Geometry:
    """The fixed geometry of the scene, from the vocabulary's scene facts."""
    s = load_vocabulary().scene

    def get(k: str) -> float:
        return float(s[k])

    wall = get("wall_thickness")
    return Geometry(Bowl(get("destination_radius"), get("destination_height"), wall),
                    Bowl(get("source_radius"), get("source_height"), wall),
                    get("particle_radius"))


def bowl_shape(client: Any, bowl: Bowl, *, visual: bool = False,
               rgba: tuple[float, float, float, float] = (0.8, 0.8, 0.8, 1)) -> int:
    """A compound shape (collision, or visual if `visual`) of a base and
    SEGMENTS wall boxes, in the bowl's frame (metres)."""
    r, h, t = bowl.radius * MM, bowl.height * MM, bowl.wall * MM
    half_len = (r - t / 2) * math.tan(math.pi / SEGMENTS) + t / 2
    types, radii, lengths, halves, positions, orientations = [], [], [], [], [], []
    types.append(client.GEOM_CYLINDER)
    radii.append(r)
    lengths.append(t)
    halves.append([0, 0, 0])
    positions.append([0, 0, t / 2])
    orientations.append([0, 0, 0, 1])
    for k in range(SEGMENTS):
        a = 2 * math.pi * k / SEGMENTS
        types.append(client.GEOM_BOX)
        radii.append(0)
        lengths.append(0)
        halves.append([t / 2, half_len, (h - t) / 2])
        positions.append([(r - t / 2) * math.cos(a), (r - t / 2) * math.sin(a), t + (h - t) / 2])
        orientations.append(client.getQuaternionFromEuler([0, 0, a]))
    if visual:
        return client.createVisualShapeArray(
            shapeTypes=types, radii=radii, lengths=lengths, halfExtents=halves,
            fileNames=[""] * len(types), meshScales=[[1, 1, 1]] * len(types),
            visualFramePositions=positions, visualFrameOrientations=orientations,
            rgbaColors=[list(rgba)] * len(types))
    return client.createCollisionShapeArray(
        shapeTypes=types, radii=radii, lengths=lengths, halfExtents=halves,
        collisionFramePositions=positions, collisionFrameOrientations=orientations)


def packing(bowl: Bowl, radius: float, count: int) -> np.ndarray:
    """`count` sphere centres (mm, in the bowl's frame) packed in layers
    from the base up: a hexagonal grid within the bowl's hollow, layers
    offset from one another, nearest the axis first. Deterministic; spheres
    that do not fit in the bowl are stacked above its rim."""
    gap = 2 * radius * 1.04
    reach = bowl.inner_radius - radius * 1.05
    grid = []
    n = int(reach // gap) + 2
    for i in range(-n, n + 1):
        for j in range(-n, n + 1):
            x = (i + 0.5 * j) * gap
            y = j * gap * math.sqrt(3) / 2
            grid.append((x, y))
    grid_a = np.array(grid)
    out: list[np.ndarray] = []
    layer = 0
    while sum(len(o) for o in out) < count:
        shift = np.array([gap / 2, gap * math.sqrt(3) / 6]) if layer % 2 else np.zeros(2)
        pts = grid_a + shift
        d = np.hypot(pts[:, 0], pts[:, 1])
        pts = pts[d <= reach]
        d = d[d <= reach]
        order = np.lexsort((pts[:, 1], pts[:, 0], np.round(d, 6)))
        pts = pts[order]
        z = bowl.wall + radius * 1.02 + layer * gap * math.sqrt(2 / 3)
        out.append(np.column_stack([pts, np.full(len(pts), z)]))
        layer += 1
    return np.concatenate(out)[:count]
