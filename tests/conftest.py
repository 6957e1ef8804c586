"""Shared fixtures: run the real `pantarhei` command in a subprocess."""
from __future__ import annotations

import os
import subprocess
import sys
from dataclasses import dataclass

import pytest


@dataclass
class Run:
    code: int
    out: str
    err: str


def run_cli(*args: str, env: dict | None = None, timeout: float = 600, cwd: str | None = None) -> Run:
    """Run `pantarhei ARGS...` with this interpreter, as a user would."""
    full_env = {**os.environ, **(env or {})}
    p = subprocess.run([sys.executable, "-m", "pantarhei.bridge", *args], capture_output=True,
                       text=True, env=full_env, timeout=timeout, cwd=cwd, stdin=subprocess.DEVNULL)
    return Run(p.returncode, p.stdout, p.stderr)


@pytest.fixture
def cli():
    return run_cli


def assert_one_line_error(r: Run, code: int = 2) -> str:
    """A user error: the given non-zero exit, one line on stderr, no traceback."""
    assert r.code == code, (r.code, r.out, r.err)
    lines = [line for line in r.err.splitlines() if line.strip()]
    assert len(lines) == 1, r.err
    assert "Traceback" not in r.err
    return lines[0]
