"""The units a number may be said in, each with what it measures and its
factor to the parameter's unit (theory/vocabulary/parameters.pl: mm, deg,
ms, g, count, permille), and what cannot be negative. Read by the reading
of quantities (quantities.py), of numbers in words (numerals.py) and of
misspellings (spelling.py), none of which the others need for it."""
from __future__ import annotations

#: unit word (as written, lower case) -> (what it measures, factor to the parameter's unit)
UNITS: dict[str, tuple[str, float]] = {
    **{w: ("length", 1.0) for w in ("mm", "millimetre", "millimetres", "millimeter",
                                    "millimeters")},
    **{w: ("length", 10.0) for w in ("cm", "cms", "centimetre", "centimetres", "centimeter",
                                     "centimeters")},
    **{w: ("length", 1000.0) for w in ("m", "metre", "metres", "meter", "meters")},
    **{w: ("length", 25.4) for w in ("inch", "inches")},
    **{w: ("length", 304.8) for w in ("foot", "feet", "ft")},
    **{w: ("angle", 1.0) for w in ("degree", "degrees", "deg", "degs")},
    **{w: ("time", 1.0) for w in ("ms", "millisecond", "milliseconds")},
    **{w: ("time", 1000.0) for w in ("s", "sec", "secs", "second", "seconds")},
    **{w: ("time", 60000.0) for w in ("min", "mins", "minute", "minutes")},
    **{w: ("mass", 1.0) for w in ("g", "gram", "grams", "gramme", "grammes")},
    **{w: ("mass", 1000.0) for w in ("kg", "kilo", "kilos", "kilogram", "kilograms")},
    **{w: ("count", 1.0) for w in ("particle", "particles")},
    # said, and refused naming what would be read: an amount of liquid by
    # its volume, a speed (wording.py writes "0.5 m/s" as "0.5 speed")
    **{w: ("volume", 1.0) for w in ("ml", "millilitre", "millilitres", "milliliter",
                                    "milliliters", "cl", "dl", "l", "litre", "litres", "liter",
                                    "liters", "oz", "ounce", "ounces")},
    "speed": ("speed", 1.0), "unit_turn_speed": ("turn speed", 1.0),
    # a property's name said with a number (properties.py): "a friction of 0.1"
    "unit_friction": ("friction", 1000.0), "unit_restitution": ("restitution", 1000.0),
    "unit_particles": ("count", 1.0),
}
#: What cannot be negative, by what it measures: its name in words.
POSITIVE = {"mass": "a mass", "time": "a time", "count": "a number of particles",
             "friction": "a friction", "restitution": "a bounciness",
             "volume": "an amount of liquid", "speed": "a speed", "turn speed": "a speed"}
