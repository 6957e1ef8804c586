"""The course of an exploration (bridge/exploration/course.py): the settings
hashed into the run key are those explore/1 names, with the algorithm's and
the oracle's versions."""
from __future__ import annotations

from pantarhei.bridge.exploration.course import ALGORITHM_VERSION, course


def test_the_course_is_what_explore_1_names_with_both_versions():
    request = {"course": ["seed", "novelty", "initial", "prior_batch"], "seed": 7,
               "novelty": 0.1, "initial": ["pour_near_rim", "pour_low"], "prior_batch": 1,
               "budget": 25, "out": "/tmp/x.pl"}
    c = course(request, "4", {"particles": 100})
    assert c == {"algorithm": ALGORITHM_VERSION, "oracle_version": "4",
                 "oracle_settings": {"particles": 100}, "seed": 7, "novelty": 0.1,
                 "initial": ["pour_low", "pour_near_rim"], "prior_batch": 1, "priors_at": "last"}
    assert "priors_at" not in course({**request, "course": ["seed"]}, "4", {})
