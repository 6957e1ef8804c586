"""oracle/store_file.py: a damaged store file is found out when it is
opened, and refused in one line before any pour."""
from __future__ import annotations

from pathlib import Path

import pytest

from pantarhei.oracle.store import Store, StoreError

from ..conftest import assert_one_line_error, run_cli
from .stores import low_pours, simulate


def damage(path: Path) -> None:
    """Overwrite the third page of an SQLite file (of the results' b-tree):
    the file still opens and takes writes to other tables."""
    data = bytearray(path.read_bytes())
    assert len(data) > 3 * 4096
    data[2 * 4096:3 * 4096] = b"\xab" * 4096
    path.write_bytes(bytes(data))


def test_a_damaged_store_is_refused_in_one_line_before_any_pour(tmp_path):
    db = tmp_path / "s.sqlite"
    simulate(db, low_pours(40))
    damage(db)
    with pytest.raises(StoreError, match="is damaged"):
        Store(db)
    junk = tmp_path / "junk.sqlite"
    junk.write_text("not a database at all\n" * 200)
    with pytest.raises(StoreError, match="is damaged .*file is not a database"):
        Store(junk)
    # the command says so in one line, and simulates nothing
    r = run_cli("simulate", "--antecedent", "pour_low", "-n", "1", "--store", str(db))
    line = assert_one_line_error(r, 1)
    assert "is damaged" in line and str(db) in line


def test_a_full_disk_is_called_a_full_disk_not_a_damaged_store(tmp_path):
    import errno
    import sqlite3

    from pantarhei.oracle.store_file import damaged

    db = sqlite3.connect(tmp_path / "s.sqlite")
    db.execute("PRAGMA max_page_count = 3")        # SQLite's own "disk is full", for real
    db.execute("CREATE TABLE t (x BLOB)")
    with pytest.raises(sqlite3.Error) as e:
        for _ in range(20):
            db.execute("INSERT INTO t VALUES (zeroblob(2000))")
    db.close()
    for err in (e.value, OSError(errno.ENOSPC, "No space left on device")):
        said = str(damaged("s.sqlite", err))
        assert "the disk is full" in said and "damaged" not in said and "\n" not in said
    assert "is damaged" in str(damaged("s.sqlite", sqlite3.DatabaseError("file is not a database")))
