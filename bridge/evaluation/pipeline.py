"""`pantarhei evaluate`: a learned theory against the oracle it was learned
from, on scenes exploration never explored.

Everything is simulated by the same oracle, through the same store, so a
second run simulates nothing:

* the exploration's own simulations, drawn again as its trace's draws
  record them (all found in the store when it is the same store);
* held-out scenes: random valid antecedents, one pour each, in three sets:
  `uniform` (uniformly random valid antecedents), `near` (an explored
  antecedent with one or two propositions added: where the theory speaks)
  and `near_random` (the same around the random exploration's antecedents);
* random exploration: the same budget spent on uniformly random valid
  antecedents, and the same rule building (equation (1) and qualify);
* the general theory asked the questions a person would type
  (general_answers.py);
* the paper's three example rules, asked of the theory and simulated
  (paper_rules.py);
* plans for goal sets a user would ask, verified and measured on fresh
  pours (plan_checks.py).

This module draws the pours every measure reads (the exploration's and
random exploration's, and the held-out scenes) and runs each measure's
stage in the order of `registry.MEASURES`, through one simulator; what the
theory says of its exploration, and its pours, are explored_pours.py's.
The numbers go into an `Evaluation` (and JSON);
`bridge/evaluation/report.py` writes them up.
"""
from __future__ import annotations

import sys
import time
from dataclasses import dataclass, field, fields
from functools import cached_property
from pathlib import Path
from typing import Any, Sequence

import numpy as np

from pantarhei.theory import defaults
from pantarhei.theory.lexicon import load_vocabulary

from pantarhei.bridge.errors import UserError
from pantarhei.bridge.evaluation.explored_pours import Learned, exploration_draws, read_learned
from pantarhei.bridge.evaluation.heldout import (near_antecedents, random_exploration, scene_pours,
                                                 simulated, uniform_scenes)
from pantarhei.bridge.evaluation.rule_building import consequents, rule_ids
from pantarhei.bridge.exploration.weights import log_densities, weights
from pantarhei.bridge.theories.model import Theory

# -- the run -------------------------------------------------------------------

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


@dataclass
class Evaluation:
    """Every figure of an evaluation, JSON-ready (`as_dict`)."""
    theory: str
    oracle: str
    settings: dict[str, Any]
    budget: int
    #: Whether the exploration's pours, simulated here, give the theory's rules.
    reproduced: bool = True
    #: Per explored antecedent: the share of its own pours that kept every expectation.
    kept_all: list[float | None] = field(default_factory=list)
    heldout: dict[str, Any] = field(default_factory=dict)
    curves: dict[str, Any] = field(default_factory=dict)
    behaviours: dict[str, int] = field(default_factory=dict)
    #: The general theory (both layers as shipped, and the general rules alone)
    #: against the models, per method's pours: held-out and one-phrase questions.
    general: dict[str, Any] = field(default_factory=dict)
    #: The shipped theory on interaction questions and random scenes (beyond.py).
    beyond: dict[str, Any] = field(default_factory=dict)
    #: Per search method: distinct nine-verdict vectors among its pours, each seen twice.
    behaviours_seen: dict[str, int] = field(default_factory=dict)
    paper_rules: list[dict[str, Any]] = field(default_factory=list)
    plans: list[dict[str, Any]] = field(default_factory=list)
    simulations: dict[str, int] = field(default_factory=dict)
    seconds: dict[str, float] = field(default_factory=dict)
    #: The figures of a measure without a field of its own, by its name
    #: (in the JSON after the plans).
    figures: dict[str, Any] = field(default_factory=dict)
    #: Not in the JSON: what the report draws from.
    explored: list[tuple[str, ...]] = field(default_factory=list, repr=False)
    explored_consequents: np.ndarray | None = field(default=None, repr=False)
    best_samples: list[np.ndarray] = field(default_factory=list, repr=False)

    def as_dict(self) -> dict[str, Any]:
        return {**{k: getattr(self, k) for k in
                   ("theory", "oracle", "settings", "budget", "reproduced", "kept_all", "heldout",
                    "curves", "behaviours", "behaviours_seen", "general", "beyond", "paper_rules",
                    "plans")},
                **self.figures, "simulations": self.simulations, "seconds": self.seconds}

    @classmethod
    def from_dict(cls, d: dict[str, Any]) -> Evaluation:
        """An evaluation from its `as_dict`."""
        own = {f.name for f in fields(cls)}
        return cls(**{k: v for k, v in d.items() if k in own},
                   figures={k: v for k, v in d.items() if k not in own})

    @property
    def plan_rate(self) -> float | None:
        """The share of the plans' pours that met their goals (None: none simulated)."""
        met = sum(p["met"] for p in self.plans if "met" in p)
        done = sum(p["simulated"] for p in self.plans if "simulated" in p)
        return met / done if done else None


def _shown(path: Path) -> str:
    """A path as the report shows it: relative to here when inside it."""
    try:
        return str(Path(path).resolve().relative_to(Path.cwd().resolve()))
    except ValueError:
        return str(path)


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


def evaluate(opts: EvaluationOptions) -> Evaluation:
    """The pours every measure reads, then every measure's stage in
    order, through one simulator."""
    # the measures' modules read this module's types: imported when run
    from pantarhei.bridge.evaluation import registry

    learned = read_learned(opts.theory)
    if opts.scenes < 1 or opts.verify < 0 or opts.paper_samples < 0:
        raise UserError("--scenes must be at least 1, --verify and --paper-samples at least 0")
    oracle = str(learned.setting("oracle", defaults()["oracle"]))
    samples = int(learned.setting("batch"))
    ev = Evaluation(theory=_shown(opts.theory), oracle=oracle,
                    settings={k: (v if len(v) > 1 else v[0]) for k, v in learned.settings.items()},
                    budget=0, explored=list(learned.antecedents))
    from pantarhei.bridge.exploration.simulation import open_simulator, oracle_identity

    version, _ = oracle_identity(oracle)
    if str(learned.setting("oracle_version", version)) != version:
        tell(f"the theory was learned with {oracle} version {learned.setting('oracle_version')}, "
            f"the oracle here is version {version}: its simulations are not reused")
    sim = open_simulator(oracle, opts.executor, opts.workers, opts.store, opts.ray_address)
    try:
        run = Simulations(sim, ev, opts.progress)
        curiosity = exploration_pours(learned, run, ev)
        # the same budget: as many pours as the exploration's (probes too), in whole batches
        ev.budget = max(1, round(len(curiosity.P) / samples)) * samples
        rnd = random_exploration_pours(opts.seed, ev.budget // samples, samples, run)
        inputs = Inputs(opts, learned, run, {"curiosity": curiosity, "random": rnd}, samples)
        for measure in registry.MEASURES:
            measure.stage(ev, inputs)
    finally:
        sim.close()
    return ev


def exploration_pours(learned: Learned, run: Simulations, ev: Evaluation) -> Pours:
    """The exploration's simulations, drawn again from its trace, and
    whether they give the theory's rules."""
    explored = learned.antecedents
    P, drawn, of, ends = exploration_draws(learned)
    S = run("exploration", P)
    ev.explored_consequents = consequents(explored, P, S, learned.qualify)
    ok = np.all(np.isfinite(S), axis=1)
    W = weights(log_densities(P[ok], [list(a) for a in explored]))
    ev.best_samples = [P[ok][int(np.argmax(W[i]))] for i in range(len(explored))]
    differ = (_differing_layer(learned, P, S) if learned.one_layer
              else _differing_rules(learned.theory, ev.explored_consequents))
    ev.reproduced = not differ
    if differ:
        tell(f"{len(differ)} rules of the theory differ from those its own pours give here "
             f"(first: {differ[0]}): another oracle build, or a theory edited by hand")
    return Pours(list(explored), P, S, [int(e) for e in ends], drawn, of)


def random_exploration_pours(seed: int, count: int, samples: int, run: Simulations) -> Pours:
    """The baseline: the same budget spent on uniformly random valid
    antecedents, `samples` pours each."""
    ants, P = random_exploration(seed, count, samples)
    return Pours(ants, P, run("random exploration", P))


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


def _differing_layer(learned: Learned, P: np.ndarray, S: np.ndarray) -> list[str]:
    """The rules of the learning curiosity's theory that the rules learned
    again from the exploration's pours (over its explored antecedents, by
    the learner the theory names) do not give, with the same head, body
    and likelihood, or the reverse."""
    from pantarhei.bridge.learning.layers import learn_general

    ok = np.all(np.isfinite(S), axis=1)
    g, _, _ = learn_general(P[ok], S[ok], int(learned.setting("seed")),
                            bodies=learned.antecedents, learner=learned.learner)
    conf = learned.theory.confidences()
    have = {(r.id, r.head, tuple(sorted(r.body)), conf.get(r.id)) for r in learned.theory.rules}
    again = {(r.id, r.head, tuple(sorted(r.body)), int(round(1000 * r.confidence)))
             for r in g.rules}
    return sorted(x[0] for x in have ^ again)


def _differing_rules(theory: Theory, heads: np.ndarray) -> list[str]:
    """The learned rules rI_E whose head is not the consequent rebuilt from
    the exploration's pours (none when the theory is reproduced)."""
    names = load_vocabulary().expectation_names
    have = {r.id: r.head for r in theory.rules}
    out = []
    for row, ids in zip(heads, rule_ids(len(heads))):
        for e, holds, rid in zip(names, row, ids):
            if have.get(rid) != (e if holds else f"neg({e})"):
                out.append(rid)
    return out
