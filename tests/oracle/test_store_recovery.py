"""oracle/store_recovery.py: the results a store could not keep mid-run
are written to a recovery file named on the error line, and taken back by
the next run."""
from __future__ import annotations

import json
import sqlite3
from pathlib import Path

import numpy as np
import pytest

from pantarhei.oracle.store import Store, StoreError
from pantarhei.oracle.store_schema import COLUMNS

from ..conftest import assert_one_line_error, run_cli
from .stores import low_pours, simulate


def test_a_failure_mid_run_keeps_the_results_in_a_recovery_file(tmp_path):
    db = tmp_path / "s.sqlite"
    Store(db).close()
    con = sqlite3.connect(db)         # the disk fills after the second result
    con.execute("CREATE TRIGGER full BEFORE INSERT ON simulation_results WHEN "
                "(SELECT COUNT(*) FROM simulation_results) >= 2 "
                "BEGIN SELECT RAISE(ABORT, 'database or disk is full'); END")
    con.commit()
    con.close()
    P = low_pours(5)
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
