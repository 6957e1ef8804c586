"""Discovery: how many behaviours each search method finds with the same
budget of pours, on the synthetic oracle (seeds 1 to 5, 775 pours each).

Methods: curiosity (discover, the default), curiosity (paper), random valid
antecedents (31 pours each), random pours from the prior, and MAP-Elites
(pyribs) over the 30 parameters with the nine verdicts as its cells.

Measures: behaviours seen (distinct nine-verdict vectors among the pours,
each shown by at least two), behaviours in the theory (distinct consequents
of the rules, for the methods that build one: one rule set per antecedent,
qualified as Algorithm 1 does), and for the curiosities the explored
antecedents and the new antecedents per iteration. Medians with the range
over the seeds.
"""
from __future__ import annotations

import json
import statistics
import tempfile
from collections import defaultdict
from pathlib import Path

import numpy as np

SEEDS = (1, 2, 3, 4, 5)
RULES, SAMPLES = 25, 31


def synthetic(P: np.ndarray) -> np.ndarray:
    from pantarhei.oracle.synthetic import SyntheticOracle

    oracle = SyntheticOracle()
    return np.array([oracle.score(p).scores for p in P])


def theory_behaviours(path: Path) -> int:
    """Distinct consequents (nine verdicts) of the rules of a learned theory."""
    from pantarhei.theory import read_facts

    f = read_facts([path])
    prov = {rid: v for rid, k, v in f["provenance"] if k == "antecedent"}
    heads: dict[str, dict[str, bool]] = defaultdict(dict)
    for rid, _, head in f["rule"]:
        neg = isinstance(head, tuple)
        heads[prov[rid]][head[1] if neg else head] = not neg
    return len({tuple(sorted(h.items())) for h in heads.values()})


def curiosity(mode: str, seed: int, tmp: Path) -> dict:
    from pantarhei.bridge.exploration.loop import Options, explore
    from pantarhei.bridge.exploration.simulation import iteration_seed
    from pantarhei.bridge.evaluation.map_elites import behaviours_seen
    from pantarhei.oracle.generative import sample

    out = tmp / f"{mode}-{seed}.pl"
    r = explore(Options(curiosity=mode, oracle="synthetic", max_rules=RULES, seed=seed, out=out,
                        store=tmp / f"{mode}-{seed}.sqlite", progress=False, executor="inline"))
    trace = [json.loads(line) for line in out.with_suffix(".trace.jsonl").read_text().splitlines()]
    P = np.vstack([sample(t["antecedent"], SAMPLES, iteration_seed(seed, t["iteration"]))
                   for t in trace])
    S = synthetic(P)
    return {"seen": behaviours_seen(S), "theory": theory_behaviours(out),
            "explored": r["explored"], "pours": len(P), "planes": r["timings"].get("planes", 0.0),
            "added": [len(t["added"]) for t in trace]}


def random_antecedents(seed: int) -> dict:
    from pantarhei.bridge.evaluation.heldout import random_antecedents as draw
    from pantarhei.bridge.evaluation.map_elites import behaviours_seen
    from pantarhei.bridge.evaluation.measures import distinct_behaviours
    from pantarhei.bridge.evaluation.rule_building import consequents
    from pantarhei.bridge.exploration.simulation import iteration_seed
    from pantarhei.oracle.generative import sample

    ants = draw(seed + 7919, RULES)          # as the evaluation draws its baseline
    P = np.vstack([sample(list(a), SAMPLES, iteration_seed(seed + 7919, i))
                   for i, a in enumerate(ants, start=1)])
    S = synthetic(P)
    return {"seen": behaviours_seen(S), "theory": distinct_behaviours(consequents(ants, P, S))}


def prior_pours(seed: int) -> dict:
    from pantarhei.bridge.evaluation.map_elites import behaviours_seen
    from pantarhei.oracle.generative import sample

    return {"seen": behaviours_seen(synthetic(sample([], RULES * SAMPLES, seed)))}


def map_elites(seed: int) -> dict:
    from pantarhei.bridge.evaluation.map_elites import behaviours_seen, map_elites as search

    return {"seen": behaviours_seen(search(synthetic, RULES * SAMPLES, seed).S)}


def spread(values: list[float]) -> str:
    return f"{statistics.median(values):g} [{min(values):g}-{max(values):g}]"


def main() -> None:
    rows: dict[str, list[dict]] = defaultdict(list)
    with tempfile.TemporaryDirectory() as d:
        tmp = Path(d)
        for seed in SEEDS:
            rows["curiosity (discover)"].append(curiosity("discover", seed, tmp))
            rows["curiosity (paper)"].append(curiosity("paper", seed, tmp))
            rows["random valid antecedents"].append(random_antecedents(seed))
            rows["random pours (prior)"].append(prior_pours(seed))
            rows["MAP-Elites (pyribs)"].append(map_elites(seed))
    print(f"synthetic oracle, {RULES * SAMPLES} pours, seeds {SEEDS[0]}-{SEEDS[-1]}: "
          "median [min-max]")
    print(f"{'method':<26} {'behaviours seen':>16} {'in the theory':>14} {'explored':>12}")
    for method, rs in rows.items():
        seen = spread([r["seen"] for r in rs])
        theory = spread([r["theory"] for r in rs]) if "theory" in rs[0] else "-"
        explored = spread([r["explored"] for r in rs]) if "explored" in rs[0] else "-"
        print(f"{method:<26} {seen:>16} {theory:>14} {explored:>12}")
    for method in ("curiosity (discover)", "curiosity (paper)"):
        for seed, r in zip(SEEDS, rows[method]):
            print(f"{method}, seed {seed}: new antecedents per iteration {r['added']}; "
                  f"planes {r['planes']:.2f} s")


if __name__ == "__main__":
    main()
