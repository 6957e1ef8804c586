"""A choice between two liquids that the vocabulary reads as different
values ("what is better to pour, honey or water?": a sticky liquid or an
ordinary one), asked without a goal, is two questions: it is refused,
asking for one of them, as "high or low" is (reading.py), where the first
would otherwise be read alone and the second, the ordinary liquid, said
nothing of. With a goal ("I want none on the table: honey or water?")
the goal is what is asked, and it is left to the reader."""
from __future__ import annotations

import re
from functools import lru_cache

from pantarhei.bridge.errors import UserError
from pantarhei.bridge.reasoning.everyday import sections


@lru_cache(maxsize=None)
def _liquids() -> tuple[re.Pattern, dict[str, int]]:
    """The phrases naming a liquid, as one pattern, and the section (the value) each is read as."""
    value: dict[str, int] = {}
    for k, s in enumerate(sections()):
        if s.words.endswith("liquid") and s.said_back != "read as the liquid poured":
            for p in s.phrases:
                value.setdefault(p, k)
    names = "|".join(re.escape(p) for p in sorted(value, key=lambda p: (-len(p), p)))
    said = rf"(?:a |an |some |plain |the )?({names})s?"
    return re.compile(rf"\b{said} ?,? or {said}\b"), value


def chosen_liquids(text: str) -> re.Match | None:
    """Where `text` (normalised) chooses between two liquids ("honey or water"), or None."""
    return _liquids()[0].search(text)


def refuse_choice(text: str) -> None:
    """UserError where `text` (normalised) chooses between two liquids read as different values, with no goal."""
    value = _liquids()[1]
    m = chosen_liquids(text)
    if m is None or sections()[value[m.group(1)]].words == sections()[value[m.group(2)]].words:
        return                                  # "water or milk": both read as an ordinary liquid
    from pantarhei.bridge.reasoning.outcomes import hear       # here: outcomes reads words with wording.py
    if hear(text).goals:
        return
    said = {k: s.said_back.removeprefix("read as ").split(":")[0] or "an ordinary liquid"
            for k, s in enumerate(sections())}
    raise UserError(f"\"{m.group(0)}\" chooses between two liquids, {m.group(1)} ({said[value[m.group(1)]]}) "
                    f"and {m.group(2)} ({said[value[m.group(2)]]}): ask about one of them (\"if I pour "
                    f"{m.group(1)}, will it splash?\")")
