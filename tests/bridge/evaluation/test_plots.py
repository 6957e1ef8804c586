"""bridge/evaluation/plots.py: the report's PNG plots of a hand-built
evaluation: their size, one held-out panel per set the evaluation has,
curiosity drawn in red and random exploration in blue, and per expectation
a bar for each figure decided (none where nothing was decided, which
`plotted` turns into NaN)."""
from __future__ import annotations

import math
from pathlib import Path

import numpy as np
from PIL import Image

from pantarhei.bridge.evaluation.plots import (plot_behaviours, plot_expectations, plot_heldout,
                                               plotted)
from tests.bridge.evaluation.evaluations import small_evaluation

RED, PINK, BLUE = (0xc0, 0x39, 0x2b), (0xf4, 0xa5, 0x82), (0x2c, 0x7f, 0xb8)


def pixels(path: Path) -> np.ndarray:
    assert path.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    return np.asarray(Image.open(path).convert("RGB"))


def painted(a: np.ndarray, rgb: tuple[int, int, int]) -> int:
    return int((a == np.array(rgb)).all(axis=2).sum())


def bars(a: np.ndarray, rgb: tuple[int, int, int], tall: int = 20) -> int:
    """Vertical runs of columns painted in rgb over more than `tall`
    pixels (a legend's patch is shorter)."""
    cols = (a == np.array(rgb)).all(axis=2).sum(axis=0) > tall
    return int(cols[0] + np.sum(cols[1:] & ~cols[:-1]))


def test_nothing_decided_is_not_a_number_which_a_plot_leaves_out():
    out = plotted([None, 0.5, 0.0])
    assert math.isnan(out[0]) and out[1:] == [0.5, 0.0]
    assert plotted(x for x in (0.25,)) == [0.25]


def test_the_behaviours_over_the_budget_for_both_methods(tmp_path):
    plot_behaviours(small_evaluation(), tmp_path / "behaviours.png")
    a = pixels(tmp_path / "behaviours.png")
    assert a.shape == (432, 768, 3)                 # 6.4 x 3.6 inches at 120 dpi
    assert painted(a, RED) > 100 and painted(a, BLUE) > 100


def test_one_held_out_panel_per_set_the_evaluation_has(tmp_path):
    ev = small_evaluation()
    plot_heldout(ev, tmp_path / "two.png")
    a = pixels(tmp_path / "two.png")
    assert a.shape[1] == 2 * 528                    # 4.4 inches at 120 dpi per panel
    assert painted(a, RED) > 100 and painted(a, BLUE) > 100
    ev.heldout = {"uniform": ev.heldout["uniform"]}
    plot_heldout(ev, tmp_path / "one.png")
    assert pixels(tmp_path / "one.png").shape[1] == 528


def test_per_expectation_a_bar_for_each_figure_decided(tmp_path):
    plot_expectations(small_evaluation(), tmp_path / "expectations.png")
    a = pixels(tmp_path / "expectations.png")
    assert a.shape == (456, 960, 3)
    # nine expectations; no_spill decided nothing (accuracy none, coverage 0): eight bars each
    assert bars(a, RED) == 8        # the theory's accuracy
    assert bars(a, PINK) == 8       # the theory's coverage
    assert bars(a, BLUE) == 8       # the tree's accuracy
