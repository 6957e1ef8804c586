"""What kind of thing an English noun names, by WordNet (Princeton's lexical
database of English, read from the files of Debian's package wordnet-base,
WordNet 3.0): whether "merlot" is a liquid (a wine, a beverage) or "sand"
is not, and whether "potter" is a person.

The files are searched, not loaded: the index of nouns is sorted, so a word
is found by bisecting the file by its byte offsets, and each sense's
hypernyms ("is a kind of") are read at the offsets the data file gives.
A question that never needs it costs nothing, and one that does reads a
few dozen lines. Without the files (WordNet not installed), every word is
of no kind WordNet knows, and the reader refuses such words as before."""
from __future__ import annotations

import os
from functools import lru_cache
from pathlib import Path

#: Where Debian's wordnet-base installs the database.
ROOT = Path("/usr/share/wordnet")


def _line(path: Path, key: str) -> str | None:
    """The line of the sorted file `path` whose first word is `key`, or None."""
    wanted = key.encode("latin-1", "replace")
    with open(path, "rb") as f:
        lo, hi = 0, os.fstat(f.fileno()).st_size
        while lo < hi:                    # the least offset whose next whole line is not before the key
            mid = (lo + hi) // 2
            f.seek(mid)
            if mid:
                f.readline()
            line = f.readline()
            if line and (line.startswith(b" ") or line.split(b" ", 1)[0] < wanted):
                lo = mid + 1
            else:
                hi = mid
        f.seek(lo)
        if lo:
            f.readline()
        line = f.readline()
    return line.decode("latin-1") if line.split(b" ", 1)[0] == wanted else None


def _synset(offset: str) -> tuple[tuple[str, ...], tuple[str, ...]]:
    """The words of the noun synset at `offset` and the offsets of its hypernyms."""
    with open(ROOT / "data.noun", "rb") as f:
        f.seek(int(offset))
        fields = f.readline().decode("latin-1").split(" | ")[0].split()
    count = int(fields[3], 16)
    words = tuple(fields[4 + 2 * k].lower() for k in range(count))
    at = 4 + 2 * count
    pointers = int(fields[at])
    up = tuple(fields[at + 2 + 4 * k] for k in range(pointers)
               if fields[at + 1 + 4 * k] in ("@", "@i") and fields[at + 3 + 4 * k] == "n")
    return words, up


@lru_cache(maxsize=4096)
def _kinds_of(offset: str) -> frozenset[str]:
    words, up = _synset(offset)
    return frozenset(words).union(*(_kinds_of(o) for o in up))


@lru_cache(maxsize=256)
def _offsets(noun: str) -> tuple[str, ...]:
    """Where each noun sense of `noun` is in the data file, the commonest first; () where WordNet
    has no such noun or is not installed."""
    if not (ROOT / "index.noun").exists():
        return ()
    line = _line(ROOT / "index.noun", noun.lower().replace(" ", "_"))
    if line is None:
        return ()
    fields = line.split()
    return tuple(fields[-int(fields[2]):])


def senses(noun: str) -> tuple[frozenset[str], ...]:
    """Per noun sense of `noun` (in WordNet's order, the commonest first),
    the words of it and of every kind it is a kind of; () where WordNet
    has no such noun or is not installed."""
    return tuple(_kinds_of(o) for o in _offsets(noun))


def is_a(noun: str, kinds: frozenset[str], first: int = 3) -> bool:
    """Whether one of the `first` senses of `noun` is a kind of one of `kinds` (WordNet's words, "liquid")."""
    return any(kinds & s for s in senses(noun)[:first])


def kind_named(noun: str, kinds: frozenset[str], first: int = 3) -> str | None:
    """The nearest kind WordNet says `noun` is, of a sense that is one of
    `kinds` (merlot: "red wine"), for saying back; None if no such sense."""
    for offset in _offsets(noun)[:first]:
        if kinds & _kinds_of(offset):
            _, up = _synset(offset)
            return _synset(up[0])[0][0].replace("_", " ") if up else None
    return None
