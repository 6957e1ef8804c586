"""The theory files (Prolog and ASP), shipped as package data.

The fact files are written in the common subset of Prolog and ASP: SWI-Prolog
and clingo read them as they are, and Python with its one reader of theory
files (`read_facts`).
"""
from __future__ import annotations

from functools import lru_cache
from pathlib import Path
from types import MappingProxyType
from typing import Mapping, Union

# The error of a malformed theory file, the messages of its checks and the
# reading of its facts are its reader's (which imports nothing of this
# package, so that the two make no import cycle); where the files are is
# theory/locations.py's, which the option table reads too (the
# table imports nothing of this package).
from pantarhei.bridge.theories.facts import (TheoryFileError, check_message,  # noqa: F401
                                             read_facts)
from pantarhei.theory.locations import (CHECK_MESSAGES_FILE, DEFAULTS_FILE,  # noqa: F401
                                        PROLOG_ENTRY, THEORY_DIR, VOCABULARY_FILES)

Value = Union[int, str, tuple]


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
    # The option table imports nothing of this package (it reads the file
    # that locations.py names); it is imported here, when first asked, and
    # not as the package loads, so that `python -m
    # pantarhei.theory.option_table` runs that module once.
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
