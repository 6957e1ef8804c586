"""Goals said in other words, each rewritten as "so that ..." as
outcomes.hear reads goals: "keep the cup still", "don't let it overflow",
"make sure it does not spill", "without losing any", "for the soup not to
jump out" (as learners of English say it), "I want to empty the whole pot
into the bowl", "with the bowl staying exactly where it is"; seeking.py
applies them (its `wanting`)."""
from __future__ import annotations

import re

#: What a value is asked of: a height, a tilt, a way ...
VALUE = (r"(?:(?:pour|pouring) (?=height|angle|speed|position))?"        # ("is there a pour height where ...")
         r"(?:height|tilt|tilting|angle|way|speed|distance|position|spot|place|amount|pose|path|route|setting|manner)s?")

#: Emptying the source, wanted: "I'd like to empty the whole mug".
_EMPTYING_WANTED = (r"\b(?:i|we) (?:want|need|would like|wish|am trying|are trying) to (?:empty|drain) (?:out )?(?:the whole"
                    r"|all of the|all the|the entire|the) ([a-z]+)")
#: A goal of emptying the source: "goal: empty the bottle completely", "goal is to pour out the whole bottle".
_EMPTYING = (r"\b(?:goal|aim|objective|task|target)s?(?: is)?:? (?:to )?(?:empty|drain|pour out) (?:out )?(?:the whole|all of the"
             r"|all the|the entire|the) ([a-z]+)(?: (?:completely|fully|entirely|totally))?")


def _out_and_in(m: re.Match) -> str:
    """"get every last bit of the melted chocolate out of the jug into the bowl": so that it all
    comes out and goes in, the liquid and the source named kept for the scene ("from the jug": so that
    it goes in, the jug not said emptied; "out of the small jug": the small jug, whose size is refused)."""
    liquid = re.search(r"\b(?:of|all) (?:the |my )?([a-z]+(?: [a-z]+)?)$", m.group(1))
    out = "" if m.group("origin") else "it all comes out and "     # "from the bottle": not emptied
    source = m.group("origin") or m.group("out_of")
    return (f"{'pouring ' + liquid.group(1) + ' ' if liquid else ''}{'from the ' + source + ' ' if source else ''}"
            f"so that {out}it all goes ")


def emptied_in(m: re.Match) -> str:
    """"I want to empty the whole pot of soup into the bowl": so that it empties and it all goes in,
    the liquid named kept for the scene (group 1 the source, group 2 the liquid, if named)."""
    return f"{'pouring ' + m.group(2) + ' ' if m.group(2) else ''}so that the {m.group(1)} empties and it all goes"


def _safe_unless_wanted(m: re.Match) -> str:
    """" so that it is safe", or nothing where a goal is said beside the match."""
    beside = f"{m.string[:m.start()]} {m.string[m.end():]}"
    return "" if re.search(r"\b(?:want|wants|wanted|so|without|need|needs)\b", beside) else " so that it is safe"


def _note_wanted(m: re.Match) -> str:
    """"so that nothing spills" (group 1) or "so that the bowl does not tip over" (group 2) for a
    note of what is not wanted, where a want is said before it; else the note as it was."""
    if not re.search(r"\b(?:want|wants|wanted|need|needs|goal|aim|trying|try)\b", m.string[:m.start()]):
        return m.group(0)
    return "so that nothing spills" if m.group(1) else f"so that the bowl does not {_MOVING[m.group(2)]}"


#: The bowl's moving, as a note of what is not wanted names it ("no wobble", "no sliding"): its verb.
_MOVING = {"wobbl": "wobble", "slid": "slide", "slip": "slip", "tip": "tip over", "mov": "move"}
#: ... said before a way or a value asked, in a clause of its own ("no splashing, what height is best").
_ASKED_AFTER = (r"(?= *(?:[,;:.!?]| - ).*\b(?:how (?:do|should|can|would|high|far|low|close|steep|much)|what (?:settings?|height"
                r"|tilt|angle|speed|pour)\b|(?:high|low) or (?:high|low)\b|(?:that is|thats|that's) all (?:i|we) want\b"
                r"|\b(?:is (?:it|that|this) )?possible\b|what(?: is|s)? the (?:highest|lowest|best|steepest|fastest|most|least)\b"
                r"|\bhow *[?.!]* *$))")      # (or "how" alone at the end: "no spill, no bowl moving, ..., how")
#: Other ways of saying a goal, said as "so that ...": "keep the cup still" (not "keep the
#: source upright": how it is held), "don't let it overflow", "make sure it does not spill"
#: (the words they drop are fillers).
WANTING = tuple((re.compile(p), r) for p, r in (
    # a way asked after a goal ("... without spilling, any tips?", "whats the trick"): the goal asks it
    (r"^(?=.*\b(?:so that|without)\b)(.*?)[,.;:?!\u2014-]* (?:any (?:tips|advice|ideas|suggestions)|tips|(?:what is|whats|what s|what)"
     r" (?:the |your )?(?:trick|secret|knack)|is there (?:a|any) (?:trick|secret|knack))(?: (?:to it|here))?[?.! ]*$", r"\1"),
    # liquid not wanted outside the bowl, or where it stands ("i dont want any drops outside the bowl", "i don't want
    # drops on the tray after"): so that nothing spills
    (r"\b(?:i|we) (?:do not|never) want (?:any |a single |one |even one |a )?(?:[a-z]+ )?(?:(?:outside|out of)(?: of)? (?:the |my )?"
     r"(?:bowl|dish|basin)|(?:on|onto) (?:the |my )?(?:table|tray|counter|floor|tablecloth|table cloth|bench|carpet|rug))"
     r"(?: after(?:wards)?)?(?:,? not even (?:one|a) (?:single )?drop)?\b", "so that nothing spills"),
    # asked negatively, as people doubting it ask: "is there no way to pour molasses without ...": is there a way
    (r"\bis there (?:really )?no (way|method|technique) to\b", r"is there a \1 to"),
    # asked whether a scene stops an outcome ("does pouring low stop it from splashing?"): whether it happens
    (r"((?:^|(?<=[.?!,;:] ))(?:does|do|did|will|would|can|could|might|may|should)\b[^.?!,;:]*?)\b(?:(?:stop|stops|prevent|prevents)"
     r" (it|them|the [a-z]+)(?: from)?|(?:keep|keeps) (it|them|the [a-z]+) from) (?=[a-z]+ing\b)", lambda m: f"{m.group(1)} will {m.group(2) or m.group(3)} "),
    (r"\bkeep(?:s|ing)? (the (?!source\b)[a-z]+) (?:(?:completely|totally|perfectly|absolutely|dead|really|nice and) )?"
     r"(still|steady|in place|put)\b", r"so that \1 stays \2"),
    (r"\b(?:do not|does not|never) lets? (it|them|the [a-z]+|any(?: of it)?|a drop|a single drop) ", r"so that \1 does not "),
    # notes run together ("no spill no touching bowl, ..."): each its own
    (r"\b(no (?:spill|spills|spilling|splash|splashes|splashing|mess)) (?=(?:no|not) [a-z])", r"\1 , "),
    # a note of what is wanted before asking how ("no splashing, how do I pour"): so that nothing spills
    (r"(?:^|(?<=[,;:.!?] )|(?<= - ))(?:no|not) (?:spill|spills|spilling|splash|splashes|splashing|mess|drips|dripping)"
     r"(?: at all)?(?: ?,? not even (?:a|one) (?:single )?(?:drop|drip))?" + _ASKED_AFTER,
     "so that nothing spills"),
    # ... or the bowl's moving ("no wobble, what settings would do that"): so that it does not move so
    (r"(?:^|(?<=[,;:.!?] )|(?<= - ))(?:(?:the )?bowl (?=not))?(?:no|not) (?:the )?(?:bowl )?(wobbl|slid|slip|tip|mov)(?:e|es|ing|ping|ement|s)?(?: over)?"
     r"(?: (?:the )?bowl)?" + _ASKED_AFTER,
     lambda m: f"so that the bowl does not {_MOVING[m.group(1)]}"),
    # ... or after a want said before it ("want to fill the bowl with juice, no spill, no tipping")
    (r"(?<=[a-z,;:] )(?:no|zero) (?:(spill|splash|mess|drip)|(wobbl|slid|slip|tip|mov))(?:e|es|ing|ping|ement|s)?(?: over)?"
     r"(?: at all| (?:on|onto) (?:the |my )?(?:table|counter|floor|stove|bench))?(?= *(?:[,;:.!?]| - |$))", _note_wanted),
    (r"(?:^|(?<=[,;:.!?] )|(?<= - ))no (?:touching|hitting|bumping|knocking|contact|touch|hit|bump|knock)(?:(?: the)? bowl)?" + _ASKED_AFTER,
     "so that the jug does not touch the bowl"),
    (r"(?:^|(?<=[,;:.!?] )|(?<= - ))(?:the )?[a-z]+ (?:is |are )?(?:not|never) touching(?: (?:the )?[a-z]+)?(?: at all)?(?: the (?:whole|entire) time)?"
     + _ASKED_AFTER, "so that the jug does not touch the bowl"),
    # ... or with no source said first and no comma before the asking ("not touching the bowl at all with the spout is
    # that possible if i pour from 5cm")
    (r"^(?:not|never) touching (?:the )?[a-z]+(?: at all)?(?: with (?:the |my |its )?[a-z]+)?(?: the (?:whole|entire) time)?"
     r"(?= (?:is (?:it|that|this)|it is|that is|thats) possible\b)", "so that the jug does not touch the bowl,"),
    # ... and not spilling so ("not spilling a single drop, is that possible if i pour from shoulder height"), or
    # named the goal ("not spilling is the goal, ...")
    (r"^(?:not|never) (?:spilling|splashing)(?: (?:a single|one single|a|one|any) (?:drop|drip))?(?: at all)?"
     r"(?= ?,? ?(?:is (?:it|that|this)|it is|that is|thats) possible\b)", "so that nothing spills,"),
    (r"^(?:not|no) (?:spilling|spills?|splashing|mess) is the (?:goal|aim|point|idea)\b", "so that nothing spills"),
    # "is there any way to pour where the container never touches the bowl": so that it does not
    (r"\b((?:any|a|some) way to pour(?: it)?) where (?=(?:it|the [a-z]+|nothing|none)\b)", r"\1 so that "),
    # a drop got on a place, or any of it getting there: landing there ("without getting a single drop on the
    # tablecloth", "without any of it getting on the floor")
    (r"\bwithout getting (?:a single|one single|even a|a|one) (?:drop|drip|speck|bit)s? (?=(?:on|onto) )", "without getting any "),
    (r"\bwithout (?:any(?: of it)?|it|them) getting (?=(?:on|onto) )", "without any of it landing "),
    # whether one can pour so and it still goes in ("can i pour the juice from way up high and it still goes in the
    # bowl"): so that it goes in
    (r"(\bcan (?:i|we|you|one)\b[^.?!,;]*?) and (it|the [a-z]+) (?:still |all ){0,2}(?:goes|go|lands|land|ends up|end up)"
     r" (?=(?:in|into|inside)\b)", r"\1 so that \2 goes "),
    # ... or that nothing spills ("can i pour the thinner into the bowl and nothing drips down the outside"): so that it does not
    (r"(\bcan (?:i|we|you|one)\b[^.?!,;]*?) and (nothing|none of it|not a drop) (?:ever )?(?=(?:drips|spills|splashes|goes|gets|lands"
     r"|runs|comes)\b)", r"\1 so that \2 "),
    # none left behind, said with "leave" ("and not leave any stuck in the cup"): so that nothing is left in it
    (r"\b(?:and )?(?:not|never|without) leav(?:e|ing) (?:any|anything)(?: of it)?(?: stuck| behind)?(?= in (?:the|my|a) [a-z]+\b)",
     "so that nothing is left"),
    # the safest value or pour, asked: the best so that it is safe ("what's the safest way to pour", "what pour is safest")
    # (with a goal said beside it, safest for that goal: "I never want the bowl to move, what pour is safest")
    (rf"\b(what|which)(?: is)? (?:the )?safest ({VALUE})\b", lambda m: f"{m.group(1)} is the best {m.group(2)}" + _safe_unless_wanted(m)),
    (r"\b(what|which) pour (is|would be) (?:the )?(safest|safer|best|better)\b",
     lambda m: f"{m.group(1)} way {m.group(2)} best" + (_safe_unless_wanted(m) if m.group(3).startswith("saf") else "")),
    # "without it making a mess": as "without making a mess"
    (r"\bwithout (?:it|them|that) (?=making (?:a |any |much of a )?mess\b)", "without "),
    # "keep the bowl from sliding", "stop it from splashing"
    (r"\b(?:keep|keeps|keeping|stop|stops|stopping|prevent|prevents|preventing) (it|them|the [a-z]+)"
     r" from (?=[a-z]+ing\b)", r"so that \1 does not "),
    (r"\bmakes? sure(?: that)? ", "make sure so that "),
    # "for the oil not going out of the bowl", as learners of English say it: so that it does not go out
    (r"\bfor (it|them|the [a-z]+) (?:not|never) (go|come|get|fall|spill|splash|drip)(?:ing|ping)?\b", r"so that \1 does not \2"),
    # "I want the water to land without ...": so that it goes in (landing on the table is a spill)
    (r"\b(so that (?:it|them|the (?:[a-z]+ )?[a-z]+)) to land\b(?! (?:on|onto|outside|all|in|into|inside|right|just|near|at)\b)",
     r"\1 goes in"),
    # "pour the syrup neatly": so that nothing spills
    (r"\b(pour(?:s|ed|ing)?(?: (?:it|them|the [a-z]+|[a-z]+))?) (?:neatly|cleanly|tidily)\b", r"\1 so that nothing spills"),
    # "and have it not slide"
    (r"\bhave (it|them|the [a-z]+) (?:not|never) (?=[a-z]+)", r"so that \1 does not "),
    # "I'd prefer the bowl not move", "we hope it doesn't tip"
    (r"\b(?:i|we) (?:would )?(?:prefer|rather|hope)(?: that)? (it|them|the [a-z]+) (?:not|never|does not|do not|will not)"
     r" (?=[a-z]+)", r"so that \1 does not "),
    # "I want to empty the whole pot of soup into the bowl": so that it empties and it all goes in
    (rf"{_EMPTYING_WANTED}(?: of ([a-z]+))?(?= into (?:the |a |my )?(?:[a-z]+ )?[a-z]+\b)", emptied_in),
    # "need to empty a heavy jug of syrup": so that it empties
    (r"(?:^|\b(?:i|we) )(?:need|want|have) to (?:empty|drain) (?:out )?(?:a|the|my) ((?:[a-z]+ )?[a-z]+)(?= of\b|$|[ ,.;!?])",
     r"so that the \1 empties"),
    # "goal: empty the bottle completely": so that it empties ("... into the bowl": it goes in too)
    (rf"{_EMPTYING}(?: of ([a-z]+))?(?= into (?:the |a |my )?(?:[a-z]+ )?[a-z]+\b)", emptied_in),
    (rf"{_EMPTYING}\b", r"so that the \1 empties"),
    # "I'd like to empty the whole mug": so that it empties (into the bowl: and it all goes in, above)
    (rf"{_EMPTYING_WANTED}\b", r"so that the \1 empties"),
    # a value there that reaches a goal: "is there any height where the water never splashes" (so that it does not)
    (rf"\b(is there (?:any|an?|some|one) {VALUE}) (?:where|at which|for which|with which|in which)"
     r" (?=(?:it|they|the [a-z]+|nothing|none|no [a-z]+) )", r"\1 so that "),
    # "for all the oil coming out", as learners of English say it: so that it all comes out
    (r"\bfor (all (?:of )?the [a-z]+|it all|all of it|everything) (?:coming|to come) out\b", r"so that \1 comes out"),
    # "I want to pour all the broth into the bowl", "my goal is to transfer all the sauce ...", "need to pour all
    # the soup ...": so that it all goes in
    # (where it comes from kept, as the pour: "all the water from a full jug into the bowl")
    (r"(?:\b(?:(?:i|we) (?:want|need|would like)|(?:my|our|the) (?:goal|aim) is)|(?:^|(?<=[.,;:!?] ))(?:need|want))"
     r" to (?:pour|get|put|transfer) (all (?:of )?the [a-z]+|it all"
     r"|all of it|everything|every drop)"
     r"(?: (from (?:the |a |my )?(?:[a-z]+ )?[a-z]+))?(?= (?:in|into)\b)", lambda m: f"pouring {m.group(2)} so that {m.group(1)} goes"
     if m.group(2) else f"so that {m.group(1)} goes"),
    # "so that none is wasted": so that nothing spills
    (r"\bso(?: that)? (?:none|nothing|no liquid|not a drop)(?: of it)? (?:is|gets|will be|goes to) wasted?\b", "so that nothing spills"),
    # "without leaving any batter stuck inside the pitcher": so that none is left behind
    (r"\bwithout leaving (?:any|a drop|a single drop|anything|some)(?: of it| (?:the )?[a-z]+)? (?:stuck |left )?(?:(?:inside|in)"
     r"(?: (?:the |a |my )?(?!bowl\b)[a-z]+)?|behind)\b", "so that none is left behind"),
    # "without losing any": so that nothing spills
    (r"\bwithout (?:losing|wasting) (?:any|a drop|a single drop|anything)(?: of it)?\b", "so that nothing spills"),
    # "without any on the counter": so that none goes on it (a place the liquid lands, a spill)
    (r"\bwithout (?:any|a drop|a single drop|one drop|one single drop|even one drop|even a drop)(?: of it| liquid| water)?"
     r" (?=(?:on|onto|all over) (?:the |a |my )?"
     r"(?:table|tablecloth|counter|countertop|worktop|floor|bench|stove|ground)\b)", "so that none goes "),
    # "avoids the cup hitting the bowl", "prevent the bowl sliding", "stop the mug clinking"
    (r"\b(?:avoid|avoids|avoiding|prevent|prevents|preventing|stop|stops|stopping) (it|them|the [a-z]+)"
     r" (?=[a-z]+ing\b)", r"so that \1 does not "),
    # "for that all the milk go inside the bowl", as learners of English say it: so that it goes in
    (r"\bfor that (?=(?:all|it|the|every|nothing|none|no)\b)", "so that "),
    # "for the soup not to jump out", as learners of English say it: so that it does not
    (r"\bfor (it|them|the [a-z]+) (?:not|never) to (?=[a-z]+)", r"so that \1 does not "),
    # a goal said with "for", as learners of English say it: "near or far for not make mess", "for no spilling"
    (r"\bfor (?:not|never) (?:make|making|let|letting) (it|them|the [a-z]+) (?=[a-z]+)", r"so that \1 does not "),
    (r"\bfor (?:not|never|no) (?=(?:make|making|spill|splash|drip|tip|slid|mov|hit|touch|overflow|toppl)[a-z]*\b)",
     "so that it does not "),
    # not wanting an outcome, said as a noun: "if I don't want any splash", "we don't want a mess"
    (r"\b(?:if )?(?:i|we|you) (?:do not|never) (?:want|need) (?:(?:any|a|a single|one|even one) )?(splash|spill|drip|leak|overflow)"
     r"(?:es|s|ing|age)?\b", r"so that it does not \1"),
    (r"\b(?:if )?(?:i|we|you) (?:do not|never) (?:want|need) (?:any|a) mess\b", "so that nothing spills"),
    # what must not happen, said first, a value asked after it: "nothing should splash out, what height do i need"
    (r"^(nothing|none of it|no liquid|not a drop|the (?:bowl|dish|cup|jug|pitcher|bottle)|it) (?:should|must|may|can)(?: (not|never))?"
     r" (?=[a-z]+\b[^.?!]*?[,.;:!?-] *(?:what|which|how)\b)", lambda m: f"so that {m.group(1)} {'does not ' if m.group(2) else ''}"),
    # less of an outcome wanted, as less of the liquid doing it: "so less goes over the side", "so that less
    # spills" (so that none does, not so that it does)
    (r"\bso(?: that)? (?:less|fewer)(?: of it| liquid| water)? (?=(?:goes|go|spills|spill|splashes|splash|drips|drip|slops"
     r"|slop|ends|end|lands|land)\b)", "so that nothing "),
    # wanting less of an outcome, said as a noun: "if I want less splashing", "if we want fewer spills"
    (r"\b(?:if|since|as) (?:i|we|you) (?:want|need|would like|wanna)(?: to (?:have|get|make))? (?:less|fewer|minimal|minimum|no)"
     r" (splash|spill|drip)(?:es|s|ing|age)?\b", r", so that it does not \1"),
    (r"\b(?:if|since|as) (?:i|we|you) (?:want|need|would like|wanna)(?: to (?:have|get|make))? (?:less|minimal|minimum|no) mess\b",
     ", so that nothing spills"),
    # a goal said as a state with no outcome in it: "with zero mess", "with no spills"
    (r"\bwith (?:zero|no|absolutely no|not a single|not one) (?:mess|spill(?:s|age|ing)?|splash(?:es|ing)?|drips?|dripping"
     r"|spillover)\b", "so that nothing spills"),
    # what it is for, as learners of English say it: "incline the jar for the water to go out from it"
    (r"\bfor (it|them|the [a-z]+|all of it|everything|it all|all (?:the )?[a-z]+) (?:to )?(?=(?:go|come|get|flow|run|drain|land|stay|end up)\b)",
     r"so that \1 "),
    # a bound asked: "what tilt should I never go past": the value asked
    (r"\b((?:what|which) (?:tilt|angle|height|speed)) (?:should|must|can|could) (i|we|you) (?:never|not) (?:go|get|tilt|pour|lift)"
     r"(?: it)? (?:past|beyond|over|above)\b", r"\1 should \2 use"),
    # "with the bowl staying exactly where it is", "with none spilling and the bowl staying put": so that it stays there
    (r"\b(?:with|(?<=ing )and) (it|them|the [a-z]+) (?:staying|remaining) (?=(?:exactly |right )?(?:where|put|still|in place|upright|steady)\b)",
     r"so that \1 stays "),
    # goals listed as states after the pour wanted: "..., none left behind and none on the bench"
    # (or left inside: "none left inside the bottle", "none left stuck inside")
    (r"(?:, |\band )(?:with )?(?:none|nothing) (?:is )?(?:left|stuck)(?: stuck)? (?:behind|inside(?: (?:the |a |my )(?!bowl\b)[a-z]+)?"
     r"|in (?:the |a |my )(?!bowl\b)[a-z]+)\b", " so that none is left behind"),
    (r"(?:, |\band )(?:with )?(?:none|nothing|not (?:a single|one)(?: one| 1| drop)?|not a drop) (?=(?:on|onto) (?:the |my )?"
     r"(?:table|bench|counter|countertop|floor|tablecloth|worktop)\b)",
     " so that none goes "),
    # "keep the table totally clean": so that nothing spills
    (r"\bkeep(?:s|ing)? (?:the |my )?(?:table|counter|countertop|worktop|bench|floor|tablecloth|cloth)(?: (?:totally|completely"
     r"|perfectly|nice and|spotlessly))? (?:clean|dry|spotless)\b", "so that nothing spills"),
    # "a way to never touch the bowl with the jug": so that the jug does not touch it
    (r"\bto (?:never|not) (touch|hit|bump|knock) the (bowl|destination) with (the [a-z]+)\b", r"so that \3 does not \1 the \2"),
    # "what is the best way to not spill": so that it does not spill
    (r"\b(?<=way )to (?:never|not) (?=(?:spill|splash|drip|overflow|slop|tip|slide|move|make a mess)\b)", "so that it does not "),
    # "is there a way to pour that doesn't spill": a pour, so that it does not
    (r"\b(a (?:way|method|technique|manner) (?:to pour|of pouring)|a pour) that (?=(?:does not|will not|would not|never)\b)",
     r"\1 so that it "),
    # "I need a pour that empties the cup completely into the bowl": so that it empties and it all goes in
    (r"\b(?:i|we) (?:need|want|would like) a pour that (?:empties|drains) (the [a-z]+)(?: completely| fully| entirely)?(?= into\b)",
     r"so that \1 empties and it all goes"),
    # "to get all the oil out of the bottle into the bowl": so that it all comes out and goes in
    (r"\b(?:(?:in order |so as )?to |(?<=how do i )|(?<=how can i )|(?<=how should i )|(?<=goal: )|(?<=goal ))get (it all|all of it"
     r"|everything|every drop|every last (?:drop|bit)(?: of (?:the |my )?[a-z]+(?: [a-z]+)?)?|all (?:of )?the [a-z]+(?: [a-z]+)?)"
     r" (?:out(?: of (?:the |a |my )?(?P<out_of>[a-z]+(?: [a-z]+)?))?|from (?:the |a |my )?(?P<origin>[a-z]+(?: [a-z]+)?))"
     r" (?:and )?(?=(?:in|into) (?!(?:one|a single) (?:go|shot|time|pour)\b)(?:the |a |my )?(?:[a-z]+ )?[a-z]+\b)", _out_and_in),
    # "what angle should I tilt to get everything out", "how do I get every drop out": so that it all comes out
    (r"\b(?:(?:in order |so as )?to |(?<=how do i )|(?<=how can i )|(?<=how should i ))get (it all|all of it|everything|every drop|every last drop|all (?:of )?the [a-z]+) out\b"
     r"(?: of (?:the |a |my )?[a-z]+)?(?![^.?!,;]*\band (?:in|into)\b)", r"so that \1 comes out"),
    # "to avoid drips outside the target", "prevent any spills": so that it does not drip, spill
    (r"\b(?:avoid|avoids|avoiding|prevent|prevents|preventing|minimi[sz]e|minimi[sz]ing|reduce|reducing)"
     r" (?:any )?(drip|spill|splash|leak|overflow)(?:s|es)?\b(?! of\b)", r"so that it does not \1"),
    # "to avoid spilling", "prevent splashing", "minimise dripping"
    (r"\b(?:avoid|avoids|avoiding|prevent|prevents|preventing|minimi[sz]e|minimi[sz]ing|reduce|reducing)"
     r" (?=(?:any )?(?!doing\b)[a-z]+ing\b)", "so that it does not "),      # (not "what should I avoid doing")
))
