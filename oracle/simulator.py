"""Simulate many parameterizations: the store first, then an executor.

    from pantarhei.oracle.simulator import make_simulator
    with make_simulator("pybullet", store="pantarhei.sqlite") as sim:
        scores = sim.simulate(P, progress=True)   # (n, 9); NaN rows failed twice
        records = sim.last_records                 # what happened, per row

A parameterization already in the store (same oracle name, version and
settings) is returned without simulating; new results are committed as
they arrive, so an interrupted run loses only the simulations in flight.
"""
from __future__ import annotations

import re
from pathlib import Path
from typing import Any, Optional

import numpy as np

from pantarhei.oracle.base import Oracle, make_oracle
from pantarhei.oracle.execution import Done, Executor, OnResult
from pantarhei.oracle.executors import make_executor
from pantarhei.oracle.result_keys import key, oracle_tag
from pantarhei.oracle.store import DEFAULT_STORE, Store
from pantarhei.theory import defaults
from pantarhei.theory.lexicon import load_vocabulary

#: Seconds a single simulation may take before it counts as hung.
DEFAULT_TIMEOUT = 120.0
#: The error of a simulation stopped by the timeout (local_executor, ray_executor).
_TIMED_OUT = re.compile(r"^timed out after ([0-9.eE+-]+) s$")


class Simulator:
    def __init__(self, oracle: Oracle, executor: Executor, store: Optional[Store],
                 timeout: Optional[float] = DEFAULT_TIMEOUT, retry_failed: bool = False):
        self.oracle = oracle
        self.executor = executor
        self.store = store
        self.timeout = timeout
        self.retry_failed = retry_failed
        self.tag = oracle_tag(oracle)
        #: Per row of the last `simulate`: the record (None if it failed).
        self.last_records: list[Optional[dict[str, Any]]] = []
        #: Per row of the last `simulate`: the error of a failed simulation.
        self.last_errors: list[Optional[str]] = []
        #: Per row of the last `simulate`: whether it came from the store.
        self.last_cached: list[bool] = []
        #: How many simulations the last `simulate` ran (not from the store).
        self.last_simulated = 0

    def keys(self, P: np.ndarray) -> list[str]:
        return [key(p, self.tag) for p in P]

    def simulate(self, P: np.ndarray, progress: bool = False) -> np.ndarray:
        """Scores (n, 9) of the parameterizations P (n, 30); a row of NaN for
        a simulation that failed twice."""
        P = np.atleast_2d(np.asarray(P, dtype=float))
        n = len(P)
        keys = self.keys(P)
        scores = np.full((n, len(load_vocabulary().expectations)), np.nan)
        records: list[Optional[dict[str, Any]]] = [None] * n
        errors: list[Optional[str]] = [None] * n
        cached = [False] * n
        rows_of: dict[str, list[int]] = {}
        for i, k in enumerate(keys):
            rows_of.setdefault(k, []).append(i)
        stored = self.store.get_many(rows_of) if self.store else {}
        todo: list[tuple[int, np.ndarray]] = []
        for k, rows in rows_of.items():
            r = stored.get(k)
            if r is not None and (r.ok or not self.retry_failed) and not self._cut_short(r.error):
                for i in rows:
                    scores[i], records[i], errors[i], cached[i] = r.scores, r.record, r.error, True
            else:
                todo.append((rows[0], P[rows[0]]))
        self._schedule(todo)
        bar = _progress_bar(n, n - sum(len(rows_of[keys[i]]) for i, _ in todo)) if progress else None

        def on_result(d: Done) -> None:
            k = keys[d.index]
            if self.store is not None:
                self.store.put(k, self.oracle, P[d.index], scores=d.scores, record=d.record,
                               error=d.error, attempts=d.attempts, seconds=d.seconds)
            for i in rows_of[k]:
                if d.scores is not None:
                    scores[i] = d.scores
                records[i], errors[i] = d.record, d.error
            if bar is not None:
                bar.update(len(rows_of[k]))
                if d.error:
                    bar.set_postfix_str("failed: " + d.error[:40])

        self._run(todo, on_result, bar)
        self.last_records, self.last_errors, self.last_cached = records, errors, cached
        self.last_simulated = len(todo)
        return scores

    def recall(self, P: np.ndarray) -> np.ndarray:
        """Scores (n, 9) of pours simulated before, as the store holds
        them (a failure, whatever stopped it, a row of NaN); a pour it
        does not hold is simulated."""
        P = np.atleast_2d(np.asarray(P, dtype=float))
        keys = self.keys(P)
        stored = self.store.get_many(keys) if self.store else {}
        scores = np.full((len(P), len(load_vocabulary().expectations)), np.nan)
        lost = []
        for i, k in enumerate(keys):
            if k in stored:
                scores[i] = stored[k].scores
            else:
                lost.append(i)
        if lost:
            scores[lost] = self.simulate(P[lost])
        return scores

    def _schedule(self, todo: list[tuple[int, np.ndarray]]) -> None:
        """StoreError if the store cannot take the results of `todo` (before
        the first pour); then `todo` longest first."""
        if self.store is not None:       # a store that cannot take them: before the first pour
            self.store.require_writable(len(todo))
        cost = getattr(self.oracle, "cost", None)
        if cost is not None:
            # longest first, so that no long simulation is left running alone at the end
            todo.sort(key=lambda t: -float(cost(t[1])))

    def _run(self, todo: list[tuple[int, np.ndarray]], on_result: OnResult,
             bar: Any) -> None:
        """Simulate `todo`; StoreError after the last pour (naming the
        recovery file) if writing failed."""
        try:
            self.executor.run(self.oracle, todo, on_result, self.timeout)
        except BaseException:
            if self.store is not None:
                self.store.save_unsaved()
            raise
        finally:
            if bar is not None:
                bar.close()
        if self.store is not None:      # StoreError naming the recovery file if writing failed
            self.store.settle()

    def _cut_short(self, error: Optional[str]) -> bool:
        """Did a stored failure time out under a shorter limit than this
        simulator's? Then it is no outcome of the pour: simulate it again."""
        m = _TIMED_OUT.match(error or "")
        return m is not None and (self.timeout is None or self.timeout > float(m.group(1)))

    def close(self) -> None:
        self.executor.close()
        if self.store is not None:
            self.store.close()

    def __enter__(self) -> "Simulator":
        return self

    def __exit__(self, *exc: Any) -> None:
        self.close()


def _progress_bar(n: int, done: int) -> Any:
    """A progress bar of n simulations, `done` of them from the store."""
    from tqdm import tqdm
    return tqdm(total=n, initial=done, unit="sim", desc="simulating", dynamic_ncols=True)


def make_simulator(oracle: str | Oracle | None = None, executor: str | None = None,
                   workers: Optional[int] = None, store: str | Path | Store | None = DEFAULT_STORE,
                   ray_address: Optional[str] = None, timeout: Optional[float] = DEFAULT_TIMEOUT,
                   retry_failed: bool = False, **oracle_options: Any) -> Simulator:
    """A simulator of the named oracle (built with `oracle_options`) on the
    named executor ("local" worker processes, "ray", or "inline"), storing
    results in the SQLite file `store` (None: nothing stored). The oracle,
    the executor and the store are by default theory/defaults.pl's."""
    oracle = str(defaults()["oracle"]) if oracle is None else oracle
    executor = str(defaults()["executor"]) if executor is None else executor
    o = make_oracle(oracle, **oracle_options) if isinstance(oracle, str) else oracle
    st = store if isinstance(store, Store) or store is None else Store(store)
    try:
        ex = make_executor(executor, workers=workers, ray_address=ray_address)
    except BaseException:
        if st is not None and not isinstance(store, Store):
            st.close()
        raise
    return Simulator(o, ex, st, timeout=timeout, retry_failed=retry_failed)
