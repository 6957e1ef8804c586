"""oracle/simulator.py: the store first, then an executor. Nothing stored is
simulated twice (a stored failure only when asked to retry it, or when it
timed out under a shorter limit), and results are committed as they
arrive, so that a run killed mid-way keeps them."""
from __future__ import annotations

import signal
import subprocess
import sys
import time

import numpy as np

from pantarhei.oracle.faults import FaultyOracle
from pantarhei.oracle.simulator import make_simulator
from pantarhei.oracle.store import Store

from .pours import with_counts
from .stores import HANGING_RUN as SCRIPT, low_pours, simulate


def expected(P):
    o = FaultyOracle()
    return np.array([o.score(p).scores for p in P])


def test_stored_results_are_not_simulated_again(tmp_path):
    db = tmp_path / "s.sqlite"
    P = with_counts([20, 21, 22])
    with make_simulator("faulty", executor="inline", store=db) as sim:
        first = sim.simulate(P)
        assert sim.last_simulated == 3
    # a fresh simulator on the same file: every result comes from the store,
    # even for an oracle that would now crash on one of them
    Q = np.vstack([P[1], P[0], with_counts([23])[0], P[1]])
    with make_simulator("faulty", executor="inline", store=db) as sim:
        second = sim.simulate(Q)
        assert sim.last_simulated == 1
        assert sim.last_cached == [True, True, False, True]
    assert np.array_equal(second[[0, 1, 3]], first[[1, 0, 1]])
    # other settings are another key: simulated afresh
    with make_simulator("faulty", executor="inline", store=db, hang=[99]) as sim:
        sim.simulate(P)
        assert sim.last_simulated == 3


def test_failed_results_are_stored_and_can_be_retried(tmp_path):
    db = tmp_path / "s.sqlite"
    P = with_counts([30, 31])
    with make_simulator("faulty", executor="local", workers=1, store=db, crash=[31]) as sim:
        S = sim.simulate(P)
        assert np.isnan(S[1]).all()
        sim.simulate(P)
        assert sim.last_simulated == 0
    with make_simulator("faulty", executor="local", workers=1, store=db, crash=[31],
                        retry_failed=True) as sim:
        sim.simulate(P)
        assert sim.last_simulated == 1


def test_a_stored_time_out_is_no_outcome_for_a_longer_limit(tmp_path):
    db = tmp_path / "s.sqlite"
    P = low_pours(2)
    with make_simulator("synthetic", executor="local", workers=1, store=str(db),
                        timeout=0.001) as sim:
        sim.simulate(P)
        assert all(e.startswith("timed out after 0.001 s") for e in sim.last_errors)
    with make_simulator("synthetic", executor="local", workers=1, store=str(db),
                        timeout=0.001) as sim:
        sim.simulate(P)                # the same limit: the stored failure stands
        assert sim.last_cached == [True, True]
    scores, sim = simulate(db, P)      # the default limit simulates them again
    assert sim.last_simulated == 2 and np.isfinite(scores).all()


def test_results_survive_a_process_killed_mid_run(tmp_path):
    db = tmp_path / "s.sqlite"
    P = with_counts([40, 41, 42, 43, 44])
    np.save(tmp_path / "P.npy", P)
    proc = subprocess.Popen([sys.executable, "-c", SCRIPT, str(db), str(tmp_path / "P.npy")])
    try:
        deadline = time.time() + 60
        while time.time() < deadline:
            if db.exists():
                with Store(db) as st:
                    if st.count() >= 3:
                        break
            time.sleep(0.2)
        time.sleep(0.5)
        assert proc.poll() is None            # stuck on the hanging one
    finally:
        proc.send_signal(signal.SIGKILL)
        proc.wait()
    with make_simulator("faulty", executor="inline", store=db, hang=[43]) as sim:
        S = sim.simulate(P[:3])
        assert sim.last_simulated == 0
    assert np.array_equal(S, expected(P[:3]))
