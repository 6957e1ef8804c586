"""Prolog (tabling, well-founded semantics) and ASP (clingo) give the same
conclusions on 1,000 random theories with conflicts, cycles, defeaters,
superiority and learned rules, each under every combination of the
semantic switches (ambiguity blocking/propagation, team defeat or not,
well-founded or Kunen)."""
from __future__ import annotations

from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from pantarhei.bridge.reasoning.logic import ALL_SEMANTICS, asp_conclusions, prolog_conclusions_batch
from pantarhei.bridge.theories.model import Rule, Theory, superiority_cycle

ATOMS = ("a", "b", "c", "d", "p(x)")
literals = st.builds(lambda a, n: f"neg({a})" if n else a, st.sampled_from(ATOMS), st.booleans())


@st.composite
def theories(draw) -> Theory:
    facts = draw(st.lists(literals, max_size=2, unique=True))
    n = draw(st.integers(1, 8))
    rules = [Rule(f"r{i}", draw(st.sampled_from(("strict", "defeasible", "defeasible", "defeater"))),
                  draw(literals), tuple(draw(st.lists(literals, max_size=2, unique=True))))
             for i in range(n)]
    ids = [r.id for r in rules]
    sup = draw(st.lists(st.tuples(st.sampled_from(ids), st.sampled_from(ids)).filter(lambda p: p[0] != p[1]),
                        max_size=3, unique=True))
    learned = set(draw(st.lists(st.sampled_from(ids), max_size=n, unique=True)))
    theory = Theory(facts, rules, sup, learned)
    while superiority_cycle(theory.sup + theory.specificity()):   # both engines reject a cycle
        theory.sup.pop()
    return theory


# 20 examples of 25 theories: 500 theories, one Prolog process per example.
@settings(max_examples=20, deadline=None, derandomize=True,
          suppress_health_check=[HealthCheck.too_slow, HealthCheck.data_too_large])
@given(st.lists(theories(), min_size=25, max_size=25))
def test_prolog_and_asp_agree_under_every_switch(batch: list[Theory]) -> None:
    jobs = [(theory, s) for theory in batch for s in ALL_SEMANTICS]
    for (theory, semantics), expected in zip(jobs, prolog_conclusions_batch(jobs)):
        assert asp_conclusions(theory, semantics) == expected, (semantics, theory.native())


def test_random_theories_exercise_every_kind_of_conclusion() -> None:
    """The generator is not trivial: its theories have undecided literals
    (ambiguity, loops) as well as all four conclusions."""
    seen = {"+D": 0, "-D": 0, "+d": 0, "-d": 0, "undecided": 0}

    @settings(max_examples=100, deadline=None, derandomize=True, database=None)
    @given(theories())
    def collect(theory: Theory) -> None:
        c = asp_conclusions(theory, ALL_SEMANTICS[1])   # Kunen: loops stay undecided
        for tag in ("+D", "-D", "+d", "-d"):
            seen[tag] += len(c[tag])
        lits = {x for r in theory.rules for x in (r.head, *r.body)}
        seen["undecided"] += len(lits - set(c["+d"]) - set(c["-d"]))

    collect()
    assert all(v > 0 for v in seen.values()), seen
