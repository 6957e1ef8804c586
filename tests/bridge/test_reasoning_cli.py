"""`pantarhei ask`, `plan` and `conclusions`, run as a user runs them."""
from __future__ import annotations

import json
from pathlib import Path

import pytest

from tests.conftest import assert_one_line_error

EX = Path(__file__).resolve().parents[2] / "examples" / "extend_by_hand"
LEARNED = str(EX / "learned.pl")
HAND = str(EX / "hand.dfl")
SCENE = "light_liquid,pour_steeply_tilted,slow_retreat,pour_centred"


def test_ask_in_words_says_what_it_understood_and_why(cli) -> None:
    r = cli("ask", "pour from the side with a light liquid", "--theory", LEARNED)
    assert r.code == 0, r.err
    assert "understood: light_liquid, pour_to_side" in r.out
    assert "[no ] no_spill" in r.out and "rule r1" in r.out


def test_ask_json_before_and_after_a_rule_added_by_hand(cli) -> None:
    before = json.loads(cli("ask", "--props", SCENE, "--theory", LEARNED, "--json").out)
    after = json.loads(cli("ask", "--props", SCENE, "--theory", LEARNED, "--theory", HAND, "--json").out)
    assert before["understood"] == sorted(SCENE.split(","))
    assert set(before["outcomes"].values()) <= {"holds", "fails", "unknown"}
    assert len(before["outcomes"]) == 9
    assert before["outcomes"]["liquid_leaves_source"] == "fails"
    assert before["reasons"]["liquid_leaves_source"]["rule"] == "r4"
    assert after["outcomes"]["liquid_leaves_source"] == "holds"
    assert after["reasons"]["liquid_leaves_source"]["rule"] == "h1"
    assert "h1 > r4" in after["reasons"]["liquid_leaves_source"]["why"]
    assert before["outcomes"]["no_spill"] == after["outcomes"]["no_spill"] == "holds"


def test_ask_why_and_why_not(cli) -> None:
    why = cli("ask", "--props", "light_liquid,pour_steeply_tilted", "--theory", LEARNED,
              "--why", "neg(liquid_leaves_source)")
    assert why.code == 0, why.err
    assert "by rule r4" in why.out and "r3 is overridden by r4" in why.out
    why_not = json.loads(cli("ask", "--props", "pour_to_side", "--theory", LEARNED,
                             "--why", "no_spill", "--json").out)
    assert why_not["literal"] == "no_spill"
    assert "rule r2 (pour_centred => no_spill) does not apply" in why_not["why"]


def test_plan_best_first_then_alternatives(cli) -> None:
    args = ("plan", "--goal", "liquid_leaves_source,no_spill", "--given", "light_liquid", "--json")
    before = json.loads(cli(*args, "--theory", LEARNED).out)
    after = json.loads(cli(*args, "--theory", LEARNED, "--theory", HAND).out)
    assert [p["chosen"] for p in before["plans"]] == [["pour_centred", "pour_upside_down"]]
    plans = [p["chosen"] for p in after["plans"]]
    assert plans[0] == ["pour_centred", "pour_upside_down"]
    assert ["pour_centred", "pour_steeply_tilted", "slow_retreat"] in plans
    assert all(len(a) <= len(b) for a, b in zip(plans, plans[1:]))
    assert all("light_liquid" in p["antecedent"] for p in after["plans"])


def test_plan_negated_goal(cli) -> None:
    for goal in ("--goal=neg(no_spill)", "--goal=-no_spill"):
        r = cli("plan", goal, "--theory", LEARNED, "--json")
        assert r.code == 0, r.err
        assert json.loads(r.out)["goals"] == ["neg(no_spill)"]
        assert json.loads(r.out)["plans"][0]["chosen"] == ["pour_to_side"]


def test_conclusions_of_both_engines_agree_and_use_dfl_literals(cli, tmp_path: Path) -> None:
    f = tmp_path / "t.dfl"
    f.write_text(">> bird\n>> penguin\nr1: bird => flies\nr2: penguin => -flies\nr2 > r1\n")
    out = {e: json.loads(cli("conclusions", str(f), "--engine", e, "--json").out) for e in ("prolog", "asp")}
    assert out["prolog"] == out["asp"]
    assert set(out["prolog"]) == {"+D", "-D", "+d", "-d"}
    assert "-flies" in out["prolog"]["+d"] and "flies" in out["prolog"]["-d"]
    loop = tmp_path / "loop.pl"
    loop.write_text("rule(r1, defeasible, p).\nbody(r1, q).\nrule(r2, defeasible, q).\nbody(r2, p).\n")
    wf = json.loads(cli("conclusions", str(loop), "--json").out)
    kunen = json.loads(cli("conclusions", str(loop), "--no-well-founded", "--engine", "asp", "--json").out)
    assert "p" in wf["-d"] and "p" not in kunen["-d"]
    text = cli("conclusions", str(loop)).out
    assert "-d p\n" in text


@pytest.mark.parametrize("args,words", [
    (("ask", "--props", "pour_to_sid", "--theory", LEARNED), "did you mean pour_to_side"),
    (("ask", "--props", "pour_to_side,pour_centred", "--theory", LEARNED), "one_value_per_dimension"),
    (("ask", "--props", "pour_below_rim,pour_centred", "--theory", LEARNED), "inside_destination"),
    (("ask", "sing me a song", "--theory", LEARNED), "understood none"),
    (("plan", "--goal", "destination_still_settle", "--theory", LEARNED), "no rule of"),
    (("plan", "--goal", "liquid_leaves_source", "--given", "light_liquid,pour_steeply_tilted,pour_level",
      "--theory", LEARNED), "unreachable goal"),
    (("plan", "--goal", "no_spil", "--theory", LEARNED), "did you mean no_spill"),
    (("conclusions", "/nonexistent/theory.dfl"), "no such theory file"),
])
def test_bad_input_gets_one_line_and_a_non_zero_exit(cli, args, words: str) -> None:
    line = assert_one_line_error(cli(*args))
    assert words in line, line


def test_malformed_files_name_the_line(cli, tmp_path: Path) -> None:
    f = tmp_path / "bad.dfl"
    f.write_text("r1: a => b\nr2 b -> c\n")
    assert f"{f}:2:" in assert_one_line_error(cli("conclusions", str(f)))
    g = tmp_path / "bad.pl"
    g.write_text("rule(r1, defeasible, b).\nrule(r2, maybe, c).\n")
    assert f"{g}:2:" in assert_one_line_error(cli("ask", "--props", "pour_centred", "--theory", str(g)))


def test_without_a_theory_the_commands_say_how_to_get_one(cli, tmp_path: Path) -> None:
    from pantarhei.bridge.reasoning import DEFAULT_THEORY

    if DEFAULT_THEORY.exists():
        pytest.skip("a learned theory is installed")
    line = assert_one_line_error(cli("ask", "pour from the side"))
    assert "no learned theory yet" in line and "--theory" in line
