"""The learners (bridge/learning/learners.py): every learner named in
LEARNERS has the one interface and gives general rules; which one learns
is the `learner` option of theory/defaults.pl, whose choices are LEARNERS'
names; the exploration and the evaluation learn through the registry, the
evaluation with the learner the theory records."""
from __future__ import annotations

import inspect
import re
from pathlib import Path
from types import MappingProxyType

import numpy as np
import pytest

from pantarhei.bridge.learning import learners
from pantarhei.bridge.learning.general_rules import General
from pantarhei.bridge.errors import UserError
from pantarhei.bridge.learning.learners import LEARNERS, default_learner, recorded_learner
from pantarhei.oracle.generative import sample
from pantarhei.theory.lexicon import load_vocabulary
from pantarhei.theory.option_table import option

NAMES = load_vocabulary().expectation_names
SPILL = NAMES.index("no_spill")
POUR_X = load_vocabulary().parameter_names.index("pour_x")
BODIES = [("pour_to_side",), ("pour_low",)]


def pours() -> tuple[np.ndarray, np.ndarray]:
    """12 pours of each body and of an ordinary pour: no_spill fails 100 mm
    or more from the destination's axis, everything else holds; one pour's
    simulation failed."""
    P = np.vstack([sample(list(b), 12, i) for i, b in enumerate([(), *BODIES])])
    S = np.full((len(P), 9), 0.9)
    S[:, SPILL] = np.where(P[:, POUR_X] >= 100, 0.1, 0.9)
    S[0] = np.nan
    return P, S


def rules_of(g: General) -> list[tuple]:
    return [(r.id, r.body, r.head, r.support, r.kept, r.confidence, r.level) for r in g.rules]


@pytest.mark.parametrize("name", sorted(LEARNERS))
def test_every_learner_takes_pours_and_gives_general_rules(name):
    learn = LEARNERS[name]
    assert learners.learner(name) is learn
    assert list(inspect.signature(learn).parameters) == ["P", "S", "seed", "bodies"]
    P, S = pours()
    g = learn(P, S, 3, BODIES)
    assert isinstance(g, General)
    for e in NAMES:
        rules = g.of(e)
        assert [r.id for r in rules if not r.body] == [f"g0_{e}"]
        assert all(re.fullmatch(rf"g\d+_{e}", r.id) for r in rules)
        assert len({r.id for r in rules}) == len(rules)
    assert {tuple(sorted(r.body)) for r in g.rules} <= {(), *BODIES}
    assert all(0 <= r.kept <= r.support <= len(P) - 1 and 0 <= r.confidence <= 1 for r in g.rules)
    assert rules_of(learn(P, S, 3, BODIES)) == rules_of(g)       # the same pours and seed


def test_an_unknown_learner_is_named_with_the_known_ones():
    with pytest.raises(ValueError, match=f"unknown learner 'nope'.*{default_learner()}"):
        learners.learner("nope")


def test_the_learner_is_an_option_of_the_table_whose_choices_are_the_learners():
    row = option("learner")
    assert row.type == "choice" and not row.prolog_only and not row.curiosities
    assert set(row.choices) == set(LEARNERS)
    assert row.default == default_learner() and learners.learner() is LEARNERS[row.default]


def test_a_theory_s_learner_is_its_setting_else_the_default():
    assert recorded_learner({"learner": ["toy"], "seed": [1]}) == "toy"
    assert recorded_learner({"seed": [1]}) == default_learner()
    assert recorded_learner({"learner": []}) == default_learner()


def test_a_theory_naming_a_learner_unknown_here_is_refused_in_one_line(tmp_path):
    from pantarhei.bridge.evaluation.explored_pours import read_learned

    theory = tmp_path / "t.pl"
    theory.write_text("setting(seed, 1).\nsetting(batch, 2).\nsetting(learner, nope).\n",
                      encoding="utf-8")
    with pytest.raises(UserError, match=r"t\.pl: setting\(learner, _\): unknown learner 'nope'"):
        read_learned(theory)


def test_the_evaluation_learns_again_with_the_learner_the_theory_names(monkeypatch):
    from pantarhei.bridge.evaluation.explored_pours import Learned
    from pantarhei.bridge.evaluation.pipeline import _differing_layer
    from pantarhei.bridge.theories.model import Theory

    default = LEARNERS[default_learner()]
    used: list[str] = []

    def named(name):
        def learn(P, S, seed, bodies):
            used.append(name)
            return default(P, S, seed, bodies)
        return learn

    monkeypatch.setattr(learners, "LEARNERS", MappingProxyType(
        {name: named(name) for name in [*LEARNERS, "toy"]}))
    P, S = pours()
    for settings, want in (({"seed": [3], "learner": ["toy"]}, "toy"),
                           ({"seed": [3]}, default_learner())):
        learned = Learned(Path("t.pl"), Theory(), settings, list(BODIES), [], [])
        assert learned.learner == want
        _differing_layer(learned, P, S)
        assert used.pop() == want and not used


def test_the_exploration_and_the_evaluation_learn_through_the_registry_s_default(monkeypatch):
    from pantarhei.bridge.evaluation.general_answers import general_theories
    from pantarhei.bridge.evaluation.explored_pours import Learned
    from pantarhei.bridge.evaluation.pipeline import Evaluation, Pours, _differing_layer
    from pantarhei.bridge.evaluation.rule_building import theory_of
    from pantarhei.bridge.exploration.session import Host, Session
    from pantarhei.bridge.theories.model import Theory

    default = LEARNERS[default_learner()]
    calls: list[set[str]] = []        # per call, the files of its callers

    def recording(P, S, seed, bodies):
        calls.append({Path(f.filename).name for f in inspect.stack()})
        return default(P, S, seed, bodies)

    monkeypatch.setattr(learners, "LEARNERS",
                        MappingProxyType({**LEARNERS, default_learner(): recording}))
    P, S = pours()
    ok = np.all(np.isfinite(S), axis=1)
    alone = default(P[ok], S[ok], 3, BODIES)

    # the exploration: the general layer explore/1 asks for
    host = Host()
    host.session = Session(run="", store=None, simulator=None, oracle_version="",
                           params=P, scores=S)
    layer = host.general({"rules": [], "seed": 3, "learner": default_learner(), "explored": [
        {"id": f"a{i + 1}", "antecedent": list(b)} for i, b in enumerate(BODIES)]})
    assert [(r["id"], r["confidence_permille"]) for r in layer["rules"]] == \
        [(r.id, int(round(1000 * r.confidence))) for r in alone.rules]

    # the evaluation: the learning curiosity's layer learned again, and the
    # general theory of curiosity's pours
    learned = Learned(Path("t.pl"), Theory(), {"seed": [3]}, list(BODIES), [], [])
    assert _differing_layer(learned, P, S)        # an empty theory: every rule differs
    ev = Evaluation("t", "synthetic", {}, len(P))
    general_theories(ev, theory_of([], np.ones((0, 9), dtype=bool), "shipped"),
                     {"curiosity": Pours(list(BODIES), P[ok], S[ok])},
                     {"uniform": ([("pour_low",)], np.ones((1, 9), dtype=bool))},
                     lambda label, X: np.full((len(X), 9), 0.9), seed=3, explored_seed=4)
    assert ev.general["curiosity"]["rules"]
    assert [c & {"session.py", "pipeline.py", "general_answers.py"} for c in calls] == \
        [{"session.py"}, {"pipeline.py"}, {"general_answers.py"}]
