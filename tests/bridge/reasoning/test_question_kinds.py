"""Questions as people type them, by kind (question_kinds.tsv): each read
as meant (its scene, the expectations it asks, the goals it wants) or, where
the vocabulary cannot say it, refused in one line naming what could not be
read and what would be; and, whatever the vocabulary's ranges, a range of
numbers read as the proposition that holds all of it, or three quarters of
it, or refused."""
from __future__ import annotations

from pathlib import Path

import pytest

from pantarhei.bridge.errors import UserError
from pantarhei.bridge.reasoning.reading import read_question, understand
from pantarhei.bridge.reasoning.dropped import dropped_words
from pantarhei.theory.lexicon import load_vocabulary

DATA = Path(__file__).with_name("question_kinds.tsv")


def _rows() -> list[tuple[str, str, str | None, str]]:
    """(kind, question, meaning or None where it must be refused, what the refusal holds)."""
    rows, kind = [], ""
    for line in DATA.read_text(encoding="utf-8").splitlines():
        if line.startswith("## "):
            kind = line[3:]
        elif line.strip() and not line.startswith("#"):
            question, meant, *says = line.split("\t")
            rows.append((kind, question, None if meant == "cannot" else meant, "".join(says)))
    return rows


ROWS = _rows()


def _names(text: str) -> list[str]:
    return sorted(n for n in text.split(",") if n)


def test_every_kind_of_wording_is_in_the_corpus():
    kinds = {k for k, *_ in ROWS}
    assert {"negation and contrast", "comparatives, to a reference point or to none", "amounts",
            "speeds", "outcomes asked", "lengths by hand", "heights said loosely",
            "states of the bowls", "verbs of tilting", "stages said with phrasal verbs", "typos",
            "would, could, should, what if", "outcome words", "units"} <= kinds
    assert all(says for _, _, meant, says in ROWS if meant is None)


@pytest.mark.parametrize("question,meant", [(q, m) for _, q, m, _ in ROWS if m is not None])
def test_read_as_meant(question, meant):
    parts = dict(part.split("=", 1) for part in meant.split(";"))
    r = read_question(question)
    assert list(r.scene) in [_names(s) for s in parts["scene"].split("|")]
    assert sorted(r.asked) == _names(parts.get("asked", ""))
    assert sorted(r.goals) == _names(parts.get("goals", ""))


@pytest.mark.parametrize("question", [q for _, q, m, _ in ROWS if m is not None])
def test_no_word_is_dropped_silently(question):
    """Each word is read, heard as what is asked, said back, shown as
    ignored, or a word of the question's frame."""
    assert dropped_words(question, read_question(question)) == []


@pytest.mark.parametrize("question,said", [
    ("im tilting it halfway, will it spill", "im: read as I'm"),
    ("the jug isnt heavy, is it", "isnt: read as isn't"),
    ("theyll pour from the side, does it splash", "theyll: read as they'll"),
    ("will teh cup tip over if i pour high", "teh: read as the"),
    ("pour from high adn tilt it halfway", "adn: read as and"),
    ("wat if u tilt it halfway", "u: read as you"),
    ("y does a lite bowl slide", "lite: read as light"),
    ("y does a lite bowl slide", "y: read as why"),
    ("tip it halfway w/o touching the bowl", "w/o: read as without"),
    ("pour w/ a heavy jug", "w/: read as with"),
    ("will it drip if its tilted steeply", "its: read as it's"),
    ("can i tilt it halfway without spilin", "spilin: read as spilling"),
    ("pour frm high lol", "frm: read as from"),
    ("does the bottle lip hit the bowl?", "lip: read as spout, a part of the source"),
    ("does the rest stay in the jug?", "the rest: read as some"),
    ("tilted the beaker way too far and it splashed. why", 'tilted the beaker way too far: read as steeply tilted: tipped far, as a pour told says it (say "upside down" for further)'),
    ("pour frm high lol", "lol: ignored: laughter as chat types it says nothing of the pour"),
    ("pour alot of milk", "alot: read as a lot"),
    ("with a heavy bowl instead of a light one", "one: read as bowl"),
    ("hw do i pour without making a mess ngl i always spill", "hw: read as how"),
    ("hw do i pour without making a mess ngl i always spill",
     "always spill: ignored: what always happens to the one asking is told of earlier pours; the answer is for the one asked"),
    ("My soup is pretty thick, does that mean it will come out of the saucepan slower and land more in the bowl?",
     "will come out of the saucepan slower: not asked: how fast the liquid flows is no expectation the vocabulary checks"),
    ("I'm a line cook. Pouring water from a jug into a bowl, does it spill?",
     "i am a line cook: read as nothing: who asks says nothing of the pour"),
    ("If I decant the merlot from the carafe into the bowl, does any of it spill?",
     'merlot: a red wine (WordNet): read as the liquid poured, an ordinary one (say "sticky" or "heavy" if it is)'),
    ("is it better to pour near the middle of the bowl or near the edge so it does not go out",
     "vs near the edge: read as nothing: the scene compared with is not read, the answer is for the one said first"),
    ("water vs olive oil, which one spills more",
     "water vs olive oil: both read as an ordinary liquid: the vocabulary does not tell them apart, so the answer is the same for both"),
])
def test_a_word_read_as_another_is_said_back(question, said):
    """Whatever the reader writes otherwise than typed (a contraction typed
    without its apostrophe, a slip of the keys) is said back."""
    assert said in read_question(question).notes


@pytest.mark.parametrize("question,says", [(q, s) for _, q, m, s in ROWS if m is None])
def test_refused_in_one_line_naming_what_would_be_read(question, says):
    with pytest.raises(UserError) as e:
        read_question(question)
    assert says in str(e.value) and "\n" not in str(e.value)


def _ranges(param: str) -> list[tuple[float, float, str]]:
    return sorted((p.model.low, p.model.high, n) for n, p in load_vocabulary().propositions.items()
                  if p.model.kind == "uniform" and p.model.param == param)


@pytest.mark.parametrize("template,param,scale", [
    ("pour {} cm above the rim", "pour_z", 10),
    ("tilt it {} degrees", "pour_pitch", 1),
    ("move in over {} seconds", "approach_duration", 1000),
    ("between {} mm above the rim", "pour_z", 1),
])
def test_a_range_is_read_as_the_proposition_that_holds_all_of_it(template, param, scale):
    """Whatever the vocabulary's ranges: a range inside one proposition's is
    that proposition; one across two is refused naming them, unless three
    quarters of it lie in one."""
    join = " and " if template.startswith("between") else " to "
    ranges = _ranges(param)
    for low, high, name in ranges:
        inner = (low + (high - low) / 4) / scale, (high - (high - low) / 4) / scale
        assert understand(template.format(join.join(f"{v:g}" for v in inner))) == [name]
    for (low_a, high_a, a), (low_b, _, b) in zip(ranges, ranges[1:]):
        across = (high_a - 1) / scale, (low_b + 1) / scale
        with pytest.raises(UserError, match="which no one proposition holds") as e:
            understand(template.format(join.join(f"{v:g}" for v in across)))
        assert a in str(e.value) and b in str(e.value)
        # three quarters of it in one: that one
        mostly = (high_a - 9 * (low_b + 1 - high_a)) / scale, (low_b + 1) / scale
        if mostly[0] * scale >= low_a:
            assert understand(template.format(join.join(f"{v:g}" for v in mostly))) == [a]
