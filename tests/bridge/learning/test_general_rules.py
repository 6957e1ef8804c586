"""The general rules and how they decide a question
(bridge/learning/general_rules.py): the highest ranked rule whose body the
scene holds decides (more specific first, then surer), an answer whose
likelihood lies within the band of one half is uncertain, and both engines
conclude, from the rules as a theory (`General.theory`), the head of the
deciding rule."""
from __future__ import annotations

import math

import numpy as np
import pytest

from pantarhei.bridge.verdicts import FAILS, HOLDS, UNKNOWN
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


# The learner ranks and answers without calling Prolog (it runs inside
# explore/1); these keep its reading equal to theory/learned_rules.pl's.

def _sample_rules(seed: int, n: int) -> list[tuple[str, int, bool, float | None]]:
    """n rules (id, body size, general, confidence) with many ties: equal
    sizes and layers, a confidence and its complement, exact halves of a
    billionth, no confidence, ids that order as text (g10 before g2)."""
    rng = np.random.default_rng(seed)
    ids = [f"{k}{i}_{e}" for k in "gr" for i in range(13) for e in ("no_spill", "source_clear")]
    seen: list[float] = [0.5]
    out = []
    for _ in range(n):
        kind, sign, j = int(rng.integers(7)), float(rng.choice([-1, 1])), 2 * int(rng.integers(8)) + 1
        if kind == 0:
            c = float(rng.random())
        elif kind == 1:
            c = int(rng.integers(0, 1001)) / 1000
        elif kind == 2:
            c = 1 - seen[int(rng.integers(len(seen)))]
        elif kind == 3:       # exactly half a billionth past a billionth
            c = 0.5 + sign * j / 1024
        elif kind == 4:       # the billionths on either side of those
            c = 0.5 + sign * (int(976562.5 * j) + int(rng.integers(2))) / 1e9
        elif kind == 5:       # a billionth or a few from another
            c = min(1.0, max(0.0, seen[int(rng.integers(len(seen)))] + int(rng.integers(-3, 4)) * 1e-9))
        else:
            c = None
        if c is not None:
            seen.append(c)
        out.append((ids[int(rng.integers(len(ids)))], int(rng.integers(0, 4)), bool(rng.integers(2)), c))
    return out


def test_the_rank_is_the_one_prolog_ranks_by() -> None:
    from pantarhei.bridge.engines.swipl import engine
    from pantarhei.bridge.learning.general_rules import rank

    rules = _sample_rules(7, 4000)
    keys = [rank(size, general, c, rid) for rid, size, general, c in rules]
    position = {k: i for i, k in enumerate(sorted(set(keys)))}
    e = engine()
    e.use_module("learned_rules")
    r = e.once("findall(rule(I, N, L, C), member([I, N, L, C], Xs), Rules), "
               "learned_rules:rank_order(Rules, Ps)",
               Xs=[[rid, size, "general" if general else "rule", "none" if c is None else c]
                   for rid, size, general, c in rules])
    assert r["Ps"] == [position[k] for k in keys]
    assert len(position) < len(keys)                  # ties, where the keys are equal


def test_the_verdict_and_likelihood_are_the_ones_prolog_answers_by() -> None:
    from pantarhei.bridge.engines.swipl import engine
    from pantarhei.bridge.learning.general_rules import verdict

    rng = np.random.default_rng(8)
    cases = [(holds, c / 1000, band) for holds in (True, False) for c in range(1001)
             for band in (0.0, 0.15, 0.2)]
    cases += [(bool(rng.integers(2)), float(x), float(b))
              for x, b in zip(rng.random(3000), rng.random(3000) / 2)]
    # at the band's edge: |x - 1/2| equal to the band less its 1e-9, or a hair either side
    cases += [(bool(h), float(0.5 + s * (b - 1e-9) + d), float(b))
              for b in rng.random(300) / 2 for s in (-1, 1) for d in (-1e-15, 0.0, 1e-15) for h in (0, 1)]
    e = engine()
    e.use_module("learned_rules")
    r = e.once("findall(V, (member([H, P, B], Cs), learned_rules:verdict(H, P, B, V)), Vs)",
               Cs=[["holds" if h else "fails", p, b] for h, p, b in cases])
    code = {"holds": HOLDS, "fails": FAILS, "uncertain": UNKNOWN}
    assert [verdict(h, p, b) for h, p, b in cases] == [code[str(v)] for v in r["Vs"]]
    assert verdict([True, False], [0.6, 0.9], 0.15).tolist() == [UNKNOWN, FAILS]
    # a learned rule's likelihood from its confidence in permille: the
    # confidence read from permille is Prolog's likelihood of a rule whose
    # head holds, to the last bit, and the likelihood of either head follows
    from pantarhei.bridge.learning.general_rules import confidence, likelihood

    r = e.once("findall(P, (between(0, 1000, C), member(L, [no_spill, neg(no_spill)]), "
               "learned_rules:likelihood(C, L, P)), Ps)")
    assert [confidence(c) for c in range(1001)] == r["Ps"][::2]
    ours = [likelihood(holds, confidence(c)) for c in range(1001) for holds in (True, False)]
    assert np.allclose(ours, r["Ps"], rtol=0, atol=1e-12)
    assert [GeneralRule("g", (), E, h, 0, 0, 0.7, 0).likelihood for h in (True, False)] == \
        [likelihood(h, 0.7) for h in (True, False)]


def test_layers_rank_a_theory_as_its_questions_do() -> None:
    """Algorithm 1's rules of a learned theory and a general layer beside
    them, ranked as bridge/learning/layers.py reads them (confidence from
    provenance), in the order queries.pl chooses its deciding rule by."""
    from pathlib import Path

    from pantarhei.bridge.learning.layers import ranked_rules
    from pantarhei.bridge.reasoning.logic import prolog_load
    from pantarhei.bridge.theories.loading import read_theory

    fixture = Path(__file__).parents[1] / "exploration" / "fixtures" / "paper_synthetic_seed3.pl"
    theory = read_theory(fixture)
    rng = np.random.default_rng(9)
    general = General(rules=[
        GeneralRule(f"g{k}_{r.head.removeprefix('neg(').rstrip(')')}", tuple(r.body),
                    r.head.removeprefix("neg(").rstrip(")"), not r.head.startswith("neg("),
                    0, 0, int(rng.integers(500, 1001)) / 1000, 0)
        for k, r in enumerate(theory.rules[::7])])
    ranked = ranked_rules(theory, general)
    both = general.theory()
    both.rules[:0] = theory.rules
    both.learned |= theory.learned
    both.provenance = list(theory.provenance) + [
        p for g in general.rules for p in ((g.id, "layer", "general"),
                                           (g.id, "confidence_permille", round(1000 * g.confidence)))]
    e = prolog_load(both)
    e.use_module("queries")
    r = e.once("findall(K-R, (member(R, Rs), queries:rank_key(R, K)), KRs), "
               "keysort(KRs, S), pairs_values(S, Ordered)", Rs=[x.id for x in ranked])
    assert [str(x) for x in r["Ordered"]] == [x.id for x in sorted(ranked, key=lambda x: x.rank)]
    assert len({x.rank[:3] for x in ranked}) > 1
