"""The process's SWI-Prolog (bridge/engines/swipl.py): values bound into
goals as terms, and one-line errors for a theory that does not load."""
from __future__ import annotations

import pytest

from pantarhei.bridge.engines.swipl import engine, prolog_quote
from pantarhei.bridge.errors import UserError


def test_bindings_arrive_as_the_terms_they_are():
    value = {"a b": 1, "it's": [True, False, "x y", 2.5], "nested": {"k": []}}
    assert prolog_quote(value) == ("_{'a b': 1, 'it\\'s': [true, false, 'x y', 2.5], "
                                   "'nested': _{'k': []}}")
    assert engine().succeeds(
        "is_dict(V), get_dict('a b', V, 1), get_dict('it''s', V, [true, false, 'x y', 2.5]), "
        "get_dict(nested, V, N), get_dict(k, N, [])", V=value)
    assert engine().succeeds("A == 'O''Brien \\\\ 1'", A="O'Brien \\ 1")


def test_once_fails_loudly_and_succeeds_says_no():
    with pytest.raises(RuntimeError, match="goal failed"):
        engine().once("X = 1, X == 2")
    assert not engine().succeeds("fail")
    assert engine().once("X is 6 * 7")["X"] == 42


def test_a_theory_that_does_not_load_is_one_line_naming_the_file(tmp_path):
    bad = tmp_path / "bad.pl"
    bad.write_text("rule(r1, defeasible, no_spill\n")
    with pytest.raises(UserError) as e:
        engine().load_theory_file(str(bad), "given.pl")
    assert str(e.value).startswith("given.pl: ") and "\n" not in str(e.value)


def test_an_argument_that_is_not_utf8_is_not_a_missing_swipl():
    """pyswip encodes the process's arguments when it is imported: one that
    is not UTF-8 made it fail, which read as SWI-Prolog not installed."""
    import subprocess
    import sys

    code = ("import sys; sys.argv.append('pour \\udcff low'); "
            "from pantarhei.bridge.engines.swipl import engine; "
            "print(engine().once('X is 6 * 7')['X'], sys.argv[-1] == 'pour \\udcff low')")
    p = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=60)
    assert (p.returncode, p.stdout) == (0, "42 True\n"), p.stderr
