"""What a theory file may hold (bridge/theories/well_formed.py): a literal
is what both engines read as one (`check_literal` refuses the same ones as
theory/theory_files.pl, word for word), and a setting's value written by
`value_text` reads back as that one value in Python, SWI-Prolog and clingo,
whatever text it holds."""
from __future__ import annotations

from pathlib import Path

from pantarhei.bridge.engines.swipl import engine, text
from pantarhei.bridge.theories import facts
from pantarhei.bridge.theories.facts import Text, term_text
from pantarhei.bridge.theories.native import read_native
from pantarhei.bridge.theories.well_formed import check_literal, value_text
from pantarhei.theory import TheoryFileError, clingo_module

LITERALS = ["p", "bird(tweety)", "neg(p(-3))", "p(a,1)", "neg(p,q)", "neg(neg(p))", "p(f(a))",
            "neg(p(f(a)))", 'p("x")', "neg(neg(neg(p)))"]

VALUES = [3, -7, "pour_low", "f(a0,1)", "f(a0, 1)", Text("why not"), "x).\nfact(pwned).\n%",
          "Upper", "", 'say "hi" \\ back', "#include \"x\".", True, 2.5]


def _python_problem(lit: str) -> str:
    try:
        check_literal(lit, "t.pl:1")
    except TheoryFileError as e:
        return str(e).removeprefix("t.pl:1: ")
    return "ok"


def test_a_literal_is_what_theory_files_pl_reads_as_one(tmp_path: Path) -> None:
    path = tmp_path / "literals.pl"
    path.write_text("".join(f"fact({lit}).\n" for lit in LITERALS))
    python = [_python_problem(term_text(f.args[0])) for f in facts.read(path)]
    r = engine().once("theory_files:read_fact_file(F, LF), "
                      "findall(P, (member(_-T, LF), "
                      "(theory_files:check_theory_fact(T, P0) -> P = P0 ; P = \"ok\")), Ps)",
                      F=str(path))
    prolog = [text(p) for p in r["Ps"]]
    assert python == prolog
    assert python.count("ok") == 5              # p ... neg(p,q): names and integers as arguments
    assert python[5] == "a literal or its negation neg(L), not a double negation neg(neg(p))"


def test_a_value_reads_back_as_itself_in_every_reader(tmp_path: Path) -> None:
    path = tmp_path / "settings.pl"
    path.write_text("".join(f"setting(k{i}, {value_text(v)}).\n" for i, v in enumerate(VALUES)))
    expected = {f"k{i}": [v if isinstance(v, int) and not isinstance(v, bool) else str(v)]
                for i, v in enumerate(VALUES)}
    assert read_native(path).settings == expected
    # SWI-Prolog reads the same facts, one per value
    said = [f.text for f in facts.read(path)]
    r = engine().once("theory_files:read_fact_file(F, LF), "
                      "findall(S, (member(_-T, LF), theory_files:term_text(T, S)), Ss)", F=str(path))
    assert [text(s) for s in r["Ss"]] == said and len(said) == len(VALUES)
    # and clingo: one setting/2 atom per value, nothing else
    ctl = clingo_module().Control(["--warn=none"])
    ctl.add("base", [], path.read_text())
    ctl.ground([("base", [])])
    atoms = [a.symbol for a in ctl.symbolic_atoms]
    assert len(atoms) == len(VALUES) and {(a.name, len(a.arguments)) for a in atoms} == {("setting", 2)}
