"""oracle/world.py: the PyBullet world of one pour as built at its start,
the source's path between its poses, and the source driven along it."""
from __future__ import annotations

import numpy as np
import pytest

from pantarhei.oracle.fidelity import CHOSEN_FIDELITY
from pantarhei.oracle.rotations import tilt_deg
from pantarhei.oracle.scene import MM
from pantarhei.oracle.world import Pour, build, drive
from pantarhei.theory.lexicon import load_vocabulary

from .pours import pour

NAMES = load_vocabulary().parameter_names


def read(**changes) -> Pour:
    return Pour(dict(zip(NAMES, (float(x) for x in pour(**changes)))))


@pytest.fixture
def world():
    w = build(read(start_x=120, start_z=200, start_pitch=20, pour_x=30, pour_z=150,
                   pour_pitch=100, end_x=200, end_z=250, particle_count=17,
                   approach_duration=600, retreat_duration=900), CHOSEN_FIDELITY)
    yield w
    w.close()


def test_the_scene_at_the_start(world):
    c, g = world.client, world.geometry
    assert len(world.particles) == 17
    pos, orn = (np.array(v) for v in c.getBasePositionAndOrientation(world.source))
    assert np.allclose(pos, [0.12, 0, 0.2]) and tilt_deg(orn) == pytest.approx(20)
    dpos, _ = c.getBasePositionAndOrientation(world.destination)
    assert np.allclose(dpos, [0, 0, g.ground_z * MM])          # resting on the ground
    assert c.getDynamicsInfo(world.destination, -1)[0] == pytest.approx(0.8)   # kg
    # the liquid at rest inside the source
    rot = np.array(c.getMatrixFromQuaternion(orn.tolist())).reshape(3, 3)
    pts = np.array([c.getBasePositionAndOrientation(b)[0] for b in world.particles])
    local = (pts - pos) @ rot / MM
    assert g.source.contains(local, 0).all()


def test_the_path_runs_from_start_to_pour_to_end(world):
    for t, which in ((0.0, "start"), (0.6, "pour"), (1.5, "end")):
        pos, orn = world.target(t)
        want_pos, want_orn = world.pour.pose(which)
        assert np.allclose(pos, want_pos) and tilt_deg(orn, want_orn) == pytest.approx(0, abs=1e-4)
    pos, orn = world.target(0.3)            # half way through the approach
    assert np.allclose(pos, [0.075, 0, 0.175]) and tilt_deg(orn) == pytest.approx(60)
    pos, orn = world.target(1.05)           # half way through the retreat
    assert np.allclose(pos, [0.115, 0, 0.2]) and tilt_deg(orn) == pytest.approx(50)


def test_a_pose_is_computed_once_and_kept_from_change(world):
    # the source is driven towards a pose every step: one computed pose, which no caller may alter
    pos, orn = world.pour.pose("pour")
    assert world.pour.pose("pour")[0] is pos
    with pytest.raises(ValueError):
        pos[0] = 0.0
    with pytest.raises(ValueError):
        orn *= -1
    assert np.allclose(world.target(0.6)[0], [0.03, 0, 0.15])


def test_the_source_is_driven_to_its_target_in_one_step(world):
    c = world.client
    pos, orn = world.target(0.05)
    drive(world, pos, orn, 1.0 / CHOSEN_FIDELITY.rate_hz)
    c.stepSimulation()
    now, q = (np.array(v) for v in c.getBasePositionAndOrientation(world.source))
    assert np.allclose(now, pos, atol=1e-6) and tilt_deg(q, orn) < 1e-3
