"""clingo in this process (bridge/engines/asp.py): an encoding solved over
the vocabulary, a checker grounded once and asked many times, and a theory
clingo cannot read as one line."""
from __future__ import annotations

import pytest

from pantarhei.bridge.engines.asp import Checker, solve
from pantarhei.bridge.errors import UserError


def test_solve_shows_the_symbols_of_every_model_asked_for(tmp_path):
    enc = tmp_path / "pick.lp"
    enc.write_text("1 { pick(P) : proposition(P, _, _, _), P = (pour_low; pour_high) } 1.\n"
                   "#show pick/1.\n")
    one = solve([enc])
    assert len(one) == 1 and str(one[0][0]) in ("pick(pour_low)", "pick(pour_high)")
    every = solve([enc], models=0)
    assert sorted(str(m[0]) for m in every) == ["pick(pour_high)", "pick(pour_low)"]
    assert solve([enc], "fact(1).", models=0) == every


def test_a_checker_answers_each_question_from_one_grounding(tmp_path):
    enc = tmp_path / "both.lp"
    enc.write_text("both :- given(pour_low), given(pour_high).\n#show both/0.\n")
    check = Checker([enc], "given")
    assert [str(s) for s in check.shown(["pour_low", "pour_high"])] == ["both"]
    assert check.shown(["pour_low"]) == []
    assert [str(s) for s in check.shown(["pour_high", "pour_low", "light_liquid"])] == ["both"]


def test_what_clingo_cannot_read_is_one_line(tmp_path):
    bad = tmp_path / "bad.lp"
    bad.write_text("p( :- q.\n")
    with pytest.raises(UserError) as e:
        solve([bad])
    assert "\n" not in str(e.value) and str(e.value)
