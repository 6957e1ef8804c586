"""`pantarhei demo`, the main job, on the synthetic oracle (the same code
path as `make demo`, which uses PyBullet)."""
from __future__ import annotations

import re

from pantarhei.bridge.theories import loading
from tests.conftest import assert_one_line_error, run_cli


def test_demo_learns_writes_asks_and_plans(tmp_path):
    out = tmp_path / "learned" / "pouring.pl"           # the directory is made
    args = ["demo", "--oracle", "synthetic", "--budget", "5", "--out", str(out),
            "--store", str(tmp_path / "s.sqlite"), "--verify", "3", "--no-progress"]
    r = run_cli(*args)
    assert r.code == 0, r.err
    theory = loading.load([out])
    settings = loading.settings(theory)
    explored, simulations = settings["explored"][0], settings["simulations"][0]
    assert 31 * explored <= simulations <= 155      # the pours of 5 batches, probes included
    assert f"explored {explored} antecedents with {simulations} simulations" in r.out
    # Algorithm 1's rules (9 per explored antecedent) and the general rules
    assert 1 <= explored <= 5
    assert len([x for x in theory.rules if x.id.startswith("r")]) == 9 * explored
    general = [x for x in theory.rules if x.id.startswith("g")]
    assert sum(not x.body for x in general) == 9                 # a default per expectation
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
    # asked as given, each question is decided, with its likelihood: by the
    # general rules where no explored antecedent speaks of it
    assert all(word != "?" and share for word, share in marks) and "assumed" not in r.out
    assert re.search(r"verified: goals met in \d of 3 simulations", r.out) or "no plan:" in r.out
    # a second run reads every simulation from the store and writes the same theory
    first = out.read_text()
    again = run_cli(*args)
    assert again.code == 0, again.err
    assert out.read_text() == first


def theory_version() -> str:
    from pantarhei.bridge.exploration.simulation import oracle_identity

    return oracle_identity("synthetic")[0]


def test_demo_refuses_bad_options_in_one_line(tmp_path):
    r = run_cli("demo", "--budget", "0", "--out", str(tmp_path / "t.pl"))
    assert "--budget" in assert_one_line_error(r)
    r = run_cli("demo", "--oracle", "synthetic", "--out", str(tmp_path))
    assert "a directory, not a file" in assert_one_line_error(r)
    r = run_cli("demo", "--oracle", "synthetic", "--out", str(tmp_path / "t.dfl"),
                "--store", str(tmp_path / "s.sqlite"))
    assert "--out and --out's DFL version are the same file" in assert_one_line_error(r)
    assert list(tmp_path.iterdir()) == []
