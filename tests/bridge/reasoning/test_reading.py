"""Words read as meant (bridge/reasoning/reading.py): each word where it
stands, negation as the other values of its dimension or refused, and a
contradiction refused; never answered as if the negation were not there."""
from __future__ import annotations

import pytest

from pantarhei.bridge.errors import UserError
from pantarhei.bridge.reasoning.reading import understand
from tests.conftest import assert_one_line_error, run_cli


@pytest.mark.parametrize("question,props", [
    ("pour from the side", ["pour_to_side"]),
    ("What happens if the liquid is very light?", ["light_liquid"]),
    ("pour_to_side, pour_low", ["pour_low", "pour_to_side"]),
    # each value word belongs to the proposition whose words stand closest to it
    ("pour low with a heavy source bowl and a light destination bowl",
     ["heavy_source", "light_destination", "pour_low"]),
    ("pour low and end high", ["end_high", "pour_low"]),
    ("start low, pour high and end low", ["end_low", "pour_high", "start_low"]),
    ("start very high above the destination", ["start_very_high"]),
    ("a liquid of medium weight in a destination bowl of medium weight",
     ["medium_destination", "medium_liquid"]),
    ("end with the source upright", ["end_upright"]),
    # a gloss that says "not" itself is no negation
    ("a dull liquid that does not bounce", ["dull_liquid"]),
])
def test_words_are_read_where_they_stand(question, props):
    assert understand(question) == props


@pytest.mark.parametrize("question,props", [
    ("the source bowl is not heavy", ["light_source"]),            # the one other value
    ("don't pour with the source rolled sideways", ["pour_level"]),
    ("a liquid that isn't light and isn't heavy", ["medium_liquid"]),
    ("never pour from the side, pour centred over the destination", ["pour_centred"]),
    ("pour high, not very high", ["pour_high"]),
])
def test_a_negation_is_read_as_the_other_values_of_its_dimension(question, props):
    assert understand(question) == props


@pytest.mark.parametrize("question,words", [
    ("do not pour from the side", "not pour_to_side leaves pour_centred, pour_near_rim or pour_far_away"),
    ("never pour from the side, pour from the front", "not pour_to_side leaves"),
    ("a liquid that is not heavy", "not heavy_liquid leaves light_liquid or medium_liquid"),
    ("pour from the side without much liquid", "not much_liquid leaves"),
    ("pour low, but not from the front", "understood nothing that \"not from the front\" excludes"),
    ("a light and heavy liquid", "says both heavy_liquid (a heavy liquid) and light_liquid"),
    ("pour from the side and pour centred", "two values of pour_alignment"),
])
def test_a_negation_or_contradiction_not_understood_is_refused(question, words):
    with pytest.raises(UserError) as e:
        understand(question)
    assert words in str(e.value) and "\n" not in str(e.value)


@pytest.mark.parametrize("question", ["do not pour from the side", "a light and heavy liquid",
                                      "a liquid that is not heavy"])
def test_ask_refuses_them_in_one_line(question):
    r = run_cli("ask", question)
    assert_one_line_error(r)
    assert r.out == ""                 # no answer as if the negation were not there
