"""`pantarhei convert` keeps every fact of a theory file, in either
direction and in place, or refuses in one line.

A concern no single module owns: the conversion is loading.converted, the
reading dfl.parse_dfl, native.read_native and facts.read, the writing
dfl.write_dfl and model.Theory.native (all bridge/theories/), run as the
`convert` command of bridge/commands/querying.py."""
from __future__ import annotations

import shutil
from pathlib import Path

import pytest

from pantarhei.bridge.reasoning.logic import conclusions
from pantarhei.bridge.theories import facts
from pantarhei.bridge.theories.dfl import parse_dfl
from pantarhei.bridge.theories.loading import DEFAULT_THEORY, load
from pantarhei.bridge.theories.native import read_native
from tests.conftest import assert_one_line_error, run_cli

EXAMPLES = Path(__file__).resolve().parents[3] / "examples" / "extend_by_hand"

#: A learned theory with one of everything: settings (one with quoted text
#: that reads as a program when unquoted), rules of each kind, bodies,
#: learned rules, provenance, explicit superiority, facts, set_aside/3,
#: the explored antecedents' explored/2 and held/4, and a fact of a
#: predicate no reader knows.
EVERYTHING = r"""% a learned theory
setting(oracle, synthetic).
setting(seed, 7).
setting(initial, pour_low).
setting(initial, light_liquid).
setting(note, "a \"quoted\" note).\n#include \"x\".\n%").
fact(bird(tweety)).
fact(neg(p(-3))).
rule(r1, defeasible, no_spill).
body(r1, pour_low).
learned(r1).
provenance(r1, support, 52).
provenance(r1, antecedent, a0).
rule(r2, defeasible, neg(no_spill)).
body(r2, pour_low).
body(r2, light_liquid).
learned(r2).
provenance(r2, parent, f(a0, "why not")).
rule(s1, strict, flies(tweety)).
body(s1, bird(tweety)).
rule(d1, defeater, neg(no_spill)).
body(d1, pour_to_side).
sup(s1, d1).
set_aside(0, 1, pour_to_side).
set_aside(0, 1, light_liquid).
probe(1, 2, "text", 2147483647).
explored(a2, pour_low).
held(a2, no_spill, 11, 12).
held(a0, no_spill, 0, 3).
"""


def _facts(path: Path) -> set[str]:
    """Every fact of a theory file, native or DFL, as native text."""
    if path.suffix == ".dfl":
        back = path.with_suffix(".again.pl")
        back.write_text(parse_dfl(path.read_text(), str(path)).native())
        path = back
    return {f.text for f in facts.read(path)}


@pytest.fixture(params=["everything", "shipped"])
def theory_file(request, tmp_path: Path) -> Path:
    path = tmp_path / "theory.pl"
    if request.param == "shipped":
        if not DEFAULT_THEORY.is_file():
            pytest.skip("no shipped theory")
        shutil.copy(DEFAULT_THEORY, path)
    else:
        path.write_text(EVERYTHING)
    return path


def test_native_to_dfl_and_back_keeps_every_fact(cli, theory_file: Path, tmp_path: Path) -> None:
    before = _facts(theory_file)
    dfl = tmp_path / "theory.dfl"
    r = cli("convert", str(theory_file), "--to", "dfl", "-o", str(dfl))
    assert r.code == 0, r.err
    assert _facts(dfl) == before
    back = tmp_path / "back.pl"
    r = cli("convert", str(dfl), "--to", "native", "-o", str(back))
    assert r.code == 0, r.err
    assert _facts(back) == before
    # and DFL to DFL again: the same file
    again = tmp_path / "again.dfl"
    assert cli("convert", str(dfl), "--to", "dfl", "-o", str(again)).code == 0
    assert again.read_text() == dfl.read_text()


def test_convert_in_place_keeps_every_fact(cli, theory_file: Path) -> None:
    before = _facts(theory_file)
    r = cli("convert", str(theory_file), "--to", "native", "-o", str(theory_file))
    assert r.code == 0, r.err
    assert _facts(theory_file) == before
    if theory_file.read_text().count("set_aside("):
        assert any(f.startswith("set_aside(") for f in before)


def test_a_dfl_file_named_as_native_is_refused_and_nothing_is_written(cli, theory_file: Path) -> None:
    text = theory_file.read_text()
    line = assert_one_line_error(cli("convert", str(theory_file), "--to", "dfl", "-o", str(theory_file)))
    assert line.endswith("(the name says how it is read)") and str(theory_file) in line
    assert theory_file.read_text() == text


def test_rules_with_variables_are_refused_not_grounded(cli, tmp_path: Path) -> None:
    dfl = tmp_path / "birds.dfl"
    dfl.write_text(">> bird(tweety)\n\nr1: bird(?x) => flies(?x)\n")
    out = tmp_path / "birds.pl"
    line = assert_one_line_error(cli("convert", str(dfl), "--to", "native", "-o", str(out)))
    assert f"{dfl}:3: rule r1 has variables" in line, line
    assert not out.exists()


def test_hand_written_dfl_converts_as_before(cli) -> None:
    r = cli("convert", str(EXAMPLES / "hand.dfl"), "--to", "native")
    assert r.code == 0, r.err
    assert "rule(h1, defeasible, liquid_leaves_source)." in r.out


def _everything(t) -> tuple:
    return (t.facts, t.rules, t.sup, t.learned, t.extra, t.settings, t.provenance)


def test_convert_to_native_keeps_everything_of_a_learned_theory(tmp_path: Path) -> None:
    shipped = read_native(DEFAULT_THEORY)
    assert shipped.settings and shipped.provenance          # what a learned theory records
    out = tmp_path / "copy.pl"
    r = run_cli("convert", str(DEFAULT_THEORY), "--to", "native", "-o", str(out))
    assert r.code == 0, r.err
    assert _everything(read_native(out)) == _everything(shipped)


def test_convert_command_writes_whole_files(cli, tmp_path: Path) -> None:
    out = tmp_path / "learned.dfl"
    r = cli("convert", str(EXAMPLES / "learned.pl"), "-o", str(out))
    assert r.code == 0, r.err
    back = tmp_path / "back.pl"
    assert cli("convert", str(out), "--to", "native", "-o", str(back)).code == 0
    assert conclusions(load(back)) == conclusions(load(EXAMPLES / "learned.pl"))
    assert "rule(h1, defeasible, liquid_leaves_source)." in cli("convert", str(EXAMPLES / "hand.dfl"),
                                                              "--to", "native").out


def test_the_explored_antecedents_pours_change_no_conclusion(tmp_path: Path) -> None:
    """explored/2 and held/4 are read by every reader and reach no
    reasoner: SWI-Prolog, clingo through Python and clingo alone with the
    encodings conclude the same with them as without."""
    import subprocess
    import sys

    from pantarhei.theory import THEORY_DIR

    with_them = tmp_path / "with.pl"
    with_them.write_text(EVERYTHING)
    without = tmp_path / "without.pl"
    without.write_text("".join(line + "\n" for line in EVERYTHING.splitlines()
                               if not line.startswith(("explored(", "held("))))
    assert "held(" not in without.read_text()
    for engine in ("prolog", "asp"):
        assert conclusions(load([with_them]), engine=engine) \
            == conclusions(load([without]), engine=engine), engine

    def clingo(path: Path) -> list[str]:
        p = subprocess.run([sys.executable, "-m", "clingo", "-V0", "--warn=none",
                            str(THEORY_DIR / "derivability.lp"), str(THEORY_DIR / "conclusions.lp"),
                            str(path)], capture_output=True, text=True, timeout=120)
        assert "SATISFIABLE" in p.stdout, p.stdout + p.stderr
        return sorted(p.stdout.split())
    assert clingo(with_them) == clingo(without)
