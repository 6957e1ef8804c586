"""How fast the liquid flows, asked beside an outcome: "will it come out of
the saucepan slower and land more in the bowl?". No expectation says how
fast the liquid leaves the source, only whether it does: the clause of its
rate is heard, said back as not asked, and the outcome beside it is what is
asked ("land more in the bowl": whether it goes in). Set against another
liquid ("does honey come out slower than water"), it asks whether the first
comes out at all, what the vocabulary says of the two, the rate said back.
Asked alone ("will it come out slower?"), it is refused, saying what would
be read."""
from __future__ import annotations

import re

from pantarhei.bridge.errors import UserError

#: A flow out of the source said with how fast: "will it come out of the saucepan slower",
#: "does the honey pour out more slowly" (not a move of the source: "move in slower").
_RATE = re.compile(
    r"\b(?P<aux>will|would|does|do|did|could|might|may) (?P<who>(?:the |any |some |most )?(?:of it|[a-z]+) )?"
    r"(?:come|comes|pour|pours|flow|flows|run|runs|drain|drains|trickle|trickles) out"
    r"(?: of (?:the |a |an |my |your |its |this |that )?(?:[a-z]+ )?[a-z]+)?"
    r" (?:a (?:lot|bit|little) |much |even )?(?:slower|faster|quicker|more slowly|more quickly|less quickly)\b")

#: Why a rate asked alone is refused, and what would be read.
RATE_ALONE = ("how fast the liquid flows is no expectation the vocabulary checks: it answers whether it "
              "comes out (\"does it come out?\") or goes in (\"does it go in?\")")


def rates(text: str) -> tuple[str, tuple[str, ...], tuple[str, ...]]:
    """(normalised `text` with each clause of a flow's rate heard as an outcome said, its
    subject left, the clauses, what is said back of them)."""
    # set against another liquid ("does honey come out slower than water"): what differs that the
    # vocabulary says is whether each comes out, asked of the first as "does syrup spill less than water" is
    # ("tht" and "thn" as a phone types than)
    text_said = text
    compared = [m for m in _RATE.finditer(text) if re.match(r" (?:than|then|tht|thn) ", text[m.end():])]
    for m in reversed(compared):
        fewer = "less" if re.search(r"slower|slowly|less", m.group(0)) else "more"
        rest = re.sub(r"^ \w+ ", " than ", text[m.end():])
        text = f"{text[:m.start()]}{m.group(0)[:m.group(0).rindex(' out') + 4]} {fewer}{rest}"
    said = tuple(f"{m.group(0)} {text_said[m.end():].split()[0]}: read as whether it comes out: {RATE_ALONE.split(':')[0]}"
                 for m in compared)
    if said:
        return text, (), said
    found = [m.group(0) for m in _RATE.finditer(text)]
    if not found:
        return text, (), ()
    # the subject stays the scene's: "does the syrup pour out slower" is of a sticky liquid
    return (_RATE.sub(lambda m: f" {m.group('who') or ''} outcome ", text), tuple(found),
            tuple(f"{said}: not asked: {RATE_ALONE.split(':')[0]}" for said in found))


def refuse_alone(rate: tuple[str, ...], asked: tuple[str, ...], goals: tuple[str, ...]) -> None:
    """UserError where a flow's rate is all that is asked."""
    if rate and not asked and not goals:
        raise UserError(f"\"{rate[0]}\": {RATE_ALONE}")
