"""Recovery files: the results a store could not keep (a full disk, say),
written as JSON lines beside it (or in the temporary folder), and taken
back by the next run that opens the store writable."""
from __future__ import annotations

import json
import os
import sqlite3
import tempfile
import time
from pathlib import Path
from typing import Optional

from pantarhei.oracle.store_schema import COLUMNS


def save(store_path: str, rows: list[tuple]) -> Optional[Path]:
    """Write `rows` (of simulation_results) to a recovery file (JSON lines,
    one result each) beside the store, or in the temporary folder if that
    fails; its path, or None if no file could be written."""
    text = "".join(json.dumps(dict(zip(COLUMNS, row))) + "\n" for row in rows)
    name = f"{Path(store_path).name}.recovered-{time.strftime('%Y%m%d-%H%M%S')}-{os.getpid()}.jsonl"
    for folder in (Path(store_path).absolute().parent, Path(tempfile.gettempdir())):
        target = folder / name
        try:
            with open(target, "x", encoding="utf-8") as f:
                f.write(text)
            return target
        except OSError:
            try:
                target.unlink()
            except OSError:
                pass
    return None


def take_back(db: sqlite3.Connection, store_path: str) -> None:
    """Insert the results of recovery files beside the store (written
    by an earlier run whose store failed), then remove the files."""
    path = Path(store_path).absolute()
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
