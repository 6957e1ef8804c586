"""What strikes the bowl's rim, said before a question is read (wording.normalising): the lip
(rim, edge) of the source, which is its spout ("does the jug's lip hit the bowl": the source's contact,
asked), and the liquid, whose striking is no outcome ("the stream hit the edge of the bowl and
jumped out": what it did next is read)."""
from __future__ import annotations

import re
from functools import lru_cache

from pantarhei.bridge.reasoning.everyday import alternation, names

#: Containers that are the destination when a lip is named: the lip of one is its rim.
_DESTINATIONS = frozenset(("bowl", "dish", "basin", "tub", "bucket", "pail", "vat", "container", "destination", "receptacle"))
#: A lip said after these is a place ("over the lip of the cup", "drip off the lip"): not the source's part.
_AT_A_PLACE = "".join(f"(?<!{w} )" for w in ("over", "past", "above", "near", "at", "to", "onto", "off", "from", "around", "along"))


def lip_of_source(text: str, said: dict[str, None]) -> str:
    """`text` with the lip of the source said as its spout ("the jug lip", "the lip of the flask"
    it is poured from): a part of the source, not the bowl's rim. Only a lip named as what
    strikes the bowl is ("does the jug's lip hit the bowl"): never one said as a place
    (_AT_A_PLACE), nor one said to rest on the bowl (a touch in the scene, which no proposition holds)."""
    if not re.search(r"\b(?:lip|rim|edge)\b", text):
        return text
    for pattern in _lips():
        text = pattern.sub(lambda m: said.setdefault(f"{m.group('part')}: read as spout, a part of the source")
                           or f"{m.group(1)}spout", text)
    return text


@lru_cache(maxsize=None)
def _lips() -> tuple[re.Pattern, ...]:
    """The lip of a source (every container of everyday.txt but the destination's words: what strikes
    the bowl is not it) striking the bowl: "the jug lip hit", "the lip of the flask touched"."""
    sources = alternation(w for w in names("bowl") if w not in _DESTINATIONS)
    strikes = r"(?: \w+){0,2}? (?:touch|hit|bump|knock|bang|clip|strike|struck|collid|scrap|graz|clink|nudg|tap|make contact)"
    # (a note's, with no article: "pitcher lip hit the bowl")
    return (re.compile(rf"{_AT_A_PLACE}\b((?:(?:the|its|a|my|your) |(?:^|(?<=[.,;:!?] )))(?:{sources}) )(?P<part>lip|rim|edge)\b"
                       rf"(?={strikes})"),
            re.compile(rf"{_AT_A_PLACE}\b((?:the|its|a) )(?P<part>lip|rim|edge)(?= of (?:the |a |an |my |this |that )?(?:{sources}){strikes})"))


def stream_striking(text: str, said: dict[str, None]) -> str:
    """`text` without the liquid's striking the bowl's rim when what it did next is told ("the stream
    hit the edge of the bowl and jumped out": it jumped out): the liquid striking the bowl is no outcome
    (the source's striking it is, and is read), what it does next is."""
    if not re.search(r"\b(?:hit|hits|hitting|struck|strikes|striking)\b", text):
        return text
    m = _striking().search(text)
    if m is None:
        return text
    said.setdefault(f"{m.group('hit').strip(' ,')}: ignored: the liquid striking the bowl is no outcome (what it does next is read)")
    return text[:m.start("hit")] + text[m.end("hit"):]


@lru_cache(maxsize=None)
def _striking() -> re.Pattern:
    """The liquid (its stream, or a liquid by its name) striking the bowl's rim, then what it did."""
    liquids = alternation(["stream", "jet", "flow", "pour", "liquid", "drop", *names("liquid")])
    return re.compile(rf"\b(?:{liquids}) (?P<hit>(?:hit|hits|hitting|struck|strikes|striking) (?:the |its )?(?:bowl |destination )?"
                      rf"(?:rim|edge|side|lip)(?: of (?:the |a |my )?(?:bowl|destination))?(?: and then| then| and| ,)+ )(?=[a-z])")
