"""Nothing computed is lost: every fault of the store is found out before
the first pour, or the results of the run are written to a recovery file
named on the error line (oracle/store.py, oracle/simulator.py)."""
from __future__ import annotations

import json
import os
import shutil
import sqlite3
import stat
import subprocess
import sys
import tempfile
from pathlib import Path

import numpy as np
import pytest

from pantarhei.oracle import baseline
from pantarhei.oracle.generative import sample
from pantarhei.oracle.simulator import make_simulator
from pantarhei.oracle.store import Store, StoreError
from pantarhei.oracle.store_schema import COLUMNS

from ..conftest import assert_one_line_error, run_cli

ROOT = os.geteuid() == 0


def pours(n: int, seed: int = 1) -> np.ndarray:
    return sample(["pour_low"], n, seed)


def simulate(store: Path, P: np.ndarray, **kw) -> tuple[np.ndarray, object]:
    with make_simulator("synthetic", executor="inline", store=str(store), **kw) as sim:
        return sim.simulate(P), sim


def damage(path: Path) -> None:
    """Overwrite the third page of an SQLite file (of the results' b-tree):
    the file still opens and takes writes to other tables."""
    data = bytearray(path.read_bytes())
    assert len(data) > 3 * 4096
    data[2 * 4096:3 * 4096] = b"\xab" * 4096
    path.write_bytes(bytes(data))


def test_a_damaged_store_is_refused_in_one_line_before_any_pour(tmp_path):
    db = tmp_path / "s.sqlite"
    simulate(db, pours(40))
    damage(db)
    with pytest.raises(StoreError, match="is damaged"):
        Store(db)
    junk = tmp_path / "junk.sqlite"
    junk.write_text("not a database at all\n" * 200)
    with pytest.raises(StoreError, match="is damaged .*file is not a database"):
        Store(junk)
    # the command says so in one line, and simulates nothing
    r = run_cli("simulate", "--antecedent", "pour_low", "-n", "1", "--store", str(db))
    line = assert_one_line_error(r, 1)
    assert "is damaged" in line and str(db) in line


def test_an_older_layout_is_migrated_and_another_refused(tmp_path):
    db = tmp_path / "old.sqlite"
    P = pours(2)
    scores, _ = simulate(tmp_path / "new.sqlite", P)
    with Store(tmp_path / "new.sqlite") as st:
        rows = st.db.execute("SELECT key, oracle, version, settings, params, scores "
                             "FROM simulation_results").fetchall()
    con = sqlite3.connect(db)         # the table as it was before status, record, error, ...
    con.execute("CREATE TABLE simulation_results (key TEXT PRIMARY KEY, oracle TEXT NOT NULL, "
                "version TEXT NOT NULL, settings TEXT NOT NULL, params TEXT NOT NULL, scores TEXT)")
    con.executemany("INSERT INTO simulation_results VALUES (?, ?, ?, ?, ?, ?)", rows)
    con.execute("INSERT INTO simulation_results VALUES ('lost', 'synthetic', '0', '{}', '[]', NULL)")
    con.commit()
    con.close()
    again, sim = simulate(db, P)
    assert sim.last_cached == [True, True] and np.array_equal(again, scores)
    with Store(db) as st:
        assert st.get("lost").status == "failed" and st.count("ok") == 2

    other = tmp_path / "other.sqlite"
    con = sqlite3.connect(other)
    con.execute("CREATE TABLE simulation_results (id INTEGER PRIMARY KEY, blob TEXT)")
    con.commit()
    con.close()
    with pytest.raises(StoreError, match="another layout .*no key, oracle, version, params, scores"):
        Store(other)


def test_a_failure_mid_run_keeps_the_results_in_a_recovery_file(tmp_path):
    db = tmp_path / "s.sqlite"
    Store(db).close()
    con = sqlite3.connect(db)         # the disk fills after the second result
    con.execute("CREATE TRIGGER full BEFORE INSERT ON simulation_results WHEN "
                "(SELECT COUNT(*) FROM simulation_results) >= 2 "
                "BEGIN SELECT RAISE(ABORT, 'database or disk is full'); END")
    con.commit()
    con.close()
    P = pours(5)
    with pytest.raises(StoreError, match="failed during the run .*disk is full.*the 3 results") as e:
        simulate(db, P)
    recovery = Path(str(e.value).split(" are in ")[1].split(" ")[0])
    assert recovery.parent == tmp_path and recovery.is_file()
    kept = [json.loads(line) for line in recovery.read_text().splitlines()]
    assert len(kept) == 3 and all(set(r) == set(COLUMNS) and r["status"] == "ok" for r in kept)

    con = sqlite3.connect(db)         # room again: the next run takes them back
    con.execute("DROP TRIGGER full")
    con.commit()
    con.close()
    scores, sim = simulate(db, P)
    assert sim.last_cached == [True] * 5 and np.isfinite(scores).all()
    assert not recovery.exists()


@pytest.mark.slow
def test_the_command_names_the_recovery_file_and_exits_non_zero(tmp_path):
    db = tmp_path / "s.sqlite"
    Store(db).close()
    con = sqlite3.connect(db)
    con.execute("CREATE TRIGGER full BEFORE INSERT ON simulation_results "
                "BEGIN SELECT RAISE(ABORT, 'database or disk is full'); END")
    con.commit()
    con.close()
    r = run_cli("simulate", "--antecedent", "pour_low", "-n", "2", "--executor", "inline",
                "--store", str(db))
    line = assert_one_line_error(r, 1)
    recovery = [f for f in tmp_path.iterdir() if ".recovered-" in f.name]
    assert len(recovery) == 1 and str(recovery[0]) in line
    assert len(recovery[0].read_text().splitlines()) == 2


def test_a_stored_time_out_is_no_outcome_for_a_longer_limit(tmp_path):
    db = tmp_path / "s.sqlite"
    P = pours(2)
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


# -- stores that can only be read ----------------------------------------------------------

@pytest.fixture
def shared_dir():
    """A folder another user can reach (pytest's tmp_path is private to root)."""
    d = Path(tempfile.mkdtemp(prefix="pantarhei-store-"))
    d.chmod(0o755)
    yield d
    for f in [d, *d.rglob("*")]:
        f.chmod(0o755 if f.is_dir() else 0o644)
    shutil.rmtree(d)


def as_reader(argv: list[str]) -> subprocess.CompletedProcess:
    """Run argv as a user for whom read-only files are read-only: this one,
    or nobody when this is root (whom permissions do not stop)."""
    if ROOT:
        if shutil.which("setpriv") is None:
            pytest.skip("running as root without setpriv: cannot be a user that permissions stop")
        argv = ["setpriv", "--reuid=65534", "--regid=65534", "--clear-groups", *argv]
    env = {**os.environ, **baseline.ENVIRONMENT}      # started with the math it pins
    return subprocess.run(argv, capture_output=True, text=True, env=env, timeout=300,
                          stdin=subprocess.DEVNULL, cwd="/")


READ = """
import sys
from pantarhei.oracle.generative import sample
from pantarhei.oracle.simulator import make_simulator
from pantarhei.oracle.store import StoreError
try:
    with make_simulator("synthetic", executor="inline", store=sys.argv[1]) as sim:
        sim.simulate(sample(["pour_low"], 4, 1)[:int(sys.argv[2])])
        print(sim.store.writable, sum(sim.last_cached), sim.last_simulated)
except StoreError as e:
    print("StoreError:", e)
"""


def read_only(path: Path) -> None:
    path.chmod(stat.S_IRUSR | stat.S_IRGRP | stat.S_IROTH | (stat.S_IXUSR | stat.S_IXGRP | stat.S_IXOTH
                                                            if path.is_dir() else 0))


@pytest.mark.parametrize("what", ["file", "folder"])
def test_a_read_only_store_serves_its_pours_and_refuses_new_ones_before_simulating(shared_dir, what):
    db = shared_dir / "s.sqlite"
    simulate(db, pours(4)[:3])
    for f in shared_dir.iterdir():       # a cleanly closed store is its file alone
        assert f == db, f
    read_only(db if what == "file" else shared_dir)
    r = as_reader([sys.executable, "-c", READ, str(db), "3"])
    assert r.returncode == 0 and r.stdout.split() == ["False", "3", "0"], r.stdout + r.stderr
    r = as_reader([sys.executable, "-c", READ, str(db), "4"])     # one pour it does not hold
    assert r.stdout.startswith("StoreError: the store") and "cannot be written" in r.stdout
    assert "1 of the pours asked for are not in it" in r.stdout
    if what == "folder":
        new = shared_dir / "new.sqlite"
        r = as_reader([sys.executable, "-c", READ, str(new), "1"])
        assert r.stdout.startswith("StoreError: cannot create the store"), r.stdout + r.stderr
        assert not new.exists()
