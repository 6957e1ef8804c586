"""Exploration hosted in Python, driven from Prolog.

Algorithm 1's control flow is Prolog (`theory/explore.pl`); this module
registers the foreign predicates it calls for the numeric work, in the
Prolog module `bridge`:

* `exploration_begin`: open the simulator and the state store, and return a
  saved state to resume from;
* `exploration_simulate`: sample(a_c, n) and simulate the batch (in the
  simulator's worker processes);
* `exploration_best_plane`: the weights of equation (1) over all
  simulations, a weighted plane fit per explored antecedent, and the
  steepest plane of all;
* `exploration_qualify`: the outcome of each explored antecedent;
* `exploration_checkpoint`: save the state after an explored antecedent;
* `exploration_end`: write the trace and its plot, and close everything.

Each takes a JSON request and unifies its second argument with a JSON
reply. An exception in Python becomes the reply `{"error": ...}` (Prolog
raises it as `exploration_error/1`) and is raised again, as it was, when the
Prolog goal returns. All Prolog calls stay on the main thread.
"""
from __future__ import annotations

import json
import sys
import time
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any, Callable, Sequence

import numpy as np

from pantarhei.oracle.generative import InvalidAntecedent, normalise, sample
from pantarhei.oracle.vocabulary import load_vocabulary
from pantarhei.theory import THEORY_DIR

from .errors import UserError
from .files import save_figure, write_text
from .exploration_state import ExplorationStore, run_key
from .planes import MIN_WEIGHT, Planes, best_abs_slope, plane_fit
from .prolog import Engine, engine as prolog_engine
from .weights import weights

#: Where the learned theory goes unless told otherwise.
DEFAULT_OUT = THEORY_DIR / "learned" / "pouring.pl"
#: The store of simulations and exploration state unless told otherwise.
DEFAULT_STORE = Path("pantarhei.sqlite")
#: Qualify modes: the weighted vote (default) and the paper's rule.
QUALIFY = ("weighted", "argmax")
#: Bumped when the course of an exploration may change for the same settings.
ALGORITHM_VERSION = "1"


def iteration_seed(seed: int, iteration: int) -> int:
    """The sampling seed of an iteration, derived from the run's seed."""
    return int(np.random.SeedSequence([int(seed), int(iteration)]).generate_state(1)[0])


def trace_path(out: Path) -> Path:
    return out.with_suffix(".trace.jsonl")


def plot_path(out: Path) -> Path:
    return out.with_suffix(".trace.png")


# ----------------------------------------------------------------------
# Simulation


def open_simulator(oracle: str, executor: str = "local", workers: int | None = None,
                   store: str | Path | None = None, ray_address: str | None = None,
                   oracle_options: dict | None = None) -> Any:
    """The simulator: `simulate(P) -> scores` with NaN rows for failures,
    every result kept in the store and never simulated twice."""
    from pantarhei.oracle.simulator import make_simulator

    return make_simulator(oracle, executor=executor, workers=workers, store=str(store),
                          ray_address=ray_address, **(oracle_options or {}))


def oracle_identity(name: str, options: dict | None = None) -> tuple[str, dict]:
    """The oracle's version and settings (UserError for an unknown name)."""
    from pantarhei.oracle.base import ORACLES, make_oracle

    if name not in ORACLES:
        raise UserError(f"unknown oracle '{name}' (choose {' or '.join(ORACLES)})")
    try:
        o = make_oracle(name, **(options or {}))
    except ImportError as e:
        raise UserError(f"the {name} oracle cannot be loaded: {e}") from None
    return str(o.version), dict(o.settings())


# ----------------------------------------------------------------------
# The session: what Python holds while Prolog explores


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
    started: float = field(default_factory=time.monotonic)
    bar: Any = None
    timings: dict[str, float] = field(default_factory=dict)

    @property
    def valid(self) -> np.ndarray:
        return np.all(np.isfinite(self.scores), axis=1)

    def log_density_of(self, aid: str, props: Sequence[str]) -> np.ndarray:
        """log P(p|a) over every simulation so far, extended as they come."""
        from pantarhei.oracle.generative import log_density

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
        if cached is not None:
            w0, planes = cached
            k = len(w0)
            if k <= len(w) and np.array_equal(w0, w[:k]) and not w[k:].any():
                return planes
        planes = plane_fit(X, S, w, float(self.settings.get("ridge", 0.0)))
        self.plane_cache[aid] = (w.copy(), planes)
        return planes

    def weight_matrix(self, entries: Sequence[dict]) -> np.ndarray:
        """Equation (1) for the explored antecedents over the simulations
        that did not fail: (antecedents, valid simulations)."""
        valid = self.valid
        ld = np.vstack([self.log_density_of(str(e["id"]), e["antecedent"])[valid] for e in entries])
        return weights(ld)


_session: Session | None = None
_error: BaseException | None = None


def _timed(name: str) -> Callable:
    def wrap(fn: Callable) -> Callable:
        def inner(request: dict) -> dict:
            t = time.perf_counter()
            try:
                return fn(request)
            finally:
                if _session is not None:
                    _session.timings[name] = _session.timings.get(name, 0.0) + time.perf_counter() - t
        return inner
    return wrap


def _need_session() -> Session:
    if _session is None:
        raise UserError("no exploration is running")
    return _session


def begin(request: dict) -> dict:
    global _session
    if _session is not None:
        end({"aborted": True})
    oracle = str(request["oracle"])
    oracle_options = dict(request.get("oracle_options") or {})
    version, oracle_settings = oracle_identity(oracle, oracle_options)
    initial = sorted(str(p) for p in request["initial"])
    course = {"algorithm": ALGORITHM_VERSION, "oracle": oracle, "oracle_version": version,
              "oracle_settings": oracle_settings, "seed": int(request["seed"]),
              "samples": int(request["samples"]), "threshold": float(request["threshold"]),
              "initial": initial, "breadth": int(request["breadth"]),
              "ridge": float(request["ridge"])}
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
    _session = Session(
        settings=dict(request, store=str(store_path)), run=run, store=store,
        simulator=simulator, oracle_version=version,
        params=saved.params.copy() if saved else np.empty((0, n_par)),
        scores=saved.scores.copy() if saved else np.empty((0, n_exp)),
        trace=list(saved.trace) if saved else [])
    if _truthy(request.get("progress", True)):
        from tqdm import tqdm

        done = saved.iteration if saved else 0
        _session.bar = tqdm(total=int(request["max_rules"]), initial=done, unit="rule",
                            desc="exploring", file=sys.stderr, dynamic_ncols=True)
        _session.bar.set_postfix_str(_postfix(_session, done))
    return {"state": saved.state if saved else "", "run": run,
            "resumed": bool(saved), "iterations": saved.iteration if saved else 0}


@_timed("simulate")
def simulate(request: dict) -> dict:
    s = _need_session()
    props = [str(p) for p in request["antecedent"]]
    iteration = int(request["iteration"])
    n = int(s.settings["samples"])
    try:
        P = sample(props, n, iteration_seed(int(s.settings["seed"]), iteration))
    except InvalidAntecedent as e:
        raise UserError(f"cannot sample {', '.join(props)}: {e}") from None
    t = time.perf_counter()
    S = np.asarray(s.simulator.simulate(P, progress=False), dtype=float)
    s.timings["oracle"] = s.timings.get("oracle", 0.0) + time.perf_counter() - t
    if S.shape != (n, len(load_vocabulary().expectations)):
        raise RuntimeError(f"the simulator returned scores of shape {S.shape}")
    s.params = np.vstack([s.params, P])
    s.scores = np.vstack([s.scores, S])
    s.pending[iteration] = (P, S)
    failed = int((~np.all(np.isfinite(S), axis=1)).sum())
    return {"simulations": len(s.params), "failed": failed}


@_timed("planes")
def best_plane(request: dict) -> dict:
    s = _need_session()
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


@_timed("qualify")
def qualify(request: dict) -> dict:
    s = _need_session()
    entries = request["antecedents"]
    mode = str(request.get("mode", "weighted"))
    if mode not in QUALIFY:
        raise UserError(f"unknown qualify mode '{mode}' (choose {' or '.join(QUALIFY)})")
    W = s.weight_matrix(entries)
    S = s.scores[s.valid]
    out = []
    for i, e in enumerate(entries):
        out.append({"id": str(e["id"]), **outcome(S, W[i], mode)})
    failed = int((~s.valid).sum())
    return {"antecedents": out, "simulations": len(s.params), "failed": failed,
            "oracle_version": s.oracle_version}


def outcome(S: np.ndarray, w: np.ndarray, mode: str) -> dict:
    """The consequent of one antecedent from its weighted simulations.

    argmax (the paper's rule): the verdicts (score > 1/2) of the simulation
    with the largest weight (the first of equals). weighted: per
    expectation, the verdict of the larger weight. The confidence of a
    verdict is the weighted share of simulations that agree with it."""
    expectations = load_vocabulary().expectation_names
    holds = S > 0.5
    mass = float(w.sum())
    used = int((w > MIN_WEIGHT).sum())
    if mass <= 0:
        share = np.full(len(expectations), 0.5)
        mean = np.full(len(expectations), 0.5)
        chosen = share > 0.5
        best = -1
    else:
        share = (w[:, None] * holds).sum(axis=0) / mass
        mean = (w[:, None] * S).sum(axis=0) / mass
        best = int(np.argmax(w))
        chosen = holds[best] if mode == "argmax" else share > 0.5
    confidence = np.where(chosen, share, 1.0 - share)
    return {"simulations": used, "weight_mass_permille": int(round(1000 * mass)),
            "sample": best,
            "outcomes": [{"expectation": e, "holds": bool(chosen[k]),
                          "confidence_permille": int(round(1000 * confidence[k])),
                          "score_permille": int(round(1000 * mean[k]))}
                         for k, e in enumerate(expectations)]}


@_timed("checkpoint")
def checkpoint(request: dict) -> dict:
    s = _need_session()
    iteration = int(request["iteration"])
    P, S = s.pending.pop(iteration)
    trace = dict(request["trace"])
    trace["elapsed_s"] = round(time.monotonic() - s.started, 3)
    s.store.save(s.run, iteration, P, S, str(request["state"]), trace)
    s.trace.append(trace)
    _append_trace(Path(str(s.settings["out"])), trace)
    if s.bar is not None:
        s.bar.update(1)
        s.bar.set_postfix_str(_postfix(s, iteration, int(request.get("a_new", 0))))
    return {}


def end(request: dict) -> dict:
    global _session
    s = _session
    if s is None:
        return {}
    _session = None
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
            _last_result.update(out=str(out), stopped=str(request.get("stopped")),
                                explored=int(request.get("explored", 0)),
                                a_new=int(request.get("a_new", 0)),
                                simulations=len(s.params),
                                failed=int((~s.valid).sum()), timings=dict(s.timings),
                                wall=time.monotonic() - s.started, **written)
    finally:
        if s.bar is not None:
            s.bar.close()
        try:
            s.simulator.close()
        finally:
            s.store.close()
    return written


_last_result: dict[str, Any] = {}


def _postfix(s: Session, explored: int, a_new: int | None = None) -> str:
    text = f"{len(s.params)} simulations, {explored} rules"
    if a_new is not None:
        text += f", {a_new} in A_new"
    return text


def _note(text: str) -> None:
    print(f"pantarhei explore: {text}", file=sys.stderr)


def _truthy(v: Any) -> bool:
    return v in (True, "true", 1, "1")


# ----------------------------------------------------------------------
# Trace and plot


def _append_trace(out: Path, entry: dict) -> None:
    with open(trace_path(out), "a", encoding="utf-8") as f:
        f.write(json.dumps(entry, sort_keys=True) + "\n")


def write_trace(path: Path, trace: Sequence[dict]) -> None:
    """The whole trace as JSON lines, written atomically."""
    write_text(path, "".join(json.dumps(entry, sort_keys=True) + "\n" for entry in trace))


def plot_trace(path: Path, trace: Sequence[dict], settings: dict | None = None) -> None:
    """|A_new| after each iteration, and the antecedents each added (PNG)."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    it = [t["iteration"] for t in trace]
    added = [len(t["added"]) for t in trace]
    size = [t["a_new"] for t in trace]
    fig, ax = plt.subplots(figsize=(7, 3.6), dpi=120)
    ax.bar(it, added, color="#8fb3d9", label="new antecedents")
    ax.plot(it, size, color="#c0392b", marker="o", markersize=3, label="|A_new|")
    ax.set_xlabel("iteration (explored antecedent)")
    ax.set_ylabel("antecedents")
    title = "Curiosity-driven exploration"
    if settings:
        title += f" ({settings.get('oracle')} oracle, seed {settings.get('seed')})"
    ax.set_title(title)
    ax.legend(loc="upper right")
    ax.grid(axis="y", alpha=0.3)
    fig.tight_layout()
    save_figure(fig, path)


# ----------------------------------------------------------------------
# The oracle at the Prolog prompt (explore:sample/4, explore:simulate/3)


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


# ----------------------------------------------------------------------
# Hosting


_HANDLERS: dict[str, Callable[[dict], dict]] = {
    "exploration_begin": begin,
    "exploration_simulate": simulate,
    "exploration_best_plane": best_plane,
    "exploration_qualify": qualify,
    "exploration_checkpoint": checkpoint,
    "exploration_end": end,
    "oracle_sample": oracle_sample,
    "oracle_simulate": oracle_simulate,
}


def _foreign(handler: Callable[[dict], dict]) -> Callable[[Any, Any], bool]:
    def predicate(request: Any, reply: Any) -> bool:
        global _error
        try:
            text = request.decode() if isinstance(request, bytes) else str(request)
            answer = handler(json.loads(text))
        except BaseException as e:  # reported to Prolog, raised again by run()
            _error = e
            answer = {"error": _error_text(e)}
        reply.unify(json.dumps(answer))
        return True
    predicate.__name__ = handler.__name__
    return predicate


def _error_text(e: BaseException) -> str:
    if isinstance(e, KeyboardInterrupt):
        return "interrupted"
    return str(e) or type(e).__name__


_registered = False


def load(eng: Engine | None = None) -> Engine:
    """The process's Prolog with the exploration loaded: the foreign
    predicates in module `bridge` and theory/explore.pl."""
    global _registered
    eng = eng or prolog_engine()
    if not _registered:
        from pyswip import Prolog

        for name, handler in _HANDLERS.items():
            Prolog.register_foreign(_foreign(handler), name=name, arity=2, module="bridge")
        _registered = True
        eng.use_module("explore")
    return eng


@dataclass
class Options:
    """The options of one exploration (see explore/1 in theory/explore.pl)."""
    oracle: str = "pybullet"
    max_rules: int = 25
    samples: int | None = None
    threshold: float = 0.1
    ridge: float = 1.0
    seed: int = 1
    initial: Sequence[str] | None = None
    breadth: int = 3
    qualify: str = "weighted"
    out: Path = DEFAULT_OUT
    store: Path = DEFAULT_STORE
    resume: bool = False
    executor: str = "local"
    workers: int | None = None
    ray_address: str | None = None
    progress: bool = True
    #: Keyword arguments of the oracle's constructor (JSON values).
    oracle_options: dict | None = None

    def prolog(self) -> str:
        from .prolog import _term

        items = [f"oracle({_term(self.oracle)})", f"max_rules({int(self.max_rules)})",
                 f"threshold({float(self.threshold)!r})", f"seed({int(self.seed)})",
                 f"breadth({int(self.breadth)})", f"ridge({float(self.ridge)!r})", f"qualify({_term(self.qualify)})",
                 f"out({_term(str(Path(self.out).absolute()))})",
                 f"store({_term(str(Path(self.store).absolute()))})",
                 f"resume({_term(bool(self.resume))})", f"executor({_term(self.executor)})",
                 f"progress({_term(bool(self.progress))})"]
        if self.samples is not None:
            items.append(f"samples({int(self.samples)})")
        if self.initial is not None:
            items.append(f"initial({_term(list(self.initial))})")
        if self.workers is not None:
            items.append(f"workers({int(self.workers)})")
        if self.ray_address:
            items.append(f"ray_address({_term(self.ray_address)})")
        if self.oracle_options:
            items.append(f"oracle_options({_term(json.dumps(self.oracle_options))})")
        return "[" + ", ".join(items) + "]"


def explore(options: Options) -> dict:
    """Run an exploration to the end and return what it did: the output
    files, why it stopped, the number of rules and simulations, and where
    the time went. UserError for bad options; an interruption is raised
    again as KeyboardInterrupt once the state is saved."""
    global _error
    eng = load()
    _error = None
    _last_result.clear()
    try:
        goal = (f"explore:explore_result({options.prolog()}, R0), "
                "(R0 == ok -> R = ok ; R0 = error(T), text_to_string(T, R))")
        result = eng.once(goal)["R"]
    finally:
        if _session is not None:
            end({"aborted": True})
    if result not in ("ok", b"ok"):
        if _error is not None:
            e, _error = _error, None
            if isinstance(e, (UserError, KeyboardInterrupt)):
                raise e
            raise UserError(_error_text(e)) from e
        raise UserError(_result_text(result))
    return dict(_last_result)


def _result_text(result: Any) -> str:
    from .prolog import text

    s = text(result)
    return s.splitlines()[0] if s else "exploration failed"
