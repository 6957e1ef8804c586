"""bridge/evaluation/report_general.py: the report's section on the general
theory, for hand-built figures: a row per theory or model with its figures
on the questions and the uniform scenes, each question as the shipped
theory answers it (the clear keys it gets wrong or leaves open, contrast
keys starred), and the general rules in words with the likelihood that
the expectation holds."""
from __future__ import annotations

import dataclasses
from pathlib import Path

from pantarhei.bridge.evaluation.report_general import general_section
from tests.bridge.evaluation.evaluations import general_figures, small_evaluation


def section(**changes) -> list[str]:
    g = {**general_figures(), **changes}
    return general_section(dataclasses.replace(small_evaluation(), general=g), Path("."))


def test_no_general_figures_no_section():
    assert general_section(small_evaluation(general=False), Path(".")) == []


def test_a_row_per_theory_or_model_with_its_figures():
    L = section()
    assert L[0] == "## The general theory, asked what a person would ask"
    assert "`bridge/evaluation/questions.json` (2: one-phrase questions" in L[2]
    rows = L[L.index("|---|---|---|---|---|---|---|---|") + 1:][:7]
    assert rows == [
        "| the shipped theory (both layers, 14 general rules) | curiosity | 97.5% | 96.0% | "
        "90.0% (80.0%) | 0.050 | 96.0% | 88.0% (70.0%) |",
        "| general rules alone (1.5 per expectation) | curiosity (300) | 100.0% | 95.0% | "
        "90.0% (80.0%) | 0.030 | 96.0% | 90.0% (100.0%) |",
        "| gradient boosting | curiosity | 100.0% | 97.0% | 90.0% (80.0%) | 0.040 | 96.0% | - |",
        "| defaults only | curiosity | 100.0% | 75.0% | 0.0% (80.0%) | 0.200 | 96.0% | - |",
        "| general rules alone (1.5 per expectation) | random (300) | 100.0% | 95.0% | "
        "90.0% (80.0%) | 0.030 | 96.0% | 90.0% (100.0%) |",
        "| gradient boosting | random | 100.0% | 97.0% | 90.0% (80.0%) | 0.040 | 96.0% | - |",
        "| defaults only | random | 100.0% | 75.0% | 0.0% (80.0%) | 0.200 | 96.0% | - |",
    ]


def test_each_question_with_the_clear_keys_the_shipped_theory_misses():
    L = section()
    assert "10 of the 40 clear keys are contrast keys." in L
    # question 0 leaves source_clear open; question 1 gets liquid_leaves_source, a
    # contrast key, wrong (no_spill, answered as its key, is not clear)
    assert "| an ordinary pour | 9 | 0 | - | source_clear |" in L
    assert "| pour from the side | 8 | 1 | liquid_leaves_source* | - |" in L
    # without contrast keys nothing is starred
    g = general_figures()
    del g["contrast"]
    L = general_section(dataclasses.replace(small_evaluation(), general=g), Path("."))
    assert "| pour from the side | 8 | 0 | liquid_leaves_source | - |" in L


def test_the_general_rules_in_words_with_the_likelihood_the_expectation_holds():
    L = section()
    assert "| `g0_no_spill` | (an ordinary pour) | `no_spill` | 0.80 | 80 of 100 |" in L
    # a rule concluding neg(no_spill) with confidence 0.9: no_spill holds in 10% of such pours
    assert "| `g1_no_spill` | pour from the side | `neg(no_spill)` | 0.10 | 11 of 12 |" in L
    assert L[-1] == ""
