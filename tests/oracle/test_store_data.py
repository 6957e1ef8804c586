"""oracle/store.py reads a store as data: a row whose scores are not nine
finite numbers in [0, 1] (edited by hand, or by another program) is never
served as a simulation, but simulated again; and an unrelated SQLite file
is refused before anything is added to it."""
from __future__ import annotations

import hashlib
import json
import sqlite3

import numpy as np
import pytest

from pantarhei.oracle.store import Store
from pantarhei.oracle.store_file import StoreError

from tests.conftest import assert_one_line_error, run_cli
from .stores import low_pours, simulate


@pytest.mark.parametrize("scores", ["[1e999,0,0,0,0,0,0,0,0]", "[-7,0,0,0,0,0,0,0,0]",
                                    "[5,0,0,0,0,0,0,0,0]", "[0.5,0.5,0.5]",
                                    "[0,0,0,0,0,0,0,0,0,0]", '["a",0,0,0,0,0,0,0,0]',
                                    "[true,0,0,0,0,0,0,0,0]", "[null,0,0,0,0,0,0,0,0]",
                                    "{}", "not json", "[[[[[[[[[[[[[[[[[[[[[[[]]]]]]]]]]]]]]]]]]]]]]]"])
def test_a_row_that_is_not_nine_scores_is_simulated_again_never_counted(tmp_path, scores):
    db = tmp_path / "s.sqlite"
    P = low_pours(3)
    first, _ = simulate(db, P)
    with sqlite3.connect(db) as con:
        (key,) = con.execute("SELECT key FROM simulation_results ORDER BY key LIMIT 1").fetchone()
        con.execute("UPDATE simulation_results SET scores = ? WHERE key = ?", (scores, key))
    with Store(db) as store:
        assert store.get(key) is None and store.refused == 1
    again, sim = simulate(db, P)
    assert sorted(sim.last_cached) == [False, True, True]
    assert np.array_equal(again, first)          # the same pours, simulated again
    with Store(db) as store:
        assert store.get(key) is not None and store.refused == 0


def test_an_edited_score_is_not_printed_as_simulated(tmp_path):
    """simulate never prints a store's 5 as a score (it simulates the pour)."""
    db = tmp_path / "s.sqlite"
    args = ("simulate", "--antecedent", "pour_low", "-n", "1", "--executor", "inline",
            "--store", str(db), "--json")
    r = run_cli(*args)
    assert r.code == 0, r.err
    with sqlite3.connect(db) as con:
        con.execute("UPDATE simulation_results SET scores = '[5,5,5,5,5,5,5,5,5]'")
    r = run_cli(*args)
    assert r.code == 0, r.err
    scores = json.loads(r.out)[0]["scores"]
    assert all(0 <= v <= 1 for v in scores.values())


def _digest(path):
    return hashlib.sha256(path.read_bytes()).hexdigest()


def test_another_programs_database_is_refused_and_left_as_it_was(tmp_path):
    db = tmp_path / "photos.sqlite"
    with sqlite3.connect(db) as con:
        con.execute("CREATE TABLE albums (name TEXT)")
        con.execute("INSERT INTO albums VALUES ('summer')")
    before = _digest(db)
    with pytest.raises(StoreError, match="another program's database"):
        Store(db)
    r = run_cli("simulate", "--antecedent", "pour_low", "-n", "1", "--executor", "inline",
                "--store", str(db))
    assert "another program's database (tables albums" in assert_one_line_error(r, 1)
    r = run_cli("explore", "--oracle", "synthetic", "--pours", "4", "--executor", "inline",
                "--no-progress", "--store", str(db), "--out", str(tmp_path / "t.pl"))
    assert r.code != 0 and "another program's database" in r.err and "Traceback" not in r.err
    assert _digest(db) == before and not (tmp_path / "t.pl").exists()
    assert sorted(p.name for p in tmp_path.iterdir()) == ["photos.sqlite"]


def test_a_store_with_the_projects_tables_beside_others_is_a_store(tmp_path):
    db = tmp_path / "s.sqlite"
    simulate(db, low_pours(1))
    with sqlite3.connect(db) as con:
        con.execute("CREATE TABLE notes (x)")
    _, sim = simulate(db, low_pours(1))
    assert sim.last_cached == [True]
