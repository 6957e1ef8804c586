"""bridge/evaluation/report_sections.py: the report's Markdown sections of a
hand-built evaluation say the figures they are given: the opening (how the
theory was learned and measured, whether it was reproduced), curiosity
against random exploration, the held-out table, the paper's three rules,
the plans, the learned rules in words, the pours drawn, and time; and
antecedents and consequents in words."""
from __future__ import annotations

from pathlib import Path

from pantarhei.bridge.evaluation import report_sections as R
from pantarhei.bridge.evaluation.headline import headline_markdown
from tests.bridge.evaluation.evaluations import small_evaluation


def test_antecedents_and_consequents_in_words():
    assert R.antecedent_words(["pour_low", "heavy_liquid"]) == \
        "pour low above the destination; a heavy liquid"
    assert R.consequent_words([True] * 9) == "everything as expected"
    assert R.consequent_words([True] * 4 + [False] + [True] * 3 + [False]) == \
        "not: source clear, no spill"


def test_the_rules_table_has_a_row_per_explored_antecedent():
    ev = small_evaluation()
    assert R.rules_table(ev)[2:] == [
        "| a1 | pour low above the destination | everything as expected | 100.0% |",
        "| a2 | pour from the side | not: no spill | 25.0% |"]
    ev.kept_all = [1.0]                 # no share known for a2
    assert R.rules_table(ev)[-1] == "| a2 | pour from the side | not: no spill | n/a |"


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


def test_curiosity_against_random_exploration_and_the_behaviours_each_method_saw():
    ev = small_evaluation()
    text = "\n".join(R.against_random(ev))
    assert "spends the same budget (24 pours) on 2 uniformly random valid antecedents" in text
    for row in ("| curiosity | 3 |", "| random valid antecedents | 2 |",
                "| random pours from the prior | 2 |", "| MAP-Elites (pyribs) | 5 |"):
        assert row in text
    ev.behaviours_seen = {}
    assert "| method | behaviours seen |" not in "\n".join(R.against_random(ev))


def test_the_held_out_table_and_the_per_expectation_plot_when_drawn(tmp_path):
    ev = small_evaluation()
    L = R.heldout_section(ev, tmp_path)
    assert "| near (20) | 2.5 | 95.0% | 90.0% | 97.0% | 80.0% | 40.0% | 90.0% |" in L
    # random exploration's theory decided nothing on the uniform scenes: no accuracy
    assert "| uniform (30) | 3.4 | 85.0% | 50.0% | 95.0% | n/a | 0.0% | 70.0% |" in L
    assert "![per expectation](expectations.png)" not in L
    (tmp_path / "expectations.png").write_bytes(b"")
    assert "![per expectation](expectations.png)" in R.heldout_section(ev, tmp_path)


def test_the_papers_rules_with_the_learned_rules_and_the_oracles_answer():
    ev = small_evaluation()
    L = R.paper_rules_section(ev)
    assert L[-3:] == [
        "| pouring from the side will result in spillage: `pour_to_side` → `neg(no_spill)` | "
        "`r2_no_spill` (with nothing else) | `neg(no_spill)` | 90.0% of 20 | `neg(no_spill)` | yes |",
        "| too light a liquid will not entirely leave the source: `light_liquid` → "
        "`neg(liquid_leaves_source)` | `r7_liquid_leaves_source` (with pour_low) | "
        "`liquid_leaves_source` | 25.0% of 20 | `liquid_leaves_source` (the oracle disagrees "
        "with the paper) | yes |",
        "| the liquid does not remain in the destination: `light_liquid`, `end_upright`, "
        "`end_low` → `neg(liquid_remains_in_destination)` | no rule | `unknown` | 60.0% of 19 | "
        "`neg(liquid_remains_in_destination)` | **no** |"]
    ev.paper_rules = [{k: v for k, v in r.items()
                       if k not in ("simulated", "oracle_share", "oracle_majority",
                                    "agrees_with_oracle")} for r in ev.paper_rules]
    assert R.paper_rules_section(ev)[-3].endswith("| `neg(no_spill)` | not simulated | n/a | **no** |")


def test_the_plans_found_measured_or_why_none():
    ev = small_evaluation()
    assert R.plans_section(ev)[-2:] == ["| no spill | pour_low | 8 of 8 |",
                                        "| everything goes well | (an ordinary pour) | 7 of 8 |"]
    ev.plans = [{"words": "carry", "goals": [], "none": "unreachable goal: no rule concludes it"},
                {"words": "no spill", "goals": [], "plan": ["pour_low", "pour_centred"]}]
    assert R.plans_section(ev)[-2:] == [
        "| carry | none found: unreachable goal: no rule concludes it | - |",
        "| no spill | pour_low, pour_centred | not simulated |"]
    ev.plans = []
    assert R.plans_section(ev)[-1] == "| (not verified) | | |"


def test_the_learned_rules_and_the_exploration_trace_when_copied(tmp_path):
    ev = small_evaluation()
    L = R.learned_rules_section(ev, tmp_path)
    assert "| a2 | pour from the side | not: no spill | 25.0% |" in L
    assert "## The exploration" not in L
    (tmp_path / "exploration.png").write_bytes(b"")
    assert R.learned_rules_section(ev, tmp_path)[-1] == "![exploration trace](exploration.png)"


def test_the_pours_drawn_and_the_time_of_each_stage():
    ev = small_evaluation()
    assert R.pours_section(ev, []) == []
    L = R.pours_section(ev, [(1, Path("/x/pour_a2.gif"))])
    assert "**a2**: pour from the side. Then: not: no spill." in L
    assert "![pour a2](pour_a2.gif)" in L
    # a stage that simulated nothing it did not find in the store: 0; one that simulates nothing: blank
    assert R.time_section(ev)[-2:] == ["| exploration | 0 | 0.4 |", "| predicting |  | 1.5 |"]
