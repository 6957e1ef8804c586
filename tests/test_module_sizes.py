"""No module of the project's code over 400 lines: every Python, Prolog and
ASP file under theory/ (but the learned theory, which is data), bridge/,
oracle/ and benchmarks/, but the ones named in `TOO_LONG`, each split by
concern before it leaves the list."""
from __future__ import annotations

from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
MOST = 400
SOURCES = ("*.py", "*.pl", "*.lp")

#: Modules over the bound, not yet split (paths from the project's folder).
TOO_LONG: set[str] = set()


def lines(path: Path) -> int:
    return len(path.read_text(encoding="utf-8").splitlines())


def sources(root: Path) -> list[Path]:
    """The project's code under `root` (theory/learned/ left out)."""
    out = []
    for folder in ("theory", "bridge", "oracle", "benchmarks"):
        for pattern in SOURCES:
            out += [p for p in (root / folder).rglob(pattern)
                    if p.relative_to(root / folder).parts[:1] != ("learned",)]
    return sorted(out)


def too_long(paths: list[Path], root: Path, known: set[str]) -> list[str]:
    """The files of `paths` over MOST lines that `known` does not name."""
    return [f"{p.relative_to(root)} ({lines(p)} lines)" for p in paths
            if lines(p) > MOST and str(p.relative_to(root)) not in known]


def test_no_module_is_over_the_bound():
    found = too_long(sources(ROOT), ROOT, TOO_LONG)
    assert not found, f"over {MOST} lines (split it by concern): " + ", ".join(found)


def test_a_long_module_is_found_and_the_learned_theory_is_not(tmp_path):
    (tmp_path / "theory" / "learned").mkdir(parents=True)
    (tmp_path / "theory" / "long.pl").write_text("a.\n" * (MOST + 1))
    (tmp_path / "theory" / "short.pl").write_text("a.\n" * MOST)
    (tmp_path / "theory" / "learned" / "pouring.pl").write_text("a.\n" * (MOST + 1))
    assert too_long(sources(tmp_path), tmp_path, set()) == [f"theory/long.pl ({MOST + 1} lines)"]
