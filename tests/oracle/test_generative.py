"""oracle/generative.py: samples lie in their propositions' support and
follow the density that `log_density` gives, for every proposition; and
`describe` reads the generative models backwards."""
from __future__ import annotations

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from scipy import stats

from pantarhei.oracle import generative as G
from pantarhei.theory.lexicon import load_vocabulary

V = load_vocabulary()
PROPS = sorted(V.propositions)
N = 400
GRID = 801
ALPHA = 1e-3


def _index(name: str) -> int:
    return V.parameter(name).index


def _tested(prop: str) -> list[int]:
    """The parameters a proposition draws (and its base), plus one it leaves
    to the prior."""
    m = V.proposition(prop).model
    out = [_index(m.param)]
    if m.base:
        out.append(_index(m.base))
    free = next(p.index for p in V.parameters if p.index not in out and not p.discrete)
    return out + [free]


def test_there_are_86_propositions():
    assert len(PROPS) == 86


@pytest.mark.parametrize("prop", PROPS)
def test_samples_lie_in_the_support(prop):
    P = G.sample([prop], 300, seed=1)
    m = V.proposition(prop).model
    i = _index(m.param)
    lo = np.array([p.low for p in V.parameters])
    hi = np.array([p.high for p in V.parameters])
    assert np.all((P >= lo) & (P <= hi))
    if m.kind == "uniform":
        assert np.all((P[:, i] >= m.low) & (P[:, i] <= m.high))
    else:
        d = P[:, i] - P[:, _index(m.base)]
        assert np.all((d >= m.low - 1e-9) & (d <= m.high + 1e-9))
    assert np.all(np.isfinite(G.log_density(P, [prop])))
    assert np.all(G.in_support(P, [prop]))
    assert np.all(P[:, V.parameter("particle_count").index] % 1 == 0)


@pytest.mark.parametrize("prop", [p for p in PROPS if V.proposition(p).model.kind == "uniform"])
def test_outside_the_range_the_density_is_zero(prop):
    m = V.proposition(prop).model
    i = _index(m.param)
    p = V.parameter(m.param)
    P = G.sample([prop], 5, seed=2)
    for v in (m.low - 1, m.high + 1):
        if p.low <= v <= p.high:
            Q = P.copy()
            Q[:, i] = v
            assert np.all(G.log_density(Q, [prop]) == -np.inf)


def _conditional_cdf(P: np.ndarray, i: int, prop: str) -> np.ndarray:
    """F(x_i | the other parameters) of each row, by integrating exp(log_density)
    along parameter i (with the trapezoid rule on a fine grid)."""
    lo, hi = V.parameters[i].low, V.parameters[i].high
    grid = np.linspace(lo, hi, GRID)
    Q = np.repeat(P, GRID, axis=0)
    Q[:, i] = np.tile(grid, len(P))
    dens = np.exp(G.log_density(Q, [prop])).reshape(len(P), GRID)
    cum = np.concatenate([np.zeros((len(P), 1)),
                          np.cumsum((dens[:, 1:] + dens[:, :-1]) / 2 * np.diff(grid), axis=1)], axis=1)
    total = cum[:, -1]
    assert np.all(total > 0)
    at = np.array([np.interp(x, grid, c) for x, c in zip(P[:, i], cum)])
    return at / total


@pytest.mark.slow
@pytest.mark.parametrize("prop", PROPS)
def test_samples_follow_the_density(prop):
    """Goodness of fit: the conditional CDF from log_density, applied to the
    samples, is uniform (Kolmogorov-Smirnov); counts, chi-square."""
    P = G.sample([prop], N, seed=11)
    for i in _tested(prop):
        if V.parameters[i].discrete:
            continue
        u = _conditional_cdf(P, i, prop)
        assert stats.kstest(u, "uniform").pvalue > ALPHA, V.parameters[i].name
    k = V.parameter("particle_count").index
    values = np.arange(V.parameters[k].low, V.parameters[k].high + 1)
    Q = np.repeat(P[:1], len(values), axis=0)
    Q[:, k] = values
    pmf = np.exp(G.log_density(Q, [prop]) - G.log_density(P[:1], [prop]))
    pmf = pmf / pmf.sum()
    support = pmf > 0
    P2 = G.sample([prop], 4000, seed=12)
    counts = np.array([(P2[:, k] == v).sum() for v in values[support]])
    assert counts.sum() == len(P2)                       # nothing outside the support
    assert stats.chisquare(counts, pmf[support] * len(P2)).pvalue > ALPHA


def test_a_wrong_sampler_would_fail_the_fit():
    """The goodness-of-fit test has teeth: samples squeezed towards the low
    end of a range are rejected."""
    P = G.sample(["pour_high"], N, seed=11)
    i = _index("pour_z")
    P[:, i] = 140 + (P[:, i] - 140) ** 2 / 110
    assert stats.kstest(_conditional_cdf(P, i, "pour_high"), "uniform").pvalue < ALPHA


def test_log_density_is_the_product_of_the_uniform_widths():
    ants = [["pour_high", "heavy_liquid"], ["approach_raising", "pour_low"],
            ["retreat_moving_away", "end_high"], []]
    for a in ants:
        P = G.sample(a, 50, seed=3)
        logp = G.log_density(P, a)
        expect = np.zeros(len(P))
        setters = {V.proposition(n).model.param: V.proposition(n).model for n in a}
        bases = {s.base for s in setters.values() if s.base}
        for p in V.parameters:
            m = setters.get(p.name)
            if p.name in bases:
                # uniform on its range, narrowed so that its dependant has room
                pl = G.distribution(a)
                expect -= np.log(pl.high[p.index] - pl.low[p.index])
            elif m is None:
                expect -= np.log(p.prior_high - p.prior_low + (1 if p.discrete else 0))
            elif m.kind == "uniform":
                expect -= np.log(min(p.high, m.high) - max(p.low, m.low))
            else:
                b = P[:, _index(m.base)]
                expect -= np.log(np.minimum(p.high, b + m.high) - np.maximum(p.low, b + m.low))
        assert np.allclose(logp, expect)


def test_same_seed_same_samples_and_order_does_not_matter():
    a = G.sample(["pour_low", "heavy_liquid"], 20, seed=5)
    b = G.sample(["heavy_liquid", "pour_low"], 20, seed=5)
    assert np.array_equal(a, b)
    assert not np.array_equal(a, G.sample(["pour_low", "heavy_liquid"], 20, seed=6))


# -- describe(P): the generative models read backwards --------------------------------------

def random_valid(seed: int) -> tuple[str, ...]:
    from pantarhei.bridge.reasoning.valid_scenes import random_antecedents

    return random_antecedents(seed, 1)[0]


@pytest.mark.slow
@settings(derandomize=True, max_examples=60, deadline=None)
@given(seed=st.integers(0, 10**6), keep=st.integers(0, 2**30), draws=st.integers(0, 10**6))
def test_every_sample_is_described_by_a_superset_of_its_antecedent(seed, keep, draws):
    full = random_valid(seed)
    # any subset of a valid antecedent is valid: keep a random part of it
    a = tuple(p for i, p in enumerate(full) if keep >> (i % 30) & 1)
    for d in G.describe(G.sample(list(a), 20, draws)):
        assert set(a) <= set(d), sorted(set(a) - set(d))


def test_one_value_per_dimension_and_none_between_values():
    p = G.sample(["pour_to_side"], 1, 3)[0]
    row = {n: float(x) for n, x in zip(V.parameter_names, p)}
    row["pour_x"] = 100.0            # between pour_near_rim (40-95) and pour_to_side (105-165)
    row["particle_mass"] = 5000.0    # the lower end of heavy_liquid
    (d,) = G.describe(G.from_dict(row)[None, :])
    dims = [V.proposition(x).dimension for x in d]
    assert len(dims) == len(set(dims))
    assert "pour_alignment" not in dims
    assert "heavy_liquid" in d


def test_relative_models_are_judged_on_the_offset_from_their_base():
    row = {n: float(x) for n, x in zip(V.parameter_names, G.sample([], 1, 5)[0])}
    row.update(pour_x=60.0, start_x=160.0)     # 100 mm farther than the pour: moving closer
    (d,) = G.describe(G.from_dict(row)[None, :])
    assert "approach_moving_closer" in d and "approach_moving_away" not in d
    row.update(start_x=30.0)                   # 30 mm nearer: moving away
    (d,) = G.describe(G.from_dict(row)[None, :])
    assert "approach_moving_away" in d


def test_canonical_sorted_tuples():
    out = G.describe(G.sample(["light_liquid"], 5, 1))
    assert all(isinstance(d, tuple) and list(d) == sorted(set(d)) for d in out)
    assert G.describe(np.empty((0, 30))) == []


def test_a_pour_is_drawn_again_from_its_parameters():
    p = G.sample(["light_liquid"], 1, 5)[0]
    assert np.array_equal(G.from_dict(G.to_dict(p)), p)


def test_in_support_is_where_the_density_is_finite() -> None:
    """The support, computed at once over the parameters of fixed
    intervals, is where log_density is finite, for bodies with relative
    and discrete parameters, on pours drawn for other bodies and on the
    edges of their intervals."""
    from pantarhei.bridge.learning.askable import askable_bodies

    bodies = list(askable_bodies(2))[::7]
    P = np.vstack([G.sample(list(b), 4, i) for i, b in enumerate(bodies)])
    dist = G.distribution(bodies[0])
    edge = P[:20].copy()
    edge[:, dist.base < 0] = dist.low[dist.base < 0]
    P = np.vstack([P, edge, P[:20] + 1e-9])
    for b in bodies:
        assert np.array_equal(G.in_support(P, b), np.isfinite(G.log_density(P, b))), b


def _one_parameter_at_a_time(antecedent: list[str], n: int, seed: int) -> np.ndarray:
    """The draws as the stream gives them one parameter at a time: each
    parameter's n values in turn, a relative one's in [0, 1) and scaled
    around its base afterwards."""
    pl = G.distribution(antecedent)
    rng = np.random.default_rng(seed)
    out = np.empty((n, len(pl.low)))
    for i in range(len(pl.low)):
        if pl.base[i] >= 0:
            out[:, i] = rng.uniform(size=n)
        elif pl.discrete[i]:
            out[:, i] = rng.integers(int(pl.low[i]), int(pl.high[i]), size=n, endpoint=True)
        else:
            out[:, i] = rng.uniform(pl.low[i], pl.high[i], size=n)
    for i in np.flatnonzero(pl.base >= 0):
        lo = np.maximum(pl.bound_low[i], out[:, pl.base[i]] + pl.low[i])
        hi = np.minimum(pl.bound_high[i], out[:, pl.base[i]] + pl.high[i])
        out[:, i] = lo + out[:, i] * (hi - lo)
    return out


@pytest.mark.parametrize("antecedent", [[], ["pour_high", "pour_centred"], ["start_low"],
                                        ["end_tilted_back", "pour_half_tilted", "little_liquid"],
                                        ["light_liquid", "start_to_side", "end_near_rim"]])
def test_the_draws_are_the_stream_one_parameter_at_a_time(antecedent) -> None:
    # every stored pour and every theory learned from them rests on these numbers
    for n, seed in ((1, 0), (2, 17), (31, 123456)):
        assert np.array_equal(G.sample(antecedent, n, seed),
                              _one_parameter_at_a_time(antecedent, n, seed))
