"""bridge/evaluation/report_sections.py: the report's parts that are no
measure's, of a hand-built evaluation, say the figures they are given: the
opening (how the theory was learned and measured, whether it was
reproduced), the pours drawn, and time."""
from __future__ import annotations

from pathlib import Path

from pantarhei.bridge.evaluation import report_sections as R
from pantarhei.bridge.evaluation.headline import headline_markdown
from tests.bridge.evaluation.evaluations import small_evaluation


def test_the_opening_says_how_the_theory_was_learned_and_measured():
    ev = small_evaluation()
    L = R.opening(ev, "pantarhei evaluate --seed 3")
    assert L[0] == "# Evaluation of `learned/t.pl`"
    assert L[2] == ("Measured by `pantarhei evaluate --seed 3` with the synthetic oracle (version 2). "
                    "The theory was learned with seed 7, 2 explored antecedents of 12 pours each "
                    "(24 pours), qualify `weighted`. All numbers below are in `evaluation.json`.")
    assert L[4] == "The exploration's own pours, simulated here, give exactly the theory's rules."
    assert L[6:] == ["## Headline", "", headline_markdown(ev).rstrip("\n")]
    ev.reproduced = False
    assert R.opening(ev, "make evaluate")[4].startswith(
        "**The exploration's own pours, simulated here, do not give all of the theory's rules**")


def test_the_pours_drawn_and_the_time_of_each_stage():
    ev = small_evaluation()
    assert R.pours_section(ev, []) == []
    L = R.pours_section(ev, [(1, Path("/x/pour_a2.gif"))])
    assert "**a2**: pour from the side. Then: not: no spill." in L
    assert "![pour a2](pour_a2.gif)" in L
    # a stage that simulated nothing it did not find in the store: 0; one that simulates nothing: blank
    assert R.time_section(ev)[-2:] == ["| exploration | 0 | 0.4 |", "| predicting |  | 1.5 |"]


def test_the_opening_says_a_one_layer_theory_s_curiosity(toy_curiosities):
    """A theory that is one layer (its curiosity's module lays it out
    without Algorithm 1's rules) is said by its curiosity and batches; one
    of two layers by its antecedents and how they were qualified."""
    one, two = toy_curiosities
    ev = small_evaluation()
    ev.settings["curiosity"] = one
    assert R.opening(ev, "make evaluate")[2].endswith(
        "2 explored antecedents in batches of 12 pours (24 pours), curiosity `one_layer`. "
        "All numbers below are in `evaluation.json`.")
    ev.settings["curiosity"] = two
    assert "2 explored antecedents of 12 pours each (24 pours), qualify `weighted`." in \
        R.opening(ev, "make evaluate")[2]
