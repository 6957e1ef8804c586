"""Who asks, said before the question ("I'm a potter and ...", "dinner
lady here, ...", "as a home brewer, ...", "Line cook here."): read as
nothing and said back, as who pours is. Being someone says nothing of the
pour, and the words of a trade are no words of the vocabulary even where
they look like one ("I'm a line cook" is no pour in line, "a high school
teacher" no pour from high).

Only a self-introduction at the start of the question is read so, ended
by a stop, a comma, a colon, a dash or "and": an article and one to four
words ("I am a/an ...", "as a/an ..."), or one to three words and "here"
("pharmacy tech here"), the last of them a person by WordNet's first two
senses of it (wordnet.py: "potter", "cook", "vendor"). "I'm a bit
worried ..." names no one, and is read as any other words; so are words
holding a number, a negation or a verb of pouring or of an outcome.

So is whom the question is said to, named first ("Honey, if I'm pouring
coffee ..."): a term of address before a comma and a word that starts a
question (a parent, as a child says it, with no comma: "mummy if I tip my
cup ..."). A liquid's name so said ("honey", "sugar") is a term of
address only where another liquid is named after it ("Honey, will it
drip?" asks of honey)."""
from __future__ import annotations

import re
from functools import lru_cache

from pantarhei.bridge.reasoning.earlier_pour import says_a_liquid
from pantarhei.bridge.reasoning.outcome_verbs import outcome_verb
from pantarhei.bridge.reasoning.wordnet import is_a

#: WordNet's word for whom a self-introduction names.
_PERSON = frozenset(("person",))
#: What is said back of a self-introduction.
_SAID = "read as nothing: who asks says nothing of the pour"
#: Words no self-introduction holds: a negation, a verb of pouring, a word of the question itself.
_NOT_WHO = re.compile(r"\b(?:not|no|never|pour\w*|tilt\w*|tip\w*|decant\w*|fill\w*|empty\w*|spill\w*|if|when|will|would"
                      r"|does|do|is|are|can|what|how|why|should|it|that|this|the|my|and|or|with|from|into)\b")


#: A term of address said first, then the question: "honey, if i am pouring ...", "love, will it ...".
_ADDRESS = re.compile(r"^(?:(?P<who>honey|hun|hon|sweetie|sweetheart|darling|dear|love|babe|sugar|buddy|pal|mate|guys)(?:,| -)"
                      # (a child's parent needs no comma: "mummy if i tip my cup ...")
                      r"|(?P<kin>mummy|mommy|mum|mom|mama|daddy|dad|papa|grandma|granny|nana|grandpa)(?:,| -)?)"
                      r" +(?=(?:if|i|can|could|will|would|what|how|should|when|is|are|do|does|did|why|which|where)\b)")
#: The terms of address that also name a liquid.
_LIQUIDS = frozenset(("honey", "sugar"))


@lru_cache(maxsize=None)
def _introduction() -> re.Pattern:
    lead = r"(?:(?:hi|hello|hey|ok|okay|so|well)[,!.]? +)?"
    end = r"(?P<end> *(?:[,.:;!]|\band\b)|$)"
    who = r"[a-z][a-z-]*(?: [a-z][a-z-]*){0,3}"
    return re.compile(rf"^(?P<intro>{lead}(?:(?:i am|as) (?:a|an) (?P<who>{who})(?: (?:here|by trade|myself))?"
                      rf"|(?P<here>[a-z][a-z-]*(?: [a-z][a-z-]*){{0,2}}) here)){end}")


def asker_said(text: str) -> tuple[str, tuple[str, ...]]:
    """`text` (normalised) without a self-introduction at its start (the
    module's docstring), and what is said back of it."""
    if (to := _ADDRESS.match(text)) and (to.group("who") not in _LIQUIDS or says_a_liquid(text[to.end():])):
        return text[to.end():], (f"{to.group('who') or to.group('kin')}: read as nothing: said to whom the question is asked",)
    if " here" not in text and not re.match(r"(?:\S+ +)?(?:i am|as) an? ", text):     # cued: no compiling otherwise
        return text, ()
    m = _introduction().match(text)
    if not m:
        return text, ()
    who = m.group("who") or m.group("here")
    words = who.split()
    if (re.search(r"\d", who) or _NOT_WHO.search(who) or any(outcome_verb(w) for w in words)
            or not m.group("end").strip() and m.end() < len(text) or not is_a(words[-1], _PERSON, first=2)):
        return text, ()
    rest = text[m.end():].strip()
    if not rest:
        return text, ()
    return rest, (f"{m.group('intro')}: {_SAID}",)
