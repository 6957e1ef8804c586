"""oracle/synthetic.py: the synthetic oracle, analytic scores with known
directions and outcomes."""
from __future__ import annotations

import pickle

import numpy as np
import pytest

from pantarhei.oracle.base import make_oracle
from pantarhei.oracle.generative import sample
from pantarhei.oracle.synthetic import DEPENDS, SyntheticOracle, ramp, scores
from pantarhei.theory.lexicon import load_vocabulary

V = load_vocabulary()
NAMES = V.parameter_names
EXPECTATIONS = V.expectation_names


def as_dict(p):
    return dict(zip(NAMES, (float(x) for x in p)))


def test_registered_deterministic_and_picklable():
    o = make_oracle("synthetic")
    assert isinstance(o, SyntheticOracle) and o.name == "synthetic"
    P = sample([], 20, seed=3)
    first = np.array([o.score(p).scores for p in P])
    again = np.array([pickle.loads(pickle.dumps(o)).score(p).scores for p in P])
    assert np.array_equal(first, again)
    assert first.shape == (20, 9)
    assert np.all((first >= 0) & (first <= 1))


def test_ramp():
    assert ramp(0, 0, 10) == 0 and ramp(5, 0, 10) == 0.5 and ramp(20, 0, 10) == 1
    assert ramp(5, 10, 0) == 0.5 and ramp(-3, 10, 0) == 1


def test_every_expectation_has_known_dependencies():
    assert set(DEPENDS) == set(EXPECTATIONS)
    assert all(set(d) <= set(NAMES) for d in DEPENDS.values())


def test_scores_depend_only_on_the_known_parameters_in_the_known_direction():
    """Nudging a parameter never changes a score that does not depend on it,
    and moves a score that does only in its known direction."""
    P = sample([], 200, seed=1)
    for p in P:
        base = scores(as_dict(p))
        for i, name in enumerate(NAMES):
            par = V.parameters[i]
            q = p.copy()
            q[i] = min(par.high, p[i] + 0.02 * (par.high - par.low))
            diff = scores(as_dict(q)) - base
            for k, e in enumerate(EXPECTATIONS):
                if name not in DEPENDS[e]:
                    assert diff[k] == 0, (e, name)
                else:
                    assert diff[k] * DEPENDS[e][name] >= -1e-12, (e, name)


def test_known_outcomes_of_the_papers_rules():
    # pouring from the side spills
    side = sample(["pour_to_side", "pour_steeply_tilted", "pour_low"], 50, seed=2)
    assert all(scores(as_dict(p))[EXPECTATIONS.index("no_spill")] < 0.5 for p in side)
    # a liquid lighter than 600 mg does not all leave the source
    light = sample(["light_liquid", "pour_steeply_tilted"], 200, seed=3)
    leaves = np.array([scores(as_dict(p))[EXPECTATIONS.index("liquid_leaves_source")]
                       for p in light])
    mass = light[:, NAMES.index("particle_mass")]
    assert np.all(leaves[mass < 600] < 0.5)
    # tilting the source upright keeps the liquid in it
    upright = sample(["pour_upright"], 50, seed=4)
    assert all(scores(as_dict(p))[EXPECTATIONS.index("liquid_leaves_source")] == 0 for p in upright)


def test_delay_slows_but_does_not_change_scores(monkeypatch):
    o = SyntheticOracle()
    p = sample([], 1, seed=5)[0]
    plain = o.score(p).scores
    monkeypatch.setenv("PANTARHEI_SYNTHETIC_DELAY", "0.001")
    assert np.array_equal(o.score(p).scores, plain)


@pytest.mark.parametrize("e", EXPECTATIONS)
def test_each_score_takes_both_verdicts_somewhere(e):
    """Somewhere in the scene space, not in the ordinary pour alone (which
    keeps the destination still): a few pours for every proposition."""
    P = np.vstack([sample([p], 5, seed=6) for p in V.propositions])
    s = np.array([scores(as_dict(p))[EXPECTATIONS.index(e)] for p in P])
    assert (s > 0.5).any() and (s <= 0.5).any()
