"""A claim someone made, asked to be checked ("my teacher says if you pour
from high it goes everywhere, is that true", "is it true that a heavy bowl
will not slide", "my sister says if you pour milk from really high the
bowl flips. is that true??"): read as the claim asked ("if you pour from
high, it goes everywhere?"), which aux_dropped.py and outcomes.py hear as
"does it go everywhere?", and said back. The condition the claim is made
under is set off from its outcome by a comma where none was typed ("if you
pour from high, it goes everywhere"); "is it true that ..." is read so only
where it has that condition to set off, and is otherwise heard as asked ("is
it true that a heavier bowl wobbles less"). A check followed by another
question ("is she right or is it the bowl?") is left as written. An outcome
asked whether it is normal, or bad ("is it bad if the bowl tips when i pour
on the side"), is asked whether it happens. A claim
of an outcome checked with a tag ("it won't spill, right?", "jug not
touching bowl right?", "..., slides or not") is asked, the tag said back. Advice against a pour, its
reason asked ("mommy says dont pour from up high but why"), asks of that pour."""
from __future__ import annotations

import re

from pantarhei.bridge.reasoning.aux_dropped import PHRASAL
from pantarhei.bridge.reasoning.outcome_verbs import outcome_verb

#: Who made the claim: "my teacher", "my little brother", "the keeper before me", "people".
_WHO = r"(?:(?:my|our|a|the|his|her|their|your) (?:[a-z]+ ){0,3}?[a-z]+|[a-z]+)"
_SAYS = (r"(?:always |once |keeps |keep |also )?(?:says?|said|saying|told me|tells me|tell me|thinks?|reckons?|claims?"
         r"|swears?)(?: to me)?(?: that)?")
#: The check asked after the claim ("is that true", "it is true?", "is he right", "who is right").
_CHECK = (r"(?:is (?:that|it|this|she|he|they) (?:true|right|correct|a myth)|(?:it )?is (?:it )?true|true|right|correct"
          r"|(?:who|which one|which of us) is right|is (?:he|she|they) (?:right|wrong))")
#: What may follow the check: nothing asked besides ("or not", "or is she making it up").
_AFTER = r"(?: or (?:not|no|what|(?:is|are) (?:she|he|they) (?:making it up|wrong|lying)|(?:does|do) it not matter))?[?.! ]*$"
_SAID = re.compile(rf"^(?:so |hey |hi )?{_WHO} {_SAYS} (?P<claim>.+?)(?: ?[,.;:!?-]+)? (?:{_CHECK}){_AFTER}")
#: Advice against a pour told, its reason asked: "mommy says dont pour from up high but why, does it make a big splash".
_ADVICE = re.compile(rf"^(?:so )?{_WHO} {_SAYS} (?:(?:i|we|you) )?(?:should not|do not|never|not to) (?P<scene>[^,.;:?!]+?),?"
                     r" (?:but )?why\b[?.! ]*(?:,? (?P<rest>.+?))?[?.! ]*$")
#: An outcome asked whether it is usual, or bad: "is it bad if the bowl tips when i pour ...", "is it normal that it splashes".
_IS_IT_USUAL = re.compile(r"^(?:so )?is it (?:really |just )?(?:normal|bad|usual|expected|weird|strange)(?: that| if| when) (?P<claim>.+?)[?.! ]*$")
_IS_IT_TRUE = re.compile(r"^(?:so |hey |hi )?is it (?:really )?(?:true|right|correct)(?: that| say)? (?P<claim>.+?)[?.! ]*$")
#: What an outcome happens to, said first in the claim's own clause ("it", "the bowl", "di water").
_SUBJECT = (r"(?:it|they|nothing|anything|something|(?:all|some|none|most|half) of (?:it|the \w+)|(?:the|a|an|my|di|your|this) (?:(?!it\b)[a-z]+ )?[a-z]+"
            r"|water|milk|liquid|juice|soup|oil)")
_BEFORE_VERB = (r"(?:(?:will|would|wont|won't|doesnt|doesn't|does not|dont|don't|do not|will not|can't|cant|cannot|never|not"
                r"|always|just|still|all|really) )*")

#: Verbs of an outcome said with a word after them (aux_dropped.py's, and "jump out", "bounce out", "fly off"),
#: which outcome_verb does not take alone.
_PHRASAL = PHRASAL | frozenset(("jump", "jumps", "bounce", "bounces", "fly", "flies"))


#: A tag asking whether what was said holds: "it won't spill, right?", "jug not touching bowl right?" (not a
#: side: "from the right?"), and "or not" after a question.
_TAG = re.compile(r"(?<!\bthe)(?<!\bto)(?<!\bfrom)(?<!\bon)(?<!\bat)(?<!\bmy)(?<!\bits)(?<!\bher)(?<!\bhis)(?<!\byour)(?<!\bor)"
                  r"(?:,| -)? (?P<tag>right|correct|yes|yeah|yea|no|eh)\?+ *$"
                  # ("or not" after a condition, the question asked first: "does the bottle touch the bowl when i pour, or not?")
                  r"|(?<=[a-z])(?:,| -)? (?P<whether>or (?:not|no))\?+ *$")

#: An outcome said as a fragment, last, with "or not" ("..., bowl on wet glass, slides or not").
_FRAGMENT_OR_NOT = re.compile(r"(?<=,) (?P<clause>(?:(?:the|my|a) )?(?:[a-z]+ )?(?P<verb>[a-z]+)) (?P<whether>or not)\?* *$")


def claim_asked(text: str) -> tuple[str, tuple[str, ...]]:
    """`text` (normalised) with a claim asked to be checked read as the
    claim asked, and what is said back; `text` as it is otherwise. A claim
    of an outcome checked with a tag ("it won't spill, right?") is asked."""
    if advice := _ADVICE.match(text):          # what the advice warns of, asked of the pour it warns against
        asked = f"if i {advice.group('scene').removeprefix('to ')}, {advice.group('rest') or 'what happens'}?"
        return asked, (f"{text.strip(' ?.!')}: read as the pour advised against, asked: {asked}",)
    usual = _IS_IT_USUAL.match(text)
    if usual and any(_outcome(w) for w in re.findall(r"[a-z]+", usual.group("claim"))):
        asked = f"{_set_off(usual.group('claim'))}?"          # "is it bad if the bowl tips ...": does it
        return asked, (f"{text.strip(' ?.!')}: read as whether it happens: {asked}",)
    m = _SAID.match(text) or _IS_IT_TRUE.match(text)
    if m is None:
        tag = _TAG.search(text)
        if tag is None and (last := _FRAGMENT_OR_NOT.search(text)) and _outcome(last.group("verb")):
            return f"{text[:last.end('clause')]}?", ("or not: read as asking whether it holds",)
        # (an outcome said never to happen, tagged, is supposed_never.py's; "or not" is a tag only after a
        # question: "teapot must touch bowl or not?" is left as it is)
        if tag is None or not any(_outcome(w) for w in re.findall(r"[a-z]+", text[:tag.start()])) \
                or re.search(r"\bnever\b", text[:tag.start()]) \
                or tag.group("whether") and not re.match(r"(?:does|do|did|will|would|is|are|can|could)\b"
                                                         r"|(?:the|my|a|your) [a-z]+ (?:is|are) [a-z]+\b", text):
            return text, ()
        return f"{_set_off(text[:tag.start()])}?", (f"{tag.group('tag') or tag.group('whether')}?: read as asking whether it holds",)
    claim = _set_off(m.group("claim").strip(" ,.;:"))
    if m.re is _IS_IT_TRUE and claim == m.group("claim").strip(" ,.;:"):
        return text, ()         # "is it true that a heavier bowl wobbles less": heard as it is asked
    asked = f"{claim}?"
    return asked, (f"{text.strip(' ?.!')}: read as the claim asked: {asked}",)


def _set_off(claim: str) -> str:
    """`claim` with its condition ("if you pour from high") set off from its
    outcome ("it goes everywhere") by a comma, where no comma is typed."""
    cond = re.match(r"(?:if|when|whenever|as long as) [^,]+", claim)
    if cond is None or "," in claim[:cond.end() + 1]:
        return claim
    found = [m for m in re.finditer(rf"(?<= )(?<!\bthe )(?<!\ba )(?<!\ban )(?<!\bmy )(?<!\bdi )(?<!\byour )(?<!\bthis )"
                                    rf"(?={_SUBJECT} {_BEFORE_VERB}(?P<verb>[a-z]+))", cond.group(0))
             if m.start() > 3 and _outcome(m.group("verb"))]
    return f"{claim[:found[-1].start()].rstrip()}, {claim[found[-1].start():]}" if found else claim


def _outcome(verb: str) -> bool:
    """Whether `verb`, as said in a claim ("goes", "spill", "flips"), is of an outcome."""
    return verb in _PHRASAL or outcome_verb(verb) or outcome_verb(re.sub(r"(?<=[^s])e?s$", "", verb))
