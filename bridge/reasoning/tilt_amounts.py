"""How far the source is tilted, said by how much tilt or how strong it
is, as learners of English say it, part of words.py's PHRASES: "with much
angle", "with a lot of angle", "a strong tilt", "make the tilting of the
bottle very strong" are steeply tilted, as "tilt it hard" is
(everyday.txt); "a little angle" or "a weak tilt" slightly tilted ("a big tilt"
is refused as a size is: everyday.txt reads it first). An angle
asked for ("how much angle") is a value asked, not said: left to be read
as one."""
from __future__ import annotations

#: Much of a tilt: "much", "a lot of", "a big".
_MUCH = r"(?:much|a lot of|lots of|a great|great|a strong|strong|plenty of)"
_LITTLE = r"(?:a little|little|a weak|weak)"
_TILTING = r"(?:angle|tilt|tilting|tip|tipping|inclination)"

TILT_AMOUNTS: tuple[tuple, ...] = (
    ("steeply tilted", (rf"re(angle|tilt|tip|inclin):(?<!how )\b(?:with |at )?{_MUCH} {_TILTING}\b",
                        r"re(strong):\b(?:make|makes|making|made) the (?:tilt|tilting|tipping|angle)(?: of (?:it|the \w+))?"
                        r" (?:very |really |so |more |too )?strong(?:er)?\b")),
    ("slightly tilted", (rf"re(angle|tilt|tip|inclin):(?<!how )\b(?:with |at )?{_LITTLE} {_TILTING}\b",)),
)
