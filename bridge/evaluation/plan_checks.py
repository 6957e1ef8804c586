"""Plans for hard goal sets: goal sets a person would ask under a context
the ordinary pour fails in (a given height, position, liquid or bowl).
For each: the ordinary pour with the context, simulated; the plan
`pantarhei plan` finds (plan_search.search: the theory's plans verified,
learned from when refuted, then manners searched in the simulation),
with its numbers and its verification per goal, measured again on
FRESH times as many fresh pours; and beside it a search of the simulation alone
(plan_search.search without the theory: every manner proposition alone
with the context, then pairs of the best singles), which says whether a
plan exists at all. Both verify a plan by the one criterion of
plan_search.verify (its first pours, then as many fresh ones confirming
it, the share of theory/defaults.pl pooled). The measure's stage,
headline row and report section."""
from __future__ import annotations

from pathlib import Path
from typing import Any, Callable

import numpy as np

from pantarhei.oracle.generative import sample

from pantarhei.bridge.errors import UserError
from pantarhei.bridge.evaluation.figures import Evaluation
from pantarhei.bridge.evaluation.formats import pct
from pantarhei.bridge.evaluation.inputs import Inputs
from pantarhei.bridge.exploration.simulation import iteration_seed
from pantarhei.bridge.theories.model import Theory

#: The share of a plan's fresh pours meeting its goals, at the least, for
#: every goal set a plan exists for.
MET = 0.80
#: The budget of the search of the simulation alone, in verifying pours
#: (`--verify`) each: enough for every manner alone (some 55 valid with a
#: context, most refuted in their first step of pours) and the first
#: pairs of the best singles. The planner's is the command's default
#: (theory/defaults.pl), in the same unit.
SEARCH_BUDGET = 50
#: The fresh pours a found plan is measured on, in verifying pours each:
#: enough that the share read is within a few points of the plan's own,
#: where twice the verifying pours read a plan that meets its goals in
#: nine pours of ten under the target about one time in ten.
FRESH = 8

#: Goal sets a person would ask under a context the ordinary pour fails
#: in: their words, the context, the goals (the liquid leaving the source
#: is added to each, as `plan` adds it).
GOAL_SETS = (
    ("pouring very high, fill the bowl without spilling", ["pour_very_high"],
     ["liquid_enters_destination", "no_spill"]),
    ("pouring offset sideways, fill the bowl without spilling", ["pour_offset_sideways"],
     ["liquid_enters_destination", "no_spill"]),
    ("pouring from the side, fill the bowl without spilling", ["pour_to_side"],
     ["liquid_enters_destination", "no_spill"]),
    ("pouring low, fill the bowl without touching it", ["pour_low"],
     ["source_clear", "liquid_enters_destination"]),
    ("starting below the rim, without touching or moving the bowl", ["start_below_rim"],
     ["source_clear", "destination_still_approach"]),
    ("ending below the rim, the bowl kept still and upright", ["end_below_rim"],
     ["destination_still_retreat", "destination_upright"]),
    ("a light liquid poured very high, fill the bowl without spilling",
     ["light_liquid", "pour_very_high"], ["liquid_enters_destination", "no_spill"]),
    ("a light bowl and a fast approach, the bowl kept still",
     ["fast_approach", "light_destination"],
     ["destination_still_approach", "destination_still_retreat"]),
)


def goal_sets() -> list[tuple[str, list[str], list[str]]]:
    """GOAL_SETS as lists: (words, context, goals)."""
    return [(words, list(given), list(goals)) for words, given, goals in GOAL_SETS]


def planner_budget() -> int:
    """The planner's budget in verifying pours: the command's default
    budget over its default verifying pours (theory/defaults.pl)."""
    from pantarhei.bridge.reasoning.planning import plan_defaults

    pours, _, budget = plan_defaults()
    return budget // pours


def plan_checks(theory: Theory, simulate: Callable[[np.ndarray], np.ndarray], verify: int,
                seed: int) -> list[dict[str, Any]]:
    """For each goal set, the ordinary pour with its context on `verify`
    pours, the plan `pantarhei plan` finds (verified with `verify` pours
    each and confirmed with as many, within planner_budget() times
    `verify` pours) measured on FRESH times as many fresh pours, and the search
    of the simulation alone (SEARCH_BUDGET times `verify`); none with
    `verify` 0."""
    from pantarhei.bridge.reasoning.plan_search import search
    from pantarhei.bridge.reasoning.planning import goals_met, plan_defaults, pouring_goals

    out = []
    if not verify:
        return out
    min_success = plan_defaults()[1]
    for i, (words, given, goals) in enumerate(goal_sets()):
        lits, added = pouring_goals(goals)
        entry: dict[str, Any] = {"words": words, "given": given, "goals": lits, "added": added}
        S = _done(simulate(sample(given, verify, iteration_seed(seed, 300_000 + 100 * i))))
        entry["ordinary"] = {"simulated": len(S), "met": int(goals_met(S, lits).sum())}
        run_seed = iteration_seed(seed, 300_001 + 100 * i)
        try:
            found = search(theory, goals, given, simulate, verify_pours=verify,
                           min_success=min_success, seed=run_seed,
                           budget=planner_budget() * verify)
            alone = search(theory, goals, given, simulate, verify_pours=verify,
                           min_success=min_success, seed=run_seed, budget=SEARCH_BUDGET * verify,
                           learn=False, use_theory=False)
        except UserError as e:
            entry["none"] = str(e)
            out.append(entry)
            continue
        entry["search"] = _searched(alone)
        entry.update(tried=len(found.tried), pours=found.pours, rounds=found.rounds)
        if not found.verified:
            entry["none"] = found.reason
            out.append(entry)
            continue
        t = found.verified[0]
        entry.update(plan=list(t.plan.chosen), antecedent=list(t.plan.antecedent), origin=t.origin,
                     numbers=_numbers(t.plan.antecedent),
                     rests_on=[s.as_dict() for s in t.said],
                     verified={"simulated": t.simulated, "met": t.met, "per_goal": t.per_goal,
                               "batches": [b.as_dict() for b in t.batches]})
        S = _done(simulate(sample(list(t.plan.antecedent), FRESH * verify,
                                  iteration_seed(seed, 350_000 + i))))
        entry.update(simulated=len(S), met=int(goals_met(S, lits).sum()),
                     per_goal={g: int(goals_met(S, [g]).sum()) for g in lits})
        out.append(entry)
    return out


def _done(S) -> np.ndarray:
    """The rows of scores whose simulation finished."""
    S = np.atleast_2d(np.asarray(S, dtype=float))
    return S[np.all(np.isfinite(S), axis=1)]


def _numbers(antecedent) -> list[str]:
    from pantarhei.bridge.reasoning.plan_numbers import fixed_ranges

    return [r.words() for r in fixed_ranges(antecedent)]


def _searched(found) -> dict[str, Any]:
    """The search of the simulation alone: what it tried, its pours, and
    the plan it verified (None: none)."""
    first = found.verified[0] if found.verified else None
    return {"tried": len(found.tried), "pours": found.pours, "budget": found.budget,
            "singles": sum(len(t.plan.chosen) == 1 for t in found.tried),
            "pairs": sum(len(t.plan.chosen) == 2 for t in found.tried),
            "plan": None if first is None else list(first.plan.chosen),
            "met": None if first is None else first.met,
            "simulated": None if first is None else first.simulated,
            "none": found.reason}


def plans_stage(ev: Evaluation, inputs: Inputs) -> None:
    """The plan for each hard goal set, verified with `--verify` pours and
    measured on FRESH times as many: `ev.plans`."""
    ev.plans = plan_checks(inputs.learned.theory, lambda X: inputs.run("plans", X, say=False),
                           inputs.opts.verify, inputs.opts.seed)


def _exists(p: dict) -> bool:
    """Does a plan exist for the goal set (found by the planner or by the
    search of the simulation)?"""
    return "plan" in p or bool((p.get("search") or {}).get("plan") is not None)


def plans_headline(ev: Evaluation) -> list[tuple[str, str, str, bool]]:
    """The lowest share of fresh pours meeting their goals among the goal
    sets a plan exists for (one the planner did not find: none met); no
    row when none was asked."""
    if not ev.plans:
        return []
    rates = [p["met"] / p["simulated"] if p.get("simulated") else 0.0
             for p in ev.plans if _exists(p) or "search" not in p]
    low = min(rates) if rates else None
    return [(f"plans for {len(ev.plans)} goal sets a user would ask, measured on fresh pours: "
             f"the lowest share meeting the goals",
             pct(low), f"at least {MET:.0%} on each", low is not None and low >= MET)]


def _share(met, simulated) -> str:
    return f"{met} of {simulated}" if simulated else "-"


def plans_section(ev: Evaluation, out: Path) -> list[str]:
    """The hard goal sets: the ordinary pour, the plan found (propositions,
    numbers, the rules its goals rest on, its verification per goal, the
    pours it took), measured on fresh pours; and the search of the
    simulation alone."""
    L = ["", "## Plans", "",
         "Goal sets a person would ask under a context the ordinary pour fails in (a height, a "
         "position, a liquid, a bowl); a pour pours, so the liquid leaving the source is a goal "
         "of each. For each: the ordinary pour with the context; the plan `pantarhei plan` finds "
         "(the theory's plans verified in the simulation, refuted ones learned from, then manners "
         "searched in the simulation), its numbers, the rules its goals rest on, its verification "
         "per goal over all its verifying pours and the pours its search took; the plan measured "
         f"again on {FRESH} times as many fresh pours; and, to say whether a plan exists, a "
         "search of the "
         "simulation alone (every manner proposition alone with the context, then pairs of the "
         "best singles, within "
         f"{SEARCH_BUDGET} times the verifying pours; the plans tried). Both verify a plan alike: "
         f"its goals met in {_bar()}.", "",
         "| goals (context) | ordinary pour | plan (manners chosen) | numbers | goals rest on | "
         "verified per goal | pours taken | fresh pours meeting the goals | simulation alone |",
         "|---|---|---|---|---|---|---|---|---|"]
    for p in ev.plans:
        head = f"{p['words']} ({', '.join(p.get('given', [])) or 'no context'})"
        o = p.get("ordinary") or {}
        ordinary = _share(o.get("met"), o.get("simulated"))
        s = p.get("search") or {}
        tried = (f"; {s['singles']} alone, {s['pairs']} pairs tried" if "singles" in s else "")
        if not s:
            alone = "-"
        elif s.get("plan") is None:
            alone = f"none in {s['pours']} pours{tried}"
        else:
            alone = (f"{', '.join(s['plan']) or 'the context alone'}: {s['met']} of "
                     f"{s['simulated']} ({s['pours']} pours{tried})")
        taken = f"{p['pours']} ({p['tried']} plans)" if "pours" in p else "-"
        if "plan" not in p:
            L.append(f"| {head} | {ordinary} | none found: {p.get('none', '')} | - | - | - | "
                     f"{taken} | - | {alone} |")
            continue
        rests = "; ".join(f"{r['goal']}: {r['rule'] or 'no rule'} {_like(r['likelihood'])}"
                          for r in p.get("rests_on", []))
        v = p.get("verified") or {}
        per_goal = "; ".join(f"{g} {n}/{v.get('simulated')}" for g, n in v.get("per_goal", {}).items())
        if len(v.get("batches", [])) > 1:
            per_goal += " (every goal: " + ", then ".join(
                f"{b['met']}/{b['simulated']}" + (" fresh" if b["batch"] == "confirming" else "")
                for b in v["batches"]) + ")"
        met = _share(p.get("met"), p.get("simulated")) if "simulated" in p else "not simulated"
        L.append(f"| {head} | {ordinary} | {', '.join(p['plan']) or '(the context alone)'} | "
                 f"{'; '.join(p.get('numbers', [])) or '-'} | {rests or '-'} | {per_goal or '-'} | "
                 f"{taken} | {met} | {alone} |")
    if not ev.plans:
        L.append("| (not verified) | | | | | | | | |")
    return L


def _bar() -> str:
    """The criterion of a verified plan, in words, with the defaults."""
    from pantarhei.bridge.reasoning.planning import plan_defaults

    share = plan_defaults()[1]
    return (f"at least {share:.0%} of its first `--verify` pours and again of all of them with "
            f"as many fresh ones, drawn after it passed the first")


def _like(x) -> str:
    return "" if x is None else f"({round(100 * x)}%)"
