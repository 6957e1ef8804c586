"""Coverage: where the pours so far are fewest.

The forest of bridge/exploration/novelty.py only knows where the pours
are, so an exploration ranked by it alone keeps to the corner of the
scene it started in. The last probe of a step (theory/curiosity/probe.pl,
fewest/5, with `--cover` above 0) goes instead to the candidate whose
rarest proposition the fewest pours so far hold: its probe's pours stay
in the pool whether it passes or not, for the forest, the planes and the
general rules, which need `min_support` pours of a proposition to answer
a question about it from its own pours.
"""
from __future__ import annotations

from typing import Sequence

import numpy as np

from pantarhei.oracle.generative import holds


def counts(params: np.ndarray) -> dict[str, int]:
    """For each proposition, the pours (rows of 30 parameters) it holds."""
    names, M = holds(params)
    return dict(zip(names, (int(c) for c in M.sum(axis=0))))


def fewest(params: np.ndarray, candidates: Sequence[Sequence[str]], enough: int) -> int:
    """The index of the candidate whose rarest proposition the fewest pours
    hold (the first of equals), or -1 when every proposition of every
    candidate is held by at least `enough` pours (or there is none)."""
    held = counts(params) if len(params) else {}
    rarest = [min((held.get(str(p), 0) for p in props), default=enough) for props in candidates]
    if not rarest or min(rarest) >= enough:
        return -1
    return int(np.argmin(rarest))
