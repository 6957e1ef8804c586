"""The general rules and how they decide a question
(bridge/learning/general_rules.py): the highest ranked rule whose body the
scene holds decides (more specific first, then surer), an answer whose
likelihood lies within the band of one half is uncertain, and both engines
conclude, from the rules as a theory (`General.theory`), the head of the
deciding rule."""
from __future__ import annotations

import math

import pytest

from pantarhei.bridge.evaluation.measures import FAILS, HOLDS, UNKNOWN
from pantarhei.bridge.learning.general_rules import General, GeneralRule, Sup
from pantarhei.bridge.reasoning.logic import ENGINES, Semantics, conclusions
from pantarhei.theory.lexicon import load_vocabulary

E = "no_spill"
# an ordinary pour keeps no spill; from the side it spills; low with a
# light liquid it is a near toss, and that more specific body wins over the
# side, which it does not contain (sup/2 by rank)
G0 = GeneralRule("g0_no_spill", (), E, True, 100, 80, 0.8, 0)
G1 = GeneralRule("g1_no_spill", ("pour_to_side",), E, False, 40, 36, 0.9, 1)
G2 = GeneralRule("g2_no_spill", ("light_liquid", "pour_low"), E, True, 20, 12, 0.6, 1)
GENERAL = General(rules=[G0, G1, G2], sup=[Sup(G1.id, G0.id, "specificity"), Sup(G2.id, G1.id, "rank")],
                  band=0.15)

#: scene -> (verdict, likelihood that no_spill holds, deciding rule)
SCENES = {
    (): (HOLDS, 0.8, G0),
    ("pour_to_side",): (FAILS, 0.1, G1),
    ("light_liquid", "pour_to_side"): (FAILS, 0.1, G1),
    ("light_liquid", "pour_low"): (UNKNOWN, 0.6, G2),               # within the band: uncertain
    ("light_liquid", "pour_low", "pour_to_side"): (UNKNOWN, 0.6, G2),
}


def test_the_highest_ranked_rule_decides() -> None:
    assert G2.rank > G1.rank > G0.rank
    for scene, (verdict, likelihood, rule) in SCENES.items():
        v, p, rid = GENERAL.answer(scene)[E]
        assert (v, rid) == (verdict, rule.id) and p == pytest.approx(likelihood), scene
        assert GENERAL.decide(scene)[E] == (verdict, rule.id)
    # no rule for the other expectations: undecided
    v, p, rid = GENERAL.answer(())["liquid_leaves_source"]
    assert (v, rid) == (UNKNOWN, None) and math.isnan(p)
    names = load_vocabulary().expectation_names
    assert GENERAL.predict([("pour_to_side",)])[0].tolist() == [FAILS if e == E else UNKNOWN for e in names]


@pytest.mark.parametrize("engine", ENGINES)
def test_both_engines_conclude_the_deciding_rule_s_head(engine: str) -> None:
    theory = GENERAL.theory()
    assert theory.learned == {G0.id, G1.id, G2.id} and theory.sup == [(G2.id, G1.id)]
    for scene, (_, _, rule) in SCENES.items():
        c = conclusions(theory.with_facts(scene), Semantics(), engine)
        other = f"neg({E})" if rule.holds else E
        assert rule.head in c["+d"] and other in c["-d"], (scene, c)
