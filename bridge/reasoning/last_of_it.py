"""The last of the liquid, said before a question is read (wording.normalising): what stays or
drips at the end is some of it ("does the last bit stay in the jug", "does the rest drip on the
bench": some); the last of it got out is every drop of it ("get the last bit out of a bottle of
ketchup": wanting it all out); the last of it poured is the pour told ("when i poured the last bit of stock into
it": pouring stock), no amount of liquid, since the vocabulary judges a whole pour."""
from __future__ import annotations

import re

#: The last of it, or the rest, said of what stays or goes: some of it.
_SOME = re.compile(r"\bthe (?:very )?(?:last (?:little )?(?:bits?|drops?|dribbles?|few drops|of it)\b|rest(?= of\b| (?:stay|stays"
                   r"|stayed|remain|remains|drip|drips|dripped|come|comes|came|go|goes|went|end|ends|is|was|slop|slops|slopped"
                   r"|spill|spills|spilled|spilt|splash|splashes|splashed|land|lands|landed|fall|falls|fell|run|runs|ran)\b))")
#: The last of it got out: "get the last bit out of a bottle of ketchup" (every drop of it, wanted out).
_GOT_OUT = re.compile(r"\b(?P<verb>get|gets|getting) (?P<last>the (?:very )?last (?:little )?(?:bits?|drops?))(?= out\b)")
#: The last of it poured: "poured the last bit of stock", "pouring the last of the soup".
_POURED = re.compile(r"\b(?P<verb>pour|pours|poured|pouring) (?P<last>the (?:very )?last (?:little )?(?:bits? |drops? |few drops )?of)"
                     r"(?= (?:the |my |a )?[a-z])")


def the_last_of(text: str, said: dict[str, None]) -> str:
    """`text` (normalised) with the last of the liquid read as the module's docstring says, each said back in `said`."""
    if " last " not in text and " rest" not in text:
        return text

    def poured(m: re.Match) -> str:
        said.setdefault(f"{m.group('last')}: read as nothing: the pour told, whose end is no amount of liquid")
        return m.group("verb")
    text = _POURED.sub(poured, text)
    text = _GOT_OUT.sub(lambda m: said.setdefault(f"{m.group('last')}: read as every drop") or f"{m.group('verb')} every drop", text)
    return _SOME.sub(lambda m: said.setdefault(f"{m.group(0)}: read as some") or "some", text)
