"""bridge/evaluation/plan_checks.py: hard goal sets (a context and goals,
the liquid leaving the source added), and for each the ordinary pour with
its context, the plan the search finds with a small hand-built theory
(clingo, the synthetic oracle), its numbers and verification per goal,
measured again on FRESH times as many fresh pours, and the search of the
simulation alone; a goal set no plan meets says why, and a refuted plan
is never reported. And the report's section and headline row of
hand-built evaluations."""
from __future__ import annotations

import numpy as np
import pytest

from pantarhei.bridge.evaluation.plan_checks import (FRESH, GOAL_SETS, MET, SEARCH_BUDGET,
                                                     goal_sets, plan_checks, planner_budget,
                                                     plans_headline, plans_section)
from pantarhei.bridge.evaluation.rule_building import theory_of
from pantarhei.bridge.reasoning.plan_numbers import fixed_ranges
from pantarhei.bridge.reasoning.valid_scenes import violations
from pantarhei.theory.lexicon import load_vocabulary
from tests.bridge.evaluation.evaluations import small_evaluation

NAMES = load_vocabulary().expectation_names


def centred_theory():
    """Pouring centred: every expectation holds."""
    return theory_of([("pour_centred",)], np.ones((1, 9), dtype=bool), "centred")


@pytest.fixture(scope="module")
def synthetic(tmp_path_factory):
    from pantarhei.bridge.exploration.simulation import open_simulator

    with open_simulator("synthetic", store=tmp_path_factory.mktemp("s") / "s.sqlite") as sim:
        yield sim.simulate


def test_the_goal_sets_are_contexts_with_goals_the_liquid_leaving_added():
    vocab = load_vocabulary()
    sets = goal_sets()
    assert [w for w, _, _ in sets] == [w for w, _, _ in GOAL_SETS]
    assert len({w for w, _, _ in sets}) == len(sets) >= 5
    for _, given, goals in sets:
        assert given and not violations(given)
        assert set(goals) <= set(NAMES) and "liquid_leaves_source" not in goals


def test_no_plans_are_checked_without_verifying_pours(synthetic):
    assert plan_checks(centred_theory(), synthetic, 0, seed=1) == []


def test_each_goal_set_gets_a_verified_plan_with_its_numbers_or_says_why(synthetic):
    verify = 3
    out = plan_checks(centred_theory(), synthetic, verify, seed=1)
    assert [p["words"] for p in out] == [w for w, _, _ in goal_sets()]
    for p, (_, given, goals) in zip(out, goal_sets()):
        assert p["goals"] == goals + ["liquid_leaves_source"] and p["given"] == given
        assert 0 <= p["ordinary"]["met"] <= p["ordinary"]["simulated"] == verify
        assert p["pours"] <= planner_budget() * verify
        assert p["search"]["pours"] <= p["search"]["budget"] == SEARCH_BUDGET * verify
        if p["search"]["plan"] is not None:      # verified alike: confirmed on fresh pours
            assert p["search"]["met"] >= 0.9 * p["search"]["simulated"] == 0.9 * 2 * verify
        if "plan" not in p:
            assert p["none"].startswith(("every candidate refuted", "unreachable in the theory",
                                         "the budget of"))
            continue
        assert set(given) <= set(p["antecedent"]) and not violations(p["antecedent"])
        v = p["verified"]
        assert v["met"] >= 0.9 * v["simulated"] > 0 and v["simulated"] == 2 * verify
        assert [(b["batch"], b["simulated"]) for b in v["batches"]] == [("first", verify),
                                                                          ("confirming", verify)]
        assert set(v["per_goal"]) == set(p["goals"]) and min(v["per_goal"].values()) >= v["met"]
        assert p["numbers"] == [r.words() for r in fixed_ranges(p["antecedent"])]
        assert [r["goal"] for r in p["rests_on"]] == p["goals"]
        assert p["simulated"] == FRESH * verify and 0 <= p["met"] <= p["simulated"]
    # the synthetic oracle fills the bowl from a centred pour at the ordinary height
    sideways = out[[w for w, _, _ in goal_sets()].index(
        "pouring from the side, fill the bowl without spilling")]
    assert sideways["ordinary"]["met"] == 0
    assert any("plan" in p for p in out)


def test_a_refuted_plan_is_never_reported(synthetic):
    def nothing_goes_well(P):
        S = np.asarray(synthetic(P), dtype=float).copy()
        S[:, NAMES.index("no_spill")] = 0.0
        return S

    out = plan_checks(centred_theory(), nothing_goes_well, 2, seed=1)
    spills = [p for p in out if "no_spill" in p["goals"]]
    assert spills and not any("plan" in p for p in spills)
    assert all(p["none"].startswith(("every candidate refuted", "unreachable in the theory"))
               and "the best" in p["none"] for p in spills)
    assert all(p["search"]["plan"] is None for p in spills)
    # the simulation alone: every manner alone first, then pairs, until
    # its budget is spent (each plan tried takes 2 pours)
    for p in spills:
        s = p["search"]
        assert s["tried"] == s["singles"] + s["pairs"] and s["pours"] == 2 * s["tried"]
        assert s["pours"] + 2 > s["budget"] == SEARCH_BUDGET * 2
        assert s["pairs"] == 0 or s["singles"] == len(valid_singles(p["given"]))


def valid_singles(given):
    vocab = load_vocabulary()
    taken = {vocab.propositions[g].dimension for g in given}
    return [m for m, x in vocab.propositions.items() if vocab.dimensions[x.dimension].role == "manner"
            and x.dimension not in taken and not violations([*given, m])]


def test_the_plans_found_with_their_numbers_or_why_none(tmp_path):
    ev = small_evaluation()
    assert plans_section(ev, tmp_path)[-2:] == [
        "| no spill (no context) | - | pour_low | - | - | - | - | 8 of 8 | - |",
        "| everything goes well (no context) | - | (the context alone) | - | - | - | - | 7 of 8 | - |"]
    ev.plans = [
        {"words": "high", "given": ["pour_high"], "goals": ["no_spill", "liquid_leaves_source"],
         "ordinary": {"simulated": 4, "met": 1}, "none": "every candidate refuted: ...",
         "tried": 5, "pours": 20, "search": {"tried": 9, "pours": 30, "plan": None}},
        {"words": "side", "given": ["pour_to_side"], "goals": ["no_spill"],
         "ordinary": {"simulated": 4, "met": 0}, "plan": ["pour_low"], "tried": 2, "pours": 8,
         "numbers": ["pour_z 0 to 60 mm"],
         "rests_on": [{"goal": "no_spill", "rule": "g3_no_spill", "likelihood": 0.91}],
         "verified": {"simulated": 4, "met": 4, "per_goal": {"no_spill": 4},
                      "batches": [{"batch": "first", "simulated": 2, "met": 2},
                                  {"batch": "confirming", "simulated": 2, "met": 2}]},
         "simulated": 8, "met": 7,
         "search": {"tried": 3, "pours": 12, "plan": ["pour_low"], "met": 4, "simulated": 4,
                    "singles": 3, "pairs": 0}}]
    assert plans_section(ev, tmp_path)[-2:] == [
        "| high (pour_high) | 1 of 4 | none found: every candidate refuted: ... | - | - | - | "
        "20 (5 plans) | - | none in 30 pours |",
        "| side (pour_to_side) | 0 of 4 | pour_low | pour_z 0 to 60 mm | no_spill: g3_no_spill "
        "(91%) | no_spill 4/4 (every goal: 2/2, then 2/2 fresh) | 8 (2 plans) | 7 of 8 | "
        "pour_low: 4 of 4 (12 pours; 3 alone, 0 pairs tried) |"]
    ev.plans = []
    assert plans_section(ev, tmp_path)[-1] == "| (not verified) | | | | | | | | |"


def test_the_headline_counts_a_plan_missed_where_one_exists():
    ev = small_evaluation()
    ev.plans = [{"words": "a", "goals": [], "plan": ["pour_low"], "simulated": 10, "met": 9,
                 "search": {"plan": None, "pours": 10}},
                {"words": "b", "goals": [], "none": "every candidate refuted",
                 "search": {"plan": None, "pours": 10}}]
    (row,) = plans_headline(ev)
    assert row[1:] == ("90.0%", f"at least {MET:.0%} on each", True)     # b has no plan at all
    ev.plans[1]["search"] = {"plan": ["pour_low"], "met": 5, "simulated": 5, "pours": 10}
    (row,) = plans_headline(ev)
    assert row[1:] == ("0.0%", f"at least {MET:.0%} on each", False)     # b has one, missed
