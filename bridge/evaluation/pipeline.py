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
theory says of its exploration, and its pours, are explored_pours.py's;
what a stage is given is inputs.py's (`Inputs`). The numbers go into an
`Evaluation` (figures.py, and JSON); `bridge/evaluation/report.py` writes
them up.
"""
from __future__ import annotations

from pathlib import Path

import numpy as np

from pantarhei.theory import defaults
from pantarhei.theory.lexicon import load_vocabulary

from pantarhei.bridge.errors import UserError
from pantarhei.bridge.evaluation import registry
from pantarhei.bridge.evaluation.explored_pours import Learned, exploration_draws, read_learned
from pantarhei.bridge.evaluation.figures import Evaluation
from pantarhei.bridge.evaluation.heldout import random_exploration
from pantarhei.bridge.evaluation.inputs import EvaluationOptions, Inputs, Pours, Simulations, tell
from pantarhei.bridge.evaluation.rule_building import consequents, rule_ids
from pantarhei.bridge.exploration.weights import log_densities, weights
from pantarhei.bridge.theories.model import Theory


# -- the run -------------------------------------------------------------------

def _shown(path: Path) -> str:
    """A path as the report shows it: relative to here when inside it."""
    try:
        return str(Path(path).resolve().relative_to(Path.cwd().resolve()))
    except ValueError:
        return str(path)


def evaluate(opts: EvaluationOptions) -> Evaluation:
    """The pours every measure reads, then every measure's stage in
    order, through one simulator."""
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


def _differing_layer(learned: Learned, P: np.ndarray, S: np.ndarray) -> list[str]:
    """The rules of the learning curiosity's theory that the rules learned
    again from the exploration's pours (over its explored antecedents but
    the wholes, by the learner the theory names) do not give, with the
    same head, body and likelihood, or the reverse."""
    from pantarhei.bridge.learning.layers import learn_general

    ok = np.all(np.isfinite(S), axis=1)
    g, _, _ = learn_general(P[ok], S[ok], int(learned.setting("seed")),
                            bodies=learned.rule_bodies, learner=learned.learner)
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
