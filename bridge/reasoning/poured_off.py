"""A pour said poured off, a rewrite of words.py's, applied before the
everyday word list (which would leave "off" unread).

Poured off ("tipping brine off into a steel bowl", "pour off a cocktail
shaker into a coupe", "pouring honey off the bucket into a bowl"): pouring
(PouredOff); "off" before what it is poured off is "from" it, and before
where it goes, or last, is shown as ignored. Lifted or eased off, or off
the side of the jar or the bowl, are no pour off, and stay as they are read.
"""
from __future__ import annotations

from pantarhei.bridge.reasoning.tipping_speed import ENDS

#: The ends of a clause, and the words that join another to it.
_JOINTS = ENDS | {"and", "then", "but", "or", "so", "when", "if", "because", "while"}

#: Verbs that pour a thing off, and the words between: what is poured ("tipping brine off"), no place.
_POURING = frozenset(f"{v}{e}" for v in ("pour", "rack", "decant", "drain", "strain") for e in ("", "s", "ed", "ing")) | {
    "tip", "tips", "tipped", "tipping"}
_NOT_POURED = _JOINTS | {"in", "into", "from", "over", "onto", "on", "at", "to", "with", "out", "it", "them", "away", "back",
                         "up", "down", "far", "way", "well", "just", "right", "straight", "too", "very", "really"}
#: After "off": what it is poured from ("off the bucket"), or where it goes, or nothing more.
_FROM = frozenset(("the", "a", "an", "my", "our", "his", "her", "their", "this", "that", "its"))
_ON = frozenset(("into", "in", "onto")) | ENDS
#: A part of a container, which "off the" names as where the liquid runs, not what it is poured from ("off the side").
_PART = frozenset(("side", "sides", "edge", "edges", "lip", "rim", "top", "spout", "end", "bottom", "outside"))


class PouredOff:
    """The rewrite of "off" said of pouring (see the module's docstring)."""

    def spans(self, words: list[str]) -> list[tuple[int, int, tuple[str, ...]]]:
        out = []
        for i, w in enumerate(words):
            if w != "off" or not _poured(words, i):
                continue
            after = words[i + 1] if i + 1 < len(words) else "."
            if after in _FROM and (words[i + 2] if i + 2 < len(words) else "") not in _PART:
                out.append((i, i + 1, ("from",)))
            elif after in _ON:
                out.append((i, i + 1, ("hedge",)))
        return out


def _poured(words: list[str], at: int) -> bool:
    """Whether a verb of pouring comes before `at`, with no more than three words of what it pours between."""
    for k in range(at - 1, max(at - 5, -1), -1):
        if words[k] in _POURING:
            return True
        if words[k] in _NOT_POURED:
            return False
    return False


POURED_OFF_SAID = "read as pouring from it: pouring off is pouring"
