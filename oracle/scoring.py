"""The 9 expectation scores, computed from the record of a pour.

Each score is continuous in [0, 1]: 1 when the expectation plainly holds,
0 when it plainly fails, and the verdict is "holds" when the score is above
one half. The record (see `physics.PouringOracle`) holds what was observed:

* ``displacement_mm[stage]`` / ``tilt_deg[stage]``: the largest distance the
  destination moved, and the largest angle its axis turned, from where it was
  at the beginning of the stage (approach, retreat, settle);
* ``final_tilt_deg``: the angle between the destination's axis and the
  vertical at the end;
* ``contact_impulse``: the total impulse (N s) of the contacts between the
  source and the destination; ``min_gap_mm``: the smallest distance between
  them (0 if they touched);
* ``fractions``: of the particles, those in the source, in the destination
  and elsewhere at the end, and ``entered_destination``: those that were
  inside the destination at some time.

The scores are continuous in what was observed: no score jumps when one
particle more or less ends up somewhere.
"""
from __future__ import annotations

from typing import Any, Mapping

import numpy as np

#: The destination counts as still if it moves less than half of this (mm)...
STILL_MM = 20.0
#: ...and turns less than half of this (degrees) during a stage.
STILL_DEG = 20.0
#: The destination counts as upright if it ends tilted less than half of this.
UPRIGHT_DEG = 45.0
#: A gap this wide (mm) between source and destination scores 1 for source_clear.
CLEAR_MM = 10.0
#: Of the liquid that entered the destination, the share that left it again
#: is taken relative to at least this fraction of all the liquid (so that the
#: score does not jump when a particle or two enter and leave).
REMAINS_FLOOR = 0.1
#: A contact impulse that would change the destination's speed by this much
#: (m/s) scores 0 for source_clear.
BUMP_SPEED = 0.1

STAGES = ("approach", "retreat", "settle")


def _clip(x: float) -> float:
    return float(min(1.0, max(0.0, x)))


def still(displacement_mm: float, tilt_deg: float) -> float:
    """1 - the larger of the normalised displacement and tilt."""
    return 1.0 - _clip(max(displacement_mm / STILL_MM, tilt_deg / STILL_DEG))


def clear(min_gap_mm: float, contact_impulse: float, destination_mass_kg: float) -> float:
    """Above 1/2 if the source never touched the destination (rising with the
    smallest gap), below 1/2 if it did (falling with the impulse)."""
    if contact_impulse > 0 or min_gap_mm <= 0:
        return 0.5 * (1.0 - _clip(contact_impulse / (destination_mass_kg * BUMP_SPEED)))
    return 0.5 + 0.5 * _clip(min_gap_mm / CLEAR_MM)


def scores(record: Mapping[str, Any]) -> np.ndarray:
    """The 9 scores, in the vocabulary's expectation order."""
    f = record["fractions"]
    entered = f["entered_destination"]
    left = max(0.0, entered - f["destination"])
    remains = 1.0 - left / max(entered, REMAINS_FLOOR)
    out = [still(record["displacement_mm"][s], record["tilt_deg"][s]) for s in STAGES]
    out += [
        1.0 - _clip(record["final_tilt_deg"] / UPRIGHT_DEG),
        clear(record["min_gap_mm"], record["contact_impulse"], record["destination_mass_kg"]),
        1.0 - f["source"],
        entered,
        _clip(remains),
        1.0 - f["elsewhere"],
    ]
    return np.clip(np.array(out, dtype=float), 0.0, 1.0)


#: One sentence per expectation: how its score is computed.
EXPLANATIONS = {
    "destination_still_approach": "1 minus the larger of the destination's largest displacement "
                                  f"during the approach over {STILL_MM:g} mm and its largest tilt "
                                  f"over {STILL_DEG:g} degrees, clipped to [0, 1].",
    "destination_still_retreat": "the same during the retreat.",
    "destination_still_settle": "the same while everything settles after the retreat.",
    "destination_upright": f"1 minus the destination's final tilt from the vertical over {UPRIGHT_DEG:g} "
                           "degrees, clipped.",
    "source_clear": f"if the bowls never touched, 1/2 + 1/2 of their smallest gap over {CLEAR_MM:g} mm "
                    "(clipped); if they did, 1/2 minus 1/2 of the contact impulse over the impulse "
                    f"that changes the destination's speed by {BUMP_SPEED:g} m/s (clipped).",
    "liquid_leaves_source": "the fraction of the particles that are out of the source at the end.",
    "liquid_enters_destination": "the fraction of the particles that were inside the destination "
                                 "at some time.",
    "liquid_remains_in_destination": "1 minus the fraction of the particles that entered the "
                                     "destination and left it again, over the fraction that "
                                     f"entered (but at least {REMAINS_FLOOR:g}), clipped.",
    "no_spill": "1 minus the fraction of the particles that end in neither bowl.",
}
