"""Which of two scenes set against each other an outcome happens to, or
happens to more ("silicone bowl vs enamel bowl - which one slides more"):
asked of the scene said first, the other being said back as not read
(comparisons.py), as "does it slide"."""
from __future__ import annotations

import re

_SET_AGAINST = re.compile(r"\b(?:vs|versus|compared (?:to|with))\b")
_WHICH = re.compile(r"\bwhich (?:one|of them|of the two|bowl|cup)(?: of them)? (?:will |would |is going to )?"
                    r"(?P<verb>[a-z]+?)(?P<ending>es|s)?\b(?P<how> (?:more|less|the most|the least|most|least|worse|better)\b)?")


def which_one(text: str) -> tuple[str, tuple[str, ...]]:
    """`text` (normalised) with "which one <outcome> more", after two scenes
    set against each other, read as "does it <outcome>", and what is said back."""
    set_against = _SET_AGAINST.search(text)
    m = _WHICH.search(text, set_against.end()) if set_against else None
    if m is None:
        return text, ()
    verb = m.group("verb") + ("e" if m.group("ending") == "es" and not re.search(r"(?:sh|ch|ss|x)$", m.group("verb"))
                              else "")
    said = f"does it {verb}"
    return (text[:m.start()] + said + text[m.end():],
            (f"{m.group(0)}: read as {said}, of the one said first",))
