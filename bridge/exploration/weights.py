"""Equation (1): how strongly each simulation belongs to each antecedent.

    w(a, p) = P(p|a) / sum over b in H of P(p|b)

computed in log space from the generative models' exact log densities, so
that 30-dimensional densities neither underflow nor overflow.
"""
from __future__ import annotations

from typing import Iterable, Sequence

import numpy as np
from scipy.special import logsumexp

from pantarhei.oracle.generative import log_density


def log_densities(P: np.ndarray, antecedents: Sequence[Iterable[str]]) -> np.ndarray:
    """log P(p|a) for each antecedent a (rows) and parameterization p
    (columns): shape (len(antecedents), len(P)), -inf outside a's support."""
    P = np.atleast_2d(np.asarray(P, dtype=float))
    if not len(antecedents):
        return np.empty((0, len(P)))
    return np.vstack([log_density(P, a) for a in antecedents])


def weights(log_dens: np.ndarray) -> np.ndarray:
    """Equation (1) from a matrix of log densities (antecedents x
    simulations): each column sums to 1 over the antecedents whose support
    holds the simulation, and is all 0 where none does."""
    log_dens = np.asarray(log_dens, dtype=float)
    if log_dens.size == 0:
        return np.zeros_like(log_dens)
    with np.errstate(invalid="ignore", divide="ignore"):
        total = logsumexp(log_dens, axis=0)
        w = np.exp(log_dens - total)
    w[:, ~np.isfinite(total)] = 0.0
    return np.nan_to_num(w, nan=0.0)


def weight(antecedent: Iterable[str], p: np.ndarray, explored: Sequence[Iterable[str]]) -> float:
    """w(a, p) of equation (1) for one parameterization; `antecedent` must be
    one of `explored` (the set H)."""
    a = tuple(sorted(antecedent))
    keys = [tuple(sorted(b)) for b in explored]
    if a not in keys:
        raise ValueError("the antecedent must be one of the explored antecedents")
    w = weights(log_densities(np.atleast_2d(p), keys))
    return float(w[keys.index(a), 0])
