"""examples/clingo_by_hand/README.md: each command, run as written, prints
exactly the output the README shows."""
from __future__ import annotations

import re
import shlex
import subprocess
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]
README = ROOT / "examples" / "clingo_by_hand" / "README.md"


def _examples() -> list[tuple[str, list[str]]]:
    out = []
    for block in re.findall(r"```\n(.*?)```", README.read_text(), flags=re.S):
        lines = block.strip("\n").splitlines()
        if lines and lines[0].startswith("$ "):
            out.append((lines[0][2:], lines[1:]))
    return out


def test_the_readme_shows_both_commands() -> None:
    assert len(_examples()) == 2


@pytest.mark.parametrize("command,expected", _examples())
def test_readme_command_prints_what_it_shows(command: str, expected: list[str]) -> None:
    argv = shlex.split(command)
    assert argv[0] == ".venv/bin/python"
    p = subprocess.run([sys.executable, *argv[1:]], cwd=ROOT, capture_output=True, text=True,
                       timeout=120)
    assert p.stdout.splitlines() == expected, p.stderr
