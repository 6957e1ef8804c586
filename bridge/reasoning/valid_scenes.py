"""Is an antecedent valid? Asked of SWI-Prolog or of clingo, same answer.
And valid antecedents drawn uniformly, by SWI-Prolog."""
from __future__ import annotations

from dataclasses import dataclass
from functools import lru_cache
from typing import Iterable

from pantarhei.theory.lexicon import UnknownProposition, load_vocabulary

from pantarhei.bridge.errors import UserError

ENGINES = ("prolog", "asp")


@dataclass(frozen=True, order=True)
class Violation:
    constraint: str
    first: str
    second: str

    def words(self) -> str:
        gloss = load_vocabulary().constraints[self.constraint]
        return f"{self.first} and {self.second}: {gloss} ({self.constraint})"


def known(props: Iterable[str]) -> list[str]:
    """The names as a sorted set (a question's reading kept with them:
    reading.Scene); UserError naming the closest known ones for the first
    unknown name."""
    reading = getattr(props, "reading", None)
    props = sorted(set(props))
    try:
        load_vocabulary().check_names(props)
    except UnknownProposition as e:
        raise UserError(str(e)) from None
    if reading is not None:
        from pantarhei.bridge.reasoning.reading import Scene

        return Scene(reading)
    return props


def violations(props: Iterable[str], engine: str = "prolog") -> list[Violation]:
    """The constraints that the antecedent breaks, sorted."""
    props = known(props)
    if engine == "prolog":
        from pantarhei.bridge.engines.swipl import engine as prolog

        found = [Violation(s["C"], s["P1"], s["P2"])
                 for s in prolog().query("validity:violation(Ps, C, P1, P2)", Ps=props)]
    elif engine == "asp":
        found = [Violation(*(a.name for a in s.arguments))
                 for s in _asp_checker().shown(props) if s.name == "violated"]
    else:
        raise UserError(f"unknown engine '{engine}' (choose prolog or asp)")
    return sorted(set(found))


@lru_cache(maxsize=1)
def _asp_checker():
    from pantarhei.bridge.engines.asp import Checker

    return Checker(["violations.lp"], "in")


def require_valid(props: Iterable[str]) -> list[str]:
    """The antecedent as a sorted list; UserError naming the first violated
    constraint if it is not valid."""
    props = known(props)
    bad = violations(props)
    if bad:
        raise UserError(invalid(bad))
    return props


def invalid(bad: list[Violation]) -> str:
    """The one line for an antecedent that breaks the constraints `bad`
    (sorted): the first, and how many more."""
    more = f" (and {len(bad) - 1} more)" if len(bad) > 1 else ""
    return f"invalid antecedent: {bad[0].words()}{more}"


def random_antecedents(seed: int, n: int) -> list[tuple[str, ...]]:
    """n antecedents drawn uniformly from the valid ones (by Prolog's
    validity:random_antecedents/3; the same seed, the same antecedents)."""
    from pantarhei.bridge.engines.swipl import engine as prolog

    r = prolog().once("validity:random_antecedents(Seed, N, As)", Seed=int(seed), N=int(n))
    return [tuple(str(p) for p in a) for a in r["As"]]


def count_valid() -> int:
    """The number of valid antecedents, counted by Prolog per component."""
    from pantarhei.bridge.engines.swipl import engine as prolog

    return int(prolog().once("validity:count_valid(N)")["N"])
