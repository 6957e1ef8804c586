"""DFL, the theory format of SPINdle and silkie (bridge/theories/dfl.py):
read and written; its facts (`>> a` and `-> a` definite, `=> a` a
defeasible rule without body, which gives +d but never +D and can be
defeated) as both engines conclude them; rules with variables grounded;
malformed files and a cyclic superiority relation named by file and line.
Expected conclusions are worked out from the definitions."""
from __future__ import annotations

from pathlib import Path

import pytest

from pantarhei.bridge.theories.dfl import parse_dfl, write_dfl
from pantarhei.bridge.reasoning.logic import Semantics, conclusions
from pantarhei.bridge.theories.loading import load
from pantarhei.bridge.theories.model import Rule
from pantarhei.bridge.theories.native import read_native
from pantarhei.theory import TheoryFileError
from tests.conftest import assert_one_line_error

EXAMPLES = Path(__file__).resolve().parents[3] / "examples" / "extend_by_hand"
ENGINES = ("prolog", "asp")

TWEETY = """# comment
>> bird(tweety)
-> penguin(opus)        % silkie's fact
=> bird(polly)
r1: bird(?x) => flies(?x)
r2: penguin(X) -> bird(X)
r3: penguin(?x) => -flies(?x)
d1: broken_wing ~> -flies(tweety)   // a defeater
r3 > r1
"""


def native(lits: str) -> list[str]:
    """DFL literals separated by spaces, as the sorted native literals."""
    return sorted(f"neg({x[1:]})" if x.startswith("-") else x for x in lits.split())


def expect(pd: str, md: str, pdd: str, mdd: str) -> dict[str, list[str]]:
    return {"+D": native(pd), "-D": native(md), "+d": native(pdd), "-d": native(mdd)}


DEFINITE = expect("a", "-a", "a", "-a")
DEFEASIBLE = expect("", "a -a", "a", "-a")


def test_dfl_kinds_facts_and_superiority() -> None:
    t = parse_dfl(TWEETY)
    assert t.facts == ["bird(tweety)", "penguin(opus)"]
    assert t.rule("r4") == Rule("r4", "defeasible", "bird(polly)")     # a defeasible fact
    kinds = {r.id: r.kind for r in t.rules}
    assert kinds["d1"] == "defeater" and kinds["r2_opus"] == "strict"
    assert ("r3_opus", "r1_opus") in t.sup


def test_rules_with_variables_are_grounded_over_the_facts() -> None:
    t = parse_dfl(TWEETY)
    heads = {r.id: r.head for r in t.rules}
    assert heads["r1_tweety"] == "flies(tweety)"
    assert heads["r1_opus"] == "flies(opus)"          # via r2's instance: bird(opus)
    assert heads["r3_opus"] == "neg(flies(opus))"
    assert "r3_tweety" not in heads                    # tweety is no penguin
    c = conclusions(t, Semantics(), "prolog")
    assert {"flies(tweety)", "flies(polly)", "neg(flies(opus))"} <= set(c["+d"])


@pytest.mark.parametrize("engine", ENGINES)
def test_write_then_read_gives_the_same_theory_and_conclusions(engine: str) -> None:
    t = parse_dfl(TWEETY)
    again = parse_dfl(write_dfl(t))
    assert again.facts == t.facts and again.rules == t.rules and sorted(again.sup) == sorted(t.sup)
    assert conclusions(again, Semantics(), engine) == conclusions(t, Semantics(), engine)


def test_native_and_dfl_versions_of_the_example_agree() -> None:
    native_theory = load([EXAMPLES / "learned.pl", EXAMPLES / "hand.pl"])
    dfl = load([EXAMPLES / "learned.pl", EXAMPLES / "hand.dfl"])
    assert conclusions(native_theory) == conclusions(dfl)
    assert read_native(EXAMPLES / "learned.pl").learned >= {"r1", "r4"}


@pytest.mark.parametrize("text,line,what", [
    ("r1: a => b\nr2 b -> c\n", 2, "expected a literal"),
    ("r1: a => b\nr1: c => d\n", 2, "a second rule labelled r1"),
    ("r1: a => b\nr1 >> r2\n", 2, "expected a rule"),
    ("r1: a => b\njust words\n", 2, "expected a rule"),
    ("r1: a, , b => c\n", 1, "separated by commas"),
    (">> p(?x)\n", 1, "without variables"),
    ("r1: a => p(?y)\n", 1, "every variable of the head"),
])
def test_malformed_dfl_names_file_and_line(text: str, line: int, what: str) -> None:
    with pytest.raises(TheoryFileError) as e:
        parse_dfl(text, "t.dfl")
    assert str(e.value).startswith(f"t.dfl:{line}: ") and what in str(e.value)


@pytest.mark.parametrize("engine", ENGINES)
def test_dfl_of_a_learned_theory_keeps_specificity_as_superiority(engine: str) -> None:
    learned = load(EXAMPLES / "learned.pl")
    text = write_dfl(learned)
    # as SPINdle and silkie read it: without the annotations
    as_dfl = parse_dfl("\n".join(x for x in text.splitlines() if not x.startswith("# pantarhei:")))
    assert not as_dfl.learned and ("r4", "r3") in as_dfl.sup
    # as Panta Rhei reads it: learned again, specificity derived again
    back = parse_dfl(text)
    assert back.learned == learned.learned and back.sup == learned.sup
    for scene in (["pour_steeply_tilted", "light_liquid"], ["pour_to_side", "end_low"]):
        for t in (as_dfl, back):
            assert conclusions(t.with_facts(scene), Semantics(), engine) == \
                conclusions(learned.with_facts(scene), Semantics(), engine)


# -- facts -------------------------------------------------------------------

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


# -- a cyclic superiority relation -------------------------------------------

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


RANGE = "an integer from -2147483648 to 2147483647, not "


@pytest.mark.parametrize("text,line,what", [
    (">> p(4294967296)\n", 1, RANGE + "4294967296"),
    (">> p(2147483647)\nr1: p(-2147483649) => q\n", 2, RANGE + "-2147483649"),
    ("r1: p(1) => q(2147483648)\n", 1, RANGE + "2147483648"),
    (">> p(" + "9" * 5001 + ")\n", 1, RANGE + "999999999999...9999 (5001 digits)"),
    (">> p(007)\n", 1, "an integer in decimal digits without leading zeros, not 007"),
])
def test_integers_clingo_cannot_hold_are_refused_in_dfl(cli, tmp_path: Path, text: str, line: int,
                                                        what: str) -> None:
    """clingo wraps an integer past 32 bits (p(4294967296) was +D p(0)):
    the reader refuses it, so that no engine and no conversion sees it."""
    f = tmp_path / "big.dfl"
    f.write_text(text)
    for engine in ENGINES:
        assert assert_one_line_error(cli("conclusions", str(f), "--engine", engine)) == \
            f"pantarhei conclusions: {f}:{line}: {what}"
    out = tmp_path / "big.pl"
    assert f"{f}:{line}: {what}" in assert_one_line_error(cli("convert", str(f), "--to", "native",
                                                              "-o", str(out)))
    assert not out.exists()
    f.write_text(text.replace("4294967296", "2147483647").replace("2147483648", "-2147483648")
                 .replace("-2147483649", "-2147483648").replace("9" * 5001, "9").replace("007", "7"))
    assert cli("convert", str(f), "--to", "native", "-o", str(out)).code == 0


@pytest.mark.parametrize("held", ["rule(h1, defeasible, flies).", "body(r2, bird).", "sup(r1, r2).",
                                  "fact(wings)."])
def test_a_pantarhei_comment_carries_no_rules(held: str) -> None:
    """What DFL has a form for is written as DFL: a rule, fact or
    superiority hidden in a `# pantarhei:` comment (which SPINdle and silkie
    skip) would decide answers those tools never see."""
    text = f">> bird\nr1: bird => flies\nr2: bird => -flies\n# pantarhei: {held}\n"
    with pytest.raises(TheoryFileError) as e:
        parse_dfl(text, "t.dfl")
    name = held.split("(")[0]
    assert str(e.value).startswith(f"t.dfl:4: # pantarhei: comments hold what DFL has no form for, "
                                   f"not {name}/")


def test_what_a_pantarhei_comment_holds_never_reaches_clingo() -> None:
    text = '>> bird\nr1: bird => flies\n# pantarhei: concl("+D", pwned).\n# pantarhei: changed.\n'
    t = parse_dfl(text, "t.dfl")
    assert len(t.extra) == 2
    assert conclusions(t, Semantics(), "asp") == conclusions(t, Semantics(), "prolog")
    assert "pwned" not in str(conclusions(t, Semantics(), "asp"))
    assert parse_dfl(write_dfl(t), "again.dfl").extra == t.extra      # kept, as convert keeps it
