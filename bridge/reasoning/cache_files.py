"""Where `ask` keeps what it makes once and reads again: a folder of the
user's cache ($XDG_CACHE_HOME/pantarhei, else ~/.cache/pantarhei), a file
named by a digest of the files it was made from (their paths, sizes and
times), so that a changed source never reads an old one."""
from __future__ import annotations

import hashlib
import os
from pathlib import Path

from pantarhei.theory import THEORY_DIR


def theory_sources() -> list[Path]:
    """Every Prolog file of theory/ but the learned theories (read when asked)."""
    return sorted(p for p in THEORY_DIR.rglob("*.pl") if "learned" not in p.parts)


def reader_sources() -> list[Path]:
    """What the reader is made of: its modules and word lists, and the
    vocabulary's files."""
    reader = Path(__file__).parent
    return sorted([*reader.glob("*.py"), *reader.glob("*.txt"), *theory_sources()])


def cache_file(kind: str, sources: list[Path], suffix: str) -> Path | None:
    """The cache file of `kind` made from `sources`, or None where one of
    them cannot be read."""
    base = Path(os.environ.get("XDG_CACHE_HOME") or Path.home() / ".cache") / "pantarhei"
    h = hashlib.sha1()
    for p in sources:
        try:
            st = p.stat()
        except OSError:
            return None
        h.update(f"{p}\0{st.st_size}\0{st.st_mtime_ns}\0".encode())
    return base / f"{kind}-{h.hexdigest()[:16]}{suffix}"


def write_whole(path: Path, data: bytes) -> None:
    """Write `data` to `path` through a file of its own renamed when
    whole, so that a reader never sees half of it; nothing is written
    where the folder cannot be made or written."""
    tmp = path.with_name(f".{path.name}.{os.getpid()}")
    try:
        path.parent.mkdir(parents=True, exist_ok=True)
        tmp.write_bytes(data)
        os.replace(tmp, path)
    except OSError:
        try:
            tmp.unlink(missing_ok=True)
        except OSError:
            pass                    # (no folder to have written in)
