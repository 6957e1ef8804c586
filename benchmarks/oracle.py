"""The simulation oracle: fidelity, speed, parallelism, memory.

1. Fidelity: the same 20 parameterizations simulated with PyBullet's
   defaults (240 Hz, 50 solver iterations, the full settling time) and with
   the chosen settings (and a few other candidates, to show why these):
   the speed-up (target >= 4x) and how many of the 180 verdicts (each score
   against 0.5) agree (target >= 95%).
2. Parallelism: the same pours on 1 and on 2 worker processes (target >=
   1.8x), simulations per minute, the peak memory of a worker, and the
   share of wall time spent stepping the physics.
3. The baseline math: the same pours on one worker started with the
   baseline math (the default: the same scores on every x86-64 machine)
   and on one using this CPU's own routines, taking turns; the median
   simulations per minute of each and their ratio.

`python -m benchmarks oracle` (or `python -m benchmarks.oracle [--quick]`).
"""
from __future__ import annotations

import argparse
import os
import statistics
import time
from dataclasses import replace
from typing import Optional

import numpy as np

#: Antecedents the 20 parameterizations are drawn from (4 each): pours that
#: go in, pours near the rim, from the side, and anything at all.
ANTECEDENTS = (
    ("pour_centred", "pour_low", "pour_steeply_tilted"),
    ("pour_near_rim", "pour_mid_height", "pour_half_tilted"),
    ("pour_to_side", "pour_steeply_tilted", "heavy_liquid"),
    ("pour_centred", "pour_high", "light_destination", "slippery_destination"),
    (),
)
PER_ANTECEDENT = 4
SEED = 2024


def parameterizations(per: int = PER_ANTECEDENT) -> np.ndarray:
    from pantarhei.oracle.generative import sample

    return np.vstack([sample(list(a), per, SEED + k) for k, a in enumerate(ANTECEDENTS)])


def run_inline(P: np.ndarray, fidelity) -> tuple[np.ndarray, list[float], list[dict]]:
    from pantarhei.oracle.physics import PouringOracle

    o = PouringOracle(fidelity)
    S, secs, recs = [], [], []
    for p in P:
        t = time.perf_counter()
        out = o.score(p)
        secs.append(time.perf_counter() - t)
        S.append(out.scores)
        recs.append(out.record)
    return np.array(S), secs, recs


#: How far the noise-floor run nudges each start_x (mm).
NUDGE_MM = 0.01


def fidelity(P: np.ndarray) -> None:
    from pantarhei.bridge.verdicts import verdicts
    from pantarhei.oracle.fidelity import CHOSEN_FIDELITY, DEFAULT_FIDELITY
    from pantarhei.theory import defaults
    from pantarhei.theory.lexicon import load_vocabulary

    n = P.size // P.shape[1] * 9
    print(f"fidelity: {len(P)} parameterizations, {n} verdicts (score > {defaults()['verdict_threshold']:g})")
    S0, t0, _ = run_inline(P, DEFAULT_FIDELITY)
    nudged = P.copy()
    nudged[:, 0] += NUDGE_MM
    Sn, _, _ = run_inline(nudged, DEFAULT_FIDELITY)
    stable = verdicts(Sn) == verdicts(S0)
    print(f"  {'settings':<62} {'median s':>8} {'total s':>8} {'speed-up':>8} "
          f"{'agree':>12} {'of stable':>10}")
    print(f"  {'PyBullet defaults: ' + DEFAULT_FIDELITY.describe():<62} "
          f"{statistics.median(t0):8.3f} {sum(t0):8.1f} {1:8.1f}x {'-':>12} {'-':>10}")
    print(f"  {f'  the same, start_x nudged by {NUDGE_MM:g} mm (noise floor)':<62} {'':8} {'':8} {'':8} "
          f"{int(stable.sum()):4d}/{n} {stable.mean():4.0%} {'-':>10}")
    c = CHOSEN_FIDELITY
    candidates = [("chosen: " + c.describe(), c),
                  ("  but 240 Hz", replace(c, rate_hz=240)),
                  ("  but 120 Hz", replace(c, rate_hz=120)),
                  ("  but 50 solver iterations", replace(c, solver_iterations=50)),
                  ("  but no early stop", replace(c, early_stop=False)),
                  ("  but PyBullet's 20 mm contact threshold", replace(c, contact_mm=20.0))]
    for label, f in candidates:
        S, t, _ = run_inline(P, f)
        same = verdicts(S) == verdicts(S0)
        agree = int(same.sum())
        print(f"  {label:<62} {statistics.median(t):8.3f} {sum(t):8.1f} "
              f"{sum(t0) / sum(t):8.1f}x {agree:4d}/{S.size} {agree / S.size:4.0%} "
              f"{same[stable].mean():10.0%}")
        if f is c:
            chosen_same = same
    names = load_vocabulary().expectation_names
    print("  chosen vs defaults, verdicts agreeing per expectation (of "
          f"{len(P)}; in brackets, the noise floor's):")
    for k, name in enumerate(names):
        print(f"    {name:<32} {int(chosen_same[:, k].sum()):3d} ({int(stable[:, k].sum())})")


def _peak_rss_mb(pid: int) -> Optional[float]:
    try:
        with open(f"/proc/{pid}/status") as f:
            for line in f:
                if line.startswith("VmHWM:"):
                    return int(line.split()[1]) / 1024
    except OSError:
        return None
    return None


def parallel(P: np.ndarray) -> None:
    from pantarhei.oracle.local_executor import LocalExecutor
    from pantarhei.oracle.physics import PouringOracle
    from pantarhei.oracle.simulator import make_simulator

    print(f"parallel: {len(P)} pours at the chosen settings, worker processes, no store "
          f"({os.cpu_count()} cores, load average {os.getloadavg()[0]:.1f} before)")
    walls, peaks, steps, inside, busy, per = {}, [], 0.0, 0.0, {}, {}
    for workers in (1, 2):
        with make_simulator(PouringOracle.name, executor=LocalExecutor.name, workers=workers, store=None) as sim:
            sim.simulate(P[:workers])                      # start the workers
            t = time.perf_counter()
            S = sim.simulate(P)
            walls[workers] = time.perf_counter() - t
            assert not np.isnan(S).any()
            recs = [r for r in sim.last_records if r]
            busy[workers] = sum(r["seconds"] for r in recs) / (workers * walls[workers])
            per[workers] = statistics.median(r["seconds"] for r in recs)
            if workers == 1:
                steps = sum(r["step_seconds"] for r in recs)
                inside = sum(r["seconds"] for r in recs)
            peaks += [m for w in sim.executor._pool if (m := _peak_rss_mb(w.process.pid))]
        print(f"  {workers} worker{'s' if workers > 1 else ' '}: {walls[workers]:7.1f} s wall, "
              f"{len(P) / walls[workers] * 60:6.0f} simulations per minute")
    print(f"  parallel speed-up on 2 workers: {walls[1] / walls[2]:.2f}x "
          f"(load average {os.getloadavg()[0]:.1f} after: other work on the machine lowers it)")
    print(f"  workers busy {busy[1]:.0%} (1) and {busy[2]:.0%} (2) of the wall time; a simulation "
          f"took {per[1]:.2f} s (1) and {per[2]:.2f} s (2), median: with 2 the cores are shared "
          "with everything else")
    print(f"  peak memory per worker: {max(peaks):.0f} MB (median {statistics.median(peaks):.0f} MB)")
    print(f"  wall time on 1 worker: {steps / walls[1]:.0%} stepping the physics, "
          f"{(inside - steps) / walls[1]:.0%} building and observing the scene, "
          f"{(walls[1] - inside) / walls[1]:.0%} outside the simulation (processes, pipes)")


#: Rounds of the baseline-math comparison (each: every pour once each way).
ROUNDS = 3


def baseline_math(P: np.ndarray, rounds: int = ROUNDS) -> None:
    from pantarhei.oracle.physics import PouringOracle
    from pantarhei.oracle.simulator import Simulator
    from pantarhei.oracle.local_executor import LocalExecutor

    print(f"baseline math: {len(P)} pours on 1 worker, {rounds} rounds taking turns "
          f"(load average {os.getloadavg()[0]:.1f} before)")
    rates: dict[str, list[float]] = {"baseline": [], "native": []}
    same = True
    sims = {m: Simulator(PouringOracle(math=m), LocalExecutor(1), store=None) for m in rates}
    try:
        for s in sims.values():
            s.simulate(P[:1])                       # start the worker
        for _ in range(rounds):
            results = {}
            for m, s in sims.items():
                t = time.perf_counter()
                results[m] = s.simulate(P)
                rates[m].append(len(P) / (time.perf_counter() - t) * 60)
            same &= bool(np.array_equal(results["baseline"], results["native"]))
    finally:
        for s in sims.values():
            s.close()
    b, n = statistics.median(rates["baseline"]), statistics.median(rates["native"])
    print(f"  {'math':<10} {'simulations per minute (median)':>32}")
    print(f"  {'baseline':<10} {b:32.1f}")
    print(f"  {'native':<10} {n:32.1f}")
    print(f"  baseline / native: {b / n:.2f} (scores {'identical' if same else 'differ'} on this CPU)")


def main(quick: bool = False) -> None:
    fidelity(parameterizations(2 if quick else PER_ANTECEDENT))
    parallel(_more(quick))
    baseline_math(_more(True)[:6])


def _more(quick: bool) -> np.ndarray:
    """Pours for the parallel run: other draws from the same antecedents."""
    from pantarhei.oracle.generative import sample

    per = 2 if quick else 8
    return np.vstack([sample(list(a), per, SEED + 100 + k) for k, a in enumerate(ANTECEDENTS)])


if __name__ == "__main__":
    ap = argparse.ArgumentParser(prog="python -m benchmarks.oracle", description=__doc__)
    ap.add_argument("--quick", action="store_true", help="fewer pours (a smoke run)")
    ap.add_argument("--math-only", action="store_true",
                    help="only the baseline-math comparison")
    args = ap.parse_args()
    if args.math_only:
        baseline_math(_more(True)[:6])
    else:
        main(args.quick)
