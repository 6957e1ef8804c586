"""DFL (SPINdle, silkie) read and written; native theory files checked."""
from __future__ import annotations

from pathlib import Path

import pytest

from pantarhei.bridge.theories.dfl import parse_dfl, write_dfl
from pantarhei.bridge.reasoning.logic import Semantics, conclusions
from pantarhei.bridge.theories.loading import load
from pantarhei.bridge.theories.model import Rule
from pantarhei.bridge.theories.native import read_native
from pantarhei.bridge.errors import UserError
from pantarhei.theory import TheoryFileError

EXAMPLES = Path(__file__).resolve().parents[3] / "examples" / "extend_by_hand"

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


@pytest.mark.parametrize("engine", ["prolog", "asp"])
def test_write_then_read_gives_the_same_theory_and_conclusions(engine: str) -> None:
    t = parse_dfl(TWEETY)
    again = parse_dfl(write_dfl(t))
    assert again.facts == t.facts and again.rules == t.rules and sorted(again.sup) == sorted(t.sup)
    assert conclusions(again, Semantics(), engine) == conclusions(t, Semantics(), engine)


def test_native_and_dfl_versions_of_the_example_agree() -> None:
    native = load([EXAMPLES / "learned.pl", EXAMPLES / "hand.pl"])
    dfl = load([EXAMPLES / "learned.pl", EXAMPLES / "hand.dfl"])
    assert conclusions(native) == conclusions(dfl)
    assert read_native(EXAMPLES / "learned.pl").learned >= {"r1", "r4"}


def test_native_text_round_trip(tmp_path: Path) -> None:
    t = load(EXAMPLES / "learned.pl")
    f = tmp_path / "copy.pl"
    f.write_text(t.native())
    again = read_native(f)
    assert again.rules == t.rules and again.learned == t.learned and again.facts == t.facts


def _everything(t) -> tuple:
    return (t.facts, t.rules, t.sup, t.learned, t.extra, t.settings, t.provenance)


def test_convert_to_native_keeps_everything_of_a_learned_theory(tmp_path: Path) -> None:
    from pantarhei.bridge.theories.loading import DEFAULT_THEORY
    from tests.conftest import run_cli

    shipped = read_native(DEFAULT_THEORY)
    assert shipped.settings and shipped.provenance          # what a learned theory records
    out = tmp_path / "copy.pl"
    r = run_cli("convert", str(DEFAULT_THEORY), "--to", "native", "-o", str(out))
    assert r.code == 0, r.err
    assert _everything(read_native(out)) == _everything(shipped)


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


@pytest.mark.parametrize("text,line,what", [
    ("rule(r1, defeasible, b).\nrule(r2, usually, c).\n", 2, "kind strict, defeasible or defeater"),
    ("rule(r1, defeasible, b).\nbody(r9, a).\n", 2, "has no rule(r9"),
    ("rule(r1, defeasible, b).\nsup(r1, r7).\n", 2, "r7, which is not a rule"),
    ("rule(r1, defeasible, b).\nbody(r1, a)\n", 2, "expected a fact such as name(arg, 1)."),
    ("fact(neg(neg(a))).\n", 1, "double negation"),
])
def test_malformed_native_files_name_file_and_line(tmp_path: Path, text: str, line: int, what: str) -> None:
    f = tmp_path / "bad.pl"
    f.write_text(text)
    with pytest.raises(UserError) as e:
        load(f)
    assert str(e.value).startswith(f"{f}:{line}: ") and what in str(e.value), str(e.value)


@pytest.mark.parametrize("engine", ["prolog", "asp"])
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


def test_convert_command_writes_whole_files(cli, tmp_path: Path) -> None:
    out = tmp_path / "learned.dfl"
    r = cli("convert", str(EXAMPLES / "learned.pl"), "-o", str(out))
    assert r.code == 0, r.err
    back = tmp_path / "back.pl"
    assert cli("convert", str(out), "--to", "native", "-o", str(back)).code == 0
    assert conclusions(load(back)) == conclusions(load(EXAMPLES / "learned.pl"))
    assert "rule(h1, defeasible, liquid_leaves_source)." in cli("convert", str(EXAMPLES / "hand.dfl"),
                                                              "--to", "native").out
