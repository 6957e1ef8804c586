"""bridge/evaluation/headline.py: the headline rows (each figure, its
target and whether it is met) of an evaluation built by hand, every
measure's in the registry's order, and the Markdown table report/README.md
opens with; the general theory's rows (general_answers.py)."""
from __future__ import annotations

import dataclasses

from pantarhei.bridge.evaluation.general_answers import general_headline
from pantarhei.bridge.evaluation.headline import headline, headline_markdown
from tests.bridge.evaluation.evaluations import general_figures, small_evaluation


def test_the_rows_of_a_hand_built_evaluation_against_their_targets():
    rows = headline(small_evaluation(general=False))
    assert rows == [
        ("behaviours in the theory at 24 pours (distinct consequents of the explored "
         "antecedents): curiosity / random valid antecedents", "2 / 1 = 2.00x", "at least 1x", True),
        ("behaviours seen at 24 pours (nine-verdict vectors two pours show): curiosity / random "
         "valid antecedents", "3 / 2 = 1.50x (MAP-Elites 5: 0.60x)", "at least 1x", True),
        ("held-out accuracy where the theory decides (near explored scenes, 20 scenes)",
         "95.0%", "at least 90%", True),
        ("held-out coverage (near explored scenes)", "90.0%", "at least 90%", True),
        ("decision tree accuracy, same simulations (near explored scenes)",
         "97.0% (+2.0 points)", "theory within 5 points", True),
        ("held-out accuracy where the theory decides (uniformly random scenes, 30 scenes)",
         "85.0%", "at least 90%", False),
        ("held-out coverage (uniformly random scenes)", "50.0%", "at least 90%", False),
        ("decision tree accuracy, same simulations (uniformly random scenes)",
         "95.0% (+10.0 points)", "theory within 5 points", False),
        ("the paper's three questions answered as the oracle's majority shows", "2 of 3", "all",
         False),
        ("plans for 2 goal sets a user would ask, measured on fresh pours: the lowest share "
         "meeting the goals", "87.5%", "at least 80% on each", True),
    ]


def test_a_held_out_set_the_theory_decides_nothing_in_is_not_met():
    ev = small_evaluation(general=False)
    ev.heldout = {"near": {**ev.heldout["near"],
                           "curiosity_theory": {"accuracy": None, "coverage": 0.0}}}
    rows = {m: (v, met) for m, v, _, met in headline(ev)}
    # the uniform set is not in this evaluation: no rows for it
    assert not any("uniformly random" in m for m in rows)
    assert rows["held-out accuracy where the theory decides (near explored scenes, 20 scenes)"] \
        == ("n/a", False)
    assert rows["held-out coverage (near explored scenes)"] == ("0.0%", False)
    # no gap to a theory that decides nothing: the tree's accuracy alone
    assert rows["decision tree accuracy, same simulations (near explored scenes)"] \
        == ("97.0%", False)


def test_a_goal_set_without_a_plan_counts_as_none_met_and_unsimulated_paper_rules_give_no_row():
    ev = small_evaluation(general=False)
    ev.plans = ev.plans + [{"goals": ["no_spill"], "words": "w", "none": "no plan"}]
    ev.paper_rules = [{k: v for k, v in r.items() if k not in ("oracle_majority", "simulated")}
                      for r in ev.paper_rules]
    rows = {m: (v, met) for m, v, _, met in headline(ev)}
    assert rows["plans for 3 goal sets a user would ask, measured on fresh pours: the lowest "
                "share meeting the goals"] == ("0.0%", False)
    assert not any("paper" in m for m in rows)


def test_the_general_rows_name_the_baselines_figures_and_the_targets():
    ev = small_evaluation()
    rows = general_headline(ev)
    assert [(m, v, met) for m, v, _, met in rows] == [
        ("questions (2): coverage of the 40 clear keys", "97.5%", True),
        ("questions: accuracy on the clear keys (defaults only: 75.0%)", "96.0%", True),
        ("questions: accuracy on the 10 contrast keys, where the defaults-only answer is wrong "
         "(25.0% of the clear keys; covered 80.0%)", "90.0%", True),
        ("calibration: mean |likelihood - share of the pours| (boosting on the same pours "
         "0.040, defaults only 0.200)", "0.050", True),
        ("coherent answers: the decided verdicts are a behaviour one of the question's pours "
         "shows", "96.0%", True),
        ("general rules per expectation (from curiosity's pours)", "1.5", True),
    ]
    assert rows == headline(ev)[8:14]       # after the held-out rows, before the paper's
    assert general_headline(dataclasses.replace(ev, general={})) == []


def test_calibration_is_not_met_more_than_two_points_behind_boosting():
    g = general_figures()
    g["curiosity"] = {**g["curiosity"], "boosting": {
        **g["curiosity"]["boosting"],
        "questions": {**g["curiosity"]["boosting"]["questions"], "calibration": 0.01}}}
    rows = general_headline(dataclasses.replace(small_evaluation(), general=g))
    cal = [r for r in rows if r[0].startswith("calibration")][0]
    assert cal[1] == "0.050" and "boosting on the same pours 0.010" in cal[0]
    assert cal[3] is False          # 0.05 is within 0.08, but 0.04 behind boosting


def test_the_markdown_table_has_a_line_per_row_and_says_whether_each_is_met():
    ev = small_evaluation()
    lines = headline_markdown(ev).splitlines()
    assert lines[:2] == ["| measure | measured | target | met |", "|---|---|---|---|"]
    rows = headline(ev)
    assert len(lines) == 2 + len(rows)
    assert lines[2] == ("| behaviours in the theory at 24 pours (distinct consequents of the "
                        "explored antecedents): curiosity / random valid antecedents | "
                        "2 / 1 = 2.00x | at least 1x | yes |")
    assert lines[-1] == ("| plans for 2 goal sets a user would ask, measured on fresh pours: the "
                         "lowest share meeting the goals | 87.5% | at least 80% on each | yes |")
    assert headline_markdown(ev).endswith("|\n")
