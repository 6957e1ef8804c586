"""Who a clause about an outcome is about: whether its subject acts ("do I
tip the cup", "does the arm hit the bowl": what is done, the scene's) or
undergoes what happens, and what staying asks of it ("does the bowl stay
put": the bowl still; "does it stay put": the liquid in the bowl)."""
from __future__ import annotations

import re
from functools import lru_cache

from pantarhei.bridge.reasoning.everyday import Matcher, names
from pantarhei.bridge.reasoning.outcome_verbs import ALL_IN as _ALL_IN
from pantarhei.bridge.reasoning.phases import STILL
from pantarhei.bridge.reasoning.vessels import destinations, in_the_source, liquids

#: Who acts: a clause with one of these in its subject says what is done, not what happens
#: ("do I tip the cup"); the source moving is the scene's too ("does the source move slowly").
_ACTORS = {"i", "we", "you", "robot", "arm", "gripper", "hand", "he", "she", "they"}
#: Verbs of one body striking another over: "knocks the bowl over", "pushes it over".
_STRIKES = re.compile(r"\b(?:knock|push|shov)")
#: What holds the source: it hitting the bowl is the source hitting it ("does the arm hit the bowl").
_HOLDING = {"robot", "arm", "gripper", "hand"}


def staying(names: tuple[str, ...], said: str, subject: list[str], left: bool = False) -> tuple[str, ...]:
    """What staying (`said`: "stay put", "stay there") asks of `subject`:
    the liquid staying put stays in the bowl it entered; the bowl staying
    there stays still; staying inside, no bowl said, asked beside leaving
    the source (`left`: "does it come out of the jar or stay inside"),
    stays in the source; anything else, `names`."""
    if left and names == (*_ALL_IN, "liquid_remains_in_destination") and re.search(r"\b(?:in|inside)$", said.strip()):
        return ("liquid_leaves_source",)
    if not re.match(r"(?:stay|stays|remain|remains|keep|keeps|be|is)\b", said) \
            or not re.search(r"\b(?:put|there|in place|where (?:it|they))\b", said):
        return names
    if names == STILL and liquids().spans(subject):
        return (*_ALL_IN, "liquid_remains_in_destination")
    if names != STILL and re.search(rf"\b(?:{destinations()})\b", " ".join(subject)):
        return STILL
    return names


def acts(subject: list[str], names: tuple[str, ...], m: re.Match | None = None) -> bool:
    """Whether a clause with `subject` says what is done rather than what
    happens, or what happens to something the scene does not hold ("is
    the table wobbly": everyday.txt's context nouns)."""
    actors = (_ACTORS - _HOLDING if names == ("source_clear",) or (names == ("destination_upright",) and m is not None
              and _STRIKES.search(m.group(0))) else _ACTORS)           # what holds the source knocks the bowl over with it
    actors = set() if "no_spill" in names else actors     # "will I spill?": whoever spills, it spills
    head = subject[:subject.index("of")] if "of" in subject else subject     # "the jug of water"
    if names == ("source_clear",) and liquids().spans(head) and not (head and in_the_source(head[-1])):
        return True     # "does the water hit the rim": no source hitting it (but "the gravy boat": a source named)
    if names in (STILL, ("destination_upright",)):      # "will they slide": the bowls
        actors = actors - {"they"}      # ("does the jug tip over": the source, held, neither tips over nor slides)
    held = names in (STILL, ("destination_upright",)) and m is not None and not _STRIKES.search(m.group(0)) and any(
        w == "source" or (in_the_source(w) and not re.search(rf"\binto (?:\w+ )?(?:\w+ )?{w}\b", m.string))
        for w in head if w not in ("of", "the", "a", "an"))     # ("the jug knocks the bowl over": the bowl)
    liquid = liquids().spans(subject)       # ("pancake batter": a liquid's name, not a pancake)
    return bool(actors.intersection(subject)) or held or any(     # ("my cereal bowl": a bowl's name, not cereal)
        not any(a <= s and e <= b for a, b in liquid) and not (e < len(subject) and _bowl_word().match(subject[e]))
        for s, e in around().spans(subject))


@lru_cache(maxsize=None)
def _bowl_word() -> re.Pattern:
    """A word that names the destination ("bowl", "dish")."""
    return re.compile(rf"(?:{destinations()})\b")


@lru_cache(maxsize=None)
def around() -> Matcher:
    """The context nouns of the everyday word list: what is around a pour."""
    return Matcher(names("context"))
