"""oracle/scene.py: the geometry of the bowls from the scene facts, which
points lie in a bowl's hollow, and the liquid packed into the source."""
from __future__ import annotations

import numpy as np
import pytest
from scipy.spatial.distance import pdist

from pantarhei.oracle.scene import Bowl, geometry, packing


def test_the_geometry_comes_from_the_scene_facts():
    g = geometry()
    assert (g.destination.radius, g.destination.height) == (70, 60)
    assert (g.source.radius, g.source.height, g.source.wall) == (45, 45, 4)
    assert g.ground_z == -60 and g.particle_radius == 5


def test_a_bowls_hollow():
    b = Bowl(radius=50, height=40, wall=5)
    points = np.array([[0, 0, 20],          # in the middle
                       [44, 0, 20],         # just inside the wall
                       [46, 0, 20],         # in the wall
                       [0, 0, 1],           # deep in the base
                       [0, 0, 3],           # on the base, within the margin
                       [0, 0, 42],          # above the rim, within the margin
                       [0, 0, 46]])         # above the margin
    assert b.inner_radius == 45
    assert b.contains(points, margin=3).tolist() == [True, True, False, False, True, True, False]


@pytest.mark.parametrize("count", [10, 60, 200])
def test_the_liquid_is_packed_in_the_source_without_overlap(count):
    g = geometry()
    r = g.particle_radius
    P = packing(g.source, r, count)
    assert P.shape == (count, 3)
    assert np.array_equal(P, packing(g.source, r, count))
    assert pdist(P).min() >= 2 * r                           # no two spheres overlap
    assert np.all(np.hypot(P[:, 0], P[:, 1]) + r <= g.source.inner_radius)
    assert np.all(P[:, 2] - r >= g.source.wall)              # above the base
    first = P[:, 2] == P[0, 2]
    d = np.hypot(P[first, 0], P[first, 1])
    assert np.all(np.diff(d) >= -1e-9)                       # nearest the axis first
