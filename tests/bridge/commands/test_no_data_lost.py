"""No command loses or overwrites a byte it did not create: every command
that writes, run with its defaults (the synthetic oracle and tiny budgets
aside) in a clean clone of the repository, leaves every tracked file as
it was, but the report's own files, which evaluate writes again. And the
outputs that could land on inputs are refused, the inputs unchanged."""
from __future__ import annotations

import hashlib
import json
import os
import subprocess
import sys
from pathlib import Path

import pytest

from pantarhei.theory import THEORY_DIR

REPO = THEORY_DIR.parent
FAST = ("--executor", "inline", "--no-progress")


@pytest.fixture(scope="module")
def clone(tmp_path_factory) -> Path:
    """A clone of the repository's last commit, with a package tree whose
    `pantarhei` is the clone's code (not the checkout the venv installed)."""
    base = tmp_path_factory.mktemp("clean")
    repo = base / "repo"
    subprocess.run(["git", "clone", "-q", "--no-hardlinks", str(REPO), str(repo)], check=True)
    pkg = base / "pkg" / "pantarhei"
    pkg.mkdir(parents=True)
    (pkg / "__init__.py").write_text("")
    for name in ("theory", "bridge", "oracle"):
        (pkg / name).symlink_to(repo / name)
    (base / "home").mkdir()
    return repo


def _env(clone: Path) -> dict:
    return {**os.environ, "PYTHONPATH": str(clone.parent / "pkg"),
            "HOME": str(clone.parent / "home"), "XDG_CACHE_HOME": str(clone.parent / "home" / ".cache")}


def run(clone: Path, *args: str) -> subprocess.CompletedProcess:
    return subprocess.run([sys.executable, "-m", "pantarhei.bridge", *args], cwd=clone,
                          env=_env(clone), capture_output=True, text=True, timeout=900,
                          stdin=subprocess.DEVNULL)


def tracked(clone: Path) -> dict[str, str]:
    files = subprocess.run(["git", "ls-files", "-z"], cwd=clone, capture_output=True,
                           check=True).stdout.decode().split("\0")
    return {f: hashlib.sha256(os.readlink(clone / f).encode() if (clone / f).is_symlink()
                              else (clone / f).read_bytes()).hexdigest() for f in files if f}


def changed(clone: Path) -> list[str]:
    """git status's lines for tracked files (modified, deleted, renamed)."""
    out = subprocess.run(["git", "status", "--porcelain", "--untracked-files=no"], cwd=clone,
                         capture_output=True, text=True, check=True).stdout
    return [line for line in out.splitlines() if line.strip()]


@pytest.mark.slow
def test_every_writing_command_with_its_defaults_leaves_what_it_did_not_write(clone):
    """explore, explore/1 at the prompt, demo, simulate, render, ask, plan,
    convert and evaluate in the clone; only evaluate's report is written
    again (its record names each file it wrote)."""
    where = subprocess.run([sys.executable, "-c", "import pantarhei.theory as t; print(t.THEORY_DIR)"],
                           env=_env(clone), capture_output=True, text=True, check=True).stdout
    assert Path(where.strip()).resolve() == (clone / "theory").resolve()   # the clone's code
    before = tracked(clone)
    steps = [
        ("explore", "--oracle", "synthetic", "--pours", "12", *FAST),
        ("prolog", "-g", "explore([oracle(synthetic), pours(12), executor(inline), "
                         "progress(false)])"),
        ("demo", "--oracle", "synthetic", "--pours", "12", "--verify", "0", "--no-progress"),
        ("simulate", "--antecedent", "pour_low", "-n", "1", *FAST),
        ("render", "--antecedent", "pour_low", "--size", "32x24", "--fps", "2"),
        ("ask", "pour from the side"),
        ("plan", "--goal", "no_spill", "--verify", "0"),
        ("convert", "theory/learned/pouring.pl"),
        ("evaluate", "--theory", "explore.pl", "--scenes", "2", "--verify", "0",
         "--paper-samples", "0", "--no-gifs", "--no-baselines", *FAST),
    ]
    for args in steps:
        r = run(clone, *args)
        assert r.returncode == 0, (args, r.stderr[-2000:])
        assert "Traceback" not in r.stderr, args
        if args[0] != "evaluate":
            assert changed(clone) == [], (args, changed(clone))
    assert (clone / "explore.pl").is_file() and (clone / "pour.gif").is_file()
    record = json.loads((clone / "report" / ".pantarhei-report.json").read_text())
    after = tracked(clone)
    rewritten = {f for f in before if before[f] != after.get(f)}
    # the report's files, and its record of them (shipped with the report)
    assert rewritten <= {f"report/{name}" for name in record} | {"report/.pantarhei-report.json"}, \
        rewritten
    assert "report/bench.txt" not in rewritten


@pytest.mark.slow
def test_outputs_never_land_on_inputs(clone):
    """evaluate into the project's folder, render's frames over its
    --params: refused in one line, every byte as it was."""
    before, status = tracked(clone), changed(clone)
    r = run(clone, "evaluate", "--out", ".", *FAST)
    assert r.returncode == 2 and "'README.md' was not written by a report" in r.stderr
    frames = clone / "frames"
    frames.mkdir(exist_ok=True)
    params = frames / "frame_0000.png"
    params.write_text(json.dumps({"params": _pour()}))
    kept = params.read_bytes()
    r = run(clone, "render", "--params", str(params), "--frames", str(frames), "--size", "32x24")
    assert r.returncode == 2 and "render writes its frames under that name" in r.stderr
    assert params.read_bytes() == kept and sorted(p.name for p in frames.iterdir()) == [params.name]
    assert tracked(clone) == before and changed(clone) == status


def _pour() -> dict:
    from pantarhei.oracle import generative

    return generative.to_dict(generative.sample(["pour_low"], 1, 0)[0])
