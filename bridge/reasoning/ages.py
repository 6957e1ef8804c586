"""How old someone is, said of who pours ("my 6 year old", "a 10-year-old", "my son is 6
years old", "aged 7"): read as nothing and said back, as who pours is; the vocabulary says
nothing of who pours, and the number is no quantity of the pour. An age said of a thing
("a 6 year old jug") is read alike: how old a thing is says nothing of the pour either."""
from __future__ import annotations

import re

from pantarhei.bridge.reasoning.numerals import NUMBER_WORDS

_SAID = "ignored: how old someone is says nothing of the pour"


def _age() -> re.Pattern:
    number = rf"(?:\d+|{'|'.join(sorted(NUMBER_WORDS, key=len, reverse=True))})"
    return re.compile(rf"\b(?:{number}[ -](?:years?|yrs?|months?)[ -]olds?|aged {number}(?: (?:years?|months?))?"
                      rf"|{number}(?: and a half)? (?:years?|yrs?) of age)\b")


def ages_said(text: str) -> tuple[str, tuple[str, ...]]:
    """`text` (normalised) without the ages it says, and what is said back of each."""
    found = tuple(dict.fromkeys(m.group(0) for m in _age().finditer(text)))
    if not found:
        return text, ()
    return _age().sub(" ", text), tuple(f"{a}: {_SAID}" for a in found)
