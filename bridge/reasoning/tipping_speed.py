"""How fast the source is tipped, said in a clause of its own right after
the tipping ("tip the jug, slow and gentle", "tilt it over the bowl, nice
and quick"): the move into the pouring pose, which tilts the source as it
goes, as "tip it slowly" is (speeds.py). A rewrite of words.py's, applied
before the everyday word list: the clause must hold a speed ("gentle"
alone says how far as much as how fast, and is left to be read as it is),
and the clause before it a verb of tipping; or said last in the clause that tips it, after
how far ("tip it halfway fast": tilted halfway, moving in fast); or right after what is
tipped, named ("tip the pot of jam really slow": moving in slowly, and pouring the pot of
jam, whose words are read as any are)."""
from __future__ import annotations

#: Verbs of tipping the source.
_TIPPING = frozenset(("tip", "tips", "tipped", "tipping", "tilt", "tilts", "tilted", "tilting"))
_SPEEDS = {"slow": "slowly", "slowly": "slowly", "fast": "fast", "quick": "fast", "quickly": "fast"}
#: Words said with the speed, of how the tipping is done: "slow and gentle", "nice and slow".
_WITH = frozenset(("and", "nice", "real", "really", "very", "gentle", "gently", "steady", "steadily", "careful",
                   "carefully", "smooth", "smoothly", "easy", "but"))
#: The marks that end a clause, as the rewrites see the words (poured_off.py's too).
ENDS = frozenset((",", ";", ".", "!", "?", ":"))


class TippingSpeed:
    """The rewrite (see the module's docstring)."""

    def spans(self, words: list[str]) -> list[tuple[int, int, tuple[str, ...]]]:
        out = []
        for i, w in enumerate(words):
            if w in _SPEEDS and _tipped_how_far(words, i):      # "tip it halfway fast": halfway, moving in fast
                out.append((i, i + 1, (";", "approach", _SPEEDS[w], ";", "pour")))
                continue
            if (named := _tipped_named(words, i)) is not None:      # the words tipped kept as they are
                verb, speed = named
                out += [(verb, verb + 1, ("approach", _NAMED_SPEEDS[w], ";", "pour")), (speed, i + 1, ("hedge",))]
                continue
            if w not in (",", ";") or not _tipped_before(words, i):
                continue
            end = next((k for k in range(i + 1, len(words)) if words[k] in ENDS), len(words))
            said = words[i + 1:end]
            speeds = {_SPEEDS[s] for s in said if s in _SPEEDS}
            if len(speeds) == 1 and all(s in _SPEEDS or s in _WITH for s in said):
                out.append((i + 1, end, ("approach", speeds.pop())))
        return out


def _tipped_before(words: list[str], at: int) -> bool:
    """Whether the clause ending at `at` holds a verb of tipping."""
    k = at - 1
    while k >= 0 and words[k] not in ENDS:
        if words[k] in _TIPPING:
            return True
        k -= 1
    return False


#: How far a source is tipped, said between the verb and its speed: "tip it halfway fast".
_HOW_FAR = frozenset(("halfway", "degrees", "deg", "upside", "steeply", "slightly", "way", "horizontal", "vertical"))
#: Words that make the speed another's: a move in or away, or the pour itself ("pour at 45 degrees fast").
_ANOTHER = frozenset(("in", "away", "out", "back", "pour", "pours", "poured", "pouring", "move", "bring", "pull"))


def _tipped_how_far(words: list[str], at: int) -> bool:
    """Whether the speed at `at` ends a clause that tips the source and says how far, with no other move in it."""
    if at + 1 < len(words) and words[at + 1] not in ENDS and words[at + 1] not in ("and", "then", "but"):
        return False
    k, far = at - 1, False
    while k >= 0 and words[k] not in ENDS:
        if words[k] in _ANOTHER:
            return False
        far = far or words[k] in _HOW_FAR
        if words[k] in _TIPPING:
            return far
        k -= 1
    return False


#: Speeds said right after what is tipped; and words that cannot be part of what is tipped (a clause's
#: joints, other moves, speeds, places, how far or how big).
_NAMED_SPEEDS = {**_SPEEDS, "gradually": "slowly", "steadily": "slowly", "rapidly": "fast"}
_NOT_TIPPED = frozenset("""and then but or so if when into in onto over to from at with big small little large tiny too far
    halfway half all way upside sideways right straight degrees degree deg slow slowly fast quick quickly it them""".split())
_NOT_TIPPED_STEMS = ("move", "pull", "bring", "brought", "slow", "quick", "steep", "slight", "horizontal", "vertical")
_INTENSE = frozenset(("very", "really", "too", "quite", "super"))


def _tipped_named(words: list[str], at: int) -> tuple[int, int] | None:
    """(where the verb of tipping is, where the speed's words start) where the speed at `at` follows a
    verb of tipping and the words it tips, named (not "it": speeds.py reads "tip it slowly"); else None."""
    if words[at] not in _NAMED_SPEEDS or (at + 1 < len(words) and words[at + 1] in ("than", "as")):
        return None
    k = at - 1
    while k >= 0 and words[k] in _INTENSE:
        k -= 1
    if k >= 0 and words[k] == "in":                  # "tip the honey in slowly"
        k -= 1
    end = k + 1
    while k >= 0 and end - k <= 6 and _tippable(words[k]):
        k -= 1
    if k < 0 or k + 1 == end or words[k] not in _TIPPING:
        return None
    return k, end


def _tippable(word: str) -> bool:
    """Whether `word` can be part of what is tipped."""
    return (word.isalpha() and word not in _NOT_TIPPED and word not in _TIPPING
            and not word.startswith(_NOT_TIPPED_STEMS))


SAID = "read as the move into the pouring pose, which tilts the source as it goes"
