"""`pantarhei rules` (bridge/commands/rules.py), run as a user runs it: a
theory's rules with their likelihood and the pours behind them, counted
for the expectation holding as `ask` counts them."""
from __future__ import annotations

import json
from pathlib import Path

from tests.conftest import assert_one_line_error

THEORY = ("rule(g0_no_spill, defeasible, no_spill).\nlearned(g0_no_spill).\n"
          "provenance(g0_no_spill, support, 60).\nprovenance(g0_no_spill, kept, 50).\n"
          "provenance(g0_no_spill, confidence_permille, 830).\n"
          "rule(g1_no_spill, defeasible, neg(no_spill)).\nbody(g1_no_spill, pour_to_side).\n"
          "learned(g1_no_spill).\nprovenance(g1_no_spill, support, 52).\n"
          "provenance(g1_no_spill, kept, 41).\nprovenance(g1_no_spill, confidence_permille, 912).\n"
          "rule(h1, defeasible, source_clear).\nbody(h1, pour_high).\n")


def test_rules_lists_each_rule_with_its_likelihood_and_pours(cli, tmp_path: Path) -> None:
    f = tmp_path / "t.pl"
    f.write_text(THEORY)
    r = cli("rules", "--theory", str(f))
    assert r.code == 0, r.err
    assert "  g1_no_spill: pour_to_side => neg(no_spill)\n" \
           "      holds in 9%; held in 11 of 52 pours of pour from the side\n" in r.out
    assert "      holds in 83%; held in 50 of 60 ordinary pours\n" in r.out
    assert "  h1: pour_high => source_clear\n      no likelihood; written by hand" in r.out
    out = json.loads(cli("rules", "--theory", str(f), "--expectation", "no_spill", "--json").out)
    assert [x["id"] for x in out["rules"]] == ["g0_no_spill", "g1_no_spill"]
    assert out["rules"][1] == {"id": "g1_no_spill", "kind": "defeasible", "body": ["pour_to_side"],
                               "head": "neg(no_spill)", "expectation": "no_spill", "learned": True,
                               "likelihood": 0.088, "held": 11, "pours": 52, "antecedent": None}


def test_rules_of_the_shipped_theory_count_pours_as_ask_does(cli) -> None:
    rows = {x["id"]: x for x in json.loads(cli("rules", "--json").out)["rules"]}
    assert rows and all(x["learned"] for x in rows.values())
    asked = json.loads(cli("ask", "--props", "pour_to_side", "--json").out)["outcomes"]
    compared = 0
    for e, o in asked.items():
        # (an answer by a rule of another body cites the explored antecedent's own pours)
        if o["evidence"] is not None and o["evidence"]["pours"] is not None \
                and rows[o["rule"]]["body"] == ["pour_to_side"]:
            compared += 1
            row = rows[o["rule"]]
            assert (row["held"], row["pours"]) == (o["evidence"]["held"], o["evidence"]["pours"])
            assert abs(row["likelihood"] - o["likelihood"]) < 1e-9
    assert compared


def test_rules_refuses_an_unknown_expectation_in_one_line(cli) -> None:
    line = assert_one_line_error(cli("rules", "--expectation", "no_spil"))
    assert "did you mean no_spill" in line


def test_render_draws_a_pour_of_a_rules_body(cli, tmp_path: Path) -> None:
    f, gif = tmp_path / "t.pl", tmp_path / "r.gif"
    f.write_text(THEORY)
    r = cli("render", "--rule", "g1_no_spill", "--theory", str(f), "--out", str(gif),
            "--size", "64x48", "--fps", "2")
    assert r.code == 0, r.err
    assert r.out.startswith("rule g1_no_spill: pour_to_side => neg(no_spill): a pour of its body")
    assert gif.read_bytes()[:6] in (b"GIF87a", b"GIF89a")
    line = assert_one_line_error(cli("render", "--rule", "g1_nospill", "--theory", str(f),
                                     "--out", str(gif)))
    assert "did you mean g1_no_spill" in line
    assert_one_line_error(cli("render", "--antecedent", "", "--theory", str(f), "--out", str(gif)))
