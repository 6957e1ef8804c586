"""The exploration's session, hosted in Python and driven from Prolog.

Algorithm 1's control flow is Prolog (`theory/curiosity.pl`); this module
registers the foreign predicates it calls for the numeric work, in the
Prolog module `bridge`:

* `exploration_begin`: open the simulator and the state store, and return a
  saved state to resume from;
* `exploration_simulate`: sample(a_c, n) and simulate the batch (in the
  simulator's worker processes);
* the foreign predicates of each curiosity's own numbers, which its
  Python modules declare (bridge/exploration/curiosity_sides.py), for the
  curiosities of the one list: this module names none of them;
* `exploration_qualify`: the consequent of each explored antecedent;
* `exploration_checkpoint`: save the state after an explored antecedent;
* `exploration_general`: the general rules of every pour of the
  exploration (bridge/learning/layers.py), which explore/1 writes beside
  Algorithm 1's rules;
* `exploration_end`: write the trace and its plot, and close everything;
* `oracle_sample`, `oracle_simulate`, `oracle_describe`: the oracle at the
  Prolog prompt (bridge/exploration/prompt_oracle.py).

Each takes a request dict and unifies its second argument with a reply
dict, as terms (bridge/engines/terms.py). An exception in Python becomes the reply `{"error": ...}` (Prolog
raises it as `exploration_error/1`) and is raised again, as it was, when the
Prolog goal returns. All Prolog calls stay on the main thread.

What Python holds while Prolog explores is owned by a `Host`, which the
engine keeps (`install(engine)`): the running `Session` (its pours and
what is cached on them: bridge/exploration/session_state.py), the last
error and the last run's result.
Nothing lives at module level. The run's course-deciding settings are
bridge/exploration/course.py; the progress bar, bridge/exploration/progress.py.
"""
from __future__ import annotations

import sys
import time
from functools import partial
from pathlib import Path
from typing import Any, Callable, Mapping, Sequence

import numpy as np

from pantarhei.bridge.engines.swipl import Engine, engine as prolog_engine
from pantarhei.bridge.engines.terms import foreign
from pantarhei.bridge.errors import UserError
from pantarhei.bridge.exploration.course import ALGORITHM_VERSION, course
from pantarhei.bridge.exploration.curiosity_sides import curiosity_handlers
from pantarhei.bridge.exploration.progress import open_bar
from pantarhei.bridge.exploration.prompt_oracle import (oracle_describe, oracle_sample,
                                                        oracle_simulate)
from pantarhei.bridge.exploration.qualify import QUALIFY
from pantarhei.bridge.exploration.simulation import (batch_pours, drawn_pours, open_simulator,
                                                     oracle_identity, trace_draws)
from pantarhei.bridge.exploration.checkpoints import ExplorationStore, other_settings, run_key
from pantarhei.bridge.exploration.session_state import Session
from pantarhei.bridge.exploration.trace import (append_trace, plot_path, plot_trace,
                                                require_distinct_outputs, rounded, trace_path,
                                                write_trace)
from pantarhei.oracle.generative import InvalidAntecedent
from pantarhei.oracle.store import DEFAULT_STORE
from pantarhei.theory import defaults
from pantarhei.theory.lexicon import load_vocabulary

__all__ = ["ALGORITHM_VERSION", "Host", "Session", "error_text", "install"]


class Host:
    """What the foreign predicates act on: at most one running Session, the
    exception that stopped the last one, and the last run's result. Its
    handlers are the shared ones and those the Python sides of the
    curiosities declare (curiosity_sides.curiosity_handlers, given
    `curiosities` and `sides` when not the one list's)."""

    def __init__(self, curiosities: Sequence[str] | None = None,
                 sides: Mapping[str, Sequence[str]] | None = None) -> None:
        self.session: Session | None = None
        self.error: BaseException | None = None
        self.result: dict[str, Any] = {}
        #: the C callbacks of the foreign predicates, alive while Prolog is
        self.callbacks: list = []
        self.handlers: dict[str, Callable[[dict], dict]] = {
            "exploration_begin": self.begin,
            "exploration_simulate": self._timed("simulate", self.simulate),
            "exploration_qualify": self._timed("qualify", self.qualify),
            "exploration_checkpoint": self._timed("checkpoint", self.checkpoint),
            "exploration_general": self._timed("generalize", self.general),
            "exploration_end": self.end,
            "oracle_sample": oracle_sample,
            "oracle_simulate": oracle_simulate,
            "oracle_describe": oracle_describe,
        }
        for name, (timing, handler) in curiosity_handlers(curiosities, sides).items():
            if name in self.handlers:
                raise ValueError(f"a curiosity declares {name}, a foreign predicate of the session")
            self.handlers[name] = self._timed(timing, partial(handler, self))

    def register(self, names: Sequence[str] | None = None) -> None:
        """Register the foreign predicates `names` (all its handlers unless
        given) in the Prolog module `bridge`, each calling `dispatch`."""
        for name in self.handlers if names is None else names:
            foreign("bridge", name, partial(self.dispatch, name), self.callbacks)

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

    def dispatch(self, name: str, request: dict) -> dict:
        """Run one handler on a request; its reply, or `{"error": ...}`
        with the exception kept for `take_error`."""
        try:
            return self.handlers[name](request)
        except BaseException as e:  # reported to Prolog, raised again by the caller
            self.error = e
            return {"error": error_text(e)}

    def take_error(self) -> BaseException | None:
        e, self.error = self.error, None
        return e

    def begin(self, request: dict) -> dict:
        """Open the store and the simulator of explore/1's request, and the
        saved state to resume from when it asks to resume and there is one."""
        if self.session is not None:
            self.end({"aborted": True})
        oracle = str(request["oracle"])
        oracle_options = dict(request.get("oracle_options") or {})
        version, oracle_settings = oracle_identity(oracle, oracle_options)
        decided_by = course(request, version, oracle_settings)
        run = run_key(decided_by)
        store_path = Path(str(request.get("store") or DEFAULT_STORE))
        require_distinct_outputs(store_path, Path(str(request["out"])), names=("store(...)", "out(...)"))
        try:
            store = ExplorationStore(store_path)
        except Exception as e:
            raise UserError(f"cannot open the store {store_path}: {e}") from None
        saved, draws = None, []
        if truthy(request.get("resume")):
            saved = store.latest(run)
            other = store.latest_course() if saved is None else None
            if other is not None and run_key(other) != run:
                store.close()
                raise UserError(other_settings(other, decided_by, store_path))
            if saved is None:
                note("no saved exploration with these settings: starting afresh")
            else:
                try:
                    draws = trace_draws(saved.trace)
                except ValueError as e:
                    note(f"the saved exploration's trace cannot be read back ({e}): starting afresh")
                    saved = None
        if saved is None:
            store.start(run, decided_by)
        out = Path(str(request["out"]))
        out.parent.mkdir(parents=True, exist_ok=True)
        trace_path(out).unlink(missing_ok=True)
        if saved is not None:
            write_trace(trace_path(out), saved.trace)
        workers = request.get("workers")
        simulator = open_simulator(oracle, str(request.get("executor", defaults()["executor"])),
                                   int(workers) if workers not in (None, "") else None,
                                   store_path, request.get("ray_address") or None, oracle_options)
        try:
            P = drawn_pours(draws, int(request["seed"]), int(request["batch"]))
            S = simulator.recall(P)
        except BaseException:
            simulator.close()
            store.close()
            raise
        self.session = Session(run=run, store=store, simulator=simulator, oracle_version=version,
                               params=P, scores=S)
        if truthy(request.get("progress", defaults()["progress"])):
            bar = request["bar"]
            self.session.bar = open_bar(int(bar["total"]), str(bar["unit"]),
                                        saved.iteration if saved else 0, len(self.session.params))
        return {"state": saved.state if saved else "", "run": run,
                "resumed": bool(saved), "iterations": saved.iteration if saved else 0}

    def batch(self, request: dict, n: int) -> tuple[np.ndarray, np.ndarray]:
        """The first n pours of the batch of `batch` pours of an iteration's
        attempt (attempt 0 is the iteration's own seed; a candidate tried
        after others gets a seed of its own; both from the run's `seed`),
        simulated, and added to the pool, except the first `probed`, which
        an earlier request of the same batch already added."""
        s = self.need_session()
        props = [str(p) for p in request["antecedent"]]
        iteration, attempt = int(request["iteration"]), int(request.get("attempt", 0))
        try:
            P = batch_pours(props, int(request["batch"]), int(request["seed"]), iteration,
                            attempt)[:n]
        except InvalidAntecedent as e:
            raise UserError(f"cannot sample {', '.join(props)}: {e}") from None
        t = time.perf_counter()
        S = np.asarray(s.simulator.simulate(P, progress=False), dtype=float)
        s.timings["oracle"] = s.timings.get("oracle", 0.0) + time.perf_counter() - t
        if S.shape != (n, len(load_vocabulary().expectations)):
            raise RuntimeError(f"the simulator returned scores of shape {S.shape}")
        have = int(request.get("probed", 0))
        s.params = np.vstack([s.params, P[have:]])
        s.scores = np.vstack([s.scores, S[have:]])
        return P, S

    def simulate(self, request: dict) -> dict:
        """A batch of `batch` pours of the request's antecedent (`batch`)."""
        s = self.need_session()
        _, S = self.batch(request, int(request["batch"]))
        failed = int((~np.all(np.isfinite(S), axis=1)).sum())
        return {"simulations": len(s.params), "failed": failed}

    def qualify(self, request: dict) -> dict:
        s = self.need_session()
        entries = request["antecedents"]
        mode = str(request.get("mode", defaults()["qualify"]))
        if mode not in QUALIFY:
            raise UserError(f"unknown qualify mode '{mode}' (choose {' or '.join(QUALIFY)})")
        out = ([{"id": str(e["id"]), **c} for e, c in zip(entries, s.consequents(entries, mode))]
               if entries else [])
        if truthy(request.get("batches")):      # batches of pours per antecedent, from the trace
            counts: dict[str, int] = {}
            for t in s.store.trace(s.run):
                counts[str(t["id"])] = counts.get(str(t["id"]), 0) + 1
            for o in out:
                o["batches"] = counts.get(o["id"], 1)
        failed = int((~s.valid).sum())
        return {"antecedents": out, "simulations": len(s.params), "failed": failed,
                "oracle_version": s.oracle_version}

    def checkpoint(self, request: dict) -> dict:
        """Save the iteration: Prolog's state and the trace line, whose
        draws record its pours (in the store already); the line is appended
        to the trace beside `out`."""
        s = self.need_session()
        iteration = int(request["iteration"])
        trace = rounded(dict(request["trace"]))
        s.store.save(s.run, iteration, str(request["state"]), trace)
        s.elapsed.append(round(time.monotonic() - s.started, 3))
        append_trace(Path(str(request["out"])), trace)
        if s.bar is not None:
            s.bar.show(iteration, len(s.params), int(request.get("a_new", 0)))
        return {}

    def general(self, request: dict) -> dict:
        """The general layer of every pour so far and of the pours the
        learner asks for where there are few (simulated as the
        exploration's are, seeded from `seed`), ranked with Algorithm 1's
        rules of the request (id, expectation, holds, body,
        confidence_permille); the explored antecedents named `ruleless`
        (the learning curiosity's wholes) get no rule of their own."""
        from pantarhei.bridge.learning.general_rules import confidence
        from pantarhei.bridge.learning.layers import Ranked, general_layer

        s = self.need_session()
        learned = [Ranked(str(r["id"]), tuple(sorted(str(b) for b in r["body"])),
                          str(r["expectation"]) if truthy(r["holds"]) else f"neg({r['expectation']})",
                          confidence(r["confidence_permille"]))
                   for r in request["rules"]]
        progress = s.bar is not None
        explored = None
        if "explored" in request:
            explored = [(str(e["id"]), [str(p) for p in e["antecedent"]])
                        for e in request["explored"]]
        return general_layer(learned, s.params, s.scores, int(request["seed"]),
                             lambda X: s.simulator.simulate(X, progress=progress), explored,
                             str(request["learner"]),
                             ruleless={str(a) for a in request.get("ruleless", [])})

    def end(self, request: dict) -> dict:
        s = self.session
        if s is None:
            return {}
        self.session = None
        written: dict[str, str] = {}
        try:
            if not truthy(request.get("aborted")):
                out = Path(str(request["out"]))
                trace = s.store.trace(s.run)
                write_trace(trace_path(out), trace)
                written["trace"] = str(trace_path(out))
                try:
                    plot_trace(plot_path(out), trace, str(request["oracle"]), int(request["seed"]))
                    written["plot"] = str(plot_path(out))
                except Exception as e:  # the theory and trace are written: say so and go on
                    note(f"could not plot the trace: {e}")
                s.store.finish(s.run)
                self.result.update(out=str(out), stopped=str(request.get("stopped")),
                                    explored=int(request.get("explored", 0)),
                                    a_new=int(request.get("a_new", 0)),
                                    simulations=len(s.params),
                                    failed=int((~s.valid).sum()), timings=dict(s.timings),
                                    elapsed=list(s.elapsed), wall=time.monotonic() - s.started,
                                    pours=(s.params.copy(), s.scores.copy()),
                                    budget={k: request["budget"][k] for k in ("total", "unit")},
                                    **written)
        finally:
            if s.bar is not None:
                s.bar.close()
            try:
                s.simulator.close()
            finally:
                s.store.close()
        return written


def note(text: str) -> None:
    """A line for the person exploring, on stderr."""
    print(f"pantarhei explore: {text}", file=sys.stderr)


def truthy(v: Any) -> bool:
    """A truth value of a request (a bool, as the foreign predicates read
    true and false, or true and 1 as text) as a bool."""
    return v in (True, "true", 1, "1")


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
        host = Host()
        host.register()
        eng.exploration_host = host
        eng.use_module("curiosity")
    return eng
