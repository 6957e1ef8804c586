"""oracle/physics.py: the PyBullet oracle at the chosen settings (physical
sanity, determinism) and the math it pins. Its pours run through `world`
and `stepping`, whose own tests are in test_world and test_stepping."""
from __future__ import annotations

import numpy as np
import pytest

from pantarhei.oracle import baseline
from pantarhei.oracle.base import make_oracle
from pantarhei.oracle.fidelity import CHOSEN_FIDELITY
from pantarhei.oracle.physics import PouringOracle
from pantarhei.oracle.result_keys import key, oracle_tag
from pantarhei.oracle.simulator import make_simulator
from pantarhei.oracle.stepping import TIMING_FIELDS
from pantarhei.theory.lexicon import load_vocabulary

from .pours import CENTRED_LOW_TIPPED, FAR_SIDE_TIPPED, HEAVY_DROP, NEVER_TILTED, pour

NAMES = load_vocabulary().expectation_names


def score(**changes):
    out = PouringOracle().score(pour(**changes))
    return dict(zip(NAMES, out.scores)), out.record


@pytest.mark.slow
def test_registered_and_chosen_settings():
    o = make_oracle("pybullet")
    assert isinstance(o, PouringOracle) and o.name == "pybullet"
    assert o.settings()["rate_hz"] == CHOSEN_FIDELITY.rate_hz
    assert make_oracle("pybullet", fidelity="default").settings()["rate_hz"] == 240


def test_the_pinned_environment_is_part_of_the_key():
    p = np.zeros(30)
    pinned, native = PouringOracle(), PouringOracle(math="native")
    assert pinned.environment() == dict(baseline.ENVIRONMENT)
    assert pinned.settings()["environment"] == dict(baseline.ENVIRONMENT)
    assert native.environment() == {}
    assert key(p, oracle_tag(pinned)) != key(p, oracle_tag(native))
    with pytest.raises(ValueError, match="unknown math"):
        PouringOracle(math="fast")


@pytest.mark.slow
def test_a_source_that_never_tilts_keeps_its_liquid():
    s, rec = score(**NEVER_TILTED)
    assert rec["fractions"]["source"] >= 0.95
    assert s["liquid_leaves_source"] <= 0.05
    assert s["liquid_enters_destination"] <= 0.05
    assert s["no_spill"] >= 0.95


@pytest.mark.slow
def test_tipped_centred_low_over_the_destination_the_liquid_goes_in_and_stays():
    s, rec = score(**CENTRED_LOW_TIPPED)
    assert s["liquid_leaves_source"] >= 0.9
    assert s["liquid_enters_destination"] >= 0.8
    assert rec["fractions"]["destination"] >= 0.8
    assert s["liquid_remains_in_destination"] >= 0.9
    assert s["destination_upright"] > 0.9


@pytest.mark.slow
def test_tipped_far_to_the_side_spills_most():
    s, rec = score(**FAR_SIDE_TIPPED)
    assert s["liquid_leaves_source"] >= 0.9
    assert rec["fractions"]["elsewhere"] >= 0.7
    assert s["no_spill"] <= 0.3
    assert s["liquid_enters_destination"] <= 0.2
    assert s["source_clear"] > 0.5          # nowhere near the destination


@pytest.mark.slow
def test_heavy_liquid_dropped_from_high_moves_a_light_slippery_destination():
    s, rec = score(**HEAVY_DROP)
    assert max(rec["displacement_mm"].values()) > 20 or max(rec["tilt_deg"].values()) > 20
    assert min(s["destination_still_retreat"], s["destination_still_settle"]) < 0.5
    # the same drop into a heavy, grippy destination leaves it still
    s2, _ = score(**{**HEAVY_DROP, "destination_mass": 3000, "destination_friction": 1500})
    assert min(s2[n] for n in NAMES[:3]) > 0.5


@pytest.mark.slow
def test_the_source_bumping_into_the_destination_is_seen():
    # the source sweeps through the destination's wall on its way in
    s, rec = score(start_x=200, start_z=-30, pour_x=0, pour_z=-30, approach_duration=600)
    assert rec["contact_impulse"] > 0
    assert s["source_clear"] < 0.5
    assert s["destination_still_approach"] < 0.5


@pytest.mark.slow
def test_scores_are_fractions_and_the_record_adds_up():
    for changes in (NEVER_TILTED, CENTRED_LOW_TIPPED, HEAVY_DROP):
        s, rec = score(**changes)
        v = np.array(list(s.values()))
        assert np.all((v >= 0) & (v <= 1))
        f = rec["fractions"]
        assert f["source"] + f["destination"] + f["elsewhere"] == pytest.approx(1.0)
        assert set(rec["displacement_mm"]) == {"approach", "retreat", "settle"}


def _without_timing(rec):
    return {k: v for k, v in rec.items() if k not in TIMING_FIELDS}


@pytest.mark.slow
def test_same_parameterization_same_result_in_any_worker():
    P = np.array([pour(**c) for c in (CENTRED_LOW_TIPPED, HEAVY_DROP, FAR_SIDE_TIPPED)])
    with make_simulator("pybullet", executor="inline", store=None) as sim:
        here = sim.simulate(P)
        rec_here = sim.last_records
    with make_simulator("pybullet", executor="local", workers=2, store=None) as sim:
        forward = sim.simulate(P)
        rec_forward = sim.last_records
        backward = sim.simulate(P[::-1])[::-1]
    assert np.array_equal(forward, here)
    assert np.array_equal(forward, backward)
    assert [_without_timing(r) for r in rec_forward] == [_without_timing(r) for r in rec_here]
