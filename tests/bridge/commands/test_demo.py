"""`pantarhei demo`, the main job, on the synthetic oracle (the same code
path as `make demo`, which uses PyBullet)."""
from __future__ import annotations

import re

from pantarhei.bridge.theories import loading
from tests.conftest import assert_one_line_error, run_cli


def test_demo_learns_writes_asks_and_plans(tmp_path):
    out = tmp_path / "learned" / "pouring.pl"           # the directory is made
    args = ["demo", "--oracle", "synthetic", "--pours", "40", "--out", str(out),
            "--store", str(tmp_path / "s.sqlite"), "--verify", "3", "--no-progress"]
    r = run_cli(*args)
    assert r.code == 0, r.err
    theory = loading.load([out])
    settings = loading.settings(theory)
    explored, simulations = settings["explored"][0], settings["simulations"][0]
    assert simulations == 40 and settings["general_own_pours"] == [0]   # every pour counted
    assert f"explored {explored} antecedents with {simulations} simulations" in r.out
    # one layer: a default per expectation and the rules of explored antecedents
    assert all(x.id.startswith("g") for x in theory.rules)
    assert sum(not x.body for x in theory.rules) == 9
    dfl = loading.load([out.with_suffix(".dfl")])         # the DFL twin reads back the same rules
    assert {(x.id, x.head, frozenset(x.body)) for x in dfl.rules} == \
           {(x.id, x.head, frozenset(x.body)) for x in theory.rules}
    header = out.with_suffix(".dfl").read_text().splitlines()[:3]
    assert header == ["# learned by pantarhei explore; settings of the exploration:",
                      "#   oracle: synthetic", f"#   oracle_version: {theory_version()}"]
    # the paper's three questions, each answered for all nine expectations, then a plan
    assert r.out.count("understood:") == 3
    marks = re.findall(r"^  \[(yes|no|maybe|\?) +(\d+%)?\] ", r.out, re.M)
    assert len(marks) == 27
    assert all(word != "?" and share for word, share in marks) and "assumed" not in r.out
    assert re.search(r"the ordinary pour.* (does not reach|already reaches) these goals", r.out)
    # a plan verified on its 3 pours and 3 fresh ones confirming it
    assert re.search(r"verified: goals met in \d of 6 simulations", r.out) or "no plan:" in r.out
    # a second run reads every simulation from the store and writes the same theory
    first = out.read_text()
    again = run_cli(*args)
    assert again.code == 0, again.err
    assert out.read_text() == first


def test_the_demo_plans_what_the_ordinary_pour_does_not_reach(tmp_path):
    """The goal query is the first of PLANS that the theory says the
    ordinary pour with what is given misses; a theory whose ordinary pour
    reaches every goal gets the clean pour."""
    from pantarhei.bridge.commands.demo import PLANS, chosen_plan

    light = tmp_path / "light.pl"
    rules = ("rule(d, defeasible, liquid_leaves_source).\nlearned(d).\n"
             "rule(l, defeasible, neg(liquid_leaves_source)).\nbody(l, light_liquid).\n"
             "learned(l).\n")
    light.write_text(rules)
    # a light liquid does not leave the source, and nothing makes it: the next query
    assert chosen_plan(loading.load([light]))[0] != ["light_liquid"]
    light.write_text(rules + "rule(t, defeasible, liquid_leaves_source).\n"
                             "body(t, light_liquid).\nbody(t, pour_upside_down).\nlearned(t).\n")
    # pouring it upside down does: that is the plan the demo asks for
    assert chosen_plan(loading.load([light])) == (["light_liquid"], ["liquid_leaves_source"], True)
    everything = tmp_path / "all.pl"
    everything.write_text("".join(f"rule(r{i}, defeasible, {e}).\nlearned(r{i}).\n"
                                  for i, e in enumerate(("liquid_leaves_source", "no_spill",
                                                         "liquid_enters_destination",
                                                         "liquid_remains_in_destination",
                                                         "destination_upright"))))
    given, goals, missed = chosen_plan(loading.load([everything]))
    assert (given, goals, missed) == (PLANS[-1][0], PLANS[-1][1].split(","), False)


def theory_version() -> str:
    from pantarhei.bridge.exploration.simulation import oracle_identity

    return oracle_identity("synthetic")[0]


def test_demo_refuses_bad_options_in_one_line(tmp_path):
    r = run_cli("demo", "--pours", "0", "--out", str(tmp_path / "t.pl"))
    assert "--pours" in assert_one_line_error(r)
    r = run_cli("demo", "--oracle", "synthetic", "--out", str(tmp_path))
    assert "a directory, not a file" in assert_one_line_error(r)
    r = run_cli("demo", "--oracle", "synthetic", "--out", str(tmp_path / "t.dfl"),
                "--store", str(tmp_path / "s.sqlite"))
    assert "--out and --out's DFL version are the same file" in assert_one_line_error(r)
    assert list(tmp_path.iterdir()) == []
