"""A source moved with what it holds named between the verb and where it
goes ("bring the jug of honey in slowly", "swing the pitcher of stew
over the bowl", "pull the jug of milk away fast"): the move's words stand
apart there, so the liquid is said first, in a clause of its own ("with
honey, bring the jug in slowly"), and the move is read as any other."""
from __future__ import annotations

import re

_MOVED = re.compile(
    r"\b(?P<verb>(?:bring|brings|bringing|brought|move|moves|moved|moving|swing|swings|swinging|swung|pull|pulls|pulled"
    r"|pulling|yank|yanks|yanked|yanking|take|takes|took|taking|carry|carries|carried|carrying|ease|eases|eased|easing))"
    r" (?P<the>the|my|a|an|his|her|our|this|that) (?P<source>[a-z]+) of (?:the |my )?(?P<liquid>[a-z]+(?: [a-z]+)?)"
    r" (?P<where>in|over|away|out|back|down)\b")


def liquid_carried(text: str) -> tuple[str, tuple[str, ...]]:
    """`text` (normalised) with the liquid of a source moved said first (the module's docstring), and what is said back."""
    said: list[str] = []

    def apart(m: re.Match) -> str:
        said.append(f"{m.group(0)}: read as with {m.group('liquid')}, {m.group('verb')} {m.group('the')} "
                    f"{m.group('source')} {m.group('where')}")
        return f"with {m.group('liquid')}, {m.group('verb')} {m.group('the')} {m.group('source')} {m.group('where')}"

    return _MOVED.sub(apart, text), tuple(said)
