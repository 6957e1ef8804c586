"""Whether a pour is safe, asked with the worry behind it: "is it ok to pour
from high up or will the bowl tip over?" (or "... from the side? It will
spill?", the worry asked next; or "is it dangerous, will the bowl fall?") asks the worry it names (whether the bowl
tips), not the three expectations "is it ok" asks alone."""
from __future__ import annotations

import re

#: Safety asked, then a worry joined by "or", or asked next: "is it ok to ... or will the bowl skid".
_WORRY = re.compile(r"\b(?:is|would|will|can|could)\b[^?.!;]*?\b(?:ok|okay|safe|safely|fine|alright|all right"
                    r"|dangerous|risky|unsafe)\b(?:[^?.!;]*?(?:\bor |[?.!;,]+ +(?:it |the \w+ )?)"
                    # (the worry said right after it, as learners say it: "is dangerous it will fall?")
                    r"| (?:that )?it (?=will|would|might|could))(?:will|would|does|do|is|could|might|can)\b")


def worried(said: str, asked: list[str], clauses: list[tuple[str, ...]], safe: tuple[str, ...]) -> list[str]:
    """`asked`, or where normalised `said` asks whether a pour is safe (`safe`: what that
    asks) with a worry joined by "or", what the clauses before and after the safety asked
    (`clauses`: the expectations each clause asked, in order)."""
    at = next((i for i, names in enumerate(clauses) if names == safe), None)
    if at is None or at == len(clauses) - 1 or not _WORRY.search(said):
        return asked
    return list(dict.fromkeys(n for names in (*clauses[:at], *clauses[at + 1:]) for n in names))
