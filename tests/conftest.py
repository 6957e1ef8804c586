"""Shared fixtures: run the real `pantarhei` command in a subprocess; a toy
curiosity's Prolog module."""
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


def toy_curiosity(module: str, rules: bool = False, python_side: str | None = None) -> str:
    """A toy curiosity's Prolog module `module`: the interface of
    theory/curiosity/interface.pl and nothing else, its theory laid out
    with Algorithm 1's rules or without (one layer), and its Python side."""
    side = f"python_side(['{python_side}']).\n" if python_side else ""
    return f""":- module({module}, []).
budget(_, 1).
progress_bar(_, _{{total:1, unit:pour}}).
probe_size(_, 0).
probed(_, _) :- fail.
priors_due(_, _) :- fail.
after_batch(_, _, [], _{{}}).
second_layer(_, _, _, []).
theory_layout(_{{rules:{str(rules).lower()}, batches:false, header:[], layer_header:[]}}).
{side}"""
