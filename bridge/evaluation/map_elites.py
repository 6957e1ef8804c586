"""The quality-diversity reference: MAP-Elites over the 30 parameters.

pyribs (`ribs`, MIT licence) runs the ask-tell loop: a `CategoricalArchive`
whose cells are the nine verdicts (each expectation holds or not: a
categorical behaviour descriptor of 2^9 cells), and a `GaussianEmitter` over
the 30 parameters normalised to [0, 1] (the parameters' bounds), started
from pours of the prior. A pour's objective is how clearly its verdicts are
decided (the mean of |score - 1/2|), so each cell keeps its clearest pour.
It spends the same pour budget as the exploration, in batches of the same
size, and knows nothing of propositions or rules.

`behaviours_seen` is the measure shared by every search method: the distinct
nine-verdict vectors among its pours that at least two pours show.
"""
from __future__ import annotations

from dataclasses import dataclass
from typing import Callable

import numpy as np

from pantarhei.bridge.verdicts import verdicts
from pantarhei.bridge.exploration.novelty import shown
from pantarhei.oracle.generative import normalise, sample
from pantarhei.theory import defaults
from pantarhei.theory.lexicon import load_vocabulary

#: The Gaussian emitter's step, in normalised units (a tenth of each range).
SIGMA = 0.1


@dataclass(frozen=True)
class Search:
    """The pours of one search, in the order they were simulated."""
    P: np.ndarray       # (budget, 30), theory units
    S: np.ndarray       # (budget, 9), scores (nan where a simulation failed)
    cells: int          # occupied cells of the archive at the end


def behaviours_seen(S: np.ndarray, at_least: int = 2) -> int:
    """How many distinct nine-verdict vectors (score above 1/2) the pours
    whose simulation did not fail show, each by at least `at_least` pours
    (the behaviours the discovering curiosity counts as seen)."""
    return len(shown(S, at_least))


def denormalise(Z: np.ndarray) -> np.ndarray:
    """Normalised parameters back to theory units (discrete ones rounded)."""
    v = load_vocabulary()
    lo = np.array([p.low for p in v.parameters], dtype=float)
    hi = np.array([p.high for p in v.parameters], dtype=float)
    P = lo + np.clip(Z, 0.0, 1.0) * (hi - lo)
    discrete = np.array([p.discrete for p in v.parameters])
    P[:, discrete] = np.round(P[:, discrete])
    return P


def map_elites(simulate: Callable[[np.ndarray], np.ndarray], budget: int, seed: int,
               batch: int = 31) -> Search:
    """Run MAP-Elites for `budget` pours (the last batch cut to fit):
    `simulate` maps pours (n, 30) in theory units to scores (n, 9)."""
    from ribs.archives import CategoricalArchive
    from ribs.emitters import GaussianEmitter
    from ribs.schedulers import Scheduler

    if budget < 1 or batch < 1:
        raise ValueError("the budget and the batch must be at least 1")
    n_par = len(load_vocabulary().parameters)
    n_exp = len(load_vocabulary().expectations)
    seeds = np.random.SeedSequence([int(seed), 0x6D6170]).generate_state(2)
    archive = CategoricalArchive(solution_dim=n_par, categories=[[False, True]] * n_exp,
                                 seed=int(seeds[0]))
    start = normalise(sample([], batch, seed=int(seeds[1])))
    emitter = GaussianEmitter(archive, sigma=SIGMA, initial_solutions=start,
                              bounds=[(0.0, 1.0)] * n_par, batch_size=batch, seed=int(seeds[1]))
    scheduler = Scheduler(archive, [emitter])
    Ps, Ss = [], []
    done = 0
    while done < budget:
        Z = scheduler.ask()[: budget - done]
        P = denormalise(Z)
        S = np.asarray(simulate(P), dtype=float)
        ok = np.all(np.isfinite(S), axis=1)
        half = float(defaults()["verdict_threshold"])
        clear = np.where(ok, np.abs(np.nan_to_num(S, nan=half) - half).mean(axis=1), -1.0)
        measures = [[bool(x) for x in row] for row in verdicts(np.nan_to_num(S, nan=0.0))]
        if len(Z) < batch:      # the last, short batch: added to the archive directly
            archive.add(Z, clear, measures)
        else:
            scheduler.tell(clear, measures)
        Ps.append(P)
        Ss.append(S)
        done += len(P)
    return Search(np.vstack(Ps), np.vstack(Ss), len(archive))
