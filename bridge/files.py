"""Files written whole or not at all: into a temporary file beside the
target, then renamed over it, so that a reader, or a crash half-way, never
sees part of one; and which format a theory file's name says it is in."""
from __future__ import annotations

import os
import tempfile
from pathlib import Path
from typing import Callable


def is_dfl(path: Path | str) -> bool:
    """Is the theory file at `path` DFL (its name ends in .dfl), not native facts?"""
    return str(path).lower().endswith(".dfl")


def theory_file_problem(path: Path | str) -> str | None:
    """Why `path` cannot be read as a theory file (no such file, a
    directory, a device or a pipe), or None."""
    p = Path(path)
    if not p.exists():
        return f"{path}: no such theory file"
    if p.is_dir():
        return f"{path}: a directory, not a theory file"
    if not p.is_file():
        return f"{path}: not a regular file (a device or a pipe), not a theory file"
    return None


def replace_with(path: Path | str, write: Callable[[Path], None]) -> None:
    """Call `write(tmp)` to write a temporary file beside `path`, then
    rename it over `path`; the temporary file goes if `write` fails."""
    path = Path(path)
    fd, name = tempfile.mkstemp(dir=path.parent, prefix=f".{path.name}.", suffix=".tmp")
    os.close(fd)
    tmp = Path(name)
    try:
        write(tmp)
        os.replace(tmp, path)
    except BaseException:
        tmp.unlink(missing_ok=True)
        raise


def require_writable_file(path: Path | str, flag: str) -> None:
    """UserError unless a file can be written at `path` (by `replace_with`:
    its folder, or the nearest one that exists, must be writable): checked
    before the work whose result goes there."""
    from pantarhei.bridge.errors import UserError

    path = Path(path)
    if path.is_dir():
        raise UserError(f"{flag} {path}: a directory, not a file")
    folder = path.absolute().parent
    while not folder.exists():
        folder = folder.parent
    if not folder.is_dir():
        raise UserError(f"{flag} {path}: {folder} is not a directory")
    if not os.access(folder, os.W_OK | os.X_OK):
        raise UserError(f"{flag} {path}: cannot write into {folder} (permission denied)")


def require_distinct(roles: dict[str, Path | str]) -> None:
    """UserError when two of a command's files (`roles`: what each is, its
    flag or the file written beside one, to its path) are the same file,
    after resolving `..` and links (a hard link too, when both exist), so
    that no output replaces an input or another output: checked before
    anything is written."""
    from pantarhei.bridge.errors import UserError

    seen: dict[object, str] = {}
    for role, path in roles.items():
        path = Path(path)
        keys: list[object] = [path.resolve()]
        try:
            st = path.stat()
            keys.append((st.st_dev, st.st_ino))
        except OSError:
            pass
        for key in keys:
            if key in seen:
                raise UserError(f"{seen[key]} and {role} are the same file {path}: "
                                f"give each its own path")
        for key in keys:
            seen[key] = role


def write_text(path: Path | str, text: str) -> None:
    """Write `text` (UTF-8) to `path` whole or not at all."""
    replace_with(path, lambda tmp: tmp.write_text(text, encoding="utf-8"))


def pyplot():
    """matplotlib.pyplot, drawing off screen (the Agg backend)."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    return plt


def save_figure(fig, path: Path | str) -> None:
    """Save a matplotlib figure as PNG whole or not at all, and close it."""
    import matplotlib.pyplot as plt

    try:
        replace_with(path, lambda tmp: fig.savefig(tmp, format="png"))
    finally:
        plt.close(fig)
