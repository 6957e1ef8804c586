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


EXAMPLE = Path(__file__).resolve().parents[3] / "examples" / "extend_by_hand"
PLAN = ["plan", "--goal", "liquid_leaves_source", "--given", "light_liquid", "--verify", "0",
        "--theory", str(EXAMPLE / "learned.pl"), "--theory", str(EXAMPLE / "hand.pl")]


def test_plan_asks_the_files_as_written_and_answers_as_before(capsys, monkeypatch) -> None:
    from pantarhei.bridge.reasoning import logic

    with monkeypatch.context() as m:
        m.setattr(logic, "load_as_written", lambda theory: None)    # Python's text, as before
        assert main(PLAN) == 0
    as_text = capsys.readouterr()
    from pantarhei.bridge.engines.swipl import Engine, engine

    def refuse(self, path: str, source: str) -> None:
        raise AssertionError(f"{source} was given to SWI-Prolog as Python's text")
    monkeypatch.setattr(Engine, "load_theory_file", refuse)
    engine().theory_digest = ""         # as in a new process: nothing read yet
    assert main(PLAN) == 0
    assert capsys.readouterr() == as_text and "pour" in as_text.out


def test_a_theory_changed_in_python_is_given_as_its_text(hand: Path, capsys) -> None:
    from pantarhei.bridge.reasoning.answers import what_happens
    from pantarhei.bridge.reasoning.written_theory import as_written, load_as_written
    from pantarhei.bridge.theories.loading import load
    from pantarhei.bridge.theories.model import Rule

    theory = as_written(load([hand]), [hand])
    assert load_as_written(theory) is not None
    said = {a.expectation: (a.value, a.rule) for a in what_happens(theory, ["pour_low"])}
    assert said["source_clear"] == ("unknown", None)
    theory.rules.append(Rule("mine", "defeasible", "source_clear", ("pour_low",)))
    assert load_as_written(theory) is None                      # changed: its text is meant
    said = {a.expectation: (a.value, a.rule) for a in what_happens(theory, ["pour_low"])}
    assert said["source_clear"] == ("holds", "mine")


def test_a_file_changed_after_python_read_it_is_not_asked(hand: Path) -> None:
    """The theory a command reasons with in Python is the one SWI-Prolog
    answers from: if its file changed since, its text is given."""
    from pantarhei.bridge.reasoning.written_theory import as_written, load_as_written
    from pantarhei.bridge.theories.loading import load

    theory = as_written(load([hand]), [hand])
    hand.write_text(HAND + "rule(h4, defeasible, source_clear).\n")
    assert load_as_written(theory) is None


def test_rules_a_plan_adds_are_read_after_the_files_as_written(hand: Path, monkeypatch) -> None:
    from pantarhei.bridge.engines.swipl import Engine, engine
    from pantarhei.bridge.reasoning import logic
    from pantarhei.bridge.reasoning.answers import what_happens
    from pantarhei.bridge.reasoning.plan_evidence import with_rules
    from pantarhei.bridge.reasoning.written_theory import AsWritten, as_written
    from pantarhei.bridge.theories.loading import load
    from pantarhei.bridge.theories.model import Rule

    planned = [([Rule("p0_source_clear", "defeasible", "source_clear", ("pour_low",))],
                [("p0_source_clear", "layer", "plans")])]
    theory = with_rules(as_written(load([hand]), [hand]), planned)
    assert isinstance(theory, AsWritten) and "rule(p0_source_clear" in theory.added
    with monkeypatch.context() as m:
        m.setattr(logic, "load_as_written", lambda theory: None)    # Python's text, as before
        as_text = what_happens(theory, ["pour_low"])

    def refuse(self, path: str, source: str) -> None:
        raise AssertionError(f"{source} was given to SWI-Prolog as Python's text")
    monkeypatch.setattr(Engine, "load_theory_file", refuse)
    engine().theory_digest = ""
    said = what_happens(theory, ["pour_low"])
    assert said == as_text
    assert {a.expectation: (a.value, a.rule) for a in said}["source_clear"] == \
        ("holds", "p0_source_clear")
