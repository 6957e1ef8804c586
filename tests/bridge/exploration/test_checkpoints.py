"""The exploration's saved state (bridge/exploration/checkpoints.py): never lose
work. A real exploration killed with SIGKILL mid-run resumes and ends with
the same theory as an uninterrupted run with the same seed; the run key
and the checkpoints of the store, read back."""
from __future__ import annotations

import json
import os
import signal
import sqlite3
import subprocess
import sys
import time
from pathlib import Path


from tests.conftest import run_cli

# Algorithm 1's rules alone: the general layer is learned from the pours
# once the loop ends, whether it ran at once or was resumed (test_explore_call.py)
ARGS = ["explore", "--curiosity", "discover", "--oracle", "synthetic", "--executor", "inline",
        "--budget", "10",
        "--seed", "3", "--no-progress", "--no-general"]


def saved_iterations(store: Path) -> int:
    if not store.exists():
        return 0
    try:
        with sqlite3.connect(store, timeout=5) as db:
            row = db.execute("SELECT max(iterations) FROM exploration_runs").fetchone()
    except sqlite3.OperationalError:      # the tables are not there yet
        return 0
    return int(row[0] or 0)


def test_killed_exploration_resumes_to_the_same_theory(tmp_path):
    whole = run_cli(*ARGS, "--out", str(tmp_path / "whole.pl"),
                    "--store", str(tmp_path / "whole.sqlite"))
    assert whole.code == 0, whole.err
    expected = (tmp_path / "whole.pl").read_text()

    store, out = tmp_path / "killed.sqlite", tmp_path / "killed.pl"
    env = {**os.environ, "PANTARHEI_SYNTHETIC_DELAY": "0.01"}
    proc = subprocess.Popen([sys.executable, "-m", "pantarhei.bridge", *ARGS, "--out", str(out),
                             "--store", str(store)], env=env, stdin=subprocess.DEVNULL,
                            stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    try:
        deadline = time.monotonic() + 120
        while saved_iterations(store) < 3 and proc.poll() is None and time.monotonic() < deadline:
            time.sleep(0.05)
        assert proc.poll() is None, "the exploration ended before it could be killed"
        proc.send_signal(signal.SIGKILL)
        proc.wait(timeout=30)
    finally:
        if proc.poll() is None:
            proc.kill()
    done = saved_iterations(store)
    assert 3 <= done
    assert not out.exists()

    resumed = run_cli(*ARGS, "--resume", "--out", str(out), "--store", str(store))
    assert resumed.code == 0, resumed.err
    assert out.read_text() == expected
    trace = (tmp_path / "killed.trace.jsonl").read_text()
    assert done < len(trace.splitlines()) <= 10     # fewer batches when probes set candidates aside
    # no timings in the trace: the same run writes the same trace, byte for byte
    assert trace == (tmp_path / "whole.trace.jsonl").read_text()


def explore_at_the_prompt(budget: int, out: Path, store: Path, resume: bool = False):
    """The discovering curiosity without the priors' batch (prior_batch(0),
    an option of explore/1 alone), run by explore/1 at the Prolog prompt."""
    options = (f"curiosity(discover), oracle(synthetic), executor(inline), progress(false), "
               f"general(false), seed(4), prior_batch(0), budget({budget}), resume({str(resume).lower()}), "
               f"out('{out}'), store('{store}')")
    return run_cli("prolog", "-g", f"explore([{options}])")


# Without the priors' batch, which is the last of the budget it was
# explored in (below).
def test_resume_of_a_finished_run_and_a_longer_one(tmp_path):
    out, store = tmp_path / "t.pl", tmp_path / "s.sqlite"
    assert explore_at_the_prompt(4, out, store).code == 0
    # resuming with a larger budget continues where it stopped ...
    longer = explore_at_the_prompt(7, out, store, resume=True)
    assert longer.code == 0, longer.err
    continued = out.read_text()
    # ... and ends where a run with that budget from scratch ends
    fresh = explore_at_the_prompt(7, tmp_path / "f.pl", tmp_path / "f.sqlite")
    assert fresh.code == 0
    assert continued == (tmp_path / "f.pl").read_text()


def test_a_longer_run_continues_after_the_priors_batch(tmp_path):
    out = tmp_path / "t.pl"
    common = ["--out", str(out), "--store", str(tmp_path / "s.sqlite")]
    short = ["explore", "--curiosity", "discover", "--oracle", "synthetic", "--executor", "inline",
             "--no-progress",
             "--no-general", "--seed", "4"]
    assert run_cli(*short, "--budget", "4", *common).code == 0
    before = out.with_suffix(".trace.jsonl").read_text().splitlines()
    assert json.loads(before[-1])["via"] == "prior"
    longer = run_cli(*short, "--budget", "7", "--resume", *common)
    assert longer.code == 0, longer.err
    after = out.with_suffix(".trace.jsonl").read_text().splitlines()
    # the shorter run's steps, its priors' batch last, then the curiosity
    # goes on; the priors are explored once
    assert after[:len(before)] == before and len(after) > len(before)
    assert [json.loads(line)["via"] for line in after].count("prior") == 1


def test_resume_with_nothing_saved_starts_afresh(tmp_path):
    r = run_cli("explore", "--curiosity", "discover", "--oracle", "synthetic", "--executor",
                "inline", "--no-progress",
                "--no-general", "--budget", "2", "--resume", "--out", str(tmp_path / "t.pl"),
                "--store", str(tmp_path / "s.sqlite"))
    assert r.code == 0
    assert "starting afresh" in r.err
    assert (tmp_path / "t.pl").exists()


def test_a_saved_run_whose_trace_lacks_its_draws_starts_afresh(tmp_path):
    """A run saved before traces recorded their draws cannot have its pours
    drawn again: --resume says so in one line and explores afresh."""
    out, store = tmp_path / "t.pl", tmp_path / "s.sqlite"
    args = [*ARGS[:ARGS.index("--budget") + 1], "3", *ARGS[ARGS.index("--budget") + 2:],
            "--out", str(out), "--store", str(store)]
    assert run_cli(*args).code == 0
    expected = out.read_text()
    with sqlite3.connect(store) as db:
        for run, iteration, trace in db.execute("SELECT run, iteration, trace FROM "
                                                "exploration_checkpoints").fetchall():
            line = json.loads(trace)
            del line["draws"]
            db.execute("UPDATE exploration_checkpoints SET trace = ? WHERE run = ? AND iteration = ?",
                       (json.dumps(line), run, iteration))
    again = run_cli(*args, "--resume")
    assert again.code == 0, again.err
    assert "does not record its draws" in again.err and "starting afresh" in again.err
    assert out.read_text() == expected


def test_the_store_gives_back_every_iteration_it_committed(tmp_path):
    import sqlite3

    from pantarhei.bridge.exploration.checkpoints import ExplorationStore, run_key

    settings = {"seed": 3, "oracle": "synthetic", "initial": ["pour_low"]}
    run = run_key(settings)
    assert run == run_key(dict(reversed(settings.items())))      # order does not matter
    assert run != run_key({**settings, "seed": 4})
    # a store of the older layout, with a second copy of the pours
    with sqlite3.connect(tmp_path / "s.sqlite") as db:
        db.execute("CREATE TABLE exploration_simulations (run TEXT, iteration INTEGER, rows INTEGER, "
                   "params BLOB, scores BLOB)")
    with ExplorationStore(tmp_path / "s.sqlite") as store:
        assert store.latest(run) is None
        store.start(run, settings)
        for i in (1, 2):
            store.save(run, i, f"st({i})", {"iteration": i})
    with ExplorationStore(tmp_path / "s.sqlite") as store:            # read back from the file
        saved = store.latest(run)
        assert (saved.iteration, saved.state, saved.finished) == (2, "st(2)", False)
        assert saved.trace == store.trace(run) == [{"iteration": 1}, {"iteration": 2}]
        store.finish(run)
        assert store.latest(run).finished
        store.start(run, settings)                                  # afresh: the saved state goes
        assert store.latest(run) is None and store.exists(run)
    with sqlite3.connect(tmp_path / "s.sqlite") as db:               # the pours once: the simulator's
        tables = {t for (t,) in db.execute("SELECT name FROM sqlite_master WHERE type = 'table'")}
    assert "exploration_simulations" not in tables
