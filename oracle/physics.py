"""The PyBullet oracle: a pour simulated and scored against the 9 expectations.

A fresh headless PyBullet world per simulation (so that every worker gives
the same result for the same parameterization): the ground, the destination
resting on it (free to slide or tip), the source held by a stiff constraint
that moves it from the start pose to the pouring pose (approach) and on to
the end pose (retreat), smoothstep-interpolated in position and slerped in
orientation, and the liquid as small spheres spawned at rest inside the
source at its start pose. Then everything settles.
"""
from __future__ import annotations

import math
import os
import sys
import time
from contextlib import contextmanager
from dataclasses import asdict, dataclass, field, replace
from typing import Any, Callable, Iterator, Optional

import numpy as np

from pantarhei.oracle import baseline, scoring
from pantarhei.oracle.base import Oracle, Outcome
from pantarhei.oracle.scene import MM, Geometry, bowl_shape, geometry, packing
from pantarhei.theory.lexicon import load_vocabulary

GRAVITY = 9.81


@dataclass(frozen=True)
class Fidelity:
    """How finely a pour is simulated (part of the key of stored results)."""
    rate_hz: int = 240               # physics steps per second
    solver_iterations: int = 50
    settle_ms: int = 2000            # longest settling after the retreat
    early_stop: bool = False         # stop settling once everything is at rest
    particle_radius_mm: Optional[float] = None   # None: the scene's
    sample_hz: int = 60              # observations per second
    rest_speed: float = 0.02         # m/s: at rest below this speed
    ccd: bool = True                 # continuous collision detection for particles
    contact_mm: float = 20.0         # contact breaking threshold (PyBullet's default: 20 mm)

    def describe(self) -> str:
        return (f"{self.rate_hz} Hz, {self.solver_iterations} solver iterations, settle "
                f"{self.settle_ms} ms{' or until at rest' if self.early_stop else ''}")


#: PyBullet's defaults: 240 Hz, 50 solver iterations, the full duration.
DEFAULT_FIDELITY = Fidelity()
#: The settings chosen by measurement (`python -m benchmarks.oracle`).
#: Measured on 40 pours (two seeds of the benchmark's set) against the
#: defaults: 180 Hz agrees on 346 of 360 verdicts at 4.4-5.1x the speed,
#: 120 Hz on 342 at 6-7x; 180 Hz keeps a margin over 95%. 10 solver
#: iterations, a 2 mm contact threshold and the early stop cost no agreement.
CHOSEN_FIDELITY = Fidelity(rate_hz=180, solver_iterations=10, settle_ms=2000, early_stop=True,
                           sample_hz=30, contact_mm=2.0)
FIDELITIES = {"default": DEFAULT_FIDELITY, "chosen": CHOSEN_FIDELITY}


def _quat(roll: float, pitch: float, yaw: float) -> np.ndarray:
    """The source's orientation (x, y, z, w) from the vocabulary's angles
    (degrees): turned by yaw about its own axis, rolled sideways about x,
    and tipped by pitch towards -x (the destination) about y."""
    def axis_angle(axis: int, deg: float) -> np.ndarray:
        q = np.zeros(4)
        q[axis] = math.sin(math.radians(deg) / 2)
        q[3] = math.cos(math.radians(deg) / 2)
        return q
    return _qmul(_qmul(axis_angle(1, -pitch), axis_angle(0, roll)), axis_angle(2, yaw))


def _qmul(a: np.ndarray, b: np.ndarray) -> np.ndarray:
    ax, ay, az, aw = a
    bx, by, bz, bw = b
    return np.array([aw * bx + ax * bw + ay * bz - az * by,
                     aw * by - ax * bz + ay * bw + az * bx,
                     aw * bz + ax * by - ay * bx + az * bw,
                     aw * bw - ax * bx - ay * by - az * bz])


def _slerp(a: np.ndarray, b: np.ndarray, s: float) -> np.ndarray:
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


@dataclass
class Pour:
    """A parameterization read into named quantities (SI units inside)."""
    p: dict[str, float]

    def pose(self, which: str) -> tuple[np.ndarray, np.ndarray]:
        pos = np.array([self.p[f"{which}_{a}"] for a in "xyz"]) * MM
        return pos, _quat(self.p[f"{which}_roll"], self.p[f"{which}_pitch"], self.p[f"{which}_yaw"])

    @property
    def approach_s(self) -> float:
        return self.p["approach_duration"] / 1000.0

    @property
    def retreat_s(self) -> float:
        return self.p["retreat_duration"] / 1000.0


@dataclass
class _Stage:
    displacement: float = 0.0
    tilt: float = 0.0
    origin: Optional[tuple[np.ndarray, np.ndarray]] = None


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
        return pa + s * (pb - pa), _slerp(qa, qb, s)

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


def build(pour: Pour, fidelity: Fidelity, *, visual: bool = False) -> World:
    """A fresh headless world with the scene of `pour` at its start."""
    with quiet():
        import pybullet as pb
        from pybullet_utils.bullet_client import BulletClient

        c = BulletClient(connection_mode=pb.DIRECT)
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


def _tilt_deg(q_a: np.ndarray, q_b: Optional[np.ndarray] = None) -> float:
    """The angle between the z axes of two orientations (or of one and the
    vertical)."""
    def up(q: np.ndarray) -> np.ndarray:
        x, y, z, w = q
        return np.array([2 * (x * z + w * y), 2 * (y * z - w * x), 1 - 2 * (x * x + y * y)])
    b = up(q_b) if q_b is not None else np.array([0.0, 0.0, 1.0])
    return math.degrees(math.acos(max(-1.0, min(1.0, float(np.dot(up(q_a), b))))))


def _to_local(points: np.ndarray, pos: np.ndarray, orn: np.ndarray, client: Any) -> np.ndarray:
    rot = np.array(client.getMatrixFromQuaternion(list(orn))).reshape(3, 3)
    return (points - pos) @ rot


def drive(w: World, pos: np.ndarray, orn: np.ndarray, dt: float) -> None:
    """Move the source kinematically: set its velocity so that it reaches
    (pos, orn) after the next step, its weight balanced."""
    c = w.client
    p0, q0 = c.getBasePositionAndOrientation(w.source)
    v = (pos - np.asarray(p0)) / dt
    q0 = np.asarray(q0)
    err = _qmul(orn, q0 * np.array([-1, -1, -1, 1]))
    if err[3] < 0:
        err = -err
    s = np.linalg.norm(err[:3])
    omega = (2 * math.atan2(s, err[3]) / dt) * err[:3] / s if s > 1e-12 else np.zeros(3)
    c.resetBaseVelocity(w.source, v.tolist(), omega.tolist())
    c.applyExternalForce(w.source, -1, [0, 0, w.pour.p["source_mass"] / 1000.0 * GRAVITY],
                         list(p0), c.WORLD_FRAME)


Frame = Callable[[World, float], None]


def run(p: np.ndarray, fidelity: Fidelity = CHOSEN_FIDELITY,
        on_frame: Optional[Frame] = None, frame_hz: float = 0.0) -> dict[str, Any]:
    """Simulate one pour; the record of what happened (see `scoring`).
    `on_frame(world, t)` is called `frame_hz` times per simulated second."""
    t_begin = time.perf_counter()
    names = load_vocabulary().parameter_names
    pour = Pour({n: float(v) for n, v in zip(names, p)})
    w = build(pour, fidelity, visual=on_frame is not None)
    try:
        return _simulate(w, on_frame, frame_hz, t_begin)
    finally:
        w.close()


def _simulate(w: World, on_frame: Optional[Frame], frame_hz: float,
              t_begin: float) -> dict[str, Any]:
    c, f, g = w.client, w.fidelity, w.geometry
    dt = 1.0 / f.rate_hz
    ta, tr = w.pour.approach_s, w.pour.retreat_s
    steps_move = int(math.ceil((ta + tr) / dt))
    steps_settle = int(math.ceil(f.settle_ms / 1000.0 / dt))
    sample_every = max(1, int(round(f.rate_hz / f.sample_hz)))
    frame_every = max(1, int(round(f.rate_hz / frame_hz))) if on_frame and frame_hz else 0
    n = len(w.particles)
    entered = np.zeros(n, dtype=bool)
    stages = {s: _Stage() for s in scoring.STAGES}
    impulse, min_gap = 0.0, math.inf
    rest_samples, step_seconds, steps_done = 0, 0.0, 0
    margin = w.particle_radius
    floor = g.ground_z + 3 * w.particle_radius
    reach = g.destination.radius + w.particle_radius

    def positions() -> np.ndarray:
        return np.array([c.getBasePositionAndOrientation(b)[0] for b in w.particles]).reshape(n, 3) / MM

    end = w.pour.pose("end")
    if on_frame:
        on_frame(w, 0.0)
    total = steps_move + steps_settle
    for k in range(1, total + 1):
        t = k * dt
        stage = "approach" if t <= ta else ("retreat" if t <= ta + tr else "settle")
        if k <= steps_move:
            pos, orn = w.target(min(t, ta + tr))
            drive(w, pos, orn, dt)
        else:
            drive(w, *end, dt)
        t0 = time.perf_counter()
        c.stepSimulation()
        step_seconds += time.perf_counter() - t0
        steps_done = k
        for cp in c.getContactPoints(w.source, w.destination):
            impulse += cp[9] * dt
        if frame_every and k % frame_every == 0:
            on_frame(w, t)
        if k % sample_every and k != total:
            continue
        dpos, dorn = (np.array(v) for v in c.getBasePositionAndOrientation(w.destination))
        st = stages[stage]
        if st.origin is None:
            st.origin = (dpos, dorn)
        st.displacement = max(st.displacement, float(np.linalg.norm(dpos - st.origin[0])) / MM)
        st.tilt = max(st.tilt, _tilt_deg(dorn, st.origin[1]))
        if stage != "settle":
            gap = c.getClosestPoints(w.source, w.destination, distance=scoring.CLEAR_MM * MM)
            if gap:
                min_gap = min(min_gap, max(0.0, min(x[8] for x in gap) / MM))
        pts = positions()
        entered |= g.destination.contains(_to_local(pts, dpos / MM, dorn, c), margin)
        if stage == "settle" and f.early_stop:
            vel = np.array([c.getBaseVelocity(b)[0] for b in w.particles]).reshape(n, 3)
            speed = np.linalg.norm(vel, axis=1)
            away = (pts[:, 2] < floor) & (np.hypot(pts[:, 0] - dpos[0] / MM, pts[:, 1] - dpos[1] / MM) > reach)
            dv, dw = c.getBaseVelocity(w.destination)
            still = bool(np.all((speed < f.rest_speed) | away)) and \
                np.linalg.norm(dv) < f.rest_speed and np.linalg.norm(dw) < 0.2
            rest_samples = rest_samples + 1 if still else 0
            if rest_samples >= 3:
                break
    if on_frame and frame_every and steps_done % frame_every:
        on_frame(w, steps_done * dt)

    pts = positions()
    dpos, dorn = (np.array(v) for v in c.getBasePositionAndOrientation(w.destination))
    spos, sorn = (np.array(v) for v in c.getBasePositionAndOrientation(w.source))
    in_dest = g.destination.contains(_to_local(pts, dpos / MM, dorn, c), margin)
    in_src = g.source.contains(_to_local(pts, spos / MM, sorn, c), margin) & ~in_dest
    entered |= in_dest
    fr = lambda m: float(np.count_nonzero(m)) / n  # noqa: E731
    return {
        "fractions": {"source": fr(in_src), "destination": fr(in_dest),
                      "elsewhere": fr(~in_src & ~in_dest), "entered_destination": fr(entered)},
        "displacement_mm": {s: round(stages[s].displacement, 3) for s in scoring.STAGES},
        "tilt_deg": {s: round(stages[s].tilt, 3) for s in scoring.STAGES},
        "final_tilt_deg": round(_tilt_deg(dorn), 3),
        "contact_impulse": float(impulse),
        "min_gap_mm": 0.0 if impulse > 0 else (round(min_gap, 3) if math.isfinite(min_gap)
                                               else scoring.CLEAR_MM),
        "destination_mass_kg": w.pour.p["destination_mass"] / 1000.0,
        "particles": n,
        "simulated_s": round(steps_done * dt, 4),
        "steps": steps_done,
        "step_seconds": step_seconds,
        "seconds": time.perf_counter() - t_begin,
    }


#: Record fields that measure the machine, not the pour.
TIMING_FIELDS = ("step_seconds", "seconds")


#: How the floating-point math of a pour is computed: "baseline", the same
#: routines on every x86-64 machine (see `baseline`), or "native", the ones
#: the libraries pick for this CPU (faster, not reproducible elsewhere).
MATHS = ("baseline", "native")


class PouringOracle(Oracle):
    """Scores a parameterization by simulating the pour in PyBullet."""
    name = "pybullet"
    version = "4"

    def __init__(self, fidelity: str | Fidelity = "chosen", math: str = "baseline",
                 **overrides: Any):
        if isinstance(fidelity, str):
            if fidelity not in FIDELITIES:
                raise ValueError(f"unknown fidelity '{fidelity}' (choose {', '.join(FIDELITIES)})")
            fidelity = FIDELITIES[fidelity]
        if math not in MATHS:
            raise ValueError(f"unknown math '{math}' (choose {', '.join(MATHS)})")
        self.fidelity = replace(fidelity, **overrides)
        self.math = math

    def settings(self) -> dict[str, Any]:
        return {**asdict(self.fidelity), "environment": self.environment()}

    def environment(self) -> dict[str, str]:
        return dict(baseline.ENVIRONMENT) if self.math == "baseline" else {}

    def cost(self, p: np.ndarray) -> float:
        """A rough relative cost of simulating p (for scheduling): particles
        times simulated seconds."""
        v = load_vocabulary()
        count = p[v.parameter("particle_count").index]
        ms = p[v.parameter("approach_duration").index] + p[v.parameter("retreat_duration").index]
        return float(count * (ms + self.fidelity.settle_ms / 4))

    def score(self, p: np.ndarray) -> Outcome:
        record = run(np.asarray(p, dtype=float), self.fidelity)
        return Outcome(scoring.scores(record), record)
