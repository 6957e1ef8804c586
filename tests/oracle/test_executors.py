"""Simulations that really crash or hang are recorded as failed, retried once,
and never stop the others; nothing stored is simulated twice."""
from __future__ import annotations

import os
import signal
import subprocess
import sys
import textwrap
import time

import numpy as np

from pantarhei.oracle.faults import FaultyOracle
from pantarhei.theory.lexicon import load_vocabulary

COUNT = load_vocabulary().parameter("particle_count").index
from pantarhei.oracle.generative import sample
from pantarhei.oracle.simulator import make_simulator
from pantarhei.oracle.store import Store


def params(counts):
    P = sample([], len(counts), seed=7)
    P[:, COUNT] = counts
    return P


def expected(P):
    o = FaultyOracle()
    return np.array([o.score(p).scores for p in P])


def test_a_crash_and_a_hang_fail_alone(tmp_path):
    P = params([10, 11, 12, 13, 14, 15, 16])
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


def test_stored_results_are_not_simulated_again(tmp_path):
    db = tmp_path / "s.sqlite"
    P = params([20, 21, 22])
    with make_simulator("faulty", executor="inline", store=db) as sim:
        first = sim.simulate(P)
        assert sim.last_simulated == 3
    # a fresh simulator on the same file: every result comes from the store,
    # even for an oracle that would now crash on one of them
    Q = np.vstack([P[1], P[0], params([23])[0], P[1]])
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
    P = params([30, 31])
    with make_simulator("faulty", executor="local", workers=1, store=db, crash=[31]) as sim:
        S = sim.simulate(P)
        assert np.isnan(S[1]).all()
        sim.simulate(P)
        assert sim.last_simulated == 0
    with make_simulator("faulty", executor="local", workers=1, store=db, crash=[31],
                        retry_failed=True) as sim:
        sim.simulate(P)
        assert sim.last_simulated == 1


SCRIPT = textwrap.dedent("""
    import sys
    import numpy as np
    from pantarhei.oracle.simulator import make_simulator
    P = np.load(sys.argv[2])
    with make_simulator("faulty", executor="local", workers=1, store=sys.argv[1],
                        timeout=600, hang=[43]) as sim:
        sim.simulate(P)
""")


def test_results_survive_a_process_killed_mid_run(tmp_path):
    db = tmp_path / "s.sqlite"
    P = params([40, 41, 42, 43, 44])
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


def test_workers_go_when_their_process_is_killed(tmp_path):
    # the worker stuck in the hanging simulation above must not outlive it
    P = params([43])
    np.save(tmp_path / "P.npy", P)
    proc = subprocess.Popen([sys.executable, "-c", SCRIPT, str(tmp_path / "s.sqlite"),
                             str(tmp_path / "P.npy")])
    time.sleep(4)
    children = subprocess.run(["pgrep", "-P", str(proc.pid)], capture_output=True, text=True)
    workers = [int(x) for x in children.stdout.split()]
    assert workers
    proc.send_signal(signal.SIGKILL)
    proc.wait()
    deadline = time.time() + 10
    while time.time() < deadline and any(_alive(w) for w in workers):
        time.sleep(0.2)
    assert not any(_alive(w) for w in workers)


def _alive(pid: int) -> bool:
    try:
        os.kill(pid, 0)
    except ProcessLookupError:
        return False
    # a zombie waiting for its reaper is gone for our purpose
    try:
        with open(f"/proc/{pid}/stat") as f:
            return f.read().split()[2] != "Z"
    except FileNotFoundError:
        return False
