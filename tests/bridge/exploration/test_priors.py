"""The priors explored after a_0 (`--prior 1`, the default): the scene where nothing is
said, every parameter drawn from its prior, as the parameters a question
leaves unsaid are; the general rules then learn from pours where the
questions are asked."""
from __future__ import annotations

from pathlib import Path

import numpy as np

from pantarhei.bridge.evaluation.pipeline import exploration_draws, read_learned
from pantarhei.oracle.generative import log_density

from tests.bridge.exploration.test_explore_discover import A0, run, trace


def test_the_priors_are_explored_after_a0_and_drawn_again_by_the_evaluation(tmp_path):
    r = run(tmp_path, seed=1, max_rules=6, prior=1)
    lines = trace(r)
    assert [t["via"] for t in lines[:2]] == ["initial", "prior"]
    assert lines[0]["antecedent"] == A0 and lines[1]["antecedent"] == []
    assert lines[1]["probes"] == []                 # explored as it is, not probed
    assert all(t["via"] != "prior" for t in lines[2:])
    # its batch: 31 pours, every one within the priors' support, where the
    # later antecedents' pours (of 15 to 20 propositions) are not
    P, _ = r["pours"]
    learned = read_learned(r["out"])
    assert learned.antecedents[:2] == [tuple(sorted(A0)), ()]
    redrawn, drawn, of, _ = exploration_draws(learned)
    assert np.array_equal(redrawn, P)               # the evaluation draws the same pours
    mine = P[of == 1]
    assert len(mine) == 31 and np.isfinite(log_density(mine, [])).all()
    later = np.isfinite(log_density(P[of >= 2], []))
    assert later.mean() < 0.1
    # its rules have an empty body, and the theory records the setting
    text = Path(r["out"]).read_text()
    assert "setting(prior, 1)." in text
    assert "provenance(r2_no_spill, antecedent, a2)." in text
    assert "body(r2_" not in text


def test_by_default_the_priors_are_explored_after_a0(tmp_path):
    from pantarhei.bridge.exploration import loop as exploration
    from pantarhei.bridge.exploration.loop import Options

    r = exploration.explore(Options(oracle="synthetic", max_rules=3, out=tmp_path / "d.pl",
                                    store=tmp_path / "d.sqlite", progress=False,
                                    executor="inline", general=False))
    assert [t["via"] for t in trace(r)][:2] == ["initial", "prior"]


def test_the_priors_take_the_second_step_and_leave_a0s_as_it_was(tmp_path):
    a = trace(run(tmp_path, name="a", seed=2, max_rules=6, prior=0))
    assert all(t["via"] != "prior" for t in a)
    c = trace(run(tmp_path, name="c", seed=2, max_rules=6, prior=1))
    # a_0's step is the same; the priors take the first place of its A_new
    assert {k: v for k, v in c[0].items() if k != "added"} == {k: v for k, v in a[0].items() if k != "added"}
    assert c[0]["added"] == a[0]["added"][:99] and c[1]["via"] == "prior"
