"""oracle/local_executor.py: simulations that really crash or hang kill
their worker process, are recorded as failed, retried once in a fresh one,
and never stop the others."""
from __future__ import annotations

import time

import numpy as np

from pantarhei.oracle.faults import FaultyOracle
from pantarhei.oracle.simulator import make_simulator
from pantarhei.oracle.store import Store

from .pours import with_counts


def expected(P):
    o = FaultyOracle()
    return np.array([o.score(p).scores for p in P])


def test_a_crash_and_a_hang_fail_alone(tmp_path):
    P = with_counts([10, 11, 12, 13, 14, 15, 16])
    db = tmp_path / "s.sqlite"
    t0 = time.perf_counter()
    with make_simulator("faulty", executor="local", workers=2, store=db, timeout=2.0,
                        crash=[11], hang=[13], flaky=[15], marker_dir=str(tmp_path)) as sim:
        S = sim.simulate(P)
        errors = sim.last_errors
        assert sim.last_simulated == 7
    elapsed = time.perf_counter() - t0
    ok = [0, 2, 4, 5, 6]
    assert np.isnan(S[1]).all() and np.isnan(S[3]).all()
    assert "SIGSEGV" in errors[1]
    assert "timed out" in errors[3]
    assert np.array_equal(S[ok], expected(P)[ok])        # the others are unaffected
    # the flaky one crashed once, really, and its retry succeeded
    assert len(list(tmp_path.glob("*"))) == 2 and errors[5] is None
    # the hang was given two chances of 2 s each, no more
    assert elapsed < 30
    with Store(db) as st:
        failed = [a for (a,) in st.db.execute("SELECT attempts FROM simulation_results "
                                              "WHERE status = 'failed'")]
        assert st.count() == 7 and st.count("failed") == 2
        assert failed == [2, 2]
        attempts = [a for (a,) in st.db.execute("SELECT attempts FROM simulation_results "
                                                "WHERE status = 'ok' ORDER BY attempts")]
        assert attempts == [1, 1, 1, 1, 2]
