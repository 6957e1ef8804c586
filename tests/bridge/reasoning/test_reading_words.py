"""Questions in everyday words (bridge/reasoning/reading.py, words.py):
every aspect of a sentence kept, each value word read of the noun it
qualifies and in the stage it is said in, everyday words read as the
vocabulary's, and a word that cannot be placed refused rather than
dropped: an answer about another pour is the worst answer."""
from __future__ import annotations

import json
from pathlib import Path

import pytest

from pantarhei.bridge.errors import UserError
from pantarhei.bridge.reasoning.reading import understand
from pantarhei.theory.lexicon import load_vocabulary
from tests.conftest import assert_one_line_error, run_cli

QUESTIONS = Path(__file__).resolve().parents[3] / "bridge" / "evaluation" / "questions.json"


def _questions() -> list[tuple[str, list[str]]]:
    return [(q["text"], sorted(q["antecedent"]))
            for q in json.loads(QUESTIONS.read_text(encoding="utf-8"))["questions"]]


@pytest.mark.parametrize("question,props", _questions(), ids=[q for q, _ in _questions()])
def test_every_evaluation_question_is_read_as_its_antecedent(question, props):
    assert understand(question) == props


@pytest.mark.parametrize("name", sorted(load_vocabulary().propositions))
def test_every_gloss_is_read_as_its_proposition(name):
    assert understand(load_vocabulary().propositions[name].gloss) == [name]


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
])
def test_everyday_words_are_read_as_the_vocabulary(question, props):
    assert understand(question) == props


@pytest.mark.parametrize("question,props", [
    ("pour a runny, bouncy liquid", ["bouncy_liquid", "runny_liquid"]),
    ("a light, slippery bowl", ["light_destination", "slippery_destination"]),
    ("a heavy liquid into a slippery light bowl",
     ["heavy_liquid", "light_destination", "slippery_destination"]),
    ("a light liquid and a heavy source bowl", ["heavy_source", "light_liquid"]),
    ("the liquid is very light", ["light_liquid"]),             # the noun before it
    ("pour low and centred, tilted halfway", ["pour_centred", "pour_half_tilted", "pour_low"]),
    ("pour upside down, rolled and offset sideways",
     ["pour_offset_sideways", "pour_rolled", "pour_upside_down"]),
])
def test_every_aspect_is_kept_and_a_value_word_is_its_nouns(question, props):
    assert understand(question) == props


@pytest.mark.parametrize("question,props", [
    ("pour low, then right the source up", ["end_upright", "pour_low"]),
    ("start high, move in slowly and pour low", ["pour_low", "slow_approach", "start_high"]),
    ("move in fast from low down", ["fast_approach", "start_low"]),     # the pose moved from
    ("pour, and keep the source steeply tilted as it moves away", ["end_steeply_tilted"]),
    ("move away fast after pouring", ["fast_retreat"]),                 # leaving, no direction
    ("pour, then move away from the bowl", ["retreat_moving_away"]),
    ("lift the source before pouring", ["approach_raising"]),
    ("pour, then move away fast and up", ["fast_retreat", "retreat_raising"]),
    ("end with the source upside down, far from the bowl", ["end_far_away", "end_upside_down"]),
    ("pour, then put the source down below the rim", ["end_below_rim"]),
])
def test_each_word_is_read_in_the_stage_it_is_said_in(question, props):
    assert understand(question) == props


@pytest.mark.parametrize("question,words", [
    ("do not move in fast", "not fast_approach leaves moderate_approach or slow_approach"),
    ("don't pour far from the cup", "not pour_far_away leaves"),
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


@pytest.mark.parametrize("question,words", [
    ("pour light", '"light"'),                                   # the light what?
    ("pour fast", '"fast"'),                                     # pouring has no speed
    ("pour from the side, tilted", '"tilted"'),                  # tilted how far?
    ("pour from the side with a purple bowl", '"purple"'),       # a word not known
    ("pour a heavy liquid from 45 degrees", '"45", "degrees"'),
])
def test_a_word_that_cannot_be_placed_is_refused_naming_it(question, words):
    with pytest.raises(UserError) as e:
        understand(question)
    assert f"could not place {words} in \"{question}\"" in str(e.value)
    assert "\n" not in str(e.value)


@pytest.mark.parametrize("question,props", [
    ("What would happen if I pour from the side?", ["pour_to_side"]),
    ("will the liquid spill if we pour it from very high up?", ["pour_very_high"]),
    ("does the destination tip over when I pour a heavy liquid into a light bowl?",
     ["heavy_liquid", "light_destination"]),
    ("sing me a song", []),                  # nothing understood: the caller says so
])
def test_the_words_of_a_question_are_not_refused(question, props):
    assert understand(question) == props


def test_ask_refuses_a_word_it_cannot_place_in_one_line():
    r = run_cli("ask", "pour from the side with a purple bowl")
    assert "purple" in assert_one_line_error(r)
    assert r.out == ""
