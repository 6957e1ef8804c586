"""Answers to questions about pouring (bridge/reasoning/answers.py): one
answer per expectation with the rule that decides it, named by its general
twin where the general layer has a rule of the same body and head."""
from __future__ import annotations

from pantarhei.bridge.reasoning.answers import what_happens
from pantarhei.bridge.theories.model import Rule, Theory


def test_an_answer_names_the_general_twin_of_algorithm_1s_rule():
    # both layers conclude no spill in general: the answer names the
    # general rule (its evidence is every pour), not a1's weighted share
    t = Theory()
    t.rules += [Rule("r1_no_spill", "defeasible", "no_spill"),
                Rule("g0_no_spill", "defeasible", "no_spill"),
                Rule("r2_no_spill", "defeasible", "neg(no_spill)", ("pour_low",))]
    t.learned = {r.id for r in t.rules}
    t.provenance += [("r1_no_spill", "confidence_permille", 580),
                     ("g0_no_spill", "layer", "general"), ("g0_no_spill", "confidence_permille", 730)]
    said = {a.expectation: a for a in what_happens(t, [])}
    assert said["no_spill"].value == "holds" and said["no_spill"].rule == "g0_no_spill"
    # a rule of Algorithm 1 with no general twin is named as it is
    said = {a.expectation: a for a in what_happens(t, ["pour_low"])}
    assert said["no_spill"].value == "fails" and said["no_spill"].rule == "r2_no_spill"


def test_the_python_example_of_the_docs_runs(capsys) -> None:
    # docs/questions.md's "From Python" example, run as written
    import re

    from pantarhei.theory import THEORY_DIR

    page = (THEORY_DIR.parent / "docs" / "questions.md").read_text()
    section = page[page.index("## From Python"):]
    code = re.search(r"```python\n(.*?)```", section, flags=re.S).group(1)
    exec(compile(code, "docs/questions.md", "exec"), {})
    out = capsys.readouterr().out
    assert re.search(r"^no_spill (holds|fails|uncertain|unknown) ", out, flags=re.M)
    assert re.search(r"^  held in \d+ of \d+ pours$", out, flags=re.M)
    assert "no_spill" in out.splitlines()[-1]          # the argument explained
