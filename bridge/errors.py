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


#: The longest error line printed (characters): a message quoting a long
#: input is cut in its middle, so that a 5 MB question is not echoed whole
#: (room for two paths of the longest a system takes).
LINE_AT_MOST = 8192

#: The longest quotation of an input in a message (`quoted`).
QUOTE_AT_MOST = 80


def escaped(text: str) -> str:
    """`text` with every control character (C0, DEL, C1, and the line and
    paragraph separators) written as an escape (`\\n`, `\\x1b`, `\\u2028`), so
    that it is one line and moves no terminal: no ESC sequence, no BEL, no CR."""
    out = []
    for ch in text:
        o = ord(ch)
        if o < 0x20 or 0x7F <= o < 0xA0:
            out.append({"\n": "\\n", "\r": "\\r", "\t": "\\t"}.get(ch, f"\\x{o:02x}"))
        elif o in (0x2028, 0x2029) or 0xD800 <= o < 0xE000:
            out.append(f"\\u{o:04x}")
        else:
            out.append(ch)
    return "".join(out)


def shortened(text: str, at_most: int) -> str:
    """`text` cut in its middle to at most `at_most` characters (with how
    many were left out)."""
    if len(text) <= at_most:
        return text
    keep = max(at_most - 24, 8)
    head, tail = keep * 2 // 3, keep - keep * 2 // 3
    return f"{text[:head]}[... {len(text) - head - tail} more ...]{text[len(text) - tail:]}"


def quoted(text: str, at_most: int = QUOTE_AT_MOST) -> str:
    """An input as a message quotes it: in single quotes, shortened, its
    control characters escaped."""
    return "'" + shortened(escaped(str(text)), at_most) + "'"


def safe_line(text: str) -> str:
    """A message as it is printed: one line, control characters escaped,
    at most LINE_AT_MOST characters."""
    return shortened(escaped(str(text)), LINE_AT_MOST)
