"""Containers and liquids the reader has no name for, each read as one.

A container: a word it does not
know, said where only a container can stand ("pour from a growler", "into
the katori", "out of the carboy", "a full demijohn of wine"), is read as
"container" (a bowl: poured from, where it is, the source), and `ask`
says so ("growler: read as a container"). A word the reader knows, or one
of them mistyped ("from the sde"), keeps its reading, and a word said
elsewhere is refused as before.

A liquid: words the reader does not know, left unread, said where only
the liquid poured can stand: after a verb of pouring ("pour the merlot
from the carafe", "pouring chilled gazpacho into the bowl"), or after a
container and "of" ("a jug of cider"), ended by a preposition, a stop or
the end, the last of them a noun WordNet (wordnet.py) says is a liquid, a
beverage, a soup or a sauce. They are read as the liquid poured, an
ordinary one, and `ask` says so, with the kind WordNet gives ("merlot: a
red wine"). A word WordNet does not know as a liquid ("pour the sand",
"pour nutella") is refused as before: the reader does not guess what a
name it does not know is; a liquid the reader knows, or a word of the
vocabulary ("pour slowly"), keeps its reading."""
from __future__ import annotations

import re
from functools import lru_cache

from pantarhei.bridge.reasoning.everyday import names
from pantarhei.bridge.reasoning.spelling import corrected, english, unknown_to_reader
from pantarhei.bridge.reasoning.suggestions import misspelt
from pantarhei.bridge.reasoning.wordnet import kind_named

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
    said = sorted({"liquid", "water", *names("liquid")}, key=lambda w: (-len(w), w))
    return re.compile(_OF.replace("{liquid}", "|".join(map(re.escape, said))))


#: Words that may stand between a verb of pouring, or a container's "of", and the liquid.
_DETERMINERS = frozenset(("the", "a", "an", "my", "our", "your", "his", "her", "their", "this", "that", "some", "hedg",
                          "som"))
#: What may follow the liquid's name: a preposition of the pour, a stop, "and".
_AFTER = frozenset(("from", "into", "out", "in", "onto", "over", "off", "and", "at", "with", "to", "through",
                    ",", ".", "?", "!", ";", ":", "bowl"))
#: WordNet's kinds of a liquid poured: a noun of one of them names one.
_LIQUIDS = frozenset(("liquid", "fluid", "beverage", "soup", "sauce", "broth"))
#: What is said back of a liquid read so, after the kind WordNet gives.
LIQUID_SAID = "read as the liquid poured, an ordinary one (say \"sticky\" or \"heavy\" if it is)"


def liquids_unnamed(tokens, taken: set[int], known: frozenset[str]) -> tuple[set[int], tuple[str, ...]]:
    """The positions of `tokens` (wording.Token) that name a liquid the
    reader does not know (the module's docstring), none of them in
    `taken` (the positions read) or in `known` (the reader's words), and
    what is said back of each."""
    def free(i: int) -> bool:
        t = tokens[i]
        return (i not in taken and t.word not in known and re.fullmatch(r"[a-z]{3,}", t.raw) is not None
                and t.raw not in _PLACES and t.raw not in _AMOUNTS)

    found: set[int] = set()
    said: list[str] = []
    i = 0
    while i < len(tokens):
        if not free(i):
            i += 1
            continue
        end = i
        while end + 1 < len(tokens) and free(end + 1):
            end += 1
        before = i          # back over a determiner and words read of the liquid ("the thick ...")
        while before > 0 and i - before < 3 and tokens[before - 1].word not in ("pour", "of") and (
                tokens[before - 1].word in _DETERMINERS or before - 1 in taken):
            before -= 1
        verb = before > 0 and tokens[before - 1].word == "pour"
        of = before > 1 and tokens[before - 1].word == "of" and tokens[before - 2].word in ("bowl", "full")
        closed = end + 1 == len(tokens) or tokens[end + 1].word in _AFTER or tokens[end + 1].raw in _AFTER
        head = tokens[end].raw
        kind = ((kind_named(head, _LIQUIDS) or head.endswith("s") and kind_named(head[:-1], _LIQUIDS))
                if (verb and closed) or of else None)
        if kind:
            found.update(range(i, end + 1))
            article = "an" if kind[0] in "aeiou" else "a"
            said.append(f"{' '.join(t.raw for t in tokens[i:end + 1])}: {article} {kind} (WordNet): {LIQUID_SAID}")
        i = end + 1
    return found, tuple(said)


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
