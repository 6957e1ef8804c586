"""An aside that says again what a number's sign says: "-2 cm (i.e. below
the rim)", "-30 degrees (tipping backwards, away from the bowl)", "set to
-1 cm (below the rim)". It is read as the number alone, said back, never
as a second value: "-1 cm below the rim" says below twice, and is refused,
but the aside only explains the minus. Any other aside is left as it is,
for the reader to read or refuse ("-2 cm (above the rim)" is below the rim,
as "-2 cm above the rim" is)."""
from __future__ import annotations

import re
from functools import lru_cache

#: What an aside may start with that only says it explains: "i.e.", "that is", "so".
_EXPLAINING = r"(?:(?:i\.? ?e\.?|ie|that is|meaning|so|=),? )?"
#: Who the aside may be said of: the source, or "it".
_HELD = r"(?:(?:the )?(?:cup|source|jug|mug|glass|bottle|beaker|it) )?(?:is |held |sits |sitting )?"
#: What a negative length says of where the source is: below the rim.
_BELOW = (rf"{_HELD}(?:just |slightly )?(?:below|under|beneath|underneath|lower than)(?: (?:it|the (?:bowl |destination )?"
          r"(?:rim|lip|edge|top)(?: (?:height|level))?|the (?:bowl|destination)|rim (?:height|level)))?")
#: What a negative tilt says: tilted back, away from the destination.
_BACK = (rf"{_HELD}(?:(?:tilted|tipped|tipping|tilting|leaning|leaned|leans|angled) )?(?:back|backwards?)"
         r"(?:,? (?:and )?away(?: from (?:the )?(?:bowl|destination))?)?|away from (?:the )?(?:bowl|destination)")
_LENGTH = r"mm|cm|m|in|inch|inches|ft|foot|feet|metres?|meters?|centimet(?:re|er)s?|millimet(?:re|er)s?"
_ANGLE = r"degrees?|degs?"


@lru_cache(maxsize=None)
def _said_again() -> re.Pattern:
    """A negative number with its unit, the words of its clause after it, and an aside in brackets."""
    return re.compile(rf"(?P<number>-\d+(?:\.\d+)?) ?(?P<unit>{_LENGTH}|{_ANGLE})\b(?P<between>[^()\[\],;:?!]{{0,60}}?)"
                      r" ?[(\[](?P<aside>[^()\[\]]*)[)\]]")


def restated(text: str) -> tuple[str, tuple[str, ...]]:
    """Normalised `text` without the asides that say again what a number's
    sign says, and what is said back of each."""
    said: list[str] = []

    def drop(m: re.Match) -> str:
        aside = m.group("aside").strip()
        says = _BELOW if re.fullmatch(_LENGTH, m.group("unit")) else _BACK
        if not re.fullmatch(rf"{_EXPLAINING}(?:{says})", aside):
            return m.group(0)
        shown = re.sub(r"\.(?=\S)", ". ", aside)      # "i. e.": each letter a word, as written
        said.append(f"{shown}: read as the sign of {m.group('number')} {m.group('unit')} says it")
        return f"{m.group('number')} {m.group('unit')}{m.group('between')}"

    if "-" not in text or not ("(" in text or "[" in text):      # cued: no compiling otherwise
        return text, ()
    return _said_again().sub(drop, text), tuple(said)
