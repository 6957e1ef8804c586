"""planeFit and bestAbsSlope: the hyperplanes that approximate the oracle
around an antecedent, and their steepest directions.

For one antecedent, each of the 9 expectation scores is regressed linearly
on the normalised parameters (each scaled to [0, 1] by its bounds), every
simulation weighted by equation (1). A plane's slope is the norm of its
gradient; its direction is the gradient itself.

With n + 1 simulations of one antecedent and n parameters, least squares is
exactly determined: the plane interpolates every simulation and its slopes
mostly amplify the scores' curvature. A small ridge penalty (`ridge`, on the
normalised parameters) keeps the planes' directions where the scores really
change; `ridge=0` is plain weighted least squares, as in the paper.
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from sklearn import config_context
from sklearn.linear_model import LinearRegression, Ridge

#: Simulations with a weight below this take no part in a fit.
MIN_WEIGHT = 1e-12


@dataclass(frozen=True)
class Planes:
    """The hyperplanes of one antecedent: score_k ~ intercept[k] + coef[k] . x."""
    intercept: np.ndarray   # (9,)
    coef: np.ndarray        # (9, 30), in score per normalised unit
    used: int               # simulations with a weight above MIN_WEIGHT
    mass: float             # sum of their weights
    mean: np.ndarray        # (9,) weighted mean scores


@dataclass(frozen=True)
class Slope:
    """The steepest plane of a set: expectation index, |gradient|, gradient."""
    expectation: int
    slope: float
    gradient: np.ndarray


def plane_fit(X: np.ndarray, S: np.ndarray, w: np.ndarray, ridge: float = 0.0) -> Planes | None:
    """Weighted least squares (with an L2 penalty `ridge` on the slopes) of
    every score column of S (n, 9) on the normalised parameters X (n, 30). Rows whose scores are not all finite,
    or whose weight is negligible, are left out; None when fewer than two
    rows remain."""
    X, S, w = np.asarray(X, float), np.asarray(S, float), np.asarray(w, float)
    keep = (w > MIN_WEIGHT) & np.all(np.isfinite(S), axis=1)
    if keep.sum() < 2:
        return None
    X, S, w = X[keep], S[keep], w[keep]
    model = Ridge(alpha=ridge) if ridge > 0 else LinearRegression()
    with config_context(assume_finite=True):    # checked above: skip sklearn's own checks
        model.fit(X, S, sample_weight=w)
    mean = (w[:, None] * S).sum(axis=0) / w.sum()
    return Planes(np.asarray(model.intercept_, float), np.atleast_2d(model.coef_).astype(float),
                  int(keep.sum()), float(w.sum()), mean)


def best_abs_slope(planes: Planes) -> Slope:
    """The plane with the largest gradient norm (the first on ties)."""
    norms = np.linalg.norm(planes.coef, axis=1)
    k = int(np.argmax(norms))
    return Slope(k, float(norms[k]), planes.coef[k].copy())
