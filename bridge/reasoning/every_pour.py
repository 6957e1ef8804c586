"""What every pour of the vocabulary does already, said as a condition: no one holds the bowl
("if I don't hold the bowl, will it stay put?"), the source is held still while it pours ("if
i dont move the pitcher at all while pouring"), and the bowl is empty before it ("into an empty
bowl", "bowl empty. spill?"; an empty source pours nothing, and is refused). Such a phrase
excludes nothing: it is read as nothing and said back with why, before the question is read
(wording.normalising)."""
from __future__ import annotations

import re

#: (the phrase, why it is read as nothing)
_EVERY_POUR = (
    (re.compile(r"\b(?:not|never|without|nobody|no one) (?:hold\w*|held|steady\w*|grip\w*)(?: on(?: to)?)?"
                r" (?:the|my|a|our) (?:bowl|dish)\b"),
     "no one holds the bowl in any pour: it stands free"),
    (re.compile(r"\b(?:not|never|without) (?:going to |gonna )?(?:mov\w*|shak\w*|jiggl\w*|wav\w*)(?: (?:the|my|a) (?!bowl\b|dish\b)[a-z]+| it| them)"
                r"(?: at all)?(?: (?:while|when|as) (?:pouring|i pour|i am pouring|it pours|it is pouring)\b"
                # (or said before tipping it where it is: "not going to move the jug at all, just tip it in place")
                r"|,? just (?=(?:tip|tilt) it in place\b))"),
     "the source is held still while it pours, in every pour (how it moves in and away is read)"),
    (re.compile(r"(?<!\bfrom )(?<!\bfrom an )(?<!\bfrom the )(?<!\bfrom a )\b(?:(?:near|nearly|almost)[ -])?empty(?= (?:(?!(?:the|a|an|my|your|our|his|her|it|into|out|in)\b)[a-z]+ )?(?:bowl|dish|basin)s?\b)"
                # (a cause asked is left to be refused: "was it because the bowl was empty?")
                r"|(?<!\bbecause the )(?<!\bbecause my )\b(?P<keep>(?:bowl|dish|basin) )(?:is |was |being |still )?"
                r"(?:completely |totally |basically |pretty much )?empty\b(?: and\b)?"),
     "every pour's destination is empty before it"),
    # (said after what else the bowl is: "the bowl is plastic and empty")
    (re.compile(r"\b(?P<keep>(?:bowl|dish|basin) (?:is|was) (?:[a-z]+ ){0,2}?[a-z]+) and (?:completely |totally )?empty\b"),
     "every pour's destination is empty before it"),
)


def as_every_pour(text: str, said: dict[str, None]) -> str:
    """`text` (normalised) without the phrases that say what every pour does (the module's
    docstring), each said back in `said` (the bowl they are said of kept)."""
    def read_as_nothing(m: re.Match, why: str) -> str:
        kept = m.groupdict().get("keep") or ""
        said.setdefault(f"{m.group(0).removeprefix(kept)}: ignored: {why}")
        return f" {kept}"

    for pattern, why in _EVERY_POUR:
        text = pattern.sub(lambda m: read_as_nothing(m, why), text)
    return re.sub(r" {2,}", " ", text)
