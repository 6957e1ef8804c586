"""Validity of antecedents (bridge/reasoning/scenes.py): Prolog and clingo
agree, and the count is right; the `check`, `count` and `vocab` commands
that report them."""
from __future__ import annotations

import json

from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from pantarhei.bridge.reasoning import scenes as validity
from pantarhei.bridge.engines.asp import solve
from pantarhei.bridge.engines.swipl import engine
from pantarhei.theory.lexicon import load_vocabulary

from tests.conftest import assert_one_line_error

VOCAB = load_vocabulary()
NAMES = sorted(VOCAB.propositions)
# Propositions that constraints link (shared parameters, conflicts): drawing
# from them often makes antecedents invalid in more than one way.
LINKED = sorted(p for p in NAMES if p.split("_")[0] in ("start", "pour", "end", "approach", "retreat"))

antecedents = st.one_of(
    st.lists(st.sampled_from(NAMES), max_size=10),
    st.lists(st.sampled_from(LINKED), max_size=6),
    st.lists(st.sampled_from(NAMES), min_size=10, max_size=30),
)


@settings(max_examples=10_000, deadline=None, derandomize=True,
          suppress_health_check=[HealthCheck.too_slow])
@given(antecedents)
def test_prolog_and_asp_agree(props):
    by_prolog = validity.violations(props, "prolog")
    by_asp = validity.violations(props, "asp")
    assert by_prolog == by_asp
    assert (not by_prolog) == engine().succeeds("validity:valid_antecedent(Ps)", Ps=props)


def test_the_random_antecedents_are_valid_and_invalid_alike():
    # the agreement test is only worth something if both verdicts are common
    from hypothesis import find

    find(antecedents, lambda ps: len(ps) > 3 and not validity.violations(ps))
    find(antecedents, lambda ps: {v.constraint for v in validity.violations(ps)} >= {
        "one_value_per_dimension", "one_model_per_parameter", "inside_destination"})


def test_count_agrees_with_clingo_enumeration_on_a_sub_vocabulary():
    dims = ["start_height", "start_alignment", "approach_vertical", "approach_horizontal",
            "pour_height", "pour_alignment", "liquid_amount"]
    choice = "{ in(P) : proposition(P, D, _, _), sub(D) }.\n" + "".join(f"sub({d})." for d in dims)
    models = solve(["validity.lp", "valid.lp"], choice, models=0)
    by_components = engine().once("validity:count_valid(Ds, N)", Ds=dims)["N"]
    assert len(models) == by_components


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
