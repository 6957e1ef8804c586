"""Which of two scenes set against each other an outcome happens to, or
happens to more ("silicone bowl vs enamel bowl - which one slides more",
"does one of them slide and not the other",
said first: "which spills less: a slow tilt vs a fast one"):
asked of the scene said first, the other being said back as not read
(comparisons.py), as "does it slide"; "which" alone too, its verb inflected
and said with how much ("which splashes less") or ending the question ("which splashes"). "Compare" before them is the frame
("compare: 30 cm vs 5 cm"), and the first named again by its number
after them ("how much more spill at 30"), two named side by side with nothing between them
("heavy bowl light bowl which one moves") set against each other as with "vs", or by how its number ranks
against the other's ("20 degrees vs 160 degrees ... at the smaller
angle"), is the one read, said back; the other named so is refused."""
from __future__ import annotations

import re

from pantarhei.bridge.errors import UserError
from pantarhei.bridge.reasoning.numerals import NUMBER_WORDS

_SET_AGAINST = re.compile(r"\b(?:vs|versus|compared (?:to|with))\b")
_WHICH = re.compile(r"\bwhich (?:"
                    # "which one is less likely to slide": how likely is how much, said back with it
                    r"(?:(?:one|of them|of the two|bowl|cup)(?: of them)? )?(?:(?:is|are|will|would)(?: be)? |be )(?:the )?"
                    r"(?:(?:less|more|least|most) (?:likely|easy)|likelier|easier|(?:less|more) prone) to (?P<verb3>[a-z]+)\b"
                    r"|(?:one|of them|of the two|bowl|cup)(?: of them)? (?:will |would |is going to )?"
                    r"(?!(?:is|are|would be|will be) (?:better|best|safer|safest|worse|worst)\b)(?P<verb>[a-z]+?)(?P<ending>es|s)?\b(?P<how> (?:more|less|the most|the least|most|least|worse|better)\b)?"
                    # "which" alone: its verb inflected and said with how much ("which splashes less")
                    r"|(?:(?:actually|really|just|usually) )?(?!(?:is|was|does)\b)(?P<verb2>[a-z]+?)(?P<ending2>es|s)\b"
                    # where to, said before how much: "which sloshes out of the basin more"
                    r"(?P<where> (?:out|over|off)(?: (?:of|over|onto) (?:the|a|my|its) [a-z]+| the [a-z]+)?"
                    r"| the (?:bowl|dish|basin)(?: over)?"      # ("which tips the bowl more")
                    r"| in(?:to)? (?:the|a|my) (?:bowl|dish|basin)| in| everywhere)?"    # ("which stays in the bowl better")
                    r"(?:(?P<how2> (?:more|less|the most|the least|most|least|better|worse|cleaner)\b)"
                    r"|(?= *[?.!]* *$))"      # ("honey vs water. which splashes")
                    # an outcome's verb not inflected, as learners say it: "which spill more"
                    r"|(?P<verb4>spill|splash|slosh|slide|tip|drip|overflow|wobble|leak|miss) (?:more|less|the most|the least)\b)")

#: A second "which" asked after the first: "... and which spills more".
_AND_WHICH = re.compile(rf"(?<=\band ){_WHICH.pattern}")


#: Two scenes named side by side with nothing between them, then which one asked, as a note lists them
#: ("heavy bowl light bowl which one moves"): set against each other.
_SIDE_BY_SIDE = re.compile(r"^((?:a |the )?[a-z]+ (bowl|jug|cup|bottle|pitcher|glass|mug|dish|pour)) ((?:a |the )?[a-z]+ \2)"
                           r"(?=,? which\b)")
_ONE_OF = re.compile(r"\b(?:does|do|will|would|can) one of them (?P<verb>[a-z]+)\b(?: (?:and|but) not the other\b)?")


_COMPARE = re.compile(r"^(?:let's |lets |please )?compar(?:e|ing)\b *:? *")
#: Two scenes compared, joined by "and" before which is asked ("comparing a 30° tilt and a 90° tilt ..., which one").
_TWO_COMPARED = re.compile(r"(?:(?<=^compare )|(?<=^comparing )|(?<=^compare : ))(?P<a>[^,;:?]+?) and (?P<b>[^,;:?]+?)(?= ?,? which\b)")
_NUMBER = r"-?\d+(?:\.\d+)?"


def which_one(text: str) -> tuple[str, tuple[str, ...]]:
    """`text` (normalised) with "which one <outcome> more", after two scenes
    set against each other, read as "does it <outcome>", and what is said back."""
    said: tuple[str, ...] = ()
    if pair := _SIDE_BY_SIDE.match(text):        # "heavy bowl light bowl which one moves"
        said = (f"{pair.group(0)}: read as {pair.group(1)} vs {pair.group(3)}",)
        text = f"{pair.group(1)} vs {pair.group(3)}{text[pair.end():]}"
    set_against = _SET_AGAINST.search(text)
    if set_against is None and _COMPARE.search(text) and (two := _TWO_COMPARED.search(text)):
        # "comparing a 30 tilt and a 90 tilt ..., which one ...": the two set against each other, as with "vs"
        said += (f"{two.group(0).strip()}: read as {two.group('a')} vs {two.group('b')}",)
        text = f"{text[:two.start()]}{two.group('a')} vs {two.group('b')}{text[two.end():]}"
        set_against = _SET_AGAINST.search(text)
    if set_against and (frame := _COMPARE.search(text)):
        said += (f"{frame.group(0).strip(' :')}: read as nothing: two scenes set against each other, "
                 "the one said first answered",)
        text = text[frame.end():]
        set_against = _SET_AGAINST.search(text)
    if set_against:
        text, said = _first_again(text, set_against, said)
        text, said = _ranked(text, set_against, said)
    m = (_WHICH.search(text, set_against.end()) or _asked_first(text[:set_against.start()])) if set_against else None
    one = _ONE_OF.search(text, set_against.end()) if set_against and m is None else None
    if one:             # "does one of them slide and not the other": does it slide, of the first
        return (text[:one.start()] + f"does it {one.group('verb')}" + text[one.end():],
                (*said, f"{one.group(0)}: read as does it {one.group('verb')}, of the one said first"))
    if m is None:
        return text, said
    while m is not None:        # and a second asked after it: "which splashes more and which spills more"
        said_verb, ending = next((m.group(f"verb{k}"), m.groupdict().get(f"ending{k}")) for k in ("", "2", "3", "4")
                                 if m.group(f"verb{k}"))
        verb = said_verb + ("e" if ending == "es" and not re.search(r"(?:sh|ch|ss|x|o)$", said_verb) else "")
        verb += " anything" if verb == "leave" and re.match(r" in\b", text[m.end():]) else ""    # "leaves more in the jug"
        verb = "get" if verb == "put" else verb             # "which one puts more liquid in the bowl": gets it in
        verb = "make" if verb in ("give", "produce", "create", "ha") else verb    # "which produces, has more splash": makes it
        verb += m.groupdict().get("where") or ""
        text, said = (text[:m.start()] + f"does it {verb}" + text[m.end():],
                      (*said, f"{m.group(0)}: read as does it {verb}, of the one said first"))
        m = _AND_WHICH.search(text, m.start() + len(f"does it {verb}"))
    return text, said


#: One of two scenes named by how its number ranks: "at the smaller angle", "for the higher one".
_RANKED = re.compile(r"\b(?:(?:at|for|with|in) )?the (smaller|lower|shallower|lesser|larger|bigger|higher|steeper|greater)"
                     r" (?:angle|tilt|one|height|value|number)\b")
_SMALLER = {"smaller", "lower", "shallower", "lesser"}


def _ranked(text: str, set_against: re.Match, said: tuple[str, ...]) -> tuple[str, tuple[str, ...]]:
    """`text` with the scene said first named by how its number ranks against the other's ("20 degrees
    vs 160 degrees ... at the smaller angle"), read as nothing and said back; UserError where it names
    the other, which is not read."""
    m = _RANKED.search(text, set_against.end())
    clause = re.search(r"[,;:?!.] ", text[set_against.end():])
    if m is None or clause is None:
        return text, said
    first, other = _value(text[:set_against.start()]), _value(text[set_against.end():set_against.end() + clause.end()])
    if first is None or other is None or first == other:
        return text, said
    if (first < other) != (m.group(1) in _SMALLER):
        raise UserError(f"\"{m.group(0)}\" asks of the scene set against the first, which is not read: ask of it alone")
    return (text[:m.start()] + text[m.end():],
            (*said, f"{m.group(0)}: read as nothing: the scene said first, named again"))


def _value(text: str) -> float | None:
    """The one number said in `text`, in figures or in words ("one hundred and sixty"), or None."""
    figures = re.findall(_NUMBER, text)
    if figures:
        return float(figures[0]) if len(figures) == 1 else None
    total, seen = 0.0, False
    for w in re.findall(r"[a-z]+", text):
        if w in NUMBER_WORDS:
            total, seen = total + NUMBER_WORDS[w], True
        elif w == "hundred" and seen:
            total *= 100
        elif seen and w != "and":
            break
    return total if seen else None


def _asked_first(text: str) -> re.Match | None:
    """"which" said first, before the scenes, ending its clause ("which spills less: a slow tilt vs a fast one")."""
    m = _WHICH.match(text)
    return m if m and re.match(r" *[:,]", text[m.end():]) else None


def _again(number: str) -> re.Pattern:
    """A scene named again by its number, with no unit: "at 30", "for the 30 cm one"."""
    return re.compile(rf"\b(?:at|for|with) (?:the )?{re.escape(number)}(?: \w+ ones?)?\b(?![\w.])"
                      r"(?! ?(?:cm|mm|m|deg|degrees?|g|kg|s|inch\w*|%))")


def _first_again(text: str, set_against: re.Match, said: tuple[str, ...]) -> tuple[str, tuple[str, ...]]:
    """`text` with the scene said first named again by its number, after the
    other ("at 30 cm vs 5 cm, how much more spill at 30"), read as nothing and said back."""
    first = re.findall(_NUMBER, text[:set_against.start()])
    clause = re.search(r"[,;:?!.] ", text[set_against.end():])
    if len(first) != 1 or clause is None:
        return text, said
    after = set_against.end() + clause.end()
    second = re.findall(_NUMBER, text[set_against.end():after])
    m = _again(first[0]).search(text, after)
    if m is None and len(second) == 1 and (other := _again(second[0]).search(text, after)):
        raise UserError(f"\"{other.group(0)}\" asks of the scene set against the first, which is not read: "
                        "ask of it alone")
    if m is None:
        return text, said
    return (text[:m.start()] + text[m.end():],
            (*said, f"{m.group(0)}: read as nothing: the scene said first, named again"))
