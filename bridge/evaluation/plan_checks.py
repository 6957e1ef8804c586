"""Plans for goal sets a user would ask, as `pantarhei plan` prints them
(verified in simulation), measured again on fresh pours. The measure's
stage, headline row and report section."""
from __future__ import annotations

from pathlib import Path
from typing import Any, Callable

import numpy as np

from pantarhei.oracle.generative import sample
from pantarhei.theory.lexicon import load_vocabulary

from pantarhei.bridge.errors import UserError
from pantarhei.bridge.evaluation.formats import pct
from pantarhei.bridge.evaluation.pipeline import Evaluation, Inputs
from pantarhei.bridge.exploration.simulation import iteration_seed
from pantarhei.bridge.theories.model import Theory

#: The share of a plan's fresh pours meeting its goals, at the least, for every goal set.
MET = 0.90

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


def plans_stage(ev: Evaluation, inputs: Inputs) -> None:
    """The plan for each goal set, verified with `--verify` pours and
    measured on twice as many: `ev.plans`."""
    ev.plans = plan_checks(inputs.learned.theory, lambda X: inputs.run("plans", X, say=False),
                           inputs.opts.verify, inputs.opts.seed)


def plans_headline(ev: Evaluation) -> list[tuple[str, str, str, bool]]:
    """The lowest share of fresh pours meeting their goals among the goal
    sets (a goal set without a plan: none); no row when none was asked."""
    rates = [p["met"] / p["simulated"] if p.get("simulated") else 0.0 for p in ev.plans]
    if not rates:
        return []
    return [(f"plans for {len(rates)} goal sets a user would ask, measured on fresh pours: "
             f"the lowest share meeting the goals",
             pct(min(rates)), "at least 90% on each", min(rates) >= MET)]


def plans_section(ev: Evaluation, out: Path) -> list[str]:
    """The plans for the goal sets, measured on fresh pours."""
    L = ["", "## Plans", "",
         "For each goal set a user would ask, the plan `pantarhei plan` prints: the first of "
         "the theory's plans whose goals were met in at least 90% of the pours that verify "
         "it; then measured again on twice as many fresh pours.", "",
         "| goals | plan (manners chosen) | fresh pours meeting the goals |", "|---|---|---|"]
    for p in ev.plans:
        if "plan" not in p:
            L.append(f"| {p['words']} | none found: {p.get('none', '')} | - |")
            continue
        met = f"{p['met']} of {p['simulated']}" if "simulated" in p else "not simulated"
        L.append(f"| {p['words']} | {', '.join(p['plan']) or '(an ordinary pour)'} | {met} |")
    if not ev.plans:
        L.append("| (not verified) | | |")
    return L
