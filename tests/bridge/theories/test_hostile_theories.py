"""Theory files are data: Python's reader (bridge/theories) and SWI-Prolog's
(theory/theory_files.pl, through defeasible:load_theory/1) refuse the same
hostile files with the same `file:line: what`, and quoted text can never
become program text for clingo or Prolog.

A concern no single module owns: Python's reader is facts.py (the
language of theory files), native.py (the forms of the theory's facts) and
well_formed.py (names, kinds, literals and their messages), checked
against theory/theory_files.pl; writing quoted text back is
model.Theory.native with well_formed.value_text."""
from __future__ import annotations

import shutil
import subprocess
from pathlib import Path

import pytest

from pantarhei.bridge.reasoning.logic import Semantics, asp_conclusions, prolog_conclusions
from pantarhei.bridge.theories import facts
from pantarhei.bridge.theories.native import read_native
from pantarhei.theory import THEORY_DIR, TheoryFileError, check_message

LITERAL = "a literal such as p, bird(tweety) or neg(p) (names and integers as arguments), not "
INJECTION = r'rule(h2, defeasible, p("x)).\n#include \"other.pl\".\nrule(h3, defeasible, q(1")).'

#: name -> (file content, line, message)
CORPUS: dict[str, tuple[bytes, int, str]] = {
    "injection through quotes": (
        b"rule(h1, defeasible, a).\n" + INJECTION.encode() + b"\n", 2,
        LITERAL + r'p("x)).\n#include \"other.pl\".\nrule(h3, defeasible, q(1")'),
    "injection through quotes, raw newlines": (
        b'rule(h2, defeasible, p("x)).\n#include "other.pl".\nrule(h3, defeasible, q(1")).\n', 1,
        check_message("expected_fact")),
    "#include": (b'fact(a).\n#include "/etc/passwd".\n', 2, check_message("hash_directive")),
    "#script": (b"#script (python)\nimport os\nos.system('touch /tmp/pwned')\n#end.\n", 1,
                check_message("hash_directive")),
    "#const after a fact on its line": (b"fact(a). #const n = 3.\n", 1, check_message("hash_directive")),
    "#show": (b"fact(a).\n\n  #show fact/1.\n", 3, check_message("hash_directive")),
    "directive": (b"fact(a).\n:- initialization(shell('touch /tmp/pwned')).\n", 2, check_message("directive")),
    "query directive": (b"?- halt.\n", 1, check_message("directive")),
    "rule": (b'fact(a).\n\nfact(b) :- shell("touch /tmp/pwned").\n', 3, check_message("rule_not_fact")),
    "term expansion": (b"term_expansion(_, fact(pwned)).\n", 1, check_message("variable")),
    "variable on a later line of its fact": (b"rule(r1,\n  defeasible,\n  X).\n", 1, check_message("variable")),
    "non-ASCII atom": ("fact(a).\nfact(café).\n".encode(), 2, check_message("not_ascii", f"{0xC3:#04x}")),
    "non-ASCII in quoted text": ('setting(note, "naïve").\n'.encode(), 1, check_message("not_ascii", f"{0xC3:#04x}")),
    "invalid UTF-8 in a comment": (b"fact(a).\n% \xff\xfe\nfact(b).\n", 2, check_message("not_ascii", f"{0xFF:#04x}")),
    "NUL byte": (b"fact(a).\nfact(b\x00).\n", 2, check_message("not_ascii", f"{0:#04x}")),
    "integer past 2^31 - 1": (b"setting(size, 3000000000).\n", 1, check_message("int_range", 3000000000)),
    "integer below -2^31": (b"setting(size, -2147483649).\n", 1, check_message("int_range", -2147483649)),
    "integer of 400 digits": (b"setting(size, 1" + b"0" * 400 + b").\n", 1,
                              check_message("int_range", "100000000000...0000 (401 digits)")),
    "integer of 5,001 digits": (b"fact(a).\nfact(p(-" + b"9" * 5001 + b")).\n", 2,
                                check_message("int_range", "-99999999999...9999 (5001 digits)")),
    "leading zeros past Python's 4,300 digits": (b"setting(size, " + b"0" * 5000 + b"1).\n", 1,
                                                 check_message("int_form", "000000000000...0001 (5001 digits)")),
    "integer in hexadecimal": (b"setting(size, 0x1F).\n", 1, check_message("expected_fact")),
    "integer with leading zeros": (b"setting(size, 007).\n", 1, check_message("int_form", "007")),
    "float": (b"setting(x, 1.5).\n", 1, check_message("float")),
    "list": (b"setting(x, [1, 2]).\n", 1, check_message("list")),
    "quoted atom": (b"fact('a').\n", 1, check_message("expected_fact")),
    "block comment": (b"/* a comment clingo does not read */\nfact(a).\n", 1, check_message("expected_fact")),
    "escape only SWI-Prolog reads": (b'setting(x, "a\\x41\\b").\n', 1, check_message("text_escape")),
    "ASP pooling": (b"fact(a;b).\n", 1, check_message("expected_fact")),
    "operator": (b"fact(a:b).\n", 1, check_message("expected_fact")),
    "no period at the end": (b"fact(a).\nfact(b)\n", 2, check_message("expected_fact")),
    "two facts without layout": (b"fact(a).fact(b).\n", 1, check_message("expected_fact")),
    "empty argument list": (b"fact().\n", 1, check_message("expected_fact")),
    "rule of another kind": (b"rule(r1, defeasible, b).\nrule(r2, usually, c).\n", 2,
                             "rule r2: kind strict, defeasible or defeater, not usually"),
    "rule of another arity": (b"rule(r1, b).\n", 1, "expected rule(Id, Kind, Head), not a rule/2 fact"),
    "rule named by a number": (b"rule(1, defeasible, b).\n", 1,
                               "rule(Id, Kind, Head): a name in lower case letters, digits and _, not 1"),
    "nested literal": (b"fact(p(f(a))).\n", 1, LITERAL + "p(f(a))"),
    "double negation": (b"fact(neg(neg(a))).\n", 1,
                        "a literal or its negation neg(L), not a double negation neg(neg(a))"),
    "a second rule of a name": (b"rule(r1, defeasible, b).\nbody(r1, a).\nrule(r1, strict, b).\n", 3,
                                "a second rule named r1"),
    "body without its rule": (b"rule(r1, defeasible, b).\nbody(r9, a).\n", 2,
                              "body(r9, _) of a rule r9 that has no rule(r9, Kind, Head) fact"),
    "a term nested 33 deep": (b"fact(a).\nfact(" + b"f(" * 32 + b"a" + b")" * 33 + b".\n", 2,
                              check_message("nesting", facts.nesting_at_most())),
    "a term nested 33 deep, the first line of a fact": (
        b"fact(p(a)).\nsetting(x,\n" + b"f(" * 32 + b"a" + b")" * 32 + b").\n", 2, check_message("nesting", facts.nesting_at_most())),
    "the name not": (b"rule(r1, defeasible, a).\nbody(r1, not).\n", 2, check_message("not_name")),
    "the name not as a functor": (b"fact(not(a)).\n", 1, check_message("not_name")),
    "a confidence of 0 for a rule's head": (
        b"rule(r1, defeasible, no_spill).\nprovenance(r1, confidence_permille, 0).\n", 2,
        "rule r1: a confidence is the permille of its pours that keep its head, 1 to 1000, not 0"),
    "a confidence past 1000": (
        b"rule(g1, defeasible, no_spill).\nprovenance(g1, layer, general).\n"
        b"provenance(g1, confidence_permille, 1200).\n", 3,
        "rule g1: a confidence is the permille of its pours that keep its head, 1 to 1000, not 1200"),
    "a confidence in words": (
        b"rule(r1, defeasible, no_spill).\nprovenance(r1, confidence_permille, high).\n", 2,
        "rule r1: a confidence is the permille of its pours that keep its head, 1 to 1000, not high"),
    "pours held past those counted": (
        b"rule(g0, defeasible, no_spill).\nexplored(a2, light_liquid).\n"
        b"held(a2, no_spill, 13, 12).\n", 3,
        "held(a2, no_spill, Held, Pours): Held of Pours pours, whole numbers with "
        "0 <= Held <= Pours, not 13 of 12"),
    "pours held in words": (
        b"fact(a).\nheld(a2, no_spill, many, 12).\n", 2,
        "held(a2, no_spill, Held, Pours): Held of Pours pours, whole numbers with "
        "0 <= Held <= Pours, not many of 12"),
    "pours held of no expectation": (
        b"fact(a).\nheld(a2, 3, 1, 2).\n", 2,
        "held(Antecedent, Expectation, Held, Pours): a name in lower case letters, digits and _, "
        "not 3"),
    "pours held without their count": (
        b"fact(a).\nheld(a2, no_spill, 11).\n", 2,
        "expected held(Antecedent, Expectation, Held, Pours), not a held/3 fact"),
    "an explored proposition as text": (
        b"fact(a).\nexplored(a2, \"light\").\n", 2,
        "explored(Antecedent, Proposition): a name in lower case letters, digits and _, "
        "not \"light\""),
}


def _prolog_errors(paths: list[Path]) -> list[str]:
    """What defeasible:load_theory/1 says of each file, in one swipl."""
    swipl = shutil.which("swipl")
    assert swipl, "SWI-Prolog is needed"
    files = ", ".join("'" + str(p).replace("'", "\\'") + "'" for p in paths)
    goal = (f"use_module('{THEORY_DIR / 'defeasible'}'), use_module('{THEORY_DIR / 'theory_files'}'), "
            f"forall(member(F, [{files}]), "
            "(catch((load_theory(F), M = ok), E, theory_files:error_message(E, M)), "
            "format('~w~n', [M])))")
    p = subprocess.run([swipl, "-q", "-g", goal, "-t", "halt"], capture_output=True, text=True, timeout=120)
    assert p.returncode == 0, p.stderr
    return p.stdout.splitlines()


def _python_error(path: Path) -> str:
    try:
        read_native(path)
    except TheoryFileError as e:
        return str(e)
    return "ok"


def test_both_readers_refuse_the_hostile_corpus_alike(tmp_path: Path) -> None:
    paths = []
    for i, (content, _, _) in enumerate(CORPUS.values()):
        path = tmp_path / f"hostile{i}.pl"
        path.write_bytes(content)
        paths.append(path)
    prolog = _prolog_errors(paths)
    assert len(prolog) == len(paths)
    for (name, (_, line, message)), path, said in zip(CORPUS.items(), paths, prolog):
        expected = f"{path}:{line}: {message}"
        assert _python_error(path) == expected, name
        assert said == expected, name


def test_quoted_text_is_written_back_quoted(tmp_path: Path) -> None:
    """Text that reads as ASP and Prolog when unquoted stays one string in
    every engine (before, a quoted argument was written back bare)."""
    hostile = r'x).\n#include \"other.pl\".\nfact(pwned).\n%'
    path = tmp_path / "t.pl"
    path.write_text(f'setting(note, "{hostile}").\nset_aside(0, 1, "{hostile}").\n'
                    "rule(r1, defeasible, a).\nfact(b).\n")
    theory = read_native(path)
    text = hostile.replace(r"\n", "\n").replace(r"\"", '"')
    assert theory.settings["note"] == [text]
    again = tmp_path / "again.pl"
    again.write_text(theory.native())
    assert read_native(again).settings == theory.settings
    assert read_native(again).extra == theory.extra
    for conclusions in (asp_conclusions(theory, Semantics()), prolog_conclusions(theory, Semantics())):
        assert "pwned" not in conclusions["+D"] and conclusions["+d"] == ["a", "b"]
    # clingo reads the written theory as the same facts
    from pantarhei.theory import clingo_module

    ctl = clingo_module().Control(["--warn=none"])
    ctl.add("base", [], theory.native())
    ctl.ground([("base", [])])
    atoms = {str(a.symbol.name) for a in ctl.symbolic_atoms}
    assert atoms == {"setting", "set_aside", "rule", "fact"}
    (note,) = [a.symbol for a in ctl.symbolic_atoms if a.symbol.name == "setting"]
    assert note.arguments[1].string == text


def test_the_shipped_theory_reads_alike(tmp_path: Path) -> None:
    """Every fact of the shipped theory, as both readers read it."""
    from pantarhei.bridge.theories.loading import DEFAULT_THEORY

    if not DEFAULT_THEORY.is_file():
        pytest.skip("no shipped theory")
    python = [f.text for f in facts.read(DEFAULT_THEORY)]
    swipl = shutil.which("swipl")
    goal = (f"use_module('{THEORY_DIR / 'theory_files'}'), read_fact_file('{DEFAULT_THEORY}', LF), "
            "forall(member(_-F, LF), (term_text(F, T), format('~w~n', [T])))")
    p = subprocess.run([swipl, "-q", "-g", goal, "-t", "halt"], capture_output=True, text=True, timeout=120)
    assert p.returncode == 0, p.stderr
    assert p.stdout.splitlines() == python


BIRDS = ("rule(r1, defeasible, flies).\nbody(r1, bird).\nrule(r2, defeasible, neg(flies)).\n"
         "body(r2, penguin).\nfact(bird).\nfact(penguin).\n")


@pytest.mark.parametrize("hostile", [
    'concl("+D", pwned).\n',           # a conclusion of conclusions.lp, forged
    "superior(r2, r1).\n",              # superiority of derivability.lp, forged
    "changed.\n",                       # kept clingo doubling its steps until killed
    "defeated(r1).\nhasbody(r2).\nsup_cycle(r1).\n",
])
def test_facts_of_other_predicates_never_reach_clingo(tmp_path: Path, hostile: str) -> None:
    """The theory's own predicates reach the encodings; anything else a
    file holds is kept aside (and written back by convert), never taken by
    clingo for an atom of its own: both engines conclude the same."""
    import signal

    path = tmp_path / "birds.pl"
    path.write_text(BIRDS + hostile)
    theory = read_native(path)
    assert theory.extra and theory.extra[0].split("(")[0] in hostile

    def too_slow(*_):
        raise TimeoutError("clingo did not finish in 20 s")

    old = signal.signal(signal.SIGALRM, too_slow)
    signal.alarm(20)
    try:
        asp = asp_conclusions(theory, Semantics())
    finally:
        signal.alarm(0)
        signal.signal(signal.SIGALRM, old)
    assert asp == prolog_conclusions(theory, Semantics())
    assert asp["+D"] == ["bird", "penguin"] and "neg(flies)" not in asp["+d"]


@pytest.mark.parametrize("command", [
    ("conclusions", "{f}"), ("conclusions", "--engine", "asp", "{f}"), ("convert", "{f}"),
    ("ask", "pour", "--theory", "{f}"), ("plan", "--goal", "no_spill", "--theory", "{f}"),
    ("prolog", "--theory", "{f}", "-g", "true"),
    ("evaluate", "--theory", "{f}", "--no-progress", "--out", "{dir}"),
])
@pytest.mark.parametrize("hostile", ["directive", "#include", "integer of 5,001 digits"])
def test_every_command_that_reads_a_theory_refuses_the_corpus_in_one_line(
        tmp_path: Path, command: tuple[str, ...], hostile: str) -> None:
    from tests.conftest import assert_one_line_error, run_cli

    content, line, message = CORPUS[hostile]
    f = tmp_path / "hostile.pl"
    f.write_bytes(content)
    r = run_cli(*(a.format(f=f, dir=tmp_path / "report") for a in command))
    assert assert_one_line_error(r).endswith(f"{f}:{line}: {message}")
    assert sorted(p.name for p in tmp_path.iterdir()) == ["hostile.pl"]     # nothing written


def test_a_term_nested_32_deep_is_read_by_both(tmp_path: Path) -> None:
    f = tmp_path / "deep.pl"
    f.write_bytes(b"setting(x, " + b"f(" * 30 + b"a" + b")" * 30 + b").\n")
    assert _python_error(f) == "ok" and _prolog_errors([f]) == ["ok"]


def test_facts_named_like_built_ins_are_data_to_both_readers(tmp_path: Path) -> None:
    """halt., true. and call(a). are facts of other predicates, kept aside
    by Python's reader and never added by SWI-Prolog's (which could not
    add them: they are built-ins)."""
    f = tmp_path / "builtins.pl"
    f.write_bytes(b"halt.\ntrue.\ncall(a).\nrule(r1, defeasible, b).\n")
    assert _python_error(f) == "ok" and _prolog_errors([f]) == ["ok"]
    assert sorted(prolog_conclusions(read_native(f))["+d"]) == ["b"]


def _costly():
    from benchmarks.hostile import CORPUS, READERS
    return [(name, engine) for name in CORPUS for engine in READERS]


@pytest.mark.slow
@pytest.mark.parametrize("name, engine", _costly())
def test_every_costly_file_is_answered_or_refused_under_the_caps(tmp_path: Path, name: str,
                                                                 engine: str) -> None:
    """benchmarks/hostile.py's corpus (files built to cost a reader more
    than their size), each read by each engine's command with its memory
    capped and killed past its time cap: an answer or one safe line, no
    traceback. (`make bench` prints their times and memory.)"""
    from benchmarks.hostile import CAP_BYTES, CAP_S, CORPUS, command, read_capped

    file, make = CORPUS[name]
    path = tmp_path / file
    path.write_bytes(make())
    r = read_capped(command(engine, path))
    assert r.code is not None, f"killed after {CAP_S} s"
    assert r.code in (0, 1, 2) and "Traceback" not in r.err and "MemoryError" not in r.err, r.err[-2000:]
    assert r.peak_bytes < CAP_BYTES
    errors = [line for line in r.err.splitlines() if not line.startswith("warning:")]
    if r.code:
        assert len(errors) == 1 and str(path) in errors[0], r.err[-2000:]
    assert not any(c in r.err for c in "\x1b\x07\r"), r.err[-2000:]


@pytest.mark.slow
def test_a_50_mb_line_on_asks_standard_input_is_skipped_in_bounded_memory() -> None:
    import sys

    from benchmarks.hostile import read_capped

    line = b"pour " * (10 * 2**20) + b"\npour from the side\n"
    r = read_capped([sys.executable, "-m", "pantarhei.bridge", "ask"], stdin=line,
                    memory=1 * 2**30)
    assert r.code == 1 and "Traceback" not in r.err, r.err[-2000:]
    assert r.err.strip() == "pantarhei ask: line 1: longer than 65536 bytes: not read"
    assert r.peak_bytes < 300 * 2**20
