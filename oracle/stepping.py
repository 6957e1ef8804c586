"""A pour run through: the source driven along its path step by step,
the destination, the source and the liquid watched at the sample rate,
and what happened written as the record that `scoring` turns into the
nine scores."""
from __future__ import annotations

import math
import time
from dataclasses import dataclass
from typing import Any, Callable, Optional

import numpy as np

from pantarhei.oracle import scoring
from pantarhei.oracle.fidelity import Fidelity
from pantarhei.oracle.rotations import tilt_deg, to_local
from pantarhei.oracle.scene import MM
from pantarhei.oracle.world import Pour, World, build, drive
from pantarhei.theory.lexicon import load_vocabulary

#: Record fields that measure the machine, not the pour.
TIMING_FIELDS = ("step_seconds", "seconds")

Frame = Callable[[World, float], None]


@dataclass
class _Stage:
    displacement: float = 0.0
    tilt: float = 0.0
    origin: Optional[tuple[np.ndarray, np.ndarray]] = None


@dataclass
class _Watch:
    """What has been seen of a pour so far."""
    entered: np.ndarray               # per particle: ever inside the destination
    stages: dict[str, _Stage]
    impulse: float = 0.0
    min_gap: float = math.inf
    rest_samples: int = 0
    step_seconds: float = 0.0
    steps_done: int = 0


def run(p: np.ndarray, fidelity: Fidelity,
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
    f = w.fidelity
    dt = 1.0 / f.rate_hz
    ta, tr = w.pour.approach_s, w.pour.retreat_s
    steps_move = int(math.ceil((ta + tr) / dt))
    steps_settle = int(math.ceil(f.settle_ms / 1000.0 / dt))
    sample_every = max(1, int(round(f.rate_hz / f.sample_hz)))
    frame_every = max(1, int(round(f.rate_hz / frame_hz))) if on_frame and frame_hz else 0
    watch = _Watch(np.zeros(len(w.particles), dtype=bool), {s: _Stage() for s in scoring.STAGES})
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
        _step(w, watch, k, dt)
        if frame_every and k % frame_every == 0:
            on_frame(w, t)
        if k % sample_every and k != total:
            continue
        if _observe(w, watch, stage):
            break
    if on_frame and frame_every and watch.steps_done % frame_every:
        on_frame(w, watch.steps_done * dt)
    return _record(w, watch, dt, t_begin)


def _step(w: World, watch: _Watch, k: int, dt: float) -> None:
    """Step k of the physics, and the impulse of the bowls' contacts in it."""
    c = w.client
    t0 = time.perf_counter()
    c.stepSimulation()
    watch.step_seconds += time.perf_counter() - t0
    watch.steps_done = k
    for cp in c.getContactPoints(w.source, w.destination):
        watch.impulse += cp[9] * dt


def _positions(w: World) -> np.ndarray:
    """Where the particles are (mm)."""
    c, n = w.client, len(w.particles)
    return np.array([c.getBasePositionAndOrientation(b)[0] for b in w.particles]).reshape(n, 3) / MM


def _observe(w: World, watch: _Watch, stage: str) -> bool:
    """One sample: how far the destination moved and tilted in this
    stage, how close the bowls came, which particles are in the
    destination; whether everything has been at rest long enough to stop."""
    c, g = w.client, w.geometry
    dpos, dorn = (np.array(v) for v in c.getBasePositionAndOrientation(w.destination))
    st = watch.stages[stage]
    if st.origin is None:
        st.origin = (dpos, dorn)
    st.displacement = max(st.displacement, float(np.linalg.norm(dpos - st.origin[0])) / MM)
    st.tilt = max(st.tilt, tilt_deg(dorn, st.origin[1]))
    if stage != "settle":
        gap = c.getClosestPoints(w.source, w.destination, distance=scoring.CLEAR_MM * MM)
        if gap:
            watch.min_gap = min(watch.min_gap, max(0.0, min(x[8] for x in gap) / MM))
    pts = _positions(w)
    watch.entered |= g.destination.contains(to_local(pts, dpos / MM, dorn, c), w.particle_radius)
    if stage == "settle" and w.fidelity.early_stop:
        watch.rest_samples = watch.rest_samples + 1 if _still(w, pts, dpos) else 0
        if watch.rest_samples >= 3:
            return True
    return False


def _still(w: World, pts: np.ndarray, dpos: np.ndarray) -> bool:
    """Is every particle at rest (or lying on the ground away from the
    destination), and the destination too?"""
    c, f, g = w.client, w.fidelity, w.geometry
    n = len(w.particles)
    floor = g.ground_z + 3 * w.particle_radius
    reach = g.destination.radius + w.particle_radius
    vel = np.array([c.getBaseVelocity(b)[0] for b in w.particles]).reshape(n, 3)
    speed = np.linalg.norm(vel, axis=1)
    away = (pts[:, 2] < floor) & (np.hypot(pts[:, 0] - dpos[0] / MM, pts[:, 1] - dpos[1] / MM) > reach)
    dv, dw = c.getBaseVelocity(w.destination)
    return bool(np.all((speed < f.rest_speed) | away)) and \
        np.linalg.norm(dv) < f.rest_speed and np.linalg.norm(dw) < 0.2


def _record(w: World, watch: _Watch, dt: float, t_begin: float) -> dict[str, Any]:
    """The record of the pour, from where everything ended and what was seen."""
    c, g = w.client, w.geometry
    n, margin, stages = len(w.particles), w.particle_radius, watch.stages
    pts = _positions(w)
    dpos, dorn = (np.array(v) for v in c.getBasePositionAndOrientation(w.destination))
    spos, sorn = (np.array(v) for v in c.getBasePositionAndOrientation(w.source))
    in_dest = g.destination.contains(to_local(pts, dpos / MM, dorn, c), margin)
    in_src = g.source.contains(to_local(pts, spos / MM, sorn, c), margin) & ~in_dest
    entered = watch.entered | in_dest
    fr = lambda m: float(np.count_nonzero(m)) / n  # noqa: E731
    impulse, min_gap, steps_done = watch.impulse, watch.min_gap, watch.steps_done
    return {
        "fractions": {"source": fr(in_src), "destination": fr(in_dest),
                      "elsewhere": fr(~in_src & ~in_dest), "entered_destination": fr(entered)},
        "displacement_mm": {s: round(stages[s].displacement, 3) for s in scoring.STAGES},
        "tilt_deg": {s: round(stages[s].tilt, 3) for s in scoring.STAGES},
        "final_tilt_deg": round(tilt_deg(dorn), 3),
        "contact_impulse": float(impulse),
        "min_gap_mm": 0.0 if impulse > 0 else (round(min_gap, 3) if math.isfinite(min_gap)
                                               else scoring.CLEAR_MM),
        "destination_mass_kg": w.pour.p["destination_mass"] / 1000.0,
        "particles": n,
        "simulated_s": round(steps_done * dt, 4),
        "steps": steps_done,
        "step_seconds": watch.step_seconds,
        "seconds": time.perf_counter() - t_begin,
    }
