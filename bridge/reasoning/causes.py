"""Two causes weighed after a pour told ("Gripper tilts the canister to 110 degrees but nothing
comes out - is the canister too full or not tilted enough?", "would lowering it fix that, or was
it the speed?"): which of them it was is the answer's to tell, not a scene to read, so the clause
that weighs them is read as nothing and said back, and the pour told before it is read. Said
alone, with no pour told before it, it is left as written (and refused as before)."""
from __future__ import annotations

import re

_SAID = "read as nothing: which cause it was is the answer's to tell; the pour told is read"

#: "is the canister too full or not tilted enough?", "was it too high or too fast?", "was it the
#: speed or was I too far off to one side?": a clause of
#: its own, at the end, its two causes said with "too", "not", "because" or "the".
_EITHER = re.compile(r"(?:(?<=[-,;:.!?\u2013\u2014] )|(?<= - ))(?:is|was|are|were) (?:it|that|this|the [a-z]+)"
                     r"(?: (?:because(?: of)?|due to))? (?:too|not|the|a|an) [a-z ]+? or (?:(?:is|was) (?:it|i|we) |(?:am|were) (?:i|we) )?"
                     r"(?:because(?: of)? )?(?:too|not|the|a|an) [a-z ]+?\s*[?.!]*$")
#: ", or was it the speed?": a second cause asked after a question of the first.
_OR_WAS = re.compile(r"(?:,| ,)? or (?:was|is) it (?:because of |due to )?(?:the|my|a|an|too) [a-z ]+?\s*[?.!]*$")


def causes_weighed(text: str) -> tuple[str, tuple[str, ...]]:
    """`text` (normalised) without a clause at its end that weighs two causes of a pour told
    before it, and what is said back of it."""
    for pattern in (_EITHER, _OR_WAS):
        m = pattern.search(text)
        if m and re.search(r"[a-z]", text[:m.start()]):
            said = m.group(0).strip(" ,?.!")
            return text[:m.start()].rstrip(" ,-") + "?", (f"{said}: {_SAID}",)
    return text, ()
