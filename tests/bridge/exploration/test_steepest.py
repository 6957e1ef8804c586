"""Which plane the loop follows next (bridge/exploration/steepest.py), on
pours of the synthetic oracle, whose dependencies are known: the paper's
steepest plane and the discovering curiosity's significant ones point
along parameters the oracle really depends on, and each move's flip lies
on the side its sign says."""
from __future__ import annotations

import numpy as np

from pantarhei.bridge.exploration.session_state import Session
from pantarhei.bridge.exploration.steepest import significant_planes, steepest_plane
from pantarhei.oracle.generative import sample
from pantarhei.oracle.synthetic import DEPENDS, scores
from pantarhei.theory.lexicon import load_vocabulary

NAMES = load_vocabulary().parameter_names
ENTRIES = [{"id": "a1", "antecedent": []}, {"id": "a2", "antecedent": ["pour_low"]}]


#: What a request of the discovering curiosity carries beside the antecedents.
TEST = {"significance": 0.05, "permutations": 99, "seed": 1, "ridge": 1.0}


def session() -> Session:
    P = np.vstack([sample(e["antecedent"], 62, seed=i) for i, e in enumerate(ENTRIES)])
    S = np.array([scores(dict(zip(NAMES, p))) for p in P])
    return Session(run="", store=None, simulator=None, oracle_version="", params=P, scores=S)


def test_the_papers_steepest_plane_follows_a_real_dependency():
    best = steepest_plane(session(), {"antecedents": ENTRIES, "ridge": 1.0})
    top = max(best["gradient"], key=lambda n: abs(best["gradient"][n]))
    assert best["antecedent"] in ("a1", "a2") and best["slope"] > 0
    assert top in DEPENDS[best["expectation"]]


def test_the_significant_planes_move_along_real_dependencies_towards_the_flip():
    best = significant_planes(session(), {"antecedents": ENTRIES, **TEST})
    assert best["significant"] and best["followed"][0]["antecedent"] == best["antecedent"]
    assert best["directions"][0]["expectation"] == best["expectation"]
    slopes = [d["slope"] for d in best["directions"]]
    assert slopes == sorted(slopes, reverse=True)
    for followed in best["followed"]:
        for d in followed["directions"]:
            for m in d["moves"]:
                assert m["parameter"] in DEPENDS[d["expectation"]], (d["expectation"], m)
                assert m["p"] <= 0.05
                assert (m["flip"] > m["mean"]) == (m["sign"] == "up")


def test_without_pours_enough_to_fit_nothing_is_significant():
    s = session()
    s.params, s.scores = s.params[:1], s.scores[:1]
    best = significant_planes(s, {"antecedents": ENTRIES[:1], **TEST})
    assert not best["significant"] and best["followed"] == [] and best["slope"] == 0.0
    assert best["antecedent"] == "a1"
