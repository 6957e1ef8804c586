"""What every measure's stage is given (`Inputs`): the options of the
evaluation, the learned theory, the one simulator every pour goes through
(`Simulations`), the pours of each way of choosing antecedents (`Pours`)
and the held-out scenes, drawn when a stage first asks for them
(`heldout_scenes`). The measures' modules read it, and pipeline.py, which
runs them in the order of registry.MEASURES, fills it."""
from __future__ import annotations

import sys
import time
from dataclasses import dataclass, field
from functools import cached_property
from pathlib import Path
from typing import Any, Sequence

import numpy as np

from pantarhei.theory import defaults
from pantarhei.theory.lexicon import load_vocabulary

from pantarhei.bridge.evaluation.explored_pours import Learned
from pantarhei.bridge.evaluation.figures import Evaluation
from pantarhei.bridge.evaluation.heldout import near_antecedents, scene_pours, simulated, uniform_scenes


@dataclass
class EvaluationOptions:
    theory: Path
    store: Path
    scenes: int = 150
    seed: int = 1
    verify: int = 10
    paper_samples: int = 20
    executor: str = field(default_factory=lambda: str(defaults()["executor"]))
    workers: int | None = None
    ray_address: str | None = None
    progress: bool = True
    #: Also spend the budget on random pours from the prior and on MAP-Elites.
    baselines: bool = True


def tell(text: str) -> None:
    """Tell the user, on stderr, what the evaluation is doing."""
    print(f"pantarhei evaluate: {text}", file=sys.stderr, flush=True)


class Simulations:
    """Every pour of an evaluation goes through one simulator (and so one
    store); each call is a stage whose pours and seconds are recorded."""

    def __init__(self, sim: Any, ev: Evaluation, progress: bool) -> None:
        self.sim, self.ev, self.progress = sim, ev, progress
        self.width = len(load_vocabulary().expectations)

    def __call__(self, label: str, P: np.ndarray, say: bool = True) -> np.ndarray:
        """Simulate P as (part of) the stage `label`: its pours and seconds add up."""
        t = time.monotonic()
        sims, secs = self.ev.simulations, self.ev.seconds
        if not len(P):
            sims.setdefault(label, 0)
            secs.setdefault(label, 0.0)
            return np.empty((0, self.width))
        if say:
            tell(f"{label}: {len(P)} pours")
        S = np.asarray(self.sim.simulate(P, progress=self.progress and say), dtype=float)
        sims[label] = sims.get(label, 0) + int(self.sim.last_simulated)
        secs[label] = round(secs.get(label, 0.0) + time.monotonic() - t, 1)
        return S


@dataclass
class Pours:
    """The pours of one way of choosing antecedents: the antecedents in
    order, their pours in that order, and their scores. `ends[k]` is the
    number of pours of the first k + 1 antecedents (`samples` each unless
    an antecedent had more batches)."""
    antecedents: list[tuple[str, ...]]
    P: np.ndarray
    S: np.ndarray
    ends: list[int] = field(default_factory=list)
    #: The antecedent each pour was drawn from (a candidate set aside after
    #: its probe is none of `antecedents`).
    drawn: list[tuple[str, ...]] = field(default_factory=list)
    #: The index in `antecedents` of the antecedent each pour belongs to
    #: (-1 for a probe of a candidate set aside): the exploration's.
    of: np.ndarray | None = None

    def __post_init__(self) -> None:
        if not self.ends and self.antecedents:
            each = len(self.P) // len(self.antecedents)
            self.ends = [each * (k + 1) for k in range(len(self.antecedents))]
        if not self.drawn:
            self.drawn = [a for a, n in zip(self.antecedents, np.diff([0, *self.ends]))
                          for _ in range(int(n))]

    def upto(self, pours: int) -> int:
        """How many antecedents have all their pours among the first `pours`."""
        return sum(1 for e in self.ends if e <= pours)


@dataclass
class Inputs:
    """What every measure's stage is given: the options, the learned
    theory, the simulator (`run`), the pours of each way of choosing
    antecedents at the same budget (`methods`: curiosity's, then random
    exploration's; `samples` pours a batch) and the held-out scenes
    (`held`, simulated when a stage first asks for them)."""
    opts: EvaluationOptions
    learned: Learned
    run: Simulations
    methods: dict[str, Pours]
    samples: int

    @cached_property
    def held(self) -> dict[str, tuple[list[tuple[str, ...]], np.ndarray]]:
        """The three sets of held-out scenes (`heldout_scenes`)."""
        return heldout_scenes(self.opts, self.methods["curiosity"].antecedents,
                              self.methods["random"].antecedents, self.run)


def heldout_scenes(opts: EvaluationOptions, explored: Sequence[tuple[str, ...]],
                   random_ants: Sequence[tuple[str, ...]], run: Simulations
                   ) -> dict[str, tuple[list[tuple[str, ...]], np.ndarray]]:
    """Three sets of held-out scenes, one pour each, never explored by
    either method: per set, the scenes whose pour did not fail and their
    verdicts."""
    known = set(explored) | set(random_ants)
    uniform = uniform_scenes(opts.seed, opts.scenes, known)
    near = near_antecedents(explored, opts.scenes, opts.seed, known | set(uniform))
    near_random = near_antecedents(random_ants, opts.scenes, opts.seed + 1,
                                   known | set(uniform) | set(near))
    held = {}
    for name, scenes in {"uniform": uniform, "near": near, "near_random": near_random}.items():
        held[name] = simulated(scenes, run(f"held-out ({name})", scene_pours(scenes, opts.seed)))
    return held
