"""A container said to be little ("a little jug", "his little cup") is
said by its size, which the vocabulary's bowls, all of one size, cannot
say: refused as "a small jug" is, never read as a little liquid (which
"a little milk" is). So is a bowl said to be wobbly ("my bowl is light and
wobbly"): its shape, which the vocabulary's bowls, all of one shape, cannot
say either (the bowl going wobbly as it is poured into is an outcome, and read)."""
from __future__ import annotations

import re
from functools import lru_cache

from pantarhei.bridge.errors import UserError
from pantarhei.bridge.reasoning.everyday import alternation, names, refused


@lru_cache(maxsize=None)
def _little() -> re.Pattern:
    # ("the little medicine cup", "the little plastic bowl": a little cup, a liquid's name or a material
    # between, never a little liquid)
    return re.compile(rf"\b(?:little|lil) (?:bitty )?(?:(?:{alternation(names('liquid', 'material'))}) )?"
                      rf"(?:{alternation(names('bowl'))})\b")


def refuse_little(text: str) -> None:
    """UserError where `text` (normalised) says a container is little (everyday.txt's words on its size)."""
    if re.search(r"\b(?:little|lil)\b", text) and (m := _little().search(text)):    # (compiled only when cued)
        raise UserError(f"could not place \"{m.group(0)}\": {refused('all of one size').said_back}")


#: A bowl said to be wobbly, as what it is: "my bowl is really light and wobbly", "the bowl is wobbly".
_WOBBLY = re.compile(r"\b(?:bowl|dish|basin|tub) is (?:(?:really|very|a bit|kind of|so|quite) )?(?:[a-z]+ and )?wobbly\b")


def refuse_wobbly(text: str) -> None:
    """UserError where `text` (normalised) says the bowl is wobbly (everyday.txt's words on its shape)."""
    if "wobbly" in text and (m := _WOBBLY.search(text)):
        raise UserError(f"could not place \"{m.group(0)}\": {refused('all of one shape').said_back}")

