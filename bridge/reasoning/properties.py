"""A body's property said by its parameter's name and a level, as people
with the simulation in mind say it: "low friction", "a high-restitution
liquid", "the friction of the bowl is high", "the cup's weight is low".
Each is read as the vocabulary's value word ("slippery", "bouncy",
"grippy", "light"), so that "low" or "high" is never read as a height.

A value said by the parameter's name and a number ("a friction of 0.1",
"restitution 0.9", "particle count 120") is the number with the
parameter as its unit ("0.1 unit_friction"), for quantities.py to read
as the proposition whose range holds it.

Each is a rewrite of words.py's kind (see wording.py): `spans(words)` gives the
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
#: A parameter's name said with a number -> the unit word quantities.py reads it with.
UNIT_OF = {"friction": "unit_friction", "restitution": "unit_restitution",
           "bounciness": "unit_restitution", "elasticity": "unit_restitution"}
#: Words that may stand between a name and its number: "a friction of 0.1", "friction = 0.1".
_TO_NUMBER = {"of", "is", "at", "to", "equal", "equals", "about", "around", "roughly", "coefficient",
              "coefficients", "value"}


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
        said = name + 1 + (words[name + 1:name + 2] in (["coefficient"], ["coefficients"]))   # "friction coefficient"
        for j in range(said, min(len(words), said + 1 + _GAP)):
            if words[j] in LEVELS:
                return [(i, said, ("hedge",)), (j, j + 1, (NAMES[words[name]][LEVELS[words[j]]],))]
            if words[j] not in _BETWEEN:
                return []
        return []


class Values:
    """The rewrite of a parameter's name with a number (see the module's docstring)."""

    def spans(self, words: list[str]) -> list[tuple[int, int, tuple[str, ...]]]:
        out: list[tuple[int, int, tuple[str, ...]]] = []
        for i, w in enumerate(words):
            if out and i < out[-1][1]:
                continue            # (a name inside the last phrase)
            unit = UNIT_OF.get(w) or ("unit_particles" if words[i:i + 2] in (["particle", "count"],
                                                                              ["particles", "count"])
                                      else None)
            if unit is None:
                continue
            j = i + (2 if unit == "unit_particles" else 1)
            while j < len(words) and words[j] in _TO_NUMBER:
                j += 1
            if j < len(words) and _number(words[j]):
                # "coefficient of friction", and the body after: "0.9 for the liquid", "on the bowl"
                first = i - 2 if words[max(0, i - 2):i] == ["coefficient", "of"] else i
                end = j + 2 if words[j + 1:j + 2] in (["for"], ["of"], ["on"]) else j + 1
                out.append((first, end, (words[j], unit)))
        return out


def _number(word: str) -> bool:
    return bool(word) and word.lstrip("-").replace(".", "", 1).isdigit()


#: What a bowl stands on, and the words that say it grips or does not.
_SURFACES = {"table", "tables", "counter", "counters", "countertop", "worktop", "benchtop", "bench",
             "tabletop", "bar", "bartop", "conveyor", "conveyors", "tray", "workbench", "hearth", "deck", "pass",
             "ledge", "boards", "shelf", "windowsill", "sill"}
#: What a bowl may stand on that is a liquid's name or no table: a surface only after "on"
#: ("sitting on wet concrete", "on a wet floor", "bowl on wet glass").
_GROUND = {"concrete", "cement", "floor", "ground", "marble", "granite", "stone", "tile", "tiles", "slab", "lino", "plate", "decking",
           "surface", "surfaces", "glass"}
#: The word that may end its name: "a wet bar top", "a slick conveyor belt".
_ENDS = {"top", "tops", "belt", "belts"}
_GRIP = {"slippery": "slippery", "slick": "slippery", "slippy": "slippery", "greasy": "slippery", "smooth": "slippery",
         "wet": "slippery", "icy": "slippery",
         "grippy": "grippy", "rough": "grippy"}
_AS = {"is", "are", "was", "seems", "looks", "feels", "very", "really", "quite", "super", "so", "pretty", "kinda", "sorta",
       "a", "bit", "little", "all"}
#: What a bowl stands on, of its own: a grip said of it is the destination's ("heavy bowl. slippery
#: bottom."), unless it is said of a container poured from ("a jug with a slippery bottom").
_UNDERSIDES = {"bottom", "bottoms", "base", "underside", "feet"}
_BOWLS = {"bowl", "bowls", "dish", "basin", "tub", "trough", "troughs", "destination"}
#: What is said back of it.
SURFACE_SAID = "read as the destination's friction: the bowl slides, or not, on what it stands on"


class Surfaces:
    """A slippery table, a counter that is slick, a slippery bottom: the
    destination's friction, for the bowl slides on what it stands on (its
    friction is the vocabulary's, not the table's). `spans(words)` gives each phrase
    and the words it is read as ("slippery destination"); a table said
    high, or sticky, is not one (everyday.txt's context nouns)."""

    def spans(self, words: list[str]) -> list[tuple[int, int, tuple[str, ...]]]:
        out: list[tuple[int, int, tuple[str, ...]]] = []
        for i, w in enumerate(words):
            if w in _UNDERSIDES and i > 0 and words[i - 1] in _GRIP and not (out and i - 1 < out[-1][1]):
                before = words[max(0, i - 5):i - 1]           # "a jug with a slippery bottom": the jug's, left as said
                k = before.index("with") if "with" in before else 0
                if k == 0 or before[k - 1] in _BOWLS:
                    out.append((i - 1, i + 1, (_GRIP[words[i - 1]], "destination")))
                continue
            if w == "wet" and not (out and i < out[-1][1]) and _wet_bowl(words, i):     # "the bowl is wet", "a wet bowl"
                end = i + 4 if words[i + 1:i + 3] in (["in", "the"], ["on", "the"]) and words[i + 3:i + 4] and \
                    words[i + 3] in _UNDERSIDES else i + 1                   # "wet in the bottom"
                out.append((i, end, ("slippery", "destination")))
                continue
            if w not in _SURFACES | _GROUND or (out and i < out[-1][1]) or words[i + 1:i + 2] == ["of"]:   # "a bar of soap"
                continue
            if w in _GROUND and "on" not in words[max(0, i - 4):i]:    # "pour wet concrete": the liquid
                continue
            grip = i - 1 if i > 0 and words[i - 1] in _GRIP else (    # "a slick table", "a slick glass table",
                i - 2 if i > 1 and words[i - 2] in _GRIP and words[i - 1].isalpha() and words[i - 1] not in _BOWLS
                else None)                                                # ("the wet grooming table", "a slippy overbed table")
            while grip is not None and grip > 0 and words[grip - 1] in _GRIP:     # "a wet slippery plate"
                grip -= 1
            if grip is not None and not (out and grip < out[-1][1]):    # "a wet bar top"
                end = i + 2 if i + 1 < len(words) and words[i + 1] in _ENDS else i + 1
                out.append((grip, end, (_GRIP[words[grip]], "destination")))
                continue
            j = i + 1
            while j < len(words) and words[j] in _AS and j - i <= 3:
                j += 1
            if j > i + 1 and words[i + 1] in _AS and j < len(words) and words[j] in _GRIP:   # "the table is slick"
                out.append((i, j + 1, (_GRIP[words[j]], "destination")))
        return out


def _wet_bowl(words: list[str], at: int) -> bool:
    """Whether "wet" at `at` is said of the bowl, which stands wet and slides: "the bowl is wet",
    "bowl wet and slick", "a wet bowl", "a wet slippery bowl" (not wet hands, nor the table wet
    with a spill)."""
    k = at - 1
    while k >= 0 and words[k] in _AS:
        k -= 1
    j = at + 1
    while j < len(words) and (words[j] in _GRIP or words[j] == "and"):
        j += 1
    return (k >= 0 and words[k] in _BOWLS) or words[j:j + 1] in (["bowl"], ["dish"], ["basin"])
