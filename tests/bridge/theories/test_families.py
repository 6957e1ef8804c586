"""The benchmark theories of defeasible logic (bridge/theories/families.py):
each gives its known answers, from SWI-Prolog and from clingo, also the
variants under other semantic switches; and each comes in the size asked."""
from __future__ import annotations

import pytest

from pantarhei.bridge.reasoning.logic import ENGINES, Semantics, conclusions
from pantarhei.bridge.theories import families as bench

DEFAULT = Semantics()

CASES = [(bench.chain, 30), (bench.circle, 30), (bench.levels, 20), (bench.teams, 2),
         (bench.tree, 3), (bench.dag, 6)]


@pytest.mark.parametrize("engine", ENGINES)
@pytest.mark.parametrize("make,size", CASES, ids=[m.__name__ for m, _ in CASES])
def test_benchmark_theories_give_their_known_answers(engine: str, make, size: int) -> None:
    b = make(size)
    c = conclusions(b.theory, DEFAULT, engine)
    assert b.proved <= set(c["+d"])
    assert b.refuted <= set(c["-d"])
    assert (b.proved | b.refuted) >= {f"a{i}" for i in range(3)}   # the answers are not empty


@pytest.mark.parametrize("engine", ENGINES)
def test_benchmark_variants_under_other_switches(engine: str) -> None:
    circle = bench.circle(12, well_founded=False)
    c = conclusions(circle.theory, Semantics(well_founded=False), engine)
    assert not circle.undecided & (set(c["+d"]) | set(c["-d"]))
    teams = bench.teams(2, team_defeat=False)
    c = conclusions(teams.theory, Semantics(team_defeat=False), engine)
    assert teams.refuted <= set(c["-d"]) and teams.proved <= set(c["+d"])


def test_benchmark_sizes_are_as_asked() -> None:
    for name in bench.NAMES:
        b = bench.of_size(name, 1000)
        assert 250 <= b.size <= 1001, (name, b.size)
