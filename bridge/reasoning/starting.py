"""An outcome said as starting ("the bowl started to wobble", "it began
sliding", "does the bowl start to tip if ..."): read as the outcome itself,
told or asked as it is said ("the bowl wobbled", "does the bowl tip"), and
said back. The vocabulary judges whether an outcome happens, not when it
begins. "Before it starts to splash" is left as it is: the most that can be
done before it, asked (outcomes.py)."""
from __future__ import annotations

import re

from pantarhei.bridge.reasoning.outcome_verbs import outcome_verb

#: The told form of an outcome's verb, where it is not the verb and "ed".
_TOLD = {"slide": "slid", "tip": "tipped", "drip": "dripped", "slip": "slipped", "spin": "spun", "run": "ran",
         "fall": "fell", "shake": "shook", "come": "came", "go": "went", "skid": "skidded", "slop": "slopped"}
_STARTED = re.compile(r"\b(?P<start>started|began|begun|starts|begins|start|begin) (?:to (?P<verb>[a-z]+)\b|(?P<ing>[a-z]+)ing\b)")


def started_as_done(text: str) -> tuple[str, tuple[str, ...]]:
    """(normalised `text` with each outcome said as starting said as the outcome, what is said back)."""
    if not re.search(r"\b(?:start|began|begin)", text):
        return text, ()
    said: list[str] = []

    def done(m: re.Match) -> str:
        verb = m.group("verb") or _base(m.group("ing"))
        if not verb or not outcome_verb(verb) or re.search(r"\bbefore (?:it|they|the \w+|anything|any of it) $", text[:m.start()]):
            return m.group(0)           # "the fastest I can tip it before it starts to splash": the most asked
        told = m.group("start") in ("started", "began", "begun")
        out = (_TOLD.get(verb) or (verb + "d" if verb.endswith("e") else verb + "ed")) if told else \
            (verb + ("es" if re.search(r"(?:sh|ch|ss|x)$", verb) else "s") if m.group("start") in ("starts", "begins") else verb)
        said.append(f"{m.group(0)}: read as {out}")
        return out
    return _STARTED.sub(done, text), tuple(said)


def _base(stem: str | None) -> str | None:
    """The plain verb of an "-ing" form's stem: "wobbl" wobble, "slid" slide, "tipp" tip."""
    if stem is None:
        return None
    for verb in (stem + "e", stem[:-1] if len(stem) > 3 and stem[-1] == stem[-2] else None, stem):
        if verb and outcome_verb(verb):
            return verb
    return None
