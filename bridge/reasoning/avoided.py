"""An outcome told as happening, then a value asked that avoids it ("my robot
hits the bowl with the cup every time, what approach speed avoids that", "the
bowl slides, which height stops that"): the outcome not happening is the goal,
read as "what approach speed so that my robot does not hit the bowl with the
cup", and said back; so is a pour told with what it did, then what to change
asked ("i poured too fast and the bowl flipped, what should i change"), the
pour told not read, and the most a value may be before an outcome ("how far
from the centre can I pour before the liquid misses")."""
from __future__ import annotations

import re

#: The outcomes told, by the forms they are told in -> the form a negation takes.
_VERBS = {"hits": "hit", "hit": "hit", "bumps": "bump", "bumped": "bump", "knocks": "knock", "knocked": "knock",
          "touches": "touch", "touched": "touch", "strikes": "strike", "struck": "strike", "scrapes": "scrape",
          "scraped": "scrape", "clinks": "clink", "clinked": "clink", "bangs": "bang", "banged": "bang",
          "slides": "slide", "slid": "slide", "moves": "move", "moved": "move", "shifts": "shift", "shifted": "shift",
          "tips": "tip", "tipped": "tip", "flips": "flip", "flipped": "flip", "falls": "fall", "fell": "fall",
          "spills": "spill", "spilled": "spill", "spilt": "spill", "splashes": "splash", "splashed": "splash",
          "drips": "drip", "dripped": "drip", "overflows": "overflow", "overflowed": "overflow",
          "misses": "miss", "missed": "miss"}
#: ... and those the most asked before may name too ("how high can I go before it slops out", "... goes over").
_BEFORE = {**_VERBS, "slops": "slop", "sloshes": "slosh", "goes over": "go over", "goes out": "go out"}     # ("before it goes over the sides")
#: (Not an outcome not wanted, said first: "no spills, what tilt should i use" is goal_wordings.py's.)
_TOLD = re.compile(
    rf"^(?!(?:no|not|never|without) )(?P<who>(?:[a-z']+ ){{1,3}}?)(?:keeps? |always )?(?P<verb>{'|'.join(_VERBS)}|keeps? (?:{'|'.join(v + 'ing' for v in ('hitt', 'bump', 'knock', 'slid', 'mov', 'tipp', 'spill', 'splash', 'dripp'))}))"
    r"(?P<rest>(?: [a-z']+)*?) *[,;.:-]+ *(?P<ask>(?:what|which)(?: [a-z]+){0,3}?)"
    r"(?: (?:avoids|would avoid|will avoid|prevents|would prevent|stops|would stop|fixes|would fix|solves|would solve)"
    r" (?:that|this|it)| should (?:i|we|you) (?:set|use|choose|pick|try|go with))(?P<end> *[?.!]* *)$")
#: A pour told in the past with what it did, then what to change asked ("i poured too fast and
#: the bowl flipped, what should i change"): the pour told is not read, its outcome not
#: happening is wanted.
_CHANGE = re.compile(
    rf"^(?P<pour>(?:last time |yesterday |earlier )?(?:i|we|the robot|my robot|the arm|(?:my |our |the |a )?(?:kid|son|daughter|child"
    rf"|friend|partner)|(?:my |our |the |a )?(?:robot|arm|gripper)|he|she|they) (?:keeps? |always )?(?:poured|pours|pouring|tilted|tipped"
    rf"|held|moved|moves|did|pulls|pulled|retracts|retracted)"
    rf"[^,;.?!]*?) and (?P<who>(?:[a-z']+ ){{1,3}}?)(?P<verb>{'|'.join(_VERBS)})(?P<rest>(?: [a-z']+)*?) *[,;.:-]+ *"
    r"(?P<ask>what (?:should|do|does|can|could|would) (?:i|we|he|she|they) (?:change|do(?: differently)?)"
    r"|how (?:do|does|can|could|should) (?:i|we|he|she|they) (?:fix|avoid|stop|prevent) (?:that|this|it)"
    r"|(?:what|which)(?: [a-z]+){0,3}? (?:avoids|would avoid|prevents|would prevent|stops|would stop) (?:that|this|it))"
    r"(?P<end> *[?.!]* *)$")
#: Drops that one gets on a place, told: they drip there ("we get a trail of drops on the table").
_GOT_DROPS = re.compile(r"\b(?:we|i|you) (?:get|got) (?:a trail of |some |a few |little |lots of )?(?:drops|drips|droplets)\b")
#: A value asked that avoids an outcome: the value, without what it does.
_AVOIDS = re.compile(r" (?:avoids|would avoid|prevents|would prevent|stops|would stop) (?:that|this|it)$")
_KEPT = {"hitt": "hit", "bump": "bump", "knock": "knock", "slid": "slide", "mov": "move", "tipp": "tip",
         "spill": "spill", "splash": "splash", "dripp": "drip"}


#: Outcomes said as a thing after "before" ("how high before splash") -> the form a negation takes.
_NOUNS = {"splash": "splash", "splashing": "splash", "splashes": "splash", "spill": "spill", "spilling": "spill",
          "spillage": "spill", "overflow": "overflow", "overflowing": "overflow", "dripping": "drip",
          "tipping": "tip", "sliding": "slide"}


#: The most a value may be before an outcome, asked: "how far from the centre can I pour before
#: the liquid misses", read as "... before the liquid starts to miss" (outcomes.py's goal).
#: (Said after the scene too: "pour water from a mug how high before it splashes out".)
#: (Or as the most said: "what's the highest you can pour from before it splashes out".)
_MOST = re.compile(rf"(?:^|(?<=[,;:.?!-] )|(?<=[a-z0-9] ))(?P<how>(?:how (?:far|high|low|steep|steeply|much|close"
                   rf"|fast|quickly|slowly|slow)|(?:what(?: is)? )?the (?:highest|lowest|furthest|farthest|steepest|fastest|quickest"
                   rf"|slowest|closest) (?:that )?(?:i|we|you|one|the robot) (?:can|could))\b[^?.!,;]{{0,100}}?)"
                   rf" before (?:(?P<who>it|they|the [a-z]+|anything|any of it) (?P<verb>{'|'.join(_BEFORE)})"
                   rf"|(?P<noun>{'|'.join(_NOUNS)}))\b")


def avoided(text: str) -> tuple[str, tuple[str, ...]]:
    """`text` (normalised) with an outcome told and a value asked that avoids
    it read as the value asked so that the outcome does not happen, and what
    is said back; `text` as it is otherwise."""
    m = _MOST.search(text)
    if m is not None:
        who, base = (m.group("who"), _BEFORE[m.group("verb")]) if m.group("verb") else ("it", _NOUNS[m.group("noun")])
        return (f"{text[:m.start()]}{m.group('how')} before {who} starts to {base}{text[m.end():]}",
                (f"{text[m.end('how'):m.end()].strip()}: read as so that {who} does not {base}, the most that can be done asked",))
    drops = _GOT_DROPS.search(text)
    m = _CHANGE.match(_GOT_DROPS.sub("it drips", text))
    if m is not None:
        told = f"{m.group('who')}does not {_VERBS[m.group('verb')]}{m.group('rest')}"
        ask = "how" if m.group("ask").startswith("how") else _AVOIDS.sub("", m.group("ask"))    # "how do i fix that": how
        return (f"{ask} so that {told}{m.group('end')}",
                (f"{m.group('pour')}: read as nothing: an earlier pour, told; the answer is for the one asked",
                 f"{m.group(0).strip(' ?.!')}: read as {ask} so that {told.strip()}",
                 *([f"{drops.group(0)}: read as it drips"] if drops else [])))
    m = _TOLD.match(text)
    if m is None:
        return text, ()
    verb = m.group("verb")
    base = _VERBS.get(verb) or _KEPT[verb.split()[1][:-3]]
    told = f"{m.group('who')}does not {base}{m.group('rest')}"
    return (f"{m.group('ask')} so that {told}{m.group('end')}",
            (f"{m.group(0).strip(' ?.!')}: read as {m.group('ask')} so that {told.strip()}",))
