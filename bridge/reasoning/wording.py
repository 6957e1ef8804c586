"""A question's words as reading.py reads them: lower case, stemmed, each
with its clause and as it was written, the everyday phrases of words.py
rewritten into the vocabulary's words.

A number keeps its sign: "-10 degrees", "\u221210 degrees" (a Unicode minus)
and "minus 10 degrees" are one token "-10"; a hyphen between two numbers
("10-20 cm") is a range ("10 to 20"), never a sign. A speed ("0.5 m/s",
"2 km/h") becomes the number and the unit "speed", a speed of tilting
("30 deg/s") the unit "unit_turn_speed": quantities.py refuses both,
naming what would be read. A number said with tilting and no unit is an
angle ("tilt it 45"), and one said "tilted back" is negative ("tilted back
by 20 degrees" is -20 degrees, read with the words "tilted back").

A word written otherwise than it is read is said back: a contraction typed
without its apostrophe ("im", "doesnt", "wont") is read as with it, a word
as chat types it ("u", "y", "wat", "lite") as the word meant, and
`normalising` gives, beside the text, what `ask` says of each ("im: read
as I'm"); spelling.py says back the words it reads as others ("teh: read
as the").
"""
from __future__ import annotations

import re
import unicodedata
from bisect import bisect_left
from dataclasses import dataclass

from pantarhei.bridge.reasoning.avoided import avoided
from pantarhei.bridge.reasoning.because import cause_asked
from pantarhei.bridge.reasoning.compared_or import compared_or
from pantarhei.bridge.reasoning.cued import Cued
from pantarhei.bridge.reasoning.asides import restated
from pantarhei.bridge.reasoning.earlier_pour import told
from pantarhei.bridge.reasoning.every_pour import as_every_pour
from pantarhei.bridge.reasoning.last_of_it import the_last_of
from pantarhei.bridge.reasoning.rim_strikers import lip_of_source, source_on_rim, spout_striking, stream_striking, touch_told
from pantarhei.bridge.reasoning.fullness import refuse_bowl_fill
from pantarhei.bridge.reasoning.little_vessels import refuse_little, refuse_wobbly
from pantarhei.bridge.reasoning.more_in import more_in
from pantarhei.bridge.reasoning.which_one import which_one
from pantarhei.bridge.reasoning.words import rewrites
from pantarhei.theory.lexicon import load_vocabulary

#: Words that end a clause (besides punctuation): negation stops there.
CLAUSE_ENDS = {"but", "then", "while", "whereas", "instead", "rather", "except", "so"}
#: "so" said of how much after these ("my bowl is so light") or before these ("hold the jug so high"): no clause ends there.
_SO_AFTER, SO_BEFORE = frozenset(("is", "are", "was", "were", "be", "looks", "seems", "feels")), frozenset("high low far close near much fast quick slow slowly steep steeply tilted hard".split())
#: A number as a question writes it ("45", "1.5", "-10"): one token.
NUMBER = r"-?\d+(?:\.\d+)?"
#: The minus signs a number may be written with: ASCII, U+2212 and the en dash.
_MINUS = "-\u2212\u2013"
#: The first letters of the units a number may be said in (quantities.py's): a number
#: said with none is an angle when said with tilting.
_UNIT_WORDS = (r"mm|cm|m|ft|inch\w*|feet|foot|met(?:re|er)\w*|centimet\w*|millimet\w*|deg\w*|s|secs?"
               r"|second\w*|ms|milli\w*|g|kg|gram\w*|kilo\w*|particle\w*|percent|rad\w*|speed"
               r"|unit_\w+|%|ml|l|cl|dl|oz|ounce\w*|lit(?:re|er)\w*")
#: What the contractions other than "n't" and "'s" stand for: "it'll", "I'm".
_CONTRACTED = {"ll": "will", "re": "are", "m": "am", "ve": "have", "d": "would"}
#: The stage words: an "and" before one starts a new clause ("tilt it and end upright").
STAGE_WORDS = ("start", "pour", "end", "finally", "final", "approach", "retreat", "then")
#: The words an "and" before which starts a new clause: the stage words, a move up or
#: down, said in its own stage ("pour low and bring it back up afterwards"), and a tilt
#: ("come in low and tilt it halfway": stages.py's to place).
_NEW_CLAUSE = (*STAGE_WORDS, "raise", "lower", "tilt", "tilts", "tilting", "tip", "tips")
#: Words that may stand between such an "and" and its stage word: "and a slow retreat",
#: and words said in passing: "hold it high and just tip it".
_BEFORE_STAGE = {"a", "an", "the", "very", "fast", "quick", "slow", "slowly", "moderate", "gentle", "just",
                 "simply"}


def stem(w: str) -> str:
    for suffix in ("ing", "ly", "ed", "es", "s"):
        if len(w) > len(suffix) + 2 and w.endswith(suffix):
            w = w[: -len(suffix)]
            break
    return w[:-1] if len(w) > 3 and w.endswith("e") else w


@dataclass(frozen=True)
class Token:
    word: str        # stemmed, lower case (a proposition's name as written)
    raw: str         # as written
    clause: int
    said_back: str = ""   # what `ask` says of an everyday word ("read as an ordinary liquid ...")


#: Contractions typed without their apostrophe, as written -> with it: each read as with
#: it and said back. Not the words of their own ("its", "well", "were", "ill", "hell",
#: "shell", "id"); "cant" only beside a pronoun (to cant a jug is to tilt it).
_BARE = {**{f"{w}nt": f"{w}n't" for w in ("do", "does", "did", "is", "are", "was", "were", "has",
                                           "have", "had", "could", "would", "should", "must",
                                           "need")},
         "wont": "won't", "im": "i'm", "ive": "i've", "youre": "you're", "youve": "you've",
         "youll": "you'll", "theyre": "they're", "theyve": "they've", "theyll": "they'll",
         "weve": "we've", "itll": "it'll", "thatll": "that'll"}
_PRONOUNS = "i|it|we|you|they|he|she|this|that"
#: Words as chat types them -> the word meant, read so and said back ("u: read as you"); "y"
#: only asking ("y does it spill"), not the offset's axis ("y = 3 cm"), and "its" only as
#: "it's" ("if its right over the middle", not "its handle"); "lite" is light, not a litre.
_CHAT = {"u": "you", "ur": "your", "wat": "what", "wut": "what", "wot": "what", "realy": "really",
         "rly": "really", "lite": "light", "b4": "before", "frm": "from", "abv": "above", "liq": "liquid", "dwn": "down", "approx": "about", "tbl": "table", "btl": "bottle",
         "qkly": "quickly", "thx": "thanks", "alot": "a lot",
         "tiped": "tipped", "tipd": "tipped", "evrywhere": "everywhere", "evry": "every",
         "pls": "please", "plz": "please", "abt": "about", "shud": "should", "wud": "would",
         "outta": "out of", "kinda": "kind of", "tho": "though", "cuz": "because", "coz": "because", "cos": "because",
         "cn": "can", "hw": "how", "cud": "could", "shld": "should",
         # letters typed in the wrong order or left out, as people type in a hurry
         "teh": "the", "hte": "the", "th": "the", "wil": "will", "wll": "will", "wen": "when", "whn": "when",
         "wht": "what", "waht": "what", "adn": "and", "nad": "and", "taht": "that", "thta": "that",
         "becuase": "because", "becasue": "because", "shoudl": "should", "shoud": "should", "woudl": "would",
         "dosnt": "doesn't", "doesent": "doesn't", "dosent": "doesn't", "owt": "out", "sirup": "syrup", "honney": "honey",
         "upon": "on", "bc": "because", "b/c": "because", "ovr": "over", "wld": "would", "cld": "could", "shd": "should"}
_CHATTED = (rf"\b(?:{'|'.join(_CHAT)})\b|\by(?= (?:does|do|did|is|are|was|would|will|can|not)\b| *\?* *$)"
            r"|\bits(?= (?:too|to|so|very(?! (?:edge|rim|lip|brim|border|middle|centre|center|top|side)\b)|really|right|just|not|over|at|in|on|upside|nearly|almost|only"
            r"|going|held|[a-z]+ed)\b)"
            # "from mug 2 bowl" (to), "best tilt 4 pouring soup" (for): a digit standing for a word,
            # between words and before what it would govern, never a number of a unit ("tilt 4 degrees")
            # "tilt it all the way n yank it away": and, between two words
            r"|(?<=[a-z] )n(?= [a-z])|\bcause(?= (?:my|i|i'm|we|she|he|they|mom|mum|dad)\b)"   # "cause my mom said no"
            r"|(?<=[a-z] )(?<!\ba )(?<!\ban )(?<!\bthe )(?:2(?= (?:the|a|an|my|your|bowl|cup|mug|glass|dish|pot|jug|jar)\b)"
            r"|4(?= (?:[a-z]+ing|the|a|an|my|your|it|me|not|no)\b))")


def unaccented(text: str) -> str:
    """`text` with its letters' accents taken off ("crème anglaise": creme anglaise)."""
    return "".join(c for c in unicodedata.normalize("NFD", text) if unicodedata.category(c) != "Mn")


def normalised(text: str) -> str:
    """`text` in lower case with its apostrophes, negative contractions,
    signs, degrees and speeds written one way."""
    return normalising(text)[0]


#: The properties of a body a simile with "like" may liken: "heavy like molten lead".
_PROPERTIES = "light|heavy|slippery|sticky|thick|thin|runny|bouncy|smooth|grippy|flimsy"
#: The values a simile may liken: "light as a feather".
_LIKENED = "light|heavy|slippery|sticky|thick|thin|runny|bouncy|slow|fast|quick|smooth|grippy|full|high|low"


#: What a verb is after "would have", and what it is asked as: "stayed put" as "stay put".
_HAD = {**{w: w[:-2] for w in ("helped", "worked", "stayed", "spilled", "splashed", "landed", "ended", "missed",
                              "knocked", "touched", "overflowed", "prevented", "avoided")},
        **{w: w[:-1] for w in ("moved", "caused")},
        "kept": "keep", "fixed": "fix", "stopped": "stop", "spilt": "spill", "tipped": "tip", "slid": "slide",
        "gone": "go", "come": "come", "hit": "hit", "fallen": "fall", "made": "make", "dripped": "drip",
        "emptied": "empty", "left": "leave", "slipped": "slip", "flipped": "flip"}


def normalising(text: str) -> tuple[str, tuple[str, ...]]:
    """`text` normalised, and what is said back of each word of it read as
    another ("doesnt: read as doesn't"), in the order written."""
    text = unaccented(text.lower().replace("\u2019", "'"))
    said: dict[str, None] = {}

    def respelt(written: str) -> str:
        meant = _BARE.get(written) or {**_CHAT, "y": "why", "its": "it's", "2": "to", "4": "for", "n": "and", "cause": "because"}.get(written, "can't")
        shown = "I" + meant[1:] if meant.startswith("i'") else meant
        said.setdefault(f"{written}: read as {shown}")
        return meant

    text = re.sub(rf"\b(?:{'|'.join(_BARE)})\b|{_CHATTED}", lambda m: respelt(m.group(0)), text)
    text = re.sub(rf"\bcant\b(?= (?:{_PRONOUNS})\b)", lambda m: respelt(m.group(0)), text)
    text = re.sub(rf"\b((?:{_PRONOUNS}) )cant\b", lambda m: m.group(1) + respelt("cant"), text)
    # "pour high and not get any splashing": wanted as "without getting any"
    text = re.sub(r"\band (?:not|never) (?:get|have|cause|make)(?= (?:any|a)\b)",
                  lambda m: said.setdefault(f"{m.group(0)}: read as without getting") or "without getting", text)
    text = re.sub(r"\band (?:not|never) (spill|splash|drip)(?: (?:a single|one|a) drop)?(?= *(?:[?.!,;]|$))",  # "... and not spill?"
                  lambda m: said.setdefault(f"{m.group(0)}: read as without {m.group(1)}ing") or f"without {m.group(1)}ing", text)
    # an outcome forbidden is one wanted not to happen: "no splashing allowed" is "without splashing"
    text = re.sub(r"\bno ([a-z]+ing) (?:allowed|permitted|please)\b",
                  lambda m: said.setdefault(f"{m.group(0)}: read as without {m.group(1)}") or f"without {m.group(1)}", text)
    # "w/o" and "w/" as notes write them: without, with
    text = re.sub(r"\bw/o\b|\bw/(?= ?[a-z])", lambda m: said.setdefault(f"{m.group(0)}: read as with{'out' * (m.group(0) == 'w/o')}")
                  or f"with{'out' * (m.group(0) == 'w/o')} ", text).replace("  ", " ")
    # a simile says the value it likens: "light as a feather", "thick as ketchup" (not "as high as
    # the rim": a comparison)
    text = re.sub(rf"(?<!\bas )\b({_LIKENED}) as (?:a |an )?(?!before\b|usual\b|normal\b|last\b|ever\b|possible\b"
                  r"|you\b|it\b|i\b|we\b|the\b|that\b|this\b)[a-z]+\b",
                  lambda m: said.setdefault(f"{m.group(0)}: read as {m.group(1)}") or m.group(1), text)
    # a property likened with "like", its example ending the clause: "heavy like molten lead", "high like a waterfall"
    text = re.sub(rf"\b({_PROPERTIES}|high|low) like (?:a |an |some )?(?!(?:{_PRONOUNS}|the|that|this|it)\b)[a-z]+(?: [a-z]+)?"
                  r"(?= *(?:[,.;:!?\u2013\u2014-]|$|and\b|but\b|or\b|does\b|will\b|would\b|is\b|without\b|so\b|if\b|when\b))",
                  lambda m: said.setdefault(f"{m.group(0)}: read as {m.group(1)}") or m.group(1), text)
    # the simile before its property: "really light, like paper light"
    text = re.sub(rf"\b(?:({_PROPERTIES}),? (?=like (?:a |an )?[a-z]+ \1\b))?like (?:a |an )?[a-z]+ ({_PROPERTIES})\b",
                  lambda m: said.setdefault(f"{m.group(0)}: read as {m.group(2)}") or m.group(2), text)
    # a second property said after a comma of the body the first is said of: "the bowl is paper, very light"
    text = re.sub(rf"\b((?:bowl|dish|basin|jug|cup|bottle|pitcher|mug|jar)s? (?:is|are|was|were) [a-z]+),"
                  rf"(?= (?:very |really |quite |super |so |pretty |fairly |rather |kinda )?(?:{_PROPERTIES})\b)", r"\1 and", text)
    # a limit asked ("how close is too close", "how high is too high"): the value asked, not one said
    text = re.sub(r"\bhow (close|near|high|low|far|steep|fast|slow) is too \1\b",
                  lambda m: said.setdefault(f"{m.group(0)}: read as how {m.group(1)} can i go") or f"how {m.group(1)} can i go", text)
    # "y/n" ending a note: whether it happens or not ("bowl slide y/n"); after a comma, what it asks ("..., yes or no")
    text = re.sub(r" *(,)? *\b(?:y/n|y or n|(?<![?] )(?:yes/no|yes or no|yes no))\b(?=[?.!]* *$)", lambda m: said.setdefault(
        f"{m.group(0).strip(' ,')}: read as " + ("what it asks" if m.group(1) else "or not")) or ("" if m.group(1) else " or not"), text)
    # less mess wanted: "is it better to pour close or from high up, for less mess?"
    text = re.sub(r"\b(?:for|with) (?:less|no|minimal|the least|minimum) (?:mess|spill(?:s|age|ing)?|splash(?:es|ing)?)(?= *[?.!]* *$)",
                  lambda m: said.setdefault(f"{m.group(0)}: read as so that nothing spills") or "so that nothing spills", text)
    # an outcome said as a thing done: "does the bowl do that little rocking thing": does it rock
    text = re.sub(r"\b(do|does|did) (?:that|the|this|a|its) (?:little |weird |funny |small )?([a-z]+ing) (?:dance |motion |move )?thing\b",
                  lambda m: said.setdefault(f"{m.group(0)}: read as {m.group(1)} {m.group(2)}") or f"{m.group(1)} {m.group(2)}", text)
    # an outcome said with "-wise" ("what's the difference ..., splash-wise"): whether it happens, asked
    text = re.sub(r"(?:^|(?<=[,;:.?!] ))(spill|splash|drip|mess|wobble|slide|tip)[- ]?wise\b",
                  lambda m: said.setdefault(f"{m.group(0).replace('-', ' ')}: read as does it {m.group(1)}") or f"does it {m.group(1)}", text)
    # none landed where it spills, said with no verb: "all of it into the bowl with no drops on the table"
    text = re.sub(r"\bwith (?:no|zero) (?:drops?|drips?|spills?|splashes|liquid|water|mess) (?=(?:on|onto) (?:the |my )?"
                  r"(?:table|counter|countertop|worktop|floor|bench|tablecloth|ground)\b)",
                  lambda m: said.setdefault(f"{m.group(0).strip()}: read as without any landing") or "without any landing ", text)
    # a bigger mess is more of it: "which makes a bigger mess", "a smaller splash"
    text = re.sub(r"\b(?:a )?(bigger|larger|worse|smaller) (mess|splash|spill)(es)?\b", lambda m: said.setdefault(
        f"{m.group(0)}: read as {(w := 'less' if m.group(1) == 'smaller' else 'more')} {m.group(2)}") or f"{w} {m.group(2)}", text)
    # "splash or no splash": whether it happens or not
    text = re.sub(r"\b([a-z]+) or no \1\b", lambda m: said.setdefault(f"{m.group(0)}: read as {m.group(1)} or not")
                  or f"{m.group(1)} or not", text)
    # "one" standing for the noun a contrast is of: "a heavy bowl instead of a light one" (not
    # one poured from or into, which the noun repeated would lose)
    text = re.sub(r"(?<!\bfrom )(?<!\binto )\b((?:a|an|the) [a-z]+ )(?!(?:and|or|but)\b)([a-z]+) (instead of|rather than|and not|not) (a|an|the) ([a-z]+) one\b",
                  lambda m: said.setdefault(f"one: read as {m.group(2)}")
                  or f"{m.group(1)}{m.group(2)} {m.group(3)} {m.group(4)} {m.group(5)} {m.group(2)}", text)
    # a probability written as one: "P(no_spill)", "p(spill)"
    text = re.sub(r"\b(p|pr|prob)\s*\((?=[^()]*\))",
                  lambda m: said.setdefault(f"{m.group(1)}: read as the chance of") or "the chance of (",
                  text)
    # a velocity is a speed: "what approach velocity keeps it clear" asks the approach's speed
    text = re.sub(r"\bvelocit(?:y|ies)\b", lambda m: said.setdefault(f"{m.group(0)}: read as speed") or "speed", text)
    # every drop of a liquid is all of it: "get every drop of the syrup into the bowl"
    text = re.sub(r"\bevery (?:last |single )?drop of (?:the |my |that |this )?",
                  lambda m: said.setdefault(f"{m.group(0).strip()}: read as all of the") or "all of the ", text)
    text = the_last_of(text, said)                     # "does the last bit stay in the jug": some; "poured the last bit of"
    # the source yeeted is flung ("yeet the cup over the bowl": a fast move in); the liquid yeeted, a force of
    # pouring, is left to be refused
    text = re.sub(r"\byeet(s|ed|ing)?(?= (?:it|(?:the|my|a|an) (?:cup|mug|jug|glass|bottle|pitcher|can|pot|pan|carton|source"
                  r"|container|flask|beaker|kettle|shaker)s?)\b)",
                  lambda m: said.setdefault(f"{m.group(0)}: read as fling") or {"s": "flings", "ed": "flung", "ing": "flinging"}.get(
                      m.group(1) or "", "fling"), text)
    # "it make splash out from bowl", as learners of English ask it: will it splash out
    text = re.sub(r"(?:^|(?<=[,;:.?!] ))(it|they) (?:make|makes) (?=(?:splash|spill|drip|overflow|slosh)\w*\b)",
                  lambda m: said.setdefault(f"{m.group(0).strip()}: read as will {m.group(1)}") or f"will {m.group(1)} ", text)
    # "how much high", as learners of English ask a value: how high
    text = re.sub(r"\bhow much (high|far|low|close|near|steep|fast|slow|slowly|quickly)\b",
                  lambda m: said.setdefault(f"{m.group(0)}: read as how {m.group(1)}") or f"how {m.group(1)}", text)
    # what would have been is asked as what would be: "would a heavier bowl have stayed put"
    # (not "would that have helped" after a pour told: that pour is past, and no help)
    text = re.sub(rf"\b((?:would|could|might|will|should)(?: (?!have\b)[a-z]+){{0,6}}?)(?<! that)(?<! this)(?<! it) have (?:been )?({'|'.join(_HAD)})\b",
                  lambda m: said.setdefault(f"have {m.group(2)}: read as {_HAD[m.group(2)]}")
                  or f"{m.group(1)} {_HAD[m.group(2)]}", text)
    text, again = restated(_normalised(text))         # "-2 cm (i.e. below the rim)"
    text = spout_striking(lip_of_source(text, said), said)   # "does the jug lip touch the bowl": its spout
    text = stream_striking(text, said)                 # "the stream hit the edge and bounced out": bounced out
    text = touch_told(source_on_rim(text, said), said)   # "if the jug touches the rim, will it tip": low, near the rim
    text = as_every_pour(text, said)                   # "if I don't hold the bowl": every pour's, nothing
    # what is going to happen, said subject first: "stock gonna land in it?" asks "will stock land in it?"
    text = re.sub(r"(?:^|(?<=[,;:.?!] ))((?:the |my |a |this |that )?(?!i\b|we\b|you\b)[a-z]+|it|they) (?:is |are )?gonna (?=[a-z]+\b)",
                  lambda m: said.setdefault(f"{m.group(0).strip()}: read as will {m.group(1)}") or f"will {m.group(1)} ", text)
    text, earlier = told(text)                         # "last time I poured from 20 cm, ...": not read
    text, avoiding = avoided(text)                     # "the bowl slides, what height stops that"
    text, cause = cause_asked(text)                    # "it runs down the side. is it because I hold it low?"
    text, compared = compared_or(text)                 # "is it better high or low": "high vs low"
    text, more = more_in(text)                         # "gets more water into the bowl": does it go in
    text, which = which_one(text)                      # "a vs b - which one slides more": does it slide
    refuse_little(text)                                # "a little jug": a size
    refuse_wobbly(text)                                # "my bowl is light and wobbly": a shape
    refuse_bowl_fill(text)                             # "how full can my bowl get": the bowl's fill
    return text, (*said, *again, *earlier, *avoiding, *cause, *compared, *more, *which)


def _normalised(text: str) -> str:
    """normalised's `text`, lower case, its bare contractions written with their apostrophe."""
    text = re.sub(rf"(\d)\s*[{_MINUS}]\s*(?=\d)", r"\1 to ", text)          # 10-20 cm: a range
    text = re.sub(rf"(?<![\w.])[{_MINUS}]\s?(?=\d)", "-", text)             # -10, \u221210
    text = re.sub(r"\bminus\s+(?=\d)", "-", text)
    # a dash between words ends a clause as a comma does ("held upside down - will any come out")
    text = re.sub(r"(?<=[a-z?!.)]) +(?:-{1,2}|[\u2013\u2014]) +(?=[a-z(])|(?<=[a-z])[\u2013\u2014](?=[a-z])", ", ", text)
    text = re.sub(r"(?<=[a-z]) / (?=[a-z])", " vs ", text)                   # "heavy bowl / light bowl": two compared
    text = re.sub(r"(?<=[a-z]) ?& ?(?=[a-z])", " and ", text)                 # "moved in qkly & tilted": and
    text = re.sub(r"\bcan't\b|\bcannot\b", "can not", text)
    text = re.sub(r"\bwon't\b", "will not", text)
    text = re.sub(r"n't\b", " not", text)
    text = re.sub(r"'(ll|re|m|ve|d)\b", lambda m: " " + _CONTRACTED[m.group(1)], text)
    text = text.replace("%", " percent ")
    text = re.sub(r"'s?\b", "", text)                 # the destination's rim
    text = re.sub(r"(\d)\s*\u00b0", r"\1 degrees ", text)  # 45\u00b0
    text = re.sub(r"(\d)\s*(?:\"|\u2033)(?=\s|$)", r"\1 inches ", text)   # 3" (inches), 1\u2032 (feet)
    text = re.sub(r"(\d)\s*\u2032(?=\s|$)", r"\1 feet ", text)
    # out from a bowl, as learners say it: out of it ("is it coming out from the cup")
    text = re.sub(r"\b((?:come|comes|coming|came|pour|pours|pouring|drain\w*|flow\w*|get|gets|getting|jump\w*|bounc\w*|splash\w*"
                  r"|fly|flies|flew|spill\w*) out) from\b", r"\1 of", text)
    # a quantity named before its number: "height: 15 cm", "tilt = 45 deg"
    text = re.sub(r"(?<=[a-z])\s*[:=]\s*(?=[-\u2212]?\d)", " ", text)
    # a contrast said first is said after what it contrasts with: "instead of fast, move in slowly"
    text = re.sub(r"^(instead of|rather than) ([a-z ]{1,30}), ([^,:;?!.]+)", r"\3 \1 \2", text)
    # a length of zero needs no unit: "lateral offset 0", "0 offset" (an angle's is tilting's, below)
    text = re.sub(rf"\b((?:offset|height|distance|gap|displacement|x|y|z)(?: of)?) 0(?:\.0+)?"
                  rf"(?![\w.%\u00b0]| ?(?:{_UNIT_WORDS})\b)", r"\1 0 mm", text)
    text = re.sub(r"(?<![\w.-])0(?:\.0+)? (?=(?:lateral |sideways |side )?(?:offset|height|distance|gap)\b)",
                  "0 mm ", text)
    # "5in", "5 in above": inches (not "pour 5 in the bowl")
    text = re.sub(r"(\d)(?:in|\s+in(?= (?:above|below|over|under|up|high|off|from|away|to the"
                  r"|higher|lower|sideways|offset|relative)\b|\s*(?:[,;.!?)]|$)))\b", r"\1 inches", text)
    # tilted back by an angle: the angle back, negative ("tilted back 20 degrees")
    text = re.sub(r"\b((?:tilt|tip|lean)\w*(?: (?:it|the \w+))?) back(?:wards?)?(?: (?:by|at|to|about|around))*"
                  r" (\d+(?:\.\d+)?)(?= ?(?:degrees?|degs?)?\b(?! ?[-\d]))", r"\1 back at -\2", text)
    # a number said with tilting and no unit is an angle: "tilt it 45", "tilted to 30 to 40",
    # "mug tilt 90 bowl slide" (a note: the next noun starts another clause)
    text = re.sub(r"\b((?:(?:tilt|tip|angl|inclin|lean)\w*|pitch(?:ed|ing)?)(?: (?:it|the \w+))?(?: (?:to|by|at|of|about|around"
                  r"|roughly|approximately|some))*) (-?\d+(?:\.\d+)?(?: (?:to|or) -?\d+(?:\.\d+)?)?)"
                  rf"(?![\w%\u00b0-]|\.\d| ?(?:{_UNIT_WORDS})\b| (?:to|or|and) -?\d)"
                  r"(?= *(?:$|[,;.!?):\u2013\u2014]|- |(?:and|then|but|so|while|before|after|from|above|over|with|into|at"
                  r"|during|when|if|in|on|towards|away|or|to|degrees?"
                  r"|bowl|bowls|cup|mug|glass|jug|liquid|water|source|destination|does|do|will|would|is"
                  r"|spill\w*|splash\w*|slid\w*|drip\w*|overflow\w*|wobbl\w*|slosh\w*)\b))",   # ("jug tilt 45 spill?")
                  r"\1 \2 degrees", text)
    text = re.sub(r"\bat (?:an? )?(-?\d+(?:\.\d+)?)(?:-| )angle\b", r"at a \1 degree angle", text)      # "at a 45 angle"
    text = re.sub(r"(\d)\s*(?:(?:deg|degs|degrees?)\s*(?:/\s*(?:s|sec)\b|per (?:second|sec)\b)"
                  r"|rpm\b)", r"\1 unit_turn_speed", text)        # 30 deg/s: a speed of tilting
    text = re.sub(r"(\d)\s*(?:(?:k?m|cm|mm)\s*/\s*(?:s|sec|h|hr)|(?:k?m|cm|mm|metres?|meters?|"
                  r"centimet(?:re|er)s?|inch(?:es)?|feet|foot) per (?:second|sec|hour|minute)|"
                  r"mph|kph|km/h)\b", r"\1 speed", text)
    return re.sub(r"(\d)([a-z])", r"\1 \2", text)       # 30cm


def names_written(text: str) -> tuple[str, tuple[str, ...]]:
    """`text` with the names of the vocabulary written as they are: a
    parameter's word by word ("pour_z = 150 mm" is "pour z = 150 mm", read
    as a height), an expectation's taken out as asked ("is no_spill
    expected?"); and the expectations named."""
    if "_" not in text:
        return text, ()
    vocab = load_vocabulary()
    params = "|".join(p.name for p in vocab.parameters)
    text = re.sub(rf"\b(?:{params})\b", lambda m: m.group(0).replace("_", " "), text)
    named = tuple(dict.fromkeys(re.findall(rf"\b(?:{'|'.join(e.name for e in vocab.expectations)})\b", text)))
    if named:
        text = re.sub(rf"\b(?:{'|'.join(named)})\b", " outcome ", text)
    return text, named

def tokens(text: str) -> list[Token]:
    """The words of `text` in the vocabulary's words, stemmed, each with its clause."""
    pairs = [(w, w, "") for w in re.findall(rf"{NUMBER}|[a-z0-9_]+|[,;.!?:()]", normalised(text))]
    joined = " ".join(w for w, _, _ in pairs)
    for pattern, words, said in rewrites():
        if isinstance(pattern, Cued):
            if not pattern.search(joined):
                continue
            spans = _spans(pattern.pattern, joined, pairs)
        else:
            spans = pattern.spans([w for w, _, _ in pairs])
        if spans:
            pairs = _rewrite(pairs, spans, words, said)
            joined = " ".join(w for w, _, _ in pairs)
    out, clause = [], 0
    for k, (word, raw, said) in enumerate(pairs):
        if (not re.match(r"[-a-z0-9_]", word) or (word in CLAUSE_ENDS and not (word == "so" and (k and pairs[k - 1][0] in _SO_AFTER or pairs[k + 1:k + 2] and pairs[k + 1][0] in SO_BEFORE)))
                or (word == "and" and _new_clause([w for w, _, _ in pairs[k + 1:k + 4]]))):
            clause += 1
            if not re.match(r"[-a-z0-9_]", word):
                continue
        out.append(Token(word if "_" in word or word[0] == "-" else stem(word), raw, clause, said))
    return out


def _new_clause(after: list[str]) -> bool:
    """Whether the words after an "and" begin a clause of their own: a stage
    word, or a move up or down or a tilt, next or after an article and a
    word of speed ("a quick approach and a slow retreat")."""
    while after and after[0] in _BEFORE_STAGE:
        after = after[1:]
    return bool(after) and after[0] in _NEW_CLAUSE


def _spans(pattern: re.Pattern, joined: str, pairs) -> list[tuple[int, int]]:
    """(first, end) of the words each match of `pattern` in `joined` (the
    words of `pairs`, spaced) covers: matches that start on a word."""
    starts, at = [], 0
    for w, _, _ in pairs:
        starts.append(at)
        at += len(w) + 1
    out, last = [], 0
    for m in pattern.finditer(joined):
        i, j = bisect_left(starts, m.start()), bisect_left(starts, m.end())
        if i < last or i == len(starts) or starts[i] != m.start():
            continue
        out.append((i, j))
        last = j
    return out


def _rewrite(pairs: list[tuple[str, str, str]], spans: list[tuple],
             words: tuple[str, ...], said: str):
    """(word, as written, said back) triples with the words of each span
    (first, end) read as `words`, said back as `said`; a span (first, end,
    its own words) is read as its own words."""
    out, last = [], 0
    for i, j, *own in spans:
        raw = " ".join(r for k, (_, r, _) in enumerate(pairs[i:j], i)    # a word read as two once
                       if k == i or r != pairs[k - 1][1])
        out += pairs[last:i] + [(w, raw, said) for w in (own[0] if own else words)]
        last = j
    return out + pairs[last:]
