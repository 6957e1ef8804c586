"""Generalization: the general theory against the oracle, on pours of the
real PyBullet oracle.

Training pours are the random baseline's exploration at the exploration's
budget (25 uniformly random valid antecedents x 31 pours, exactly as
`pantarhei evaluate` draws them); held-out are 150 other uniformly random
valid antecedents, one pour each; the questions are the one-phrase questions
of `bridge/evaluation/questions.json`, 20 pours each, whose majority is the
key (clear where at least 75% agree). Every pour is kept in the store
(`generalization.sqlite` here), so a second run simulates nothing.

Measured: held-out coverage and accuracy of the general theory beside a
decision tree and gradient boosting trained on the same pours with the same
features (the pours' descriptions, one-hot); coverage and accuracy of the
questions; rules per expectation; the time to generalize 10,000 pours
(synthetic oracle, no simulation) and agreement with SWI-Prolog.
"""
from __future__ import annotations

import json
import time
from dataclasses import dataclass
from pathlib import Path

import numpy as np

HERE = Path(__file__).resolve().parent
STORE = HERE.parent / "generalization.sqlite"
WORKERS = 2
ANTECEDENTS, SAMPLES = 25, 31        # the exploration's budget: 775 pours
SCENES = 150
SEED = 1


@dataclass
class Pours:
    """Pours drawn for a list of antecedents: `of[i]` is the antecedent the
    i-th pour was sampled for."""
    antecedents: list[tuple[str, ...]]
    of: np.ndarray
    P: np.ndarray
    S: np.ndarray


def draw(seed: int = SEED) -> dict[str, Pours]:
    """The parameterizations of the three sets (nothing simulated yet)."""
    from pantarhei.bridge.evaluation.heldout import random_exploration, scene_pours, uniform_scenes
    from pantarhei.bridge.evaluation.questions import question_pours, questions

    train_ants, P_train = random_exploration(seed, ANTECEDENTS, SAMPLES)
    scenes = uniform_scenes(seed, SCENES, set(train_ants))
    asked = questions()
    P_q, of = question_pours(asked, seed)
    empty = np.empty((0, 9))
    return {
        "train": Pours(train_ants, np.repeat(np.arange(ANTECEDENTS), SAMPLES), P_train, empty),
        "heldout": Pours(scenes, np.arange(len(scenes)), scene_pours(scenes, seed), empty),
        "questions": Pours([q.antecedent for q in asked], of, P_q, empty),
    }


def simulate(sets: dict[str, Pours], store: Path = STORE, workers: int = WORKERS,
             progress: bool = True) -> dict[str, Pours]:
    """Score every pour with PyBullet through the store; failed pours dropped."""
    from pantarhei.bridge.exploration.simulation import open_simulator
    from pantarhei.oracle.physics import PouringOracle

    sim = open_simulator(PouringOracle.name, None, workers, store)
    try:
        for name, s in sets.items():
            S = np.asarray(sim.simulate(s.P, progress=progress), dtype=float)
            ok = np.all(np.isfinite(S), axis=1)
            s.of, s.P, s.S = s.of[ok], s.P[ok], S[ok]
    finally:
        sim.close()
    return sets


def in_prior_support(P: np.ndarray, bodies) -> list[int]:
    """How many pours lie in the support of P(.|B) for each body B: the
    pours importance weights P(p|B)/q(p) could count at all."""
    from pantarhei.oracle.generative import in_support

    return [int(in_support(P, list(b)).sum()) for b in bodies]


def speed(n: int = 10_000, seed: int = SEED) -> tuple[int, float]:
    """Seconds to generalize about n pours of random valid antecedents
    (synthetic oracle: no simulation in the time)."""
    from pantarhei.bridge.evaluation.heldout import random_exploration
    from pantarhei.bridge.learning.generalize import Settings, generalize
    from pantarhei.oracle.simulator import make_simulator

    _, P = random_exploration(seed, -(-n // SAMPLES), SAMPLES)
    P = P[:n]
    sim = make_simulator("synthetic", executor="inline", store=None)
    try:
        S = np.asarray(sim.simulate(P), dtype=float)
    finally:
        sim.close()
    t = time.perf_counter()
    generalize(P, S, Settings(seed=seed))
    return len(P), time.perf_counter() - t


def scored(sets: dict[str, Pours], oracle: str, store: Path | None) -> dict[str, Pours]:
    """Every set scored: by PyBullet through the store, or by another
    oracle inline without one."""
    from pantarhei.oracle.base import REAL_ORACLES

    if oracle in REAL_ORACLES:
        return simulate(sets, store)
    from pantarhei.oracle.simulator import make_simulator

    sim = make_simulator(oracle, executor="inline", store=None)
    for s in sets.values():
        s.S = np.asarray(sim.simulate(s.P), dtype=float)
    sim.close()
    return sets


def run(oracle: str | None = None, store: Path | None = STORE, seed: int = SEED,
        prolog_sample: int = 60) -> dict:
    from pantarhei.bridge.evaluation.measures import question_key
    from pantarhei.bridge.verdicts import verdicts
    from pantarhei.bridge.evaluation.rule_building import predict
    from pantarhei.bridge.learning.generalize import Settings, generalize
    from pantarhei.oracle.generative import describe
    from pantarhei.theory import defaults

    oracle = str(defaults()["oracle"]) if oracle is None else oracle
    sets = scored(draw(seed), oracle, store)
    tr, ho, qs = sets["train"], sets["heldout"], sets["questions"]
    report: dict = {"oracle": oracle, "pours": {k: len(v.P) for k, v in sets.items()}}
    y_held = verdicts(ho.S)
    held = {"antecedent": [ho.antecedents[i] for i in ho.of], "description": describe(ho.P)}
    key, clear = question_key(qs.S, qs.of, len(qs.antecedents))
    report["questions_clear"] = int(clear.sum())
    t = time.perf_counter()
    general = generalize(tr.P, tr.S, Settings(seed=seed))
    report["general"] = _measured(general, time.perf_counter() - t, held, y_held,
                                  qs.antecedents, key, clear)
    report.update(_against_defaults(general, held["antecedent"], y_held, qs.antecedents, key, clear))
    report.update(_models(describe(tr.P), verdicts(tr.S), held, y_held, qs.antecedents, key, clear, seed))
    report["by_question"] = _by_question(general, qs.antecedents, key, clear)
    # importance weights: the explored pours in the support of P(.|B)
    report["pours_in_prior_support"] = dict(zip(
        ["(none)"] + [" ".join(b) for b in qs.antecedents[:5]],
        in_prior_support(tr.P, [()] + qs.antecedents[:5])))
    # SWI-Prolog decides as the learner says
    scenes = held["antecedent"][:prolog_sample // 2] + qs.antecedents[:prolog_sample // 2]
    agree = (predict(general.theory("general"), scenes) == general.predict(scenes)).mean()
    report["prolog_agreement"] = float(agree)
    report["rules"] = [{"id": r.id, "body": list(r.body), "head": r.head, "support": r.support,
                        "kept": r.kept, "confidence": round(r.confidence, 3), "level": r.level}
                       for r in general.rules]
    return report


def _measured(g, secs: float, held: dict, y_held: np.ndarray, asked: list,
              key: np.ndarray, clear: np.ndarray) -> dict:
    """A general theory's rules, and its held-out and question scores."""
    from pantarhei.bridge.evaluation.measures import accuracy, question_scores
    from pantarhei.theory.lexicon import load_vocabulary

    names = load_vocabulary().expectation_names
    r: dict = {"seconds": round(secs, 1),
               "rules_per_expectation": len(g.rules) / len(names),
               "rules": {e: len(g.of(e)) for e in names}}
    for label, scenes in held.items():
        a = accuracy(g.predict(scenes), y_held)
        r[f"heldout_{label}"] = {"coverage": a.overall_coverage, "accuracy": a.overall_accuracy}
    r["questions"] = question_scores(g.predict(asked), key, clear)
    return r


def _against_defaults(g, held_scenes: list, y_held: np.ndarray, asked: list,
                      key: np.ndarray, clear: np.ndarray) -> dict:
    """What the defaults alone would say (how much the exceptions add),
    and the clear verdicts of the questions that the defaults get wrong."""
    from pantarhei.bridge.evaluation.measures import accuracy, question_scores

    defaults = type(g)(rules=[x for x in g.rules if not x.body])
    hard = clear & (defaults.predict(asked) != key)
    return {"defaults_only": {
                "heldout_antecedent": accuracy(defaults.predict(held_scenes), y_held).overall_accuracy,
                "questions": question_scores(defaults.predict(asked), key, clear)["accuracy"]},
            "questions_against_the_default": {
                "cases": int(hard.sum()),
                "right": int(((g.predict(asked) == key) & hard).sum())}}


def _models(train_desc, Y: np.ndarray, held: dict, y_held: np.ndarray, asked: list,
            key: np.ndarray, clear: np.ndarray, seed: int) -> dict:
    """The decision tree and gradient boosting, trained on the same pours
    with the same features, on the held-out scenes and the questions."""
    from pantarhei.bridge.evaluation.measures import accuracy, model_predictions, question_scores

    out: dict = {}
    for label, scenes in held.items():
        for name, pred in model_predictions(train_desc, Y, scenes, seed).items():
            a = accuracy(pred, y_held)
            out[f"{name}_{label}"] = {"coverage": a.overall_coverage, "accuracy": a.overall_accuracy}
    for name, pred in model_predictions(train_desc, Y, asked, seed).items():
        out[f"{name}_questions"] = question_scores(pred, key, clear)
    return out


def _by_question(general, asked: list, key: np.ndarray, clear: np.ndarray) -> list[dict]:
    """The questions one by one, as the general theory answers them: the
    clear verdicts it decides wrongly."""
    from pantarhei.bridge.evaluation.questions import questions
    from pantarhei.theory.lexicon import load_vocabulary

    names = load_vocabulary().expectation_names
    pred = general.predict(asked)
    return [{"text": q.text, "wrong": [names[k] for k in range(len(names))
                                       if clear[i, k] and pred[i, k] != -1 and pred[i, k] != key[i, k]]}
            for i, q in enumerate(questions())]


def answer_time(repeats: int = 3) -> dict:
    """Milliseconds SWI-Prolog's what_happens/3 takes on the shipped theory
    (both layers), per one-phrase question: the median and the slowest, over every
    question asked `repeats` times (the theory loaded once)."""
    import statistics

    from pantarhei.bridge.reasoning.logic import prolog_load
    from pantarhei.bridge.theories.loading import load

    theory = load()
    from pantarhei.bridge.evaluation.questions import questions

    asked = [q.antecedent for q in questions()]
    e = prolog_load(theory)
    e.use_module("queries")
    times = []
    for _ in range(repeats):
        for a in asked:
            t = time.perf_counter()
            e.once("queries:what_happens(Scene, [], _)", Scene=list(a))
            times.append(1000 * (time.perf_counter() - t))
    return {"rules": len(theory.rules), "sup": len(theory.sup),
            "median_ms": round(statistics.median(times), 2), "max_ms": round(max(times), 2)}


def main() -> None:
    report = run()
    n, secs = speed()
    report["speed"] = {"pours": n, "seconds": round(secs, 1)}
    report["what_happens_on_the_shipped_theory"] = answer_time()
    rules = report.pop("rules")
    print(json.dumps(report, indent=1))
    print(f"{len(rules)} general rules; the first 20:")
    for r in rules[:20]:
        print(f"  {r['id']}: {' & '.join(r['body']) or '(default)'} => {r['head']} "
              f"({r['kept']} of {r['support']} pours, confidence {r['confidence']})")
