"""A question that asks for a value with a goal: "how high should I hold it
so nothing spills", "what's the best tilt so it all goes in" (or "height
and angle"), "which tilt
keeps it in the bowl", "so it does not tip, should I pour low or high". The value is a plan's to find, not a scene's to say:
with a goal said, the words that ask for it are heard (the answer says
whether the theory expects the goal of the scene said, the ordinary pour
where nothing else is, and points to `plan` for how); with none, they are
left for the scene, where they are refused as asking for a value.

"I want the bowl not to move", "I'd like it to stay in the cup", "I want it
all to go in", "I'd like to empty the whole mug", "keep the cup still", "to
avoid spilling", "to keep it all in the bowl": a goal, said as "so that the
bowl does not move". "What do I need to change", "what tilt works": a value
asked for, as "what tilt should I use".
"""
from __future__ import annotations

import re
from functools import lru_cache

from pantarhei.bridge.errors import UserError
from pantarhei.bridge.reasoning.cued import Cued
from pantarhei.bridge.reasoning.goal_lists import goal_list
from pantarhei.bridge.reasoning.goal_wordings import VALUE as _VALUE, WANTING as _WANTING, emptied_in
from pantarhei.bridge.reasoning.speeds import POURING_SPEED, SPEED_LAST
from pantarhei.bridge.reasoning.vessels import destinations, liquids

#: A value asked with "how": "how high", "how far from the centre".
_HOW = (r"(?:(?:far|close|near) (?:from|to) the (?:centre|center|middle|side|edge|rim)(?: of (?:the )?[a-z]+)?|high|low|far|fast|quick|quickly|slow|slowly|steep|steeply|much|close|near|heavy|light"
        r"|tilted|full)")
#: A value that is asked for ("the best height"), not said ("medium height").
_BEST = (r"(?:best|better|right|ideal|optimal|safest|safer|correct|perfect|proper|max|maximum|min|minimum"
         r"|highest|lowest|steepest|easiest|gentlest|cleanest|simplest|neatest)")
_WHO = r"(?:i|we|you|it|they|he|she|the robot|one)"
_ACT = (r"(?:hold|pour|tilt|keep|put|have|place|go|position|use|do|set|angle|raise|lift|move"
        r"|start|end|tip)")
#: What the act is done to: "it", "the jug" (not "the heavy" of "the heavy stuff": the scene's).
_WHAT = (r"(?: (?:it|them|the \w+(?! (?!(?:so|to|without|and|or|from|into|in|at|with|for|if|when|while|such|that|over|on|up)\b)[a-z])))?"
         r"(?: (?:from|at|to|up|in))?")
#: The words that ask for a value (compiled by _asking, where a goal is said).
_ASKING_SOURCE = (
    # a value that works: "what tilt works", "which height would work best", "which position of cup is best"
    rf"\b(?:what|which) {_VALUE}(?: {_VALUE})?(?: of (?:the |my |a )?[a-z]+)? (?:works?|would work|will work|is best|would be best"
    rf"|(?:is|would be) (?:good|right|ideal|safe|safest|better))(?: best)?(?= |$|[?.!,])"
    rf"|\b(?:(?:what|which)(?: is| be)?(?: the| a)?(?: {_BEST}| good| decent| suitable| sensible)?|(?:the |a )?{_BEST}) (?:(?:pour|pouring|approach|retreat|withdraw|withdrawal|retraction) )?{_VALUE}(?: {_VALUE})?"   # "tilt angle", "pour height"
    rf"(?:(?:,| and| or|, and|, or) (?:the |a )?{_VALUE})*"      # "the best height and angle"
    rf"(?: (?:to {_ACT}{_WHAT}|(?:should|do|can|must|would|could|shall) {_WHO} {_ACT}{_WHAT}"
    rf"|for (?:it|pouring|the pour)))?(?=[ ?.!,;:]|$)"
    # how much liquid is asked for: "how much should be in the cup to begin with"
    rf"|\bhow much(?: liquid| water| of it)? (?:should|must|can|could) (?:there )?be in (?:the |my |a )?[a-z]+"
    rf"(?: to (?:begin|start) with| at (?:the )?(?:start|first))?(?=[ ?.!,;:]|$)"
    # a value asked as learners of English order it: "how much angle I must give to the jar"
    rf"|\bhow much {_VALUE}(?: {_WHO})? (?:must|should|need to|have to|can|do)(?: {_WHO})? (?:give|{_ACT})"
    rf"(?: (?:to )?(?:it|them|the \w+))?(?= |$|[?.!,])"
    # (not a speed of pouring, which the vocabulary has none of: "how slowly should I go")
    rf"|\bhow(?: (?:very|really))? (?!(?:fast|quick|quickly|slow|slowly) (?:should|do|can|must|would|could|shall)"
    rf" {_WHO}(?: (?:need|have) to)? (?:pour|go)\b){_HOW}(?: (?:over|across|above|up|down|back|in|out|away))?(?: (?:should|do|can|must|would|could|shall|is) {_WHO}"
    rf"(?: (?:be\b|{_ACT}{_WHAT}))?)?(?=[ ?.!,;:]|$)"

    rf"|\bhow (?:should|do|can|must|would|could|shall) {_WHO} {_ACT}{_WHAT}(?=[ ?.!,;:]|$)"
    # "how high should the cup be", "how far do I need to tilt"
    rf"|\bhow(?: (?:very|really))? (?!(?:fast|quick|quickly|slow|slowly) )(?={_HOW} )\w+ (?:should|do|does|must|would"
    rf"|could|will) (?:{_WHO}|the \w+) (?:be|(?:need to |have to )?{_ACT}{_WHAT})(?=[ ?.!,]|$)"
    # the most a move may be: "what's the fastest I can move away", "the highest we could pour"
    rf"|\b(?:what(?: is)? )?the (?:fastest|slowest|quickest|highest|lowest|steepest|furthest|farthest|closest"
    rf"|nearest|heaviest|lightest)(?: [a-z]+)? (?:that )?{_WHO} (?:can|could|should|may|might|dare) {_ACT}{_WHAT}"
    rf"(?: (?:away|in|out|over|from|into))?(?=[ ?.!,]|$)"
    # where it should be: "where should the spout be", "where should I hold the jug"
    rf"|\bwhere (?:should|do|can|must|would|could|shall) (?:{_WHO}|the \w+) (?:be|{_ACT}{_WHAT})(?=[ ?.!,]|$)"
    # whether a value is there that reaches a goal: "is there any height where nothing splashes"
    rf"|\bis there (?:any|an?|some|one) {_VALUE}(?: to {_ACT}{_WHAT})?(?=[ ?.!,;:]|$)"
    # what a body needs: "what friction does it need", "what weight would the bowl need"
    rf"|\bwhat (?:{_VALUE}|friction|weight|mass|bounciness) (?:does|do|would|should|will) (?:it|they|the \w+) need(?=[ ?.!,]|$)"
    # what to avoid: "what should I avoid", "what should I not do"
    rf"|\bwhat (?:should|must|do|would|can) {_WHO} (?:need to |have to )?(?:avoid(?: doing)?|not do|never do)(?=[ ?.!,]|$)"
    # what to change or do: "what do I need to change", "what should we adjust"
    rf"|\bwhat (?:do|should|must|would|can) {_WHO} (?:need to |have to )?(?:change|adjust|alter|do differently|have done differently|have changed)(?=[ ?.!,]|$)"
    # a choice of two speeds, noted: "slow approach or fast?"
    rf"|\b(?:a )?(?:slow|fast|quick) (?:approach|retreat) or (?:a )?(?:slow|fast|quick)(?: one)?(?=[ ?.!,]|$)"
    # a choice of two values: "should I pour from low or high", "do we tilt it a bit or a lot"
    rf"|\b(?:should|do|can|must|would|could|shall) {_WHO} {_ACT}{_WHAT} (?:[a-z]+ ){{1,3}}?or(?: [a-z]+){{1,3}}?"
    rf"(?= *[?.!]* *$| *[,;:])")


@lru_cache(maxsize=None)
def _asking() -> re.Pattern:
    return re.compile(_ASKING_SOURCE)
#: A value said to keep an outcome: "which tilt keeps it in the bowl" (so that it stays in it).
_KEEPS = re.compile(rf"\b((?:what|which)(?: the)?(?: \w+)? {_VALUE}) (keeps|will keep|would keep)"
                    r" (it|them|the \w+) (in(?: the \w+)?|still|upright|steady|in place)\b")
#: A value said not to cause an outcome: "which height does not make the bowl slide" (so that it does not).
_NOT_CAUSING = re.compile(rf"\b((?:what|which)(?: the)?(?: \w+)? (?:{_VALUE}|pours?|pouring)|(?:any|a|some) (?:way|pour) (?:to pour )?that)"
                          r" ((?:does|do|will|would) not (?:make|let|cause))"
                          r" (it|them|the \w+)(?: to)? (?=[a-z])")
#: Wanting an outcome: "I want the bowl not to move", "we'd like it to stay in".
_WANT = re.compile(r"(?:\b(?:i|we) (?:just |really |only )?|^(?:just |really |only )?|(?<=[.!?] ))(?:want|need|would like|wish)(?: for)? (it(?: all)?|all of it|everything|them|nothing"
                   r"|every drop|each drop|every bit|all (?:of )?the (?:[a-z]+ )?[a-z]+"
                   # (where it comes from said after it: "all of the juice from the carton to land in the bowl")
                   r"|the (?:[a-z]+ )?(?!source\b)[a-z]+)(?: from (?P<origin>(?:the|my|a) (?:[a-z]+ )?[a-z]+))?(?= (?:not |never )?to\b)")



@lru_cache(maxsize=None)
def _keeping_in() -> re.Pattern:
    """Keeping the liquid in a bowl named: "to keep everything in a light
    bowl" (so that everything stays in it; in the jug, it stays in the
    source), not "keep it in place"."""
    return re.compile(r"\b(?:to |so as to )?keep(?:s|ing)? (it|them|it all|all of it|everything|the [a-z]+) in"
                      rf"(?= (?:the |a |an |my |your |this |that )?(?:[a-z]+ ){{0,2}}?(?:{destinations()}|jug|source)\b)")


#: A value said to get the liquid in: "what tilt angle gets all the liquid into the bowl" (so that it goes in).
#: A value said to empty the source: "what tilt angle gets every last drop out" (so that it empties).
_EMPTIES = re.compile(rf"\b((?:what|which)(?: the)?(?: \w+)? {_VALUE}) (?:gets|will get|would get) (?:every last drop|every drop"
                      r"|all of it|it all|everything|all (?:of )?the (?:liquid|water)|it) out(?: of (?:the |a |an |my )?[a-z]+)?\b")
_GETS = re.compile(rf"\b((?:what|which)(?: the)?(?: \w+)? {_VALUE}) (?:gets|will get|would get)"
                   r" (it|it all|all(?: of)? the \w+|everything|the \w+) (?=in\b|into\b)")


def wanting(text: str) -> tuple[str, tuple[str, ...]]:
    """`text` with its goals said as "so that ...", as outcomes.hear reads
    them, and the words of wanting it rewrote ("i want")."""
    text, said = goal_list(text)              # "goal: transfer all the water, nothing on the bench"
    said += tuple(m.group(0).strip() for m in _keeping_in().finditer(text))
    text = _keeping_in().sub(r"so that \1 stays in", text)
    said += tuple(m.group(2) for m in _KEEPS.finditer(text))
    text = _KEEPS.sub(r"\1 so that \3 stays \4", text)
    said += tuple(m.group(2) for m in _NOT_CAUSING.finditer(text))
    text = _NOT_CAUSING.sub(r"\1 so that \3 does not ", text)
    said += tuple(m.group(0)[m.end(1) - m.start():].strip() for m in _EMPTIES.finditer(text))
    text = _EMPTIES.sub(r"\1 so that it empties", text)
    said += tuple(m.group(0)[m.end(1) - m.start():m.start(2) - m.start()].strip() for m in _GETS.finditer(text))
    text = _GETS.sub(r"\1 so that \2 goes ", text)
    said += tuple(m.group(0)[:m.start(1) - m.start()].strip() for m in _WANT.finditer(text))     # "i want"
    # (where it comes from kept for the scene: "all the juice from the heavy jug to land in it")
    text = _WANT.sub(lambda m: f"pouring from {m.group('origin')}, so that {m.group(1)}" if m.group("origin")
                     else f"so that {m.group(1)}", text)
    for pattern, wanted in _WANTING:
        said += tuple(m.group(0).strip() for m in pattern.finditer(text))
        text = pattern.sub(wanted, text)
    brim = _to_the_brim().search(text) if re.search(r" to the | all the way| completely| right up", text) else None
    if brim:
        raise UserError(f"\"{brim.group(0)}\": how full the bowl gets is no outcome the vocabulary says: say "
                        "\"fill the bowl\" (it all goes in and stays there) or \"without spilling\"")
    filling = _filling()
    if filling.search(text):
        said += tuple(m.group(0).strip() for m in filling.pattern.finditer(text))
        # with a spill unwanted where it would land ("without a drop on the table"): that says it stays in
        verb = "goes into" if _ON_THE_TABLE.search(text) else "ends up in"
        text = filling.pattern.sub(lambda m: f"so that it all {verb} {next(g for g in m.groups() if g)}", text)
    for cued, wanted in _WANTING_CUED:
        if cued.search(text):
            said += tuple(m.group(0).strip() for m in cued.pattern.finditer(text))
            text = cued.pattern.sub(wanted, text)
    return text, said


#: Who wants a bowl filled: "I want to", "goal:" (_filling's and _to_the_brim's).
_WANTS_FILLED = (r"(?:\b(?:i|we) (?:would like|like|want|wanna|need|wish|am trying|are trying|hope|aim|plan|have|had)"
                 r"|\b(?:goal|aim|objective|task|target)s?(?: is)?:?"
                 # said with no one ("want to fill the bowl ...", "got to fill a patient's basin")
                 r"|(?:^|(?<=[.,;:!?] ))(?:want|wanna|need|trying|got|gotta|have))(?: to)? ")


#: A spill unwanted on what the bowl stands on: "without a single drop on the table", "without any getting on the floor".
_ON_THE_TABLE = re.compile(r"\b(?:without|so that none|so that nothing)\b[^.?!,]*?\b(?:on|onto|hitting|touching) (?:the |my |our )?"
                           r"(?:table|tablecloth|counter|countertop|worktop|floor|bench|stove)\b")


@lru_cache(maxsize=None)
def _to_the_brim() -> re.Pattern:
    """A bowl filled to a level: "fill the bowl to the brim", "... all the way", "I want to fill a mug right to the top" (a
    source so filled, not wanted, is full: fullness.py)."""
    level = (r"(?: up)? (?:(?:right |all the way |up )?to the (?:top|brim|rim)\b"
             r"|(?:all the way|completely|right up)(?! (?:in|into|to|down|over)\b))")     # ("fill the bowl all the way")
    some = r"(?:the|a|an|my|this|that|our|your) (?:[a-z]+ )?"
    return re.compile(rf"\bfill(?:s|ed|ing)? (?:up )?{some}(?:bowl|bowls|basin|dish|destination){level}"
                      rf"|{_WANTS_FILLED}fill (?:up )?{some}(?:{destinations()}){level}")


@lru_cache(maxsize=None)
def _filling() -> Cued:
    """Filling the bowl, wanted: "I'd like to fill the bowl", "goal: fill the bowl", "have the bowl end up full"
    (so that it all ends up in it: it goes in and stays; that it goes in, where a spill on the table is
    unwanted beside it, which says it stays); not how full ("fill the bowl
    halfway"; "fill the bowl to the brim", a level, is refused before: _to_the_brim), nor the source
    filled ("filling the cup to the top": a full source)."""
    bowl = rf"((?:the|a|an|my|this|that|our|your) (?:[a-z']+ )?(?:{destinations()}))"
    return Cued(rf"{_WANTS_FILLED}fill (?:up )?{bowl}(?: up)?(?!(?: (?:{destinations()}))? (?:half|halfway|about|around|a quarter|a third|to (?:half|a |\d)|\d))\b"
                rf"|\b(?:i|we) (?:would |want to |need to )?have {bowl} (?:end up |be )?(?:full|filled(?: up)?)\b"
                rf"|\b(?:i|we) (?:want|need|would like) {bowl} (?:to be |to end up )?(?:full|filled(?: up)?)\b"
                # the bowl wanted still while it is filled: "I need the bowl to stay put while I fill it"
                rf"|\b(?:while|as) (?:i|we) fill (it)\b(?! (?:to|all|up|right|completely|full|half)\b)",
                ("fill", "full"))


#: Whether a person can get the liquid in, or empty the source into the bowl: wanted, or asked
#: where a manner is said ("can I still get everything into the bowl if I tilt more").
_CAN_GET = (r"\b(?:can|could) (?:i|we|you) (?:still )?(?:get|put) (it all|all of it|everything|every drop|every last drop"
            r"|all (?:of )?the [a-z]+|the (?:whole|entire) [a-z]+) (?:of [a-z]+ )?(?=(?:in|into|inside)\b)")
#: ... or get it all out of the source, said after the manner: "can I pour without tilting past
#: horizontal and still get it all out" (so that it comes out).
_CAN_OUT = (r"(\b(?:can|could) (?:i|we|you) (?:[a-z0-9]+ ){0,12}?)(?:and )?(?:still )?get (it all|all of it|everything"
            r"|every drop|every last drop|all (?:of )?the [a-z]+) out\b(?: of (?:the |a |my )?[a-z]+)?")
#: ... or still get it in, said after the manner or the value asked: "how far to the side can I be
#: and still get it all in the bowl" (so that it goes in).
_STILL_GET = (r"\b(?:and|while) still (?:get|getting) (it all|all of it|everything|every drop|every last drop|all (?:of )?the [a-z]+|it)"
              r" (?=(?:in|into|inside)\b)")
_CAN_EMPTY = (r"\b(?:can|could) (?:i|we|you) (?:still )?(?:empty|drain) (it|(?:the|my|a) (?:full )?[a-z]+)(?: out)?"
              r"(?: completely| fully| all the way| entirely)?(?= (?:into|without)\b| *[?.!,]| *$)")
#: Wanting, compiled when cued: "I need none of it on the table" (so that none goes on it),
#: "how do I get all the soup into the bowl" (so that it goes in).
_WANTING_CUED = (
    # "I don't want the cup to touch the bowl" ("don't want ...", "not wanting ...", as notes say it): so that it does not
    (Cued(r"(?:(?:\b(?:i|we) |^)(?:do not|never) (?:want|wish)|^not wanting)(?: for)? (it|them|the (?!source\b)[a-z]+|any(?: of it| of the (?:[a-z]+ )?[a-z]+)?(?: in the [a-z]+)?)"
          r" (?:to |(?=[a-z]+ing\b))",
          ("not want", "never want", "not wish", "never wish", "not wanting")), r"so that \1 does not "),
    # "I want every drop in the bowl": so that it goes in
    # (where it comes from kept for the scene: "all the soup from the pot in the bowl")
    (Cued(r"(?:^|(?<=[.,;:!?] )|\b(?:i|we) )(?:want|need|would like) (every drop|all of it|it all|everything|all (?:of )?the (?:\w+ )?\w+)"
          r"(?: from (?P<origin>(?:the|my|a) (?:[a-z]+ )?[a-z]+))? (?=(?:in|into|inside)\b)",
          ("want", "need", "like")), lambda m: f"{f'pouring from {m.group(2)}, ' if m.group(2) else ''}so that {m.group(1)} stays "),
    # "I need the whole jug of batter in the bowl": so that the jug empties and it all goes in
    (Cued(r"(?:^|(?<=[.,;:!?] )|\b(?:i|we) )(?:want|need|would like) the (?:whole|entire) ([a-z]+)(?: of (?:the |my )?([a-z]+))?"
          r"(?= (?:in|into|inside)\b)", ("whole", "entire")), emptied_in),
    # "I want to get all of the syrup out of the cup and into the bowl": so that the cup empties and it goes in
    (Cued(r"\b(?:i|we) (?:want|need|would like) to get (it all|all of it|everything|all (?:of )?the [a-z]+) out of"
          r" ((?:the|my|a) [a-z]+) and (?=(?:in|into|inside)\b)", (" get ",)), r"so that \2 empties and so that \1 goes "),
    # "I want every last drop out of the measuring cup and into the bowl": the same, said without "get"
    (Cued(r"\b(?:i|we) (?:want|need|would like) (every last drop|every drop|it all|all of it|everything|all (?:of )?the [a-z]+)"
          r" out of ((?:the|my|a) (?:[a-z]+ )?[a-z]+) and (?=(?:in|into|inside)\b)", (" out of ",)),
     r"so that \2 empties and so that \1 goes "),
    # "... and none on the table", wanted beside another: so that none goes on it
    (Cued(r"\b((?:want|need|like|have|so that)\b.*\b(?:and|with)) (none|nothing)(?: of it)? (?=(?:on|onto|all over) )",
          (" and none", " and nothing", " with nothing", " with none")), r"\1 so that \2 goes "),
    # "and have it all land in the bowl": so that it does
    (Cued(r"\bhave (it all|it|everything|all of it) (?=(?:land|go|end up|stay)\b)", ("have ",)), r"so that \1 "),
    # "I'd like nothing spilled", "goal: no mess": so that nothing spills
    (Cued(r"\b(?:i|we) (?:want|need|would like|wish for|prefer) (?:nothing|not a drop|not a single drop|not one drop|no liquid"
          r"|none of it|not a drop of it) (?:spilled|spilt|wasted)\b"
          r"|\b(?:goal|aim|objective|target)s?(?: is)?:? (?:zero|no|none of the) (?:spill|spills|spillage|spilling|mess|splash"
          r"|splashes|splashing|drips|dripping)\b", ("spilled", "spilt", "wasted", "goal", "aim", "objective", "target")),
     "so that nothing spills"),
    # "... but not a drop spilled", beside another thing wanted: so that nothing spills too
    (Cued(r"\b((?:want|need|like|so that)\b[^.?!]*?\b(?:and|but) )(?:nothing|not a drop|not a single drop|not one drop"
          r"|none of it) (?:spilled|spilt)\b", ("spilled", "spilt")), r"\1nothing spills"),
    # "I want the cup empty at the end", "I need all of it out of the bottle": so that the source empties
    (Cued(r"\b(?:i|we) (?:want|need|would like) ((?:the|my|a) (?!(?:[a-z]+ )?(?:bowl|destination)s?\b)(?:[a-z]+ )?[a-z]+)"
          r" (?:to be |to end up )?(?:empty|emptied|completely empty|totally empty)(?: at the end| afterwards| after)?\b",
          ("empty", "emptied")), r"so that \1 empties"),
    (Cued(r"\b(?:i|we) (?:want|need|would like) (?:every last drop|every drop|it all|all of it|everything|all (?:of )?the [a-z]+)"
          r" out of ((?:the|my|a) (?:[a-z]+ )?[a-z]+)\b(?! and (?:in|into|inside)\b)", (" out of ",)), r"so that \1 empties"),
    # "I'd like zero spill", "we want no mess": so that nothing spills
    (Cued(r"\b(?:i|we) (?:want|need|would like|wish for) (?:zero|no|none of the) (?:spill|spills|spillage|spilling|mess"
          r"|splash|splashes|splashing|drips|dripping)\b", ("zero", " no ", "none of")), "so that nothing spills"),
    # "best way to get every last drop out of the bottle": so that the bottle empties, a way asked
    (Cued(r"\b(?:the )?(?:best|easiest|safest|quickest) way to (?:get|pour|tip) (?:every last drop|every drop|all of it|it all"
          r"|everything|all the liquid) out(?: of (?:the |a |my )?([a-z]+))?", ("way to",)), r"the best way so that it empties"),
    (Cued(r"\b(?:i|we) (?:want|need|would like) (none|nothing|no liquid|no water)(?: of it)?(?: ending up| landing| getting"
          r"| going)? (?=(?:on|onto|all over) )",
          ("want", "need", "like")), r"so that \1 goes "),
    # "I don't want any of it (anything) on the counter": so that none goes on it
    (Cued(r"(?:\b(?:i|we) |^)(?:do not|never) (?:want|need) any(?:thing| of it| liquid| water)?(?: ending up| landing| getting| going)?"
          r" (?=(?:on|onto|all over) )", ("want", "need")), "so that none goes "),
    (Cued(r"\bhow (?:do|can|could|should|would) (?:i|we|you) get (it all|all of it|everything|all the [a-z]+|it|the [a-z]+)"
          r" (?=(?:in|into|inside)\b)", (" get ",)), r"how so that \1 goes "),
    # "can I still get everything into the bowl", "can I empty the mug completely into the bowl":
    # so that it goes in (and the source empties); asked where a manner is said (if_it_can)
    (Cued(_CAN_GET, (" get ", " put ")), r"so that \1 goes "),
    (Cued(_STILL_GET, ("still get",)), r"so that \1 goes "),    # "while still getting it all in"
    (Cued(_CAN_EMPTY, ("empty", "drain")), r"so that \1 empties"),
    (Cued(_CAN_OUT, (" out",)), r"\1so that \2 comes out"),
)


#: A speed asked of pouring itself ("what pour speed", "what speed should I pour at"), which
#: the vocabulary has none of (the moves in and away have): no value a plan finds.
_POURING_SPEED = Cued(POURING_SPEED, ("speed", "rate", "pace", "velocity"))
_SPEED_LAST = re.compile(SPEED_LAST)


def sought(text: str) -> tuple[str, tuple[str, ...]]:
    """`text` without the words that ask for a value, and those words
    (to be called only where a goal is said); a speed of pouring is left
    for the scene, which refuses it."""
    found = [_value_asked(m) for m in _asking().finditer(text) if _POURING_SPEED.search(m.group(0)) is None
             and _SPEED_LAST.match(text, m.start()) is None]
    said = tuple(text[start:end].strip() for start, end in found)
    for start, end in reversed(found):
        text = f"{text[:start]} {text[end:]}"
    return text, said


def _value_asked(m: re.Match) -> tuple[int, int]:
    """Where `m` asks for a value: the liquid it pours is left for the scene ("how could we
    pour the syrup so nothing spills": a sticky liquid)."""
    words = m.group(0).split()
    if len(words) > 2 and words[-2] == "the" and liquids().spans(words[-1:]):
        return m.start(), m.start() + m.group(0).rstrip().rfind(" the ")
    return m.start(), m.end()


#: Whether a scene said reaches a goal said: "is pouring from 20 cm ok?", "is that a problem?",
#: "is a 100 degree tilt enough?", "does a 90 degree tilt do that?", "is that possible?", "is that
#: possible with a light bowl?", "is that all possible at 40 cm?", "is there any height where it never splashes?".
_REACHES = Cued(r"\b(?:is|would|will)(?: (?:(?:that|this|it)(?: all)?|[a-z]+ing\b[a-z0-9 ]{0,30}?|(?:a|an|the) [a-z0-9 ]{1,30}?|\d[a-z0-9. ]{0,30}?))?"
                r" (?:be )?(?:ok|okay|fine|alright|all right|a problem|an issue|enough|possible|doable|feasible"
                r"|achievable)(?= *[?.!]* *$| (?:with|if|when|using|by|at|from) )|\b(?:does|would|will|can|could)(?: (?:a|an|the|that|this) [a-z0-9 ]{1,30}?)?"
                r" (?:do (?:that|it|this|the trick)|work|achieve (?:that|it|this))(?= *[?.!]* *$)"
                r"|(?<=[,:;] )(?:doable|possible|feasible|achievable|ok|okay)(?= *[?.!]* *$| (?:at|with|from|if|when|using|by) )"   # "... - doable?"
                # the outcome not wanted, asked of a scene: "I don't want the jug to touch the bowl - will it if I hold it low?"
                r"|\b(?:will|would|does|could) it(?= if\b)"
                # which is better for a goal: "is it better to pour from the left side or the center to avoid spilling?"
                r"|\b(?:is|would) it (?:be )?(?:better|safer|best|wiser) (?:to|if)\b"
                # whether a scene helps reach it: "would it help if I held the pitcher lower, so I don't spill?"
                r"|\b(?:would|will|does|could|might) it help (?:if|to)\b"
                rf"|\bis there (?:really )?(?:any|an?|some|one|no) {_VALUE}\b",   # "is there any height where it never splashes"
                ("is there", "ok", "fine", "alright", "all right", "problem", "issue", "enough", "possible", "doable", "feasible",
                 "achievable", " do ", "work", "achieve", "it if", "better", "safer", "best", "wiser", "help"))


def reaches(text: str) -> bool:
    """Whether normalised `text` asks whether the scene it says reaches the
    goal it says (to be asked only where a goal is said): the goal's
    expectations are then what it asks, not whether the pour is safe."""
    return _REACHES.search(text) is not None


#: "can I pour ... without ...", "without hitting the bowl, could we pour ...": whether it can
#: be done so; not "how can I pour without ...", which asks for a value.
_CAN = re.compile(r"\b(?:can|could|may) (?:i|we|you|one|the robot)\b")
#: The robot asked whether it can: "can the robot pour ...", "could the arm", "can it".
_CAN_IT = Cued(r"\b(?:can|could|may) (?:it|(?:the|a|an|my|our|your|this|that) (?:robot(?: arm)?|arm|gripper|machine))\b",
               ("can ", "could ", "may "))


#: A goal said with "so (that)" after "can I pour ...": "so it never drips", "so that nothing spills", "and it still goes in",
#: "and nothing drips".
_SO_THAT = re.compile(r"\bso(?: that)? (?:it|they|nothing|none|no [a-z]+|the [a-z]+) (?:still )?(?:never|does not|do not|will not|spills|goes)\b"
                      r"|\band (?:it|the [a-z]+) (?:still |all )?(?:goes|go|lands|land|ends up|end up) (?:in|into|inside)\b"
                      r"|\band (?:nothing|none of it|not a drop) (?:ever )?(?:drips|spills|splashes)\b")


def if_it_can(text: str, goals: tuple[str, ...], manners: bool) -> tuple[tuple[str, ...], tuple[str, ...]]:
    """(asked, goals) of `goals` heard in normalised `text`: a question
    whether the robot can pour without an outcome ("can the robot pour
    honey without making a mess?") asks whether its pour, the scene said
    (the ordinary pour where nothing is), has the outcome, and wants it;
    whether a person can pour so in a manner said ("can I pour from low
    down at the edge without hitting the bowl?") asks whether the outcome
    happens there; said of no manner ("can I pour without spilling?") it
    wants the outcome, which a plan finds. A goal said with "so" after it
    ("can I pour the cream so it never drips?") is asked too, and wanted, as is one said
    in a clause before "can I" and a manner ("I don't want any on the counter, can I pour from 20 cm"; "without
    the jug touching the bowl, can I come in low?" asks it alone)."""
    so_that = _CAN.search(text) and _SO_THAT.search(text)       # "can I pour the cream so it never drips?"
    asked = tuple(g.removeprefix("neg(").removesuffix(")") for g in goals)
    if goals and manners and re.search(rf"[,;:.!?] +(?:so |then |but |and )?{_CAN.pattern}[^,;:.?!]*[?.!]* *$", text) \
            and not re.search(r"\b(?:how|what|which|where|without) ", text) \
            and re.search(r"\b(?:want|wants|wanted|need|needs|would like|goal|aim)\b", text[:_CAN.search(text).start()]):
        return asked, goals     # the goal said first ("no spill, can I ...")
    if not (goals and (" without " in f" {text} " or so_that or re.search(f"{_CAN_GET}|{_CAN_EMPTY}|{_CAN_OUT}|{_STILL_GET}", text))
            and not re.search(r"\b(?:how|what|which|where) ", text) and (so_that or not re.search(r"\bso(?: that| as)? ", text))):
        return (), goals
    if _CAN_IT.search(text) or so_that:
        return asked, goals
    if manners and _CAN.search(text):         # the manner said before the goal ("can I pour from 40 cm without
        said_first = re.search(rf"{_CAN.pattern}[^,;.?!]*? without\b(?!.*\b(?:if|when|while)\b)", text) and not re.search(
            f"{_CAN_GET}|{_CAN_EMPTY}|{_CAN_OUT}|{_STILL_GET}", text)    # spilling"): wanted too (not getting it all in)
        return asked, goals if said_first else ()
    return (), goals
