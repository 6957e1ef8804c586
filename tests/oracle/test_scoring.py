"""oracle/scoring.py: the 9 scores from a record: bounds, verdicts, continuity."""
from __future__ import annotations

import numpy as np
import pytest

from pantarhei.oracle import scoring
from pantarhei.theory.lexicon import load_vocabulary

NAMES = load_vocabulary().expectation_names


def record(source=0.0, destination=1.0, entered=1.0, move=(0.0, 0.0, 0.0), tilt=(0.0, 0.0, 0.0),
           final_tilt=0.0, impulse=0.0, gap=10.0, mass=0.5):
    return {"fractions": {"source": source, "destination": destination,
                          "elsewhere": 1.0 - source - destination, "entered_destination": entered},
            "displacement_mm": dict(zip(scoring.STAGES, move)),
            "tilt_deg": dict(zip(scoring.STAGES, tilt)),
            "final_tilt_deg": final_tilt, "contact_impulse": impulse, "min_gap_mm": gap,
            "destination_mass_kg": mass}


def scores(**kw):
    return dict(zip(NAMES, scoring.scores(record(**kw))))


def test_a_perfect_pour_scores_one_everywhere():
    assert all(v == 1.0 for v in scores().values())


def test_every_expectation_has_an_explanation():
    assert set(scoring.EXPLANATIONS) == set(NAMES)


def test_stillness_falls_with_displacement_or_tilt_of_that_stage():
    s = scores(move=(0.0, scoring.STILL_MM / 2, 100.0), tilt=(scoring.STILL_DEG * 0.75, 0, 0))
    assert s["destination_still_approach"] == pytest.approx(0.25)
    assert s["destination_still_retreat"] == pytest.approx(0.5)
    assert s["destination_still_settle"] == 0.0


def test_upright_and_clear():
    assert scores(final_tilt=90)["destination_upright"] == 0.0
    assert scores(final_tilt=10)["destination_upright"] > 0.5
    assert scores(gap=5.0)["source_clear"] == pytest.approx(0.75)
    touched = scores(gap=0.0, impulse=0.01)["source_clear"]
    assert 0.0 < touched < 0.5
    assert scores(gap=0.0, impulse=1.0)["source_clear"] == 0.0


def test_liquid_fractions():
    s = scores(source=0.2, destination=0.5, entered=0.7)
    assert s["liquid_leaves_source"] == pytest.approx(0.8)
    assert s["liquid_enters_destination"] == pytest.approx(0.7)
    assert s["liquid_remains_in_destination"] == pytest.approx(1 - 0.2 / 0.7)
    assert s["no_spill"] == pytest.approx(0.7)


def test_remains_does_not_jump_when_a_particle_or_two_bounce_in_and_out():
    values = [scores(destination=0.0, entered=e, source=0.0)["liquid_remains_in_destination"]
              for e in np.linspace(0.0, 0.02, 5)]
    assert max(np.abs(np.diff(values))) < 0.1
    assert scores(destination=0.0, entered=0.6)["liquid_remains_in_destination"] == 0.0


def test_scores_stay_in_the_unit_interval():
    rng = np.random.default_rng(0)
    for _ in range(200):
        src, dst = rng.dirichlet([1, 1, 1])[:2]
        r = record(source=src, destination=dst, entered=min(1.0, dst + rng.uniform(0, 0.3)),
                   move=rng.uniform(0, 100, 3), tilt=rng.uniform(0, 180, 3),
                   final_tilt=rng.uniform(0, 180), impulse=rng.choice([0, rng.uniform(0, 5)]),
                   gap=rng.uniform(0, 10), mass=rng.uniform(0.02, 3))
        s = scoring.scores(r)
        assert s.shape == (9,) and np.all((s >= 0) & (s <= 1))
