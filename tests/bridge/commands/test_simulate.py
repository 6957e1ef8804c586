"""The commands `pantarhei simulate` and `pantarhei render`
(bridge/commands/simulate.py), run as a user would: the oracle's command
line (what `render` draws is tested in tests/oracle/test_render.py)."""
from __future__ import annotations

import json

import pytest

from pantarhei.oracle.generative import to_dict
from pantarhei.oracle.store import Store
from pantarhei.theory.lexicon import load_vocabulary

from tests.conftest import assert_one_line_error
from tests.oracle.pours import BASE, CENTRED_LOW_TIPPED, pour

EXPECTATIONS = load_vocabulary().expectation_names


@pytest.mark.slow
def test_simulate_samples_simulates_and_stores(cli, tmp_path):
    db = tmp_path / "s.sqlite"
    args = ("simulate", "--antecedent", "pour_centred,pour_low,little_liquid", "-n", "2",
            "--seed", "4", "--json", "--store", str(db), "--workers", "2")
    r = cli(*args)
    assert r.code == 0, r.err
    out = json.loads(r.out)
    assert len(out) == 2
    for item in out:
        assert set(item["scores"]) == set(EXPECTATIONS)
        assert all(0 <= v <= 1 for v in item["scores"].values())
        assert -20 <= item["params"]["pour_x"] <= 20 and 0 <= item["params"]["pour_z"] <= 60
        assert 10 <= item["params"]["particle_count"] <= 30
        f = item["record"]["fractions"]
        assert f["source"] + f["destination"] + f["elsewhere"] == pytest.approx(1)
    with Store(db) as st:
        assert st.count("ok") == 2
    again = cli(*args)
    assert again.code == 0 and json.loads(again.out) == out     # same seed, same result


@pytest.mark.slow
def test_simulate_given_parameterizations_and_print_them(cli, tmp_path):
    f = tmp_path / "pours.json"
    f.write_text(json.dumps([{"params": to_dict(pour(**CENTRED_LOW_TIPPED))}, {"params": BASE}]))
    r = cli("simulate", "--params", str(f), "--no-store", "--executor", "inline")
    assert r.code == 0, r.err
    assert r.out.count("pour ") == 2
    for e in EXPECTATIONS:
        assert r.out.count(e) == 2
    assert "holds" in r.out and "in the destination" in r.out
    assert "argv" not in r.out


BAD = [
    (("simulate", "--antecedent", "pour_centred,pour_lo"), "unknown proposition 'pour_lo'"),
    (("simulate", "--antecedent", "pour_centred,pour_far_away"), "one_value_per_dimension"),
    (("render", "--antecedent", "pour_low,pour_high", "--out", "x.gif"), "invalid antecedent"),
    (("simulate", "--antecedent", "pour_low", "-n", "0"), "-n: must be at least 1"),
    (("simulate", "--antecedent", "pour_low", "-n", "1000000000000"), "-n: must be at most"),
    (("simulate", "--antecedent", "pour_low", "--workers", "0"), "--workers"),
    # seeds within 0 .. 2**31 - 1, whatever the command
    (("simulate", "--antecedent", "pour_low", "--seed", "-1"), "--seed: must be at least 0"),
    (("simulate", "--antecedent", "pour_low", "--seed", "2147483648"), "at most 2147483647"),
    (("render", "--antecedent", "pour_low", "--seed", "-1"), "--seed: must be at least 0"),
    (("render", "--antecedent", "pour_low", "--seed", "4294967296"), "at most 2147483647"),
    (("plan", "--goal", "no_spill", "--verify", "2", "--seed", "-1"), "--seed: must be at least 0"),
    (("explore", "--seed", "4294967296"), "at most 2147483647"),
    # a positive, finite time limit
    (("simulate", "--antecedent", "pour_low", "--timeout", "0"), "--timeout: must be more than 0"),
    (("simulate", "--antecedent", "pour_low", "--timeout", "-5"), "--timeout: must be more than 0"),
    (("simulate", "--antecedent", "pour_low", "--timeout", "nan"), "finite"),
    (("explore", "--uncertainty", "inf"), "--uncertainty: must be a finite number"),
    (("simulate", "--antecedent", "pour_low", "--ray-address", "1.2.3.4:6379"), "--executor ray"),
    (("render", "--antecedent", "pour_low", "--out", "x.png"), ".gif"),
    (("render", "--antecedent", "pour_low", "--size", "big"), "--size"),
]


@pytest.mark.parametrize("args,words", BAD)
def test_bad_input_is_one_line(cli, tmp_path, args, words):
    line = assert_one_line_error(cli(*args, "--store", str(tmp_path / "s.sqlite"))
                                 if args[0] == "simulate" else cli(*args))
    assert words in line
    assert not (tmp_path / "s.sqlite").exists()


def _params_file(tmp_path, content):
    f = tmp_path / "p.json"
    f.write_text(content if isinstance(content, str) else json.dumps(content))
    return str(f)


@pytest.mark.parametrize("content,words", [
    ('[{"params": {"start_x": 1,}}]', "malformed JSON at line 1"),
    ([{"params": {k: v for k, v in BASE.items() if k != "pour_pitch"}}], "'pour_pitch' is missing"),
    ([{"params": {**BASE, "pour_pitch": 500}}], "'pour_pitch' = 500 is outside its bounds"),
    ([{"params": {**BASE, "particle_count": 12.5}}], "whole number"),
    ([{"params": {**BASE, "pour_wobble": 1}}], "unknown parameter 'pour_wobble'"),
    ([{"params": {**BASE, "pour_x": "near"}}], "must be a number"),
    ([{"params": BASE}, 3], "item 2 is not an object"),
    ([], "non-empty list"),
])
def test_bad_parameter_files_are_one_line(cli, tmp_path, content, words):
    line = assert_one_line_error(cli("simulate", "--params", _params_file(tmp_path, content),
                                     "--no-store"))
    assert words in line


def test_missing_parameter_file(cli, tmp_path):
    line = assert_one_line_error(cli("simulate", "--params", str(tmp_path / "nope.json")))
    assert "cannot read" in line


def test_render_refuses_to_draw_over_the_pours_it_reads(cli, tmp_path):
    f = tmp_path / "pour.gif"                  # parameterizations in a file named like a GIF
    text = json.dumps([{"params": BASE}])
    f.write_text(text)
    r = cli("render", "--params", str(f), "--out", str(tmp_path / "sub" / ".." / "pour.gif"))
    assert "--params and --out are the same file" in assert_one_line_error(r)
    assert f.read_text() == text
