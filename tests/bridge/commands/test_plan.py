"""`pantarhei plan` (bridge/commands/plan.py), run as a user runs it: the
theory's plans (clingo) best first; a pour that pours unless a goal says
otherwise; plans verified in the simulation (the synthetic oracle, asked
for with --oracle, stands in for PyBullet), refuted ones learned from and
never shown as verified, the search going on until a plan is verified or
saying why none is in one line; each plan's numbers; the context in
words; the learned theory written only where asked."""
from __future__ import annotations

import json
from pathlib import Path

import pytest

from pantarhei.theory.lexicon import load_vocabulary
from tests.conftest import assert_one_line_error

EX = Path(__file__).resolve().parents[3] / "examples" / "extend_by_hand"
LEARNED = str(EX / "learned.pl")
HAND = str(EX / "hand.dfl")


def test_plan_best_first_then_alternatives(cli) -> None:
    args = ("plan", "--goal", "liquid_leaves_source,no_spill", "--given", "light_liquid", "--json",
            "--verify", "0")
    before = json.loads(cli(*args, "--theory", LEARNED).out)
    after = json.loads(cli(*args, "--theory", LEARNED, "--theory", HAND).out)
    assert before["added_goals"] == []          # the goals speak of the liquid leaving
    assert [p["chosen"] for p in before["plans"]] == [["pour_centred", "pour_upside_down"]]
    plans = [p["chosen"] for p in after["plans"]]
    assert plans[0] == ["pour_centred", "pour_upside_down"]
    assert ["pour_centred", "pour_steeply_tilted", "slow_retreat"] in plans
    assert all(len(a) <= len(b) for a, b in zip(plans, plans[1:]))
    assert all("light_liquid" in p["antecedent"] for p in after["plans"])


CONFIDENT = """rule(r1, defeasible, no_spill).
learned(r1).
provenance(r1, confidence_permille, 550).
rule(r2, defeasible, no_spill).
body(r2, pour_centred).
learned(r2).
provenance(r2, confidence_permille, 950).
"""


def test_plan_rests_on_the_most_confident_rules_first(cli, tmp_path: Path) -> None:
    # the default already concludes no spill, but only just: the plan that
    # pours centred rests on a rule of 95%, and comes first
    f = tmp_path / "confident.pl"
    f.write_text(CONFIDENT)
    r = cli("plan", "--goal", "no_spill", "--theory", str(f), "--json", "--verify", "0")
    assert r.code == 0, r.err
    out = json.loads(r.out)
    assert [p["chosen"] for p in out["plans"]] == [["pour_centred"], []]
    assert out["plans"][0]["rests_on"][0] == {"goal": "no_spill", "rule": "r2", "likelihood": 0.95,
                                              "verdict": "holds"}
    # without confidences the cheapest plan comes first
    f.write_text("\n".join(line for line in CONFIDENT.splitlines() if "provenance" not in line))
    r = cli("plan", "--goal", "no_spill", "--theory", str(f), "--json", "--verify", "0")
    assert [p["chosen"] for p in json.loads(r.out)["plans"]] == [[]]


#: Pouring upright keeps the source clear of the destination, but pours
#: nothing; pouring high keeps it clear as well, and pours.
DRY = """rule(r1, defeasible, neg(source_clear)).
rule(r2, defeasible, source_clear).
body(r2, pour_upright).
rule(r3, defeasible, liquid_leaves_source).
rule(r4, defeasible, neg(liquid_leaves_source)).
body(r4, pour_upright).
rule(r5, defeasible, source_clear).
body(r5, pour_high).
sup(r2, r1).
sup(r4, r3).
sup(r5, r1).
"""


def test_a_pour_pours_unless_a_goal_says_otherwise(cli, tmp_path: Path) -> None:
    f = tmp_path / "dry.pl"
    f.write_text(DRY)
    r = cli("plan", "--goal", "source_clear", "--theory", str(f), "--verify", "0", "--json")
    assert r.code == 0, r.err
    out = json.loads(r.out)
    assert out["goals"] == ["source_clear", "liquid_leaves_source"]
    assert out["added_goals"] == ["liquid_leaves_source"]
    plans = [p["antecedent"] for p in out["plans"]]
    assert plans and ["pour_upright"] not in plans and ["pour_high"] in plans
    text = cli("plan", "--goal", "source_clear", "--theory", str(f), "--verify", "0").out
    assert "liquid_leaves_source added: a pour pours" in text
    # asked to pour nothing, the dry plan is the one
    r = cli("plan", "--goal", "source_clear,-liquid_leaves_source", "--theory", str(f), "--verify",
            "0", "--json")
    out = json.loads(r.out)
    assert out["added_goals"] == [] and out["plans"][0]["chosen"] == ["pour_upright"]


def test_a_verified_plan_for_a_pouring_goal_poured_in_every_pour_counted(cli, tmp_path: Path) -> None:
    f = tmp_path / "dry.pl"
    f.write_text(DRY)
    r = cli("plan", "--goal", "source_clear", "--theory", str(f), "--verify", "6", "--oracle",
            "synthetic", "--store", str(tmp_path / "s.sqlite"), "--json")
    assert r.code == 0, r.err
    out = json.loads(r.out)
    for p in out["plans"]:
        assert "pour_upright" not in p["antecedent"]
        v = p["verified"]
        assert v["per_goal"]["liquid_leaves_source"] >= v["met"] >= 0.9 * v["simulated"] > 0


#: A theory that thinks pouring far away fills the destination (it does not).
WISHFUL = """rule(r0, defeasible, liquid_leaves_source).
rule(r1, defeasible, neg(liquid_enters_destination)).
rule(r2, defeasible, liquid_enters_destination).
body(r2, pour_far_away).
rule(r3, defeasible, liquid_enters_destination).
body(r3, pour_centred).
sup(r2, r1).
sup(r3, r1).
"""


def test_a_refuted_plan_is_learned_from_and_never_shown_as_verified(cli, tmp_path: Path) -> None:
    f = tmp_path / "wishful.pl"
    f.write_text(WISHFUL)
    args = ("plan", "--goal", "liquid_enters_destination", "--theory", str(f), "--oracle",
            "synthetic", "--store", str(tmp_path / "s.sqlite"), "--verify", "6")
    proposed = json.loads(cli(*args[:5], "--verify", "0", "--json").out)["plans"]
    assert [p["chosen"] for p in proposed][:1] == [["pour_far_away"]]
    r = cli(*args, "--json")
    assert r.code == 0, r.err
    out = json.loads(r.out)
    assert [p["chosen"] for p in out["plans"]] == [["pour_centred"]]
    assert out["plans"][0]["verified"]["met"] >= 0.9 * out["plans"][0]["verified"]["simulated"]
    far = [t for t in out["search"]["tried"] if t["chosen"] == ["pour_far_away"]]
    assert far and not far[0]["verified"] and far[0]["per_goal"]["liquid_enters_destination"] == 0
    assert out["search"]["pours"] <= out["search"]["budget"] == 80
    text = cli(*args).out
    assert "refuted: pour_far_away" in text and "best plan (1 proposition)" in text
    assert "\n  pour_far_away" not in text          # not among a plan's propositions


#: A theory that thinks raising the source on its approach keeps it clear
#: of the destination: in the synthetic oracle some 70% of such pours do;
#: with seed 2 the first 10 all do, and 6 of the next 10.
RAISING = """rule(r0, defeasible, liquid_leaves_source).
rule(r1, defeasible, neg(source_clear)).
rule(r2, defeasible, source_clear).
body(r2, approach_raising).
sup(r2, r1).
"""


def test_a_plan_passing_its_first_pours_by_luck_is_not_printed_as_verified(cli, tmp_path: Path
                                                                           ) -> None:
    f = tmp_path / "raising.pl"
    f.write_text(RAISING)
    args = ("plan", "--goal", "source_clear", "--theory", str(f), "--oracle", "synthetic",
            "--store", str(tmp_path / "s.sqlite"), "--verify", "10", "--seed", "2")
    r = cli(*args, "--json")
    assert r.code == 0, r.err
    out = json.loads(r.out)
    raising = out["search"]["tried"][0]
    assert raising["chosen"] == ["approach_raising"] and raising["origin"] == "theory"
    first, confirming = raising["batches"]
    assert first == {"batch": "first", "simulated": 10, "met": 10}      # it passed its first 10
    assert confirming["batch"] == "confirming" and confirming["met"] < 9
    assert not raising["verified"] and raising["met"] == 10 + confirming["met"]
    assert out["search"]["confirm"] == 10
    assert out["plans"] and all(p["chosen"] != ["approach_raising"] for p in out["plans"])
    for p in out["plans"]:          # every plan shown: its share of every verifying pour
        v = p["verified"]
        assert [b["batch"] for b in v["batches"]] == ["first", "confirming"]
        assert v["simulated"] == sum(b["simulated"] for b in v["batches"]) == 20
        assert v["met"] >= 0.9 * v["simulated"]
        assert v["per_goal_share"] == {g: round(n / 20, 3) for g, n in v["per_goal"].items()}
    text = cli(*args).out
    k, n = confirming["met"], confirming["simulated"]     # stopped once it can no longer pass
    assert (f"refuted: approach_raising (theory, round 1): every goal met in {10 + k} of {10 + n} "
            f"pours: 10 of the first 10, then {k} of {n} fresh ones confirming it (not "
            f"confirmed)") in text
    assert "\n  approach_raising" not in text        # not among a plan's propositions
    assert "per goal, of every verifying pour: source_clear 20 of 20 (100%)" in text
    # with no budget left for another plan, none is found, and the line says why
    line = assert_one_line_error(cli(*args, "--pours", "20"))
    assert line.endswith(f"the best, approach_raising, met them in 10 of 10, then in {k} of {n} "
                         f"fresh pours confirming it"), line


def test_no_plan_found_says_why_in_one_line(cli, tmp_path: Path) -> None:
    # a theory that thinks pouring far away fills the destination and
    # keeps the source full: no pour does both
    f = tmp_path / "wishful.pl"
    f.write_text(WISHFUL + "rule(r4, defeasible, neg(liquid_leaves_source)).\n"
                           "body(r4, pour_far_away).\nsup(r4, r0).\n")
    args = ("plan", "--goal", "liquid_enters_destination,-liquid_leaves_source", "--theory", str(f),
            "--oracle", "synthetic", "--store", str(tmp_path / "s.sqlite"), "--verify", "4")
    r = cli(*args, "--pours", "8")
    line = assert_one_line_error(r)
    assert r.out == ""                               # nothing printed as a plan
    assert line.startswith("pantarhei plan: no plan found: every candidate refuted: none of the "), line
    assert "(the budget of 8 pours is spent)" in line and "met them in 0 of" in line, line
    r = cli(*args, "--pours", "8", "--json")          # for a program: the search, no plan
    out = json.loads(r.out)
    assert r.code == 2 and out["plans"] == [] and f"no plan found: {out['none']}" in r.err
    assert out["search"]["tried"] and not any(t["verified"] for t in out["search"]["tried"])
    # a goal no rule concludes: unreachable in the theory, and not found by searching either
    g = tmp_path / "silent.pl"
    g.write_text("rule(r1, defeasible, liquid_leaves_source).\n")
    line = assert_one_line_error(cli("plan", "--goal", "neg(no_spill)", "--theory", str(g),
                                     "--oracle", "synthetic", "--store", str(tmp_path / "s.sqlite"),
                                     "--verify", "4", "--pours", "8"))
    assert line.startswith("pantarhei plan: no plan found: unreachable in the theory (unreachable "
                           "goal: no rule of"), line


def test_the_learned_theory_is_written_only_where_asked(cli, tmp_path: Path) -> None:
    from pantarhei.bridge.theories.loading import DEFAULT_THEORY, load

    f = tmp_path / "wishful.pl"
    f.write_text(WISHFUL)
    before = DEFAULT_THEORY.read_bytes()
    out = tmp_path / "learned.pl"
    args = ("plan", "--goal", "liquid_enters_destination", "--theory", str(f), "--oracle",
            "synthetic", "--store", str(tmp_path / "s.sqlite"), "--verify", "6")
    r = cli(*args, "--learned-out", str(out))
    assert r.code == 0, r.err
    assert f"written to {out}" in r.out
    learned = load([str(out)])
    planned = [r for r in learned.rules if r.id.startswith("p")]
    assert {r.body for r in planned} == {("pour_far_away",), ("pour_centred",)}
    far = learned.rule("p0_liquid_enters_destination")
    assert far.head == "neg(liquid_enters_destination)"
    prov = {(k, v) for rid, k, v in learned.provenance if rid == far.id}
    assert ("layer", "plans") in prov and ("support", 2) in prov and ("kept", 2) in prov
    assert f.read_text() == WISHFUL and DEFAULT_THEORY.read_bytes() == before
    line = assert_one_line_error(cli(*args, "--learned-out", str(DEFAULT_THEORY)))
    assert "that is the shipped theory" in line


def test_each_plan_carries_its_numbers(cli) -> None:
    vocab = load_vocabulary()
    r = cli("plan", "--goal", "no_spill", "--given", "pour_very_high", "--theory", LEARNED,
            "--verify", "0", "--json")
    assert r.code == 0, r.err
    p = json.loads(r.out)["plans"][0]
    fixes = {x["parameter"]: x for x in p["fixes"]}
    assert fixes["pour_z"] == {"parameter": "pour_z", "unit": "mm", "low": 250, "high": 400,
                               "by": "pour_very_high"}
    for name in p["antecedent"]:
        m = vocab.propositions[name].model
        assert fixes[m.param]["by"] == name
        if m.kind == "uniform":
            assert (fixes[m.param]["low"], fixes[m.param]["high"]) == (m.low, m.high)
    assert sorted([*fixes, *(x["parameter"] for x in p["ordinary"])]) == \
        sorted(vocab.parameter_names)
    ordinary = {x["parameter"]: x for x in p["ordinary"]}
    assert (ordinary["destination_mass"]["low"], ordinary["destination_mass"]["high"]) == (200, 600)
    assert [s["goal"] for s in p["rests_on"]] == ["no_spill", "liquid_leaves_source"]
    text = cli("plan", "--goal", "no_spill", "--given", "pour_very_high", "--theory", LEARNED,
               "--verify", "0").out
    assert "pour_z 250 to 400 mm" in text and "pour_very_high (given)" in text
    assert "left to the ordinary pour:" in text and "destination_mass 200 to 600 g" in text


def test_the_context_in_words(cli) -> None:
    r = cli("plan", "pour very high with a light liquid", "--goal", "no_spill", "--theory", LEARNED,
            "--verify", "0", "--json")
    assert r.code == 0, r.err
    assert json.loads(r.out)["given"] == ["light_liquid", "pour_very_high"]
    line = assert_one_line_error(cli("plan", "pour very high", "--given", "light_liquid", "--goal",
                                     "no_spill", "--theory", LEARNED, "--verify", "0"))
    assert "not both" in line


def test_negated_goal(cli) -> None:
    for goal in ("--goal=neg(no_spill)", "--goal=-no_spill"):
        r = cli("plan", goal, "--theory", LEARNED, "--json", "--verify", "0")
        assert r.code == 0, r.err
        out = json.loads(r.out)
        assert out["goals"] == ["neg(no_spill)", "liquid_leaves_source"]
        assert "pour_to_side" in out["plans"][0]["chosen"]


@pytest.mark.parametrize("args,words", [
    (("plan", "--goal", "destination_still_settle", "--theory", LEARNED, "--verify", "0"),
     "no rule of"),
    (("plan", "--goal", "liquid_leaves_source", "--given", "light_liquid,pour_steeply_tilted,pour_level",
      "--theory", LEARNED, "--verify", "0"), "unreachable goal"),
    (("plan", "--goal", "no_spil", "--theory", LEARNED), "did you mean no_spill"),
    (("plan", "--goal", "no_spill", "--min-success", "1.5"), "--min-success"),
    (("plan", "--goal", "no_spill", "--pours", "5"), "--pours 5: the budget must hold one plan's"),
    (("plan", "sing me a song", "--goal", "no_spill", "--verify", "0"), "understood none"),
])
def test_bad_input_gets_one_line_and_a_non_zero_exit(cli, args, words: str) -> None:
    line = assert_one_line_error(cli(*args))
    assert words in line, line


@pytest.mark.parametrize("oracle", ["synthetic", "faulty"])
def test_plan_verifies_with_a_real_oracle_unless_told(cli, tmp_path: Path, oracle: str) -> None:
    """A theory that names a test-only oracle (analytic scores, or faults)
    has no plan "verified" by it unless --oracle asks for one; --verify 0
    still shows its plans."""
    f = tmp_path / "wishful.pl"
    f.write_text(f"setting(oracle, {oracle}).\n" + WISHFUL)
    store = tmp_path / "s.sqlite"
    line = assert_one_line_error(cli("plan", "--goal", "liquid_enters_destination", "--theory", str(f),
                                     "--verify", "2", "--store", str(store)))
    assert line == (f"pantarhei plan: {f}: setting(oracle, {oracle}) names a test-only oracle: plans "
                    f"are verified in a real simulation only (pybullet); --verify 0 shows the "
                    f"theory's plans unverified"), line
    assert not store.exists()
    r = cli("plan", "--goal", "liquid_enters_destination", "--theory", str(f), "--verify", "0", "--json")
    assert r.code == 0, r.err
    assert "verified" not in json.loads(r.out)["plans"][0]
