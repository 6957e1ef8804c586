"""A bare number set against a number said with its unit takes that unit:
"tilted to 45 degrees instead of 90" is 90 degrees, "from 10 cm rather
than 30" is 30 cm, "45 degrees, not 90" is 90 degrees. The unit carried
is said back, so that the reading shows it."""
from __future__ import annotations

import re

from pantarhei.bridge.reasoning.units import UNITS
from pantarhei.bridge.reasoning.wording import NUMBER, Token, stem

#: The words that set one value against another, as stemmed: "instead of", "rather than",
#: "not", "vs", "versus".
_AGAINST = (("instead", "of"), ("rather", "than"), ("not",), ("vs",), ("versus",))
#: How many words may stand between the number with its unit and the words setting another against it.
_REACH = 3


def _unit(t: Token) -> bool:
    return t.raw in UNITS or t.word in UNITS or t.word in {stem(k) for k in UNITS}


def carried(tokens: list[Token]) -> list[Token]:
    """The tokens with a unit put after each bare number that follows
    words setting it against a number just said with its unit."""
    out = list(tokens)
    for i in range(len(tokens) - 1, 0, -1):
        t = tokens[i]
        if not re.fullmatch(NUMBER, t.word) or (i + 1 < len(tokens) and _unit(tokens[i + 1])):
            continue
        words = tuple(w.word for w in tokens[:i])
        cue = next((c for c in _AGAINST if words[len(words) - len(c):] == tuple(stem(w) for w in c)), None)
        if cue is None:
            continue
        k = i - len(cue) - 1            # the unit of the number before, within reach
        before = [j for j in range(k, max(0, k - _REACH) - 1, -1)
                  if j > 0 and _unit(tokens[j]) and re.fullmatch(NUMBER, tokens[j - 1].word)]
        if not before:
            continue
        unit = tokens[before[0]]
        out.insert(i + 1, Token(unit.word, unit.raw, t.clause,
                                f"the unit of {tokens[before[0] - 1].raw} {unit.raw}, said before"))
    return out
