"""Which plane the loop follows next: `exploration_steepest_plane` and
`exploration_significant_planes`, which the curiosity's module in
theory/curiosity/ chooses between.

The paper's curiosity takes the steepest plane of any explored antecedent
(bestAbsSlope, `steepest_plane`). The discovering one tests every explored
antecedent's planes against shuffles and follows each antecedent with a
significant component, steepest significant plane first, along each of
its significant planes: its significant parameters, largest first, each
with the antecedent's mean value and the value past which the plane's
verdict flips (theory units, `significant_planes`). The first of them is
the best, as the paper's steepest plane. Each request carries the
settings of its fits: `ridge`, and for the test `permutations`,
`significance` and `seed`.
"""
from __future__ import annotations

from typing import TYPE_CHECKING

import numpy as np

from pantarhei.bridge.exploration.planes import Planes, best_abs_slope
from pantarhei.bridge.exploration.significance import Tested
from pantarhei.oracle.generative import normalise
from pantarhei.theory import defaults
from pantarhei.theory.lexicon import load_vocabulary

if TYPE_CHECKING:
    from pantarhei.bridge.exploration.session import Host, Session


def handlers() -> dict:
    """The foreign predicates of the paper's and the discovering curiosity's
    planes (bridge/exploration/curiosity_sides.py): by name, the timing
    they count towards and the handler."""
    return {"exploration_steepest_plane": ("planes", steepest_plane_request),
            "exploration_significant_planes": ("planes", significant_planes_request)}


def steepest_plane_request(host: Host, request: dict) -> dict:
    return steepest_plane(host.need_session(), request)


def significant_planes_request(host: Host, request: dict) -> dict:
    return significant_planes(host.need_session(), request)


def steepest_plane(s: Session, request: dict) -> dict:
    """The steepest plane of the explored antecedents (the paper's), their
    planes fitted with L2 penalty `ridge`."""
    entries = request["antecedents"]
    ridge = float(request["ridge"])
    W = s.weight_matrix(entries)
    valid = s.valid
    X = normalise(s.params[valid])
    S = s.scores[valid]
    best: tuple[float, int, int, Planes, np.ndarray] | None = None
    for i, e in enumerate(entries):
        planes = s.planes_of(str(e["id"]), X, S, W[i], ridge)
        if planes is None:
            continue
        slope = best_abs_slope(planes)
        if best is None or slope.slope > best[0]:
            best = (slope.slope, i, slope.expectation, planes, slope.gradient)
    names = load_vocabulary().parameter_names
    expectations = load_vocabulary().expectation_names
    if best is None:
        return {"antecedent": str(entries[-1]["id"]), "expectation": expectations[0],
                "slope": 0.0, "mean": 0.5, "gradient": {n: 0.0 for n in names}}
    slope, i, k, planes, gradient = best
    return {"antecedent": str(entries[i]["id"]), "expectation": expectations[k],
            "slope": float(slope), "mean": float(planes.mean[k]),
            "gradient": {n: float(g) for n, g in zip(names, gradient)}}


def significant_planes(s: Session, request: dict) -> dict:
    """The discovering curiosity's planes (see the module's text): every
    antecedent with a significant plane, followed, and the first of them."""
    entries = request["antecedents"]
    alpha = float(request["significance"])
    ridge, permutations, seed = float(request["ridge"]), int(request["permutations"]), int(request["seed"])
    W = s.weight_matrix(entries)
    valid = s.valid
    X = normalise(s.params[valid])
    S = s.scores[valid]
    names, expectations = load_vocabulary().parameter_names, load_vocabulary().expectation_names
    found: list[tuple[float, int, Tested]] = []
    for i, e in enumerate(entries):
        tested = s.tested_of(i + 1, str(e["id"]), X, S, W[i], ridge, permutations, seed)
        if tested is None:
            continue
        slope = float(tested.slopes(alpha).max())
        if slope > 0:
            found.append((-slope, i, tested))
    if not found:
        return {"antecedent": str(entries[-1]["id"]), "significant": False,
                "expectation": expectations[0], "slope": 0.0, "mean": 0.5,
                "gradient": {n: 0.0 for n in names}, "directions": [], "followed": []}
    found.sort(key=lambda f: (f[0], f[1]))
    followed = [{"antecedent": str(entries[i]["id"]), "directions": _directions(tested, alpha)}
                for _, i, tested in found]
    _, i, tested = found[0]
    sig = tested.significant(alpha)
    first = followed[0]["directions"][0]
    k = expectations.index(first["expectation"])
    return {"antecedent": str(entries[i]["id"]), "significant": True,
            "expectation": first["expectation"], "slope": first["slope"],
            "mean": first["mean"],
            "gradient": {n: float(g) if sig[k, j] else 0.0
                         for j, (n, g) in enumerate(zip(names, tested.coef[k]))},
            "directions": followed[0]["directions"], "followed": followed}


def _directions(tested: Tested, alpha: float) -> list[dict]:
    """An antecedent's significant planes, steepest first, each with the
    moves along its significant parameters (`_moves`)."""
    expectations = load_vocabulary().expectation_names
    slopes = tested.slopes(alpha)
    directions = []
    for k in np.argsort(-slopes, kind="stable"):
        if slopes[k] <= 0:
            continue
        directions.append({"expectation": expectations[k], "slope": float(slopes[k]),
                           "mean": float(tested.mean[k]), "moves": _moves(tested, alpha, k)})
    return directions


def _moves(tested: Tested, alpha: float, k: int) -> list[dict]:
    """Plane k's significant parameters, largest component first, each with
    the antecedent's mean value and the value past which the plane through
    that mean crosses the verdict threshold (theory units), and the
    component's p-value."""
    vocab = load_vocabulary()
    half = float(defaults()["verdict_threshold"])
    names = vocab.parameter_names
    lo = np.array([p.low for p in vocab.parameters], dtype=float)
    hi = np.array([p.high for p in vocab.parameters], dtype=float)
    sig = tested.significant(alpha)
    m = float(tested.mean[k])
    moves = []
    for j in np.argsort(-np.abs(np.where(sig[k], tested.coef[k], 0.0)), kind="stable"):
        if not sig[k, j]:
            break
        g = float(tested.coef[k, j])
        # the plane through the antecedent's mean crosses the threshold along j here
        flip = float(tested.centre[j]) + (half - m) / g
        moves.append({"parameter": names[j], "component": g,
                      "sign": "up" if (half - m) / g > 0 else "down",
                      "mean": float(lo[j] + tested.centre[j] * (hi[j] - lo[j])),
                      "flip": float(lo[j] + flip * (hi[j] - lo[j])),
                      "p": float(tested.p[k, j])})
    return moves
