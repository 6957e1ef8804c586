"""Hostile inputs: a corpus of small files (and one long line on standard
input) built to cost a reader more than its size, each read by every
engine's command under a time and memory cap: Python's reader (`convert`),
SWI-Prolog's (`ask --theory`) and clingo's (`conclusions --engine asp`).
Each row is one reading: its exit, wall seconds and peak memory (the
largest resident set of the command's processes); the last lines give the
worst time and memory per engine.

Target: every reading answers or refuses (exit 0, 1 or 2, no traceback)
within 10 s and 1 GB on 2 cores. tests/bridge/theories/test_hostile_theories.py
reads the same corpus under its caps.
"""
from __future__ import annotations

import os
import signal
import subprocess
import sys
import tempfile
import time
from dataclasses import dataclass
from pathlib import Path
from typing import Callable

TARGET_S, TARGET_BYTES = 10.0, 2**30
#: The caps a reading runs under: past them it is killed and counts as failed.
CAP_S, CAP_BYTES = 60.0, 2 * 2**30


def _lines(lines) -> bytes:
    return ("\n".join(lines) + "\n").encode()


def _five_variables() -> bytes:
    return _lines([f">> p({i})" for i in range(20)]
                  + ["r1: p(?a), p(?b), p(?c), p(?d), p(?e) => q(?a, ?b, ?c, ?d, ?e)"])


def _chain(n: int, cycle: bool) -> bytes:
    return _lines([f"rule(r{i}, defeasible, a{i})." for i in range(n)]
                  + [f"sup(r{i}, r{i + 1})." for i in range(n - 1)]
                  + ([f"sup(r{n - 1}, r0)."] if cycle else []))


def _defeat_chain(n: int) -> bytes:
    """Each b_i is defeated when b_(i-1) holds: n alternations of the
    well-founded fixpoint (a loop elsewhere keeps the theory cyclic)."""
    lines = ["rule(loop, defeasible, x).", "body(loop, x)."]
    for i in range(1, n + 1):
        lines += [f"rule(r{i}, defeasible, b{i}).", f"rule(s{i}, defeasible, neg(b{i})).",
                  f"body(s{i}, b{i - 1}).", f"sup(s{i}, r{i})."]
    return _lines(["rule(r0, defeasible, b0)."] + lines)


def _shared_key(n: int) -> bytes:
    """Learned rules for no_spill and its negation sharing their largest
    body literal: every pair is a candidate for specificity."""
    lines = []
    for i in range(n):
        head = "no_spill" if i % 2 else "neg(no_spill)"
        lines += [f"rule(l{i}, defeasible, {head}).", f"body(l{i}, zz).",
                  f"body(l{i}, p{i}).", f"learned(l{i})."]
    return _lines(lines)


def _long_body(n: int) -> bytes:
    return _lines(["rule(big, defeasible, no_spill).", "learned(big)."]
                  + [f"body(big, p{i})." for i in range(n)]
                  + ["rule(small, defeasible, neg(no_spill)).", "body(small, p1).", "learned(small)."])


#: name -> (file name, its bytes)
CORPUS: dict[str, tuple[str, Callable[[], bytes]]] = {
    "five variables over 20 facts (DFL)": ("five.dfl", _five_variables),
    "superiority chain of 2,000 rules": ("chain.pl", lambda: _chain(2000, False)),
    "superiority cycle of 3,000 rules": ("cycle.pl", lambda: _chain(3000, True)),
    "defeat chain of 1,000 links": ("defeat.pl", lambda: _defeat_chain(1000)),
    "3,000 learned rules sharing their key literal": ("shared.pl", lambda: _shared_key(3000)),
    "one rule of 20,000 body literals": ("body.pl", lambda: _long_body(20000)),
    "a fact nested 400 deep": ("deep.pl", lambda: b"fact(" + b"f(" * 400 + b"a" + b")" * 401 + b".\n"),
    "a fact nested 400 deep (DFL)": ("deep.dfl", lambda: b">> p(" + b"f(" * 400 + b"a" + b")" * 401 + b"\n"),
    "1 MB of open parentheses": ("parens.pl", lambda: b"fact(" * 200_000),
    "a name of 1 MB": ("name.pl", lambda: b"fact(a" + b"b" * 1_000_000 + b").\n"),
    "a literal of 200,000 arguments": ("wide.pl", lambda: b"fact(p(" + b"a," * 200_000 + b"a)).\n"),
    "the name not": ("not.pl", lambda: b"rule(r1, defeasible, not).\nrule(r2, defeasible, no_spill).\n"
                                       b"body(r2, not).\n"),
    "facts named like built-ins": ("builtin.pl", lambda: b"halt.\ntrue.\ncall(a).\n"
                                                         b"rule(r1, defeasible, no_spill).\n"),
    "terminal escapes in a DFL line": ("escape.dfl", lambda: b"r1: a => b\x1b]0;pwned\x07\x1b[2J\r\n"),
}

#: engine -> the command that reads FILE with it
READERS: dict[str, tuple[str, ...]] = {
    "python": ("convert", "{file}"),
    "prolog": ("ask", "--theory", "{file}", "pour from the side"),
    "clingo": ("conclusions", "--engine", "asp", "{file}"),
}

#: A line of standard input as long as the issue's: read by ask a line at a time.
STDIN_BYTES = 50 * 2**20


@dataclass
class Reading:
    code: int | None        # None: killed at the cap
    seconds: float
    peak_bytes: int
    err: str


def write_corpus(folder: Path) -> dict[str, Path]:
    """The corpus as files in `folder`: name -> path."""
    out = {}
    for name, (file, make) in CORPUS.items():
        path = folder / file
        path.write_bytes(make())
        out[name] = path
    return out


def command(engine: str, path: Path) -> list[str]:
    return [sys.executable, "-m", "pantarhei.bridge",
            *(a.replace("{file}", str(path)) for a in READERS[engine])]


#: The small process between the caller and the command read: a process made
#: by fork counts its parent's resident memory in its own peak (Linux keeps it
#: across exec), so the command is forked from this one, capped, and its own
#: peak (kB) written to the file named first; its exit is the command's.
_LAUNCH = """
import os, resource, signal, sys
peak, memory, argv = sys.argv[1], int(sys.argv[2]), sys.argv[3:]
pid = os.fork()
if pid == 0:
    try:
        resource.setrlimit(resource.RLIMIT_AS, (memory, memory))
        os.execvp(argv[0], argv)
    finally:
        os._exit(127)
_, status, usage = os.wait4(pid, 0)
with open(peak, "w") as f:
    f.write(str(usage.ru_maxrss))
if os.WIFSIGNALED(status):
    signal.signal(os.WTERMSIG(status), signal.SIG_DFL)
    os.kill(os.getpid(), os.WTERMSIG(status))
sys.exit(os.waitstatus_to_exitcode(status))
"""


def read_capped(argv: list[str], stdin: bytes | None = None, seconds: float = CAP_S,
                memory: int = CAP_BYTES, cwd: str | None = None) -> Reading:
    """Run `argv` with its address space capped at `memory` bytes and
    killed (its whole process group) past `seconds`: its exit, wall time
    and the peak resident memory of its processes (the caller's own
    memory not counted, however large)."""
    with tempfile.TemporaryFile() as err, tempfile.TemporaryFile() as feed, \
            tempfile.NamedTemporaryFile("r") as peak:
        if stdin is not None:
            feed.write(stdin)
            feed.seek(0)
        start = time.monotonic()
        p = subprocess.Popen([sys.executable, "-c", _LAUNCH, peak.name, str(memory), *argv],
                             stdin=feed if stdin is not None else subprocess.DEVNULL,
                             stdout=subprocess.DEVNULL, stderr=err, start_new_session=True,
                             cwd=cwd)
        code: int | None = None
        while True:
            pid, status, usage = os.wait4(p.pid, os.WNOHANG)
            if pid:
                code = os.waitstatus_to_exitcode(status)
                break
            if time.monotonic() - start > seconds:
                os.killpg(p.pid, signal.SIGKILL)
                _, status, usage = os.wait4(p.pid, 0)
                break
            time.sleep(0.02)
        wall = time.monotonic() - start
        err.seek(0)
        text = err.read(200_000).decode("utf-8", "replace")
        kb = peak.read().strip()
    # the command's peak and its children's, or the launcher's when it was killed
    return Reading(code, wall, int(kb or usage.ru_maxrss) * 1024, text)


def readings(folder: Path, engines=tuple(READERS)) -> list[tuple[str, str, Reading]]:
    """(file, engine, reading) for every file of the corpus and engine,
    and ask reading a 50 MB line on standard input (engine prolog)."""
    rows = []
    for name, path in write_corpus(folder).items():
        for engine in engines:
            rows.append((name, engine, read_capped(command(engine, path))))
    line = b"pour " * (STDIN_BYTES // 5) + b"\npour from the side\n"
    rows.append(("a 50 MB line on ask's standard input", "prolog",
                 read_capped([sys.executable, "-m", "pantarhei.bridge", "ask"], stdin=line)))
    return rows


def main() -> int:
    with tempfile.TemporaryDirectory() as d:
        rows = readings(Path(d))
    print(f"{'input':<48} {'engine':<7} {'exit':>5} {'s':>7} {'MB':>7}")
    worst: dict[str, tuple[float, int]] = {}
    failed = 0
    for name, engine, r in rows:
        bad = r.code not in (0, 1, 2) or "Traceback" in r.err
        failed += bad
        print(f"{name:<48} {engine:<7} {'killed' if r.code is None else r.code:>5} "
              f"{r.seconds:7.2f} {r.peak_bytes / 2**20:7.0f}{'  FAILED' if bad else ''}")
        s, m = worst.get(engine, (0.0, 0))
        worst[engine] = (max(s, r.seconds), max(m, r.peak_bytes))
    for engine, (s, m) in worst.items():
        met = s <= TARGET_S and m <= TARGET_BYTES
        print(f"{'  ' if met else '! '}worst {engine}: {s:.2f} s, {m / 2**20:.0f} MB "
              f"(target {TARGET_S:.0f} s, {TARGET_BYTES // 2**20} MB)")
    print(f"{failed} readings failed (a traceback, a crash or the cap of {CAP_S:.0f} s and "
          f"{CAP_BYTES // 2**30} GB)")
    return 0


if __name__ == "__main__":
    sys.exit(main())
