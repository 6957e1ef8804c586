"""`pantarhei ask` in one crossing (bridge/reasoning/asking.py and
theory/ask.pl): Python reads the words, one swipl process reads the theory
files as written and answers. What Python still does beside it is tested
equal to it: the answers asked in this process (answers.what_happens, for
theories held in Python) and the checks of a DFL file, which only Python
reads."""
from __future__ import annotations

import subprocess
import sys
from pathlib import Path

import pytest

from pantarhei.bridge.errors import UserError
from pantarhei.bridge.reasoning.answers import what_happens
from pantarhei.bridge.reasoning.asking import Door
from pantarhei.bridge.theories import loading
from pantarhei.theory import THEORY_DIR

EXAMPLES = THEORY_DIR.parent / "examples" / "extend_by_hand"
SCENES = ([], ["pour_to_side"], ["light_liquid"], ["light_liquid", "end_upright", "end_low"],
          ["pour_below_rim"], ["pour_steeply_tilted", "light_liquid", "slow_retreat"],
          ["heavy_liquid", "light_destination"], ["pour_centred"])


def test_ask_starts_no_prolog_in_python() -> None:
    # the theory is read and asked by swipl alone: pyswip is never loaded
    code = ("import sys; from pantarhei.bridge.cli import main; "
            "c = main(['ask', 'pour from the side']); "
            "assert 'pyswip' not in sys.modules, 'pyswip loaded'; sys.exit(c)")
    p = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=120)
    assert p.returncode == 0, p.stderr
    assert "] no_spill" in p.stdout


@pytest.mark.parametrize("files", [["theory/learned/pouring.pl"],
                                   ["examples/extend_by_hand/learned.pl",
                                    "examples/extend_by_hand/hand.pl"]])
def test_the_door_answers_as_the_theory_asked_in_this_process(files: list[str]) -> None:
    paths = [str(THEORY_DIR.parent / f) for f in files]
    theory = loading.load(paths, pouring=True)
    with Door([(p, p, False) for p in paths], " + ".join(paths)) as door:
        for scene in SCENES:
            assert door.answers(scene) == what_happens(theory, scene), scene


def test_a_dfl_file_asked_through_its_stand_in_answers_as_its_native_twin() -> None:
    from pantarhei.bridge.commands.querying import _stand_ins

    learned = str(EXAMPLES / "learned.pl")
    answers = []
    for hand in ("hand.dfl", "hand.pl"):
        with _stand_ins([learned, str(EXAMPLES / hand)]) as (files, source, unread):
            assert unread is None and files[1][1] == str(EXAMPLES / hand)
            with Door(files, source) as door:
                answers.append([door.answers(s) for s in SCENES])
    assert answers[0] == answers[1]


#: Files the checks of a single theory file refuse or warn of.
CHECKED = {
    "empty": "% nothing but a comment\n",
    "unknown body and head": ("rule(r1, defeasible, no_spill).\nbody(r1, pour_sidewise).\n"
                              "rule(r2, defeasible, spilled).\nbody(r2, pour_to_side).\nfact(wet).\n"),
    "own words pass": "rule(r1, defeasible, wet).\nbody(r1, pour_to_side).\nrule(r2, defeasible, no_spill).\nbody(r2, wet).\n",
    "general body": "rule(g1, defeasible, no_spill).\nbody(g1, pour_sideways).\nprovenance(g1, layer, general).\n",
    "general head": "rule(g1, defeasible, neg(spills)).\nprovenance(g1, layer, general).\n",
    "general confidence": ("rule(g1, defeasible, no_spill).\nprovenance(g1, layer, general).\n"
                           "provenance(g1, confidence_permille, 1200).\n"),
    "general support": ("rule(g1, defeasible, no_spill).\nprovenance(g1, layer, general).\n"
                        "provenance(g1, support, many).\n"),
    "general kept": ("rule(g1, defeasible, no_spill).\nprovenance(g1, layer, general).\n"
                     "provenance(g1, kept, 9).\nprovenance(g1, support, 4).\n"),
    "fine": "rule(r1, defeasible, no_spill).\nbody(r1, pour_to_side).\n",
}


def _python_checks(path: Path, capsys) -> tuple[str, list[str]]:
    try:
        loading.load(path, pouring=True)
        error = "loaded"
    except UserError as e:
        error = str(e)
    warnings = [line.removeprefix("warning: ").split(" is not a proposition")[0]
                for line in capsys.readouterr().err.splitlines()]
    return error, warnings


@pytest.mark.parametrize("name", sorted(CHECKED))
def test_python_checks_a_file_as_prolog_does(name: str, tmp_path: Path, capsys) -> None:
    # Python checks a file only where Prolog cannot read it (DFL): both
    # checks say the same of the same theory
    path = tmp_path / "theory.pl"
    path.write_text(CHECKED[name])
    with Door([(str(path), str(path), False)], str(path)) as door:
        warnings, error = door.status()
    capsys.readouterr()
    prolog = (error or "loaded", [f"{w}: {what} {n}" for w, what, n in warnings])
    assert _python_checks(path, capsys) == prolog


def test_a_theory_error_comes_after_the_scenes(tmp_path: Path) -> None:
    bad = tmp_path / "bad.pl"
    bad.write_text("rule(r1, defeasible, b).\nsup(r1, r9).\n")
    with Door([(str(bad), str(bad), False)], str(bad)) as door:
        with pytest.raises(UserError, match="invalid antecedent: pour_centred and pour_to_side"):
            door.answers(["pour_centred", "pour_to_side"])
        with pytest.raises(UserError, match=rf"{bad}:2: sup\(r1, r9\) names r9, which is not a rule"):
            door.answers(["pour_to_side"])


def test_a_compiled_state_answers_as_the_sources(tmp_path: Path, monkeypatch) -> None:
    import shutil
    import time

    from pantarhei.bridge.reasoning.asking import compiled_state, serving

    monkeypatch.setenv("XDG_CACHE_HOME", str(tmp_path))
    swipl = shutil.which("swipl")
    state = compiled_state(swipl)
    assert state is not None and state.parent == tmp_path / "pantarhei"
    first = serving(swipl)                 # from the sources, compiling the state meanwhile
    assert "-x" not in first
    deadline = time.monotonic() + 120
    while not state.is_file() and time.monotonic() < deadline:
        time.sleep(0.2)
    second = serving(swipl)
    assert second[1:3] == ["-x", str(state)]
    shipped = str(THEORY_DIR / "learned" / "pouring.pl")
    request = "answer([pour_to_side]).\nwhy([light_liquid], neg(liquid_leaves_source)).\n"
    said = [subprocess.run([*argv, "--", f"file:{shipped}", shipped], input=request,
                           capture_output=True, text=True, timeout=120).stdout
            for argv in (first, second)]
    assert said[0] == said[1] and said[0].count("end\n") == 2


#: Theories of several files (name -> texts) that Python's loader (plan,
#: conclusions, convert) and ask's refuse alike.
MERGED = {
    "a rule defined twice": ["fact(a).\nrule(r1, defeasible, b).\n",
                             "fact(c).\n% r1 again\nrule(r1, defeasible, d).\n"],
    "sup across files": ["rule(r1, defeasible, b).\n", "rule(r2, defeasible, neg(b)).\nsup(r2, r1).\n"],
    "sup naming no rule": ["rule(r1, defeasible, b).\n", "rule(r3, defeasible, b).\nsup(r3, r9).\n"],
    "a cycle across files": ["rule(r1, defeasible, b).\nrule(r2, defeasible, neg(b)).\n",
                             "fact(c).\nsup(r2, r1).\nsup(r1, r2).\n"],
}


@pytest.mark.parametrize("name", sorted(MERGED))
def test_python_merges_files_as_prolog_does(name: str, tmp_path: Path, capsys) -> None:
    paths = []
    for i, text in enumerate(MERGED[name]):
        paths.append(tmp_path / f"t{i}.pl")
        paths[-1].write_text(text)
    try:
        loading.load(paths, pouring=True)
        python = "loaded"
    except UserError as e:
        python = str(e)
    with Door([(str(p), str(p), False) for p in paths], "") as door:
        _, error = door.status()
    capsys.readouterr()
    assert python == (error or "loaded")


def test_a_file_name_that_is_not_utf8_is_read(tmp_path: Path) -> None:
    import os
    import shutil

    name = os.fsdecode(bytes(tmp_path) + b"/learned\xff.pl")
    shutil.copy(EXAMPLES / "learned.pl", name)
    with Door([(name, name, False)], name) as door:
        said = door.answers(["pour_to_side"])
    with Door([(str(EXAMPLES / "learned.pl"),) * 2 + (False,)], "") as door:
        assert said == door.answers(["pour_to_side"])


def test_a_dfl_files_superiority_errors_name_the_line_it_is_written_on(cli, tmp_path: Path) -> None:
    # the stand-in's lines are not the DFL file's: ask names the line the
    # user wrote, as the commands that read the files in Python do
    learned = str(EXAMPLES / "learned.pl")
    mine = tmp_path / "mine.dfl"
    mine.write_text("h1: light_liquid => liquid_leaves_source\n\n# a comment\nh1 > r99  # mine\n")
    ask = cli("ask", "--props", "light_liquid", "--theory", learned, "--theory", str(mine))
    conclusions = cli("conclusions", learned, str(mine))
    assert ask.err == f"pantarhei ask: {mine}:4: sup(h1, r99) names r99, which is not a rule\n"
    assert conclusions.err.split(": ", 1)[1] == ask.err.split(": ", 1)[1]
    # a cycle across files, the DFL file's pair on its line 3
    mine.write_text("h1: light_liquid => liquid_leaves_source\n\nh1 > r4\n")
    hand = tmp_path / "hand.pl"
    hand.write_text("rule(h2, defeasible, neg(liquid_leaves_source)).\nsup(r4, h1).\n")
    ask = cli("ask", "--props", "light_liquid", "--theory", learned, "--theory", str(mine),
              "--theory", str(hand))
    assert f"{mine}:3: the superiority relation has a cycle" in ask.err
