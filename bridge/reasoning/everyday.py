"""The everyday word list (everyday.txt, beside this module): the names
of liquids, containers, materials, the things around a pour, hedges,
degree phrases and the words the vocabulary cannot say, each with the
words it is read as and what `ask` says back of it. The file's header
says how it is written.

A phrase matches its plural by a small rule, not a dictionary: its last
word with "s" or "es", or "ies" for a final "y" ("jugs", "glasses",
"parties"); the words people type about pouring need no more (a verb's
inflections are words.py's and outcomes.py's).
"""
from __future__ import annotations

import re
from dataclasses import dataclass
from functools import lru_cache
from pathlib import Path

FILE = Path(__file__).with_name("everyday.txt")
#: The word that phrases too vague to read become ("pour from above": over
#: the destination's middle, or high above it?), and a section of refused
#: phrases is read as: reading.py places it nowhere, so a question that
#: says one is refused naming the phrase.
UNCLEAR = "unclear"


@dataclass(frozen=True)
class Section:
    words: str                    # what its phrases are read as: "sticky liquid", "bowl", "unclear"
    said_back: str                # what `ask` says of each ("" for nothing)
    phrases: tuple[str, ...]      # as written, the longest first


@lru_cache(maxsize=None)
def sections() -> tuple[Section, ...]:
    """The file's sections, in its order."""
    out: list[Section] = []
    words, said, phrases = None, "", []
    for line in FILE.read_text(encoding="utf-8").splitlines():
        line = line.strip()
        if not line or line.startswith("#"):
            continue
        if line.startswith("=="):
            if words is not None:
                out.append(_section(words, said, phrases))
            words, _, said = (part.strip() for part in line[2:].partition("|"))
            phrases = []
            continue
        if words is None:
            raise ValueError(f"{FILE}: a phrase before the first section: {line!r}")
        phrases += [p.strip() for p in line.split(",") if p.strip()]
    if words is not None:
        out.append(_section(words, said, phrases))
    return tuple(out)


def refused(saying: str) -> Section:
    """The section of words the vocabulary cannot say whose reason holds `saying` ("all of one size")."""
    return next(s for s in sections() if s.words == UNCLEAR and saying in s.said_back)


def _section(words: str, said: str, phrases: list[str]) -> Section:
    return Section(words, said, tuple(sorted(dict.fromkeys(phrases), key=lambda p: (-len(p), p))))


def forms(phrase: str) -> tuple[tuple[str, ...], ...]:
    """`phrase` and its plurals, as words (see the module's docstring)."""
    *head, last = phrase.split()
    ends = [last, last + "s", last + "es"] + ([last[:-1] + "ies"] if last.endswith("y") else [])
    return tuple((*head, e) for e in ends)


#: Containers' names that are also what a container is made of, before another's name or "one":
#: "a glass jug", "a light tin one".
_MADE_OF = frozenset(("glass", "tin"))


class Matcher:
    """Where a question's words hold the phrases of one section, found by
    looking the words up (no regular expression to compile: `ask` reads
    one question and exits). `before`: phrases that may stand before one
    of these as part of its name ("a milk carton"); `glass_before`:
    phrases before which "glass" (or "tin") is what a bowl is made of ("a glass jug");
    `held`: phrases of `before` that are read with the name, as what the
    container holds, each with the words it is read as ("the honey jar": a
    sticky liquid), before `read_as` (the section's words), unless a phrase
    of `apart` is said apart from the name ("water from the honey jar": water)."""

    def __init__(self, phrases, before=(), glass_before=(), held=None, read_as=(), apart=()):
        self.table = frozenset(f for p in phrases for f in forms(p))
        self.before = frozenset(f for p in before for f in forms(p))
        self.held = {f: words for p, words in (held or {}).items() for f in forms(p)}
        self.read_as = tuple(read_as)
        self.apart = frozenset(f for p in apart for f in forms(p))
        self.glass_before = frozenset(f for p in glass_before for f in forms(p))
        self.longest = max(map(len, self.table | self.before | self.glass_before), default=0)
        # the words a phrase may begin with: a word that begins none is passed at once
        self.firsts = frozenset(f[0] for f in self.table | self.before) | _MADE_OF

    def _at(self, table: frozenset, words: list[str], i: int) -> int:
        """The length of the longest phrase of `table` at `i`, or 0."""
        for n in range(min(self.longest, len(words) - i), 0, -1):
            if tuple(words[i:i + n]) in table:
                return n
        return 0

    def spans(self, words: list[str]) -> list[tuple]:
        """(first, end) of each phrase in `words`, left to right, the longest
        first; (first, end, its own words) for a name read with what it holds."""
        out, i = [], 0
        while i < len(words):
            if words[i] not in self.firsts:
                i += 1
                continue
            n = self._at(self.before, words, i)
            m = self._at(self.table, words, i + n) if n else 0
            if not m:
                n, m = 0, self._at(self.table, words, i)
            if not m and words[i] in _MADE_OF and self._at(self.glass_before, words, i + 1):
                m = 1
            if m:
                held = self.held.get(tuple(words[i:i + n])) if n else None
                if held and not self._said_apart(words, i, i + n + m):
                    out.append((i, i + n + m, held + self.read_as))
                else:
                    out.append((i, i + n + m))
                i += n + m
            else:
                i += 1
        return out

    def _said_apart(self, words: list[str], first: int, end: int) -> bool:
        """Whether a phrase of `apart` is said outside words[first:end]."""
        rest = words[:first] + ["."] + words[end:]
        return any(self._at(self.apart, rest, k) for k in range(len(rest)))


def plural(phrase: str) -> str:
    """A regular expression for `phrase` and its plurals: the words of
    forms(), which the lookups match."""
    *head, _ = phrase.split()
    ends = "|".join(re.escape(f[-1]) for f in forms(phrase))
    return " ".join([*(re.escape(w) for w in head), f"(?:{ends})"])


def names(*words: str) -> tuple[str, ...]:
    """The phrases of the sections read as any of `words` ("liquid", "context")."""
    return tuple(p for s in sections() if any(w in s.words.split() for w in words)
                 for p in s.phrases)


def alternation(phrases) -> str:
    """One regular expression for the phrases and their plurals, the longest first."""
    return "|".join(plural(p) for p in sorted(phrases, key=lambda p: (-len(p), p)))
