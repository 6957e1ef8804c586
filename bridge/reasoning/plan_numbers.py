"""A plan in numbers a robot can act on: the ranges of the parameters its
propositions fix, the parameters it leaves to the ordinary pour, and the
rule and likelihood each goal rests on.

The ranges are those the generative models draw a plan's pours from
(oracle/generative.py over theory/vocabulary/): a proposition that draws a
parameter uniformly fixes it to its range (within the parameter's bounds);
one that draws it relative to a base (the start and end poses move
relative to the pouring pose) fixes it to the base plus an offset range;
every other parameter follows its prior, the ordinary pour.
"""
from __future__ import annotations

from dataclasses import asdict, dataclass
from typing import Sequence

from pantarhei.theory.lexicon import load_vocabulary

from pantarhei.bridge.theories.model import Theory, complement


@dataclass(frozen=True)
class Range:
    """A parameter's range: `low` to `high` in `unit`; for a relative one,
    the offset from `base` (the parameter is base + low to base + high)."""
    parameter: str
    unit: str
    low: float
    high: float
    base: str | None = None
    by: str | None = None        # the proposition that fixes it (None: the ordinary pour)

    def words(self) -> str:
        lo, hi = _number(self.low), _number(self.high)
        if self.base is None:
            return f"{self.parameter} {lo} to {hi} {self.unit}"
        return f"{self.parameter} {self.base} {_signed(self.low)} to {_signed(self.high)} {self.unit}"

    def as_dict(self) -> dict:
        return {k: v for k, v in asdict(self).items() if v is not None}


def _number(x: float) -> str:
    return f"{x:g}"


def _signed(x: float) -> str:
    return f"{'+' if x >= 0 else '-'} {abs(x):g}"


def fixed_ranges(antecedent: Sequence[str]) -> list[Range]:
    """The parameters the antecedent's propositions fix, in the
    vocabulary's parameter order, each with the range its pours are drawn
    from (oracle/generative.py's distribution: bounds applied, a base
    narrowed so that its dependant keeps a range)."""
    from pantarhei.oracle.generative import distribution

    vocab = load_vocabulary()
    d = distribution(antecedent)
    by = {vocab.proposition(p).model.param: p for p in antecedent}
    out = []
    for prm in vocab.parameters:
        if prm.name not in by:
            continue
        i = prm.index
        base = vocab.parameters[int(d.base[i])].name if d.base[i] >= 0 else None
        out.append(Range(prm.name, prm.unit, float(d.low[i]), float(d.high[i]), base, by[prm.name]))
    return out


def ordinary_ranges(antecedent: Sequence[str]) -> list[Range]:
    """The parameters the antecedent leaves to the ordinary pour, each with
    the range of its prior (narrowed where a relative parameter the
    antecedent fixes needs it)."""
    from pantarhei.oracle.generative import distribution

    vocab = load_vocabulary()
    d = distribution(antecedent)
    fixed = {vocab.proposition(p).model.param for p in antecedent}
    return [Range(p.name, p.unit, float(d.low[p.index]), float(d.high[p.index]))
            for p in vocab.parameters if p.name not in fixed]


@dataclass(frozen=True)
class Support:
    """What the theory says of one goal in a plan's scene: the deciding
    rule (None: undecided), the likelihood that the goal literal holds
    (None: the rule records none), and the theory's verdict on the goal."""
    goal: str
    rule: str | None
    likelihood: float | None
    verdict: str

    def as_dict(self) -> dict:
        return asdict(self)


def rests_on(theory: Theory, antecedent: Sequence[str], goals: Sequence[str]) -> list[Support]:
    """Per goal literal, the rule of `theory` it rests on in the scene
    `antecedent` and its likelihood, as `pantarhei ask` answers it
    (theory/ask.pl in this process's SWI-Prolog)."""
    from pantarhei.bridge.reasoning.answers import what_happens

    answers = {a.expectation: a for a in what_happens(theory, list(antecedent))}
    out = []
    for g in goals:
        negated = g.startswith("neg(")
        a = answers.get(complement(g) if negated else g)
        if a is None:
            out.append(Support(g, None, None, "unknown"))
            continue
        like = a.likelihood
        if like is not None and negated:
            like = 1 - like
        verdict = a.value
        if negated and verdict in ("holds", "fails"):
            verdict = "fails" if verdict == "holds" else "holds"
        out.append(Support(g, a.rule or None, None if like is None else round(float(like), 3),
                           verdict))
    return out
