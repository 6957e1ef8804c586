"""The front door (bridge/cli.py, and the shared flags of
bridge/commands/options.py): each command imports what it uses, only the
commands that compute with floats restart with the pinned math, `ask`
answers questions one a line from standard input, and bad options are
refused in one line before any work starts."""
from __future__ import annotations

import json
import os
import subprocess
import sys

import pytest

from pantarhei.bridge.cli import parser
from pantarhei.oracle import baseline
from tests.conftest import assert_one_line_error, run_cli


def imported(*args: str) -> set[str]:
    """The modules `pantarhei ARGS` imports (python -X importtime)."""
    env = {k: v for k, v in os.environ.items() if k not in baseline.ENVIRONMENT}
    p = subprocess.run([sys.executable, "-X", "importtime", "-m", "pantarhei.bridge", *args],
                       capture_output=True, text=True, env=env, stdin=subprocess.DEVNULL,
                       timeout=300)
    assert p.returncode == 0, p.stderr[-2000:]
    return {line.split("|")[-1].strip() for line in p.stderr.splitlines()
            if line.startswith("import time:")}


@pytest.mark.parametrize("args", [("--help",), ("ask", "--props", "pour_to_side"), ("vocab",)])
def test_asking_imports_neither_the_learners_nor_numpy_nor_restarts(args):
    mods = imported(*args)
    assert "pantarhei.bridge.cli" in mods
    heavy = {m for m in mods if m.split(".")[0] in ("sklearn", "scipy", "numpy", "pybullet")}
    assert not heavy, sorted(heavy)[:5]
    assert not any(m.startswith("pantarhei.bridge.exploration") for m in mods)


def test_only_commands_that_compute_with_floats_pin_the_math():
    def pinned(*argv: str) -> bool:
        from pantarhei.bridge.cli import pinned as pin

        return pin(parser().parse_args(list(argv)))

    for argv in (["simulate", "-a", "pour_low"], ["render", "-a", "pour_low"], ["explore"],
                 ["demo"], ["evaluate"], ["prolog"], ["plan", "--goal", "no_spill", "--verify", "3"]):
        assert pinned(*argv), argv
    for argv in (["ask", "pour low"], ["vocab"], ["check", "pour_low"], ["count"],
                 ["plan", "--goal", "no_spill", "--verify", "0"], ["conclusions", "f.pl"],
                 ["convert", "f.pl"]):
        assert not pinned(*argv), argv


def test_a_pinned_command_runs_with_the_baseline_math():
    goal = "getenv('OPENBLAS_CORETYPE', V), write(V), nl"
    env = {k: v for k, v in os.environ.items() if k not in baseline.ENVIRONMENT}
    p = subprocess.run([sys.executable, "-m", "pantarhei.bridge", "prolog", "-g", goal],
                       capture_output=True, text=True, env=env, stdin=subprocess.DEVNULL,
                       timeout=300)
    assert p.returncode == 0, p.stderr
    assert p.stdout.split()[-1] == baseline.ENVIRONMENT["OPENBLAS_CORETYPE"]


def ask_lines(text: str, *args: str) -> subprocess.CompletedProcess:
    return subprocess.run([sys.executable, "-m", "pantarhei.bridge", "ask", *args], input=text,
                          capture_output=True, text=True, timeout=300)


def test_ask_answers_each_line_of_standard_input():
    r = ask_lines("pour from the side\n\n# a comment\nsing me a song\nwith a light liquid\n",
                  "--json")
    assert r.returncode == 1          # one question was not understood
    decoder, out, answers = json.JSONDecoder(), r.stdout.strip(), []
    while out:
        obj, end = decoder.raw_decode(out)
        answers.append(obj)
        out = out[end:].strip()
    assert [a["understood"] for a in answers] == [["pour_to_side"], ["light_liquid"]]
    assert all(len(a["outcomes"]) == 9 for a in answers)
    lines = [line for line in r.stderr.splitlines() if line.strip()]
    assert len(lines) == 1 and lines[0].startswith("pantarhei ask: line 4: understood none")
    # `-` reads standard input too, and every answered question exits 0
    r = ask_lines("pour from the side\n", "-")
    assert r.returncode == 0 and r.stdout.count("understood: pour_to_side") == 1
    # nothing to ask: one line
    r = ask_lines("\n", "-")
    assert r.returncode == 2 and "give a scene" in r.stderr


BAD = [
    (("ask", "pour from the side", "--why", ""), "--why: give an expectation"),
    (("ask", "pour from the side", "--why", "  "), "--why: give an expectation"),
    (("explore", "--out", "."), "a directory, not a file"),
    (("demo", "--oracle", "synthetic", "--out", "."), "a directory, not a file"),
    (("explore", "--out", "a_file/learned.pl"), "is not a directory"),
    (("explore", "--budget", "1000000000", "--out", "t.pl"), "--budget: must be at most"),
    (("explore", "--batch", "0", "--out", "t.pl"), "--batch: must be at least 1"),
    (("explore", "--uncertainty", "-1", "--out", "t.pl"), "--uncertainty: must be at least 0"),
    (("evaluate", "--scenes", "10000000000"), "--scenes: must be at most"),
    (("plan", "--goal", "no_spill", "--verify", "1000000000000"), "--verify: must be at most"),
    (("render", "--antecedent", "pour_low", "--size", "100000x100000"), "--size"),
    (("render", "--antecedent", "pour_low", "--out", "."), "--out must name a .gif"),
    (("render", "--antecedent", "pour_low", "--out", "a_file/p.gif"), "is not a directory"),
    (("prolog", "-g", "foo(("), "--goal: syntax error"),
    (("simulate", "--antecedent", "pour_low", "--workers", "1000000"), "--workers: must be at most"),
]


@pytest.mark.parametrize("args,words", BAD)
def test_bad_options_are_one_line_before_any_work(tmp_path, args, words):
    (tmp_path / "a_file").write_text("")
    line = assert_one_line_error(run_cli(*args, "--store", "s.sqlite", cwd=str(tmp_path))
                                 if args[0] in ("explore", "demo", "simulate", "evaluate")
                                 else run_cli(*args, cwd=str(tmp_path)))
    assert words in line
    assert [f.name for f in tmp_path.iterdir()] == ["a_file"]      # nothing was written


@pytest.mark.parametrize("content,words", [
    (b'[{"params": {"start_x": 1' + b"0" * 400 + b"}}]", "'start_x' must be a number, not inf"),
    (b'[{"params": {"start_x": 1' + b"0" * 5000 + b"}}]", "'start_x' must be a number, not inf"),
    (b'\xff\xfe[{"params": {}}]', "not UTF-8 text"),
])
def test_parameter_files_with_huge_numbers_or_other_bytes_are_one_line(tmp_path, content, words):
    f = tmp_path / "p.json"
    f.write_bytes(content)
    line = assert_one_line_error(run_cli("simulate", "--params", str(f), "--no-store"))
    assert words in line
