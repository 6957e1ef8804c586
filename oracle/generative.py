"""Generative models: from an antecedent to parameterizations, and back.

`sample(a, n, seed)` draws parameterizations from P(p|a); `log_density(P, a)`
is log P(p|a) for the very same distribution, exactly:

* a parameter that a proposition of `a` draws uniformly is uniform on the
  proposition's range (within the parameter's bounds);
* a parameter that no proposition draws follows its prior (uniform over the
  prior's range, within the bounds); counts are uniform over the whole
  numbers in range;
* a parameter drawn relative to a base (the start and end poses move relative
  to the pouring pose) is uniform on [base + low, base + high] clipped to its
  bounds; the base is then restricted to the values for which that clipped
  range is not empty, so the density stays a product of uniform densities.

Parameterizations are rows of 30 numbers in the vocabulary's parameter order,
in the theory's units (mm, deg, ms, g, mg, permille, count).
"""
from __future__ import annotations

from dataclasses import dataclass
from functools import lru_cache
from typing import Iterable, Mapping, Sequence

import numpy as np

from pantarhei.theory.lexicon import Vocabulary, load_vocabulary


class InvalidAntecedent(ValueError):
    """An antecedent whose propositions cannot be sampled together."""


@dataclass(frozen=True)
class Distribution:
    """The compiled distribution of one antecedent.

    `low`/`high` hold each parameter's interval (for relative parameters, the
    offset interval); `base[i]` is the base parameter's index or -1.
    """
    low: np.ndarray
    high: np.ndarray
    base: np.ndarray
    discrete: np.ndarray
    bound_low: np.ndarray
    bound_high: np.ndarray


def canonical(antecedent: Iterable[str]) -> tuple[str, ...]:
    """The antecedent as a sorted tuple of distinct names."""
    return tuple(sorted(set(antecedent)))


@lru_cache(maxsize=4096)
def _distribution(antecedent: tuple[str, ...]) -> Distribution:
    vocab = load_vocabulary()
    vocab.check_names(antecedent)
    n = len(vocab.parameters)
    bl = np.array([p.low for p in vocab.parameters], dtype=float)
    bh = np.array([p.high for p in vocab.parameters], dtype=float)
    low = np.array([p.prior_low for p in vocab.parameters], dtype=float)
    high = np.array([p.prior_high for p in vocab.parameters], dtype=float)
    base = np.full(n, -1)
    setter: dict[str, str] = {}
    for name in antecedent:
        m = vocab.proposition(name).model
        i = vocab.parameter(m.param).index
        if m.param in setter:
            raise InvalidAntecedent(f"{setter[m.param]} and {name} both set {m.param}")
        setter[m.param] = name
        if m.kind == "uniform":
            low[i], high[i] = max(bl[i], m.low), min(bh[i], m.high)
        else:
            base[i] = vocab.parameter(m.base).index
            low[i], high[i] = m.low, m.high
    for i in np.flatnonzero(base >= 0):
        b = base[i]
        if base[b] >= 0:
            raise InvalidAntecedent("a relative parameter cannot be the base of another")
        # the base must leave a non-empty range for the dependent parameter
        low[b] = max(low[b], bl[i] - high[i])
        high[b] = min(high[b], bh[i] - low[i])
    roots = base < 0
    if np.any(low[roots] > high[roots]):
        bad = vocab.parameters[int(np.flatnonzero(roots & (low > high))[0])].name
        raise InvalidAntecedent(f"the propositions leave no value for {bad}")
    discrete = np.array([p.discrete for p in vocab.parameters])
    low = np.where(discrete, np.ceil(low), low)
    high = np.where(discrete, np.floor(high), high)
    return Distribution(low, high, base, discrete, bl, bh)


def distribution(antecedent: Iterable[str]) -> Distribution:
    """The compiled distribution of an antecedent (cached)."""
    return _distribution(canonical(antecedent))


def sample(antecedent: Iterable[str], n: int, seed: int) -> np.ndarray:
    """n parameterizations drawn from P(p|antecedent), shape (n, 30): each
    parameter's n values in turn from one stream (a run of parameters drawn
    as doubles at once, the same numbers as one at a time)."""
    pl = distribution(antecedent)
    rng = np.random.default_rng(seed)
    k = len(pl.low)
    out = np.empty((n, k))
    counted = pl.discrete & (pl.base < 0)
    i = 0
    while i < k:
        if counted[i]:
            out[:, i] = rng.integers(int(pl.low[i]), int(pl.high[i]), size=n, endpoint=True)
            i += 1
            continue
        j = i + 1
        while j < k and not counted[j]:
            j += 1
        u = rng.random((j - i, n)).T
        lo, hi = pl.low[i:j], pl.high[i:j]
        # a relative parameter keeps its draw in [0, 1), scaled below
        out[:, i:j] = np.where(pl.base[i:j] < 0, lo + (hi - lo) * u, u)
        i = j
    for i in np.flatnonzero(pl.base >= 0):
        lo, hi = _relative_range(pl, i, out[:, pl.base[i]])
        out[:, i] = lo + out[:, i] * (hi - lo)
    return out


def _relative_range(pl: Distribution, i: int, base_values: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    lo = np.maximum(pl.bound_low[i], base_values + pl.low[i])
    hi = np.minimum(pl.bound_high[i], base_values + pl.high[i])
    return lo, hi


def log_density(P: np.ndarray, antecedent: Iterable[str]) -> np.ndarray:
    """log P(p|antecedent) for each row p of P (-inf outside the support)."""
    pl = distribution(antecedent)
    P = np.atleast_2d(np.asarray(P, dtype=float))
    out = np.zeros(len(P))
    for i in range(len(pl.low)):
        x = P[:, i]
        if pl.base[i] < 0:
            lo, hi = pl.low[i], pl.high[i]
            if pl.discrete[i]:
                inside = (x >= lo) & (x <= hi) & (x == np.round(x))
                width = hi - lo + 1
            else:
                inside = (x >= lo) & (x <= hi)
                width = hi - lo
            out += np.where(inside, -np.log(width), -np.inf)
        else:
            lo, hi = _relative_range(pl, i, P[:, pl.base[i]])
            inside = (x >= lo) & (x <= hi) & (hi > lo)
            with np.errstate(divide="ignore", invalid="ignore"):
                out += np.where(inside, -np.log(np.where(hi > lo, hi - lo, 1.0)), -np.inf)
    return out


def in_support(P: np.ndarray, antecedent: Iterable[str]) -> np.ndarray:
    """Whether each row of P can be drawn for the antecedent: where
    log_density is finite, each parameter inside its interval (a discrete
    one whole, a relative one's interval, around its base, not empty),
    the parameters of fixed intervals compared at once."""
    pl = distribution(antecedent)
    P = np.atleast_2d(np.asarray(P, dtype=float))
    fixed = pl.base < 0
    X = P[:, fixed]
    ok = ((X >= pl.low[fixed]) & (X <= pl.high[fixed])).all(axis=1)
    whole = pl.discrete[fixed]
    ok &= (X[:, whole] == np.round(X[:, whole])).all(axis=1)
    if np.any(pl.high[fixed][~whole] <= pl.low[fixed][~whole]):
        ok[:] = False       # an empty interval: no density anywhere
    for i in np.flatnonzero(~fixed):
        lo, hi = _relative_range(pl, i, P[:, pl.base[i]])
        x = P[:, i]
        ok &= (x >= lo) & (x <= hi) & (hi > lo)
    return ok


def normalise(P: np.ndarray, vocab: Vocabulary | None = None) -> np.ndarray:
    """Parameters scaled to [0, 1] by their bounds (for plane fits)."""
    vocab = vocab or load_vocabulary()
    lo = np.array([p.low for p in vocab.parameters], dtype=float)
    hi = np.array([p.high for p in vocab.parameters], dtype=float)
    return (np.asarray(P, dtype=float) - lo) / (hi - lo)


def to_dict(p: Sequence[float]) -> dict[str, float]:
    """One parameterization as {parameter name: value}."""
    names = load_vocabulary().parameter_names
    return {n: (int(v) if load_vocabulary().parameters[i].discrete else float(v))
            for i, (n, v) in enumerate(zip(names, p))}


def from_dict(d: Mapping[str, float]) -> np.ndarray:
    """A parameterization from {name: value}; every parameter must be given,
    within its bounds (ValueError naming the first that is not)."""
    vocab = load_vocabulary()
    unknown = sorted(set(d) - set(vocab.parameter_names))
    if unknown:
        raise ValueError(f"unknown parameter '{unknown[0]}'")
    row = np.empty(len(vocab.parameters))
    for p in vocab.parameters:
        if p.name not in d:
            raise ValueError(f"parameter '{p.name}' is missing")
        v = d[p.name]
        if isinstance(v, bool) or not isinstance(v, (int, float)) or not np.isfinite(v):
            raise ValueError(f"parameter '{p.name}' must be a number, not {v!r}")
        if not p.low <= v <= p.high:
            raise ValueError(f"parameter '{p.name}' = {v} is outside its bounds [{p.low}, {p.high}] {p.unit}")
        if p.discrete and v != int(v):
            raise ValueError(f"parameter '{p.name}' must be a whole number, not {v}")
        row[p.index] = v
    return row


# -- judging: from a parameterization back to propositions -----------------------

@dataclass(frozen=True)
class Judge:
    """Every proposition's support as arrays, in `names` order: the
    proposition holds p when p[param] (or p[param] - p[base] for a relative
    model) lies in [low, high]; `base` is -1 for uniform models."""
    names: tuple[str, ...]
    dimension: tuple[str, ...]
    param: np.ndarray
    base: np.ndarray
    low: np.ndarray
    high: np.ndarray


@lru_cache(maxsize=1)
def judge() -> Judge:
    """The supports of the vocabulary's propositions, per dimension in rank
    order (the first value of a dimension that holds p is the one kept)."""
    vocab = load_vocabulary()
    names, dims, param, base, low, high = [], [], [], [], [], []
    for dim in vocab.dimensions.values():
        for name in dim.values:
            m = vocab.proposition(name).model
            par = vocab.parameter(m.param)
            names.append(name)
            dims.append(dim.name)
            param.append(par.index)
            if m.kind == "uniform":
                base.append(-1)
                low.append(max(par.low, m.low))
                high.append(min(par.high, m.high))
            else:
                base.append(vocab.parameter(m.base).index)
                low.append(m.low)
                high.append(m.high)
    arrays = [np.array(param), np.array(base), np.array(low, dtype=float), np.array(high, dtype=float)]
    for a in arrays:
        a.flags.writeable = False       # cached: shared by every caller
    return Judge(tuple(names), tuple(dims), *arrays)


def holds(P: np.ndarray) -> tuple[tuple[str, ...], np.ndarray]:
    """Which propositions hold each parameterization: the proposition names
    and a boolean matrix (len(P) x names), at most one True per dimension."""
    j = judge()
    P = np.atleast_2d(np.asarray(P, dtype=float))
    x = P[:, j.param] - np.where(j.base >= 0, P[:, np.maximum(j.base, 0)], 0.0)
    inside = (x >= j.low) & (x <= j.high)
    # where two values of a dimension share a boundary point, the lower rank keeps it
    first = np.zeros_like(inside)
    dims = np.array(j.dimension)
    for d in dict.fromkeys(j.dimension):
        cols = np.flatnonzero(dims == d)
        block = inside[:, cols]
        pick = np.argmax(block, axis=1)
        any_ = block.any(axis=1)
        first[np.flatnonzero(any_), cols[pick[any_]]] = True
    return j.names, first


def describe(P: np.ndarray) -> list[tuple[str, ...]]:
    """For each parameterization (row of 30 numbers), the propositions whose
    generative model holds it, as a canonical sorted tuple: per dimension the
    value whose support contains it (uniform models on their parameter's
    range, relative models on the offset from their base), none where it
    falls between values."""
    names, M = holds(P)
    return [canonical(names[k] for k in np.flatnonzero(row)) for row in M]
