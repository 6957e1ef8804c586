"""oracle/result_keys.py: the key of a stored result, from the canonical
parameterization and the oracle's name, version and settings."""
from __future__ import annotations

import numpy as np

from pantarhei.oracle.base import Oracle, Outcome
from pantarhei.oracle.result_keys import DECIMALS, canonical, key, oracle_tag


class Tagged(Oracle):
    name = "tagged"

    def __init__(self, version="1", **settings):
        self.version = version
        self._settings = settings

    def settings(self):
        return self._settings

    def score(self, p):
        return Outcome(np.zeros(9))


def test_values_closer_than_the_kept_decimals_share_a_key():
    p = np.linspace(-250, 250, 30)
    tag = oracle_tag(Tagged())
    assert key(p, tag) == key(p + 10.0 ** -(DECIMALS + 2), tag)
    assert key(p, tag) != key(p + 10.0 ** -(DECIMALS - 1), tag)
    assert canonical([1.23456789, 2]) == [1.234568, 2.0]


def test_minus_zero_is_zero():
    p = np.zeros(30)
    q = p.copy()
    q[3] = -1e-9          # rounds to -0.0
    assert canonical(q)[3] == 0.0 and str(canonical(q)[3]) == "0.0"
    assert key(q, "t") == key(p, "t")


def test_name_version_and_settings_make_the_tag_whatever_their_order():
    p = np.ones(30)
    a = Tagged(rate=180, ccd=True)
    assert oracle_tag(a) == oracle_tag(Tagged(ccd=True, rate=180))
    for other in (Tagged(rate=240, ccd=True), Tagged(version="2", rate=180, ccd=True)):
        assert oracle_tag(other) != oracle_tag(a)
        assert key(p, oracle_tag(other)) != key(p, oracle_tag(a))
