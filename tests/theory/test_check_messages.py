"""The messages of the checks of a theory file that both readers make
(theory/check_messages.pl): each text is written once, and SWI-Prolog
(check_message/3 of theory_files.pl, ask's load_theories/2) and Python
(pantarhei.theory.check_message, the theory loader) say the same of the
same bad file: each message of the table has one here."""
from __future__ import annotations

import re
import shutil
import subprocess
from pathlib import Path

import pytest

from pantarhei.bridge.errors import UserError
from pantarhei.bridge.theories import loading
from pantarhei.theory import CHECK_MESSAGES_FILE, THEORY_DIR, check_message, read_facts

#: Bad files (name -> their texts, one file each, read as one theory) and
#: the file and line the message names.
CYCLIC = {
    "a cycle in one file": (
        ["rule(r1, defeasible, b).\nrule(r2, defeasible, neg(b)).\nsup(r1, r2).\nsup(r2, r1).\n"],
        0, 3),
    "a cycle across two files": (
        ["rule(r1, defeasible, b).\nrule(r2, defeasible, neg(b)).\nsup(r1, r2).\n",
         "fact(a).\nsup(r2, r1).\n"], 0, 3),
    "a rule superior to itself": (
        ["rule(r1, defeasible, b).\nfact(a).\nsup(r1, r1).\n"], 0, 3),
    "a cycle through specificity": (
        ["rule(r1, defeasible, p).\nbody(r1, a).\nrule(r2, defeasible, p).\nbody(r2, a).\n"
         "body(r2, b).\nrule(r3, defeasible, neg(p)).\nbody(r3, a).\nlearned(r2).\nlearned(r3).\n"
         "sup(r1, r2).\nsup(r3, r1).\n"], 0, 10),
}


#: The start of a general rule's theory.
GENERAL = "rule(g1, defeasible, no_spill).\nprovenance(g1, layer, general).\n"

#: A bad file for each other message of the table: key -> (its text, the
#: line the message names, the message's arguments).
BAD = {
    "arity": ("fact(a).\nrule(r1, defeasible).\n", 2, ("rule(Id, Kind, Head)", "rule", 2)),
    "name_argument": ('fact(a).\nrule("r1", defeasible, b).\n', 2,
                      ("rule(Id, Kind, Head)", '"r1"')),
    "kind": ("rule(r1, sometimes, b).\n", 1, ("r1", "sometimes")),
    "held": ("fact(a).\nheld(a2, no_spill, 13, 12).\n", 2, ("a2", "no_spill", 13, 12)),
    "confidence": ("rule(r1, defeasible, b).\nprovenance(r1, confidence_permille, 0).\n", 2,
                   ("r1", 0)),
    "double_negation": ("fact(a).\nrule(r1, defeasible, neg(neg(b))).\n", 2, ("neg(neg(b))",)),
    "literal": ("fact(p(f(a))).\n", 1, ("p(f(a))",)),
    "second_rule": ("rule(r1, defeasible, b).\nrule(r1, defeasible, c).\n", 2, ("r1",)),
    "dangling_body": ("fact(a).\nbody(r9, a).\n", 2, ("r9", "r9", "r9")),
    "sup_not_a_rule": ("rule(r1, defeasible, b).\nsup(r1, r9).\n", 2, ("r1", "r9", "r9")),
    "empty_theory": ("% nothing\n", 0, ()),
    "general_body": (GENERAL + "body(g1, pour_sideways).\n", 3, ("g1", "pour_sideways")),
    "general_head": ("rule(g1, defeasible, wet).\nprovenance(g1, layer, general).\n", 1,
                     ("g1", "wet")),
    "general_count": (GENERAL + "provenance(g1, support, many).\n", 3, ("g1", "support", "many")),
    "general_kept": (GENERAL + "provenance(g1, support, 3).\nprovenance(g1, kept, 5).\n", 4,
                     ("g1", 5, 3)),
}
#: Messages no native file can bring out of both readers: a general rule's
#: confidence past 0 to 1000 is refused first as any rule's (`confidence`).
NO_NATIVE_FILE = {"general_confidence"}
#: Messages whose bad files other tests give both readers: a file past 32
#: MiB and a name the vocabulary does not know, a warning
#: (tests/bridge/theories/test_loading.py), and the language of theory
#: files (the hostile corpus of tests/bridge/theories/test_hostile_theories.py).
ELSEWHERE = {"too_large", "unknown_name", "not_ascii", "expected_fact", "directive",
             "hash_directive", "rule_not_fact", "variable", "float", "list", "not_name",
             "text_escape", "nesting", "int_range", "int_form"}
#: Two files whose second defines the first's rule again (the message
#: names the second's line and the first file).
TWICE = ("rule(r1, defeasible, b).\n", "fact(c).\nrule(r1, defeasible, d).\n")


def _swipl(goal: str) -> list[str]:
    swipl = shutil.which("swipl")
    assert swipl, "SWI-Prolog is needed"
    p = subprocess.run([swipl, "-q", "-g", goal, "-t", "halt"], capture_output=True, text=True,
                       timeout=120)
    assert p.returncode == 0, p.stderr
    return p.stdout.splitlines()


def _quoted(path: Path) -> str:
    return "'" + str(path).replace("\\", "\\\\").replace("'", "\\'") + "'"


def _prolog_errors(theories: list[list[Path]]) -> list[str]:
    """What `ask` says of each theory (its files: load_theories/2, its
    error as error_line/2 prints it), in one swipl."""
    lists = ", ".join("[" + ", ".join(map(_quoted, files)) + "]" for files in theories)
    return _swipl(f"use_module({_quoted(THEORY_DIR / 'ask')}), "
                  f"forall(member(Fs, [{lists}]), "
                  "(catch((ask:load_theories(Fs, _), M = ok), E, ask:error_line(E, M)), "
                  "format('~w~n', [M])))")


def _python_error(files: list[Path]) -> str:
    try:
        loading.load(files)
    except UserError as e:
        return str(e)
    return "ok"


def test_every_message_is_one_text_with_its_arguments_as_w():
    rows = read_facts([CHECK_MESSAGES_FILE])["check_message"]
    assert rows and len({key for key, _ in rows}) == len(rows)
    for key, text in rows:
        # format/2's ~w alone, which Python writes as SWI-Prolog does
        assert re.sub("~w", "", text).count("~") == 0, key


def test_both_languages_render_every_message_alike():
    rows = read_facts([CHECK_MESSAGES_FILE])["check_message"]
    args = {key: [f"x{i} > y" for i in range(text.count("~w"))] for key, text in rows}
    calls = ", ".join(f"{key}-[{', '.join(_quoted(Path(a)) for a in args[key])}]" for key, _ in rows)
    prolog = _swipl(f"use_module({_quoted(THEORY_DIR / 'theory_files')}), "
                    f"forall(member(K-As, [{calls}]), "
                    "(check_message(K, As, M), format('~w~n', [M])))")
    assert prolog == [check_message(key, *args[key]) for key, _ in rows]


def test_both_readers_say_the_same_of_the_same_cyclic_theory(tmp_path: Path):
    theories = []
    for i, (texts, _, _) in enumerate(CYCLIC.values()):
        files = []
        for j, text in enumerate(texts):
            f = tmp_path / f"t{i}_{j}.pl"
            f.write_text(text, encoding="utf-8")
            files.append(f)
        theories.append(files)
    prolog = _prolog_errors(theories)
    assert len(prolog) == len(theories)
    for (name, (_, k, line)), files, said in zip(CYCLIC.items(), theories, prolog):
        python = _python_error(files)
        assert python == said, name
        assert python.startswith(f"{files[k]}:{line}: the superiority relation has a cycle, "), name


def test_an_unknown_check_or_a_wrong_count_of_arguments_is_refused():
    with pytest.raises(KeyError):
        check_message("no_such_check", "x")
    with pytest.raises(ValueError, match="takes 1 arguments, not 2"):
        check_message("superiority_cycle", "a", "b")


def test_every_message_has_a_bad_file_here():
    keys = {key for key, _ in read_facts([CHECK_MESSAGES_FILE])["check_message"]}
    assert keys == (set(BAD) | {"superiority_cycle", "already_defined", "no_such_file"}
                    | NO_NATIVE_FILE | ELSEWHERE)


def test_both_readers_say_each_message_of_the_table_of_its_bad_file(tmp_path: Path):
    theories = []
    for key, (text, _, _) in BAD.items():
        f = tmp_path / f"{key}.pl"
        f.write_text(text, encoding="utf-8")
        theories.append([f])
    prolog = _prolog_errors(theories)
    assert len(prolog) == len(theories)
    for (key, (_, line, args)), files, said in zip(BAD.items(), theories, prolog):
        expected = f"{files[0]}{f':{line}' if line else ''}: " + check_message(key, *args)
        assert _python_error(files) == expected, key
        assert said == expected, key


def test_both_readers_say_a_rule_is_already_defined_in_an_earlier_file(tmp_path: Path):
    files = []
    for i, text in enumerate(TWICE):
        files.append(tmp_path / f"f{i}.pl")
        files[-1].write_text(text, encoding="utf-8")
    (said,) = _prolog_errors([files])
    assert _python_error(files) == said == f"{files[1]}:2: " + check_message(
        "already_defined", "r1", files[0])


def test_both_fact_readers_say_a_file_is_missing_alike(tmp_path: Path):
    from pantarhei.bridge.theories import facts

    missing = tmp_path / "missing.pl"
    (said,) = _swipl(f"use_module({_quoted(THEORY_DIR / 'theory_files')}), "
                     f"catch(read_fact_file({_quoted(missing)}, _), E, "
                     "(theory_files:theory_error_message(E, M), writeln(M)))")
    with pytest.raises(facts.TheoryFileError) as e:
        facts.read(missing)
    assert said.replace(":0:", ":") == str(e.value) == f"{missing}: " + check_message("no_such_file")
