"""Containers the reader has no name for, read as one: a word it does not
know, said where only a container can stand ("pour from a growler", "into
the katori", "out of the carboy", "a full demijohn of wine"), is read as
"container" (a bowl: poured from, where it is, the source), and `ask`
says so ("growler: read as a container"). A word the reader knows, or one
of them mistyped ("from the sde"), keeps its reading, and a word said
elsewhere is refused as before."""
from __future__ import annotations

import re
from functools import lru_cache

from pantarhei.bridge.reasoning.everyday import names
from pantarhei.bridge.reasoning.spelling import corrected, english, unknown_to_reader
from pantarhei.bridge.reasoning.suggestions import misspelt

#: Where only a container stands after an article: poured from it, into it, out of it (the
#: last word of its noun: "from a hevy jug" names the jug).
_SLOT = re.compile(r"\b(from|into|out of|outside|inside|outside of|inside of) (the|a|an|my|your|our|this|that|his|her)"
                   r" ([a-z]{3,})(?= *(?:[,;:.!?]|$| (?:held|and|or|but|with|into|onto|to|over|if|when|while|then|from"
                   r"|does|do|will|would|is|was|at|in|so|without|tilted|tipped)\b))")
#: A container of a liquid: "a full demijohn of wine", "a carboy of wort".
_OF = r"\b(a|an|the|my|your|one) (?:(full|half full|heavy|light) )?([a-z]{3,}) of (?=(?:the |some )?(?:{liquid})\b)"


#: Where, or when, said after "from": no container ("pour from the front", "from the beginning").
_PLACES = frozenset(("front", "back", "rear", "top", "bottom", "middle", "beginning", "outset", "start", "end",
                     "left", "right", "north", "south", "east", "west", "outside", "inside", "distance",
                     "ceiling", "shelf", "window", "door", "wall", "corner", "puddle", "sink", "air"))


#: How much, said before "of" a liquid: an amount, no container ("a bunch of water").
_AMOUNTS = frozenset(("bunch", "lot", "lots", "load", "loads", "ton", "tons", "heap", "heaps", "pile", "piles",
                      "couple", "few", "bit", "dash", "drop", "drops", "splash", "glug", "glugs", "ounce", "ounces",
                      "pint", "pints", "quart", "gallon", "gallons", "liter", "litre", "liters", "litres", "amount",
                      "quantity", "volume", "portion", "serving", "measure", "shot", "sip", "drizzle", "trickle"))


@lru_cache(maxsize=None)
def _of() -> re.Pattern:
    said = sorted({"liquid", "water", *names("liquid")}, key=len, reverse=True)
    return re.compile(_OF.replace("{liquid}", "|".join(map(re.escape, said))))


def _mistyped(word: str) -> bool:
    """Whether `word` is a word the reader knows, mistyped ("sde": side): no
    English word, and one spelling.py reads as another."""
    return not english(word) and (corrected(word)[0] != word or bool(misspelt([word])))


def containers_named(text: str) -> tuple[str, tuple[str, ...]]:
    """`text` (normalised) with each container the reader has no name for
    read as "container", and what is said back of each."""
    said: dict[str, None] = {}

    def bowl(m: re.Match, at: int) -> str:
        word = m.group(at)
        if not unknown_to_reader(word) or word in _PLACES or word in _AMOUNTS or _mistyped(word):
            return m.group(0)
        said.setdefault(f"{word}: read as a container")
        return m.group(0)[:m.start(at) - m.start()] + "container" + m.group(0)[m.end(at) - m.start():]

    text = _SLOT.sub(lambda m: bowl(m, 3), text)
    text = _of().sub(lambda m: bowl(m, 3), text) if " of " in text else text     # (compiled only then)
    return text, tuple(said)
