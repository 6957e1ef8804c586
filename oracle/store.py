"""The store of simulation results: an embedded SQLite file in WAL mode.

Each result is keyed by a hash of the canonical parameterization and of the
oracle's name, version and settings, so a parameterization is simulated once
per oracle configuration. Results are committed one by one as they arrive.
Other parts of the program keep their own tables in the same file; this
module only touches tables named `simulation...`.
"""
from __future__ import annotations

import hashlib
import json
import math
import sqlite3
import time
from dataclasses import dataclass
from pathlib import Path
from typing import Any, Iterable, Optional

import numpy as np

from pantarhei.oracle.base import Oracle
from pantarhei.theory import defaults
from pantarhei.theory.lexicon import load_vocabulary

#: The store of simulations (and exploration state) unless told otherwise,
#: relative to the working directory (theory/defaults.pl).
DEFAULT_STORE = Path(str(defaults()["store"]))

#: Decimal places a parameter value keeps in the key (theory units).
DECIMALS = 6

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
"""


def canonical(p: Iterable[float]) -> list[float]:
    """A parameterization as the list of numbers its key is made of."""
    out = []
    for v in p:
        r = round(float(v), DECIMALS)
        out.append(0.0 if r == 0 else r)
    return out


def oracle_tag(oracle: Oracle) -> str:
    """The oracle's name, version and settings as one canonical string."""
    return json.dumps({"name": oracle.name, "version": oracle.version,
                       "settings": oracle.settings()}, sort_keys=True, separators=(",", ":"))


def key(p: Iterable[float], tag: str) -> str:
    """The key of a parameterization's result under an oracle's tag."""
    text = json.dumps(canonical(p), separators=(",", ":")) + "|" + tag
    return hashlib.sha256(text.encode()).hexdigest()


@dataclass
class Result:
    """A stored result: scores (9,) or NaN for a failed simulation."""
    key: str
    status: str
    scores: np.ndarray
    record: Optional[dict[str, Any]]
    error: Optional[str]
    attempts: int

    @property
    def ok(self) -> bool:
        return self.status == "ok"


def _nan_json(x: Any) -> Any:
    if isinstance(x, float) and not math.isfinite(x):
        return None
    if isinstance(x, dict):
        return {k: _nan_json(v) for k, v in x.items()}
    if isinstance(x, (list, tuple)):
        return [_nan_json(v) for v in x]
    if isinstance(x, np.generic):
        return _nan_json(x.item())
    return x


def connect(path: str | Path, timeout: float = 60.0) -> sqlite3.Connection:
    """A connection to the store file (made with its folder if need be) in
    WAL mode, autocommitting: the one way every table of the file is opened."""
    path = str(path)
    if path != ":memory:":
        Path(path).parent.mkdir(parents=True, exist_ok=True)
    db = sqlite3.connect(path, timeout=timeout, isolation_level=None)
    db.execute("PRAGMA journal_mode=WAL")
    db.execute("PRAGMA synchronous=NORMAL")
    return db


class Store:
    """Results of simulations in one SQLite file (or in memory for ':memory:')."""

    def __init__(self, path: str | Path, timeout: float = 60.0):
        self.path = str(path)
        self.db = connect(self.path, timeout)
        self.db.executescript(SCHEMA)

    def get_many(self, keys: Iterable[str]) -> dict[str, Result]:
        """The stored results among `keys`."""
        keys = list(dict.fromkeys(keys))
        found: dict[str, Result] = {}
        for i in range(0, len(keys), 500):
            chunk = keys[i:i + 500]
            rows = self.db.execute(
                "SELECT key, status, scores, record, error, attempts FROM simulation_results "
                f"WHERE key IN ({','.join('?' * len(chunk))})", chunk)
            for k, status, scores, record, error, attempts in rows:
                s = np.array([np.nan if v is None else v for v in json.loads(scores)], dtype=float) \
                    if scores else np.full(len(load_vocabulary().expectations), np.nan)
                found[k] = Result(k, status, s, json.loads(record) if record else None, error, attempts)
        return found

    def get(self, k: str) -> Optional[Result]:
        return self.get_many([k]).get(k)

    def put(self, k: str, oracle: Oracle, p: Iterable[float], *, scores: Optional[np.ndarray],
            record: Optional[dict[str, Any]], error: Optional[str], attempts: int,
            seconds: Optional[float] = None) -> None:
        """Record one result (ok if `scores` is given, else failed) and commit."""
        status = "ok" if scores is not None else "failed"
        self.db.execute(
            "INSERT OR REPLACE INTO simulation_results (key, oracle, version, settings, params, "
            "status, scores, record, error, attempts, seconds, created) "
            "VALUES (?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?)",
            (k, oracle.name, oracle.version, json.dumps(oracle.settings(), sort_keys=True),
             json.dumps(canonical(p)), status,
             json.dumps(_nan_json([float(v) for v in scores])) if scores is not None else None,
             json.dumps(_nan_json(record)) if record is not None else None,
             error, attempts, seconds, time.time()))

    def count(self, status: Optional[str] = None) -> int:
        if status is None:
            return int(self.db.execute("SELECT COUNT(*) FROM simulation_results").fetchone()[0])
        return int(self.db.execute("SELECT COUNT(*) FROM simulation_results WHERE status = ?",
                                   (status,)).fetchone()[0])

    def close(self) -> None:
        self.db.close()

    def __enter__(self) -> "Store":
        return self

    def __exit__(self, *exc: Any) -> None:
        self.close()
