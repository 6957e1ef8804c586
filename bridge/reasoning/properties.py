"""A body's property said by its parameter's name and a level, as people
with the simulation in mind say it: "low friction", "a high-restitution
liquid", "the friction of the bowl is high", "the cup's weight is low".
Each is read as the vocabulary's value word ("slippery", "bouncy",
"grippy", "light"), so that "low" or "high" is never read as a height.

A rewrite of words.py's kind (see wording.py): `spans(words)` gives the
words each such phrase covers and the words they are read as; a name
apart from its level ("the friction of the bowl is high") is read as
nothing and its level as the value word, the words between kept.
"""
from __future__ import annotations

#: A parameter's name -> the value words for its low and its high level.
NAMES = {
    "friction": ("slippery", "grippy"), "grip": ("slippery", "grippy"),
    "traction": ("slippery", "grippy"),
    "bounciness": ("dull", "bouncy"), "restitution": ("dull", "bouncy"),
    "elasticity": ("dull", "bouncy"),
    "mass": ("light", "heavy"), "weight": ("light", "heavy"),
    "viscosity": ("runny", "sticky"),
}
#: The levels, low (0) or high (1).
LEVELS = {"low": 0, "small": 0, "high": 1, "large": 1}
#: Words that may stand between a name and its level: "the friction of the bowl is very low".
_BETWEEN = {"of", "for", "the", "a", "an", "its", "is", "are", "was", "be", "being", "very",
            "really", "quite", "pretty", "rather", "extremely", "super", "destination", "source",
            "liquid", "target", "bowl", "cup", "both", "fairly"}
#: How many words may stand between a name and its level.
_GAP = 5


class Levels:
    """The rewrite (see the module's docstring)."""

    def spans(self, words: list[str]) -> list[tuple[int, int, tuple[str, ...]]]:
        out: list[tuple[int, int, tuple[str, ...]]] = []
        i = 0
        while i < len(words):
            found = self._at(words, i)
            out += found
            i = found[-1][1] if found else i + 1
        return out

    @staticmethod
    def _at(words: list[str], i: int) -> list[tuple[int, int, tuple[str, ...]]]:
        w = words[i]
        if w in LEVELS and i + 1 < len(words) and words[i + 1] in NAMES:     # "low friction"
            return [(i, i + 2, (NAMES[words[i + 1]][LEVELS[w]],))]
        name = i + 2 if w in ("coefficient", "coefficients") and words[i + 1:i + 2] == ["of"] else i
        if name >= len(words) or words[name] not in NAMES:
            return []
        # "the friction of the bowl is high": the name read as nothing (a hedge), the level
        # as the value word, the words between as they are
        for j in range(name + 1, min(len(words), name + 2 + _GAP)):
            if words[j] in LEVELS:
                return [(i, name + 1, ("hedge",)), (j, j + 1, (NAMES[words[name]][LEVELS[words[j]]],))]
            if words[j] not in _BETWEEN:
                return []
        return []
