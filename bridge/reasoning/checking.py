"""An answer checked against the simulation: `pantarhei ask --check N`.

The question's propositions are sampled N times, seeded, as `pantarhei
simulate --antecedent Q` samples them (whatever the question leaves unsaid
follows the priors: the ordinary pour), and simulated through the store
with the oracle the theory was learned from. Each expectation's observed
share is the share of the pours simulated whose score exceeds one half;
an answer the pours contradict is flagged (`contradicts`)."""
from __future__ import annotations

from dataclasses import dataclass
from typing import Callable, Sequence

import numpy as np


@dataclass(frozen=True)
class Observed:
    """What the pours of a question did for one expectation: it held in
    `held` of `simulated` pours (the failed ones left out)."""
    held: int
    simulated: int

    @property
    def share(self) -> float | None:
        return self.held / self.simulated if self.simulated else None

    def as_json(self) -> dict:
        return {"held": self.held, "simulated": self.simulated, "share": self.share}


def observe(scene: Sequence[str], n: int, seed: int,
            simulate: Callable[[np.ndarray], np.ndarray]) -> dict[str, Observed]:
    """Per expectation (the vocabulary's order), what `n` pours sampled for
    the scene with `seed` did (`simulate`: parameterizations to scores,
    NaN rows for failures)."""
    from pantarhei.bridge.verdicts import verdicts
    from pantarhei.oracle.generative import sample
    from pantarhei.theory.lexicon import load_vocabulary

    S = np.atleast_2d(np.asarray(simulate(sample(list(scene), n, seed)), dtype=float))
    done = np.all(np.isfinite(S), axis=1)
    held = verdicts(S[done]).sum(axis=0) if done.any() else np.zeros(S.shape[1], dtype=int)
    names = load_vocabulary().expectation_names
    return {e: Observed(int(held[k]), int(done.sum())) for k, e in enumerate(names)}


def contradicts(verdict: str, observed: Observed) -> bool:
    """Do the pours contradict an answer? A `holds` (yes) where at most half
    of them held, a `fails` (no) where more than half held, an `uncertain`
    (maybe: such pours split) where all of them went one way; never an
    `unknown` (the theory says nothing), nor with no pour simulated."""
    share = observed.share
    if share is None:
        return False
    if verdict == "holds":
        return share <= 0.5
    if verdict == "fails":
        return share > 0.5
    if verdict == "uncertain":
        return observed.held in (0, observed.simulated) and observed.simulated > 1
    return False


def checking_oracle(files: Sequence[str]) -> str:
    """The oracle a theory's answers are checked with: the one it was
    learned from (the first `setting(oracle, O)` of its native files),
    the default oracle (theory/defaults.pl) otherwise."""
    import re

    from pantarhei.bridge.files import is_dfl
    from pantarhei.theory import defaults

    pattern = re.compile(r"^setting\(\s*oracle\s*,\s*([a-z][A-Za-z0-9_]*)\s*\)\s*\.", re.M)
    for path in files:
        if is_dfl(path):
            continue
        try:
            with open(path, encoding="utf-8", errors="replace") as f:
                m = pattern.search(f.read())
        except OSError:
            continue
        if m:
            return m.group(1)
    return str(defaults()["oracle"])
