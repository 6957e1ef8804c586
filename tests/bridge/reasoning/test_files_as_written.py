"""SWI-Prolog reads the theory files as they are written
(bridge/reasoning/logic.py's prolog_read: theory/ask.pl's load_theories/2,
what `ask` reads them with) for `conclusions --engine prolog` and
`prolog`: no Python re-serialization of a file (Theory.native) reaches it,
its warnings and errors name the file and line as written, and the
conclusions are those Python's reader gives clingo."""
from __future__ import annotations

from pathlib import Path

import pytest

from pantarhei.bridge.cli import main
from pantarhei.bridge.theories.model import Theory

#: Comments, and facts in an order Theory.native() would change (settings
#: first, provenance after its rule); two names no proposition or
#: expectation, on lines 9 and 11 as written.
HAND = """\
% written by hand
provenance(h2, note, "written by hand").
sup(h1, h2).
rule(h2, defeasible, neg(no_spill)).
body(h2, pour_to_side).
setting(seed, 3).
rule(h1, defeasible, no_spill).
body(h1, pour_to_side).
body(h1, lihgt_liquid).   % a typo: h1 never fires
fact(pour_to_side).
rule(h3, defeasible, nospill).
body(h3, pour_low).
"""


@pytest.fixture
def hand(tmp_path: Path) -> Path:
    f = tmp_path / "hand.pl"
    f.write_text(HAND)
    return f


@pytest.fixture
def not_rewritten(monkeypatch):
    """A theory written out again by Python for SWI-Prolog fails the test."""
    def refuse(self: Theory) -> str:
        raise AssertionError(f"{self.source} was re-serialized for SWI-Prolog")
    monkeypatch.setattr(Theory, "native", refuse)


def test_conclusions_are_of_the_file_as_written(hand: Path, capsys, not_rewritten) -> None:
    assert main(["conclusions", "--engine", "prolog", str(hand)]) == 0
    by_prolog = capsys.readouterr()
    assert by_prolog.err == ""          # conclusions is for any theory: no warnings
    assert "+d -no_spill" in by_prolog.out.splitlines()
    assert "-d no_spill" in by_prolog.out.splitlines()


def test_both_engines_conclude_the_same_of_the_file(hand: Path, capsys) -> None:
    assert main(["conclusions", "--engine", "prolog", str(hand)]) == 0
    by_prolog = capsys.readouterr().out
    assert main(["conclusions", "--engine", "asp", str(hand)]) == 0     # Python's reader
    assert by_prolog == capsys.readouterr().out and by_prolog


def test_prolog_warns_at_the_lines_as_written(hand: Path, capsys, not_rewritten) -> None:
    assert main(["prolog", "--theory", str(hand), "--goal",
                 "what_happens([pour_to_side], O), memberchk(outcome(no_spill, fails, _, h2), O)"]) == 0
    assert capsys.readouterr().err.splitlines() == [
        f"warning: {hand}:9: rule h1: body lihgt_liquid is not a proposition or expectation "
        f"of pouring (did you mean light_liquid?)",
        f"warning: {hand}:11: rule h3: head nospill is not a proposition or expectation "
        f"of pouring (did you mean no_spill?)"]


def test_a_rule_named_twice_across_files_is_refused_where_written(hand: Path, tmp_path: Path,
                                                                   capsys, not_rewritten) -> None:
    more = tmp_path / "more.pl"
    more.write_text("% more rules\n\nrule(h3, defeasible, no_spill).\n")
    assert main(["conclusions", "--engine", "prolog", str(hand), str(more)]) == 2
    assert capsys.readouterr().err == (f"pantarhei conclusions: {more}:3: rule h3 is already "
                                       f"defined in {hand}\n")


def test_a_dfl_file_is_read_by_python_and_merged_after_the_files(hand: Path, tmp_path: Path,
                                                                 capsys) -> None:
    dfl = tmp_path / "low.dfl"
    dfl.write_text("d1: pour_low => source_clear\n")
    assert main(["prolog", "--theory", str(hand), "--theory", str(dfl), "--goal",
                 "what_happens([pour_low], O), memberchk(outcome(source_clear, holds, _, d1), O)"]) == 0
