"""oracle/stepping.py: a pour run through step by step (approach, retreat,
settling), watched at the sample rate, shown at the frame rate, stopped
early once at rest, and written as the record that `scoring` reads."""
from __future__ import annotations

from dataclasses import replace

import pytest

from pantarhei.oracle import scoring
from pantarhei.oracle.fidelity import CHOSEN_FIDELITY
from pantarhei.oracle.stepping import TIMING_FIELDS, run

from .pours import pour

pytestmark = pytest.mark.slow

#: A short pour that never tilts the source: 0.3 s approach, 0.3 s retreat.
SHORT = pour(particle_count=10, approach_duration=300, retreat_duration=300)
#: The chosen settings (180 Hz, 30 samples a second), settling for 1 s.
FULL = replace(CHOSEN_FIDELITY, settle_ms=1000, early_stop=False)


def test_the_whole_pour_is_stepped_and_recorded():
    frames = []
    rec = run(SHORT, FULL, on_frame=lambda w, t: frames.append(t), frame_hz=10)
    assert rec["steps"] == 108 + 180 and rec["simulated_s"] == pytest.approx(1.6)
    assert frames == pytest.approx([k / 10 for k in range(17)])     # from the start, 10 a second
    assert rec["particles"] == 10 and rec["destination_mass_kg"] == 0.8
    assert set(rec["displacement_mm"]) == set(rec["tilt_deg"]) == set(scoring.STAGES)
    assert rec["fractions"] == {"source": 1.0, "destination": 0.0, "elsewhere": 0.0,
                                "entered_destination": 0.0}       # never tilted
    assert rec["contact_impulse"] == 0 and rec["min_gap_mm"] == scoring.CLEAR_MM
    assert all(rec[k] > 0 for k in TIMING_FIELDS)


def test_settling_stops_once_everything_is_at_rest():
    full = run(SHORT, FULL)
    early = run(SHORT, replace(FULL, early_stop=True))
    # three samples at rest after the retreat (at 30 a second)
    assert early["simulated_s"] == pytest.approx(0.7)
    same = lambda r: {k: v for k, v in r.items()  # noqa: E731
                      if k not in (*TIMING_FIELDS, "steps", "simulated_s")}
    assert same(early) == same(full)
