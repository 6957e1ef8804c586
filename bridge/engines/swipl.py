"""SWI-Prolog hosted in this process through pyswip.

One engine per process, on the main thread only (pyswip is not
thread-safe). `engine()` starts it and loads the theory's modules. Goals
take their values as bindings (`engine().once("p(X, Y)", X=...)`), never by
pasting text into the goal; `prolog_quote` is the one way to write a value
as Prolog text where a whole program is written out.
"""
from __future__ import annotations

import sys
import threading
from functools import lru_cache
from typing import Any, Iterator

from pantarhei.bridge.errors import SWIPL_MISSING, MissingEngine, UserError
from pantarhei.theory import THEORY_DIR, prolog_modules

#: The Prolog modules of theory/ that every engine loads at start.
STARTUP_MODULES = ("theory_files", "vocabulary", "validity")


class Engine:
    """A thin wrapper over pyswip's Prolog: queries, and loading modules and
    theories with errors turned into UserError (one line)."""

    def __init__(self) -> None:
        argv = sys.argv     # pyswip encodes it as UTF-8 on import, and never uses it:
        sys.argv = [a.encode("utf-8", "surrogateescape").decode("utf-8", "replace") for a in argv]
        try:                # an argument that is not UTF-8 is not a missing SWI-Prolog
            from pyswip import Prolog
        except Exception:  # ImportError, or pyswip's own "SWI-Prolog not found"
            raise MissingEngine(SWIPL_MISSING) from None
        finally:
            sys.argv = argv
        self._prolog = Prolog()
        self._thread = threading.get_ident()
        #: The digest of the theory text that defeasible:load_theory/1 last
        #: loaded (see reasoning.logic.prolog_load).
        self.theory_digest = ""
        #: What the exploration's foreign predicates call (see
        #: exploration.session.install): set once per engine.
        self.exploration_host: Any = None
        for m in STARTUP_MODULES:
            self.use_module(m)

    def use_module(self, name: str) -> None:
        """Load theory/<name>.pl (one of the theory's modules, or an
        absolute path) as a module."""
        if not name.startswith("/") and name not in prolog_modules():
            raise ValueError(f"{name} is not a Prolog module of theory/")
        path = name if name.startswith("/") else str(THEORY_DIR / name)
        self._load("use_module(F)", path)

    def load_theory_file(self, path: str, source: str) -> None:
        """Make the theory in `path` the current theory of defeasible.pl;
        an error names `source` (the file the user gave)."""
        try:
            self._load("defeasible:load_theory(F)", path)
        except UserError as e:
            raise UserError(f"{source}: {str(e).split(': ', 1)[-1]}") from None

    def load_theory_files(self, files: list[tuple[str, str, bool]]) -> list[tuple[str, str, str]]:
        """Make the theory files as written the current theory of
        defeasible.pl, merged and checked as `ask` reads them
        (theory/ask.pl's load_theories/2): (path read, name said, checked)
        each, `checked` for a stand-in for a file read and checked before.
        The unknown names its rules use, (where, what, name); UserError
        (one line, naming the file and line) for a theory not read."""
        self.use_module("ask")
        r = self.once(
            "maplist([P, N, K, file(P, N, K)]>>true, Ps, Ns, Ks, Fs), "
            "catch(( ask:load_theories(Fs, Ws), R = ok, "
            "        findall(S, ( member(unknown(W, T, U), Ws), "
            "                     format(string(S), '~w\\t~w\\t~w', [W, T, U]) ), Ss) ), "
            "      E, ( ask:error_line(E, R), Ss = [] ))",
            Ps=[p for p, _, _ in files], Ns=[n for _, n, _ in files],
            Ks=["checked" if c else "file" for _, _, c in files])
        if text(r["R"]) != "ok":
            raise UserError(text(r["R"]))
        return [tuple(text(s).split("\t")) for s in r["Ss"]]

    def _load(self, goal: str, path: str) -> None:
        result = self.once(f"catch(({goal}, R = ok), E, theory_files:error_message(E, R))", F=path)
        if text(result["R"]) != "ok":
            raise UserError(text(result["R"]))

    def query(self, goal: str, **bindings: Any) -> Iterator[dict]:
        """All solutions of goal; keyword arguments are bound as variables."""
        if threading.get_ident() != self._thread:
            raise RuntimeError("Prolog must be called from the thread that started it")
        prefix = ", ".join(f"{k} = {prolog_quote(v)}" for k, v in bindings.items())
        full = f"{prefix}, ({goal})" if prefix else goal
        yield from self._prolog.query(full)

    def once(self, goal: str, **bindings: Any) -> dict:
        """The first solution of goal (RuntimeError if it fails). The query
        is closed before returning: pyswip must not have two open at once."""
        solutions = self.query(goal, **bindings)
        try:
            for sol in solutions:
                return sol
        finally:
            solutions.close()
        raise RuntimeError(f"goal failed: {goal}")

    def succeeds(self, goal: str, **bindings: Any) -> bool:
        """Whether goal has a solution (the query closed before returning)."""
        try:
            self.once(goal, **bindings)
        except RuntimeError:
            return False
        return True


def prolog_quote(value: Any) -> str:
    """A Python value written as a Prolog term: text as a quoted atom, lists
    and tuples as lists, a dict as a dict with quoted keys, booleans as
    true/false, numbers as they are."""
    if isinstance(value, dict):
        return "_{" + ", ".join(f"{prolog_quote(k)}: {prolog_quote(v)}"
                                for k, v in value.items()) + "}"
    if isinstance(value, (list, tuple)):
        return "[" + ", ".join(prolog_quote(v) for v in value) + "]"
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, (int, float)):
        return repr(value)
    s = str(value).replace("\\", "\\\\").replace("'", "\\'")
    return f"'{s}'"


@lru_cache(maxsize=1)
def engine() -> Engine:
    """The process's Prolog engine, started on first use."""
    return Engine()


def text(value: Any) -> str:
    """A string that came back from Prolog (pyswip gives text as bytes)."""
    if isinstance(value, bytes):
        return value.decode()
    if isinstance(value, list):
        return bytes(value).decode() if all(isinstance(c, int) for c in value) else str(value)
    return str(value)
