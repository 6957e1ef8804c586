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
is; a time the move into the pouring pose or out of it; a mass the bowl it
qualifies; a count the particles of liquid. The value is converted to the
parameter's unit (theory/vocabulary/parameters.pl) and read as the
proposition of that parameter whose range holds it; a number no range
holds, or a measure no parameter takes ("pour for 3 seconds": pouring has
no duration of its own), is refused naming the ranges there are.
"""
from __future__ import annotations

from dataclasses import dataclass

from pantarhei.bridge.errors import UserError
from pantarhei.theory.lexicon import load_vocabulary

#: unit word (as written, lower case) -> (what it measures, factor to the parameter's unit)
UNITS: dict[str, tuple[str, float]] = {
    **{w: ("length", 1.0) for w in ("mm", "millimetre", "millimetres", "millimeter",
                                    "millimeters")},
    **{w: ("length", 10.0) for w in ("cm", "centimetre", "centimetres", "centimeter",
                                     "centimeters")},
    **{w: ("length", 1000.0) for w in ("m", "metre", "metres", "meter", "meters")},
    **{w: ("length", 25.4) for w in ("inch", "inches")},
    **{w: ("length", 304.8) for w in ("foot", "feet", "ft")},
    **{w: ("angle", 1.0) for w in ("degree", "degrees", "deg", "degs")},
    **{w: ("time", 1.0) for w in ("ms", "millisecond", "milliseconds")},
    **{w: ("time", 1000.0) for w in ("s", "sec", "secs", "second", "seconds")},
    **{w: ("mass", 1.0) for w in ("g", "gram", "grams", "gramme", "grammes")},
    **{w: ("mass", 1000.0) for w in ("kg", "kilo", "kilos", "kilogram", "kilograms")},
    **{w: ("count", 1.0) for w in ("particle", "particles")},
}

#: The words beside a number that pick its parameter, by what they choose;
#: they are read with the number (a height's with the rim it is measured from).
CUES = {
    "roll": ("roll", "sideways"),
    "pitch": ("tilt", "pitch", "angle"),
    "side": ("side", "away", "far", "off", "distance"),
    "offset": ("sideways", "offset"),
    "height": ("high", "above", "below", "height", "up", "rim"),
}
#: The words read with a number besides its cues: a roll is "tilted sideways".
ALSO_READ = {"roll": ("tilt",)}
#: How far from a number its cue words may stand.
REACH = 4


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
    the body `body`; UserError for a measure no parameter takes there."""
    if q.measures == "angle":
        return (f"{pose}_roll", "roll") if cues & set(CUES["roll"]) else (f"{pose}_pitch", "pitch")
    if q.measures == "length":
        if cues & set(CUES["side"]):
            return f"{pose}_x", "side"
        if cues & {"offset"} or (cues & {"sideways"} and not cues & set(CUES["height"])):
            return f"{pose}_y", "offset"
        if not cues & set(CUES["height"]):
            raise UserError(f"\"{q.text}\": above the destination, or to its side? say "
                            f"\"{q.text} above\" or \"{q.text} to the side\"")
        return f"{pose}_z", "height"
    if q.measures == "time":
        if move is None:
            raise UserError(f"\"{q.text}\": pouring takes no time of its own; say how long "
                            "the source takes to move in (before pouring) or to move away "
                            "(after pouring)")
        return f"{move}_duration", ""
    if q.measures == "mass":
        if body not in ("source", "destination"):
            raise UserError(f"\"{q.text}\": the mass of which bowl? say \"a source bowl of "
                            f"{q.text}\" or \"a destination bowl of {q.text}\"")
        return f"{body}_mass", ""
    return "particle_count", ""


def proposition(q: Quantity, param: str, cues: set[str]) -> str:
    """The proposition whose range of `param` holds `q` (a height said
    "below" the rim is under it: negative); UserError naming the ranges
    there are if none does."""
    vocab = load_vocabulary()
    unit = next(p.unit for p in vocab.parameters if p.name == param)
    v = -q.value if param.endswith("_z") and "below" in cues else q.value
    ranges = sorted((p.model.low, p.model.high, n) for n, p in vocab.propositions.items()
                    if p.model.kind == "uniform" and p.model.param == param)
    holding = [name for low, high, name in ranges if low <= v <= high]
    if holding:     # on the bound of two ranges, the upper: 0 mm above the rim is low
        return holding[-1]
    said = "; ".join(f"{n} {lo} to {hi} {unit}" for lo, hi, n in ranges)
    raise UserError(f"\"{q.text}\" is {v:g} {unit} of {param}, which no proposition holds"
                    + (f" ({said}): say one of these" if said else
                       ": the vocabulary has no proposition of it"))
