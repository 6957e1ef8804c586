"""The bodies a person can ask about (bridge/learning/askable.py): the
empty one, every proposition alone and exactly the pairs that SWI-Prolog's
validity constraints (theory/validity.pl) find valid; and whether two bodies
can hold together in one scene."""
from __future__ import annotations

from itertools import combinations

from pantarhei.bridge.learning.askable import askable_bodies, together, valid
from pantarhei.bridge.reasoning.valid_scenes import violations
from pantarhei.theory.lexicon import load_vocabulary

NAMES = sorted(load_vocabulary().propositions)


def test_the_askable_pairs_are_the_valid_ones() -> None:
    singles = [()] + [(n,) for n in NAMES]
    assert askable_bodies(0) == [()] and askable_bodies(1) == singles
    bodies = askable_bodies(2)
    assert bodies[:len(singles)] == singles
    valid = [p for p in combinations(NAMES, 2) if not violations(p, "prolog")]
    assert bodies[len(singles):] == valid
    assert 0 < len(valid) < len(NAMES) * (len(NAMES) - 1) // 2


def test_two_bodies_hold_together_when_their_union_is_valid() -> None:
    assert together(("pour_low",), ("light_liquid", "pour_centred"))
    assert together(("pour_low", "light_liquid"), ("light_liquid",))     # shared propositions
    assert not together(("pour_low",), ("light_liquid", "pour_high"))   # one value per dimension
    assert not together(("pour_below_rim",), ("pour_centred",))
    assert {v.constraint for v in violations(["pour_below_rim", "pour_centred"])} == {"inside_destination"}


def test_validity_read_from_clingo_s_pairs_is_prolog_s() -> None:
    """Every constraint is broken by a pair, so the pairs clingo names are
    all the learner needs: on many antecedents, valid and invalid alike,
    it says what Prolog's valid_antecedent/1 says."""
    import numpy as np

    from pantarhei.bridge.engines.swipl import engine

    rng = np.random.default_rng(5)
    linked = [n for n in NAMES if n.split("_")[0] in ("start", "pour", "end", "approach", "retreat")]
    sets = [sorted({str(p) for p in rng.choice(pool, size=int(rng.integers(0, k)))})
            for pool, k in ((NAMES, 8), (linked, 6)) for _ in range(5000)]
    r = engine().once("findall(V, (member(S, Ss), (validity:valid_antecedent(S) -> V = 1 ; V = 0)), Vs)",
                      Ss=sets)
    assert [int(valid(s)) for s in sets] == r["Vs"]
    assert 0.1 < sum(r["Vs"]) / len(sets) < 0.9
