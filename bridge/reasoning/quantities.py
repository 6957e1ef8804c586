"""Numbers with units in a question, read as the proposition whose range
holds them: "tilted at 45 degrees" is pour_half_tilted, "30 cm above the
bowl" pour_very_high, "move in over 3 seconds" slow_approach, "a 2 kg bowl"
heavy_destination, "50 particles" some_liquid.

The unit says what is measured (a length, an angle, a time, a mass, a
count); the stage the number is said in (reading.py's stages), the words
beside it and the body it qualifies say which parameter: an angle is the
tilt of the source in its stage, or its roll if "roll" or "sideways" is
said; a length its height above the destination's rim ("below": under the
rim), or its distance from the destination's axis if "side", "away",
"far" or "off" is said, or its sideways offset if "sideways" or "offset"
is; a time the move into the pouring pose or out of it (a tilt said "over 2 s"
is the move in's, which carries the tilt; "held for 5 s" no move's); a mass the bowl it
qualifies; a count the particles of liquid. The value is converted to the
parameter's unit (theory/vocabulary/parameters.pl) and read as the
proposition of that parameter whose range holds it (one between two
ranges, in the ordinary pour's, as the ordinary pour: "a 600 g jug"); a
number no range holds, or a measure no parameter takes ("pour for 3 seconds": pouring has
no duration of its own), is refused naming the ranges there are.

The most a number may be ("not tilted past 30 degrees", "no more than 60
degrees") is read as the value nearest it of those it leaves (bounds.py);
a range typed with both ends, three quarters of it in one value ("5 to 10
cm"), as that value.

A number keeps its sign (wording.py): "tilted at -10 degrees" is tilted
back, "-3 cm above the rim" below it; a negative mass, time, count or
amount is refused, as is a minus said with "below" ("-5 cm below the
rim"). A speed ("0.5 m/s") and an amount of liquid in millilitres or
grams ("100 grams of water") are refused naming what would be read.
"""
from __future__ import annotations

import re
from dataclasses import dataclass

from pantarhei.bridge.errors import UserError
from pantarhei.bridge.reasoning.bounds import SAID as BOUND_SAID, bounded_values, nearest_below, upper_bound
from pantarhei.bridge.reasoning.carried_units import carried
from pantarhei.bridge.reasoning.nouns import Nouns, roles
from pantarhei.bridge.reasoning.stages import MOVE, POSE, stages
from pantarhei.bridge.reasoning.units import POSITIVE, UNITS
from pantarhei.bridge.reasoning.wording import NUMBER, Token, stem
from pantarhei.theory.lexicon import load_vocabulary

#: The words beside a number that pick its parameter, by what they choose;
#: they are read with the number (a height's with the rim it is measured from).
CUES = {
    "roll": ("roll", "sideways"),
    "pitch": ("tilt", "pitch", "angle", "forward", "forwards"),
    "yaw": ("yaw", "turn", "rotate", "spin", "twist"),
    "side": ("side", "away", "far", "off", "distance", "axis", "x"),
    "offset": ("sideways", "offset", "axis", "y"),
    "height": ("high", "above", "below", "height", "up", "rim", "z", "h", "drop", "fall"),
}
#: The words read with a number besides its cues: a roll is "tilted sideways", a pitch
#: "rotated forward".
ALSO_READ = {"roll": ("tilt",), "pitch": ("rotate", "turn")}
#: The cues that place a length (a tilt's places none: "pouring from 10 cm at a steep angle").
_PLACING = frozenset(w for c in ("side", "offset", "height") for w in CUES[c])
#: Words that say a time as a span a move takes: "over 2 s", not "held for 5 s".
_SPAN = {"over", "in", "within"}
#: How far from a number its cue words may stand.
REACH = 4
#: Words that may stand between a number and the cue beside it: "a height of 20 cm",
#: "tilted at 45 degrees", "20 cm to the side".
_BESIDE = {stem(w) for w in ("of", "a", "an", "the", "at", "to", "from", "by", "about", "around",
                              "roughly", "approximately", "some")}


@dataclass(frozen=True)
class Quantity:
    value: float
    measures: str          # "length", "angle", "time", "mass" or "count"
    text: str              # as written: "45 degrees"


def parameter(q: Quantity, pose: str, move: str | None, cues: set[str],
              body: str | None) -> tuple[str, str]:
    """(the parameter `q` gives, the cue it was chosen by: a key of CUES, or
    "") for a quantity said in the stage with pose `pose` and movement
    `move` (reading.py's _POSE and _MOVE), beside the cue words `cues`, of
    the body `body`; UserError for a measure no parameter takes there, or
    a negative one where nothing can be negative."""
    if q.value < 0 and q.measures in POSITIVE:
        raise UserError(f"\"{q.text}\": {POSITIVE[q.measures]} cannot be negative")
    if q.measures == "speed":
        raise UserError(f"\"{q.text}\" is a speed, which the vocabulary says by how long the "
                        "source takes to move in or away: say \"move in fast\", \"move in slowly\", "
                        "\"move in over 2 seconds\" or \"move away fast\"")
    if q.measures == "turn speed":
        raise UserError(f"\"{q.value:g} degrees a second\" is a speed of tilting, which the vocabulary has no "
                        "proposition of: it says how far the source is tilted (\"tilted "
                        "halfway\", \"tilted at 45 degrees\") and how fast it moves in or away "
                        "(\"move in slowly\")")
    if q.measures == "volume":
        raise UserError(_AMOUNT.format(q.text))
    if q.measures == "angle":
        if cues & set(CUES["roll"]):
            return f"{pose}_roll", "roll"
        if cues & set(CUES["yaw"]) and not cues & set(CUES["pitch"]):    # no proposition holds it
            return f"{pose}_yaw", "yaw"
        return f"{pose}_pitch", "pitch"
    if q.measures == "length":
        if cues & {"offset", "y"} or (cues & {"sideways"} and not cues & set(CUES["height"])
                                 and not cues & set(CUES["side"])):
            return f"{pose}_y", "offset"
        if cues & set(CUES["side"]):
            return f"{pose}_x", "side"
        if not cues & set(CUES["height"]):
            raise UserError(f"\"{q.text}\": above the destination, or to its side? say "
                            f"\"{q.text} above\" or \"{q.text} to the side\"")
        return f"{pose}_z", "height"
    if q.measures == "time":
        if move is None and cues & set(CUES["pitch"]):          # "tilted to 90 degrees over 2 s"
            raise UserError(f"\"{q.text}\": the vocabulary has no speed of tilting: it says how far "
                            f"the source is tilted and how long it takes to move in: say \"tilted "
                            f"halfway\", \"move in over {q.text}\"")
        if move is None:
            raise UserError(f"\"{q.text}\": pouring takes no time of its own; say how long "
                            "the source takes to move in (before pouring) or to move away "
                            "(after pouring)")
        return f"{move}_duration", ""
    if q.measures in ("friction", "restitution"):
        owner = {"source": "source", "destination": "destination", "liquid": "particle"}.get(body)
        if owner is None:
            raise UserError(f"\"{q.text}\": the {q.measures} of which? say \"a destination bowl "
                            f"with a {q.measures} of ...\", \"a source bowl ...\" or \"a liquid ...\"")
        return f"{owner}_{q.measures}", ""
    if q.measures == "mass":
        if body == "particle":          # "the particles weigh 0.5 g each"
            return "particle_mass", ""
        if body not in ("source", "destination"):
            raise UserError(f"\"{q.text}\": the mass of which bowl? say \"a source bowl of "
                            f"{q.text}\" or \"a destination bowl of {q.text}\"")
        return f"{body}_mass", ""
    return "particle_count", ""


_AMOUNT = ("\"{}\" of liquid: the vocabulary counts the liquid in particles; say \"with 50 "
           "particles\", \"a little liquid\", \"some liquid\", \"much liquid\" or \"a full cup\"")


class Unheld(UserError):
    """A number of the parameter `param` that no proposition's range holds."""

    def __init__(self, message: str, param: str):
        super().__init__(message)
        self.param = param


def proposition(q: Quantity, param: str, cues: set[str], low: float | None = None, typed: bool = False) -> str:
    """The proposition whose range of `param` holds `q` (a height said
    "below" the rim is under it: negative), or all of the range from `low`
    to `q` where one is said ("8 to 10 cm"), or else, for a range `typed`
    with both its ends, MOST of it ("5 to 10 cm": medium height); "" for a number between two ranges that
    the ordinary pour's holds; Unheld naming the ranges there are if
    none does."""
    vocab = load_vocabulary()
    unit = next(p.unit for p in vocab.parameters if p.name == param)
    if param.endswith("_z") and "below" in cues and q.value < 0:
        raise UserError(f"\"{q.text}\" below: say \"{q.text[1:]} below the rim\" or \"{q.text} "
                        "above the rim\", not both a minus and below")
    sign = -1 if param.endswith("_z") and "below" in cues else 1
    ends = [sign * q.value] if low is None else sorted({sign * low, sign * q.value})
    ranges = sorted((p.model.low, p.model.high, n) for n, p in vocab.propositions.items()
                    if p.model.kind == "uniform" and p.model.param == param)
    # on the bound of two ranges, the upper: 0 mm above the rim is low; a range, the one
    # holding all of it: 30 to 40 degrees is slightly tilted (5 to 40)
    holding = [n for lo, hi, n in ranges if lo <= ends[0] and ends[-1] <= hi]
    if holding:
        return holding[-1]
    mostly = [n for lo, hi, n in ranges if typed and len(ends) > 1
              and min(hi, ends[1]) - max(lo, ends[0]) >= (ends[1] - ends[0]) * MOST]
    if mostly:                  # "5 to 10 cm": 50 to 60 mm low, 60 to 100 mm medium height
        return mostly[0]
    prior = next((p.prior_low, p.prior_high) for p in vocab.parameters if p.name == param)
    if ranges and prior[0] <= ends[0] and ends[-1] <= prior[1] and not any(
            lo <= ends[-1] and ends[0] <= hi for lo, hi, _ in ranges):
        return ""           # between two values, in the ordinary pour's range: a 600 g jug
    said = "; ".join(f"{n} {lo} to {hi} {unit}" for lo, hi, n in ranges)
    value = " to ".join(f"{v:g}" for v in ends)
    away = sorted((min(abs(lo - ends[0]), abs(hi - ends[0])), n) for lo, hi, n in ranges)
    nearest = away[0][1] if len(away) == 1 or away and away[0][0] < away[1][0] else ""
    raise Unheld(f"\"{q.text}\" is {value} {unit} of {param}, which no "
                    f"{'one ' if len(ends) > 1 else ''}proposition holds"
                    + (f" ({said}): say {'a value within ' if len(ends) > 1 else ''}one of these"
                       + (f" (the nearest: {nearest})" if len(ends) == 1 and nearest else "")
                       if said else ": the vocabulary has no proposition of it"), param)


#: The share of a range typed with both ends ("5 to 10 cm") one value must hold to be read.
MOST = 0.75
MOSTLY = "a range across two values, three quarters of it or more in this one: read as it"


def _holds(name: str, low: float, high: float) -> bool:
    """Whether the range of proposition `name` holds all of `low` to `high` (either sign)."""
    m = load_vocabulary().propositions[name].model
    return any(m.low <= min(a, b) and max(a, b) <= m.high for a, b in ((low, high), (-low, -high)))


def ordinary_said(param: str) -> str:
    """What is said back of a number read as the ordinary pour: its range there."""
    p = next(p for p in load_vocabulary().parameters if p.name == param)
    return (f"between the vocabulary's values of {param}, in the ordinary pour's range ({p.prior_low:g} to "
            f"{p.prior_high:g} {p.unit}): read as the ordinary pour")


def read_numbers(tokens: list[Token], placeable: frozenset[str]) -> list[Token]:
    """The tokens with each number and its unit ("45 degrees"), and the
    words beside it that picked its parameter ("tilted at"), read as one:
    the proposition whose range holds it. The cue that stands beside the
    number ("at 10 cm height", "20 cm to the side") picks the parameter
    before the others of its clause ("from the side at 10 cm height" is
    a height, and the side is the pour's)."""
    tokens = bounded_values(carried(tokens))     # "45 degrees instead of 90": 90 degrees; "not past halfway"
    numbers = [i for i, t in enumerate(tokens[:-1]) if re.fullmatch(NUMBER, t.word)
               and _unit(tokens[i + 1]) and tokens[i + 1].clause == t.clause]
    if not numbers:
        return tokens
    stage = stages(tokens)
    noun = Nouns(tokens, roles(tokens, placeable), placeable)
    cue_of = {stem(w): w for ws in (*CUES.values(), *ALSO_READ.values()) for w in ws}
    read: dict[int, Token] = {}
    dropped: set[int] = set()
    for i in numbers:
        unit = _unit(tokens[i + 1])
        said = tokens[i].raw if tokens[i].raw == tokens[i + 1].raw else f"{tokens[i].raw} {unit}"
        q = Quantity(float(tokens[i].word) * UNITS[unit][1], UNITS[unit][0], said)
        k = _past(tokens, i + 2, 1, _BESIDE)
        if UNITS[unit][0] == "mass" and i + 2 < len(tokens) and tokens[i + 2].word == "of" \
                and any(tokens[m].word == "liquid" for m in range(k, min(k + 2, len(tokens)))):
            raise UserError(_AMOUNT.format(q.text))
        # (the words beside a number count for none: "tilt the jug by about 45 degrees")
        start = max(0, min(i - REACH, _past(tokens, i - 1, -1, _BESIDE) + 1 - REACH))
        near = [k for k in range(start, min(len(tokens), i + 2 + REACH))
                if k not in (i, i + 1) and tokens[k].clause == tokens[i].clause
                and tokens[k].word in cue_of and k not in dropped]
        if not near and i > 0 and tokens[i - 1].clause == tokens[i].clause - 1 and tokens[i - 1].word in cue_of:
            near = [i - 1]          # said after it, set off by a comma: "I pour from high, 30 centimetre"
        sides = [_past(tokens, i + 2, 1, _BESIDE), _past(tokens, i - 1, -1, _BESIDE)]
        if i > 0 and tokens[i - 1].word == "of":            # "a height of 20 cm"
            sides.reverse()
        beside = [k for k in sides if k in near]
        cues = {cue_of[tokens[k].word] for k in near}        # "tilt" picks a pitch, as a cue
        choosing = {cue_of[tokens[beside[0]].word]} | (cues & {"below", "offset"}) if beside else cues
        if q.measures == "length" and not choosing & _PLACING and (_poured_from(tokens, i, stage) or _bare(tokens, i)):
            choosing = {"height"}           # "pour from 40 cm", "pouring it from about 6 inches": the height poured from
        if q.measures == "time" and any(cue_of.get(tokens[k].word) in CUES["pitch"] for k in range(
                max(0, i - 8), i) if tokens[k].clause == tokens[i].clause):
            choosing = choosing | {"tilt"}          # "tilted to 90 degrees over 2 s": the tilting's time
        at = noun.at(i, i + 1)
        body = None if at is None else noun.roles[at]
        if body == "liquid" and "particle" in tokens[at].raw:
            body = "particle"                  # the mass of a particle of liquid
        if q.measures == "mass":       # "the bowl is really light, like 50 g": the bowl's
            body = _weighed(tokens, noun.roles, i) or body
        # where a move before pouring goes to is the pouring pose: "raise it to 20 cm before pouring"
        pose = "pour" if stage[i] == "approach" and q.measures == "length" and i > 0 \
            and tokens[i - 1].word == "to" and _low_end(tokens, i) is None else POSE[stage[i]]
        move, spans = MOVE[stage[i]], set()
        if q.measures == "time" and move is None and "tilt" in choosing and tokens[i - 1].word in _SPAN:
            move, spans = "approach", {i - 1}     # "tilted to 90 degrees over 2 s": the move in carries the tilt
        param, by = parameter(q, pose, move, choosing, body)
        bound = upper_bound(tokens, i, q.measures, set(cue_of)) \
            if q.measures != "length" or "below" not in cues else set()      # not "at most 2 cm below"
        if param == "particle_mass":
            q = Quantity(q.value * 1000, q.measures, q.text)     # g to the parameter's mg
        read_too = (*CUES.get(by, ()), *ALSO_READ.get(by, ()))
        used = {k for k in near if cue_of[tokens[k].word] in read_too} | spans
        if by == "offset":          # "offset 8 cm to one side": the offset's direction, one phrase
            used |= _direction(tokens, _past(tokens, i + 2, 1, _BESIDE), i + 2, near)
        low = _low_end(tokens, i)          # "8 to 10 cm": the range, read only if one holds it
        if low is not None:
            used |= {i - 2, i - 1}
            q = Quantity(q.value, q.measures, f"{tokens[i - 2].raw} to {said}"
                         if tokens[i - 2].raw != tokens[i].raw else said)
        nearest = nearest_below(q.value, param, q.text) if bound and low is None else None
        used |= bound if nearest else set()        # "not tilted past 30 degrees": at most 30 (bounds.py)
        raw = " ".join(dict.fromkeys(tokens[k].raw for k in sorted({i, i + 1} | used)))
        at_low = None if low is None else float(tokens[low].word) * q.value / float(tokens[i].word)
        name = nearest or proposition(q, param, cues, at_low, low is not None and tokens[low].raw != tokens[i].raw)
        read[i] = Token(name or stem("hedge"), raw, tokens[i].clause, BOUND_SAID if nearest else (
            (MOSTLY if at_low is not None and not _holds(name, at_low, q.value) else tokens[i + 1].said_back)
            if name else ordinary_said(param)))    # a unit carried, said back
        dropped |= {i + 1} | used
    return [read.get(i, t) for i, t in enumerate(tokens) if i not in dropped]


#: Weights said of a body, which a mass said just after them gives in grams ("light, like 50 g").
_WEIGHTS = frozenset({"light", "heavy", "lightweight", "weighty"})


def _weighed(tokens: list[Token], roles: dict[int, str], i: int) -> str | None:
    """The bowl whose weight the clause just before the mass at `i` says,
    where the mass begins its own clause as an aside ("the bowl is really
    light, like 50 g", "a heavy pot - about 2 kg"); None otherwise."""
    first = next(k for k in range(i, -1, -1) if k == 0 or tokens[k - 1].clause != tokens[i].clause)
    if first == 0 or i - first > 2 or tokens[first - 1].word not in _WEIGHTS:
        return None
    said = tokens[first - 1].clause
    bodies = [roles[k] for k in range(first - 1, -1, -1) if k in roles and tokens[k].clause == said]
    return bodies[0] if bodies and bodies[0] in ("source", "destination") else None


def _direction(tokens: list[Token], k: int, after: int, near: list[int]) -> set[int]:
    """{k} if the word at `k`, just after an offset's number (from `after`
    on), says which way it goes ("to the side", "to one side"), not where
    the pour comes from ("from the side"); else none."""
    if k not in near or tokens[k].word != stem("side") or "from" in tokens[k].raw.split() \
            or any(tokens[m].word == "from" for m in range(after, k)):
        return set()
    return {k}


#: Words that say a number is near what it is: "from about 6 inches".
_ROUGHLY = {stem(w) for w in ("about", "around", "roughly", "approximately", "some", "maybe", "like", "nearly", "almost")}


def _poured_from(tokens: list[Token], i: int, stage: list[str]) -> bool:
    """Whether the length at `i` is said as where the pour comes from: "from" (and a word of
    roughly) before it, or "at", in a clause that pours, in the pour's stage ("pour from 40 cm",
    "pouring syrup into a tin from about 6 inches", "pour at 5 cm"; not "move in from 30 cm", refused:
    above or to the side?)."""
    k = _past(tokens, i - 1, -1, _ROUGHLY)
    return (k > 0 and tokens[k].word in ("from", "at") and stage[i] == "pour"
            and any(tokens[m].word == "pour" and tokens[m].clause == tokens[i].clause for m in range(k)))


def _bare(tokens: list[Token], i: int) -> bool:
    """Whether the length at `i` stands alone, a clause of its own in a list of the pour's values
    ("tilt 180, 20cm, fast in fast out", "90deg tilt, 5cm - drips?"): its height, as people
    listing a pour mean it (not "20 cm from the centre", nor "move in 20 cm")."""
    return all(k in (i, i + 1) or tokens[k].word in _ROUGHLY for k in range(len(tokens)) if tokens[k].clause == tokens[i].clause)


def _low_end(tokens: list[Token], i: int) -> int | None:
    """The position of the first number of a range said "8 to 10 cm" (or
    "8 or 10 cm", "between 8 and 10 cm") whose
    second number is at `i`; None if the number at `i` begins none."""
    said = tokens[i - 1].word in ("to", "or") or (tokens[i - 1].word == "and" and i >= 3
                                          and tokens[i - 3].raw == "between")
    if i >= 2 and said and re.fullmatch(NUMBER, tokens[i - 2].word) \
            and tokens[i - 2].clause == tokens[i].clause and float(tokens[i].word) != 0:
        return i - 2
    return None


#: A unit's stem -> the unit: a unit a rewrite gives ("an inch or two") is read by its stem.
_STEMS = {stem(k): k for k in UNITS}


def _unit(t: Token) -> str | None:
    """The key of UNITS that `t` says: as written ("cm"), as properties.py
    writes it, or as a rewrite gives it (its stem)."""
    return t.raw if t.raw in UNITS else (t.word if t.word in UNITS else _STEMS.get(t.word))


def _past(tokens: list[Token], j: int, step: int, words: set[str]) -> int:
    """The first position from j on, going by `step`, that holds none of `words`."""
    while 0 <= j < len(tokens) and tokens[j].word in words:
        j += step
    return j
