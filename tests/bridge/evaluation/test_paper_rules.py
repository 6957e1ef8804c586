"""bridge/evaluation/paper_rules.py: the paper's three example rules asked
of a small hand-built theory (its learned rules for each, what it says) and
simulated by a stand-in oracle whose verdicts are known: the share of pours
where the paper's literal holds, the oracle's majority and whether the
theory agrees with it; failed pours are not counted. And the report's
section of a hand-built evaluation."""
from __future__ import annotations

import numpy as np

from pantarhei.bridge.evaluation.paper_rules import PAPER_RULES, paper_rules, paper_rules_section
from pantarhei.bridge.evaluation.rule_building import theory_of
from pantarhei.theory.lexicon import load_vocabulary
from tests.bridge.evaluation.evaluations import small_evaluation

NAMES = load_vocabulary().expectation_names


def spills_and_empties(P: np.ndarray) -> np.ndarray:
    """Every pour spills (no_spill 0.1), all its liquid leaves the source
    and none remains in the destination; everything else holds."""
    S = np.full((len(P), 9), 0.9)
    S[:, NAMES.index("no_spill")] = 0.1
    S[:, NAMES.index("liquid_remains_in_destination")] = 0.1
    return S


def side_theory():
    """From the side: no_spill fails; light liquid poured low: the liquid
    does not all leave the source."""
    heads = np.ones((2, 9), dtype=bool)
    heads[0, NAMES.index("no_spill")] = False
    heads[1, NAMES.index("liquid_leaves_source")] = False
    return theory_of([("pour_to_side",), ("light_liquid", "pour_low")], heads, "side")


def test_the_theory_is_asked_each_of_the_papers_scenes():
    out = paper_rules(side_theory(), spills_and_empties, 0, seed=1)
    assert [(r["scene"], r["literal"]) for r in out] == [(list(p), lit) for p, lit, _ in PAPER_RULES]
    side, light, righted = out
    assert side["paper_words"] == "pouring from the side will result in spillage"
    assert side["learned"] == [{"rule": "r1_no_spill", "also_needs": []}]
    assert side["theory_says"] == "neg(no_spill)" and side["rule"] == "r1_no_spill"
    # the rule for the light liquid also needs pouring low: it does not apply to the scene alone
    assert light["learned"] == [{"rule": "r2_liquid_leaves_source", "also_needs": ["pour_low"]}]
    assert light["theory_says"] == "unknown" and light["rule"] is None      # no rule: null
    assert righted["learned"] == [] and righted["theory_says"] == "unknown"
    # nothing simulated with n = 0
    assert not any("simulated" in r or "oracle_share" in r for r in out)


def test_the_oracles_share_and_majority_and_whether_the_theory_agrees():
    out = paper_rules(side_theory(), spills_and_empties, 5, seed=1)
    side, light, righted = out
    assert (side["simulated"], side["oracle_share"], side["oracle_majority"]) == (5, 1.0, "neg(no_spill)")
    assert side["agrees_with_oracle"] is True
    # the liquid always leaves the source: the oracle's majority is the paper's literal's complement
    assert (light["oracle_share"], light["oracle_majority"]) == (0.0, "liquid_leaves_source")
    assert light["agrees_with_oracle"] is False
    assert (righted["oracle_share"], righted["oracle_majority"]) == \
        (1.0, "neg(liquid_remains_in_destination)")
    assert righted["agrees_with_oracle"] is False          # the theory says nothing


def test_each_scene_is_sampled_and_failed_pours_are_not_counted():
    seen = []

    def every_other_fails(P: np.ndarray) -> np.ndarray:
        seen.append(P)
        S = spills_and_empties(P)
        S[1::2] = np.nan
        S[2, NAMES.index("no_spill")] = 0.9     # of the first scene's 3 pours left, one keeps no_spill
        return S

    out = paper_rules(side_theory(), every_other_fails, 6, seed=1)
    assert len(seen) == 1 and seen[0].shape == (18, 30)
    assert [r["simulated"] for r in out] == [3, 3, 3]
    assert out[0]["oracle_share"] == 2 / 3 and out[0]["oracle_majority"] == "neg(no_spill)"


def test_a_scene_whose_pours_all_failed_has_no_share_and_no_majority():
    out = paper_rules(side_theory(), lambda P: np.full((len(P), 9), np.nan), 4, seed=1)
    for r in out:
        assert r["simulated"] == 0 and r["oracle_share"] is None and r["oracle_majority"] is None
        assert r["agrees_with_oracle"] is False


def test_the_papers_rules_with_the_learned_rules_and_the_oracles_answer(tmp_path):
    ev = small_evaluation()
    L = paper_rules_section(ev, tmp_path)
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
    assert paper_rules_section(ev, tmp_path)[-3].endswith("| `neg(no_spill)` | not simulated | n/a | **no** |")
