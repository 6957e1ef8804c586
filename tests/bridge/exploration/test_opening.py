"""Beginning a session (bridge/exploration/opening.py): the settings hashed
into the run key are those explore/1 names, with the algorithm's and the
oracle's versions; the progress bar counts the budget in its own unit."""
from __future__ import annotations

from types import SimpleNamespace

import numpy as np

from pantarhei.bridge.exploration.opening import ALGORITHM_VERSION, course, postfix, progress


def test_the_course_is_what_explore_1_names_with_both_versions():
    request = {"course": ["seed", "novelty", "initial", "prior_batch"], "seed": 7,
               "novelty": 0.1, "initial": ["pour_near_rim", "pour_low"], "prior_batch": 1,
               "budget": 25, "out": "/tmp/x.pl"}
    c = course(request, "4", {"particles": 100})
    assert c == {"algorithm": ALGORITHM_VERSION, "oracle_version": "4",
                 "oracle_settings": {"particles": 100}, "seed": 7, "novelty": 0.1,
                 "initial": ["pour_low", "pour_near_rim"], "prior_batch": 1, "priors_at": "last"}
    assert "priors_at" not in course({**request, "course": ["seed"]}, "4", {})


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
