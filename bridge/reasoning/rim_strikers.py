"""What strikes the bowl's rim, said before a question is read (wording.normalising): the lip
(rim, edge) of the source, which is its spout ("does the jug's lip hit the bowl": the source's contact,
asked; a spout said alone, "spout hit the edge": the source's), the source said to touch the rim as
the scene of another question ("if the jug touches the rim, will the bowl tip?": poured low, near the
rim), and the liquid, whose striking is no outcome ("the stream hit the edge of the bowl and jumped
out": what it did next is read)."""
from __future__ import annotations

import re
from functools import lru_cache

from pantarhei.bridge.errors import UserError
from pantarhei.bridge.reasoning.everyday import alternation, names

#: Why the source set on the bowl (rested, put) is refused: leaning it there is pouring low near the rim.
_SET_ON = ("no proposition sets the source on the bowl, a touch (whether it hits the bowl is asked): say where it is"
           " held (\"pour low near the rim\")")
#: Containers that are the destination when a lip is named: the lip of one is its rim.
_DESTINATIONS = frozenset(("bowl", "dish", "basin", "tub", "bucket", "pail", "vat", "container", "destination", "receptacle"))
#: A lip said after these is a place ("over the lip of the cup", "drip off the lip"): not the source's part.
_AT_A_PLACE = "".join(f"(?<!{w} )" for w in ("over", "past", "above", "near", "at", "to", "onto", "off", "from", "around", "along"))


def lip_of_source(text: str, said: dict[str, None]) -> str:
    """`text` with the lip of the source said as its spout ("the jug lip", "the lip of the flask"
    it is poured from): a part of the source, not the bowl's rim. Only a lip named as what
    strikes the bowl is ("does the jug's lip hit the bowl"): never one said as a place
    (_AT_A_PLACE), nor one said to rest on the bowl (a touch in the scene: source_on_rim's)."""
    if not re.search(r"\b(?:lip|rim|edge)\b", text):
        return text
    for pattern in _lips():
        text = pattern.sub(lambda m: said.setdefault(f"{m.group('part')}: read as spout, a part of the source")
                           or f"{m.group(1)}spout", text)
    return text


@lru_cache(maxsize=None)
def source_names() -> tuple[str, ...]:
    """Every container of everyday.txt but the destination's words: those a source may be."""
    return tuple(w for w in names("bowl") if w not in _DESTINATIONS)


def _strikers() -> tuple[str, ...]:
    """What may strike the bowl as the source: the sources' names, and a bucket, a pail or a container
    (destinations' words that are the source when it is what strikes)."""
    return (*source_names(), "bucket", "pail", "container")


@lru_cache(maxsize=None)
def _lips() -> tuple[re.Pattern, ...]:
    """The lip of a source (every container of everyday.txt but the destination's words: what strikes
    the bowl is not it) striking the bowl: "the jug lip hit", "the lip of the flask touched"."""
    sources = alternation(source_names())
    strikes = r"(?: \w+){0,2}? (?:touch|hit|bump|knock|bang|clip|strike|struck|collid|scrap|graz|clink|nudg|tap|make contact)"
    # (a note's, with no article: "pitcher lip hit the bowl")
    return (re.compile(rf"{_AT_A_PLACE}\b((?:(?:the|its|a|my|your) |(?:^|(?<=[.,;:!?] )))(?:{sources}) )(?P<part>lip|rim|edge)\b"
                       rf"(?={strikes})"),
            re.compile(rf"{_AT_A_PLACE}\b((?:the|its|a) )(?P<part>lip|rim|edge)(?= of (?:the |a |an |my |this |that )?(?:{sources}){strikes})"))


def spout_striking(text: str, said: dict[str, None]) -> str:
    """`text` with a spout said first to strike the bowl, no source named with it ("spout hit the edge of the
    bowl and the bowl tipped right over"): the source's, as "the jug's lip" is."""
    if "spout" not in text:
        return text
    m = re.search(r"(?:^|(?<=[.,;:!?] ))(?:the |its |my )?spout (?=(?:hit|hits|bumped|bumps|clipped|clips|knocked|knocks|touched"
                  r"|touches|banged|bangs|scraped|scrapes)\b)", text)
    if m is None:
        return text
    said.setdefault(f"{m.group(0).strip()}: read as the source, whose spout it is")
    return f"{text[:m.start()]}the source {text[m.end():]}"


def source_on_rim(text: str, said: dict[str, None]) -> str:
    """`text` with the source said to touch (rest on, lean on, strike) the bowl's rim, as the scene of
    another question ("if the beaker touches the rim of the dish, will the dish tip?", "pitcher touching
    bowl edge when pouring, the bowl will fall?", "bowl wobble when jug hits edge?"), said as poured low
    near the rim: the scenes in which a source meets the rim; so is the bowl itself struck in a condition ("if
    the jug bumps it"), but not as the source moves ("on the way in"). Only a touch in a condition ("if", "when",
    "while") or one said as a note's first clause ("bottle touching bowl rim spill") is so read, with
    something else asked before or after it. No proposition says a touch; whether it touches is asked
    as itself ("does the cup touch the rim?", "bottle touching bowl rim?", "the cup touches the rim when
    I pour low?"), and a touch not wanted ("without the jar touching the rim") is a goal: neither is
    rewritten, nor is a condition that asks whether ("tell me if the jug touches the rim when I pour low").
    The source leaned on the bowl by someone in a condition ("when I leaned the pitcher on
    it") is read so too; one set there ("if I rest the jug on the rim", "when i put the jug on it") is refused."""
    def set_on_rim(m: re.Match) -> str:
        if not m.group("verb").startswith("lean"):      # "if I rest the jug on the rim": set there, a touch said
            raise UserError(f"could not place \"{m.group(0)[len(m.group('when')) + 1:]}\": {_SET_ON}")
        if m.group("when") not in ("if", "when", "while", "once") or m.group("source") == "it":
            return m.group(0)           # ("and i leaned it on the rim": told, not a condition)
        said.setdefault(f"{m.group(0)[len(m.group('when')) + 1:]}: read as low near the rim, where the source meets it"
                        " (no proposition says a touch)")
        return f"{m.group('when')} the {m.group('how') or ''}{m.group('source')} low near the rim"     # ("the heavy jug")
    text = _set_on_rim().sub(set_on_rim, text)
    if re.search(r"\b(?:sitting|resting|sat|rested|propped|balanc)", text) and (resting := _resting_on_rim().search(text)):
        # "pan edge sitting right on the bowl lip": set there too (searched only when cued)
        raise UserError(f"could not place \"{resting.group(0).strip(' ,;.')}\": {_SET_ON}")
    if not re.search(r"\b(?:touch|contact|rest|lean|sit|hit|bump|knock|clip|strike|bang|brush|tap)", text):
        return text             # (no touch said: no compiling)

    def low_near_rim(m: re.Match) -> str:
        before = re.split(r"[,.;:!?]| - ", text[:m.start()])[-1]
        if re.search(r"\b(?:not|never|no|without|want|wants|wanted|avoid|avoiding|stop|prevent)\b"
                     r"(?: (?!(?:if|when|whenever|while|once)\b)\w+){0,3} ?$", before):
            return m.group(0)           # "without the jar touching the rim": a goal
        condition = re.search(r"\b(?:if|when|whenever|while|once)\b(?: \w+){0,4} ?$", before)
        if condition and re.search(r"\b(?:tell me|know|wonder|wondering|see|check|ask|asking) $", before[:condition.start()]):
            condition = None            # "tell me if the jug touches the rim": whether it does
        if not condition and (before.strip() or not m.group("touch").startswith(("touching", "contacting", "resting", "leaning",
                                                                                  "sitting", "is ", "keep", "banging", "hitting"))):
            return m.group(0)           # "the cup touches the rim when I pour low?": the touch asked
        if re.fullmatch(r"[?.!]*", text[m.end():].strip()) and not (
                condition and re.sub(r"\b(?:what|happens|happen|would|will|so|and|then)\b", "", before[:condition.start()]).strip()):
            return m.group(0)           # "what if the jug hits the rim?": whether it does, asked
        if not m.group("rim") and (not condition or re.match(r",? *(?:on the way|on its way|as it|while (?:coming|moving|going"
                                                             r"|pulling|bringing|lifting))\b", text[m.end():])):
            return m.group(0)           # the bowl itself struck, not in a condition (the touch, asked or told), or as it moves
        touch = f"{m.group('part') or ''} {m.group('touch')}".strip()
        said.setdefault(f"{touch}: read as low near the rim, where the source meets it (no proposition says a touch)")
        return f"{m.group('source')} low near the rim"
    return _on_rim().sub(low_near_rim, text)


@lru_cache(maxsize=None)
def _set_on_rim() -> re.Pattern:
    """Someone setting the source on the bowl (its rim, its edge, it) in a condition (what is set on it is the
    source, a bucket too: "if I lean the bucket on its lip")."""
    sources, destinations = alternation(_strikers()), alternation(_DESTINATIONS - {"container"})
    return re.compile(
        rf"\b(?P<when>if|when|while|once|whenever|every time|each time|and) (?:i|we|you|he|she|they) (?P<verb>lean|leans|leaned|leant|leaning|rest|rests|rested|resting"
        rf"|prop|props|propped|propping|balance|balances|balanced|balancing|put|puts|putting|set|sets|setting|place|places"
        rf"|placed|placing|sit|sits|sat) (?:(?:the|my|a|her|his|our) (?P<how>[a-z]+ )?)?(?P<source>{sources}|it)"
        rf" (?:down )?(?:right |just |directly )?(?:on|against) (?:it|(?:its|the) (?:rim|edge|lip)(?: of (?:the |my |a )?(?:{destinations}))?"
        rf"|(?:the|my) (?:{destinations})(?:'s (?:rim|edge|lip))?)\b")


@lru_cache(maxsize=None)
def _resting_on_rim() -> re.Pattern:
    """The source (or its edge, lip or spout) noted resting on the bowl, with no one said: "pan edge sitting right on
    the bowl lip", "the jug resting on the rim"."""
    sources, destinations = alternation(_strikers()), alternation(_DESTINATIONS - {"container"})
    return re.compile(
        rf"(?:^|(?<=[,;.:] ))(?:the |my |a )?(?:{sources})(?: (?:edge|lip|spout|rim|neck))? (?:is )?(?:sitting|resting|sat|rested|propped"
        rf"|balanced|balancing) (?:right |just |directly )?(?:on|against) (?:the |my |its )?(?:(?:{destinations})(?:'s)? )?(?:rim|edge|lip)\b"
        rf"(?! of (?!(?:the |a |my )?(?:{destinations})\b))")      # (not "the edge of the table")


@lru_cache(maxsize=None)
def _on_rim() -> re.Pattern:
    """A source touching (or striking) the rim, then what else is said (or the question's end)."""
    sources, destinations = alternation(["container", "source", *source_names()]), alternation(_DESTINATIONS - {"container"})
    return re.compile(
        rf"(?P<source>\b(?:(?:the|my|a|its|your) )?(?:{sources}))(?P<part> (?:spout|lip|rim|edge|mouth|neck))? "
        rf"(?P<touch>(?:is touch|(?:(?:is|keeps|keep) )?(?:touches|touching|contacts|contacting|makes contact with|is in contact with"
        rf"|rests on|resting on|leans on|leaning on|sits on|sitting on|hits|bumps|knocks|clips|strikes|hitting|banging|bumping|knocking"
        rf"|brushes against|brushing against|bangs against|bangs into|bumps into|bangs|taps)) (?:(?:the |its |a )?"
        rf"(?:(?:{destinations}) )?(?P<rim>rim|edge|lip)"
        rf"(?: of (?:the |a |my |its )?(?:{destinations}))?|(?:the |a |my )(?:{destinations})|it))\b(?=[,.;:!?]? *(?:(?:when|while|during)\b|[,.;:!?] *)?"
        rf"(?!(?:ok|okay|fine|alright|all right|or not|or no|yes|no)\b)[a-z]| *[?.!]* *$|(?:,| -) (?:ok|okay|fine|alright)\b)")


def touch_told(text: str, said: dict[str, None]) -> str:
    """`text` with the source told to strike the bowl as the first clause of a question about
    something else ("cup bumps the bowl when i move it in fast does that knock the bowl over",
    "pitcher comes in too fast and hits the bowl, does the bowl flip"), asked as whether it does:
    no proposition says a touch, and the answer says whether the theory expects it. A touch in a
    condition ("if the jug bumps it") is source_on_rim's."""
    if not re.search(r"\b(?:hits|bumps|knocks|touches|clips|bangs|nudges|scrapes)\b", text):
        return text

    def asked(m: re.Match) -> str:
        said.setdefault(f"{m.group('source')} {m.group('move') or ''}{m.group('verb')}: asked whether it does (no proposition says a touch)")
        move = f"{m.group('source')} {m.group('move')[:-len(' and ')]}, does it" if m.group("move") else f"does {m.group('source')}"
        return f"{move} hit {m.group('struck')}{m.group('rest')}? "
    return _touch_told().sub(asked, text)


@lru_cache(maxsize=None)
def _touch_told() -> re.Pattern:
    """A source striking the bowl (its rim, it), told first, and what else is said before a question (a
    bucket striking it is the source: "the bucket bumps into the basin")."""
    sources, destinations = alternation(_strikers()), alternation(_DESTINATIONS - {"container"})
    return re.compile(
        rf"^(?P<source>(?:(?:the|my|a|his|her|our|your) )?(?:[a-z]+ )?(?:{sources})(?: (?:spout|lip|neck|mouth))?) "
        rf"(?P<move>(?:comes|moves|goes|swings|drops) (?:[a-z]+ ){{0,4}}?and )?"
        rf"(?P<verb>(?:hits|bumps|knocks|touches|clips|bangs|nudges|scrapes)(?: into| against)?) "
        rf"(?P<struck>(?:(?:the|my|a|its) )?(?:(?:{destinations})(?:'s)? ?)?(?:rim|edge|lip|side)?(?<! )(?: of (?:the |my )?(?:{destinations}))?)"
        rf"(?P<rest>(?: (?!(?:does|do|will|would|can|could|is|did)\b)[a-z]+){{0,8}}?)(?:,? (?:and |so )?|[.;:!?]+ )"
        rf"(?=(?:does|do|will|would|can|could|is|did)\b)")


def stream_striking(text: str, said: dict[str, None]) -> str:
    """`text` without the liquid's striking the bowl's rim when what it did next is told ("the stream
    hit the edge of the bowl and jumped out": it jumped out): the liquid striking the bowl is no outcome
    (the source's striking it is, and is read), what it does next is. The liquid said to strike the rim in a
    condition ("does the bowl wobble when the stream hits the edge of it") says where it is poured: near the rim
    (a liquid named there is kept: "when the honey lands on the edge of it")."""
    if not re.search(r"\b(?:hit|hits|hitting|struck|strikes|striking|lands)\b", text):
        return text
    if (when := _landing_on_rim().search(text)) is not None:       # "if the water hits the edge, does it flip"
        said.setdefault(f"{when.group(0).strip()}: read as poured near the rim, where the stream lands")
        liquid = "" if when.group("liquid") in ("stream", "jet", "flow", "pour", "liquid") else f" the {when.group('liquid')}"
        return f"{text[:when.start()]}{when.group('when')} i pour{liquid} near the rim{text[when.end():]}"
    m = _striking().search(text)
    if m is None:
        return text
    said.setdefault(f"{m.group('hit').strip(' ,')}: ignored: the liquid striking the bowl is no outcome (what it does next is read)")
    return text[:m.start("hit")] + text[m.end("hit"):]


@lru_cache(maxsize=None)
def _striking() -> re.Pattern:
    """The liquid (its stream, or a liquid by its name) striking the bowl's rim, then what it did."""
    liquids = alternation(["stream", "jet", "flow", "pour", "liquid", "drop", *names("liquid")])
    return re.compile(rf"\b(?:{liquids}) (?P<hit>(?:hit|hits|hitting|struck|strikes|striking) (?:the |its )?(?:bowl |destination )?"
                      rf"(?:rim|edge|side|lip)(?: of (?:the |a |my )?(?:bowl|destination))?(?: and then| then| and| ,)+ )(?=[a-z])")


@lru_cache(maxsize=None)
def _landing_on_rim() -> re.Pattern:
    """The liquid striking the bowl's rim, said as the condition of what is asked ("if the water hits the edge")."""
    liquids = alternation(["stream", "jet", "flow", "pour", "liquid", "water", *names("liquid")])
    return re.compile(rf"\b(?P<when>if|when|whenever|once|as soon as|the moment) (?:the |its |my |a )?(?P<liquid>{liquids})"
                      rf" (?:hits|hit|strikes|lands on) (?:right )?(?:on )?(?:the |its )?(?:bowl |destination )?"
                      rf"(?:rim|edge|lip|side(?: wall)?)(?: of (?:it|the bowl|the destination))?\b(?! and\b)")
