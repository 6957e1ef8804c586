"""Where a question chooses between two liquids by name ("honey or water",
"milk or oil"), or sets them against each other ("pouring water vs
pouring olive oil"): the phrases of the everyday word list that name a liquid,
and the value (the list's section) each is read as. choices.py refuses
such a choice without a goal; compared_or.py leaves it to choices.py."""
from __future__ import annotations

import re
from functools import lru_cache

from pantarhei.bridge.reasoning.everyday import sections


@lru_cache(maxsize=None)
def _liquids() -> tuple[re.Pattern, dict[str, int], re.Pattern, re.Pattern]:
    """The phrases naming a liquid, chosen between as one pattern, the
    section (the value) each is read as, two set against each other, and
    two poured at once."""
    value: dict[str, int] = {}
    for k, s in enumerate(sections()):
        if s.words.endswith("liquid") and s.said_back != "read as the liquid poured":
            for p in s.phrases:
                value.setdefault(p, k)
    names = "|".join(re.escape(p) for p in sorted(value, key=lambda p: (-len(p), p)))
    said = rf"(?:a |an |some |plain |the )?({names})s?"
    return re.compile(rf"\b{said} ?,? or {said}\b"), value, re.compile(
        rf"\b(?:pouring |pour )?{said} ?,? (?:vs\.?|versus|compared (?:to|with)|against) (?:pouring |pour )?{said}\b"), re.compile(
        rf"\bpour(?:s|ed|ing)? {said} and {said}\b")


def chosen_liquids(text: str) -> re.Match | None:
    """Where `text` (normalised) chooses between two liquids ("honey or water"), or None."""
    return _liquids()[0].search(text)


def set_against_liquids(text: str) -> re.Match | None:
    """Where `text` (normalised) sets two liquids against each other ("water vs olive oil"), or None."""
    return _liquids()[2].search(text)


def poured_together(text: str) -> re.Match | None:
    """Where `text` (normalised) pours two liquids at once ("pour bleach and vinegar into the same bowl"), or None."""
    return _liquids()[3].search(text)


def liquid_values() -> dict[str, int]:
    """Each phrase naming a liquid, and the section of the everyday word
    list (the value) it is read as."""
    return _liquids()[1]


def read_alike(m: re.Match) -> bool:
    """Whether the two liquids of `m` (chosen_liquids', set_against_liquids' or poured_together's
    match) are read as one value ("water or milk": an ordinary liquid both)."""
    value = liquid_values()
    return sections()[value[m.group(1)]].words == sections()[value[m.group(2)]].words
