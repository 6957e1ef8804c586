"""The priors explored with the last batch of the budget (`--prior-batch 1`, the
default): the scene where nothing is said, every parameter drawn from its
prior, as the parameters a question leaves unsaid are; the general rules
then learn from pours where the questions are asked, and the curiosity's
course before that batch is the one it takes without it."""
from __future__ import annotations

from pathlib import Path

import numpy as np

from pantarhei.bridge.evaluation.explored_pours import exploration_draws, read_learned
from pantarhei.oracle.generative import log_density

from tests.bridge.exploration.test_explore_discover import A0, run, trace


def test_the_priors_take_the_last_batch_and_are_drawn_again_by_the_evaluation(tmp_path):
    r = run(tmp_path, seed=1, budget=6, prior_batch=1)
    lines = trace(r)
    assert [t["via"] for t in lines].count("prior") == 1
    last = lines[-1]
    assert last["via"] == "prior" and last["antecedent"] == []
    assert last["probes"] == []                     # explored as it is, not probed
    assert r["stopped"] == "budget"
    # its batch: 31 pours, every one within the priors' support, where the
    # curiosity's antecedents' pours after a_0's (of 15 to 20 propositions)
    # are not
    P, _ = r["pours"]
    learned = read_learned(r["out"])
    assert learned.antecedents[0] == tuple(sorted(A0)) and learned.antecedents[-1] == ()
    redrawn, drawn, of, _ = exploration_draws(learned)
    assert np.array_equal(redrawn, P)               # the evaluation draws the same pours
    k = len(learned.antecedents) - 1
    mine = P[of == k]
    assert len(mine) == 31 and np.isfinite(log_density(mine, [])).all()
    before = np.isfinite(log_density(P[(of > 0) & (of < k)], []))
    assert before.mean() < 0.1
    # its rules have an empty body, and the theory records the setting
    text = Path(r["out"]).read_text()
    assert "setting(prior_batch, 1)." in text
    assert f"provenance(r{k + 1}_no_spill, antecedent, a{k + 1})." in text
    assert f"body(r{k + 1}_" not in text


def test_by_default_the_priors_are_explored(tmp_path):
    from pantarhei.bridge.exploration import explore_call as exploration
    from pantarhei.bridge.exploration.explore_call import ExploreOptions

    r = exploration.explore(ExploreOptions(curiosity="discover", oracle="synthetic", budget=3,
                                    out=tmp_path / "d.pl",
                                    store=tmp_path / "d.sqlite", progress=False,
                                    executor="inline", general=False))
    assert [t["via"] for t in trace(r)] == ["initial", "prior"]


def test_the_course_before_the_priors_is_the_one_without_them(tmp_path):
    a = trace(run(tmp_path, name="a", seed=2, budget=8, prior_batch=0))
    assert all(t["via"] != "prior" for t in a)
    c = trace(run(tmp_path, name="c", seed=2, budget=8, prior_batch=1))
    assert c[-1]["via"] == "prior"
    # every step before the priors' batch is the same step, to the digit;
    # the reserved batch costs the course at most its last step
    assert c[:-1] == a[:len(c) - 1]
    assert len(a) - 1 <= len(c) - 1 <= len(a)


def test_when_a_new_is_empty_the_priors_come_before_the_stop(tmp_path):
    # the novelty level 1 queues nothing: a_0 gets its more batches, then
    # the priors theirs, and A_new stays empty
    r = run(tmp_path, seed=1, budget=10, prior_batch=1, novelty=1.0)
    assert [t["via"].split("(")[0] for t in trace(r)] == ["initial", "more", "more",
                                                          "prior", "more", "more"]
    assert r["stopped"] == "a_new_empty"
