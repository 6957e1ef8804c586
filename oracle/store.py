"""The store of simulation results: an embedded SQLite file in WAL mode.

Each result is keyed by a hash of the canonical parameterization and of the
oracle's name, version and settings, so a parameterization is simulated once
per oracle configuration. Results are committed one by one as they arrive.
Other parts of the program keep their own tables in the same file; this
module only touches tables named `simulation...`.

Nothing computed is lost: opening a store checks it (a damaged file, an
older table layout, which is migrated where it can be) and writes to it
once, so that a store that cannot take results is found out before the
first pour. One that can only be read (a read-only file or folder) is
opened read-only: its cached pours are served, and a pour it does not hold
is refused before it is simulated (`require_writable`). If writing fails
mid-run (a full disk), the results it could not keep are written to a
recovery file beside it (or in the temporary folder), which `StoreError`
names; the next run that opens the store writable takes them back.
"""
from __future__ import annotations

import hashlib
import json
import math
import os
import sqlite3
import tempfile
import time
import urllib.parse
from dataclasses import dataclass
from pathlib import Path
from typing import TYPE_CHECKING, Any, Iterable, Optional

from pantarhei.theory import defaults

if TYPE_CHECKING:
    import numpy as np

    from pantarhei.oracle.base import Oracle

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


class StoreError(RuntimeError):
    """A store that cannot be read or written; str() is one line saying
    what happened and what to do."""



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
    if hasattr(x, "item") and type(x).__module__ == "numpy":      # a numpy scalar
        return _nan_json(x.item())
    return x


def _connect(path: str | Path, timeout: float = 60.0) -> sqlite3.Connection:
    """A connection to the store file (made with its folder if need be) in
    WAL mode, autocommitting: the one way every table of the file is opened."""
    path = str(path)
    if path != ":memory:":
        Path(path).parent.mkdir(parents=True, exist_ok=True)
    db = sqlite3.connect(path, timeout=timeout, isolation_level=None)
    db.execute("PRAGMA journal_mode=WAL")
    db.execute("PRAGMA synchronous=NORMAL")
    return db


def connect(path: str | Path, timeout: float = 60.0) -> sqlite3.Connection:
    """A connection to the store file (made with its folder if need be) in
    WAL mode, autocommitting: the one way every table of the file is opened;
    StoreError in one line if it cannot be opened to be written."""
    try:
        return _connect(path, timeout)
    except (sqlite3.Error, OSError) as e:
        if _read_only(e):
            raise StoreError(f"the store {path} cannot be written ({_reason(e)}): give a writable "
                             f"--store") from None
        raise _damaged(str(path), e) from None


def _reason(e: BaseException) -> str:
    """An OS or SQLite error in a few words."""
    if isinstance(e, OSError):
        return e.strerror or str(e)
    return " ".join(str(e).replace("*** in database main ***", "").split()).rstrip(".")


def _read_only(e: BaseException) -> bool:
    """Is `e` SQLite or the OS saying the file or its folder cannot be written?"""
    text = str(e).lower()
    return (isinstance(e, PermissionError)
            or any(w in text for w in ("readonly", "read-only", "unable to open", "disk i/o error")))


def _damaged(path: str, e: BaseException) -> StoreError:
    return StoreError(f"the store {path} is damaged ({_reason(e)}): move it aside and run again "
                      f"to start a new one, or give another --store")


class Store:
    """Results of simulations in one SQLite file (or in memory for ':memory:').

    `writable` is False for a store that can only be read (`read_only_why`
    says why); `StoreError` for one that cannot be read at all."""

    def __init__(self, path: str | Path, timeout: float = 60.0):
        self.path = str(path)
        self.writable = True
        self.read_only_why: Optional[str] = None
        #: Rows put() could not write, kept for the recovery file.
        self.unsaved: list[tuple] = []
        #: Why writing failed mid-run (None while it works).
        self.failure: Optional[str] = None
        if Path(self.path).is_dir():
            raise StoreError(f"{self.path}: a directory, not a store file (give a file with --store)")
        try:
            self.db = self._open_writable(timeout)
        except (sqlite3.Error, OSError) as e:
            if not _read_only(e) or not Path(self.path).is_file():
                if _read_only(e):
                    raise StoreError(f"cannot create the store {self.path} ({_reason(e)}): give a "
                                     f"writable --store") from None
                raise _damaged(self.path, e) from None
            self.writable, self.read_only_why = False, _reason(e)
            self.db = self._open_read_only(timeout)

    # -- opening ---------------------------------------------------------------

    def _open_writable(self, timeout: float) -> sqlite3.Connection:
        """Opened, checked, migrated if need be, and written once."""
        db = _connect(self.path, timeout)
        try:
            self._check(db)
            db.execute("BEGIN IMMEDIATE")
            try:
                self._migrate(db)
                db.execute("COMMIT")
            except BaseException:
                db.execute("ROLLBACK")
                raise
            db.executescript(SCHEMA)
            db.execute("INSERT OR REPLACE INTO simulation_store VALUES ('opened', ?)",
                       (repr(time.time()),))
            if self.path != ":memory:":
                self._take_back_recovered(db)
        except BaseException:
            db.close()
            raise
        return db

    def _open_read_only(self, timeout: float) -> sqlite3.Connection:
        """The file read-only: with its write-ahead log where SQLite can
        use it, else as it is on disk (a read-only folder, where SQLite
        cannot make the log's index)."""
        uri = "file:" + urllib.parse.quote(str(Path(self.path).absolute()))
        last: BaseException | None = None
        for mode in ("mode=ro", "immutable=1"):
            try:
                db = sqlite3.connect(f"{uri}?{mode}", uri=True, timeout=timeout, isolation_level=None)
            except sqlite3.Error as e:
                last = e
                continue
            try:
                self._check(db)
                if not self._has_table(db):
                    raise StoreError(f"the store {self.path} cannot be written "
                                     f"({self.read_only_why}) and holds no simulations yet: give "
                                     f"a writable --store")
                missing = self._missing_columns(db)
                if missing:
                    raise StoreError(f"the store {self.path} has an older layout (no "
                                     f"{', '.join(missing)}) and cannot be written to bring it up "
                                     f"to date ({self.read_only_why}): give a writable --store")
                return db
            except StoreError:
                db.close()
                raise
            except sqlite3.DatabaseError as e:
                db.close()
                last = e
                if not _read_only(e):
                    raise _damaged(self.path, e) from None
        raise StoreError(f"cannot read the store {self.path} ({_reason(last)})")

    def _check(self, db: sqlite3.Connection) -> None:
        """StoreError for a damaged file (SQLite's quick check)."""
        try:
            problems = [r[0] for r in db.execute("PRAGMA quick_check(3)")]
        except sqlite3.DatabaseError as e:
            if _read_only(e):
                raise
            raise _damaged(self.path, e) from None
        if problems != ["ok"]:
            raise _damaged(self.path, RuntimeError(problems[0]))

    @staticmethod
    def _has_table(db: sqlite3.Connection) -> bool:
        return db.execute("SELECT 1 FROM sqlite_master WHERE type = 'table' AND "
                          "name = 'simulation_results'").fetchone() is not None

    @staticmethod
    def _missing_columns(db: sqlite3.Connection) -> list[str]:
        have = {row[1] for row in db.execute("PRAGMA table_info(simulation_results)")}
        return [c for c in COLUMNS if c not in have]

    def _migrate(self, db: sqlite3.Connection) -> None:
        """Bring an older simulation_results table up to SCHEMA's layout,
        or StoreError naming the columns it lacks that cannot be made."""
        if not self._has_table(db):
            return
        missing = self._missing_columns(db)
        if not missing:
            return
        lost = [c for c in missing if c not in ADDABLE]
        if lost:
            raise StoreError(f"the store {self.path} has a table simulation_results of another "
                             f"layout (no {', '.join(lost)}): move it aside or give another --store")
        for c in missing:
            db.execute(f"ALTER TABLE simulation_results ADD COLUMN {c} {ADDABLE[c]}")
        if "status" in missing:
            db.execute("UPDATE simulation_results SET status = "
                       "CASE WHEN scores IS NULL THEN 'failed' ELSE 'ok' END")

    # -- results -----------------------------------------------------------------

    def get_many(self, keys: Iterable[str]) -> dict[str, Result]:
        """The stored results among `keys`."""
        import numpy as np

        from pantarhei.theory.lexicon import load_vocabulary

        keys = list(dict.fromkeys(keys))
        found: dict[str, Result] = {}
        try:
            for i in range(0, len(keys), 500):
                chunk = keys[i:i + 500]
                rows = self.db.execute(
                    "SELECT key, status, scores, record, error, attempts FROM simulation_results "
                    f"WHERE key IN ({','.join('?' * len(chunk))})", chunk).fetchall()
                for k, status, scores, record, error, attempts in rows:
                    s = np.array([np.nan if v is None else v for v in json.loads(scores)], dtype=float) \
                        if scores else np.full(len(load_vocabulary().expectations), np.nan)
                    found[k] = Result(k, status, s, json.loads(record) if record else None, error,
                                      attempts)
        except (sqlite3.DatabaseError, ValueError) as e:
            raise StoreError(f"cannot read the store {self.path} ({_reason(e)})") from None
        return found

    def get(self, k: str) -> Optional[Result]:
        return self.get_many([k]).get(k)

    def require_writable(self, pours: int) -> None:
        """StoreError unless the store can take `pours` new results: called
        before they are simulated."""
        if not self.writable and pours:
            raise StoreError(f"the store {self.path} cannot be written ({self.read_only_why}) and "
                             f"{pours} of the pours asked for are not in it: give a writable "
                             f"--store (or simulate without one)")

    def put(self, k: str, oracle: Oracle, p: Iterable[float], *, scores: Optional[np.ndarray],
            record: Optional[dict[str, Any]], error: Optional[str], attempts: int,
            seconds: Optional[float] = None) -> None:
        """Record one result (ok if `scores` is given, else failed) and
        commit. A result that cannot be written is kept in `unsaved` (see
        `settle`), and so is every later one."""
        status = "ok" if scores is not None else "failed"
        row = (k, oracle.name, oracle.version, json.dumps(oracle.settings(), sort_keys=True),
               json.dumps(canonical(p)), status,
               json.dumps(_nan_json([float(v) for v in scores])) if scores is not None else None,
               json.dumps(_nan_json(record)) if record is not None else None,
               error, attempts, seconds, time.time())
        if self.failure is None:
            if not self.writable:
                self.failure = f"it cannot be written: {self.read_only_why}"
            else:
                try:
                    self.db.execute(f"INSERT OR REPLACE INTO simulation_results ({', '.join(COLUMNS)}) "
                                    f"VALUES ({', '.join('?' * len(COLUMNS))})", row)
                    return
                except sqlite3.Error as e:
                    self.failure = _reason(e)
        self.unsaved.append(row)

    def save_unsaved(self) -> Optional[Path]:
        """Write the results put() could not keep to a recovery file (JSON
        lines, one result each) beside the store, or in the temporary
        folder if that fails; its path, or None if there were none or no
        file could be written."""
        if not self.unsaved:
            return None
        text = "".join(json.dumps(dict(zip(COLUMNS, row))) + "\n" for row in self.unsaved)
        name = f"{Path(self.path).name}.recovered-{time.strftime('%Y%m%d-%H%M%S')}-{os.getpid()}.jsonl"
        for folder in (Path(self.path).absolute().parent, Path(tempfile.gettempdir())):
            target = folder / name
            try:
                with open(target, "x", encoding="utf-8") as f:
                    f.write(text)
                self.unsaved = []
                return target
            except OSError:
                try:
                    target.unlink()
                except OSError:
                    pass
        return None

    def settle(self) -> None:
        """StoreError if writing failed during the run, after the results
        not kept were written to a recovery file (named in the error)."""
        if self.failure is None:
            return
        n = len(self.unsaved)
        saved = self.save_unsaved()
        where = (f"the {n} results it could not keep are in {saved} (the next run with a "
                 f"writable store at {self.path} takes them back if the file is beside it)"
                 if saved else f"the {n} results it could not keep could not be written anywhere")
        raise StoreError(f"the store {self.path} failed during the run ({self.failure}): {where}")

    def _take_back_recovered(self, db: sqlite3.Connection) -> None:
        """Insert the results of recovery files beside the store (written
        by an earlier run whose store failed), then remove the files."""
        path = Path(self.path).absolute()
        for f in sorted(path.parent.glob(f"{path.name}.recovered-*.jsonl")):
            try:
                rows = [json.loads(line) for line in f.read_text(encoding="utf-8").splitlines()
                        if line.strip()]
                db.execute("BEGIN IMMEDIATE")
                try:
                    db.executemany(
                        f"INSERT OR IGNORE INTO simulation_results ({', '.join(COLUMNS)}) "
                        f"VALUES ({', '.join('?' * len(COLUMNS))})",
                        [tuple(r[c] for c in COLUMNS) for r in rows])
                    db.execute("COMMIT")
                except BaseException:
                    db.execute("ROLLBACK")
                    raise
                f.unlink()
            except (OSError, ValueError, KeyError, TypeError, sqlite3.Error):
                continue        # left for a later run, or for the person named on the error line

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
