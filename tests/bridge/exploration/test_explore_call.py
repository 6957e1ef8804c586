"""explore() of bridge/exploration/explore_call.py: whole explorations on the
synthetic oracle with the paper's curiosity:
the theory, the trace, the plot, the known directions, and the same result
for the same seed. (The discovering curiosity: test_explore_discover.py.)"""
from __future__ import annotations

import json
from collections import defaultdict
from pathlib import Path

import clingo
import numpy as np
import pytest

from pantarhei.bridge.exploration import explore_call as exploration, session
from pantarhei.bridge.errors import UserError
from pantarhei.bridge.exploration.explore_call import ExploreOptions
from pantarhei.bridge.engines.swipl import engine
from pantarhei.bridge.reasoning.valid_scenes import violations
from pantarhei.oracle.synthetic import DEPENDS
from pantarhei.theory.lexicon import load_vocabulary
from pantarhei.theory import read_facts

V = load_vocabulary()


def run(tmp: Path, name: str = "t", **kw) -> dict:
    opts = dict(curiosity="paper", oracle="synthetic", budget=8, out=tmp / f"{name}.pl",
                store=tmp / "store.sqlite", progress=False, executor="inline",
                general=False)          # Algorithm 1's rules alone
    opts.update(kw)
    return exploration.explore(ExploreOptions(**opts))


def test_the_general_layer_follows_algorithm_1s_rules(tmp_path):
    from pantarhei.bridge.theories.loading import load

    alone = Path(run(tmp_path, "alone")["out"]).read_text()
    both = Path(run(tmp_path, "both", general=True)["out"]).read_text()
    # the same exploration, its general layer written after Algorithm 1's rules (unchanged)
    assert both.startswith(alone.rstrip("\n"))
    theory = load([tmp_path / "both.pl"])
    general = [r for r in theory.rules if r.id.startswith("g")]
    assert sorted(r.id for r in general if not r.body) == sorted(f"g0_{e}" for e in V.expectation_names)
    assert {r.id for r in general} <= theory.learned


@pytest.fixture(scope="module")
def explored(tmp_path_factory):
    tmp = tmp_path_factory.mktemp("explore")
    result = run(tmp)
    return tmp, result


def test_writes_a_theory_both_engines_load(explored):
    tmp, result = explored
    out = Path(result["out"])
    assert out == tmp / "t.pl" and out.is_file()
    facts = read_facts([out])                        # clingo's parser
    ctl = clingo.Control()
    ctl.load(str(out))
    ctl.ground([("base", [])])
    assert any(True for _ in ctl.symbolic_atoms.by_signature("rule", 3))
    eng = engine()
    eng.once(f"theory_files:load_facts('{out}', explore_test_theory)")
    n = int(eng.once("aggregate_all(count, explore_test_theory:rule(_, _, _), N)")["N"])
    assert n == len(facts["rule"]) == 9 * result["explored"]


def test_one_rule_per_outcome_literal_with_provenance(explored):
    tmp, result = explored
    f = read_facts([Path(result["out"])])
    settings = defaultdict(list)
    for k, v in f["setting"]:
        settings[k].append(v)
    assert settings["oracle"] == ["synthetic"] and settings["seed"] == [1]
    assert settings["batch"] == [31] and settings["explored"] == [result["explored"]]
    assert settings["simulations"] == [31 * result["explored"]]
    assert sorted(settings["initial"]) == ["pour_mid_height", "pour_near_rim", "pour_steeply_tilted"]
    bodies = defaultdict(set)
    for rid, prop in f["body"]:
        bodies[rid].add(prop)
    prov = defaultdict(dict)
    for rid, key, value in f["provenance"]:
        prov[rid][key] = value
    by_antecedent = defaultdict(list)
    for rid, kind, head in f["rule"]:
        assert kind == "defeasible" and rid in {l[0] for l in f["learned"]}
        name = head[1] if isinstance(head, tuple) else head
        assert name in V.expectation_names
        if isinstance(head, tuple):
            assert head[0] == "neg"
        p = prov[rid]
        assert {"antecedent", "parent", "simulations", "weight_mass_permille",
                "confidence_permille"} <= set(p)
        assert 500 <= p["confidence_permille"] <= 1000
        by_antecedent[p["antecedent"]].append((name, bodies[rid]))
    assert len(by_antecedent) == result["explored"]
    for rules in by_antecedent.values():
        assert sorted(n for n, _ in rules) == sorted(V.expectation_names)
        assert len({frozenset(b) for _, b in rules}) == 1
        assert not violations(sorted(rules[0][1]))


def test_trace_and_plot(explored):
    tmp, result = explored
    lines = [json.loads(l) for l in (tmp / "t.trace.jsonl").read_text().splitlines()]
    assert [t["iteration"] for t in lines] == list(range(1, result["explored"] + 1))
    assert lines[0]["antecedent"] == ["pour_mid_height", "pour_near_rim", "pour_steeply_tilted"]
    size = 1
    for t in lines:
        size += len(t["added"]) - 1
        assert t["a_new"] == size
        assert t["best"]["expectation"] in V.expectation_names and t["best"]["slope"] > 0
    png = (tmp / "t.trace.png").read_bytes()
    assert png[:8] == b"\x89PNG\r\n\x1a\n"


def test_every_explored_antecedent_is_new(explored):
    tmp, result = explored
    lines = [json.loads(l) for l in (tmp / "t.trace.jsonl").read_text().splitlines()]
    explored_sets = [tuple(t["antecedent"]) for t in lines]
    assert len(set(explored_sets)) == len(explored_sets)
    for t in lines:
        for a in t["added"]:
            assert not violations(a)


def test_exploration_moves_along_the_known_directions(explored):
    """The steepest direction found from a_0 is one the synthetic oracle is
    known to have, and the antecedents it adds move that parameter that way."""
    tmp, result = explored
    first = json.loads((tmp / "t.trace.jsonl").read_text().splitlines()[0])
    best = first["best"]
    top = best["direction"][0]
    assert top["parameter"] in DEPENDS[best["expectation"]]
    # the direction heads towards the other verdict: against the gradient
    # where the expectation mostly holds
    sign = DEPENDS[best["expectation"]][top["parameter"]]
    assert np.sign(top["component"]) == (-sign if best["mean"] > 0.5 else sign)
    eng = engine()
    moved = 0
    for a in first["added"]:
        changed = set(a) ^ set(first["antecedent"])
        params = {V.propositions[p].model.param for p in changed}
        if top["parameter"] in params:
            moved += 1
            m0 = float(eng.once(f"curiosity:parameter_mean({first['antecedent']}, {top['parameter']}, M)"
                                .replace("'", ""))["M"])
            m1 = float(eng.once(f"curiosity:parameter_mean({a}, {top['parameter']}, M)"
                                .replace("'", ""))["M"])
            assert (m1 - m0) * top["component"] > 0
    assert moved >= 1


def test_same_seed_same_theory_and_other_seed_runs(tmp_path, explored):
    tmp, result = explored
    again = run(tmp_path)
    assert Path(again["out"]).read_text() == Path(result["out"]).read_text()
    other = run(tmp_path, name="o", seed=2, qualify="argmax", budget=3)
    text = Path(other["out"]).read_text()
    assert "setting(seed, 2)." in text and "setting(qualify, argmax)." in text


def test_stops_when_a_new_is_empty(tmp_path):
    # a slope setting no plane reaches: only a_0 is explored
    r = run(tmp_path, slope=1e9)
    assert r["explored"] == 1 and r["stopped"] == "a_new_empty"
    assert "setting(stopped, a_new_empty)." in Path(r["out"]).read_text()


def test_bad_options_are_user_errors(tmp_path):
    with pytest.raises(UserError, match="not a known proposition"):
        run(tmp_path, initial=["pour_sideways"])
    with pytest.raises(UserError, match="invalid"):
        run(tmp_path, initial=["pour_low", "pour_high"])
    assert not (tmp_path / "t.pl").exists()


def test_failed_simulations_are_left_out_and_counted(tmp_path):
    """With an oracle whose simulations really crash (a segfault in the
    worker) for some particle counts, the exploration goes on, leaves the
    failed ones out of weights and fits, and says how many failed."""
    crash = list(range(40, 57))            # about a sixth of the prior's counts (40 to 140)
    r = exploration.explore(ExploreOptions(
        curiosity="discover", oracle="faulty", oracle_options={"crash": crash}, budget=2,
        batch=16, probe=0,
        out=tmp_path / "f.pl", store=tmp_path / "f.sqlite", progress=False,
        executor="local", workers=2, initial=["pour_low"], general=False))
    assert r["explored"] == 2 and 0 < r["failed"] < r["simulations"]
    f = read_facts([Path(r["out"])])
    settings = dict(f["setting"])
    assert settings["failed_simulations"] == r["failed"]
    used = {v for rid, k, v in f["provenance"] if k == "simulations"}
    assert max(used) <= r["simulations"] - r["failed"]


def test_why_it_stopped_is_said_in_the_budget_s_unit():
    assert exploration.stop_text({"stopped": "budget", "budget": {"total": 25, "unit": "rule"}}) \
        == "25 rules"
    assert exploration.stop_text({"stopped": "budget", "budget": {"total": 775, "unit": "pour"}}) \
        == "775 pours"
    assert exploration.stop_text({"stopped": "a_new_empty"}) == "A_new is empty"


def test_the_result_carries_the_budget_as_explore_1_counts_it(tmp_path):
    r = run(tmp_path, budget=2, batch=8)
    assert r["budget"] == {"total": 2, "unit": "rule"}
