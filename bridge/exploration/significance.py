"""Planes that see signal: a permutation test of every slope of an
antecedent's planes.

With n + 1 pours for n parameters a plane fits anything, so a steep plane is
not yet a reason to explore. The test asks what the same weighted pours give
with the link between parameters and scores broken: the score rows are
shuffled among the pours (each pour keeps its parameters and its weight of
equation (1)), the planes are fitted again, and the observed slopes are set
against those of the shuffles.

Every component (parameter j, expectation k) of the planes is judged at once
(the single-step max-T method of Westfall and Young): each |slope| is
standardised by its own spread under the shuffles, and a component is
significant at level alpha when at most a share alpha of the shuffles has a
largest standardised |slope|, over all 30 x 9 components, at least as large.
So the chance that noise alone makes any component of an antecedent's planes
significant is at most alpha, and a parameter that cannot matter (the yaw of
round bowls) is chosen with probability well below alpha.

The planes are weighted ridge regressions in closed form. With the
parameters centred at their weighted mean, the slopes are B = A S with
A = (Xc' W Xc + ridge I)^-1 Xc' W, and A does not change when the scores
are shuffled: every shuffle costs one matrix product.
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from pantarhei.bridge.exploration.planes import MIN_WEIGHT


@dataclass(frozen=True)
class Tested:
    """The planes of one antecedent with their permutation test."""
    coef: np.ndarray        # (9, 30) slopes, score per normalised unit
    mean: np.ndarray        # (9,) weighted mean scores
    centre: np.ndarray      # (30,) weighted mean of the normalised parameters
    p: np.ndarray           # (9, 30) p-values adjusted over all components (max-T)
    used: int               # pours with a weight

    def significant(self, alpha: float) -> np.ndarray:
        """(9, 30) booleans: the components significant at level alpha."""
        return self.p <= alpha

    def slopes(self, alpha: float) -> np.ndarray:
        """(9,) the norm of each plane's significant components (0 where none is)."""
        return np.linalg.norm(np.where(self.significant(alpha), self.coef, 0.0), axis=1)


def shuffle_seed(seed: int, antecedent: int, used: int) -> int:
    """The seed of one test: from the run's seed, the antecedent's number and
    the number of pours it weighs, so that the same planes always get the same
    shuffles (a resumed run tests as the uninterrupted one did)."""
    return int(np.random.SeedSequence([int(seed), int(antecedent), int(used)])
               .generate_state(1)[0])


def permutation_test(X: np.ndarray, S: np.ndarray, w: np.ndarray, ridge: float,
                     permutations: int, seed: int) -> Tested | None:
    """Fit the weighted ridge planes of the scores S (n, 9) on the normalised
    parameters X (n, 30) and test every slope against `permutations` shuffles
    of the score rows (seeded by `seed`). Rows without a weight or with a
    failed score are left out; None when fewer than three remain."""
    X, S, w = np.asarray(X, float), np.asarray(S, float), np.asarray(w, float)
    keep = (w > MIN_WEIGHT) & np.all(np.isfinite(S), axis=1)
    n = int(keep.sum())
    if n < 3:
        return None
    X, S, w = X[keep], S[keep], w[keep]
    total = w.sum()
    centre = w @ X / total
    Xc = X - centre
    XtW = Xc.T * w
    A = np.linalg.solve(XtW @ Xc + ridge * np.eye(X.shape[1]), XtW)    # (30, n)
    mean = w @ S / total
    coef = (A @ S).T                                                     # (9, 30)
    rng = np.random.default_rng(seed)
    order = np.argsort(rng.random((permutations, n)), axis=1)            # one shuffle a row
    null = np.einsum("jn,bnk->bkj", A, S[order])                         # (B, 9, 30)
    spread = np.sqrt(np.mean(null ** 2, axis=0))                         # (9, 30)
    with np.errstate(divide="ignore", invalid="ignore"):
        observed = np.where(spread > 1e-12, np.abs(coef) / spread, 0.0)
        shuffled = np.where(spread > 1e-12, np.abs(null) / spread, 0.0)
    top = np.sort(shuffled.reshape(permutations, -1).max(axis=1))        # (B,)
    beaten = permutations - np.searchsorted(top, observed, side="left")  # shuffles >= observed
    p = (1.0 + beaten) / (permutations + 1.0)
    p = np.where(observed > 0, p, 1.0)
    return Tested(coef, mean, centre, p, n)
