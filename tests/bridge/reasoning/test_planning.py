"""Planning a pour (bridge/reasoning/planning.py, clingo): the manners
chosen make the theory conclude the goal, as SWI-Prolog concludes it from
the plan's antecedent; what is given is kept; a goal no valid choice of
manners reaches is refused, naming it."""
from __future__ import annotations

import pytest

from pantarhei.bridge.errors import UserError
from pantarhei.bridge.reasoning.logic import conclusions
from pantarhei.bridge.reasoning.planning import Plan, parse_goal, plan, pouring_goals
from pantarhei.bridge.theories.model import Rule, Theory

#: pouring spills, unless poured centred
THEORY = Theory(rules=[Rule("r1", "defeasible", "neg(no_spill)"),
                       Rule("r2", "defeasible", "no_spill", ("pour_centred",))],
                sup=[("r2", "r1")], source="centred.pl")


@pytest.mark.parametrize("goal,literal", [("spill", "spill"), ("-no_spill", "neg(no_spill)"),
                                          ("not no_spill", "neg(no_spill)"),
                                          ("neg(no_spill)", "neg(no_spill)")])
def test_a_goal_is_read_as_a_literal(goal: str, literal: str) -> None:
    assert parse_goal(goal) == literal


def test_the_plan_makes_the_theory_conclude_the_goal() -> None:
    plans = plan(THEORY, ["no_spill"], ["light_liquid"])
    assert plans == [Plan(("pour_centred",), ("light_liquid", "pour_centred"))]
    assert "no_spill" in conclusions(THEORY.with_facts(plans[0].antecedent))["+d"]
    # the default concludes the negated goal: nothing need be chosen
    assert plan(THEORY, ["-no_spill"])[0].chosen == ()


def test_a_goal_that_no_valid_manner_reaches_is_refused() -> None:
    # pouring from the side leaves no way to pour centred
    with pytest.raises(UserError, match="^unreachable goal: no valid choice of manners makes the "
                                        "theory conclude no_spill given pour_to_side$"):
        plan(THEORY, ["no_spill"], ["pour_to_side"])


@pytest.mark.parametrize("goals,out,added", [
    (["source_clear"], ["source_clear", "liquid_leaves_source"], ["liquid_leaves_source"]),
    (["-no_spill"], ["neg(no_spill)", "liquid_leaves_source"], ["liquid_leaves_source"]),
    (["liquid_leaves_source", "no_spill"], ["liquid_leaves_source", "no_spill"], []),
    (["-liquid_leaves_source"], ["neg(liquid_leaves_source)"], []),
])
def test_a_pour_pours_unless_a_goal_says_otherwise(goals, out, added) -> None:
    assert pouring_goals(goals) == (out, added)


def test_a_plan_chosen_exactly_is_excluded_but_not_what_adds_to_it() -> None:
    plans = plan(THEORY, ["no_spill"], ["light_liquid"], exclude=[("pour_centred",)])
    assert plans and all(p.chosen != ("pour_centred",) and "pour_centred" in p.chosen
                         and len(p.chosen) == 2 and "light_liquid" in p.antecedent for p in plans)
    # the theory reaches the negated goal with nothing chosen; excluded, it
    # adds a manner that keeps the default deciding
    plans = plan(THEORY, ["-no_spill"], exclude=[()], alternatives=2)
    assert plans and all(p.chosen and "pour_centred" not in p.chosen for p in plans)
