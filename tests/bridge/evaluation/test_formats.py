"""bridge/evaluation/formats.py: how the report writes a share, a number,
an antecedent and a consequent."""
from __future__ import annotations

from pantarhei.bridge.evaluation.formats import antecedent_words, consequent_words, num, pct


def test_a_share_is_a_percentage_and_a_number_has_three_decimals():
    assert pct(0.875) == "87.5%" and pct(1) == "100.0%" and pct(0.0) == "0.0%"
    assert num(0.04) == "0.040" and num(1 / 3) == "0.333"
    assert pct(None) == "n/a" and num(None) == "n/a"


def test_antecedents_and_consequents_in_words():
    assert antecedent_words(["pour_low", "heavy_liquid"]) == \
        "pour low above the destination; a heavy liquid"
    assert consequent_words([True] * 9) == "everything as expected"
    assert consequent_words([True] * 4 + [False] + [True] * 3 + [False]) == \
        "not: source clear, no spill"
