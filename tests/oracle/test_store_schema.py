"""oracle/store_schema.py: a store of an older layout is migrated (its
results kept, their status derived), one of another layout refused."""
from __future__ import annotations

import sqlite3

import numpy as np
import pytest

from pantarhei.oracle.store import Store, StoreError

from .stores import low_pours, simulate


def test_an_older_layout_is_migrated_and_another_refused(tmp_path):
    db = tmp_path / "old.sqlite"
    P = low_pours(2)
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
