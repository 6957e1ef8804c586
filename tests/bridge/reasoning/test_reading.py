"""Questions read as meant (bridge/reasoning/reading.py): every evaluation
question as its antecedent and every gloss as its proposition; each word
where it stands, of the noun it qualifies and in the stage it is said in,
every aspect of a sentence kept; negation read as the other values of its
dimension or refused, a contradiction refused, and a word that cannot be
placed refused rather than dropped: never answered as if the negation were
not there, for an answer about another pour is the worst answer. (The
everyday words read as the vocabulary's are words.py's: test_words.py.)"""
from __future__ import annotations

import json
import re
from pathlib import Path

import pytest

from pantarhei.bridge.errors import UserError
from pantarhei.bridge.reasoning.reading import read_question, understand
from pantarhei.theory.lexicon import load_vocabulary
from tests.conftest import assert_one_line_error, run_cli


def refusal(question: str) -> str:
    """The one line `understand` refuses `question` with."""
    with pytest.raises(UserError) as e:
        understand(question)
    assert "\n" not in str(e.value)
    return str(e.value)


QUESTIONS = Path(__file__).resolve().parents[3] / "bridge" / "evaluation" / "questions.json"


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
    ("never pour high", []),                 # the ordinary pour, at 50 to 120 mm, lies outside it
    ("do not pour from the side", []),
    ("do not pour centred", ["pour_near_rim"]),              # the nearest place off the middle, said back
    ("can't I pour from the side?", ["pour_to_side"]),        # asked negatively: negates nothing
])
def test_a_negation_is_read_as_the_other_values_of_its_dimension(question, props):
    assert understand(question) == props


@pytest.mark.parametrize("question,words", [
    ("do not pour low", "not pour_low leaves pour_below_rim, pour_mid_height, pour_high or pour_very_high"),
    ("never pour from the side, pour from the front", "could not place \"front\""),
    ("never pour upside down", "not pour_upside_down leaves pour_tilted_back, pour_upright"),
    ("pour from the side without much liquid", "not much_liquid leaves"),
    ("pour low, but not from the front", "understood nothing that \"not from the front\" excludes"),
    ("a light and heavy liquid", "says both heavy_liquid (a heavy liquid) and light_liquid"),
    ("pour from the side and pour centred", "two values of pour_alignment"),
])
def test_a_negation_or_contradiction_not_understood_is_refused(question, words):
    assert words in refusal(question)


@pytest.mark.parametrize("question", ["do not pour low", "a light and heavy liquid",
                                      "do not pour upside down"])
def test_ask_refuses_them_in_one_line(question):
    r = run_cli("ask", question)
    assert_one_line_error(r)
    assert r.out == ""                 # no answer as if the negation were not there


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
    ("pour light", '"light"'),                                   # the light what?
    ("pour fast", '"pour fast"'),                                # pouring has no speed
    ("start tilted and pour from the side", '"tilted"'),         # tilted how far?
    ("pour from the side with a furry bowl", '"furry"'),         # a word not known
    ("pour a heavy liquid from 45 furlongs", '"45", "furlongs"'),     # no unit known
])
def test_a_word_that_cannot_be_placed_is_refused_naming_it(question, words):
    assert f"could not place {words} in \"{question}\"" in refusal(question)


@pytest.mark.parametrize("question,props", [
    ("What would happen if I pour from the side?", ["pour_to_side"]),
    ("will the liquid spill if we pour it from very high up?", ["pour_very_high"]),
    ("does the destination tip over when I pour a heavy liquid into a light bowl?",
     ["heavy_liquid", "light_destination"]),
    # a question of pouring that names no proposition asks of the ordinary pour
    ("pour", []),
    ("what happens if I pour water into a cup?", []),
])
def test_the_words_of_a_question_are_not_refused(question, props):
    assert understand(question) == props


def test_ask_refuses_a_word_it_cannot_place_in_one_line():
    r = run_cli("ask", "pour from the side with a furry bowl")
    assert "furry" in assert_one_line_error(r)
    assert r.out == ""


@pytest.mark.parametrize("words", [
    "pour from the side",                                     # one reading, many times
    "light",                                                  # value words without a noun
    "not a",                                                  # negations, each with a scope
    "a light bowl , not heavy and then pour low",             # clauses, stages, nouns
])
def test_a_long_question_is_read_in_time_linear_in_its_length(words):
    """About 100 KB in one line (the reader grew with its square: such a
    line took a minute and more; read in time linear in its length, it
    takes a few seconds, and the bound leaves room for a busy machine)."""
    import signal

    def too_slow(*_):
        raise TimeoutError("reading a 100 KB question took more than 10 s")

    question = " ".join([words] * (100_000 // (len(words) + 1)))
    old = signal.signal(signal.SIGALRM, too_slow)
    signal.alarm(10)
    try:
        try:
            understand(question)
        except UserError as e:          # refused in one line is an answer too
            assert "\n" not in str(e)
    finally:
        signal.alarm(0)
        signal.signal(signal.SIGALRM, old)


@pytest.mark.parametrize("question", ["sing me a song", "what happens?", "pour a song"])
def test_a_question_that_says_nothing_of_a_pour_is_refused(question):
    with pytest.raises(UserError, match="understood none of"):
        understand(question)


def test_ask_answers_pour_alone_as_the_ordinary_pour():
    r = run_cli("ask", "what happens if I pour?")
    assert r.code == 0 and "an ordinary pour" in r.out


@pytest.mark.parametrize("question,props", [
    # each noun phrase of a coordination keeps its own words, negated or not
    ("the source is not heavy and the destination is heavy",
     ["heavy_destination", "light_source"]),
    ("the source is heavy and the destination is light", ["heavy_source", "light_destination"]),
    ("the liquid is sticky and the source is not light", ["heavy_source", "sticky_liquid"]),
    # a value said of coordinated nouns, or of bowls in the plural, is said of each
    ("the source and the destination are both heavy", ["heavy_destination", "heavy_source"]),
    ("a light source and destination", ["light_destination", "light_source"]),
    ("both bowls are slippery", ["slippery_destination", "slippery_source"]),
    ("a heavy glass", ["heavy_destination"]),                        # a glass is one bowl
    # everyday verbs and adverbs
    ("pour steeply", ["pour_steeply_tilted"]),
    ("finish with the source upside down", ["end_upside_down"]),
    ("pour, then put the source back upright", ["end_upright"]),
    ("only a few drops", ["little_liquid"]),
])
def test_coordination_and_everyday_words(question, props):
    assert understand(question) == props


@pytest.mark.parametrize("question,words", [
    ("pour from the side and from above", '"from above"'),      # above: how high, or where?
    ("the destination is full", '"full"'),                      # the source is what is filled
    ("pour into a sticky bowl", '"sticky"'),                    # the liquid is what is sticky
    ("pour with the bowl upside down", '"upside"'),             # the bowl is the destination
])
def test_words_said_of_what_they_cannot_be_said_of_are_refused(question, words):
    assert f"could not place {words}" in refusal(question)


@pytest.mark.parametrize("question,props", [
    ("tilted at 45 degrees", ["pour_half_tilted"]),
    ("tilt the source 100\u00b0 when pouring", ["pour_steeply_tilted"]),
    ("end at 10 degrees", ["end_slightly_tilted"]),
    ("pour with the source rolled 20 degrees", ["pour_rolled"]),
    ("30 cm above the bowl", ["pour_very_high"]),
    ("pour 70 mm above the bowl", ["pour_mid_height"]),
    ("pour 2 cm below the rim", ["pour_below_rim"]),
    ("pour 0 cm above the rim", ["pour_low"]),       # on a bound: the upper range
    ("start 0.1 m above the destination, then pour low", ["pour_low", "start_mid_height"]),
    ("pour 15 cm to the side", ["pour_to_side"]),
    ("pour 5cm sideways", ["pour_offset_sideways"]),
    ("move in over 3 seconds", ["slow_approach"]),
    ("pour, then move away in 500 ms", ["fast_retreat"]),
    ("a 2 kg bowl", ["heavy_destination"]),
    ("pour from a source bowl of 300 g", ["light_source"]),
    ("50 particles of liquid", ["some_liquid"]),
])
def test_numbers_with_units_are_read_as_the_proposition_whose_range_holds_them(question, props):
    assert understand(question) == props


@pytest.mark.parametrize("question,words", [
    ("pour for 3 seconds", "pouring takes no time of its own"),
    ("pour 10 cm from the bowl", "above the destination, or to its side?"),
    ("pour with the source tilted 200 degrees", "200 deg of pour_pitch, which no proposition "
                                                "holds (pour_tilted_back -30 to -5 deg;"),
    ("pour from a 3 kg source bowl", "3000 g of source_mass, which no proposition holds"),
    ("pour with 35 particles", "which no proposition holds (little_liquid 10 to 30 count;"),
    ("pour with 148 particles", "say one of these (the nearest: very_much_liquid)"),
    ("a 5 kg liquid", "the mass of which bowl?"),
])
def test_a_number_no_proposition_holds_is_refused_naming_the_ranges(question, words):
    assert words in refusal(question)


def _answer_lines(out: str) -> list[str]:
    """The expectation of each answer line of `ask`'s output, in order."""
    return [m.group(1) for m in re.finditer(r"^  \[[^\]]*\]\s+(\w+)", out, re.M)]


def test_ask_answers_the_expectations_asked_first():
    r = run_cli("ask", "will it overflow if I pour from the side, and will the bowl tip?")
    assert r.code == 0, r.err
    assert "understood: pour_to_side" in r.out
    asked = ["liquid_remains_in_destination", "no_spill", "destination_upright"]
    assert f"asked: {', '.join(asked)}" in r.out
    assert _answer_lines(r.out)[:3] == asked and len(_answer_lines(r.out)) == 9


def test_ask_hears_a_goal_and_points_to_plan():
    r = run_cli("ask", "pour from the side without spilling")
    assert r.code == 0, r.err
    assert "wanted: no_spill" in r.out
    assert "pantarhei plan --goal no_spill --given pour_to_side" in r.out
    assert _answer_lines(r.out)[0] == "no_spill"


def test_ask_says_back_everyday_words_and_shows_what_it_ignored():
    r = run_cli("ask", "--json", "will it overflow if I pour milk into a very light plastic cup?")
    assert r.code == 0, r.err
    out = json.loads(r.out)
    assert out["understood"] == ["light_destination"]
    assert out["asked"] == ["liquid_remains_in_destination", "no_spill"]
    assert any(n.startswith("milk: read as an ordinary liquid") for n in out["notes"])
    assert out["ignored"] == ["very"]


@pytest.mark.parametrize("question,words", [
    ("pour from the sde", "did you mean 'side' for 'sde'?"),           # too short to read as side
    ("pour a havy liquid from the sde", "did you mean 'heavy' for 'havy', 'side' for 'sde'?"),
    ("tilt the jug to the left", '"tilt the jug to the left"'),        # an English word: never read as "lift"
])
def test_a_misspelt_word_is_refused_with_the_word_it_is_close_to(question, words):
    assert words in refusal(question)


@pytest.mark.parametrize("question,word", [
    ("Would pouring from the side have helped?", "held"),
    ("pour from the side differently, does it spill", "different"),
    ("pour from the side, were the guests pleased", "please"),
])
def test_an_english_word_is_not_offered_as_a_slip_for_another(question, word):
    # the word is refused as not placed, but it is spelt right: no "did you mean"
    said = refusal(question)
    assert "could not place" in said and f"'{word}'" not in said


@pytest.mark.parametrize("question,scene,said", [
    ("pour from the side, tilded steeply", ["pour_steeply_tilted", "pour_to_side"],
     "tilded: read as tilted"),
    ("pour a havy liquid from the side", ["heavy_liquid", "pour_to_side"], "havy: read as heavy"),
    ("pour it verry high", ["pour_very_high"], "verry: read as very"),     # not "jerry"
])
def test_a_mistyped_word_near_one_word_is_read_as_it_and_said_back(question, scene, said):
    r = read_question(question)
    assert list(r.scene) == scene and said in r.notes


@pytest.mark.parametrize("question", ["the bowl the the slide jug", "a light bowl vs a heavy bowl, which one is very likely to slide?"])
def test_a_verb_of_an_outcome_is_never_offered_as_a_scene_word_misspelt(question):
    with pytest.raises(UserError) as refused:
        read_question(question)
    assert '"slide"' in str(refused.value) and "'side'" not in str(refused.value)


@pytest.mark.parametrize("question", ["no spills, what tilt should i use", "no drips - what speed should i use"])
def test_an_outcome_not_wanted_said_first_is_not_told_of_a_word(question):
    # "no spills, what tilt": nothing spills, wanted; "no" is not what spills
    r = read_question(question)
    assert list(r.goals) == ["no_spill"] and not any("so that no " in n for n in r.notes)
