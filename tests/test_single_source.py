"""Each fact once: the verdict threshold (a score above it holds), the
default oracle, executor and store, and the bounds and choices of the
options are written in theory/defaults.pl and taken from there; the source
files (Python and Prolog, docs and tests aside) hold no copy of them."""
from __future__ import annotations

import ast
import io
import re
import tokenize
from pathlib import Path

import pytest

from pantarhei.theory import defaults
from pantarhei.theory.option_table import option

ROOT = Path(__file__).resolve().parents[1]
#: The folders of the source, as the package maps them.
SOURCE = ("bridge", "oracle", "theory", "benchmarks")
#: The one home of the facts below.
HOME = ROOT / "theory" / "defaults.pl"

#: Comparisons with one half that are not a score's verdict: a share of
#: pours (the majority of a weighted vote, or of the pours that held) and a
#: predicted probability that an expectation holds.
NOT_A_SCORE = {"share", "p[i]"}

#: The registries that name an oracle or an executor as itself: the table
#: of oracles and of executors, and each one's own name.
NAMED_HERE = {"oracle/base.py", "oracle/physics.py", "oracle/executors.py",
              "oracle/local_executor.py"}


def _files(suffix: str) -> list[Path]:
    return sorted(p for d in SOURCE for p in (ROOT / d).rglob(f"*{suffix}")
                  if "learned" not in p.relative_to(ROOT).parts and p != HOME)


def _rel(p: Path) -> str:
    return p.relative_to(ROOT).as_posix()


def threshold_copies_py(text: str) -> list[str]:
    """The comparisons of a Python source against one half in the verdict's
    form (`x > 0.5`, `x <= 0.5`, `0.5 < x`, `0.5 >= x`), but of a share."""
    toks = [t for t in tokenize.generate_tokens(io.StringIO(text).readline)
            if t.type not in (tokenize.COMMENT, tokenize.NL, tokenize.NEWLINE)]
    found = []
    for i in range(1, len(toks) - 1):
        t, nxt = toks[i], toks[i + 1]
        half = nxt.type == tokenize.NUMBER and ast.literal_eval(nxt.string) == 0.5
        if t.type == tokenize.OP and t.string in (">", "<=") and half:
            left = re.search(r"[\w.\[\]]+\s*$", t.line[: t.start[1]])
            if left is None or left.group(0).strip() not in NOT_A_SCORE:
                found.append(f"{t.start[0]}: {t.line.strip()}")
        back = toks[i - 1]
        if (t.type == tokenize.OP and t.string in ("<", ">=") and back.type == tokenize.NUMBER
                and ast.literal_eval(back.string) == 0.5):
            found.append(f"{t.start[0]}: {t.line.strip()}")
    return found


def threshold_copies_pl(text: str) -> list[str]:
    """The comparisons of a Prolog source against one half in the verdict's
    form (`X > 0.5`, `X =< 0.5`), comments aside."""
    found = []
    for n, line in enumerate(text.splitlines(), 1):
        code = line.split("%", 1)[0]
        if re.search(r"(?<![=<])(>|=<)\s*0\.50*(?![\d])|0\.50*\s*(<|>=)(?!=)", code):
            found.append(f"{n}: {line.strip()}")
    return found


def literal_copies(text: str, literals: set) -> list[str]:
    """The string constants of a Python source among `literals`, docstrings
    aside."""
    tree = ast.parse(text)
    docs = {id(n.body[0].value) for n in ast.walk(tree)
            if isinstance(n, (ast.Module, ast.FunctionDef, ast.AsyncFunctionDef, ast.ClassDef))
            and n.body and isinstance(n.body[0], ast.Expr)
            and isinstance(n.body[0].value, ast.Constant)}
    return [f"{n.lineno}: {n.value!r}" for n in ast.walk(tree)
            if isinstance(n, ast.Constant) and isinstance(n.value, str)
            and n.value in literals and id(n) not in docs]


def test_the_verdict_threshold_lives_in_defaults_pl():
    assert defaults()["verdict_threshold"] == 0.5
    assert "default(verdict_threshold_permille, 500)." in HOME.read_text(encoding="utf-8")


def test_no_source_compares_a_score_with_one_half_of_its_own():
    copies = {_rel(p): c for p in _files(".py")
              if (c := threshold_copies_py(p.read_text(encoding="utf-8")))}
    copies.update({_rel(p): c for p in _files(".pl")
                   if (c := threshold_copies_pl(p.read_text(encoding="utf-8")))})
    assert copies == {}, "the verdict threshold is theory/defaults.pl's (bridge/verdicts.py)"


def test_no_source_names_the_default_oracle_executor_or_store():
    literals = {str(defaults()["oracle"]), str(defaults()["executor"]), str(defaults()["store"])}
    copies = {_rel(p): c for p in _files(".py")
              if _rel(p) not in NAMED_HERE
              and (c := literal_copies(p.read_text(encoding="utf-8"), literals))}
    assert copies == {}, "the defaults are theory/defaults.pl's (pantarhei.theory.defaults)"


def test_no_prolog_module_names_the_default_executor_or_oracle():
    atoms = {str(defaults()["oracle"]), str(defaults()["executor"])}
    copies = {}
    for p in _files(".pl"):
        for n, line in enumerate(p.read_text(encoding="utf-8").splitlines(), 1):
            code = re.sub(r'"[^"]*"', "", line.split("%", 1)[0])
            if any(re.search(rf"\b{a}\b", code) for a in atoms):
                copies.setdefault(_rel(p), []).append(f"{n}: {line.strip()}")
    assert copies == {}


def test_the_shared_flags_take_their_bounds_and_choices_from_the_option_table():
    from pantarhei.bridge.commands import options
    from pantarhei.bridge.exploration.qualify import QUALIFY

    assert QUALIFY == option("qualify").choices
    assert (0, options.SEED_MAX) == (option("seed").low, option("seed").high)
    assert (1, options.WORKERS_MAX) == (option("workers").low, option("workers").high)
    bounds = {str(int(option(name).high)) for name in ("seed", "workers")} | {"2**31", "2 ** 31"}
    for p in _files(".py"):
        text = p.read_text(encoding="utf-8")
        if _rel(p).startswith("bridge/commands/"):
            found = [b for b in bounds if re.search(rf"(?<![\w*]){re.escape(b)}(?![\w*])", text)]
            assert found == [], f"{_rel(p)} copies an option's bound"
        assert '("weighted", "argmax")' not in text, f"{_rel(p)} copies qualify's choices"


@pytest.mark.parametrize("copy, py", [
    ("ok = S > 0.5\n", True), ("ok = scores[:, k] <= 0.5\n", True), ("ok = 0.5 < x\n", True),
    ("    (   Mean > 0.5 -> S = 1 ; S = 0 ),\n", False), ("    X =< 0.5,\n", False)])
def test_a_copy_of_the_threshold_is_found(copy, py):
    found = threshold_copies_py(copy) if py else threshold_copies_pl(copy)
    assert len(found) == 1


@pytest.mark.parametrize("fine, py", [
    ("ok = share > 0.5\nm = like >= 0.5\nc = abs(x - 0.5)\n", True),
    ("    (   Share >= 0.5 -> V = holds ; V = fails ),  % above 0.5\n", False)])
def test_a_majority_or_a_centre_is_not_the_threshold(fine, py):
    assert (threshold_copies_py(fine) if py else threshold_copies_pl(fine)) == []


def test_a_copy_of_a_default_is_found_but_not_in_a_docstring():
    src = '"""make_simulator("pybullet")"""\ndef f(executor="local"):\n    """local"""\n'
    assert literal_copies(src, {"pybullet", "local"}) == ["2: 'local'"]


def prolog_code(text: str) -> list[str]:
    """The lines of a Prolog source without its comments (`%` and `/* */`)
    and the text of its strings, numbered as in the file."""
    text = re.sub(r"/\*.*?\*/", lambda m: "\n" * m.group(0).count("\n"), text, flags=re.S)
    return [re.sub(r'"(?:[^"\\]|\\.)*"', '""', line).split("%", 1)[0]
            for line in text.splitlines()]


def name_copies_pl(text: str, names: set) -> list[str]:
    """The lines of a Prolog source whose code writes an atom of `names`."""
    pattern = re.compile(rf"(?<!\w)(?:{'|'.join(map(re.escape, sorted(names)))})(?!\w)")
    return [f"{n}: {line.strip()}" for n, line in enumerate(prolog_code(text), 1)
            if pattern.search(line)]


def test_a_curiosity_is_named_only_in_its_own_files_and_the_list():
    """A curiosity's name (a value of the option table's `curiosity` row,
    theory/defaults.pl) is written only there, in its Prolog module
    (theory/curiosity/NAME.pl, with its tests) and in its Python side, the
    modules its module declares; the benchmarks choose curiosities to run,
    as the tests and docs do. No other module writes one, not even to tell
    which curiosity wrote a theory: what differs between curiosities is
    asked of the curiosity's module (as the evaluation asks the layout of
    a theory's recorded curiosity)."""
    from pantarhei.bridge.exploration.curiosity_sides import curiosities, python_sides

    names = set(curiosities())
    own = {f"theory/curiosity/{n}.pl" for n in names}
    for modules in python_sides().values():
        own |= {m.removeprefix("pantarhei.").replace(".", "/") + ".py" for m in modules}
    copies = {}
    for p in _files(".pl") + _files(".py"):
        rel = _rel(p)
        if rel in own or rel.startswith("benchmarks/"):
            continue
        text = p.read_text(encoding="utf-8")
        found = name_copies_pl(text, names) if p.suffix == ".pl" else literal_copies(text, names)
        if found:
            copies[rel] = found
    assert copies == {}, "a curiosity is named in its own files and the option table's list"


@pytest.mark.parametrize("source, py, found", [
    (":- use_module(curiosity/learn).\n", False, 1),
    ("unsaid(batch, none, learn, N) :- default(learn_batch, N).\n", False, 1),
    ("curiosity_module(learn, curiosity_learn).\n% learn: the learning one\nx(\"learn\").\n", False, 1),
    ("/* learn\n   and paper */\nlearned(X) :- relearn(X).\n", False, 0),
    ("if s.get('curiosity') == 'learn':\n    pass\n", True, 1),
    ('"""learn"""\nlearner = "learner"\n', True, 0)])
def test_a_curiosity_s_name_is_found_in_code_and_not_in_comments(source, py, found):
    names = {"learn", "paper"}
    copies = literal_copies(source, names) if py else name_copies_pl(source, names)
    assert len(copies) == found


def test_the_nesting_bound_of_theory_files_lives_in_defaults_pl():
    """Both readers of theory files take how deep a term may nest from
    theory/defaults.pl, and neither writes it: a fact nested as deep is
    read, one deeper refused, by Python's reader and SWI-Prolog's."""
    import subprocess

    from pantarhei.bridge.theories import facts

    most = defaults()["nesting_at_most"]
    assert "default(nesting_at_most, " in HOME.read_text(encoding="utf-8")
    assert facts.nesting_at_most() == most
    deepest = "p(" + "f(" * (most - 1) + "a" + ")" * most + ".\n"
    too_deep = "p(" + "f(" * most + "a" + ")" * (most + 1) + ".\n"
    assert facts.parse(deepest)
    with pytest.raises(facts.TheoryFileError, match=f"nested at most {most} deep"):
        facts.parse(too_deep)
    prolog = subprocess.run(
        ["swipl", "-q", "-g", "fact_reader:nesting_at_most(N), write(N), halt",
         str(ROOT / "theory" / "fact_reader.pl")], capture_output=True, text=True, timeout=60)
    assert prolog.stdout.strip() == str(most), prolog.stderr
    for rel in ("bridge/theories/facts.py", "theory/fact_reader.pl"):
        text = (ROOT / rel).read_text(encoding="utf-8")
        assert not re.search(rf"(?i)nesting\w*(\s*=\s*|\(){most}\b", text), f"{rel} writes the bound"


def test_an_option_one_curiosity_reads_is_declared_in_its_module():
    """theory/defaults.pl declares the options that several curiosities
    read, or every one; an option that one curiosity alone reads is
    declared in that curiosity's module (theory/curiosity/NAME.pl), which
    the option table reads."""
    from pantarhei.bridge.theories.facts import read_facts
    from pantarhei.theory.option_table import CURIOSITY_DIR, declarations, option_table

    facts = read_facts([HOME])
    readers: dict[str, set] = {}
    for name, curiosity in facts.get("used_by", []):
        readers.setdefault(name, set()).add(curiosity)
    shared = {row[0] for row in facts["option"]}
    assert not {n for n, cs in readers.items() if len(cs) == 1}, \
        "an option one curiosity reads is declared in its module, not in theory/defaults.pl"
    for o in option_table():
        if o.name not in shared:
            declared = declarations(CURIOSITY_DIR / f"{o.curiosities[0]}.pl")
            assert o.name in {row[0] for row in declared["option"]}, o.name
    assert any(o.name not in shared for o in option_table())


def test_the_unknown_name_warning_is_written_once():
    """A name of a theory of pouring that the vocabulary does not know is
    said in the words of one message, theory/check_messages.pl's
    `unknown_name` (found by one check, theory/ask.pl's, whether
    SWI-Prolog or Python read the file: tests/bridge/theories/
    test_loading.py): no other source writes them."""
    words = "is not a proposition or expectation of pouring"
    found = [_rel(p) for p in _files(".py") + _files(".pl")
             if words in p.read_text(encoding="utf-8")]
    assert found == ["theory/check_messages.pl"]


#: The checks of a theory file made once, each in one module whatever reader
#: read the file: a general rule's words and evidence (theory_checks.pl), a
#: sup/2 pair naming no rule (ask.pl), a cycle of the superiority relation
#: (superiority.pl): Python hands them the theories it read,
#: bridge/theories/prolog_checks.py; and an unknown name (found by
#: theory_checks.pl, said by bridge/theories/unknown_names.py).
SINGLE_CHECKS = {"general_body": "theory/theory_checks.pl",
                 "general_head": "theory/theory_checks.pl",
                 "general_confidence": "theory/theory_checks.pl",
                 "general_count": "theory/theory_checks.pl",
                 "general_kept": "theory/theory_checks.pl", "sup_not_a_rule": "theory/ask.pl",
                 "superiority_cycle": "theory/superiority.pl",
                 "unknown_name": "bridge/theories/unknown_names.py"}


def _says(path: Path, key: str) -> bool:
    """Whether the code of `path` (not its comments or docstrings) says the
    message `key`: a Python string that is the key (or an f-string that
    gives it to check_message), or in Prolog the key
    given to check_message/3 or bound to be given to it."""
    text = path.read_text(encoding="utf-8")
    if path.suffix == ".py":
        call = re.compile(rf"check_message\(\s*['\"]{key}['\"]")     # in an f-string
        return any(t.type == tokenize.STRING and (t.string.strip("\"'") == key or call.search(t.string))
                   for t in tokenize.generate_tokens(io.StringIO(text).readline))
    code = re.sub(r"/\*.*?\*/", "", text, flags=re.S)
    code = "\n".join(line.split("%", 1)[0] for line in code.splitlines())
    return bool(re.search(rf"(check_message\(\s*|=\s*){key}\b", code))


def test_each_check_made_once_says_its_message_in_one_module():
    from pantarhei.theory import CHECK_MESSAGES_FILE, read_facts

    texts = dict(read_facts([CHECK_MESSAGES_FILE])["check_message"])
    files = [p for p in _files(".py") + _files(".pl") if p != CHECK_MESSAGES_FILE]
    for key, home in SINGLE_CHECKS.items():
        assert [_rel(p) for p in files if _says(p, key)] == [home], key
        # nor are its words copied: the longest part of its text between
        # its arguments is in the table alone
        words = max(str(texts[key]).split("~w"), key=len).strip()
        assert len(words) > 12, key
        assert [_rel(p) for p in files if words in p.read_text(encoding="utf-8")] == [], key


def test_the_general_learner_s_tuning_lives_in_defaults_pl():
    """Every default of the general learner's Settings but the seed is read
    from theory/defaults.pl (`general_NAME`), none written in the class."""
    import dataclasses

    from pantarhei.bridge.learning.generalize import Settings
    from pantarhei.theory import defaults

    tuned = [f for f in dataclasses.fields(Settings) if f.name not in ("seed", "band")]
    assert tuned and all(f.default is dataclasses.MISSING for f in tuned)
    assert all(getattr(Settings(), f.name) == defaults()[f"general_{f.name}"] for f in tuned)
