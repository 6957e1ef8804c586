"""Two scenes joined by "or" in a question that compares them ("is it
better to pour from directly over the middle of the bowl or from near the
edge?", "a heavy bowl or a light bowl, which one slides more?", "which
spills less: a slow tilt, or tipping it fast?") are read as two scenes set
against each other with "vs" are (comparisons.py, which_one.py): the one
said first is answered, the other said back as not read, and refused if
it says what the vocabulary cannot (set_against.py); "or" is said back as
read as "vs".

A question compares where it says "better", "safer", "worse", "preferable",
"which", whether it makes a difference, or how likely, more or less ("would a full glass or a half-full glass be more
likely to overflow"). Without such a word ("pour high or low, does it spill?", "pour
from the side or the middle") two values of one dimension are still
refused, asking for one; asked with "should" ("should I hold it over the
middle or near the rim", with a goal), the choice is the plan's to make
(seeking.py), and with no goal ("should I hold the jug close to the bowl
or higher up?") it asks which is better, as "is it better to" does; a choice of two liquids is choices.py's; an "or" before a
number ("1 or 2 cm": a range), "or not", "or so" or a question of its own
("or will the bowl skid?") is no second scene. Two liquids poured "and" one another, with "which" asked
after them ("if i pour honey and water from the same height which one splashes more"), are compared too."""
from __future__ import annotations

import re

from pantarhei.bridge.reasoning.two_liquids import chosen_liquids, poured_together, read_alike

_COMPARING = re.compile(r"\b(?:better|best|safer|safest|worse|worst|preferable|which|likelier"
                        r"|(?:more|less|most|least) (?:likely|prone)|(?:make|makes) (?:a|any|much of a) difference"
                        r"|(?:does|do|would|will) it (?:really )?matter|^(?:so )?is (?:there )?(?:a |any )?difference)\b")
_ASKED_WHAT_TO_DO = re.compile(r"\b(?:should|shall)\b")
#: An outcome compared between two liquids chosen between ("which one drips more", "more likely to
#: overflow"): they are compared, not chosen (choices.py refuses a choice with no outcome compared).
_OUTCOME_COMPARED = re.compile(r"\bwhich(?: one| of them| of the two)? (?!is better|would be better|is best)[a-z]+"
                               r"|\b(?:more|less|most|least) (?:likely|prone)\b|\blikelier\b")
#: "should I ... or ...", asked of no goal: which is better.
_SHOULD = re.compile(r"\b(?:should|shall) (?:i|we|you|she|he|they|the robot)\b")
#: An outcome asked in a clause of its own ("should I pour low or high, will it spill?"): two values, refused.
_ASKS = re.compile(r"[,;:.?!] *(?:will|does|do|would|is|are|can|could|might)\b|\boutcome\b")
#: A goal said: "so nothing spills", "without spilling", "to avoid a mess", "I want the bowl upright".
_GOAL = re.compile(r"\b(?:so|without|in order to|to (?:avoid|keep|prevent|stop|get|make|fill|empty)"
                   r"|wants?|wanted|needs?|(?:i|we)(?: would|'d| d)? like|goal|aim)\b")
#: The words a second scene may begin with: where ("from near the edge"), how ("slowly", "tipping it
#: fast"), a body ("a light bowl"), a value ("low").
_SCENE = (r"(?:from|at|near|over|above|below|under|with|by|in|on|off|close|closer|directly|right|just|straight|far"
          r"|further|high|higher|low|lower|slow|slowly|fast|quick|quickly|gently|a|an|the|one|[a-z]+ing"
          # a way said by its verb: "or come in fast and pour from higher up"
          r"|come|bring|hold|held|keep|pour|move|use"
          # a liquid said by how it runs: "pouring thick cream at 90 degrees or thin milk at 45 degrees"
          r"|thin|thick|runny|sticky|watery"
          # how heavy or slippery the body said before it is: "does it matter if the bowl is heavy or light"
          r"|heavy|heavier|light|lighter|slippery|grippy|bouncy)\b")
#: A second scene's first words that are no scene: an outcome ("or spilling"), or what asks.
_NOT_A_SCENE = (r"(?:spill|splash|overflow|drip|leak|slid|slip|toppl|wobbl|tip(?:ping|s)? over|anything|something"
                r"|nothing|everything|either|neither)")
_OR = re.compile(rf"(?: ,)? \bor (?={_SCENE})(?!{_NOT_A_SCENE})")


#: Better by an outcome named after the two: "..., less spill?", "which one spills less".
_BETTER_BY = re.compile(r"[,;:] (?:which one |which )?(?:(?:less|more) (?:spill|spills|spilling|mess|splash|splashes|splashing|drips|dripping)"
                        r"|(?:spills|splashes|drips) (?:less|more))\b")
#: Which of two is better, asked in other words: read as "is it better to A or B" (which: the
#: words as asked, and what they say).
_WHICH_BETTER = tuple((re.compile(p), r) for p, r in (
    # "which is better, pouring from the middle or from the edge?"
    (r"^(?:so )?which(?: one| way| option)? (?:is|would be|will be) (?:the )?(better|best|safer|safest)(?: (?:option|choice|way|one))?"
     rf"(?: to do)?[,:;]? (?=.+ or {_SCENE})", r"is it \1 to "),
    # "pouring from the middle or from the edge, which is better?"
    (rf"^(.+ or {_SCENE}.*?)[,;:] *(?:so )?which(?: one)? (?:is|would be|will be) (?:the )?(better|best|safer|safest)(?= *[?.!]* *$)",
     r"is it \2 to \1"),
    # "is better pour in center of bowl or near of edge", as learners of English ask it
    (r"^(?:it )?is (better|safer) (?:to )?(?=.+ or )", r"is it \1 to "),
    # "better to move the cup away fast or slow?"
    (r"^(?:so )?(better|safer) to (?=.+ or )", r"is it \1 to "),
    # "what works better for a light bowl, pouring low or high?"
    (r"^(?:so )?(?:what|which)(?: one)? (?:works?|is) (better|best|safer) for ((?:a|an|the) [a-z ]+?)[,:;] (.+ or .+?) *[?.!]* *$",
     r"with \2, is it \1 to \3?"),
    (r"^(?:so )?(?:what|which)(?: one)? works? (better|best|safer)[,:;] (?=.+ or )", r"is it \1 to "),
    # "is it better, pouring from the middle or from the edge?"
    (r"^is it (better|safer)[,:;] (?=.+ or )", r"is it \1 to "),
    # "is it safer to pour close to the rim than from high", "is pouring low better than pouring high"
    (rf"^is it (better|safer) to (.+?) than (?:to )?(?={_SCENE})(?!last\b|before\b|usual\b|normal\b)", r"is it \1 to \2 or "),
    (rf"^is ((?:[a-z]+ing|a|an|the) .+?) (better|safer) than (?:to )?(?={_SCENE})(?!last\b|before\b|usual\b|normal\b)",
     r"is it \2 to \1 or "),
))


#: Two things compared in other words, said as "A vs B" (and "which one ..." where an outcome is named),
#: as comparisons.py and which_one.py read them: "what's the difference between A and B", "compare A
#: and B: which drips more", "which is less messy: A or B", "is A more stable than B".
_LIKENED = {"messy": ("spills", False), "stable": ("slides", True), "steady": ("slides", True),
            "safe": ("spills", True), "likely to spill": ("spills", False), "likely to splash": ("splashes", False),
            "likely to tip": ("tips over", False), "likely to tip over": ("tips over", False),
            "likely to slide": ("slides", False), "likely to drip": ("drips", False),
            "likely to knock the bowl over": ("tips over", False), "likely to knock over the bowl": ("tips over", False),
            "likely to tip the bowl over": ("tips over", False), "likely to tip over the bowl": ("tips over", False),
            "likely to make the bowl slide": ("slides", False), "likely to make the bowl move": ("slides", False)}
_ADJECTIVE = "|".join(sorted(_LIKENED, key=len, reverse=True))
_SET_AGAINST = tuple((re.compile(p), r) for p, r in (
    (r"^(?:so )?(?:what is|what|whats) the difference between (?P<a>.+?) and (?P<b>.+?)(?P<end> *[?.!]* *)$",
     "{a} vs {b}{end}"),
    (r"^(?:so )?is there (?:any|a|much) difference between (?P<a>.+?) and (?P<b>.+?)(?P<end> *[?.!]* *)$", "{a} vs {b}{end}"),
    (r"^(?:so )?how does (?P<a>.+?) compare (?:with|to) (?P<b>.+?)(?P<end> *[?.!]* *)$", "{a} vs {b}{end}"),
    # (not a value's "to": "compare tilting the bottle to 90 degrees versus 120 degrees")
    (r"^compare (?P<a>.+?) (?:and|with|to(?! -?\d)|versus|vs) (?P<b>.+?)[:,;.] *(?P<q>(?:which|what) .+)$", "{a} vs {b}, {q}"),
    (rf"^(?:so )?(?:which(?: one)? (?:is|would be|will be)|what(?:s| is)?) (?P<more>less|more) (?P<adj>{_ADJECTIVE})[,:;]? (?P<a>.+?) or "
     r"(?P<b>.+?)(?P<end> *[?.!]* *)$", "{a} vs {b}, which one {verb} {how}{end}"),
    (rf"^(?:so )?(?:is|would) (?P<a>.+?) (?:be )?(?P<more>less|more) (?P<adj>{_ADJECTIVE}) than (?P<b>.+?)(?P<end> *[?.!]* *)$",
     "{a} vs {b}, which one {verb} {how}{end}"),
    # "which is messier: pouring the water from 5 cm up or from 30 cm up?"
    (r"^(?:so )?which(?: one)? (?:is|would be|will be) (?:the )?messier[,:;]? (?P<a>.+?) or (?P<b>.+?)(?P<end> *[?.!]* *)$",
     "{a} vs {b}, which one spills more{end}"),
    # "is it less messy to pour the smoothie from a heavy jug or a light plastic cup?"
    (r"^(?:so )?is it (?P<how>less|more) messy to (?P<a>.+?) or (?:from )?(?P<b>.+?)(?P<end> *[?.!]* *)$",
     "{a} vs {b}, which one spills {how}{end}"),
    # "does pouring from high spill more than pouring from low?", "is pouring from high up worse than
    # pouring it low, for splashing?", "is it messier to pour high than low"
    # (what is said of both after them stays: "... than a heavy one if I pour from high")
    (r"^(?:so )?(?:does|do|would|will|could|can) (?P<a>(?:a|an|the|pouring|tipping|tilting|holding) .+?) (?P<verb>spill|splash|drip"
     r"|slide|tip over|tip|move|overflow) (?P<how>more|less) than (?:when )?(?P<b>(?:(?! (?:if|when|while)\b)[^,])+?)"
     r"(?P<both>(?: (?:if|when|while) [^,]+?)?)(?P<end> *[?.!]* *)$", "{a}{both} vs {b}, which one {verb}s {how}{end}"),
    (r"^(?:so )?is (?P<a>(?:a|an|the|pouring|tipping|tilting|holding) .+?) (?:messier|worse(?= than [^,]+,? for))"
     r" than (?P<b>(?:(?! (?:if|when|while)\b)[^,])+?)(?P<both>(?: (?:if|when|while) [^,]+?)?)"
     r"(?:,? for (?:splashing|spilling|spills|splashes|mess))?(?P<end> *[?.!]* *)$", "{a}{both} vs {b}, which one spills more{end}"),
    # "would a runny liquid like water or a sticky one like molasses splash more from the same height?"
    (r"^(?:so )?(?:would|will|does|do|could|can) (?P<a>(?:a|an|the|pouring|tipping|tilting) .+?) or "
     r"(?P<b>(?:a|an|the|pouring|tipping|tilting) .+?) (?P<verb>spill|splash|drip|slide|tip over|tip|move|overflow) "
     r"(?P<how>more|less)(?P<end>.*)$", "{a} vs {b}, which one {verb}s {how}{end}"),
))


def _set_against(text: str) -> tuple[str, tuple[str, ...]]:
    """`text` with two things compared in other words said as "A vs B", and what is said back."""
    for pattern, said in _SET_AGAINST:
        m = pattern.match(text)
        if m is None:
            continue
        parts = m.groupdict()
        if "adj" in parts:
            verb, inverted = _LIKENED[parts["adj"]]
            parts.update(verb=verb, how="less" if (parts["more"] == "more") == inverted else "more")
        out = said.format(**parts)
        return out, (f"{text.strip(' ?.!')}: read as {out.strip(' ?.!')}",)
    return text, ()


#: An outcome's comparative in "-ier", said between two scenes: "messier" is "more messy".
_IER = re.compile(r"\b(mess|splash|dripp|slosh|spill|slipp|wobbl)i(er|est)\b")


def _more(m: re.Match) -> str:
    """An outcome's comparative (_IER's match) as "more" or "most" and the outcome: "messier", "more messy"."""
    return f"{'more' if m.group(2) == 'er' else 'most'} {m.group(1)}y"


def compared_or(text: str) -> tuple[str, tuple[str, ...]]:
    """`text` (normalised) with the "or" between two scenes it compares
    read as "vs", and what is said back of it; `text` as it is otherwise.
    An outcome's comparative in "-ier" ("is it messier to pour from high up
    or from just above?") is read first as "more" and the outcome, where
    two scenes are set against each other ("or", "than", "vs")."""
    said: tuple[str, ...] = ()
    both = poured_together(text)
    if both and re.search(r"\bwhich\b", text[both.end():]):    # "pour honey and water ... which one splashes more"
        text = text[:both.start()] + both.group(0).replace(" and ", " vs ", 1) + text[both.end():]
        said = (f"{both.group(1)} and {both.group(2)}: read as {both.group(1)} vs {both.group(2)}: two liquids compared, "
                "the one said first answered",)
    if re.search(r"\b(?:or|than|vs|versus)\b", text):
        said += tuple(dict.fromkeys(f"{m.group(0)}: read as {_more(m)}" for m in _IER.finditer(text)))
        text = _IER.sub(_more, text)
    text, compared = _compared_or(text)
    return text, said + compared


def _compared_or(text: str) -> tuple[str, tuple[str, ...]]:
    """compared_or's reading of `text`, its comparatives in "-ier" read."""
    text, said = _set_against(text)
    if said:
        return text, said
    for pattern, asked in _WHICH_BETTER:
        m = pattern.search(text)
        if m is not None:
            if _BETTER_BY.search(text, m.end()):       # better by an outcome named after: that outcome is what is asked
                said = (f"{m.group(0).strip(' ,;:')}: read as nothing: which is better is asked as what is named after it",)
                text = pattern.sub("", text, count=1)
                break
            said = (f"{m.group(0).strip(' ,;:')}: read as {m.expand(asked).strip()}",)
            text = pattern.sub(asked, text, count=1)
            break
    should = _SHOULD.search(text)
    if (should and not _COMPARING.search(text) and not _GOAL.search(text) and _OR.search(text, should.end())
            and not _ASKS.search(text, should.end())):
        said += (f"{should.group(0)}: read as is it better to, of two scenes",)
        text = text[:should.start()] + "is it better to" + text[should.end():]
    elif not _COMPARING.search(text) or _ASKED_WHAT_TO_DO.search(text):
        return text, said
    liquids = chosen_liquids(text)
    if liquids and not read_alike(liquids) and _OUTCOME_COMPARED.search(text):      # "is syrup or water more likely to leave some in the bottle?"
        at = text.index(" or ", liquids.start())
        return (text[:at] + " vs " + text[at + 4:],
                (*said, "or: read as vs: two liquids compared, the one said first answered"))
    m = _OR.search(text)
    if m is None or m.start() == 0 or liquids:
        return (text, said) if said else (text, ())
    return (text[:m.start()] + " vs " + text[m.end():],
            (*said, "or: read as vs: two scenes compared, the one said first answered"))
