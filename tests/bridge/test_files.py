"""Files written whole or not at all (bridge/files.py), and the check that
a file can be written before the work whose result goes there."""
from __future__ import annotations

import os

import pytest

from pantarhei.bridge.errors import UserError
from pantarhei.bridge.files import replace_with, require_writable_file, write_text


def test_a_write_that_fails_leaves_the_old_file_and_no_temporary(tmp_path):
    path = tmp_path / "theory.pl"
    write_text(path, "old\n")

    def half(tmp):
        tmp.write_text("half")
        raise RuntimeError("crash")

    with pytest.raises(RuntimeError):
        replace_with(path, half)
    assert path.read_text() == "old\n"
    assert os.listdir(tmp_path) == ["theory.pl"]
    write_text(path, "new ✓\n")
    assert path.read_text(encoding="utf-8") == "new ✓\n"


def test_where_nothing_can_be_written_is_said_before_any_work(tmp_path):
    require_writable_file(tmp_path / "not" / "yet" / "there.pl", "--out")   # folders made later
    with pytest.raises(UserError, match="--out .*: a directory, not a file"):
        require_writable_file(tmp_path, "--out")
    (tmp_path / "file").write_text("")
    with pytest.raises(UserError, match="is not a directory"):
        require_writable_file(tmp_path / "file" / "x.pl", "--out")


def test_two_roles_on_one_file_are_refused_however_it_is_named(tmp_path):
    from pantarhei.bridge.files import require_distinct

    require_distinct({"--store": tmp_path / "s.sqlite", "--out": tmp_path / "t.pl"})
    (tmp_path / "sub").mkdir()
    with pytest.raises(UserError, match=r"^--store and --out are the same file .*: give each its own path$"):
        require_distinct({"--store": tmp_path / "x", "--out": tmp_path / "sub" / ".." / "x"})
    (tmp_path / "real.pl").write_text("")
    (tmp_path / "link.pl").symlink_to(tmp_path / "real.pl")
    os.link(tmp_path / "real.pl", tmp_path / "hard.pl")
    for other in ("link.pl", "hard.pl"):
        with pytest.raises(UserError, match="--store and --out are the same file"):
            require_distinct({"--store": tmp_path / "real.pl", "--out": tmp_path / other})
