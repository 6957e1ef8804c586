"""The native theory format read (bridge/theories/native.py): its facts
(`fact(a)`, a strict or defeasible rule without body) as both engines
conclude them, files whose facts are not of their forms named by file and
line, and a theory read back from the text `Theory.native()` writes."""
from __future__ import annotations

from pathlib import Path

import pytest

from pantarhei.bridge.errors import UserError
from pantarhei.bridge.reasoning.logic import Semantics, conclusions
from pantarhei.bridge.theories.loading import load
from pantarhei.bridge.theories.native import read_native

EXAMPLES = Path(__file__).resolve().parents[3] / "examples" / "extend_by_hand"

DEFINITE = {"+D": ["a"], "-D": ["neg(a)"], "+d": ["a"], "-d": ["neg(a)"]}
DEFEASIBLE = {"+D": [], "-D": ["a", "neg(a)"], "+d": ["a"], "-d": ["neg(a)"]}


@pytest.mark.parametrize("engine", ["prolog", "asp"])
@pytest.mark.parametrize("text,expected", [
    ("fact(a).\n", DEFINITE),
    ("rule(f, defeasible, a).\n", DEFEASIBLE),
    ("rule(f, strict, a).\n", DEFINITE),
])
def test_native_facts(engine: str, text: str, expected: dict, tmp_path: Path) -> None:
    f = tmp_path / "t.pl"
    f.write_text(text)
    assert conclusions(load(f), Semantics(), engine) == expected


def test_native_text_round_trip(tmp_path: Path) -> None:
    t = load(EXAMPLES / "learned.pl")
    f = tmp_path / "copy.pl"
    f.write_text(t.native())
    again = read_native(f)
    assert again.rules == t.rules and again.learned == t.learned and again.facts == t.facts


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
