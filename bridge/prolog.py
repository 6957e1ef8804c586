"""SWI-Prolog hosted in this process through pyswip.

One engine per process, on the main thread only (pyswip is not
thread-safe). `engine()` starts it and loads the theory's modules.
"""
from __future__ import annotations

import threading
from functools import lru_cache
from typing import Any, Iterator

from pantarhei.theory import THEORY_DIR

from .errors import SWIPL_MISSING, MissingEngine, UserError

#: The Prolog modules of theory/ loaded into every engine.
MODULES = ("theory_files", "vocabulary", "validity")


class Engine:
    """A thin wrapper over pyswip's Prolog: queries, and loading modules with
    theory errors turned into UserError (`file:line: what was expected`)."""

    def __init__(self) -> None:
        try:
            from pyswip import Prolog
        except Exception:  # ImportError, or pyswip's own "SWI-Prolog not found"
            raise MissingEngine(SWIPL_MISSING) from None
        self._prolog = Prolog()
        self._thread = threading.get_ident()
        for m in MODULES:
            self.use_module(m)

    def use_module(self, name: str) -> None:
        """Load theory/<name>.pl (or an absolute path) as a module."""
        path = name if name.startswith("/") else str(THEORY_DIR / name)
        result = self.once(
            "catch((use_module(Path), R = ok), E, "
            "(  catch(theory_files:error_message(E, R), _, fail) -> true "
            "; format(string(R), '~p', [E]) ))",
            Path=path)
        if result["R"] != "ok":
            raise UserError(_text(result["R"]))

    def query(self, goal: str, **bindings: Any) -> Iterator[dict]:
        """All solutions of goal; keyword arguments are bound as variables."""
        if threading.get_ident() != self._thread:
            raise RuntimeError("Prolog must be called from the thread that started it")
        prefix = ", ".join(f"{k} = {_term(v)}" for k, v in bindings.items())
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


def _text(value: Any) -> str:
    if isinstance(value, bytes):
        return value.decode()
    if isinstance(value, list):
        return bytes(value).decode() if all(isinstance(c, int) for c in value) else str(value)
    return str(value)


def _term(value: Any) -> str:
    """A Python value written as a Prolog term (atoms quoted, lists as lists)."""
    if isinstance(value, (list, tuple)):
        return "[" + ", ".join(_term(v) for v in value) + "]"
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
    return _text(value)
