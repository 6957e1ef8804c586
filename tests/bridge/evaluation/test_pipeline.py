"""`pantarhei evaluate` on theories learned from the synthetic oracle: the
whole evaluation runs in seconds, against analytic scores."""
from __future__ import annotations

import json
from pathlib import Path

import numpy as np
import pytest

from pantarhei.bridge.evaluation import pipeline as E
from pantarhei.bridge.evaluation.heldout import near_antecedents
from pantarhei.bridge.evaluation.measures import distinct_behaviours
from pantarhei.bridge.evaluation.plan_checks import FRESH, goal_sets
from pantarhei.bridge.evaluation.rule_building import predict, theory_of
from pantarhei.bridge.reasoning.valid_scenes import violations
from pantarhei.theory.lexicon import load_vocabulary
from tests.conftest import run_cli

#: The pours each plan is verified with in the small evaluation.
VERIFY = 4


@pytest.fixture(scope="module")
def evaluated(learned, tmp_path_factory) -> tuple[E.Evaluation, Path]:
    theory, store = learned
    opts = E.EvaluationOptions(theory=theory, store=store, scenes=25, seed=3, verify=VERIFY,
                               paper_samples=5, executor="inline", progress=False)
    return E.evaluate(opts), store


def test_rules_rebuilt_from_the_store_are_the_theory_prolog_wrote(evaluated, learned):
    ev, _ = evaluated
    L = E.read_learned(learned[0])
    # the exploration's own pours, every batch of them, drawn again: all in its store
    assert ev.simulations["exploration"] == 0 and ev.reproduced
    names = load_vocabulary().expectation_names
    for i, row in enumerate(ev.explored_consequents, start=1):
        for e, holds in zip(names, row):
            assert L.theory.rule(f"r{i}_{e}").head == (e if holds else f"neg({e})")
    # the behaviours at the budget both methods are compared at (whole
    # batches within either's pours): of the antecedents whose pours all lie
    # within it
    _, _, _, ends = E.exploration_draws(L)
    within = sum(1 for e in ends if e <= ev.curves["budget"][-1])
    assert within >= len(ends) - 1
    assert ev.behaviours["curiosity"] == distinct_behaviours(ev.explored_consequents[:within])
    assert ev.curves["curiosity"]["behaviours"][-1] == ev.behaviours["curiosity"]


def test_curves_cover_the_budget_and_never_lose_behaviours_of_random_exploration(evaluated):
    ev, _ = evaluated
    c = ev.curves
    batches = ev.budget // 12
    assert c["budget"] == [12 * k for k in range(1, batches + 1)]
    for method in ("curiosity", "random"):
        assert len(c[method]["behaviours"]) == batches
        for name in ("uniform", "near", "near_random"):
            assert all(0 <= x <= 1 for x in c[method]["coverage"][name])
    assert ev.simulations["exploration"] == 0          # all of them came from the store
    assert ev.simulations["random exploration"] == ev.budget


def test_held_out_scenes_are_valid_and_never_explored(evaluated):
    ev, _ = evaluated
    near = near_antecedents(ev.explored, 20, 5, set(ev.explored))
    assert len(near) == 20 and len(set(near)) == 20
    for a in near:
        assert a not in ev.explored and not violations(a)
        assert any(set(x) < set(a) and 1 <= len(a) - len(x) <= 2 for x in ev.explored)
    h = ev.heldout
    assert h["uniform"]["scenes"] == 25 and h["near"]["scenes"] == 25
    # the learned theory holds general rules: it decides most scenes (not
    # those where its pours split: uncertain), far more than Algorithm 1's rules
    assert h["uniform"]["curiosity_theory"]["coverage"] >= 0.8
    assert h["near"]["curiosity_tree"]["coverage"] == 1.0
    assert h["near_random"]["scenes"] == 25
    # Algorithm 1's rules alone (random exploration's theory) decide near their antecedents only
    assert h["near_random"]["random_theory"]["coverage"] > h["uniform"]["random_theory"]["coverage"]


def test_the_general_theory_beside_the_models_on_held_out_scenes_and_questions(evaluated, learned):
    from pantarhei.bridge.evaluation.questions import questions
    from pantarhei.bridge.theories.loading import load

    ev, _ = evaluated
    g = ev.general
    assert len(g["questions"]) == len(questions()) >= 80
    for who in ("shipped", "curiosity", "random"):
        assert g[who]["uniform"]["scenes"] == 25
        q = g[who]["questions"]
        assert 0 < q["coverage"] <= 1 and 0 <= q["calibration"] <= 1 and 0 <= q["coherent"] <= 1
    # the contrast keys are the clear keys where the defaults-only theory is wrong
    key, clear, contrast = (np.array(g[k], dtype=bool) for k in ("key", "clear", "contrast"))
    assert contrast.sum() and (contrast <= clear).all()
    base = g["curiosity"]["defaults"]
    assert base["questions"]["contrast_accuracy"] == 0.0 and base["questions"]["contrast"] == contrast.sum()
    assert base["questions"]["coverage"] == 1.0
    # the learner's own pours: one proposition alone, everything else an ordinary pour
    assert g["curiosity"]["pours"] > len(E.exploration_draws(E.read_learned(learned[0]))[0])
    for method in ("curiosity", "random"):
        for model in ("boosting", "defaults"):
            assert 0 <= g[method][model]["questions"]["accuracy"] <= 1
            assert g[method][model]["questions"]["calibration"] is not None
    # the evaluation learns from the exploration's pours the very general rules the theory holds
    shipped = {(r.id, r.head, tuple(sorted(r.body))) for r in load([learned[0]]).rules
               if r.id.startswith("g")}
    assert shipped == {(r["id"], r["head"], tuple(sorted(r["body"]))) for r in g["curiosity"]["rules"]}


def test_predict_is_what_swi_prolog_concludes():
    names = load_vocabulary().expectation_names
    ants = [("pour_low",), ("pour_low", "light_liquid")]
    heads = np.ones((2, 9), dtype=bool)
    heads[1, 0] = False
    th = theory_of(ants, heads, "two rules")
    p = predict(th, [["pour_low"], ["pour_low", "light_liquid"], ["light_liquid"]])
    assert (p[0] == 1).all()
    assert p[1, 0] == 0 and (p[1, 1:] == 1).all()      # the more specific rule wins
    assert (p[2] == -1).all()
    assert len(names) == p.shape[1]


def test_plans_and_paper_rules_are_checked_in_simulation(evaluated):
    ev, _ = evaluated
    assert len(ev.plans) == len(goal_sets()) >= 5
    found = [p for p in ev.plans if "plan" in p]
    assert found, "the synthetic theory reaches some goal set"
    for p in found:
        assert not violations(p["antecedent"])
        # measured on FRESH times the verifying pours
        assert 0 <= p["met"] <= p["simulated"] <= FRESH * VERIFY
    assert all(p.get("none") for p in ev.plans if "plan" not in p)
    assert len(ev.paper_rules) == 3
    for r in ev.paper_rules:
        assert r["theory_says"] in (r["literal"], "unknown", r["literal"][4:-1])
        assert r["simulated"] == 5 and 0 <= r["oracle_share"] <= 1


def test_behaviours_seen_by_every_search_method_with_the_same_budget(evaluated):
    ev, _ = evaluated
    assert set(ev.behaviours_seen) == {"curiosity", "random", "prior", "map_elites"}
    assert ev.simulations["random pours"] + ev.simulations["MAP-Elites"] <= 2 * ev.budget
    assert ev.simulations["MAP-Elites"] > 0
    for method, seen in ev.behaviours_seen.items():
        assert 1 <= seen <= ev.budget // 2, method


def test_the_report_and_its_figures(evaluated, tmp_path):
    from pantarhei.bridge.evaluation.headline import headline
    from pantarhei.bridge.evaluation.report import write

    ev, _ = evaluated
    path = write(ev, tmp_path / "rep", gifs=False)
    text = path.read_text()
    n = len(ev.explored)
    assert "## Headline" in text and f"| a{n} |" in text
    # the learned fixture explores with --batch 12: the opening names it
    assert f"{n} explored antecedents of 12 pours each" in text
    assert len(ev.kept_all) == n and all(0 <= k <= 1 for k in ev.kept_all)
    for name in ("behaviours.png", "heldout.png", "expectations.png", "evaluation.json"):
        assert (tmp_path / "rep" / name).stat().st_size > 0
    assert json.loads((tmp_path / "rep" / "evaluation.json").read_text())["budget"] == ev.budget
    for measure, value, target, met in headline(ev):
        assert f"| {measure} | {value} |" in text
    assert f"| MAP-Elites (pyribs) | {ev.behaviours_seen['map_elites']} |" in text


def test_the_command_end_to_end_simulates_nothing_the_second_time_and_gives_the_same_figures(
        evaluated, learned, tmp_path):
    ev, _ = evaluated
    theory, store = learned
    r = run_cli("evaluate", "--theory", str(theory), "--store", str(store), "--out",
                str(tmp_path / "r"), "--scenes", "25", "--seed", "3", "--verify", "4",
                "--paper-samples", "5", "--executor", "inline", "--no-progress")
    assert r.code == 0, r.err
    assert "behaviours in the theory" in r.out and f"report: {tmp_path / 'r' / 'README.md'}" in r.out
    again = json.loads((tmp_path / "r" / "evaluation.json").read_text())
    assert sum(again.pop("simulations").values()) == 0      # every pour from the store
    figures = json.loads(json.dumps(ev.as_dict()))
    figures.pop("simulations"), figures.pop("seconds"), again.pop("seconds")
    assert again == figures
