"""The session behind the exploration's foreign predicates
(bridge/exploration/session.py), called from the real SWI-Prolog: an error
in Python is one line in Prolog and is kept to be raised again as it was."""
from __future__ import annotations

import pytest

from pantarhei.bridge.errors import UserError
from pantarhei.bridge.exploration.session import install


@pytest.fixture(scope="module")
def eng():
    return install()


def test_without_a_session_prolog_gets_one_line_and_python_the_error(eng):
    host = eng.exploration_host
    host.take_error()
    r = eng.once("catch(curiosity_bridge:call_bridge(exploration_simulate, "
                 "_{antecedent: [pour_low], iteration: 1}, _), exploration_error(M), true), "
                 "string(M)")
    assert r["M"] in (b"no exploration is running", "no exploration is running")
    e = host.take_error()
    assert isinstance(e, UserError) and str(e) == "no exploration is running"
    assert host.take_error() is None


def test_the_prompt_oracle_answers_through_the_same_door(eng):
    r = eng.once("curiosity_bridge:call_bridge(oracle_sample, "
                 "_{antecedent: [pour_low], n: 2, seed: 1}, R), "
                 "get_dict(rows, R, Rows), length(Rows, N), Rows = [Row|_], length(Row, K)")
    assert (r["N"], r["K"]) == (2, 30)
    bad = eng.once("catch(curiosity_bridge:call_bridge(oracle_sample, "
                   "_{antecedent: [pour_sideways], n: 1, seed: 1}, _), exploration_error(M), true)")
    assert "pour_sideways" in str(bad["M"])
    assert eng.exploration_host.take_error() is not None
