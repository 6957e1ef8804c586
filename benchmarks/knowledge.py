"""What the curiosity's pours teach: the general rules learned from an
exploration's pours against those learned from the pours of random valid
antecedents at the same budget, on the questions a person would type
(bridge/evaluation/questions.json, 20 pours each, seed 1, as `pantarhei
evaluate` draws them), and how far theories of several seeds agree.

    pantarhei explore --seed 101 --out runs/s101.pl
    pantarhei explore --seed 102 --out runs/s102.pl
    python -m benchmarks.knowledge runs/s101.pl runs/s102.pl

For each theory (its exploration's seed S): coverage and accuracy on the
clear keys, accuracy on the contrast keys (the clear keys where the
defaults-only theory is wrong) and calibration, for the general rules of
its pours and of random valid antecedents' pours (seed S, the same number
of batches), each with the learner's own pours (bridge/learning/gaps.py);
then the medians with their range; then, for each pair of theories as
written, the share of the question decisions both make on which they
agree. Every pour goes through the store (pantarhei.sqlite).
"""
from __future__ import annotations

import itertools
import sys
from pathlib import Path

import numpy as np


def measure(paths: list[str]) -> tuple[list[dict], dict[tuple[str, str], float]]:
    from pantarhei.bridge.evaluation import pipeline as E
    from pantarhei.bridge.evaluation.measures import (contrast_keys, defaults_only,
                                                      question_key, question_measures,
                                                      question_shares, verdicts)
    from pantarhei.bridge.evaluation.questions import question_pours, questions
    from pantarhei.bridge.evaluation.rule_building import answer_matrix
    from pantarhei.bridge.exploration.simulation import open_simulator
    from pantarhei.bridge.learning.layers import learn_general
    from pantarhei.bridge.theories.loading import load
    from pantarhei.oracle.store import DEFAULT_STORE
    from pantarhei.theory.lexicon import load_vocabulary

    names = load_vocabulary().expectation_names
    asked = questions()
    scenes = [q.antecedent for q in asked]
    first = E.read_learned(paths[0])
    sim = open_simulator(str(first.setting("oracle", "pybullet")), "local", None,
                         Path(DEFAULT_STORE).absolute())
    rows, decisions = [], {}
    try:
        ev = E.Evaluation(theory="", oracle="", settings={}, budget=0)
        run = E.Simulations(sim, ev, progress=False)
        P_q, of = question_pours(asked, 1)
        S_q = run("questions", P_q, say=False)
        ok = np.all(np.isfinite(S_q), axis=1)
        key, clear = question_key(S_q[ok], of[ok], len(asked))
        share = question_shares(S_q[ok], of[ok], len(asked))
        V, of_ok = verdicts(S_q[ok]), of[ok]
        for path in paths:
            learned = E.read_learned(path)
            seed, samples = int(learned.setting("seed")), int(learned.setting("batch"))
            P, _, _, _ = E.exploration_draws(learned)
            S = run("exploration", P, say=False)
            batches = max(1, round(len(P) / samples))
            rnd = E.random_exploration_pours(seed, batches, samples, run)
            row = {"theory": path, "seed": seed}
            contrast = None
            for method, (Pm, Sm) in (("curiosity", (P, S)), ("random", (rnd.P, rnd.S))):
                okm = np.all(np.isfinite(Sm), axis=1)
                g, Pg, Sg = learn_general(Pm[okm], Sm[okm], seed,
                                          lambda X: run("own", X, say=False))
                if contrast is None:
                    contrast = contrast_keys(key, clear, defaults_only(verdicts(Sg), len(asked))[0])
                lik = np.array([[g.answer(q)[e][1] for e in names] for q in scenes])
                row[method] = question_measures(g.predict(scenes), lik, share, key, clear,
                                                contrast, V, of_ok)
            rows.append(row)
            decisions[path] = answer_matrix(load([path]), scenes)[0]
    finally:
        sim.close()
    agree = {}
    for a, b in itertools.combinations(paths, 2):
        both = (decisions[a] != -1) & (decisions[b] != -1)
        agree[(a, b)] = float((decisions[a] == decisions[b])[both].mean()) if both.any() else float("nan")
    return rows, agree


def _spread(values: list[float]) -> str:
    v = [x for x in values if x is not None]
    if not v:
        return "n/a"
    return f"{np.median(v):.3f} [{min(v):.3f}-{max(v):.3f}]"


def main(argv: list[str] | None = None) -> None:
    paths = list(sys.argv[1:] if argv is None else argv)
    if not paths:
        raise SystemExit("give one or more theories written by pantarhei explore")
    rows, agree = measure(paths)
    keys = ("coverage", "accuracy", "contrast_accuracy", "calibration", "coherent")
    print("theory  seed  pours  " + "  ".join(keys))
    for r in rows:
        for method in ("curiosity", "random"):
            q = r[method]
            print(f"{r['theory']}  {r['seed']}  {method:9}  "
                  + "  ".join(f"{q[k]:.3f}" if q[k] is not None else "n/a" for k in keys)
                  + f"  (contrast keys {q['contrast']})")
    for method in ("curiosity", "random"):
        print(f"median [range], {method}: "
              + ", ".join(f"{k} {_spread([r[method][k] for r in rows])}" for k in keys))
    for (a, b), s in agree.items():
        print(f"{a} / {b}: agree on {100 * s:.1f}% of the question decisions both make")


if __name__ == "__main__":
    main()
