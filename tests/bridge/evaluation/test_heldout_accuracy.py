"""bridge/evaluation/heldout_accuracy.py: the report's section on the
held-out scenes of a hand-built evaluation says its figures and draws its
plots (per expectation only with near scenes)."""
from __future__ import annotations

from pantarhei.bridge.evaluation.heldout_accuracy import heldout_section
from tests.bridge.evaluation.evaluations import small_evaluation


def test_the_held_out_table_and_the_per_expectation_plot_when_drawn(tmp_path):
    ev = small_evaluation()
    L = heldout_section(ev, tmp_path)
    assert "| near (20) | 2.5 | 95.0% | 90.0% | 97.0% | 80.0% | 40.0% | 90.0% |" in L
    # random exploration's theory decided nothing on the uniform scenes: no accuracy
    assert "| uniform (30) | 3.4 | 85.0% | 50.0% | 95.0% | n/a | 0.0% | 70.0% |" in L
    assert "![per expectation](expectations.png)" in L
    for name in ("heldout.png", "expectations.png"):
        assert (tmp_path / name).read_bytes()[:4] == b"\x89PNG"
    # without near scenes, no plot per expectation
    ev.heldout["near"]["scenes"] = 0
    (tmp_path / "none").mkdir()
    assert "![per expectation](expectations.png)" not in heldout_section(ev, tmp_path / "none")
    assert not (tmp_path / "none" / "expectations.png").exists()
