"""Hand-made parameterizations of pours for the tests (theory units)."""
from __future__ import annotations

import numpy as np

from pantarhei.oracle.generative import from_dict, sample
from pantarhei.theory.lexicon import load_vocabulary

BASE = dict(
    start_x=150, start_y=0, start_z=100, start_roll=0, start_pitch=0, start_yaw=0,
    pour_x=150, pour_y=0, pour_z=100, pour_roll=0, pour_pitch=0, pour_yaw=0,
    end_x=150, end_y=0, end_z=150, end_roll=0, end_pitch=0, end_yaw=0,
    approach_duration=800, retreat_duration=800,
    source_mass=500, source_restitution=100, source_friction=500,
    destination_mass=800, destination_restitution=100, destination_friction=800,
    particle_mass=1000, particle_restitution=100, particle_friction=300, particle_count=24)


def pour(**changes: float) -> np.ndarray:
    """BASE with some parameters changed, as a row of 30 numbers."""
    unknown = set(changes) - set(BASE)
    assert not unknown, unknown
    return from_dict({**BASE, **changes})


def with_counts(counts, seed: int = 7) -> np.ndarray:
    """Pours drawn from the prior with the given particle counts (by which
    the faulty oracle picks the pours that crash or hang), one row each."""
    P = sample([], len(counts), seed=seed)
    P[:, load_vocabulary().parameter("particle_count").index] = counts
    return P


#: The source moves over the destination but never tilts.
NEVER_TILTED = dict(start_x=150, pour_x=0, pour_z=60, end_x=-120, end_z=120)
#: Tipped fully while centred low over the destination, then taken away upright.
CENTRED_LOW_TIPPED = dict(pour_x=0, pour_z=15, pour_pitch=110, end_x=150, end_z=150)
#: Tipped fully far to the side of the destination.
FAR_SIDE_TIPPED = dict(pour_x=230, pour_z=40, pour_pitch=120, end_x=240, end_z=150, end_pitch=120)
#: Heavy liquid dropped from high into a very light, slippery destination.
HEAVY_DROP = dict(start_x=0, start_z=400, pour_x=20, pour_z=400, pour_pitch=180, end_x=20,
                  end_z=400, end_pitch=180, approach_duration=300,
                  destination_mass=20, destination_friction=0, particle_mass=10000,
                  particle_count=60, particle_restitution=500)
