"""An earlier pour told before the question ("last time I poured from
20 cm and it splashed, if I go down to 8 cm is it better?"): each question
is read alone, so the pour told is not read, and said back; "is it better"
after it asks about the outcome told (whether it splashes), not the three
expectations of "is it better to", as do "will that fix it" and a scene said to
stop it ("yesterday the bowl slid off the tray when I emptied the kettle into it,
would a heavier bowl stop that?": with a heavier bowl, does the bowl slide); a value asked
after it ("on my last try nothing came out at all, how far do I need to go?") wants the
outcome told not to happen again (here, that it comes out)."""
from __future__ import annotations

import re
from functools import lru_cache

from pantarhei.bridge.reasoning.everyday import alternation, names

#: What asks its cause: "why?", "what went wrong", "what did I do wrong".
CAUSE = re.compile(r"^(?:so |and |but )?(?:why|how come|how|what gives|what went wrong(?: there| here)?|what did (?:i|we|he|she|they|you) do wrong|what happened(?: there| here)?"
                    r"|what(?:s| is)? (?:caused|causes|causing) (?:that|this|it)|what(?:s| is)? the reason(?: for (?:that|this|it))?|why did (?:that|this|it) happen|why is that|why (?:does|did) (?:that|this|it)"
                    r"|why (?:that|this|it) (?:happen|happens|happened|is happening)"      # as learners ask it: "why this happen?"
                    r"|why (?:it|the bowl) (?:move|moves|slide|slides|tip|tips|fall|falls)(?: like (?:that|this))?"     # "why it move like that"
                    r"|why (?:did|does) (?:it|the bowl) do that|why (?:did not|does not) (?:it|they|the \w+)(?: [a-z]+){0,5}"
                    r"|how (?:is|was) (?:that|this|it) (?:even )?possible|how (?:does|did|could|can) (?:that|this|it) (?:even )?happen"
                    # as learners of English ask it, and what was being done: "what I do wrong?", "what was I doing"
                    r"|what (?:i|we) (?:do|did|am doing|was doing) wrong"
                    # whether it should happen, or what is done wrong: "is that normal or am i doing it wrong"
                    r"|(?:is|was) (?:that|this|it) normal(?: or (?:am|was) (?:i|we) doing (?:it|something|anything) wrong)?"
                    r"|(?:is|was) (?:that|this) (?:why|the reason)(?: why)?"
                    r"|(?:am|was) (?:i|we) doing (?:it|something|anything) wrong|what (?:am|was) (?:i|we) doing(?: wrong| there| here)?"
                    # ("was I holding it wrong", "am i tilting wrong", "what was wrong", "whats wrong")
                    r"|(?:am|was|are|were) (?:i|we|they|you) (?:just )?(?:holding|tilting|tipping|pouring|using)(?: it| them)? wrong"
                    r"|what(?: was| is)? wrong"
                    r"|what made (?:that|this|it|the \w+) (?:happen|move|slide|tip|tip over|fall|fall over|spill|splash)"
                    r"(?: happen)?"
                    # one of two causes asked: "was it the weight or the angle?", "was it the speed or was I too far off"
                    r"|(?:was|is) it (?:the |my )?[a-z]+ or (?:(?:(?:was|is) (?:it|i|we)|(?:am|were) (?:i|we)) (?:too |the |my )?[a-z]+(?: [a-z]+){0,5}|(?:the |my )?[a-z]+)"
                    # one cause named, no value said: "was it the height?" (of the pour told)
                    r"|(?:was|is) it (?:the |my |because of the )?(?:height|tilt|angle|speed|weight|position|distance))"
                    r"(?: (?:lol|lmao|haha|ugh|smh|pls|please))?[?.! ]*$")      # ("what am i doing wrong lol")
#: What asks for a remedy: "what should I change", "how do I stop that", "any tips", "what's the trick".
REMEDY = re.compile(
    r"^(?:so |and |but )?(?:what (?:should|do|can|could|would|must|shall) (?:i|we|you|he|she|they) (?:do|change|try|adjust)"
    r"(?: (?:differently|different|instead|next time|then|now|to fix (?:it|that|this)|about (?:it|that|this)))*"
    r"|what (?:do|would|can|could) you (?:suggest|recommend|advise)"
    # (as learners of English ask it too: "how I can avoid this")
    r"|how (?:(?:do|can|could|should|would|to) (?:i|we|you)?|(?:i|we) (?:can|could|should|do))(?: ?(?:stop|avoid|prevent|fix|solve|handle))(?: (?:that|this|it))?"
    r"(?: (?:happening|from happening))?(?: (?:again|next time|in future|in the future))*"
    r"|how (?:do|can|could|should|would) (?:i|we|you) (?:pour|do)(?: it| this| that)?(?: (?:then|instead|next time|differently|right|properly|better|again))*"
    # "how do i not do that", "how can we not have that happen"
    r"|how (?:do|can|could|should|would) (?:i|we|you) not (?:do|have) (?:that|this|it)(?: happen)?(?: (?:again|next time))?"
    r"|any (?:tips|advice|ideas|suggestions|help)(?: (?:on|for) (?:that|this|it|next time))?"
    r"|(?:tips|advice|help)(?: please)?"
    # "what's the trick", "is there a trick to it"
    r"|(?:what is|whats|what s|what) (?:the |your )?(?:trick|secret|knack)(?: (?:to it|here|to that|to this))?"
    r"|is there (?:a|any) (?:trick|secret|knack)(?: (?:to it|to that|to this))?"
    # what would have been right: "what should I have done?", "how should I have done it?"
    r"|(?:what|how) (?:should|could|would) (?:i|we) have (?:done|poured)(?: it| that)?(?: (?:differently|different|instead|better|then))?)"
    r"(?: please)?[?.! ]*$")
#: When the pour told was: "last time", "yesterday", "previously", "the other day".
WHEN = (r"(?:(?:the )?(?:last time|previous time|first time|other day|yesterday|previously|earlier|before"
         r"|last night|last week|this morning)|(?:on )?(?:my|the) (?:last|previous|first) (?:try|attempt|go))")
#: Its outcome, told in the past ("and it splashed"), with the question that asks it again.
_TOLD = {"splash": "does it splash", "spill": "does it spill", "drip": "does it drip",
         "overflow": "does it overflow", "slosh": "does it slosh out", "tip": "does the bowl tip over",
         "slid": "does the bowl slide", "slide": "does the bowl slide", "mov": "does the bowl move",
         "miss": "does it miss", "bounc": "does it bounce out", "flip": "does the bowl tip over",
         "fell": "does the bowl tip over", "skid": "does the bowl slide", "knock": "does the jug hit the bowl",
         "came out": "does it come out", "hit": "does the jug hit the bowl", "splatter": "does it splash"}
#: What is wanted again where a value is asked after the outcome told: it not happening, or,
#: where nothing came out, it coming out.
_AGAIN = {"came out": "it comes out", "tip": "the bowl does not tip over", "flip": "the bowl does not tip over",
          "fell": "the bowl does not tip over", "slid": "the bowl does not slide", "skid": "the bowl does not slide",
          "mov": "the bowl does not move", "knock": "the jug does not hit the bowl", "bounc": "it does not bounce out",
          "slosh": "it does not slosh out", "spilt": "it does not spill", "hit": "the jug does not hit the bowl"}
#: A second outcome told after the first ("the jug hit the rim and the whole thing flipped over"): wanted not again too.
_SECOND = re.compile(r" and (?:then )?(?:it|everything|the (?:whole )?[a-z]+) (?:(?:got|was) )?(?P<out>tip|flip|fell|slid|skid|mov|knock"
                     r"|spill|spilt|splash|overflow|slosh)\w*")
#: A value asked after it, with no goal said: "how far do I need to go".
_VALUE_ASKED = re.compile(r"^(?:so )?(?:how (?:far|high|low|much|close|steep|steeply|fast|slow|slowly)|what|which)\b(?!.*\b(?:so|without)\b)")
#: How to keep it from happening again, asked: "how do I avoid that" (how should I pour so that it does not).
_AVOID = re.compile(r"^how (?:do|can|could|should|would) (?:i|we|you) (?:avoid|fix|stop|prevent) (?:that|this|it)\b")
#: Who did what the earlier pour did: "it", "the bowl", "half of it".
_WHO = (r"(?:it|the (?:bowl|liquid|water|milk|[a-z]+)|(?:half|some|most|all|a lot|part|much) of it"
        r"|(?:half|some|most|all|a lot|part|much) (?:of )?the [a-z]+|(?P<none>nothing|none of it))")
#: What it did: "splashed", "slid off the edge of the tray", "bounced out".
_OUT = (r"(?:(?P<out>splash|spill|spilt|drip|overflow|slosh|tip|slid|mov|miss|bounc|flip|fell|skid|knock|hit|came out"
        r"|splatter)\w*"
        # where it landed, a spill: "half of it went on the counter", "it went everywhere"
        r"|(?P<onto>(?:went|landed|ended up|got|fell) (?:on|onto|all over) (?:the |my )?(?:counter|countertop|table|floor"
        r"|worktop|bench|stove|tablecloth)|(?:went|got) (?:everywhere|all over the place)))")
#: Why it did, told after it ("because I was too far to the left"): the earlier pour's, not read.
_WHY = r"(?: (?:because|since|as|cause) [^,;.?!]*)?"
#: What may come after an earlier pour told: the question (after a comma or a full stop, or after
#: "lol" typed as one).
_NEXT = (r"(?: *[,;.] *| (?:lol|lmao|haha|ugh|smh|oops)[,;.]? )(?=(?:now|this time|if|so|what|which|how|why|will|would|does|do|is|can"
         r"|could|should)\b)")
_POUR = re.compile(
    rf"^{WHEN},? (?:when )?(?:i|we|you|they|he|she|the robot|my robot) (?P<verb>poured|pour|held|tilted|tipped|did it)"
    rf"(?P<how>[^,;.?!]*?)(?: and {_WHO} (?:[a-z]+ and )?{_OUT}(?P<part> over| out| everywhere)?{_WHY})?{_NEXT}")
#: The pour told in the past with no time said, its outcome after it: "i poured from high up and it
#: went everywhere, how high should I pour?" (without the outcome, "i poured from high up, did it
#: spill?" asks about the pour told, and is read).
_PAST = re.compile(
    rf"^(?:(?:ok|okay|so|well|um|hey|hi)[ ,]+)*(?:i|we) (?P<verb>poured|tipped|tilted|held|emptied|tried pouring)"
    rf"(?P<how>[^,;.?!]*?) and {_WHO} (?:[a-z]+ and )?{_OUT}(?P<part> over| out| everywhere)?{_WHY}{_NEXT}")
#: Its outcome told first, the pour after it: "yesterday the bowl slid off the tray when I emptied the kettle into it".
_OUTCOME_FIRST = re.compile(
    rf"^{WHEN},? {_WHO} {_OUT}[^,;.?!]*?(?: when (?:i|we|you|they|he|she|the robot|my robot)"
    rf" (?:poured|emptied|tipped|tilted|held|did it)[^,;.?!]*?)?{_NEXT}")
#: Asked whether the pour now is better, or ends what happened, or what was wrong with it: about the
#: outcome told.
_BETTER = re.compile(r"\b(?:is|will|would) (?:it|that|this) (?:be )?(?:any )?better\b"
                     r"|\b(?:will|would|does|could|can) (?:that|this|it) (?:fix|stop|prevent|solve) (?:it|that|this)\b"
                     r"|\b(?:will|would|could|might) (?:that|this|it) help\b"
                     # what was wrong with the pour told: whether it happens again, asked
                     r"|\bwhat (?:did|have) (?:i|we) (?:do|done) wrong\b")
#: A scene said to end what happened: "would a heavier bowl stop that", "would pouring centred
#: have helped", "would a heavier bowl have stayed put" (with it, does it happen); mishaps.py's too.
HELPS = re.compile(r"\b(?:will|would|does|do|could|can|might) (?P<scene>(?:a|an|the|my|some) [a-z ]+?|[a-z]+ing\b[a-z ]*?"
                   r"|cent(?:er|re)d?)"      # "would center have fixed it": poured over the middle
                   r" (?:(?:have )?(?:fix|stop|prevent|solve)(?:ed)?(?: (?:it|that|this))?|(?:have )?help(?:ed)?"
                   r"|have (?:stayed put|stayed(?: upright| up| standing)?|kept (?:it|them) (?:in|still|upright|put)|worked|been better)"
                   r"|(?:stay put|stay(?: upright| up| standing)?|keep (?:it|them) in|work|be better)"
                   # the scene as the cause of what was told: "does pulling back fast do that?"
                   r"|(?:do|cause) (?:that|this))\b")


#: The pour told, as the scene asked of it says it: tipped, tilted or held as it was; poured otherwise.
_AS_DONE = {"tipped": "tip", "tilted": "tilt", "held": "hold"}


def told(text: str) -> tuple[str, tuple[str, ...]]:
    """`text` (normalised) without an earlier pour told at its start, and
    what is said back of it; `text` as it is where it tells none."""
    m = _POUR.match(text) or _OUTCOME_FIRST.match(text) or _PAST.match(text)
    if m is None:
        return text, ()
    rest = text[m.end():]
    said = [f"{m.group(0).strip(' ,;.')}: read as nothing: an earlier pour, told; the answer is for the one asked"]
    out = "spilt" if m.group("onto") else m.group("out")
    cause = CAUSE.match(rest.strip()) is not None
    if out is None and (cause or REMEDY.match(rest.strip())):
        return text, ()             # what it did told past this module's forms: mishaps.py's to read
    if out and re.match(r"(?:so )?(?:is|was) (?:it|that|this)(?: just| maybe)? (?:too|because)\b", rest.strip()):
        return text, ()             # a cause named ("is that because it was too high"): mishaps.py's to read
    verb = "spill" if out == "spilt" else out
    if out and cause and re.search(r"\band (?:the|it|my|a|an|then)\b", m.groupdict().get("how") or ""):
        return text, ()             # more told between ("... and the whole bowl scooted across ..."): mishaps.py's
    if out and cause and m.groupdict().get("how") is not None:
        did = _AS_DONE.get(m.group("verb"), "pour")        # "i tipped it in slowly": if i tip it in slowly
        if did in ("tip", "tilt") and re.search(r"\btoo (?:far|much)\b", m.group("how")):
            did = m.group("verb")       # (tipped too far, as told: steeply; "if i tip it too far" asks how far)
        asked = f"if i {did}{m.group('how')}, {_TOLD[verb]}?"     # "... and the bowl fell over, how come?"
        said.append(f"{rest.strip(' ?.!')}: read as {asked.strip(' ?')}, asked of the earlier pour")
        rest = asked
    elif out and _BETTER.search(rest):
        asked = _BETTER.search(rest).group(0)
        rest = _BETTER.sub(_TOLD[verb], rest, count=1)
        said.append(f"{asked}: read as {_TOLD[verb]}, as the earlier pour did")
    elif out and (_VALUE_ASKED.match(rest) or _AVOID.match(rest)) and (m.group("none") or out != "came out"):
        wanted = _AGAIN.get(verb, f"it does not {verb}{m.groupdict().get('part') or ''}")
        for then in dict.fromkeys("spill" if o.group("out") == "spilt" else o.group("out") for o in _SECOND.finditer(m.group(0))):
            wanted += "" if then == verb else " and " + _AGAIN.get(then, f"it does not {then}")
        asked = rest.rstrip(" ?.!")
        rest = f"{_AVOID.sub('how should i pour', asked)} so that {wanted}?"
        said.append(f"{asked}: read as asked so that {wanted}, as the earlier pour did not")
    elif out and HELPS.search(rest):
        stops = HELPS.search(rest)
        rest = f"{rest[:stops.start()]}with {stops.group('scene')}, {_TOLD[verb]}{rest[stops.end():]}"
        said.append(f"{stops.group(0)}: read as {_TOLD[verb]}, as the earlier pour did, with {stops.group('scene')}")
    poured = liquid_named().search(m.group(0))       # the liquid told stays: "i poured honey and it spilled ..."
    if poured and re.search(r"\bso (?:that )?(?:it|nothing|none|the)\b|\bwithout\b", rest) and not says_a_liquid(rest):
        rest = f"pouring {poured.group(0)}, {rest}"      # (only where a goal is asked of it)
    return rest, tuple(said)


@lru_cache(maxsize=None)
def liquid_named(before: str = "") -> re.Pattern:
    """A liquid by one of its names (everyday.txt's), after the pattern `before` where one is given."""
    return re.compile(rf"{before}\b(?:{alternation(names('liquid'))})\b")


#: How a liquid runs, said in place of its name: "thin", "sticky".
_RUNS = re.compile(r"\b(?:thin|thick|runny|sticky|liquid)\b")


def says_a_liquid(text: str) -> bool:
    """Whether `text` names a liquid, or says how one runs: where it does, a liquid told of an
    earlier pour does not stay for the one asked."""
    return bool(liquid_named().search(text) or _RUNS.search(text))
