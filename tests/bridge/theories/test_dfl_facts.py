"""Facts in both formats and both engines: a defeasible fact (`=> a`, a
defeasible rule without body) gives +d but never +D and can be defeated;
`-> a` and `>> a` are definite facts; a theory of facts only is a theory;
a cyclic superiority relation is rejected; so are files that are no
theory. Expected conclusions are worked out from the definitions."""
from __future__ import annotations

from pathlib import Path

import pytest

from pantarhei.bridge.theories.dfl import parse_dfl
from pantarhei.bridge.errors import UserError
from pantarhei.bridge.reasoning.logic import Semantics, conclusions
from pantarhei.bridge.theories.loading import load
from pantarhei.bridge.theories.model import Rule, Theory
from tests.conftest import assert_one_line_error

ENGINES = ("prolog", "asp")


def native(lits: str) -> list[str]:
    """DFL literals separated by spaces, as the sorted native literals."""
    return sorted(f"neg({x[1:]})" if x.startswith("-") else x for x in lits.split())


def expect(pd: str, md: str, pdd: str, mdd: str) -> dict[str, list[str]]:
    return {"+D": native(pd), "-D": native(md), "+d": native(pdd), "-d": native(mdd)}


DEFINITE = expect("a", "-a", "a", "-a")
DEFEASIBLE = expect("", "a -a", "a", "-a")


@pytest.mark.parametrize("engine", ENGINES)
@pytest.mark.parametrize("text,expected", [
    ("=> a\n", DEFEASIBLE),
    ("-> a\n", DEFINITE),
    (">> a\n", DEFINITE),
    ("f: => a\n", DEFEASIBLE),
    ("f: -> a\n", DEFINITE),                    # a strict rule without body proves +D like a fact
])
def test_dfl_facts(engine: str, text: str, expected: dict) -> None:
    assert conclusions(parse_dfl(text), Semantics(), engine) == expected


@pytest.mark.parametrize("engine", ENGINES)
@pytest.mark.parametrize("text,expected", [
    ("fact(a).\n", DEFINITE),
    ("rule(f, defeasible, a).\n", DEFEASIBLE),
    ("rule(f, strict, a).\n", DEFINITE),
])
def test_native_facts(engine: str, text: str, expected: dict, tmp_path: Path) -> None:
    f = tmp_path / "t.pl"
    f.write_text(text)
    assert conclusions(load(f), Semantics(), engine) == expected


def test_an_unlabelled_fact_keeps_clear_of_labels() -> None:
    t = parse_dfl("=> a\nr1: a => b\n=> c\n")
    assert [(r.id, r.head) for r in t.rules] == [("line1", "a"), ("r1", "b"), ("r3", "c")]


@pytest.mark.parametrize("engine", ENGINES)
def test_a_defeasible_fact_is_defeated(engine: str) -> None:
    # f2 beats f1: -a is +d, a is not
    beaten = parse_dfl("f1: => a\nf2: => -a\nf2 > f1\n")
    assert conclusions(beaten, Semantics(), engine) == expect("", "a -a", "-a", "a")
    # a definite -a: the rule for a is not applicable against it
    assert conclusions(parse_dfl("=> a\n-> -a\n"), Semantics(), engine) == expect("-a", "a", "-a", "a")
    # an applicable defeater for -a that nothing beats: neither a nor -a
    blocked = parse_dfl("=> a\n-> b\nd1: b ~> -a\n")
    assert conclusions(blocked, Semantics(), engine) == expect("b", "a -a -b", "b", "a -a -b")


@pytest.mark.parametrize("engine", ENGINES)
def test_a_strict_fact_is_not_defeated(engine: str) -> None:
    t = parse_dfl("-> a\nf2: => -a\n-> b\nd1: b ~> -a\n")
    assert conclusions(t, Semantics(), engine) == expect("a b", "-a -b", "a b", "-a -b")


@pytest.mark.parametrize("engine", ENGINES)
@pytest.mark.parametrize("text,out", [
    ("=> a\n", "-D a\n-D -a\n+d a\n-d -a\n"),
    ("-> a\n", "+D a\n-D -a\n+d a\n-d -a\n"),
    (">> a\n", "+D a\n-D -a\n+d a\n-d -a\n"),
])
def test_a_theory_of_facts_only_from_the_command_line(cli, engine: str, text: str, out: str,
                                                      tmp_path: Path) -> None:
    """In a process of its own, as a user runs it."""
    f = tmp_path / "facts.dfl"
    f.write_text(text)
    r = cli("conclusions", str(f), "--engine", engine)
    assert (r.code, r.out, r.err) == (0, out, "")


CYCLES = [
    ("r1: a => b\nr2: a => -b\nr1 > r2\nr2 > r1\n>> a\n", 3, "r1 > r2 > r1"),
    ("r1: a => b\nr1 > r1\n", 2, "r1 > r1"),
    ("r1: => b\nr2: => b\nr3: => -b\nr1 > r2\nr2 > r3\nr3 > r1\n", 4, "r1 > r2 > r3 > r1"),
]


@pytest.mark.parametrize("text,line,cycle", CYCLES)
def test_cyclic_superiority_in_dfl_names_line_and_rules(cli, text: str, line: int, cycle: str,
                                                        tmp_path: Path) -> None:
    f = tmp_path / "cyclic.dfl"
    f.write_text(text)
    for engine in ENGINES:
        msg = assert_one_line_error(cli("conclusions", str(f), "--engine", engine))
        assert msg.endswith(f"{f}:{line}: the superiority relation has a cycle, {cycle}: it must be acyclic")


def test_cyclic_superiority_in_native_files(cli, tmp_path: Path) -> None:
    f = tmp_path / "cyclic.pl"
    f.write_text("fact(a).\nrule(r1, defeasible, b).\nbody(r1, a).\nrule(r2, defeasible, neg(b)).\n"
                 "body(r2, a).\nsup(r1, r2).\nsup(r2, r1).\n")
    msg = assert_one_line_error(cli("conclusions", str(f)))
    assert msg.endswith(f"{f}:6: the superiority relation has a cycle, r1 > r2 > r1: it must be acyclic")
    g = tmp_path / "other.pl"                        # a cycle across files, once merged
    g.write_text("rule(r3, defeasible, b).\nsup(r3, r1).\nsup(r2, r3).\n")
    h = tmp_path / "first.pl"
    h.write_text("rule(r1, defeasible, b).\nrule(r2, defeasible, neg(b)).\nsup(r1, r2).\n")
    assert "r1 > r2 > r3 > r1" in assert_one_line_error(cli("conclusions", str(h), str(g)))


@pytest.mark.parametrize("engine", ENGINES)
def test_each_engine_rejects_cyclic_superiority_itself(engine: str) -> None:
    """A theory that did not come through `load` (which checks first)."""
    rules = [Rule("r1", "defeasible", "b", ("a",)), Rule("r2", "defeasible", "neg(b)", ("a",))]
    for sup in ([("r1", "r2"), ("r2", "r1")], [("r1", "r1")]):
        t = Theory(["a"], rules, sup, source="t.pl")
        with pytest.raises(UserError, match=r"^t\.pl: the superiority relation has a cycle.*r1"):
            conclusions(t, Semantics(), engine)
    assert conclusions(Theory(["a"], rules, [("r1", "r2")]), Semantics(), engine)["+d"] == ["a", "b"]


def test_cycle_through_specificity_of_learned_rules() -> None:
    # r2 beats r3 by specificity (learned, conflicting, r3's body inside r2's)
    t = Theory([], [Rule("r1", "defeasible", "p", ("a",)), Rule("r2", "defeasible", "p", ("a", "b")),
                    Rule("r3", "defeasible", "neg(p)", ("a",))], [("r1", "r2"), ("r3", "r1")], {"r2", "r3"},
               source="t.pl")
    for engine in ENGINES:
        with pytest.raises(UserError, match="cycle"):
            conclusions(t, Semantics(), engine)


@pytest.mark.parametrize("path,words", [
    ("/dev/null", "/dev/null: not a regular file"),
    ("/nonexistent/theory.dfl", "no such theory file"),
])
def test_what_is_wrong_with_a_path(cli, path: str, words: str) -> None:
    assert words in assert_one_line_error(cli("conclusions", path))


def test_a_directory_and_empty_files(cli, tmp_path: Path) -> None:
    assert "a directory, not a theory file" in assert_one_line_error(cli("conclusions", str(tmp_path)))
    for name, text in (("empty.pl", ""), ("comments.dfl", "# nothing yet\n")):
        f = tmp_path / name
        f.write_text(text)
        assert f"{f}: an empty theory" in assert_one_line_error(cli("conclusions", str(f)))
