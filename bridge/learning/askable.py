"""Which bodies a person can ask about: the empty one, every proposition
alone and every valid pair (one value per dimension, one proposition per
parameter, no listed conflict); and whether two bodies can hold together
in one scene."""
from __future__ import annotations

from functools import lru_cache
from itertools import combinations
from typing import Sequence

from pantarhei.theory.lexicon import load_vocabulary


@lru_cache(maxsize=1)
def _conflicts() -> frozenset[frozenset[str]]:
    from pantarhei.theory import VOCABULARY_FILES, read_facts

    return frozenset(frozenset(c[1:]) for c in read_facts(VOCABULARY_FILES).get("conflict", []))


def _askable(body: Sequence[str]) -> bool:
    """Whether a body is a valid antecedent: one value per dimension, one
    proposition per parameter, no listed conflict."""
    v = load_vocabulary()
    props = [v.proposition(p) for p in body]
    if len({p.dimension for p in props}) < len(props) or len({p.model.param for p in props}) < len(props):
        return False
    return not any(frozenset(pair) in _conflicts() for pair in combinations(body, 2))


def askable_bodies(max_body: int) -> list[tuple[str, ...]]:
    """The empty body, every proposition alone and every valid pair (up to
    `max_body` propositions), in canonical order."""
    names = sorted(load_vocabulary().propositions)
    out: list[tuple[str, ...]] = [()]
    if max_body >= 1:
        out += [(n,) for n in names]
    if max_body >= 2:
        out += [b for b in combinations(names, 2) if _askable(b)]
    return out


def together(a: Sequence[str], b: Sequence[str]) -> bool:
    """Whether one scene can hold both bodies."""
    return _askable(tuple(sorted(set(a) | set(b))))
