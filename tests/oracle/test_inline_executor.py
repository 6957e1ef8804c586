"""oracle/inline_executor.py: simulations in this process, one after the
other, an exception retried once and then recorded as the task's error."""
from __future__ import annotations

import os
from collections import Counter

import numpy as np

from pantarhei.oracle.base import Oracle, Outcome
from pantarhei.oracle.inline_executor import InlineExecutor


class Troubled(Oracle):
    """Scores p[0] / 10, but raises on its first try of the pours in
    `once` and on every try of those in `always`."""
    name = "troubled"

    def __init__(self, once=(), always=()):
        self.once, self.always = set(once), set(always)
        self.tries: Counter = Counter()

    def score(self, p):
        k = int(p[0])
        self.tries[k] += 1
        if k in self.always or (k in self.once and self.tries[k] == 1):
            raise ValueError(f"pour {k} went wrong\nin detail")
        return Outcome(np.full(9, k / 10), {"pid": os.getpid()})


def test_tasks_run_here_in_order_and_a_failure_is_retried_once():
    oracle = Troubled(once=[2], always=[3])
    done = []
    ex = InlineExecutor()
    try:
        ex.run(oracle, [(10 + k, np.full(30, float(k))) for k in range(5)], done.append, None)
    finally:
        ex.close()
    assert [d.index for d in done] == [10, 11, 12, 13, 14]
    assert [d.attempts for d in done] == [1, 1, 2, 2, 1]
    assert [d.error for d in done] == [None] * 3 + ["ValueError: pour 3 went wrong", None]
    assert done[3].scores is None and done[3].record is None
    assert np.array_equal(done[2].scores, np.full(9, 0.2))
    assert all(d.record["pid"] == os.getpid() for d in done if d.record)   # in this process
    assert oracle.tries == Counter({0: 1, 1: 1, 2: 2, 3: 2, 4: 1})
