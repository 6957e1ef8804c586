"""modify, run by the real SWI-Prolog from Python: on random antecedents and
directions, only valid, new antecedents that move along the direction, as
Python's validity checks and generative models see them. The single steps
(up and down a graded dimension, a free parameter, an invalid step, the
direction) are plunit tests beside the module: theory/curiosity/modify.plt."""
from __future__ import annotations

import numpy as np
import pytest

from pantarhei.bridge.exploration.session import install
from pantarhei.bridge.engines.swipl import text
from pantarhei.bridge.reasoning.valid_scenes import violations
from pantarhei.oracle.generative import distribution
from pantarhei.theory.lexicon import load_vocabulary

V = load_vocabulary()
NAMES = V.parameter_names


@pytest.fixture(scope="module")
def eng():
    return install()


def parse(eng, props, direction, breadth, exclude):
    d = "[" + ", ".join(f"{x}-({float(g)!r})" for x, g in direction) + "]"
    ex = "[" + ", ".join("[" + ", ".join(sorted(e)) + "]" for e in exclude) + "]"
    ps = "[" + ", ".join(props) + "]"
    results = []
    for sol in eng.query(f"curiosity:modify({ps}, {d}, {breadth}, {ex}, New), "
                         "member(mod(P, X, S), New), atomic_list_concat(P, ',', A)"):
        results.append((tuple(text(sol["A"]).split(",")) if text(sol["A"]) else (),
                        text(sol["X"]), text(sol["S"])))
    return results


def mean(eng, props, x):
    ps = "[" + ", ".join(props) + "]"
    return float(eng.once(f"curiosity:parameter_mean({ps}, {x}, M)")["M"])


def random_valid_antecedent(rng):
    dims = list(V.dimensions.values())
    while True:
        chosen = rng.choice(len(dims), size=rng.integers(0, 6), replace=False)
        props = sorted(dims[i].values[rng.integers(len(dims[i].values))] for i in chosen)
        if not violations(props):
            return props


def test_modify_keeps_only_valid_new_antecedents_moving_along_the_direction(eng):
    rng = np.random.default_rng(7)
    seen = 0
    for trial in range(60):
        props = random_valid_antecedent(rng)
        g = rng.normal(size=len(NAMES))
        direction = list(zip(NAMES, g))
        top = [NAMES[i] for i in np.argsort(-np.abs(g))[:3]]
        exclude = [props] + [random_valid_antecedent(rng) for _ in range(3)]
        first = parse(eng, props, direction, 3, [props])
        # exclude some of the answers of a first call: they must not come back
        exclude += [list(p) for p, _, _ in first[::2]]
        new = parse(eng, props, direction, 3, exclude)
        assert len(set(p for p, _, _ in new)) == len(new)
        for p1, x, sign in new:
            seen += 1
            assert list(p1) == sorted(p1)
            assert not violations(list(p1)), p1
            distribution(p1)                          # the generative models can sample it
            assert sorted(p1) not in [sorted(e) for e in exclude]
            assert x in top
            component = g[NAMES.index(x)]
            assert sign == ("up" if component > 0 else "down")
            moved = mean(eng, list(p1), x) - mean(eng, props, x)
            assert moved * component > 0
            # one proposition added, or one replaced by its neighbour in rank
            added, removed = set(p1) - set(props), set(props) - set(p1)
            assert len(added) == 1 and len(removed) <= 1
            if removed:
                (a,), (r,) = added, removed
                pa, pr = V.propositions[a], V.propositions[r]
                assert pa.dimension == pr.dimension and abs(pa.rank - pr.rank) == 1
    assert seen > 50
