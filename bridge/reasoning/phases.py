"""When a stillness asked about is asked of: the bowl staying still is
three expectations, one a phase (the move in, the move away, the settling),
and a question that names the phase asks that one alone: "does the bowl
slide when the cup comes in" (the move in), "will it move when the arm
goes away", "during the retreat phase" (the move away), "while everything
settles" (the settling), said after the outcome or before it, in a clause
of its own ("when I take the bottle away, does the bowl move?"). "Still in the same
spot after the jug is taken away" asks all three: the bowl has not moved
by then. A phase said by a clause that ends there is heard with the
outcome; one going on ("when the cup comes in fast") is left for the
scene too. What stays in the bowl is judged after the move away, so that
move said with it is heard ("does it slosh back out once the cup is
gone").

A stillness wanted right after a move said ("the fastest I can move away
without the bowl sliding", "move the cup in and out without ...", "move
the pitcher away after pouring so the glass bowl doesn't wobble") is
wanted of that move's phase.

And a place the liquid may land instead of the bowl, asked beside it:
"does it go in the bowl or on the table", and wanted not to ("so it goes
in the bowl and not outside"), asks whether it spills too; the bowl said
beside a spill ("end up on the table instead of in the dish") whether it
goes in too; and
staying said after going in ("does it go in and stay") asks whether it
stays in the bowl."""
from __future__ import annotations

import re

from pantarhei.bridge.reasoning.cued import Cued
from pantarhei.bridge.reasoning.moves import DONE
from pantarhei.bridge.reasoning.vessels import liquids

STILL = ("destination_still_approach", "destination_still_retreat", "destination_still_settle")

_WHO = r"(?:(?:the|a|an|my|your|its|this|that) )?(?:[a-z]+ )?(?:[a-z]+)"
_WHEN = r"(?:when|while|whilst|as|once)"
#: What is moved, said between the verb and its particle: "when you pull the cup away".
_WHAT = r"(?:(?:the|a|an|its|my|your|this|that) [a-z]+ )?"
#: (the phase, the words that say it after an outcome asked)
_PHASES = (
    ("destination_still_approach",
     rf"{_WHEN} {_WHO} (?:com(?:e|es|ing)|mov(?:e|es|ing)|is (?:brought|moved)|gets? (?:brought|moved)"
     rf"|swing(?:s|ing)?|go(?:es|ing)?) in\b(?: to pour\b)?"
     rf"|{_WHEN} {_WHO} approach(?:es|ing)?\b|(?:during|in) the approach(?: phase| stage| move)?\b"
     r"|on (?:its|the) way in\b"),
    ("destination_still_retreat",
     rf"{_WHEN} {_WHO} (?:go(?:es|ing)?|mov(?:e|es|ing)|pull(?:s|ing)?|back(?:s|ing)?|draw(?:s|ing)?|tak(?:e|es|ing)"
     rf"|(?:is|gets?) (?:taken|moved|pulled|drawn)) {_WHAT}(?:back )?away\b"
     rf"|{_WHEN} {_WHO} (?:retreat(?:s|ing)?|withdraw(?:s|ing)?|pull(?:s|ing)? back)\b"
     r"|(?:during|in) the retreat(?: phase| stage| move)?\b|on (?:its|the) way (?:out|back)\b"),
    ("destination_still_settle",          # everything settling, the source gone: "while everything settles"
     rf"{_WHEN} (?:everything|it all|things|it|the (?:liquid|water|bowl|[a-z]+)) (?:settles|settle|is settling"
     r"|settling|comes to rest|is coming to rest)\b|(?:during|in) the settl(?:e|ing)(?: phase| stage)?\b"),
    (("destination_still_retreat", "destination_still_settle"),      # after the pour: the move away and after
     r"afterwards?\b|after (?:the )?pour(?:ing)?\b(?! (?:ends|is over|is done|has ended|finishes)\b)"
     # done pouring: "after I'm done pouring", "once the jar stops pouring" (moves.py's)
     rf"|(?:after|once){DONE}"),
    (None,      # after the move away: by then, every phase is past
     rf"(?:after|once) {_WHO} (?:is|gets?|has been) (?:taken|moved|pulled|drawn) away\b"
     rf"|(?:after|once) {_WHO} (?:goes|moves|has gone|has moved|pulls) away\b|after the retreat\b"
     rf"|(?:after|once) {_WHO} (?:is|has) gone\b"),
)
#: What stays in the bowl is judged once everything settles: the move away said with it is heard
#: ("does it slosh back out once the cup is gone").
_SETTLED = _PHASES[-1][1]
#: Where a clause ends: the phase heard with its outcome is all of it.
_ENDS = r"(?= *(?:[?.!,;:]|$| or\b| and\b| lol\b))"
#: A place the liquid may land said beside the bowl it goes in: the spill asked too.
_ELSEWHERE = Cued(r"\boutcome (?P<said>or (?:also |maybe |even )?(?:on|onto|all over|over) (?:the |a |my )?"
                  r"(?:table|counter|floor|worktop|countertop|ground|bench)s?\b"
                  # not there: "go in the bowl and not outside", "and not on the table"
                  r"|(?:and|but|,)? ?not (?:outside|(?:on|onto|all over) (?:the |a |my )?"
                  r"(?:table|counter|floor|worktop|countertop|ground|bench|tablecloth)s?|everywhere)(?= *(?:[?.!,;]|$)))",
                  ("outcome or ", "not "))
#: The bowl said as where it should have gone, beside a spill asked: "will some of it end up on the
#: table instead of in the dish?" asks whether it goes in too.
_INSTEAD = Cued(r"\boutcome (?P<said>(?:instead of|rather than) (?:going )?(?:in|into|inside) (?:the |a |an |my )?"
                r"(?:bowl|dish|destination|glass|pot|basin|container|mug|cup)s?)(?= *(?:[?.!,;]|$))", ("instead", "rather"))

#: Staying said after going in, with no place: it stays where it went.
_STAYS = Cued(r"\boutcome (?P<said>(?:,? ?and|,) (?:then )?(?:it )?(?:stay|stays|remain|remains)(?: there)?)"
              r"(?= *(?:[?.!]|$))", ("stay", "remain"))


def during(text: str, asked: list[str]) -> tuple[str, list[str], list[str]]:
    """`text` (after outcomes.hear took out what it asks: "outcome" stands
    for each clause), the expectations `asked` with the phase it names, and
    the phrases heard."""
    heard: list[str] = []
    if _ELSEWHERE.search(text) and "no_spill" not in asked and any(
            n in asked for n in ("liquid_enters_destination", "liquid_remains_in_destination")):
        heard += [m.group("said") for m in _ELSEWHERE.pattern.finditer(text)]
        asked = [*asked, "no_spill"]
        text = _ELSEWHERE.pattern.sub("outcome", text)
    instead = _INSTEAD.search(text)
    if instead and "no_spill" in asked and "liquid_enters_destination" not in asked:
        heard.append(instead.group("said"))
        asked = [*asked, "liquid_enters_destination"]
        text = text[:instead.start("said")] + text[instead.end():]
    stays = _STAYS.search(text)         # "does it go in the bowl and stay": and stay in it
    if stays and "liquid_enters_destination" in asked:
        heard.append(stays.group("said"))
        asked = [*asked, *(n for n in ("liquid_remains_in_destination",) if n not in asked)]
        text = text[:stays.start("said")] + text[stays.end():]
    if not all(n in asked for n in STILL):
        m = re.search(rf"\boutcome (?P<said>{_SETTLED}){_ENDS}", text) if "liquid_remains_in_destination" in asked else None
        if m:
            heard.append(m.group("said"))
            text = text[:m.start("said")] + text[m.end():]
        return text, asked, heard
    for phase, words in _PHASES:
        after = re.search(rf"\boutcome(?P<gap>(?: ,)?(?: (?:at all|all|around|about|much|even))*) (?P<said>{words})", text)
        # or said first, its clause before the outcome's: "when the cup comes in, does the bowl slide?"
        m = after or re.search(rf"(?:^|[.?!;:] ) *(?P<said>{words})(?P<more>[^,.?!;:]*) *, *(?:then )?(?:[a-z]+ ){{0,3}}?"
                               r"outcome\b", text)
        if m is None:
            continue
        if phase == "destination_still_approach" and liquids().spans(m.group("said").split()[1:4]):
            heard.append(m.group("said"))       # "when the cream goes in": while pouring, no phase of its own
            text = text[:m.start("said")] + text[m.end("said"):]
            return text, asked, heard
        if phase is not None:
            asked = [n for n in asked if n not in STILL or n in (phase if isinstance(phase, tuple) else (phase,))]
        if re.match(_ENDS, text[m.end():]) if after else not m.group("more").strip():
            heard.append(m.group("said"))       # the clause is the phase's alone
            text = text[:m.start("said")] + text[m.end() if after else m.end("said"):]
        return text, asked, heard
    return text, asked, heard


#: A move said right before a stillness wanted ("move away without the bowl sliding"), by its way.
_MOVED = re.compile(r"\b(?:(?P<verb>mov(?:e|es|ing)|go(?:es|ing)?|com(?:e|es|ing)|pull(?:s|ing)?|bring(?:s|ing)?|draw(?:s|ing)?)"
                    r"(?: (?:it|them|(?:the|my|your|a) [a-z]+))?(?P<way> in and (?:out|away|back)| in| away| back| out)"
                    r"|(?P<named>retreat|withdraw|approach)(?:s|ing)?)(?: (?:fast|quickly|slowly|quick|slow))?(?: after (?:the )?pour(?:ing)?)?"
                    r"(?: (?:it|they|(?:the|my|a) (?:[a-z]+ )?[a-z]+)(?: does| do| will| would)?)? outcome\b")
_WAYS = {"in": ("destination_still_approach",), "approach": ("destination_still_approach",)}


def moving(text: str, goals: list[str]) -> list[str]:
    """`goals` with a stillness wanted right after a move said in `text` (after outcomes.hear
    took out the goal: "outcome" stands for it) wanted of that move's phase alone."""
    m = _MOVED.search(text)
    if m is None or not all(n in goals for n in STILL):
        return goals
    way = (m.group("way") or m.group("named")).strip()
    phases = (STILL[:2] if way.startswith("in and") else
              _WAYS.get(way, ("destination_still_retreat",)))
    return [n for n in goals if n not in STILL or n in phases]
