"""The exploration's state, kept in the oracle's SQLite store file.

Tables of their own (prefixed `exploration_`), written through a connection
of their own in WAL mode, beside the simulator's results:

* `exploration_runs`: one row per run, keyed by a hash of the settings that
  decide its course (course/2 of theory/defaults.pl: oracle, seed, batch,
  significance or slope, initial antecedent, breadth of modify, ...), with
  those settings as JSON;
* `exploration_checkpoints`: after every explored antecedent, the state of
  the loop (the explored antecedents and A_new, as Prolog term text) and
  that iteration's trace line, whose draws say which pours it simulated.

The pours themselves are the simulator's rows of `simulation_results`,
each committed as it arrives: a checkpoint is written after its pours, so
a run killed at any moment resumes from a consistent state, its pours
drawn again from the trace and their scores read from the store
(bridge/exploration/session.py). A table `exploration_simulations` of an
older layout (a second copy of those pours) is dropped when the store is
opened.
"""
from __future__ import annotations

import hashlib
import json
import sqlite3
import time
from dataclasses import dataclass
from pathlib import Path
from typing import Any, Mapping

from pantarhei.oracle.store_file import connect

SCHEMA = """
CREATE TABLE IF NOT EXISTS exploration_runs (
    run TEXT PRIMARY KEY,
    settings TEXT NOT NULL,
    started REAL NOT NULL,
    updated REAL NOT NULL,
    iterations INTEGER NOT NULL DEFAULT 0,
    finished INTEGER NOT NULL DEFAULT 0
);
CREATE TABLE IF NOT EXISTS exploration_checkpoints (
    run TEXT NOT NULL,
    iteration INTEGER NOT NULL,
    state TEXT NOT NULL,
    trace TEXT NOT NULL,
    PRIMARY KEY (run, iteration)
);
DROP TABLE IF EXISTS exploration_simulations;
"""


def run_key(course: Mapping[str, Any]) -> str:
    """The run's key: a hash of its course (bridge/exploration/course.py)."""
    text = json.dumps(course, sort_keys=True, separators=(",", ":"))
    return hashlib.sha256(text.encode()).hexdigest()[:16]


def other_settings(saved: Mapping[str, Any], wanted: Mapping[str, Any], store: Path) -> str:
    """The line refusing --resume when the store's saved exploration was run
    with other settings than these: it names both (the settings that
    differ), so that resuming never starts afresh over --out unasked."""
    wanted = json.loads(json.dumps(wanted, sort_keys=True))

    def shown(course: Mapping[str, Any], keys: list[str]) -> str:
        return ", ".join(f"{k}={json.dumps(course.get(k))}" for k in keys)

    keys = sorted(k for k in set(saved) | set(wanted) if saved.get(k) != wanted.get(k))
    return (f"--resume: the exploration saved in {store} was run with {shown(saved, keys)}, "
            f"not {shown(wanted, keys)}: give its settings to resume it, or leave out "
            f"--resume to start afresh")


@dataclass
class Checkpoint:
    """The latest saved state of a run: the loop's state and the trace up
    to it (its draws are every pour so far)."""
    iteration: int
    state: str
    trace: list[dict]
    finished: bool


class ExplorationStore:
    """The exploration tables of one SQLite file."""

    def __init__(self, path: str | Path):
        self.path = Path(path)
        self._db = connect(self.path)
        self._db.executescript(SCHEMA)

    def close(self) -> None:
        self._db.close()

    def __enter__(self) -> "ExplorationStore":
        return self

    def __exit__(self, *exc: Any) -> None:
        self.close()

    def start(self, run: str, course: Mapping[str, Any]) -> None:
        """Begin the run afresh, forgetting any saved state of it; its
        course is kept as JSON (column `settings`)."""
        with self._transaction():
            self._forget(run)
            now = time.time()
            self._db.execute("INSERT INTO exploration_runs (run, settings, started, updated) "
                             "VALUES (?, ?, ?, ?)",
                             (run, json.dumps(course, sort_keys=True), now, now))

    def forget(self, run: str) -> None:
        with self._transaction():
            self._forget(run)

    def _forget(self, run: str) -> None:
        for table in ("exploration_runs", "exploration_checkpoints"):
            self._db.execute(f"DELETE FROM {table} WHERE run = ?", (run,))

    def save(self, run: str, iteration: int, state: str, trace: Mapping[str, Any]) -> None:
        """Commit one iteration: the loop's state after it and its trace
        line (its pours are in the store already)."""
        with self._transaction():
            self._db.execute("INSERT OR REPLACE INTO exploration_checkpoints VALUES (?, ?, ?, ?)",
                             (run, iteration, state, json.dumps(trace, sort_keys=True)))
            self._db.execute("UPDATE exploration_runs SET iterations = ?, updated = ? WHERE run = ?",
                             (iteration, time.time(), run))

    def finish(self, run: str) -> None:
        with self._transaction():
            self._db.execute("UPDATE exploration_runs SET finished = 1, updated = ? WHERE run = ?",
                             (time.time(), run))

    def exists(self, run: str) -> bool:
        return self._db.execute("SELECT 1 FROM exploration_runs WHERE run = ?",
                                (run,)).fetchone() is not None

    def iterations(self, run: str) -> int:
        """How many iterations of the run are saved (0 if none)."""
        row = self._db.execute("SELECT iterations FROM exploration_runs WHERE run = ?",
                               (run,)).fetchone()
        return int(row[0]) if row else 0

    def trace(self, run: str, last: int | None = None) -> list[dict]:
        """The trace lines of the run's saved iterations (up to `last`), in order."""
        upto = "" if last is None else " AND iteration <= ?"
        return [json.loads(t) for (t,) in self._db.execute(
            f"SELECT trace FROM exploration_checkpoints WHERE run = ?{upto} ORDER BY iteration",
            (run,) if last is None else (run, last))]

    def latest(self, run: str) -> Checkpoint | None:
        """The run's latest checkpoint, or None when nothing of it is saved."""
        row = self._db.execute("SELECT iterations, finished FROM exploration_runs WHERE run = ?",
                               (run,)).fetchone()
        if row is None or row[0] == 0:
            return None
        last, finished = int(row[0]), bool(row[1])
        (state,) = self._db.execute("SELECT state FROM exploration_checkpoints "
                                    "WHERE run = ? AND iteration = ?", (run, last)).fetchone()
        return Checkpoint(last, state, self.trace(run, last), finished)

    def latest_course(self) -> dict | None:
        """The course of the run saved last (None when no run is saved)."""
        row = self._db.execute("SELECT settings FROM exploration_runs WHERE iterations > 0 "
                               "ORDER BY updated DESC LIMIT 1").fetchone()
        try:
            course = json.loads(row[0]) if row else None
        except (TypeError, ValueError):
            return None
        return course if isinstance(course, dict) else None

    def _transaction(self) -> "_Transaction":
        return _Transaction(self._db)


class _Transaction:
    def __init__(self, db: sqlite3.Connection):
        self._db = db

    def __enter__(self) -> None:
        self._db.execute("BEGIN IMMEDIATE")

    def __exit__(self, exc_type: Any, *rest: Any) -> None:
        self._db.execute("COMMIT" if exc_type is None else "ROLLBACK")
