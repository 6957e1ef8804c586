"""No two modules of the project share a name across its languages: every
Python, Prolog and ASP file (but the tests, the benchmarks, the learned
theory, which is data, and Python's `__init__`, `__main__` and `conftest`)
has a stem of its own, so that a name says which file is meant."""
from __future__ import annotations

import os
from collections import defaultdict
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
SOURCES = {".py", ".pl", ".lp"}
#: Folders (from the project's folder) that hold no module of the project's.
LEFT_OUT = {("tests",), ("benchmarks",), ("report",), ("theory", "learned")}
#: Python's file names that every package may have.
STANDARD = {"__init__", "__main__", "conftest"}


def modules(root: Path) -> list[Path]:
    """The project's modules under `root`, hidden and generated folders
    (.venv, .git, __pycache__, *.egg-info) left out."""
    out = []
    for folder, subfolders, files in os.walk(root):
        here = Path(folder)
        parts = here.relative_to(root).parts
        subfolders[:] = [d for d in subfolders
                         if not (d.startswith(".") or d == "__pycache__" or d.endswith(".egg-info")
                                 or (*parts, d) in LEFT_OUT)]
        out += [here / f for f in files
                if Path(f).suffix in SOURCES and Path(f).stem not in STANDARD]
    return sorted(out)


def shared_stems(paths: list[Path], root: Path) -> list[str]:
    """Each stem that two or more of `paths` share, with their files."""
    by_stem: dict[str, list[str]] = defaultdict(list)
    for p in paths:
        by_stem[p.stem].append(str(p.relative_to(root)))
    return [f"{stem}: {', '.join(files)}" for stem, files in sorted(by_stem.items())
            if len(files) > 1]


def test_no_two_modules_share_a_name():
    found = shared_stems(modules(ROOT), ROOT)
    assert not found, "modules sharing a name (rename one for what it holds): " + "; ".join(found)


def test_a_shared_name_is_found_across_folders_and_languages(tmp_path):
    for name in ("theory/scene.lp", "oracle/scene.py", "theory/rules.pl", "theory/learned/rules.py",
                 "bridge/__init__.py", "oracle/__init__.py", "tests/oracle/scene.py",
                 "benchmarks/rules.py", ".venv/lib/scene.py", "theory/scene.plt"):
        (tmp_path / name).parent.mkdir(parents=True, exist_ok=True)
        (tmp_path / name).write_text("")
    assert shared_stems(modules(tmp_path), tmp_path) == ["scene: oracle/scene.py, theory/scene.lp"]
