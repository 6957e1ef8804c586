"""The exploration benchmark (benchmarks/exploration.py) asks for runs that
explore/1 accepts: its options are the option table's, read by Prolog's
settings/2, so that a renamed option breaks this test and not `make bench`
an hour in."""
from __future__ import annotations

import pytest

from benchmarks.exploration import run_options
from pantarhei.bridge.exploration.session import install


@pytest.mark.parametrize("curiosity", ["discover", "paper"])
def test_the_measured_runs_are_explorations_prolog_accepts(tmp_path, curiosity):
    # a breadth other than the default, as the largest budget measures
    # (an option the discovering curiosity does not read: not passed to it)
    o = run_options(5, tmp_path, seed=2, breadth=6, curiosity=curiosity)
    r = install().once(f"curiosity_settings:settings({o.prolog()}, S), "
                       "get_dict(curiosity, S, C), get_dict(budget, S, B), get_dict(slope, S, L), "
                       "get_dict(breadth, S, W)")
    assert (str(r["C"]), r["B"]) == (curiosity, 5)
    assert (r["L"] == 0.0) == (curiosity == "paper")
    assert (r["W"] == 6) == (curiosity == "paper")
