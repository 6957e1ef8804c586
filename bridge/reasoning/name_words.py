"""Whether a word the reader does not know, said right before the noun of
a bowl or of the liquid, is part of that thing's name ("a martini glass",
"tomato soup", "the fryer tin", "a mixer bowl") or says a quality of it
("a wobbly bowl", "a sturdier jug"): a name's word is shown as ignored,
a quality refused as any word the reader does not know.

A word ending as a quality does (_QUALITY: "wobbly", "rounded", "fancy")
says one; a word ending in "-er" says one only where it is the
comparative of a quality: of a word the reader reads as a value or
refuses as one it cannot say ("slicker": slick, slippery; "warmer": warm,
a temperature), or of one that ends as a quality does itself
("sturdier": sturdy), by
the spelling of comparatives ("heavier": heavy, "bigger": big, "nicer":
nice). Any other "-er" word is a noun ("fryer": a comparative of "fry"
would be "frier"; "butter", "mixer"), or the comparative of a word that
says nothing of the pour ("cheaper"), and is part of the name. An "-ing"
word says what the thing is for ("a mixing bowl", "a dosing dish", "a
measuring cup"), part of its name, unless it is a verb of an outcome
(outcome_verbs.py: "a leaking jug", "a wobbling bowl"), which says how the
thing behaves and is refused."""
from __future__ import annotations

import re
from typing import Collection

from pantarhei.bridge.reasoning.nouns import BOWL
from pantarhei.bridge.reasoning.outcome_verbs import outcome_verb
from pantarhei.bridge.reasoning.spelling import english
from pantarhei.bridge.reasoning.wording import Token, tokens as words_of

#: Endings of words that say a quality rather than a name ("a wobbly bowl", "a rounded
#: jug", "a fancy glass"): such a word before a bowl is refused, as any the reader does not know.
_QUALITY = re.compile(r"(?:y|ly|est|ed|ing|ful|less|ous|ive|al|ic|able|ible|ish)$")
#: Words that say how much or which, not a name: "more liquid", "another bowl".
_HOW_MUCH = frozenset(("more", "less", "extra", "enough", "additional", "another", "same", "other", "whole",
                       "half", "double", "twice", "triple", "several", "few", "many", "plenty", "both", "each",
                       "every", "second", "third", "next", "last", "first", "new", "old", "own", "spare"))


def names_part(tokens: list[Token], i: int, placeable: Collection[str]) -> bool:
    """Whether the word at `i`, one the reader does not know, is part of the
    name of the bowl or liquid after it ("a martini glass", "tomato soup"):
    an English word (not a typo, which spelling.py reads) that says no
    quality (see the module's docstring; `placeable`: the reader's value
    words, whose comparatives say one), said right before the noun, which
    says what is read of the body."""
    t = tokens[i]
    return (i + 1 < len(tokens) and tokens[i + 1].word in (BOWL, "liquid") and tokens[i + 1].clause == t.clause
            and re.fullmatch(r"[a-z]{3,}", t.raw) is not None and not says_quality(t.raw, placeable)
            and t.raw not in _HOW_MUCH and english(t.raw))


def says_quality(word: str, placeable: Collection[str]) -> bool:
    """Whether `word` ends as a word of a quality does, or is the
    comparative of a quality (see the module's docstring)."""
    if word.endswith("ing") and len(word) > 5:        # what it is for, unless how it behaves
        return outcome_verb(word)
    if _QUALITY.search(word):
        return True
    return word.endswith("er") and any(
        _QUALITY.search(base) or any(t.word in placeable for t in words_of(base))
        for base in _bases(word) if english(base))


def _bases(word: str) -> list[str]:
    """The words `word` (ending in "-er") is the comparative of, by their
    spelling: "heavier" of heavy, "bigger" of big, "nicer" of nice, "cheaper"
    of cheap; a word ending in a consonant and "y" takes "-ier", so "fryer" is
    the comparative of none."""
    stem = word[:-2]
    out = []
    if stem.endswith("i"):
        out.append(stem[:-1] + "y")
    elif not re.search(r"[^aeiou]y$", stem):
        out.append(stem)
    if len(stem) > 2 and stem[-1] == stem[-2] and stem[-1] not in "aeiouy":
        out.append(stem[:-1])
    out.append(word[:-1])                       # nicer: nice, wider: wide
    return [b for b in out if len(b) > 1]
