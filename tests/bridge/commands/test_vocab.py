"""`pantarhei vocab`, `check` and `count` (bridge/commands/vocab.py), run as
a user runs them: both engines' verdicts, the constraints an antecedent
breaks, one line for an unknown name or a missing engine."""
from __future__ import annotations

import json

from pantarhei.bridge.engines.swipl import engine
from pantarhei.theory.lexicon import load_vocabulary

from tests.conftest import assert_one_line_error

VOCAB = load_vocabulary()


def test_count_of_the_whole_vocabulary(cli):
    r = cli("count")
    assert r.code == 0
    n = int(r.out.strip())
    assert n == engine().once("validity:count_valid(N)")["N"]
    # every combination of one value or none per dimension, less the invalid
    upper = 1
    for d in VOCAB.dimensions.values():
        upper *= len(d.values) + 1
    assert 0 < n < upper


def test_check_valid(cli):
    for eng in ("prolog", "asp"):
        r = cli("check", "--engine", eng, "pour_near_rim", "pour_low", "pour_half_tilted")
        assert (r.code, r.out.strip()) == (0, "valid")


def test_check_invalid_names_each_violated_constraint(cli):
    args = ["pour_below_rim", "pour_centred", "start_high", "approach_lowering"]
    outs = []
    for eng in ("prolog", "asp"):
        r = cli("check", "--engine", eng, *args)
        assert r.code == 1
        assert "inside_destination" in r.out and "one_model_per_parameter" in r.out
        outs.append(r.out)
    assert outs[0] == outs[1]


def test_unknown_proposition_names_the_closest(cli):
    line = assert_one_line_error(cli("check", "pour_form_side"))
    assert "unknown proposition 'pour_form_side'" in line and "pour_to_side" in line


def test_missing_swipl_says_how_to_install(cli):
    r = cli("check", "pour_low", env={"LIBSWIPL_PATH": "/nonexistent/libswipl.so",
                                      "SWI_HOME_DIR": "/nonexistent"})
    assert "swi-prolog-nox" in assert_one_line_error(r)


def test_missing_clingo_says_how_to_install():
    import subprocess
    import sys

    code = ("import sys; sys.modules['clingo'] = None\n"
            "from pantarhei.bridge.cli import main\n"
            "sys.exit(main(['check', '--engine', 'asp', 'pour_low']))")
    p = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True)
    assert p.returncode == 2 and "pip install clingo" in p.stderr and "Traceback" not in p.stderr


def test_vocab_json(cli):
    r = cli("vocab", "--json")
    assert r.code == 0
    data = json.loads(r.out)
    assert [len(data[k]) for k in ("parameters", "propositions", "expectations")] == [30, 86, 9]
    assert all("name" in x for k in ("parameters", "propositions", "expectations") for x in data[k])
    side = next(p for p in data["propositions"] if p["name"] == "pour_to_side")
    assert side["gloss"] == "pour from the side" and side["model"]["parameter"] == "pour_x"
