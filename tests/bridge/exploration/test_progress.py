"""The progress bar (bridge/exploration/progress.py) counts the budget in
the unit explore/1 names: pours, or explored antecedents (rules)."""
from __future__ import annotations

import io

from pantarhei.bridge.exploration.progress import open_bar, position, postfix


def test_a_bar_of_pours_counts_pours_and_says_batches():
    assert position("pour", 2, 40) == 40
    assert postfix("pour", 1, 40, 5) == "1 batch, 5 in A_new"
    assert postfix("pour", 10, 40, 64) == "10 batches, 64 in A_new"


def test_a_bar_of_rules_counts_explored_antecedents_and_says_simulations():
    assert position("rule", 2, 40) == 2
    assert postfix("rule", 2, 40) == "40 simulations, 2 rules"


def test_the_bar_moves_to_where_the_exploration_is(monkeypatch):
    err = io.StringIO()
    monkeypatch.setattr("sys.stderr", err)
    bar = open_bar(93, "pour", 1, 31)
    assert (bar.bar.total, bar.bar.n) == (93, 31)
    bar.show(2, 62, 7)
    assert bar.bar.n == 62 and "2 batches, 7 in A_new" in str(bar.bar)
    bar.close()
