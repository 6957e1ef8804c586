"""oracle/base.py: the oracles named in ORACLES and built by `make_oracle`,
and what every oracle has by default."""
from __future__ import annotations

import pickle

import numpy as np
import pytest

from pantarhei.oracle.base import ORACLES, Oracle, Outcome, make_oracle


@pytest.mark.parametrize("name", sorted(ORACLES))
def test_every_named_oracle_is_built_under_its_name_and_picklable(name):
    o = make_oracle(name)
    assert isinstance(o, Oracle) and o.name == name
    again = pickle.loads(pickle.dumps(o))
    assert type(again) is type(o) and again.settings() == o.settings()


def test_options_reach_the_oracle_and_an_unknown_name_is_a_key_error():
    assert make_oracle("faulty", crash=[12, 3]).settings()["crash"] == [3, 12]
    with pytest.raises(KeyError):
        make_oracle("mujoco")


def test_an_oracle_must_score_and_has_no_settings_by_default():
    with pytest.raises(TypeError):
        Oracle()  # type: ignore[abstract]

    class Plain(Oracle):
        def score(self, p):
            return Outcome(np.zeros(9))

    assert Plain().settings() == {} and Plain().environment() == {}
    a, b = Plain().score(None), Plain().score(None)
    a.record["x"] = 1
    assert b.record == {}           # every outcome its own record


def test_the_option_table_offers_the_oracles_and_executors_there_are():
    """The names a command offers are the option table's (theory/defaults.pl);
    each is one this package builds: the oracles but the test-only faulty
    one, and every executor."""
    from pantarhei.bridge.commands.options import choices
    from pantarhei.oracle.executors import EXECUTORS

    assert set(choices("oracle")) == set(ORACLES) - {"faulty"}
    assert choices("executor") == tuple(EXECUTORS)
