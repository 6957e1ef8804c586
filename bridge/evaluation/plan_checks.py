"""Plans for goal sets a user would ask, as `pantarhei plan` prints them
(verified in simulation), measured again on fresh pours. Part of
`pantarhei evaluate` (pipeline.py)."""
from __future__ import annotations

from typing import Any, Callable

import numpy as np

from pantarhei.oracle.generative import sample
from pantarhei.theory.lexicon import load_vocabulary

from pantarhei.bridge.errors import UserError
from pantarhei.bridge.exploration.simulation import iteration_seed
from pantarhei.bridge.theories.model import Theory

#: Goal sets a user would ask a plan for, with their words.
GOAL_SETS = (
    ("no spill", ["no_spill"]),
    ("all the liquid into the destination, and kept there",
     ["liquid_leaves_source", "liquid_enters_destination", "liquid_remains_in_destination"]),
    ("the destination kept still and upright",
     ["destination_still_approach", "destination_still_retreat", "destination_still_settle",
      "destination_upright"]),
    ("empty the source without spilling", ["liquid_leaves_source", "no_spill"]),
    ("a clean pour: no bump, no spill, the liquid stays in",
     ["source_clear", "no_spill", "liquid_remains_in_destination"]),
    ("everything goes well", None),
    ("carry the liquid without pouring any", ["neg(liquid_leaves_source)", "no_spill"]),
    ("empty the source, but not into the destination",
     ["liquid_leaves_source", "neg(liquid_enters_destination)"]),
)


def goal_sets() -> list[tuple[str, list[str]]]:
    """GOAL_SETS with every expectation for "everything goes well"."""
    names = load_vocabulary().expectation_names
    return [(words, list(goals) if goals else list(names)) for words, goals in GOAL_SETS]


def plan_checks(theory: Theory, simulate: Callable[[np.ndarray], np.ndarray], verify: int,
                seed: int) -> list[dict[str, Any]]:
    """For each goal set, the plan `pantarhei plan` would print (the first
    of the theory's plans whose goals were met in at least 90% of `verify`
    pours), measured again on twice as many fresh pours; none with
    `verify` 0."""
    from pantarhei.bridge.reasoning.planning import goals_met, verified_plans

    out = []
    if not verify:
        return out
    for i, (words, goals) in enumerate(goal_sets()):
        entry: dict[str, Any] = {"goals": goals, "words": words}
        try:
            good, tried = verified_plans(theory, goals, [], simulate,
                                         verify, iteration_seed(seed, 300_000 + 100 * i),
                                         0.9)
        except UserError as e:
            entry["none"] = str(e)
            out.append(entry)
            continue
        entry["tried"] = len(tried)
        if not good:
            entry["none"] = "no plan the theory proposes met the goals in 90% of its pours"
            out.append(entry)
            continue
        p = good[0].plan
        n = 2 * verify
        P = sample(list(p.antecedent), n, iteration_seed(seed, 350_000 + i))
        S = simulate(P)
        rows = S[np.all(np.isfinite(S), axis=1)]
        entry.update(plan=list(p.chosen), antecedent=list(p.antecedent),
                     simulated=int(len(rows)), met=int(goals_met(rows, goals).sum()))
        out.append(entry)
    return out
