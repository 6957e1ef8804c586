"""The bowl that strikes another, in an outcome asked: what hits a bowl, or
knocks it over, is the source ("does a heavy pot hit the bowl": a heavy
source, not a heavy destination); not one hit ("is the bowl hit"), nor
where no bowl is struck. Read by outcomes.py."""
from __future__ import annotations

import re
from functools import lru_cache

from pantarhei.bridge.reasoning.everyday import Matcher, names
from pantarhei.bridge.reasoning.vessels import destinations


@lru_cache(maxsize=None)
def containers() -> Matcher:
    """The names of everyday.txt's bowls, those poured from among them."""
    return Matcher(names("bowl"))


def striker(subject: list[str], asks: tuple[str, ...], m: re.Match, modal: bool) -> list[str]:
    """`subject` of the outcome asked by `m` (of the expectations `asks`),
    with the bowl that strikes another said as the source, where a modal
    asks it (`modal`: "does", "will")."""
    verb = next((v for g, v in m.groupdict().items() if g[0] == "v" and v), "")
    contact = asks == ("source_clear",) or (asks == ("destination_upright",) and verb.startswith("knock"))
    spans = containers().spans(subject)
    if not (contact and spans and modal) or "by" in subject:
        return subject
    after = m.string[m.end():m.end() + 60].split()[:4]
    struck = f"{verb} {m.group('rest') or ''} {' '.join(after)}"
    if not re.search(rf"\b(?:{destinations()})\b", struck):
        return subject
    end = spans[0][1]
    for first, last in spans[1:]:       # "a glass tumbler": one bowl's name
        end = last if first == end else end
    return [*subject[:end], "as", "the", "source", *subject[end:]]
