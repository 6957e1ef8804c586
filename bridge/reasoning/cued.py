"""A pattern of phrases compiled only when a text first holds one of its
cues: a literal every match must contain. The reader holds some two
hundred such patterns (words.py), and a question names a few of the
things they read; compiling them all cost each `ask` a tenth of a
second. `search` finds what the compiled pattern would, and None where
no cue is in the text."""
from __future__ import annotations

import re
from functools import cached_property
from typing import Sequence


class Cued:
    """`source`, a regular expression, with `cues` (None: no cue is known,
    the pattern is always tried)."""

    def __init__(self, source: str, cues: Sequence[str] | None) -> None:
        self.source = source
        self.cues = None if cues is None else tuple(cues)

    @cached_property
    def pattern(self) -> re.Pattern:
        return re.compile(self.source)

    def cued(self, text: str) -> bool:
        """Whether `text` holds a cue (a match is possible)."""
        return self.cues is None or any(c in text for c in self.cues)

    def search(self, text: str) -> re.Match | None:
        return self.pattern.search(text) if self.cued(text) else None
