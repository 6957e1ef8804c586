"""oracle/store.py: a store that can only be read (a read-only file or
folder) serves the pours it holds and refuses new ones before simulating.
(Its damaged files are tested in test_store_file, its older layouts in
test_store_schema, its recovery files in test_store_recovery.)"""
from __future__ import annotations

import os
import shutil
import stat
import subprocess
import sys
import tempfile
from pathlib import Path

import pytest

from pantarhei.oracle import baseline

from .stores import low_pours, simulate

ROOT = os.geteuid() == 0


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
    simulate(db, low_pours(4)[:3])
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
