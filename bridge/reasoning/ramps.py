"""A tilt moved from one angle to another: "the tilt is ramped from 0 to
135 degrees", "tip it from 0 to 90 degrees". The source starts at the
first and pours at the second (the move into the pouring pose carries the
tilt, so a time said of it, "over 2 seconds", is that move's:
quantities.py). A rewrite of words.py's kind (see wording.py): `spans(words)`
gives each phrase and the words it is read as ("start tilted at 0 degrees ,
pour tilted at 135 degrees"). A range said without a move ("tilted 30 to 40 degrees")
is quantities.py's, read only where one proposition holds all of it.
"""
from __future__ import annotations

import re

from pantarhei.bridge.reasoning.units import UNITS

#: Verbs that move a tilt from one angle to another.
_MOVING = re.compile(r"(?:ramp|increas|rais|sweep|swept|rotat|turn|tilt|tip|chang|var|go|went|mov|bring|brought)"
                     r"\w*")
_DEGREES = {w for w, (measures, _) in UNITS.items() if measures == "angle"}
_NUMBER = re.compile(r"-?\d+(?:\.\d+)?")


class Ramps:
    """The rewrite (see the module's docstring)."""

    def spans(self, words: list[str]) -> list[tuple[int, int, tuple[str, ...]]]:
        out: list[tuple[int, int, tuple[str, ...]]] = []
        for i, w in enumerate(words):
            verb = _verb(words, i) if w == "from" else None
            if verb is None or i + 1 >= len(words) or not _NUMBER.fullmatch(words[i + 1]):
                continue
            first = words[i + 1]
            j = i + 2 + (i + 2 < len(words) and words[i + 2] in _DEGREES)
            if j + 2 < len(words) and words[j] == "to" and _NUMBER.fullmatch(words[j + 1]) \
                    and words[j + 2] in _DEGREES:
                out.append((_said_of(words, verb), j + 3, (
                    "start", "tilted", "at", first, "degrees", ",", "pour", "tilted", "at", words[j + 1], "degrees")))
        return out


def _verb(words: list[str], i: int) -> int | None:
    """Where the verb that moves the tilt stands before the "from" at `i`,
    past "it" or "the <noun>", or None."""
    k = i - 1
    if k >= 2 and words[k - 1] == "the":
        k -= 2
    elif k >= 1 and words[k] in ("it", "them"):
        k -= 1
    return k if k >= 0 and _MOVING.fullmatch(words[k]) else None


def _said_of(words: list[str], verb: int) -> int:
    """Where the phrase of the verb at `verb` begins: at "the tilt is" or
    "the angle gets" before it, read with it."""
    k = verb
    if k >= 1 and words[k - 1] in ("is", "gets", "was", "being"):
        k -= 1
    if k >= 1 and words[k - 1] in ("tilt", "angle", "pitch"):
        k -= 1 + (k >= 2 and words[k - 2] == "the")
    return k if k < verb else verb
