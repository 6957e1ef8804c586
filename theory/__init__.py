"""The theory files (Prolog and ASP), shipped as package data.

The fact files are written in the common subset of Prolog and ASP: SWI-Prolog
and clingo read them as they are, and Python with its one reader of theory
files (`read_facts`).
"""
from __future__ import annotations

from collections import defaultdict
from functools import lru_cache
from pathlib import Path
from types import MappingProxyType
from typing import Iterable, Mapping, Union

# The error of a malformed theory file and the messages of its checks are
# its reader's (which imports nothing of this package, so that the two
# make no import cycle).
from pantarhei.bridge.theories.facts import (CHECK_MESSAGES, TheoryFileError,  # noqa: F401
                                             check_message)

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


#: The messages of the checks of a theory file that both readers make
#: (`check_message`, the reader's; SWI-Prolog's check_message/3 of
#: theory_files.pl).
CHECK_MESSAGES_FILE = THEORY_DIR / CHECK_MESSAGES


def default_theory() -> Path:
    """The learned theory that the exploration writes and questions ask
    when no theory file is named (default(theory, F) of defaults.pl, under
    theory/)."""
    return THEORY_DIR / str(defaults()["theory"])


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


class MissingEngine(RuntimeError):
    """clingo or SWI-Prolog is not installed; str() says how to install it."""


CLINGO_MISSING = "clingo is not installed: run `make setup`, or `pip install clingo==5.8.3`"


def clingo_module():
    """The clingo module, or MissingEngine saying how to install it."""
    try:
        import clingo
    except ImportError:
        raise MissingEngine(CLINGO_MISSING) from None
    return clingo


def read_facts(paths: Iterable[Path | str]) -> dict[str, list[tuple]]:
    """The ground facts of theory files: predicate name -> argument tuples.

    Atoms and quoted text both come back as `str`, integers as `int`, and
    compound terms as tuples `(name, arg, ...)`. Facts keep file order.
    Read by the one Python reader of theory files
    (bridge/theories/facts.py, which refuses what SWI-Prolog's
    theory_files.pl refuses, with the same `file:line: what`).
    """
    from pantarhei.bridge.theories.facts import read

    facts: dict[str, list[tuple]] = defaultdict(list)
    for path in paths:
        for f in read(path):
            facts[f.name].append(tuple(f.args))
    return dict(facts)


