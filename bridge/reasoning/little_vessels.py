"""A container said to be little ("a little jug", "his little cup") is
said by its size, which the vocabulary's bowls, all of one size, cannot
say: refused as "a small jug" is, never read as a little liquid (which
"a little milk" is)."""
from __future__ import annotations

import re
from functools import lru_cache

from pantarhei.bridge.errors import UserError
from pantarhei.bridge.reasoning.everyday import alternation, names


@lru_cache(maxsize=None)
def _little() -> re.Pattern:
    # ("the little medicine cup", "the little plastic bowl": a little cup, a liquid's name or a material
    # between, never a little liquid)
    return re.compile(rf"\b(?:little|lil) (?:bitty )?(?:(?:{alternation(names('liquid', 'material'))}) )?"
                      rf"(?:{alternation(names('bowl'))})\b")


def refuse_little(text: str) -> None:
    """UserError where `text` (normalised) says a container is little."""
    if re.search(r"\b(?:little|lil)\b", text) and (m := _little().search(text)):    # (compiled only when cued)
        raise UserError(f"could not place \"{m.group(0)}\": the vocabulary's bowls are all of one size: it "
                        "says how heavy, slippery or bouncy a bowl is, not how big")
