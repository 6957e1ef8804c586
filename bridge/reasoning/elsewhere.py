"""Liquid said to go somewhere other than the bowl: "half of it went on the
counter instead of the bowl", "the juice went on the floor not in the
bowl", "it went everywhere except the bowl". The outcome before it is heard
(a spill); what it went instead of is going in, asked as "instead of in the
bowl" already is (outcomes.py hears both)."""
from __future__ import annotations

import re
from functools import lru_cache

from pantarhei.bridge.reasoning.everyday import alternation
from pantarhei.bridge.reasoning.vessels import bowl_names


@lru_cache(maxsize=None)
def _pattern() -> re.Pattern:
    bowls = alternation([*bowl_names(), "destination"])
    # (an outcome heard, then at most two words of where it went that is no outcome's: "going on the desk")
    return re.compile(
        rf"\boutcome(?: (?!(?:and|but|or|so|if|when|while|instead|rather|not|except)\b)[a-z]+){{0,2}},? (?:and )?"
        rf"(?:instead of|rather than|not|but not|except(?: for)?|but(?= in\b| into\b))"
        rf"(?: (?:in|into|inside))? (?:the |my |a |your |our )?(?:[a-z]+ )?(?:{bowls})\b"
        r"(?= *(?:[,.;:!?\u2013\u2014-]|$)| (?:and|when|while|if|because|so|why|what|how|was|i|we|my)\b)")


def instead_of_the_bowl(text: str) -> tuple[str, tuple[str, ...]]:
    """(`text`, an outcome already heard in it as "outcome", with the bowl
    its liquid went instead of said as "instead of going into the bowl";
    the words so read)."""
    if "outcome" not in text:
        return text, ()
    said: list[str] = []

    def instead(m: re.Match) -> str:
        said.append(m.group(0).removeprefix("outcome").strip(" ,"))
        return "outcome instead of going into the bowl"
    return _pattern().sub(instead, text), tuple(said)
