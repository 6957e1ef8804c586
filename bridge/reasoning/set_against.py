"""The scene a question sets its own against ("60 degrees vs 90 degrees",
"compared to a light bowl") is not read (comparisons.py), so what it says
must be something the vocabulary can say: a volume of liquid ("vs 90
degrees with 200 ml of oil") or a word the reader cannot place ("vs aim at
the side wall") refuses the question, naming it, as it would were it said
alone; otherwise the answer would stand for a question that was not asked."""
from __future__ import annotations

import re
from functools import lru_cache
from typing import Collection

from pantarhei.bridge.errors import UserError
from pantarhei.bridge.reasoning.comparisons import COMPARED, VERSUS
from pantarhei.bridge.reasoning.everyday import sections
from pantarhei.bridge.reasoning.numerals import NUMBER_WORDS
from pantarhei.bridge.reasoning.outcomes import hear
from pantarhei.bridge.reasoning.spelling import corrected
from pantarhei.bridge.reasoning.suggestions import names_part
from pantarhei.bridge.reasoning.wording import tokens

_OTHER = re.compile(rf"\b(?:{VERSUS}|{COMPARED})\b\.?"
                    r" (?P<other>[^,;:.!?]+?)(?= *(?:[,;:.!?]| - )|$)")
#: A unit a number is said in, which the reader reads with the number before it.
_UNIT = re.compile(r"mm|cm|m|ft|inch\w*|feet|foot|deg\w*|s|secs?|second\w*|ms|g|kg|gram\w*|percent")
_VOLUME = re.compile(r"(?<![\w.])\d+(?:\.\d+)? ?(?:ml|millilit\w*|cl|dl|l|lit(?:re|er)s?|oz|ounces?)\b")


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
    unknown = [t.raw for i, t in enumerate(said) if t.word not in known and t.raw not in known and not re.match(r"-?\d", t.word)
               and not _UNIT.fullmatch(t.raw) and not names_part(said, i, placeable)]
    if unknown:
        raise UserError("could not place " + ", ".join(f'"{w}"' for w in dict.fromkeys(unknown))
                        + f" in the scene set against the first (\"{m.group(0)}\"): ask of one scene the "
                        "vocabulary can say, with the words of `pantarhei vocab`")
