"""The reader's regular expressions kept compiled between questions.

The reader is some eight hundred regular expressions, a few of them tens
of thousands of characters long, and Python compiles each afresh in every
process: more of `ask`'s time than all the rest of its reading. Within
`kept_patterns()`, what Python's compiler makes of each pattern (the code
its matching engine runs) is kept in the cache folder `ask` keeps its
lexicon in, and read back in the next process instead of compiled again.

The file is named by the Python that wrote it and by a digest of the
reader's sources, and each pattern in it by its own text and flags, so a
pattern is only ever given the code compiled from it. The code is made
and checked by CPython's own compiler (re._parser, re._compiler, _sre):
the engine checks every code it is given, a damaged or foreign file is
read as empty, and any pattern that cannot be built from what is kept is
compiled as usual. A folder that cannot be written keeps nothing."""
from __future__ import annotations

import array
import hashlib
import marshal
import re
import sys
from contextlib import contextmanager
from pathlib import Path
from typing import Iterator

from pantarhei.bridge.reasoning.cache_files import cache_file, reader_sources, write_whole

#: At most this many patterns are kept: past it, the file keeps only those
#: of the last process (patterns made from a question's own words come and go).
KEPT_AT_MOST = 4000
#: A longer file is not read (it is none this module wrote).
BYTES_AT_MOST = 64 << 20

_MAGIC = b"pantarhei-patterns-1\n"
#: Flags whose patterns are compiled as re compiles them (re.TEMPLATE is gone from later Pythons).
_LEFT_TO_RE = re.DEBUG | getattr(re, "TEMPLATE", 0)

try:                       # CPython's compiler, as re uses it (absent elsewhere: nothing is kept)
    import _sre
    from re import _compiler, _parser
    _CODE = next((t for t in "IL" if array.array(t).itemsize == _sre.CODESIZE), None)
except (ImportError, AttributeError):     # pragma: no cover (another Python)
    _sre = _compiler = _parser = _CODE = None


def _path() -> Path | None:
    """Where this Python keeps the patterns of the present sources, or None."""
    return cache_file(f"patterns-{sys.implementation.cache_tag}-{_sre.MAGIC}", reader_sources(), ".bin")


def _read(path: Path) -> dict:
    """The patterns kept in `path`: {(text, flags): (flags, code, groups,
    groupindex, indexgroup)}; empty where there is none, or it is damaged."""
    try:
        if path.stat().st_size > BYTES_AT_MOST:
            return {}
        data = path.read_bytes()
    except OSError:
        return {}
    head, digest, body = data[:len(_MAGIC)], data[len(_MAGIC):len(_MAGIC) + 32], data[len(_MAGIC) + 32:]
    if head != _MAGIC or hashlib.sha256(body).digest() != digest:
        return {}
    try:
        kept = marshal.loads(body)
    except (ValueError, EOFError, TypeError):
        return {}
    return kept if isinstance(kept, dict) else {}


def _write(path: Path, kept: dict) -> None:
    body = marshal.dumps(kept)
    write_whole(path, _MAGIC + hashlib.sha256(body).digest() + body)


def _compiled(text: str, flags: int) -> tuple:
    """What CPython's compiler makes of `text` (re.error where it is no
    pattern), as kept."""
    parsed = _parser.parse(text, flags)
    code = _compiler._code(parsed, flags)
    groupindex = dict(parsed.state.groupdict)
    indexgroup = [None] * parsed.state.groups
    for name, i in groupindex.items():
        indexgroup[i] = name
    return (int(flags | parsed.state.flags), array.array(_CODE, code).tobytes(),
            parsed.state.groups - 1, groupindex, tuple(indexgroup))


def _built(text: str, entry: tuple) -> re.Pattern:
    flags, code, groups, groupindex, indexgroup = entry
    return _sre.compile(text, flags, array.array(_CODE, code).tolist(), groups, dict(groupindex), indexgroup)


@contextmanager
def kept_patterns() -> Iterator[None]:
    """Within it, every pattern compiled from a str is built from the code
    kept for it where there is one; the code of those compiled anew is kept
    on leaving."""
    path = _path() if _CODE is not None else None
    if path is None:
        yield
        return
    kept = _read(path)
    made: dict = {}
    used: dict = {}
    compile_anew = _compiler.compile

    def compile_kept(p, flags=0):
        if type(p) is not str or flags & _LEFT_TO_RE:
            return compile_anew(p, flags)
        key = (p, int(flags))
        entry = kept.get(key)
        if entry is not None:
            try:
                pattern = _built(p, entry)
            except (TypeError, ValueError, RuntimeError, OverflowError, re.error):
                entry = None                  # damaged: compiled anew below
            else:
                used[key] = entry
                return pattern
        entry = _compiled(p, key[1])
        made[key] = used[key] = entry
        return _built(p, entry)

    _compiler.compile = compile_kept
    try:
        yield
    finally:
        _compiler.compile = compile_anew
        if made:
            _write(path, {**kept, **made} if len(kept) + len(made) <= KEPT_AT_MOST else used)
