"""The everyday word list (bridge/reasoning/everyday.txt), word by word:
each phrase of it, said in a question, is read as its section says (a
liquid's name as the liquid it is, a container as a bowl, a material or
what is around the pour said back as ignored with the reason), or refused
naming why; and its plurals with it."""
from __future__ import annotations

import pytest

from pantarhei.bridge.errors import UserError
from pantarhei.bridge.reasoning.everyday import Matcher, forms, sections
from pantarhei.bridge.reasoning.reading import read_question

#: The kinds of section the reader knows what to do with.
KINDS = {"hedge", "material", "bowl", "bowl poured from", "sticky liquid", "heavy liquid", "liquid", "context", "part",
         "unclear", "a bit", "little", "much", "full", "slightly tilted", "steeply tilted", "low", "high",
         "to the side", "very", "start slightly tilted", "into the middle", "right over", "into", "from", "upright",
         "tilted", "tilted halfway", "slowly", "fast", "slippery destination", "pour", "poured", "near the rim"}


def _phrases(*kinds: str) -> list[tuple[str, str]]:
    return [(p, s.said_back) for s in sections() if s.words in kinds for p in s.phrases]


def test_every_section_is_of_a_kind_the_reader_knows_and_says_why_when_it_ignores():
    assert {s.words for s in sections()} <= KINDS
    for s in sections():
        assert s.phrases, s.words
        if s.words in ("material", "context", "part", "unclear"):
            assert s.said_back, s.words            # ignored or refused: the reason is said


def _noted(question: str, phrase: str, said: str) -> bool:
    return f"{phrase}: {said}" in read_question(question).notes


@pytest.mark.parametrize("phrase,said", _phrases("liquid", "sticky liquid", "heavy liquid"))
def test_a_liquid_by_its_name_is_read_as_the_liquid_it_is(phrase, said):
    kind = next(s.words for s in sections() if phrase in s.phrases)
    scene = {"liquid": [], "sticky liquid": ["sticky_liquid"], "heavy liquid": ["heavy_liquid"]}[kind]
    question = f"pour {phrase} from the side"
    assert list(read_question(question).scene) == sorted(["pour_to_side", *scene])
    assert not said or _noted(question, phrase, said)


@pytest.mark.parametrize("phrase,said", _phrases("slippery destination"))
def test_a_bowl_standing_on_ice_is_slippery(phrase, said):
    question = f"pour from the side, {phrase}"
    assert list(read_question(question).scene) == ["pour_to_side", "slippery_destination"]
    assert _noted(question, phrase, said)


@pytest.mark.parametrize("phrase,said", _phrases("pour"))
def test_a_pour_typed_as_it_sounds_is_a_pour(phrase, said):
    question = f"if {phrase.removeprefix('i ').removeprefix('we ')} the milk from high up, does it splash"
    assert list(read_question(question).scene) == ["pour_high"] and read_question(question).asked == ("no_spill",)
    assert _noted(f"does it splash if {phrase} from high up", phrase, said)


@pytest.mark.parametrize("phrase,said", _phrases("poured"))
def test_a_pour_told_typed_as_it_sounds_is_a_pour_told(phrase, said):
    question = f"{phrase} the milk from high up and it splashed, why"
    assert list(read_question(question).scene) == ["pour_high"] and read_question(question).asked == ("no_spill",)
    assert _noted(question, phrase, said)


@pytest.mark.parametrize("phrase,said", _phrases("bowl", "bowl poured from"))
def test_a_container_is_a_bowl_the_source_when_poured_from(phrase, said):
    assert list(read_question(f"pour from a heavy {phrase}").scene) == ["heavy_source"]
    assert list(read_question(f"pour into a light {phrase}").scene) == ["light_destination"]


@pytest.mark.parametrize("phrase,said", _phrases("bowl", "bowl poured from"))
def test_a_container_said_alone_is_the_bowl_people_use_it_as(phrase, said):
    """A jug, a bottle, a kettle is poured from; a cup, a glass, a pot poured into."""
    kind = next(s.words for s in sections() if phrase in s.phrases)
    body = "source" if kind == "bowl poured from" else "destination"
    assert list(read_question(f"what if the {phrase} is heavy?").scene) == [f"heavy_{body}"]


@pytest.mark.parametrize("phrase,said", _phrases("material"))
def test_a_material_or_colour_is_said_back_as_ignored_and_takes_nothing_down(phrase, said):
    question = (f"pour into a light bowl {phrase}" if phrase.startswith("made ")
                else f"pour into a light {phrase} bowl")
    assert list(read_question(question).scene) == ["light_destination"]
    assert said.startswith("ignored") and _noted(question, phrase, said)


@pytest.mark.parametrize("phrase,said", _phrases("context"))
def test_what_is_around_the_pour_is_said_back_as_ignored(phrase, said):
    question = f"pour from the side into a bowl by the {phrase}"
    assert list(read_question(question).scene) == ["pour_to_side"]
    assert said.startswith("ignored") and _noted(question, phrase, said)


@pytest.mark.parametrize("phrase,said", _phrases("part"))
def test_a_part_of_a_bowl_is_said_back_as_ignored_and_the_bowl_read(phrase, said):
    of = phrase.endswith(" of")
    question = f"pour from the {phrase} a heavy jug" if of else f"pour from the {phrase}"
    assert list(read_question(question).scene) == (["heavy_source"] if of else [])
    assert _noted(question, phrase, said)


@pytest.mark.parametrize("phrase,said", _phrases("hedge"))
def test_a_hedge_is_read_as_nothing(phrase, said):
    assert list(read_question(f"{phrase}, pour from the side").scene) == ["pour_to_side"]


@pytest.mark.parametrize("phrase,said", _phrases("unclear"))
def test_a_word_the_vocabulary_cannot_say_is_refused_naming_why(phrase, said):
    with pytest.raises(UserError) as e:
        read_question(f"pour from the side, {phrase}")
    assert f'"{phrase}"' in str(e.value) and said in str(e.value) and "\n" not in str(e.value)


@pytest.mark.parametrize("phrase,template,props", [
    *((p, "tilt the jug {}", ["pour_slightly_tilted"]) for p, _ in _phrases("a bit")),
    *((p, "pour with the source held {}", ["pour_slightly_tilted"])
      for p, _ in _phrases("slightly tilted")),
    *((p, "pour {} milk" if p.endswith(" of") else "pour from a {} jug", ["little_liquid"])
      for p, _ in _phrases("little")),
    *((p, "pour {} milk", ["much_liquid"]) for p, _ in _phrases("much")),
    *((p, "pour from a jug {}", ["very_much_liquid"]) for p, _ in _phrases("full")),
    *((p, "pour from {}", ["pour_low"]) for p, _ in _phrases("low")),
    *((p, "pour from {}", ["pour_high"]) for p, _ in _phrases("high")),
    *((p, "pour it {} of the bowl", ["pour_centred"]) for p, _ in _phrases("into the middle")),
    *((p, "pour with the jug {}", ["pour_near_rim"]) for p, _ in _phrases("near the rim")),
    *((p, "pour with the source held {}", ["pour_upright"]) for p, _ in _phrases("upright")),
    *((p, "pour {} the middle of the bowl", ["pour_centred"]) for p, _ in _phrases("right over")),
    *((p, "tip the jug {} the bowl from high", ["pour_high"]) for p, _ in _phrases("into")),
    *((p, "pour {} jug into the bowl from high" if p.endswith(" the") else "pour {} the jug into the bowl from high", ["pour_high"])
      for p, _ in _phrases("from")),
])
def test_a_degree_phrase_is_read_as_the_degree_it_says(phrase, template, props):
    assert list(read_question(template.format(phrase)).scene) == props


def test_a_phrase_matches_its_plurals_and_nothing_longer():
    assert forms("jug") == (("jug",), ("jugs",), ("juges",))
    assert ("glasses",) in forms("glass") and ("parties",) in forms("party")
    m = Matcher(["gravy boat", "jug"], before=["milk"])
    words = "pour the milk jugs into two gravy boats not a jugged boat".split()
    assert [words[i:j] for i, j in m.spans(words)] == [["milk", "jugs"], ["gravy", "boats"]]


def test_glass_is_a_material_only_before_a_container():
    m = Matcher(["plastic"], glass_before=["jug"])
    words = "a glass jug a glass a plastic glass".split()
    assert [words[i:j] for i, j in m.spans(words)] == [["glass"], ["plastic"]]
