"""The progress bar (bridge/exploration/progress.py) counts the budget in
its own unit."""
from __future__ import annotations

from types import SimpleNamespace

import numpy as np

from pantarhei.bridge.exploration.progress import postfix, progress


def test_progress_counts_pours_for_discover_and_rules_for_the_paper():
    pours = np.zeros((40, 30))
    discover = SimpleNamespace(settings={"curiosity": "discover", "budget": 3, "batch": 31},
                               params=pours)
    assert progress(discover, 2) == (93, "pour", 40)
    assert postfix(discover, 1, 5) == "1 batch, 5 in A_new"
    paper = SimpleNamespace(settings={"curiosity": "paper", "budget": 3, "batch": 31}, params=pours)
    assert progress(paper, 2) == (3, "rule", 2)
    assert postfix(paper, 2) == "40 simulations, 2 rules"


def test_progress_counts_every_pour_for_the_learning_curiosity():
    pours = np.zeros((40, 30))
    learn = SimpleNamespace(settings={"curiosity": "learn", "budget": 3, "batch": 4,
                                      "pours": 775}, params=pours)
    assert progress(learn, 10) == (775, "pour", 40)
    assert postfix(learn, 10, 64) == "10 batches, 64 in A_new"
