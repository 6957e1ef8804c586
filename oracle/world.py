"""The PyBullet world of one pour: a parameterization read into named
quantities (`Pour`), the scene built at its start (`build`: the ground,
the destination resting on it, the source at its start pose and the liquid
as small spheres at rest inside it), and the source moved kinematically
along its path (`World.target`, `drive`)."""
from __future__ import annotations

import math
import os
import sys
from contextlib import contextmanager
from dataclasses import dataclass, field
from functools import lru_cache
from typing import Any, Iterator

import numpy as np

from pantarhei.oracle.fidelity import Fidelity
from pantarhei.oracle.rotations import qmul, quat, slerp, smoothstep
from pantarhei.oracle.scene import MM, Geometry, bowl_shape, geometry, packing

GRAVITY = 9.81


@dataclass
class Pour:
    """A parameterization read into named quantities (SI units inside)."""
    p: dict[str, float]
    #: Each pose once computed (the source is driven towards one every step).
    poses: dict[str, tuple[np.ndarray, np.ndarray]] = field(default_factory=dict, repr=False,
                                                            compare=False)

    def pose(self, which: str) -> tuple[np.ndarray, np.ndarray]:
        """The source's position (m) and orientation at `which`: start,
        pour or end (read-only arrays)."""
        if which not in self.poses:
            pos = np.array([self.p[f"{which}_{a}"] for a in "xyz"]) * MM
            orn = quat(self.p[f"{which}_roll"], self.p[f"{which}_pitch"], self.p[f"{which}_yaw"])
            for a in (pos, orn):
                a.flags.writeable = False
            self.poses[which] = (pos, orn)
        return self.poses[which]

    @property
    def approach_s(self) -> float:
        return self.p["approach_duration"] / 1000.0

    @property
    def retreat_s(self) -> float:
        return self.p["retreat_duration"] / 1000.0


@dataclass
class World:
    """A live PyBullet world of one pour (used by the oracle and by render)."""
    client: Any
    source: int
    destination: int
    particles: list[int]
    geometry: Geometry
    particle_radius: float            # mm
    pour: Pour
    fidelity: Fidelity
    timeline: tuple[float, float, float] = field(default=(0.0, 0.0, 0.0))

    def target(self, t: float) -> tuple[np.ndarray, np.ndarray]:
        """Where the source should be at time t (s)."""
        ta, tr = self.pour.approach_s, self.pour.retreat_s
        if t <= ta:
            a, b, s = "start", "pour", smoothstep(t / ta)
        else:
            a, b, s = "pour", "end", smoothstep((t - ta) / tr)
        (pa, qa), (pb, qb) = self.pour.pose(a), self.pour.pose(b)
        return pa + s * (pb - pa), slerp(qa, qb, s)

    def close(self) -> None:
        try:
            self.client.disconnect()
        except Exception:  # already gone
            pass


@contextmanager
def quiet() -> Iterator[None]:
    """Silence what the physics engine prints when it loads and connects."""
    sys.stdout.flush()
    sys.stderr.flush()
    saved = [os.dup(1), os.dup(2)]
    devnull = os.open(os.devnull, os.O_WRONLY)
    os.dup2(devnull, 1)
    os.dup2(devnull, 2)
    try:
        yield
    finally:
        os.dup2(saved[0], 1)
        os.dup2(saved[1], 2)
        for fd in (*saved, devnull):
            os.close(fd)


@lru_cache(maxsize=1)
def _client_class() -> type:
    """pybullet_utils' BulletClient, each function it binds to the world's
    client kept once bound: a pour looks its functions up some hundred
    thousand times, and each lookup would bind anew."""
    from pybullet_utils.bullet_client import BulletClient

    class Client(BulletClient):
        def __getattr__(self, name: str):
            attribute = super().__getattr__(name)
            if name != "disconnect":      # disconnecting marks the client closed
                self.__dict__[name] = attribute
            return attribute
    return Client


def build(pour: Pour, fidelity: Fidelity, *, visual: bool = False) -> World:
    """A fresh headless world with the scene of `pour` at its start."""
    with quiet():
        import pybullet as pb

        c = _client_class()(connection_mode=pb.DIRECT)
    c.setPhysicsEngineParameter(fixedTimeStep=1.0 / fidelity.rate_hz,
                                numSolverIterations=fidelity.solver_iterations,
                                deterministicOverlappingPairs=1,
                                contactBreakingThreshold=fidelity.contact_mm * MM)
    c.setGravity(0, 0, -GRAVITY)
    g = geometry()
    p = pour.p
    ground_z = g.ground_z * MM
    plane = c.createMultiBody(0, c.createCollisionShape(c.GEOM_PLANE),
                              c.createVisualShape(c.GEOM_BOX, halfExtents=[1, 1, 0.001],
                                                   visualFramePosition=[0, 0, -0.001],
                                                   rgbaColor=[0.55, 0.6, 0.55, 1])
                              if visual else -1, [0, 0, ground_z], useMaximalCoordinates=True)
    c.changeDynamics(plane, -1, lateralFriction=1.0, restitution=1.0)

    dest = c.createMultiBody(p["destination_mass"] / 1000.0, bowl_shape(c, g.destination),
                             bowl_shape(c, g.destination, visual=True, rgba=(0.3, 0.45, 0.8, 1))
                             if visual else -1, [0, 0, ground_z], useMaximalCoordinates=True)
    c.changeDynamics(dest, -1, lateralFriction=p["destination_friction"] / 1000.0,
                     restitution=p["destination_restitution"] / 1000.0)

    pos, orn = pour.pose("start")
    src = c.createMultiBody(p["source_mass"] / 1000.0, bowl_shape(c, g.source),
                            bowl_shape(c, g.source, visual=True, rgba=(0.85, 0.5, 0.25, 1))
                            if visual else -1, pos.tolist(), orn.tolist(),
                            useMaximalCoordinates=True)
    c.changeDynamics(src, -1, lateralFriction=p["source_friction"] / 1000.0,
                     restitution=p["source_restitution"] / 1000.0)
    radius = fidelity.particle_radius_mm or g.particle_radius
    count = int(round(p["particle_count"]))
    local = packing(g.source, radius, count) * MM
    rot = np.array(c.getMatrixFromQuaternion(orn.tolist())).reshape(3, 3)
    world = local @ rot.T + pos
    shape = c.createCollisionShape(c.GEOM_SPHERE, radius=radius * MM)
    vshape = c.createVisualShape(c.GEOM_SPHERE, radius=radius * MM,
                                 rgbaColor=[0.2, 0.6, 1.0, 1]) if visual else -1
    particles = []
    for xyz in world:
        b = c.createMultiBody(p["particle_mass"] / 1e6, shape, vshape, xyz.tolist(),
                             useMaximalCoordinates=True)
        c.changeDynamics(b, -1, lateralFriction=p["particle_friction"] / 1000.0,
                         restitution=p["particle_restitution"] / 1000.0,
                         rollingFriction=0.0005, spinningFriction=0.0005,
                         ccdSweptSphereRadius=(0.9 * radius * MM) if fidelity.ccd else 0.0)
        particles.append(b)
    return World(c, src, dest, particles, g, radius, pour, fidelity)


def drive(w: World, pos: np.ndarray, orn: np.ndarray, dt: float) -> None:
    """Move the source kinematically: set its velocity so that it reaches
    (pos, orn) after the next step, its weight balanced."""
    c = w.client
    p0, q0 = c.getBasePositionAndOrientation(w.source)
    v = (pos - np.asarray(p0)) / dt
    q0 = np.asarray(q0)
    err = qmul(orn, q0 * np.array([-1, -1, -1, 1]))
    if err[3] < 0:
        err = -err
    s = np.linalg.norm(err[:3])
    omega = (2 * math.atan2(s, err[3]) / dt) * err[:3] / s if s > 1e-12 else np.zeros(3)
    c.resetBaseVelocity(w.source, v.tolist(), omega.tolist())
    c.applyExternalForce(w.source, -1, [0, 0, w.pour.p["source_mass"] / 1000.0 * GRAVITY],
                         list(p0), c.WORLD_FRAME)
