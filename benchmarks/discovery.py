"""Discovery: how many behaviours each search method finds with the same
budget of pours (775: 25 batches of 31; the discovering curiosity's probes
count in it, and it stops when another step might exceed it).

Methods: curiosity (discover), curiosity (paper), random valid antecedents
(31 pours each), random pours from the prior, and MAP-Elites (pyribs) over
the 30 parameters with the nine verdicts as its cells.

Measures: behaviours seen (distinct nine-verdict vectors among the pours,
each shown by at least two), behaviours in the theory (distinct consequents
of the rules of Algorithm 1, for the methods that build one: one rule set
per antecedent, qualified as Algorithm 1 does), the accuracy and coverage
of the general rules learned from each method's pours on 150 uniformly
random held-out scenes (one pour each, drawn as `pantarhei evaluate` draws
them for the same seed), and for the curiosities the explored antecedents,
the new antecedents per iteration, which explored antecedents turned out to
have a consequent not seen before, and what was left to discover: how many
of the random valid antecedents of the same seed have a consequent the
curiosity's theory lacks. And whether a theory's behaviours are the
simulation's or its noise's: each rule set's antecedent gets a fresh batch
of 31 pours (seeded by the run's seed and the antecedent's propositions,
so an antecedent two methods explored gets the same batch); a rule set is
reproduced when the verdicts of the larger share of that batch are its
consequent, and the confirmed behaviours in the theory are the distinct
consequents of the reproduced rule sets. Medians with the range over the
seeds.

By default the synthetic oracle, seeds 1 to 5, every method. The
environment chooses otherwise (the PyBullet oracle takes about 10 minutes a
method and seed on 2 cores; its pours are kept in the project's store, so a
second run simulates nothing):

    PANTARHEI_BENCH_ORACLE=pybullet PANTARHEI_BENCH_SEEDS=1,2,3 \\
    PANTARHEI_BENCH_METHODS=discover,random python -m benchmarks discovery

PANTARHEI_BENCH_EXPLORE gives the curiosities other options, as
`pantarhei explore` takes them, with a flag for each option of explore/1
alone too (for example "--jumps 310 --resample 0"; by
default the option table's), and PANTARHEI_BENCH_RULES the budget in
batches of 31 (by default the project's 25, the paper's scale; every method
gets as many pours).
"""
from __future__ import annotations

import json
import os
import statistics
import tempfile
from collections import defaultdict
from pathlib import Path
from typing import Callable

import numpy as np

SAMPLES = 31
#: what a line per method and seed shows
SHOWN = ("seen", "theory", "confirmed", "reproduced", "explored", "pours", "other", "general",
         "covered", "left")
#: added to the run's seed for the confirming batches (apart from every other draw)
CONFIRM_SEED = 104729
METHODS = {"discover": "curiosity (discover)", "paper": "curiosity (paper)",
           "random": "random valid antecedents", "prior": "random pours (prior)",
           "map_elites": "MAP-Elites (pyribs)"}


def settings() -> tuple[str, tuple[int, ...], tuple[str, ...], int, Path]:
    """The oracle, seeds and methods this run measures, its budget in
    batches of SAMPLES pours (PANTARHEI_BENCH_RULES; by default the
    project's budget), and the store."""
    from pantarhei.theory import defaults

    oracle = os.environ.get("PANTARHEI_BENCH_ORACLE", "synthetic")
    rules = os.environ.get("PANTARHEI_BENCH_RULES", str(defaults()["budget"]))
    if not rules.isdigit() or int(rules) < 1:
        raise SystemExit(f"PANTARHEI_BENCH_RULES must be a whole number of at least 1, not {rules!r}")
    seeds = tuple(int(s) for s in os.environ.get("PANTARHEI_BENCH_SEEDS", "1,2,3,4,5").split(","))
    methods = tuple(os.environ.get("PANTARHEI_BENCH_METHODS", ",".join(METHODS)).split(","))
    unknown = set(methods) - set(METHODS)
    if unknown:
        raise SystemExit(f"unknown method {sorted(unknown)[0]} (choose from {', '.join(METHODS)})")
    from pantarhei.oracle.store import DEFAULT_STORE

    return oracle, seeds, methods, int(rules), Path(DEFAULT_STORE).absolute()


def simulator(oracle: str, store: Path) -> Callable[[np.ndarray], np.ndarray]:
    if oracle == "synthetic":
        from pantarhei.oracle.synthetic import SyntheticOracle

        o = SyntheticOracle()
        return lambda P: np.array([o.score(p).scores for p in P])
    from pantarhei.bridge.exploration.simulation import open_simulator

    sim = open_simulator(oracle, None, None, store)
    return lambda P: np.asarray(sim.simulate(P, progress=False), dtype=float)


def theory_consequents(path: Path) -> dict[str, tuple[bool, ...]]:
    """The consequent (nine verdicts, in the vocabulary's order) of each
    explored antecedent's rules (Algorithm 1's) of a learned theory, by the
    antecedent's id."""
    from pantarhei.theory import read_facts
    from pantarhei.theory.lexicon import load_vocabulary

    f = read_facts([path])
    prov = {rid: v for rid, k, v in f["provenance"] if k == "antecedent"}
    heads: dict[str, dict[str, bool]] = defaultdict(dict)
    for rid, _, head in f["rule"]:
        if rid not in prov:                 # a general rule: not an explored antecedent's
            continue
        neg = isinstance(head, tuple)
        heads[prov[rid]][head[1] if neg else head] = not neg
    names = load_vocabulary().expectation_names
    return {a: tuple(h[e] for e in names) for a, h in heads.items()}


def explore_options() -> dict:
    """The explore options PANTARHEI_BENCH_EXPLORE gives (flags as
    `pantarhei explore` takes them, checked by its parser, and a flag for
    each option of explore/1 alone too, as --jumps 310), the others the
    option table's defaults."""
    import argparse
    import shlex

    from pantarhei.bridge.commands import explore as command

    parser = argparse.ArgumentParser(prog="PANTARHEI_BENCH_EXPLORE")
    command.add_flags(parser, every=True)
    args = parser.parse_args(shlex.split(os.environ.get("PANTARHEI_BENCH_EXPLORE", "")))
    return command.option_values(args)


def curiosity(mode: str, seed: int, rules: int, tmp: Path, oracle: str, store: Path) -> dict:
    from pantarhei.bridge.exploration.explore_call import ExploreOptions, explore
    from pantarhei.bridge.evaluation.map_elites import behaviours_seen
    from pantarhei.theory import defaults

    out = tmp / f"{mode}-{seed}.pl"
    inline = oracle == "synthetic"
    r = explore(ExploreOptions(**{**explore_options(), "curiosity": mode, "oracle": oracle,
                           "budget": rules, "seed": seed, "out": out,
                           "store": tmp / f"{mode}-{seed}.sqlite" if inline else store,
                           "progress": False, "executor": "inline" if inline else defaults()["executor"],
                           "general": False}))
    trace = [json.loads(line) for line in out.with_suffix(".trace.jsonl").read_text().splitlines()]
    P, S = r["pours"]                       # every pour of the exploration, as it simulated them
    wall, sim = r.get("wall", 0.0), r.get("timings", {}).get("oracle", 0.0)
    of = theory_consequents(out)
    # in the order of exploration, whether each antecedent's consequent was new
    order = [of[t["id"]] for t in trace if t["id"] in of]
    props = {t["id"]: tuple(t["antecedent"]) for t in trace}
    fresh = [c not in order[:i] for i, c in enumerate(order)]
    return {"seen": behaviours_seen(S), "theory": len(set(of.values())),
            "consequents": set(of.values()), "fresh": fresh,
            "rules": [(props[a], c) for a, c in of.items()],
            "explored": r["explored"], "pours": len(P),
            "other": (wall - sim) / wall if wall > 0 else 0.0,
            "added": [len(t["added"]) for t in trace],
            "antecedents": [tuple(t["antecedent"]) for t in trace], "P": P, "S": S}


def random_antecedents(seed: int, rules: int, simulate: Callable) -> dict:
    from pantarhei.bridge.evaluation.heldout import random_exploration
    from pantarhei.bridge.evaluation.map_elites import behaviours_seen
    from pantarhei.bridge.evaluation.measures import distinct_behaviours
    from pantarhei.bridge.evaluation.rule_building import consequents

    ants, P = random_exploration(seed, rules, SAMPLES)     # as the evaluation draws its baseline
    S = simulate(P)
    C = consequents(ants, P, S)
    heads = [tuple(bool(v) for v in c) for c in C]
    return {"seen": behaviours_seen(S), "theory": distinct_behaviours(C), "consequents": heads,
            "rules": [(tuple(a), c) for a, c in zip(ants, heads)],
            "antecedents": ants, "P": P, "S": S}


def confirm(seed: int, rows: dict[str, dict], simulate: Callable) -> None:
    """For each method with a theory: how many of its rule sets a fresh batch
    of their antecedent reproduces (the verdicts of the larger share of its
    pours that did not fail are the consequent), and the distinct
    consequents of those (the confirmed behaviours in the theory), kept in
    its row."""
    from pantarhei.bridge.exploration.novelty import candidate_seed
    from pantarhei.bridge.exploration.qualify import consequent
    from pantarhei.oracle.generative import sample

    for r in rows.values():
        if "rules" not in r:
            continue
        P = np.vstack([sample(list(a), SAMPLES, candidate_seed(seed + CONFIRM_SEED, a))
                       for a, _ in r["rules"]])
        S = np.asarray(simulate(P), dtype=float).reshape(len(r["rules"]), SAMPLES, -1)
        kept = set()
        reproduced = 0
        for (_, c), B in zip(r["rules"], S):
            B = B[np.all(np.isfinite(B), axis=1)]
            # equal weights: the verdicts of the larger share
            heads = consequent(B, np.ones(len(B)), "weighted")["outcomes"]
            if len(B) and tuple(o["holds"] for o in heads) == c:
                reproduced += 1
                kept.add(c)
        r["confirmed"] = len(kept)
        r["reproduced"] = f"{reproduced}/{len(r['rules'])}"


def left_new(rows: dict[str, dict]) -> None:
    """For each curiosity, what it left to discover: of the random valid
    antecedents of the same seed, how many have a consequent its theory
    lacks (needs the random method in the run)."""
    if "random" not in rows:
        return
    for m in ("discover", "paper"):
        if m in rows:
            have = rows[m]["consequents"]
            rows[m]["left"] = sum(c not in have for c in rows["random"]["consequents"])


def prior_pours(seed: int, rules: int, simulate: Callable) -> dict:
    from pantarhei.bridge.evaluation.map_elites import behaviours_seen
    from pantarhei.bridge.exploration.simulation import iteration_seed
    from pantarhei.oracle.generative import sample

    # as the evaluation draws its baseline
    P = sample([], rules * SAMPLES, iteration_seed(seed + 7919, 0))
    S = simulate(P)
    return {"seen": behaviours_seen(S), "P": P, "S": S}


def map_elites(seed: int, rules: int, simulate: Callable) -> dict:
    from pantarhei.bridge.evaluation.map_elites import behaviours_seen, map_elites as search

    qd = search(simulate, rules * SAMPLES, seed, batch=SAMPLES)
    return {"seen": behaviours_seen(qd.S), "P": qd.P, "S": qd.S}


def general_accuracy(seed: int, rows: dict[str, dict], known: set, simulate: Callable) -> None:
    """Per method: coverage and accuracy of the general rules learned from
    its pours (with the run's seed) on 150 uniform held-out scenes, none in
    `known`, kept in its row."""
    from pantarhei.bridge.evaluation.heldout import scene_pours, simulated, uniform_scenes
    from pantarhei.bridge.evaluation.measures import accuracy
    from pantarhei.bridge.learning.generalize import Settings, generalize

    drawn = uniform_scenes(seed, 150, known)
    scenes, y = simulated(drawn, simulate(scene_pours(drawn, seed)))
    for r in rows.values():
        # generalize leaves out the pours whose simulation failed
        a = accuracy(generalize(r["P"], r["S"], Settings(seed=seed)).predict(scenes), y)
        r["general"] = round(100 * a.overall_accuracy, 1)
        r["covered"] = round(100 * a.overall_coverage, 1)


def spread(values: list[float]) -> str:
    return f"{statistics.median(values):g} [{min(values):g}-{max(values):g}]"


def main() -> None:
    oracle, seeds, methods, rules, store = settings()
    simulate = simulator(oracle, store)
    rows: dict[str, list[dict]] = defaultdict(list)
    with tempfile.TemporaryDirectory() as d:
        tmp = Path(d)
        for seed in seeds:
            of_seed: dict[str, dict] = {}
            for m in methods:
                if m in ("discover", "paper"):
                    of_seed[m] = curiosity(m, seed, rules, tmp, oracle, store)
                elif m == "random":
                    of_seed[m] = random_antecedents(seed, rules, simulate)
                elif m == "prior":
                    of_seed[m] = prior_pours(seed, rules, simulate)
                else:
                    of_seed[m] = map_elites(seed, rules, simulate)
            # the held-out scenes avoid what curiosity and random exploration explored
            known = {a for m in ("discover", "random")
                     for a in of_seed.get(m, {}).get("antecedents", [])}
            general_accuracy(seed, of_seed, known, simulate)
            confirm(seed, of_seed, simulate)
            left_new(of_seed)
            for m, r in of_seed.items():
                rows[METHODS[m]].append(r)
                print(f"  {oracle}, seed {seed}, {METHODS[m]}: "
                      + ", ".join(f"{k} {v}" for k, v in r.items() if k in SHOWN), flush=True)
    print(f"{oracle} oracle, {rules * SAMPLES} pours, seeds {','.join(map(str, seeds))}: "
          "median [min-max]")
    print(f"{'method':<26} {'behaviours seen':>16} {'in the theory':>14} {'confirmed':>12} "
          f"{'explored':>12} {'general rules: accuracy %':>26} {'coverage %':>18}")
    for method, rs in rows.items():
        seen = spread([r["seen"] for r in rs])
        theory = spread([r["theory"] for r in rs]) if "theory" in rs[0] else "-"
        confirmed = spread([r["confirmed"] for r in rs]) if "confirmed" in rs[0] else "-"
        explored = spread([r["explored"] for r in rs]) if "explored" in rs[0] else "-"
        general = spread([r["general"] for r in rs])
        covered = spread([r["covered"] for r in rs])
        print(f"{method:<26} {seen:>16} {theory:>14} {confirmed:>12} {explored:>12} {general:>26} "
              f"{covered:>18}")
    free = (" (the synthetic oracle's scores cost nothing)" if oracle == "synthetic"
            else " (pours read from the store count as not simulated)")
    for m in ("discover", "paper"):
        for seed, r in zip(seeds, rows.get(METHODS[m], [])):
            fresh, k = r["fresh"], min(10, len(r["fresh"]))
            print(f"{METHODS[m]}, seed {seed}: new antecedents per iteration {r['added']}; "
                  f"explored antecedents with a new consequent: {sum(fresh[:k])} of the first {k}, "
                  f"{sum(fresh[k:])} of the other {len(fresh) - k}; "
                  + (f"left to discover: {r['left']} of the {rules} random valid antecedents have "
                     "a consequent its theory lacks; " if "left" in r else "")
                  + f"everything but simulation {100 * r['other']:.1f}% of the wall time{free}")


if __name__ == "__main__":
    main()
