"""More of the liquid got into the bowl, or onto the table, asked ("which
way gets more water into the bowl", "would tilting to 45 degrees get
more of the honey into the bowl", "does a full jug get more water on the
table"): whether it goes in, or spills, how much being the answer's to
say ("which gets more" is which_one.py's); the liquid named is kept as the pour's ("pouring honey, ... get it
into the bowl"), never read as more liquid in the source."""
from __future__ import annotations

import re

_MORE = re.compile(r"(?<!\bwhich )(?<!\bwhich one )\b(get|gets|got|getting|put|puts) (?:more|less)(?: of (?:it|the ([a-z]+))| (?!(?:in|into|on|onto)\b)([a-z]+))?"
                   r"(?= (?:(?P<inside>in|into) (?:the |my )?(?:bowl|dish|basin)|(?:on|onto) (?:the |my )?"
                   r"(?:table|counter|countertop|worktop|floor|bench|tablecloth|stove))\b)")


def more_in(text: str) -> tuple[str, tuple[str, ...]]:
    """`text` (normalised) with more of the liquid got into the bowl read as getting it in, or onto
    the table as getting some there (the module's docstring), and what is said back."""
    m = _MORE.search(text)
    if m is None:
        return text, ()
    liquid = m.group(2) or m.group(3)
    pour = f"pouring {liquid}, " if liquid else ""
    got = f"{m.group(1)} {'it' if m.group('inside') else 'some'}"
    return (f"{pour}{text[:m.start()]}{got}{text[m.end():]}",
            (f"{m.group(0)}: read as {pour}{got}: whether it {'goes in' if m.group('inside') else 'spills'}, "
             "how much is the answer's",))
