"""what_happens/2 checks its scene as `ask` does, in `pantarhei prolog` and
in plain SWI-Prolog alike; a theory file that cannot be read is one
readable line in plain SWI-Prolog too.

The Prolog side of questions, which no Python module owns: what_happens/2
of theory/queries.pl and load_theory/1 of theory/defeasible.pl (with
theory/theory_files.pl's messages), through theory/pantarhei.pl and the
`prolog` command."""
from __future__ import annotations

import subprocess

import pytest

from pantarhei.theory import PROLOG_ENTRY
from tests.conftest import run_cli


def swipl(goal: str) -> subprocess.CompletedProcess:
    return subprocess.run(["swipl", "-q", "-g", goal, "-t", "halt", str(PROLOG_ENTRY)],
                          capture_output=True, text=True, timeout=30, stdin=subprocess.DEVNULL)


BAD_SCENES = [
    ("what_happens([asdf], O)", "asdf is not a known proposition"),
    ("what_happens([pour_low, pour_very_high], O)", "pour_low and pour_very_high"),
    ("what_happens(X, O)", "not sufficiently instantiated"),
    ("what_happens([pour_low|_], O)", "not sufficiently instantiated"),
    ("what_happens(pour_low, O)", "Type error"),
]


@pytest.mark.parametrize("goal,words", BAD_SCENES)
def test_plain_swipl_refuses_a_bad_scene_at_once(goal, words):
    p = swipl(goal)                    # timeout=30: an unbound scene once ran into the stack limit
    assert p.returncode != 0
    errors = [line for line in p.stderr.splitlines() if line.startswith("ERROR")]
    assert len(errors) == 1 and words in errors[0], p.stderr


@pytest.mark.parametrize("goal,words", BAD_SCENES[:3])
def test_pantarhei_prolog_refuses_a_bad_scene(goal, words):
    r = run_cli("prolog", "-g", goal, timeout=60)
    assert r.code == 1 and words in r.err and "Traceback" not in r.err


def test_a_valid_scene_is_answered():
    p = swipl("what_happens([pour_to_side], O), length(O, N), write(N), nl")
    assert p.returncode == 0 and p.stdout.strip() == "9", p.stderr


def test_plain_swipl_says_what_is_wrong_with_a_theory_file(tmp_path):
    bad = tmp_path / "bad.pl"
    bad.write_text("rule(r1, defeasible, no_spill).\nfoo(.\n")
    p = swipl(f"load_theory('{bad}')")
    assert p.returncode != 0
    assert "Unknown message" not in p.stderr
    assert f"{bad}:2:" in p.stderr, p.stderr
