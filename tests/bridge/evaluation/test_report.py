"""bridge/evaluation/report.py: the report of a hand-built evaluation:
README.md with its sections in order saying the evaluation's figures, the
plots, the exploration's trace copied beside them, evaluation.json read
back by `load` with the same figures; which pours get a GIF (the first of
each behaviour, then the earliest others), and one rendered by PyBullet."""
from __future__ import annotations

import json

import numpy as np

from pantarhei.bridge.evaluation.headline import headline, headline_markdown
from pantarhei.bridge.evaluation.report import gif_choices, load, render_gifs, write
from pantarhei.oracle.generative import sample
from tests.bridge.evaluation.evaluations import small_evaluation

SECTIONS = ["## Headline", "## Curiosity against random exploration",
            "## The general theory, asked what a person would ask", "## Held-out scenes",
            "## The paper's three example rules", "## Plans", "## The learned rules",
            "## The exploration", "## Time and simulations"]


def test_the_report_writes_its_sections_in_order_with_the_figures(tmp_path):
    theory = tmp_path / "t.pl"
    theory.with_suffix(".trace.png").write_bytes(b"\x89PNG trace")
    ev = small_evaluation(theory=str(theory))
    readme = write(ev, tmp_path / "rep", gifs=False, command="pantarhei evaluate --seed 3")
    assert readme == tmp_path / "rep" / "README.md"
    text = readme.read_text(encoding="utf-8")
    places = [text.index(s + "\n") for s in SECTIONS]
    assert places == sorted(places)
    assert "Measured by `pantarhei evaluate --seed 3` with the synthetic oracle" in text
    assert headline_markdown(ev) in text
    assert "| a2 | pour from the side | not: no spill | 25.0% |" in text
    assert "| near (20) | 2.5 | 95.0% | 90.0% | 97.0% | 80.0% | 40.0% | 90.0% |" in text
    assert "![per expectation](expectations.png)" in text
    assert "## Pours behind three rules" not in text           # no GIFs asked for
    for name in ("behaviours.png", "heldout.png", "expectations.png"):
        assert (tmp_path / "rep" / name).read_bytes()[:4] == b"\x89PNG"
    assert (tmp_path / "rep" / "exploration.png").read_bytes() == b"\x89PNG trace"
    assert text.endswith("| predicting |  | 1.5 |\n")


def test_evaluation_json_reads_back_with_the_same_figures(tmp_path):
    ev = small_evaluation(theory=str(tmp_path / "t.pl"))
    write(ev, tmp_path / "rep", gifs=False)
    saved = json.loads((tmp_path / "rep" / "evaluation.json").read_text(encoding="utf-8"))
    assert saved == json.loads(json.dumps(ev.as_dict()))
    again = load(tmp_path / "rep" / "evaluation.json")
    assert again.as_dict() == saved
    assert headline(again) == headline(ev)


def test_without_near_scenes_no_per_expectation_plot_and_no_trace_to_copy(tmp_path):
    ev = small_evaluation(theory=str(tmp_path / "t.pl"))
    ev.heldout["near"]["scenes"] = 0
    text = write(ev, tmp_path / "rep", gifs=True).read_text(encoding="utf-8")
    assert not (tmp_path / "rep" / "expectations.png").exists()
    assert "expectations.png" not in text
    assert not (tmp_path / "rep" / "exploration.png").exists() and "## The exploration\n" not in text
    # GIFs are drawn for the PyBullet oracle only
    assert not list((tmp_path / "rep").glob("*.gif"))


def test_the_pours_drawn_are_the_first_of_each_behaviour_then_the_earliest():
    ev = small_evaluation()
    a, b, c = [True] * 9, [True] * 8 + [False], [False] * 9
    ev.explored_consequents = np.array([a, a, b, a, c])
    assert gif_choices(ev) == [0, 2, 4]
    assert gif_choices(ev, k=5) == [0, 2, 4, 1, 3]
    assert gif_choices(ev, k=1) == [0]
    ev.explored_consequents = None
    assert gif_choices(ev) == []


def test_a_chosen_pour_rendered_as_a_gif(tmp_path):
    ev = small_evaluation()
    ev.oracle = "pybullet"
    ev.explored_consequents = np.array([[True] * 9, [True] * 9])
    ev.best_samples = [sample(["pour_low", "little_liquid"], 1, 1)[0],
                       sample(["pour_to_side"], 1, 1)[0]]
    drawn = render_gifs(ev, tmp_path, k=1)
    assert drawn == [(0, tmp_path / "pour_a1.gif")]
    assert (tmp_path / "pour_a1.gif").read_bytes()[:6] == b"GIF89a"
