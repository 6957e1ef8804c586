"""A yes-or-no question asked without its auxiliary, as learners of English
and people in a hurry type it ("it fall down?", "The bowl move or stay?",
"water go on the table?"): a clause that begins with what the outcome
happens to and goes on with a verb of an outcome, then a question mark,
is read with "does" before it ("does it fall down?"; "is" before one going on: "jug not touching
bowl at all?"), as outcomes.py hears questions; so is an outcome's verb asked alone after a scene ("pour high,
wobble?": does it wobble?, "full jug, tipped over?"), and a place said wet ("table wet?": does the
table get wet?), and an outcome going on said first as a note's topic, nothing
asked ("bowl tipping - heavy pitcher - off center"), and a cause asked so ("why the liquid not go in
the bowl", "why comes the water over the edge"); so are outcomes asked in a word or two ("all in?": does
it all go in?, "leftover?": is any left in the source?, "still in bowl after?": does it stay in the bowl?), and an
outcome's verb said first, before the note's scene ("wobble? light bowl, pouring from kettle", "splash, low pour, full
cup"); an outcome said again as what it is like ("..., like running down the side?") is asked too;
going out said after staying in the bowl is out of it ("stay in bowl or go out?"). A bowl told with no
article is "the bowl" ("bowl tipped over"), and "ok or not" ending a note asks whether it is ok. A clause with an auxiliary of its own, or none of these subjects, is left as it is."""
from __future__ import annotations

import re

from pantarhei.bridge.reasoning.outcome_verbs import outcome_verb
from pantarhei.bridge.reasoning.starting import started_as_done

#: What an outcome happens to, said first: "it", "the bowl", "all the water", "some of it".
_SUBJECT = (r"(?:it|they|(?:all |some |any |most |half )?(?:of )?(?:the |my |this )?(?:light |heavy |slippery |plastic |glass "
            r"|metal |full |empty )?(?:bowl|water|liquid|milk|juice|oil|soup"
            r"|tea|coffee|stuff|jug|cup|bottle|pitcher)|(?:some|any|all|none) of it)")     # (not "any tips?")
#: Verbs of an outcome said with a word after them, which outcome_verb does not take alone.
PHRASAL = frozenset(("go", "come", "stay", "get", "land", "end", "fall", "goes", "comes", "stays", "gets", "lands", "ends",
                      "falls"))
_AUX_WORDS = r"(?:will|would|does|do|did|is|are|was|were|can|could|might|may|should|shall|gonna)"
_AUX = re.compile(rf"\b{_AUX_WORDS}\b")
_CLAUSE = re.compile(rf"(?:^|(?<=[,.;:!?] )|(?<= - ))(?P<subject>{_SUBJECT}) (?:not )?(?!{_AUX_WORDS}\b)(?P<verb>[a-z]+)\b(?P<rest>[^,.;:!?]*"
                     # (its condition after it: "it go in the bowl if I pour ..., not ...?"; no question of its own)
                     rf"(?: (?:if|when|while) (?:(?!\b(?:{_AUX_WORDS}|am|why|how|what)\b)[^.;:!?])*)?)"
                     r"(?:,? (?:yes|no|right|or not|or no))?\?")     # (a tag after it: "..., yes?")


#: An outcome's verb alone as a clause asked ("pour high, wobble?"): of "it".
#: (or after the bowl it is asked of, ending a note: "off center pour light bowl wobble?")
_ALONE = re.compile(r"(?:(?<=[,.;:!?] )|(?<= - )|(?<=\bbowl )|(?<=\bdish )|(?<=\bbasin ))(?P<verb>[a-z]+)"
                    r"(?P<part> over| out| off| down| away)?\?")
#: Outcomes asked in a word or two, as notes ask them ("jug, bowl, very fast tilt, all in?"): what each asks.
_FRAGMENTS = {"all in": "does it all go in", "all out": "does it all come out", "leftover": "is any left in the source",
              "leftovers": "is any left in the source", "any left": "is any left in the source",
              "anything left": "is anything left in the source", "everything out": "does everything come out",
              "all of it in": "does it all go in", "everything in": "does everything go in",
              "in or out": "does it all go in or spill", "goes in": "does it go in", "go in": "does it go in", "goes in or not": "does it go in",
              "still goes in": "does it still go in", "still go in": "does it still go in",
              # still in the bowl, after: it went in and stayed ("honey, high pour, still in bowl after?")
              **{f"{said} in{bowl}{after}": f"does it {'all go in' if said == 'all' else 'stay in the bowl'}{after}"
                 for said in ("all", "still", "stays", "stay") for bowl in ("", " bowl", " the bowl")
                 for after in ("", " after", " afterwards")}}
_FRAGMENT = re.compile(rf"(?:^|(?<=[,.;:!?] )|(?<= - ))(?P<said>{'|'.join(sorted(_FRAGMENTS, key=len, reverse=True))})"
                       r"(?:\?|(?<=in or out|in or not)[.!]*$)")       # ("side pour. in or out": its question mark left off)
#: "ok or not" ending a note, however set off ("pour high - ok or not"): "is it ok?".
_OK_OR_NOT = re.compile(r"(?:,| -)? (?:ok|okay) or not\b[ ?]*$")
#: A bowl told without its article, with what it did ("bowl tipped over", "bottle empty, bowl slid. why"):
#: "the bowl", as mishaps and outcomes read it.
_BARE_TOLD = re.compile(r"(?:^|(?<=[,.;:!?] )|(?<= - ))(?P<bowl>bowl|dish|basin) (?P<verb>[a-z]+(?:ed|d)|slid|fell|spun|shook)\b")
#: An outcome said again as what it is like, after one asked: "does any end up outside the bowl, like running down
#: the side?" (asked: "or does it run down the side?").
_LIKE = re.compile(r",? (?:like|as in|e\.g\.|say) (runn|dribbl|dripp|trickl|spill|splash|slosh|slopp)ing (?=(?:down|over|out|onto|on)\b)")
_LIKE_BASE = {"runn": "run", "dribbl": "dribble", "dripp": "drip", "trickl": "trickle", "spill": "spill", "splash": "splash",
              "slosh": "slosh", "slopp": "slop"}
#: Going out said after staying in the bowl, out of it (spilling out): "the ayran stay in bowl or go out?".
_OUT_AFTER_IN = re.compile(r"\b(stays? in (?:the |my )?)(bowl|dish|basin) or (?:go|goes|come|comes) out\b(?! of\b)")
#: A bowl's outcome told in the present, as learners of English tell it, its cause asked after it ("the bowl
#: fall down, why?", "when i pour, the bowl move, why?"): told in the past, as mishaps reads it.
#: (said "the bowl it fall down", "the bowl go slide", and where: "the bowl slide on the table, why")
_PRESENT_TOLD = re.compile(r"(?:^|(?<=[,.;:!?] )|(?<= - )|(?<= but )|(?<= and ))(?P<bowl>the (?:bowl|dish|basin))(?: it| go)? (?P<verb>fall|move|tip"
                           r"|slide|flip|wobble|shake|spin|go(?= sideways))(?P<part> over| down| off| sideways)?(?P<where>(?: (?!why\b)[a-z]+){0,4}?)"
                           r"(?=[,.;]? *(?:why|how come|what (?:i|we) (?:do|did) wrong)\b)")
_PAST = {"fall": "fell", "move": "moved", "tip": "tipped", "slide": "slid", "flip": "flipped", "wobble": "wobbled",
         "shake": "shook", "spin": "spun", "go": "went"}
#: An outcome's verb asked first, before the scene as a note ("wobble? light bowl, pouring from kettle",
#: "splash, low pour, full cup"): of "it".
_FIRST = re.compile(r"^(?P<verb>[a-z]+)(?P<part> over| out| off)?(?P<end>\?|,)(?= )")
#: Words of an outcome that are said of it, not done: "ok?" is "is it ok?".
_SAID_OF = frozenset(("ok", "okay", "fine", "safe", "alright", "good", "bad", "messy", "clean"))
#: Where the liquid lands, said wet ("table wet?", "floor gets wet?"): whether it gets wet.
_WET = re.compile(r"(?:^|(?<=[,.;:!?] )|(?<= - ))(?:the |my )?(?P<place>table|counter|countertop|worktop|floor|bench|tray"
                  r"|stove|cloth|tablecloth|shirt|hands?) (?:get |gets |stay |stays )?wet\?")


#: An outcome going on, said first as a note's topic with nothing asked ("bowl tipping - heavy pitcher - off
#: center"): asked, as "bowl tipping?" is.
_TOPIC = re.compile(r"^(?:the |my )?(?:bowl|dish|basin) (?P<verb>[a-z]+ing)(?: over| around| about| off| away)?(?= - |, |: )")
_ASKING = re.compile(rf"{_AUX.pattern}|\b(?:why|how|what|which|when|where|if)\b")


#: ... or with its verb before what it happens to, as learners of English ask it: "why comes the water over the edge".
_WHY_INVERTED = re.compile(rf"^why (?P<verb>[a-z]+s) (?P<subject>{_SUBJECT})\b")
#: A cause asked without its auxiliary: "why the liquid not go in the bowl", "why the bowl move?".
_WHY = re.compile(rf"^(?P<why>why|how come) (?P<subject>{_SUBJECT}) (?:not |never )?(?P<verb>[a-z]+)\b")


def aux_restored(text: str) -> tuple[str, tuple[str, ...]]:
    """`text` (normalised) with "does" before each yes-or-no clause asked
    without its auxiliary (the module's docstring), and what is said back; an
    outcome said as starting is read as the outcome first (starting.py)."""
    text, begun = started_as_done(text)
    said: list[str] = list(begun)
    text = _BARE_TOLD.sub(lambda m: f"the {m.group(0)}" if outcome_verb(m.group("verb")) else m.group(0), text)

    def past(m: re.Match) -> str:
        told = f"{m.group('bowl')} {_PAST[m.group('verb')]}{m.group('part') or ''}{m.group('where')}"
        said.append(f"{m.group(0)}: read as {told}")
        return told
    text = _PRESENT_TOLD.sub(past, text)
    if "?" in text or _ASKING.search(text):
        for m in _LIKE.finditer(text):
            said.append(f"{m.group(0).strip(' ,')}: read as or does it {_LIKE_BASE[m.group(1)]}")
        text = _LIKE.sub(lambda m: f", or does it {_LIKE_BASE[m.group(1)]} ", text)
    for m in _OUT_AFTER_IN.finditer(text):
        said.append(f"{m.group(0)[m.end(2) - m.start() + 4:]}: read as out of the {m.group(2)}")
    text = _OUT_AFTER_IN.sub(r"\1\2 or spill out", text)
    first = _FIRST.match(text)
    if first and outcome_verb(first.group("verb")) and (first.group("end") == "?" or not (
            "?" in text or _ASKING.search(text))):      # ("spill, what should i do": asked after it)
        verb = first.group(0).rstrip("?,")
        said.append(f"{verb}: read as does it {verb}")
        text = f"does it {verb}?{text[first.end():]}"

    def restore(m: re.Match) -> str:
        verb = m.group("verb")
        if _AUX.search(m.group(0)) or not (outcome_verb(verb) or verb in PHRASAL):
            return m.group(0)
        asked = re.sub(r" or (?:stay|stays|stay still|stay put)(?=\?$)", "", m.group(0))     # "move or stay?": one question
        aux = "is" if verb.endswith("ing") else "does"      # "jug not touching bowl at all?": is it not touching
        said.append(f"{m.group(0).rstrip('?')}: read as {aux} {asked.rstrip('?')}")
        return f"{aux} {asked}"

    def alone(m: re.Match) -> str:
        verb = m.group("verb")
        if not outcome_verb(verb):
            return m.group(0)
        before = re.split(r"[,.;:!?]| - ", m.string[:m.start()])[-1]
        if re.search(r"\b(?:bowl|dish|basin) $", before) and (re.search(r"(?:ing|s|ed)$", verb) or re.search(
                rf"{_AUX.pattern}|\b(?:if|when|while|without|so|that|what|why|how)\b", before)):
            return m.group(0)           # "... without the bowl sliding?", "what if the bowl moves?": said, not a note's

        aux = "is" if verb in _SAID_OF else "does"        # "45 deg, ok?": is it ok?
        if m.group("part"):                                # "full jug, tipped over?": whether it happens
            said.append(f"{verb}{m.group('part')}: read as asked whether it happens")
            return f"{aux} it {verb}{m.group('part')}?"
        said.append(f"{verb}: read as {aux} it {verb}")
        return f"{aux} it {verb}?"

    def wet(m: re.Match) -> str:
        said.append(f"{m.group(0).rstrip('?')}: read as does the {m.group('place')} get wet")
        return f"does the {m.group('place')} get wet?"

    def fragment(m: re.Match) -> str:
        said.append(f"{m.group('said')}: read as {_FRAGMENTS[m.group('said')]}")
        return f"{_FRAGMENTS[m.group('said')]}?"

    topic = _TOPIC.match(text) if "?" not in text and not _ASKING.search(text) else None
    if topic and outcome_verb(topic.group("verb")):      # "bowl tipping - heavy pitcher - off center"
        text = f"{topic.group(0)}?{text[topic.end():]}"
    inverted = _WHY_INVERTED.match(text)
    if inverted:                                        # "why comes the water over the edge": why does it come
        verb = inverted.group("verb")
        base = next((b for b in (verb[:-2], verb[:-1]) if outcome_verb(b) or b in PHRASAL), None)
        if base:
            said.append(f"{inverted.group(0)}: read as why does {inverted.group('subject')} {base}")
            text = f"why does {inverted.group('subject')} {base}{text[inverted.end():]}"
    why = _WHY.match(text)
    if why and (outcome_verb(why.group("verb")) or why.group("verb") in PHRASAL) and not _AUX.match(text, why.end("why") + 1):    # "why the liquid not go in"
        said.append(f"{why.group(0)}: read as {why.group('why')} does {text[why.end('why') + 1:why.end()]}")
        text = f"{why.group('why')} does {text[why.end('why') + 1:]}"
    text = _FRAGMENT.sub(fragment, text) if "?" in text or "in or " in text else text
    if _OK_OR_NOT.search(text):                         # "jug touching bowl rim - ok or not": ok?
        said.append("ok or not: read as is it ok")
        text = _OK_OR_NOT.sub(", is it ok?", text)
    text = _CLAUSE.sub(restore, text)
    text = _ALONE.sub(alone, text) if "?" in text else text
    return (_WET.sub(wet, text) if " wet?" in text else text), tuple(said)
