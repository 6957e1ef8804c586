"""An earlier pour told before the question ("last time I poured from
20 cm and it splashed, if I go down to 8 cm is it better?"): each question
is read alone, so the pour told is not read, and said back; "is it better"
after it asks about the outcome told (whether it splashes), not the three
expectations of "is it better to"."""
from __future__ import annotations

import re

#: When the pour told was: "last time", "yesterday", "previously", "the other day".
_WHEN = (r"(?:the )?(?:last time|previous time|first time|other day|yesterday|previously|earlier|before"
         r"|last night|last week|this morning)")
#: Its outcome, told in the past ("and it splashed"), with the question that asks it again.
_TOLD = {"splash": "does it splash", "spill": "does it spill", "drip": "does it drip",
         "overflow": "does it overflow", "slosh": "does it slosh out", "tip": "does the bowl tip over",
         "slid": "does the bowl slide", "slide": "does the bowl slide", "mov": "does the bowl move",
         "miss": "does it miss"}
_POUR = re.compile(
    rf"^{_WHEN},? (?:when )?(?:i|we|you|they|he|she|the robot|my robot) (?:poured|pour|held|tilted|tipped|did it)"
    r"(?P<how>[^,;.?!]*?)(?: and (?:it|the (?:bowl|liquid|water|milk|[a-z]+)) (?P<out>splash|spill|spilt|drip|overflow|slosh|tip|slid"
    r"|mov|miss)\w*(?: over| out| everywhere)?)? *[,;.] *(?=(?:now|this time|if|so|what|will|would|does|do|is|can|should)\b)")
#: Asked whether the pour now is better: about the outcome told.
_BETTER = re.compile(r"\b(?:is|will|would) (?:it|that|this) (?:be )?(?:any )?better\b")


def told(text: str) -> tuple[str, tuple[str, ...]]:
    """`text` (normalised) without an earlier pour told at its start, and
    what is said back of it; `text` as it is where it tells none."""
    m = _POUR.match(text)
    if m is None:
        return text, ()
    rest = text[m.end():]
    said = [f"{m.group(0).strip(' ,;.')}: read as nothing: an earlier pour, told; the answer is for the one asked"]
    out = m.group("out")
    if out and _BETTER.search(rest):
        verb = "spill" if out == "spilt" else out
        rest = _BETTER.sub(_TOLD[verb], rest, count=1)
        said.append(f"better: read as {_TOLD[verb]}, as the earlier pour did")
    return rest, tuple(said)
