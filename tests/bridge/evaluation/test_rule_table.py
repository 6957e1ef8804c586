"""bridge/evaluation/rule_table.py: the learned rules in words, a row
per explored antecedent with the share of its pours that kept every
expectation, and the exploration's trace when there is one."""
from __future__ import annotations

from pantarhei.bridge.evaluation.rule_table import learned_rules_section, rules_table
from tests.bridge.evaluation.evaluations import small_evaluation


def test_the_rules_table_has_a_row_per_explored_antecedent():
    ev = small_evaluation()
    assert rules_table(ev)[2:] == [
        "| a1 | pour low above the destination | everything as expected | 100.0% |",
        "| a2 | pour from the side | not: no spill | 25.0% |"]
    ev.kept_all = [1.0]                 # no share known for a2
    assert rules_table(ev)[-1] == "| a2 | pour from the side | not: no spill | n/a |"


def test_the_learned_rules_and_the_exploration_trace_when_copied(tmp_path):
    ev = small_evaluation()
    L = learned_rules_section(ev, tmp_path)
    assert "| a2 | pour from the side | not: no spill | 25.0% |" in L
    assert "## The exploration" not in L
    (tmp_path / "exploration.png").write_bytes(b"")
    assert learned_rules_section(ev, tmp_path)[-1] == "![exploration trace](exploration.png)"
