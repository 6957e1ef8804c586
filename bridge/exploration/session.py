"""The exploration's session, hosted in Python and driven from Prolog.

Algorithm 1's control flow is Prolog (`theory/curiosity.pl`); this module
registers the foreign predicates it calls for the numeric work, in the
Prolog module `bridge`:

* `exploration_begin`: open the simulator and the state store, and return a
  saved state to resume from;
* `exploration_simulate`: sample(a_c, n) and simulate the batch (in the
  simulator's worker processes);
* `exploration_best_plane`: the weights of equation (1) over all
  simulations, a weighted plane fit per explored antecedent, and the
  steepest plane of all;
* `exploration_probe`: simulate the first pours of a candidate's batch and
  say whether they show a new, reproducible consequent;
* `exploration_qualify`: the consequent of each explored antecedent;
* `exploration_checkpoint`: save the state after an explored antecedent;
* `exploration_end`: write the trace and its plot, and close everything;
* `oracle_sample`, `oracle_simulate`, `oracle_describe`: the oracle at the
  Prolog prompt.

Each takes a JSON request and unifies its second argument with a JSON
reply. An exception in Python becomes the reply `{"error": ...}` (Prolog
raises it as `exploration_error/1`) and is raised again, as it was, when the
Prolog goal returns. All Prolog calls stay on the main thread.

What Python holds while Prolog explores is owned by a `Host`, which the
engine keeps (`install(engine)`): the running `Session`, the last error and
the last run's result. Nothing lives at module level.
"""
from __future__ import annotations

import json
import sys
import time
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any, Callable, Sequence

import numpy as np

from pantarhei.bridge.engines.swipl import Engine, engine as prolog_engine
from pantarhei.bridge.errors import UserError
from pantarhei.bridge.exploration.coverage import fewest
from pantarhei.bridge.exploration.novelty import PASS, Known, discount, known, novelties, probe_score
from pantarhei.bridge.exploration.planes import Planes, best_abs_slope, plane_fit
from pantarhei.bridge.exploration.qualify import QUALIFY, consequent
from pantarhei.bridge.exploration.significance import Tested, permutation_test, shuffle_seed
from pantarhei.bridge.exploration.simulation import batch_seed, open_simulator, oracle_identity
from pantarhei.bridge.exploration.state import ExplorationStore, run_key
from pantarhei.bridge.exploration.trace import (append_trace, plot_path, plot_trace,
                                                probe_evidence, rounded, trace_path,
                                                write_trace)
from pantarhei.bridge.exploration.weights import weights
from pantarhei.oracle.generative import (InvalidAntecedent, log_density,
                                         normalise, sample)
from pantarhei.oracle.store import DEFAULT_STORE
from pantarhei.theory.lexicon import load_vocabulary

#: Bumped when the course of an exploration may change for the same settings.
ALGORITHM_VERSION = "4"


@dataclass
class Session:
    settings: dict
    run: str
    store: ExplorationStore
    simulator: Any
    oracle_version: str
    params: np.ndarray
    scores: np.ndarray
    trace: list[dict]
    pending: dict[int, tuple[np.ndarray, np.ndarray]] = field(default_factory=dict)
    log_dens: dict[str, np.ndarray] = field(default_factory=dict)
    plane_cache: dict[str, tuple[np.ndarray, Planes | None]] = field(default_factory=dict)
    test_cache: dict[str, tuple[np.ndarray, Tested | None]] = field(default_factory=dict)
    #: What the last novelty estimate knew: ((pours, antecedents), Known).
    known: tuple[tuple[int, int], Known] | None = None
    started: float = field(default_factory=time.monotonic)
    bar: Any = None
    timings: dict[str, float] = field(default_factory=dict)
    #: Seconds since the start after each explored antecedent (kept out of the trace).
    elapsed: list[float] = field(default_factory=list)
    #: Pours already in the pool of each probed (iteration, attempt).
    probed: dict[tuple[int, int], int] = field(default_factory=dict)
    #: The probe of each (iteration, attempt) not yet in the trace, as the
    #: trace will hold it (its score, and `by` what it was chosen).
    probes_now: dict[tuple[int, int], dict] = field(default_factory=dict)

    @property
    def valid(self) -> np.ndarray:
        return np.all(np.isfinite(self.scores), axis=1)

    def log_density_of(self, aid: str, props: Sequence[str]) -> np.ndarray:
        """log P(p|a) over every simulation so far, extended as they come."""
        have = self.log_dens.get(aid)
        n = len(self.params)
        if have is None:
            have = log_density(self.params, props) if n else np.empty(0)
        elif len(have) < n:
            have = np.concatenate([have, log_density(self.params[len(have):], props)])
        self.log_dens[aid] = have
        return have

    def planes_of(self, aid: str, X: np.ndarray, S: np.ndarray, w: np.ndarray) -> Planes | None:
        """The antecedent's planes, fitted again only when its weights
        changed: an antecedent whose support holds none of the new
        simulations, and none that a new antecedent shares, keeps its planes."""
        cached = self.plane_cache.get(aid)
        if cached is not None and _same_weights(cached[0], w):
            return cached[1]
        planes = plane_fit(X, S, w, float(self.settings.get("ridge", 0.0)))
        self.plane_cache[aid] = (w.copy(), planes)
        return planes

    def tested_of(self, number: int, aid: str, X: np.ndarray, S: np.ndarray,
                  w: np.ndarray) -> Tested | None:
        """The antecedent's planes and their permutation test, done again
        only when its weights changed (as `planes_of`)."""
        cached = self.test_cache.get(aid)
        if cached is not None and _same_weights(cached[0], w):
            return cached[1]
        used = int(((w > 0) & np.all(np.isfinite(S), axis=1)).sum())
        tested = permutation_test(X, S, w, float(self.settings.get("ridge", 0.0)),
                                  int(self.settings["permutations"]),
                                  shuffle_seed(int(self.settings["seed"]), number, used))
        self.test_cache[aid] = (w.copy(), tested)
        return tested

    def weight_matrix(self, entries: Sequence[dict]) -> np.ndarray:
        """Equation (1) for the explored antecedents over the simulations
        that did not fail: (antecedents, valid simulations)."""
        valid = self.valid
        ld = np.vstack([self.log_density_of(str(e["id"]), e["antecedent"])[valid] for e in entries])
        return weights(ld)

    def consequents(self, entries: Sequence[dict], mode: str) -> list[dict]:
        """Qualify each explored antecedent from its weighted simulations
        (`qualify.consequent`, in the order of `entries`)."""
        W = self.weight_matrix(entries)
        S = self.scores[self.valid]
        return [consequent(S, W[i], mode) for i in range(len(entries))]

    def verdicts(self, entries: Sequence[dict]) -> list[tuple[bool, ...]]:
        """The consequent of each explored antecedent as nine verdicts,
        qualified as the run's settings say."""
        mode = str(self.settings.get("qualify", "weighted"))
        return [tuple(o["holds"] for o in c["outcomes"]) for c in self.consequents(entries, mode)]


def _same_weights(w0: np.ndarray, w: np.ndarray) -> bool:
    """Whether weights w over the simulations so far are those cached (w0)
    with none on the simulations since: what was fitted on w0 still holds."""
    k = len(w0)
    return k <= len(w) and np.array_equal(w0, w[:k]) and not w[k:].any()


class Host:
    """What the foreign predicates act on: at most one running Session, the
    exception that stopped the last one, and the last run's result."""

    def __init__(self) -> None:
        self.session: Session | None = None
        self.error: BaseException | None = None
        self.result: dict[str, Any] = {}
        self.handlers: dict[str, Callable[[dict], dict]] = {
            "exploration_begin": self.begin,
            "exploration_simulate": self._timed("simulate", self.simulate),
            "exploration_best_plane": self._timed("planes", self.best_plane),
            "exploration_predict": self._timed("planes", self.predict),
            "exploration_probe": self._timed("probe", self.probe),
            "exploration_fewest": self._timed("probe", self.fewest),
            "exploration_qualify": self._timed("qualify", self.qualify),
            "exploration_checkpoint": self._timed("checkpoint", self.checkpoint),
            "exploration_end": self.end,
            "oracle_sample": oracle_sample,
            "oracle_simulate": oracle_simulate,
            "oracle_describe": oracle_describe,
        }

    def _timed(self, name: str, fn: Callable[[dict], dict]) -> Callable[[dict], dict]:
        def inner(request: dict) -> dict:
            t = time.perf_counter()
            try:
                return fn(request)
            finally:
                if self.session is not None:
                    timings = self.session.timings
                    timings[name] = timings.get(name, 0.0) + time.perf_counter() - t
        return inner

    def need_session(self) -> Session:
        if self.session is None:
            raise UserError("no exploration is running")
        return self.session

    def dispatch(self, name: str, request_text: str) -> str:
        """Run one handler on a JSON request; its JSON reply, or
        `{"error": ...}` with the exception kept for `take_error`."""
        try:
            answer = self.handlers[name](json.loads(request_text))
        except BaseException as e:  # reported to Prolog, raised again by the caller
            self.error = e
            answer = {"error": error_text(e)}
        return json.dumps(answer)

    def take_error(self) -> BaseException | None:
        e, self.error = self.error, None
        return e

    def begin(self, request: dict) -> dict:
        if self.session is not None:
            self.end({"aborted": True})
        oracle = str(request["oracle"])
        oracle_options = dict(request.get("oracle_options") or {})
        version, oracle_settings = oracle_identity(oracle, oracle_options)
        initial = sorted(str(p) for p in request["initial"])
        course = {"algorithm": ALGORITHM_VERSION, "oracle": oracle, "oracle_version": version,
                  "oracle_settings": oracle_settings, "seed": int(request["seed"]),
                  "samples": int(request["samples"]), "threshold": float(request["threshold"]),
                  "initial": initial, "breadth": int(request["breadth"]),
                  "ridge": float(request["ridge"])}
        if request.get("curiosity", "paper") != "paper":   # the paper's runs keep their keys
            course.update(curiosity=str(request["curiosity"]),
                          permutations=int(request["permutations"]),
                          resample=int(request["resample"]),
                          novelty=float(request["novelty"]), queue=int(request["queue"]),
                          jumps=int(request["jumps"]))
            if int(request.get("probe", 0)):       # runs without probes keep their keys
                course.update(probe=int(request["probe"]),
                              probe_attempts=int(request["probe_attempts"]))
                if int(request.get("cover", 0)):   # runs without coverage keep their keys
                    course.update(cover=int(request["cover"]))
            if int(request.get("prior", 0)):       # runs without the priors keep their keys
                course.update(prior=int(request["prior"]), prior_batch="last")
        run = run_key(course)
        store_path = Path(str(request.get("store") or DEFAULT_STORE))
        try:
            store = ExplorationStore(store_path)
        except Exception as e:
            raise UserError(f"cannot open the store {store_path}: {e}") from None
        vocab = load_vocabulary()
        n_par, n_exp = len(vocab.parameters), len(vocab.expectations)
        saved = None
        if _truthy(request.get("resume")):
            saved = store.latest(run, n_par, n_exp)
            if saved is None:
                _note("no saved exploration with these settings: starting afresh")
        if saved is None:
            store.start(run, course)
        out = Path(str(request["out"]))
        out.parent.mkdir(parents=True, exist_ok=True)
        trace_path(out).unlink(missing_ok=True)
        if saved is not None:
            write_trace(trace_path(out), saved.trace)
        workers = request.get("workers")
        simulator = open_simulator(oracle, str(request.get("executor", "local")),
                                   int(workers) if workers not in (None, "") else None,
                                   store_path, request.get("ray_address") or None, oracle_options)
        self.session = Session(
            settings=dict(request, store=str(store_path)), run=run, store=store,
            simulator=simulator, oracle_version=version,
            params=saved.params.copy() if saved else np.empty((0, n_par)),
            scores=saved.scores.copy() if saved else np.empty((0, n_exp)),
            trace=list(saved.trace) if saved else [])
        if _truthy(request.get("progress", True)):
            from tqdm import tqdm

            done = saved.iteration if saved else 0
            total, unit, initial = _progress(self.session, done)
            self.session.bar = tqdm(total=total, initial=initial, unit=unit,
                                    desc="exploring", file=sys.stderr, dynamic_ncols=True)
            self.session.bar.set_postfix_str(_postfix(self.session, done))
        return {"state": saved.state if saved else "", "run": run,
                "resumed": bool(saved), "iterations": saved.iteration if saved else 0}

    def batch(self, request: dict, n: int) -> tuple[np.ndarray, np.ndarray]:
        """The first n pours of the batch of an iteration's attempt
        (attempt 0 is the iteration's own seed; a candidate probed after
        others gets a seed of its own), simulated, and added to the pool
        and to what the iteration's checkpoint saves, except those a probe
        of the same batch already added."""
        s = self.need_session()
        props = [str(p) for p in request["antecedent"]]
        iteration, attempt = int(request["iteration"]), int(request.get("attempt", 0))
        samples = int(s.settings["samples"])
        try:
            P = sample(props, samples, batch_seed(int(s.settings["seed"]), iteration, attempt))[:n]
        except InvalidAntecedent as e:
            raise UserError(f"cannot sample {', '.join(props)}: {e}") from None
        t = time.perf_counter()
        S = np.asarray(s.simulator.simulate(P, progress=False), dtype=float)
        s.timings["oracle"] = s.timings.get("oracle", 0.0) + time.perf_counter() - t
        if S.shape != (n, len(load_vocabulary().expectations)):
            raise RuntimeError(f"the simulator returned scores of shape {S.shape}")
        have = s.probed.get((iteration, attempt), 0)
        s.params = np.vstack([s.params, P[have:]])
        s.scores = np.vstack([s.scores, S[have:]])
        s.probed[(iteration, attempt)] = max(have, n)
        P0, S0 = s.pending.get(iteration, (P[:0], S[:0]))
        s.pending[iteration] = (np.vstack([P0, P[have:]]), np.vstack([S0, S[have:]]))
        return P, S

    def simulate(self, request: dict) -> dict:
        s = self.need_session()
        _, S = self.batch(request, int(s.settings["samples"]))
        failed = int((~np.all(np.isfinite(S), axis=1)).sum())
        return {"simulations": len(s.params), "failed": failed}

    def probe(self, request: dict) -> dict:
        """Simulate the first `probe` pours of a candidate's batch and say
        whether they show a new, reproducible consequent
        (novelty.probe_score against the explored antecedents' consequents,
        at least novelty.PASS)."""
        s = self.need_session()
        samples = int(s.settings["samples"])
        _, S = self.batch(request, min(int(s.settings["probe"]), samples))
        # rounded as the trace keeps it, so that a resumed run and another
        # machine read the same score from it
        score = rounded(probe_score(S, samples, s.verdicts(request["antecedents"])))
        passed = score >= PASS
        s.probes_now[(int(request["iteration"]), int(request["attempt"]))] = {
            "score": score, "by": str(request.get("by", "novelty"))}
        return {"score": score, "pass": passed, "simulations": len(s.params)}

    def fewest(self, request: dict) -> dict:
        """Which candidate's rarest proposition the fewest pours so far hold,
        when fewer than `enough` (bridge/exploration/coverage.py; -1: none)."""
        s = self.need_session()
        return {"index": fewest(s.params[s.valid], request["candidates"], int(request["enough"]))}

    def probe_record(self) -> tuple[float, int]:
        """The probes' scores summed, and how many probes there were, so far
        (those of the trace and of the iteration under way): of the probes
        of the forest's candidates, not those that went where the pours are
        fewest."""
        s = self.need_session()
        return probe_evidence([*s.trace, {"probes": list(s.probes_now.values())}])[-1]

    def best_plane(self, request: dict) -> dict:
        s = self.need_session()
        if s.settings.get("curiosity") == "discover":
            return self.significant_planes(request)
        entries = request["antecedents"]
        W = s.weight_matrix(entries)
        valid = s.valid
        X = normalise(s.params[valid])
        S = s.scores[valid]
        best: tuple[float, int, int, Planes, np.ndarray] | None = None
        for i, e in enumerate(entries):
            planes = s.planes_of(str(e["id"]), X, S, W[i])
            if planes is None:
                continue
            slope = best_abs_slope(planes)
            if best is None or slope.slope > best[0]:
                best = (slope.slope, i, slope.expectation, planes, slope.gradient)
        names = load_vocabulary().parameter_names
        expectations = load_vocabulary().expectation_names
        if best is None:
            return {"antecedent": str(entries[-1]["id"]), "expectation": expectations[0],
                    "slope": 0.0, "mean": 0.5, "gradient": {n: 0.0 for n in names}}
        slope, i, k, planes, gradient = best
        return {"antecedent": str(entries[i]["id"]), "expectation": expectations[k],
                "slope": float(slope), "mean": float(planes.mean[k]),
                "gradient": {n: float(g) for n, g in zip(names, gradient)}}

    def significant_planes(self, request: dict) -> dict:
        """The discovering curiosity's planes: every explored antecedent's
        planes tested against shuffles. Each antecedent with a significant
        component is followed (steepest significant plane first) along each
        of its significant planes: its significant parameters, largest first,
        each with the antecedent's mean value and the value past which the
        plane's verdict flips (theory units). The first is the best, as the
        paper's steepest plane."""
        s = self.need_session()
        entries = request["antecedents"]
        alpha = float(s.settings["threshold"])
        W = s.weight_matrix(entries)
        valid = s.valid
        X = normalise(s.params[valid])
        S = s.scores[valid]
        vocab = load_vocabulary()
        names, expectations = vocab.parameter_names, vocab.expectation_names
        found: list[tuple[float, int, Tested]] = []
        for i, e in enumerate(entries):
            tested = s.tested_of(i + 1, str(e["id"]), X, S, W[i])
            if tested is None:
                continue
            slope = float(tested.slopes(alpha).max())
            if slope > 0:
                found.append((-slope, i, tested))
        if not found:
            return {"antecedent": str(entries[-1]["id"]), "significant": False,
                    "expectation": expectations[0], "slope": 0.0, "mean": 0.5,
                    "gradient": {n: 0.0 for n in names}, "directions": [], "followed": []}
        found.sort(key=lambda f: (f[0], f[1]))
        lo = np.array([p.low for p in vocab.parameters], dtype=float)
        hi = np.array([p.high for p in vocab.parameters], dtype=float)
        followed = []
        for _, i, tested in found:
            sig = tested.significant(alpha)
            slopes = tested.slopes(alpha)
            directions = []
            for k in np.argsort(-slopes, kind="stable"):
                if slopes[k] <= 0:
                    continue
                m = float(tested.mean[k])
                moves = []
                for j in np.argsort(-np.abs(np.where(sig[k], tested.coef[k], 0.0)), kind="stable"):
                    if not sig[k, j]:
                        break
                    g = float(tested.coef[k, j])
                    # the plane through the antecedent's mean crosses 1/2 along j here
                    flip = float(tested.centre[j]) + (0.5 - m) / g
                    moves.append({"parameter": names[j], "component": g,
                                  "sign": "up" if (0.5 - m) / g > 0 else "down",
                                  "mean": float(lo[j] + tested.centre[j] * (hi[j] - lo[j])),
                                  "flip": float(lo[j] + flip * (hi[j] - lo[j])),
                                  "p": float(tested.p[k, j])})
                directions.append({"expectation": expectations[k], "slope": float(slopes[k]),
                                   "mean": m, "moves": moves})
            followed.append({"antecedent": str(entries[i]["id"]), "directions": directions})
        _, i, tested = found[0]
        sig = tested.significant(alpha)
        first = followed[0]["directions"][0]
        k = expectations.index(first["expectation"])
        return {"antecedent": str(entries[i]["id"]), "significant": True,
                "expectation": first["expectation"], "slope": first["slope"],
                "mean": first["mean"],
                "gradient": {n: float(g) if sig[k, j] else 0.0
                             for j, (n, g) in enumerate(zip(names, tested.coef[k]))},
                "directions": followed[0]["directions"], "followed": followed}

    def predict(self, request: dict) -> dict:
        """The novelty of each candidate antecedent (bridge/exploration/novelty.py)
        given every pour so far and the consequents of the explored
        antecedents, and whether it reaches the level to be queued once
        scaled by the probes' record (novelty.discount)."""
        s = self.need_session()
        entries = request["antecedents"]
        key = (len(s.params), len(entries))
        if s.known is None or s.known[0] != key:
            seed = int(s.settings["seed"])
            s.known = (key, known(s.params, s.scores, s.verdicts(entries), int(s.settings["samples"]),
                                  seed, shuffle_seed(seed, 0, len(s.params))))
        k = s.known[1]
        level = float(s.settings["novelty"])
        scale = discount(*self.probe_record())
        found = novelties(k, [[str(p) for p in props] for props in request["candidates"]])
        return {"novelty": [f["novelty"] for f in found],
                "queued": [f["novelty"] * scale >= level for f in found]}

    def qualify(self, request: dict) -> dict:
        s = self.need_session()
        entries = request["antecedents"]
        mode = str(request.get("mode", "weighted"))
        if mode not in QUALIFY:
            raise UserError(f"unknown qualify mode '{mode}' (choose {' or '.join(QUALIFY)})")
        out = [{"id": str(e["id"]), **c} for e, c in zip(entries, s.consequents(entries, mode))]
        if s.settings.get("curiosity") == "discover":   # batches of pours per antecedent
            counts: dict[str, int] = {}
            for t in s.trace:
                counts[str(t["id"])] = counts.get(str(t["id"]), 0) + 1
            for o in out:
                o["batches"] = counts.get(o["id"], 1)
        failed = int((~s.valid).sum())
        return {"antecedents": out, "simulations": len(s.params), "failed": failed,
                "oracle_version": s.oracle_version}

    def checkpoint(self, request: dict) -> dict:
        s = self.need_session()
        iteration = int(request["iteration"])
        P, S = s.pending.pop(iteration)
        trace = rounded(dict(request["trace"]))
        s.probes_now = {k: v for k, v in s.probes_now.items() if k[0] != iteration}
        s.store.save(s.run, iteration, P, S, str(request["state"]), trace)
        s.trace.append(trace)
        s.elapsed.append(round(time.monotonic() - s.started, 3))
        append_trace(Path(str(s.settings["out"])), trace)
        if s.bar is not None:
            s.bar.set_postfix_str(_postfix(s, iteration, int(request.get("a_new", 0))), refresh=False)
            s.bar.update(_progress(s, iteration)[2] - s.bar.n)
        return {}

    def end(self, request: dict) -> dict:
        s = self.session
        if s is None:
            return {}
        self.session = None
        written: dict[str, str] = {}
        try:
            if not _truthy(request.get("aborted")):
                out = Path(str(request["out"]))
                write_trace(trace_path(out), s.trace)
                written["trace"] = str(trace_path(out))
                try:
                    plot_trace(plot_path(out), s.trace, s.settings)
                    written["plot"] = str(plot_path(out))
                except Exception as e:  # the theory and trace are written: say so and go on
                    _note(f"could not plot the trace: {e}")
                s.store.finish(s.run)
                self.result.update(out=str(out), stopped=str(request.get("stopped")),
                                    explored=int(request.get("explored", 0)),
                                    a_new=int(request.get("a_new", 0)),
                                    simulations=len(s.params),
                                    failed=int((~s.valid).sum()), timings=dict(s.timings),
                                    elapsed=list(s.elapsed), wall=time.monotonic() - s.started,
                                    pours=(s.params.copy(), s.scores.copy()), **written)
        finally:
            if s.bar is not None:
                s.bar.close()
            try:
                s.simulator.close()
            finally:
                s.store.close()
        return written


def _progress(s: Session, iteration: int) -> tuple[int, str, int]:
    """The progress bar's total, unit and position after `iteration`
    iterations: for the discovering curiosity, whose budget is in pours,
    the pours of max_rules batches and the pours spent (probes included);
    for the paper's, max_rules explored antecedents."""
    rules = int(s.settings["max_rules"])
    if s.settings.get("curiosity") == "discover":
        return rules * int(s.settings["samples"]), "pour", len(s.params)
    return rules, "rule", iteration


def _postfix(s: Session, explored: int, a_new: int | None = None) -> str:
    text = (f"{explored} batch{'' if explored == 1 else 'es'}"
            if s.settings.get("curiosity") == "discover"
            else f"{len(s.params)} simulations, {explored} rules")
    if a_new is not None:
        text += f", {a_new} in A_new"
    return text


def _note(text: str) -> None:
    print(f"pantarhei explore: {text}", file=sys.stderr)


def _truthy(v: Any) -> bool:
    return v in (True, "true", 1, "1")


def oracle_sample(request: dict) -> dict:
    props = [str(p) for p in request["antecedent"]]
    try:
        P = sample(props, int(request["n"]), int(request["seed"]))
    except (InvalidAntecedent, ValueError) as e:
        raise UserError(str(e)) from None
    return {"rows": P.tolist()}


def oracle_simulate(request: dict) -> dict:
    oracle = str(request.get("oracle", "pybullet"))
    oracle_identity(oracle)
    P = np.asarray(request["rows"], dtype=float)
    n = len(load_vocabulary().parameters)
    if P.ndim != 2 or P.shape[1] != n:
        raise UserError(f"expected rows of {n} numbers")
    workers = request.get("workers")
    sim = open_simulator(oracle, str(request.get("executor", "local")),
                         int(workers) if workers is not None else None,
                         Path(str(request.get("store") or DEFAULT_STORE)).absolute())
    try:
        S = np.asarray(sim.simulate(P, progress=False), dtype=float)
    finally:
        sim.close()
    return {"scores": [[float(x) if np.isfinite(x) else "nan" for x in row] for row in S]}


def oracle_describe(request: dict) -> dict:
    """The propositions whose generative models hold each row (describe)."""
    from pantarhei.oracle.generative import describe

    P = np.asarray(request["rows"], dtype=float)
    n = len(load_vocabulary().parameters)
    if P.ndim != 2 or P.shape[1] != n or not np.all(np.isfinite(P)):
        raise UserError(f"expected rows of {n} numbers")
    return {"props": [list(d) for d in describe(P)]}


def error_text(e: BaseException) -> str:
    """An exception as the one line Prolog reports."""
    if isinstance(e, KeyboardInterrupt):
        return "interrupted"
    return str(e) or type(e).__name__


def install(eng: Engine | None = None) -> Engine:
    """The process's Prolog with the exploration loaded: a Host owned by
    the engine, the foreign predicates (module `bridge`) that call it, and
    theory/curiosity.pl. Registering twice does nothing."""
    eng = eng or prolog_engine()
    if eng.exploration_host is None:
        from pyswip import Prolog

        host = Host()
        for name in host.handlers:
            Prolog.register_foreign(_foreign(eng, name), name=name, arity=2, module="bridge")
        eng.exploration_host = host
        eng.use_module("curiosity")
    return eng


def _foreign(eng: Engine, name: str) -> Callable[[Any, Any], bool]:
    def predicate(request: Any, reply: Any) -> bool:
        text = request.decode() if isinstance(request, bytes) else str(request)
        reply.unify(eng.exploration_host.dispatch(name, text))
        return True
    predicate.__name__ = name
    return predicate
