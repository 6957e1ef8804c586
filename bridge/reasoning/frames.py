"""Questions asked in a frame, said as the plain question they ask: a
question about a clause ("is it true that the bowl tips", "tell me whether
it spills") or an outcome caused ("does pouring high make it tip") is asked
as "does the bowl tip"; an outcome typed as a note, with no word that asks
("cup hits bowl??", "bowl tips?"), is asked as "does the cup hit the bowl", and so is the
source supposed to strike the bowl ("what if the cup hits the bowl"), and
an outcome asked with its verb first ("hits the mug the bowl?").
outcomes.py hears the plain question."""
from __future__ import annotations

import re

from pantarhei.bridge.reasoning.cued import Cued

#: Questions asked about a clause ("is it true that the bowl tips", "tell me whether it
#: spills", "I'd like to know if the jug hits the bowl"): asked as "does the bowl tip".
FRAMES = tuple((re.compile(p), r) for p, r in (
    (r"\b(?:is it true|is it the case|would you say|does the theory (?:say|predict|expect))(?: that)? ",
     " does "),
    (r"\b(?:know|tell (?:me|us)|predict|wonder(?:ing)?|check|find out|figure out|see|ask(?:ing)?"
     r"|curious|unsure|not sure|any idea|no idea)(?: about)? (?:whether|if) ", " does "),
    # what a scene said means for an outcome: "does that mean it will come out slower", "does this mean the bowl tips"
    (r"\b(?:does|would|will|could) (?:that|this|it) (?:mean|imply)(?: that)?(?= (?:it|they|the [a-z]+|a [a-z]+)"
     r" (?:will|would|could|might|can|does|do)\b)", " "),
    (r"\b(?:does|would|will|could) (?:that|this|it) (?:mean|imply)(?: that)? ", " does "),
    # how much of an outcome a scene changes: whether it happens with it ("does that change how
    # much ends up in the bowl", as everyday.txt's "change whether")
    (r"\b(?:change|changes|affect|affects|alter|alters|make (?:a|any) difference to|makes (?:a|any) difference to)"
     r" (?=how much\b)", " "),
    # how much spills, named as a measure: "fraction spilled?", "spill fraction?", "the share spilt"
    (r"\b(?:(?:the |what )?(?:fraction|share|proportion|percentage|percent|amount|volume) (?:of (?:it|liquid|the \w+) )?"
     r"(?:spilled|spilt)|spill(?:ed)? (?:fraction|share|proportion|percentage))(?= *[?.!]* *$)", " how much spills "),
    # the source left with liquid stuck in it: "does the cup end up with some liquid still stuck inside it"
    (r"\b(does|will|would) (the [a-z]+) end up with ((?:some|any|a bit of|a little)(?: of the| the)?(?: [a-z]+)?) (?:still )?"
     r"(?:stuck|left) (?:inside|in) (?:it|them)\b", r"\1 \3 stay stuck in \2"),
    # a puddle said where it lies: "will there be a puddle next to the bowl" (a spill)
    (r"\b(a |any |some )?(puddles?|mess|drips|spills?)(?: (?:next to|beside|around|by|near|under|on the table by) (?:the )?(?:bowl|dish|it))(?= *[?.!]* *$| after\b| afterwards?\b| later\b| when\b| if\b)",
     r" \1\2"),
    # how much goes in, named as a measure: "fraction entering the bowl?"
    (r"\b(?:the |what )?(?:fraction|share|proportion|percentage|percent|amount) (?:of (?:it|liquid|the \w+) )?(?:entering|that enters"
     r"|going in(?:to)?|that goes in(?:to)?|landing in|in)(?= (?:the )?(?:bowl|target|destination|receiver) *[?.!]* *$)", " how much goes into "),
    # an outcome expected, as a noun: "would you expect spilling", "do you predict any splashing"
    (r"\b(?:expect|predict|anticipate|see|observe|get|cause|causes|notice)(?: any| some| a| much)? "
     r"(?=(?:spill|splash|drip|leak|slosh|splatter|dribbl)\w*\b(?! of\b))", " will it "),
    # more or less of an outcome made: "does pouring from higher up make more splashing (or less)": how much of it, asked
    (r"\b(?:make|makes|cause|causes|create|creates|give|gives|produce|produces) (?=(?:more|less)(?: or (?:more|less))? (?:spill|splash|mess|drip"
     r"|slosh|splatter)\w*\b)", ", "),
    # an outcome caused: "does pouring from high make it tip" (the bowl tipping), "cause the cup to slide"
    # (not wanted: "so as not to make the bowl move" is so that it does not)
    (r"\bso(?: as)? (?:not|never) to (?:make|cause) (it|them|the [a-z]+)(?: to)? ", r"so that \1 does not "),
    # "would that cause it to splash": that, the scene said before, is the scene; will it splash
    (r"\b(?:would|will|does|did|could|can|might|may) (?:that|this) (?:make|cause) (it|them|the [a-z]+)(?: to)? (?=(?:tip"
     r"|toppl|fall|slid|slip|mov|shift|wobbl|spill|splash|overflow|drip|rock|budg|skid)\w*\b)", r" will \1 "),
    (r"(?<!\bto )\b(?:make|makes|made|making|cause|causes|caused|causing) (it|them|the [a-z]+)(?: to)? (?=(?:tip"
     r"|toppl|fall|slid|slip|mov|shift|wobbl|spill|splash|overflow|drip|rock|budg|skid)\w*\b)", r" will \1 "),
))


#: Contact asked of by its noun alone: "contact between source and bowl?", "any collision
#: with the bowl?" (not "in contact with", which states it).
CONTACT = Cued(r"(?<!\bin )\b(?:(?:is|will) there (?:be )?)?(?:any |some |no |a |the )?"
               r"(?:contact|collisions?) (?:between|with)\b(?: (?:the |its )?(?:bowl'?s? |destination )?(?:rim|edge|lip)\b(?! of\b))?"
               r"|\b(?:is|will|would|could) there (?:be )?(?:any |some |no |a )?collisions?\b"
               r"|(?:^|(?<=[,:;.!?] ))(?:(?:any |a |the )?(?:risk|chance|danger|odds|possibility|likelihood)"
               r" of )?(?:any |a )?(?:(?:rim|edge|bowl) )?(?:collisions?|contact)(?: or not)?(?= *[?.!]* *$)",   # ("rim contact?")
               ("contact", "collision"))


#: "Or not" as chat types it: "bowl stays put or nah".
NAH = Cued(r"\bor nah\b", ("or nah",))


#: The source striking the bowl, supposed: "what if the cup hits the bowl" asks whether it does
#: (what follows a spill or a slide is another question: "what if the milk spills").
STRUCK = Cued(r"\b(?:what if|what happens if|suppose|imagine if)(?= (?:the |a |an |my |your |this |that |it )?"
              r"(?:[a-z]+ ){0,3}(?:hits|bumps|touches|knocks|collides|strikes|scrapes|clips|bonks|bangs|nudges)\b)",
              ("what if", "happens if", "suppose", "imagine if"))


#: An outcome typed as a note: a clause of a noun (with its article) and an outcome's verb,
#: ending with a question mark, and no word that asks: "cup hits bowl??", "jug bumps the pot?".
NOTE = re.compile(r"(?:^|(?<=[,:;.!=>\u2013\u2014\u2192] )|(?<= - ))(?=(?:tips|topples|slides|spills|moves|shifts|wobbles"
                  r"|splashes|overflows|drips|budges|slips|skids|flips|stays (?:put|still|in place|upright)"
                  r"|(?<=[=>\u2192] )(?:splash|spill|tip|slide|move|drip|overflow))(?: over)?"     # "= spill?", "-> spill?"
                  r"(?: or (?:not|nah))? *\?|"
                  r"(?:the |a |an |my |your |this |that )?[a-z]+ (?:still |even |really |also )?"
                  r"(?:hits|bumps|touches|knocks|collides|strikes|scrapes|clips|tips|topples|slides|shifts"
                  r"|moves|wobbles|spills|splashes|overflows|drips|leaks|stays(?= (?:put|still|where|in place))"
                  r"|misses|overshoots|lands|flips|skids|budges|scoots|slips|empties|ends up|falls over"
                  r"|gets (?:knocked|pushed|hit|bumped|shoved)|(?:goes|comes|pours|flows) out"
                  # (the verb bare, as notes and learners type it: "bowl slide or not", "it still arrive in")
                  r"|hit|bump|touch|tip|topple|slide|shift|move|wobble|spill|splash|overflow|miss|land|arrive|flip"
                  r"|reach|reaches|(?:go|come|pour|flow) out"
                  r"|skid|budge|slip|fall over|stay(?= (?:put|still|where|in place|inside|in))"
                  r")\b[^,:;.!?]*(?:\?| or (?:not|nah|no)\b))")


#: A verb alone at the end of a note with no word that asks: "high pour thin liquid spill?",
#: "bowl slide y/n" (not "what if the milk spills?", "what fraction spills?").
LAST = re.compile(r"(?<=[a-z] )(?<!\bmore )(?<!\bless )(?=(?:spill|spills|splash|splashes|tip|tips|slide|slides|move|moves|overflow"
                  r"|overflows|topple|topples)(?: over)?(?: *\?+| or (?:not|nah) *\?*) *$)")
_ASKS = re.compile(r"\b(?:what|which|how|why|whether|if|suppose|imagine|will|would|does|do|did|could|can|might"
                   r"|may|should|shall|is|are|was|were)\b")


#: An outcome asked with its verb first, as a learner of English may order a question ("hits
#: the mug the bowl?", "goes it then all in the bowl?"): asked as "does the mug hit the bowl".
_FIRST = {"hits": "hit", "bumps": "bump", "touches": "touch", "knocks": "knock", "clips": "clip", "spills": "spill",
          "splashes": "splash", "drips": "drip", "goes": "go", "lands": "land", "tips": "tip", "slides": "slide",
          "falls": "fall", "comes": "come", "stays": "stay", "overflows": "overflow"}
VERB_FIRST = Cued(rf"(?:^|(?<=[,:;.?!] ))(?P<verb>{'|'.join(_FIRST)}) (?P<who>it|they|the [a-z]+)"
                  r"(?: (?:then|also|still|really))?(?P<all> all)?\b(?=[^.!?]*\?)", tuple(f"{v} " for v in _FIRST))


def asked_plainly(text: str) -> tuple[str, tuple[str, ...]]:
    """(normalised `text` with each frame said as the question it asks, the
    frames' phrases, heard with the outcome)."""
    phrases: list[str] = []
    for said, wanted in FRAMES:
        phrases.extend(m.group(0).strip() for m in said.finditer(text))
        text = said.sub(wanted, text)
    if NAH.search(text):
        phrases.append("or nah")
        text = NAH.pattern.sub("or not", text)
    if STRUCK.search(text):
        phrases.extend(m.group(0) for m in STRUCK.pattern.finditer(text))
        text = STRUCK.pattern.sub(" does ", text)
    if VERB_FIRST.search(text):
        phrases.extend(m.group(0) for m in VERB_FIRST.pattern.finditer(text))
        text = VERB_FIRST.pattern.sub(lambda m: f"does {m.group('who')}{m.group('all') or ''} {_FIRST[m.group('verb')]}", text)
    if not _ASKS.search(text):
        text = LAST.sub("does ", text)
    return NOTE.sub("does ", text), tuple(phrases)
