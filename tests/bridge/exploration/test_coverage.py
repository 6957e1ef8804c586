"""Coverage: the last probe of a step goes where the pours so far are
fewest, so that every proposition gets pours of its own."""
from __future__ import annotations

import numpy as np

from pantarhei.bridge.exploration.coverage import counts, fewest
from pantarhei.bridge.exploration.trace import probe_evidence
from pantarhei.bridge.learning.generalize import Settings
from pantarhei.oracle.generative import sample

from tests.bridge.exploration.test_explore_discover import run, trace


def test_the_candidate_whose_rarest_proposition_has_the_fewest_pours():
    # 5 pours upside down, 40 tilted back: one value of the tilt each
    P = np.vstack([sample(["pour_upside_down"], 5, 1), sample(["pour_tilted_back"], 40, 2)])
    held = counts(P)
    assert held["pour_upside_down"] == 5 and held["pour_tilted_back"] == 40
    cands = [["pour_tilted_back"], ["pour_tilted_back", "pour_upside_down"], ["pour_upside_down"]]
    assert fewest(P, cands, 31) == 1                    # its rarest: 5 pours; the first of equals
    assert fewest(P, cands[:1], 31) == -1                # 40 pours: covered
    assert fewest(P, cands, 5) == -1                     # fewer than 5: none
    assert fewest(P[:0], cands, 31) == 0                 # no pours: the first
    assert fewest(P, [], 31) == -1


def test_the_probes_record_leaves_out_the_probes_that_went_where_pours_are_fewest():
    trace = [{"probes": [{"score": 0.2, "kept": False},
                         {"score": 0.9, "kept": True, "by": "fewest"}]}]
    assert probe_evidence(trace) == [(0.2, 1)]


def test_covering_gives_every_proposition_pours_of_its_own(tmp_path):
    # synthetic seed 1, the paper's budget: ranked by the forest alone some
    # propositions (two, with the ordinary pour's priors) are held by fewer
    # pours than a general rule needed (min_support); with the last probe of
    # each step going where the pours are fewest, none is
    need = 10     # the pours a body needed before the general learner asked for its own
    rare = {}
    for cover in (0, 31):
        r = run(tmp_path, name=f"c{cover}", seed=1, budget=25, cover=cover)
        P, S = r["pours"]
        rare[cover] = sorted(p for p, n in counts(P[np.all(np.isfinite(S), axis=1)]).items()
                             if n < need)
        lines = trace(r)
        by = [(i, p.get("by", "novelty")) for t in lines for i, p in enumerate(t["probes"])]
        if cover:
            # only the last of a step's probes, and only in some steps
            assert {i for i, b in by if b == "fewest"} == {2}
            assert 0 < sum(b == "fewest" for _, b in by) < len(lines)
        else:
            assert all(b == "novelty" for _, b in by)
    assert len(rare[0]) >= 2 and rare[31] == []
