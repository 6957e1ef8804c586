"""Where the value words of each reading stand in a question: every
place a phrase of the vocabulary (its words in any order, each beside the
nearest of the others in one clause, at most `MAX_GAP` other words
between them) can be read, and the order readings are taken in."""
from __future__ import annotations

from bisect import bisect_left
from typing import Iterable

from pantarhei.bridge.reasoning.wording import Token

#: The most other words between the words of one reading.
MAX_GAP = 4


def occurrences(tokens: list[Token], phrases: Iterable[tuple[str, ...]]):
    """(value words, their positions) for every reading the question holds:
    anchored on each of its words, the nearest of each other in its clause."""
    where: dict[str, list[int]] = {}              # word -> its positions, in order
    for i, t in enumerate(tokens):
        where.setdefault(t.word, []).append(i)
    for words in phrases:
        if not all(w in where for w in words):
            continue
        for a in sorted({i for w in words for i in where[w]}):
            t = tokens[a]
            at = {t.word: a}
            for w in words:
                if w != t.word:
                    near = nearest(where[w], a, tokens, t.clause)
                    if near is not None:
                        at[w] = near
            span = max(at.values()) - min(at.values()) + 1
            if "very" in at and at["very"] + 1 not in at.values():
                continue            # "very" raises the word right after it ("very smooth and ... much": no very much)
            if len(at) == len(words) and span - len(words) <= MAX_GAP:
                yield words, frozenset(at.values())


def nearest(positions: list[int], a: int, tokens: list[Token], clause: int) -> int | None:
    """The position of `positions` (in order) in `clause` nearest to `a`,
    the earlier of two as near; None if there is none. Words of one clause
    stand together, so the nearest is beside where `a` would go, or the
    nearest in the clause on that side."""
    k = bisect_left(positions, a)
    near = [positions[j] for j in (k - 1, k)
            if 0 <= j < len(positions) and tokens[positions[j]].clause == clause]
    return min(near, key=lambda i: (abs(i - a), i)) if near else None


def closest(reading: tuple[tuple[str, ...], frozenset[int]]) -> tuple:
    """The order readings are taken in: the most words first, then the
    closest together, then the earliest."""
    words, positions = reading
    return (-len(words), max(positions) - min(positions), min(positions))
