"""Defeasible theories as values (bridge/theories/model.py): a superiority
relation with a cycle (`Theory.check_acyclic`) is refused in one line that
names the file, the line of the sup/2 fact and the rules of the cycle, also
when the cycle only appears once files are merged. The explored
antecedents' ids are written and read as theory/learned_rules.pl's
antecedent_id/2 writes and reads them."""
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


def test_antecedent_ids_are_the_ones_prolog_writes_and_reads() -> None:
    from pantarhei.bridge.engines.swipl import engine
    from pantarhei.bridge.theories.model import antecedent_id, antecedent_index

    e = engine()
    e.use_module("learned_rules")
    numbers = [*range(0, 120), 999, 1000, 123456789]
    r = e.once("findall(Id, (member(I, Is), learned_rules:antecedent_id(I, Id)), Ids)", Is=numbers)
    assert [antecedent_id(i) for i in numbers] == [str(x) for x in r["Ids"]]
    ids = [*(antecedent_id(i) for i in numbers), "none", "a", "b1", "a-1", "a1x", "a 1", "a+1",
           "a1.0", "a0x1", "a1e3", "a007", "a\u0663", "A1", "ra1"]
    r = e.once("findall(I, (member(S, Ss), atom_string(Id, S), "
               "(learned_rules:antecedent_id(I0, Id) -> I = I0 ; I = none)), Is)", Ss=ids)
    assert [antecedent_index(a) for a in ids] == [None if str(i) == "none" else i for i in r["Is"]]
    assert antecedent_index("a12") == 12 and antecedent_index("none") is None
