"""Everyday words for the vocabulary's words (bridge/reasoning/words.py),
as reading.py reads questions with them: the phrases of `PHRASES` ("a full
cup", "come in quickly") read as the vocabulary's words, in their
inflections, and a negation or contradiction said in them still refused."""
from __future__ import annotations

import pytest

from pantarhei.bridge.errors import UserError
from pantarhei.bridge.reasoning.reading import understand


@pytest.mark.parametrize("question,props", [
    ("pour far from the cup", ["pour_far_away"]),
    ("a full container", ["very_much_liquid"]),
    ("pour from a filled jug", ["very_much_liquid"]),
    ("come in quickly", ["fast_approach"]),
    ("pour low over the rim", ["pour_low", "pour_near_rim"]),
    ("pour water into a heavy mug", ["heavy_destination"]),
    ("pour a viscous liquid", ["sticky_liquid"]),
    ("a liquid that does not bounce", ["dull_liquid"]),
    # a bowl is the destination, unless it is the one poured from
    ("pour out of a heavy cup into a light bowl", ["heavy_source", "light_destination"]),
    ("how much liquid spills if I pour from the side?", ["pour_to_side"]),
    # everyday verbs and adverbs for the dimensions
    ("move the cup in quickly and pour", ["fast_approach"]),
    ("pull the cup back fast", ["fast_retreat"]),
    ("what if the receiving bowl is light and slippery?",
     ["light_destination", "slippery_destination"]),
    ("pour syrup into a light cup", ["light_destination", "sticky_liquid"]),
    ("tilt the jug a bit", ["pour_slightly_tilted"]),
    ("tilt the source sideways while pouring", ["pour_rolled"]),
    ("end with the source tilted back", ["end_tilted_back"]),
    ("pour from a distance", ["pour_far_away"]),
    ("pour off to one side", ["pour_to_side"]),
    ("pour offset to the side", ["pour_offset_sideways"]),
    ("pour from the edge of the bowl", ["pour_near_rim"]),
    ("pour the water from a great height", ["pour_very_high"]),
    ("use a heavy glass as the source", ["heavy_source"]),
    ("take 4 seconds to move in", ["slow_approach"]),
])
def test_everyday_words_are_read_as_the_vocabulary(question, props):
    assert understand(question) == props


@pytest.mark.parametrize("question,words", [
    ("do not pour near the rim of the cup", "not pour_near_rim leaves"),
    ("don't pour at medium height over the cup", "not pour_mid_height leaves"),
    ("a light and heavy cup", "says both heavy_destination (a heavy destination bowl) and "
                              "light_destination"),
    ("move in fast and slowly", "two values of approach_speed"),
])
def test_negation_and_contradiction_in_everyday_words_are_still_refused(question, words):
    with pytest.raises(UserError) as e:
        understand(question)
    assert words in str(e.value) and "\n" not in str(e.value)


def test_a_negation_in_everyday_words_beside_the_value_said():
    assert understand("a light bowl, not a heavy cup") == ["light_destination"]


def test_no_filler_is_a_word_a_proposition_is_named_by():
    """A filler is dropped from every question: one that shared its stem
    with a word of a proposition's name ("nearly" with the "near" of
    pour_near_rim) would silence that word. Those below are fillers on
    purpose: "to", "in" and "down" say nothing alone, "move" is every
    movement's verb."""
    from pantarhei.bridge.reasoning.reading import _IGNORED
    from pantarhei.bridge.reasoning.wording import stem as _stem
    from pantarhei.theory.lexicon import load_vocabulary

    named = {_stem(w) for n in load_vocabulary().propositions for w in n.split("_")}
    assert named & _IGNORED == {_stem(w) for w in ("to", "in", "down", "move")}
