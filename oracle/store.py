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

The keys are made in `result_keys`, the file is opened and checked in
`store_file`, its layout and migration are `store_schema`'s, and the
recovery files `store_recovery`'s; this module reads and writes results.
"""
from __future__ import annotations

import json
import math
import sqlite3
import time
import urllib.parse
from dataclasses import dataclass
from pathlib import Path
from typing import TYPE_CHECKING, Any, Iterable, Optional

from pantarhei.oracle import store_recovery
from pantarhei.oracle.result_keys import canonical
from pantarhei.oracle.store_file import (StoreError, check, damaged, open_file, read_only, reason,
                                         require_ours)
from pantarhei.oracle.store_schema import COLUMNS, SCHEMA, has_table, migrate, missing_columns
from pantarhei.theory import defaults

if TYPE_CHECKING:
    import numpy as np

    from pantarhei.oracle.base import Oracle

#: The store of simulations (and exploration state) unless told otherwise,
#: relative to the working directory (theory/defaults.pl).
DEFAULT_STORE = Path(str(defaults()["store"]))


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


def _result(row: tuple, n: int) -> Optional[Result]:
    """A row of simulation_results as a Result, or None when it is not one
    a simulation wrote: an ok row's scores must be `n` finite numbers in
    [0, 1] (a row edited to 1e999, -7 or 5, or with another number of
    scores, is refused), its record an object; a failed row's scores are
    NaN whatever it holds."""
    import numpy as np

    k, status, scores, record, error, attempts = row
    try:
        rec = json.loads(record) if record else None
        values = json.loads(scores) if status == "ok" else None
    except (TypeError, ValueError, RecursionError):
        return None
    if status == "failed":
        return Result(k, status, np.full(n, np.nan), rec if isinstance(rec, dict) else None,
                      error if isinstance(error, str) else None, _attempts(attempts))
    if status != "ok" or not isinstance(rec, (dict, type(None))) or not isinstance(values, list) \
            or len(values) != n:
        return None
    if not all(type(v) in (int, float) and math.isfinite(v) and 0.0 <= v <= 1.0 for v in values):
        return None
    return Result(k, status, np.array(values, dtype=float), rec,
                  error if isinstance(error, str) else None, _attempts(attempts))


def _attempts(v: Any) -> int:
    return v if type(v) is int and 0 <= v < 2**31 else 1


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
        #: Rows read that were not results (`_result`): left out, so simulated again.
        self.refused = 0
        if Path(self.path).is_dir():
            raise StoreError(f"{self.path}: a directory, not a store file (give a file with --store)")
        try:
            self.db = self._open_writable(timeout)
        except (sqlite3.Error, OSError) as e:
            if not read_only(e) or not Path(self.path).is_file():
                if read_only(e):
                    raise StoreError(f"cannot create the store {self.path} ({reason(e)}): give a "
                                     f"writable --store") from None
                raise damaged(self.path, e) from None
            self.writable, self.read_only_why = False, reason(e)
            self.db = self._open_read_only(timeout)

    # -- opening ---------------------------------------------------------------

    def _open_writable(self, timeout: float) -> sqlite3.Connection:
        """Opened, checked, migrated if need be, and written once."""
        db = open_file(self.path, timeout)
        try:
            check(db, self.path)
            db.execute("BEGIN IMMEDIATE")
            try:
                migrate(db, self.path)
                db.execute("COMMIT")
            except BaseException:
                db.execute("ROLLBACK")
                raise
            db.executescript(SCHEMA)
            db.execute("INSERT OR REPLACE INTO simulation_store VALUES ('opened', ?)",
                       (repr(time.time()),))
            if self.path != ":memory:":
                store_recovery.take_back(db, self.path)
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
                check(db, self.path)
                require_ours(db, self.path)
                if not has_table(db):
                    raise StoreError(f"the store {self.path} cannot be written "
                                     f"({self.read_only_why}) and holds no simulations yet: give "
                                     f"a writable --store")
                missing = missing_columns(db)
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
                if not read_only(e):
                    raise damaged(self.path, e) from None
        raise StoreError(f"cannot read the store {self.path} ({reason(last)})")

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
                for row in rows:
                    result = _result(row, len(load_vocabulary().expectations))
                    if result is None:      # not a result: simulated again, never counted
                        self.refused += 1
                    else:
                        found[result.key] = result
        except sqlite3.DatabaseError as e:
            raise StoreError(f"cannot read the store {self.path} ({reason(e)})") from None
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
                    self.failure = reason(e)
        self.unsaved.append(row)

    def save_unsaved(self) -> Optional[Path]:
        """Write the results put() could not keep to a recovery file (JSON
        lines, one result each) beside the store, or in the temporary
        folder if that fails; its path, or None if there were none or no
        file could be written."""
        if not self.unsaved:
            return None
        target = store_recovery.save(self.path, self.unsaved)
        if target is not None:
            self.unsaved = []
        return target

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
