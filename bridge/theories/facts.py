"""The language of theory files, read in Python: ground facts, nothing else.

A theory file is ASCII text: facts `name.` or `name(Arg, ...).`, where an
argument is a name (`[a-z][A-Za-z0-9_]*`), an integer in decimal from
-2147483648 to 2147483647 (what clingo can hold), quoted text `"..."` (on
with `\\\\`, `\\"` and `\\n` as its only escapes) or a term of
those; `%` starts a comment to the end of the line. That is the subset of
Prolog and ASP that both engines read the same way, and theory/fact_reader.pl
reads the same language in SWI-Prolog: the two reject the same files with
the same `file:line: what` (its words theory/check_messages.pl's,
`check_message`; the line where the offending fact starts, or of
the offending byte). Directives (`:- ...`, `#include`, `#script`, ...),
rules, variables, quoted atoms, lists, floats, block comments and anything
else are refused: a theory file is data.

Quoted text comes back as `Text` (a `str`), so that it is written back
quoted and escaped (`term_text`), never as bare program text.
"""
from __future__ import annotations

import gc
import re
from collections import defaultdict
from contextlib import contextmanager
from functools import lru_cache
from pathlib import Path
from types import MappingProxyType
from typing import Iterable, Mapping, NamedTuple


class TheoryFileError(ValueError):
    """A theory file that is not in the common subset; str() is `file:line:
    what`. Defined with the reader that raises it, which imports nothing
    of the project (pantarhei.theory, whose `read_facts` is this reader,
    names it too)."""


#: The integers clingo holds (32-bit); theory files stay within them.
INT_MIN, INT_MAX = -2 ** 31, 2 ** 31 - 1

# The messages of what this reader and SWI-Prolog's refuse are
# theory/check_messages.pl's (`check_message`); this one is Python's alone.
NAME = "a name in lower case letters, digits and _, not '{}'"

#: The table of the messages of the checks both readers make, in the
#: folder of the package pantarhei.theory (theory/).
CHECK_MESSAGES = "check_messages.pl"
#: The project's defaults, in the same folder: among them how deep a term
#: may nest (`nesting_at_most`).
DEFAULTS = "defaults.pl"


def check_message(key: str, *args: object) -> str:
    """The message of the check `key` of a theory file, as
    theory/check_messages.pl writes it once for both readers: each `~w`
    of its text is the next of `args`, written as it is (as SWI-Prolog's
    format/2 writes it). KeyError for a check the table lacks, ValueError
    for as many arguments as the text does not take."""
    parts = _check_messages()[key].split("~w")
    if len(parts) != len(args) + 1:
        raise ValueError(f"check message {key} takes {len(parts) - 1} arguments, not {len(args)}")
    return "".join(part + str(arg) for part, arg in zip(parts, args)) + parts[-1]


@lru_cache(maxsize=None)
def _check_messages() -> Mapping[str, str]:
    """The table, read by this reader."""
    return MappingProxyType({str(f.args[0]): str(f.args[1]) for f in read(_theory_file(CHECK_MESSAGES))
                             if f.name == "check_message" and len(f.args) == 2})


@lru_cache(maxsize=None)
def nesting_at_most() -> int:
    """How deep a term may nest (a theory's facts nest two or three deep),
    so that every reader after this one may recurse on terms without
    running out: `default(nesting_at_most, N)` of theory/defaults.pl, as
    SWI-Prolog's reader takes it (fact_reader.pl). That file, the
    project's own, is read before the bound is known, without it."""
    path = _theory_file(DEFAULTS)
    facts = _parse(check_bytes(path.read_bytes(), str(path)), str(path), 1, None)
    return next(int(f.args[1]) for f in facts
                if f.name == "default" and f.args[:1] == ("nesting_at_most",))


def _theory_file(name: str) -> Path:
    """A file of theory/, found where pantarhei.theory is without importing
    it (it imports this module)."""
    from importlib.util import find_spec

    return Path(find_spec("pantarhei.theory").origin).parent / name


class Text(str):
    """Quoted text of a theory file (written back quoted by `term_text`)."""

    __slots__ = ()


class Fact(NamedTuple):
    """One fact: its predicate name, arguments (str names, `Text`, int, or
    tuples `(name, arg, ...)` for terms) and the line where it starts."""
    name: str
    args: tuple
    line: int

    @property
    def text(self) -> str:
        return term_text((self.name, *self.args) if self.args else self.name)


def term_text(value) -> str:
    """A value as native text: names and integers as they are, `Text`
    quoted and escaped, terms `name(arg,...)`."""
    if isinstance(value, tuple):
        return f"{value[0]}({','.join(term_text(v) for v in value[1:])})"
    if isinstance(value, Text):
        return quote(value)
    return str(value)


def quote(s: str) -> str:
    """Text as quoted native text (both engines read it back as the same text)."""
    return '"' + s.replace("\\", "\\\\").replace('"', '\\"').replace("\n", "\\n") + '"'


#: What may follow a backslash in SWI-Prolog's quoted text.
_SWI_ESCAPES = frozenset("abfrtvesc01234567x`'\n")
_BAD_BYTE = re.compile(rb"[^\x20-\x7e\t\n\r]")
_TOKEN = re.compile(r"""
    (?P<ws>[ \t\r\n]+)
  | (?P<comment>%[^\n]*)
  | (?P<name>[a-z][A-Za-z0-9_]*)
  | (?P<var>[A-Z_][A-Za-z0-9_]*)
  | (?P<float>-?[0-9]+\.[0-9]|-?[0-9]+[eE][+-]?[0-9])
  | (?P<int>-?[0-9]+(?![A-Za-z0-9_']))
  | (?P<text>"(?:[^"\\]|\\.)*")
  | (?P<open>\()
  | (?P<close>\))
  | (?P<comma>,)
  | (?P<end>\.(?=[ \t\r\n%]|\Z))
  | (?P<neck>:-|\?-)
  | (?P<list>\[)
  | (?P<other>.)
""", re.X | re.S)
# A line holding one fact whose arguments are names, integers or terms of
# those (the usual case), read without the tokenizer.
# (never the name not, which the tokenizer refuses)
_NAME = r"(?!not(?![A-Za-z0-9_]))[a-z][A-Za-z0-9_]*"
_A0 = rf"(?:{_NAME}|-?[0-9]+)"
_A1 = rf"(?:{_NAME}\({_A0}(?:[ \t]*,[ \t]*{_A0})*\)|{_A0})"
_FLAT = re.compile(rf"^[ \t]*({_NAME})\(({_A1}(?:[ \t]*,[ \t]*{_A1})*)\)\.[ \t\r]*(?:%[^\n]*)?$",
                   re.M)
_FLAT_ARG = re.compile(r"([a-z][A-Za-z0-9_]*)(?:\(([^()]*)\))?|(-?[0-9]+)")
_COMMA = re.compile(r"[ \t]*,[ \t]*")
_DIGITS = frozenset("-0123456789")


def read(path: Path | str) -> list[Fact]:
    """The facts of a theory file; TheoryFileError (`file:line: what`)."""
    path = Path(path)
    try:
        data = path.read_bytes()
    except FileNotFoundError:
        raise TheoryFileError(f"{path}: " + check_message("no_such_file")) from None
    except IsADirectoryError:
        raise TheoryFileError(f"{path}: a directory, not a theory file") from None
    except OSError as e:
        raise TheoryFileError(f"{path}: cannot be read ({e.strerror})") from None
    return parse(data, str(path))


def read_facts(paths: Iterable[Path | str]) -> dict[str, list[tuple]]:
    """The ground facts of theory files: predicate name -> argument tuples.

    Atoms and quoted text both come back as `str`, integers as `int`, and
    compound terms as tuples `(name, arg, ...)`. Facts keep file order.
    This reader refuses what SWI-Prolog's fact_reader.pl refuses, with
    the same `file:line: what` (pantarhei.theory names it too)."""
    facts: dict[str, list[tuple]] = defaultdict(list)
    for path in paths:
        for f in read(path):
            facts[f.name].append(tuple(f.args))
    return dict(facts)


def check_bytes(data: bytes, source: str, first_line: int = 1) -> str:
    """`data` as text, or TheoryFileError naming the line of its first byte
    that is not printable ASCII (tab, newline and carriage return allowed)."""
    m = _BAD_BYTE.search(data)
    if m:
        line = first_line + data.count(b"\n", 0, m.start())
        raise TheoryFileError(f"{source}:{line}: " + check_message("not_ascii", f"{data[m.start()]:#04x}"))
    return data.decode("ascii")


def parse(data: bytes | str, source: str = "<theory>", first_line: int = 1) -> list[Fact]:
    """The facts of theory-file text (bytes, or str), in file order."""
    if isinstance(data, str):
        data = data.encode("utf-8", errors="surrogateescape")
    text = check_bytes(data, source, first_line)
    most = nesting_at_most()
    with _no_gc():
        return _parse(text, source, first_line, most)


@contextmanager
def _no_gc():
    """Without the cycle collector: facts make no cycles, and collecting
    while a million tuples pile up makes reading large files quadratic."""
    enabled = gc.isenabled()
    gc.disable()
    try:
        yield
    finally:
        if enabled:
            gc.enable()


def _parse(text: str, source: str, first_line: int, most: int | None) -> list[Fact]:
    """The facts of `text`, its terms nested at most `most` deep (None: any)."""
    facts: list[Fact] = []
    append = facts.append
    pos, line = 0, first_line
    for m in _FLAT.finditer(text):
        start = m.start()
        if start < pos:
            continue
        while pos < start:
            # anything else: the tokenizer, up to the end of a line between facts
            eol, line = _Tokens(text, source, facts, most).run(pos, line)
            pos, line = eol + 1, line + 1
        if pos != start:
            continue                    # the tokenizer read on into this line
        name, args = m.groups()
        if "(" in args:
            append(Fact(name, tuple(
                (f, *[_value(x, source, line) for x in _COMMA.split(inner)]) if inner
                else f if f else _integer(number, source, line)
                for f, inner, number in _FLAT_ARG.findall(args)), line))
        else:
            append(Fact(name, tuple([_integer(x, source, line) if x[0] in _DIGITS else x
                                     for x in _COMMA.split(args)]), line))
        pos, line = m.end() + 1, line + 1
    while pos < len(text):
        eol, line = _Tokens(text, source, facts, most).run(pos, line)
        pos, line = eol + 1, line + 1
    return facts


def _value(token: str, source: str, line: int):
    if token[0] in _DIGITS:
        return _integer(token, source, line)
    return token


def _integer(token: str, source: str, line: int) -> int:
    if len(token) <= 11:
        n = int(token)
        if INT_MIN <= n <= INT_MAX and str(n) == token:
            return n
    raise TheoryFileError(f"{source}:{line}: " + integer_problem(token))


def integer_problem(token: str) -> str | None:
    """Why the text of an integer (`-?[0-9]+`) is not one a theory may
    hold, or None: outside clingo's -2147483648 .. 2147483647 (decided
    without converting thousands of digits), or not plain decimal (leading
    zeros, -0)."""
    sign = "-" if token[:1] == "-" else ""
    significant = token[len(sign):].lstrip("0") or "0"
    if len(significant) > 10 or not INT_MIN <= int(sign + significant) <= INT_MAX:
        return check_message("int_range", integer_shown(token))
    if str(int(sign + significant)) != token:
        return check_message("int_form", integer_shown(token))
    return None


def integer_shown(token: str) -> str:
    """An integer's text as a message shows it: whole up to 24 characters,
    a longer one by its ends and its number of digits."""
    if len(token) <= 24:
        return token
    return f"{token[:12]}...{token[-4:]} ({len(token.lstrip('-'))} digits)"


def _unescape(token: str, source: str, line: int) -> Text:
    body = token[1:-1]
    if "\\" not in body:
        return Text(body)
    out, i = [], 0
    while i < len(body):
        c = body[i]
        if c == "\\":
            nxt = body[i + 1]
            if nxt not in '\\"n':
                # an escape SWI-Prolog reads (but clingo does not), or none at all
                raise TheoryFileError(f"{source}:{line}: " + check_message(
                    "text_escape" if nxt in _SWI_ESCAPES else "expected_fact"))
            out.append("\n" if nxt == "n" else nxt)
            i += 2
        else:
            out.append(c)
            i += 1
    return Text("".join(out))


class _Tokens:
    """Facts token by token: a stack of the terms being built. Every error
    names the line where its fact starts."""

    def __init__(self, text: str, source: str, facts: list[Fact], most: int | None) -> None:
        self.text, self.source, self.facts = text, source, facts
        self.most = most                # how deep a term may nest (None: any)
        self.start = 0                  # the line of the current fact; 0 between facts
        self.stack: list[list] = []     # open terms [name, arg, ...]
        self.state = "value"            # value (a value may come) | open | after

    def fail(self, check: str = "expected_fact", *args: object):
        """Raise the message of `check` (theory/check_messages.pl)."""
        raise TheoryFileError(f"{self.source}:{self.start}: " + check_message(check, *args))

    def run(self, pos: int, line: int) -> tuple[int, int]:
        """Read from pos (at line) until a newline between facts, or the
        end; the position of that newline and its line."""
        text, match = self.text, _TOKEN.match
        while pos < len(text):
            m = match(text, pos)
            kind, tok = m.lastgroup, m.group()
            if kind == "ws":
                nl = tok.find("\n")
                if nl >= 0 and not self.start:
                    return pos + nl, line
                line += tok.count("\n")
            elif kind != "comment":
                if not self.start:
                    self.start = line
                    if tok == "#":
                        self.fail("hash_directive")
                    if kind == "neck":
                        self.fail("directive")
                self.token(kind, tok, text, m.end())
                if kind == "text":
                    line += tok.count("\n")
            pos = m.end()
        if self.start:
            self.fail()
        return pos, line

    def token(self, kind: str, tok: str, text: str, after: int) -> None:
        if kind == "var":
            self.fail("variable")
        if kind == "float":
            self.fail("float")
        if kind == "list":
            self.fail("list")
        state = self.state
        if state == "value":
            if kind == "name" and tok == "not":
                self.fail("not_name")
            if kind == "name":
                if text.startswith("(", after):
                    if self.most is not None and len(self.stack) >= self.most:
                        self.fail("nesting", self.most)
                    self.stack.append([tok])
                    self.state = "open"
                    return
                self.value(tok)
            elif kind == "int" and self.stack:
                self.value(_integer(tok, self.source, self.start))
            elif kind == "text" and self.stack:
                self.value(_unescape(tok, self.source, self.start))
            else:
                self.fail()
        elif state == "open":            # just after name(
            self.state = "value"
        elif state == "after":
            if kind == "comma" and self.stack:
                self.state = "value"
            elif kind == "close" and self.stack:
                self.value(tuple(self.stack.pop()))
            elif kind == "end" and not self.stack:
                self.state = "value"
                self.start = 0
            elif kind == "neck" and tok == ":-" and not self.stack:
                self.fail("rule_not_fact")
            else:
                self.fail()

    def value(self, value) -> None:
        if self.stack:
            self.stack[-1].append(value)
        else:
            name, args = (value[0], value[1:]) if isinstance(value, tuple) else (value, ())
            self.facts.append(Fact(name, args, self.start))
        self.state = "after"
