"""Defeasible reasoning: known answers of classic and benchmark theories,
from SWI-Prolog and from clingo, under the semantic switches."""
from __future__ import annotations

import pytest

from pantarhei.bridge.theories import families as bench
from pantarhei.bridge.theories.dfl import parse_dfl
from pantarhei.bridge.reasoning.logic import ENGINES, Semantics, conclusions
from pantarhei.bridge.theories.model import Rule, Theory

DEFAULT = Semantics()


def concl(dfl: str, engine: str, semantics: Semantics = DEFAULT) -> dict[str, set[str]]:
    return {k: set(v) for k, v in conclusions(parse_dfl(dfl), semantics, engine).items()}


@pytest.mark.parametrize("engine", ENGINES)
def test_superiority_overrides_the_general_rule(engine: str) -> None:
    c = concl(">> bird\n>> penguin\nr1: bird => flies\nr2: penguin => -flies\nr2 > r1\n", engine)
    assert "neg(flies)" in c["+d"] and "flies" in c["-d"]
    assert {"bird", "penguin"} <= c["+D"] and "neg(flies)" in c["-D"]


@pytest.mark.parametrize("engine", ENGINES)
def test_strict_rules_are_definite_and_beat_defeasible_ones(engine: str) -> None:
    c = concl(">> penguin\nr1: penguin -> bird\nr2: bird => flies\nr3: penguin -> -flies\n", engine)
    assert {"bird", "neg(flies)"} <= c["+D"]
    assert "flies" in c["-d"] and "neg(flies)" in c["+d"]


@pytest.mark.parametrize("engine", ENGINES)
def test_a_defeater_blocks_but_never_concludes(engine: str) -> None:
    c = concl("r1: => p\nd1: ~> -p\n", engine)
    assert {"p", "neg(p)"} <= c["-d"]


@pytest.mark.parametrize("engine", ENGINES)
def test_ambiguity_blocking_and_propagation_differ(engine: str) -> None:
    nixon = "r1: => a\nr2: => -a\nr3: => b\nr4: a => -b\n"
    blocking = concl(nixon, engine)
    propagation = concl(nixon, engine, Semantics(ambiguity="propagation"))
    assert {"a", "neg(a)"} <= blocking["-d"] and {"a", "neg(a)"} <= propagation["-d"]
    assert "b" in blocking["+d"]          # the ambiguity of a is blocked
    assert "b" in propagation["-d"]       # ... or propagated to b


@pytest.mark.parametrize("engine", ENGINES)
def test_team_defeat(engine: str) -> None:
    teams = "r1: => p\nr2: => p\nr3: => -p\nr4: => -p\nr1 > r3\nr2 > r4\n"
    assert "p" in concl(teams, engine)["+d"]
    assert "p" in concl(teams, engine, Semantics(team_defeat=False))["-d"]


@pytest.mark.parametrize("engine", ENGINES)
def test_loops_fail_under_the_well_founded_semantics_only(engine: str) -> None:
    loop = "r1: p => q\nr2: q => p\nr3: => s\nr4: p ~> -s\n"
    wf = concl(loop, engine)
    kunen = concl(loop, engine, Semantics(well_founded=False))
    assert {"p", "q"} <= wf["-d"] and "s" in wf["+d"]
    assert not {"p", "q", "s"} & (kunen["+d"] | kunen["-d"])   # all undecided
    assert {"p", "q"} <= kunen["-D"]                            # no strict rules: -D anyway


@pytest.mark.parametrize("engine", ENGINES)
def test_specificity_among_learned_rules_and_sup_overrides_it(engine: str) -> None:
    def theory(sup: list[tuple[str, str]]) -> Theory:
        return Theory(facts=["steep", "light"],
                      rules=[Rule("r1", "defeasible", "leaves", ("steep",)),
                             Rule("r2", "defeasible", "neg(leaves)", ("light", "steep"))],
                      sup=sup, learned={"r1", "r2"})
    assert "neg(leaves)" in conclusions(theory([]), DEFAULT, engine)["+d"]
    assert "leaves" in conclusions(theory([("r1", "r2")]), DEFAULT, engine)["+d"]
    not_learned = theory([])
    not_learned.learned = {"r2"}           # specificity only among learned rules
    c = conclusions(not_learned, DEFAULT, engine)
    assert {"leaves", "neg(leaves)"} <= set(c["-d"])


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
