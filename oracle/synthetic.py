"""A synthetic oracle: analytic score functions with known answers.

Each of the 9 expectation scores is a small formula of a few parameters,
built from ramps (0 below one value, 1 beyond another, linear in between),
their minimum and maximum. So it is known, for every expectation, which
parameters it depends on and in which direction (`DEPENDS`), and what its
verdict is anywhere (the score against one half). It follows the paper's
example rules: pouring from the side spills, a light liquid does not all
leave the source, and a light liquid with the source righted low above the
destination does not remain in it.

It is a real oracle (deterministic, picklable, named "synthetic") for
testing exploration without physics, and instantaneous. Setting the
environment variable PANTARHEI_SYNTHETIC_DELAY to a number of seconds makes
each simulation take that long, to watch or interrupt an exploration; the
scores do not depend on it.
"""
from __future__ import annotations

import os
import time
from typing import Any, Mapping

import numpy as np

from pantarhei.oracle.base import Oracle, Outcome
from pantarhei.theory import defaults
from pantarhei.theory.lexicon import load_vocabulary

#: Expectation -> {parameter: +1 if the score rises with it, -1 if it falls}.
DEPENDS: dict[str, dict[str, int]] = {
    "destination_still_approach": {"approach_duration": +1, "destination_mass": +1},
    "destination_still_retreat": {"retreat_duration": +1, "destination_mass": +1},
    "destination_still_settle": {"destination_friction": +1, "destination_mass": +1},
    "destination_upright": {"destination_mass": +1},
    "source_clear": {"pour_z": +1, "start_z": +1},
    "liquid_leaves_source": {"pour_pitch": +1, "particle_mass": +1},
    "liquid_enters_destination": {"pour_pitch": +1, "particle_mass": +1, "pour_x": -1,
                                  "pour_z": -1, "pour_y": -1},
    "liquid_remains_in_destination": {"pour_pitch": +1, "particle_mass": +1, "pour_x": -1,
                                      "pour_z": -1, "pour_y": -1, "end_z": +1},
    "no_spill": {"pour_x": -1, "pour_z": -1, "pour_y": -1},
}

DELAY_VARIABLE = "PANTARHEI_SYNTHETIC_DELAY"


def ramp(x: float, zero: float, one: float) -> float:
    """0 at `zero`, 1 at `one`, linear in between and flat beyond (falling
    when one < zero)."""
    return float(min(1.0, max(0.0, (x - zero) / (one - zero))))


def scores(v: Mapping[str, float]) -> np.ndarray:
    """The 9 scores of the parameterization v (name -> value, theory units),
    in the vocabulary's expectation order."""
    leaves = min(ramp(v["pour_pitch"], 40, 100), ramp(v["particle_mass"], 200, 1000))
    no_spill = min(ramp(v["pour_x"], 120, 80), ramp(v["pour_z"], 300, 150),
                   ramp(v["pour_y"], 60, 20))
    enters = min(leaves, no_spill)
    remains = min(enters, max(ramp(v["particle_mass"], 300, 1200), ramp(v["end_z"], 20, 120)))
    s = {
        "destination_still_approach": max(ramp(v["approach_duration"], 300, 1200),
                                          ramp(v["destination_mass"], 200, 800)),
        "destination_still_retreat": max(ramp(v["retreat_duration"], 300, 1200),
                                         ramp(v["destination_mass"], 200, 800)),
        "destination_still_settle": max(ramp(v["destination_friction"], 100, 600),
                                        ramp(v["destination_mass"], 300, 1000)),
        "destination_upright": ramp(v["destination_mass"], 25, 100),
        "source_clear": min(ramp(v["pour_z"], -30, 10), ramp(v["start_z"], -30, 10)),
        "liquid_leaves_source": leaves,
        "liquid_enters_destination": enters,
        "liquid_remains_in_destination": remains,
        "no_spill": no_spill,
    }
    return np.array([s[e] for e in load_vocabulary().expectation_names])


class SyntheticOracle(Oracle):
    """Analytic scores of the parameters (see the module's documentation)."""

    name = "synthetic"
    version = "2"

    def score(self, p: np.ndarray) -> Outcome:
        delay = os.environ.get(DELAY_VARIABLE)
        if delay:
            time.sleep(float(delay))
        names = load_vocabulary().parameter_names
        v = dict(zip(names, (float(x) for x in np.asarray(p, dtype=float))))
        s = scores(v)
        holds = float(defaults()["verdict_threshold"])
        record: dict[str, Any] = {"oracle": "synthetic",
                                  "verdicts": {e: bool(x > holds) for e, x in
                                               zip(load_vocabulary().expectation_names, s)}}
        return Outcome(s, record)
