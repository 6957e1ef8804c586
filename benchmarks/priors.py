"""Where the questions are asked: how well the general rules' model of an
exploration's pours knows the scene where nothing is said (every parameter
from its prior, as the parameters a question leaves unsaid are), and how
the theory answers the one-phrase questions.

    pantarhei explore --curiosity discover --seed 2 --out runs/prior2.pl
    python -m benchmarks.priors theory/learned/pouring.pl runs/prior2.pl

For each learned theory: its explored antecedents and their distinct
consequents, the behaviours its pours show; the model of its pours
(bridge/learning/meaning.py, `Meaning`) against `--pours` pours drawn
from the priors (seeded, simulated by the theory's oracle through the
store): the mean over the nine expectations of the gap between the share
of those pours that keep it and the share the model expects, and how
often the model's verdict for a pour is the simulation's; and the
theory's answers to the one-phrase questions against the keys of
`report/evaluation.json` (the majority of 20 pours of each question, as
`make evaluate` drew them), on the clear cases. Every pour is read from the
store when it is there.
"""
from __future__ import annotations

import argparse
import json
from pathlib import Path

import numpy as np

REPORT = Path(__file__).resolve().parents[1] / "report" / "evaluation.json"


def measure(path: Path, pours: int, seed: int, report: Path) -> dict:
    from pantarhei.bridge.evaluation.map_elites import behaviours_seen
    from pantarhei.bridge.evaluation.measures import question_misses, question_scores
    from pantarhei.bridge.verdicts import verdicts
    from pantarhei.bridge.evaluation.explored_pours import exploration_draws, read_learned
    from pantarhei.bridge.evaluation.rule_building import predict
    from pantarhei.bridge.exploration.simulation import open_simulator
    from pantarhei.bridge.learning.generalize import Settings
    from pantarhei.bridge.learning.meaning import Meaning
    from pantarhei.bridge.theories.loading import load
    from pantarhei.oracle.generative import normalise, sample
    from pantarhei.oracle.store import DEFAULT_STORE
    from pantarhei.theory import defaults
    from pantarhei.theory.lexicon import load_vocabulary

    from benchmarks.discovery import theory_consequents

    learned = read_learned(path)
    P, _, _, _ = exploration_draws(learned)
    Q = sample([], pours, seed)
    sim = open_simulator(str(learned.setting("oracle", defaults()["oracle"])), None, None,
                         Path(DEFAULT_STORE).absolute())
    try:
        S = np.asarray(sim.simulate(P, progress=False), dtype=float)
        SQ = np.asarray(sim.simulate(Q, progress=False), dtype=float)
    finally:
        sim.close()
    ok, okq = np.all(np.isfinite(S), axis=1), np.all(np.isfinite(SQ), axis=1)
    model = Meaning(P[ok], verdicts(S[ok]), Settings(seed=int(learned.setting("seed", 1))))
    truth = verdicts(SQ[okq])
    expected = model.shares(normalise(Q[okq]))
    of = theory_consequents(path)
    out = {"explored": len(of), "theory": len(set(of.values())), "seen": behaviours_seen(S),
           "pours": len(P),
           "gap": float(np.abs(expected.mean(axis=0) - truth.mean(axis=0)).mean()),
           "verdicts": float(((expected >= 0.5) == truth).mean()),
           "shares": {"simulated": truth.mean(axis=0).round(2).tolist(),
                      "expected": expected.mean(axis=0).round(2).tolist()}}
    ev = json.loads(report.read_text(encoding="utf-8"))["general"]
    key, clear = np.array(ev["key"]), np.array(ev["clear"])
    asked = [tuple(q["antecedent"]) for q in ev["questions"]]
    answers = predict(load([path]), asked)
    out["questions"] = question_scores(answers, key, clear)
    names = load_vocabulary().expectation_names
    out["wrong"] = [f"{q['text']}: {names[k]}" for q, (wrong, _) in
                    zip(ev["questions"], question_misses(answers, key, clear)) for k in wrong]
    return out


def main(argv: list[str] | None = None) -> None:
    p = argparse.ArgumentParser(prog="python -m benchmarks.priors", description=__doc__.split("\n\n")[0])
    p.add_argument("theories", nargs="+", type=Path, metavar="THEORY")
    p.add_argument("--pours", type=int, default=93, help="pours drawn from the priors (default 93)")
    p.add_argument("--seed", type=int, default=4242, help="their seed (default 4242)")
    p.add_argument("--report", type=Path, default=REPORT,
                   help="the evaluation whose question keys are used (default report/evaluation.json)")
    args = p.parse_args(argv)
    if args.pours < 1:
        raise SystemExit("--pours must be at least 1")
    for path in args.theories:
        r = measure(path, args.pours, args.seed, args.report)
        q = r["questions"]
        print(f"{path}: explored {r['explored']}, {r['theory']} distinct consequents, "
              f"{r['seen']} behaviours seen in {r['pours']} pours; under the priors the model's "
              f"shares are off by {r['gap']:.3f} on average, its verdicts right for "
              f"{100 * r['verdicts']:.1f}% (shares simulated {r['shares']['simulated']}, expected "
              f"{r['shares']['expected']}); one-phrase questions right {100 * q['accuracy']:.1f}% "
              f"of {q['clear']} clear cases (coverage {100 * q['coverage']:.1f}%); wrong: "
              f"{'; '.join(r['wrong']) or 'none'}", flush=True)


if __name__ == "__main__":
    main()
