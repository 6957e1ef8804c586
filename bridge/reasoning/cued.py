"""A pattern of phrases compiled only when a text first holds one of its
cues: a literal every match must contain. The reader holds some two
hundred such patterns (words.py), and a question names a few of the
things they read; compiling them all cost each `ask` a tenth of a
second. `search` finds what the compiled pattern would, and None where
no cue is in the text.

A phrase is words, each read with its inflections ("move" is move,
moves, moved, moving), a part in brackets optional ("[the] bowl"), its
alternatives split by "|"; or a regular expression after "re:" (no cue:
always tried), or after "re(cue|cue):", cued by the literals given, one of
which every match must contain."""
from __future__ import annotations

import re
from functools import cached_property
from typing import Sequence


#: Words read as written, without inflections.
_FUNCTION_WORDS = {"a", "an", "the", "it", "of", "to", "in", "at", "on", "by", "from", "into",
                   "over", "with", "and", "up", "down", "way"}
#: A phrase's elements: an optional part in brackets, or a word.
_ELEMENT = re.compile(r"\[[^\]]*\]|\S+")


class Cued:
    """`source`, a regular expression, with `cues` (None: no cue is known,
    the pattern is always tried)."""

    def __init__(self, source: str, cues: Sequence[str] | None) -> None:
        self.source = source
        self.cues = None if cues is None else tuple(cues)

    @cached_property
    def pattern(self) -> re.Pattern:
        return re.compile(self.source)

    def cued(self, text: str) -> bool:
        """Whether `text` holds a cue (a match is possible)."""
        return self.cues is None or any(c in text for c in self.cues)

    def search(self, text: str) -> re.Match | None:
        return self.pattern.search(text) if self.cued(text) else None

    @classmethod
    def of(cls, phrases: Sequence[str]) -> Cued:
        """The phrases as one pattern, cued by each one's first word that
        is not optional (less what its inflections change)."""
        cues = [_cues(p) for p in phrases]
        return cls("|".join(f"(?:{_pattern(p)})" for p in phrases),
                   None if None in cues else [c for each in cues for c in each])


def _base(w: str) -> str:
    """What every inflection of a word keeps: move for moving, put."""
    return w if w in _FUNCTION_WORDS or not w.endswith("e") else w[:-1]


def _word(w: str) -> str:
    """A word and its inflections: move, moves, moved, moving; put, putting."""
    if w in _FUNCTION_WORDS:
        return re.escape(w)
    return rf"{re.escape(_base(w))}(?:{re.escape(w[-1])}?(?:e|es|ed|ing|s|d)?)?"


#: A regular expression with its cues: "re(thick|stick):...".
_CUED_RE = re.compile(r"re\(([^)]*)\):")


def _cues(phrase: str) -> list[str] | None:
    """The cues given ("re(a|b):"), or the base of a phrase's first word
    not optional; None for "re:" or all optional."""
    given = _CUED_RE.match(phrase)
    if given:
        return given.group(1).split("|")
    if phrase.startswith("re:"):
        return None
    cue = next((_base(e) for e in _ELEMENT.findall(phrase) if not e.startswith("[")), None)
    return None if cue is None else [cue]


def _pattern(phrase: str) -> str:
    given = _CUED_RE.match(phrase)
    if given:
        return phrase[given.end():]
    if phrase.startswith("re:"):
        return phrase[3:]
    parts = []
    for element in _ELEMENT.findall(phrase):
        if element.startswith("["):
            alternatives = "|".join(" ".join(_word(w) for w in alt.split())
                                    for alt in element[1:-1].split("|"))
            parts.append(rf"(?:(?:{alternatives}) )?")
        else:
            parts.append(_word(element) + " ")
    return r"\b" + "".join(parts)[:-1] + r"\b"
