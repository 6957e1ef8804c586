"""The scene a question sets its own against ("60 degrees vs 90 degrees",
"compared to a light bowl") is not read (comparisons.py), so what it says
must be something the vocabulary can say: a volume of liquid ("vs 90
degrees with 200 ml of oil"), a word the reader cannot place ("vs aim at
the side wall") or a number no proposition holds, of a parameter the first
scene says ("5 cm above vs 50 cm above"), refuses the question, naming it,
as it would were it said alone; so does a scene that differs from the first only in what the
vocabulary does not say ("glass bowl vs plastic bowl", "cup vs jug": which
container, what it is made of; "from the left or right": which side), the answer being the same for both; otherwise
the answer would stand for a question that was not asked."""
from __future__ import annotations

import re
from functools import lru_cache
from typing import Collection

from pantarhei.bridge.errors import UserError
from pantarhei.bridge.reasoning.comparisons import COMPARED, VERSUS
from pantarhei.bridge.reasoning.everyday import sections
from pantarhei.bridge.reasoning.nouns import BOWL
from pantarhei.bridge.reasoning.numerals import NUMBER_WORDS
from pantarhei.bridge.reasoning.outcomes import hear
from pantarhei.bridge.reasoning.quantities import Unheld, read_numbers
from pantarhei.bridge.reasoning.spelling import corrected
from pantarhei.bridge.reasoning.suggestions import names_part
from pantarhei.bridge.reasoning.wording import stem, tokens
from pantarhei.theory.lexicon import load_vocabulary

_OTHER = re.compile(rf"\b(?:{VERSUS}|{COMPARED})\b\.?"
                    r" (?P<other>[^,;:.!?]+?)(?= *(?:[,;:.!?]| - )|$)")
#: A unit a number is said in, which the reader reads with the number before it.
_UNIT = re.compile(r"mm|cm|m|ft|inch\w*|feet|foot|deg\w*|s|secs?|second\w*|ms|g|kg|gram\w*|percent")
#: A number, as the reader tokenises it (its value is read with its unit).
_NUMBER = re.compile(r"-?\d")
_VOLUME = re.compile(r"(?<![\w.])\d+(?:\.\d+)? ?(?:ml|millilit\w*|cl|dl|l|lit(?:re|er)s?|oz|ounces?)\b")
#: One side set against the other ("from the left or right", read as "the left vs the right").
_SIDES = re.compile(rf"\b(?:left|right)(?:[- ]hand)?(?: side)? (?:{VERSUS}) (?:the |your |my )?(?:left|right)\b")


@lru_cache(maxsize=None)
def _everyday() -> tuple[re.Pattern, dict[str, str | None]]:
    """The everyday word list's phrases as one pattern, the longest first, and for each the reason it is
    refused, or None where it is read ("a small angle" is, "small" alone is not)."""
    why = {p: s.said_back if s.words == "unclear" else None for s in reversed(sections()) for p in s.phrases}
    return re.compile(rf"\b(?:{'|'.join(re.escape(p) for p in sorted(why, key=len, reverse=True))})\b"), why


def refuse_unsayable(text: str, known: Collection[str], placeable: Collection[str]) -> None:
    """UserError where the scene `text` (normalised) sets its own against
    holds a volume or a word the reader cannot place (none of `known`,
    the reader's lexicon's words; `placeable`, its value words, tell a
    word of a quality from a word of a bowl's name, name_words.py)."""
    m = _OTHER.search(text)
    if m is None:
        return
    other = m.group("other")
    if _SIDES.search(text):
        raise UserError("left or right: the vocabulary's offset names no side, and its two sides are alike: "
                        "ask of one (\"from the side\", \"offset sideways\")")
    if volume := _VOLUME.search(other):
        raise UserError(f"\"{volume.group(0)}\" of liquid, in the scene set against the first (\"{m.group(0)}\"): "
                        "the vocabulary counts the liquid in particles; say \"a little liquid\", \"some liquid\", "
                        "\"much liquid\" or \"a full cup\"")
    phrases, why = _everyday()      # "vs tipping it all at once": a phrase the vocabulary refuses, as alone
    if unclear := next((p.group(0) for p in phrases.finditer(other) if why[p.group(0)]), None):
        raise UserError(f"could not place \"{unclear}\" in the scene set against the first (\"{m.group(0)}\"): "
                        f"{why[unclear]}")
    heard = _OTHER.search(hear(corrected(text)[0]).scene)     # what it asks is the first scene's too
    said = tokens(heard.group("other")) if heard else []
    known = set(known) | set(NUMBER_WORDS) | {"hundred", "thousand", "same", "outcome"}
    unknown = [t.raw for i, t in enumerate(said) if t.word not in known and t.raw not in known and not _NUMBER.match(t.word)
               and not _UNIT.fullmatch(t.raw) and not names_part(said, i, placeable)]
    if unknown:
        raise UserError("could not place " + ", ".join(f'"{w}"' for w in dict.fromkeys(unknown))
                        + f" in the scene set against the first (\"{m.group(0)}\"): ask of one scene the "
                        "vocabulary can say, with the words of `pantarhei vocab`")
    first = tokens(heard.string[:heard.start()]) if heard else []
    try:        # a number no proposition holds, of a parameter the first scene says ("5 cm above vs 50 cm above")
        read_numbers(said, frozenset(placeable))
    except Unheld as e:
        if e.param in _params(first, placeable):
            raise UserError(f"in the scene set against the first (\"{m.group(0)}\"): {e}") from None
    except UserError:   # which parameter a number is of may need the first scene's words: left to the answer
        pass
    _refuse_names_alone(first, said, m.group(0), placeable)


def _params(said: list, placeable: Collection[str]) -> set[str]:
    """The parameters of the numbers in `said` (a scene's tokens), read alone ("5 cm above": pour_z)."""
    try:
        read = read_numbers(said, frozenset(placeable))
    except UserError:
        return set()
    props = load_vocabulary().propositions
    return {getattr(props[t.word].model, "param", None) for t in read if t.word in props}


#: Words that say no scene of their own: articles, what joins a pour to its bodies, and what is read as nothing.
_JOINING = frozenset(("a", "an", "the", "my", "your", "our", "this", "that", "one", "pour", "from", "into", "in", "of", "with",
                      "and", "same", stem("hedge")))
#: What the vocabulary does not say of a body, by the word a name is read as.
_UNSAID = {"material": "what a bowl is made of", BOWL: "which container is used"}


def _refuse_names_alone(first: list, other: list, said: str, placeable: Collection[str]) -> None:
    """UserError where the scene set against the first differs from it only in a name the vocabulary
    does not say ("glass bowl vs plastic bowl", "from a pitcher from 10 cm vs from a mug from 10 cm"),
    neither saying a value the other does not ("heavy ceramic bowl vs the paper ones" is the heavy bowl's):
    the answer would be the same for both, and would stand for a difference it cannot tell."""
    named, words = {(t.word, t.raw) for t in first}, {t.word for t in first}
    new = [t for t in other if t.word not in _JOINING and (t.word, t.raw) not in named]
    values = {t.word for t in other if t.word in placeable or _NUMBER.match(t.word)}
    alone = [t for t in first if (t.word in placeable or _NUMBER.match(t.word)) and t.word not in values]
    if new and not alone and all(t.word in _UNSAID and t.word in words for t in new):
        raise UserError(f"the scene set against the first (\"{said}\") differs from it only in "
                        f"{' and '.join(dict.fromkeys(_UNSAID[t.word] for t in new))}, which the vocabulary does not say: the answer would be the same for both; "
                        "set against each other what it says (\"a light bowl vs a heavy bowl\") or ask of one scene")
