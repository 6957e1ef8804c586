"""bridge/evaluation/plan_checks.py: the goal sets a user would ask (every
expectation for "everything goes well"), and for each the plan a small
hand-built theory proposes (clingo), verified and measured again on twice
as many fresh pours of a stand-in oracle; a goal set no rule reaches, or no
plan meets, says why; failed pours are not counted. And the report's
section of a hand-built evaluation."""
from __future__ import annotations

import numpy as np

from pantarhei.bridge.evaluation.plan_checks import GOAL_SETS, goal_sets, plan_checks, plans_section
from pantarhei.bridge.evaluation.rule_building import theory_of
from pantarhei.theory.lexicon import load_vocabulary
from tests.bridge.evaluation.evaluations import small_evaluation

NAMES = load_vocabulary().expectation_names


def low_theory():
    """Pouring low: every expectation holds."""
    return theory_of([("pour_low",)], np.ones((1, 9), dtype=bool), "low")


def all_hold(P: np.ndarray) -> np.ndarray:
    return np.full((len(P), 9), 0.9)


def test_the_goal_sets_with_every_expectation_for_everything_goes_well():
    sets = goal_sets()
    assert [w for w, _ in sets] == [w for w, _ in GOAL_SETS]
    assert dict(sets)["no spill"] == ["no_spill"]
    assert dict(sets)["everything goes well"] == list(NAMES)
    assert dict(sets)["carry the liquid without pouring any"] == \
        ["neg(liquid_leaves_source)", "no_spill"]


def test_no_plans_are_checked_without_verifying_pours():
    assert plan_checks(low_theory(), all_hold, 0, seed=1) == []


def test_each_reachable_goal_set_gets_the_theorys_plan_measured_on_twice_the_pours():
    out = plan_checks(low_theory(), all_hold, 3, seed=1)
    assert [p["words"] for p in out] == [w for w, _ in goal_sets()]
    assert [p["goals"] for p in out] == [g for _, g in goal_sets()]
    reached = [p for p in out if "plan" in p]
    # every goal set but the two that ask for a negated expectation
    assert len(reached) == len(out) - 2
    for p in reached:
        assert p["plan"] == ["pour_low"] and p["antecedent"] == ["pour_low"]
        assert p["tried"] == 1 and p["simulated"] == 6 and p["met"] == 6
    carry = out[[w for w, _ in goal_sets()].index("carry the liquid without pouring any")]
    assert carry["none"] == "unreachable goal: no rule of low concludes neg(liquid_leaves_source)"
    assert "plan" not in carry and "simulated" not in carry


def test_a_plan_whose_pours_miss_the_goals_is_none():
    out = plan_checks(low_theory(), lambda P: np.full((len(P), 9), 0.1), 3, seed=1)
    first = out[0]
    assert first["words"] == "no spill" and first["tried"] == 1
    assert first["none"] == "no plan the theory proposes met the goals in 90% of its pours"
    assert not any("plan" in p for p in out)


def test_failed_fresh_pours_are_not_counted():
    calls = []

    def every_other_fails(P: np.ndarray) -> np.ndarray:
        calls.append(len(P))
        S = all_hold(P)
        S[1::2] = np.nan
        if len(calls) == 2:                     # the fresh pours: the first spills
            S[0, NAMES.index("no_spill")] = 0.1
        return S

    first = plan_checks(low_theory(), every_other_fails, 4, seed=1)[0]
    assert first["goals"] == ["no_spill"] and calls[:2] == [4, 8]
    # 8 fresh pours, 4 of them failed, one of the others spilled
    assert (first["simulated"], first["met"]) == (4, 3)


def test_the_plans_found_measured_or_why_none(tmp_path):
    ev = small_evaluation()
    assert plans_section(ev, tmp_path)[-2:] == ["| no spill | pour_low | 8 of 8 |",
                                        "| everything goes well | (an ordinary pour) | 7 of 8 |"]
    ev.plans = [{"words": "carry", "goals": [], "none": "unreachable goal: no rule concludes it"},
                {"words": "no spill", "goals": [], "plan": ["pour_low", "pour_centred"]}]
    assert plans_section(ev, tmp_path)[-2:] == [
        "| carry | none found: unreachable goal: no rule concludes it | - |",
        "| no spill | pour_low, pour_centred | not simulated |"]
    ev.plans = []
    assert plans_section(ev, tmp_path)[-1] == "| (not verified) | | |"
