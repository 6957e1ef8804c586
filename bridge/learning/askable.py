"""Which bodies a person can ask about: the empty one, every proposition
alone and every valid pair; whether two bodies can hold together in
one scene; and whether a pair may interact as physics goes (`suspect`).

Validity is clingo's (theory/violations.lp), asked once: every constraint
there is broken by a pair of propositions, whatever else the antecedent
holds, so clingo names, with every proposition in, each pair that breaks
one; an antecedent is valid when none of its pairs is among them. The
learner asks this of thousands of bodies inside explore/1, where Prolog
cannot be asked again; tests/bridge/learning/test_askable.py keeps it equal
to Prolog's valid_antecedent/1."""
from __future__ import annotations

from functools import lru_cache
from itertools import combinations
from typing import Iterable, Sequence

from pantarhei.theory.lexicon import load_vocabulary


@lru_cache(maxsize=1)
def clashing_pairs() -> frozenset[frozenset[str]]:
    """The pairs of propositions that break a validity constraint, from one
    call of clingo over the whole vocabulary (violated/3 of violations.lp)."""
    from pantarhei.bridge.engines.asp import solve

    every = "".join(f"in({p})." for p in sorted(load_vocabulary().propositions))
    (shown,) = solve(["violations.lp"], every)
    return frozenset(frozenset(str(a) for a in s.arguments[1:]) for s in shown if s.name == "violated")


def valid(props: Iterable[str]) -> bool:
    """Whether the propositions (known names) form a valid antecedent."""
    clash = clashing_pairs()
    return not any(frozenset(pair) in clash for pair in combinations(sorted(set(props)), 2))


def askable_bodies(max_body: int) -> list[tuple[str, ...]]:
    """The empty body, every proposition alone and every valid pair (up to
    `max_body` propositions), in canonical order."""
    names = sorted(load_vocabulary().propositions)
    out: list[tuple[str, ...]] = [()]
    if max_body >= 1:
        out += [(n,) for n in names]
    if max_body >= 2:
        out += [b for b in combinations(names, 2) if valid(b)]
    return out


def together(a: Sequence[str], b: Sequence[str]) -> bool:
    """Whether one scene can hold both bodies."""
    return valid([*a, *b])


def suspect(body: Sequence[str]) -> bool:
    """Whether a pair may interact as physics goes: its propositions set
    parameters of one group (one pose, the liquid, a bowl, the motion),
    a relative model's base parameter counted with its own."""
    if len(body) != 2:
        return False
    vocabulary = load_vocabulary()
    group = {p.name: p.group for p in vocabulary.parameters}

    def groups(name: str) -> set[str]:
        m = vocabulary.propositions[name].model
        return {group[m.param]} | ({group[m.base]} if m.base else set())
    return bool(groups(body[0]) & groups(body[1]))
