"""bridge/evaluation/behaviours.py: the report's section on curiosity
against random exploration says the behaviours each method saw, and draws
the behaviours over the budget."""
from __future__ import annotations

from pantarhei.bridge.evaluation.behaviours import behaviours_section
from tests.bridge.evaluation.evaluations import small_evaluation


def test_curiosity_against_random_exploration_and_the_behaviours_each_method_saw(tmp_path):
    ev = small_evaluation()
    text = "\n".join(behaviours_section(ev, tmp_path))
    assert "spends the same budget (24 pours) on 2 uniformly random valid antecedents" in text
    for row in ("| curiosity | 3 |", "| random valid antecedents | 2 |",
                "| random pours from the prior | 2 |", "| MAP-Elites (pyribs) | 5 |"):
        assert row in text
    assert (tmp_path / "behaviours.png").read_bytes()[:4] == b"\x89PNG"
    ev.behaviours_seen = {}
    assert "| method | behaviours seen |" not in "\n".join(behaviours_section(ev, tmp_path))
