"""The vocabulary (parameters, propositions, dimensions, expectations) as
Python objects, read from the theory's fact files.

The single source is `theory/vocabulary/*.pl`; this module only reads it.
"""
from __future__ import annotations

import difflib
from dataclasses import dataclass
from functools import lru_cache
from typing import Iterable, Optional

from pantarhei.theory import VOCABULARY_FILES, read_facts


@dataclass(frozen=True)
class Parameter:
    name: str
    index: int
    group: str
    unit: str
    low: int
    high: int
    prior_low: int
    prior_high: int
    gloss: str

    @property
    def discrete(self) -> bool:
        """Counts take whole values; everything else is continuous."""
        return self.unit == "count"


@dataclass(frozen=True)
class Model:
    """How a proposition draws its parameter: uniform on [low, high], or
    relative to a base parameter: param = base + d, d uniform on [low, high]."""
    kind: str           # "uniform" or "relative"
    param: str
    low: int
    high: int
    base: Optional[str] = None


@dataclass(frozen=True)
class Proposition:
    name: str
    dimension: str
    rank: int
    gloss: str
    model: Model


@dataclass(frozen=True)
class Dimension:
    name: str
    aspect: str
    schema: str
    gloss: str
    role: str
    values: tuple[str, ...]


@dataclass(frozen=True)
class Expectation:
    name: str
    stage: str
    gloss: str


class UnknownProposition(ValueError):
    """A name that is not a proposition; the message names the closest ones."""

    def __init__(self, name: str, known: Iterable[str]):
        close = difflib.get_close_matches(name, list(known), n=3, cutoff=0.5)
        hint = f" (did you mean {', '.join(close)}?)" if close else ""
        super().__init__(f"unknown proposition '{name}'{hint}")
        self.name = name


@dataclass(frozen=True)
class Vocabulary:
    parameters: tuple[Parameter, ...]
    propositions: dict[str, Proposition]
    dimensions: dict[str, Dimension]
    expectations: tuple[Expectation, ...]
    constraints: dict[str, str]
    scene: dict[str, int]

    @property
    def parameter_names(self) -> tuple[str, ...]:
        return tuple(p.name for p in self.parameters)

    @property
    def expectation_names(self) -> tuple[str, ...]:
        return tuple(e.name for e in self.expectations)

    def parameter(self, name: str) -> Parameter:
        for p in self.parameters:
            if p.name == name:
                return p
        raise KeyError(name)

    def proposition(self, name: str) -> Proposition:
        try:
            return self.propositions[name]
        except KeyError:
            raise UnknownProposition(name, self.propositions) from None

    def check_names(self, names: Iterable[str]) -> None:
        """Raise UnknownProposition for the first name that is not known."""
        for n in names:
            self.proposition(n)


@lru_cache(maxsize=None)
def load_vocabulary() -> Vocabulary:
    """The vocabulary of `theory/vocabulary/`, read once per process."""
    f = read_facts(VOCABULARY_FILES)
    priors = {name: (lo, hi) for name, (_uniform, lo, hi) in f["prior"]}
    glosses = dict(f["parameter_gloss"])
    parameters = tuple(
        Parameter(name, i, group, unit, lo, hi, *priors[name], glosses[name])
        for i, (name, group, unit, lo, hi) in enumerate(f["parameter"]))
    models = {}
    for prop, param, m in f["model"]:
        if m[0] == "uniform":
            models[prop] = Model("uniform", param, m[1], m[2])
        else:
            models[prop] = Model("relative", param, m[2], m[3], base=m[1])
    propositions = {name: Proposition(name, dim, rank, gloss, models[name])
                    for name, dim, rank, gloss in f["proposition"]}
    roles = dict(f["role"])
    dimensions = {}
    for dim, aspect, schema, gloss in f["dimension"]:
        values = tuple(sorted((p for p in propositions.values() if p.dimension == dim),
                              key=lambda p: p.rank))
        dimensions[dim] = Dimension(dim, aspect, schema, gloss, roles[dim],
                                    tuple(p.name for p in values))
    expectations = tuple(Expectation(*e) for e in f["expectation"])
    return Vocabulary(parameters, propositions, dimensions, expectations,
                      dict(f["constraint"]), {c: v for c, _unit, v in f["scene"]})
