"""Defeasible theories as values (bridge/theories/model.py): a superiority
relation with a cycle (`Theory.check_acyclic`) is refused in one line that
names the file, the line of the sup/2 fact and the rules of the cycle, also
when the cycle only appears once files are merged."""
from __future__ import annotations

from pathlib import Path

from tests.conftest import assert_one_line_error


def test_cyclic_superiority_in_native_files(cli, tmp_path: Path) -> None:
    f = tmp_path / "cyclic.pl"
    f.write_text("fact(a).\nrule(r1, defeasible, b).\nbody(r1, a).\nrule(r2, defeasible, neg(b)).\n"
                 "body(r2, a).\nsup(r1, r2).\nsup(r2, r1).\n")
    msg = assert_one_line_error(cli("conclusions", str(f)))
    assert msg.endswith(f"{f}:6: the superiority relation has a cycle, r1 > r2 > r1: it must be acyclic")
    g = tmp_path / "other.pl"                        # a cycle across files, once merged
    g.write_text("rule(r3, defeasible, b).\nsup(r3, r1).\nsup(r2, r3).\n")
    h = tmp_path / "first.pl"
    h.write_text("rule(r1, defeasible, b).\nrule(r2, defeasible, neg(b)).\nsup(r1, r2).\n")
    assert "r1 > r2 > r3 > r1" in assert_one_line_error(cli("conclusions", str(h), str(g)))
