"""The layout of the store's tables (`simulation_results`, one row per
result, and `simulation_store`), and the migration of an older layout of
simulation_results: the columns it lacks are added where they can be."""
from __future__ import annotations

import sqlite3

from pantarhei.oracle.store_file import StoreError

SCHEMA = """
CREATE TABLE IF NOT EXISTS simulation_results (
    key        TEXT PRIMARY KEY,
    oracle     TEXT NOT NULL,
    version    TEXT NOT NULL,
    settings   TEXT NOT NULL,
    params     TEXT NOT NULL,
    status     TEXT NOT NULL CHECK (status IN ('ok', 'failed')),
    scores     TEXT,
    record     TEXT,
    error      TEXT,
    attempts   INTEGER NOT NULL,
    seconds    REAL,
    created    REAL NOT NULL
);
CREATE INDEX IF NOT EXISTS simulation_results_oracle ON simulation_results (oracle, version);
CREATE TABLE IF NOT EXISTS simulation_store (
    name       TEXT PRIMARY KEY,
    value      TEXT NOT NULL
);
"""

#: The columns of simulation_results in their order (SCHEMA's).
COLUMNS = ("key", "oracle", "version", "settings", "params", "status", "scores", "record",
           "error", "attempts", "seconds", "created")
#: Columns an older layout may lack, and what they are added as (status is
#: then derived from the scores).
ADDABLE = {
    "status": "TEXT NOT NULL DEFAULT 'ok' CHECK (status IN ('ok', 'failed'))",
    "record": "TEXT",
    "error": "TEXT",
    "attempts": "INTEGER NOT NULL DEFAULT 1",
    "seconds": "REAL",
    "created": "REAL NOT NULL DEFAULT 0",
    "settings": "TEXT NOT NULL DEFAULT '{}'",
}


def has_table(db: sqlite3.Connection) -> bool:
    return db.execute("SELECT 1 FROM sqlite_master WHERE type = 'table' AND "
                      "name = 'simulation_results'").fetchone() is not None


def missing_columns(db: sqlite3.Connection) -> list[str]:
    have = {row[1] for row in db.execute("PRAGMA table_info(simulation_results)")}
    return [c for c in COLUMNS if c not in have]


def migrate(db: sqlite3.Connection, path: str) -> None:
    """Bring an older simulation_results table up to SCHEMA's layout,
    or StoreError naming the columns it lacks that cannot be made."""
    if not has_table(db):
        return
    missing = missing_columns(db)
    if not missing:
        return
    lost = [c for c in missing if c not in ADDABLE]
    if lost:
        raise StoreError(f"the store {path} has a table simulation_results of another "
                         f"layout (no {', '.join(lost)}): move it aside or give another --store")
    for c in missing:
        db.execute(f"ALTER TABLE simulation_results ADD COLUMN {c} {ADDABLE[c]}")
    if "status" in missing:
        db.execute("UPDATE simulation_results SET status = "
                   "CASE WHEN scores IS NULL THEN 'failed' ELSE 'ok' END")
