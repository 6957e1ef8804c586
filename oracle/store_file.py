"""The store's SQLite file: how it is opened (WAL mode, autocommitting,
its folder made if need be), checked for damage, and how what goes wrong
with it is said in one line (`StoreError`)."""
from __future__ import annotations

import sqlite3
from pathlib import Path


class StoreError(RuntimeError):
    """A store that cannot be read or written; str() is one line saying
    what happened and what to do."""


#: The prefixes of the project's tables (the simulations' and the
#: explorations'): a database that holds tables, none of them these, is
#: another program's and is never written to.
OWN_TABLES = ("simulation_", "exploration_")


def require_ours(db: sqlite3.Connection, path: str) -> None:
    """StoreError when the database holds tables and none of the project's
    (`OWN_TABLES`): an unrelated SQLite file given as --store is refused
    before anything is added to it (SQLite's own error for a file that is
    not a database)."""
    names = [n for (n,) in db.execute("SELECT name FROM sqlite_master WHERE type = 'table'")
             if not str(n).startswith("sqlite_")]
    if names and not any(str(n).startswith(OWN_TABLES) for n in names):
        shown = ", ".join(str(n)[:40] for n in names[:3]) + (", ..." if len(names) > 3 else "")
        raise StoreError(f"the store {path} is another program's database (tables {shown}; "
                         f"none of pantarhei's): give another --store")


def open_file(path: str | Path, timeout: float = 60.0) -> sqlite3.Connection:
    """`connect` without its StoreError: SQLite's or the OS's own error if
    the file cannot be opened (StoreError for another program's database)."""
    path = str(path)
    if path != ":memory:":
        Path(path).parent.mkdir(parents=True, exist_ok=True)
    db = sqlite3.connect(path, timeout=timeout, isolation_level=None)
    try:
        require_ours(db, path)
    except BaseException:
        db.close()
        raise
    db.execute("PRAGMA journal_mode=WAL")
    db.execute("PRAGMA synchronous=NORMAL")
    return db


def connect(path: str | Path, timeout: float = 60.0) -> sqlite3.Connection:
    """A connection to the store file (made with its folder if need be) in
    WAL mode, autocommitting: the one way every table of the file is opened;
    StoreError in one line if it cannot be opened to be written."""
    try:
        return open_file(path, timeout)
    except (sqlite3.Error, OSError) as e:
        if read_only(e):
            raise StoreError(f"the store {path} cannot be written ({reason(e)}): give a writable "
                             f"--store") from None
        raise damaged(str(path), e) from None


def reason(e: BaseException) -> str:
    """An OS or SQLite error in a few words."""
    if isinstance(e, OSError):
        return e.strerror or str(e)
    return " ".join(str(e).replace("*** in database main ***", "").split()).rstrip(".")


def read_only(e: BaseException) -> bool:
    """Is `e` SQLite or the OS saying the file or its folder cannot be written?"""
    text = str(e).lower()
    return (isinstance(e, PermissionError)
            or any(w in text for w in ("readonly", "read-only", "unable to open", "disk i/o error")))


def full(e: BaseException) -> bool:
    """Is `e` SQLite or the OS saying the disk is full?"""
    import errno

    return ((isinstance(e, OSError) and e.errno in (errno.ENOSPC, errno.EDQUOT))
            or "disk is full" in str(e).lower() or "no space left" in str(e).lower())


def damaged(path: str, e: BaseException) -> StoreError:
    """The error of a store file SQLite cannot read as a database, or of
    one it cannot open for want of disk space (no fault of the file's)."""
    if full(e):
        return StoreError(f"the store {path} cannot be written: the disk is full ({reason(e)}): "
                          f"free some space, or give a --store on another disk")
    return StoreError(f"the store {path} is damaged ({reason(e)}): move it aside and run again "
                      f"to start a new one, or give another --store")


def check(db: sqlite3.Connection, path: str) -> None:
    """StoreError for a damaged file (SQLite's quick check)."""
    try:
        problems = [r[0] for r in db.execute("PRAGMA quick_check(3)")]
    except sqlite3.DatabaseError as e:
        if read_only(e):
            raise
        raise damaged(path, e) from None
    if problems != ["ok"]:
        raise damaged(path, RuntimeError(problems[0]))
