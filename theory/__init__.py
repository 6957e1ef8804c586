"""The theory files (Prolog and ASP), shipped as package data.

The fact files are written in the common subset of Prolog and ASP, so Python
reads them with clingo's own parser: one reader for ASP and Python, and the
same files that SWI-Prolog consults.
"""
from __future__ import annotations

from collections import defaultdict
from functools import lru_cache
from pathlib import Path
from types import MappingProxyType
from typing import Iterable, Mapping, Union

#: The folder that holds the theory files.
THEORY_DIR = Path(__file__).resolve().parent
#: The vocabulary fact files, read by SWI-Prolog and by clingo alike.
VOCABULARY_FILES = tuple(THEORY_DIR / "vocabulary" / f"{name}.pl"
                         for name in ("parameters", "propositions", "expectations", "constraints"))

#: The file that loads every Prolog module of the theory (and the shipped
#: theory) into a plain SWI-Prolog: the one list of the Prolog modules.
PROLOG_ENTRY = THEORY_DIR / "pantarhei.pl"

Value = Union[int, str, tuple]


#: The project's defaults (exploration settings, a_0, where the learned
#: theory and the store go), read by Prolog and Python alike.
DEFAULTS_FILE = THEORY_DIR / "defaults.pl"


@lru_cache(maxsize=None)
def defaults() -> Mapping[str, object]:
    """theory/defaults.pl as a read-only mapping, read once per process:
    `default(Key, V)` facts by key (a `Key_permille` value becomes `Key` as a
    float), the defaults of the option table (`option/5`, as
    pantarhei.theory.option_table reads them), and `initial`, the tuple of
    default_initial/1 propositions in file order."""
    from pantarhei.theory.option_table import option_table

    facts = read_facts([DEFAULTS_FILE])
    out: dict[str, object] = {}
    for key, value in facts.get("default", []):
        if key.endswith("_permille"):
            out[key[: -len("_permille")]] = value / 1000
        else:
            out[key] = {"true": True, "false": False}.get(value, value) if isinstance(value, str) else value
    for o in option_table():
        if o.default is not None:
            out.setdefault(o.name, o.default)
    out["initial"] = tuple(p for (p,) in facts.get("default_initial", []))
    return MappingProxyType(out)


def prolog_modules() -> tuple[str, ...]:
    """The Prolog modules of theory/, in load order, as pantarhei.pl lists
    them (`:- use_module(Name).` lines)."""
    import re

    text = PROLOG_ENTRY.read_text(encoding="utf-8")
    return tuple(re.findall(r"^:- use_module\(([a-z_]+)\)\.", text, flags=re.M))


class TheoryFileError(ValueError):
    """A theory file that is not in the common subset; str() is `file:line: what`."""


class MissingEngine(RuntimeError):
    """clingo or SWI-Prolog is not installed; str() says how to install it."""


CLINGO_MISSING = "clingo is not installed: run `make setup`, or `pip install clingo==5.8.3`"


def clingo_module():
    """The clingo module, or MissingEngine saying how to install it."""
    try:
        import clingo
        import clingo.ast  # noqa: F401  (loads the submodule)
    except ImportError:
        raise MissingEngine(CLINGO_MISSING) from None
    return clingo


def read_facts(paths: Iterable[Path | str]) -> dict[str, list[tuple]]:
    """Read ground facts with clingo's parser: predicate name -> argument tuples.

    Atoms and quoted text both come back as `str`, integers as `int`, and
    compound terms as tuples `(name, arg, ...)`. Facts keep file order.
    Anything but a ground fact raises TheoryFileError naming file and line.
    """
    ast = clingo_module().ast
    facts: dict[str, list[tuple]] = defaultdict(list)
    messages: list[str] = []

    def logger(_code, message: str) -> None:
        messages.append(message)

    def on_statement(stm) -> None:
        if stm.ast_type in (ast.ASTType.Program, ast.ASTType.Comment):
            return
        line = f"{stm.location.begin.filename}:{stm.location.begin.line}"
        head = getattr(stm, "head", None)
        if (stm.ast_type != ast.ASTType.Rule or stm.body or head is None
                or head.ast_type != ast.ASTType.Literal or head.sign != ast.Sign.NoSign
                or head.atom.ast_type != ast.ASTType.SymbolicAtom):
            raise TheoryFileError(f"{line}: expected a ground fact such as name(arg, 1).")
        term = _term(head.atom.symbol, line)
        if isinstance(term, str):
            facts[term].append(())
        else:
            facts[term[0]].append(term[1:])

    for path in paths:
        path = Path(path)
        if not path.is_file():
            raise TheoryFileError(f"{path}: no such file")
        try:
            ast.parse_files([str(path)], on_statement, logger=logger, message_limit=1)
        except RuntimeError:
            first = messages[0].splitlines()[0] if messages else f"{path}: cannot parse"
            raise TheoryFileError(_clean_clingo_message(first)) from None
    return dict(facts)


def _term(t, line: str) -> Value:
    clingo = clingo_module()
    SymbolType, ast = clingo.SymbolType, clingo.ast

    kind = t.ast_type
    if kind == ast.ASTType.SymbolicTerm:
        sym = t.symbol
        if sym.type == SymbolType.Number:
            return sym.number
        if sym.type == SymbolType.String:
            return sym.string
        if sym.type == SymbolType.Function and not sym.arguments and not sym.negative:
            return sym.name
    elif kind == ast.ASTType.UnaryOperation and t.operator_type == ast.UnaryOperator.Minus:
        inner = _term(t.argument, line)
        if isinstance(inner, int):
            return -inner
    elif kind == ast.ASTType.Function and not t.external and t.name:
        args = tuple(_term(a, line) for a in t.arguments)
        return (t.name, *args) if args else t.name
    raise TheoryFileError(f"{line}: expected an atom, an integer, quoted text or a term of those")


def _clean_clingo_message(message: str) -> str:
    # "file:12:5-9: error: syntax error, unexpected ." -> "file:12: syntax error, unexpected ."
    import re

    m = re.match(r"^(.*?):(\d+):\d+(?:-\d+(?::\d+)?)?: (?:error|info): (.*)$", message)
    if not m:
        return message
    return f"{m.group(1)}:{m.group(2)}: {m.group(3)}"
