"""An outcome asked with another said after "without": "will the milk find its
way into the bowl without any of it going onto the tablecloth?" asks both
(whether it goes in, whether any spills), as "will it go in and will any of
it go onto the tablecloth" would; it is no goal, since the question asks
whether it happens so. Whether someone can pour so ("can I pour it in
without spilling?") is seeking.if_it_can's, "without tilting" a manner, and an
outcome wanted with "so" ("do I need to tip it so the milk goes in without
splashing") a goal."""
from __future__ import annotations

import re
from functools import lru_cache

from pantarhei.bridge.reasoning.outcome_verbs import OUTCOMES
from pantarhei.bridge.reasoning.vessels import filled


@lru_cache(maxsize=None)
def _pattern() -> re.Pattern:
    verbs = "|".join(f"(?:{filled(v)})" for v, _, _ in OUTCOMES)
    return re.compile(
        rf"(\b(?:will|would|does|do|did|might)\b(?: (?!so\b)[a-z]+){{0,12}}? (?:{verbs})\b(?: [a-z]+){{0,6}}?) without"
        rf"(?= (?:(?:any|a single|a|one) )?(?:(?:drop|bit)s? )?(?:of (?:it|them|the [a-z]+) )?(?:it |them |the [a-z]+ )?"
        rf"(?:ever |even )?(?:getting |being )?(?:{verbs})\b)")


def without_asked(text: str) -> tuple[str, tuple[str, ...]]:
    """(normalised `text` with "without" after an outcome asked said as "and will", the
    words so read)."""
    if " without " not in text or _pattern().search(text) is None:
        return text, ()
    return _pattern().sub(r"\1 and will", text), ("without",)
