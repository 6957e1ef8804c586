"""The session behind the exploration's foreign predicates
(bridge/exploration/session.py), called from the real SWI-Prolog: an error
in Python is one line in Prolog and is kept to be raised again as it was.
The session's pours (bridge/exploration/session_state.py): the log
densities grow with the pours and equal those computed at once, and an
antecedent's planes and tests are fitted again only when its weights
change."""
from __future__ import annotations

import numpy as np
import pytest

from pantarhei.bridge.errors import UserError
from pantarhei.bridge.exploration.session import install
from pantarhei.bridge.exploration.session_state import Session
from pantarhei.oracle.generative import log_density, normalise, sample


@pytest.fixture(scope="module")
def eng():
    return install()


def test_without_a_session_prolog_gets_one_line_and_python_the_error(eng):
    host = eng.exploration_host
    host.take_error()
    r = eng.once("catch(curiosity_foreign:call_bridge(exploration_simulate, "
                 "_{antecedent: [pour_low], iteration: 1}, _), exploration_error(M), true), "
                 "string(M)")
    assert r["M"] in (b"no exploration is running", "no exploration is running")
    e = host.take_error()
    assert isinstance(e, UserError) and str(e) == "no exploration is running"
    assert host.take_error() is None


def test_the_prompt_oracle_answers_through_the_same_door(eng):
    r = eng.once("curiosity_foreign:call_bridge(oracle_sample, "
                 "_{antecedent: [pour_low], n: 2, seed: 1}, R), "
                 "get_dict(rows, R, Rows), length(Rows, N), Rows = [Row|_], length(Row, K)")
    assert (r["N"], r["K"]) == (2, 30)
    bad = eng.once("catch(curiosity_foreign:call_bridge(oracle_sample, "
                   "_{antecedent: [pour_sideways], n: 1, seed: 1}, _), exploration_error(M), true)")
    assert "pour_sideways" in str(bad["M"])
    assert eng.exploration_host.take_error() is not None


def session(P: np.ndarray) -> Session:
    rng = np.random.default_rng(0)
    return Session(run="", store=None, simulator=None, oracle_version="", params=P,
                   scores=rng.random((len(P), 9)))


def test_log_densities_grow_with_the_pours():
    P = np.vstack([sample(["pour_low"], 20, seed=1), sample([], 20, seed=2)])
    s = session(P[:20])
    s.log_density_of("a1", ["pour_low"])
    s.params = P
    assert np.array_equal(s.log_density_of("a1", ["pour_low"]), log_density(P, ["pour_low"]))


def test_planes_are_fitted_again_only_when_the_weights_change():
    P = sample([], 40, seed=3)
    s = session(P)
    X, w = normalise(P), np.ones(40)
    first = s.planes_of("a1", X, s.scores, w, 1.0)
    assert s.planes_of("a1", X, s.scores, w.copy(), 1.0) is first
    more = np.concatenate([w, np.zeros(5)])            # new pours outside its support
    X5 = np.vstack([X, X[:5]])
    S5 = np.vstack([s.scores, s.scores[:5]])
    assert s.planes_of("a1", X5, S5, more, 1.0) is first
    assert s.planes_of("a1", X, s.scores, w, 0.0) is not first     # fitted on other settings
    w2 = w.copy()
    w2[0] = 0.5
    assert s.planes_of("a1", X, s.scores, w2, 1.0) is not first
    tested = s.tested_of(1, "a1", X, s.scores, w2, 1.0, 19, 1)
    assert s.tested_of(1, "a1", X, s.scores, w2, 1.0, 19, 1) is tested
    assert s.tested_of(1, "a1", X, s.scores, w2, 1.0, 19, 2) is not tested
    assert s.tested_of(1, "a1", X, s.scores, w, 1.0, 19, 2) is not tested


def test_failed_pours_take_no_part_in_the_weights_or_the_verdicts():
    P = np.vstack([sample(["pour_low"], 10, seed=4), sample(["pour_to_side"], 10, seed=5)])
    s = session(P)
    s.scores[3] = np.nan
    entries = [{"id": "a1", "antecedent": ["pour_low"]}, {"id": "a2", "antecedent": ["pour_to_side"]}]
    W = s.weight_matrix(entries)
    assert W.shape == (2, 19) and np.allclose(W.sum(axis=0), 1.0)
    verdicts = s.verdicts(entries, "weighted")
    assert len(verdicts) == 2 and all(len(v) == 9 for v in verdicts)


class Synthetic:
    """The synthetic oracle's scores, as a simulator gives them."""

    def simulate(self, P: np.ndarray, progress: bool = False) -> np.ndarray:
        from pantarhei.oracle.synthetic import scores
        from pantarhei.theory.lexicon import load_vocabulary

        names = load_vocabulary().parameter_names
        return np.array([scores(dict(zip(names, p))) for p in P])


def test_the_pours_come_from_the_requests_and_the_store_holds_each_step_s(tmp_path):
    """The session keeps no setting nor a count of Prolog's: the batch, the
    seed and the pours a probe added come with each request; a checkpoint
    saves Prolog's state and trace line, no copy of the pours."""
    from pantarhei.bridge.exploration.checkpoints import ExplorationStore
    from pantarhei.bridge.exploration.session import Host
    from pantarhei.bridge.exploration.simulation import batch_seed

    store = ExplorationStore(tmp_path / "s.sqlite")
    store.start("r", {})
    host = Host()
    host.session = Session(run="r", store=store, simulator=Synthetic(), oracle_version="",
                           params=np.empty((0, 30)), scores=np.empty((0, 9)))
    step = {"antecedent": ["pour_low"], "iteration": 1, "attempt": 0, "batch": 10, "seed": 7}
    probed = host.handlers["exploration_probe"]({**step, "probe": 3, "qualify": "weighted",
                                                "antecedents": [{"id": "a1", "antecedent": ["pour_low"]}]})
    assert probed["simulations"] == 3
    assert host.simulate({**step, "probed": 3})["simulations"] == 10    # 7 more, not 10
    assert np.array_equal(host.session.params, sample(["pour_low"], 10, batch_seed(7, 1, 0)))
    checkpoint = {"state": "s", "trace": {"draws": []}, "out": str(tmp_path / "t.pl")}
    host.checkpoint({**checkpoint, "iteration": 1})
    host.simulate({**step, "iteration": 2, "batch": 4})
    host.checkpoint({**checkpoint, "iteration": 2, "state": "s2"})
    saved = store.latest("r")
    assert (saved.iteration, saved.state, saved.trace) == (2, "s2", [{"draws": []}] * 2)
    assert len(host.session.params) == 14
    store.close()
