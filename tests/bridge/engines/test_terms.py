"""Prolog terms as Python values and back (bridge/engines/terms.py), through
a foreign predicate registered in the real SWI-Prolog."""
from __future__ import annotations

import pytest

from pantarhei.bridge.engines.swipl import engine
from pantarhei.bridge.engines.terms import foreign


@pytest.fixture(scope="module")
def echo():
    """terms_test:echo/2 and terms_test:reply/2: the first hands its
    request back, and keeps what Python read; the second replies with
    the request's "reply" entry, looked up in `replies`."""
    eng, seen, keep = engine(), [], []
    replies = {"big": 2**70, "object": object(), "tuple": (1, ("a", 2.0))}

    def hand_back(request):
        seen.append(request)
        return request

    foreign("terms_test", "echo", hand_back, keep)
    foreign("terms_test", "reply", lambda request: replies[request["reply"]], keep)
    yield eng, seen
    keep.clear()


def test_values_cross_both_ways(echo):
    eng, seen = echo
    # = and not ==: each dict's tag is a variable of its own
    assert eng.succeeds(
        "terms_test:echo(_{a: [1, -2.5, \"text\", x, true, false, null], "
        "'größe': _{c: [], d: _{}}, e: 1.0e300, f: -9223372036854775808}, R), "
        "R = _{a: [1, -2.5, text, x, true, false, null], "
        "'größe': _{c: [], d: _{}}, e: 1.0e300, f: -9223372036854775808}")
    assert seen[-1] == {"a": [1, -2.5, "text", "x", True, False, None],
                        "größe": {"c": [], "d": {}}, "e": 1.0e300, "f": -2**63}
    assert type(seen[-1]["e"]) is float and type(seen[-1]["a"][0]) is int


def test_a_tuple_is_written_as_a_list(echo):
    eng, _ = echo
    assert eng.succeeds("terms_test:reply(_{reply: tuple}, R), R == [1, [a, 2.0]]")


@pytest.mark.parametrize("goal, says", [
    ("terms_test:echo(_{a: f(x)}, R)", "not a dict, list, atom, string or number"),
    ("terms_test:echo(_{a: _}, R)", "not a dict, list, atom, string or number"),
    ("terms_test:reply(_{reply: big}, R)", "beyond 64 bits"),
    ("terms_test:reply(_{reply: object}, R)", "cannot write a object"),
])
def test_what_is_not_a_value_is_an_error_reply(echo, goal, says):
    eng, _ = echo
    result = eng.once(f"{goal}, get_dict(error, R, E), atom_string(E, S)")
    message = result["S"].decode() if isinstance(result["S"], bytes) else str(result["S"])
    assert says in message
