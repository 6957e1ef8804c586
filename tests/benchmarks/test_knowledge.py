"""benchmarks/knowledge.py on the synthetic oracle: every method's pours
counted up to the budget, the curiosity's theory at a budget learned over
what it had explored by then, the table and the plot written."""
from __future__ import annotations

import numpy as np

from benchmarks import knowledge, knowledge_methods


def test_the_designed_experiment_asks_each_proposition_in_turn(tmp_path):
    from pantarhei.theory.lexicon import load_vocabulary

    sim = lambda P: np.zeros((len(P), 9))  # noqa: E731  (the pours only are looked at)
    chosen = knowledge.designed(101, 100, sim)
    assert len(chosen.P) == 100
    n = len(load_vocabulary().propositions) + 1
    assert chosen.bodies(100)[0] == () and len(chosen.bodies(100)) == min(100, n)
    rnd = knowledge.random_bodies(101, 30, sim)
    assert len(rnd.P) == 30 and rnd.bodies(30)[0] == () and len(rnd.bodies(30)) == 30 // knowledge_methods._batch()


def test_random_exploration_pours_uniformly_random_valid_antecedents():
    """Random valid antecedents: a batch each, every pour drawn for its
    antecedent, the antecedents valid and of many propositions, the same
    seed the same pours."""
    from pantarhei.bridge.reasoning.valid_scenes import violations
    from pantarhei.oracle.generative import in_support

    sim = lambda P: np.zeros((len(P), 9))  # noqa: E731  (the pours only are looked at)
    batch = knowledge_methods._batch()
    chosen = knowledge.random_valid(101, 10 * batch, sim)
    bodies = chosen.bodies(10 * batch)
    assert len(chosen.P) == 10 * batch and len(bodies) == 10
    assert all(not violations(b) for b in bodies) and min(map(len, bodies)) > 2
    for i, b in enumerate(bodies):
        assert in_support(chosen.P[i * batch:(i + 1) * batch], b).all()
    assert np.array_equal(knowledge.random_valid(101, 10 * batch, sim).P, chosen.P)


def test_curves_table_and_plot(tmp_path):
    knowledge.main(["--oracle", "synthetic", "--seeds", "101", "--budgets", "24,48",
                    "--methods", "curiosity,designed", "--store", str(tmp_path / "s.sqlite"),
                    "--report", str(tmp_path)])
    text = (tmp_path / "knowledge-synthetic.md").read_text()
    rows = [ln for ln in text.splitlines() if ln.startswith("| curiosity") or
            ln.startswith("| designed")]
    assert [r.split(" | ")[:2] for r in rows] == [["| curiosity", "24"], ["| designed", "24"],
                                                  ["| curiosity", "48"], ["| designed", "48"]]
    assert (tmp_path / "knowledge-synthetic.png").stat().st_size > 1000
    import json
    rows = json.loads((tmp_path / "knowledge-synthetic.json").read_text())
    for r in rows:       # each theory on every question set, over its bodies and every askable one
        for tag in ("", "askable_"):
            for prefix in ("", "interaction_", "random_"):
                assert 0 <= r[f"{tag}{prefix}accuracy"] <= 1
                assert r[f"{tag}{prefix}confident_errors"] >= 0
            assert r[f"{tag}theory_behaviours"] <= r["behaviours"] + 40
        for prefix in ("", "interaction_", "random_"):     # boosting of the same pours beside it
            assert 0 <= r[f"boosting_{prefix}calibration"] <= 1
            assert 0 <= r[f"boosting_{prefix}accuracy"] <= 1


def test_the_targets_are_each_met_or_not_by_the_median_of_the_seeds():
    def rows(method, pours, **measures):
        return [{"method": method, "seed": seed, "pours": pours,
                 **{k: v[i] for k, v in measures.items()}} for i, seed in enumerate((1, 2, 3))]
    full = rows("curiosity", 775, contrast_accuracy=[0.97, 0.98, 0.90], calibration=[0.04] * 3,
                boosting_calibration=[0.02, 0.05, 0.025], behaviours=[40, 41, 42],
                theory_behaviours=[4, 5, 6], interaction_confident_errors=[0, 2, 0],
                askable_contrast_accuracy=[0.9] * 3)
    others = (rows("random_valid", 775, behaviours=[44, 45, 46], theory_behaviours=[3, 4, 5])
              + rows("uncertainty", 775, askable_contrast_accuracy=[0.8, 0.95, 0.95]))
    lines = knowledge.targets(full + others, knowledge.summary)
    said = {ln.split(" | ")[0].lstrip("| "): ln.rsplit(" | ", 1)[1].rstrip(" |") for ln in lines
            if ln.startswith("| ") and not ln.startswith("| target")}
    assert said["behaviours seen"] == "**no**"                  # 41 against random's 45
    assert said["behaviours in the theory"] == "yes"            # 5 against 4
    assert said["interactions: confident errors"] == "yes"      # the median seed has none
    assert said["questions: contrast accuracy"] == "yes"        # median 0.97
    assert said["questions: calibration beside boosting on the same pours (the theory's less "
                "boosting's, per seed)"] == "**no**"            # +0.015 at the median seed
    assert said["knowledge per pour at 775 pours, every askable body: questions' contrast "
                "accuracy"] == "**no**"                         # 0.90 against 0.95
    assert said["knowledge per pour at 200 pours, every askable body: questions' contrast "
                "accuracy"] == "not measured"
    assert said["interactions: calibration"] == "not measured"
    assert knowledge.targets(rows("curiosity", 400, contrast_accuracy=[1, 1, 1]),
                             knowledge.summary) == []


def test_the_curiositys_theory_at_a_budget_has_what_it_explored_by_then(tmp_path):
    from pantarhei.bridge.exploration.simulation import open_simulator

    sim = open_simulator("synthetic", "inline", None, tmp_path / "s.sqlite")
    try:
        run = lambda P: np.asarray(sim.simulate(P, progress=False), dtype=float)  # noqa: E731
        chosen = knowledge.curiosity(101, 40, "synthetic", tmp_path / "s.sqlite", run)
    finally:
        sim.close()
    assert len(chosen.P) == 40
    assert chosen.bodies(4) == [()]
    assert set(chosen.bodies(20)) <= set(chosen.bodies(40)) and len(chosen.bodies(40)) > 1


def test_the_curiositys_wholes_are_no_bodies_of_its_theory(tmp_path):
    """With whole steps, the bodies are the antecedents a question says
    (at most `body` propositions), as the theory explore writes has them."""
    from pantarhei.bridge.exploration.simulation import open_simulator

    sim = open_simulator("synthetic", "inline", None, tmp_path / "s.sqlite")
    try:
        run = lambda P: np.asarray(sim.simulate(P, progress=False), dtype=float)  # noqa: E731
        chosen = knowledge.curiosity(101, 40, "synthetic", tmp_path / "s.sqlite", run,
                                     {"whole_every": 2})
    finally:
        sim.close()
    assert len(chosen.bodies(40)) > 1 and all(len(b) <= 2 for b in chosen.bodies(40))


def test_rows_measured_are_kept_and_not_measured_again(tmp_path, monkeypatch):
    import json

    args = ["--oracle", "synthetic", "--seeds", "101", "--budgets", "24", "--methods",
            "designed", "--store", str(tmp_path / "s.sqlite"), "--report", str(tmp_path)]
    knowledge.main(args)
    data = tmp_path / "knowledge-synthetic.json"
    rows = json.loads(data.read_text())
    assert [(r["method"], r["seed"], r["pours"]) for r in rows] == [("designed", 101, 24)]
    rows[0]["contrast_accuracy"] = 0.123            # a row measured before is kept as it is
    data.write_text(json.dumps(rows))
    asked = []
    real = knowledge.designed
    monkeypatch.setattr(knowledge, "designed", lambda *a: asked.append(a) or real(*a))
    knowledge.main(args[:5] + ["24,48"] + args[6:])
    assert [a[:2] for a in asked] == [(101, 48)]     # only the budget it lacked
    rows = json.loads(data.read_text())
    assert [(r["pours"], r["contrast_accuracy"] == 0.123) for r in rows] == [(24, True),
                                                                             (48, False)]
    assert "| designed | 24 | 0.123" in (tmp_path / "knowledge-synthetic.md").read_text()
    data.write_text("{not json")
    try:
        knowledge.main(args)
    except SystemExit as e:
        assert "knowledge-synthetic.json" in str(e) and "move it aside" in str(e)
    else:
        raise AssertionError("a damaged rows file was read")
    data.write_text(json.dumps([{**rows[0], "method": "random", "contrast_accuracy": 0.5},
                                {**rows[0], "contrast_accuracy": 0.123}]))
    knowledge.main(args + ["--fresh"])      # this run's row again; another method's kept
    again = json.loads(data.read_text())
    assert [(r["method"], r["pours"]) for r in again] == [("random", 24), ("designed", 24)]
    assert again[0]["contrast_accuracy"] == 0.5 and again[1]["contrast_accuracy"] != 0.123
