"""How full the source is, said as a share of full: "half full", "a quarter
full", "three quarters full", "filled to 90 percent" ("nearly full" says
no share: everyday.txt refuses it). A full source is what the
vocabulary's fullest amount holds (very_much_liquid, 150 to 200
particles); the share of it said spans a range of particles, read as the
amount of liquid whose range holds the most of it (half: 75 to 100
particles, much liquid), said back (SAID). A rewrite of words.py's kind
(see wording.py): `spans(words)` gives each phrase and the words it is
read as.
"""
from __future__ import annotations

import re
from functools import lru_cache

from pantarhei.theory.lexicon import load_vocabulary

#: Shares of full said in words, by their words as tokens.
SHARES = {("half",): 0.5, ("a", "quarter"): 0.25, ("quarter",): 0.25, ("one", "quarter"): 0.25,
          ("a", "third"): 1 / 3, ("third",): 1 / 3, ("one", "third"): 1 / 3, ("two", "thirds"): 2 / 3,
          ("three", "quarters"): 0.75, ("halfway",): 0.5, ("half", "way"): 0.5}
#: Words that say full after a share ("half full", "a quarter filled").
_FULL = {"full", "filled"}
_NUMBER = re.compile(r"\d+(?:\.\d+)?")
#: What is said back of a share read.
SAID = "read as the amount of liquid whose range holds the most of that share of a full source"


#: The word that says each amount of liquid, from the least to the most, of the body it is said
#: of ("the jug is much" is read as the jug's liquid; "the bowl is half full" is refused: the
#: destination is empty before the pour).
_WORDS = ("little", "some", "much", "full")


@lru_cache(maxsize=None)
def _amounts() -> tuple[tuple[str, float, float], ...]:
    """(word, low, high) of each amount of liquid, from the least."""
    vocab = load_vocabulary()
    names = vocab.dimensions["liquid_amount"].values
    return tuple((word, vocab.propositions[n].model.low, vocab.propositions[n].model.high)
                 for word, n in zip(_WORDS, names, strict=True))


def amount(share: float) -> str:
    """The word of the amount of liquid whose range holds the most of
    `share` of a full source."""
    full = _amounts()[-1]
    low, high = share * full[1], share * full[2]
    return max(_amounts(), key=lambda a: (min(high, a[2]) - max(low, a[1]), -abs(a[1] - low)))[0]


class Fullness:
    """The rewrite (see the module's docstring)."""

    def spans(self, words: list[str]) -> list[tuple[int, int, tuple[str, ...]]]:
        out: list[tuple[int, int, tuple[str, ...]]] = []
        i = 0
        while i < len(words):
            share, end = _share(words, i)
            if share is not None:
                out.append((i, end, tuple(amount(share).split())))
            i = end if share is not None else i + 1
        return out


def _share(words: list[str], i: int) -> tuple[float | None, int]:
    """The share of full said from `i` on, and where its phrase ends."""
    for said, share in SHARES.items():
        k = i + len(said)
        if tuple(words[i:k]) == said and k < len(words) and words[k] in _FULL:
            return share, k + 1
    # "90 percent full", "filled to 90 percent"
    if i + 2 < len(words) and _NUMBER.fullmatch(words[i]) and words[i + 1] in ("percent", "%") \
            and words[i + 2] in _FULL and 0 < float(words[i]) <= 100:
        return float(words[i]) / 100, i + 3
    if i + 3 < len(words) and words[i] in _FULL and words[i + 1] == "to" and _NUMBER.fullmatch(words[i + 2]) \
            and words[i + 3] in ("percent", "%") and 0 < float(words[i + 2]) <= 100:
        return float(words[i + 2]) / 100, i + 4
    return None, i
