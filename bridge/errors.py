"""Errors for users: one clear line and a non-zero exit, never a traceback."""
from __future__ import annotations

from pantarhei.theory import CLINGO_MISSING, MissingEngine, TheoryFileError  # noqa: F401  (re-exported)


class UserError(Exception):
    """Bad input or a missing engine. `str()` is the one line to print."""

    def __init__(self, message: str, exit_code: int = 2):
        super().__init__(message)
        self.exit_code = exit_code


SWIPL_MISSING = ("SWI-Prolog is not installed (or pyswip cannot find libswipl): "
                 "run `make setup`, or `apt-get install swi-prolog-nox`")
