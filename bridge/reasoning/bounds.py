"""A value said as the most it may be: "not tilted past 30 degrees", "no
more than 60 degrees", "at most 45 degrees", "less than 30 degrees", "just
under ninety degrees", "don't tilt it past horizontal", "no more than
halfway".

An upper bound leaves the values of its parameter below it, a run from
the low end of the scale (tilted back, upright; below the rim) up to the
value whose range holds the bound. A limit is said of what one goes up
to, so the bound is read as the value of that run nearest it, the one
whose range holds it (on the edge of two ranges, the lower), and said
back; the run's far end (upright, no tilt at all) is what the bound is
furthest from. A bound that leaves every value ("at most 170 degrees")
excludes nothing and is refused asking for the value. A lower bound ("at
least 45 degrees", "past 30 degrees", "more than halfway") leaves a run up
to the scale's far end, each value a pour of its own, and stays refused
(suggestions.py).
"""
from __future__ import annotations

from pantarhei.bridge.errors import UserError
from pantarhei.bridge.reasoning.everyday import UNCLEAR
from pantarhei.bridge.reasoning.negation import NEGATION_STEMS
from pantarhei.bridge.reasoning.nouns import BOWL, OBJECT_STEMS
from pantarhei.bridge.reasoning.wording import Token, stem
from pantarhei.bridge.reasoning.words import FILLERS
from pantarhei.theory.lexicon import load_vocabulary

#: Bounds said before a number, as written: the most it may be, alone or negated
#: (a lower bound negated is an upper one: "not more than 60 degrees").
_AT_MOST = {"at most", "no more than", "less than", "fewer than", "up to"}
_NEGATED = {"past", "beyond", "more than", "over"}
#: Said before an angle or a count (never a length: "under the rim" is a height): "just under 90 degrees".
_UNDER = {"under", "below"}
#: Words that may stand between a bound and its number: "no more than about 60 degrees".
_ABOUT = {stem(w) for w in ("about", "around", "roughly", "approximately", "some", "like")}
#: Words that may stand between a negation and the bound it negates: "don't tilt the mug past".
_BETWEEN = {stem(w) for w in FILLERS} | set(OBJECT_STEMS) | {BOWL} | {
    stem(w) for w in ("tilt", "tilts", "tilted", "tip", "tips", "tipped", "lean", "angle", "turn", "rotate",
                      "go", "goes", "going", "went", "gone", "get", "gets",
                      # a height bounded: "never lift the jug more than an inch above the rim"
                      "lift", "lifts", "lifted", "raise", "raises", "raised", "hold", "holds", "held")}
#: The words of a tilt said by its value, which "past" before them bounds: "past horizontal"
#: (steeply tilted, as words.py reads it), "past halfway", "beyond upright" (not "upside down",
#: the scale's end: a bound there excludes nothing).
_TILT_VALUES = {stem(w) for w in ("steeply", "slightly", "halfway", "half", "upright", "tilted")}
#: The verbs of tilting a bound may hold, read with the value it bounds where the value needs
#: one ("halfway"; "horizontal" is read alone).
_READ_WITH_VERB = {stem(w) for w in ("halfway", "half")}
_TILTING = {stem(w) for w in ("tilt", "tilts", "tilted", "tip", "tips", "tipped", "lean", "turn", "rotate")}
_WHICH = {"the", "a", "an", "my", "your", "our", "their", "his", "her", "that", "this"}
SAID = "a bound, the most it may be: read as the value nearest it"


def upper_bound(tokens: list[Token], i: int, measures: str, cues: set[str]) -> set[int]:
    """The positions of the words that say the number at `i` is the most it
    may be (the bound, its negation and the words between, which are read
    with it), or none where it is said as no upper bound; `cues` are the
    words that may stand between a negation and the bound besides _BETWEEN."""
    j = i - 1
    while j >= 0 and tokens[j].word in _ABOUT:
        j -= 1
    if j < 0 or tokens[j].clause != tokens[i].clause:
        return set()
    said = tokens[j].raw
    if said in _AT_MOST and tokens[j].word == UNCLEAR or said in _UNDER and measures != "length":
        if _negation(tokens, j, cues) is not None:
            raise UserError(f"not {said} {tokens[i].raw}: a bound, the least it may be, which leaves the "
                            "value open: say the value (\"tilted halfway\", \"pour high\") or a range with "
                            "both ends (\"30 to 40 degrees\")")
        return {j}
    negation = _negation(tokens, j, cues) if said in _NEGATED else None
    return set() if negation is None else set(range(negation, j + 1)) - _kept(tokens, negation, j)


def nearest_below(value: float, param: str, text: str) -> str | None:
    """The value of `param` an upper bound of `value` is read as: the
    nearest of those it leaves (None where `param` has no values);
    UserError if it leaves none or all."""
    vocab = load_vocabulary()
    ranges = sorted((p.model.low, p.model.high, n) for n, p in vocab.propositions.items()
                    if p.model.kind == "uniform" and p.model.param == param)
    left = [n for lo, _, n in ranges if lo < value]
    if not ranges:
        return None
    if 0 < len(left) < len(ranges):
        return left[-1]
    raise UserError(f"at most {text} leaves {'every' if left else 'no'} value of {param}: say the value "
                    "(\"tilted halfway\", \"pour high\") or a range with both ends (\"30 to 40 degrees\")")


def bounded_values(tokens: list[Token]) -> list[Token]:
    """The tokens with a tilt said by its value and bounded above ("don't tilt
    it past horizontal", "no more than halfway") read as that value, the
    bound's words read with it and said back."""
    out = list(tokens)
    drop: set[int] = set()
    for k, t in enumerate(tokens):
        value = [m for m in range(k + 1, min(k + 4, len(tokens))) if tokens[m].clause == t.clause
                 and tokens[m].word in _TILT_VALUES]
        if t.raw in ("past", "beyond") and t.word != UNCLEAR and value and value[0] in (k + 1, k + 2) \
                and (negation := _negation(tokens, k, set())) is not None:
            bound = set(range(negation, k + 1)) - _kept(tokens, negation, k)
        elif t.word == UNCLEAR and t.raw.startswith("more than ha") and k > 0 \
                and tokens[k - 1].word in ("no", "not") and tokens[k - 1].clause == t.clause:
            bound, value = {k - 1}, [k]          # "no more than halfway": its words one token
            out[k] = Token(stem("halfway"), t.raw, t.clause)
        else:
            continue
        raw = " ".join(tokens[m].raw for m in sorted(bound | {value[0]}))
        for m in value:
            if tokens[m].raw == tokens[value[0]].raw:
                out[m] = Token(out[m].word, raw, t.clause, SAID)
        # the verb of tilting stays, read with the value ("don't tilt it past halfway": tilted halfway)
        drop |= {m for m in bound - set(value) if tokens[m].word not in _TILTING
                 or tokens[value[0]].word not in _READ_WITH_VERB}
    return [t for m, t in enumerate(out) if m not in drop]


def _negation(tokens: list[Token], j: int, cues: set[str]) -> int | None:
    """The position of the negation of the bound at `j` in its clause, with
    only the verb, the noun and words of the frame between them; None if none."""
    k = j - 1
    while k >= 0 and tokens[k].clause == tokens[j].clause and tokens[k].word not in NEGATION_STEMS:
        if tokens[k].word not in _BETWEEN and tokens[k].word not in cues:
            return None
        k -= 1
    return k if k >= 0 and tokens[k].clause == tokens[j].clause and tokens[k].word in NEGATION_STEMS else None


def _kept(tokens: list[Token], first: int, last: int) -> set[int]:
    """The positions between a negation and its bound that are read on their
    own: a noun ("the mug") and the word before it that says which."""
    nouns = {m for m in range(first + 1, last) if tokens[m].word in OBJECT_STEMS or tokens[m].word == BOWL}
    return nouns | {m - 1 for m in nouns if tokens[m - 1].word in _WHICH}
