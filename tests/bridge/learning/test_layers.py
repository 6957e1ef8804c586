"""The two layers of a learned theory (bridge/learning/layers.py),
Algorithm 1's rules and the general rules, as one linear order that both
engines follow."""
from __future__ import annotations

import pytest

from pantarhei.bridge.learning.general_rules import General, GeneralRule
from pantarhei.bridge.learning.layers import ranked_rules, superiority
from pantarhei.bridge.reasoning.logic import ENGINES, Semantics, conclusions
from pantarhei.bridge.theories.model import Rule, Theory


def layered(scene: list[str]) -> Theory:
    """Algorithm 1 explored the priors (a1: nothing said; 58% of its
    weighted pours spill) and a scene pouring low (a2: 90% keep no spill);
    the general layer's default is a near toss (51% keep no spill), with an
    exception pouring high."""
    t = Theory(facts=list(scene))
    t.rules += [Rule("r1_no_spill", "defeasible", "neg(no_spill)"),
                Rule("r2_no_spill", "defeasible", "no_spill", ("pour_low",))]
    t.provenance += [("r1_no_spill", "confidence_permille", 580),
                     ("r2_no_spill", "confidence_permille", 900)]
    g = General(rules=[GeneralRule("g0_no_spill", (), "no_spill", True, 700, 357, 0.51, 0),
                       GeneralRule("g1_no_spill", ("pour_high",), "no_spill", False, 40, 30, 0.7, 1)])
    t.learned = {r.id for r in t.rules}
    sup = superiority(ranked_rules(t, g))       # Algorithm 1's theory and the general layer
    t.rules += [r.rule() for r in g.rules]
    t.learned |= {r.id for r in g.rules}
    t.sup = sup
    return t


def test_of_two_rules_for_the_same_body_the_general_one_wins():
    t = layered([])
    # the general default beats Algorithm 1's rule for the priors, though
    # that one is surer: the general one is estimated from every pour
    assert ("g0_no_spill", "r1_no_spill") in t.sup
    # a larger body still wins first (specificity, derived by the engines),
    # and rules that no scene holds together get no sup/2
    assert not any("r2_no_spill" in pair and "g0_no_spill" in pair for pair in t.sup)
    assert ("g1_no_spill", "r1_no_spill") not in t.sup


@pytest.mark.parametrize("engine", ENGINES)
def test_both_engines_decide_by_the_layers_order(engine):
    def says(scene):
        c = conclusions(layered(scene), Semantics(), engine)
        return "no_spill" in c["+d"], "neg(no_spill)" in c["+d"]

    assert says([]) == (True, False)                  # the general default
    assert says(["pour_low"]) == (True, False)        # a2's rule, more specific
    assert says(["pour_high"]) == (False, True)       # the general exception
