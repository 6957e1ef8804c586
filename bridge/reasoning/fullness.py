"""How full the source is, said as a share of full: "half full", "a quarter
full", "three quarters full", "half cup", "filled to 90 percent" ("nearly full" says
no share: everyday.txt refuses it), or filled to a share ("fills the cup
halfway"). A full source is what the
vocabulary's fullest amount holds (very_much_liquid, 150 to 200
particles); the share of it said spans a range of particles, read as the
amount of liquid whose range holds the most of it (half: 75 to 100
particles, much liquid), said back (SAID). A rewrite of words.py's kind
(see wording.py): `spans(words)` gives each phrase and the words it is
read as. A share said of the bowl ("the bowl was only half full", "a nearly
full bowl"), and how full the bowl gets asked ("how full can my bowl get"),
are refused: every pour's bowl is empty before it.
"""
from __future__ import annotations

import re
from functools import lru_cache

from pantarhei.bridge.errors import UserError
from pantarhei.theory.lexicon import load_vocabulary

#: Shares of full said in words, by their words as tokens.
SHARES = {("half",): 0.5, ("a", "quarter"): 0.25, ("quarter",): 0.25, ("one", "quarter"): 0.25,
          ("a", "third"): 1 / 3, ("third",): 1 / 3, ("one", "third"): 1 / 3, ("two", "thirds"): 2 / 3,
          ("three", "quarters"): 0.75, ("halfway",): 0.5, ("half", "way"): 0.5}
#: Words that say full after a share ("half full", "a quarter filled").
_FULL = {"full", "filled"}
#: Sources a share may be said of, by name: "half cup", "half jug".
_SOURCES = frozenset(("cup", "jug", "pitcher", "bottle", "glass", "mug", "carton", "kettle", "jar", "teapot", "beaker",
                      "flask", "bucket", "pot", "can", "tin", "thermos", "carafe"))
#: The bowl filled is a goal's (seeking.py), not an amount the source holds.
_FILLED_BOWLS = {"bowl", "bowls", "destination", "target"}
#: The bowl said to hold liquid already: "the bowl was only half full", "the dish is half full".
_HELD_BOWLS = _FILLED_BOWLS | {"dish", "basin", "tub"}
_NUMBER = re.compile(r"\d+(?:\.\d+)?")
#: Why a bowl said to hold liquid before the pour is refused (suggestions.py's too).
HOLDS_LIQUID = "the destination is empty before the pour: the vocabulary says nothing of pouring into a bowl that holds liquid"
FILLS_BOWL = ("the destination is empty before the pour: the vocabulary says nothing of how full it gets; ask "
              "whether the liquid goes in and stays in (\"does it all go in?\")")
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
            if words[i] == "full" and words[i + 1:i + 2] and words[i + 1] in _HELD_BOWLS and words[i + 2:i + 3] != ["of"]:
                raise UserError(f"could not place \"{' '.join(words[max(0, i - 1):i + 2])}\": {HOLDS_LIQUID}")   # "a nearly full bowl"
            if words[i] == "keep" and _kept_pouring(words, i):     # "will it overflow if i keep pouring"
                raise UserError(f"could not place \"{' '.join(words[i - 1:i + 2 + (words[i + 1] == 'on')])}\": {FILLS_BOWL}")
            if words[i] == "full" and (bowl := _bowl_full(words, i)) is not None:      # "the bowl is already full", "bowl full."
                raise UserError(f"could not place \"{' '.join(words[bowl:i + 1])}\": {HOLDS_LIQUID}")
            share, end = _filled_to(words, i) if words[i] in _FILLING else (None, i)
            share, end = (share, end) if share is not None else _share(words, i)
            if share is not None and (filled := _bowl_filled(words, i)) is not None:
                raise UserError(f"could not place \"{' '.join(words[filled:end])}\": {FILLS_BOWL}")
            if share is not None and words[end:end + 1] and words[end] in _HELD_BOWLS:       # "a half full bowl"
                raise UserError(f"could not place \"{' '.join(words[i:end + 1])}\": {HOLDS_LIQUID}")
            if share is not None and _of_the_bowl(words, i):
                said = i - 1 if words[i - 1] in _HELD_BOWLS else max(0, i - 4)     # ("bowl half full": the note's words)
                raise UserError(f"could not place \"{' '.join(words[said:end])}\": {HOLDS_LIQUID}")
            if share is not None:
                out.append((i, end, tuple(amount(share).split())))
            i = end if share is not None else i + 1
        return out


def _of_the_bowl(words: list[str], i: int) -> bool:
    """Whether the share said at `i` is said of the bowl: "the bowl was only half full", "bowl half full"."""
    before = words[max(0, i - 4):i]
    return before[-1:] and before[-1] in _HELD_BOWLS or any(      # (or right after it, as notes say it: "bowl half full")
        w in _HELD_BOWLS and before[k + 1:k + 2] in (["is"], ["was"], ["are"], ["were"], ["s"]) for k, w in enumerate(before))


def _kept_pouring(words: list[str], i: int) -> bool:
    """Whether "keep" at `i` goes on pouring into the bowl until it is full, in a condition ("if i keep
    pouring", "and you keep going"), not where ("keep pouring on one side"), nor what others keep doing."""
    k = i + 1 + (words[i + 1:i + 2] == ["on"])
    return (words[i - 2:i - 1] in (["if"], ["when"], ["and"], ["once"]) and words[i - 1] in ("i", "you", "we")
            and words[k:k + 1] in (["pouring"], ["going"])
            and words[k + 1:k + 2] not in (["on"], ["from"], ["at"], ["over"], ["off"], ["into"], ["in"], ["to"]))


def _bowl_full(words: list[str], i: int) -> int | None:
    """Where the bowl is said, if "full" at `i` is said of it as it stands ("the bowl is already full", "bowl
    full"), not wanted of it ("i want the bowl full", "get the bowl full": seeking.py's); else None."""
    k = i - 1 - (words[i - 1:i] == ["already"])
    k -= words[k:k + 1] in (["is"], ["was"], ["s"])
    return k if (k >= 0 and words[k] in _HELD_BOWLS - {"destination"} and words[i + 1:i + 2] != ["of"]  # ("a bowl full of cereal")
                 and not _WANTING.intersection(words[max(0, k - 3):k])) else None


#: Words that want the bowl full, before it: "i'd like the bowl full".
_WANTING = frozenset(("want", "wants", "wanted", "like", "need", "needs", "get", "keep", "make", "have", "fill", "filled", "filling"))


#: Words between a bowl filled and the share it is filled to: "fill the bowl up to about half full".
_BOWL_TO = frozenset(("about", "around", "roughly", "approximately", "only", "just", "up", "to", "exactly", "maybe"))


def _bowl_filled(words: list[str], i: int) -> int | None:
    """Where the filling starts, if the share said at `i` is one the bowl is filled to: "fill a glass
    bowl about half full", "want the bowl to end up half full"; else None."""
    for k in range(i - 1, max(-1, i - 7), -1):
        if words[k] in _FILLING:
            bowl = next((b for b in range(i - 1, k, -1) if words[b] in _HELD_BOWLS), None)
            return k if bowl is not None and all(w in _BOWL_TO for w in words[bowl + 1:i]) else None
        if words[k] in (",", ";", ".", "and", "then"):
            break
    # ... or wanted to end up so: "i want the bowl to end up exactly half full", "get the bowl about half full"
    bowl = next((b for b in range(i - 1, max(-1, i - 7), -1) if words[b] in _HELD_BOWLS), None)
    if bowl is None or not all(w in _BOWL_TO | _ENDING for w in words[bowl + 1:i]):
        return None
    wanted = any(words[k] in _WANTING or words[k - 1:k + 1] == ["so", "that"]      # (a want is read as "so that" by now)
                 for k in range(bowl - 1, max(-1, bowl - 4), -1))
    return bowl - (words[bowl - 1:bowl] in (["the"], ["my"], ["a"])) if wanted else None


#: Words of the bowl ending up filled to a share: "the bowl to end up half full".
_ENDING = frozenset(("end", "ends", "ended", "ending", "be", "is"))


#: Verbs of filling the source, said with the share it is filled to: "fills the cup halfway".
_FILLING = frozenset(("fill", "fills", "filled", "filling"))


def _filled_to(words: list[str], i: int) -> tuple[float | None, int]:
    """The share a source is filled to, said after the verb at `i` and the source ("fill the cup
    halfway", "fills the jug to half", "fill it a third of the way", "fill the jug half full"), and
    where it ends; (None, i + 1) where none is (nor the bowl's: seeking.py's goal)."""
    k = i + 1 + (words[i + 1:i + 2] == ["up"])
    k += words[k:k + 1] in (["the"], ["a"], ["my"], ["your"], ["her"], ["his"], ["this"])
    if k >= len(words) or words[k] in _FILLED_BOWLS or words[k] in _FULL:
        return None, i + 1
    k += 1
    k += words[k:k + 1] == ["to"]
    for said, share in SHARES.items():
        end = k + len(said)
        if tuple(words[k:end]) == said:
            end += 3 if words[end:end + 3] == ["of", "the", "way"] else (end < len(words) and words[end] in _FULL)
            return share, end
    return None, i + 1


def _share(words: list[str], i: int) -> tuple[float | None, int]:
    """The share of full said from `i` on, and where its phrase ends."""
    for said, share in SHARES.items():
        k = i + len(said)
        if tuple(words[i:k]) != said or k >= len(words):
            continue
        if words[k] in _FULL:
            return share, k + 1
        # a share of a source named ("half cup", "half jug vs full jug"): of it full, its name kept ("half a cup",
        # "a half glass", "half cup of juice" are volumes: refused)
        if words[k] in _SOURCES and words[k + 1:k + 2] != ["of"] and words[i - 1:i] != ["a"]:
            return share, k
    # "90 percent full", "filled to 90 percent"
    if i + 2 < len(words) and _NUMBER.fullmatch(words[i]) and words[i + 1] in ("percent", "%") \
            and words[i + 2] in _FULL and 0 < float(words[i]) <= 100:
        return float(words[i]) / 100, i + 3
    if i + 3 < len(words) and words[i] in _FULL and words[i + 1] == "to" and _NUMBER.fullmatch(words[i + 2]) \
            and words[i + 3] in ("percent", "%") and 0 < float(words[i + 2]) <= 100:
        return float(words[i + 2]) / 100, i + 4
    return None, i


#: What a source is filled to when it is full ("to the top", "right to the brim").
_TOP = {"top", "brim"}
_UP_TO = {"right", "all", "the", "way", "up", "completely"}


class Filled:
    """A source filled to the top, named between ("filling the cup right to
    the top", "if I fill the jug all the way to the brim"): read as full.
    Not the bowl, nor a purpose ("to fill the cup to the top": a goal)."""

    def spans(self, words: list[str]) -> list[tuple[int, int, tuple[str, ...]]]:
        out: list[tuple[int, int, tuple[str, ...]]] = []
        for i, w in enumerate(words):
            if w not in _FILLING or (i > 0 and words[i - 1] == "to"):
                continue
            k = i + 1 + (i + 1 < len(words) and words[i + 1] == "up")
            if k >= len(words) or words[k] not in ("the", "a", "an", "my", "your", "this", "that"):
                continue
            for noun in (k + 1, k + 2):             # "the cup", "the glass jug"
                end = _to_the_top(words, noun + 1)
                if end and noun < len(words) and words[noun] not in _FILLED_BOWLS:
                    out.append((i, end, ("full",)))
                    break
        return out


def _to_the_top(words: list[str], k: int) -> int | None:
    """Where "to the top" (after "right", "all the way") said from `k` ends, or None."""
    while k < len(words) and words[k] in _UP_TO and words[k:k + 2] != ["the", "top"]:
        k += 1
    return k + 3 if words[k:k + 2] == ["to", "the"] and k + 2 < len(words) and words[k + 2] in _TOP else None


#: How full the bowl gets, asked: "how full can my bowl get before it spills".
_BOWL_FILL = re.compile(r"\bhow full (?:can|could|does|do|will|would|should|may) (?:the|my|a|this|that|our|your) "
                        r"(?:[a-z]+ )?(?:bowl|dish|basin|destination|tub)s? (?:get|gets|be|become|go)\b")


def refuse_bowl_fill(text: str) -> None:
    """UserError where `text` (normalised) asks how full the bowl gets, which the vocabulary cannot
    say: every pour's bowl is empty before it, and what is asked of it is whether the liquid stays in."""
    if m := _BOWL_FILL.search(text):
        raise UserError(f"could not place \"{m.group(0)}\": the destination is empty before the pour: the vocabulary "
                        "says nothing of how full it gets; ask whether it overflows (\"does it overflow?\")")
