"""An outcome told as what keeps happening, then whether one scene is its cause asked ("when I
pour the gravy, it always seems to run down the side instead of into the dish. Is it because I
hold it too low?"): whether the outcome happens with that scene, read as "if I hold it too low,
does it run down the side instead of going into the dish?", the pour told before it kept (each
question is read alone: the outcome told is what is asked). Two causes weighed ("... or not
tilted enough?") are causes.py's."""
from __future__ import annotations

import re
from functools import lru_cache

from pantarhei.bridge.reasoning.everyday import alternation, names

#: The cause asked, in a clause of its own at the end: "... is it because I hold it too low?".
_ASKED = re.compile(r"[.?!;,]+ *(?:is|was|could|might) (?:it|that|this)(?: be)? because (?:of )?"
                    r"(?P<scene>(?:i|we|you|he|she|they|the|my|it) [a-z0-9 ]+?) *[?.!]* *$")


@lru_cache(maxsize=None)
def _told() -> re.Pattern:
    """The outcome told right before the cause ("it always seems to run down the side"), ending its
    clause, said of it, a bowl named, or a container named bare first in a note ("pitcher lip hit the
    bowl and knocked it sideways, was it because ...")."""
    bare = alternation(names("bowl"))
    return re.compile(rf"\b(?P<who>it|(?:the|my|our|your) [a-z]+|(?:^|(?<=[.;:!?] ))(?:{bare})(?: (?:spout|rim|edge|handle|base))?)"
                      r" (?:always |often |sometimes |usually |still |just )*"
                      r"(?:seems? to |tends? to )?(?P<what>[a-z][^.?!;,]{0,120}?) *$")


def cause_asked(text: str) -> tuple[str, tuple[str, ...]]:
    """`text` (normalised) with an outcome told and one cause of it asked read as whether the
    outcome happens with that cause, and what is said back; `text` as it is otherwise."""
    cause = _ASKED.search(text)
    if cause is None or " or " in cause.group("scene"):
        return text, ()
    m = _told().search(text, max(0, cause.start() - 200), cause.start())
    if m is None:
        return text, ()
    # the outcome told after a pour's liquid, of what its own clause names ("i poured the syrup from the bottle
    # and the bowl tipped over"): what the bowl did
    while re.match(r"(?:from|into|in|out of|onto|of|to|with|on|at|over|and|then|but)\b", m.group("what")) and (
            later := re.search(r"\b(?:and|then|but|so) (?=(?:it|the|my|our|your) )", m.group("what"))) is not None:
        last = _told().search(text, m.start("what") + later.end(), cause.start())
        if last is None:
            break
        m = last
    # a place it went instead of the bowl, said with no verb: "instead of into the dish"
    what = re.sub(r"\b(instead of|rather than) (?=in|into|inside)\b", r"\1 going ", m.group("what"))
    who = m.group("who") if re.match(r"(?:it|the|my|our|your)\b", m.group("who")) else f"the {m.group('who')}"
    asked = f"if {cause.group('scene')}, does {who} {what}?"
    return (f"{text[:m.start()]}{asked}",
            (f"{text[m.start():].strip(' ?.!')}: read as {asked}",))
