"""`pantarhei ask --check N` (bridge/commands/answering.py,
bridge/reasoning/checking.py), run as a user runs it, with the synthetic
oracle (pouring from the side spills there): the share observed beside
each answer, the answers the pours contradict flagged, the pours kept."""
from __future__ import annotations

import json
import sqlite3
from pathlib import Path

from tests.conftest import assert_one_line_error

# r1 says pouring from the side spills nothing, r2 that it does
THEORY = ("setting(oracle, synthetic).\n"
          "rule(r1, defeasible, no_spill).\nbody(r1, pour_to_side).\n"
          "rule(r2, defeasible, neg(liquid_enters_destination)).\nbody(r2, pour_to_side).\n")


def test_check_flags_the_answers_the_pours_contradict(cli, tmp_path: Path) -> None:
    theory, store = tmp_path / "t.pl", tmp_path / "s.sqlite"
    theory.write_text(THEORY)
    args = ("ask", "pour from the side", "--theory", str(theory), "--check", "10",
            "--store", str(store))
    r = cli(*args)
    assert r.code == 0, r.err
    spill = next(line for line in r.out.splitlines() if "] " in line and "no_spill" in line)
    enters = next(line for line in r.out.splitlines() if "liquid_enters_destination " in line)
    assert spill.startswith("  [yes       ]  seen   0%!"), spill
    assert enters.startswith("  [no        ]  seen   0% "), enters
    assert "1 answer the pours contradict (!)" in r.out
    out = json.loads(cli(*args, "--json").out)
    assert out["check"] == {"pours": 10, "seed": 0, "oracle": "synthetic", "store": str(store)}
    assert out["outcomes"]["no_spill"]["check"] == {
        "held": 0, "simulated": 10, "share": 0.0, "contradicts": True}
    assert out["outcomes"]["liquid_enters_destination"]["check"]["contradicts"] is False
    assert out["outcomes"]["source_clear"]["verdict"] == "unknown"
    assert out["outcomes"]["source_clear"]["check"]["contradicts"] is False
    # the pours are kept: the store holds the 10 pours of the question
    with sqlite3.connect(store) as db:
        tables = [t for (t,) in db.execute("select name from sqlite_master where type='table'")]
        assert max(db.execute(f"select count(*) from {t}").fetchone()[0] for t in tables) >= 10


def test_check_is_refused_with_why(cli, tmp_path: Path) -> None:
    theory = tmp_path / "t.pl"
    theory.write_text(THEORY)
    r = cli("ask", "pour from the side", "--theory", str(theory), "--check", "3",
            "--why", "no_spill", "--store", str(tmp_path / "s.sqlite"))
    assert "--check" in assert_one_line_error(r)


def test_why_takes_a_negated_expectation_and_gives_its_steps_in_json(cli, tmp_path: Path) -> None:
    theory = tmp_path / "t.pl"
    theory.write_text(THEORY)
    r = cli("ask", "pour from the side", "--theory", str(theory), "--why", "-liquid_enters_destination")
    assert r.code == 0, r.err
    assert "neg(liquid_enters_destination) by rule r2" in r.out
    out = json.loads(cli("ask", "pour from the side", "--theory", str(theory), "--why",
                         "-liquid_enters_destination", "--json").out)
    assert out["literal"] == "neg(liquid_enters_destination)"
    assert out["steps"][0].startswith("neg(liquid_enters_destination) by rule r2")
    assert "; ".join(out["steps"]) == out["why"]
    proof = out["proof"]                  # the argument as a structure
    assert (proof["kind"], proof["rule"], proof["literal"]) == (
        "defeasible", "r2", "neg(liquid_enters_destination)")
    assert proof["body"] == [{"kind": "given", "literal": "pour_to_side",
                              "text": "pour_to_side is given"}]
    assert proof["text"] == out["steps"][0]
    why_not = json.loads(cli("ask", "--props", "pour_low", "--theory", str(theory), "--why",
                             "no_spill", "--json").out)["proof"]
    assert why_not["kind"] == "not_concluded" and why_not["reasons"]
    assert all({"kind", "rules", "literals", "text"} <= set(r) for r in why_not["reasons"])
    assert cli("ask", "-h").code == 0


def test_theory_files_named_say_they_replace_the_shipped_theory(cli, tmp_path: Path) -> None:
    from pantarhei.theory import default_theory

    theory = tmp_path / "t.pl"
    theory.write_text(THEORY)
    alone = cli("ask", "pour from the side", "--theory", str(theory))
    assert alone.code == 0, alone.err
    assert "in place of the shipped theory, which is not read" in alone.out
    assert json.loads(cli("ask", "pour from the side", "--theory", str(theory), "--json").out)[
        "replaces_shipped"] is True
    both = cli("ask", "pour from the side", "--theory", str(default_theory()), "--theory", str(theory))
    assert both.code == 0, both.err
    assert "in place of" not in both.out
    assert "in place of" not in cli("ask", "pour from the side").out
