"""A question of what follows an outcome ("what if the milk spills?"), which
the vocabulary cannot say: it says whether an outcome happens, not what
happens after it."""
from __future__ import annotations

import re

from pantarhei.bridge.reasoning.outcome_verbs import OUTCOMES
from pantarhei.bridge.reasoning.vessels import filled

#: Why a question of what follows an outcome is refused, and what would be read.
FOLLOWS = ("asks what follows an outcome, which the vocabulary cannot say; it answers whether it "
           "happens: \"will it spill?\", \"does the bowl move?\"")


def follows(text: str) -> bool:
    """Whether normalised `text` asks what follows an outcome ("what if the
    milk spills?"), which the vocabulary cannot say."""
    verbs = "|".join(f"(?:{filled(v)})" for v, _, _ in OUTCOMES)
    return bool(re.search(rf"\b(?:what if|suppose|imagine)(?: [a-z]+){{0,4}}? (?:{verbs})\b", text))
